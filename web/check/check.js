// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation page (contract: check-page.md): an editor whose text is in the address, and each
// display equation's verdict beside it, as ImpulseLab's derivation checker gives it. The checker
// runs in a Web Worker (check_worker.js, started from the text of impulselab-check.js): nothing of
// it is written again here; this script only edits, asks and shows.
(() => {
  'use strict';

  const $ = (id) => document.getElementById(id);
  const examples = window.impulselabDerivations || [];
  const defaultExample = 'elastic-line';
  // A check starts this long after the last keystroke; one check runs at a time, and the text
  // typed meanwhile is checked next (never a queue of stale texts).
  const debounceMs = 60;
  // A check of a text the reader has since changed is abandoned (the worker restarted) once it
  // has run this long (the step budget bounds each step, not a whole file; starting the worker
  // again costs about a second, so a check that ends soon is better awaited).
  const abandonAfterMs = 4000;
  // Chromium keeps addresses up to 2 MB; a longer text is not written into the address.
  const longestAddress = 2000000;
  const failing = new Set(['does-not-follow', 'dimensions', 'undecided']);
  const verdictWords = {
    'premise': 'premise', 'follows': 'follows', 'follows-one-way': 'follows one way',
    'follows-if': 'follows if', 'does-not-follow': 'does not follow', 'dimensions': 'dimensions',
    'undecided': 'undecided',
  };
  // One mark per verdict in the editor's margin (STACK's equivalence display): the worst of a line.
  const marginMarks = {
    'premise': '·', 'follows': '✓', 'follows-one-way': '⇒', 'follows-if': '?', 'undecided': '…',
    'dimensions': '✗', 'does-not-follow': '✗',
  };
  const severity = ['premise', 'follows', 'follows-one-way', 'follows-if', 'undecided', 'dimensions',
                    'does-not-follow'];

  // The address: #file= and the text (encodeURIComponent; bytes that are not UTF-8 as %XX), or
  // #example=NAME.
  const {encodeBytes, decodeFragment, utf8Text, download, opened} = window.impulselabFiles;

  // ---------------------------------------------------------------------------------------------
  // State.

  const state = {
    text: '',           // the editor's text
    bytes: null,        // the file's bytes when they are not UTF-8 (until the reader edits them)
    example: null,      // the example whose text this is, or null
    worker: null,
    workerReady: false,
    nextId: 1,
    inFlight: null,     // {id, text, bytes, started} of the check running
    shownId: 0,         // the check whose answer is shown
    wanted: null,       // {id, text, bytes}: the text whose answer is wanted next
    timer: null,        // the debounce of keystrokes
    abandonTimer: null, // when the check running is abandoned for a newer text
    lastHash: null,
    report: null,       // the parsed report shown, or null
    errorPlace: null,   // {line, column, message} of the refusal shown
    changedAt: null,    // when the text last changed (the event's time)
  };
  // For measurements (web/test/check_measure.mjs): when the worker was ready, and for each answer
  // shown, when its text changed, when it was sent to the worker and when it was shown
  // (performance.now(), ms since the page began loading), and the check's own time in the worker.
  const times = {workerReady: null, answers: []};
  window.impulselabCheckTimes = times;

  function exampleNamed(name) {
    return examples.find((e) => e.name === name) || null;
  }

  function exampleWithText(text) {
    return examples.find((e) => e.text === text) || null;
  }

  // The name the report gives the file (check-page.md): the example's, or "check.html".
  function fileName() {
    return state.bytes === null && state.example ? state.example.name : 'check.html';
  }

  // ---------------------------------------------------------------------------------------------
  // The worker.

  function startWorker() {
    if (typeof impulselabCheckModule !== 'function' || typeof impulselabCheckWorker !== 'function') {
      showFailure('The checker (impulselab-check.js) did not load.');
      return;
    }
    const source = `var impulselabCheckModule = ${impulselabCheckModule.toString()};\n` +
                   'var createImpulseLabCheck = impulselabCheckModule();\n' +
                   `(${impulselabCheckWorker.toString()})();\n`;
    const url = URL.createObjectURL(new Blob([source], {type: 'text/javascript'}));
    state.workerReady = false;
    state.worker = new Worker(url);
    URL.revokeObjectURL(url);
    state.worker.onmessage = (event) => receive(event.data);
    state.worker.onerror = (event) => {
      event.preventDefault();
      showFailure(`The checker stopped: ${event.message || 'an error in its worker'}.`);
    };
  }

  function restartWorker() {
    clearTimeout(state.abandonTimer);
    if (state.worker) {
      state.worker.terminate();
    }
    state.inFlight = null;
    startWorker();
  }

  function receive(message) {
    if (message.ready) {
      times.workerReady = performance.now();
      state.workerReady = true;
      state.moduleSeconds = message.seconds;
      pump();
      return;
    }
    if (message.failed) {
      showFailure(`The checker could not start: ${message.failed}`);
      return;
    }
    if (!state.inFlight || message.id !== state.inFlight.id) {
      return;  // the answer of an abandoned check
    }
    const asked = state.inFlight;
    state.inFlight = null;
    clearTimeout(state.abandonTimer);
    if (message.crashed) {
      message.result = '';
      message.error = `internal error (please report it): the checker stopped: ${message.crashed}`;
      message.line = message.column = 0;
      restartWorker();
    }
    // Shown only if it is the answer for the text in the editor now; otherwise the text typed
    // since is checked next.
    if (asked.text === state.text && asked.bytes === state.bytes) {
      show(message, asked);
    }
    pump();
  }

  // Sends the text wanted to the worker when it is free.
  function pump() {
    if (!state.workerReady || state.wanted === null) {
      return;
    }
    if (state.inFlight) {
      // The check running is of an older text: abandoned once it has run too long.
      const left = abandonAfterMs - (performance.now() - state.inFlight.started);
      clearTimeout(state.abandonTimer);
      if (left <= 0) {
        restartWorker();
      } else {
        state.abandonTimer = setTimeout(pump, left);
      }
      return;
    }
    const wanted = state.wanted;
    state.wanted = null;
    state.inFlight = {...wanted, started: performance.now()};
    state.worker.postMessage({id: wanted.id, text: wanted.bytes !== null ? wanted.bytes : wanted.text,
                              file: wanted.file});
    status('Checking…');
  }

  // Asks for the current text to be checked, after @p delay ms without another change.
  function requestCheck(delay) {
    document.body.dataset.ready = 'false';
    clearTimeout(state.timer);
    const ask = () => {
      state.wanted = {id: state.nextId++, text: state.text, bytes: state.bytes, file: fileName(),
                      changedAt: state.changedAt};
      pump();
    };
    if (delay > 0) {
      state.timer = setTimeout(ask, delay);
    } else {
      ask();
    }
  }

  // ---------------------------------------------------------------------------------------------
  // The editor: a textarea, a margin of line numbers and verdict marks, and a layer behind the text
  // that marks lines (the first failing one, the refused one).

  const editor = $('editor');
  const gutter = $('gutter');
  const marks = $('marks');

  function lineHeight() {
    return parseFloat(getComputedStyle(editor).lineHeight);
  }

  function lineCount() {
    let n = 1;
    for (let i = state.text.indexOf('\n'); i >= 0; i = state.text.indexOf('\n', i + 1)) {
      ++n;
    }
    return n;
  }

  // The margin: every line's number (a keystroke adds or removes only the lines it changed), and
  // the mark of the worst verdict of the equations that begin on a line, or of the refusal.
  function drawLineNumbers() {
    const n = lineCount();
    while (gutter.children.length < n) {
      const number = document.createElement('div');
      number.textContent = String(gutter.children.length + 1);
      gutter.appendChild(number);
    }
    while (gutter.children.length > n) {
      gutter.lastChild.remove();
    }
  }

  function drawGutter() {
    drawLineNumbers();
    for (const number of gutter.querySelectorAll('div[class]')) {
      number.removeAttribute('class');
      number.removeAttribute('title');
      number.textContent = number.textContent.replace(/[^0-9]/g, '');
    }
    const byLine = new Map();
    if (state.errorPlace) {
      byLine.set(state.errorPlace.line, 'refused');
    } else if (state.report) {
      for (const e of state.report.equations) {
        const before = byLine.get(e.line);
        if (!before || severity.indexOf(e.verdict) > severity.indexOf(before)) {
          byLine.set(e.line, e.verdict);
        }
      }
    }
    for (const [line, verdict] of byLine) {
      const number = gutter.children[line - 1];
      if (!number) {
        continue;
      }
      const mark = document.createElement('span');
      mark.className = 'mark-in-margin';
      mark.textContent = verdict === 'refused' ? '!' : marginMarks[verdict];
      number.className = verdict;
      number.title = verdict === 'refused' ? 'refused here' : verdictWords[verdict];
      number.appendChild(mark);
    }
    syncScroll();
  }

  // The layer behind the text: the first failing equation's line, the refused line (with the
  // message under it).
  function drawMarks() {
    marks.innerHTML = '';
    const h = lineHeight();
    const top = parseFloat(getComputedStyle(editor).paddingTop);
    const add = (line, cls, message) => {
      const band = document.createElement('div');
      band.className = `line-mark ${cls}`;
      band.style.top = `${top + (line - 1) * h}px`;
      band.style.height = `${h}px`;
      marks.appendChild(band);
      if (message) {
        const note = document.createElement('div');
        note.className = `line-note ${cls}`;
        note.style.top = `${top + line * h}px`;
        note.textContent = message;
        marks.appendChild(note);
      }
    };
    if (state.errorPlace) {
      add(state.errorPlace.line, 'refused', state.errorPlace.message);
    } else if (state.report) {
      const first = state.report.equations.find((e) => failing.has(e.verdict));
      if (first) {
        add(first.line, 'first-failure', null);
      }
    }
    syncScroll();
  }

  function syncScroll() {
    gutter.style.transform = `translateY(${-editor.scrollTop}px)`;
    marks.style.transform = `translate(${-editor.scrollLeft}px, ${-editor.scrollTop}px)`;
  }

  // Puts the caret at the start of @p line (1-based), column @p column, and the line in view.
  function goToLine(line, column = 1) {
    const lines = state.text.split('\n');
    let offset = 0;
    for (let i = 0; i < Math.min(line - 1, lines.length); ++i) {
      offset += lines[i].length + 1;
    }
    offset += Math.max(0, Math.min(column - 1, (lines[line - 1] || '').length));
    editor.focus();
    editor.setSelectionRange(offset, offset);
    const h = lineHeight();
    const y = (line - 1) * h;
    if (y < editor.scrollTop || y > editor.scrollTop + editor.clientHeight - 2 * h) {
      editor.scrollTop = Math.max(0, y - editor.clientHeight / 3);
    }
    syncScroll();
  }

  // ---------------------------------------------------------------------------------------------
  // Showing an answer.

  function status(text) {
    $('status').textContent = text;
  }

  function showFailure(text) {
    status(text);
    $('check-error').textContent = text;
    document.body.dataset.ready = 'true';
  }

  function escapeHtml(text) {
    return String(text).replace(/[&<>"']/g, (c) => ({'&': '&amp;', '<': '&lt;', '>': '&gt;',
                                                     '"': '&quot;', '\'': '&#39;'})[c]);
  }

  function plural(n, one, many) {
    return `${n} ${n === 1 ? one : many}`;
  }

  function show(answer, asked) {
    state.shownId = asked.id;
    state.errorPlace = null;
    state.report = null;
    $('result-json').textContent = answer.result;
    $('check-error').textContent = answer.error;
    if (answer.error) {
      if (answer.line > 0) {
        state.errorPlace = {line: answer.line, column: answer.column, message: answer.error};
      }
      status(`Refused${answer.line > 0 ? ` at line ${answer.line}, column ${answer.column}` : ''}: ` +
             'nothing is checked until the file can be read.');
      $('summary').textContent = 'Nothing is checked until the file can be read: ' +
                                 (answer.line > 0 ? `see line ${answer.line} in the editor.` : answer.error);
      $('equations').innerHTML = '';
      showNotes([]);
    } else {
      state.report = JSON.parse(answer.result);
      showReport(state.report, answer.seconds);
    }
    drawGutter();
    drawMarks();
    // For programs: how many answers were shown (a test waits for the next), and that this one is.
    document.body.dataset.shown = String(Number(document.body.dataset.shown || 0) + 1);
    times.answers.push({changed: asked.changedAt, sent: asked.started, shown: performance.now(),
                        worker: answer.seconds * 1000});
    document.body.dataset.ready = 'true';
  }

  // What the file holds that is not checked (an equation in inline math on a line of its own), as
  // the report's notes say it.
  function showNotes(notes) {
    const list = $('notes');
    list.replaceChildren(...notes.map((n) => {
      const item = document.createElement('li');
      item.innerHTML = `Line ${n.line}: <code>${escapeHtml(n.written)}</code> is ${escapeHtml(n.text)}.`;
      return item;
    }));
    list.hidden = notes.length === 0;
  }

  function showReport(report, seconds) {
    const s = report.summary;
    const parts = [];
    for (const verdict of severity) {
      if (s[verdict] > 0) {
        parts.push(`${s[verdict]} ${verdictWords[verdict]}`);
      }
    }
    const first = report.equations.find((e) => failing.has(e.verdict));
    $('summary').innerHTML = report.equations.length === 0 ? 'No display equation.' :
      `${plural(report.equations.length, 'equation', 'equations')}: ${escapeHtml(parts.join(', '))}.` +
      (first ? ` <a href="#" class="first-failure-link" data-line="${first.line}">The first that does not ` +
               `pass: line ${first.line}</a>.` : ' Every step passes.');
    status(`Checked in ${seconds.toFixed(2)} s${first ? `; the first equation that does not pass is on line ${first.line}` : ''}.`);
    showNotes(report.notes || []);
    const list = $('equations');
    list.replaceChildren();  // first, so that each formula typeset before can move into the new list
    list.append(...report.equations.map((e) => equationItem(e, e === first)));
    typesetPending();
  }

  // ---------------------------------------------------------------------------------------------
  // Formulas: typeset by the site's MathJax, each LaTeX once (a keystroke re-typesets only the
  // equations it changed).

  const typeset = new Map();  // LaTeX (display or inline) → its element, typeset or queued
  let pendingTypeset = [];

  function formula(latex, display = true) {
    const key = `${display ? 'D' : 'I'}${latex}`;
    const make = () => {
      const element = document.createElement(display ? 'div' : 'span');
      element.className = display ? 'math display' : 'math';
      const script = document.createElement('script');
      script.type = display ? 'math/tex; mode=display' : 'math/tex';
      script.text = latex;
      element.appendChild(script);
      pendingTypeset.push(element);
      return element;
    };
    let element = typeset.get(key);
    if (!element) {
      element = make();
      typeset.set(key, element);
    } else if (element.isConnected) {
      element = make();  // the same formula twice in one report: typeset twice
    }
    return element;
  }

  function mathJaxReady() {
    return window.MathJax && window.MathJax.Hub && typeof window.MathJax.Hub.Queue === 'function';
  }

  function typesetPending() {
    if (!mathJaxReady() || pendingTypeset.length === 0) {
      return;
    }
    const elements = pendingTypeset.filter((e) => e.isConnected);
    pendingTypeset = pendingTypeset.filter((e) => !e.isConnected);
    if (elements.length > 0) {
      window.MathJax.Hub.Queue(['Typeset', window.MathJax.Hub, elements]);
    }
    if (typeset.size > 2000) {  // a long session: forget what is no longer shown
      for (const [key, element] of typeset) {
        if (!element.isConnected) {
          typeset.delete(key);
        }
      }
    }
  }
  document.addEventListener('mathjax-ready', typesetPending);

  // An exact value of a counterexample ("1/3", "-2") as LaTeX; anything else as text.
  function exactTex(value) {
    const m = String(value).match(/^(-?)([0-9]+)\/([0-9]+)$/);
    if (m) {
      return `${m[1]}\\tfrac{${m[2]}}{${m[3]}}`;
    }
    return /^-?[0-9]+$/.test(value) ? value : `\\text{${String(value).replace(/[{}\\]/g, '')}}`;
  }

  function numberTex(x) {
    if (typeof x !== 'number' || !isFinite(x)) {
      return `\\text{${x}}`;
    }
    const text = Number(x.toPrecision(6)).toString();
    const m = text.match(/^(-?[0-9.]+)e([+-]?[0-9]+)$/);
    return m ? `${m[1]} \\cdot 10^{${Number(m[2])}}` : text;
  }

  function counterexampleTex(e) {
    const exact = e.counterexample_exact || null;
    const parts = Object.entries(e.counterexample).map(([symbol, value]) => {
      const x = exact ? exact[symbol] : value;
      const write = (v, i) => (exact ? exactTex(v) : numberTex(Array.isArray(value) ? value[i] : v));
      const shown = Array.isArray(x) ? `\\left[${write(x[0], 0)},\\ ${write(x[1], 1)}\\right]` : write(x);
      return `${symbol} = ${shown}`;
    });
    return parts.join(',\\quad ');
  }

  // One equation of the report: its line, its verdict, the equation typeset, and what the
  // verdict carries (the condition, the residual and counterexample, the dimensions, how).
  function equationItem(e, first) {
    const li = document.createElement('li');
    li.className = `equation ${e.verdict}${first ? ' first-failure' : ''}`;
    const head = document.createElement('div');
    head.className = 'equation-head';
    const go = document.createElement('button');
    go.type = 'button';
    go.className = 'line-button';
    go.textContent = `line ${e.line}`;
    go.setAttribute('aria-label', `line ${e.line}, column ${e.column}: go to it in the editor`);
    go.addEventListener('click', () => goToLine(e.line, e.column));
    const verdict = document.createElement('span');
    verdict.className = `mark ${e.verdict}`;
    verdict.textContent = verdictWords[e.verdict] || e.verdict;
    head.append(go, verdict);
    if (e.tag !== null) {
      const tag = document.createElement('span');
      tag.className = 'tag';
      tag.textContent = `(${e.tag})`;
      head.append(tag);
    }
    if (first) {
      const note = document.createElement('span');
      note.className = 'first-note';
      note.textContent = 'the first that does not pass';
      head.append(note);
    }
    li.append(head, formula(e.latex));
    const details = document.createElement('div');
    details.className = 'details';
    const line = (label, content) => {
      const p = document.createElement('p');
      const b = document.createElement('span');
      b.className = 'label';
      b.textContent = `${label} `;
      p.append(b, ...content);
      details.append(p);
    };
    if (e.verdict === 'follows-if') {
      line('Condition:', [formula(e.condition, false)]);
      if (e.condition_needed === false) {
        line('', [document.createTextNode('(not shown to be needed)')]);
      }
    }
    if (e.verdict === 'does-not-follow') {
      line('What is left over:', [formula(e.residual, false)]);
      if (e.counterexample && Object.keys(e.counterexample).length > 0) {
        line(e.counterexample_exact ? 'Values that break it (exact):' : 'Values that break it:',
             [formula(counterexampleTex(e), false)]);
      }
    }
    if (e.verdict === 'dimensions') {
      line('Dimensions:', [document.createTextNode(`${e.dimensions[0]} against ${e.dimensions[1]}` +
                                                   (e.dimensions_text ? `: ${e.dimensions_text}` : ''))]);
    }
    if (e.from && e.from.length > 0) {
      line('Checked against:', [document.createTextNode(`line ${e.from.join(', line ')}`)]);
    }
    if (e.how) {
      // Its formulas ($…$) typeset too.
      const parts = e.how.split(/\$([^$]*)\$/).map((part, k) => (k % 2 === 1 ? formula(part, false)
                                                                        : document.createTextNode(part)));
      line(e.decided_by ? `How (${e.decided_by}):` : 'What was tried:', parts);
    }
    if (details.childNodes.length > 0) {
      li.append(details);
    }
    return li;
  }

  // ---------------------------------------------------------------------------------------------
  // Loading a text: from the address, the menu, a file, or the keyboard.

  function fillMenu() {
    const menu = $('example');
    const own = document.createElement('option');
    own.value = '';
    own.textContent = '(your own text)';
    menu.appendChild(own);
    const groups = new Map();
    for (const e of examples) {
      if (!groups.has(e.group)) {
        const g = document.createElement('optgroup');
        g.label = e.group;
        groups.set(e.group, g);
        menu.appendChild(g);
      }
      const option = document.createElement('option');
      option.value = e.name;
      option.textContent = e.label;
      groups.get(e.group).appendChild(option);
    }
  }

  // Shows @p content (a string, or bytes that are not UTF-8) in the editor and checks it.
  function load(content, {hash = null} = {}) {
    state.changedAt = performance.now();
    if (typeof content === 'string') {
      state.text = content;
      state.bytes = null;
    } else {
      state.bytes = content;
      state.text = new TextDecoder().decode(content);  // shown with U+FFFD where bytes are not UTF-8
    }
    state.example = state.bytes === null ? exampleWithText(state.text) : null;
    editor.value = state.text;
    editor.scrollTop = 0;
    $('example').value = state.example ? state.example.name : '';
    writeAddress(hash);
    drawGutter();
    requestCheck(0);
  }

  function writeAddress(hash = null) {
    if (hash === null) {
      hash = '#file=' + (state.bytes !== null ? encodeBytes(state.bytes) : encodeURIComponent(state.text));
    }
    if (hash.length > longestAddress) {
      status('This text is too long for the address: use "Download" to keep it.');
      return;
    }
    state.lastHash = hash;
    if (location.hash !== hash) {
      history.replaceState(null, '', hash);
    }
  }

  function loadFromAddress() {
    const hash = location.hash;
    if (hash.startsWith('#file=')) {
      const bytes = decodeFragment(hash.slice('#file='.length));
      const text = utf8Text(bytes);
      load(text !== null ? text : bytes, {hash});
      return;
    }
    if (hash.startsWith('#example=')) {
      const name = decodeURIComponent(hash.slice('#example='.length));
      const example = exampleNamed(name);
      if (example) {
        load(example.text, {hash});
        return;
      }
      status(`There is no example named "${name}": the page opened on another.`);
    }
    const fallback = exampleNamed(defaultExample) || examples[0];
    state.lastHash = location.hash;
    if (fallback) {
      load(fallback.text, {hash: location.hash});
    } else {
      load('', {hash: location.hash});
    }
  }

  editor.addEventListener('input', (event) => {
    state.changedAt = event.timeStamp;
    state.text = editor.value;
    state.bytes = null;  // edited: the text as shown is the file now
    state.example = exampleWithText(state.text);
    $('example').value = state.example ? state.example.name : '';
    writeAddress();
    drawLineNumbers();  // the margin follows a scroll by itself (the scroll event)
    requestCheck(debounceMs);
  });
  editor.addEventListener('scroll', syncScroll);

  $('example').addEventListener('change', (event) => {
    const example = exampleNamed(event.target.value);
    if (example) {
      load(example.text, {hash: `#example=${encodeURIComponent(example.name)}`});
    }
  });

  $('open-file').addEventListener('change', async (event) => {
    const content = await opened(event);
    if (content !== null) {
      load(content);
    }
  });

  $('download').addEventListener('click', () => {
    download(state.bytes !== null ? state.bytes : state.text,
             `${state.example ? state.example.name : 'derivation'}.md`, 'text/markdown');
  });

  $('summary').addEventListener('click', (event) => {
    const link = event.target.closest('.first-failure-link');
    if (link) {
      event.preventDefault();
      goToLine(Number(link.dataset.line));
    }
  });

  window.addEventListener('hashchange', () => {
    if (location.hash !== state.lastHash) {
      loadFromAddress();
    }
  });
  window.addEventListener('resize', drawMarks);

  fillMenu();
  startWorker();
  loadFromAddress();
})();
