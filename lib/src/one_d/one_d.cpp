// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/one_d/one_d.hpp"

#include <cmath>
#include <string>

#include "impulse/core/error.hpp"

namespace impulse::one_d {

Body from_velocity(double mass, double velocity) {
  require_positive("mass", mass);
  require_finite("velocity", velocity);
  return {mass, mass * velocity};
}

void validate(const Body& body, const char* name) {
  if (is_positive(body.mass) && std::isfinite(body.momentum)) [[likely]] {
    return;  // the common case: no message, no string built
  }
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_finite(prefix + ".momentum", body.momentum);
}

double velocity(const Body& body) {
  return body.momentum / body.mass;
}

double kinetic_energy(const Body& body) {
  return body.momentum * body.momentum / (2.0 * body.mass);
}

double normal_velocity(const Body& body, double outward) {
  return outward * body.momentum / body.mass;
}

namespace {
// (1.3) for a body already validated: a = 1/m, b = elasticity * p / m, with p cast on the
// body's outward direction.
ScalarContribution share(const Body& body, double outward, Elasticity elasticity) {
  return {1.0 / body.mass, elasticity.value() * normal_velocity(body, outward)};
}
}  // namespace

ScalarContribution contribution(const Body& body, double outward, Elasticity elasticity) {
  validate(body);
  require_unit_direction("outward direction", outward);
  return share(body, outward, elasticity);  // (1.3)
}

Body apply_impulse(const Body& body, double outward, double Fdt) {
  // Section 1: p1' = p1 - Fdt, p2' = p2 + Fdt; the sign is the body's outward direction.
  return {body.mass, body.momentum - outward * Fdt};
}

Collision collide(const Body& first, Elasticity first_elasticity, const Body& second,
                  Elasticity second_elasticity, double normal) {
  validate(first, "first");
  validate(second, "second");
  require_unit_direction("normal", normal);
  // Validated once above; the ⊕ of the two shares of (1.3), then Fdt = B / A.
  const ScalarSolution solution =
      solve(share(first, normal, first_elasticity) + share(second, -normal, second_elasticity));
  return {solution, apply_impulse(first, normal, solution.Fdt),
          apply_impulse(second, -normal, solution.Fdt)};
}

}  // namespace impulse::one_d
