// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Section 3: a rigid body in the plane, one contact point.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "impulse/core/checked.hpp"
#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/core/plane.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"

/// @brief Section 3 of the paper: rigid bodies in the plane (two translations and a rotation).
///
/// A rigid body has a mass m, a moment of inertia I about its origin (its centre of mass), the
/// origin's position, a momentum @f$ \vec{p} @f$ and an angular momentum L about the origin.
/// A contact point at world position x has the arm @f$ \vec{r} = x - \text{position} @f$.
namespace impulse::rigid_2d {

/// @brief A rigid body in the plane.
struct RigidBody {
  double mass = 1.0;                                   ///< m > 0
  double inertia = 1.0;                                ///< I > 0, about the origin
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< the origin (centre of mass)
  Eigen::Vector2d p = Eigen::Vector2d::Zero();         ///< momentum @f$ \vec{p} @f$
  double L = 0.0;                                      ///< angular momentum about the origin
};

/// @brief Throws InvalidInput unless mass and inertia are positive and finite and the rest finite.
/// @param body the body to check
/// @param name how the message names it
inline void validate(const RigidBody& body, const char* name = "body");

/// @brief @f$ \vec{v} = \vec{p}/m @f$, the velocity of the origin.
/// @param body the body
/// @return its translational velocity
[[nodiscard]] inline Eigen::Vector2d velocity(const RigidBody& body);

/// @brief @f$ \omega = L/I @f$.
/// @param body the body
/// @return its angular velocity
[[nodiscard]] inline double angular_velocity(const RigidBody& body);

/// @brief (3.1): @f$ E_k = E_r + E_t = L^2/2I + \|\vec{p}\|^2/2m @f$.
/// @param body the body
/// @return its kinetic energy
[[nodiscard]] inline double kinetic_energy(const RigidBody& body);

/// @brief Angular momentum about the world origin: @f$ L + \det(\text{position}, \vec{p}) @f$.
/// @param body the body
/// @return spin plus orbital angular momentum
[[nodiscard]] inline double angular_momentum_about_origin(const RigidBody& body);

/// @brief The velocity of the body's material point at @p point (section 3.2):
/// @f$ \vec{v_v} = \frac{L}{I}[-r_y, r_x] + \frac{\vec{p}}{m} @f$.
/// @param body the body
/// @param point the point in world coordinates
/// @return the point's velocity
[[nodiscard]] inline Eigen::Vector2d point_velocity(const RigidBody& body,
                                                    const Eigen::Vector2d& point);

/// @brief Section 3.2 with the motion known (a body's ω and the velocity of its origin, kept to
/// measure many of its points): @f$ \omega[-r_y, r_x] + \vec{v} @f$.
/// @param omega the angular velocity L/I
/// @param velocity the velocity of the origin, p/m
/// @param r the point relative to the origin
/// @return the point's velocity
[[nodiscard]] inline Eigen::Vector2d point_velocity(double omega, const Eigen::Vector2d& velocity,
                                                    const Eigen::Vector2d& r);

/// @brief The point velocity cast on the body's outward normal, positive towards the other body.
/// @param body the body
/// @param point the contact point in world coordinates
/// @param n the body's outward unit normal there
/// @return @f$ \frac{L\det(\vec{r},\vec{n})}{I} + \frac{\vec{p}\cdot\vec{n}}{m} @f$
[[nodiscard]] inline double normal_velocity(const RigidBody& body, const Eigen::Vector2d& point,
                                            const Eigen::Vector2d& n);

/// @brief The body's share at one contact, (3.6) and (3.10) joined by the elasticity:
/// @f$ a = \frac{\det(\vec{r},\vec{n})^2}{I} + \frac{\|\vec{n}\|^2}{m} @f$,
/// @f$ b = e\left(\frac{L\det(\vec{r},\vec{n})}{I} + \frac{\vec{p}\cdot\vec{n}}{m}\right) @f$.
/// @param body the body (validated)
/// @param point the contact point in world coordinates
/// @param n the body's own outward unit normal (validated)
/// @param elasticity its elasticity (1 gives (3.10), 2 gives (3.6))
/// @return (a, b)
[[nodiscard]] inline ScalarContribution contribution(const RigidBody& body,
                                                     const Eigen::Vector2d& point,
                                                     const Eigen::Vector2d& n,
                                                     Elasticity elasticity);

/// @brief The body after the impulse @f$ -\vec{n}\,F\,dt @f$ at @p point ((3.2), (3.3)):
/// @f$ \vec{p}' = \vec{p} - \vec{n}\,F\,dt @f$,
/// @f$ L' = L + \det(\vec{r}, -\vec{n}\,F\,dt) @f$.
/// @param body the body before
/// @param point where the impulse acts, in world coordinates
/// @param n the body's outward unit normal there
/// @param Fdt the impulse magnitude
/// @return the body after
[[nodiscard]] inline RigidBody apply_impulse(const RigidBody& body, const Eigen::Vector2d& point,
                                             const Eigen::Vector2d& n, double Fdt);

/// @brief Two rigid bodies colliding at one point, solved.
struct Collision {
  ScalarSolution solution;  ///< Fdt with the summed A and B (section 3.4)
  RigidBody bumper;         ///< the bumper after
  RigidBody wedge;          ///< the wedge after
};

/// @brief Collides two rigid bodies at one point: @f$ F\,dt\,(A_1 + A_2) = B_1 + B_2 @f$,
/// checking the bodies, the point and the normal first (InvalidInput naming "bumper", "wedge",
/// "point" or "normal"; the normal must be of unit length).
/// @param bumper the body whose outward normal is @p n
/// @param bumper_elasticity its elasticity
/// @param wedge the body whose outward normal is -@p n
/// @param wedge_elasticity its elasticity
/// @param point the contact point in world coordinates
/// @param n unit normal, outward from the bumper
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const RigidBody& bumper, Elasticity bumper_elasticity,
                                       const RigidBody& wedge, Elasticity wedge_elasticity,
                                       const Eigen::Vector2d& point, const Eigen::Vector2d& n);

/// @brief Collides two rigid bodies checked when they were made, along a normal checked when it
/// was made: only the point is tested (finite, else InvalidInput naming "point").
/// @param bumper the body whose outward normal is @p n
/// @param bumper_elasticity its elasticity
/// @param wedge the body whose outward normal is -@p n
/// @param wedge_elasticity its elasticity
/// @param point the contact point in world coordinates
/// @param n the normal, outward from the bumper
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const Checked<RigidBody>& bumper,
                                       Elasticity bumper_elasticity,
                                       const Checked<RigidBody>& wedge, Elasticity wedge_elasticity,
                                       const Eigen::Vector2d& point, const UnitNormal& n);

// The single-contact path is defined here, inline, so that the caller's compiler sees the whole
// formula: bench/single_contact.cpp measures it against the same impulse written by hand.

namespace detail {
// The test behind validate(), the same as its checks one by one, in one branch for the caller.
// No test raises a floating-point exception for a NaN or an infinity (see is_positive and
// all_finite), so a caller that traps them gets the refusal.
inline bool acceptable(const RigidBody& body) {
  const bool mass_ok = is_positive(body.mass);
  const bool inertia_ok = is_positive(body.inertia);
  const bool rest_ok =
      all_finite(body.position.x(), body.position.y(), body.p.x(), body.p.y(), body.L);
  return mass_ok & inertia_ok & rest_ok;
}
// Throws InvalidInput naming the first bad field of a body that failed the test.
[[noreturn]] void refuse(const RigidBody& body, const char* name);
// Runs the checks of collide() one by one and throws the first failing one's message.
[[noreturn]] void refuse_collision(const RigidBody& bumper, const RigidBody& wedge,
                                   const Eigen::Vector2d& point, const Eigen::Vector2d& n);
}  // namespace detail

inline void validate(const RigidBody& body, const char* name) {
  if (!detail::acceptable(body)) [[unlikely]] {
    detail::refuse(body, name);  // builds the message only now
  }
}

inline Eigen::Vector2d velocity(const RigidBody& body) {
  return body.p / body.mass;
}

inline double angular_velocity(const RigidBody& body) {
  return body.L / body.inertia;
}

inline double kinetic_energy(const RigidBody& body) {
  // (3.1): E_k = E_r + E_t
  return body.L * body.L / (2.0 * body.inertia) + body.p.squaredNorm() / (2.0 * body.mass);
}

inline double angular_momentum_about_origin(const RigidBody& body) {
  return body.L + det(body.position, body.p);
}

inline Eigen::Vector2d point_velocity(double omega, const Eigen::Vector2d& velocity,
                                      const Eigen::Vector2d& r) {
  return omega * quarter_turn(r) + velocity;  // section 3.2
}

inline Eigen::Vector2d point_velocity(const RigidBody& body, const Eigen::Vector2d& point) {
  return point_velocity(angular_velocity(body), velocity(body), point - body.position);
}

inline double normal_velocity(const RigidBody& body, const Eigen::Vector2d& point,
                              const Eigen::Vector2d& n) {
  return point_velocity(body, point).dot(n);  // (3.8) before the impulse
}

namespace detail {
// (3.6) at elasticity 2, (3.10) at elasticity 1, for a body, point and normal already validated.
// with the lever arm det(r, n), which the body's update needs again.
struct ArmedShare {
  ScalarContribution share;
  double arm = 0.0;  // det(r, n)
};
// `squared` is |n|², the same for the bumper's n and the wedge's -n: a collision computes it once.
inline ArmedShare armed_share(const RigidBody& body, const Eigen::Vector2d& point,
                              const Eigen::Vector2d& n, double squared, Elasticity elasticity) {
  const double arm = det(point - body.position, n);  // det(r, n)
  return {{arm * arm / body.inertia + squared / body.mass,
           elasticity.value() * (body.L * arm / body.inertia + body.p.dot(n) / body.mass)},
          arm};
}
inline ScalarContribution share(const RigidBody& body, const Eigen::Vector2d& point,
                                const Eigen::Vector2d& n, Elasticity elasticity) {
  return armed_share(body, point, n, n.squaredNorm(), elasticity).share;
}
// The body after the impulse -n Fdt whose lever arm det(r, n) is known: (3.2) with
// det(r, -n Fdt) = -Fdt det(r, n).
inline RigidBody apply_armed(const RigidBody& body, const Eigen::Vector2d& n, double arm,
                             double Fdt) {
  RigidBody after = body;
  after.p -= n * Fdt;    // (3.2), translation
  after.L -= arm * Fdt;  // (3.2), rotation
  return after;
}
}  // namespace detail

inline ScalarContribution contribution(const RigidBody& body, const Eigen::Vector2d& point,
                                       const Eigen::Vector2d& n, Elasticity elasticity) {
  validate(body);
  require_finite("point", point);
  require_unit_normal("normal", n);
  return detail::share(body, point, n, elasticity);
}

inline RigidBody apply_impulse(const RigidBody& body, const Eigen::Vector2d& point,
                               const Eigen::Vector2d& n, double Fdt) {
  const Eigen::Vector2d impulse = -n * Fdt;  // (3.3)
  RigidBody after = body;
  after.p += impulse;                              // (3.2), translation
  after.L += det(point - body.position, impulse);  // (3.2), rotation
  return after;
}

namespace detail {
// Section 3.4 for bodies, point and normal already checked: Fdt (A1 + A2) = B1 + B2, the wedge
// with its own normal -n, then each body's update.
// `squared` is |n|², known beforehand for an impulse::UnitNormal.
inline Collision collide_checked(const RigidBody& bumper, Elasticity bumper_elasticity,
                                 const RigidBody& wedge, Elasticity wedge_elasticity,
                                 const Eigen::Vector2d& point, const Eigen::Vector2d& n,
                                 double squared) {
  const ArmedShare first = armed_share(bumper, point, n, squared, bumper_elasticity);
  const ArmedShare second = armed_share(wedge, point, -n, squared, wedge_elasticity);
  const ScalarSolution solution = solve(first.share + second.share);
  return {solution, apply_armed(bumper, n, first.arm, solution.Fdt),
          apply_armed(wedge, -n, second.arm, solution.Fdt)};
}
}  // namespace detail

inline Collision collide(const RigidBody& bumper, Elasticity bumper_elasticity,
                         const RigidBody& wedge, Elasticity wedge_elasticity,
                         const Eigen::Vector2d& point, const Eigen::Vector2d& n) {
  // All the checks in one branch, as in detail::acceptable; only when it fails do they run one
  // by one, out of line, to throw the first failing one's message.
  const bool bumper_ok = detail::acceptable(bumper);
  const bool wedge_ok = detail::acceptable(wedge);
  const bool point_ok = all_finite(point.x(), point.y());
  const bool normal_ok = is_unit_normal(n);
  if (!(bumper_ok & wedge_ok & point_ok & normal_ok)) [[unlikely]] {
    detail::refuse_collision(bumper, wedge, point, n);
  }
  return detail::collide_checked(bumper, bumper_elasticity, wedge, wedge_elasticity, point, n,
                                 n.squaredNorm());
}

inline Collision collide(const Checked<RigidBody>& bumper, Elasticity bumper_elasticity,
                         const Checked<RigidBody>& wedge, Elasticity wedge_elasticity,
                         const Eigen::Vector2d& point, const UnitNormal& n) {
  if (!all_finite(point.x(), point.y())) [[unlikely]] {
    require_finite("point", point);
  }
  return detail::collide_checked(bumper.get(), bumper_elasticity, wedge.get(), wedge_elasticity,
                                 point, n.vector(), n.squared_norm());
}

}  // namespace impulse::rigid_2d
