// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation page, check.html, in headless Chromium (label web), against the command line
// built beside it:
//
//   files     every derivation file of the project (tests/derivations/, tutorials/, the paper's and
//             the checker's own sections in derivations/) given in the address: result-json is what
//             `impulselab check FILE --format json` prints (timings aside; `file` is the example's
//             name or "check.html"), or check-error its refusal (the same LINE:COLUMN and message)
//             with result-json empty; the first equation that does not pass (the command line's
//             message names its line) or the refused line is marked in the editor
//   examples  every example of the menu, chosen from it: the command line's report for its file,
//             the address #example=NAME
//   editing   keystrokes in the editor: the page checks again, the address holds the text typed,
//             the result is the command line's for that text; that address opened afresh shows
//             the same; a file opened, the text downloaded; every control named and reached by
//             Tab; the equations typeset by MathJax without an error; nothing wider than a phone
//   server    the page from a static web server (http://127.0.0.1), not only from disk: its worker
//             starts and checks as from disk
//   links     the "edit this derivation" links of the site's pages open their files, checked as the
//             command line checks them; collide.html and check.html link to each other
//
// On every page: no console error, no exception, no request outside the site.
//
// usage: node check_test.mjs GROUP --site DIR --cli PROGRAM --source DIR
import {spawnSync} from 'node:child_process';
import {createServer} from 'node:http';
import {existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {extname, join, relative} from 'node:path';
import {check, checkClean, pathOption, runGroup} from './harness.mjs';

const args = process.argv.slice(2);
const group = args[0];
const site = pathOption(args, 'site');
const cli = pathOption(args, 'cli');
const source = pathOption(args, 'source');
const page = join(site, 'check.html');
const pageUrl = `file://${page}`;
const scratch = mkdtempSync(join(tmpdir(), 'impulselab-check-test-'));

// --- The command line ------------------------------------------------------------------------

// What `impulselab check FILE --format json` gives: its status, its report, its refusal without
// "FILE:" (LINE:COLUMN: message), and the line its message names as the first that does not pass.
function commandLine(file) {
  const run = spawnSync(cli, ['check', file, '--format', 'json'], {encoding: 'utf8'});
  const lines = run.stderr.split('\n').filter((l) => l !== '');
  const refusal = run.status === 2 ? lines.find((l) => l.startsWith(`${file}:`)) : undefined;
  const failing = lines.map((l) => l.match(/: line ([0-9]+) [a-z-]+ \(the first equation that does not pass\)$/))
      .find((m) => m);
  return {
    file,
    text: readFileSync(file),
    status: run.status,
    report: run.status === 2 ? null : JSON.parse(run.stdout),
    error: refusal ? refusal.slice(file.length + 1) : '',
    stderr: run.stderr,
    firstFailing: failing ? Number(failing[1]) : null,
  };
}

function commandLineOnText(text) {
  const file = join(scratch, 'typed.md');
  writeFileSync(file, text);
  return commandLine(file);
}

// --- The page --------------------------------------------------------------------------------

// A file in the address as check-page.md says: its text as encodeURIComponent writes it; bytes
// that are not UTF-8 (no file of the project has any) each as %XX.
function fragmentOf(bytes) {
  const text = bytes.toString('utf8');
  return Buffer.from(text, 'utf8').equals(bytes) ? encodeURIComponent(text) :
    [...bytes].map((b) => `%${b.toString(16).padStart(2, '0')}`).join('');
}

async function shown(p) {
  return Number(await p.evaluate('document.body.dataset.shown || 0'));
}

// Opens the page afresh at @p url, and waits for its first answer.
async function open(browser, url, viewport) {
  const p = await browser.newPage(viewport);
  await p.goto(url);
  await p.waitFor('document.body.dataset.ready === "true"', 60000);
  return p;
}

// Changes the address's fragment of an open page and waits for the page to show its answer.
async function navigate(p, url) {
  const before = await shown(p);
  await p.send('Page.navigate', {url});
  await p.waitFor(`Number(document.body.dataset.shown) > ${before} && document.body.dataset.ready === "true"`, 60000);
}

async function pageState(p) {
  return p.evaluate(`({
    result: document.getElementById('result-json').textContent,
    error: document.getElementById('check-error').textContent,
    hash: location.hash,
    example: document.getElementById('example').value,
    editor: document.getElementById('editor').value,
    firstFailure: [...document.querySelectorAll('#equations .equation.first-failure .line-button')]
        .map((b) => b.textContent),
    marked: [...document.querySelectorAll('#gutter .refused, #gutter .does-not-follow, #gutter .dimensions, #gutter .undecided')]
        .map((d) => parseInt(d.textContent, 10)),
    refusedInMargin: [...document.querySelectorAll('#gutter .refused')].map((d) => parseInt(d.textContent, 10)),
    bandLines: [...document.querySelectorAll('#marks .line-mark')].map((m) => m.className),
    note: (document.querySelector('#marks .line-note') || {}).textContent || '',
  })`);
}

function textOfHash(hash) {
  if (!hash.startsWith('#file=')) {
    throw new Error(`the address holds no text: ${hash.slice(0, 80)}`);
  }
  return Buffer.from(decodeURIComponent(hash.slice('#file='.length)), 'utf8');
}

function examplesOfSite() {
  const text = readFileSync(join(site, 'examples.js'), 'utf8');
  const window = {};
  new Function('window', text)(window);
  return window.impulselabDerivations;
}

// --- Checks ----------------------------------------------------------------------------------

// How a report is compared with the command line's. Every key, in the same order, and every
// value, except:
//  - the timings (`seconds`, the report's and each equation's), the only thing that changes from
//    one run to the next by design;
//  - `file`, which check-page.md sets (the example's name or "check.html");
//  - a worst relative residual of the numeric method (numeric.worst_relative_residual, and its two
//    digits in `how`) below 1e-9, which the checker counts as rounding (numeric_holds_below in
//    derivations/src/file/sample.hpp): the WebAssembly build and the native one round differently
//    (1.3e-12 natively against 1.25e-11 for a step of lab 8's derivation A), and either says the
//    same of the step;
//  - the order of terms in a formula. GiNaC orders the terms of a sum and the factors of a product
//    by hashes seeded with the address of each type's name (GiNaC's hash_seed.h): the command
//    line starts `check` at fixed addresses, so it prints one order on every run, but the
//    WebAssembly build meets another. A residual that differs must be the same expression in
//    another order: the command line, given the two as the equations \Xi = page's and
//    \Xi = command line's, finds the second to follow exactly (`follows` by its exact method; a
//    refusal or any other verdict leaves the difference reported); its plain text
//    (`residual_text`) is then the same too. A `how` that differs must have the same words, and
//    each of its formulas ($…$) that differs must be the same expression so (a formula with a
//    relation in it must be the same text; a condition X ≠ 0 is compared by its X; a formula may
//    also be the other's negative, and the formulas may come in another order: GiNaC writes a
//    factor with either sign, and lists the factors of an equation in its order).
const roundingBelow = 1e-9;
const residualFigure = /worst relative residual (?:below )?(-?[0-9.]+(?:e[-+]?[0-9]+)?)/g;

// The values of a report by their places ("equations[3].how"), with the keys of each object in
// order and the length of each array; timings and `file` left out, residuals of rounding as one.
function leaves(value, path = '', out = new Map()) {
  if (Array.isArray(value)) {
    out.set(`${path}#length`, value.length);
    value.forEach((v, i) => leaves(v, `${path}[${i}]`, out));
  } else if (value !== null && typeof value === 'object') {
    const keys = Object.keys(value).filter((k) => k !== 'seconds' && !(path === '' && k === 'file'));
    out.set(`${path}#keys`, keys.join(','));
    keys.forEach((k) => leaves(value[k], path ? `${path}.${k}` : k, out));
  } else if (path.endsWith('.worst_relative_residual') && Math.abs(value) < roundingBelow) {
    out.set(path, `below ${roundingBelow}`);
  } else if (path.endsWith('.how')) {
    out.set(path, value.replace(residualFigure, (all, x) => (Math.abs(Number(x)) < roundingBelow ?
      `worst relative residual below ${roundingBelow}` : all)));
  } else {
    out.set(path, value);
  }
  return out;
}

const withoutFormulas = (how) => how.replace(/\$[^$]*\$/g, '$…$');
const formulasOf = (how) => [...how.matchAll(/\$([^$]*)\$/g)].map((m) => m[1]);

// Whether the residuals @p a and @p b (LaTeX, as the report prints them) are one expression
// written in two orders: the command line checks \Xi = a then \Xi = b.
function sameExpression(a, b) {
  const file = join(scratch, 'same-expression.md');
  writeFileSync(file, `# Two orders of one residual\n\n$$\\Xi = ${a}$$\n\n$$\\Xi = ${b}$$\n`);
  const run = spawnSync(cli, ['check', file, '--format', 'json'], {encoding: 'utf8'});
  if (run.status !== 0) {
    return false;
  }
  const step = JSON.parse(run.stdout).equations[1];
  return step.verdict === 'follows' && step.decided_by === 'exact';
}

// Whether two formulas of a `how` are one: the same text, or (without a relation) the same
// expression in another order or with the other sign (a factor GiNaC wrote the other way round,
// v_2' - v_2 against -v_2' + v_2); a condition X \neq 0 likewise by its X.
function sameFormula(f, g) {
  if (f === g) {
    return true;
  }
  const condition = /^(.*) \\neq 0$/;
  const [cf, cg] = [f.match(condition), g.match(condition)];
  if (cf && cg) {
    return sameFormula(cf[1], cg[1]);
  }
  const relation = /=|\\neq\b|<|>|\\leq?\b|\\geq?\b/;
  if (relation.test(f) || relation.test(g)) {
    return false;
  }
  return sameExpression(f, g) || sameExpression(f, `-\\left(${g}\\right)`);
}

// Whether two `how` texts say the same: the same words, and the same formulas (sameFormula), in
// any order (the factors of one equation are listed in GiNaC's order).
function sameHow(a, b) {
  const left = formulasOf(b);
  return withoutFormulas(a) === withoutFormulas(b) && formulasOf(a).length === left.length &&
    formulasOf(a).every((f) => {
      const at = left.findIndex((g) => sameFormula(f, g));
      return at >= 0 && left.splice(at, 1).length === 1;
    });
}

// The places where the page's report @p page differs from the command line's, @p line: [] when
// it is the command line's.
function differences(page, line) {
  const mine = leaves(page);
  const theirs = leaves(line);
  const sameResidual = (path) => {
    const a = mine.get(path);
    const b = theirs.get(path);
    return typeof a === 'string' && typeof b === 'string' && a !== '' && b !== '' &&
      (a === b || sameExpression(a, b));
  };
  return [...mine].filter(([path, value]) => !theirs.has(path) || theirs.get(path) !== value)
      .concat([...theirs.keys()].filter((path) => !mine.has(path)).map((path) => [path, undefined]))
      .filter(([path, value]) => {
        if (value === undefined || !theirs.has(path)) {
          return true;
        }
        if (path.endsWith('.residual')) {
          return !sameResidual(path);
        }
        if (path.endsWith('.residual_text')) {
          return !sameResidual(path.replace(/_text$/, ''));
        }
        if (path.endsWith('.how')) {
          return !sameHow(value, theirs.get(path));
        }
        return true;
      }).map(([path, value]) => `${path}: ${JSON.stringify(value)} against ${JSON.stringify(theirs.get(path))}`);
}

// The page shows what the command line gives for the same file; @p name is the `file` the page's
// report must carry (the example's name, or "check.html").
function checkAgainstCommandLine(state, line, name, where) {
  if (line.status === 2) {
    check(line.error !== '', `${where}: the command line places its refusal`, line.stderr);
    check(state.error === line.error, `${where}: check-error is the command line's message`,
          `page: ${state.error}\nline: ${line.error}`);
    check(state.result === '', `${where}: result-json is empty`, state.result.slice(0, 100));
    const place = Number(line.error.split(':')[0]);
    check(state.refusedInMargin.join() === String(place) && state.bandLines.join() === 'line-mark refused' &&
          state.note === state.error, `${where}: the refusal shown at its line ${place} in the editor`,
          JSON.stringify({margin: state.refusedInMargin, bands: state.bandLines, note: state.note}));
    return;
  }
  check(state.error === '', `${where}: no refusal`, state.error);
  let report = null;
  try {
    report = JSON.parse(state.result);
  } catch (e) {
    check(false, `${where}: result-json is JSON`, state.result.slice(0, 200));
    return;
  }
  check(report.file === name, `${where}: the report names the file ${name}`, report.file);
  const found = differences(report, line.report);
  check(found.length === 0, `${where}: result-json is the command line's (timings aside)`, found.slice(0, 8).join('\n'));
  // The command line's exit 1 names the first equation that does not pass: the page marks it.
  const marked = line.firstFailing === null ? '' : `line ${line.firstFailing}`;
  check(state.firstFailure.join() === marked, `${where}: the first failing equation marked (${marked || 'none'})`,
        state.firstFailure.join());
  check(state.bandLines.join() === (marked ? 'line-mark first-failure' : ''), `${where}: its line marked in the editor`,
        state.bandLines.join());
}

function derivationFiles() {
  const folder = (dir) => (existsSync(join(source, dir)) ?
    readdirSync(join(source, dir)).filter((f) => f.endsWith('.md')).sort().map((f) => join(source, dir, f)) : []);
  const labs = readdirSync(join(source, 'tutorials')).filter((d) => /^[0-9][0-9]-/.test(d)).sort()
      .flatMap((d) => [...folder(`tutorials/${d}/derivations`), ...folder(`tutorials/${d}/solutions`)]);
  return [
    ...folder('tests/derivations/files'), ...folder('tests/derivations/malformed'),
    ...readdirSync(join(source, 'tests/derivations'), {withFileTypes: true})
        .filter((e) => e.isDirectory() && !['files', 'malformed'].includes(e.name))
        .flatMap((e) => folder(`tests/derivations/${e.name}`)),
    ...folder('tutorials/derivations'), ...labs,
    ...folder('derivations/paper'), ...folder('derivations/beyond'),
  ];
}

// --- The groups ------------------------------------------------------------------------------

const groups = {
  async files(browser) {
    const files = derivationFiles();
    check(files.length >= 80, 'the derivation files are found', files.length);
    const examples = examplesOfSite();
    let p = null;
    for (const file of files) {
      const line = commandLine(file);
      const url = `${pageUrl}#file=${fragmentOf(line.text)}`;
      if (p === null) {
        p = await open(browser, url);
      } else {
        await navigate(p, url);
      }
      const state = await pageState(p);
      const example = examples.find((e) => Buffer.from(e.text, 'utf8').equals(line.text));
      const where = relative(source, file);
      checkAgainstCommandLine(state, line, example ? example.name : 'check.html', where);
      check(state.example === (example ? example.name : ''), `${where}: the menu shows ${example ? example.name : 'no example'}`,
            state.example);
    }
    checkClean(p, 'files');
  },

  async examples(browser) {
    const examples = examplesOfSite();
    const names = examples.map((e) => e.name);
    for (const expected of ['elastic-line', 'verdicts-tour', 'a-ball-against-a-wall', 'section1', 'section5']) {
      check(names.includes(expected), `the menu has ${expected}`, names.join(' '));
    }
    const p = await open(browser, pageUrl);
    check((await pageState(p)).example === 'elastic-line', 'without a fragment the page opens on an example');
    for (const e of examples) {
      const before = await shown(p);
      await p.evaluate(`(() => { const s = document.getElementById('example');
                                  s.value = ${JSON.stringify(e.name)};
                                  s.dispatchEvent(new Event('change')); })()`);
      await p.waitFor(`Number(document.body.dataset.shown) > ${before} && document.body.dataset.ready === "true"`, 60000);
      const state = await pageState(p);
      checkAgainstCommandLine(state, commandLine(join(source, e.file)), e.name, `example ${e.name}`);
      check(state.hash === `#example=${e.name}`, `example ${e.name}: the address names it`, state.hash);
      check(state.editor === e.text && e.text === readFileSync(join(source, e.file), 'utf8'),
            `example ${e.name}: the editor holds its file`);
    }
    // #example= in the address.
    await navigate(p, `${pageUrl}#example=section3`);
    const state = await pageState(p);
    checkAgainstCommandLine(state, commandLine(join(source, 'derivations/paper/section3.md')), 'section3', '#example=section3');
    checkClean(p, 'examples');
  },

  async editing(browser) {
    const file = join(source, 'tutorials/derivations/elastic-line.md');
    const original = readFileSync(file, 'utf8');
    const p = await open(browser, `${pageUrl}#example=elastic-line`);
    const first = await pageState(p);
    checkAgainstCommandLine(first, commandLine(file), 'elastic-line', 'elastic-line');

    // A slip typed into the last display equation: "= 0" becomes "= 1" ... typed at the end of
    // the first line that holds a $$ block's end, character by character.
    const lines = original.split('\n');
    const target = lines.findIndex((l, i) => i > 0 && /\$\$\s*$/.test(l) && /=/.test(l));
    check(target > 0, 'elastic-line has a display equation on one line', target);
    const offset = lines.slice(0, target).join('\n').length + 1 + lines[target].lastIndexOf('$$');
    await p.evaluate(`(() => { const e = document.getElementById('editor'); e.focus();
                                e.setSelectionRange(${offset}, ${offset}); })()`);
    for (const ch of ' + 1') {
      await p.send('Input.insertText', {text: ch});
    }
    await p.waitFor(`document.getElementById('editor').value.length === ${original.length + 4}`);
    await p.waitFor('document.body.dataset.ready === "true"', 30000);
    let state = await pageState(p);
    const typed = original.slice(0, offset) + ' + 1' + original.slice(offset);
    check(state.editor === typed, 'the keystrokes are in the editor');
    check(state.hash.startsWith('#file=') && textOfHash(state.hash).toString('utf8') === typed,
          'the address holds the text typed', state.hash.slice(0, 120));
    check(state.example === '', 'an edited example is no longer the example in the menu', state.example);
    check(state.result !== first.result, 'the text typed is checked again');
    checkAgainstCommandLine(state, commandLineOnText(typed), 'check.html', 'elastic-line with a slip typed');

    // The shared link, opened afresh, shows the same.
    const shared = await open(browser, pageUrl + state.hash);
    const again = await pageState(shared);
    const reportOf = (json) => JSON.stringify([...leaves(JSON.parse(json))]);
    check(again.editor === typed && reportOf(again.result) === reportOf(state.result),
          'the address opened afresh shows the same text and report (timings aside)');
    checkClean(shared, 'shared link');
    await shared.close();
    await p.send('Page.bringToFront');

    // Backspace four times: the example again, byte for byte.
    for (let k = 0; k < 4; ++k) {
      for (const type of ['rawKeyDown', 'keyUp']) {
        await p.send('Input.dispatchKeyEvent', {type, key: 'Backspace', code: 'Backspace', windowsVirtualKeyCode: 8,
                                                nativeVirtualKeyCode: 8});
      }
    }
    await p.waitFor(`document.getElementById('editor').value.length === ${original.length}`);
    await p.waitFor('document.body.dataset.ready === "true" && document.getElementById("example").value === "elastic-line"', 30000);
    state = await pageState(p);
    checkAgainstCommandLine(state, commandLine(file), 'elastic-line', 'the slip deleted again');

    // A refusal typed: an unclosed brace, shown at its line.
    await p.send('Input.insertText', {text: '{'});
    await p.waitFor('document.body.dataset.ready === "true" && document.getElementById("check-error").textContent !== ""', 30000);
    state = await pageState(p);
    checkAgainstCommandLine(state, commandLineOnText(state.editor), 'check.html', 'a brace typed');

    // A file opened.
    const opened = join(source, 'tutorials/08-find-the-slip/derivations/c-spinning-body.md');
    const {root} = await p.send('DOM.getDocument');
    const {nodeId} = await p.send('DOM.querySelector', {nodeId: root.nodeId, selector: '#open-file'});
    let before = await shown(p);
    await p.send('DOM.setFileInputFiles', {nodeId, files: [opened]});
    await p.waitFor(`Number(document.body.dataset.shown) > ${before} && document.body.dataset.ready === "true"`, 30000);
    state = await pageState(p);
    checkAgainstCommandLine(state, commandLine(opened), 'c-spinning-body', 'opened c-spinning-body.md');
    check(textOfHash(state.hash).equals(readFileSync(opened)), 'the opened file is in the address as it is');

    // Bytes that are not UTF-8, in a file opened: the reader's refusal at its place.
    const binary = join(scratch, 'latin1.md');
    writeFileSync(binary, Buffer.concat([Buffer.from('# Notes\n\n$$ x = 1 $$\n\nCaf'), Buffer.from([0xe9]), Buffer.from('\n')]));
    before = await shown(p);
    await p.send('DOM.setFileInputFiles', {nodeId, files: [binary]});
    await p.waitFor(`Number(document.body.dataset.shown) > ${before} && document.body.dataset.ready === "true"`, 30000);
    checkAgainstCommandLine(await pageState(p), commandLine(binary), 'check.html', 'a file that is not UTF-8');

    // An equation in inline math on a line of its own: not checked, and the page says so, as the
    // command line's report does (its notes).
    const lone = join(scratch, 'lone-inline.md');
    writeFileSync(lone, '# Notes\n\n$x = 2 y$\n\n$$y = x/2$$\n\n$$x = 2 y$$\n');
    before = await shown(p);
    await p.send('DOM.setFileInputFiles', {nodeId, files: [lone]});
    await p.waitFor(`Number(document.body.dataset.shown) > ${before} && document.body.dataset.ready === "true"`, 30000);
    checkAgainstCommandLine(await pageState(p), commandLine(lone), 'check.html', 'an equation in inline math alone');
    const notes = await p.evaluate(`(() => { const l = document.getElementById('notes');
      return {hidden: l.hidden, items: [...l.querySelectorAll('li')].map((i) => i.textContent)}; })()`);
    check(!notes.hidden && notes.items.length === 1 && notes.items[0].startsWith('Line 3: $x = 2 y$ is not checked'),
          'the equation in inline math is listed as not checked', JSON.stringify(notes));

    // The text downloaded: the file opened, byte for byte.
    await p.send('DOM.setFileInputFiles', {nodeId, files: [opened]});
    await p.waitFor(`document.getElementById('example').value === 'c-spinning-body' && document.body.dataset.ready === "true"`, 30000);
    const downloads = join(scratch, 'downloads');
    mkdirSync(downloads);
    await p.send('Browser.setDownloadBehavior', {behavior: 'allow', downloadPath: downloads});
    await p.evaluate('document.getElementById("download").click()');
    const saved = join(downloads, 'c-spinning-body.md');
    for (let k = 0; k < 100 && !existsSync(saved); ++k) {
      await new Promise((r) => setTimeout(r, 50));
    }
    check(existsSync(saved) && readFileSync(saved).equals(readFileSync(opened)), 'the downloaded file is the text');

    // MathJax typesets every equation shown, without an error.
    await p.waitFor(`window.MathJax && MathJax.Hub && document.querySelectorAll('#equations .math.display').length > 0 &&
                     [...document.querySelectorAll('#equations .math')].every((m) => m.querySelector('svg'))`, 30000);
    const math = await p.evaluate(`({
      equations: document.querySelectorAll('#equations li').length,
      typeset: document.querySelectorAll('#equations .math.display svg').length,
      errors: document.querySelectorAll('#equations .noError, #equations merror, #equations [data-mjx-error], #equations .MathJax_Error').length,
    })`);
    check(math.typeset === math.equations && math.errors === 0, 'every equation typeset by MathJax, none in error',
          JSON.stringify(math));

    // Every control named (the accessibility tree) and reached by Tab.
    const {nodes} = await p.send('Accessibility.getFullAXTree');
    const roles = new Set(['button', 'combobox', 'textbox', 'link', 'ListBox', 'listbox', 'PopUpButton',
                           'DisclosureTriangle']);
    const controls = nodes.filter((n) => !n.ignored && n.role && roles.has(n.role.value));
    const unnamed = controls.filter((n) => !n.name || String(n.name.value).trim() === '');
    check(controls.length >= 10, 'the accessibility tree lists the controls', controls.length);
    check(unnamed.length === 0, 'every control has a name', unnamed.map((n) => n.role.value).join(', '));
    const focusable = await p.evaluate(`(() => {
      const all = [...document.querySelectorAll('a[href], button, input, select, textarea, summary')].filter((e) => !e.disabled);
      all.forEach((e, k) => { e.dataset.tabTest = String(k); });
      return all.length; })()`);
    await p.evaluate('document.activeElement && document.activeElement.blur()');
    const reached = new Set();
    for (let k = 0; k < 2 * focusable + 2; ++k) {  // from where the focus was, round the page
      await p.press('Tab');
      const at = await p.evaluate('document.activeElement && document.activeElement.dataset ? document.activeElement.dataset.tabTest : undefined');
      if (at !== undefined && at !== null) {
        reached.add(at);
      }
    }
    check(reached.size === focusable, 'Tab reaches every control', `${reached.size} of ${focusable}`);

    // A phone: nothing wider than the window.
    await p.setViewport({width: 360, height: 740, deviceScaleFactor: 2, mobile: true});
    await new Promise((r) => setTimeout(r, 300));
    const width = await p.evaluate('document.documentElement.scrollWidth');
    check(width <= 360, 'nothing wider than a phone (360 px)', width);
    checkClean(p, 'editing');
  },

  async server(browser) {
    const types = {'.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml',
                   '.png': 'image/png', '.woff': 'font/woff', '.otf': 'font/otf'};
    const server = createServer((request, response) => {
      const path = join(site, decodeURIComponent(new URL(request.url, 'http://x').pathname));
      if (path === join(site, 'favicon.ico')) {  // asked for by the browser itself; the site has none
        response.writeHead(204);
        response.end();
        return;
      }
      if (!path.startsWith(site) || !existsSync(path)) {
        response.writeHead(404);
        response.end();
        return;
      }
      response.writeHead(200, {'Content-Type': types[extname(path)] || 'application/octet-stream'});
      response.end(readFileSync(path));
    });
    await new Promise((r) => server.listen(0, '127.0.0.1', r));
    const origin = `http://127.0.0.1:${server.address().port}`;
    try {
      const file = join(source, 'derivations/paper/section3.md');
      const p = await open(browser, `${origin}/check.html#example=section3`);
      checkAgainstCommandLine(await pageState(p), commandLine(file), 'section3', 'from a web server: #example=section3');
      const slip = join(source, 'tutorials/08-find-the-slip/derivations/b-two-bodies-stick.md');
      await navigate(p, `${origin}/check.html#file=${fragmentOf(readFileSync(slip))}`);
      checkAgainstCommandLine(await pageState(p), commandLine(slip), 'b-two-bodies-stick', 'from a web server: #file=');
      checkClean(p, 'server', new RegExp(`^(${origin.replace(/[.]/g, '\\.')}/|data:|blob:)`));
    } finally {
      server.close();
    }
  },

  async links(browser) {
    // The "edit this derivation" links of the site's pages.
    const links = new Map();
    for (const file of readdirSync(site).filter((f) => f.endsWith('.html'))) {
      const html = readFileSync(join(site, file), 'utf8');
      for (const m of html.matchAll(/href="check\.html(#(?:file|example)=[^"]*)"/g)) {
        links.set(m[1].replace(/&amp;/g, '&'), file);
      }
    }
    const pages = new Set(links.values());
    for (const expected of ['derivations.html', 'lab_8.html', 'section1.html', 'section2.html', 'section3.html',
                            'section4.html', 'section5.html']) {
      check(pages.has(expected), `${expected} links to check.html with its derivation`, [...pages].join(' '));
    }
    const examples = examplesOfSite();
    let p = null;
    for (const [hash, file] of links) {
      if (p === null) {
        p = await open(browser, pageUrl + hash);
      } else {
        await navigate(p, pageUrl + hash);
      }
      const state = await pageState(p);
      const example = hash.startsWith('#example=') ? examples.find((e) => `#example=${e.name}` === hash) :
                      examples.find((e) => Buffer.from(e.text, 'utf8').equals(textOfHash(hash)));
      check(example !== undefined, `${file}: its link ${hash.slice(0, 40)} opens an example of the project`);
      if (example) {
        checkAgainstCommandLine(state, commandLine(join(source, example.file)), example.name, `edit this derivation, ${file}`);
      }
    }
    // collide.html and check.html link to each other.
    const collide = readFileSync(join(site, 'collide.html'), 'utf8');
    check(/href="check\.html"/.test(collide), 'collide.html links to check.html');
    const links2 = await p.evaluate(`[...document.querySelectorAll('a[href]')].map((a) => a.getAttribute('href'))`);
    check(links2.includes('collide.html'), 'check.html links to collide.html', links2.join(' '));
    for (const href of links2.filter((h) => /^[a-z_0-9]+\.html$/.test(h))) {
      check(existsSync(join(site, href)), `check.html's link ${href} is a page of the site`);
    }
    checkClean(p, 'links');
  },
};

if (!existsSync(page)) {
  console.log(`${page} not found: the page is built with the docs (cmake --build --preset docs)`);
  process.exit(1);
}
// The group `server` reaches its own web server on 127.0.0.1; every other host stays unresolvable.
await runGroup(groups, group, 'node check_test.mjs GROUP --site DIR --cli PROGRAM --source DIR',
               () => rmSync(scratch, {recursive: true, force: true}),
               group === 'server' ? {hostResolverRules: 'MAP * ~NOTFOUND, EXCLUDE 127.0.0.1'} : {});
