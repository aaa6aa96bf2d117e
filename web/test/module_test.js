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
  // Galperin's billiard with mass ratio 10^6 needs 3141 collisions; the bound is 1000 per contact
  // (2000 here) by default.
  const scene = {
    dimension: 1,
    elasticity: 2,
    bodies: [
      {name: 'wall', kind: 'static'},
      {name: 'light', kind: 'material', mass: 1, velocity: 0},
      {name: 'heavy', kind: 'material', mass: 1e6, velocity: -1},
    ],
    contacts: [
      {bumper: 'wall', wedge: 'light', normal: 1},
      {bumper: 'light', wedge: 'heavy', normal: 1},
    ],
    solver: {method: 'serial'},
  };
  const out = m.solveScene(JSON.stringify(scene));
  assert.match(out.error, /^serial collisions did not end: after 2000 collisions/);
  assert.equal(out.result, '');
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
