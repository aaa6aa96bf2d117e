// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/elasticity.hpp"

#include <cmath>

#include "impulse/core/error.hpp"

namespace impulse {

Elasticity::Elasticity(double value) : value_(value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw InvalidInput("elasticity must be finite and at least 0, got " + format_number(value));
  }
}

Elasticity Elasticity::from_restitution(double restitution) {
  if (!(std::isfinite(restitution) && restitution >= -1.0)) {
    throw InvalidInput("restitution must be finite and at least -1, got " +
                       format_number(restitution));
  }
  return Elasticity(1.0 + restitution);
}

}  // namespace impulse
