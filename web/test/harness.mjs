// SPDX-License-Identifier: GPL-3.0-or-later
// What the browser tests and measurements of the pages share: their options, counted checks with
// their failures printed, the page's cleanliness (no console error, no exception, no request
// outside the site), running one group of checks in a fresh headless Chromium, and the medians of
// a measurement.
import {resolve} from 'node:path';
import {Browser} from './chromium.mjs';

// The value of --NAME in @p args, as an absolute path.
export function pathOption(args, name) {
  const at = args.indexOf(`--${name}`);
  if (at < 0 || at + 1 >= args.length) {
    throw new Error(`missing --${name}`);
  }
  return resolve(args[at + 1]);
}

let failures = 0;
let checks = 0;

// One check: counted, and printed with @p detail when @p condition is false.
export function check(condition, what, detail = '') {
  checks += 1;
  if (!condition) {
    failures += 1;
    console.log(`FAIL ${what}${detail ? `\n     ${String(detail).split('\n').join('\n     ')}` : ''}`);
  }
}

// No console error, no exception, and no request but to @p site (file:, data:, blob: by default).
export function checkClean(p, where, site = /^(file|data|blob):/) {
  check(p.problems().length === 0, `${where}: no console error, no exception`, p.problems().join('\n'));
  const outside = p.requests.filter((u) => !site.test(u));
  check(outside.length === 0, `${where}: no request outside the site`, outside.join('\n'));
}

// Runs groups[name](browser) in a fresh Chromium (started with @p launch, see chromium.mjs), then
// @p cleanup; prints the count and exits 0 when every check passed (an exception is a failure).
export async function runGroup(groups, name, usage, cleanup = () => {}, launch = {}) {
  if (!groups[name]) {
    console.log(`usage: ${usage.replace('GROUP', `(${Object.keys(groups).join('|')})`)}`);
    process.exit(2);
  }
  const browser = await Browser.launch(launch);
  try {
    await groups[name](browser);
  } catch (e) {
    failures += 1;
    console.log(`FAIL ${name}: ${e.stack}`);
  } finally {
    await browser.close();
    cleanup();
  }
  console.log(`${name}: ${checks} checks, ${failures} failed`);
  process.exit(failures === 0 ? 0 : 1);
}

// The median, 90th percentile and largest of @p values.
export function stats(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const at = (q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  return {median: at(0.5), p90: at(0.9), max: sorted[sorted.length - 1], n: values.length};
}

// One line of a measurement: what, and its stats.
export function show(what, s, unit = 'ms') {
  console.log(`${what.padEnd(62)} median ${s.median.toFixed(1)} ${unit}, 90% ${s.p90.toFixed(1)}, ` +
              `max ${s.max.toFixed(1)} (${s.n} runs)`);
}
