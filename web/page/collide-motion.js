// SPDX-License-Identifier: GPL-3.0-or-later
// The motion shown before and after the instant of the impulses: each body moves in a straight
// line and turns at its velocity and spin as the library gives them (before, then after), until
// its drawn outline would run into another body or a static surface (the whole line a surface is
// drawn on); there it stops, and the
// page marks "a later collision" (or, before the instant, "an earlier collision"), which it does
// not compute. A contact's marker moves with its point while the two bodies still touch there,
// and fades as they part. These are drawing rules (where outlines meet), not physics: the
// numbers are the library's.
'use strict';

(function (collide) {
  const {add, sub, mul, dot, norm, rotate} = collide;

  // How deep two outlines overlap along the axis that separates them best (negative: apart by at
  // least that much), and a point of the deepest overlap. Convex outlines: polygons (their edges'
  // normals are the axes) and circles (the axis from the centre to the polygon's nearest corner).
  function project(o, axis) {
    if (o.circle) {
      const c = dot(o.circle[0], axis);
      return [c - o.circle[1], c + o.circle[1]];
    }
    let lo = Infinity;
    let hi = -Infinity;
    for (const p of o.polygon) {
      const x = dot(p, axis);
      lo = Math.min(lo, x);
      hi = Math.max(hi, x);
    }
    return [lo, hi];
  }

  function axesOf(o, other) {
    if (o.circle) {
      if (other.circle) {
        const d = sub(other.circle[0], o.circle[0]);
        return [norm(d) > 0 ? mul(d, 1 / norm(d)) : [1, 0]];
      }
      let best = null;
      for (const p of other.polygon) {
        const d = sub(p, o.circle[0]);
        if (!best || norm(d) < norm(best)) {
          best = d;
        }
      }
      return norm(best) > 0 ? [mul(best, 1 / norm(best))] : [];
    }
    const axes = [];
    const ps = o.polygon;
    for (let k = 0; k < ps.length; ++k) {
      const e = sub(ps[(k + 1) % ps.length], ps[k]);
      const l = norm(e);
      if (l > 0) {
        axes.push([-e[1] / l, e[0] / l]);
      }
    }
    return axes;
  }

  function deepest(o, axis, toward) {
    // The point of @p o furthest along @p axis * toward.
    if (o.circle) {
      return add(o.circle[0], mul(axis, o.circle[1] * toward));
    }
    let best = o.polygon[0];
    for (const p of o.polygon) {
      if (dot(p, axis) * toward > dot(best, axis) * toward) {
        best = p;
      }
    }
    return best;
  }

  // {depth, point, axis}: the axis (unit) points from a towards b; the point is b's deepest
  // towards a.
  collide.penetration = (a, b) => {
    let depth = Infinity;
    let point = null;
    let best = [1, 0];
    for (const axis of [...axesOf(a, b), ...axesOf(b, a)]) {
      const [a0, a1] = project(a, axis);
      const [b0, b1] = project(b, axis);
      // How far a must move back along the axis to clear b, or forward: the smaller one (when one
      // interval holds the other, their overlap alone would understate it).
      const ahead = a1 - b0;
      const behind = b1 - a0;
      const overlap = Math.min(ahead, behind);
      if (overlap < depth) {
        const toward = ahead <= behind ? 1 : -1;
        depth = overlap;
        best = mul(axis, toward);
        point = deepest(b, axis, -toward);
      }
    }
    return {depth, point, axis: best};
  };
  collide.project = project;

  // How deep an outline lies behind a static surface, taken as the whole line it is drawn on
  // (a floor drawn short is still the floor): {depth, point}.
  collide.behind = (o, s) => {
    if (o.circle) {
      const [c, r] = o.circle;
      return {depth: r - dot(sub(c, s.through), s.outward), point: sub(c, mul(s.outward, r))};
    }
    let best = o.polygon[0];
    for (const p of o.polygon) {
      if (dot(sub(p, s.through), s.outward) < dot(sub(best, s.through), s.outward)) {
        best = p;
      }
    }
    return {depth: -dot(sub(best, s.through), s.outward), point: best};
  };

  // Body i's pose at time t (in the scene's seconds; 0 the instant), stopped where the timeline
  // stops it.
  collide.poseAt = (l, i, t) => {
    const d = l.drawn[i];
    const angle0 = d.shape ? d.shape.angle : 0;
    if (d.kind === 'static') {
      return {centre: d.centre, angle: angle0};
    }
    if (l.timeline) {
      const side = t < 0 ? l.timeline.before : l.timeline.after;
      t = t < 0 ? Math.max(t, side.stop[i]) : Math.min(t, side.stop[i]);
    }
    const m = l.motion[i];
    const v = t < 0 ? m.before : m.after;
    const w = t < 0 ? m.spinBefore : m.spinAfter;
    return {centre: add(d.centre, mul(v, t)), angle: angle0 + w * t};
  };

  // Where each body stops, before and after: computed once per layout, when the time first
  // leaves the instant.
  collide.timeline = (l) => {
    if (!l.timeline) {
      l.timeline = collide.timed('timeline', () => ({after: march(l, 1), before: march(l, -1)}));
    }
    return l.timeline;
  };

  function march(l, sign) {
    const n = l.drawn.length;
    const T = l.scales.window;
    // stop[i]: the time body i stops (±Infinity: it has not stopped; 0: it does not move).
    const side = {stop: new Array(n).fill(0), events: []};
    const movable = [];
    l.drawn.forEach((d, i) => {
      const m = l.motion[i];
      const v = sign > 0 ? m.after : m.before;
      const w = sign > 0 ? m.spinAfter : m.spinBefore;
      if (d.kind !== 'static' && (norm(v) > 0 || w !== 0)) {
        movable.push(i);
        side.stop[i] = sign * Infinity;
      }
    });
    if (!movable.length) {
      return side;
    }
    const moving = new Set(movable);
    // Candidates: a moving body against every other body whose bounding circle it can reach
    // within the window, and against every static surface.
    const pairs = [];
    const velocity = (i) => (sign > 0 ? l.motion[i].after : l.motion[i].before);
    const spin = (i) => (sign > 0 ? l.motion[i].spinAfter : l.motion[i].spinBefore);
    const round = (i) => l.drawn[i].shape.type === 'ball' || l.drawn[i].shape.type === 'disc';
    const margin = 0.05 * l.typical;
    // Two bodies that move alike (the same velocity, no turning) keep their places to each other;
    // a body that does not turn (or is round) and moves off a surface, or along it, cannot go
    // behind it: neither pair needs looking at.
    // (Alike within 1e-9 of the fastest speed of a point: the library's rounding is not motion.)
    const fastest = Math.max(...movable.map((i) => norm(velocity(i)) + Math.abs(spin(i)) * l.drawn[i].radius));
    const unturned = (i) => round(i) || Math.abs(spin(i)) * l.drawn[i].radius <= 1e-9 * fastest;
    const together = (i, j) => unturned(i) && (!moving.has(j) || unturned(j)) &&
                               norm(sub(velocity(i), moving.has(j) ? velocity(j) : [0, 0])) <= 1e-9 * fastest;
    l.drawn.forEach((d, j) => {
      if (d.kind === 'static') {
        return;
      }
      for (const i of movable) {
        if (i === j || (moving.has(j) && j < i) || together(i, j)) {
          continue;
        }
        // Closest approach of the two centres over [0, T] (moving in straight lines).
        const dc = sub(l.drawn[j].centre, l.drawn[i].centre);
        const dv = mul(sub(moving.has(j) ? velocity(j) : [0, 0], velocity(i)), sign);
        const vv = dot(dv, dv);
        const s = vv > 0 ? Math.max(0, Math.min(T, -dot(dc, dv) / vv)) : 0;
        if (norm(add(dc, mul(dv, s))) <= l.drawn[i].radius + l.drawn[j].radius + margin) {
          pairs.push({i, j, surface: null});
        }
      }
    });
    for (const i of movable) {
      for (const surface of l.surfaces) {
        if (unturned(i) && sign * dot(velocity(i), surface.outward) >= -1e-9 * fastest) {
          continue;
        }
        pairs.push({i, j: -1, surface});
      }
    }
    const outlineAt = (k, t, stop) => collide.outline(l, k, poseClamped(l, k, t, stop, sign));
    const depthOf = (pair, t, stop) => (pair.surface ? collide.behind(outlineAt(pair.i, t, stop), pair.surface)
                                                     : collide.penetration(outlineAt(pair.i, t, stop), outlineAt(pair.j, t, stop)));
    for (const pair of pairs) {
      pair.depth0 = depthOf(pair, 0, side.stop).depth;
    }
    // Deeper than at the instant by 1.5% of a typical size: they have met (less would stop bodies
    // that roll on at a contact they keep).
    const tolerance = 0.015 * l.typical;
    const steps = 80;
    let live = pairs;
    for (let k = 1; k <= steps && live.length; ++k) {
      const t = sign * k * T / steps;
      for (const pair of live) {
        if (stopped(side, pair)) {
          continue;
        }
        const found = depthOf(pair, t, side.stop);
        if (found.depth > pair.depth0 + tolerance) {
          // Between the last step and this one: halve the interval to the time they meet.
          let lo = sign * (k - 1) * T / steps;
          let hi = t;
          for (let r = 0; r < 10; ++r) {
            const mid = (lo + hi) / 2;
            if (depthOf(pair, mid, side.stop).depth > pair.depth0 + tolerance) {
              hi = mid;
            } else {
              lo = mid;
            }
          }
          const at = depthOf(pair, hi, side.stop).point || l.drawn[pair.i].centre;
          for (const b of [pair.i, pair.j]) {
            if (b >= 0 && moving.has(b) && Math.abs(side.stop[b]) === Infinity) {
              side.stop[b] = lo;
            }
          }
          side.events.push({t: lo, point: at, bodies: [pair.i, pair.j], surface: pair.surface ? pair.surface.body : -1});
        }
      }
      live = live.filter((pair) => !stopped(side, pair));
    }
    return side;
  }

  // Whether neither body of the pair moves any more.
  function stopped(side, pair) {
    const still = (b) => b < 0 || Math.abs(side.stop[b]) !== Infinity;
    return still(pair.i) && still(pair.j);
  }

  function poseClamped(l, i, t, stop, sign) {
    const d = l.drawn[i];
    const angle0 = d.shape ? d.shape.angle : 0;
    const m = l.motion[i];
    const s = sign > 0 ? Math.min(t, stop[i]) : Math.max(t, stop[i]);
    const v = sign > 0 ? m.after : m.before;
    const w = sign > 0 ? m.spinAfter : m.spinBefore;
    return {centre: add(d.centre, mul(v, s)), angle: angle0 + w * s};
  }

  // Where contact v's marker is at time t and how visible: it moves with the contact point while
  // both bodies still touch there (the point fixed in each movable body, or on the surface), and
  // fades over a tenth of a typical size as they part. {at, normal, alpha}.
  collide.markerAt = (l, v, t) => {
    const c = l.contacts[v];
    const p0 = l.points[v];
    if (t === 0) {
      return {at: p0, normal: c.normal, alpha: 1};
    }
    const carried = (b) => {
      const d = l.drawn[b];
      if (d.kind === 'static') {
        return null;
      }
      const pose = collide.poseAt(l, b, t);
      const turn = pose.angle - (d.shape ? d.shape.angle : 0);
      return {point: add(pose.centre, rotate(sub(p0, d.centre), turn)), turn};
    };
    const b = carried(c.bumper);
    const w = carried(c.wedge);
    let at;
    let apart;
    let normal = c.normal;
    if (b && w) {
      at = mul(add(b.point, w.point), 0.5);
      apart = norm(sub(b.point, w.point));
      normal = rotate(c.normal, b.turn);
    } else {
      const moved = b || w;
      at = moved.point;
      apart = Math.abs(dot(sub(moved.point, p0), c.normal));
    }
    const alpha = Math.max(0, Math.min(1, 1 - apart / (0.1 * l.typical)));
    return {at, normal, alpha};
  };
})(window.collide);
