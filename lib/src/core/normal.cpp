// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/normal.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "impulse/core/error.hpp"

namespace impulse {

UnitNormal::UnitNormal(std::string_view what, const Eigen::Vector2d& direction) : n_(direction) {
  const double largest = std::fmax(std::abs(direction.x()), std::abs(direction.y()));  // quiet
  // Squared only where that cannot overflow (a unit vector's largest coordinate is at least
  // 1/sqrt(2)): a caller that traps floating-point exceptions gets no SIGFPE for [1e300, 0].
  const bool moderate = std::isgreaterequal(largest, 0.5) && std::islessequal(largest, 2.0);
  if (moderate && is_unit_normal(direction)) [[likely]] {
    squared_ = direction.squaredNorm();
    return;  // unit within the tolerance: kept as given
  }
  if (!all_finite_in(direction) || !std::isgreater(largest, 0.0)) {
    throw InvalidInput(std::string(what) + " must be a finite non-zero vector, got [" +
                       format_number(direction.x()) + ", " + format_number(direction.y()) + "]");
  }
  // Scaled by a power of two first (exact), so that neither the length nor the quotient
  // overflows or loses the bits of a subnormal.
  const int exponent = std::ilogb(largest);
  const Eigen::Vector2d scaled(std::scalbn(direction.x(), -exponent),
                               std::scalbn(direction.y(), -exponent));
  const double length = std::hypot(scaled.x(), scaled.y());
  n_ = scaled / length;
  squared_ = n_.squaredNorm();
  given_length_ = std::scalbn(length, exponent);
}

UnitNormal UnitNormal::from_degrees(double degrees) {
  if (!std::isfinite(degrees)) {
    throw InvalidInput("normal_angle must be finite, got " + format_number(degrees));
  }
  // Reduced to rest in [-45, 45] degrees and a number of quarter turns, so that multiples of 90
  // degrees give exact zeros and ones.
  const double turn = std::fmod(degrees, 360.0);  // exact
  const long quarters = std::lround(turn / 90.0);
  const double rest = turn - 90.0 * static_cast<double>(quarters);
  const double radians = rest * (std::numbers::pi / 180.0);
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  UnitNormal normal;
  switch (((quarters % 4) + 4) % 4) {  // a quarter turn maps (x, y) to (-y, x)
    case 0:
      normal.n_ = {c, s};
      break;
    case 1:
      normal.n_ = {-s, c};
      break;
    case 2:
      normal.n_ = {-c, -s};
      break;
    default:
      normal.n_ = {s, -c};
      break;
  }
  normal.n_ += Eigen::Vector2d::Zero();  // -0 becomes +0 (a sine of -0 at a multiple of 90°)
  normal.squared_ = normal.n_.squaredNorm();
  return normal;
}

}  // namespace impulse
