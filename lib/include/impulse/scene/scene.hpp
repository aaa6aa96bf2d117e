// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Scenes: named bodies and contacts, checked, solved and reported.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/methods.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"

/// @brief A scene as a student writes it (see the scene format), and everything a report of its
/// collision shows.
///
/// The flow is the library's: the scene's bodies and contacts become multipoint bodies and
/// contacts, multipoint::resolve assembles and solves A·Fdt = B and applies the impulses, and the
/// result gathers the section modules' energies, momenta and approach speeds before and after.
/// A one-dimensional scene lies on the x axis: its numbers are the x coordinates of vectors
/// whose y coordinate is 0, and its normals are ±x.
///
/// Checking a scene (validate) throws InvalidInput with the place in the scene format first,
/// e.g. `bodies[1].mass: must be positive and finite, got -1`; a file reader puts the file name
/// in front.
namespace impulse::scene {

/// @brief The kinds of body of the scene format.
enum class BodyKind {
  material,     ///< a point mass (sections 1, 2, 4)
  rigid,        ///< mass, moment of inertia and rotation, 2D only (sections 3, 5)
  static_body,  ///< the format's "static": immovable, contributes nothing to A and B
};

/// @brief The scene format's name of a kind ("material", "rigid", "static").
/// @param kind the kind
/// @return its name
[[nodiscard]] std::string_view to_string(BodyKind kind);

/// @brief Which of two alternative keys gave a body's motion (so that messages name that key).
enum class Given {
  velocity,  ///< `velocity` (or `angular_velocity`)
  momentum,  ///< `momentum` (or `angular_momentum`)
};

/// @brief A body of a scene. Fields that do not apply to its kind are ignored.
struct Body {
  std::string name;                                    ///< unique, not empty
  BodyKind kind = BodyKind::material;                  ///< material, rigid or static
  double mass = 1.0;                                   ///< m > 0 (material, rigid)
  double inertia = 1.0;                                ///< I > 0 about the origin (rigid)
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< the origin, world coordinates (rigid)
  Given linear_given = Given::velocity;                ///< whether `linear` is v or p
  Eigen::Vector2d linear = Eigen::Vector2d::Zero();    ///< the velocity or momentum given
  Given angular_given = Given::velocity;               ///< whether `angular` is ω or L (rigid)
  double angular = 0.0;                                ///< angular velocity or momentum (rigid)
  std::optional<double> elasticity;                    ///< own elasticity; else the scene's
};

/// @brief A contact point between two bodies of a scene.
struct Contact {
  std::size_t bumper = 0;  ///< index of the body whose outward normal is `normal`
  std::size_t wedge = 0;   ///< index of the other body (outward normal -`normal`)
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< unit, outward from the bumper
  std::optional<Eigen::Vector2d> point;  ///< world position; needed when a body is rigid
};

/// @brief A whole scene: the scene format's top level.
struct Scene {
  int dimension = 2;                 ///< 1 (section 1) or 2 (sections 2-5)
  std::optional<double> elasticity;  ///< the default elasticity of every body
  std::vector<Body> bodies;          ///< at least one
  std::vector<Contact> contacts;     ///< at least one
  SolverOptions solver;              ///< the policies for dependent and inconsistent systems
  // Added for the other methods (issue 9), after the fields above so that their order stays.
  /// How the impulses are found (the scene format's `solver.method`); the paper's
  /// simultaneous system by default.
  methods::Method method = methods::Method::simultaneous;
  /// Method serial: the bound on collisions (`solver.max_collisions`) and the approach
  /// tolerance.
  methods::SerialOptions serial;
  /// Method complementarity: the algorithm and its tolerance. Its `dependent` policy is ignored:
  /// the scene's `solver.dependent` applies.
  methods::ComplementarityOptions complementarity;
};

/// @brief Throws InvalidInput for anything the scene format refuses: a dimension other than 1
/// or 2, no bodies or no contacts, empty or repeated names, a rigid body in 1D, a mass or
/// inertia that is not positive and finite (or whose inverse overflows), a non-finite
/// coordinate, a motion whose momentum or velocity overflows, a negative elasticity, a body
/// without an elasticity when the scene has no default, a contact index out of range, a body in
/// contact with itself, a contact between two static bodies, a normal that is not a unit vector
/// (±1 in 1D), a rigid body's contact without a point, a negative bound on serial collisions.
/// @param scene the scene
void validate(const Scene& scene);

/// @brief The elasticity each body collides with: its own, else the scene's default (static
/// bodies, which contribute nothing, get 1).
/// @param scene a valid scene
/// @return one elasticity per body
[[nodiscard]] std::vector<Elasticity> elasticities(const Scene& scene);

/// @brief The scene's bodies as the multipoint module takes them (1D embedded on the x axis).
/// @param scene a valid scene
/// @return one body per scene body, same order
[[nodiscard]] std::vector<multipoint::Body> model_bodies(const Scene& scene);

/// @brief The scene's contacts as the multipoint module takes them (a missing point is the
/// origin, which only rigid bodies would use and they always have one).
/// @param scene a valid scene
/// @return one contact per scene contact, same order
[[nodiscard]] std::vector<multipoint::Contact> model_contacts(const Scene& scene);

/// @brief The scene with every body colliding at elasticity @p value: the default becomes
/// @p value and the bodies' own elasticities are dropped (what `sweep` does).
/// @param scene the scene
/// @param value the elasticity (checked by validate when the scene is solved)
/// @return the changed copy
[[nodiscard]] Scene with_elasticity(Scene scene, double value);

/// @brief A body's motion at one instant.
struct Motion {
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< @f$ \vec{v} @f$ (of the origin)
  Eigen::Vector2d momentum = Eigen::Vector2d::Zero();  ///< @f$ \vec{p} @f$
  double angular_velocity = 0.0;                       ///< ω (rigid; 0 otherwise)
  double angular_momentum = 0.0;                       ///< L about the origin (rigid; 0 otherwise)
};

/// @brief One body before and after the collision.
struct BodyReport {
  std::string name;                    ///< the body's name
  BodyKind kind = BodyKind::material;  ///< its kind
  Motion before;                       ///< motion before
  Motion after;                        ///< motion after (zero for a static body)
  double energy_before = 0.0;          ///< its kinetic energy before
  double energy_after = 0.0;           ///< its kinetic energy after
};

/// @brief The impulse at one contact.
struct ImpulseReport {
  std::size_t contact = 0;                              ///< contact index v
  std::string bumper;                                   ///< the bumper's name
  std::string wedge;                                    ///< the wedge's name
  double magnitude = 0.0;                               ///< @f$ F_v\,dt @f$
  Eigen::Vector2d on_bumper = Eigen::Vector2d::Zero();  ///< @f$ -\vec{n}\,F_v\,dt @f$
};

/// @brief One contact's approach speed (sum of both bodies' normal velocities; > 0 closing).
struct ContactReport {
  std::size_t contact = 0;       ///< contact index v
  double approach_before = 0.0;  ///< before the impulses
  double approach_after = 0.0;   ///< after them
};

/// @brief Everything a report of a solved scene shows.
///
/// `status` is SolveStatus::non_finite when the system or any reported quantity is not finite
/// (numbers beyond the range of doubles); the other fields are then not meaningful.
struct Result {
  int dimension = 2;                          ///< the scene's dimension
  SolveStatus status = SolveStatus::success;  ///< whether the numbers below are meaningful
  std::vector<ImpulseReport> impulses;        ///< one per contact
  std::vector<BodyReport> bodies;             ///< one per body
  double energy_before = 0.0;                 ///< total kinetic energy before
  double energy_after = 0.0;                  ///< after
  double energy_change = 0.0;                 ///< after - before
  Eigen::Vector2d momentum_before = Eigen::Vector2d::Zero();  ///< of the movable bodies
  Eigen::Vector2d momentum_after = Eigen::Vector2d::Zero();   ///< of the movable bodies
  std::vector<ContactReport> contacts;                        ///< one per contact
  /// A, B, Fdt, rank, residual, policies. Whatever the method, A and B are the paper's system of
  /// the scene and rank, dependent, consistent and condition_estimate describe it; Fdt is the
  /// method's impulses and residual is @f$ \|A\,F\,dt - B\| @f$ for them.
  Solution system;
  // Added for the other methods (issue 9), after the fields above so that their order stays.
  methods::Method method = methods::Method::simultaneous;  ///< the method that found Fdt
  /// Method complementarity: the solution with its slack and diagnostics (its Fdt is
  /// system.Fdt). Empty otherwise.
  methods::ComplementaritySolution complementarity;
  /// Method serial: the order of the collisions, the passes and whether they finished. A
  /// result whose serial status is not SerialStatus::finished reports the state at the bound.
  methods::SerialDiagnostics serial;
};

/// @brief Validates, solves and reports: with multipoint::resolve for the paper's method, else
/// with methods::solve_complementarity or methods::resolve_serial (the system A·Fdt = B is then
/// solved as well, for its diagnostics).
/// @param scene the scene (validated: InvalidInput as in validate)
/// @return the report
[[nodiscard]] Result solve(const Scene& scene);

/// @brief Whether the method finished: false when serial collisions stopped at their bound or
/// a complementarity problem has no solution (which no valid scene gives).
/// @param result a solved scene
/// @return true when the result is the method's answer (possibly approximate: see
///         methods::LcpStatus::iteration_limit)
[[nodiscard]] bool finished(const Result& result);

}  // namespace impulse::scene
