// SPDX-License-Identifier: GPL-3.0-or-later
// The laws every exact solution obeys, measured on a resolved scene: one header for the hostile
// tests (tests/hostile/) and the fuzzer (fuzz/scene_fuzzer.cpp), which hold a result to them
// with tolerances of their own.
//
// Each law gives a Departure: how far the result is from it, and the sum of the magnitudes the
// compared quantities are computed from (the scale that rounding is relative to).
//
// For any impulses F (the method's, outcome.Fdt), sections 4 and 5 give the motion after:
//   approach after  u' = u - A·F,
//   energy change   ΔE = Fᵀ(A·F/2 - u)                        (kinematics, any method);
// with one elasticity e for every movable body, B = e·u, and an exact solution of A·F = B has
//   approach after  u' = (1 - e)·u,
//   energy change   ΔE = (e/2 - 1)·uᵀF                        (the paper's system);
// and, whatever the elasticities, the total momentum is unchanged when no body is static (each
// impulse acts on two bodies with opposite signs).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "impulse/core/solve.hpp"
#include "impulse/scene/scene.hpp"

namespace impulse::laws {

/// How far a result is from a law, and the magnitudes that the compared quantities sum.
struct Departure {
  double found = 0.0;  ///< |computed - what the law says|
  double scale = 0.0;  ///< the sum of the magnitudes it is computed from

  /// found over scale (0 when there is nothing to compare).
  [[nodiscard]] double relative() const { return scale > 0.0 ? found / scale : 0.0; }
};

/// The elasticity every movable body collides with (the scene's, or each body's own if they are
/// equal); nothing when they differ, and B is then not a multiple of u.
inline std::optional<double> common_elasticity(const scene::Scene& s) {
  std::optional<double> common;
  for (const scene::Body& body : s.bodies) {
    if (body.kind == scene::BodyKind::static_body) {
      continue;
    }
    const double e = s.elasticity_of(body);
    if (common && *common != e) {
      return std::nullopt;
    }
    common = e;
  }
  return common;
}

/// Whether a body is static (it takes momentum, and the totals leave it out).
inline bool any_static(const scene::Scene& s) {
  return std::any_of(s.bodies.begin(), s.bodies.end(),
                     [](const scene::Body& b) { return b.kind == scene::BodyKind::static_body; });
}

/// The spread of the movable bodies' 1/m and 1/I: the largest over the smallest (1 for a single
/// movable body without rotation). The QR of the factor G is accurate relative to its largest
/// rows, which carry 1/√m: a spread s costs about √s in the residual even at κ = 1.
inline double spread(const scene::Scene& s) {
  double largest = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const scene::Body& b : s.bodies) {
    if (b.kind == scene::BodyKind::static_body) {
      continue;
    }
    largest = std::max(largest, 1.0 / b.mass);
    smallest = std::min(smallest, 1.0 / b.mass);
    if (b.kind == scene::BodyKind::rigid) {
      largest = std::max(largest, 1.0 / b.inertia);
      smallest = std::min(smallest, 1.0 / b.inertia);
    }
  }
  return smallest > 0.0 && smallest < std::numeric_limits<double>::infinity() ? largest / smallest
                                                                              : 1.0;
}

/// A norm that neither overflows nor underflows in its squares.
inline double norm(const Eigen::Vector2d& v) {
  return impulse::detail::quiet_norm(v);
}

/// Momentum: the change of the movable bodies' total momentum (0 by the law), against
/// Σ |p| + |p'| + 2 Σ |F|. Not a law when a body is static (nothing is then measured).
inline Departure momentum(const scene::Scene& s, const scene::Result& r) {
  Departure d;
  if (any_static(s)) {
    return d;
  }
  d.scale = 2.0 * r.outcome.Fdt.cwiseAbs().sum();
  for (const scene::BodyReport& b : r.bodies) {
    d.scale += norm(b.before.momentum) + norm(b.after.momentum);
  }
  d.found = norm(r.momentum_after - r.momentum_before);
  return d;
}

/// The speeds summed into contact v's approach before and after: each of its bodies' point
/// velocities (translation and rotation at the contact's arm).
inline double contact_speeds(const scene::Scene& s, const scene::Result& r, std::size_t v) {
  const scene::Contact& c = s.contacts[v];
  double speeds = 0.0;
  for (const std::size_t k : {c.bumper, c.wedge}) {
    const scene::BodyReport& b = r.bodies[k];
    speeds += norm(b.before.velocity) + norm(b.after.velocity);
    if (s.bodies[k].kind == scene::BodyKind::rigid) {
      const double arm = norm(c.point.value_or(Eigen::Vector2d::Zero()) - s.bodies[k].position);
      speeds += (std::abs(b.before.angular_velocity) + std::abs(b.after.angular_velocity)) * arm;
    }
  }
  return speeds;
}

/// The energy of each body's change of motion, summed: terms that cancel in ΔE.
inline double change_energy(const scene::Scene& s, const scene::Result& r) {
  double total = 0.0;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const scene::Body& body = s.bodies[k];
    if (body.kind == scene::BodyKind::static_body) {
      continue;
    }
    const scene::BodyReport& b = r.bodies[k];
    total += (b.after.momentum - b.before.momentum).squaredNorm() / (2.0 * body.mass);
    if (body.kind == scene::BodyKind::rigid) {
      const double dL = b.after.angular_momentum - b.before.angular_momentum;
      total += dL * dL / (2.0 * body.inertia);
    }
  }
  return total;
}

/// Energy at one elasticity e: ΔE against (e/2 - 1) uᵀF, on the scale E + E' + the energies of
/// the changes + |e/2 - 1| Σ |u_v F_v|.
inline Departure energy(const scene::Scene& s, const scene::Result& r, double e) {
  double work = 0.0;        // uᵀF
  double work_terms = 0.0;  // Σ |u_v F_v|
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    const double term = r.contacts[v].approach_before * r.outcome.Fdt(static_cast<Eigen::Index>(v));
    work += term;
    work_terms += std::abs(term);
  }
  const double factor = e / 2.0 - 1.0;
  return {std::abs(r.energy_change - factor * work),
          r.energy_before + r.energy_after + change_energy(s, r) + std::abs(factor) * work_terms};
}

/// Contact v's approach after at one elasticity e against (1 - e) u_v, on the scale of
/// |1 - e| |u_v| and the speeds summed at v.
inline Departure approach(const scene::Scene& s, const scene::Result& r, std::size_t v, double e) {
  const double u = r.contacts[v].approach_before;
  return {std::abs(r.contacts[v].approach_after - (1.0 - e) * u),
          std::abs(1.0 - e) * std::abs(u) + contact_speeds(s, r, v)};
}

/// The kinematics of any impulses F (whatever the method): the approach speeds after are
/// u - A·F, the energy changes by Fᵀ(A·F/2 - u). `AF` and `AF_terms` are A·F and |A|·|F|.
struct Kinematics {
  Departure energy;                 ///< ΔE against Fᵀ(A·F/2 - u)
  std::vector<Departure> approach;  ///< u'_v against u_v - (A·F)_v, per contact
};

/// Measures the kinematics of @p r, given A·F and |A|·|F| for its impulses.
inline Kinematics kinematics(const scene::Scene& s, const scene::Result& r,
                             const Eigen::VectorXd& AF, const Eigen::VectorXd& AF_terms) {
  Kinematics k;
  double predicted = 0.0;
  double predicted_terms = 0.0;
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    const auto i = static_cast<Eigen::Index>(v);
    const double u = r.contacts[v].approach_before;
    const double F = r.outcome.Fdt(i);
    predicted += F * (AF(i) / 2.0 - u);
    predicted_terms += std::abs(F) * (AF_terms(i) / 2.0 + std::abs(u));
    k.approach.push_back({std::abs(r.contacts[v].approach_after - (u - AF(i))),
                          std::abs(u) + AF_terms(i) + contact_speeds(s, r, v)});
  }
  k.energy = {std::abs(r.energy_change - predicted),
              r.energy_before + r.energy_after + predicted_terms};
  return k;
}

}  // namespace impulse::laws
