// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/one_d/one_d.hpp"

#include <string>

#include "impulse/core/error.hpp"

// The single-contact path is inline in the header; here are the parts that build messages.
namespace impulse::one_d {

Body from_velocity(double mass, double velocity) {
  require_positive("mass", mass);
  require_finite("velocity", velocity);
  return {mass, mass * velocity};
}

void detail::refuse(const Body& body, const char* name) {
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_finite(prefix + ".momentum", body.momentum);
  throw InvalidInput(prefix + " was refused");  // not reached: the checks match the test
}

void detail::refuse_collision(const Body& first, const Body& second, double normal) {
  validate(first, "first");
  validate(second, "second");
  require_unit_direction("normal", normal);
  throw InvalidInput("collide was refused");  // not reached: the checks match the test
}

}  // namespace impulse::one_d
