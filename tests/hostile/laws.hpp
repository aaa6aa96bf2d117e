// SPDX-License-Identifier: GPL-3.0-or-later
// What the hostile-number tests measure on a solved scene: how far the result is from the laws
// that every exact solution obeys, each relative to the magnitudes that the reported quantity
// is summed from, next to the solution's condition estimate.
//
// With one elasticity e for every movable body, B = e·u (u: the approach speeds before) and an
// exact solution has A·Fdt = e·u, so
//   approach after  u' = u - A·Fdt = (1 - e)·u,
//   energy change   ΔE = -uᵀFdt + Fdtᵀ·A·Fdt / 2 = (e/2 - 1)·uᵀFdt,
// and, whatever the elasticities, the total momentum is unchanged when no body is static
// (each impulse acts on two bodies with opposite signs).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "impulse/scene/scene.hpp"

namespace impulse::test {

/// The relative departures from the laws of one solved scene.
struct Departures {
  double condition = 1.0;  ///< the solution's condition estimate
  double momentum = 0.0;   ///< |Δ total p| / (Σ |p| + |p'| + 2 Σ |Fdt|); 0 with a static body
  double energy = 0.0;     ///< |ΔE - (e/2 - 1) uᵀFdt| / (E + E' + Σ energy of each change)
  double approach = 0.0;   ///< max over contacts of |u'_v - (1 - e) u_v| / (speeds summed at v)
};

/// The elasticity every movable body collides with (the scene's, or each body's own if equal).
inline double common_elasticity(const scene::Scene& s) {
  double common = std::numeric_limits<double>::quiet_NaN();
  for (const scene::Body& body : s.bodies) {
    if (body.kind != scene::BodyKind::static_body) {
      const double e = body.elasticity.value_or(s.elasticity.value_or(1.0));
      common = std::isnan(common) || common == e ? e : std::numeric_limits<double>::infinity();
    }
  }
  return common;
}

/// Measures @p r, the solved @p s (status success, one elasticity for every movable body).
inline Departures departures(const scene::Scene& s, const scene::Result& r) {
  Departures d;
  d.condition = r.system.condition_estimate;
  const double e = common_elasticity(s);

  const bool any_static = std::any_of(s.bodies.begin(), s.bodies.end(), [](const scene::Body& b) {
    return b.kind == scene::BodyKind::static_body;
  });
  if (!any_static) {
    double scale = 2.0 * r.system.Fdt.cwiseAbs().sum();
    for (const scene::BodyReport& b : r.bodies) {
      scale += b.before.momentum.norm() + b.after.momentum.norm();
    }
    d.momentum = (r.momentum_after - r.momentum_before).norm() / scale;
  }

  double change_energy = 0.0;  // Σ over bodies of the kinetic energy of its change of motion
  double work = 0.0;           // uᵀFdt
  double work_scale = 0.0;     // Σ |u_v Fdt_v|
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const scene::Body& body = s.bodies[k];
    if (body.kind == scene::BodyKind::static_body) {
      continue;
    }
    const scene::BodyReport& b = r.bodies[k];
    change_energy += (b.after.momentum - b.before.momentum).squaredNorm() / (2.0 * body.mass);
    if (body.kind == scene::BodyKind::rigid) {
      const double dL = b.after.angular_momentum - b.before.angular_momentum;
      change_energy += dL * dL / (2.0 * body.inertia);
    }
  }
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    const double term = r.contacts[v].approach_before * r.impulses[v].magnitude;
    work += term;
    work_scale += std::abs(term);
  }
  const double expected_change = (e / 2.0 - 1.0) * work;
  d.energy =
      std::abs(r.energy_change - expected_change) /
      (r.energy_before + r.energy_after + change_energy + std::abs(e / 2.0 - 1.0) * work_scale);

  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    const scene::Contact& c = s.contacts[v];
    double speeds = std::abs(e - 1.0) * std::abs(r.contacts[v].approach_before);
    for (const std::size_t k : {c.bumper, c.wedge}) {
      const scene::BodyReport& b = r.bodies[k];
      speeds += b.before.velocity.norm() + b.after.velocity.norm();
      if (s.bodies[k].kind == scene::BodyKind::rigid && c.point) {
        const double arm = (*c.point - s.bodies[k].position).norm();
        speeds += (std::abs(b.before.angular_velocity) + std::abs(b.after.angular_velocity)) * arm;
      }
    }
    const double target = (1.0 - e) * r.contacts[v].approach_before;
    if (speeds > 0.0) {
      d.approach = std::max(d.approach, std::abs(r.contacts[v].approach_after - target) / speeds);
    }
  }
  return d;
}

}  // namespace impulse::test
