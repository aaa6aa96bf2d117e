// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Section 2: point masses in the plane, one contact, cast onto the normal.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "impulse/core/checked.hpp"
#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"

/// @brief Section 2 of the paper: material bodies (point masses) in the plane.
///
/// The collision only acts along the contact normal, so each body's momentum is cast onto its own
/// outward normal, @f$ p_n = \vec{p}\cdot\vec{n} @f$, and section 1 applies to @f$ p_n @f$.
/// The bumper's outward normal is @f$ \vec{n} @f$, the wedge's @f$ -\vec{n} @f$.
namespace impulse::material_2d {

/// @brief A point mass in the plane.
struct PointMass {
  double mass = 1.0;                            ///< m > 0
  Eigen::Vector2d p = Eigen::Vector2d::Zero();  ///< momentum @f$ \vec{p} @f$
};

/// @brief A point mass from its velocity.
/// @param mass m > 0
/// @param velocity @f$ \vec{v} @f$
/// @return the point mass with @f$ \vec{p} = m\vec{v} @f$
[[nodiscard]] PointMass from_velocity(double mass, const Eigen::Vector2d& velocity);

/// @brief Throws InvalidInput unless the mass is positive and finite and the momentum finite.
/// @param body the body to check
/// @param name how the message names it
inline void validate(const PointMass& body, const char* name = "body");

/// @brief @f$ \vec{v} = \vec{p}/m @f$.
/// @param body the body
/// @return its velocity
[[nodiscard]] inline Eigen::Vector2d velocity(const PointMass& body);

/// @brief @f$ E_t = \|\vec{p}\|^2 / 2m @f$.
/// @param body the body
/// @return its kinetic energy
[[nodiscard]] inline double kinetic_energy(const PointMass& body);

/// @brief The paper's cast of @p v onto the direction of @p direction:
/// @f$ \vec{v}\cdot\vec{d}/\|\vec{d}\| @f$ (a plain dot product when @p direction is a unit
/// normal).
/// @param v the vector to cast
/// @param direction a non-zero direction (zero or non-finite throws InvalidInput)
/// @return the signed length of v along the direction
[[nodiscard]] double cast(const Eigen::Vector2d& v, const Eigen::Vector2d& direction);

/// @brief The normal velocity @f$ \vec{p}\cdot\vec{n}/m @f$, positive when moving along @p n.
/// @param body the body
/// @param n its outward unit normal
/// @return the normal velocity
[[nodiscard]] inline double normal_velocity(const PointMass& body, const Eigen::Vector2d& n);

/// @brief The body's share of (1.3) on the cast: @f$ a = \|\vec{n}\|^2/m @f$,
/// @f$ b = e\,(\vec{p}\cdot\vec{n})/m @f$ (the single-contact form of (4.5)/(4.8)).
/// @param body the body (validated)
/// @param n its own outward unit normal (validated)
/// @param elasticity its elasticity
/// @return (a, b)
[[nodiscard]] inline ScalarContribution contribution(const PointMass& body,
                                                     const Eigen::Vector2d& n,
                                                     Elasticity elasticity);

/// @brief The vectorised impulse on a body of outward normal @p n: @f$ -\vec{n}\,F\,dt @f$.
/// @param n the body's outward unit normal
/// @param Fdt the impulse magnitude
/// @return the impulse vector
[[nodiscard]] inline Eigen::Vector2d impulse_vector(const Eigen::Vector2d& n, double Fdt);

/// @brief The body after the impulse: @f$ \vec{p}' = \vec{p} - \vec{n}\,F\,dt @f$.
/// @param body the body before
/// @param n its outward unit normal
/// @param Fdt the impulse magnitude
/// @return the body after
[[nodiscard]] inline PointMass apply_impulse(const PointMass& body, const Eigen::Vector2d& n,
                                             double Fdt);

/// @brief A two-body collision in the plane, solved.
struct Collision {
  ScalarSolution solution;  ///< Fdt with the summed A and B
  PointMass bumper;         ///< the bumper after
  PointMass wedge;          ///< the wedge after
};

/// @brief Collides two point masses at one contact, checking them and the normal first
/// (InvalidInput naming "bumper", "wedge" or "normal"; the normal must be of unit length).
/// @param bumper the body whose outward normal is @p n
/// @param bumper_elasticity its elasticity
/// @param wedge the body whose outward normal is -@p n
/// @param wedge_elasticity its elasticity
/// @param n unit normal, outward from the bumper
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const PointMass& bumper, Elasticity bumper_elasticity,
                                       const PointMass& wedge, Elasticity wedge_elasticity,
                                       const Eigen::Vector2d& n);

/// @brief Collides two point masses checked when they were made, along a normal checked when it
/// was made: nothing is tested again.
/// @param bumper the body whose outward normal is @p n
/// @param bumper_elasticity its elasticity
/// @param wedge the body whose outward normal is -@p n
/// @param wedge_elasticity its elasticity
/// @param n the normal, outward from the bumper
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const Checked<PointMass>& bumper,
                                       Elasticity bumper_elasticity,
                                       const Checked<PointMass>& wedge, Elasticity wedge_elasticity,
                                       const UnitNormal& n);

// The single-contact path is defined here, inline, so that the caller's compiler sees the whole
// formula: bench/single_contact.cpp measures it against the same impulse written by hand.

namespace detail {
// The test behind validate(), the same as its checks one by one, in one branch for the caller.
inline bool acceptable(const PointMass& body) {
  const bool mass_ok = is_positive(body.mass);
  const bool momentum_ok = all_finite(body.p.x(), body.p.y());
  return mass_ok & momentum_ok;
}
// Throws InvalidInput naming the first bad field of a body that failed the test.
[[noreturn]] void refuse(const PointMass& body, const char* name);
// Runs the checks of collide() one by one and throws the first failing one's message.
[[noreturn]] void refuse_collision(const PointMass& bumper, const PointMass& wedge,
                                   const Eigen::Vector2d& n);
}  // namespace detail

inline void validate(const PointMass& body, const char* name) {
  if (!detail::acceptable(body)) [[unlikely]] {
    detail::refuse(body, name);  // builds the message only now
  }
}

inline Eigen::Vector2d velocity(const PointMass& body) {
  return body.p / body.mass;
}

inline double kinetic_energy(const PointMass& body) {
  return body.p.squaredNorm() / (2.0 * body.mass);
}

inline double normal_velocity(const PointMass& body, const Eigen::Vector2d& n) {
  return body.p.dot(n) / body.mass;  // p_n / m, with p_n = p . n (section 2)
}

namespace detail {
// (1.3) on the cast p_n = p . n for a body and normal already validated; (4.5)/(4.8) with a
// single contact.
// `squared` is |n|², the same for the bumper's n and the wedge's -n: a collision computes it once.
inline ScalarContribution share(const PointMass& body, const Eigen::Vector2d& n, double squared,
                                Elasticity elasticity) {
  return {squared / body.mass, elasticity.value() * normal_velocity(body, n)};
}
inline ScalarContribution share(const PointMass& body, const Eigen::Vector2d& n,
                                Elasticity elasticity) {
  return share(body, n, n.squaredNorm(), elasticity);
}
}  // namespace detail

inline ScalarContribution contribution(const PointMass& body, const Eigen::Vector2d& n,
                                       Elasticity elasticity) {
  validate(body);
  require_unit_normal("normal", n);
  return detail::share(body, n, elasticity);
}

inline Eigen::Vector2d impulse_vector(const Eigen::Vector2d& n, double Fdt) {
  return -n * Fdt;
}

inline PointMass apply_impulse(const PointMass& body, const Eigen::Vector2d& n, double Fdt) {
  return {body.mass, body.p + impulse_vector(n, Fdt)};
}

namespace detail {
// The collision of two bodies and a normal already checked: the ⊕ of the two shares, then
// Fdt = B / A, then each body's update.
// `squared` is |n|², known beforehand for an impulse::UnitNormal.
inline Collision collide_checked(const PointMass& bumper, Elasticity bumper_elasticity,
                                 const PointMass& wedge, Elasticity wedge_elasticity,
                                 const Eigen::Vector2d& n, double squared) {
  const ScalarSolution solution = solve(share(bumper, n, squared, bumper_elasticity) +
                                        share(wedge, -n, squared, wedge_elasticity));
  return {solution, apply_impulse(bumper, n, solution.Fdt), apply_impulse(wedge, -n, solution.Fdt)};
}
}  // namespace detail

inline Collision collide(const PointMass& bumper, Elasticity bumper_elasticity,
                         const PointMass& wedge, Elasticity wedge_elasticity,
                         const Eigen::Vector2d& n) {
  const bool bumper_ok = detail::acceptable(bumper);
  const bool wedge_ok = detail::acceptable(wedge);
  const bool normal_ok = is_unit_normal(n);
  if (!(bumper_ok & wedge_ok & normal_ok)) [[unlikely]] {
    detail::refuse_collision(bumper, wedge, n);  // the checks one by one, with messages
  }
  return detail::collide_checked(bumper, bumper_elasticity, wedge, wedge_elasticity, n,
                                 n.squaredNorm());
}

inline Collision collide(const Checked<PointMass>& bumper, Elasticity bumper_elasticity,
                         const Checked<PointMass>& wedge, Elasticity wedge_elasticity,
                         const UnitNormal& n) {
  return detail::collide_checked(bumper.get(), bumper_elasticity, wedge.get(), wedge_elasticity,
                                 n.vector(), n.squared_norm());
}

}  // namespace impulse::material_2d
