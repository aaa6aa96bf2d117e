// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/rigid_2d/rigid_2d.hpp"

#include <string>

#include "impulse/core/error.hpp"

// The single-contact path is inline in the header; here is the part that builds messages.
namespace impulse::rigid_2d {

void detail::refuse(const RigidBody& body, const char* name) {
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_positive(prefix + ".inertia", body.inertia);
  require_finite(prefix + ".position", body.position);
  require_finite(prefix + ".p", body.p);
  require_finite(prefix + ".L", body.L);
  throw InvalidInput(prefix + " was refused");  // not reached: the checks match the test
}

void detail::refuse_collision(const RigidBody& bumper, const RigidBody& wedge,
                              const Eigen::Vector2d& point, const Eigen::Vector2d& n) {
  validate(bumper, "bumper");
  validate(wedge, "wedge");
  require_finite("point", point);
  require_unit_normal("normal", n);
  throw InvalidInput("collide was refused");  // not reached: the checks match the test
}

}  // namespace impulse::rigid_2d
