// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas: bodies, static surfaces, contacts (point, normal, impulse), velocities and spins,
// at the time of the animation, and the handles the pointer can take. Labels are placed where
// they cover no other label (one that finds no room is left out: the tables have it). While the
// scene is refused, the last solved scene is drawn dimmed.
'use strict';

(function (collide) {
  const {$, add, sub, mul, norm, num, state} = collide;
  const canvas = $('view');
  const context = canvas.getContext('2d');
  collide.canvas = canvas;
  // As last drawn: what the pointer can take, the labels, the impulse arrows, the markers.
  collide.drawn = {handles: [], labels: [], arrows: [], markers: [], events: [], outlines: []};

  collide.transform = (l) => {
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
  };

  // Arrows from each [from, to] of @p list, drawn together (two paths: the shafts, the heads).
  function arrows(list, style, width, dashed) {
    const dpr = devicePixelRatio;
    context.save();
    context.strokeStyle = style;
    context.fillStyle = style;
    context.lineWidth = width;
    context.setLineDash(dashed ? [6 * dpr, 4 * dpr] : []);
    const heads = [];
    context.beginPath();
    for (const [from, to] of list) {
      const length = Math.hypot(to[0] - from[0], to[1] - from[1]);
      if (length < 1) {
        continue;
      }
      const head = Math.min(12 * dpr, length * 0.45);
      const angle = Math.atan2(to[1] - from[1], to[0] - from[0]);
      context.moveTo(from[0], from[1]);
      context.lineTo(to[0] - head * 0.7 * Math.cos(angle), to[1] - head * 0.7 * Math.sin(angle));
      heads.push([to, head, angle]);
    }
    context.stroke();
    context.setLineDash([]);
    context.beginPath();
    for (const [to, head, angle] of heads) {
      context.moveTo(to[0], to[1]);
      context.lineTo(to[0] - head * Math.cos(angle - 0.4), to[1] - head * Math.sin(angle - 0.4));
      context.lineTo(to[0] - head * Math.cos(angle + 0.4), to[1] - head * Math.sin(angle + 0.4));
      context.closePath();
    }
    context.fill();
    context.restore();
  }
  const arrow = (from, to, style, width, dashed) => arrows([[from, to]], style, width, dashed);

  // A label at the first of @p places ([x, y, align]) where it covers no label drawn before and
  // stays on the canvas; none: it is left out. Text with a white rim, readable over lines.
  function label(text, places, style = '#1d2430', size = 12) {
    const dpr = devicePixelRatio;
    context.font = `${size * dpr}px system-ui, sans-serif`;
    const width = context.measureText(text).width;
    const height = size * dpr;
    for (const [x, y, align] of places) {
      const left = align === 'center' ? x - width / 2 : align === 'right' ? x - width : x;
      const box = [left - 2 * dpr, y - height * 0.85, left + width + 2 * dpr, y + height * 0.3];
      if (box[0] < 0 || box[2] > canvas.width || box[1] < 0 || box[3] > canvas.height) {
        continue;
      }
      if (collide.drawn.labels.some((o) => box[0] < o.box[2] && o.box[0] < box[2] && box[1] < o.box[3] && o.box[1] < box[3])) {
        continue;
      }
      context.save();
      context.textAlign = 'left';
      context.lineJoin = 'round';
      context.strokeStyle = 'rgba(255, 255, 255, 0.9)';
      context.lineWidth = 3 * dpr;
      context.strokeText(text, left, y);
      context.fillStyle = style;
      context.fillText(text, left, y);
      context.restore();
      collide.drawn.labels.push({text, box});
      return true;
    }
    return false;
  }

  // A handle the pointer can take: drawn (a round or square knob, all drawn together at the end),
  // or only registered where the drawing already shows it (a contact's point, the tip of its
  // normal).
  let knobs = [];
  function handle(at, shape, kind, extra) {
    collide.drawn.handles.push({kind, at, ...extra});
    if (shape !== 'none') {
      knobs.push([at, shape]);
    }
  }
  function drawKnobs() {
    const dpr = devicePixelRatio;
    context.save();
    context.fillStyle = '#fff';
    context.strokeStyle = '#1f5fae';
    context.lineWidth = 2 * dpr;
    context.beginPath();
    for (const [at, shape] of knobs) {
      if (shape === 'square') {
        context.rect(at[0] - 6 * dpr, at[1] - 6 * dpr, 12 * dpr, 12 * dpr);
      } else {
        context.moveTo(at[0] + 7 * dpr, at[1]);
        context.arc(at[0], at[1], 7 * dpr, 0, 2 * Math.PI);
      }
    }
    context.fill();
    context.stroke();
    context.restore();
    knobs = [];
  }

  collide.draw = () => {
    const dpr = devicePixelRatio;
    context.setTransform(1, 0, 0, 1, 0, 0);
    context.clearRect(0, 0, canvas.width, canvas.height);
    collide.drawn = {handles: [], labels: [], arrows: [], markers: [], events: [], outlines: []};
    knobs = [];
    const l = state.layout;
    if (!l) {
      context.fillStyle = '#5a6372';
      context.font = `${15 * dpr}px system-ui, sans-serif`;
      context.textAlign = 'center';
      const words = state.out && state.out.pending ? 'Serial collisions are running: see how far above.'
                    : state.out && state.out.error ? 'The scene was refused: see the message.' : 'No scene.';
      context.fillText(words, canvas.width / 2, canvas.height / 2);
      return;
    }
    const refused = !state.result;
    const view = collide.transform(l);
    const px = (world) => world * view.scale;
    const time = state.t * l.scales.window;
    if (time !== 0) {
      collide.timeline(l);
    }
    const step = collide.serialShown();  // a serial collision stepped to, or null
    context.save();
    context.globalAlpha = refused ? 0.4 : 1;

    // Static surfaces, hatched on the body's side.
    for (const s of l.surfaces) {
      const tangent = [-s.outward[1], s.outward[0]];
      const a = view.to(add(s.through, mul(tangent, s.from)));
      const b = view.to(add(s.through, mul(tangent, s.to)));
      const inward = [-s.outward[0], s.outward[1]];  // screen y points down
      const depth = 10 * dpr;
      const selected = collide.selection && collide.selection.body === s.body;
      context.strokeStyle = selected ? '#1f5fae' : '#4a5260';
      context.lineWidth = (selected ? 4 : 2) * dpr;
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
      collide.drawn.outlines.push({body: l.drawn[s.body].name, surface: [add(s.through, mul(tangent, s.from)),
                                   add(s.through, mul(tangent, s.to))], outward: s.outward});
      // The name inside the body, near one end, where the bodies on it do not cover it.
      const ends = [b, a].map((e) => [e[0] + inward[0] * 24 * dpr, e[1] + inward[1] * 24 * dpr + 4 * dpr]);
      label(l.drawn[s.body].name, [[ends[0][0], ends[0][1], 'right'], [ends[1][0], ends[1][1], 'left'],
                                   [(ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2, 'center']], '#4a5260');
    }

    // Bodies.
    const names = [];
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      const pose = collide.poseAt(l, i, time);
      const c = view.to(pose.centre);
      const s = d.shape;
      const selected = collide.selection && collide.selection.body === i;
      context.save();
      context.fillStyle = d.colour + '33';
      context.strokeStyle = selected ? '#1d2430' : d.colour;
      context.lineWidth = (selected ? 3.5 : 2) * dpr;
      context.translate(c[0], c[1]);
      context.rotate(-pose.angle);
      context.beginPath();
      if (s.type === 'ball' || s.type === 'disc') {
        context.arc(0, 0, px(s.r), 0, 2 * Math.PI);
      } else {
        // A rod is a line in the scene: drawn 6 px thick.
        const hy = s.type === 'rod' ? Math.max(px(s.hy), 3 * dpr) : px(s.hy);
        context.rect(-px(s.hx), -hy, 2 * px(s.hx), 2 * hy);
      }
      context.fill();
      context.stroke();
      if (s.type !== 'ball') {
        context.beginPath();  // a mark that shows the turning
        context.moveTo(0, 0);
        context.lineTo(px(s.hx) * 0.8, 0);
        context.stroke();
      }
      context.restore();
      context.fillStyle = d.colour;
      context.beginPath();
      context.arc(c[0], c[1], 2.5 * dpr, 0, 2 * Math.PI);
      context.fill();
      collide.drawn.outlines.push({body: d.name, ...collide.outline(l, i, pose)});
      names.push([d, c, s]);
    });

    // Contacts: the point, the normal (outward from the bumper), the impulse, where the contact
    // point is at this time; faded as the bodies part.
    const impulses = state.result ? state.result.impulses : state.valid ? state.valid.result.impulses : [];
    const markers = l.contacts.map((c, v) => collide.markerAt(l, v, time));
    drawImpulses(l, view, impulses, markers, step);
    // Drawn together, contact by contact only where one fades or is stepped to.
    const normals = [];
    const dots = [];
    l.contacts.forEach((c, v) => {
      const marker = markers[v];
      collide.drawn.markers.push({contact: v, at: marker.at, alpha: marker.alpha});
      if (marker.alpha <= 0) {
        return;
      }
      const p = view.to(marker.at);
      const tip = [p[0] + marker.normal[0] * 28 * dpr, p[1] - marker.normal[1] * 28 * dpr];
      const stepped = step && step.contact === v;
      if (marker.alpha < 1 || stepped) {
        context.save();
        context.globalAlpha *= marker.alpha;
        arrow(p, tip, stepped ? '#a4460e' : '#444', (stepped ? 2.5 : 1.5) * dpr, false);
        context.fillStyle = '#000';
        context.beginPath();
        context.arc(p[0], p[1], 3.5 * dpr, 0, 2 * Math.PI);
        context.fill();
        context.restore();
      } else {
        normals.push([p, tip]);
        dots.push(p);
      }
      if (time === 0 && l.current && !step && c.point && l.dim === 2) {
        handle(p, 'none', 'point', {contact: v});
        handle(tip, 'none', 'normal', {contact: v, centre: p});
      }
    });
    arrows(normals, '#444', 1.5 * dpr, false);
    context.fillStyle = '#000';
    context.beginPath();
    for (const p of dots) {
      context.moveTo(p[0] + 3.5 * dpr, p[1]);
      context.arc(p[0], p[1], 3.5 * dpr, 0, 2 * Math.PI);
    }
    context.fill();
    // Velocities (solid before, dashed after) with a handle on the one before; spins on a ring.
    const beforeArrows = [];
    const afterArrows = [];
    const rings = [];
    const shownAfter = (i) => (step ? {v: collide.vec(step.velocity[i]), w: step.angular_velocity[i]}
                                    : {v: l.motion[i].after, w: l.motion[i].spinAfter});
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      const pose = collide.poseAt(l, i, time);
      const c = view.to(pose.centre);
      const m = l.motion[i];
      const after = shownAfter(i);
      const tipOf = (v) => view.to(add(pose.centre, mul(v, l.scales.arrow)));
      if (time >= 0) {
        afterArrows.push([c, tipOf(after.v)]);
      }
      if (time <= 0) {
        const tip = tipOf(m.before);
        beforeArrows.push([c, tip]);
        if (l.current && !step) {
          handle(Math.hypot(tip[0] - c[0], tip[1] - c[1]) < 8 * dpr ? c : tip, 'dot', 'velocity', {body: i});
        }
      }
      if (d.kind === 'rigid') {
        const ring = Math.max(px(d.radius) * 0.8, 14 * dpr);
        rings.push([c, ring]);
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
          spinArc(after.w, '#1a7f37', true);
        }
        if (time <= 0) {
          spinArc(m.spinBefore, '#1f5fae', false);
          const angle = Math.PI / 2 + m.spinBefore * l.scales.spin;
          if (l.current && !step) {
            handle([c[0] + ring * Math.cos(angle), c[1] - ring * Math.sin(angle)], 'square', 'spin', {body: i, centre: c});
          }
        }
      }
    });

    context.strokeStyle = 'rgba(154, 163, 176, 0.55)';
    context.lineWidth = 1 * dpr;
    context.beginPath();
    for (const [c, ring] of rings) {
      context.moveTo(c[0] + ring, c[1]);
      context.arc(c[0], c[1], ring, 0, 2 * Math.PI);
    }
    context.stroke();
    arrows(afterArrows, '#1a7f37', 2.5 * dpr, true);
    arrows(beforeArrows, '#1f5fae', 2.5 * dpr, false);
    drawKnobs();

    // Where a body stopped: a collision the page does not compute.
    const side = time > 0 && l.timeline ? l.timeline.after : time < 0 && l.timeline ? l.timeline.before : null;
    for (const e of side ? side.events : []) {
      if (Math.abs(time) < Math.abs(e.t)) {
        continue;
      }
      const p = view.to(e.point);
      context.strokeStyle = '#b42318';
      context.lineWidth = 2 * dpr;
      context.beginPath();
      for (let k = 0; k < 4; ++k) {
        const a = k * Math.PI / 4;
        context.moveTo(p[0] - 7 * dpr * Math.cos(a), p[1] - 7 * dpr * Math.sin(a));
        context.lineTo(p[0] + 7 * dpr * Math.cos(a), p[1] + 7 * dpr * Math.sin(a));
      }
      context.stroke();
      collide.drawn.events.push({t: e.t, point: e.point});
    }
    context.restore();

    // Labels last, each where it covers no other: the contacts' impulses, then the bodies' names,
    // then the collisions not computed.
    // Up to 12 contacts labelled (4 on a phone's canvas, where more would cover the bodies).
    const labelled = canvas.width / devicePixelRatio < 500 ? 4 : 12;
    if (l.contacts.length <= labelled && impulses.length === l.contacts.length) {
      l.contacts.forEach((c, v) => {
        const marker = markers[v];
        if (marker.alpha < 0.5) {
          return;
        }
        const p = view.to(marker.at);
        const tip = [p[0] + marker.normal[0] * 28 * dpr, p[1] - marker.normal[1] * 28 * dpr];
        const i = impulses[v];
        const magnitude = step ? step.Fdt[v] : i.magnitude;
        const tangential = !step && i.tangential !== undefined ? `, tangential ${num(i.tangential, Math.abs(magnitude))}` : '';
        const text = `${v}: Fdt ${num(magnitude)}${tangential}`;
        const reach = Math.max(l.drawn[c.bumper].radius, l.drawn[c.wedge].radius);
        const above = view.to(add(marker.at, [0, reach]));
        label(text, [[tip[0] + 4 * dpr, tip[1], 'left'], [tip[0] - 4 * dpr, tip[1], 'right'],
                     [above[0], above[1] - 8 * dpr, 'center'], [above[0], above[1] - 22 * dpr, 'center'],
                     [p[0] + 6 * dpr, p[1] + 16 * dpr, 'left'], [p[0] - 6 * dpr, p[1] + 16 * dpr, 'right'],
                     [tip[0] + 4 * dpr, tip[1] - 14 * dpr, 'left'], [tip[0] + 4 * dpr, tip[1] + 14 * dpr, 'left']],
              magnitude < 0 ? '#b42318' : '#1d2430', 11);
      });
    }
    if (l.drawn.length <= 30) {  // beyond, the names would cover each other: the tables have them
      for (const [d, c, s] of names) {
        const extent = px(s.type === 'box' || s.type === 'rod' ? Math.hypot(s.hx, s.hy) : s.r);
        const fits = 2 * px(Math.min(s.hx, s.hy)) > 16 * dpr;
        label(d.name, [...(fits ? [[c[0], c[1] - 6 * dpr, 'center']] : []), [c[0], c[1] + extent + 14 * dpr, 'center'],
                       [c[0], c[1] - extent - 6 * dpr, 'center'], [c[0] + extent + 4 * dpr, c[1] + 4 * dpr, 'left'],
                       [c[0] - extent - 4 * dpr, c[1] + 4 * dpr, 'right']]);
      }
    }
    if (collide.drawn.events.length) {
      const e = view.to(collide.drawn.events[0].point);
      label(time > 0 ? 'a later collision, not computed here' : 'an earlier collision, not computed here',
            [[e[0], e[1] - 10 * dpr, 'center'], [e[0], e[1] + 20 * dpr, 'center'], [8 * dpr, 16 * dpr, 'left']], '#b42318', 11);
    }
  };

  // Each contact's impulse as the whole vector the library reports (on_bumper: the normal part,
  // and with friction the tangential part too), drawn from the contact point on the body that
  // receives it: the bumper, or the wedge (the vector reversed) when the bumper is static. The
  // longest is 60 px (less on a small canvas); with friction its two parts are drawn thin and
  // dotted, as the sides of the parallelogram. Up to 12 contacts (beyond, the arrows would cover
  // the bodies). While serial collisions are stepped, the impulses summed so far.
  function drawImpulses(l, view, impulses, markers, step) {
    if (l.contacts.length > 12 || impulses.length !== l.contacts.length) {
      return;
    }
    const dpr = devicePixelRatio;
    const vectors = impulses.map((i, v) => {
      const c = l.contacts[v];
      const onStatic = l.drawn[c.bumper].kind === 'static';
      const sign = onStatic ? -1 : 1;
      const magnitude = step ? step.Fdt[v] : i.magnitude;
      const whole = step ? mul(c.normal, -sign * magnitude)
                         : mul(l.dim === 1 ? [Number(i.on_bumper), 0] : collide.vec(i.on_bumper), sign);
      return {whole, normal: mul(c.normal, -sign * magnitude), body: onStatic ? c.wedge : c.bumper,
              rough: !step && i.tangential !== undefined};
    });
    const longest = Math.max(0, ...vectors.map((w) => norm(w.whole)));
    if (!(longest > 0)) {
      return;
    }
    const length = Math.min(60 * dpr, 0.25 * Math.min(canvas.width, canvas.height)) / longest;
    const colour = '#a4460e';
    vectors.forEach((w, v) => {
      const marker = markers[v];
      if (marker.alpha <= 0) {
        return;
      }
      context.save();
      context.globalAlpha *= marker.alpha;
      const p = view.to(marker.at);
      const screen = (x) => [p[0] + x[0] * length, p[1] - x[1] * length];
      const tip = screen(w.whole);
      if (w.rough && norm(sub(w.whole, w.normal)) > 1e-12 * longest) {
        const corner = screen(w.normal);
        context.strokeStyle = colour;
        context.lineWidth = 1 * dpr;
        context.setLineDash([2 * dpr, 3 * dpr]);
        context.beginPath();
        context.moveTo(p[0], p[1]);
        context.lineTo(corner[0], corner[1]);
        context.lineTo(tip[0], tip[1]);
        context.stroke();
        context.setLineDash([]);
      }
      arrow(p, tip, colour, 3 * dpr, false);
      context.restore();
      collide.drawn.arrows.push({contact: v, body: l.drawn[w.body].name, from: p, to: tip});
    });
  }

  collide.resizeCanvas = () => {
    const rect = canvas.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width * devicePixelRatio));
    const height = Math.max(1, Math.round(rect.height * devicePixelRatio));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    collide.draw();
  };
})(window.collide);
