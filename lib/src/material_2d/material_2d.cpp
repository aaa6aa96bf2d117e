// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/material_2d/material_2d.hpp"

#include <string>

#include "impulse/core/error.hpp"

// The single-contact path is inline in the header; here are the parts that build messages.
namespace impulse::material_2d {

PointMass from_velocity(double mass, const Eigen::Vector2d& velocity) {
  require_positive("mass", mass);
  require_finite("velocity", velocity);
  return {mass, mass * velocity};
}

void detail::refuse(const PointMass& body, const char* name) {
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_finite(prefix + ".p", body.p);
  throw InvalidInput(prefix + " was refused");  // not reached: the checks match the test
}

void detail::refuse_collision(const PointMass& bumper, const PointMass& wedge,
                              const Eigen::Vector2d& n) {
  validate(bumper, "bumper");
  validate(wedge, "wedge");
  require_unit_normal("normal", n);
  throw InvalidInput("collide was refused");  // not reached: the checks match the test
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

}  // namespace impulse::material_2d
