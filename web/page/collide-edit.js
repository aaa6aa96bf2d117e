// SPDX-License-Identifier: GPL-3.0-or-later
// Building a scene on the canvas: a palette adds a disc, a box, a rod (rigid bodies whose moment
// of inertia is the shape's: m r²/2, m (w² + h²)/12, m L²/12) or a static wall; a body or a wall
// is dragged where it goes, and where it comes to touch another, it snaps against it and a
// contact is made there, its normal across the touching faces (drag the normal's tip to turn it,
// the contact's point to move it); a body or a contact is selected and deleted; undo and reset.
// The handles of the velocity (the arrow's tip) and of the spin (the ring) set the motion before.
// What is built is the scene in the address, as any other: the library solves it.
'use strict';

(function (collide) {
  const {$, add, sub, mul, dot, norm, round, state} = collide;
  const canvas = collide.canvas;
  collide.selection = null;  // {body} or {contact}
  let dragging = null;

  // The grid positions are written on: a thousandth of the scene's typical size, in round steps.
  const gridOf = (l) => 10 ** (Math.floor(Math.log10(l ? l.typical : 1)) - 3);
  const snapTo = (x, g) => Math.round(x / g) * g + 0;
  const onGrid = (p, g) => [Number(snapTo(p[0], g).toPrecision(12)), Number(snapTo(p[1], g).toPrecision(12))];

  function pointerAt(event) {
    const rect = canvas.getBoundingClientRect();
    return [(event.clientX - rect.left) * canvas.width / rect.width, (event.clientY - rect.top) * canvas.height / rect.height];
  }

  // Whether the layout drawn is this scene's (a refused scene with other bodies shows the last
  // solved one, which the canvas does not edit).
  const editable = () => state.layout && state.layout.current && state.scene;

  // The body under a point of the canvas (at the instant): movable bodies first, then surfaces.
  function bodyAt(l, view, p) {
    const world = view.from(p);
    const slack = 8 * devicePixelRatio / view.scale;
    for (let i = l.drawn.length - 1; i >= 0; --i) {
      const d = l.drawn[i];
      if (d.kind === 'static') {
        continue;
      }
      const outline = collide.outline(l, i, collide.poseAt(l, i, 0));
      const found = collide.penetration(outline, {circle: [world, slack]});
      if (found.depth > 0) {
        return i;
      }
    }
    for (const s of l.surfaces) {
      const tangent = [-s.outward[1], s.outward[0]];
      const along = dot(sub(world, s.through), tangent);
      const across = dot(sub(world, s.through), s.outward);
      if (along >= s.from && along <= s.to && across <= 2 * slack && across >= -20 * devicePixelRatio / view.scale) {
        return s.body;
      }
    }
    return -1;
  }

  canvas.addEventListener('pointerdown', (event) => {
    if (!editable()) {
      return;
    }
    const l = state.layout;
    const view = collide.transform(l);
    const p = pointerAt(event);
    // Touch targets of 44 px: a handle is taken within 22 px of its centre.
    let best = null;
    for (const h of collide.drawn.handles) {
      const distance = Math.hypot(h.at[0] - p[0], h.at[1] - p[1]) / devicePixelRatio;
      const priority = h.kind === 'velocity' || h.kind === 'spin' ? 0 : 4;  // a body's handles first
      if (distance <= 22 && (!best || distance + priority < best.score)) {
        best = {...h, score: distance + priority};
      }
    }
    let target = best;
    if (!target && state.t === 0) {
      const body = bodyAt(l, view, p);
      if (body >= 0) {
        target = {kind: 'move', body};
      }
    }
    collide.selection = target && target.kind === 'move' ? {body: target.body}
                      : target && (target.kind === 'point' || target.kind === 'normal') ? {contact: target.contact}
                      : target ? {body: target.body} : null;
    collide.syncSelection();
    if (!target) {
      collide.draw();
      return;
    }
    event.preventDefault();
    canvas.focus({preventScroll: true});
    collide.pause();
    collide.setTime(0);
    const world = view.from(p);
    dragging = {...target, start: world, moved: false, key: `${target.kind}-${target.body}-${target.contact}-${event.timeStamp}`};
    if (target.kind === 'move') {
      const d = l.drawn[target.body];
      const scene = state.scene;
      dragging.position = d.kind === 'rigid' ? collide.vec(scene.bodies[target.body].position) : null;
      dragging.points = scene.contacts.map((c) => (c.point !== undefined ? collide.vec(c.point) : null));
      dragging.name = d.name;
      if (d.kind === 'static') {
        const surface = l.surfaces.find((s) => s.body === target.body);
        dragging.wall = surface ? {through: surface.through, outward: surface.outward, from: surface.from, to: surface.to} : null;
      }
    }
    state.frozen = {scales: l.scales, box: l.box};
    canvas.setPointerCapture(event.pointerId);
    collide.draw();
  });

  canvas.addEventListener('pointermove', (event) => {
    if (!dragging || !state.layout) {
      return;
    }
    const l = state.layout;
    const view = collide.transform(l);
    const world = view.from(pointerAt(event));
    const g = gridOf(l);
    const i = dragging.body;
    const stream = {event, keepView: true, stream: dragging.key};
    dragging.moved = true;
    if (dragging.kind === 'velocity') {
      const v = mul(sub(world, l.drawn[i].centre), 1 / l.scales.arrow);
      collide.edit((scene) => {
        delete scene.bodies[i].momentum;
        scene.bodies[i].velocity = l.dim === 1 ? round(v[0], 3) : [round(v[0], 3), round(v[1], 3)];
      }, stream);
    } else if (dragging.kind === 'spin') {
      const c = dragging.centre;
      const q = pointerAt(event);
      let angle = Math.atan2(-(q[1] - c[1]), q[0] - c[0]) - Math.PI / 2;
      angle = Math.atan2(Math.sin(angle), Math.cos(angle));
      collide.edit((scene) => {
        delete scene.bodies[i].angular_momentum;
        scene.bodies[i].angular_velocity = round(angle / l.scales.spin, 3);
      }, stream);
    } else if (dragging.kind === 'point') {
      collide.edit((scene) => {
        scene.contacts[dragging.contact].point = onGrid(world, g);
      }, stream);
    } else if (dragging.kind === 'normal') {
      const q = pointerAt(event);
      const c = dragging.centre;
      const degrees = Math.round(Math.atan2(-(q[1] - c[1]), q[0] - c[0]) * 1800 / Math.PI) / 10 + 0;
      collide.edit((scene) => {
        const contact = scene.contacts[dragging.contact];
        delete contact.normal;
        contact.normal_angle = degrees;
      }, stream);
    } else if (dragging.kind === 'move') {
      moveBy(sub(world, dragging.start), g, stream);
    }
  });

  // The dragged body (or wall) moved by @p delta from where the drag began, its contact points
  // with it.
  function moveBy(delta, g, options, extra) {
    const i = dragging.body;
    const name = dragging.name;
    if (dragging.wall) {
      state.walls.set(name, {...dragging.wall, through: add(dragging.wall.through, delta)});
    } else if (!dragging.position) {
      return;  // a point mass has no position in the scene format: its contacts place it
    }
    collide.edit((scene) => {
      if (dragging.position) {
        scene.bodies[i].position = onGrid(add(dragging.position, delta), g);
      }
      scene.contacts.forEach((c, v) => {
        if ((c.bumper === name || c.wedge === name) && dragging.points[v]) {
          c.point = onGrid(add(dragging.points[v], delta), g);
        }
      });
      if (extra) {
        extra(scene);
      }
    }, options);
  }

  function endDrag(event) {
    if (!dragging) {
      return;
    }
    const done = dragging;
    if (done.kind === 'move' && done.moved && state.layout) {
      settle(done, event);
    }
    dragging = null;
    state.frozen = null;
    if (done.moved) {
      collide.show(state.text, {fromControls: true, immediate: true});
    }
  }
  canvas.addEventListener('pointerup', endDrag);
  canvas.addEventListener('pointercancel', endDrag);

  // Where a dragged body comes to rest: against the nearest body or wall within 12 px (snapped
  // so that they touch), with a contact at each point where it then touches another, and none
  // where it no longer does. A contact kept between the same two bodies keeps its order (bumper,
  // wedge); a new one has the other body as bumper (a wall always is).
  function settle(done, event) {
    if (!done.wall && !done.position) {
      return;  // a point mass: nothing moved
    }
    const i = done.body;
    const wall = Boolean(done.wall);
    const g = gridOf(state.layout);
    // The outlines of the others and of the dragged one, in the layout as it now is.
    const others = () => {
      const l = state.layout;
      const list = [];
      l.drawn.forEach((d, j) => {
        if (j !== i && d.kind !== 'static') {
          list.push({body: j, outline: collide.outline(l, j, collide.poseAt(l, j, 0))});
        } else if (j !== i && !wall) {
          for (const s of l.surfaces.filter((f) => f.body === j)) {
            list.push({body: j, surface: s});
          }
        }
      });
      return list;
    };
    const mine = () => {
      const l = state.layout;
      return wall ? collide.surfaceOutline(l, l.surfaces.find((s) => s.body === i)) : collide.outline(l, i, collide.poseAt(l, i, 0));
    };
    // How far apart (negative) or into each other, and across which axis (from the dragged one
    // to the other): a wall is the whole line it is drawn on.
    const meet = (a, o) => {
      if (!o.surface) {
        return collide.penetration(a, o.outline);
      }
      return {...collide.behind(a, o.surface), axis: mul(o.surface.outward, -1)};
    };
    // Snap against the nearest within 12 px (or run into it by at most a quarter of a typical
    // size: deeper is not a touch, e.g. behind a wall's line far from where it is drawn).
    const view = collide.transform(state.layout);
    const reach = 12 * devicePixelRatio / view.scale;
    let nearest = null;
    for (const o of others()) {
      const found = meet(mine(), o);
      if (found.depth > -reach && found.depth < 0.25 * state.layout.typical && (!nearest || found.depth > nearest.depth)) {
        nearest = found;
      }
    }
    if (nearest) {
      const now = wall ? state.walls.get(done.name).through : collide.vec(state.scene.bodies[i].position);
      const from = wall ? done.wall.through : done.position;
      moveBy(sub(sub(now, from), mul(nearest.axis, nearest.depth)), g, {keepView: true, stream: done.key});
    }
    // The contacts where it touches now.
    const touching = [];
    const a = mine();
    for (const o of others()) {
      const found = meet(a, o);
      if (found.depth > -2 * g && found.depth < 0.25 * state.layout.typical) {
        const b = o.surface ? collide.surfaceOutline(state.layout, o.surface) : o.outline;
        for (const point of touchPoints(a, b, found.axis, 2 * g, Boolean(o.surface))) {
          touching.push({other: o.body, point: onGrid(point, g), axis: found.axis});
        }
      }
    }
    const name = done.name;
    collide.edit((scene) => {
      const kept = scene.contacts.filter((c) => c.bumper !== name && c.wedge !== name);
      const old = scene.contacts.filter((c) => c.bumper === name || c.wedge === name);
      for (const t of touching) {
        const otherName = scene.bodies[t.other].name;
        const before = old.find((c) => c.bumper === otherName || c.wedge === otherName);
        const bumper = before ? before.bumper : otherName;
        const wedge = before ? before.wedge : name;
        // The normal is outward from the bumper: from the other body towards this one, or back.
        const normal = mul(t.axis, bumper === name ? 1 : -1);
        const contact = {bumper, wedge, ...normalKey(normal), point: t.point};
        if (before && before.friction !== undefined) {
          contact.friction = before.friction;
        }
        kept.push(contact);
      }
      scene.contacts = kept;
    }, {event, keepView: true, stream: done.key});
  }

  // A normal as the scene writes it: [x, y] along an axis, else its angle in degrees (to 0.1°).
  function normalKey(n) {
    for (const axis of [[1, 0], [0, 1], [-1, 0], [0, -1]]) {
      if (Math.abs(n[0] - axis[0]) < 1e-9 && Math.abs(n[1] - axis[1]) < 1e-9) {
        return {normal: axis};
      }
    }
    return {normal_angle: Math.round(Math.atan2(n[1], n[0]) * 1800 / Math.PI) / 10 + 0};
  }

  // Where outlines @p a and @p b touch, across @p axis (from a to b): a circle's nearest point;
  // two polygons' corners that lie on the other's face, the two furthest apart (on a wall, @p line:
  // a's corners on its line, wherever along it).
  function touchPoints(a, b, axis, tolerance, line) {
    if (line && a.polygon) {
      const deepest = Math.max(...a.polygon.map((p) => dot(p, axis)));
      const on = a.polygon.filter((p) => dot(p, axis) >= deepest - tolerance);
      const tangent = [-axis[1], axis[0]];
      on.sort((p, q) => dot(p, tangent) - dot(q, tangent));
      const ends = dot(on[on.length - 1], tangent) - dot(on[0], tangent) > tolerance ? [on[0], on[on.length - 1]] : [on[0]];
      const [b0] = collide.project(b, axis);
      return ends.map((p) => add(p, mul(axis, (deepest + b0) / 2 - dot(p, axis))));
    }
    const [, a1] = collide.project(a, axis);
    const [b0] = collide.project(b, axis);
    const middle = (a1 + b0) / 2;
    const onPlane = (p) => add(p, mul(axis, middle - dot(p, axis)));
    if (a.circle) {
      return [onPlane(add(a.circle[0], mul(axis, a.circle[1])))];
    }
    if (b.circle) {
      return [onPlane(sub(b.circle[0], mul(axis, b.circle[1])))];
    }
    const tangent = [-axis[1], axis[0]];
    const [ta0, ta1] = collide.project(a, tangent);
    const [tb0, tb1] = collide.project(b, tangent);
    const lo = Math.max(ta0, tb0) - tolerance;
    const hi = Math.min(ta1, tb1) + tolerance;
    const candidates = [...a.polygon.filter((p) => dot(p, axis) >= a1 - tolerance),
                        ...b.polygon.filter((p) => dot(p, axis) <= b0 + tolerance)]
        .filter((p) => dot(p, tangent) >= lo && dot(p, tangent) <= hi);
    if (!candidates.length) {
      return [];
    }
    candidates.sort((p, q) => dot(p, tangent) - dot(q, tangent));
    const first = candidates[0];
    const last = candidates[candidates.length - 1];
    return dot(last, tangent) - dot(first, tangent) > tolerance ? [onPlane(first), onPlane(last)] : [onPlane(first)];
  }

  // ---------------------------------------------------------------------------------------------
  // The palette.

  function freeName(scene, stem) {
    const taken = new Set(scene.bodies.map((b) => b.name));
    let k = 1;
    while (taken.has(`${stem} ${k}`)) {
      ++k;
    }
    return `${stem} ${k}`;
  }

  // A spot in the view where a body of bounding radius @p r covers nothing.
  function freeSpot(l, r) {
    const [x0, y0, x1, y1] = l.box;
    const taken = (p) => l.drawn.some((d, j) => d.kind !== 'static' && norm(sub(p, d.centre)) < d.radius + r + 0.1 * r) ||
                         l.surfaces.some((s) => collide.penetration({circle: [p, 1.1 * r]}, collide.surfaceOutline(l, s)).depth > 0);
    for (let row = 0; row < 6; ++row) {
      for (let col = 0; col < 9; ++col) {
        const x = (x0 + x1) / 2 + (col % 2 ? 1 : -1) * Math.ceil(col / 2) * 2.2 * r;
        const p = [x, y1 - r * (1.3 + 2.2 * row)];
        if (p[1] - r > y0 && x - r > x0 && x + r < x1 && !taken(p)) {
          return p;
        }
      }
    }
    return [x1 + 1.5 * r, (y0 + y1) / 2];
  }

  collide.addBody = (type) => {
    if (!state.scene || state.scene.dimension === 1) {
      return;
    }
    const l = state.layout;
    const size = l ? l.typical : 0.5;
    const g = gridOf(l);
    const scene = state.scene;
    if (type === 'wall') {
      const name = freeName(scene, 'wall');
      const box = l ? l.box : [-2, -2, 2, 2];
      const floor = !(l && l.surfaces.some((s) => s.outward[1] > 0.99));
      const wall = floor ? {through: onGrid([(box[0] + box[2]) / 2, box[1] + 0.1 * (box[3] - box[1])], g), outward: [0, 1]}
                         : {through: onGrid([box[2] - 0.1 * (box[2] - box[0]), (box[1] + box[3]) / 2], g), outward: [-1, 0]};
      const half = 0.4 * (floor ? box[2] - box[0] : box[3] - box[1]);
      state.walls.set(name, {...wall, from: -half, to: half});
      collide.edit((s) => s.bodies.push({name, kind: 'static'}));
    } else {
      const shape = type === 'disc' ? {type, r: size, hx: size, hy: size, angle: 0}
                  : type === 'box' ? {type, hx: size, hy: 0.7 * size, r: Math.hypot(size, 0.7 * size), angle: 0}
                  : {type: 'rod', hx: 2 * size, hy: 0.002 * size, r: 2 * size, angle: 0};
      const name = freeName(scene, type);
      const mass = 1;
      // The moment of inertia of the uniform shape about its centre.
      const inertia = type === 'disc' ? mass * shape.r ** 2 / 2
                    : type === 'box' ? mass * (shape.hx ** 2 + shape.hy ** 2) / 3 : mass * shape.hx ** 2 / 3;
      const at = onGrid(l ? freeSpot(l, shape.r) : [0, 2 * size], g);
      state.shapes.set(name, shape);
      collide.edit((s) => s.bodies.push({name, kind: 'rigid', mass, inertia: round(inertia, 6), position: at,
                                         velocity: [0, -1]}));
    }
    collide.selection = {body: state.scene.bodies.length - 1};
    collide.syncSelection();
    collide.draw();
  };

  collide.deleteSelected = () => {
    const selected = collide.selection;
    if (!selected || !state.scene) {
      return;
    }
    collide.selection = null;
    collide.edit((scene) => {
      if (selected.contact !== undefined) {
        scene.contacts.splice(selected.contact, 1);
      } else {
        const name = scene.bodies[selected.body].name;
        scene.bodies.splice(selected.body, 1);
        scene.contacts = scene.contacts.filter((c) => c.bumper !== name && c.wedge !== name);
        // Its drawn shape stays known, for undo.
      }
    });
    collide.syncSelection();
  };

  // A fresh scene to build on: a floor, and a disc falling onto it.
  collide.newScene = () => {
    collide.load(JSON.stringify({
      dimension: 2, elasticity: 1.5,
      bodies: [{name: 'floor', kind: 'static'},
               {name: 'disc 1', kind: 'rigid', mass: 1, inertia: 0.125, position: [0, 0.5], velocity: [0.5, -1]}],
      contacts: [{bumper: 'floor', wedge: 'disc 1', normal: [0, 1], point: [0, 0]}],
    }));
  };

  // What is selected, in words beside the palette; the delete button follows it.
  collide.syncSelection = () => {
    const selected = collide.selection;
    const scene = state.scene;
    let text = 'Nothing selected: tap a body, a wall or a contact point.';
    if (selected && scene && selected.contact !== undefined && scene.contacts[selected.contact]) {
      const c = scene.contacts[selected.contact];
      text = `Selected: contact ${selected.contact} (${c.bumper}–${c.wedge}).`;
    } else if (selected && scene && scene.bodies[selected.body]) {
      text = `Selected: ${scene.bodies[selected.body].name}.`;
    } else {
      collide.selection = null;
    }
    $('selection').textContent = text;
    $('delete').disabled = !collide.selection;
    const flat = !scene || scene.dimension !== 2;
    for (const id of ['add-disc', 'add-box', 'add-rod', 'add-wall']) {
      $(id).disabled = flat;
    }
    $('palette-hint').textContent = !scene ? '' : flat ? 'The palette builds scenes in the plane: choose "New scene" to start one.' : '';
  };

  for (const type of ['disc', 'box', 'rod', 'wall']) {
    $(`add-${type}`).addEventListener('click', () => collide.addBody(type));
  }
  $('delete').addEventListener('click', collide.deleteSelected);
  $('undo').addEventListener('click', collide.undo);
  $('reset').addEventListener('click', () => {
    collide.selection = null;
    collide.reset();
  });
  $('new-scene').addEventListener('click', collide.newScene);
  // From the keyboard: the arrows move the selected body (or wall) by a tenth of a typical size
  // (a hundredth with Shift), and it settles as a dropped one does.
  const steps = {ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1]};
  function nudge(direction, fine) {
    const selected = collide.selection;
    const l = state.layout;
    if (!selected || selected.body === undefined || !editable()) {
      return;
    }
    const d = l.drawn[selected.body];
    const surface = l.surfaces.find((f) => f.body === selected.body);
    if (d.kind === 'material' || (d.kind === 'static' && !surface)) {
      return;
    }
    const scene = state.scene;
    dragging = {kind: 'move', body: selected.body, name: d.name, start: [0, 0], moved: true, key: `keys-${d.name}`,
                position: d.kind === 'rigid' ? collide.vec(scene.bodies[selected.body].position) : null,
                points: scene.contacts.map((c) => (c.point !== undefined ? collide.vec(c.point) : null)),
                wall: d.kind === 'static' ? {through: surface.through, outward: surface.outward, from: surface.from, to: surface.to} : null};
    const done = dragging;
    moveBy(mul(direction, l.typical * (fine ? 0.01 : 0.1)), gridOf(l), {stream: done.key, keepView: true});
    settle(done);
    dragging = null;
    state.frozen = null;
    collide.show(state.text, {fromControls: true, immediate: true});
  }

  canvas.addEventListener('keydown', (event) => {
    if (steps[event.key]) {
      event.preventDefault();
      nudge(steps[event.key], event.shiftKey);
    } else if ((event.key === 'Enter' || event.key === ' ') && state.scene && state.scene.bodies.length) {
      // The next body selected.
      event.preventDefault();
      const at = collide.selection && collide.selection.body !== undefined ? collide.selection.body : -1;
      collide.selection = {body: (at + 1) % state.scene.bodies.length};
      collide.syncSelection();
      collide.draw();
    } else if (event.key === 'Delete' || event.key === 'Backspace') {
      event.preventDefault();
      collide.deleteSelected();
    } else if (event.key === 'Escape') {
      collide.selection = null;
      collide.syncSelection();
      collide.draw();
    }
  });
  document.addEventListener('keydown', (event) => {
    const typing = /^(INPUT|TEXTAREA|SELECT)$/.test(document.activeElement.tagName);
    if ((event.ctrlKey || event.metaKey) && !event.shiftKey && event.key === 'z' && !typing) {
      event.preventDefault();
      collide.undo();
    }
  });
})(window.collide);
