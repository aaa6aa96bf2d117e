// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Beyond the paper: the contact with friction between any section's two bodies — its
/// W and u0 from the bodies, and the bodies after its impulse.
#pragma once

#include <Eigen/Core>

#include "impulse/friction/contact.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::friction {

/// @brief The tangent of a contact: the bumper's outward normal turned a quarter
/// counter-clockwise, @f$ \vec{t} = [-n_y, n_x] @f$ (the scene format's).
/// @param normal the bumper's outward unit normal
/// @return the unit tangent
[[nodiscard]] Eigen::Vector2d tangent(const Eigen::Vector2d& normal);

/// @brief W and u0 of the contact between two bodies (a point mass, a rigid body, or a static
/// body, which contributes nothing).
///
/// Each body's share is the paper's own block (multipoint::contribution, i.e. (4.5) for a
/// point mass and (5.3) for a rigid body, at elasticity 1) over two directions at the contact
/// point: its outward normal (the bumper's @f$ \vec{n} @f$, the wedge's @f$ -\vec{n} @f$) and
/// the direction against which the tangential impulse pushes it (the bumper's
/// @f$ -\vec{t} @f$, the wedge's @f$ \vec{t} @f$; each body receives minus its direction times
/// the impulse). The two blocks are summed as the paper's ⊕ sums them:
/// @f$ W = a_{bumper} + a_{wedge} @f$ and @f$ u_0 = -(b_{bumper} + b_{wedge}) @f$. So
/// @f$ W_{nn} @f$ is the paper's A for this contact ((3.6)/(3.10), (4.5)/(4.8), (5.3)/(5.5) with
/// one contact) and @f$ -u_{0,n} @f$ its approach speed (multipoint::approach).
/// @param bumper the body whose outward normal is @p normal
/// @param wedge the other body
/// @param point the contact point in world coordinates (used by rigid bodies)
/// @param normal unit normal, outward from the bumper
/// @return W and u0 (InvalidInput for a bad body, point or normal, with the place named)
[[nodiscard]] ContactDynamics dynamics(const multipoint::Body& bumper,
                                       const multipoint::Body& wedge, const Eigen::Vector2d& point,
                                       const Eigen::Vector2d& normal);

/// @brief The whole impulse on the bumper: @f$ -\vec{n}\,P_n + \vec{t}\,P_t @f$ (the wedge
/// receives the opposite). The scene format's `on_bumper` with friction.
/// @param normal the bumper's outward unit normal
/// @param impulse the contact's impulse (ContactImpulse::normal and ContactImpulse::tangential)
/// @return the impulse vector on the bumper
[[nodiscard]] Eigen::Vector2d on_bumper(const Eigen::Vector2d& normal,
                                        const ContactImpulse& impulse);

/// @brief The two bodies of a contact.
struct Pair {
  multipoint::Body bumper;  ///< the body whose outward normal is the contact's normal
  multipoint::Body wedge;   ///< the other body
};

/// @brief The bodies after the impulse: the bumper receives @f$ -\vec{n}\,P_n + \vec{t}\,P_t @f$
/// at @p point, the wedge the opposite, through multipoint::apply_impulses (each body's own
/// apply_impulse: @f$ \vec{p}' = \vec{p} + \vec{J} @f$, and (3.2) for a rigid body's
/// @f$ L' = L + \det(\vec{r}, \vec{J}) @f$; a static body does not move).
/// @param bumper the bumper before
/// @param wedge the wedge before
/// @param point the contact point in world coordinates
/// @param normal unit normal, outward from the bumper
/// @param impulse the contact's impulse (its normal and tangential parts)
/// @return both bodies after
[[nodiscard]] Pair apply(const multipoint::Body& bumper, const multipoint::Body& wedge,
                         const Eigen::Vector2d& point, const Eigen::Vector2d& normal,
                         const ContactImpulse& impulse);

/// @brief A collision with friction between two bodies, resolved.
struct Collision {
  ContactImpulse impulse;  ///< impulses, velocities at the contact, phases, works
  /// The bodies after (the bodies before unless impulse.status is ContactStatus::resolved).
  Pair after;
};

/// @brief Collides two bodies at one contact with friction: dynamics(), resolve_contact(),
/// apply().
/// @param bumper the body whose outward normal is @p normal
/// @param wedge the other body
/// @param point the contact point in world coordinates
/// @param normal unit normal, outward from the bumper
/// @param law μ, the elasticity and the law of restitution
/// @return the impulse and both bodies after
[[nodiscard]] Collision collide(const multipoint::Body& bumper, const multipoint::Body& wedge,
                                const Eigen::Vector2d& point, const Eigen::Vector2d& normal,
                                const ContactLaw& law);

}  // namespace impulse::friction
