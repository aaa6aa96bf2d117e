// SPDX-License-Identifier: GPL-3.0-or-later
// The site's search page (search.html?q=…): every word of the query must appear in a part of a
// page (its title, heading or text, as docs/tools/site.cpp cut it into search-index.js); parts
// whose title or heading hold the query come first, then those that hold it most often. Works
// from disk, offline: the index is a script, not a request.
(function () {
  'use strict';
  const records = window.IMPULSELAB_SEARCH || [];
  const form = document.getElementById('search-form');
  const input = document.getElementById('search-query');
  const status = document.getElementById('search-status');
  const list = document.getElementById('search-results');
  if (!form || !input || !status || !list) {
    return;
  }
  const normal = (text) => text.toLowerCase();
  const lowered = records.map((r) => ({t: normal(r.t), h: normal(r.h), x: normal(r.x)}));

  function count(text, word) {
    let n = 0;
    for (let at = text.indexOf(word); at >= 0; at = text.indexOf(word, at + word.length)) {
      ++n;
    }
    return n;
  }

  // An equation number "3.6" is worth more where it stands as one: "(3.6)", not "13.6".
  function whole(text, word) {
    const escaped = word.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
    return new RegExp('(^|[^0-9a-z.])' + escaped + '($|[^0-9a-z])').test(text);
  }

  function snippet(text, word) {
    const at = Math.max(0, normal(text).indexOf(word));
    const from = Math.max(0, at - 80);
    const to = Math.min(text.length, at + word.length + 120);
    const before = (from > 0 ? '…' : '') + text.slice(from, at);
    const match = text.slice(at, at + word.length);
    const after = text.slice(at + word.length, to) + (to < text.length ? '…' : '');
    const p = document.createElement('p');
    p.className = 'search-snippet';
    p.append(before);
    const mark = document.createElement('mark');
    mark.textContent = match;
    p.append(mark, after);
    return p;
  }

  function search(query) {
    const words = normal(query).split(/\s+/).filter((w) => w !== '');
    if (words.length === 0) {
      return [];
    }
    const found = [];
    lowered.forEach((r, k) => {
      const all = r.t + ' ' + r.h + ' ' + r.x;
      if (!words.every((w) => all.includes(w))) {
        return;
      }
      let score = 0;
      for (const w of words) {
        score += (r.t.includes(w) ? 100 : 0) + (r.h.includes(w) ? 50 : 0) +
                 (whole(all, w) ? 20 : 0) + Math.min(count(r.x, w), 20);
      }
      found.push({k, score});
    });
    found.sort((a, b) => b.score - a.score || a.k - b.k);
    return found.map((f) => records[f.k]);
  }

  function show(query) {
    list.replaceChildren();
    const results = search(query);
    const shown = results.slice(0, 100);
    status.textContent = query.trim() === '' ? 'Type a word, an equation number (3.6) or a check (eq-3.6).'
      : results.length === 0 ? `Nothing found for “${query}”.`
      : `${results.length} part${results.length === 1 ? '' : 's'} of the site found for “${query}”` +
        (results.length > shown.length ? `, the first ${shown.length} shown.` : '.');
    const first = normal(query).split(/\s+/).filter((w) => w !== '')[0] || '';
    for (const r of shown) {
      const item = document.createElement('li');
      const link = document.createElement('a');
      link.href = r.u;
      link.textContent = r.h && r.h !== r.t ? `${r.t}: ${r.h}` : r.t;
      item.append(link, snippet(r.x, first));
      list.append(item);
    }
    document.body.dataset.searched = 'true';
  }

  const query = new URLSearchParams(window.location.search).get('q') || '';
  input.value = query;
  show(query);
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    const url = new URL(window.location.href);
    url.searchParams.set('q', input.value);
    window.history.replaceState(null, '', url.toString());
    show(input.value);
  });
})();
