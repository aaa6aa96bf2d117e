// SPDX-License-Identifier: GPL-3.0-or-later
// The physics of the friction tests from the definitions, independently of the library's
// helpers: a point's velocity, an impulse applied to a body, and random bodies and contacts.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <variant>

#include "impulse/friction/contact.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "support/random_bodies.hpp"
#include "support/sampling.hpp"

namespace impulse::test::friction {

using multipoint::Body;
using Vector2d = Eigen::Vector2d;

// The three laws of restitution, for the tests that hold each of them to a law of physics.
inline constexpr impulse::friction::RestitutionLaw all_laws[] = {
    impulse::friction::RestitutionLaw::newton, impulse::friction::RestitutionLaw::poisson,
    impulse::friction::RestitutionLaw::energetic};

// The floor: the striking body is the bumper, its outward normal points down, n = (0, -1), so
// the tangent is t = [-n_y, n_x] = (1, 0) and the impulse on the body is (P_t, P_n).
inline const Vector2d down(0, -1);

inline double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Velocity of the body's material point at x: v + omega [-r_y, r_x]; a point mass moves as a
// whole; a static body does not move.
inline Vector2d velocity_at(const Body& body, const Vector2d& x) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p / m->mass;
  }
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    const Vector2d r = x - b->position;
    return b->p / b->mass + b->L / b->inertia * Vector2d(-r.y(), r.x());
  }
  return Vector2d::Zero();
}

// The impulse J at x: p += J, and for a rigid body L += det(r, J).
inline void push(Body& body, const Vector2d& x, const Vector2d& J) {
  if (auto* m = std::get_if<material_2d::PointMass>(&body)) {
    m->p += J;
  } else if (auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    b->p += J;
    b->L += cross(x - b->position, J);
  }
}

inline double energy(const Body& body) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p.squaredNorm() / (2 * m->mass);
  }
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    return b->p.squaredNorm() / (2 * b->mass) + b->L * b->L / (2 * b->inertia);
  }
  return 0.0;
}

inline Vector2d momentum(const Body& body) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p;
  }
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    return b->p;
  }
  return Vector2d::Zero();
}

// Angular momentum about the point c: L + det(position - c, p) for a rigid body; a point mass
// sits at the contact point, so its arm about it is zero.
inline double angular_momentum_about(const Body& body, const Vector2d& c) {
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    return b->L + cross(b->position - c, b->p);
  }
  return 0.0;
}

// Which sections' bodies meet at a contact.
enum class Pairing { material, rigid, material_static, rigid_static, mixed };

inline const char* name(Pairing pairing) {
  switch (pairing) {
    case Pairing::material:
      return "two point masses";
    case Pairing::rigid:
      return "two rigid bodies";
    case Pairing::material_static:
      return "a point mass and a static body";
    case Pairing::rigid_static:
      return "a rigid body and a static body";
    case Pairing::mixed:
      return "a point mass and a rigid body";
  }
  return "?";
}

inline material_2d::PointMass random_point_mass(Sampler& sample) {
  const double m = sample.mass();
  return {m, m * sample.vector(10)};
}

// A random contact of the pairing; the static body, if any, is the bumper or the wedge at
// random.
struct Hit {
  Body bumper;
  Body wedge;
  Vector2d point;
  Vector2d normal;
};

inline Hit random_hit(Sampler& sample, Pairing pairing) {
  Hit h{multipoint::StaticBody{}, multipoint::StaticBody{}, sample.vector(5), sample.unit_vector()};
  switch (pairing) {
    case Pairing::material:
      h.bumper = random_point_mass(sample);
      h.wedge = random_point_mass(sample);
      break;
    case Pairing::rigid:
      h.bumper = random_rigid_body(sample);
      h.wedge = random_rigid_body(sample);
      break;
    case Pairing::material_static:
      h.bumper = random_point_mass(sample);
      break;
    case Pairing::rigid_static:
      h.bumper = random_rigid_body(sample);
      break;
    case Pairing::mixed:
      h.bumper = random_point_mass(sample);
      h.wedge = random_rigid_body(sample);
      break;
  }
  if (sample.coin()) {
    std::swap(h.bumper, h.wedge);
    h.normal = -h.normal;
  }
  return h;
}

// The size of the terms that make up a point's velocity, |v| + |omega| |r|, summed over both
// bodies: the scale of speeds and of their rounding errors (the point's speed itself may be
// small by cancellation).
inline double speed_scale(const Body& body, const Vector2d& x) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p.norm() / m->mass;
  }
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    return b->p.norm() / b->mass + std::abs(b->L / b->inertia) * (x - b->position).norm();
  }
  return 0.0;
}

inline double speed_scale(const Hit& h) {
  return speed_scale(h.bumper, h.point) + speed_scale(h.wedge, h.point);
}

// A bound on the size of W from the definitions: a unit impulse at x moves the body's point
// there by at most 1/m + |r|^2 / I.
inline double mobility(const Body& body, const Vector2d& x) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return 1.0 / m->mass;
  }
  if (const auto* b = std::get_if<rigid_2d::RigidBody>(&body)) {
    return 1.0 / b->mass + (x - b->position).squaredNorm() / b->inertia;
  }
  return 0.0;
}

inline double mobility(const Hit& h) {
  return mobility(h.bumper, h.point) + mobility(h.wedge, h.point);
}

}  // namespace impulse::test::friction
