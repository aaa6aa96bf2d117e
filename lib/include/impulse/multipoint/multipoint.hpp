// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Sections 4 and 5: many bodies, many contact points, one linear system.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <variant>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"

/// @brief Sections 4 and 5 of the paper: every contact gets an equation, every body a block.
///
/// Each body brings a square block over the contacts it touches: (4.5)/(4.8) for a point mass,
/// (5.3)/(5.5) for a rigid body, each computed with the body's own outward normal at each
/// contact. The blocks are summed with ⊕ into A·Fdt = B and solved; the impulses are then applied
/// to every body. Section 1's bodies on a line are the special case of normals @f$ \pm\vec{x} @f$.
namespace impulse::multipoint {

/// @brief An immovable body: zero inverse mass and inertia, zero velocity. It contributes nothing.
struct StaticBody {
  /// @brief All static bodies are alike.
  /// @return true
  bool operator==(const StaticBody&) const = default;
};

/// @brief Any body of sections 4 and 5.
using Body = std::variant<material_2d::PointMass, rigid_2d::RigidBody, StaticBody>;

/// @brief A contact point between two bodies.
struct Contact {
  std::size_t bumper = 0;  ///< index of the body whose normal is `normal`
  std::size_t wedge = 0;   ///< index of the other body (normal -`normal`)
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< unit, outward from the bumper
  Eigen::Vector2d point = Eigen::Vector2d::Zero();    ///< world position (used by rigid bodies)
};

/// @brief One body's view of one contact: the contact's index and the body's own outward normal.
struct Touch {
  Eigen::Index contact = 0;                           ///< global contact index v
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< @f$ \vec{n_v} @f$ of this body
  Eigen::Vector2d point = Eigen::Vector2d::Zero();    ///< contact point, world coordinates
};

/// @brief Throws InvalidInput for a bad body, a contact index out of range, a body in contact
/// with itself or a non-unit normal; the message names the place ("contacts[2].normal").
/// @param bodies the bodies
/// @param contacts the contacts between them
void validate(std::span<const Body> bodies, std::span<const Contact> contacts);

/// @brief The contacts body @p body takes part in, each with the body's own outward normal
/// (`normal` as bumper, `-normal` as wedge), in contact order.
/// @param body index of the body
/// @param contacts all contacts
/// @return the body's touches
[[nodiscard]] std::vector<Touch> touches(std::size_t body, std::span<const Contact> contacts);

/// @brief A point mass's block, (4.5) and (4.8) joined by the elasticity:
/// @f$ a_{vk} = \frac{\vec{n_k}\cdot\vec{n_v}}{m} @f$,
/// @f$ b_v = e\,\frac{\vec{p}\cdot\vec{n_v}}{m} @f$.
/// @param body the point mass
/// @param touches its contacts with its own normals
/// @param elasticity its elasticity
/// @return the block over its contacts
[[nodiscard]] BlockContribution material_block(const material_2d::PointMass& body,
                                               std::span<const Touch> touches,
                                               Elasticity elasticity);

/// @brief A rigid body's block, (5.3) and (5.5) joined by the elasticity:
/// @f$ a_{vk} = \frac{\det(\vec{r_k},\vec{n_k})\det(\vec{r_v},\vec{n_v})}{I}
///            + \frac{\vec{n_k}\cdot\vec{n_v}}{m} @f$,
/// @f$ b_v = e\left(\frac{L\det(\vec{r_v},\vec{n_v})}{I} + \frac{\vec{p}\cdot\vec{n_v}}{m}\right)
/// @f$.
/// @param body the rigid body
/// @param touches its contacts with its own normals
/// @param elasticity its elasticity
/// @return the block over its contacts
[[nodiscard]] BlockContribution rigid_block(const rigid_2d::RigidBody& body,
                                            std::span<const Touch> touches, Elasticity elasticity);

/// @brief Whichever block fits the body; a static body's block is empty.
/// @param body any body
/// @param touches its contacts with its own normals
/// @param elasticity its elasticity
/// @return the block over its contacts
[[nodiscard]] BlockContribution contribution(const Body& body, std::span<const Touch> touches,
                                             Elasticity elasticity);

/// @brief The paper's @f$ \mathbf{A_1} \oplus \cdots \oplus \mathbf{A_M} @f$ and
/// @f$ \vec{B_1} \oplus \cdots \oplus \vec{B_M} @f$ (section 4.5).
/// @param bodies the bodies (validated with the contacts)
/// @param elasticities one per body (a size mismatch throws InvalidInput)
/// @param contacts the contacts
/// @return the assembled system
[[nodiscard]] ContactSystem assemble(std::span<const Body> bodies,
                                     std::span<const Elasticity> elasticities,
                                     std::span<const Contact> contacts);

/// @brief The same ⊕, with the storage of A chosen by the caller (e.g. to compare the dense and
/// sparse methods on one scene).
/// @param bodies the bodies (validated with the contacts)
/// @param elasticities one per body (a size mismatch throws InvalidInput)
/// @param contacts the contacts
/// @param storage dense, sparse, or automatic (sparse above sparse_threshold contacts)
/// @return the assembled system
[[nodiscard]] ContactSystem assemble(std::span<const Body> bodies,
                                     std::span<const Elasticity> elasticities,
                                     std::span<const Contact> contacts, Storage storage);

/// @brief The velocity of @p body's material point at @p point (zero for a static body).
/// @param body any body
/// @param point world position
/// @return the point's velocity
[[nodiscard]] inline Eigen::Vector2d point_velocity(const Body& body, const Eigen::Vector2d& point);

/// @brief A body's motion at one instant, kept to measure many of its points: whether it turns,
/// its angular velocity, the velocity of its origin and where that is (a point mass's velocity
/// alone; all zero for a static body).
struct Motion {
  bool turns = false;                                  ///< a rigid body's
  double omega = 0.0;                                  ///< L/I
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< p/m
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();    ///< a rigid body's position
};

/// @brief The motion of @p body now.
/// @param body any body
/// @return its motion
[[nodiscard]] inline Motion motion(const Body& body);

/// @brief The velocity of the material point at @p point of a body moving so: the same number,
/// bit for bit, as point_velocity() of the body.
/// @param motion the body's motion
/// @param point world position
/// @return the point's velocity
[[nodiscard]] inline Eigen::Vector2d point_velocity(const Motion& motion,
                                                    const Eigen::Vector2d& point);

/// @brief Each contact's approach speed: the sum of both bodies' normal velocities, each cast on
/// its own outward normal. Positive: closing; zero: equal normal velocities.
/// @param bodies the bodies
/// @param contacts the contacts
/// @return one approach speed per contact
[[nodiscard]] Eigen::VectorXd approach(std::span<const Body> bodies,
                                       std::span<const Contact> contacts);

/// @brief The bodies after the impulses: at contact v the bumper receives
/// @f$ -\vec{n_v}\,F_v dt @f$ and the wedge @f$ +\vec{n_v}\,F_v dt @f$, at the contact point.
/// @param bodies the bodies before
/// @param contacts the contacts
/// @param Fdt one impulse magnitude per contact (a size mismatch throws InvalidInput)
/// @return the bodies after
[[nodiscard]] std::vector<Body> apply_impulses(std::span<const Body> bodies,
                                               std::span<const Contact> contacts,
                                               const Eigen::Ref<const Eigen::VectorXd>& Fdt);

/// @brief One body's share of one contact alone, the (a, b) of the 1×1 system of that contact:
/// the single-contact form of its block, i.e. section 1's (1.3), section 2's cast or section 3's
/// (3.6)/(3.10) (material_2d::contribution, rigid_2d::contribution without their checks). A static
/// body's share is zero. Allocates nothing.
/// @param body the body (checked: a Configuration's)
/// @param touch the contact, with the body's own outward normal
/// @param elasticity the body's elasticity
/// @return (a, b)
[[nodiscard]] inline ScalarContribution share(const Body& body, const Touch& touch,
                                              Elasticity elasticity);

/// @brief The impulse @f$ -\vec{n}\,F\,dt @f$ on @p body at the touch's point, its own normal
/// @f$ \vec{n} @f$ (material_2d::apply_impulse or rigid_2d::apply_impulse; nothing for a static
/// body).
/// @param body the body, changed in place
/// @param touch the contact, with the body's own outward normal
/// @param Fdt the impulse magnitude
inline void apply_impulse(Body& body, const Touch& touch, double Fdt);

/// @brief Kinetic energy of one body (0 for a static body).
/// @param body any body
/// @return its kinetic energy
[[nodiscard]] double kinetic_energy(const Body& body);

/// @brief Total kinetic energy.
/// @param bodies the bodies
/// @return the sum of their kinetic energies
[[nodiscard]] double kinetic_energy(std::span<const Body> bodies);

/// @brief Total linear momentum of the movable bodies.
/// @param bodies the bodies
/// @return the sum of their momenta
[[nodiscard]] Eigen::Vector2d momentum(std::span<const Body> bodies);

/// @brief The solved system and the bodies after.
struct Resolution {
  Solution solution;        ///< impulses, A, B and diagnostics
  std::vector<Body> after;  ///< the bodies after the impulses (the bodies before if not success)
};

/// @brief Assembles, solves and applies.
/// @param bodies the bodies
/// @param elasticities one per body
/// @param contacts the contacts
/// @param options solver policies
/// @return the solution and the bodies after
[[nodiscard]] Resolution resolve(std::span<const Body> bodies,
                                 std::span<const Elasticity> elasticities,
                                 std::span<const Contact> contacts,
                                 const SolverOptions& options = {});

/// @brief Assembles, solves and applies, every body with the same elasticity.
/// @param bodies the bodies
/// @param elasticity everyone's elasticity
/// @param contacts the contacts
/// @param options solver policies
/// @return the solution and the bodies after
[[nodiscard]] Resolution resolve(std::span<const Body> bodies, Elasticity elasticity,
                                 std::span<const Contact> contacts,
                                 const SolverOptions& options = {});

/// @brief Bodies, their elasticities and the contacts between them, checked once when made: the
/// collision of sections 4 and 5 before it is resolved.
///
/// Everything that takes a Configuration trusts it: assembling its system, its approach speeds,
/// the bodies after a set of impulses and the methods of impulse::methods check nothing again.
/// The free functions above (assemble(), approach(), apply_impulses(), resolve()) check their
/// arguments and then do the same work as these members.
class Configuration {
 public:
  /// @brief Checks and keeps: validate() on the bodies and contacts, one elasticity per body
  /// (else InvalidInput).
  /// @param bodies the bodies
  /// @param elasticities one per body
  /// @param contacts the contacts between them
  Configuration(std::vector<Body> bodies, std::vector<Elasticity> elasticities,
                std::vector<Contact> contacts);

  /// @brief The tag of the constructor that trusts its caller.
  struct Trusted {
    /// @brief Only made on purpose.
    explicit Trusted() = default;
  };

  /// @brief Keeps bodies and contacts that the caller has already checked for everything
  /// validate() checks, and one elasticity per body (a scene's World checks more, with the
  /// scene format's places). Nothing is checked again.
  /// @param trusted the tag
  /// @param bodies the bodies
  /// @param elasticities one per body
  /// @param contacts the contacts between them
  Configuration(Trusted trusted, std::vector<Body> bodies, std::vector<Elasticity> elasticities,
                std::vector<Contact> contacts);

  /// @brief The bodies before the collision.
  /// @return one per body
  [[nodiscard]] std::span<const Body> bodies() const { return bodies_; }
  /// @brief Each body's elasticity.
  /// @return one per body
  [[nodiscard]] std::span<const Elasticity> elasticities() const { return elasticities_; }
  /// @brief The contacts.
  /// @return one per contact
  [[nodiscard]] std::span<const Contact> contacts() const { return contacts_; }
  /// @brief The contacts that body @p body takes part in, each with its own outward normal, in
  /// contact order (as touches() gives them, computed once).
  /// @param body index of the body
  /// @return its touches
  [[nodiscard]] std::span<const Touch> touches(std::size_t body) const { return touches_[body]; }

  /// @brief The ⊕ of every body's block (section 4.5), as the free assemble() without its checks.
  /// @param storage dense, sparse, or automatic (sparse above sparse_threshold contacts)
  /// @return the system A·Fdt = B
  [[nodiscard]] ContactSystem assemble(Storage storage = Storage::automatic) const;

  /// @brief Each contact's approach speed for a state of these bodies: the sum of both bodies'
  /// normal velocities, each cast on its own outward normal (> 0: closing).
  /// @param state these bodies, before or after impulses (same order, same kinds)
  /// @return one speed per contact
  [[nodiscard]] Eigen::VectorXd approach(std::span<const Body> state) const;

  /// @brief Contact @p v's approach speed for a state of these bodies.
  /// @param state these bodies, before or after impulses
  /// @param v the contact
  /// @return its approach speed
  [[nodiscard]] inline double approach(std::span<const Body> state, Eigen::Index v) const;

  /// @brief Contact @p v's approach speed for the motions of these bodies (the same number as
  /// for the bodies moving so).
  /// @param motions one per body
  /// @param v the contact
  /// @return its approach speed
  [[nodiscard]] inline double approach(std::span<const Motion> motions, Eigen::Index v) const;

  /// @brief The bodies after the impulses @p Fdt, one per contact (the bumper receives
  /// @f$ -\vec{n_v}\,F_v dt @f$, the wedge the opposite).
  /// @param Fdt one magnitude per contact (a size mismatch throws InvalidInput)
  /// @return the bodies after
  [[nodiscard]] std::vector<Body> after(const Eigen::Ref<const Eigen::VectorXd>& Fdt) const;

  /// @brief Contact @p v's impulse alone on a state of these bodies: both its bodies changed.
  /// @param state these bodies, changed in place
  /// @param v the contact
  /// @param Fdt its impulse magnitude
  inline void apply(std::vector<Body>& state, Eigen::Index v, double Fdt) const;

 private:
  std::vector<Body> bodies_;
  std::vector<Elasticity> elasticities_;
  std::vector<Contact> contacts_;
  std::vector<std::vector<Touch>> touches_;
};

// Inline below: serial collisions measure and change single contacts some ten times per
// collision, a hundred thousand collisions on a stack of 50 boxes.

inline Eigen::Vector2d point_velocity(const Body& body, const Eigen::Vector2d& point) {
  if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    return rigid_2d::point_velocity(*rigid, point);
  }
  if (const auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    return material_2d::velocity(*mass);
  }
  return Eigen::Vector2d::Zero();  // a static body
}

inline ScalarContribution share(const Body& body, const Touch& touch, Elasticity elasticity) {
  if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    return rigid_2d::detail::share(*rigid, touch.point, touch.normal, elasticity);
  }
  if (const auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    return material_2d::detail::share(*mass, touch.normal, elasticity);
  }
  return ScalarContribution{};  // a static body
}

inline void apply_impulse(Body& body, const Touch& touch, double Fdt) {
  if (auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    *rigid = rigid_2d::apply_impulse(*rigid, touch.point, touch.normal, Fdt);
  } else if (auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    *mass = material_2d::apply_impulse(*mass, touch.normal, Fdt);
  }
}

inline Motion motion(const Body& body) {
  if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    return {true, rigid_2d::angular_velocity(*rigid), rigid_2d::velocity(*rigid), rigid->position};
  }
  if (const auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    return {false, 0.0, material_2d::velocity(*mass), Eigen::Vector2d::Zero()};
  }
  return {};  // a static body
}

inline Eigen::Vector2d point_velocity(const Motion& motion, const Eigen::Vector2d& point) {
  return motion.turns
             ? rigid_2d::point_velocity(motion.omega, motion.velocity, point - motion.origin)
             : motion.velocity;
}

namespace detail {
// Contact c's approach speed in a state of its bodies (the bodies, or their motions).
template <class State>
double approach_at(const State& state, const Contact& c) {
  return point_velocity(state[c.bumper], c.point).dot(c.normal) +
         point_velocity(state[c.wedge], c.point).dot(-c.normal);
}

// Contact c's impulse on a state of its bodies: -n Fdt on the bumper, +n Fdt on the wedge.
inline void apply_at(std::vector<Body>& state, const Contact& c, Eigen::Index v, double Fdt) {
  apply_impulse(state[c.bumper], Touch{v, c.normal, c.point}, Fdt);
  apply_impulse(state[c.wedge], Touch{v, -c.normal, c.point}, Fdt);
}
}  // namespace detail

inline double Configuration::approach(std::span<const Body> state, Eigen::Index v) const {
  return detail::approach_at(state, contacts_[static_cast<std::size_t>(v)]);
}

inline double Configuration::approach(std::span<const Motion> motions, Eigen::Index v) const {
  return detail::approach_at(motions, contacts_[static_cast<std::size_t>(v)]);
}

inline void Configuration::apply(std::vector<Body>& state, Eigen::Index v, double Fdt) const {
  detail::apply_at(state, contacts_[static_cast<std::size_t>(v)], v, Fdt);
}

}  // namespace impulse::multipoint
