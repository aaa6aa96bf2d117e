// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The two plane operations the paper uses: det and the quarter turn.
#pragma once

#include <Eigen/Core>

namespace impulse {

/// @brief @f$ \det(\vec{a}, \vec{b}) = a_x b_y - a_y b_x @f$, the 2D cross product.
///
/// With @f$ \vec{r} @f$ an arm and @f$ \vec{F}dt @f$ an impulse, it is the angular impulse
/// about the arm's origin (3.2); with a unit normal, @f$ \det(\vec{r}, \vec{n}) @f$ is the lever
/// arm of a normal impulse.
/// @param a first column
/// @param b second column
/// @return the determinant of [a b]
[[nodiscard]] inline double det(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// @brief @f$ [-r_y, r_x] @f$: @p r turned a quarter counter-clockwise.
///
/// A point at arm @f$ \vec{r} @f$ of a body spinning at @f$ \omega @f$ moves at
/// @f$ \omega\,[-r_y, r_x] @f$ (section 3.2).
/// @param r the arm
/// @return r rotated by +90°
[[nodiscard]] inline Eigen::Vector2d quarter_turn(const Eigen::Vector2d& r) {
  return {-r.y(), r.x()};
}

}  // namespace impulse
