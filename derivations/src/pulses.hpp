// SPDX-License-Identifier: GPL-3.0-or-later
// Shapes of a collision's force over its duration, for the quadrature checks of sections 4 and
// 5: on [0, 1], each with unit integral f and its running integral g (g(0) = 0, g(1) = 1).
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "numeric.hpp"

namespace impulse::derivations {

struct Pulse {
  const char* name;
  double (*f)(double);  ///< the shape, unit integral over [0, 1]
  double (*g)(double);  ///< its integral from 0
};

/// A constant force (rectangle), a half-sine, a triangle and a skewed (early-peaking) pulse.
inline const std::vector<Pulse>& pulses() {
  static const std::vector<Pulse> p{
      {"rectangle", [](double) { return 1.0; }, [](double t) { return t; }},
      {"half-sine", [](double t) { return std::numbers::pi / 2 * std::sin(std::numbers::pi * t); },
       [](double t) { return (1 - std::cos(std::numbers::pi * t)) / 2; }},
      {"triangle", [](double t) { return t < 0.5 ? 4 * t : 4 * (1 - t); },
       [](double t) { return t < 0.5 ? 2 * t * t : 1 - 2 * (1 - t) * (1 - t); }},
      {"skewed", [](double t) { return 12 * t * (1 - t) * (1 - t); },
       [](double t) { return 6 * t * t - 8 * t * t * t + 3 * t * t * t * t; }},
  };
  return p;
}

/// The integral over the collision time [0, 1], split where the triangular pulse has its kink;
/// `scale` as in num::integrate.
inline double over_pulse(const std::function<double(double)>& f, double scale = 0.0) {
  return num::integrate(f, 0, 0.5, scale) + num::integrate(f, 0.5, 1, scale);
}

}  // namespace impulse::derivations
