// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation page's speed in headless Chromium (a measurement, not a test: timings are not
// asserted). Times are the page's own (performance.now(), window.impulselabCheckTimes):
//
//   ready      check.html opened from disk, a fresh page each time: the checker's worker ready
//              (its WebAssembly compiled), and the first report shown (the default example)
//   section 3  the paper's section 3 (46 equations) chosen from the menu once the page is ready:
//              from the choice to its report shown; the check alone, in the worker; and the check
//              once more in the same page, after another example
//   keystroke  one character typed into the prose of a file of 20 steps (the example
//              elastic-line's four steps, five times over, each copy after `given:`): from the
//              key's input event to the new report shown
//   typing     the page's own work on the main thread for one keystroke in section 4 (its input
//              handler: the address, the margin, the next check asked for), which is all that
//              typing waits for: the check runs in the worker
//
// With --cli, the command line checks the same two files in the same run, interleaved with the
// page's checks: the report's own `seconds` (the check, as the worker's time is) and the whole
// process, for the ratio of WebAssembly to native.
//
// usage: node check_measure.mjs --site DIR [--repeat N] [--cli PROGRAM]
import {spawnSync} from 'node:child_process';
import {mkdtempSync, readFileSync, rmSync, writeFileSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {Browser} from './chromium.mjs';
import {show, stats} from './harness.mjs';

const args = process.argv.slice(2);
const site = resolve(args[args.indexOf('--site') + 1]);
const repeat = args.includes('--repeat') ? Number(args[args.indexOf('--repeat') + 1]) : 10;
const cli = args.includes('--cli') ? resolve(args[args.indexOf('--cli') + 1]) : null;
const scratch = mkdtempSync(join(tmpdir(), 'impulselab-check-measure-'));
const native = {};  // what -> {check: [ms], process: [ms]}
function runNative(what, text) {
  if (!cli) {
    return;
  }
  const file = join(scratch, 'file.md');
  writeFileSync(file, text);
  const start = performance.now();
  const run = spawnSync(cli, ['check', file, '--format', 'json'], {encoding: 'utf8'});
  const wall = performance.now() - start;
  native[what] = native[what] || {check: [], process: []};
  native[what].check.push(JSON.parse(run.stdout).seconds * 1000);
  native[what].process.push(wall);
}
const url = `file://${join(site, 'check.html')}`;

// The examples as the site holds them.
const window = {};
new Function('window', readFileSync(join(site, 'examples.js'), 'utf8'))(window);
const example = (name) => window.impulselabDerivations.find((e) => e.name === name).text;

// 20 steps: elastic-line's derivation (1 premise, 4 steps) five times, each copy after `given:`
// (its first equation a premise again) and without the tag, which may name one equation only.
function twentySteps() {
  const text = example('elastic-line');
  const start = text.indexOf('A perfectly elastic collision');
  const end = text.indexOf('<!-- expect');
  const body = text.slice(start, end).replace(/ \\tag\{1\.1\}/, '');
  let file = text.slice(0, start) + body;
  for (let k = 2; k <= 5; ++k) {
    file += `\n## Again (${k})\n\ngiven:\n\n${body}`;
  }
  return file;
}

const browser = await Browser.launch();
// The check's own time as the report gives it (`seconds`), as the command line's is measured.
const reportSeconds = async (page) =>
  1000 * await page.evaluate('JSON.parse(document.getElementById("result-json").textContent).seconds');
const waitNext = async (page, count) =>
  page.waitFor(`window.impulselabCheckTimes && impulselabCheckTimes.answers.length > ${count} && ` +
               'document.body.dataset.ready === "true"', 120000);
try {
  const ready = [];
  const first = [];
  const section = [];
  const sectionWorker = [];
  const sectionCheck = [];
  const sectionAgain = [];
  for (let k = 0; k < repeat; ++k) {
    const page = await browser.newPage({width: 1280, height: 800});
    await page.goto(url);
    await waitNext(page, 0);
    const t = await page.evaluate('impulselabCheckTimes');
    ready.push(t.workerReady);
    first.push(t.answers[0].shown);
    // Section 3 from the menu.
    const count = t.answers.length;
    const chosen = await page.evaluate(`(() => { const s = document.getElementById('example');
                                         s.value = 'section3'; const at = performance.now();
                                         s.dispatchEvent(new Event('change')); return at; })()`);
    await waitNext(page, count);
    const answer = (await page.evaluate('impulselabCheckTimes')).answers[count];
    section.push(answer.shown - chosen);
    sectionWorker.push(answer.worker);
    sectionCheck.push(await reportSeconds(page));
    // Once more, after another example: V8 has compiled the module's hot code better by then.
    for (const name of ['elastic-line', 'section3']) {
      const n = await page.evaluate('impulselabCheckTimes.answers.length');
      await page.evaluate(`(() => { const s = document.getElementById('example'); s.value = '${name}';
                                    s.dispatchEvent(new Event('change')); })()`);
      await waitNext(page, n);
    }
    sectionAgain.push(await reportSeconds(page));
    await page.close();
    runNative('section 3', example('section3'));
  }
  show('ready: the worker\'s module compiled, from the start of loading', stats(ready));
  show('ready: the first report shown (elastic-line), from the start', stats(first));
  show('section 3 (46 equations), chosen to shown', stats(section));
  show('section 3, in the worker (check and JSON report)', stats(sectionWorker));
  show('section 3, the check (the report\'s seconds)', stats(sectionCheck));
  show('section 3 checked again in the same page, the check', stats(sectionAgain));

  // A keystroke in a file of 20 steps.
  const text = twentySteps();
  const page = await browser.newPage({width: 1280, height: 800});
  await page.goto(`${url}#file=${encodeURIComponent(text)}`);
  await waitNext(page, 0);
  const steps = await page.evaluate('JSON.parse(document.getElementById("result-json").textContent).equations' +
                                    '.filter((e) => e.verdict !== "premise").length');
  const prose = text.indexOf('Expanding the squares') + 'Expanding'.length;
  await page.evaluate(`(() => { const e = document.getElementById('editor'); e.focus();
                                e.setSelectionRange(${prose}, ${prose}); })()`);
  const keystroke = [];
  const keystrokeWorker = [];
  const keystrokeCheck = [];
  for (let k = 0; k < 3 * repeat; ++k) {
    const count = await page.evaluate('impulselabCheckTimes.answers.length');
    await page.send('Input.insertText', {text: k % 2 === 0 ? ' ' : 'x'});
    await waitNext(page, count);
    const answer = (await page.evaluate('impulselabCheckTimes')).answers[count];
    keystroke.push(answer.shown - answer.changed);
    keystrokeWorker.push(answer.worker);
    keystrokeCheck.push(await reportSeconds(page));
    runNative('20 steps', text);
  }
  show(`keystroke: a file of ${steps} steps, input event to report shown`, stats(keystroke));
  show('keystroke: in the worker (check and JSON report)', stats(keystrokeWorker));
  show('keystroke: the check (the report\'s seconds)', stats(keystrokeCheck));
  for (const [what, times] of Object.entries(native)) {
    show(`native: ${what}, the check (the report's seconds)`, stats(times.check));
    show(`native: ${what}, the whole process`, stats(times.process));
  }
  if (native['section 3']) {
    console.log('ratio WebAssembly / native, the check (the reports\' seconds, medians): section 3 ' +
                `${(stats(sectionCheck).median / stats(native['section 3'].check).median).toFixed(2)}, ` +
                `20 steps ${(stats(keystrokeCheck).median / stats(native['20 steps'].check).median).toFixed(2)}`);
  }
  // The main thread's work per keystroke, on the longest example.
  await page.close();
  const long = await browser.newPage({width: 1280, height: 800});
  await long.goto(`${url}#example=section4`);
  await waitNext(long, 0);
  const typing = await long.evaluate(`(() => { const e = document.getElementById('editor'); const times = [];
    for (let k = 0; k < ${3 * repeat}; ++k) {
      e.value += ' ';  // the textarea's own editing, not the page's, is left out
      const start = performance.now();
      e.dispatchEvent(new Event('input'));
      times.push(performance.now() - start);
    }
    return {times, lines: e.value.split('\\n').length}; })()`);
  show(`typing: the input handler on the main thread, section 4 (${typing.lines} lines)`, stats(typing.times));
  const size = readFileSync(join(site, 'impulselab-check.js')).length;
  console.log(`module: impulselab-check.js ${size} bytes (${(size / 1048576).toFixed(2)} MiB)`);
  await long.close();
} finally {
  await browser.close();
  rmSync(scratch, {recursive: true, force: true});
}
