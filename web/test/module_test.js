// SPDX-License-Identifier: GPL-3.0-or-later
// The page's module in Node, without a browser (test web:module of the `wasm` preset): it loads,
// solves a scene to the values worked out by hand, refuses bad scenes with the reader's messages
// (text and bytes that are not UTF-8 alike), warns as the command line does, and goes on working
// after a refusal (an exception that escaped would have aborted the module).
//
// usage: node module_test.js build/wasm/web/impulselab-wasm.js
'use strict';
const assert = require('node:assert/strict');
const path = require('node:path');

const createImpulseLab = require(path.resolve(process.argv[2]));

// The scene format's own example: a (mass 1, velocity [1.5, 0]) hits b (mass 1, at rest) on the
// normal [1, 0], elasticity 2.
const example = {
  dimension: 2,
  elasticity: 2,
  bodies: [
    {name: 'a', kind: 'material', mass: 1, velocity: [1.5, 0]},
    {name: 'b', kind: 'material', mass: 1, velocity: [0, 0]},
  ],
  contacts: [{bumper: 'a', wedge: 'b', normal: [1, 0]}],
};

const checks = [];
function check(name, body) {
  checks.push([name, body]);
}

// Equal within 1e-12 of the scene's scale: the minimum-norm solve rounds (Fdt = 1.4999999999999996
// here, as natively), so a hand value is met to rounding, not to the bit.
function near(actual, expected, scale) {
  const a = [actual].flat(2);
  const e = [expected].flat(2);
  assert.equal(a.length, e.length, `${actual} against ${expected}`);
  a.forEach((x, i) => assert.ok(Math.abs(x - e[i]) <= 1e-12 * scale, `${actual} against ${expected}`));
}

check('the scene format example solves to its hand values', (m) => {
  const out = m.solveScene(JSON.stringify(example));
  assert.equal(out.error, '');
  assert.deepEqual(out.warnings, []);
  const r = JSON.parse(out.result);
  assert.deepEqual(Object.keys(r),
                   ['impulses', 'bodies', 'energy', 'momentum', 'contacts', 'system']);
  // A = 1/m_a + 1/m_b = 2; B = e (u_a + u_b) = 2 (1.5 + 0) = 3; Fdt = B/A = 1.5 (4.5).
  assert.deepEqual(r.system.A, [[2]]);
  assert.deepEqual(r.system.B, [3]);
  near(r.impulses[0].magnitude, 1.5, 1.5);
  near(r.impulses[0].on_bumper, [-1.5, 0], 1.5);
  // a gives all its momentum to b: p_a' = 1.5 - 1.5 = 0, p_b' = 0 + 1.5.
  near(r.bodies[0].velocity, [0, 0], 1.5);
  near(r.bodies[1].velocity, [1.5, 0], 1.5);
  // Energy 1.5^2 / 2 = 1.125 before and after; the approach speed is reversed.
  near([r.energy.before, r.energy.after, r.energy.change], [1.125, 1.125, 0], 1.125);
  near([r.contacts[0].approach_before, r.contacts[0].approach_after], [1.5, -1.5], 1.5);
  // The details the page draws: each body's motion before and after, and its energy.
  const d = JSON.parse(out.details);
  assert.equal(d.dimension, 2);
  assert.deepEqual(d.bodies.map((b) => b.kind), ['material', 'material']);
  assert.deepEqual(d.bodies[0].before.velocity, [1.5, 0]);
  near(d.bodies[1].after.momentum, [1.5, 0], 1.5);
  near(d.bodies.map((b) => [b.energy_before, b.energy_after]), [[1.125, 0], [0, 1.125]], 1.125);
});

check('a refused scene gives the reader\'s message with its place, and no result', (m) => {
  const bad = structuredClone(example);
  bad.bodies[1].mass = -1;
  const out = m.solveScene(JSON.stringify(bad));
  assert.equal(out.error, 'bodies[1].mass: must be positive and finite, got -1');
  assert.equal(out.result, '');
  assert.equal(out.details, '');
});

check('bytes that are not UTF-8 reach the reader as bytes', (m) => {
  // {"a": "<0xFF>"}: the byte after the opening quote, line 1, column 8 (the quote is column 7).
  const bytes = new Uint8Array([...Buffer.from('{"a": "'), 0xff, ...Buffer.from('"}')]);
  const out = m.solveScene(bytes);
  assert.match(out.error, /^line 1, column 8: syntax error while parsing value - invalid string: ill-formed UTF-8 byte/);
});

check('the command line\'s warnings: an impulse that pulls', (m) => {
  // Lab 7's rod (mass 1, I = 1/3, ends at x = -1 and 1 on the ground, falling at 1, spinning at
  // 5, elasticity 2): A = [[4, -2], [-2, 4]], B = 2 (1 + 5, 1 - 5) = (12, -8), so
  // Fdt = (8/3, -2/3) and the rising end pulls.
  const rod = {
    dimension: 2,
    elasticity: 2,
    bodies: [
      {name: 'ground', kind: 'static'},
      {name: 'rod', kind: 'rigid', mass: 1, inertia: 1 / 3, position: [0, 0], velocity: [0, -1],
       angular_velocity: 5},
    ],
    contacts: [
      {bumper: 'ground', wedge: 'rod', normal: [0, 1], point: [-1, 0]},
      {bumper: 'ground', wedge: 'rod', normal: [0, 1], point: [1, 0]},
    ],
  };
  const out = m.solveScene(JSON.stringify(rod));
  assert.equal(out.error, '');
  const fdt = JSON.parse(out.result).impulses.map((i) => i.magnitude);
  assert.ok(Math.abs(fdt[0] - 8 / 3) < 1e-12 && Math.abs(fdt[1] + 2 / 3) < 1e-12, String(fdt));
  assert.deepEqual(out.warnings, ['contact 1 (ground\u2013rod): negative impulse -0.666667 (the contact pulls)']);
});

check('serial collisions beyond their bound: the command line\'s message, no result', (m) => {
  // Galperin's billiard with mass ratio 10^8 needs 31415 collisions; the bound is 100 per contact
  // and at least 10000 (10000 here) by default.
  const scene = {
    dimension: 1,
    elasticity: 2,
    bodies: [
      {name: 'wall', kind: 'static'},
      {name: 'light', kind: 'material', mass: 1, velocity: 0},
      {name: 'heavy', kind: 'material', mass: 1e8, velocity: -1},
    ],
    contacts: [
      {bumper: 'wall', wedge: 'light', normal: 1},
      {bumper: 'light', wedge: 'heavy', normal: 1},
    ],
    solver: {method: 'serial'},
  };
  const out = m.solveScene(JSON.stringify(scene));
  assert.match(out.error, /^serial collisions did not end: after 10000 collisions/);
  assert.equal(out.result, '');
});

check('a scene solved in slices gives solveScene\'s answer, whatever the slice', (m) => {
  // A light ball between a wall and a heavy one (10^6 times its mass) closing on it: serial
  // collisions go back and forth (3141 of them: Galperin's billiard), so they end within the
  // default bound (10,000 here) and stop at a bound of 50, unfinished. Each sliced run advances a
  // slice at a time and ends with solveScene's answer.
  const scene = (bound) => JSON.stringify({
    dimension: 1, elasticity: 2,
    bodies: [{name: 'wall', kind: 'static'}, {name: 'light', kind: 'material', mass: 1, velocity: 0},
             {name: 'heavy', kind: 'material', mass: 1e6, velocity: -1}],
    contacts: [{bumper: 'wall', wedge: 'light', normal: 1}, {bumper: 'light', wedge: 'heavy', normal: 1}],
    solver: {method: 'serial', ...(bound ? {max_collisions: bound} : {})},
  });
  for (const text of [scene(0), scene(50), JSON.stringify(example)]) {
    const whole = m.solveScene(text);
    for (const slice of [1, 7, 5000]) {
      let out = m.solveBegin(text, slice);
      let slices = 1;
      while (out.pending) {
        assert.equal(out.collisions, slices * slice);  // a slice runs as many as it is given
        assert.ok(out.collisions < out.bound);
        out = m.solveAdvance(slice);
        slices += 1;
      }
      assert.deepEqual([out.result, out.details, out.warnings, out.error],
                       [whole.result, whole.details, whole.warnings, whole.error]);
      if (slice === 1 && text === scene(50)) {
        assert.equal(slices, 50);  // 50 collisions, the end seen with the last one
      }
    }
  }
  // A refusal comes at once, in solveScene's words; a new scene drops the one in progress.
  const bad = structuredClone(example);
  bad.bodies[0].mass = 0;
  assert.equal(m.solveBegin(JSON.stringify(bad), 10).error, m.solveScene(JSON.stringify(bad)).error);
  assert.equal(m.solveBegin(scene(0), 10).pending, true);
  const answer = m.solveBegin(JSON.stringify(example), 10);
  assert.equal(answer.pending, false);
  assert.equal(answer.result, m.solveScene(JSON.stringify(example)).result);
  assert.match(m.solveAdvance(10).error, /no scene is being solved/);
});

check('the three methods side by side: what solve --compare --format json prints', (m) => {
  // One contact: every method gives the example's Fdt = 1.5 (the paper's system has one row; a
  // single collision is that row; the impulse pushes, so complementarity keeps it).
  const out = m.compareScene(JSON.stringify(example), 'methods');
  assert.equal(out.error, '');
  assert.equal(out.unfinished, '');
  const r = JSON.parse(out.result);
  assert.deepEqual(Object.keys(r), ['simultaneous', 'complementarity', 'serial']);
  for (const method of Object.keys(r)) {
    assert.equal(r[method].method, method);
    near(r[method].impulses[0].magnitude, 1.5, 1.5);
  }
  // The three laws: without friction at one contact they agree (scene format, "Friction and
  // restitution laws").
  const laws = JSON.parse(m.compareScene(JSON.stringify(example), 'restitution').result);
  assert.deepEqual(Object.keys(laws), ['newton', 'poisson', 'energetic']);
  for (const law of Object.keys(laws)) {
    near(laws[law].impulses[0].magnitude, 1.5, 1.5);
  }
  const bad = structuredClone(example);
  bad.bodies[0].mass = 0;
  assert.equal(m.compareScene(JSON.stringify(bad), 'methods').error,
               'bodies[0].mass: must be positive and finite, got 0');
});

check('a sweep of the elasticity: the rows of impulselab sweep', (m) => {
  // Fdt = e u / (1/m_a + 1/m_b) = 1.5 e / 2; energy after = (1.5 - Fdt)^2 / 2 + Fdt^2 / 2;
  // approach after = 1.5 - 2 Fdt = 1.5 (1 - e).
  const out = m.sweepScene(JSON.stringify(example), [1, 1.5, 2]);
  assert.equal(out.error, '');
  const rows = JSON.parse(out.rows);
  assert.equal(rows.length, 3);
  rows.forEach((row, k) => {
    const e = [1, 1.5, 2][k];
    const fdt = 0.75 * e;
    const after = ((1.5 - fdt) ** 2 + fdt ** 2) / 2;
    near(row, [e, after, after - 1.125, fdt, 1.5 * (1 - e)], 1.5);
  });
  assert.match(m.sweepScene(JSON.stringify(example), [-1]).error,
               /^elasticity: must be finite and at least 0, got -1 \(at elasticity -1\)$/);
});

check('serial collisions one at a time: the state after each collision', (m) => {
  // Three equal balls, the first at 1, elasticity 2: contact 0 gives ball 2 the speed of ball
  // 1 (which stops), then contact 1 passes it to ball 3; two collisions.
  const cradle = {
    dimension: 1,
    elasticity: 2,
    bodies: [1, 0, 0].map((v, k) => ({name: `b${k}`, kind: 'material', mass: 1, velocity: v})),
    contacts: [{bumper: 'b0', wedge: 'b1', normal: 1}, {bumper: 'b1', wedge: 'b2', normal: 1}],
  };
  const steps = [1, 2, 3].map((k) => JSON.parse(m.serialStep(JSON.stringify(cradle), k).step));
  assert.deepEqual(steps.map((s) => [s.contact, s.collisions, s.finished]), [[0, 1, false], [1, 2, true], [1, 2, true]]);
  near(steps[0].velocity.map((v) => v[0]), [0, 1, 0], 1);
  near(steps[0].Fdt, [1, 0], 1);
  near(steps[1].velocity.map((v) => v[0]), [0, 0, 1], 1);
  near(steps[1].Fdt, [1, 1], 1);
  near(steps[1].energy_after, 0.5, 0.5);
  // 0 is the scene format's "no bound of its own": the whole run.
  const whole = JSON.parse(m.serialStep(JSON.stringify(cradle), 0).step);
  assert.deepEqual([whole.contact, whole.collisions, whole.finished], [1, 2, true]);
});

createImpulseLab().then((m) => {
  let failed = 0;
  for (const [name, body] of checks) {
    try {
      body(m);
      console.log(`ok   ${name}`);
    } catch (e) {
      failed += 1;
      console.log(`FAIL ${name}\n${e.stack}`);
    }
  }
  process.exit(failed === 0 ? 0 : 1);
}, (e) => {
  console.log(`the module did not load: ${e}`);
  process.exit(1);
});
