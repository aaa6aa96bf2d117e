// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive page (collide.html), its first script: the namespace every script of the page
// shares (window.collide: classic scripts, since a page opened from disk cannot load modules),
// and small helpers: numbers as the command line prints them, plane vectors, colours, escaping.
// Nothing of the physics is computed by the page: the library, compiled to WebAssembly, does it.
'use strict';

(function (collide) {
  collide.$ = (id) => document.getElementById(id);

  const palette = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b',
                   '#e377c2', '#7f7f7f', '#bcbd22'];
  collide.colour = (i) => palette[i % palette.length];

  collide.escapeHtml = (text) => String(text).replace(/[&<>"']/g, (c) => ({
    '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', '\'': '&#39;'})[c]);

  // Six significant digits, as the command line's text report (printf's %g); a value within 1e-12
  // of @p scale (the largest of its kind) is rounding, shown as 0. What is not a number is shown
  // as a dash, never as "undefined" or "NaN".
  collide.num = (x, scale) => {
    if (typeof x !== 'number' || Number.isNaN(x)) {
      return '–';
    }
    if (!isFinite(x)) {
      return x > 0 ? '∞' : '−∞';
    }
    if (x === 0 || (scale !== undefined && Math.abs(x) <= 1e-12 * Math.abs(scale))) {
      return '0';
    }
    const exponent = Math.floor(Math.log10(Math.abs(Number(x.toPrecision(6)))));
    if (exponent < -4 || exponent >= 6) {
      const [mantissa, power] = x.toExponential(5).split('e');
      return `${Number(mantissa)}e${power.replace('+', '')}`;
    }
    return String(Number(x.toPrecision(6)));
  };

  // A number a person would type: @p digits significant digits.
  collide.round = (x, digits) => (x === 0 ? 0 : Number(x.toPrecision(digits)));
  // A coordinate on a grid of 1/1000 (positions, points), without "-0".
  collide.grid = (x) => Math.round(x * 1000) / 1000 + 0;

  collide.isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
  collide.vec = (v) => (Array.isArray(v) ? [Number(v[0]) || 0, Number(v[1]) || 0] : [Number(v) || 0, 0]);
  collide.add = (a, b) => [a[0] + b[0], a[1] + b[1]];
  collide.sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
  collide.mul = (a, s) => [a[0] * s, a[1] * s];
  collide.dot = (a, b) => a[0] * b[0] + a[1] * b[1];
  collide.cross = (a, b) => a[0] * b[1] - a[1] * b[0];
  collide.norm = (a) => Math.hypot(a[0], a[1]);
  collide.unit = (a) => {
    const n = Math.hypot(a[0], a[1]);
    return n > 0 ? [a[0] / n, a[1] / n] : [1, 0];
  };
  collide.rotate = (a, angle) => [a[0] * Math.cos(angle) - a[1] * Math.sin(angle),
                                  a[0] * Math.sin(angle) + a[1] * Math.cos(angle)];
  collide.median = (values) => {
    const sorted = [...values].sort((a, b) => a - b);
    return sorted.length ? sorted[Math.floor(sorted.length / 2)] : 1;
  };

  // A count as the page writes it: 12,345.
  collide.countText = (n) => Number(n).toLocaleString('en-US');

  // Where the time of one update goes (web/test/measure.mjs prints it by part).
  collide.phases = {};
  collide.timed = (name, work) => {
    const started = performance.now();
    const value = work();
    collide.phases[name] = (collide.phases[name] || 0) + performance.now() - started;
    return value;
  };
})(window.collide = window.collide || {});
