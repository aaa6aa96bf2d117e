// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Section 1: material bodies on a line, one contact.
#pragma once

#include <cmath>

#include "impulse/core/checked.hpp"
#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"

/// @brief Section 1 of the paper: material bodies that move on one line.
///
/// Positions and momenta are signed along the line's axis. At a contact each body has an outward
/// direction, +1 or -1 (its normal on the line): the body on the left has +1, the one on the
/// right -1. A body's normal velocity @f$ s\,p/m @f$ is positive when it moves towards the other
/// body, which is the paper's sign convention for @f$ p_1 @f$ and @f$ p_2 @f$.
namespace impulse::one_d {

/// @brief A material body on a line.
struct Body {
  double mass = 1.0;      ///< m > 0
  double momentum = 0.0;  ///< p, signed along the axis
};

/// @brief A body from its velocity instead of its momentum.
/// @param mass m > 0
/// @param velocity v, signed along the axis
/// @return the body with p = m v
[[nodiscard]] Body from_velocity(double mass, double velocity);

/// @brief Throws InvalidInput unless the mass is positive and finite and the momentum finite.
/// @param body the body to check
/// @param name how the message names it ("body", "bumper")
inline void validate(const Body& body, const char* name = "body");

/// @brief v = p / m.
/// @param body the body
/// @return its velocity along the axis
[[nodiscard]] inline double velocity(const Body& body);

/// @brief @f$ E_k = p^2 / 2m @f$.
/// @param body the body
/// @return its kinetic energy
[[nodiscard]] inline double kinetic_energy(const Body& body);

/// @brief The body's velocity cast on its outward direction: @f$ s\,p/m @f$.
/// @param body the body
/// @param outward its outward direction at the contact, +1 or -1
/// @return positive when the body moves towards the other one
[[nodiscard]] inline double normal_velocity(const Body& body, double outward);

/// @brief The body's share of (1.3): @f$ a = 1/m @f$, @f$ b = e\,(s\,p)/m @f$.
///
/// Summed over both bodies this is
/// @f$ F\,dt\,(\frac{1}{m_1}+\frac{1}{m_2}) = \frac{e_1 p_1}{m_1}+\frac{e_2 p_2}{m_2} @f$,
/// which is (1.1) at e = 2 and (1.2) at e = 1.
/// @param body the body (validated)
/// @param outward its outward direction at the contact, +1 or -1
/// @param elasticity the body's own elasticity (the paper's elasticity_1 or elasticity_2)
/// @return (a, b)
[[nodiscard]] inline ScalarContribution contribution(const Body& body, double outward,
                                                     Elasticity elasticity);

/// @brief The body after the impulse: @f$ p' = p - s\,F\,dt @f$ (section 1, first display).
/// @param body the body before
/// @param outward its outward direction at the contact, +1 or -1
/// @param Fdt the impulse magnitude
/// @return the body after
[[nodiscard]] inline Body apply_impulse(const Body& body, double outward, double Fdt);

/// @brief A two-body collision on a line, solved.
struct Collision {
  ScalarSolution solution;  ///< Fdt with the summed A and B
  Body first;               ///< the first body after
  Body second;              ///< the second body after
};

/// @brief Collides two bodies at one point with (1.3), checking them first (InvalidInput naming
/// "first", "second" or "normal").
/// @param first the body whose outward direction is @p normal
/// @param first_elasticity its elasticity
/// @param second the body whose outward direction is -@p normal
/// @param second_elasticity its elasticity
/// @param normal +1 when @p first is on the left of @p second, -1 otherwise
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const Body& first, Elasticity first_elasticity,
                                       const Body& second, Elasticity second_elasticity,
                                       double normal = 1.0);

/// @brief Collides two bodies checked when they were made, with (1.3): only the direction is
/// tested (+1 or -1), the bodies not again.
/// @param first the body whose outward direction is @p normal
/// @param first_elasticity its elasticity
/// @param second the body whose outward direction is -@p normal
/// @param second_elasticity its elasticity
/// @param normal +1 when @p first is on the left of @p second, -1 otherwise
/// @return the impulse and both bodies after
[[nodiscard]] inline Collision collide(const Checked<Body>& first, Elasticity first_elasticity,
                                       const Checked<Body>& second, Elasticity second_elasticity,
                                       double normal = 1.0);

// The single-contact path is defined here, inline, so that the caller's compiler sees the whole
// formula: bench/single_contact.cpp measures it against the same impulse written by hand.

namespace detail {
// The test behind validate(), the same as its checks one by one, in one branch for the caller.
inline bool acceptable(const Body& body) {
  const bool mass_ok = is_positive(body.mass);
  const bool momentum_ok = all_finite(body.momentum);
  return mass_ok & momentum_ok;
}
// Throws InvalidInput naming the first bad field of a body that failed the test.
[[noreturn]] void refuse(const Body& body, const char* name);
// Runs the checks of collide() one by one and throws the first failing one's message.
[[noreturn]] void refuse_collision(const Body& first, const Body& second, double normal);
}  // namespace detail

inline void validate(const Body& body, const char* name) {
  if (!detail::acceptable(body)) [[unlikely]] {
    detail::refuse(body, name);  // builds the message only now
  }
}

inline double velocity(const Body& body) {
  return body.momentum / body.mass;
}

inline double kinetic_energy(const Body& body) {
  return body.momentum * body.momentum / (2.0 * body.mass);
}

inline double normal_velocity(const Body& body, double outward) {
  return outward * body.momentum / body.mass;
}

namespace detail {
// (1.3) for a body already validated: a = 1/m, b = elasticity * p / m, with p cast on the
// body's outward direction.
inline ScalarContribution share(const Body& body, double outward, Elasticity elasticity) {
  return {1.0 / body.mass, elasticity.value() * normal_velocity(body, outward)};
}
}  // namespace detail

inline ScalarContribution contribution(const Body& body, double outward, Elasticity elasticity) {
  validate(body);
  require_unit_direction("outward direction", outward);
  return detail::share(body, outward, elasticity);  // (1.3)
}

inline Body apply_impulse(const Body& body, double outward, double Fdt) {
  // Section 1: p1' = p1 - Fdt, p2' = p2 + Fdt; the sign is the body's outward direction.
  return {body.mass, body.momentum - outward * Fdt};
}

namespace detail {
// The collision of two bodies and a direction already checked: the ⊕ of the two shares of (1.3),
// then Fdt = B / A, then each body's update.
inline Collision collide_checked(const Body& first, Elasticity first_elasticity, const Body& second,
                                 Elasticity second_elasticity, double normal) {
  const ScalarSolution solution =
      solve(share(first, normal, first_elasticity) + share(second, -normal, second_elasticity));
  return {solution, apply_impulse(first, normal, solution.Fdt),
          apply_impulse(second, -normal, solution.Fdt)};
}
}  // namespace detail

inline Collision collide(const Body& first, Elasticity first_elasticity, const Body& second,
                         Elasticity second_elasticity, double normal) {
  const bool first_ok = detail::acceptable(first);
  const bool second_ok = detail::acceptable(second);
  if (!(first_ok & second_ok & ((normal == 1.0) | (normal == -1.0)))) [[unlikely]] {
    detail::refuse_collision(first, second, normal);  // the checks one by one, with messages
  }
  return detail::collide_checked(first, first_elasticity, second, second_elasticity, normal);
}

inline Collision collide(const Checked<Body>& first, Elasticity first_elasticity,
                         const Checked<Body>& second, Elasticity second_elasticity, double normal) {
  if (!((normal == 1.0) | (normal == -1.0))) [[unlikely]] {
    require_unit_direction("normal", normal);
  }
  return detail::collide_checked(first.get(), first_elasticity, second.get(), second_elasticity,
                                 normal);
}

}  // namespace impulse::one_d
