// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/material_2d/material_2d.hpp"

#include <cmath>
#include <string>

#include "impulse/core/error.hpp"

namespace impulse::material_2d {

PointMass from_velocity(double mass, const Eigen::Vector2d& velocity) {
  require_positive("mass", mass);
  require_finite("velocity", velocity);
  return {mass, mass * velocity};
}

void validate(const PointMass& body, const char* name) {
  if (is_positive(body.mass) && std::isfinite(body.p.x()) && std::isfinite(body.p.y())) [[likely]] {
    return;  // the common case: no message, no string built
  }
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_finite(prefix + ".p", body.p);
}

Eigen::Vector2d velocity(const PointMass& body) {
  return body.p / body.mass;
}

double kinetic_energy(const PointMass& body) {
  return body.p.squaredNorm() / (2.0 * body.mass);
}

double cast(const Eigen::Vector2d& v, const Eigen::Vector2d& direction) {
  require_finite("direction", direction);
  const double length = direction.norm();
  if (!(length > 0.0)) {
    throw InvalidInput("direction must be non-zero, got [" + format_number(direction.x()) + ", " +
                       format_number(direction.y()) + "]");
  }
  return v.dot(direction) / length;
}

double normal_velocity(const PointMass& body, const Eigen::Vector2d& n) {
  return body.p.dot(n) / body.mass;  // p_n / m, with p_n = p . n (section 2)
}

namespace {
// (1.3) on the cast p_n = p . n for a body and normal already validated; (4.5)/(4.8) with a
// single contact.
ScalarContribution share(const PointMass& body, const Eigen::Vector2d& n, Elasticity elasticity) {
  return {n.squaredNorm() / body.mass, elasticity.value() * normal_velocity(body, n)};
}
}  // namespace

ScalarContribution contribution(const PointMass& body, const Eigen::Vector2d& n,
                                Elasticity elasticity) {
  validate(body);
  require_unit_normal("normal", n);
  return share(body, n, elasticity);
}

Eigen::Vector2d impulse_vector(const Eigen::Vector2d& n, double Fdt) {
  return -n * Fdt;
}

PointMass apply_impulse(const PointMass& body, const Eigen::Vector2d& n, double Fdt) {
  return {body.mass, body.p + impulse_vector(n, Fdt)};
}

Collision collide(const PointMass& bumper, Elasticity bumper_elasticity, const PointMass& wedge,
                  Elasticity wedge_elasticity, const Eigen::Vector2d& n) {
  validate(bumper, "bumper");
  validate(wedge, "wedge");
  require_unit_normal("normal", n);
  // Validated once above; the ⊕ of the two shares, then Fdt = B / A.
  const ScalarSolution solution =
      solve(share(bumper, n, bumper_elasticity) + share(wedge, -n, wedge_elasticity));
  return {solution, apply_impulse(bumper, n, solution.Fdt), apply_impulse(wedge, -n, solution.Fdt)};
}

}  // namespace impulse::material_2d
