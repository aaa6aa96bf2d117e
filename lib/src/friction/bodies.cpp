// SPDX-License-Identifier: GPL-3.0-or-later
// W and u0 from the paper's own blocks, and the impulse applied by the paper's own updates.
//
// A body's block over two "touches" at the same point, with directions g_1 and g_2, is
// a_ij = g_i.g_j / m + det(r, g_i) det(r, g_j) / I and (at elasticity 1) b_i = v_point . g_i:
// the inverse effective mass of that body along the directions, and its velocity along them.
// With g_1 = the body's outward normal and g_2 = minus the direction of its tangential impulse,
// an impulse (P_n, P_t) on the contact gives the body -g_1 P_n - g_2 P_t, and so the sums of the
// two blocks are W and -u0.
#include "impulse/friction/bodies.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"

namespace impulse::friction {

namespace {

using multipoint::Body;

void check(const Body& body, const char* name) {
  if (const auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    material_2d::validate(*mass, name);
  } else if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    rigid_2d::validate(*rigid, name);
  }
}

void check(const Body& bumper, const Body& wedge, const Eigen::Vector2d& point,
           const Eigen::Vector2d& normal) {
  check(bumper, "bumper");
  check(wedge, "wedge");
  require_finite("point", point);
  require_unit_normal("normal", normal);
}

// det W without cancellation. Each body adds (|n|^2 / m) I_2 + g g^T / I to W, where
// g = (det(r, d_1), det(r, d_2)) are the arms of its two directions (d_1, d_2) = (n, -t) for the
// bumper and (-n, t) for the wedge: its directions are orthogonal and of |n|'s length, so the
// translational part is a multiple of the identity. With c the sum of the |n|^2 / m and
// h_k = g_k / sqrt(I_k) (the matrix determinant lemma, twice),
//   det(c I + h_1 h_1^T + h_2 h_2^T) = c^2 + c (|h_1|^2 + |h_2|^2) + det(h_1, h_2)^2,
// a sum of terms none of which is negative.
double determinant(const Body& bumper, const Body& wedge, const Eigen::Vector2d& point,
                   const Eigen::Vector2d& normal) {
  const Eigen::Vector2d t = tangent(normal);
  double c = 0.0;
  std::array<Eigen::Vector2d, 2> h{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  const std::array<std::pair<const Body*, double>, 2> sides{{{&bumper, 1.0}, {&wedge, -1.0}}};
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& [body, side] = sides[k];
    if (const auto* mass = std::get_if<material_2d::PointMass>(body)) {
      c += normal.squaredNorm() / mass->mass;
    } else if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(body)) {
      c += normal.squaredNorm() / rigid->mass;
      const Eigen::Vector2d r = point - rigid->position;
      h[k] = side * Eigen::Vector2d(det(r, normal), -det(r, t)) / std::sqrt(rigid->inertia);
    }
  }
  const double coupling = det(h[0], h[1]);
  return c * c + c * (h[0].squaredNorm() + h[1].squaredNorm()) + coupling * coupling;
}

}  // namespace

Eigen::Vector2d tangent(const Eigen::Vector2d& normal) {
  return quarter_turn(normal);  // [-n_y, n_x]
}

ContactDynamics dynamics(const Body& bumper, const Body& wedge, const Eigen::Vector2d& point,
                         const Eigen::Vector2d& normal) {
  check(bumper, wedge, point, normal);
  const Eigen::Vector2d t = tangent(normal);
  // Each body's own directions: its outward normal, and minus the way its tangential impulse
  // pushes it (the bumper is pushed along +t, the wedge along -t).
  const std::array<multipoint::Touch, 2> bumper_touches{{{0, normal, point}, {1, -t, point}}};
  const std::array<multipoint::Touch, 2> wedge_touches{{{0, -normal, point}, {1, t, point}}};
  ContactDynamics contact;
  for (const auto& [body, touches] : {std::pair{&bumper, std::span(bumper_touches)},
                                      std::pair{&wedge, std::span(wedge_touches)}}) {
    // (4.5) for a point mass, (5.3) for a rigid body, at elasticity 1; nothing for a static body.
    const BlockContribution block =
        multipoint::contribution(*body, touches, Elasticity::inelastic());
    if (!block.contacts.empty()) {
      contact.W += block.a;   // the ⊕ of the two bodies' blocks
      contact.u0 -= block.b;  // b at elasticity 1 is the velocity along the directions
    }
  }
  contact.determinant = determinant(bumper, wedge, point, normal);
  return contact;
}

Eigen::Vector2d on_bumper(const Eigen::Vector2d& normal, const ContactImpulse& impulse) {
  return -normal * impulse.normal + tangent(normal) * impulse.tangential;
}

Pair apply(const Body& bumper, const Body& wedge, const Eigen::Vector2d& point,
           const Eigen::Vector2d& normal, const ContactImpulse& impulse) {
  check(bumper, wedge, point, normal);
  require_finite("impulse", Eigen::Vector2d(impulse.normal, impulse.tangential));
  // Two contacts at the same point between the same bodies: the normal one, and one whose
  // "normal" is -t, so that the bumper receives -(-t) P_t = t P_t and the wedge -t P_t.
  const std::array<Body, 2> bodies{bumper, wedge};
  const std::array<multipoint::Contact, 2> contacts{
      {{0, 1, normal, point}, {0, 1, -tangent(normal), point}}};
  const std::vector<Body> after = multipoint::apply_impulses(
      bodies, contacts, Eigen::Vector2d(impulse.normal, impulse.tangential));
  return {after[0], after[1]};
}

Collision collide(const Body& bumper, const Body& wedge, const Eigen::Vector2d& point,
                  const Eigen::Vector2d& normal, const ContactLaw& law) {
  Collision collision;
  collision.impulse = resolve_contact(dynamics(bumper, wedge, point, normal), law);
  collision.after = collision.impulse.status == ContactStatus::resolved
                        ? apply(bumper, wedge, point, normal, collision.impulse)
                        : Pair{bumper, wedge};
  return collision;
}

}  // namespace impulse::friction
