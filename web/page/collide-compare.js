// SPDX-License-Identifier: GPL-3.0-or-later
// Side by side and swept: the scene resolved by the three methods, or by the three laws of
// restitution, in columns (what `impulselab solve --compare` and `--compare restitution` print,
// Module.compareScene), and the kinetic energy after and each impulse plotted against the
// elasticity every body collides at (what `impulselab sweep` writes, Module.sweepScene). Both are
// computed after the scene's own result is drawn, and only while they are shown.
'use strict';

(function (collide) {
  const {$, isObject, num, vec, escapeHtml, colour, state} = collide;
  const svgNS = 'http://www.w3.org/2000/svg';
  let pending = 0;

  // Called after every update of the scene: the views shown follow it, once the result is drawn.
  collide.refreshSideViews = () => {
    clearTimeout(pending);
    const compare = $('compare').value;
    const sweep = $('sweep-box').open;
    if (!compare) {
      clearCompare();
    }
    if (!compare && !sweep) {
      return;
    }
    pending = setTimeout(() => {
      if (compare) {
        collide.timed('compare', renderCompare);
      }
      if (sweep) {
        collide.timed('sweep', renderSweep);
      }
    }, 0);
  };

  function clearCompare() {
    $('compare-view').textContent = '';
    $('compare-json').textContent = '';
    $('compare-warnings').textContent = '';
    $('compare-error').textContent = '';
  }

  // ---------------------------------------------------------------------------------------------
  // The three methods, or the three laws, side by side.

  const methodNames = {simultaneous: 'The paper\'s system', complementarity: 'Complementarity', serial: 'Serial collisions',
                       newton: 'Newton\'s law', poisson: 'Poisson\'s law', energetic: 'Energetic law'};

  function renderCompare() {
    const what = $('compare').value;
    const input = state.bytes !== null ? state.bytes : state.text;
    const out = state.module.compareScene(input, what);
    $('compare-json').textContent = out.result;
    $('compare-error').textContent = out.error;
    $('compare-warnings').innerHTML = [...out.warnings, ...(out.unfinished ? out.unfinished.split('\n') : [])]
        .map((w) => `<li>${escapeHtml(w)}</li>`).join('');
    const view = $('compare-view');
    view.dataset.shows = `${what} ${state.version}`;  // which comparison of which scene (for the tests)
    if (!out.result) {
      view.textContent = '';
      return;
    }
    const results = JSON.parse(out.result);
    const names = Object.keys(results);
    const solved = names.filter((n) => !results[n].error);
    const first = results[solved[0]];
    if (!first) {
      view.textContent = '';
      return;
    }
    const dim = first.bodies.length && Array.isArray(first.bodies[0].velocity) ? 2 : 1;
    const cell = (n, f) => (results[n].error ? '–' : f(results[n]));
    const largestImpulse = Math.max(0, ...solved.flatMap((n) => results[n].impulses.map((i) => Math.abs(i.magnitude))));
    const rows = [];
    const impulses = first.impulses.slice(0, 12);
    for (const i of impulses) {
      rows.push([`F dt, contact ${i.contact} (${i.bumper}–${i.wedge})`, ...names.map((n) => cell(n, (r) => {
        const j = r.impulses[i.contact];
        return num(j.magnitude, largestImpulse) + (j.tangential !== undefined ? `, tangential ${num(j.tangential, largestImpulse)}` : '');
      }))]);
    }
    const speeds = Math.max(0, ...solved.flatMap((n) => results[n].bodies.map((b) => collide.norm(vec(b.velocity)))));
    const kinds = state.details ? state.details.bodies.map((b) => b.kind) : [];
    for (const [k, b] of first.bodies.slice(0, 12).entries()) {
      if (kinds[k] === 'static') {
        continue;
      }
      rows.push([`Velocity after, ${b.name}`, ...names.map((n) => cell(n, (r) => collide.vectorText(r.bodies[k].velocity, dim, speeds)))]);
      if (b.angular_velocity !== undefined) {
        rows.push([`Spin after, ${b.name}`, ...names.map((n) => cell(n, (r) => num(r.bodies[k].angular_velocity)))]);
      }
    }
    for (const c of first.contacts.slice(0, 12)) {
      rows.push([`Approach after, contact ${c.contact}`, ...names.map((n) => cell(n, (r) => num(r.contacts[c.contact].approach_after, speeds)))]);
    }
    const energy = first.energy.before;
    rows.push(['Kinetic energy after (before: ' + num(energy) + ')',
               ...names.map((n) => cell(n, (r) => num(r.energy.after, energy)))]);
    rows.push(['Momentum after', ...names.map((n) => cell(n, (r) => collide.vectorText(r.momentum.after, dim, collide.norm(vec(r.momentum.before)))))]);
    rows.push(['How it went', ...names.map((n) => (results[n].error ? results[n].error : summary(results[n])))]);
    let html = '<div class="table-box"><table id="compare-table"><thead><tr><th class="name"></th>' +
               names.map((n) => `<th>${escapeHtml(methodNames[n] || n)}</th>`).join('') + '</tr></thead><tbody>';
    for (const row of rows) {
      html += `<tr><th class="name" scope="row">${escapeHtml(row[0])}</th>` + row.slice(1).map((x) => `<td>${escapeHtml(x)}</td>`).join('') + '</tr>';
    }
    html += '</tbody>';
    if (first.impulses.length > impulses.length) {
      html += `<caption>The first ${impulses.length} of ${first.impulses.length} contacts (all of them in the JSON below)</caption>`;
    }
    view.innerHTML = html + '</table></div>' + energyBars(results, names);
  }

  function summary(r) {
    const block = r.method && isObject(r[r.method]) ? r[r.method] : null;
    if (block && typeof block.collisions === 'number') {
      return `${block.collisions} collision${block.collisions === 1 ? '' : 's'} in ${block.passes} pass${block.passes === 1 ? '' : 'es'}`;
    }
    if (block && typeof block.algorithm === 'string') {
      return `${block.algorithm}, ${block.iterations} iteration${block.iterations === 1 ? '' : 's'}`;
    }
    if (block && typeof block.phases === 'string') {
      return `the exact single-contact rule: ${block.phases}`;
    }
    return `rank ${r.system.rank}, residual ${num(r.system.residual)}`;
  }

  // The kinetic energy after of each column, as bars against the energy before (dashed).
  function energyBars(results, names) {
    const solved = names.filter((n) => !results[n].error);
    const before = results[solved[0]].energy.before;
    const largest = Math.max(before, ...solved.map((n) => results[n].energy.after), 1e-300);
    const width = 520;
    const left = 150;
    const scale = (width - left - 70) / largest;
    const height = 26 * names.length + 10;
    let svg = `<svg xmlns="${svgNS}" class="chart" viewBox="0 0 ${width} ${height}" role="img" aria-label="Kinetic energy after, ` +
              `each column against the energy before (${num(before)})">`;
    names.forEach((n, k) => {
      const y = 6 + 26 * k;
      svg += `<text x="${left - 6}" y="${y + 14}" text-anchor="end">${escapeHtml(methodNames[n] || n)}</text>`;
      if (!results[n].error) {
        const e = results[n].energy.after;
        svg += `<rect x="${left}" y="${y}" width="${Math.max(0, e * scale).toFixed(2)}" height="18" fill="${colour(k)}" fill-opacity="0.75"/>` +
               `<text x="${(left + Math.max(0, e * scale) + 6).toFixed(2)}" y="${y + 14}">${num(e, before)}</text>`;
      }
    });
    const mark = (left + before * scale).toFixed(2);
    svg += `<line x1="${mark}" y1="0" x2="${mark}" y2="${height}" stroke="#1d2430" stroke-dasharray="4 3"/>`;
    return `<div class="chart compare-energy">${svg}</svg></div>`;
  }

  $('compare').addEventListener('change', collide.refreshSideViews);

  // ---------------------------------------------------------------------------------------------
  // The sweep.

  // The elasticities of FROM:TO:STEP as `impulselab sweep` lays them out: FROM + i·STEP while not
  // past TO, and TO itself when the grid meets it within rounding.
  collide.sweepGrid = (from, to, step) => {
    if (!(isFinite(from) && isFinite(to) && step > 0 && from >= 0 && from <= to)) {
      return null;
    }
    const steps = (to - from) / step;
    const nearest = Math.round(steps);
    const whole = Math.abs(steps - nearest) <= 1e-9 * Math.max(1, steps) ? nearest : Math.floor(steps);
    if (whole + 1 > 2001) {
      return null;
    }
    const values = [];
    for (let i = 0; i <= whole; ++i) {
      const e = from + i * step;
      values.push(i === whole && Math.abs(e - to) <= 1e-9 * step ? to : Math.min(e, to));
    }
    return values;
  };

  function renderSweep() {
    $('sweep-chart').dataset.shows = String(state.version);  // which scene (for the tests)
    const from = $('sweep-from').valueAsNumber;
    const to = $('sweep-to').valueAsNumber;
    const step = $('sweep-step').valueAsNumber;
    const grid = collide.sweepGrid(from, to, step);
    const chart = $('sweep-chart');
    if (!grid) {
      $('sweep-error').textContent = 'The range: from at least 0, to at least from, a positive step, at most 2001 values.';
      chart.textContent = '';
      $('sweep-csv').textContent = '';
      return;
    }
    const input = state.bytes !== null ? state.bytes : state.text;
    const out = state.module.sweepScene(input, grid);
    $('sweep-error').textContent = out.error;
    const rows = JSON.parse(out.rows);
    if (!rows.length) {
      chart.textContent = '';
      $('sweep-csv').textContent = '';
      return;
    }
    const contacts = (rows[0].length - 3) / 2;
    const header = ['elasticity', 'energy_after', 'energy_change', ...[...Array(contacts).keys()].map((v) => `impulse_${v}`),
                    ...[...Array(contacts).keys()].map((v) => `approach_after_${v}`)];
    $('sweep-csv').textContent = [header.join(','), ...rows.map((r) => r.map((x) => String(x + 0)).join(','))].join('\n') + '\n';
    const before = rows[0][1] - rows[0][2];
    // The scene's own elasticity, when every body collides at it.
    const scene = state.scene;
    const own = scene && typeof scene.elasticity === 'number' && scene.bodies.every((b) => b.elasticity === undefined)
                    ? scene.elasticity : undefined;
    const names = scene ? scene.contacts.map((c) => `${c.bumper}–${c.wedge}`) : [];
    chart.innerHTML = plot('Kinetic energy after', rows, [{column: 1, colour: '#1d2430', name: 'energy after'}], own, before, 'energy before') +
                      plot('Impulse F dt at each contact', rows,
                           [...Array(Math.min(contacts, 12)).keys()].map((v) => ({column: 3 + v, colour: colour(v),
                                                                                 name: `contact ${v}${names[v] ? ` (${names[v]})` : ''}`})), own);
    chart.insertAdjacentHTML('beforeend', `<p class="legend">${[...Array(Math.min(contacts, 12)).keys()].map((v) =>
        `<span style="color:${colour(v)}">— contact ${v}${names[v] ? ` (${escapeHtml(names[v])})` : ''}</span>`).join(' ')}` +
        `${contacts > 12 ? ` (the first 12 of ${contacts}; all in the rows below)` : ''}</p>`);
  }

  // A line chart of @p rows (x: column 0) for @p series; @p level a dashed line across (the
  // energy before), the elasticities 1 and 2 marked, and @p own (the scene's, when it has one).
  function plot(title, rows, series, own, level, levelName) {
    const width = 520;
    const height = 190;
    const pad = {left: 54, right: 12, top: 22, bottom: 30};
    const xs = rows.map((r) => r[0]);
    const ys = rows.flatMap((r) => series.map((s) => r[s.column])).concat(level !== undefined ? [level] : []);
    const x0 = Math.min(...xs);
    const x1 = Math.max(...xs, x0 + 1e-9);
    let y0 = Math.min(0, ...ys);
    let y1 = Math.max(...ys);
    if (!(y1 > y0)) {
      y1 = y0 + 1;
    }
    const X = (x) => pad.left + (x - x0) / (x1 - x0) * (width - pad.left - pad.right);
    const Y = (y) => height - pad.bottom - (y - y0) / (y1 - y0) * (height - pad.top - pad.bottom);
    let svg = `<svg xmlns="${svgNS}" viewBox="0 0 ${width} ${height}" role="img" aria-label="${escapeHtml(title)} against the elasticity, ` +
              `from ${num(x0)} to ${num(x1)}">`;
    svg += `<text x="${pad.left}" y="14">${escapeHtml(title)}</text>`;
    svg += `<line x1="${pad.left}" y1="${Y(0)}" x2="${width - pad.right}" y2="${Y(0)}" stroke="#c9d0da"/>`;
    for (const [e, word] of [[1, 'inelastic'], [2, 'elastic']]) {
      if (e >= x0 && e <= x1) {
        svg += `<line x1="${X(e)}" y1="${pad.top}" x2="${X(e)}" y2="${height - pad.bottom}" stroke="#c9d0da" stroke-dasharray="3 3"/>` +
               `<text x="${X(e) + 3}" y="${pad.top + 10}" class="small">${e}: ${word}</text>`;
      }
    }
    if (own !== undefined && own >= x0 && own <= x1) {
      svg += `<line x1="${X(own)}" y1="${pad.top}" x2="${X(own)}" y2="${height - pad.bottom}" stroke="#1f5fae"/>` +
             `<text x="${X(own) + 3}" y="${height - pad.bottom - 4}" class="small">this scene, ${num(own)}</text>`;
    }
    for (const y of [y0, y1]) {
      svg += `<text x="${pad.left - 4}" y="${Y(y) + 4}" text-anchor="end">${num(y)}</text>`;
    }
    svg += `<text x="${X(x0)}" y="${height - 10}" text-anchor="start">${num(x0)}</text>` +
           `<text x="${X(x1)}" y="${height - 10}" text-anchor="end">${num(x1)}</text>` +
           `<text x="${(X(x0) + X(x1)) / 2}" y="${height - 10}" text-anchor="middle">elasticity</text>`;
    if (level !== undefined) {
      svg += `<line x1="${pad.left}" y1="${Y(level)}" x2="${width - pad.right}" y2="${Y(level)}" stroke="#5a6372" stroke-dasharray="6 4"/>` +
             `<text x="${width - pad.right}" y="${Y(level) - 4}" text-anchor="end" class="small">${escapeHtml(levelName)}</text>`;
    }
    for (const s of series) {
      const points = rows.map((r) => `${X(r[0]).toFixed(2)},${Y(r[s.column]).toFixed(2)}`).join(' ');
      svg += `<polyline points="${points}" fill="none" stroke="${s.colour}" stroke-width="2"><title>${escapeHtml(s.name)}</title></polyline>`;
    }
    return `${svg}</svg>`;
  }

  for (const id of ['sweep-from', 'sweep-to', 'sweep-step']) {
    $(id).addEventListener('input', collide.refreshSideViews);
  }
  $('sweep-box').addEventListener('toggle', collide.refreshSideViews);
})(window.collide);
