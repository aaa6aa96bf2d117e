// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive page (collide.html). The ImpulseLab library, compiled to WebAssembly, reads and
// solves the scene (Module.solveScene: the scene reader, the solver and the report of
// `impulselab solve --format json`); this script only keeps the scene, lays it out, draws it and
// animates the straight-line motion and rotation the library's velocities before and after give.
// Nothing of the physics is computed here.
//
// The state is the scene, in the address: #scene= followed by the scene's JSON, percent-encoded
// as encodeURIComponent writes it (bytes that are not UTF-8 as %XX), so a link reproduces the
// page. The contract is web-page.md; the README says how to build and open the page.
'use strict';

(function () {
  // ---------------------------------------------------------------------------------------------
  // The address: bytes in and out of the fragment.

  const unreserved = /[A-Za-z0-9\-_.!~*'()]/;

  // The scene's bytes as the fragment holds them: what encodeURIComponent writes for UTF-8 text,
  // and %XX for every other byte.
  function encodeBytes(bytes) {
    let text = '';
    for (const byte of bytes) {
      const c = String.fromCharCode(byte);
      text += byte < 0x80 && unreserved.test(c) ? c
                                                 : '%' + byte.toString(16).toUpperCase().padStart(2, '0');
    }
    return text;
  }

  // The bytes a fragment stands for: %XX is a byte, any other character its UTF-8 bytes.
  function decodeFragment(fragment) {
    const bytes = [];
    const encoder = new TextEncoder();
    for (let i = 0; i < fragment.length; ++i) {
      const hex = fragment.slice(i + 1, i + 3);
      if (fragment[i] === '%' && /^[0-9A-Fa-f]{2}$/.test(hex)) {
        bytes.push(parseInt(hex, 16));
        i += 2;
      } else {
        const code = fragment.codePointAt(i);
        const c = String.fromCodePoint(code);
        bytes.push(...encoder.encode(c));
        i += c.length - 1;
      }
    }
    return new Uint8Array(bytes);
  }

  function utf8Text(bytes) {
    try {
      return new TextDecoder('utf-8', {fatal: true}).decode(bytes);
    } catch (e) {
      return null;
    }
  }

  const fragmentKey = '#scene=';

  // ---------------------------------------------------------------------------------------------
  // Small helpers.

  const $ = (id) => document.getElementById(id);
  const presets = window.impulselabPresets || [];
  const defaultPreset = 'box-lands-flat';
  const palette = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b',
                   '#e377c2', '#7f7f7f', '#bcbd22'];
  const colour = (i) => palette[i % palette.length];

  function escapeHtml(text) {
    return String(text).replace(/[&<>"']/g, (c) => ({'&': '&amp;', '<': '&lt;', '>': '&gt;',
                                                     '"': '&quot;', '\'': '&#39;'})[c]);
  }

  // Six significant digits, as the command line's text report; values within 1e-12 of the
  // largest of their kind shown as 0 (rounding, not a value).
  function num(x, scale) {
    if (typeof x !== 'number' || !isFinite(x)) {
      return String(x);
    }
    if (scale !== undefined && Math.abs(x) <= 1e-12 * Math.abs(scale)) {
      return '0';
    }
    if (x === 0) {
      return '0';
    }
    // As printf's %g: six significant digits, exponential below 1e-4 and from 1e6 on.
    const exponent = Math.floor(Math.log10(Math.abs(Number(x.toPrecision(6)))));
    if (exponent < -4 || exponent >= 6) {
      const [mantissa, power] = x.toExponential(5).split('e');
      return `${Number(mantissa)}e${power.replace('+', '')}`;
    }
    return String(Number(x.toPrecision(6)));
  }

  const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
  const vec = (v) => (Array.isArray(v) ? [Number(v[0]) || 0, Number(v[1]) || 0] : [Number(v) || 0, 0]);
  const add = (a, b) => [a[0] + b[0], a[1] + b[1]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
  const mul = (a, s) => [a[0] * s, a[1] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1];
  const cross = (a, b) => a[0] * b[1] - a[1] * b[0];
  const norm = (a) => Math.hypot(a[0], a[1]);
  const rotate = (a, angle) => [a[0] * Math.cos(angle) - a[1] * Math.sin(angle),
                                a[0] * Math.sin(angle) + a[1] * Math.cos(angle)];
  const median = (values) => {
    const sorted = [...values].sort((a, b) => a - b);
    return sorted.length ? sorted[Math.floor(sorted.length / 2)] : 1;
  };
  // A number a person would type: @p digits significant digits.
  const round = (x, digits) => (x === 0 ? 0 : Number(x.toPrecision(digits)));

  // ---------------------------------------------------------------------------------------------
  // The state.

  const state = {
    module: null,
    text: '',      // the scene as the library read it (a string), when it is UTF-8
    bytes: null,   // the scene's bytes, when they are not UTF-8
    scene: null,   // the scene as an object, when its text is JSON shaped like a scene
    canonical: '', // JSON.stringify of that object: the text the page writes after a change
    fromControls: false,
    out: null,     // what Module.solveScene returned
    result: null,  // its report, parsed
    details: null, // the bodies' motion before and after, parsed
    layout: null,  // where everything is drawn at t = 0
    frozen: null,  // the view kept still while a handle is dragged
    t: 0,          // animation time, in units of the layout's window (-1 .. 1)
    playing: false,
    lastFrame: 0,
    shown: 0,
    lastHash: '',
    fragmentTimer: 0,
    lastFragmentWrite: 0,
    phases: {},    // where the last update's time went (for web/test/measure.mjs)
  };

  // ---------------------------------------------------------------------------------------------
  // Solving: every scene goes through the library, and only through it.

  function solve(input) {
    const started = performance.now();
    const out = state.module.solveScene(input);
    state.phases.library = performance.now() - started;
    return {
      error: out.error,
      warnings: out.warnings,
      resultText: out.result,
      result: out.result ? JSON.parse(out.result) : null,
      details: out.details ? JSON.parse(out.details) : null,
    };
  }

  function sceneShaped(value) {
    return isObject(value) && Array.isArray(value.bodies) && Array.isArray(value.contacts) &&
           value.bodies.every(isObject) && value.contacts.every(isObject);
  }

  // Shows the scene given as text (or bytes that are not UTF-8). @p options.relayout: a new
  // scene (controls rebuilt, view fitted); @p options.event: the input event that caused it.
  function show(input, options) {
    const started = performance.now();
    state.phases = {};
    if (typeof input === 'string') {
      state.text = input;
      state.bytes = null;
    } else {
      state.text = '';
      state.bytes = input;
    }
    let parsed = null;
    if (state.bytes === null) {
      try {
        parsed = JSON.parse(state.text);
      } catch (e) {
        parsed = null;
      }
    }
    state.scene = sceneShaped(parsed) ? parsed : null;
    state.canonical = state.scene ? JSON.stringify(state.scene) : '';
    state.fromControls = Boolean(options.fromControls);
    const solveStart = performance.now();
    state.out = solve(state.bytes === null ? state.text : state.bytes);
    const solveEnd = performance.now();
    state.result = state.out.result;
    state.details = state.out.details;
    timed('layout', () => {
      state.layout = !state.details ? null
                   : options.relayout || !state.frozen ? layout(state.scene, state.details)
                   : layout(state.scene, state.details, state.frozen);
    });
    if (options.relayout) {
      buildBodyControls();
    }
    render();
    timed('address', () => writeFragment(Boolean(options.immediate)));
    state.shown += 1;
    document.body.dataset.shown = String(state.shown);
    document.body.dataset.ready = 'true';
    const rendered = performance.now();
    if (window.impulselabReadyMs === undefined) {
      window.impulselabReadyMs = rendered;  // since the page began to load (for web/test/measure.mjs)
    }
    const since = options.event ? options.event.timeStamp : started;
    // For web/test/measure.mjs: the time from the event to the result drawn (this function's end),
    // and to the frame that shows it painted (a message posted from the next animation frame runs
    // once that frame's style, layout and paint are done).
    requestAnimationFrame(() => {
      const channel = new MessageChannel();
      channel.port1.onmessage = () => {
        window.impulselabTiming = {
          solve_ms: solveEnd - solveStart,
          update_ms: rendered - since,
          frame_ms: performance.now() - since,
          contacts: state.result ? state.result.contacts.length : 0,
          phases: state.phases,
        };
      };
      channel.port2.postMessage(null);
    });
  }

  // The scene changed through a control: @p change edits the scene object.
  function edit(change, event, keepView) {
    if (!state.scene) {
      return;
    }
    change(state.scene);
    if (!keepView) {
      state.frozen = null;
    }
    // A stream of changes (a slider dragged, a handle moved) writes the address at most every
    // 150 ms; a single change (a menu, a field left) at once.
    const stream = event && (event.type === 'input' || event.type.startsWith('pointer'));
    show(JSON.stringify(state.scene), {fromControls: true, event, immediate: !stream});
  }

  // ---------------------------------------------------------------------------------------------
  // The address.

  function writeFragment(immediate) {
    clearTimeout(state.fragmentTimer);
    const write = () => {
      // encodeURIComponent writes UTF-8 text as the contract says; bytes that are not UTF-8 each
      // as %XX.
      const hash = fragmentKey + (state.bytes !== null ? encodeBytes(state.bytes) : encodeURIComponent(state.text));
      state.lastHash = hash;
      state.lastFragmentWrite = performance.now();
      if (location.hash !== hash) {
        history.replaceState(null, '', hash);
      }
    };
    // A slider dragged across writes the address after the result is drawn, at most every 150 ms
    // (browsers throttle changes of the history); the last position is always written.
    if (immediate) {
      write();
    } else {
      state.fragmentTimer = setTimeout(write, Math.max(0, 150 - (performance.now() - state.lastFragmentWrite)));
    }
  }

  function loadFromAddress() {
    const hash = location.hash;
    if (hash.startsWith(fragmentKey)) {
      const bytes = decodeFragment(hash.slice(fragmentKey.length));
      const text = utf8Text(bytes);
      state.lastHash = hash;
      show(text !== null ? text : bytes, {relayout: true, immediate: true});
    } else {
      loadPreset(defaultPreset);
    }
  }

  function loadPreset(id) {
    const preset = presets.find((p) => p.id === id) || presets[0];
    if (!preset) {
      show('', {relayout: true, immediate: true});
      return;
    }
    show(JSON.stringify(preset.scene), {relayout: true, immediate: true});
  }

  function matchingPreset() {
    if (!state.scene) {
      return '';
    }
    const found = presets.find((p) => JSON.stringify(p.scene) === state.canonical);
    return found ? found.id : '';
  }

  // ---------------------------------------------------------------------------------------------
  // Where things are drawn. The scene gives rigid bodies their positions and the contact points
  // at rigid bodies; point masses have no position in the format, so they are set side by side
  // along their contacts' normals, each a disc whose area grows with its mass.

  function layout(scene, details, frozen) {
    if (!scene || !details) {
      return null;
    }
    const bodies = scene.bodies;
    const index = new Map(bodies.map((b, i) => [b.name, i]));
    const n = bodies.length;
    const dim = details.dimension;
    const kinds = details.bodies.map((b) => b.kind);
    const contacts = scene.contacts.map((c) => ({
      bumper: index.get(c.bumper),
      wedge: index.get(c.wedge),
      normal: dim === 1 ? [Number(c.normal), 0] : vec(c.normal),
      point: c.point !== undefined ? vec(c.point) : null,
    }));

    // Sizes: a rigid body is drawn as the uniform box (or rod) its mass and inertia allow; a
    // point mass as a disc.
    const materialMasses = bodies.filter((b, i) => kinds[i] === 'material').map((b) => b.mass);
    const massScale = median(materialMasses.length ? materialMasses : [1]);
    const rigidSizes = bodies.filter((b, i) => kinds[i] === 'rigid')
                           .map((b) => Math.sqrt(3 * b.inertia / b.mass));
    const base = rigidSizes.length ? 0.5 * median(rigidSizes) : 0.5;
    const drawn = bodies.map((b, i) => ({
      kind: kinds[i],
      name: b.name,
      colour: colour(i),
      centre: null,
      radius: kinds[i] === 'material'
                  ? Math.min(2, Math.max(0.5, Math.cbrt(b.mass / massScale))) * base : 0,
      shape: null,
    }));
    for (let i = 0; i < n; ++i) {
      if (kinds[i] === 'rigid') {
        drawn[i].centre = vec(bodies[i].position);
      }
    }
    // Point masses at a contact with a point sit against it.
    for (const c of contacts) {
      if (!c.point) {
        continue;
      }
      if (kinds[c.bumper] === 'material' && !drawn[c.bumper].centre) {
        drawn[c.bumper].centre = sub(c.point, mul(c.normal, drawn[c.bumper].radius));
      }
      if (kinds[c.wedge] === 'material' && !drawn[c.wedge].centre) {
        drawn[c.wedge].centre = add(c.point, mul(c.normal, drawn[c.wedge].radius));
      }
    }
    // The rest along the normals, component by component.
    const spread = () => {
      let changed = true;
      while (changed) {
        changed = false;
        for (const c of contacts) {
          const b = drawn[c.bumper];
          const w = drawn[c.wedge];
          if (b.kind !== 'material' || w.kind !== 'material' || c.point) {
            continue;
          }
          const gap = b.radius + w.radius;
          if (b.centre && !w.centre) {
            w.centre = add(b.centre, mul(c.normal, gap));
            changed = true;
          } else if (w.centre && !b.centre) {
            b.centre = sub(w.centre, mul(c.normal, gap));
            changed = true;
          }
        }
      }
    };
    spread();
    for (let i = 0; i < n; ++i) {
      if (drawn[i].kind === 'material' && !drawn[i].centre) {
        let right = 0;
        let any = false;
        for (const d of drawn) {
          if (d.centre) {
            right = Math.max(right, d.centre[0] + (d.radius || 1) + 1);
            any = true;
          }
        }
        drawn[i].centre = [any ? right + drawn[i].radius : 0, 0];
        spread();
      }
    }

    // Contact points, and a little apart where one point mass touches several bodies at one spot
    // (a bead on two supports), so that each can be seen.
    const points = contacts.map((c) => {
      if (c.point) {
        return c.point;
      }
      const b = drawn[c.bumper];
      const w = drawn[c.wedge];
      if (b.kind === 'material') {
        return add(b.centre, mul(c.normal, b.radius));
      }
      return sub(w.centre, mul(c.normal, w.radius));
    });
    const seen = new Map();
    contacts.forEach((c, v) => {
      if (c.point) {
        return;
      }
      const key = points[v].map((x) => x.toFixed(9)).join(',');
      if (!seen.has(key)) {
        seen.set(key, []);
      }
      seen.get(key).push(v);
    });
    for (const group of seen.values()) {
      if (group.length < 2) {
        continue;
      }
      group.forEach((v, k) => {
        const c = contacts[v];
        const m = drawn[c.bumper].kind === 'material' ? c.bumper : c.wedge;
        const angle = (k - (group.length - 1) / 2) * 1.4 / Math.max(1, group.length - 1);
        points[v] = add(drawn[m].centre, rotate(sub(points[v], drawn[m].centre), angle));
      });
    }

    // Rigid shapes: a rod when the contact points lie on a line through the centre at its
    // half-length; else a box turned to the first contact's normal, its faces through the points.
    for (let i = 0; i < n; ++i) {
      if (drawn[i].kind !== 'rigid') {
        continue;
      }
      const half = Math.sqrt(3 * bodies[i].inertia / bodies[i].mass);
      const arms = [];
      let axis = null;
      contacts.forEach((c, v) => {
        if (c.bumper === i || c.wedge === i) {
          arms.push(sub(points[v], drawn[i].centre));
          axis = axis || c.normal;
        }
      });
      const rodLike = arms.length > 0 && arms.every((a) => Math.abs(norm(a) - half) <= 0.02 * half) &&
                      arms.every((a) => Math.abs(cross(a, arms[0])) <= 1e-6 * half * half);
      if (rodLike) {
        const along = arms[0];
        drawn[i].shape = {hx: half, hy: Math.max(0.05 * half, 0.04), angle: Math.atan2(along[1], along[0])};
      } else {
        const u = axis ? mul(axis, 1 / (norm(axis) || 1)) : [1, 0];
        const w = [-u[1], u[0]];
        let ea = 0;
        let eb = 0;
        for (const a of arms) {
          ea = Math.max(ea, Math.abs(dot(a, u)));
          eb = Math.max(eb, Math.abs(dot(a, w)));
        }
        if (ea === 0 && eb === 0) {
          ea = eb = half / Math.SQRT2;
        } else if (ea * ea + eb * eb < half * half) {
          eb = Math.sqrt(half * half - ea * ea);
        }
        drawn[i].shape = {hx: Math.max(ea, 0.04 * half), hy: Math.max(eb, 0.04 * half),
                          angle: Math.atan2(u[1], u[0])};
      }
      drawn[i].radius = half;
    }

    // Static bodies: a hatched surface through their contact points, across each normal.
    const surfaces = [];
    contacts.forEach((c, v) => {
      for (const [s, other, outward] of [[c.bumper, c.wedge, c.normal], [c.wedge, c.bumper, mul(c.normal, -1)]]) {
        if (drawn[s].kind !== 'static') {
          continue;
        }
        const shared = contacts.filter((o) => o.bumper === other || o.wedge === other).length;
        const reach = Math.max(drawn[other].radius, 0.3) * (shared > 1 && drawn[other].kind === 'material' ? 0.35 : 1.3);
        let surface = surfaces.find((f) => f.body === s && Math.abs(dot(f.outward, outward) - 1) < 1e-9 &&
                                           Math.abs(dot(sub(points[v], f.through), outward)) < 1e-6);
        const tangent = [-outward[1], outward[0]];
        const along = surface ? dot(sub(points[v], surface.through), tangent) : 0;
        if (!surface) {
          surface = {body: s, outward, through: points[v], from: -reach, to: reach};
          surfaces.push(surface);
        } else {
          surface.from = Math.min(surface.from, along - reach);
          surface.to = Math.max(surface.to, along + reach);
        }
      }
    });

    // Motion: each movable body's velocity and spin before and after, from the library.
    const motion = details.bodies.map((b) => ({
      before: vec(b.before.velocity),
      after: vec(b.after.velocity),
      spinBefore: b.before.angular_velocity,
      spinAfter: b.after.angular_velocity,
    }));
    const movable = drawn.map((d, i) => i).filter((i) => drawn[i].kind !== 'static');
    const sizes = movable.map((i) => drawn[i].radius);
    const typical = median(sizes.length ? sizes : [base]);
    let fastest = 0;
    for (const i of movable) {
      const m = motion[i];
      fastest = Math.max(fastest, norm(m.before), norm(m.after),
                         Math.abs(m.spinBefore) * drawn[i].radius,
                         Math.abs(m.spinAfter) * drawn[i].radius);
    }
    let spinFastest = 0;
    for (const i of movable) {
      spinFastest = Math.max(spinFastest, Math.abs(motion[i].spinBefore), Math.abs(motion[i].spinAfter));
    }
    const scales = frozen ? frozen.scales : {
      // The largest velocity arrow is 1.5 times the typical size; the window of the animation
      // lets the fastest point travel two typical sizes each way.
      arrow: fastest > 0 ? 1.5 * typical / fastest : 1,
      window: fastest > 0 ? 2 * typical / fastest : 1,
      spin: spinFastest > 0 ? Math.min(0.6, 0.75 * Math.PI / spinFastest) : 0.6,
    };

    const result = {dim, drawn, contacts, points, surfaces, motion, scales, typical, box: null};
    result.box = frozen ? frozen.box : bounds(result);
    return result;
  }

  // Where a body is at time t (in seconds of the scene; 0 the instant of the impulses).
  function placeAt(l, i, t) {
    const d = l.drawn[i];
    if (d.kind === 'static') {
      return {centre: d.centre, angle: d.shape ? d.shape.angle : 0};
    }
    const m = l.motion[i];
    const v = t < 0 ? m.before : m.after;
    const w = t < 0 ? m.spinBefore : m.spinAfter;
    return {centre: add(d.centre, mul(v, t)), angle: (d.shape ? d.shape.angle : 0) + w * t};
  }

  function bounds(l) {
    let box = [Infinity, Infinity, -Infinity, -Infinity];
    const take = (p, r) => {
      box = [Math.min(box[0], p[0] - r), Math.min(box[1], p[1] - r),
             Math.max(box[2], p[0] + r), Math.max(box[3], p[1] + r)];
    };
    const T = l.scales.window;
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      const reach = d.radius;
      for (const t of [-T, 0, T]) {
        take(placeAt(l, i, t).centre, reach);
      }
      take(add(d.centre, mul(l.motion[i].before, l.scales.arrow)), 0.1 * l.typical);
      take(add(d.centre, mul(l.motion[i].after, l.scales.arrow)), 0.1 * l.typical);
    });
    for (const p of l.points) {
      take(p, 0.2 * l.typical);
    }
    for (const s of l.surfaces) {
      const tangent = [-s.outward[1], s.outward[0]];
      take(add(s.through, mul(tangent, s.from)), 0.3 * l.typical);
      take(add(s.through, mul(tangent, s.to)), 0.3 * l.typical);
    }
    if (!isFinite(box[0])) {
      box = [-1, -1, 1, 1];
    }
    const margin = 0.08 * Math.max(box[2] - box[0], box[3] - box[1], 1e-9);
    return [box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin];
  }

  // ---------------------------------------------------------------------------------------------
  // The canvas.

  const canvas = $('view');
  const context = canvas.getContext('2d');
  let handles = [];  // what the pointer can drag, as last drawn

  function transform(l) {
    const width = canvas.width;
    const height = canvas.height;
    const [x0, y0, x1, y1] = l.box;
    const scale = Math.min(width / (x1 - x0), height / (y1 - y0));
    const ox = (width - scale * (x1 - x0)) / 2;
    const oy = (height - scale * (y1 - y0)) / 2;
    return {
      scale,
      to: (p) => [ox + (p[0] - x0) * scale, height - oy - (p[1] - y0) * scale],
      from: (q) => [x0 + (q[0] - ox) / scale, y0 + (height - oy - q[1]) / scale],
    };
  }

  function arrow(from, to, style, width, dashed) {
    const length = Math.hypot(to[0] - from[0], to[1] - from[1]);
    if (length < 1) {
      return;
    }
    const head = Math.min(12 * devicePixelRatio, length * 0.45);
    const angle = Math.atan2(to[1] - from[1], to[0] - from[0]);
    context.save();
    context.strokeStyle = style;
    context.fillStyle = style;
    context.lineWidth = width;
    context.setLineDash(dashed ? [6 * devicePixelRatio, 4 * devicePixelRatio] : []);
    context.beginPath();
    context.moveTo(from[0], from[1]);
    context.lineTo(to[0] - head * 0.7 * Math.cos(angle), to[1] - head * 0.7 * Math.sin(angle));
    context.stroke();
    context.setLineDash([]);
    context.beginPath();
    context.moveTo(to[0], to[1]);
    context.lineTo(to[0] - head * Math.cos(angle - 0.4), to[1] - head * Math.sin(angle - 0.4));
    context.lineTo(to[0] - head * Math.cos(angle + 0.4), to[1] - head * Math.sin(angle + 0.4));
    context.closePath();
    context.fill();
    context.restore();
  }

  // Text with a white rim, readable over lines and bodies.
  function halo(text, x, y, style = '#1d2430') {
    context.save();
    context.lineJoin = 'round';
    context.strokeStyle = 'rgba(255, 255, 255, 0.9)';
    context.lineWidth = 3 * devicePixelRatio;
    context.strokeText(text, x, y);
    context.fillStyle = style;
    context.fillText(text, x, y);
    context.restore();
  }

  function draw() {
    const dpr = devicePixelRatio;
    context.setTransform(1, 0, 0, 1, 0, 0);
    context.clearRect(0, 0, canvas.width, canvas.height);
    handles = [];
    impulseArrows = [];
    const l = state.layout;
    if (!l) {
      context.fillStyle = '#5a6372';
      context.font = `${15 * dpr}px system-ui, sans-serif`;
      context.textAlign = 'center';
      context.fillText(state.out && state.out.error ? 'The scene was refused: see the message below.'
                                                    : 'No scene.',
                       canvas.width / 2, canvas.height / 2);
      return;
    }
    const view = transform(l);
    const px = (world) => world * view.scale;
    const time = state.t * l.scales.window;

    // Static surfaces, hatched on the body's side.
    for (const s of l.surfaces) {
      const tangent = [-s.outward[1], s.outward[0]];
      const a = view.to(add(s.through, mul(tangent, s.from)));
      const b = view.to(add(s.through, mul(tangent, s.to)));
      const inward = [-s.outward[0], s.outward[1]];  // screen y points down
      const depth = 10 * dpr;
      context.strokeStyle = '#4a5260';
      context.lineWidth = 2 * dpr;
      context.beginPath();
      context.moveTo(a[0], a[1]);
      context.lineTo(b[0], b[1]);
      context.stroke();
      context.lineWidth = 1 * dpr;
      const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
      const steps = Math.max(2, Math.floor(length / (9 * dpr)));
      context.beginPath();
      for (let k = 0; k <= steps; ++k) {
        const p = [a[0] + (b[0] - a[0]) * k / steps, a[1] + (b[1] - a[1]) * k / steps];
        context.moveTo(p[0], p[1]);
        context.lineTo(p[0] + inward[0] * depth - (b[0] - a[0]) / length * depth * 0.6,
                       p[1] + inward[1] * depth - (b[1] - a[1]) / length * depth * 0.6);
      }
      context.stroke();
      const name = l.drawn[s.body].name;
      context.fillStyle = '#4a5260';
      context.font = `${12 * dpr}px system-ui, sans-serif`;
      context.textAlign = 'center';
      // The name near one end, inside the body, where the bodies on it do not cover it.
      const end = Math.abs(b[0] - a[0]) >= Math.abs(b[1] - a[1]) ? (b[0] > a[0] ? b : a) : (b[1] > a[1] ? b : a);
      context.textAlign = 'right';
      halo(name, end[0] + inward[0] * 22 * dpr, end[1] + inward[1] * 22 * dpr + 4 * dpr);
    }

    // Bodies.
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      const at = placeAt(l, i, time);
      const c = view.to(at.centre);
      context.save();
      context.fillStyle = d.colour + '33';
      context.strokeStyle = d.colour;
      context.lineWidth = 2 * dpr;
      if (d.kind === 'material') {
        context.beginPath();
        context.arc(c[0], c[1], px(d.radius), 0, 2 * Math.PI);
        context.fill();
        context.stroke();
      } else {
        context.translate(c[0], c[1]);
        context.rotate(-at.angle);
        context.beginPath();
        context.rect(-px(d.shape.hx), -px(d.shape.hy), 2 * px(d.shape.hx), 2 * px(d.shape.hy));
        context.fill();
        context.stroke();
        context.beginPath();  // a mark that shows the turning
        context.moveTo(0, 0);
        context.lineTo(px(d.shape.hx) * 0.8, 0);
        context.stroke();
      }
      context.restore();
      context.fillStyle = d.colour;
      context.beginPath();
      context.arc(c[0], c[1], 2.5 * dpr, 0, 2 * Math.PI);
      context.fill();
      context.font = `${12 * dpr}px system-ui, sans-serif`;
      context.textAlign = 'center';
      // The name inside the body when it fits, else under it.
      const inside = d.kind === 'rigid' ? 2 * px(Math.min(d.shape.hx, d.shape.hy)) > 14 * dpr
                                        : 2 * px(d.radius) > context.measureText(d.name).width + 6 * dpr;
      const below = d.kind === 'material' ? px(d.radius) : px(Math.hypot(d.shape.hx, d.shape.hy));
      if (l.drawn.length <= 30) {  // beyond, the names would cover each other: the tables have them
        halo(d.name, c[0], inside ? c[1] - 6 * dpr : c[1] + below + 14 * dpr);
      }
    });

    // Contacts: the point, the normal (outward from the bumper), the impulse's size.
    const impulses = state.result ? state.result.impulses : [];
    drawImpulses(l, view, impulses);
    l.contacts.forEach((c, v) => {
      const p = view.to(l.points[v]);
      const tip = [p[0] + c.normal[0] * 28 * dpr, p[1] - c.normal[1] * 28 * dpr];
      arrow(p, tip, '#444', 1.5 * dpr, false);
      context.fillStyle = '#000';
      context.beginPath();
      context.arc(p[0], p[1], 3.5 * dpr, 0, 2 * Math.PI);
      context.fill();
      const magnitude = impulses[v] ? impulses[v].magnitude : NaN;
      if (l.contacts.length <= 12) {
        // Beside the normal's tip; for a normal across the screen (a row of balls), above the
        // bodies instead, where the next body does not hide it.
        const across = Math.abs(c.normal[1]) < 0.7;
        const reach = Math.max(l.drawn[c.bumper].radius, l.drawn[c.wedge].radius);
        const at = across ? view.to(add(l.points[v], [0, reach])) : tip;
        context.font = `${11 * dpr}px system-ui, sans-serif`;
        context.textAlign = across ? 'center' : 'left';
        const x = across ? at[0] : at[0] + 4 * dpr;
        let y = across ? at[1] - 8 * dpr - (v % 2) * 13 * dpr : at[1];
        // With friction, the tangential impulse too: on a second line under the normal's tip, on the
        // same line above a row of bodies (whose labels take two rows already).
        const tangential = impulses[v] && impulses[v].tangential !== undefined
                               ? `tangential ${num(impulses[v].tangential, Math.abs(magnitude))}` : '';
        if (tangential && !across) {
          // Under the first line; both a line higher where the canvas ends.
          if (y + 13 * dpr > canvas.height - 4 * dpr) {
            y -= 13 * dpr;
          }
          halo(tangential, x, y + 13 * dpr);
        }
        halo(`${v}: Fdt ${num(magnitude)}${tangential && across ? `, ${tangential}` : ''}`, x, y,
             magnitude < 0 ? '#b42318' : '#1d2430');
      }
    });

    // Velocities (solid before, dashed after) with a handle on the one before; spins on a ring.
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      const at = placeAt(l, i, time);
      const c = view.to(at.centre);
      const m = l.motion[i];
      const tipOf = (v) => view.to(add(at.centre, mul(v, l.scales.arrow)));
      if (time >= 0) {
        arrow(c, tipOf(m.after), '#1a7f37', 2.5 * dpr, true);
      }
      if (time <= 0) {
        const tip = tipOf(m.before);
        arrow(c, tip, '#1f5fae', 2.5 * dpr, false);
        const handle = Math.hypot(tip[0] - c[0], tip[1] - c[1]) < 6 * dpr ? c : tip;
        context.fillStyle = '#fff';
        context.strokeStyle = '#1f5fae';
        context.lineWidth = 2 * dpr;
        context.beginPath();
        context.arc(handle[0], handle[1], 6 * dpr, 0, 2 * Math.PI);
        context.fill();
        context.stroke();
        handles.push({kind: 'velocity', body: i, at: handle});
      }
      if (d.kind === 'rigid') {
        const ring = px(d.radius) * 0.8;
        context.strokeStyle = 'rgba(154, 163, 176, 0.55)';
        context.lineWidth = 1 * dpr;
        context.beginPath();
        context.arc(c[0], c[1], ring, 0, 2 * Math.PI);
        context.stroke();
        const spinArc = (w, style, dashed) => {
          const sweep = w * l.scales.spin;
          if (Math.abs(sweep) < 1e-3) {
            return;
          }
          context.save();
          context.strokeStyle = style;
          context.lineWidth = 3 * dpr;
          context.setLineDash(dashed ? [6 * dpr, 4 * dpr] : []);
          context.beginPath();
          // Screen angles turn clockwise; the scene's counter-clockwise spin is positive.
          context.arc(c[0], c[1], ring, -Math.PI / 2, -Math.PI / 2 - sweep, sweep > 0);
          context.stroke();
          context.restore();
        };
        if (time >= 0) {
          spinArc(m.spinAfter, '#1a7f37', true);
        }
        if (time <= 0) {
          spinArc(m.spinBefore, '#1f5fae', false);
          const angle = Math.PI / 2 + m.spinBefore * l.scales.spin;
          const h = [c[0] + ring * Math.cos(angle), c[1] - ring * Math.sin(angle)];
          context.fillStyle = '#fff';
          context.strokeStyle = '#1f5fae';
          context.lineWidth = 2 * dpr;
          context.beginPath();
          context.rect(h[0] - 5 * dpr, h[1] - 5 * dpr, 10 * dpr, 10 * dpr);
          context.fill();
          context.stroke();
          handles.push({kind: 'spin', body: i, at: h, centre: c});
        }
      }
    });

    // The clock, in the corner.
    context.fillStyle = '#5a6372';
    context.font = `${12 * dpr}px system-ui, sans-serif`;
    context.textAlign = 'left';
    context.fillText(time < 0 ? 'before the impulses' : time > 0 ? 'after the impulses' : 'the instant of contact',
                     8 * dpr, 16 * dpr);
    context.fillStyle = '#1f5fae';
    context.fillText('— velocity before', 8 * dpr, canvas.height - 24 * dpr);
    context.fillStyle = '#1a7f37';
    context.fillText('- - velocity after', 8 * dpr, canvas.height - 8 * dpr);
  }

  // Each contact's impulse as the whole vector the library reports (on_bumper: the normal part,
  // and with friction the tangential part too), drawn from the contact point on the body that
  // receives it: the bumper, or the wedge (the vector reversed) when the bumper is static. The
  // longest is 60 px (less on a small canvas); with friction its two parts are drawn thin and
  // dotted, as the sides of the parallelogram. Up to 12 contacts (beyond, the arrows would cover
  // the bodies).
  let impulseArrows = [];  // as drawn, for the browser tests

  function drawImpulses(l, view, impulses) {
    impulseArrows = [];
    if (l.contacts.length > 12 || impulses.length !== l.contacts.length) {
      return;
    }
    const dpr = devicePixelRatio;
    const vectors = impulses.map((i, v) => {
      const c = l.contacts[v];
      const onStatic = l.drawn[c.bumper].kind === 'static';
      const sign = onStatic ? -1 : 1;
      const whole = mul(l.dim === 1 ? [Number(i.on_bumper), 0] : vec(i.on_bumper), sign);
      const normal = mul(c.normal, -sign * i.magnitude);
      return {whole, normal, body: onStatic ? c.wedge : c.bumper, rough: i.tangential !== undefined};
    });
    const longest = Math.max(0, ...vectors.map((w) => norm(w.whole)));
    if (!(longest > 0)) {
      return;
    }
    // At most 60 px, and a quarter of a small canvas (a phone's), where 60 px would hide the scene.
    const length = Math.min(60 * dpr, 0.25 * Math.min(canvas.width, canvas.height)) / longest;
    const colour = '#a4460e';
    vectors.forEach((w, v) => {
      const p = view.to(l.points[v]);
      const screen = (x) => [p[0] + x[0] * length, p[1] - x[1] * length];
      const tip = screen(w.whole);
      if (w.rough && norm(sub(w.whole, w.normal)) > 1e-12 * longest) {
        const corner = screen(w.normal);
        context.save();
        context.strokeStyle = colour;
        context.lineWidth = 1 * dpr;
        context.setLineDash([2 * dpr, 3 * dpr]);
        context.beginPath();
        context.moveTo(p[0], p[1]);
        context.lineTo(corner[0], corner[1]);
        context.lineTo(tip[0], tip[1]);
        context.stroke();
        context.restore();
      }
      arrow(p, tip, colour, 3 * dpr, false);
      impulseArrows.push({contact: v, body: l.drawn[w.body].name, from: p, to: tip});
    });
    context.fillStyle = colour;
    context.font = `${12 * dpr}px system-ui, sans-serif`;
    context.textAlign = 'left';
    context.fillText('→ impulse at each contact', 8 * dpr, 32 * dpr);  // under the clock
  }

  function resizeCanvas() {
    const rect = canvas.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width * devicePixelRatio));
    const height = Math.max(1, Math.round(rect.height * devicePixelRatio));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    draw();
  }

  // Dragging a handle: the velocity before (the arrow's tip), or the spin (the ring's handle).
  let dragging = null;

  function pointerAt(event) {
    const rect = canvas.getBoundingClientRect();
    return [(event.clientX - rect.left) * canvas.width / rect.width,
            (event.clientY - rect.top) * canvas.height / rect.height];
  }

  canvas.addEventListener('pointerdown', (event) => {
    if (!state.layout) {
      return;
    }
    const p = pointerAt(event);
    let best = null;
    for (const h of handles) {
      const distance = Math.hypot(h.at[0] - p[0], h.at[1] - p[1]);
      if (distance <= 12 * devicePixelRatio && (!best || distance < best.distance)) {
        best = {...h, distance};
      }
    }
    if (!best) {
      return;
    }
    event.preventDefault();
    pause();
    setTime(0);
    dragging = best;
    state.frozen = {scales: state.layout.scales, box: state.layout.box};
    canvas.setPointerCapture(event.pointerId);
  });

  canvas.addEventListener('pointermove', (event) => {
    if (!dragging || !state.layout) {
      return;
    }
    const l = state.layout;
    const view = transform(l);
    const i = dragging.body;
    const world = view.from(pointerAt(event));
    const d = l.drawn[i];
    if (dragging.kind === 'velocity') {
      const v = mul(sub(world, d.centre), 1 / l.scales.arrow);
      const digits = 3;
      edit((scene) => {
        const body = scene.bodies[i];
        delete body.momentum;
        body.velocity = l.dim === 1 ? round(v[0], digits) : [round(v[0], digits), round(v[1], digits)];
      }, event, true);
    } else {
      const c = dragging.centre;
      const q = pointerAt(event);
      let angle = Math.atan2(-(q[1] - c[1]), q[0] - c[0]) - Math.PI / 2;
      angle = Math.atan2(Math.sin(angle), Math.cos(angle));
      const w = round(angle / l.scales.spin, 3);
      edit((scene) => {
        const body = scene.bodies[i];
        delete body.angular_momentum;
        body.angular_velocity = w;
      }, event, true);
    }
  });

  const endDrag = () => {
    if (dragging) {
      dragging = null;
      state.frozen = null;
      show(state.text, {immediate: true});
    }
  };
  canvas.addEventListener('pointerup', endDrag);
  canvas.addEventListener('pointercancel', endDrag);

  // ---------------------------------------------------------------------------------------------
  // The animation.

  const timeInput = $('time');
  const playButton = $('play');

  function setTime(t) {
    state.t = Math.max(-1, Math.min(1, t));
    timeInput.value = String(Math.round(state.t * 1000));
    const seconds = state.layout ? state.t * state.layout.scales.window : 0;
    $('time-text').textContent = `t = ${num(round(seconds, 3))}`;
    draw();
  }

  function frame(now) {
    if (!state.playing) {
      return;
    }
    const started = performance.now();
    const elapsed = Math.min(0.1, (now - state.lastFrame) / 1000);
    state.lastFrame = now;
    // The whole window (-T .. T) takes 3 s, or 15 s in slow motion.
    const rate = (2 / 3) * ($('slow').checked ? 0.2 : 1);
    let t = state.t + elapsed * rate;
    if (t > 1) {
      t = -1;
    }
    setTime(t);
    window.impulselabFrameMs = performance.now() - started;  // the cost of one frame's drawing
    requestAnimationFrame(frame);
  }

  function play() {
    if (state.playing || !state.layout) {
      return;
    }
    state.playing = true;
    playButton.setAttribute('aria-pressed', 'true');
    playButton.textContent = '\u23F8\uFE0E Pause';
    if (state.t >= 1) {
      state.t = -1;
    }
    state.lastFrame = performance.now();
    requestAnimationFrame(frame);
  }

  function pause() {
    state.playing = false;
    playButton.setAttribute('aria-pressed', 'false');
    playButton.textContent = '\u25B6\uFE0E Play';
  }

  playButton.addEventListener('click', () => (state.playing ? pause() : play()));
  $('step-back').addEventListener('click', () => {
    pause();
    setTime(state.t - 0.05);
  });
  $('step-forward').addEventListener('click', () => {
    pause();
    setTime(state.t + 0.05);
  });
  timeInput.addEventListener('input', () => {
    pause();
    setTime(Number(timeInput.value) / 1000);
  });

  // ---------------------------------------------------------------------------------------------
  // The controls of each body, built once per scene; their values follow the scene.

  const fields = [];  // {element, get(scene) -> value shown}

  function addField(container, spec) {
    // spec: {id, label, value(scene), set(scene, value), min, max, step, log, slider, ariaName}
    const row = document.createElement('div');
    row.className = 'row';
    const label = document.createElement('label');
    label.htmlFor = spec.id;
    label.textContent = spec.label;
    row.appendChild(label);
    let slider = null;
    if (spec.slider) {
      slider = document.createElement('input');
      slider.type = 'range';
      slider.id = spec.id + '-slider';
      slider.setAttribute('aria-label', `${spec.ariaName}, slider${spec.log ? ' (logarithmic)' : ''}`);
      slider.min = String(spec.slider[0]);
      slider.max = String(spec.slider[1]);
      slider.step = String(spec.slider[2]);
      row.appendChild(slider);
    }
    const input = document.createElement('input');
    input.type = 'number';
    input.id = spec.id;
    input.step = 'any';
    if (spec.min !== undefined) {
      input.min = String(spec.min);
    }
    input.setAttribute('aria-label', spec.ariaName);
    row.appendChild(input);
    container.appendChild(row);

    const toSlider = (x) => (spec.log ? Math.log10(x) : x);
    const fromSlider = (s) => (spec.log ? round(10 ** s, 3) : round(s, 3));
    const field = {
      input,
      slider,
      refresh(scene) {
        const value = spec.value(scene);
        if (document.activeElement !== input && value !== undefined && input.value !== String(value)) {
          input.value = String(value);
        }
        if (slider && document.activeElement !== slider && typeof value === 'number' && isFinite(value) &&
            slider.value !== String(toSlider(value))) {
          slider.value = String(toSlider(value));
        }
      },
    };
    input.addEventListener('input', (event) => {
      const value = input.valueAsNumber;
      if (input.value.trim() === '' || !isFinite(value)) {
        return;  // half typed: wait
      }
      edit((scene) => spec.set(scene, value), event);
      if (slider) {
        slider.value = String(toSlider(value));
      }
    });
    if (slider) {
      slider.addEventListener('input', (event) => {
        const value = fromSlider(Number(slider.value));
        input.value = String(value);
        edit((scene) => spec.set(scene, value), event);
      });
    }
    fields.push(field);
    return field;
  }

  function bodyVelocity(scene, i) {
    const body = scene.bodies[i];
    if (body.velocity !== undefined) {
      return vec(body.velocity);
    }
    return state.details ? vec(state.details.bodies[i].before.velocity) : [0, 0];
  }

  function bodySpin(scene, i) {
    const body = scene.bodies[i];
    if (body.angular_velocity !== undefined) {
      return Number(body.angular_velocity);
    }
    return state.details ? state.details.bodies[i].before.angular_velocity : 0;
  }

  function buildBodyControls() {
    const container = $('bodies');
    container.textContent = '';
    fields.length = 0;
    const scene = state.scene;
    if (!scene) {
      container.innerHTML = '<p class="static-note">The controls appear when the scene is a JSON ' +
                            'object with bodies and contacts.</p>';
      syncControls();
      return;
    }
    const dim = scene.dimension === 1 ? 1 : 2;
    // Scenes of hundreds of bodies get controls for the first 40 only (the canvas and the scene
    // text reach the rest).
    const shown = Math.min(scene.bodies.length, 40);
    for (let i = 0; i < shown; ++i) {
      const body = scene.bodies[i];
      const name = String(body.name);
      const card = document.createElement('fieldset');
      card.className = 'body-card';
      const legend = document.createElement('legend');
      legend.innerHTML = `<span class="swatch" style="background:${colour(i)}"></span>` +
                         `${escapeHtml(name)} <small>(${escapeHtml(body.kind)})</small>`;
      card.appendChild(legend);
      const id = `body-${i}`;
      if (body.kind === 'static') {
        const note = document.createElement('p');
        note.className = 'static-note';
        note.textContent = 'Static: it does not move; it adds nothing to A and B.';
        card.appendChild(note);
        container.appendChild(card);
        continue;
      }
      addField(card, {id: `${id}-mass`, label: 'Mass', ariaName: `Mass of ${name}`, min: 0,
                      slider: [-2, 6, 0.01], log: true,
                      value: (s) => s.bodies[i].mass,
                      set: (s, x) => { s.bodies[i].mass = x; }});
      if (body.kind === 'rigid') {
        addField(card, {id: `${id}-inertia`, label: 'Moment of inertia',
                        ariaName: `Moment of inertia of ${name}`, min: 0,
                        slider: [-3, 4, 0.01], log: true,
                        value: (s) => s.bodies[i].inertia,
                        set: (s, x) => { s.bodies[i].inertia = x; }});
      }
      addField(card, {id: `${id}-elasticity`, label: 'Elasticity', ariaName: `Elasticity of ${name}`,
                      min: 0, slider: [0, 3, 0.05],
                      value: (s) => (s.bodies[i].elasticity !== undefined ? s.bodies[i].elasticity : s.elasticity),
                      set: (s, x) => { s.bodies[i].elasticity = x; }});
      const setVelocity = (s, axis, x) => {
        const v = bodyVelocity(s, i);
        v[axis] = x;
        delete s.bodies[i].momentum;
        s.bodies[i].velocity = dim === 1 ? v[0] : v;
      };
      if (dim === 1) {
        addField(card, {id: `${id}-vx`, label: 'Velocity', ariaName: `Velocity of ${name}`,
                        slider: [-10, 10, 0.1],
                        value: (s) => bodyVelocity(s, i)[0], set: (s, x) => setVelocity(s, 0, x)});
      } else {
        addField(card, {id: `${id}-vx`, label: 'Velocity x', ariaName: `Velocity of ${name}, x`,
                        slider: [-10, 10, 0.1],
                        value: (s) => bodyVelocity(s, i)[0], set: (s, x) => setVelocity(s, 0, x)});
        addField(card, {id: `${id}-vy`, label: 'Velocity y', ariaName: `Velocity of ${name}, y`,
                        slider: [-10, 10, 0.1],
                        value: (s) => bodyVelocity(s, i)[1], set: (s, x) => setVelocity(s, 1, x)});
      }
      if (body.kind === 'rigid') {
        addField(card, {id: `${id}-spin`, label: 'Spin (angular velocity)',
                        ariaName: `Spin of ${name}`, slider: [-20, 20, 0.1],
                        value: (s) => bodySpin(s, i),
                        set: (s, x) => {
                          delete s.bodies[i].angular_momentum;
                          s.bodies[i].angular_velocity = x;
                        }});
      }
      container.appendChild(card);
    }
    if (shown < scene.bodies.length) {
      const note = document.createElement('p');
      note.className = 'static-note';
      note.textContent = `Controls for the first ${shown} of ${scene.bodies.length} bodies; edit ` +
                         'the others in the scene\'s JSON below.';
      container.appendChild(note);
    }
    syncControls();
  }

  const methodSelect = $('method');
  const dependentSelect = $('dependent');
  const restitutionSelect = $('restitution');
  const frictionRange = $('friction');
  const frictionNumber = $('friction-number');
  const defaultRange = $('default-elasticity');
  const defaultNumber = $('default-elasticity-number');

  // The contacts that have a μ of their own (the page edits only the scene's default): named
  // under the control, so that a reader knows why the slider does not move them.
  function contactFrictionNote(scene) {
    const own = scene.contacts.map((c, v) => [c, v]).filter(([c]) => c.friction !== undefined);
    if (own.length === 0) {
      return '';
    }
    const shown = own.slice(0, 6).map(([c, v]) => `contact ${v} (${c.bumper}–${c.wedge}) μ = ${num(Number(c.friction))}`);
    return `Contacts with a μ of their own, which the slider leaves as they are: ${shown.join('; ')}` +
           `${own.length > shown.length ? `; and ${own.length - shown.length} more` : ''} (edit them in the scene's JSON below).`;
  }

  function syncControls() {
    const scene = state.scene;
    const enabled = Boolean(scene);
    for (const element of [methodSelect, dependentSelect, restitutionSelect, frictionRange, frictionNumber,
                           defaultRange, defaultNumber]) {
      element.disabled = !enabled;
    }
    $('contact-friction').textContent = scene ? contactFrictionNote(scene) : '';
    if (scene) {
      const solver = isObject(scene.solver) ? scene.solver : {};
      methodSelect.value = solver.method || 'simultaneous';
      dependentSelect.value = solver.dependent || 'minimum-norm';
      restitutionSelect.value = solver.restitution || 'newton';
      // No key is μ = 0: a frictionless scene.
      const mu = scene.friction === undefined ? 0 : scene.friction;
      if (typeof mu === 'number') {
        if (document.activeElement !== frictionNumber && frictionNumber.valueAsNumber !== mu) {
          frictionNumber.value = String(mu);
        }
        if (document.activeElement !== frictionRange) {
          frictionRange.value = String(mu);
        }
      }
      const hasDefault = typeof scene.elasticity === 'number';
      $('default-elasticity-row').hidden = !hasDefault;
      if (hasDefault) {
        if (document.activeElement !== defaultNumber) {
          defaultNumber.value = String(scene.elasticity);
        }
        if (document.activeElement !== defaultRange) {
          defaultRange.value = String(scene.elasticity);
        }
      }
      for (const field of fields) {
        field.refresh(scene);
      }
    }
    const preset = $('preset');
    const id = matchingPreset();
    preset.value = id;
    fillSceneText();
  }

  // The scene's text in the editor, while the editor is open (a closed one is filled when opened).
  function fillSceneText() {
    if ($('scene-text-box').open && document.activeElement !== $('scene-text')) {
      $('scene-text').value = state.bytes !== null ? new TextDecoder().decode(state.bytes)
                            : state.fromControls && state.scene ? JSON.stringify(state.scene, null, 2)
                            : state.text;
    }
  }
  $('scene-text-box').addEventListener('toggle', fillSceneText);

  function setSolver(key, value, fallback) {
    edit((scene) => {
      if (!isObject(scene.solver)) {
        scene.solver = {};
      }
      if (value === fallback) {
        delete scene.solver[key];
      } else {
        scene.solver[key] = value;
      }
      if (Object.keys(scene.solver).length === 0) {
        delete scene.solver;
      }
    });
  }

  methodSelect.addEventListener('change', (event) => setSolver('method', methodSelect.value, 'simultaneous', event));
  dependentSelect.addEventListener('change', () => setSolver('dependent', dependentSelect.value, 'minimum-norm'));
  // Newton's law is the default: choosing it removes the key, so that a scene without friction
  // stays the paper's, byte for byte.
  restitutionSelect.addEventListener('change', () => setSolver('restitution', restitutionSelect.value, 'newton'));

  // The scene's default μ. 0 removes the key (a frictionless scene keeps its text, and so its
  // address and result); a new key goes after the default elasticity, where the scene format's
  // examples write it, so that μ set back to a preset's value gives that preset's scene again.
  function setFriction(scene, mu) {
    if (mu === 0) {
      delete scene.friction;
      return;
    }
    if (Object.prototype.hasOwnProperty.call(scene, 'friction')) {
      scene.friction = mu;
      return;
    }
    const entries = Object.entries(scene);
    const after = entries.findIndex(([key]) => key === 'elasticity');
    const at = after >= 0 ? after + 1 : entries.findIndex(([key]) => key === 'dimension') + 1;
    entries.splice(at, 0, ['friction', mu]);
    for (const [key] of entries) {
      delete scene[key];
    }
    for (const [key, value] of entries) {
      scene[key] = value;
    }
  }
  frictionRange.addEventListener('input', (event) => {
    frictionNumber.value = frictionRange.value;
    edit((scene) => setFriction(scene, Number(frictionRange.value)), event);
  });
  frictionNumber.addEventListener('input', (event) => {
    if (frictionNumber.value.trim() === '' || !isFinite(frictionNumber.valueAsNumber)) {
      return;  // half typed: wait
    }
    frictionRange.value = frictionNumber.value;
    edit((scene) => setFriction(scene, frictionNumber.valueAsNumber), event);
  });
  defaultRange.addEventListener('input', (event) => {
    defaultNumber.value = defaultRange.value;
    edit((scene) => { scene.elasticity = Number(defaultRange.value); }, event);
  });
  defaultNumber.addEventListener('input', (event) => {
    if (defaultNumber.value.trim() === '' || !isFinite(defaultNumber.valueAsNumber)) {
      return;
    }
    defaultRange.value = defaultNumber.value;
    edit((scene) => { scene.elasticity = defaultNumber.valueAsNumber; }, event);
  });

  // ---------------------------------------------------------------------------------------------
  // Presets, files, the scene's text.

  function buildPresetMenu() {
    const select = $('preset');
    const own = document.createElement('option');
    own.value = '';
    own.textContent = 'Your own scene';
    select.appendChild(own);
    let group = null;
    for (const p of presets) {
      if (!group || group.label !== p.group) {
        group = document.createElement('optgroup');
        group.label = p.group;
        select.appendChild(group);
      }
      const option = document.createElement('option');
      option.value = p.id;
      option.textContent = p.label;
      group.appendChild(option);
    }
    select.addEventListener('change', () => {
      if (select.value) {
        pause();
        loadPreset(select.value);
        setTime(0);
      }
    });
  }

  $('open-file').addEventListener('change', async (event) => {
    const file = event.target.files[0];
    if (!file) {
      return;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    const text = utf8Text(bytes);
    pause();
    show(text !== null ? text : bytes, {relayout: true, immediate: true});
    setTime(0);
    event.target.value = '';
  });

  $('download').addEventListener('click', () => {
    const content = state.bytes !== null ? state.bytes
                  : state.fromControls && state.scene ? JSON.stringify(state.scene, null, 2) + '\n'
                  : state.text;
    const blob = new Blob([content], {type: 'application/json'});
    const link = document.createElement('a');
    link.href = URL.createObjectURL(blob);
    link.download = (matchingPreset() || 'scene') + '.json';
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  });

  $('apply-text').addEventListener('click', () => {
    pause();
    show($('scene-text').value, {relayout: true, immediate: true});
    setTime(0);
  });

  window.addEventListener('hashchange', () => {
    if (location.hash !== state.lastHash) {
      pause();
      loadFromAddress();
      setTime(0);
    }
  });

  // ---------------------------------------------------------------------------------------------
  // The results beside the canvas.

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
      $('summary').textContent = '';
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

    const method = r.method || 'simultaneous';
    const methodName = {simultaneous: 'the paper\'s system', complementarity: 'complementarity',
                        serial: 'serial collisions'}[method];
    const p = r.momentum;
    const momentumScale = norm(vec(p.before)) + norm(vec(p.after));
    $('summary').textContent =
        `Method: ${methodName}. Kinetic energy ${num(r.energy.before)} → ${num(r.energy.after, r.energy.before)} ` +
        `(change ${num(r.energy.change, r.energy.before)}). Momentum ${vectorText(p.before, dim, momentumScale)} → ` +
        `${vectorText(p.after, dim, momentumScale)}.` +
        (r.serial ? ` ${r.serial.collisions} collisions in ${r.serial.passes} passes.` : '') +
        (r.complementarity ? ` Algorithm: ${r.complementarity.algorithm}, ${r.complementarity.iterations} iterations.` : '');
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

  function renderEnergy() {
    const box = $('energy-chart');
    const d = state.details;
    if (!d) {
      box.innerHTML = '';
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
    box.innerHTML = svg + '</svg>';
  }

  function renderMomentum() {
    const box = $('momentum-chart');
    const d = state.details;
    if (!d) {
      box.innerHTML = '';
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
    box.innerHTML = svg + '</svg>';
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
        const cell = Math.max(1, Math.floor(240 / n));
        map.width = map.height = cell * n;
        map.hidden = false;
        map.setAttribute('aria-label', `A, ${n} by ${n}: blue positive entries, red negative, white zero`);
        const g = map.getContext('2d');
        g.fillStyle = '#fff';
        g.fillRect(0, 0, map.width, map.height);
        for (let v = 0; v < n; ++v) {
          for (let j = 0; j < n; ++j) {
            const x = s.A[v][j];
            if (Math.abs(x) > 1e-12 * scaleA) {
              const strength = Math.min(1, Math.abs(x) / scaleA);
              g.fillStyle = x > 0 ? `rgba(31, 95, 174, ${0.15 + 0.85 * strength})` : `rgba(180, 35, 24, ${0.15 + 0.85 * strength})`;
              g.fillRect(j * cell, v * cell, cell, cell);
            }
          }
        }
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
    source.innerHTML = 'Each body adds its share to A and B (' +
        equations.map((e) => `<a href="${e.page}"${used.includes(e.id) ? ' class="used"' : ''}>(${e.id})</a> ${e.what}`)
                 .join('; ') +
        `). This scene: <strong>${used.map((id) => `(${id})`).join(', ')}</strong>; ` +
        'the elasticity e of each body scales its share of B (1 inelastic, 2 elastic).';
  }

  function timed(name, work) {
    const started = performance.now();
    work();
    state.phases[name] = (state.phases[name] || 0) + performance.now() - started;
  }

  function render() {
    const out = state.out;
    $('scene-error').textContent = out ? out.error : '';
    const warnings = $('warnings');
    warnings.innerHTML = out ? out.warnings.map((w) => `<li>${escapeHtml(w)}</li>`).join('') : '';
    // The library's warning that the collision gained energy, again beside the energy bars.
    const gained = out ? out.warnings.filter((w) => w.startsWith('energy gained')) : [];
    $('energy-warnings').innerHTML = gained.map((w) => `<li>${escapeHtml(w)} (the bar after passes the ` +
                                                     'dashed line of the energy before; <a href="friction.html#friction_energy">' +
                                                     'why</a>)</li>').join('');
    $('result-json').textContent = out ? out.resultText : '';
    if (out && out.error && state.scene === null) {
      $('scene-text-box').open = true;
    }
    timed('controls', syncControls);
    timed('tables', renderTables);
    timed('energy', renderEnergy);
    timed('momentum', renderMomentum);
    timed('system', renderSystem);
    timed('canvas', () => setTime(state.t));
  }

  // For the browser tests: where the handles are drawn, in the window's coordinates.
  window.impulselabPage = {
    handles() {
      const rect = canvas.getBoundingClientRect();
      return handles.map((h) => ({kind: h.kind, body: h.body,
                                  x: rect.left + h.at[0] * rect.width / canvas.width,
                                  y: rect.top + h.at[1] * rect.height / canvas.height}));
    },
    // Each impulse arrow: its contact, the body it acts on, its direction on the screen (x to the
    // right, y up) and its length in pixels of the canvas.
    impulseArrows() {
      return impulseArrows.map((a) => ({contact: a.contact, body: a.body,
                                         dx: a.to[0] - a.from[0], dy: a.from[1] - a.to[1]}));
    },
  };

  // ---------------------------------------------------------------------------------------------
  // Start: the module, then the scene of the address (or an example).

  buildPresetMenu();
  new ResizeObserver(resizeCanvas).observe(canvas);
  window.createImpulseLab().then((module) => {
    state.module = module;
    loadFromAddress();
  }, (error) => {
    $('scene-error').textContent = `The library did not load: ${error}`;
    document.body.dataset.ready = 'true';
  });
})();
