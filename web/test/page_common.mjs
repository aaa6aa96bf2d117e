// SPDX-License-Identifier: GPL-3.0-or-later
// What the browser tests of the page share (page_test.mjs, bench_test.mjs): their options, the
// command line run on a scene, results compared as the contract compares them, the page opened
// and read, the checks and their count, and the run of one group.
//
// options: GROUP --site DIR --cli PROGRAM --source DIR --screenshots DIR
import {spawnSync} from 'node:child_process';
import {existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {check, checkClean, runGroup} from './harness.mjs';

const args = process.argv.slice(2);
export const group = args[0];
const option = (name) => {
  const at = args.indexOf(`--${name}`);
  if (at < 0 || at + 1 >= args.length) {
    throw new Error(`missing --${name}`);
  }
  return resolve(args[at + 1]);
};
export const site = option('site');
export const cli = option('cli');
export const source = option('source');
export const screenshots = option('screenshots');
export const page = join(site, 'collide.html');
export const pageUrl = `file://${page}`;
export const scratch = mkdtempSync(join(tmpdir(), 'impulselab-web-test-'));

// --- The command line ------------------------------------------------------------------------

// What `impulselab solve FILE --format json` gives (or another verb with other options): its output, its message without
// "impulselab: error: FILE: ", its warnings without "impulselab: warning: " and "FILE: ".
export function commandLine(file, options = ['--format', 'json'], verb = 'solve') {
  // (A report may pass spawnSync's 1 MiB default: serial collisions list every one.)
  const run = spawnSync(cli, [verb, file, ...options], {encoding: 'utf8', maxBuffer: 256 << 20});
  const lines = run.stderr.split('\n').filter((l) => l !== '');
  const strip = (line, prefix) => {
    let text = line.slice(prefix.length);
    if (text.startsWith(`${file}: `)) {
      text = text.slice(file.length + 2);
    }
    return text;
  };
  return {
    scene: readFileSync(file, 'latin1'),
    status: run.status,
    stdout: run.stdout,
    error: lines.filter((l) => l.startsWith('impulselab: error: ')).map((l) => strip(l, 'impulselab: error: ')).join('\n'),
    warnings: lines.filter((l) => l.startsWith('impulselab: warning: ')).map((l) => strip(l, 'impulselab: warning: ')),
  };
}

export function commandLineOnText(text, options, verb) {
  const file = join(scratch, 'scene.json');
  writeFileSync(file, text);
  return commandLine(file, options, verb);
}

// --- Comparing results -------------------------------------------------------------------------

// The page's report against the command line's: the same keys in the same order, the same
// strings and booleans, numbers equal within a relative 1e-12 of the size of their quantity in
// the report. The WebAssembly build and the native one round differently (Eigen vectorises on
// x86-64, not in WebAssembly), so a velocity that is 0 in exact arithmetic comes out as 6.7e-16 on
// one and 5.6e-16 on the other next to velocities of 1: compared with its own size it would
// differ wholly, compared with the velocities of the report it is equal to 1e-12. The size of a
// quantity is the largest number of the report in its unit: velocities (of the bodies, the
// approach speeds, B, the residual of A·Fdt = B, the complementarity slack), momenta (of the
// bodies, the totals, the impulses), energies; an angular velocity is measured against the
// velocities divided by the longest arm of the scene (the distance from a rigid body's origin to
// its contact point), an angular momentum against the momenta times that arm; anything else
// against the largest number of its own key (every entry of A, the condition estimate).
export function kindOf(path) {
  return path.replace(/\[[0-9]+\]/g, '[]');
}

const units = {
  'bodies[].velocity[]': 'velocity', 'bodies[].velocity': 'velocity',
  'contacts[].approach_before': 'velocity', 'contacts[].approach_after': 'velocity',
  'system.B[]': 'velocity', 'system.residual': 'velocity',
  'complementarity.slack[]': 'velocity', 'complementarity.complementarity_residual': 'velocity',
  'complementarity.slip_after[]': 'velocity', 'impulses[].tangential': 'momentum',
  'bodies[].momentum[]': 'momentum', 'bodies[].momentum': 'momentum',
  'momentum.before[]': 'momentum', 'momentum.before': 'momentum',
  'momentum.after[]': 'momentum', 'momentum.after': 'momentum',
  'impulses[].magnitude': 'momentum', 'impulses[].on_bumper[]': 'momentum', 'impulses[].on_bumper': 'momentum',
  'energy.before': 'energy', 'energy.after': 'energy', 'energy.change': 'energy',
  'bodies[].angular_velocity': 'angular velocity', 'bodies[].angular_momentum': 'angular momentum',
};

export function largestByUnit(value, path, sizes) {
  if (typeof value === 'number') {
    const unit = units[kindOf(path)] || kindOf(path);
    sizes.set(unit, Math.max(sizes.get(unit) || 0, Math.abs(value)));
  } else if (Array.isArray(value)) {
    value.forEach((x, i) => largestByUnit(x, `${path}[${i}]`, sizes));
  } else if (value !== null && typeof value === 'object') {
    for (const key of Object.keys(value)) {
      largestByUnit(value[key], path ? `${path}.${key}` : key, sizes);
    }
  }
  return sizes;
}

// The longest arm of the scene: from a rigid body's origin to one of its contact points.
export function longestArm(sceneText) {
  let arm = 0;
  try {
    const scene = JSON.parse(sceneText);
    const rigid = new Map(scene.bodies.filter((b) => b.kind === 'rigid').map((b) => [b.name, b.position]));
    for (const c of scene.contacts) {
      for (const name of [c.bumper, c.wedge]) {
        if (rigid.has(name) && c.point) {
          arm = Math.max(arm, Math.hypot(c.point[0] - rigid.get(name)[0], c.point[1] - rigid.get(name)[1]));
        }
      }
    }
  } catch (e) {
    // not a scene: no arm
  }
  return arm;
}

export function sizesOf(page, line, sceneText) {
  const sizes = largestByUnit(line, '', largestByUnit(page, '', new Map()));
  const arm = longestArm(sceneText);
  if (arm > 0) {
    sizes.set('angular velocity', Math.max(sizes.get('angular velocity') || 0, (sizes.get('velocity') || 0) / arm));
    sizes.set('angular momentum', Math.max(sizes.get('angular momentum') || 0, (sizes.get('momentum') || 0) * arm));
  }
  return sizes;
}

export function differences(page, line, sizes, path = '') {
  const found = [];
  const kind = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v);
  if (kind(page) !== kind(line)) {
    return [`${path}: ${JSON.stringify(page)} against ${JSON.stringify(line)}`];
  }
  if (kind(page) === 'number') {
    const size = sizes.get(units[kindOf(path)] || kindOf(path));
    if (!(Math.abs(page - line) <= 1e-12 * size)) {
      found.push(`${path}: ${page} against ${line} (the size of its quantity: ${size})`);
    }
  } else if (kind(page) === 'array') {
    if (page.length !== line.length) {
      return [`${path}: ${page.length} elements against ${line.length}`];
    }
    page.forEach((x, i) => found.push(...differences(x, line[i], sizes, `${path}[${i}]`)));
  } else if (kind(page) === 'object') {
    const keys = Object.keys(page).join(',');
    const lineKeys = Object.keys(line).join(',');
    if (keys !== lineKeys) {
      return [`${path}: keys ${keys} against ${lineKeys}`];
    }
    for (const key of Object.keys(page)) {
      found.push(...differences(page[key], line[key], sizes, path ? `${path}.${key}` : key));
    }
  } else if (page !== line) {
    found.push(`${path}: ${JSON.stringify(page)} against ${JSON.stringify(line)}`);
  }
  return found;
}

// --- The page --------------------------------------------------------------------------------

const unreserved = /[A-Za-z0-9\-_.!~*'()]/;
export function encodeBytes(bytes) {
  let text = '';
  for (const byte of bytes) {
    const c = String.fromCharCode(byte);
    text += byte < 0x80 && unreserved.test(c) ? c : '%' + byte.toString(16).toUpperCase().padStart(2, '0');
  }
  return text;
}

export async function shown(p) {
  return Number(await p.evaluate('document.body.dataset.shown || 0'));
}

// Opens the page afresh on @p hash.
export async function open(browser, hash, viewport) {
  const p = await browser.newPage(viewport);
  await p.goto(pageUrl + hash);
  await p.waitFor('document.body.dataset.ready === "true"');
  return p;
}

// Changes the address's fragment of an open page (a link followed within the page) and waits
// for the page to show it.
export async function navigate(p, hash) {
  const before = await shown(p);
  await p.send('Page.navigate', {url: pageUrl + hash});
  await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
}

export async function pageState(p) {
  return p.evaluate(`({
    result: document.getElementById('result-json').textContent,
    error: document.getElementById('scene-error').textContent,
    warnings: [...document.querySelectorAll('#warnings li')].map((li) => li.textContent),
    hash: location.hash,
  })`);
}

export function sceneOfHash(hash) {
  if (!hash.startsWith('#scene=')) {
    throw new Error(`the address holds no scene: ${hash.slice(0, 80)}`);
  }
  return decodeURIComponent(hash.slice('#scene='.length));
}

// --- Checks ----------------------------------------------------------------------------------

// Counted checks and the page's cleanliness: harness.mjs's, shared with the derivation page's tests.
export {check, checkClean};

// The page shows what the command line gives for the same scene.
export function checkAgainstCommandLine(state, line, where) {
  if (line.status === 0) {
    check(state.error === '', `${where}: no error`, state.error);
    let page = null;
    try {
      page = JSON.parse(state.result);
    } catch (e) {
      check(false, `${where}: result-json is JSON`, state.result.slice(0, 200));
      return;
    }
    const expected = JSON.parse(line.stdout);
    const found = differences(page, expected, sizesOf(page, expected, line.scene));
    check(found.length === 0, `${where}: result-json is the command line's`, found.slice(0, 10).join('\n'));
    check(JSON.stringify(state.warnings) === JSON.stringify(line.warnings), `${where}: the command line's warnings`,
          `page: ${JSON.stringify(state.warnings)}\nline: ${JSON.stringify(line.warnings)}`);
  } else {
    check(line.error !== '', `${where}: the command line explains its refusal`, line.error);
    check(state.error === line.error, `${where}: scene-error is the command line's message`,
          `page: ${state.error}\nline: ${line.error}`);
    check(state.result === '', `${where}: result-json is empty`, state.result.slice(0, 100));
  }
}

// The address of @p state opened afresh in a new page: the same result and address, and the
// controls named in @p controls (id: value) showing those values; then back to page @p p.
export async function checkSharedLink(browser, p, state, controls, where) {
  const shared = await open(browser, state.hash);
  const again = await pageState(shared);
  check(again.result === state.result && again.hash === state.hash, `${where}: the same result`);
  const values = {};
  for (const id of Object.keys(controls)) {
    values[id] = await shared.evaluate(`document.getElementById(${JSON.stringify(id)}).value`);
  }
  check(JSON.stringify(values) === JSON.stringify(controls), `${where}: the same controls`, JSON.stringify(values));
  checkClean(shared, where);
  await shared.close();
  await p.send('Page.bringToFront');
}

export function jsonFiles(folder) {
  const dir = join(source, folder);
  return readdirSync(dir).filter((f) => f.endsWith('.json')).sort().map((f) => join(dir, f));
}

export function presetsOfSite() {
  const text = readFileSync(join(site, 'presets.js'), 'utf8');
  const window = {};
  new Function('window', text)(window);
  return window.impulselabPresets;
}

// Runs the group named on the command line, one of @p groups (name: async (browser) => {}), and
// exits with 0 when every check passed.
export async function run(groups, program) {
  if (groups[group] && !existsSync(page)) {
    console.log(`${page} not found: the page is built with the docs (cmake --build --preset docs)`);
    process.exit(1);
  }
  await runGroup(groups, group,
                 `node ${program} GROUP --site DIR --cli PROGRAM --source DIR --screenshots DIR`,
                 () => rmSync(scratch, {recursive: true, force: true}));
}
