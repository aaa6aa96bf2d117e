// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/rigid_2d/rigid_2d.hpp"

#include <cmath>
#include <string>

#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"

namespace impulse::rigid_2d {

void validate(const RigidBody& body, const char* name) {
  if (is_positive(body.mass) && is_positive(body.inertia) && std::isfinite(body.position.x()) &&
      std::isfinite(body.position.y()) && std::isfinite(body.p.x()) && std::isfinite(body.p.y()) &&
      std::isfinite(body.L)) [[likely]] {
    return;  // the common case: no message, no string built
  }
  const std::string prefix(name);
  require_positive(prefix + ".mass", body.mass);
  require_positive(prefix + ".inertia", body.inertia);
  require_finite(prefix + ".position", body.position);
  require_finite(prefix + ".p", body.p);
  require_finite(prefix + ".L", body.L);
}

Eigen::Vector2d velocity(const RigidBody& body) {
  return body.p / body.mass;
}

double angular_velocity(const RigidBody& body) {
  return body.L / body.inertia;
}

double kinetic_energy(const RigidBody& body) {
  // (3.1): E_k = E_r + E_t
  return body.L * body.L / (2.0 * body.inertia) + body.p.squaredNorm() / (2.0 * body.mass);
}

double angular_momentum_about_origin(const RigidBody& body) {
  return body.L + det(body.position, body.p);
}

Eigen::Vector2d point_velocity(const RigidBody& body, const Eigen::Vector2d& point) {
  const Eigen::Vector2d r = point - body.position;
  return angular_velocity(body) * quarter_turn(r) + velocity(body);  // section 3.2
}

double normal_velocity(const RigidBody& body, const Eigen::Vector2d& point,
                       const Eigen::Vector2d& n) {
  return point_velocity(body, point).dot(n);  // (3.8) before the impulse
}

namespace {
// (3.6) at elasticity 2, (3.10) at elasticity 1, for a body, point and normal already validated.
ScalarContribution share(const RigidBody& body, const Eigen::Vector2d& point,
                         const Eigen::Vector2d& n, Elasticity elasticity) {
  const double arm = det(point - body.position, n);  // det(r, n)
  return {arm * arm / body.inertia + n.squaredNorm() / body.mass,
          elasticity.value() * (body.L * arm / body.inertia + body.p.dot(n) / body.mass)};
}
}  // namespace

ScalarContribution contribution(const RigidBody& body, const Eigen::Vector2d& point,
                                const Eigen::Vector2d& n, Elasticity elasticity) {
  validate(body);
  require_finite("point", point);
  require_unit_normal("normal", n);
  return share(body, point, n, elasticity);
}

RigidBody apply_impulse(const RigidBody& body, const Eigen::Vector2d& point,
                        const Eigen::Vector2d& n, double Fdt) {
  const Eigen::Vector2d impulse = -n * Fdt;  // (3.3)
  RigidBody after = body;
  after.p += impulse;                              // (3.2), translation
  after.L += det(point - body.position, impulse);  // (3.2), rotation
  return after;
}

Collision collide(const RigidBody& bumper, Elasticity bumper_elasticity, const RigidBody& wedge,
                  Elasticity wedge_elasticity, const Eigen::Vector2d& point,
                  const Eigen::Vector2d& n) {
  validate(bumper, "bumper");
  validate(wedge, "wedge");
  require_finite("point", point);
  require_unit_normal("normal", n);
  // Section 3.4: Fdt (A1 + A2) = B1 + B2, the wedge with its own normal -n.
  // Validated once above.
  const ScalarSolution solution =
      solve(share(bumper, point, n, bumper_elasticity) + share(wedge, point, -n, wedge_elasticity));
  return {solution, apply_impulse(bumper, point, n, solution.Fdt),
          apply_impulse(wedge, point, -n, solution.Fdt)};
}

}  // namespace impulse::rigid_2d
