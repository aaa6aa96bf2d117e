// SPDX-License-Identifier: GPL-3.0-or-later
// The results beside the canvas, all from the library's report: the summary, the tables of
// impulses, bodies and approach speeds, the kinetic energy as stacked bars and the momentum as a
// diagram, and the system A·Fdt = B typeset (MathJax) with the paper's equations that build it.
'use strict';

(function (collide) {
  const {$, isObject, num, vec, add, norm, escapeHtml, colour, state} = collide;

  function vectorText(v, dim, scale) {
    const x = vec(v);
    return dim === 1 ? num(x[0], scale) : `[${num(x[0], scale)}, ${num(x[1], scale)}]`;
  }

  // Fills @p table: @p head the header cells ([text, class]), @p rows arrays of cells (a text, or
  // {text, cls, colour}). The cells are rebuilt only when the table's shape changes; otherwise only
  // the texts that changed are written, so that a control moved on a scene of a hundred contacts
  // does not rebuild a thousand cells.
  function fillTable(table, head, allRows, what) {
    // A table shows its first 25 rows (a person reads no more; a change then redraws a few
    // hundred cells, not thousands): the JSON below has them all.
    const rows = allRows.slice(0, 25);
    const shape = `${head.map((h) => h[0]).join('|')}#${rows.length}`;
    if (table.dataset.shape !== shape) {
      table.dataset.shape = shape;
      table.textContent = '';
      const thead = table.createTHead().insertRow();
      for (const [text, cls] of head) {
        const th = document.createElement('th');
        th.textContent = text;
        if (cls) {
          th.className = cls;
        }
        thead.appendChild(th);
      }
      const body = table.createTBody();
      for (let r = 0; r < rows.length; ++r) {
        const tr = body.insertRow();
        for (let c = 0; c < head.length; ++c) {
          tr.insertCell();
        }
      }
    }
    const note = rows.length < allRows.length
                     ? `The first ${rows.length} of ${allRows.length} ${what || 'rows'} (all of them in the JSON below)` : '';
    if (note || table.caption) {
      const caption = table.caption || table.createCaption();
      if (caption.textContent !== note) {
        caption.textContent = note;
      }
    }
    const body = table.tBodies[0];
    rows.forEach((row, r) => {
      const cells = body.rows[r].cells;
      row.forEach((cell, c) => {
        const value = typeof cell === 'object' ? cell : {text: cell};
        const td = cells[c];
        if (td.textContent !== value.text) {
          td.textContent = value.text;
        }
        const cls = value.cls || '';
        if (td.className !== cls) {
          td.className = cls;
        }
        if (value.colour && td.style.getPropertyValue('--colour') !== value.colour) {
          td.style.setProperty('--colour', value.colour);
        }
      });
    });
  }

  function renderTables() {
    const r = state.result;
    const d = state.details;
    const impulses = $('impulses-table');
    const bodiesTable = $('bodies-table');
    const contactsTable = $('contacts-table');
    if (!r || !d) {
      for (const table of [impulses, bodiesTable, contactsTable]) {
        table.textContent = '';
        delete table.dataset.shape;
      }
      return;
    }
    const dim = d.dimension;
    // With friction (or a law other than Newton's) the report gives each contact's tangential
    // impulse and how its slip ended: two more columns.
    const rough = r.impulses.some((i) => i.tangential !== undefined);
    const largestImpulse = Math.max(0, ...r.impulses.map((i) => Math.max(Math.abs(i.magnitude),
                                                                         Math.abs(i.tangential || 0))));
    fillTable(impulses, [['contact'], ['bumper → wedge', 'name'], [rough ? 'F dt, normal' : 'F dt'],
                         ...(rough ? [['tangential']] : []), ['on the bumper'], ...(rough ? [['ends', 'name']] : [])],
              r.impulses.map((i) => {
                const pulls = i.magnitude < -1e-12 * largestImpulse;
                const friction = rough ? [i.tangential !== undefined ? num(i.tangential, largestImpulse) : ''] : [];
                const slip = rough ? [{text: i.slip !== undefined ? String(i.slip) : '', cls: 'name'}] : [];
                return [String(i.contact), {text: `${i.bumper} → ${i.wedge}`, cls: 'name'},
                        {text: num(i.magnitude, largestImpulse) + (pulls ? ' (pulls)' : ''), cls: pulls ? 'pulls' : ''},
                        ...friction, vectorText(i.on_bumper, dim, largestImpulse), ...slip];
              }));
    $('friction-facts').textContent = frictionFacts(r) +
        (rough ? ' "ends": slip (still sliding), stick, or reversed (sliding back).' : '');

    const speeds = d.bodies.flatMap((b) => [norm(vec(b.before.velocity)), norm(vec(b.after.velocity))]);
    const largestSpeed = Math.max(0, ...speeds);
    const largestMomentum = Math.max(0, ...d.bodies.map((b) => norm(vec(b.after.momentum))));
    const rigid = d.bodies.some((b) => b.kind === 'rigid');
    const largestSpin = Math.max(0, ...d.bodies.flatMap((b) => [Math.abs(b.before.angular_velocity), Math.abs(b.after.angular_velocity)]));
    fillTable(bodiesTable,
              [['body', 'name'], ['velocity before'], ['after'],
               ...(rigid ? [['spin before'], ['after']] : []), ['momentum after']],
              d.bodies.map((b, i) => {
                const spins = b.kind === 'rigid' ? [num(b.before.angular_velocity, largestSpin), num(b.after.angular_velocity, largestSpin)] : ['', ''];
                return [{text: b.name + (b.kind === 'static' ? ' (static)' : ''), cls: 'name body', colour: colour(i)},
                        vectorText(b.before.velocity, dim, largestSpeed), vectorText(b.after.velocity, dim, largestSpeed),
                        ...(rigid ? spins : []), vectorText(b.after.momentum, dim, largestMomentum)];
              }));

    const largestApproach = Math.max(0, ...r.contacts.flatMap((c) => [Math.abs(c.approach_before), Math.abs(c.approach_after)]));
    fillTable(contactsTable, [['contact'], ['before'], ['after'], ['', 'name']],
              r.contacts.map((c) => {
                const after = Math.abs(c.approach_after) <= 1e-12 * largestApproach ? 0 : c.approach_after;
                const word = after > 0 ? 'still closing' : after < 0 ? 'separating' : 'neither';
                return [String(c.contact), num(c.approach_before, largestApproach),
                        num(c.approach_after, largestApproach), {text: word, cls: 'name'}];
              }));

  }

  // The summary under the canvas: the method, energy and momentum before and after.
  function renderSummary() {
    const r = state.result;
    if (!r || !state.details) {
      $('summary').textContent = '';
      return;
    }
    const dim = state.details.dimension;
    const method = r.method || 'simultaneous';
    const methodName = {simultaneous: 'the paper\'s system', complementarity: 'complementarity',
                        serial: 'serial collisions'}[method];
    const p = r.momentum;
    const momentumScale = norm(vec(p.before)) + norm(vec(p.after));
    $('summary').textContent =
        `Method: ${methodName}. Kinetic energy ${num(r.energy.before)} → ${num(r.energy.after, r.energy.before)} ` +
        `(change ${num(r.energy.change, r.energy.before)}). Momentum ${vectorText(p.before, dim, momentumScale)} → ` +
        `${vectorText(p.after, dim, momentumScale)}.` +
        methodFacts(r);
  }

  // What the method says of itself in its block, in words (a block without these keys, as the
  // exact single-contact rule's, says nothing here).
  function methodFacts(r) {
    const s = r.serial;
    const c = r.complementarity;
    const count = (n, one, many) => `${n} ${n === 1 ? one : many}`;
    if (isObject(s) && typeof s.collisions === 'number' && typeof s.passes === 'number') {
      return ` ${count(s.collisions, 'collision', 'collisions')} in ${count(s.passes, 'pass', 'passes')}.`;
    }
    if (isObject(c) && typeof c.algorithm === 'string' && typeof c.iterations === 'number') {
      return ` Algorithm: ${c.algorithm}, ${count(c.iterations, 'iteration', 'iterations')}.`;
    }
    return '';
  }

  // What the exact single-contact rule reports, in words: the law, the phases of slip with the
  // normal impulse at which each ended (as the command line's text report writes them), and the
  // works; for serial collisions, the laws of each contact.
  function frictionFacts(r) {
    const block = r.method ? r[r.method] : null;
    if (!isObject(block) || block.restitution === undefined) {
      return '';
    }
    const laws = {newton: 'Newton\'s restitution', poisson: 'Poisson\'s restitution', energetic: 'energetic restitution'};
    const law = laws[block.restitution] || block.restitution;
    if (Array.isArray(block.friction)) {
      const mus = block.friction.slice(0, 12).map((mu) => num(mu)).join(', ');
      return `Serial collisions, each resolved by the exact single-contact rule: ${law}; friction μ of ` +
             `contacts 0, 1, …: ${mus}${block.friction.length > 12 ? ', …' : ''}; a contact "ends" as its last ` +
             'collision ended.';
    }
    if (typeof block.phases !== 'string' || !Array.isArray(block.phase_ends)) {
      return '';
    }
    const scale = Math.max(...block.phase_ends.map(Math.abs), 0);
    const phases = block.phases.split(', ').map((phase, k) =>
        `${phase} until ${k === 0 ? 'Fdt = ' : ''}${num(block.phase_ends[k], scale)}`).join(', ');
    const i = r.impulses[0];
    const works = [block.work_compression, block.work_restitution, block.work_tangential];
    const workScale = Math.max(...works.map(Math.abs), 0);
    return `Contact ${i.contact} (${i.bumper}–${i.wedge}), followed through the normal impulse by the exact ` +
           `single-contact rule: friction μ = ${num(block.friction)}, ${law}, elasticity ${num(block.elasticity)}. ` +
           `Phases: ${phases}; compression ended at Fdt = ${num(block.compression, scale)}. Work of the normal ` +
           `impulse in compression ${num(works[0], workScale)}, in restitution ${num(works[1], workScale)}; ` +
           `of friction ${num(works[2], workScale)}.`;
  }

  const svgNS = 'http://www.w3.org/2000/svg';

  // Writes @p html into @p box only when it differs from what was written last.
  const written = new WeakMap();
  function setHtml(box, html) {
    if (written.get(box) !== html) {
      box.innerHTML = html;
      written.set(box, html);
    }
  }

  function renderEnergy() {
    const box = $('energy-chart');
    const d = state.details;
    if (!d) {
      setHtml(box, '');
      return;
    }
    const width = 520;
    const left = 60;
    const right = 90;
    const barHeight = 22;
    const totals = [0, 0];
    d.bodies.forEach((b) => {
      totals[0] += b.energy_before;
      totals[1] += b.energy_after;
    });
    const largest = Math.max(totals[0], totals[1], 1e-300);
    const scale = (width - left - right) / largest;
    let svg = `<svg xmlns="${svgNS}" viewBox="0 0 ${width} 70" role="img" aria-label="Kinetic energy before ` +
              `${num(totals[0])} and after ${num(totals[1])}, each body a part of the bar">`;
    ['before', 'after'].forEach((when, row) => {
      const y = 6 + row * (barHeight + 12);
      svg += `<text x="${left - 6}" y="${y + 15}" text-anchor="end">${when}</text>`;
      let x = left;
      d.bodies.forEach((b, i) => {
        const e = row === 0 ? b.energy_before : b.energy_after;
        const w = Math.max(0, e * scale);
        if (w > 0) {
          svg += `<rect x="${x.toFixed(2)}" y="${y}" width="${w.toFixed(2)}" height="${barHeight}" ` +
                 `fill="${colour(i)}" fill-opacity="0.75"><title>${escapeHtml(b.name)}: ${num(e)}</title></rect>`;
        }
        x += w;
      });
      svg += `<text x="${(x + 6).toFixed(2)}" y="${y + 15}">${num(totals[row], largest)}</text>`;
    });
    // The energy before, marked across the bar after: a gain shows as a bar past the line.
    const mark = (left + totals[0] * scale).toFixed(2);
    svg += `<line x1="${mark}" y1="2" x2="${mark}" y2="${2 * barHeight + 22}" stroke="#1d2430" ` +
           'stroke-dasharray="4 3" stroke-width="1"/>';
    setHtml(box, svg + '</svg>');
  }

  function renderMomentum() {
    const box = $('momentum-chart');
    const d = state.details;
    if (!d) {
      setHtml(box, '');
      return;
    }
    const movable = d.bodies.map((b, i) => [b, i]).filter(([b]) => b.kind !== 'static');
    const chains = ['before', 'after'].map((when) => {
      let at = [0, 0];
      const parts = movable.map(([b, i], k) => {
        const p = vec(b[when].momentum);
        // In one dimension the arrows would lie on each other: each gets a row of its own.
        const from = d.dimension === 1 ? [at[0], -k] : at;
        at = add(at, p);
        return {from, to: d.dimension === 1 ? [at[0], -k] : at, i};
      });
      return {parts, total: d.dimension === 1 ? [at[0], -movable.length] : at};
    });
    let box2 = [0, 0, 0, 0];
    for (const chain of chains) {
      for (const part of [...chain.parts, {from: [0, chain.total[1]], to: chain.total}]) {
        for (const p of [part.from, part.to]) {
          box2 = [Math.min(box2[0], p[0]), Math.min(box2[1], p[1]), Math.max(box2[2], p[0]), Math.max(box2[3], p[1])];
        }
      }
    }
    const size = 200;
    const pad = 18;
    const spanX = Math.max(box2[2] - box2[0], 1e-300);
    const spanY = d.dimension === 1 ? Math.max(box2[3] - box2[1], 1) : Math.max(box2[3] - box2[1], 1e-300);
    const scale = d.dimension === 1 ? (size - 2 * pad) / spanX : (size - 2 * pad) / Math.max(spanX, spanY);
    const rowHeight = d.dimension === 1 ? Math.min(18, (size - 2 * pad) / (movable.length + 1)) : 0;
    const height = d.dimension === 1 ? 2 * pad + rowHeight * (movable.length + 1)
                                     : Math.max(60, (box2[3] - box2[1]) * scale + 2 * pad);
    const toScreen = (p, panel) => d.dimension === 1
        ? [panel * (size + 20) + pad + (p[0] - box2[0]) * scale, pad + (-p[1]) * rowHeight]
        : [panel * (size + 20) + pad + (p[0] - box2[0]) * scale,
           height / 2 + ((box2[3] + box2[1]) / 2 - p[1]) * scale];
    let svg = `<svg xmlns="${svgNS}" viewBox="0 0 ${2 * size + 20} ${height + 16}" role="img" ` +
              'aria-label="Momentum of each body, tip to tail, before and after">' +
              '<defs><marker id="tip" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="10" markerHeight="10" ' +
              'markerUnits="userSpaceOnUse" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" ' +
              'fill="context-stroke"/></marker><marker id="total-tip" viewBox="0 0 10 10" refX="9" refY="5" ' +
              'markerWidth="16" markerHeight="16" markerUnits="userSpaceOnUse" orient="auto-start-reverse">' +
              '<path d="M0,0 L10,5 L0,10 z" fill="#8e949c"/></marker></defs>';
    chains.forEach((chain, panel) => {
      const origin = toScreen([0, 0], panel);
      svg += `<text x="${panel * (size + 20) + 4}" y="${height + 12}">${panel ? 'after' : 'before'}</text>`;
      svg += `<line x1="${origin[0]}" y1="0" x2="${origin[0]}" y2="${height}" stroke="#c9d0da"/>`;
      // The total first, wide and pale, so that the bodies' arrows stay visible on top of it.
      const a = toScreen(d.dimension === 1 ? [0, chain.total[1]] : [0, 0], panel);
      const b = toScreen(chain.total, panel);
      if (Math.hypot(b[0] - a[0], b[1] - a[1]) > 0.5) {
        svg += `<line x1="${a[0].toFixed(2)}" y1="${a[1].toFixed(2)}" x2="${b[0].toFixed(2)}" y2="${b[1].toFixed(2)}" ` +
               'stroke="#8e949c" stroke-width="7" marker-end="url(#total-tip)"/>';
      }
      for (const part of chain.parts) {
        const from = toScreen(part.from, panel);
        const to = toScreen(part.to, panel);
        if (Math.hypot(to[0] - from[0], to[1] - from[1]) > 0.5) {
          svg += `<line x1="${from[0].toFixed(2)}" y1="${from[1].toFixed(2)}" x2="${to[0].toFixed(2)}" y2="${to[1].toFixed(2)}" ` +
                 `stroke="${colour(part.i)}" stroke-width="2.5" marker-end="url(#tip)"/>`;
        }
      }
    });
    setHtml(box, svg + '</svg>');
  }

  // The system, typeset by MathJax up to 8 contacts (a bigger matrix is a table), with the
  // equations of the paper that give each body's share.
  const equations = [
    {id: '1.3', page: 'section1.html#eq_1_3', what: 'two bodies on a line'},
    {id: '3.6', page: 'section3.html#eq_3_6', what: 'a rigid body at one contact, elastic'},
    {id: '3.10', page: 'section3.html#eq_3_10', what: 'inelastic'},
    {id: '4.5', page: 'section4.html#eq_4_5', what: 'point masses at many contacts, elastic'},
    {id: '4.8', page: 'section4.html#eq_4_8', what: 'inelastic'},
    {id: '5.3', page: 'section5.html#eq_5_3', what: 'rigid bodies at many contacts, elastic'},
    {id: '5.5', page: 'section5.html#eq_5_5', what: 'inelastic'},
  ];

  function sceneEquations(d, r) {
    const rigid = d.bodies.some((b) => b.kind === 'rigid');
    const many = r.contacts.length > 1;
    if (rigid) {
      return many ? ['5.3', '5.5'] : ['3.6', '3.10'];
    }
    return many ? ['4.5', '4.8'] : ['1.3'];
  }

  function texNumber(x, scale) {
    const text = num(x, scale);
    const m = /^(-?[0-9.]+)e(-?)([0-9]+)$/.exec(text);
    return m ? `${m[1]}\\cdot 10^{${m[2]}${m[3]}}` : text;
  }

  function renderSystem() {
    const box = $('system-equation');
    const facts = $('system-facts');
    const source = $('system-source');
    const r = state.result;
    if (!r) {
      box.textContent = '';
      facts.textContent = '';
      source.textContent = '';
      return;
    }
    const s = r.system;
    const n = s.B.length;
    const fdt = r.impulses.map((i) => i.magnitude);
    const scaleA = s.A ? Math.max(0, ...s.A.flat().map(Math.abs)) : 0;
    const scaleB = Math.max(0, ...s.B.map(Math.abs));
    const scaleF = Math.max(0, ...fdt.map(Math.abs));
    const mathJax = window.MathJax && window.MathJax.Hub && typeof window.MathJax.Hub.Queue === 'function';
    if (n <= 8 && s.A && mathJax) {
      const column = (values, scale) => `\\begin{pmatrix} ${values.map((x) => texNumber(x, scale)).join(' \\\\ ')} \\end{pmatrix}`;
      const unknowns = `\\begin{pmatrix} ${fdt.map((x, v) => `F_{${v}}\\,dt`).join(' \\\\ ')} \\end{pmatrix}`;
      const matrix = `\\begin{pmatrix} ${s.A.map((row) => row.map((x) => texNumber(x, scaleA)).join(' & ')).join(' \\\\ ')} \\end{pmatrix}`;
      const tex = `\\underbrace{${matrix}}_{\\mathbf{A}} ${unknowns} = \\underbrace{${column(s.B, scaleB)}}_{\\vec{B}}, ` +
                  `\\qquad ${unknowns} = ${column(fdt, scaleF)}`;
      box.innerHTML = '';
      const script = document.createElement('script');
      script.type = 'math/tex; mode=display';
      script.text = tex;
      box.appendChild(script);
      window.MathJax.Hub.Queue(['Typeset', window.MathJax.Hub, box]);
    } else {
      // Too big to typeset: A as a picture (blue positive, red negative, white zero: a cradle's
      // band, a stack's blocks), and the first rows of F dt and B as a table.
      if (!box.querySelector('canvas.matrix-map')) {
        box.innerHTML = '<canvas class="matrix-map" role="img"></canvas><div class="table-box">' +
                        '<table id="system-table" aria-label="The impulses and B, row by row"></table></div>';
      }
      const map = box.querySelector('canvas.matrix-map');
      if (s.A) {
        // One pixel per entry, enlarged by the style (pixelated): a hundred by a hundred is one
        // image written at once.
        const cell = Math.max(1, Math.floor(240 / n));
        if (map.width !== n) {
          map.width = map.height = n;
        }
        map.style.width = map.style.height = `${cell * n}px`;
        map.hidden = false;
        map.setAttribute('aria-label', `A, ${n} by ${n}: blue positive entries, red negative, white zero`);
        const g = map.getContext('2d');
        const image = g.createImageData(n, n);
        const pixels = image.data;
        for (let v = 0; v < n; ++v) {
          const row = s.A[v];
          for (let j = 0; j < n; ++j) {
            const x = row[j];
            // Over white: the colour at opacity 0.15 + 0.85 of the entry's share of the largest.
            const a = Math.abs(x) > 1e-12 * scaleA ? 0.15 + 0.85 * Math.min(1, Math.abs(x) / scaleA) : 0;
            const [r, gr, b] = x > 0 ? [31, 95, 174] : [180, 35, 24];
            const k = 4 * (v * n + j);
            pixels[k] = 255 + (r - 255) * a;
            pixels[k + 1] = 255 + (gr - 255) * a;
            pixels[k + 2] = 255 + (b - 255) * a;
            pixels[k + 3] = 255;
          }
        }
        g.putImageData(image, 0, 0);
      } else {
        map.hidden = true;
      }
      fillTable(box.querySelector('table'), [['v'], ['F_v dt'], ['B_v']],
                [...Array(n).keys()].map((v) => [String(v), num(fdt[v], scaleF), num(s.B[v], scaleB)]));
    }
    const method = r.method || 'simultaneous';
    facts.innerHTML =
        `${n} contact${n === 1 ? '' : 's'}; rank ${s.rank}${s.dependent ? ' (dependent: ' + escapeHtml(s.policy) + ' solution)' : ''}; ` +
        `residual ‖A·Fdt − B‖ = ${num(s.residual)}; ${s.consistent ? 'consistent' : 'inconsistent'}` +
        (s.condition_estimate !== undefined ? `; condition estimate ${num(s.condition_estimate)}` : '') + '.' +
        (method === 'simultaneous' ? ''
                                   : ` The impulses are those of ${method === 'serial' ? 'serial collisions' : 'complementarity'}; ` +
                                     'A and B are the paper\'s system of the same scene.') +
        (r.impulses.some((i) => i.tangential !== undefined)
             ? ' With friction or another law of restitution the normal impulses F dt are the exact rule\'s (under ' +
               'Impulses), and A and B the paper\'s frictionless system: the residual measures how far they moved the answer.'
             : '');
    const used = sceneEquations(state.details, r);
    source.innerHTML = 'Each body adds its share to A and B, by the paper\'s equations: ' +
        equations.map((e) => `<a href="${e.page}"${used.includes(e.id) ? ' class="used"' : ''}>(${e.id})</a> ${e.what}`)
                 .join('; ') +
        `. This scene: <strong>${used.map((id) => `(${id})`).join(', ')}</strong>; ` +
        'the elasticity e of each body scales its share of B (1 inelastic, 2 elastic).';
  }

  // The panels, each drawn at once when it is on the screen, else just after (the update then
  // ends when they are: collide.show). A scene of a hundred contacts has a thousand cells and a
  // matrix of ten thousand entries below the fold.
  const panels = [{name: 'tables', render: renderTables, boxes: ['impulses-table', 'bodies-table', 'contacts-table']},
                  {name: 'energy', render: renderEnergy, boxes: ['energy-chart']},
                  {name: 'momentum', render: renderMomentum, boxes: ['momentum-chart']},
                  {name: 'system', render: renderSystem, boxes: ['system-equation', 'system-facts']}];
  const onScreen = new Set();
  const watcher = new IntersectionObserver((entries) => {
    for (const e of entries) {
      if (e.isIntersecting) {
        onScreen.add(e.target.id);
      } else {
        onScreen.delete(e.target.id);
      }
    }
  });
  for (const panel of panels) {
    for (const id of panel.boxes) {
      watcher.observe($(id));
    }
  }

  // Returns the drawing left for just after (a function), or null.
  collide.renderResults = () => {
    collide.timed('summary', renderSummary);
    const later = [];
    for (const panel of panels) {
      if (panel.boxes.some((id) => onScreen.has(id))) {
        collide.timed(panel.name, panel.render);
      } else {
        later.push(panel);
      }
    }
    // (Unless the scene shown by then is refused: its last result stays as it is.)
    return later.length ? () => (state.result || !state.valid) && later.forEach((panel) => collide.timed(panel.name, panel.render))
                        : null;
  };
  collide.fillTable = fillTable;
  collide.vectorText = vectorText;
})(window.collide);
