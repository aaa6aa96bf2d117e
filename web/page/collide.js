// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive page (collide.html), its last script: one update of everything shown, what the
// browser tests may ask the page, and the start (the module, then the scene of the address).
//
// The scripts, in the order the page loads them (classic scripts: a page opened from disk cannot
// load modules), each a concern: collide-util.js (helpers), collide-state.js (the state, the
// address, solving, undo), collide-layout.js (where things are drawn), collide-motion.js (the
// motion before and after, stopped where outlines meet), collide-draw.js (the canvas),
// collide-edit.js (building on the canvas), collide-controls.js (the fields and the messages at
// them), collide-results.js (the tables and charts), collide-compare.js (side by side, the
// sweep), collide-animation.js (the time, serial collisions one at a time), and this one. The
// ImpulseLab library, compiled to WebAssembly, reads and solves every scene: no physics is
// computed here.
'use strict';

(function (collide) {
  const {$, escapeHtml, state} = collide;

  // One update: the messages, the controls, the results (kept, dimmed, while the scene is
  // refused), the canvas, then the side views. Returns what is left to draw just after (the
  // panels off the screen), or null.
  collide.render = ({rebuild}) => {
    const out = state.out;
    const refused = Boolean(out && out.error);
    const pending = Boolean(out && out.pending);  // serial collisions still running
    $('scene-error').textContent = out ? out.error : '';
    $('refusal').hidden = !refused && !pending;
    $('refusal').classList.toggle('pending', pending);
    document.body.classList.toggle('refused', (refused || pending) && Boolean(state.valid));
    $('warnings').innerHTML = out ? out.warnings.map((w) => `<li>${escapeHtml(w)}</li>`).join('') : '';
    // The library's warning that the collision gained energy, again beside the energy bars.
    const gained = out ? out.warnings.filter((w) => w.startsWith('energy gained')) : [];
    $('energy-warnings').innerHTML = gained.map((w) => `<li>${escapeHtml(w)} (the bar after passes the dashed line of ` +
                                                'the energy before; <a href="friction.html#friction_energy">why</a>)</li>').join('');
    $('result-json').textContent = out ? out.resultText : '';
    if (out && out.error && state.scene === null) {
      $('scene-text-box').open = true;
    }
    if (rebuild) {
      collide.timed('controls', collide.buildBodyControls);
      collide.selection = null;
    }
    collide.timed('controls', collide.syncControls);
    collide.timed('messages', collide.showMessages);
    collide.syncSelection();
    collide.syncHistory();
    const later = !(refused || pending) || !state.valid ? collide.renderResults() : null;
    collide.syncSerial();
    collide.timed('canvas', () => collide.setTime(state.t));
    if (!pending) {
      collide.refreshSideViews();  // once the serial collisions have ended
    }
    return later;
  };

  // For the browser tests: what is drawn, in the window's coordinates (handles, impulse arrows)
  // or the scene's (outlines, markers).
  window.impulselabPage = {
    handles() {
      const rect = collide.canvas.getBoundingClientRect();
      const sx = rect.width / collide.canvas.width;
      const sy = rect.height / collide.canvas.height;
      return collide.drawn.handles.map((h) => ({kind: h.kind, body: h.body, contact: h.contact,
                                               x: rect.left + h.at[0] * sx, y: rect.top + h.at[1] * sy}));
    },
    // Each impulse arrow: its contact, the body it acts on, its direction on the screen (x to the
    // right, y up) and its length in pixels of the canvas.
    impulseArrows() {
      return collide.drawn.arrows.map((a) => ({contact: a.contact, body: a.body, dx: a.to[0] - a.from[0], dy: a.from[1] - a.to[1]}));
    },
    // At the time shown: each body's outline ({circle: [[x, y], r]} or {polygon}), each static
    // surface ({surface: [a, b], outward}), each contact's marker ({at, alpha}), the collisions
    // not computed, the canvas's labels (boxes in canvas pixels), the time in seconds.
    drawn() {
      const l = state.layout;
      return {time: l ? state.t * l.scales.window : 0, typical: l ? l.typical : 0,
              outlines: collide.drawn.outlines, markers: collide.drawn.markers, events: collide.drawn.events,
              labels: collide.drawn.labels};
    },
    // A point of the scene in the window's coordinates.
    toWindow(p) {
      const rect = collide.canvas.getBoundingClientRect();
      const q = collide.transform(state.layout).to(p);
      return {x: rect.left + q[0] * rect.width / collide.canvas.width, y: rect.top + q[1] * rect.height / collide.canvas.height};
    },
    serialStep() {
      return collide.serialShown();
    },
  };

  // Start: the module, then the scene of the address (or an example).
  collide.buildPresetMenu();
  new ResizeObserver(collide.resizeCanvas).observe(collide.canvas);
  // Fields scrolled into view stay below the pinned canvas (collide.css).
  new ResizeObserver(() => document.documentElement.style.setProperty('--pinned-height', `${$('pinned').offsetHeight}px`))
      .observe($('pinned'));
  window.createImpulseLab().then((module) => {
    state.module = module;
    collide.loadFromAddress();
  }, (error) => {
    $('scene-error').textContent = `The library did not load: ${error}`;
    $('refusal').hidden = false;
    document.body.dataset.ready = 'true';
  });
})(window.collide);
