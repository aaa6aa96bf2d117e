// SPDX-License-Identifier: GPL-3.0-or-later
#include "models/shapes.hpp"

#include <cmath>
#include <numbers>

namespace impulse::derivations::models {

const std::vector<file::PulseShape>& pulse_shapes() {
  static const std::vector<file::PulseShape> all{
      {"constant", [](double) { return 1.0; }, {}},
      {"half-sine",
       [](double u) { return std::numbers::pi / 2 * std::sin(std::numbers::pi * u); },
       {}},
      {"triangle", [](double u) { return u < 0.5 ? 4 * u : 4 * (1 - u); }, {0.5}},
      {"skewed", [](double u) { return 12 * u * (1 - u) * (1 - u); }, {}},
  };
  return all;
}

}  // namespace impulse::derivations::models
