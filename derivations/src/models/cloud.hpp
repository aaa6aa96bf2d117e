// SPDX-License-Identifier: GPL-3.0-or-later
// A rigid body made of point masses, for checks that need a body independent of the paper's
// formulas: energy and momenta are summed point by point, and the response to impulses comes
// from Gauss's principle (the rigid motion closest, in the mass metric, to the points' free
// response), not from Newton-Euler's formulas that the paper uses.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "numeric.hpp"

namespace impulse::derivations::cloud {

struct Cloud {
  std::vector<double> m;
  std::vector<Eigen::Vector2d> r;  ///< arms from the centre of mass
  Eigen::Vector2d V = Eigen::Vector2d::Zero();
  double w = 0;
  [[nodiscard]] double mass() const;
  [[nodiscard]] double inertia() const;  ///< about the centre of mass
  [[nodiscard]] Eigen::Vector2d velocity(std::size_t i) const;
  [[nodiscard]] Eigen::Vector2d velocity_at(const Eigen::Vector2d& arm) const;
  [[nodiscard]] double energy() const;
  [[nodiscard]] Eigen::Vector2d momentum() const;
  [[nodiscard]] double angular_momentum() const;  ///< about the centre of mass
};

/// 3 to 6 point masses (masses 1e-3 .. 1e3), centre of mass at the origin, moving at random.
Cloud sample(num::Random& r);

/// An impulse J at the material point i.
struct Kick {
  std::size_t point;
  Eigen::Vector2d J;
};

/// The body after the impulses, by Gauss's principle: the change (dV, dw) minimises
/// sum_i m_i |dV + dw perp(r_i) - J_i / m_i|^2 (J_i the impulse at point i, zero elsewhere).
Cloud after(const Cloud& body, const std::vector<Kick>& kicks);

}  // namespace impulse::derivations::cloud
