// SPDX-License-Identifier: GPL-3.0-or-later
// Random bodies shared by the property tests of several sections: the ranges of Sampler.
#pragma once

#include "impulse/rigid_2d/rigid_2d.hpp"
#include "support/sampling.hpp"

namespace impulse::test {

/// A rigid body of random mass and inertia, position within 5 of the origin, velocity components
/// within 10, spin within 10.
inline rigid_2d::RigidBody random_rigid_body(Sampler& sample) {
  rigid_2d::RigidBody b;
  b.mass = sample.mass();
  b.inertia = sample.mass();
  b.position = sample.vector(5);
  b.p = b.mass * sample.vector(10);
  b.L = b.inertia * sample.uniform(-10, 10);
  return b;
}

}  // namespace impulse::test
