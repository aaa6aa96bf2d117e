// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Scenes: named bodies and contacts, checked once into a World, resolved by a method into
/// a Result.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/names.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/friction/contact.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/methods.hpp"
#include "impulse/methods/outcome.hpp"
#include "impulse/methods/resolve.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"

/// @brief A scene as a student writes it (see the scene format), and everything a report of its
/// collision shows.
///
/// The flow is the paper's, once: a Scene is checked once into a World (every rule of the scene
/// format, with its place: `bodies[1].mass: must be positive and finite, got -1`), whose bodies
/// and contacts the lower layers trust; resolve() assembles each body's contribution, ⊕ them into
/// A·Fdt = B, solves it once, lets the method resolve the contacts (methods::resolve) and
/// gathers the Result: impulses, each body before and after, energies, momenta and approach
/// speeds, the system and the method's own words. The reports (scene/report.hpp, and the JSON
/// of scene/json.hpp) are built from the Result alone.
///
/// A one-dimensional scene lies on the x axis: its numbers are the x coordinates of vectors
/// whose y coordinate is 0, and its normals are ±x.
namespace impulse::scene {

/// @brief The kinds of body of the scene format.
enum class BodyKind {
  material,     ///< a point mass (sections 1, 2, 4)
  rigid,        ///< mass, moment of inertia and rotation, 2D only (sections 3, 5)
  static_body,  ///< the format's "static": immovable, contributes nothing to A and B
};

}  // namespace impulse::scene

namespace impulse {
/// @brief The scene format's names of the kinds of body.
template <>
struct EnumNames<scene::BodyKind> {
  /// "material", "rigid", "static"
  static constexpr std::array<Named<scene::BodyKind>, 3> table{
      {{scene::BodyKind::material, "material"},
       {scene::BodyKind::rigid, "rigid"},
       {scene::BodyKind::static_body, "static"}}};
};
}  // namespace impulse

namespace impulse::scene {

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
  /// Outward from the bumper: any finite non-zero vector (a number in 1D), made unit when the
  /// scene is checked (a vector not of unit length within 1e-9 is divided by its length, and
  /// the report notes it). A file's `"normal_angle"` in degrees arrives here as
  /// impulse::UnitNormal::from_degrees() of it.
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();
  std::optional<Eigen::Vector2d> point;  ///< world position; needed when a body is rigid
  /// Beyond the paper: Coulomb's coefficient μ at this contact (finite, ≥ 0); without it, the
  /// scene's `friction`, else 0.
  std::optional<double> friction = std::nullopt;
};

/// @brief A whole scene: the scene format's top level.
struct Scene {
  int dimension = 2;                 ///< 1 (section 1) or 2 (sections 2-5)
  std::optional<double> elasticity;  ///< the default elasticity of every body
  std::vector<Body> bodies;          ///< at least one
  std::vector<Contact> contacts;     ///< at least one
  SolverOptions solver;              ///< the policies for dependent and inconsistent systems
  /// How the impulses are found (the scene format's `solver.method`); the paper's
  /// simultaneous system by default.
  methods::Method method = methods::Method::simultaneous;
  /// Method serial: the bound on collisions (`solver.max_collisions`) and the approach
  /// tolerance.
  methods::SerialOptions serial;
  /// Method complementarity: the algorithm and its tolerance. Its `dependent` policy is ignored:
  /// the scene's `solver.dependent` applies.
  methods::ComplementarityOptions complementarity;
  /// Beyond the paper: Coulomb's coefficient μ of every contact without its own (the format's
  /// top-level `friction`, finite, ≥ 0); without it, 0.
  std::optional<double> friction = std::nullopt;
  /// How the elasticity is applied once the bodies stop approaching (`solver.restitution`):
  /// Newton's (the paper's) by default, Poisson's or the energetic law.
  friction::RestitutionLaw restitution = friction::RestitutionLaw::newton;

  /// @brief The elasticity @p body collides at: its own, else the scene's (a World refuses a
  /// body with neither; 1 is returned for it here).
  /// @param body one of the scene's bodies
  /// @return the elasticity
  [[nodiscard]] double elasticity_of(const Body& body) const {
    return body.elasticity.value_or(elasticity.value_or(1.0));
  }
};

/// @brief A scene checked once: every rule of the scene format, then its bodies and contacts as
/// the lower layers take them (a multipoint::Configuration that nothing checks again).
///
/// Refused, with InvalidInput naming the place: a dimension other than 1 or 2, no bodies or no
/// contacts, empty or repeated names, a rigid body in 1D, a mass or inertia that is not positive
/// and finite (or whose inverse overflows), a non-finite coordinate, a motion whose momentum or
/// velocity overflows, a negative elasticity, a body without an elasticity when the scene has
/// no default, a contact index out of range, a body in contact with itself, a contact between
/// two static bodies, a zero or non-finite normal, a rigid body's contact
/// without a point, a bound on serial collisions outside 0 (the default) to
/// methods::most_collisions, and more contacts than impulse::dense_limit with policies that only
/// the dense method serves. With friction or a restitution law other than Newton's
/// (methods::has_contact_law()): a friction that is negative or not finite, and, at each contact,
/// bodies that collide at different elasticities, an elasticity below 1, or above 2 for the
/// energetic law (the exact rule takes one elasticity per contact, from compression on).
class World {
 public:
  /// @brief Checks @p scene and keeps it with its model.
  /// @param scene the scene (InvalidInput as above)
  explicit World(Scene scene);

  /// @brief The scene as it was given.
  /// @return the scene
  [[nodiscard]] const Scene& scene() const { return scene_; }
  /// @brief The scene's bodies (1D on the x axis), elasticities and contacts with unit normals.
  /// @return the checked configuration
  [[nodiscard]] const multipoint::Configuration& configuration() const { return configuration_; }
  /// @brief What the check changed, in words: normals not of unit length made unit.
  /// @return one sentence each, naming the place
  [[nodiscard]] std::span<const std::string> notes() const { return notes_; }
  /// @brief How the reports name contact @p v: "contact 2 (a–b)", bumper then wedge.
  /// @param v the contact
  /// @return its name
  [[nodiscard]] std::string contact_name(Eigen::Index v) const;
  /// @brief The options of the methods: the scene's solver, complementarity and serial options,
  /// and contact_name() for their sentences (which refers to this world: the options are for use
  /// while it lives).
  /// @return the options
  [[nodiscard]] methods::Options options() const;
  /// @brief The same world with every body colliding at elasticity @p value: the scene's
  /// default becomes @p value and the bodies' own elasticities are dropped (as `sweep` does);
  /// only the elasticity is checked.
  /// @param value the elasticity (InvalidInput "elasticity: must be finite and at least 0, …")
  /// @return the changed world
  [[nodiscard]] World with_elasticity(double value) const;

 private:
  World(Scene scene, std::vector<std::string> notes, multipoint::Configuration configuration);
  Scene scene_;
  std::vector<std::string> notes_;
  multipoint::Configuration configuration_;
};

/// @brief The first rule World checks, on its own for a reader that must look bodies up by name
/// before the rest is read: a name that is empty or already taken is refused with its place,
/// `bodies[1].name: "a" is already the name of bodies[0]`.
/// @param bodies the scene's bodies
void validate_names(std::span<const Body> bodies);

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
  /// The elasticity it collided at: its own (`own_elasticity`, the scene's
  /// `bodies[k].elasticity`), else the scene's default (`elasticity`); 1 for a static body.
  double elasticity = 1.0;
  bool own_elasticity = false;  ///< whether `elasticity` is the body's own
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

/// @brief Everything a report of a resolved scene shows.
///
/// `status` is SolveStatus::non_finite when the system or any reported quantity is not finite
/// (numbers beyond the range of doubles); the other fields are then not meaningful.
struct Result {
  int dimension = 2;                          ///< the scene's dimension
  SolveStatus status = SolveStatus::success;  ///< whether the numbers below are meaningful
  std::vector<ImpulseReport> impulses;        ///< one per contact: the method's impulses
  std::vector<BodyReport> bodies;             ///< one per body
  double energy_before = 0.0;                 ///< total kinetic energy before
  double energy_after = 0.0;                  ///< after
  double energy_change = 0.0;                 ///< after - before
  Eigen::Vector2d momentum_before = Eigen::Vector2d::Zero();  ///< of the movable bodies
  Eigen::Vector2d momentum_after = Eigen::Vector2d::Zero();   ///< of the movable bodies
  std::vector<ContactReport> contacts;                        ///< one per contact
  /// The paper's system of the scene, solved once: A, B, rank, dependent, consistent, condition
  /// estimate, and the paper's own impulses and residual (whatever the method).
  Solution system;
  methods::Method method = methods::Method::simultaneous;  ///< the method that found the impulses
  /// The method's answer: its impulses (outcome.Fdt), the bodies after as it produced them, the
  /// residual @f$ \|A\,F\,dt - B\| @f$ of its impulses, whether it finished, and its words.
  methods::Outcome outcome;
  std::vector<std::string> notes;  ///< what checking the scene changed (World::notes)
};

/// @brief The pipeline, once: assembles the world's system, solves it, lets @p method resolve
/// the contacts (methods::resolve) and reports.
/// @param world the checked scene
/// @param method the method (the scene's own: resolve(const World&))
/// @return the report
[[nodiscard]] Result resolve(const World& world, methods::Method method);

/// @brief resolve() in slices, for a caller that must return within a frame: the paper's system
/// assembled and solved (and a method that cannot take the scene refused) at once, the serial
/// method's collisions a bounded number at a time (methods::SerialMethod), any other method when
/// finished. Advanced in one slice or in many, finish() gives exactly resolve()'s report.
///
/// The world must outlive this object.
class Resolving {
 public:
  /// @brief Starts resolving @p world by @p method (InvalidInput as resolve()).
  /// @param world the checked scene
  /// @param method the method
  Resolving(const World& world, methods::Method method);
  /// @brief Frees its state.
  ~Resolving();
  /// @brief Takes over another resolution in progress (which is left without state).
  /// @param other the one taken over
  Resolving(Resolving&& other) noexcept;
  /// @brief Takes over another resolution in progress (which is left without state).
  /// @param other the one taken over
  /// @return this one
  Resolving& operator=(Resolving&& other) noexcept;

  /// @brief Runs at most @p collisions more serial collisions.
  /// @param collisions how many at most (at least 1)
  /// @return whether the method has ended (always, for a method other than serial)
  bool advance(std::int64_t collisions);
  /// @brief The serial collisions so far (0 for another method).
  /// @return their number
  [[nodiscard]] std::int64_t collisions() const;
  /// @brief The bound on serial collisions (0 for another method).
  /// @return the bound
  [[nodiscard]] std::int64_t bound() const;
  /// @brief The report, once advance() has returned true.
  /// @return resolve()'s report
  [[nodiscard]] Result finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// @brief resolve() with the scene's own method (its `solver.method`).
/// @param world the checked scene
/// @return the report
[[nodiscard]] Result resolve(const World& world);

/// @brief Several methods on one world, the system assembled and solved once for all of them
/// (what `solve --compare` shows). A method that cannot take the scene's contact law
/// (unsupported()) is refused before any method runs: InvalidInput `"contacts: the method …"`.
/// @param world the checked scene
/// @param methods the methods, in the order of the results
/// @return one report per method
[[nodiscard]] std::vector<Result> resolve(const World& world,
                                          std::span<const methods::Method> methods);

/// @brief Why @p method cannot resolve the world with its contact law (friction at several
/// contacts, say), or "" when it can: the method's row of the table of methods answers.
/// @param world the checked scene
/// @param method the method
/// @return a sentence, or empty
[[nodiscard]] std::string unsupported(const World& world, methods::Method method);

/// @brief Checks and resolves: resolve(World(scene)).
/// @param scene the scene (InvalidInput as World)
/// @return the report
[[nodiscard]] Result solve(const Scene& scene);

}  // namespace impulse::scene
