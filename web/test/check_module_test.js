// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation page's module in Node, without a browser (test web:check-module of the `wasm`
// preset): it loads, gives a small derivation the verdicts worked out by hand below, refuses
// malformed files with their place (text and bytes that are not UTF-8 alike), and goes on working
// after a refusal (an exception that escaped would have aborted the module). The browser tests
// (check_test.mjs) compare it with the command line on every derivation file of the project.
//
// usage: node check_module_test.js build/wasm/web/impulselab-check.js
'use strict';
const assert = require('node:assert/strict');
const path = require('node:path');

const createImpulseLabCheck = require(path.resolve(process.argv[2]));

// Six equations, one of each kind a step can get here (line numbers in the comments):
const text = [
  '# Momentum of one body, and a slip',  // 1
  '',
  'assume: m > 0',                        // 3
  '',
  '$$ p = m v $$',                        // 5: the first equation, a premise
  '',
  '$$ v = \\frac{p}{m} $$',               // 7: divided by m, which is > 0: follows both ways
  '',
  '$$ v^2 = \\frac{p^2}{m^2} $$',         // 9: squared: follows, but v = -p/m also gives it
  '',
  '$$ v = \\frac{p}{2m} $$',              // 11: a slip (the 2)
  '',
  'given:',                               // 13
  '',
  '$$ a x = a y $$',                      // 15: a premise again (given:)
  '',
  '$$ x = y $$',                          // 17: divided by a, which may be 0
  '',
].join('\n');

const checks = [];
function check(name, body) {
  checks.push([name, body]);
}

check('a derivation gets the verdicts worked out by hand', (m) => {
  const out = m.checkDerivation(text, {file: 'hand.md'});
  assert.equal(out.error, '');
  assert.equal(out.line, 0);
  assert.equal(out.status, 1);  // a step does not follow: the command line's exit status 1
  const r = JSON.parse(out.result);
  assert.deepEqual(Object.keys(r), ['file', 'equations', 'summary', 'seconds']);
  assert.equal(r.file, 'hand.md');
  assert.deepEqual(r.equations.map((e) => [e.line, e.verdict]), [
    [5, 'premise'],
    // p = m v and m > 0: v = p/m, and multiplying back by m gives p = m v again.
    [7, 'follows'],
    // v = p/m gives v² = p²/m²; but v = -p/m satisfies v² = p²/m² and not v = p/m.
    [9, 'follows-one-way'],
    // v = p/m with p = 1, m = 1 makes v = 1, and p/(2m) = 1/2.
    [11, 'does-not-follow'],
    [15, 'premise'],
    // a x = a y is (x - y) a = 0: x = y where a ≠ 0; at a = 0 any x, y satisfy it.
    [17, 'follows-if'],
  ]);
  assert.deepEqual(r.equations.map((e) => e.from), [[], [5], [7], [9], [], [15]]);
  assert.equal(r.equations[1].converse, true);
  assert.equal(r.equations[2].converse, false);
  assert.equal(r.equations[5].condition, 'a \\neq 0');
  // The counterexample, evaluated here: it must satisfy line 9 and the fact m > 0, and break
  // line 11.
  const c = r.equations[3].counterexample;
  assert.ok(c.m > 0, `m = ${c.m}`);
  assert.ok(Math.abs(c.v * c.v - (c.p * c.p) / (c.m * c.m)) <= 1e-12, JSON.stringify(c));
  assert.ok(Math.abs(c.v - c.p / (2 * c.m)) > 1e-6, JSON.stringify(c));
  // The residual is what is left of v - p/(2m) on one of the two branches of line 9: p = m v
  // gives v - m v/(2m) = v/2, p = -m v gives v + m v/(2m) = 3v/2. Which branch the checker takes
  // follows GiNaC's order of the factors (the command line takes either from one run to the next).
  assert.ok(['v/2', '3*v/2'].includes(r.equations[3].residual_text), r.equations[3].residual_text);
  assert.deepEqual(r.summary, {
    'premise': 2, 'follows': 1, 'follows-one-way': 1, 'follows-if': 1, 'does-not-follow': 1,
    'dimensions': 0, 'undecided': 0,
  });
});

check('without a file name the report names the page', (m) => {
  const out = m.checkDerivation('$$ x = 1 $$\n\n$$ 2 x = 2 $$\n', {});
  assert.equal(out.status, 0);
  const r = JSON.parse(out.result);
  assert.equal(r.file, 'check.html');
  assert.deepEqual(r.equations.map((e) => e.verdict), ['premise', 'follows']);
});

check('a malformed file is refused with its place, and nothing is checked', (m) => {
  // Line 3: "$$ a = {b + c $$": the brace opened at column 8 is never closed.
  const out = m.checkDerivation('# Bad\n\n$$ a = {b + c $$\n', {file: 'bad.md'});
  assert.equal(out.result, '');
  assert.equal(out.status, 2);
  assert.deepEqual([out.line, out.column], [3, 8]);
  assert.match(out.error, /^3:8: expected '\}'/);
});

check('a division by zero in a step is a refusal at its place, not a crash', (m) => {
  const out = m.checkDerivation('# Bad\n\n$$ a = \\frac{1}{0} $$\n', {});
  assert.equal(out.result, '');
  assert.deepEqual([out.line, out.column], [3, 8]);
  assert.match(out.error, /division by zero/);
});

check('bytes that are not UTF-8 are refused at their place', (m) => {
  // Line 1 is "$$ x = 1 $$", line 2 holds the byte 0xFF at its first column.
  const bytes = new Uint8Array([...Buffer.from('$$ x = 1 $$\n'), 0xff, 0x0a]);
  const out = m.checkDerivation(bytes, {});
  assert.equal(out.result, '');
  assert.equal(out.line, 2);
  assert.match(out.error, /^2:1: expected UTF-8 text/);
});

check('a file without a display equation is refused (the contract)', (m) => {
  const out = m.checkDerivation('Only prose here.\n', {});
  assert.equal(out.result, '');
  assert.equal(out.status, 2);
  assert.notEqual(out.error, '');
});

check('a step budget outside the command line\'s (0 to 3600 s) is refused', (m) => {
  for (const stepSeconds of [0, -1, 'two', 3601, Infinity, NaN]) {
    const out = m.checkDerivation(text, {stepSeconds});
    assert.equal(out.result, '', String(stepSeconds));
    assert.equal(out.error, 'stepSeconds: expected a time from 0 to 3600 seconds');
  }
  for (const stepSeconds of [0.5, 3600]) {
    assert.equal(m.checkDerivation(text, {stepSeconds}).error, '');
  }
});

check('the module goes on working after its refusals', (m) => {
  const out = m.checkDerivation(text, {file: 'hand.md'});
  assert.equal(JSON.parse(out.result).equations.length, 6);
});

(async () => {
  const m = await createImpulseLabCheck();
  let failed = 0;
  for (const [name, body] of checks) {
    try {
      body(m);
      console.log(`ok: ${name}`);
    } catch (e) {
      ++failed;
      console.log(`FAILED: ${name}\n${e.stack}`);
    }
  }
  process.exit(failed === 0 ? 0 : 1);
})();
