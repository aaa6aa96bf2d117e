// SPDX-License-Identifier: GPL-3.0-or-later
// The page as a lab bench, in headless Chromium (label web), against the command line built
// beside it:
//
//   motion    every preset played to the end of its window and back to its start: no body goes
//             behind a static surface or into another body further than at the instant (2% of a
//             typical size); every contact's marker still shown sits on the two bodies it joins;
//             the rod of lab 3 stops on the ground ("a later collision"); serial collisions of the
//             3-ball cradle stepped one at a time, each state worked by hand
//   editor    a scene built on the canvas with the mouse (a new scene; a disc, a box and a rod
//             from the palette, dragged onto the floor and onto each other; a velocity and a
//             normal dragged; a body selected and deleted; undo; reset): each contact where the
//             bodies touch, and each result the command line's for the scene the address then
//             holds; the built scene's address opened afresh draws the same shapes; screenshots
//   compare   the three methods and the three laws side by side: the command line's
//             `solve --compare --format json` and `--compare restitution`, and their warnings;
//             the sweep: the rows of `impulselab sweep`; screenshots at 1280 and 390 px
//   defects   what a reader found wrong: no "undefined" or "NaN" in any text; a refusal and a
//             warning beside the field they name, in words, the field marked, the last result
//             kept dimmed; 1e400 refused at its field; one focus ring at a time; labels that do
//             not cover each other at 390 px; handles taken 20 px away; a rod kept a rod when its
//             mass changes; the canvas and the summary in view while a field is edited on a
//             phone; the hint on rough contacts and the equations' list as they should read
//   slices    serial collisions too many for one frame (Galperin's billiard, 314,159 of them) run
//             a slice per frame: the page says how far they are while they run, then shows the
//             command line's answer; two keys in a row end with the last scene's answer; beyond
//             their bound, the command line's refusal
//
// usage: node bench_test.mjs GROUP --site DIR --cli PROGRAM --source DIR --screenshots DIR
import {mkdirSync, readFileSync} from 'node:fs';
import {writeFile} from 'node:fs/promises';
import {join} from 'node:path';
import {check, checkAgainstCommandLine, checkClean, commandLineOnText, differences, navigate, open, pageState,
        presetsOfSite, run, sceneOfHash, screenshots, shown, sizesOf, source} from './page_common.mjs';

const phone = {width: 390, height: 844, deviceScaleFactor: 2, mobile: true};
const hashOf = (scene) => '#scene=' + encodeURIComponent(typeof scene === 'string' ? scene : JSON.stringify(scene));
const sceneFile = (path) => readFileSync(join(source, path), 'utf8');

// --- Geometry of what is drawn (the test's own: the page's outlines, read as points) -----------

const dot = (a, b) => a[0] * b[0] + a[1] * b[1];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];

// How far an outline lies behind a surface's line (its points' furthest, for a circle the centre
// less the radius).
function behind(outline, s) {
  if (outline.circle) {
    return outline.circle[1] - dot(sub(outline.circle[0], s.surface[0]), s.outward);
  }
  return Math.max(...outline.polygon.map((p) => -dot(sub(p, s.surface[0]), s.outward)));
}

// How deep one outline runs into another: the deepest of points along each boundary (a
// polygon's corners and the middles of its sides, 32 points of a circle) inside the other.
function depthIn(p, o) {
  if (o.circle) {
    return Math.max(0, o.circle[1] - Math.hypot(p[0] - o.circle[0][0], p[1] - o.circle[0][1]));
  }
  const ps = o.polygon;
  const area = ps.reduce((sum, q, k) => sum + (q[0] * ps[(k + 1) % ps.length][1] - ps[(k + 1) % ps.length][0] * q[1]), 0);
  let depth = Infinity;
  for (let k = 0; k < ps.length; ++k) {
    const e = sub(ps[(k + 1) % ps.length], ps[k]);
    const length = Math.hypot(e[0], e[1]);
    if (length > 0) {
      // The distance inside this side (positive inside), for either winding.
      depth = Math.min(depth, Math.sign(area) * (e[0] * (p[1] - ps[k][1]) - e[1] * (p[0] - ps[k][0])) / length);
    }
  }
  return Math.max(0, depth);
}
function boundary(o) {
  if (o.circle) {
    return [...Array(32).keys()].map((k) => [o.circle[0][0] + o.circle[1] * Math.cos(k * Math.PI / 16),
                                            o.circle[0][1] + o.circle[1] * Math.sin(k * Math.PI / 16)]);
  }
  return o.polygon.flatMap((q, k) => [q, [(q[0] + o.polygon[(k + 1) % o.polygon.length][0]) / 2,
                                          (q[1] + o.polygon[(k + 1) % o.polygon.length][1]) / 2]]);
}
function overlap(a, b) {
  return Math.max(...boundary(a).map((q) => depthIn(q, b)), ...boundary(b).map((q) => depthIn(q, a)));
}

// Distance from a point to an outline's boundary (a surface: to its line).
function distance(p, o) {
  if (o.surface) {
    return Math.abs(dot(sub(p, o.surface[0]), o.outward));
  }
  if (o.circle) {
    return Math.abs(Math.hypot(p[0] - o.circle[0][0], p[1] - o.circle[0][1]) - o.circle[1]);
  }
  let best = Infinity;
  const ps = o.polygon;
  for (let k = 0; k < ps.length; ++k) {
    const a = ps[k];
    const e = sub(ps[(k + 1) % ps.length], a);
    const ee = dot(e, e);
    const s = ee > 0 ? Math.max(0, Math.min(1, dot(sub(p, a), e) / ee)) : 0;
    best = Math.min(best, Math.hypot(p[0] - a[0] - s * e[0], p[1] - a[1] - s * e[1]));
  }
  return best;
}

const drawn = (p) => p.evaluate('impulselabPage.drawn()');

async function pressOn(p, id, key) {
  await p.evaluate(`document.getElementById(${JSON.stringify(id)}).focus()`);
  await p.press(key);
}

// Waits for the page to show a change made by @p act.
async function change(p, act) {
  const before = await shown(p);
  await act();
  await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
  return pageState(p);
}


// --- The groups ------------------------------------------------------------------------------

const groups = {
  async motion(browser) {
    const presets = presetsOfSite();
    const p = await open(browser, hashOf(presets[0].scene));
    for (const [k, preset] of presets.entries()) {
      if (k > 0) {
        await navigate(p, hashOf(preset.scene));
      }
      const scene = preset.scene;
      await p.evaluate('document.getElementById("view").scrollIntoView()');
      await pressOn(p, 'time', 'Home');
      await pressOn(p, 'time', 'End');
      await pressOn(p, 'time', 'ArrowLeft');
      await pressOn(p, 'time', 'ArrowRight');
      await p.evaluate('document.getElementById("time").value = "0"; document.getElementById("time").dispatchEvent(new Event("input"))');
      const at0 = await drawn(p);
      const tolerance = 0.02 * at0.typical;
      const byName = (d) => new Map(d.outlines.filter((o) => !o.surface).map((o) => [o.body, o]));
      const surfaces = at0.outlines.filter((o) => o.surface);
      const start = byName(at0);
      for (const key of ['End', 'Home']) {
        await pressOn(p, 'time', key);
        const d = await drawn(p);
        const when = `${preset.id} at t = ${d.time.toPrecision(3)}`;
        const now = byName(d);
        for (const [name, o] of now) {
          for (const s of surfaces) {
            const deeper = behind(o, s) - Math.max(0, behind(start.get(name), s));
            check(deeper <= tolerance, `${when}: ${name} is not behind the surface of ${s.body}`,
                  `${deeper.toPrecision(3)} deeper than at the instant (tolerance ${tolerance.toPrecision(3)})`);
          }
          for (const [other, q] of now) {
            if (other > name) {
              const deeper = overlap(o, q) - overlap(start.get(name), start.get(other));
              check(deeper <= tolerance, `${when}: ${name} and ${other} do not run into each other`,
                    `${deeper.toPrecision(3)} deeper than at the instant`);
            }
          }
        }
        // A marker still shown sits on both bodies of its contact (on a static one: its line).
        for (const m of d.markers.filter((x) => x.alpha > 0.05)) {
          const c = scene.contacts[m.contact];
          for (const name of [c.bumper, c.wedge]) {
            const o = now.get(name) || d.outlines.find((x) => x.surface && x.body === name);
            if (!o) {
              continue;  // a static body the page draws no line for
            }
            const off = distance(m.at, o);
            check(off <= tolerance + 0.1 * d.typical * (1 - m.alpha), `${when}: the marker of contact ${m.contact} is on ${name}`,
                  `${off.toPrecision(3)} away (alpha ${m.alpha.toFixed(2)})`);
          }
        }
      }
    }

    // The rod of lab 3 lands on one end (m = 1, L = 2 at 30° from the ground, falling at 2): after
    // the impulse it turns and falls on, and its other end meets the ground, where the page stops
    // it and says so, instead of drawing it through the floor.
    await navigate(p, hashOf(sceneFile('tutorials/scenes/rod-hits-ground.json')));
    await pressOn(p, 'time', 'End');
    const end = await drawn(p);
    const rod = end.outlines.find((o) => o.body === 'rod');
    const lowest = Math.min(...rod.polygon.map((q) => q[1]));
    check(lowest >= -0.02 * end.typical, 'the rod of lab 3 stops on the ground (y = 0)', `its lowest point at ${lowest}`);
    check(end.events.length >= 1 && end.labels.some((l) => l.text === 'a later collision, not computed here'),
          'the rod of lab 3: the later collision is marked', JSON.stringify(end.events));

    // Serial collisions one at a time: three equal balls, the first at 1, elasticity 2. Collision
    // 1 (contact 0) passes ball 1's speed to ball 2 (Fdt = 1: A = 2, B = 2·1), collision 2
    // (contact 1) passes it on to ball 3; kinetic energy 1/2 throughout.
    const cradle = JSON.parse(sceneFile('tutorials/scenes/newton-cradle-3.json'));
    cradle.solver = {method: 'serial'};
    await navigate(p, hashOf(cradle));
    const stepped = [];
    for (let k = 0; k < 3; ++k) {
      await p.evaluate('document.getElementById("collision-forward").click()');
      stepped.push(await p.evaluate('[impulselabPage.serialStep(), document.getElementById("collision-text").textContent]'));
    }
    const velocities = stepped.map(([s]) => s && s.velocity.map((v) => v[0]));
    const near = (a, b) => a && a.length === b.length && a.every((x, i) => Math.abs(x - b[i]) < 1e-12);
    check(near(velocities[0], [0, 1, 0]) && near(velocities[1], [0, 0, 1]) && near(velocities[2], [0, 0, 1]),
          'the 3-ball cradle, serial: the balls after collisions 1 and 2 (no third)', JSON.stringify(velocities));
    check(stepped[1][1].startsWith('Collision 2 of 2: contact 1 (ball 2–ball 3), its impulse F dt 1 ') &&
          stepped[0][1].includes('kinetic energy after it 0.5'), 'the 3-ball cradle: each collision in words', stepped[1][1]);
    checkClean(p, 'motion');
  },

  async editor(browser) {
    mkdirSync(screenshots, {recursive: true});
    const p = await open(browser, '', {width: 1280, height: 900});
    const click = (id) => p.evaluate(`document.getElementById(${JSON.stringify(id)}).click()`);
    const scene = async () => JSON.parse(sceneOfHash((await pageState(p)).hash));
    const againstLine = async (where) => {
      const state = await pageState(p);
      checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), where);
      return state;
    };
    const outline = async (name) => (await drawn(p)).outlines.find((o) => o.body === name);
    const centre = (o) => (o.circle ? o.circle[0] : [o.polygon.reduce((s, q) => s + q[0], 0) / o.polygon.length,
                                                      o.polygon.reduce((s, q) => s + q[1], 0) / o.polygon.length]);
    const toWindow = (q) => p.evaluate(`impulselabPage.toWindow(${JSON.stringify(q)})`);
    // Drags body @p name so that its centre goes to @p target (in the scene's coordinates).
    const dragBody = async (name, target) => {
      const from = await toWindow(centre(await outline(name)));
      const to = await toWindow(target);
      await change(p, () => p.drag([from.x, from.y], [to.x, to.y], 12));
    };
    await p.evaluate('document.getElementById("view").scrollIntoView()');

    // A new scene: a floor and a disc of radius 0.5 on it.
    await change(p, () => click('new-scene'));
    await againstLine('editor, new scene');
    const built = await scene();
    check(built.bodies.length === 2 && built.contacts.length === 1, 'a new scene: a floor and a disc', JSON.stringify(built));

    // A disc from the palette (radius 0.5, I = m r²/2 = 0.125), dropped 0.03 above the floor at x = 2:
    // it snaps down onto the floor (within 12 px) and a contact is made under it, normal up.
    await change(p, () => click('add-disc'));
    let s = await scene();
    const disc = s.bodies[s.bodies.length - 1];
    check(disc.name === 'disc 2' && disc.kind === 'rigid' && disc.inertia === 0.125, 'the palette adds a disc', JSON.stringify(disc));
    await againstLine('editor, a disc added');
    await dragBody('disc 2', [2, 0.53]);
    s = await scene();
    const onFloor = s.contacts.filter((c) => c.wedge === 'disc 2');
    check(onFloor.length === 1 && onFloor[0].bumper === 'floor' && JSON.stringify(onFloor[0].normal) === '[0,1]' &&
          Math.abs(onFloor[0].point[0] - 2) < 0.01 && Math.abs(onFloor[0].point[1]) < 1e-9,
          'the disc dropped near the floor touches it at (2, 0), normal up', JSON.stringify(onFloor));
    check(Math.abs(s.bodies.find((b) => b.name === 'disc 2').position[1] - 0.5) < 1e-9, 'and rests on it: its centre at 0.5',
          JSON.stringify(s.bodies.find((b) => b.name === 'disc 2')));
    await againstLine('editor, the disc on the floor');

    // A box (half sides 0.5 and 0.35) dropped onto the floor at x = -2: two contacts, its corners.
    await change(p, () => click('add-box'));
    await dragBody('box 1', [-2, 0.37]);
    s = await scene();
    const corners = s.contacts.filter((c) => c.wedge === 'box 1').map((c) => c.point).sort((a, b) => a[0] - b[0]);
    check(corners.length === 2 && Math.abs(corners[0][0] + 2.5) < 0.01 && Math.abs(corners[1][0] + 1.5) < 0.01 &&
          corners.every((q) => Math.abs(q[1]) < 1e-9), 'the box on the floor touches it at its two corners', JSON.stringify(corners));
    await againstLine('editor, the box on the floor');

    // A rod (length 2) laid across the top of the box (its top at 0.7): contacts at the box's
    // top corners, the box the bumper (the rod was dropped onto it).
    await change(p, () => click('add-rod'));
    await dragBody('rod 1', [-2, 0.72]);
    s = await scene();
    const onBox = s.contacts.filter((c) => c.wedge === 'rod 1');
    check(onBox.length === 2 && onBox.every((c) => c.bumper === 'box 1' && JSON.stringify(c.normal) === '[0,1]' &&
                                                 Math.abs(c.point[1] - 0.7) < 1e-9),
          'the rod across the box touches its two top corners', JSON.stringify(onBox));
    await againstLine('editor, the rod on the box');

    // The disc's velocity dragged: its handle 60 px to the right.
    const handle = (await p.evaluate('impulselabPage.handles()')).find((h) => h.kind === 'velocity' &&
                                                                             h.body === s.bodies.findIndex((b) => b.name === 'disc 2'));
    await change(p, () => p.drag([handle.x, handle.y], [handle.x + 60, handle.y], 6));
    s = await scene();
    check(s.bodies.find((b) => b.name === 'disc 2').velocity[0] > 0, 'the disc\'s velocity dragged to the right',
          JSON.stringify(s.bodies.find((b) => b.name === 'disc 2')));
    await againstLine('editor, the disc\'s velocity');

    // The normal of the box's first contact with the floor turned: its tip dragged 20 px to the
    // left. (A disc's is left radial: a disc is told from a box by its normals through its centre.)
    const v = s.contacts.findIndex((c) => c.wedge === 'box 1');
    const tip = (await p.evaluate('impulselabPage.handles()')).find((h) => h.kind === 'normal' && h.contact === v);
    await change(p, () => p.drag([tip.x, tip.y], [tip.x - 20, tip.y], 4));
    s = await scene();
    check(s.contacts[v].normal === undefined && s.contacts[v].normal_angle > 90 && s.contacts[v].normal_angle < 150,
          'the normal turned to the left: its angle in degrees', JSON.stringify(s.contacts[v]));
    const withBox = await againstLine('editor, the normal turned');

    // From the keyboard: Enter on the canvas selects the bodies in turn; an arrow moves the disc
    // a tenth of the page's typical size along the floor, and its contact goes with it.
    const step = 0.1 * (await drawn(p)).typical;
    await p.evaluate('document.getElementById("view").focus()');
    for (let k = 0; k < 6 && await p.evaluate('document.getElementById("selection").textContent') !== 'Selected: disc 2.'; ++k) {
      await p.press('Enter');
    }
    await change(p, () => p.press('ArrowRight'));
    s = await scene();
    const moved = s.contacts.filter((c) => c.wedge === 'disc 2');
    check(Math.abs(s.bodies.find((b) => b.name === 'disc 2').position[0] - (2 + step)) < 1e-3 && moved.length === 1 &&
          Math.abs(moved[0].point[0] - (2 + step)) < 1e-3 && moved[0].point[1] === 0,
          'the disc moved from the keyboard, its contact with it', `${JSON.stringify(moved)}, a step of ${step}`);
    await againstLine('editor, the disc moved from the keyboard');
    await change(p, () => click('undo'));

    // The box selected by a click and deleted: it and its four contacts go.
    const boxAt = await toWindow(centre(await outline('box 1')));
    await p.mouse('mouseMoved', boxAt.x, boxAt.y);
    await p.mouse('mousePressed', boxAt.x, boxAt.y, 1);
    await p.mouse('mouseReleased', boxAt.x, boxAt.y, 0);
    check((await p.evaluate('document.getElementById("selection").textContent')) === 'Selected: box 1.', 'a click selects the box');
    await change(p, () => click('delete'));
    s = await scene();
    check(!s.bodies.some((b) => b.name === 'box 1') && !s.contacts.some((c) => c.bumper === 'box 1' || c.wedge === 'box 1'),
          'the box and its contacts deleted', JSON.stringify(s.contacts));
    await againstLine('editor, the box deleted');
    await change(p, () => click('undo'));
    check((await pageState(p)).hash === withBox.hash, 'undo brings the box back: the address as it was');
    await p.evaluate('document.getElementById("canvas-shot") || document.getElementById("view").scrollIntoView()');
    await p.screenshot(join(screenshots, 'editor-1280.png'), writeFile);

    // The built scene's address opened afresh: the same result, the disc a circle, the rod a rod.
    const fresh = await open(browser, withBox.hash, phone);
    const again = await pageState(fresh);
    check(again.result === withBox.result, 'the built scene opened afresh: the same result');
    const shapes = (await fresh.evaluate('impulselabPage.drawn()')).outlines;
    const rod = shapes.find((o) => o.body === 'rod 1');
    const side = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
    check(shapes.find((o) => o.body === 'disc 2').circle && rod.polygon &&
          side(rod.polygon[0], rod.polygon[1]) / side(rod.polygon[1], rod.polygon[2]) > 50,
          'and drawn with the same shapes: the disc a circle, the rod a line', JSON.stringify(rod));
    await fresh.evaluate('document.getElementById("view").scrollIntoView()');
    await fresh.screenshot(join(screenshots, 'editor-390.png'), writeFile);
    checkClean(fresh, 'editor, opened afresh');
    await fresh.close();
    await p.send('Page.bringToFront');

    await change(p, () => click('reset'));
    check(JSON.stringify(await scene()) === JSON.stringify(built), 'reset: the scene as it was given (the new scene)');
    checkClean(p, 'editor');
  },

  async compare(browser) {
    mkdirSync(screenshots, {recursive: true});
    const files = ['tutorials/scenes/box-lands-flat.json', 'tutorials/scenes/newton-cradle-5.json',
                   'tutorials/07-three-ways/two-balls-hit-one.json', 'tutorials/07-three-ways/rod-spins-off-ground.json',
                   'tutorials/09-rough-floor/rod-rough-floor.json', 'tutorials/scenes/tunnelling-1d.json'];
    const p = await open(browser, hashOf(sceneFile(files[0])));
    // The comparison chosen from the menu, once the page shows it for the scene shown.
    const choose = async (value) => {
      await p.evaluate(`(() => { const s = document.getElementById('compare');
          s.value = ${JSON.stringify(value)}; s.dispatchEvent(new Event('change')); })()`);
      await p.waitFor(`document.getElementById('compare-view').dataset.shows === '${value} ' + document.body.dataset.version`);
    };
    for (const [k, file] of files.entries()) {
      if (k > 0) {
        await navigate(p, hashOf(sceneFile(file)));
      }
      for (const [value, options] of [['methods', ['--compare', '--format', 'json']],
                                      ['restitution', ['--compare', 'restitution', '--format', 'json']]]) {
        await choose(value);
        const text = sceneFile(file);
        const line = commandLineOnText(text, options);
        const pageJson = await p.evaluate('document.getElementById("compare-json").textContent');
        const error = await p.evaluate('document.getElementById("compare-error").textContent');
        const where = `${file}, --compare ${value}`;
        if (line.stdout === '') {
          check(error === line.error && pageJson === '', `${where}: the command line's refusal`, `page: ${error}\nline: ${line.error}`);
          continue;
        }
        const mine = JSON.parse(pageJson);
        const theirs = JSON.parse(line.stdout);
        check(JSON.stringify(Object.keys(mine)) === JSON.stringify(Object.keys(theirs)), `${where}: the same columns`);
        for (const name of Object.keys(theirs)) {
          const found = differences(mine[name], theirs[name], sizesOf(mine[name], theirs[name], text));
          check(found.length === 0, `${where}: ${name} is the command line's`, found.slice(0, 5).join('\n'));
        }
        // The command line's warnings, then why a method did not finish (its exit status 1).
        const warnings = await p.evaluate('[...document.querySelectorAll("#compare-warnings li")].map((li) => li.textContent)');
        const expected = [...line.warnings, ...(line.error ? line.error.split('\n') : [])];
        check(JSON.stringify(warnings) === JSON.stringify(expected), `${where}: the command line's warnings`,
              `page: ${JSON.stringify(warnings)}\nline: ${JSON.stringify(expected)}`);
        const table = await p.evaluate('document.getElementById("compare-table") ? document.getElementById("compare-table").textContent : ""');
        check(table.includes('Kinetic energy after') && Object.keys(theirs).length === 3, `${where}: shown in three columns`);
      }
    }
    // Screenshots of the comparison of the methods, on the box landing flat.
    await navigate(p, hashOf(sceneFile(files[0])));
    await choose('methods');
    for (const [viewport, suffix] of [[{width: 1280, height: 800}, '1280'], [phone, '390']]) {
      await p.setViewport(viewport);
      await p.evaluate('document.getElementById("compare").scrollIntoView()');
      await new Promise((r) => setTimeout(r, 200));
      await p.screenshot(join(screenshots, `compare-${suffix}.png`), writeFile);
    }
    await p.setViewport({width: 1280, height: 800});
    await p.evaluate(`(() => { const s = document.getElementById('compare'); s.value = ''; s.dispatchEvent(new Event('change')); })()`);
    check(await p.evaluate('document.getElementById("compare-view").textContent === ""'), 'nothing side by side: the view empty');

    // The sweep: the rows of `impulselab sweep FILE --elasticity 0:3:0.05`, each number within
    // 1e-12 of the largest of its column.
    const swept = 'document.getElementById("sweep-chart").dataset.shows === document.body.dataset.version';
    await navigate(p, hashOf(sceneFile('tutorials/scenes/elastic-1d.json')));
    await p.evaluate('document.getElementById("sweep-box").open = true');
    await p.waitFor(swept);
    for (const file of files) {
      await navigate(p, hashOf(sceneFile(file)));
      await p.waitFor(swept);
      const csv = await p.evaluate('document.getElementById("sweep-csv").textContent');
      const error = await p.evaluate('document.getElementById("sweep-error").textContent');
      const line = commandLineOnText(sceneFile(file), ['--elasticity', '0:3:0.05'], 'sweep');
      if (line.status !== 0) {
        check(csv === '' && error !== '', `${file}, sweep: refused as the command line refuses it`, `page: ${error}\nline: ${line.error}`);
        continue;
      }
      const rows = (text) => text.trim().split('\n').map((r) => r.split(','));
      const mine = rows(csv);
      const theirs = rows(line.stdout);
      check(mine[0].join(',') === theirs[0].join(','), `${file}, sweep: the same columns`, `${mine[0]}\n${theirs[0]}`);
      check(mine.length === theirs.length, `${file}, sweep: the same rows`, `${mine.length} against ${theirs.length}`);
      const scale = theirs[0].map((h, c) => Math.max(...theirs.slice(1).map((r) => Math.abs(Number(r[c])))));
      const off = [];
      theirs.slice(1).forEach((r, k) => r.forEach((x, c) => {
        if (!(Math.abs(Number(mine[k + 1] && mine[k + 1][c]) - Number(x)) <= 1e-12 * scale[c])) {
          off.push(`row ${k + 1}, ${theirs[0][c]}: ${mine[k + 1] && mine[k + 1][c]} against ${x}`);
        }
      }));
      check(off.length === 0, `${file}, sweep: the command line's numbers`, off.slice(0, 5).join('\n'));
    }
    await navigate(p, hashOf(sceneFile(files[0])));
    await p.waitFor(swept);
    for (const [viewport, suffix] of [[{width: 1280, height: 800}, '1280'], [phone, '390']]) {
      await p.setViewport(viewport);
      await p.evaluate('document.getElementById("sweep-box").scrollIntoView()');
      await new Promise((r) => setTimeout(r, 200));
      await p.screenshot(join(screenshots, `sweep-${suffix}.png`), writeFile);
    }
    checkClean(p, 'compare');
  },

  async slices(browser) {
    // A light ball between a wall and a heavy one closing on it: serial collisions go back and
    // forth, π's first digits of them (Galperin): 314,159 for a mass ratio of 10^10, which the
    // page cannot run in one frame; a bound of 400,000 lets them end.
    const billiard = (ratio, bound) => ({
      dimension: 1, elasticity: 2,
      bodies: [{name: 'wall', kind: 'static'}, {name: 'light', kind: 'material', mass: 1, velocity: 0},
               {name: 'heavy', kind: 'material', mass: ratio, velocity: -1}],
      contacts: [{bumper: 'wall', wedge: 'light', normal: 1}, {bumper: 'light', wedge: 'heavy', normal: 1}],
      solver: {method: 'serial', ...(bound ? {max_collisions: bound} : {})},
    });
    const line = (state) => commandLineOnText(sceneOfHash(state.hash));
    const p = await open(browser, hashOf(billiard(1e10, 400000)));
    const opened = await pageState(p);
    checkAgainstCommandLine(opened, line(opened), 'the billiard opened: the command line\'s answer');
    check(JSON.parse(opened.result || '{}').impulses !== undefined, 'the billiard ends within its bound');

    // What the page says while they run: every text of the refusal's place while it is pending.
    await p.evaluate(`window.slicesSeen = [];
      new MutationObserver(() => {
        if (document.getElementById('refusal').classList.contains('pending')) {
          window.slicesSeen.push(document.getElementById('refusal-words').textContent);
        }
      }).observe(document.getElementById('refusal-words'), {childList: true, subtree: true, characterData: true})`);
    // The light ball's mass a step down (10^-0.01): a ratio a little above 10^10, as many collisions.
    const after = await change(p, () => pressOn(p, 'body-1-mass-slider', 'ArrowLeft'));
    const seen = await p.evaluate('window.slicesSeen');
    const words = /^Serial collisions: [0-9,]+ so far, of at most 400,000; the result follows when they end \(the last scene solved stays, dimmed\)\.$/;
    check(seen.length >= 1 && seen.every((text) => words.test(text)), 'while they run, the page says how far they are',
          JSON.stringify(seen.slice(0, 3)));
    const counts = seen.map((text) => Number(text.match(/[0-9,]+/)[0].replace(/,/g, '')));
    check(counts.every((n, k) => k === 0 || n > counts[k - 1]), 'and how far grows from frame to frame', counts.join(', '));
    checkAgainstCommandLine(after, line(after), 'after a key: the command line\'s answer for the new scene');
    check(await p.evaluate('!document.getElementById("refusal").classList.contains("pending") && ' +
                           '!document.body.classList.contains("refused")'), 'then nothing is dimmed');
    const timing = await p.evaluate('window.impulselabTiming');
    check(timing && timing.first_ms < timing.update_ms, 'the first frame drawn before the result', JSON.stringify(timing));

    // Two keys before the first scene's collisions end: the answer is the second scene's.
    await p.evaluate('document.getElementById("body-1-mass-slider").focus()');
    await p.press('ArrowLeft');
    await p.press('ArrowLeft');
    await p.waitFor('!document.getElementById("refusal").classList.contains("pending")');
    await new Promise((r) => setTimeout(r, 200));
    const twice = await pageState(p);
    checkAgainstCommandLine(twice, line(twice), 'two keys in a row: the answer for the scene the address holds');

    // Beyond their bound (the default, 100 per contact and at least 10,000; a ratio of 10^8 needs
    // 31,415): refused in the command line's words.
    await navigate(p, hashOf(billiard(1e8)));
    const bounded = await pageState(p);
    checkAgainstCommandLine(bounded, line(bounded), 'beyond the bound: the command line\'s refusal');
    checkClean(p, 'slices');
  },

  async defects(browser) {
    const presets = presetsOfSite();
    const p = await open(browser, hashOf(presets[0].scene), {width: 1280, height: 800});
    // Every text of the page (also what is folded away or out of view), its labels, the canvas's.
    const texts = () => p.evaluate(`[document.body.textContent,
        ...[...document.querySelectorAll('[aria-label], [title]')].map((e) => e.getAttribute('aria-label') + ' ' + (e.getAttribute('title') || '')),
        ...(window.impulselabPage.drawn ? impulselabPage.drawn().labels.map((l) => l.text) : [])].join('\\n')`);

    // No "undefined", no "NaN": every preset, by each method and each law (the single rough contact
    // of lab 9 by serial collisions once said "undefined collisions in undefined passes").
    for (const preset of presets) {
      for (const method of ['simultaneous', 'complementarity', 'serial']) {
        for (const law of preset.id === 'rod-rough-floor' || preset.id === 'box-lands-flat' ? ['newton', 'poisson'] : ['newton']) {
          const scene = {...preset.scene, solver: {...(preset.scene.solver || {}), method, ...(law === 'newton' ? {} : {restitution: law})}};
          await navigate(p, hashOf(scene));
          const found = (await texts()).split('\n').filter((l) => /\bundefined\b|\bNaN\b/.test(l));
          check(found.length === 0, `${preset.id}, ${method}, ${law}: no "undefined" or "NaN" in any text`, found.slice(0, 3).join('\n'));
        }
      }
    }

    // A refusal beside its field: the mass of the cradle's first ball typed as -1.
    const cradle = sceneFile('tutorials/scenes/newton-cradle-3.json');
    await navigate(p, hashOf(cradle));
    const good = await pageState(p);
    // A number typed into a field, as a reader types it; then the page shown and its address written.
    const type = async (id, text) => {
      const hash = await p.evaluate('location.hash');
      await change(p, async () => {
        await p.evaluate(`(() => { const e = document.getElementById(${JSON.stringify(id)}); e.focus(); e.select(); })()`);
        await p.send('Input.insertText', {text});
      });
      await p.waitFor(`location.hash !== ${JSON.stringify(hash)}`);
      return pageState(p);
    };
    const beside = (id) => p.evaluate(`(() => {
      const input = document.getElementById(${JSON.stringify(id)});
      const message = document.getElementById(input.getAttribute('aria-describedby') || '');
      if (!message || !message.checkVisibility()) {
        return {invalid: input.getAttribute('aria-invalid'), text: '', gap: Infinity};
      }
      const a = input.getBoundingClientRect();
      const b = message.getBoundingClientRect();
      return {invalid: input.getAttribute('aria-invalid'), text: message.textContent, warning: message.classList.contains('warning'),
              gap: Math.max(0, b.top - a.bottom, a.top - b.bottom), across: Math.min(a.right, b.right) - Math.max(a.left, b.left)};
    })()`);
    let state = await type('body-0-mass', '-1');
    let at = await beside('body-0-mass');
    check(at.invalid === 'true' && at.gap <= 24 && at.across > 0, 'mass -1: the message beside the field, the field marked invalid',
          JSON.stringify(at));
    check(at.text === 'ball 1, mass: must be positive and finite, got -1', 'mass -1: in words (the body\'s name, not bodies[0])', at.text);
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'mass -1');
    check(await p.evaluate('document.body.classList.contains("refused") && getComputedStyle(document.getElementById("energy-chart")).opacity < 1 && ' +
                           'document.getElementById("bodies-table").textContent.includes("ball 1")'),
          'mass -1: the last result kept, dimmed');
    state = await type('body-0-mass', '1');
    at = await beside('body-0-mass');
    check(at.invalid !== 'true' && at.text === '' && state.result === good.result, 'mass 1 again: the message gone, the result back');

    // The library's warnings beside their fields: elasticity 0.5 (a coefficient of restitution
    // typed for the elasticity), and 5.
    state = await type('default-elasticity-number', '0.5');
    at = await beside('default-elasticity-number');
    check(at.warning && at.gap <= 24 && at.text.startsWith('elasticity of every body without its own: 0.5 is below 1'),
          'elasticity 0.5: the library\'s warning beside the field', JSON.stringify(at));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'elasticity 0.5');
    state = await type('body-0-elasticity', '5');
    at = await beside('body-0-elasticity');
    check(at.warning && at.text.startsWith('ball 1, elasticity: 5 is above 2'), 'elasticity 5: the warning beside ball 1\'s field', JSON.stringify(at));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'elasticity 5');

    // 1e400 is no double: refused at the field, the address and the result as they were, dimmed.
    await navigate(p, hashOf(cradle));
    const before = await pageState(p);
    await p.evaluate('(() => { const e = document.getElementById("body-1-mass"); e.focus(); e.select(); })()');
    await p.send('Input.insertText', {text: '1e400'});
    at = await beside('body-1-mass');
    check(at.invalid === 'true' && at.gap <= 24 && at.text.startsWith('ball 2, mass: not a number'), '1e400: refused at the field',
          JSON.stringify(at));
    check((await pageState(p)).hash === before.hash && await p.evaluate('document.body.classList.contains("field-refused")'),
          '1e400: the scene kept, the results dimmed');
    await type('body-1-mass', '1');
    check(!(await p.evaluate('document.body.classList.contains("field-refused")')), 'a number again: nothing dimmed');

    // One focus ring at a time: Tab through the page, each focused place drawn once.
    await p.evaluate('document.activeElement && document.activeElement.blur(); window.scrollTo(0, 0)');
    const rings = [];
    for (let k = 0; k < 40; ++k) {
      await p.press('Tab');
      rings.push(await p.evaluate(`[document.activeElement === document.body ? 'BODY'
          : document.activeElement.id || document.activeElement.textContent.trim().slice(0, 20),
        [...document.querySelectorAll('body *')].filter((e) => { const s = getComputedStyle(e);
          return s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0 && e.checkVisibility({opacityProperty: true}); }).length]`));
    }
    const doubled = rings.filter(([id, n]) => id !== 'BODY' && n !== 1);
    check(rings.some(([id]) => id === 'open-file') && rings.some(([id]) => id === 'view'),
          'Tab reaches the file field and the canvas', JSON.stringify(rings.map(([id]) => id)));
    check(doubled.length === 0, 'Tab: one focus ring at a time', JSON.stringify(doubled));

    // Labels that cover no other label, every preset at 390 px (a phone) and 1280 px.
    for (const viewport of [phone, {width: 1280, height: 800}]) {
      await p.setViewport(viewport);
      for (const preset of presets) {
        await navigate(p, hashOf(preset.scene));
        await p.evaluate('document.getElementById("view").scrollIntoView()');
        const labels = (await drawn(p)).labels;
        const covered = [];
        labels.forEach((a, i) => labels.slice(i + 1).forEach((b) => {
          if (a.box[0] < b.box[2] && b.box[0] < a.box[2] && a.box[1] < b.box[3] && b.box[1] < a.box[3]) {
            covered.push(`"${a.text}" and "${b.text}"`);
          }
        }));
        check(covered.length === 0, `${preset.id} at ${viewport.width} px: no label over another`, covered.join(', '));
      }
    }

    // Touch targets of 44 px: a velocity handle taken 20 px from its centre, on a phone.
    await p.setViewport(phone);
    await navigate(p, hashOf(cradle));
    await p.evaluate('document.getElementById("view").scrollIntoView()');
    const handle = (await p.evaluate('impulselabPage.handles()')).find((h) => h.kind === 'velocity' && h.body === 0);
    const was = await shown(p);
    await p.drag([handle.x + 14, handle.y + 14], [handle.x - 26, handle.y + 14], 6);
    await new Promise((r) => setTimeout(r, 300));
    check(await shown(p) > was, 'a handle taken 20 px from its centre');
    const small = await p.evaluate(`[...document.querySelectorAll('button, select, input[type=number]')]
        .filter((e) => e.checkVisibility() && e.getBoundingClientRect().height < 44).map((e) => e.id)`);
    check(small.length === 0, 'buttons, menus and number fields 44 px tall on a phone', small.join(', '));

    // On a phone, a field being edited leaves the canvas and the summary in view.
    await navigate(p, hashOf(sceneFile('tutorials/scenes/newton-cradle-5.json')));
    await p.evaluate('document.getElementById("body-2-mass").focus()');
    await new Promise((r) => setTimeout(r, 300));
    const inView = await p.evaluate(`['view', 'summary', 'body-2-mass'].map((id) => {
      const r = document.getElementById(id).getBoundingClientRect();
      return [id, r.top >= -1 && r.bottom <= innerHeight + 1];
    })`);
    check(inView.every(([, visible]) => visible), 'a phone: the canvas, the summary and the field edited in view', JSON.stringify(inView));
    await p.setViewport({width: 1280, height: 800});

    // A rod stays a rod when its mass changes (it once turned into a large square).
    await navigate(p, hashOf(sceneFile('tutorials/scenes/rod-hits-ground.json')));
    await change(p, () => pressOn(p, 'body-1-mass-slider', 'End'));
    const rod = (await drawn(p)).outlines.find((o) => o.body === 'rod');
    const side = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
    check(rod.polygon && side(rod.polygon[0], rod.polygon[1]) / side(rod.polygon[1], rod.polygon[2]) > 10,
          'the rod\'s mass at its largest: still drawn as a rod', JSON.stringify(rod));

    // The words: the rough contacts' hint, the equations' list.
    const page = await p.evaluate('document.body.textContent.replace(/\\s+/g, " ")');
    check(!page.includes('((1.3)'), 'the list of equations reads without "((1.3)"');
    check(!/several contacts only by serial collisions/.test(page) && page.includes('complementarity takes friction with Newton\'s law'),
          'the hint on rough contacts: complementarity solves them with Newton\'s law');
    checkClean(p, 'defects');
  },
};

await run(groups, 'bench_test.mjs');
