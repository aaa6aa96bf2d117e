// SPDX-License-Identifier: GPL-3.0-or-later
// Where things are drawn at the instant of the impulses: drawing rules, not physics. The scene
// gives rigid bodies their positions and the contact points at rigid bodies; point masses have
// no position in the format, so they are set side by side along their contacts' normals, each a
// ball whose area grows with its mass. A rigid body is drawn as the shape its mass and moment of
// inertia allow: a disc (I = m r²/2) when its contacts lie on that circle with normals through
// its centre, a rod (I = m L²/12) when they lie on a line through its centre at or beyond its
// ends, else a box (I = m (w² + h²)/12) turned to its first normal. The shape found when a scene
// is loaded is kept while it is edited (a mass changed does not turn a rod into a box). Static
// bodies are surfaces through their contact points, across each normal.
'use strict';

(function (collide) {
  const {vec, add, sub, mul, dot, cross, norm, unit, rotate, median, colour} = collide;

  // A rigid body's shape from its mass, moment of inertia and contacts (arms from its centre,
  // and the normals there).
  function inferShape(body, arms, normals) {
    const m = Number(body.mass);
    const I = Number(body.inertia);
    const half = Math.sqrt(3 * I / m);   // a uniform box's half diagonal, a rod's half length
    const radius = Math.sqrt(2 * I / m);  // a uniform disc's radius
    if (!(half > 0) || !isFinite(half)) {
      return {type: 'disc', r: 0.5, hx: 0.5, hy: 0.5, angle: 0};
    }
    if (arms.length === 0) {
      return {type: 'disc', r: radius, hx: radius, hy: radius, angle: 0};
    }
    const lengths = arms.map(norm);
    const disc = lengths.every((l) => Math.abs(l - radius) <= 0.02 * radius) &&
                 arms.every((a, k) => Math.abs(cross(unit(a), unit(normals[k]))) <= 0.02);
    if (disc) {
      return {type: 'disc', r: radius, hx: radius, hy: radius, angle: 0};
    }
    const longest = Math.max(...lengths);
    const along = arms[lengths.indexOf(longest)];
    // A rod: every contact on a line through its centre, and one at its end (or beyond: a mass or
    // inertia changed since the rod was drawn), or several whose normals cross the line (a rod
    // lying on supports; a box touched on two opposite faces has its normals along the line); it
    // is a line, of a thousandth of its length.
    const collinear = arms.every((a) => Math.abs(cross(a, along)) <= 0.01 * longest * longest);
    const across = arms.length >= 2 && normals.every((n) => Math.abs(cross(unit(along), unit(n))) > 0.5);
    if (collinear && longest > 0 && (longest >= 0.98 * half || across)) {
      const hx = Math.max(half, longest);
      return {type: 'rod', hx, hy: 0.001 * hx, r: hx, angle: Math.atan2(along[1], along[0])};
    }
    const u = unit(normals[0]);
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
    const hx = Math.max(ea, 0.04 * half);
    const hy = Math.max(eb, 0.04 * half);
    return {type: 'box', hx, hy, r: Math.hypot(hx, hy), angle: Math.atan2(u[1], u[0])};
  }
  collide.inferShape = inferShape;

  collide.layout = (scene, details, frozen) => {
    const state = collide.state;
    const bodies = scene.bodies;
    const index = new Map(bodies.map((b, i) => [b.name, i]));
    const n = bodies.length;
    const dim = details.dimension;
    const kinds = details.bodies.map((b) => b.kind);
    const contacts = scene.contacts.map((c) => ({
      bumper: index.get(c.bumper),
      wedge: index.get(c.wedge),
      normal: dim === 1 ? [Math.sign(Number(c.normal)) || 1, 0]
            : c.normal_angle !== undefined ? [Math.cos(c.normal_angle * Math.PI / 180), Math.sin(c.normal_angle * Math.PI / 180)]
            : unit(vec(c.normal)),
      point: c.point !== undefined ? vec(c.point) : null,
    }));

    // Sizes: point masses are balls whose area grows with the mass, scaled to the rigid bodies.
    const materialMasses = bodies.filter((b, i) => kinds[i] === 'material').map((b) => b.mass);
    const massScale = median(materialMasses.length ? materialMasses : [1]);
    const rigidSizes = bodies.filter((b, i) => kinds[i] === 'rigid').map((b) => Math.sqrt(3 * b.inertia / b.mass));
    const base = rigidSizes.length ? 0.5 * median(rigidSizes) : 0.5;
    const drawn = bodies.map((b, i) => ({
      kind: kinds[i],
      name: b.name,
      colour: colour(i),
      centre: kinds[i] === 'rigid' ? vec(b.position) : null,
      radius: kinds[i] === 'material' ? Math.min(2, Math.max(0.5, Math.cbrt(b.mass / massScale))) * base : 0,
      shape: null,
    }));
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
    for (const d of drawn) {
      if (d.kind === 'material') {
        d.shape = {type: 'ball', r: d.radius, hx: d.radius, hy: d.radius, angle: 0};
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
      return b.kind === 'material' ? add(b.centre, mul(c.normal, b.radius)) : sub(w.centre, mul(c.normal, w.radius));
    });
    const seen = new Map();
    contacts.forEach((c, v) => {
      if (!c.point) {
        const key = points[v].map((x) => x.toFixed(9)).join(',');
        seen.set(key, [...(seen.get(key) || []), v]);
      }
    });
    for (const group of seen.values()) {
      group.forEach((v, k) => {
        if (group.length < 2) {
          return;
        }
        const c = contacts[v];
        const m = drawn[c.bumper].kind === 'material' ? c.bumper : c.wedge;
        const angle = (k - (group.length - 1) / 2) * 1.4 / Math.max(1, group.length - 1);
        points[v] = add(drawn[m].centre, rotate(sub(points[v], drawn[m].centre), angle));
      });
    }

    // Rigid shapes: kept from the last layout of the same body, else found from the contacts.
    for (let i = 0; i < n; ++i) {
      if (drawn[i].kind !== 'rigid') {
        continue;
      }
      let shape = state.shapes.get(drawn[i].name);
      if (!shape) {
        const arms = [];
        const normals = [];
        contacts.forEach((c, v) => {
          if (c.bumper === i || c.wedge === i) {
            arms.push(sub(points[v], drawn[i].centre));
            normals.push(c.normal);
          }
        });
        shape = inferShape(bodies[i], arms, normals);
        state.shapes.set(drawn[i].name, shape);
      }
      drawn[i].shape = shape;
      drawn[i].radius = shape.r;
    }

    // Static bodies: the editor's walls as they were built; the others a surface through their
    // contact points, across each normal.
    const surfaces = [];
    drawn.forEach((d, s) => {
      const wall = d.kind === 'static' ? state.walls.get(d.name) : null;
      if (wall) {
        surfaces.push({body: s, outward: wall.outward, through: wall.through, from: wall.from, to: wall.to, built: true});
      }
    });
    contacts.forEach((c, v) => {
      for (const [s, other, outward] of [[c.bumper, c.wedge, c.normal], [c.wedge, c.bumper, mul(c.normal, -1)]]) {
        if (drawn[s].kind !== 'static' || state.walls.has(drawn[s].name)) {
          continue;
        }
        const shared = contacts.filter((o) => o.bumper === other || o.wedge === other).length;
        const reach = Math.max(drawn[other].radius, 0.3) *
                      (shared > 1 && drawn[other].kind === 'material' ? 0.35 : 1.3);
        let surface = surfaces.find((f) => f.body === s && Math.abs(dot(f.outward, outward) - 1) < 1e-9 &&
                                           Math.abs(dot(sub(points[v], f.through), outward)) < 1e-6);
        const tangent = [-outward[1], outward[0]];
        if (!surface) {
          surfaces.push({body: s, outward, through: points[v], from: -reach, to: reach});
        } else {
          const along = dot(sub(points[v], surface.through), tangent);
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
    let spinFastest = 0;
    for (const i of movable) {
      const m = motion[i];
      fastest = Math.max(fastest, norm(m.before), norm(m.after), Math.abs(m.spinBefore) * drawn[i].radius,
                         Math.abs(m.spinAfter) * drawn[i].radius);
      spinFastest = Math.max(spinFastest, Math.abs(m.spinBefore), Math.abs(m.spinAfter));
    }
    const scales = frozen ? frozen.scales : {
      // The largest velocity arrow is 1.5 times the typical size; the window of the animation
      // lets the fastest point travel two typical sizes each way.
      arrow: fastest > 0 ? 1.5 * typical / fastest : 1,
      window: fastest > 0 ? 2 * typical / fastest : 1,
      spin: spinFastest > 0 ? Math.min(0.6, 0.75 * Math.PI / spinFastest) : 0.6,
    };
    const result = {dim, drawn, contacts, points, surfaces, motion, scales, typical, box: null, timeline: null};
    result.box = frozen ? frozen.box : bounds(result);
    return result;
  };

  function bounds(l) {
    let box = [Infinity, Infinity, -Infinity, -Infinity];
    const take = (p, r) => {
      box = [Math.min(box[0], p[0] - r), Math.min(box[1], p[1] - r), Math.max(box[2], p[0] + r), Math.max(box[3], p[1] + r)];
    };
    const T = l.scales.window;
    l.drawn.forEach((d, i) => {
      if (d.kind === 'static') {
        return;
      }
      for (const t of [-T, 0, T]) {
        take(add(d.centre, mul(t < 0 ? l.motion[i].before : l.motion[i].after, t)), d.radius);
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

  // The outline of body @p i of layout @p l placed at @p pose ({centre, angle}), in the scene's
  // coordinates: {circle: [centre, r]} or {polygon: [corners]}; a static surface (@p i its index
  // among the surfaces) as the strip behind it.
  collide.outline = (l, i, pose) => {
    const d = l.drawn[i];
    const s = d.shape;
    if (s.type === 'ball' || s.type === 'disc') {
      return {circle: [pose.centre, s.r]};
    }
    const corners = [[s.hx, s.hy], [-s.hx, s.hy], [-s.hx, -s.hy], [s.hx, -s.hy]];
    return {polygon: corners.map((c) => add(pose.centre, rotate(c, pose.angle)))};
  };
  collide.surfaceOutline = (l, s) => {
    const tangent = [-s.outward[1], s.outward[0]];
    const a = add(s.through, mul(tangent, s.from));
    const b = add(s.through, mul(tangent, s.to));
    const depth = mul(s.outward, -4 * l.typical);
    return {polygon: [a, add(a, depth), add(b, depth), b]};
  };
})(window.collide);
