// SPDX-License-Identifier: GPL-3.0-or-later
// The page's speed in headless Chromium (a measurement, not a test: timings are not asserted).
//
//   ready       from the start of loading collide.html from disk to the result shown
//               (data-ready), fresh page each time, the default example and a 100-contact scene
//   control     a key pressed on a mass slider to the result redrawn: from the key event to the
//               result drawn on the screen (solve, canvas, summary, the panels in view), to
//               everything drawn (the panels out of view too, just after) and to the frame that
//               shows it painted (style, layout and paint done); serial collisions that run over
//               several frames (a slice each): also the key to the first frame drawn and the
//               longest piece of work between the key and the result,
//               for scenes of 1 to 100 contacts and each method
//   animation   the 5-ball cradle playing: frames per second and the cost of drawing one frame
//
// With --versus DIR (another build of the page, e.g. main's), the control figures are measured on
// both pages in turn, key by key, so that both see the same load of the machine, and their ratio
// is printed.
//
// usage: node measure.mjs --site DIR [--repeat N] [--versus DIR] [--only control] [--scenes REGEX]
import {resolve, join} from 'node:path';
import {Browser} from './chromium.mjs';

const args = process.argv.slice(2);
const site = resolve(args[args.indexOf('--site') + 1]);
const repeat = args.includes('--repeat') ? Number(args[args.indexOf('--repeat') + 1]) : 20;
const url = `file://${join(site, 'collide.html')}`;
const versus = args.includes('--versus') ? `file://${join(resolve(args[args.indexOf('--versus') + 1]), 'collide.html')}` : null;
const only = args.includes('--only') ? args[args.indexOf('--only') + 1] : null;
const matching = args.includes('--scenes') ? new RegExp(args[args.indexOf('--scenes') + 1]) : /./;

const stats = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  const at = (q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  return {min: sorted[0], median: at(0.5), p90: at(0.9), max: sorted[sorted.length - 1], n: values.length};
};
const show = (what, s, unit = 'ms') =>
  console.log(`${what.padEnd(58)} median ${s.median.toFixed(2)} ${unit}, 90% ${s.p90.toFixed(2)}, ` +
              `min ${s.min.toFixed(2)}, max ${s.max.toFixed(2)} (${s.n} runs)`);

// Scenes built here for their size (they are not physics: bodies and contacts as a lab writes them).
function cradle(balls, method) {
  const bodies = [];
  const contacts = [];
  for (let k = 0; k < balls; ++k) {
    bodies.push({name: `ball ${k + 1}`, kind: 'material', mass: 1, velocity: k === 0 ? 1 : 0});
    if (k > 0) {
      contacts.push({bumper: `ball ${k}`, wedge: `ball ${k + 1}`, normal: 1});
    }
  }
  return {dimension: 1, elasticity: 2, bodies, contacts, ...(method ? {solver: {method}} : {})};
}

// `rough`: the boxes also slide sideways at 1, with friction mu = 0.5 at every contact and the
// restitution law `rough` names (newton, poisson, energetic): the page's 100-contact friction scene.
function stack(boxes, method, rough) {
  const bodies = [{name: 'ground', kind: 'static'}];
  const contacts = [];
  for (let k = 0; k < boxes; ++k) {
    bodies.push({name: `box ${k + 1}`, kind: 'rigid', mass: 1, inertia: 5 / 12, position: [0, k + 0.5],
                 velocity: [rough ? 1 : 0, -1]});
    const below = k === 0 ? 'ground' : `box ${k}`;
    for (const x of [-1, 1]) {
      contacts.push({bumper: below, wedge: `box ${k + 1}`, normal: [0, 1], point: [x, k]});
    }
  }
  const solver = {...(method ? {method} : {}), ...(rough && rough !== 'newton' ? {restitution: rough} : {})};
  return {dimension: 2, elasticity: 1.5, ...(rough ? {friction: 0.5} : {}), bodies, contacts,
          ...(Object.keys(solver).length ? {solver} : {})};
}

const browser = await Browser.launch();
try {
  // Page ready from disk.
  for (const [what, hash] of only === 'control' ? [] :  [['ready: the default example', ''],
                              ['ready: 100 boxes stacked (200 contacts)', '#scene=' + encodeURIComponent(JSON.stringify(stack(100)))]]) {
    const times = [];
    for (let k = 0; k < Math.min(repeat, 10); ++k) {
      const page = await browser.newPage({width: 1280, height: 800});
      await page.goto(url + hash);
      await page.waitFor('window.impulselabReadyMs !== undefined');
      times.push(await page.evaluate('window.impulselabReadyMs'));
      await page.close();
    }
    show(what, stats(times));
  }

  // A control changed to the result redrawn (on both pages in turn with --versus).
  const page = await browser.newPage({width: 1280, height: 800});
  await page.goto(url);
  await page.waitFor('document.body.dataset.ready === "true"');
  const other = versus ? await browser.newPage({width: 1280, height: 800}) : null;
  if (other) {
    await other.goto(versus);
    await other.waitFor('document.body.dataset.ready === "true"');
  }
  const scenes = [
    ['cradle of 2 balls (1 contact)', cradle(2)],
    ['cradle of 5 balls (4 contacts)', cradle(5)],
    ['cradle of 101 balls (100 contacts)', cradle(101)],
    ['cradle of 101 balls (100 contacts), complementarity', cradle(101, 'complementarity')],
    ['cradle of 101 balls (100 contacts), serial', cradle(101, 'serial')],
    ['50 boxes stacked (100 contacts)', stack(50)],
    ['50 boxes stacked (100 contacts), complementarity', stack(50, 'complementarity')],
    ['50 boxes stacked (100 contacts), serial', stack(50, 'serial')],
    // With friction: the paper's method refuses it (its refusal is timed too), complementarity
    // takes Newton's law only, serial collisions every law.
    ['50 boxes sliding, friction 0.5 (100 contacts), the paper\'s method', stack(50, '', 'newton')],
    ['50 boxes sliding, friction 0.5 (100 contacts), complementarity', stack(50, 'complementarity', 'newton')],
    ['50 boxes sliding, friction 0.5 (100 contacts), serial, Newton', stack(50, 'serial', 'newton')],
    ['50 boxes sliding, friction 0.5 (100 contacts), serial, Poisson', stack(50, 'serial', 'poisson')],
    ['50 boxes sliding, friction 0.5 (100 contacts), serial, energetic', stack(50, 'serial', 'energetic')],
  ];
  // Opens @p scene on @p p and presses a key on its first mass slider @p repeat times (with
  // @p next, the same on another page in between): the times of each press.
  const open = async (p, address, scene) => {
    const before = Number(await p.evaluate('document.body.dataset.shown'));
    await p.send('Page.navigate', {url: address + '#scene=' + encodeURIComponent(JSON.stringify(scene))});
    await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
    const slider = scene.bodies[0].kind === 'static' ? 'body-1-mass-slider' : 'body-0-mass-slider';
    await p.evaluate(`document.getElementById('${slider}').focus()`);
  };
  const press = async (p, k) => {
    await p.send('Page.bringToFront');
    const shown = Number(await p.evaluate('document.body.dataset.shown'));
    await p.evaluate('window.impulselabTiming = undefined');
    await p.press(k % 2 === 0 ? 'ArrowRight' : 'ArrowLeft');
    await p.waitFor(`Number(document.body.dataset.shown) > ${shown} && window.impulselabTiming`);
    return p.evaluate('window.impulselabTiming');
  };
  for (const [what, scene] of scenes.filter(([name]) => matching.test(name))) {
    await open(page, url, scene);
    if (other) {
      await open(other, versus, scene);
    }
    const update = [];
    const all = [];
    const frame = [];
    const solve = [];
    const first = [];
    const longest = [];
    const versusUpdate = [];
    const phases = new Map();
    for (let k = 0; k < repeat; ++k) {
      const t = await press(page, k);
      update.push(t.update_ms);
      all.push(t.all_ms === undefined ? t.update_ms : t.all_ms);
      frame.push(t.frame_ms);
      solve.push(t.solve_ms);
      first.push(t.first_ms === undefined ? t.update_ms : t.first_ms);
      longest.push(t.longest_ms === undefined ? t.update_ms : t.longest_ms);
      for (const [name, ms] of Object.entries(t.phases || {})) {
        phases.set(name, [...(phases.get(name) || []), ms]);
      }
      if (other) {
        versusUpdate.push((await press(other, k)).update_ms);
      }
    }
    show(`control: ${what}: key to result drawn`, stats(update));
    show(`control: ${what}: key to everything drawn`, stats(all));
    show(`control: ${what}: key to the frame painted`, stats(frame));
    show(`control: ${what}: of which the library`, stats(solve));
    // Serial collisions run a slice per frame: the first frame shows how far they are, and no
    // piece of the page's work between the key and the result is longer than this.
    show(`control: ${what}: key to the first frame drawn`, stats(first));
    show(`control: ${what}: the longest piece of work (one frame's)`, stats(longest));
    console.log(`  medians by part (ms): ${[...phases].map(([name, v]) => `${name} ${stats(v).median.toFixed(1)}`).join(', ')}`);
    if (other) {
      show(`control: ${what}: key to result drawn, the other page`, stats(versusUpdate));
      const ratios = update.map((x, k) => x / versusUpdate[k]);
      console.log(`  this page / the other, key by key: median ${stats(ratios).median.toFixed(2)} ` +
                  `(from ${Math.min(...ratios).toFixed(2)} to ${Math.max(...ratios).toFixed(2)})`);
    }
  }
  const problems = page.problems();
  if (problems.length) {
    console.log('console errors:', problems);
  }

  if (only !== 'control') {
    // The 5-ball cradle animating.
    const before = Number(await page.evaluate('document.body.dataset.shown'));
    await page.send('Page.navigate', {url: url + '#scene=' + encodeURIComponent(JSON.stringify(cradle(5)))});
    await page.waitFor(`Number(document.body.dataset.shown) > ${before}`);
    await page.evaluate('document.getElementById("view").scrollIntoView()');
    const result = await page.evaluate(`new Promise((done) => {
      document.getElementById('play').click();
      const stamps = [];
      const costs = [];
      const tick = (now) => {
        stamps.push(now);
        costs.push(window.impulselabFrameMs || 0);
        if (now - stamps[0] < 3000) {
          requestAnimationFrame(tick);
        } else {
          document.getElementById('play').click();
          done({stamps, costs});
        }
      };
      requestAnimationFrame(tick);
    })`);
    const seconds = (result.stamps[result.stamps.length - 1] - result.stamps[0]) / 1000;
    const intervals = result.stamps.slice(1).map((t, k) => t - result.stamps[k]);
    console.log(`animation: the 5-ball cradle: ${((result.stamps.length - 1) / seconds).toFixed(1)} frames per second over ${seconds.toFixed(1)} s`);
    show('animation: interval between frames', stats(intervals));
    show('animation: drawing one frame', stats(result.costs.slice(2)));
    await page.close();
  }
} finally {
  await browser.close();
}
