// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive page in headless Chromium (label web), against the command line built beside it:
//
//   presets     every preset, chosen from the menu: its result-json is what `impulselab solve
//               --format json` prints for its scene file, the address holds that scene, and a
//               screenshot of it at 1280×800 and at 360 px wide goes into the screenshots folder
//   scenes      every example scene and every scene of the tests, given in the address: the same
//               result as the command line (or its refusal), and the same warnings
//   malformed   every malformed scene of the command line's tests, given in the address: the
//               command line's message (without its file name) in scene-error, result-json empty
//   interaction a control changed from the keyboard, a velocity handle dragged with the mouse, the
//               method changed: result and address change, and the result is the command line's
//               for the scene the address then holds; that address opened afresh shows the same;
//               a scene file opened, the scene downloaded; every control labelled and reached by
//               Tab; nothing wider than the window at 360 px; the animation plays; the system
//               typeset
//   links       every "try it" link of the site opens its scene without an error
//   friction    the friction μ and the restitution law set through their controls on the rod of
//               lab 9: the result is the command line's for the scene the address then holds, the
//               hand-worked impulses of the docs page, the energy-gained warning for Newton's law
//               only; μ = 0 and Newton's law write no key (the address returns byte for byte);
//               the address round-trips the keys; the whole impulse drawn; the methods that refuse
//               several contacts with friction show the command line's message
//
// On every page: no console error, no exception, no request outside the site (file:, data:,
// blob: only).
//
// usage: node page_test.mjs GROUP --site DIR --cli PROGRAM --source DIR --screenshots DIR
import {mkdirSync, readdirSync, readFileSync, existsSync} from 'node:fs';
import {writeFile} from 'node:fs/promises';
import {basename, join} from 'node:path';
import {checkAgainstCommandLine, check, checkClean, checkSharedLink, commandLine, commandLineOnText, encodeBytes,
        jsonFiles, navigate, open, pageState, presetsOfSite, run, sceneOfHash, scratch, screenshots, shown, site,
        source} from './page_common.mjs';

// --- The groups ------------------------------------------------------------------------------

const groups = {
  async presets(browser) {
    mkdirSync(screenshots, {recursive: true});
    const presets = presetsOfSite();
    check(presets.length >= 18, 'the page has the presets of the tutorials and labs', presets.length);
    // One page, in front (a page in the background gets no frames): every preset at 1280×800, then
    // every preset at the width of a phone.
    const p = await open(browser, '', {width: 1280, height: 800});
    const sizes = [[{width: 1280, height: 800}, ''],
                   [{width: 360, height: 740, deviceScaleFactor: 2, mobile: true}, '-360']];
    for (const [viewport, suffix] of sizes) {
      await p.setViewport(viewport);
      for (const preset of presets) {
        const before = await shown(p);
        await p.evaluate(`(() => { const s = document.getElementById('preset');
                                    s.value = ${JSON.stringify(preset.id)};
                                    s.dispatchEvent(new Event('change')); })()`);
        await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
        const state = await pageState(p);
        if (suffix === '') {
          checkAgainstCommandLine(state, commandLine(join(source, preset.file)), `preset ${preset.id}`);
          check(JSON.stringify(JSON.parse(sceneOfHash(state.hash))) === JSON.stringify(preset.scene),
                `preset ${preset.id}: the address holds its scene`);
        }
        // MathJax typesets in its own time: the shot waits for it (up to 8 contacts; a table beyond).
        await p.waitFor(`document.querySelector('#system-equation svg') || document.querySelector('#system-equation table')`);
        const width = await p.evaluate('document.documentElement.scrollWidth');
        check(width <= viewport.width, `preset ${preset.id}${suffix}: nothing wider than the window`, width);
        await p.screenshot(join(screenshots, `${preset.id}${suffix}.png`), writeFile);
      }
      await p.fullScreenshot(join(screenshots, `page-full${suffix || '-1280'}.png`), writeFile, viewport);
    }
    checkClean(p, 'presets');
  },

  async scenes(browser) {
    const files = [
      ...jsonFiles('tutorials/scenes'),
      ...readdirSync(join(source, 'tutorials')).filter((d) => /^[0-9][0-9]-/.test(d))
          .flatMap((d) => jsonFiles(join('tutorials', d))),
      ...jsonFiles('tests/cli/scenes'),
      ...jsonFiles('fuzz/regressions'),
    ];
    check(files.length >= 20, 'the example and test scenes are found', files.length);
    const p = await open(browser, '#scene=' + encodeBytes(readFileSync(files[0])));
    for (const [k, file] of files.entries()) {
      if (k > 0) {
        await navigate(p, '#scene=' + encodeBytes(readFileSync(file)));
      }
      checkAgainstCommandLine(await pageState(p), commandLine(file), file.slice(source.length + 1));
    }
    checkClean(p, 'scenes');
  },

  async malformed(browser) {
    const files = jsonFiles('tests/cli/malformed');
    check(files.length >= 40, 'the malformed scenes are found', files.length);
    const p = await open(browser, '#scene=' + encodeBytes(readFileSync(files[0])));
    for (const [k, file] of files.entries()) {
      if (k > 0) {
        await navigate(p, '#scene=' + encodeBytes(readFileSync(file)));
      }
      const line = commandLine(file);
      check(line.status === 2, `${basename(file)}: the command line refuses it`, line.status);
      checkAgainstCommandLine(await pageState(p), line, `malformed ${basename(file)}`);
    }
    checkClean(p, 'malformed');
  },

  async interaction(browser) {
    const cradle = JSON.parse(readFileSync(join(source, 'tutorials/scenes/newton-cradle-3.json'), 'utf8'));
    const p = await open(browser, '#scene=' + encodeURIComponent(JSON.stringify(cradle)));
    const first = await pageState(p);
    checkAgainstCommandLine(first, commandLineOnText(JSON.stringify(cradle)), 'cradle');
    check(await p.evaluate('document.getElementById("preset").value') === 'newton-cradle-3',
          'a scene given in the address that is a preset shows as that preset');

    // The mass of ball 1 one step up from the keyboard: 10^0.01 = 1.023, written as 1.02.
    await p.evaluate('document.getElementById("body-0-mass-slider").focus()');
    let before = await shown(p);
    await p.press('ArrowRight');
    await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
    await p.waitFor(`location.hash !== ${JSON.stringify(first.hash)}`);
    let state = await pageState(p);
    let scene = JSON.parse(sceneOfHash(state.hash));
    check(scene.bodies[0].mass === 1.02, 'a key on the mass slider changes the mass in the address', scene.bodies[0].mass);
    check(state.result !== first.result, 'and the result changes');
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'cradle, heavier ball 1');
    check(await p.evaluate('document.getElementById("body-0-mass").value') === '1.02', 'the number field follows the slider');

    // The shared link, opened afresh, shows the same.
    await checkSharedLink(browser, p, state, {'body-0-mass': '1.02', 'preset': ''}, 'shared link');

    // The velocity of ball 1 dragged on the canvas: its handle, 40 px to the left.
    await p.evaluate('document.getElementById("view").scrollIntoView()');
    const handles = await p.evaluate('impulselabPage.handles()');
    const handle = handles.find((h) => h.kind === 'velocity' && h.body === 0);
    check(handle !== undefined, 'ball 1 has a velocity handle', JSON.stringify(handles));
    const previous = state;
    await p.drag([handle.x, handle.y], [handle.x - 40, handle.y + 30]);
    await p.waitFor(`location.hash !== ${JSON.stringify(previous.hash)}`);
    state = await pageState(p);
    scene = JSON.parse(sceneOfHash(state.hash));
    check(typeof scene.bodies[0].velocity === 'number' && scene.bodies[0].velocity < 1,
          'dragging the handle to the left slows ball 1 (a 1D scene keeps a number)', scene.bodies[0].velocity);
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'cradle, ball 1 dragged');

    // The method, from the keyboard: End on the menu chooses its last entry, serial collisions.
    const dragged = state;
    await p.evaluate('document.getElementById("method").focus()');
    before = await shown(p);
    await p.press('End');
    await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
    check(await p.evaluate(`location.hash !== ${JSON.stringify(dragged.hash)}`), 'a choice from a menu is in the address at once');
    state = await pageState(p);
    scene = JSON.parse(sceneOfHash(state.hash));
    check(scene.solver && scene.solver.method === 'serial', 'the method is in the address', JSON.stringify(scene.solver));
    check(JSON.parse(state.result).method === 'serial', 'and the result is the serial method\'s');
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'cradle, serial');

    // A scene file opened.
    const oblique = join(source, 'tutorials/scenes/oblique-2d.json');
    const {root} = await p.send('DOM.getDocument');
    const {nodeId} = await p.send('DOM.querySelector', {nodeId: root.nodeId, selector: '#open-file'});
    before = await shown(p);
    await p.send('DOM.setFileInputFiles', {nodeId, files: [oblique]});
    await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
    state = await pageState(p);
    checkAgainstCommandLine(state, commandLine(oblique), 'opened oblique-2d.json');
    check(sceneOfHash(state.hash) === readFileSync(oblique, 'utf8'), 'the opened file is in the address as it is');

    // The scene downloaded: the file is the scene of the address.
    const downloads = join(scratch, 'downloads');
    mkdirSync(downloads);
    await p.send('Browser.setDownloadBehavior', {behavior: 'allow', downloadPath: downloads});
    await p.evaluate('document.getElementById("download").click()');
    for (let k = 0; k < 100 && !existsSync(join(downloads, 'oblique-2d.json')); ++k) {
      await new Promise((r) => setTimeout(r, 50));
    }
    const downloaded = existsSync(join(downloads, 'oblique-2d.json')) ? readFileSync(join(downloads, 'oblique-2d.json'), 'utf8') : '';
    check(downloaded !== '' && JSON.stringify(JSON.parse(downloaded)) === JSON.stringify(JSON.parse(sceneOfHash(state.hash))),
          'the downloaded scene is the scene of the address', downloaded.slice(0, 100));

    // Every control labelled (its name in the accessibility tree) and reached by Tab.
    await navigate(p, '#scene=' + encodeURIComponent(readFileSync(join(source, 'tutorials/scenes/spinning-rigid-pair.json'), 'utf8')));
    const {nodes} = await p.send('Accessibility.getFullAXTree');
    const roles = new Set(['button', 'checkbox', 'combobox', 'slider', 'spinbutton', 'textbox', 'link',
                           'radio', 'ListBox', 'listbox', 'PopUpButton', 'DisclosureTriangle']);
    const controls = nodes.filter((n) => !n.ignored && n.role && roles.has(n.role.value));
    const unnamed = controls.filter((n) => !n.name || String(n.name.value).trim() === '');
    check(controls.length >= 25, 'the accessibility tree lists the controls', controls.length);
    check(unnamed.length === 0, 'every control has a name', unnamed.map((n) => n.role.value).join(', '));
    const focusable = await p.evaluate(`[...document.querySelectorAll('a[href], button, input, select, textarea, summary')]
        .filter((e) => !e.disabled && e.checkVisibility({contentVisibilityAuto: true}) || e.id === 'open-file').map((e) => e.id || e.textContent.trim())`);
    await p.evaluate('document.activeElement && document.activeElement.blur(); window.scrollTo(0, 0)');
    const reached = new Set();
    for (let k = 0; k < focusable.length + 10; ++k) {
      await p.press('Tab');
      reached.add(await p.evaluate('document.activeElement.id || document.activeElement.textContent.trim()'));
    }
    const missed = focusable.filter((id) => !reached.has(id));
    check(missed.length === 0, 'Tab reaches every control', missed.join(', '));

    // The animation plays, and the system is typeset.
    await p.evaluate('document.getElementById("play").click()');
    await new Promise((r) => setTimeout(r, 400));
    const time = await p.evaluate('document.getElementById("time").value');
    await p.evaluate('document.getElementById("play").click()');
    check(time !== '0', 'the animation moves the time', time);
    await p.waitFor('document.querySelector("#system-equation svg")');
    check(await p.evaluate('document.querySelector("#system-equation .merror, #system-equation [data-mjx-error]") === null'),
          'the system is typeset without a MathJax error');
    checkClean(p, 'interaction');
  },

  async friction(browser) {
    const rod = presetsOfSite().find((preset) => preset.id === 'rod-rough-floor');
    check(rod !== undefined, 'the rod on a rough floor (lab 9) is a preset');
    if (!rod) {
      return;
    }
    const rodText = JSON.stringify(rod.scene);
    const rodHash = '#scene=' + encodeURIComponent(rodText);
    const p = await open(browser, rodHash);
    const value = (id) => p.evaluate(`document.getElementById(${JSON.stringify(id)}).value`);
    const energyWarnings = () => p.evaluate(`[...document.querySelectorAll('#energy-warnings li')].map((li) => li.textContent)`);
    const gained = "energy gained: Newton's restitution with friction; see the docs page on friction";
    // Waits for the page to show a change made by @p act, and for the address to follow it.
    const change = async (act) => {
      const before = await shown(p);
      const hash = await p.evaluate('location.hash');
      await act();
      await p.waitFor(`Number(document.body.dataset.shown) > ${before}`);
      await p.waitFor(`location.hash !== ${JSON.stringify(hash)}`);
      const state = await pageState(p);
      return {state, scene: JSON.parse(sceneOfHash(state.hash)), result: state.result ? JSON.parse(state.result) : null};
    };
    const press = (id, key) => change(async () => {
      await p.evaluate(`document.getElementById(${JSON.stringify(id)}).focus()`);
      await p.press(key);
    });
    // A number typed into a field, as a reader types it (a trusted input event).
    const type = (id, text) => change(async () => {
      await p.evaluate(`(() => { const e = document.getElementById(${JSON.stringify(id)}); e.focus(); e.value = ''; })()`);
      await p.send('Input.insertText', {text});
    });
    const near = (x, y, tolerance) => typeof x === 'number' && Math.abs(x - y) <= tolerance;

    // The rod as lab 9 and the docs page "Friction and restitution" work it by hand: m = 1, L = 1,
    // I = 1/12 at 45°, centre velocity (0.7, -1), μ = 0.8, e = 1.9, Newton's law. W = [[2.5, -1.5],
    // [-1.5, 2.5]], u0 = (-1, 0.7): the slip stops at P_n = 0.2, the end sticks (1.5 <= 0.8 * 2.5),
    // compression ends at 0.2 + 0.26/1.6 = 0.3625, and Newton's law ends at u = (0.9, 0), so
    // P = W^-1 (u - u0) = (0.925, 0.275); the energy goes from 0.745 to 0.795.
    let state = await pageState(p);
    checkAgainstCommandLine(state, commandLineOnText(rodText), 'rod, Newton');
    let result = JSON.parse(state.result);
    check(near(result.impulses[0].magnitude, 0.925, 1e-12) && near(result.impulses[0].tangential, 0.275, 1e-12) &&
          result.impulses[0].slip === 'stick', 'rod, Newton: the hand-worked impulse (0.925, 0.275), sticking',
          JSON.stringify(result.impulses[0]));
    check(near(result.energy.after, 0.795, 1e-12), 'rod, Newton: the energy after is 0.795 (gained 0.05)', result.energy.after);
    check(await value('preset') === 'rod-rough-floor' && await value('friction-number') === '0.8' &&
          await value('friction') === '0.8' && await value('restitution') === 'newton',
          'the controls show the preset, μ = 0.8 and Newton\'s law');
    check(JSON.stringify(await energyWarnings()).includes(gained), 'rod, Newton: the energy-gained warning beside the energy bars',
          JSON.stringify(await energyWarnings()));
    const facts = await p.evaluate('document.getElementById("friction-facts").textContent');
    check(facts.includes('slip until Fdt = 0.2, stick until 0.925; compression ended at Fdt = 0.3625'),
          'rod, Newton: the phases of slip as the text report writes them', facts);
    const table = await p.evaluate('document.getElementById("impulses-table").textContent');
    check(table.includes('tangential') && table.includes('0.275') && table.includes('stick'),
          'rod, Newton: the impulses table has the tangential impulse and how the slip ended', table);
    // The impulse on the rod, (P_t, P_n) = (0.275, 0.925) for the normal (0, -1) and the tangent
    // (1, 0): drawn as the whole vector, 73.4° from the floor, not along the normal (90°); its
    // 60 px length leaves 1/60 rad of rounding.
    const arrows = await p.evaluate('impulselabPage.impulseArrows()');
    check(arrows.length === 1 && arrows[0].body === 'rod' &&
          near(Math.atan2(arrows[0].dy, arrows[0].dx), Math.atan2(0.925, 0.275), 0.02),
          'rod: the impulse drawn on the rod as the whole vector', JSON.stringify(arrows));

    // The law from the keyboard: End is the energetic law, then Up is Poisson's, Home Newton's.
    // Hand values (the docs page): energetic P_n = 0.3625 + sqrt(0.1489640625), P_t = 0.1690752,
    // energy 0.66104625; Poisson's P_n = 1.9 * 0.3625 = 0.68875, P_t = 0.13325, energy 0.62702625.
    const laws = [['End', 'energetic', 0.3625 + Math.sqrt(0.1489640625), 0.66104625],
                  ['ArrowUp', 'poisson', 0.68875, 0.62702625]];
    for (const [key, law, normal, energy] of laws) {
      let scene;
      ({state, scene, result} = await press('restitution', key));
      check(scene.solver && scene.solver.restitution === law, `rod, ${law}: the law is in the address`, JSON.stringify(scene.solver));
      checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), `rod, ${law}`);
      check(near(result.impulses[0].magnitude, normal, 1e-9) && near(result.energy.after, energy, 1e-12),
            `rod, ${law}: the hand-worked impulse and energy`, JSON.stringify([result.impulses[0], result.energy]));
      check((await energyWarnings()).length === 0 && !state.warnings.some((w) => w.startsWith('energy gained')),
            `rod, ${law}: no energy gained, no warning`, JSON.stringify(state.warnings));
    }
    let scene;
    ({state, scene} = await press('restitution', 'Home'));
    check(scene.solver === undefined && state.hash === rodHash, 'Newton\'s law writes no key: the preset\'s address again',
          state.hash.slice(0, 200));
    check(await value('preset') === 'rod-rough-floor', 'and the menu shows the preset again');
    check(JSON.stringify(await energyWarnings()).includes(gained), 'rod, Newton again: the warning is back');

    // μ from the keyboard: Home is 0, no key (the frictionless rod: the paper's 1.9/2.5 = 0.76 and
    // no tangential column); a step up is 0.05, written after the elasticity.
    let resultText;
    ({state, scene, result} = await press('friction', 'Home'));
    resultText = state.result;
    check(scene.friction === undefined && JSON.stringify(scene) === JSON.stringify({...rod.scene, friction: undefined}),
          'μ = 0 writes no key', JSON.stringify(scene));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'rod, μ = 0');
    check(near(result.impulses[0].magnitude, 0.76, 1e-12) && !('tangential' in result.impulses[0]),
          'rod, μ = 0: the paper\'s impulse 0.76, no tangential impulse', JSON.stringify(result.impulses[0]));
    ({state, scene} = await press('friction', 'ArrowRight'));
    check(scene.friction === 0.05 && Object.keys(scene).join(',') === Object.keys(rod.scene).join(','),
          'a step of the slider: μ = 0.05, in its place after the elasticity', Object.keys(scene).join(','));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'rod, μ = 0.05');
    check(await value('friction-number') === '0.05', 'the number field follows the slider');
    ({state} = await type('friction-number', '0.8'));
    check(state.hash === rodHash, 'μ typed back to 0.8: the preset\'s address byte for byte', state.hash.slice(0, 200));

    // The address round-trips both keys: Poisson's law and μ = 0.3 (the slip reverses).
    await press('restitution', 'ArrowDown');
    ({state, scene} = await type('friction-number', '0.3'));
    check(scene.friction === 0.3 && scene.solver.restitution === 'poisson', 'μ = 0.3 and Poisson\'s law in the address',
          JSON.stringify(scene));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'rod, Poisson, μ = 0.3');
    check(JSON.parse(state.result).impulses[0].slip === 'reversed', 'rod at μ = 0.3: the slip reverses (1.5 > 0.3 * 2.5)');
    await checkSharedLink(browser, p, state, {'friction-number': '0.3', 'friction': '0.3', 'restitution': 'poisson'},
                          'friction, shared link');

    // A frictionless scene of two contacts: μ and the law set and set back leave its address and
    // its result as they were, byte for byte; with μ = 0.5 the paper's method refuses it with the
    // command line's message, complementarity and serial collisions solve it.
    const box = presetsOfSite().find((preset) => preset.id === 'box-lands-flat');
    const boxHash = '#scene=' + encodeURIComponent(JSON.stringify(box.scene));
    await navigate(p, boxHash);
    const boxResult = (await pageState(p)).result;
    ({state, scene} = await type('friction-number', '0.5'));
    check(scene.friction === 0.5, 'box: μ = 0.5 in the address', JSON.stringify(scene));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'box, μ = 0.5, the paper\'s method');
    check(state.error.includes('cannot resolve 2 contacts with friction'), 'box, μ = 0.5: the paper\'s method refuses it', state.error);
    await p.evaluate('document.getElementById("view").scrollIntoView()');
    // The last scene solved (μ = 0) stays on the canvas and in the tables, dimmed, until the scene
    // is right again: its two impulses, 0.75 each, straight up.
    check(await p.evaluate('document.body.classList.contains("refused")'), 'box refused: the last result is kept, dimmed');
    check(await p.evaluate(`impulselabPage.impulseArrows().every((a) => Math.abs(a.dx) < 1e-9 && a.dy > 0)`) &&
          (await p.evaluate('document.getElementById("impulses-table").textContent')).includes('0.75'),
          'box refused: the impulses drawn and listed are the last solved scene\'s');
    ({state} = await press('method', 'ArrowDown'));
    check(JSON.parse(sceneOfHash(state.hash)).solver.method === 'complementarity', 'box: complementarity chosen');
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'box, μ = 0.5, complementarity');
    // Landing flat and straight, by symmetry neither corner slips: both stick, no friction acts,
    // and the normal impulses are the frictionless ones, 0.75 each (A = [[3.4, -1.4], [-1.4, 3.4]],
    // B = 1.5 on each row: (3.4 - 1.4) F dt = 1.5).
    const lcp = JSON.parse(state.result || 'null');
    check(lcp && lcp.impulses.every((i) => Math.abs(i.magnitude - 0.75) < 1e-12 && Math.abs(i.tangential) < 1e-12 &&
                                           i.slip === 'stick'),
          'box, μ = 0.5, complementarity: both corners stick with 0.75 each', (state.result || state.error).slice(0, 300));
    ({state, result} = await press('method', 'End'));
    checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(state.hash)), 'box, μ = 0.5, serial');
    check(result && result.impulses.every((i) => typeof i.tangential === 'number' && typeof i.slip === 'string'),
          'box, serial: each contact\'s tangential impulse and slip', state.result.slice(0, 200));
    await press('method', 'Home');
    ({state} = await type('friction-number', '0'));
    check(state.hash === boxHash && state.result === boxResult, 'box: μ set back to 0, the same address and result byte for byte',
          state.hash.slice(0, 200));
    await press('restitution', 'ArrowDown');
    ({state} = await press('restitution', 'Home'));
    check(state.hash === boxHash && state.result === boxResult, 'box: the law set back to Newton\'s, the same address and result');
    checkClean(p, 'friction');
  },

  async links(browser) {
    // The "try it" links of the site's pages.
    const links = new Map();
    for (const file of readdirSync(site).filter((f) => f.endsWith('.html'))) {
      const html = readFileSync(join(site, file), 'utf8');
      for (const m of html.matchAll(/href="collide\.html(#scene=[^"]*)"/g)) {
        links.set(m[1], file);
      }
    }
    check(links.size >= 8, 'the section and lab pages link to the page with their scenes', links.size);
    const entries = [...links.entries()];
    const p = await open(browser, entries[0][0]);
    for (const [k, [hash, file]] of entries.entries()) {
      if (k > 0) {
        await navigate(p, hash);
      }
      const state = await pageState(p);
      check(state.error === '' && state.result !== '', `${file}: its "try it" link opens its scene`, state.error);
      checkAgainstCommandLine(state, commandLineOnText(sceneOfHash(hash)), `try it from ${file}`);
    }
    // The page's own links to the paper's equations on the section pages land on their anchors.
    const equations = await p.evaluate(`[...document.querySelectorAll('#system-source a')].map((a) => a.getAttribute('href'))`);
    check(equations.length >= 7, 'the page links to the equations (1.3) to (5.5)', equations.join(' '));
    for (const href of equations) {
      const [file, anchor] = href.split('#');
      const html = existsSync(join(site, file)) ? readFileSync(join(site, file), 'utf8') : '';
      check(html.includes(`id="${anchor}"`), `the link ${href} lands on its equation`);
    }
    checkClean(p, 'links');
  },
};

await run(groups, 'page_test.mjs');
