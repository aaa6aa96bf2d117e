// SPDX-License-Identifier: GPL-3.0-or-later
// The documentation site as a student reads it, in headless Chromium (label docs; one browser for
// every page, driven over the DevTools pipe by web/test/chromium.mjs):
//
//   pages        every page Doxygen wrote, at 390 px wide once its formulas are typeset: the
//                menu is there with its entries, nothing is wider than the window, no ** or
//                backtick of unrendered Markdown and no TeX is left in its text, every formula
//                is typeset with its number, nothing is asked of the network, and every link
//                and file it names leads to a file and an anchor of the site
//   checks       every check of the report shows on its section's page the statement it
//                checked; a claim its words; an erratum its printed form and correction, each
//                with a term boxed; a refutation by argument says so; every symbol of every
//                counterexample on any page is in the notation page's glossary
//   labs         every lab numbers its questions and closes one answer after each; has
//                breadcrumbs and a way to its sections of the paper, which lead back to it; each
//                section page leads to the previous and the next
//   search       the search page finds "3.6" on section 3, "eq-3.6" at its check, "restitution",
//                and the interactive pages
//   screenshots  a section page, a page of the report and a lab, at 1280 and 390 px
//   detectors    each detector above, fed a page made wrong on purpose, reports it
//
// usage: node site_test.mjs GROUP --site DIR --report check.json --screenshots DIR
//        [--only a.html,b.html]  (pages: those pages alone)
import {existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync} from 'node:fs';
import {writeFile} from 'node:fs/promises';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {parseArgs} from 'node:util';
import {Browser} from '../../web/test/chromium.mjs';

const {values: given, positionals} = parseArgs({
  allowPositionals: true,
  options: {site: {type: 'string'}, report: {type: 'string'}, screenshots: {type: 'string'},
            only: {type: 'string'}},
});
const group = positionals[0];
const option = (name) => {
  if (given[name] === undefined) {
    throw new Error(`missing --${name}`);
  }
  return resolve(given[name]);
};

const failures = [];
function check(condition, message) {
  if (!condition) {
    failures.push(message);
  }
}
function expectNone(problems, what) {
  for (const p of problems) {
    failures.push(`${what}: ${p}`);
  }
}

// --- In the page: the detectors (each a function evaluated in the page, returning problems) ------

// Whether MathJax has typeset the page (at once when the page has no MathJax): ready, its queue
// empty and idle.
const typeset = `!document.querySelector('script[src*="MathJax.js"]') ||
  (window.MathJax !== undefined && MathJax.isReady === true && MathJax.Hub.queue.pending === 0 &&
   !MathJax.Hub.queue.running)`;

// The menu's links, by file.
const menuProblems = (required) => `(() => {
  const menu = document.getElementById('main-menu');
  if (!menu) { return ['no menu (#main-menu)']; }
  const files = [...menu.querySelectorAll('a')].map((a) => (a.getAttribute('href') || '').split('#')[0]);
  return ${JSON.stringify(required)}.filter((f) => !files.includes(f)).map((f) => 'the menu has no link to ' + f);
})()`;

// What sticks out of a window @p width wide: the page's width and the elements that stick out
// (those inside a box that scrolls on its own do not).
const widthProblems = (width) => `(() => {
  const page = document.documentElement.scrollWidth;
  if (page <= ${width}) { return []; }
  const clipped = (e) => {
    for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
      const o = getComputedStyle(a).overflowX;
      if (o !== 'visible') { return true; }
    }
    return false;
  };
  const name = (e) => e.tagName.toLowerCase() + (e.id ? '#' + e.id : '') +
    (typeof e.className === 'string' && e.className ? '.' + e.className.trim().split(/\\s+/)[0] : '');
  const wide = [...document.body.querySelectorAll('*')]
    .filter((e) => e.getBoundingClientRect().right + window.scrollX > ${width} + 1 && !clipped(e))
    .filter((e) => ![...e.children].some((c) => c.getBoundingClientRect().right + window.scrollX > ${width} + 1 && !clipped(c)))
    .slice(0, 3)
    .map((e) => name(e) + ' to ' + Math.round(e.getBoundingClientRect().right + window.scrollX) + ' px');
  return ['the page is ' + page + ' px wide at ' + ${width} + ' px: ' + wide.join(', ')];
})()`;

// ** and backticks in the text a reader sees (not in code, formulas or scripts).
const slipProblems = `(() => {
  const skip = (node) => {
    for (let e = node.parentElement; e; e = e.parentElement) {
      const tag = e.tagName;
      if (tag === 'SCRIPT' || tag === 'STYLE' || tag === 'CODE' || tag === 'PRE' || tag === 'TT' ||
          tag === 'TEXTAREA' || tag === 'KBD' ||
          (e.classList && (e.classList.contains('fragment') || e.classList.contains('MathJax') ||
                           e.classList.contains('MathJax_Display') || e.classList.contains('MathJax_Preview')))) {
        return true;
      }
    }
    return false;
  };
  const problems = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const text = node.textContent;
    const at = Math.max(text.indexOf('**'), text.indexOf('\`'));
    if (at >= 0 && !skip(node)) {
      problems.push('unrendered Markdown: "' + text.slice(Math.max(0, at - 40), at + 40).replace(/\\s+/g, ' ') + '"');
    }
  }
  return problems;
})()`;

// The TeX of every formula of the page (MathJax keeps it in a script), or of those under @p selector.
const formulas = (selector = '') => `[...document.querySelectorAll('${selector} script[type^="math/tex"]')].map((s) => s.textContent)`;

// The questions and answers of a lab: "Question N." in bold, then <details class="answer"> whose
// summary is "Answer N", one after each question, closed.
const labProblems = `(() => {
  const marks = [...document.querySelectorAll('b, strong, details.answer')];
  const problems = [];
  let questions = 0, answers = 0, open = null;
  for (const e of marks) {
    if (e.tagName === 'DETAILS') {
      ++answers;
      const n = Number(((e.querySelector('summary') || {}).textContent || '').replace(/^Answer\\s*/, ''));
      if (open === null) { problems.push('an answer (' + n + ') follows no question'); }
      else if (n !== open) { problems.push('answer ' + n + ' follows question ' + open); }
      if (e.open) { problems.push('answer ' + n + ' is open'); }
      open = null;
      continue;
    }
    const m = /^Question (\\d+)\\.$/.exec(e.textContent.trim());
    if (!m) { continue; }
    if (open !== null) { problems.push('question ' + open + ' has no answer'); }
    ++questions;
    open = Number(m[1]);
    if (open !== questions) { problems.push('question ' + open + ' is number ' + questions + ' of the page'); }
  }
  if (open !== null) { problems.push('question ' + open + ' has no answer'); }
  if (questions === 0) { problems.push('no question ("Question 1.")'); }
  if (answers !== questions) { problems.push(questions + ' questions, ' + answers + ' answers'); }
  return problems;
})()`;

// Formulas MathJax did not typeset, an equation number not shown, MathJax's errors, and TeX left
// in the text a reader sees (outside code, formulas and scripts). Run in the page.
function mathProblemsInPage() {
  const problems = [];
  for (const script of document.querySelectorAll('script[type^="math/tex"]')) {
    if (!script.id || !document.getElementById(`${script.id}-Frame`)) {
      problems.push(`formula ${script.id || '?'} has no typeset output: ${script.textContent.slice(0, 60)}`);
    }
    for (const m of script.textContent.matchAll(/\\tag\{([^}]*)\}/g)) {
      if (!document.getElementById(`mjx-eqn-${m[1]}`)) {
        problems.push(`the equation number (${m[1]}) is not shown`);
      }
    }
  }
  for (const e of document.querySelectorAll('.merror, [class*="MathJax_Error"]')) {
    problems.push(`MathJax reports an error: ${e.textContent.slice(0, 80)}`);
  }
  const skipped = (node) => {
    for (let e = node.parentElement; e; e = e.parentElement) {
      if (['SCRIPT', 'STYLE', 'CODE', 'PRE', 'TT', 'TEXTAREA'].includes(e.tagName) ||
          e.classList.contains('fragment') || e.classList.contains('MathJax') ||
          e.classList.contains('MathJax_Display') || e.classList.contains('MathJax_Preview')) {
        return true;
      }
    }
    return false;
  };
  let prose = '';
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (!skipped(node)) {
      prose += node.textContent;
    }
  }
  for (const raw of ['\\f$', '\\f[', '\\f]', '\\(', '\\)', '\\[', '\\]', '\\frac', '\\tag', '\\vec',
                     '\\det', '\\sum', '\\left', '\\mathrm', '\\begin']) {
    const at = prose.indexOf(raw);
    if (at >= 0) {
      problems.push(`raw TeX in the text: "${prose.slice(Math.max(0, at - 40), at + 60).replace(/\s+/g, ' ')}"`);
    }
  }
  if (document.body.textContent.includes('Math Processing Error')) {
    problems.push('MathJax shows "Math Processing Error"');
  }
  return problems;
}

// Every address the page names (href, src, data, srcset, poster), with the tag that names it.
function addressesInPage() {
  const found = [];
  for (const e of document.querySelectorAll('[href], [src], [data], [srcset], [poster]')) {
    for (const a of ['href', 'src', 'data', 'srcset', 'poster']) {
      const value = e.getAttribute(a);
      if (value !== null) {
        found.push({tag: e.tagName.toLowerCase(), attribute: a, value});
      }
    }
  }
  return found;
}

// --- Outside the page ----------------------------------------------------------------------------

// What two statements are compared by: no spaces, no gathered environment around them.
function comparable(tex) {
  return tex.replace(/\\begin\{gathered\}|\\end\{gathered\}/g, '').replace(/\s+/g, '');
}

// The symbols of a formula: letters (a subscript is an index, not a symbol), Greek letters, a
// letter under \bar, \tilde or \hat, a word in \mathit; dt is one symbol.
export function symbolsOf(tex) {
  const found = new Set();
  let t = tex.replace(/\\(mathit|mathrm|text|operatorname)\{([A-Za-z]+)\}/g, (m, c, w) => {
    found.add(w.length === 1 ? w : w);
    return ' ';
  });
  t = t.replace(/\\(bar|tilde|hat)\{([A-Za-z]|\\[A-Za-z]+)\}/g, (m, a, x) => {
    found.add(`\\${a}{${x}}`);
    return ' ';
  });
  t = t.replace(/_\{[^{}]*\}|_\\?[A-Za-z0-9]/g, ' ');
  t = t.replace(/\^\{[^{}]*\}|\^[A-Za-z0-9-]/g, ' ');
  const ignored = new Set(['times', 'cdot', 'leq', 'geq', 'neq', 'le', 'ge', 'Rightarrow', 'exists',
    'sum', 'det', 'quad', 'qquad', 'left', 'right', 'frac', 'vert', 'Vert', 'vec', 'mathbf',
    'boxed', 'in', 'infty', 'dots', 'ldots', 'cos', 'sin', 'tan', 'exp', 'ln', 'sqrt', 'Big',
    'big', 'int', 'limits', 'begin', 'end', 'mathrm', 'mathit']);
  for (const m of t.matchAll(/\\([A-Za-z]+)/g)) {
    if (!ignored.has(m[1])) {
      found.add(`\\${m[1]}`);
    }
  }
  t = t.replace(/\\[A-Za-z]+|\\./g, ' ').replace(/[0-9.]+/g, ' ');
  for (const m of t.matchAll(/[A-Za-z]+/g)) {
    if (m[0] === 'dt') {
      found.add('dt');
    } else {
      for (const c of m[0].replace(/dt$/, '')) {
        found.add(c);
      }
      if (m[0].endsWith('dt') && m[0].length > 2) {
        found.add('dt');
      }
    }
  }
  return found;
}

function doxygenPages(site) {
  return readdirSync(site).filter((f) => f.endsWith('.html')).filter((f) => {
    const head = readFileSync(join(site, f), 'utf8').slice(0, 600);
    return head.includes('content="Doxygen');
  }).sort();
}

function webPages(site) {
  return ['collide.html', 'check.html'].filter((f) => existsSync(join(site, f)));
}

// The page a check's statement is on: section3.html for 3.1, friction.html for friction.2.
function sectionPage(section) {
  const top = section.split('.')[0];
  return /^[0-9]+$/.test(top) ? `section${top}.html` : `${top}.html`;
}

// A URL that leaves the site: any scheme but file, data, blob, about, javascript and mailto, or
// "//host".
function leavesSite(url) {
  if (url.startsWith('//')) {
    return true;
  }
  const m = /^([A-Za-z][A-Za-z0-9+.-]*):/.exec(url);
  return m !== null && !['file', 'data', 'blob', 'about', 'javascript', 'mailto'].includes(m[1].toLowerCase());
}

const anchorsOf = new Map();
function hasAnchor(file, anchor) {
  if (!anchorsOf.has(file)) {
    anchorsOf.set(file, readFileSync(file, 'utf8'));
  }
  const html = anchorsOf.get(file);
  return html.includes(`id="${anchor}"`) || html.includes(`name="${anchor}"`);
}

// What a page loads from outside the site, and the links and files it names that lead to no file
// of the site or to an anchor its target does not have.
function addressProblems(pageFile, addresses, domIds) {
  const problems = [];
  for (const {tag, attribute, value} of addresses) {
    const loads = attribute !== 'href' || tag === 'link';
    if (leavesSite(value)) {
      if (loads) {
        problems.push(`<${tag} ${attribute}="${value}"> loads from outside the site`);
      }
      continue;
    }
    if (attribute === 'srcset' || /^[A-Za-z][A-Za-z0-9+.-]*:/.test(value) || value === '') {
      continue;
    }
    const hash = value.indexOf('#');
    const path = decodeURIComponent(value.slice(0, Math.min(...[value.indexOf('?'), hash, value.length].filter((x) => x >= 0))));
    const anchor = hash >= 0 ? value.slice(hash + 1) : '';
    const target = path === '' ? pageFile : resolve(join(pageFile, '..'), path);
    if (!existsSync(target)) {
      problems.push(`${value} (no file ${target})`);
      continue;
    }
    if (anchor === '' || !target.endsWith('.html') ||
        (target.endsWith('collide.html') && anchor.startsWith('scene=')) ||
        (target.endsWith('check.html') && (anchor.startsWith('file=') || anchor.startsWith('example=')))) {
      continue;  // the interactive page's state, not an anchor: the web tests open each such link
    }
    const found = target === pageFile ? domIds.includes(anchor) || hasAnchor(target, anchor) : hasAnchor(target, anchor);
    if (!found) {
      problems.push(`${value} (no anchor ${anchor} in ${target.split('/').pop()})`);
    }
  }
  return problems;
}

async function open(page, url) {
  await page.goto(url);
  await page.waitFor(typeset, 30000);
}

// --- The groups ----------------------------------------------------------------------------------

async function pagesGroup(browser, site, {only = null, tabs = 3} = {}) {
  const required = ['index.html', 'section1.html', 'section2.html', 'section3.html', 'section4.html',
    'section5.html', 'notation.html', 'errata.html', 'check_report.html', 'derivations.html',
    'labs.html', ...webPages(site)];
  const names = only || doxygenPages(site);
  check(names.length > 0, `no page of Doxygen's in ${site}`);
  // Each page alone in a tab; a few tabs at once, taking the next page as one is done (most of a
  // page's time is MathJax typesetting it, on one core of the browser's).
  let next = 0;
  const tab = async () => {
    const page = await browser.newPage({width: 390, height: 844, mobile: true});
    while (next < names.length) {
      const name = names[next++];
      page.requests = [];
      await open(page, `file://${join(site, name)}`);
      expectNone(await page.evaluate(menuProblems(required)), name);
      expectNone(await page.evaluate(widthProblems(390)), name);
      expectNone(await page.evaluate(slipProblems), name);
      expectNone(await page.evaluate(`(${mathProblemsInPage})()`), name);
      const addresses = await page.evaluate(`(${addressesInPage})()`);
      const ids = await page.evaluate(`[...document.querySelectorAll('[id]')].map((e) => e.id)`);
      expectNone(addressProblems(join(site, name), addresses, ids), name);
      expectNone(page.requests.filter(leavesSite).map((u) => `asked the network for ${u}`), name);
    }
    await page.close();
  };
  await Promise.all(Array.from({length: tabs}, tab));
  return names.length;
}

async function checksGroup(browser, site, report) {
  const checks = [...report.checks, ...((report.beyond_the_paper || {}).checks || [])];
  const page = await browser.newPage({width: 1280, height: 800});
  const pageFormulas = new Map();
  const formulasOf = async (name) => {
    if (!pageFormulas.has(name)) {
      await open(page, `file://${join(site, name)}`);
      pageFormulas.set(name, (await page.evaluate(formulas())).map(comparable));
    }
    return pageFormulas.get(name);
  };
  for (const c of checks) {
    const name = sectionPage(c.section);
    const shown = await formulasOf(name);
    check(shown.includes(comparable(c.display)), `${c.id}: its statement is not on ${name}`);
  }
  // The evidence of errata and refutations, on the errata page and on their section pages.
  for (const name of ['errata.html', ...new Set(checks.map((c) => sectionPage(c.section)))]) {
    await open(page, `file://${join(site, name)}`);
    for (const c of checks) {
      if (name === 'errata.html' && (!report.checks.includes(c) || c.status === 'verified')) {
        continue;
      }
      if (name !== 'errata.html' && sectionPage(c.section) !== name) {
        continue;
      }
      // A block is needed for what a statement and a verdict alone do not say: the evidence of
      // an erratum or a refutation, the words of a claim of the paper.
      if (!c.correction && !c.counterexample && !(c.kind === 'claim' && report.checks.includes(c))) {
        continue;
      }
      const where = name === 'errata.html' ? `#errata-check-${c.id.replace(/[^A-Za-z0-9]/g, '-')}` : '';
      const block = name === 'errata.html'
        ? `document.getElementById('${where.slice(1)}')`
        : `document.getElementById('check-${c.id.replace(/[^A-Za-z0-9]/g, '-')}')`;
      const found = await page.evaluate(`(() => {
        let b = ${block};
        if (!b) { return null; }
        // On the errata page the entry is the heading and what follows it, up to the next heading.
        const parts = [];
        if (b.tagName === 'A' || /^H[1-6]$/.test(b.tagName)) {
          let e = b.closest('h1,h2,h3,h4') || b;
          for (e = e.nextElementSibling; e && !/^H[1-6]$/.test(e.tagName); e = e.nextElementSibling) { parts.push(e); }
        } else { parts.push(b); }
        const all = (sel) => parts.flatMap((p) => [...(p.matches(sel) ? [p] : []), ...p.querySelectorAll(sel)]);
        const tex = (sel) => all(sel + ' script[type^="math/tex"]').map((s) => s.textContent);
        return {printed: tex('.printed'), corrected: tex('.corrected'), words: all('.words').map((w) => w.textContent.trim()),
                argument: all('.argument').length, counterexample: all('.counterexample').length};
      })()`);
      if (found === null) {
        failures.push(`${c.id}: no block of it on ${name}`);
        continue;
      }
      if (c.correction) {
        check(found.printed.some((t) => t.includes('\\boxed')), `${c.id} on ${name}: the printed form marks no term`);
        check(found.corrected.some((t) => t.includes('\\boxed')), `${c.id} on ${name}: the correction marks no term`);
      }
      if (c.kind === 'claim' && report.checks.includes(c)) {
        check(found.words.some((w) => w.length > 'The claim, in our words:'.length + 10),
              `${c.id} on ${name}: the claim is not given in words beside its formalisation`);
      }
      if (c.counterexample) {
        const byArgument = c.counterexample.startsWith('none of ');
        check(byArgument ? found.argument > 0 : found.counterexample > 0,
              `${c.id} on ${name}: ${byArgument ? 'a refutation by argument does not say so' : 'no counterexample'}`);
      }
    }
  }
  // Every symbol of every counterexample is in the notation page's glossary.
  await open(page, `file://${join(site, 'notation.html')}`);
  const glossary = new Set((await page.evaluate(
    `[...document.querySelectorAll('table tr > td:first-child script[type^="math/tex"]')].map((s) => s.textContent)`))
    .flatMap((tex) => [...symbolsOf(tex)]));
  check(glossary.size > 0, 'the notation page has no glossary (no formula in a first column)');
  for (const name of doxygenPages(site)) {
    const html = readFileSync(join(site, name), 'utf8');
    if (!html.includes('class="counterexample"')) {
      continue;
    }
    await open(page, `file://${join(site, name)}`);
    for (const tex of await page.evaluate(formulas('.counterexample'))) {
      for (const symbol of symbolsOf(tex)) {
        check(glossary.has(symbol), `${name}: the counterexample's symbol ${symbol} (in ${tex}) is not in the notation page's glossary`);
      }
    }
  }
  await page.close();
}

async function labsGroup(browser, site) {
  const labs = readdirSync(site).filter((f) => /^lab_[0-9]+\.html$/.test(f)).sort();
  check(labs.length > 0, 'no lab page (lab_N.html)');
  const page = await browser.newPage({width: 1280, height: 800});
  for (const name of labs) {
    await open(page, `file://${join(site, name)}`);
    expectNone(await page.evaluate(labProblems), name);
    // Breadcrumbs, and the way to the sections of the paper the lab is about, and back.
    const crumbs = await page.evaluate(`[...document.querySelectorAll('.breadcrumbs a')].map((a) => a.getAttribute('href'))`);
    check(crumbs.includes('index.html') && crumbs.includes('labs.html'), `${name}: no breadcrumbs to the start page and the labs`);
    const sections = await page.evaluate(`[...document.querySelectorAll('.pager a')].map((a) => a.getAttribute('href')).filter((h) => /^section[0-9]+\\.html$/.test(h))`);
    check(sections.length > 0, `${name}: no link to a section of the paper`);
    for (const section of sections) {
      check(readFileSync(join(site, section), 'utf8').includes(`href="${name}"`), `${section} does not link back to ${name}`);
    }
  }
  // Each section page leads to the previous and the next section.
  const numbered = readdirSync(site).filter((f) => /^section[0-9]+\.html$/.test(f)).sort();
  for (const [k, name] of numbered.entries()) {
    await open(page, `file://${join(site, name)}`);
    const pager = await page.evaluate(`[...document.querySelectorAll('.pager a')].map((a) => a.getAttribute('href'))`);
    for (const neighbour of [numbered[k - 1], numbered[k + 1]].filter((x) => x)) {
      check(pager.includes(neighbour), `${name}: no link to ${neighbour} in its pager`);
    }
  }
  await page.close();
}

async function searchGroup(browser, site) {
  const page = await browser.newPage({width: 1280, height: 800});
  const results = async (query) => {
    await page.goto(`file://${join(site, 'search.html')}?q=${encodeURIComponent(query)}`);
    await page.waitFor('document.body.dataset.searched === "true"');
    return page.evaluate(`[...document.querySelectorAll('#search-results li a')].map((a) => a.getAttribute('href'))`);
  };
  if (!existsSync(join(site, 'search.html'))) {
    failures.push('the site has no search page (search.html)');
    return;
  }
  const expectations = [
    ['3.6', (h) => h.startsWith('section3.html'), 'section 3'],
    ['eq-3.6', (h) => h.includes('#check-eq-3-6'), 'the check eq-3.6'],
    ['restitution', () => true, 'any page'],
    ...webPages(site).map((f) => [f.replace('.html', ''), (h) => h === f, f]),
  ];
  for (const [query, wanted, what] of expectations) {
    const found = await results(query);
    check(found.length > 0, `a search for "${query}" finds nothing`);
    check(found.some(wanted), `a search for "${query}" does not find ${what} (found ${found.slice(0, 5).join(', ')})`);
  }
  await page.close();
}

async function screenshotsGroup(browser, site, folder) {
  mkdirSync(folder, {recursive: true});
  for (const name of ['section3.html', 'check_report_3.html', 'lab_3.html']) {
    for (const width of [1280, 390]) {
      const viewport = {width, height: width === 390 ? 844 : 800, mobile: width === 390};
      const page = await browser.newPage(viewport);
      await open(page, `file://${join(site, name)}`);
      const file = join(folder, `${name.replace('.html', '')}-${width}.png`);
      await page.fullScreenshot(file, writeFile, viewport);
      console.log(`screenshot: ${file}`);
      await page.close();
    }
  }
}

// Each detector against a page made wrong on purpose: it must report it.
async function detectorsGroup(browser, site) {
  const scratch = mkdtempSync(join(tmpdir(), 'impulselab-site-detectors-'));
  try {
    const page = await browser.newPage({width: 390, height: 844, mobile: true});
    const html = (body) => `<!DOCTYPE html><html><head><meta name="viewport" content="width=device-width, initial-scale=1"/></head><body>${body}</body></html>`;
    const write = (name, body) => {
      writeFileSync(join(scratch, name), html(body));
      return `file://${join(scratch, name)}`;
    };
    // A page without the menu, too wide, with ** and a backtick in its text.
    await open(page, write('broken.html', '<p>Some **bold** and a `code` slip.</p><div style="width:1000px">wide</div><pre>**in code is fine**</pre>'));
    const menu = await page.evaluate(menuProblems(['section1.html']));
    const wide = await page.evaluate(widthProblems(390));
    const slips = await page.evaluate(slipProblems);
    check(menu.length === 1 && menu[0].includes('no menu'), `the menu detector missed a page without the menu: ${JSON.stringify(menu)}`);
    check(wide.length === 1 && wide[0].includes('px wide at 390 px: div'), `the width detector missed a page 1000 px wide: ${JSON.stringify(wide)}`);
    check(slips.length === 1 && slips[0].includes('**bold**'), `the Markdown detector missed ** and a backtick: ${JSON.stringify(slips)}`);
    // A formula that typesets, a \\frac left raw, a script from outside, two links to nowhere.
    if (site !== null) {
      symlinkSync(join(site, 'mathjax'), join(scratch, 'mathjax'));
      writeFileSync(join(scratch, 'math.html'), '<html><head><script type="text/x-mathjax-config">' +
        'MathJax.Hub.Config({extensions: ["tex2jax.js", "TeX/AMSmath.js"], jax: ["input/TeX", "output/HTML-CSS"]});' +
        '</script><script type="text/javascript" async="async" src="mathjax/MathJax.js"></script>' +
        '<script src="https://example.invalid/tracker.js"></script></head><body><p>\\[ a = b \\tag{9.9} \\]</p>' +
        '<p>Raw: \\frac{1}{2}</p><a href="missing.html">gone</a> <a href="math.html#nowhere">no anchor</a></body></html>');
      page.requests = [];
      await open(page, `file://${join(scratch, 'math.html')}`);
      const math = await page.evaluate(`(${mathProblemsInPage})()`);
      check(math.length === 1 && math[0].includes('\\frac{1}{2}'), `the MathJax detector: ${JSON.stringify(math)}`);
      const addresses = addressProblems(join(scratch, 'math.html'), await page.evaluate(`(${addressesInPage})()`), []);
      check(addresses.length === 3 && addresses.filter((p) => p.includes('outside')).length === 1,
            `the address detector: ${JSON.stringify(addresses)}`);
      check(JSON.stringify(page.requests.filter(leavesSite)) === '["https://example.invalid/tracker.js"]',
            `the request detector: ${JSON.stringify(page.requests)}`);
      // Without MathJax nothing is typeset: the TeX stays in the text.
      writeFileSync(join(scratch, 'plain.html'), '<html><body><p>\\[ a = b \\tag{9.9} \\]</p><p>Raw: \\frac{1}{2}</p></body></html>');
      await open(page, `file://${join(scratch, 'plain.html')}`);
      const plain = await page.evaluate(`(${mathProblemsInPage})()`);
      check(plain.length >= 3, `the MathJax detector on a page without MathJax: ${JSON.stringify(plain)}`);
    }
    // A menu without one entry.
    await open(page, write('menu.html', '<div id="main-nav"><ul id="main-menu"><li><a href="section1.html">§1</a></li></ul></div>'));
    const partial = await page.evaluate(menuProblems(['section1.html', 'notation.html']));
    check(partial.length === 1 && partial[0].includes('notation.html'), `the menu detector missed a missing entry: ${JSON.stringify(partial)}`);
    // A lab with more questions than answers, and one with an open answer.
    await open(page, write('lab.html', '<p><b>Question 1.</b> a?</p><details class="answer"><summary>Answer 1</summary>x</details><p><b>Question 2.</b> b?</p><p><b>Question 3.</b> c?</p><details class="answer" open><summary>Answer 3</summary>y</details>'));
    const lab = await page.evaluate(labProblems);
    check(lab.some((p) => p.includes('question 2 has no answer')) && lab.some((p) => p.includes('3 questions, 2 answers')) &&
          lab.some((p) => p.includes('answer 3 is open')), `the labs detector missed a missing and an open answer: ${JSON.stringify(lab)}`);
    await open(page, write('lab2.html', '<p><b>Question 1.</b> a?</p><details class="answer"><summary>Answer 1</summary>x</details><details class="answer"><summary>Answer 2</summary>y</details>'));
    const extra = await page.evaluate(labProblems);
    check(extra.some((p) => p.includes('follows no question')), `the labs detector missed an answer too many: ${JSON.stringify(extra)}`);
    // Symbols: a counterexample's ρ and F̄ against a glossary of m and p.
    const symbols = symbolsOf('\\rho = 1 \\times 10^{-17}, \\bar{F} = 0.5, m_{1} = 2, \\vec{p} = [0, 1], F\\,dt');
    check(['\\rho', '\\bar{F}', 'm', 'p', 'F', 'dt'].every((s) => symbols.has(s)) && !symbols.has('\\times'),
          `the symbols of a counterexample are read wrong: ${[...symbols].join(' ')}`);
    // A statement compared with the page's formulas.
    check(comparable('\\begin{gathered} a = b \\\\ c \\end{gathered}') === comparable('a = b \\\\ c') &&
          comparable('a = b') !== comparable('a = -b'), 'statements are compared wrong');
    await page.close();
  } finally {
    rmSync(scratch, {recursive: true, force: true});
  }
}

// --- main ----------------------------------------------------------------------------------------

const browser = await Browser.launch();
const started = Date.now();
try {
  if (group === 'detectors') {
    await detectorsGroup(browser, given.site === undefined ? null : option('site'));
  } else {
    const site = option('site');
    if (group === 'pages') {
      const n = await pagesGroup(browser, site, {only: given.only ? given.only.split(',') : null});
      console.log(`${n} pages opened at 390 px`);
    } else if (group === 'checks') {
      await checksGroup(browser, site, JSON.parse(readFileSync(option('report'), 'utf8')));
    } else if (group === 'labs') {
      await labsGroup(browser, site);
    } else if (group === 'search') {
      await searchGroup(browser, site);
    } else if (group === 'screenshots') {
      await screenshotsGroup(browser, site, option('screenshots'));
    } else {
      throw new Error(`unknown group ${group}`);
    }
  }
} finally {
  await browser.close();
}
console.log(`${group}: ${failures.length} failure${failures.length === 1 ? '' : 's'} (${((Date.now() - started) / 1000).toFixed(1)} s)`);
// How many of each kind, and the pages they are on (the list below stops at 200).
const kinds = [['menu', /menu/], ['wider than the window', /px wide at/], ['unrendered Markdown', /unrendered Markdown/],
  ['formulas', /raw TeX|no typeset output|equation number|MathJax reports|Math Processing/], ['links', /\(no (file|anchor) /],
  ['outside the site', /outside the site|asked the network/]];
for (const [kind, pattern] of kinds) {
  const matching = failures.filter((f) => pattern.test(f));
  if (matching.length > 0) {
    const pages = new Set(matching.map((f) => f.split(':')[0]));
    console.log(`  ${kind}: ${matching.length} on ${pages.size} page${pages.size === 1 ? '' : 's'}` +
                (pages.size <= 12 ? ` (${[...pages].join(', ')})` : ''));
  }
}
for (const f of failures.slice(0, 200)) {
  console.log(`  ${f}`);
}
if (failures.length > 200) {
  console.log(`  … and ${failures.length - 200} more`);
}
process.exit(failures.length === 0 ? 0 : 1);
