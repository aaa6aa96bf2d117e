// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/scene/scene.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <variant>

#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/core/text.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"

namespace impulse::scene {

namespace {

using Eigen::Vector2d;

[[noreturn]] void refuse(const std::string& path, std::string_view message) {
  std::string text(path);
  text.append(": ").append(message);
  throw InvalidInput(text);
}

// A vector as the scene file writes it: a plain number in 1D, [x, y] in 2D.
std::string show(const Vector2d& v, int dimension) {
  if (dimension == 1 && v.y() == 0.0) {
    return format_number(v.x());
  }
  std::string text("[");
  text.append(format_number(v.x())).append(", ").append(format_number(v.y())).append("]");
  return text;
}

std::string_view key_of(Given given, bool angular) {
  if (angular) {
    return given == Given::velocity ? "angular_velocity" : "angular_momentum";
  }
  return given == Given::velocity ? "velocity" : "momentum";
}

// The largest value whose inverse overflows: 1 / DBL_MAX rounds to 2^-1024 (a subnormal), whose
// inverse 2^1024 is beyond DBL_MAX; the inverse of the next double up is below DBL_MAX.
constexpr double largest_without_inverse = 1.0 / std::numeric_limits<double>::max();

// Masses and inertias: positive, finite, and with an inverse that is a double too (A holds 1/m).
// The inverse is not computed to be tested: its overflow would raise a floating-point exception.
void require_positive_inverse(const std::string& path, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    refuse(path, "must be positive and finite, got " + format_number(value));
  }
  if (value <= largest_without_inverse) {
    refuse(path, "is too small: its inverse overflows a double, got " + format_number(value));
  }
}

void require_finite_vector(const std::string& path, const Vector2d& v, int dimension) {
  if (!all_finite_in(v)) {
    refuse(path, "must be finite, got " + show(v, dimension));
  }
  if (dimension == 1 && v.y() != 0.0) {
    refuse(path, "must lie on the x axis in a 1D scene (y = 0), got " + show(v, 2));
  }
}

void require_elasticity(const std::string& path, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    refuse(path, "must be finite and at least 0, got " + format_number(value));
  }
}

void require_friction(const std::string& path, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    refuse(path, "must be finite and at least 0, got " + format_number(value));
  }
}

// The motion as given, and the other one of the pair (m v or p / m), must both be doubles.
void require_motion(const std::string& place, const Body& body, int dimension) {
  const std::string path = member_place(place, key_of(body.linear_given, false));
  require_finite_vector(path, body.linear, dimension);
  // Computed to find out whether it overflows: exceptions held (see HeldFloatingPointExceptions).
  const bool other_finite = [&] {
    const impulse::detail::HeldFloatingPointExceptions held;
    return all_finite_in(body.linear_given == Given::velocity ? Vector2d(body.mass * body.linear)
                                                              : Vector2d(body.linear / body.mass));
  }();
  if (!other_finite) {
    refuse(path, std::string(body.linear_given == Given::velocity ? "mass times velocity"
                                                                  : "momentum over mass") +
                     " overflows a double: mass " + format_number(body.mass) + ", " +
                     std::string(key_of(body.linear_given, false)) + " " +
                     show(body.linear, dimension));
  }
  if (body.kind != BodyKind::rigid) {
    return;
  }
  const std::string angular_path = member_place(place, key_of(body.angular_given, true));
  if (!std::isfinite(body.angular)) {
    refuse(angular_path, "must be finite, got " + format_number(body.angular));
  }
  const bool angular_other_finite = [&] {
    const impulse::detail::HeldFloatingPointExceptions held;
    return std::isfinite(body.angular_given == Given::velocity ? body.inertia * body.angular
                                                               : body.angular / body.inertia);
  }();
  if (!angular_other_finite) {
    refuse(angular_path, "overflows a double once combined with the inertia " +
                             format_number(body.inertia) + ", got " + format_number(body.angular));
  }
}

void validate_body(const Scene& scene, std::size_t i) {
  const Body& body = scene.bodies[i];
  const std::string place = element_place("bodies", i);
  if (body.kind == BodyKind::static_body) {
    return;  // immovable: nothing else of it is used
  }
  if (body.kind == BodyKind::rigid && scene.dimension != 2) {
    refuse(member_place(place, "kind"),
           "a rigid body needs dimension 2, this scene has dimension " +
               std::to_string(scene.dimension));
  }
  require_positive_inverse(member_place(place, "mass"), body.mass);
  if (body.kind == BodyKind::rigid) {
    require_positive_inverse(member_place(place, "inertia"), body.inertia);
    require_finite_vector(member_place(place, "position"), body.position, scene.dimension);
  }
  require_motion(place, body, scene.dimension);
  if (body.elasticity) {
    require_elasticity(member_place(place, "elasticity"), *body.elasticity);
  } else if (!scene.elasticity) {
    refuse(place,
           "needs an elasticity: give it \"elasticity\" or give the scene a default "
           "\"elasticity\"");
  }
}

void validate_contact(const Scene& scene, std::size_t v) {
  const Contact& c = scene.contacts[v];
  const std::string place = element_place("contacts", v);
  for (const auto& [role, index] : {std::pair{"bumper", c.bumper}, std::pair{"wedge", c.wedge}}) {
    if (index >= scene.bodies.size()) {
      refuse(member_place(place, role), "must name one of the " +
                                            std::to_string(scene.bodies.size()) +
                                            " bodies, got index " + std::to_string(index));
    }
  }
  const Body& bumper = scene.bodies[c.bumper];
  const Body& wedge = scene.bodies[c.wedge];
  if (c.bumper == c.wedge) {
    refuse(place, "bumper and wedge are the same body " + in_quotes(bumper.name) +
                      ": a body cannot be in contact with itself");
  }
  if (bumper.kind == BodyKind::static_body && wedge.kind == BodyKind::static_body) {
    refuse(place, "joins two static bodies, " + in_quotes(bumper.name) + " and " +
                      in_quotes(wedge.name) + ": at least one of them must be able to move");
  }
  if (scene.dimension == 1) {
    if (!(c.normal.y() == 0.0 && std::isfinite(c.normal.x()) && c.normal.x() != 0.0)) {
      refuse(member_place(place, "normal"),
             "must be a non-zero number (+1 or -1: its sign is the direction), got " +
                 show(c.normal, 1));
    }
  } else {
    const bool zero = c.normal.x() == 0.0 && c.normal.y() == 0.0;
    if (!all_finite_in(c.normal) || zero) {
      refuse(member_place(place, "normal"),
             "must be a finite non-zero vector, got " + show(c.normal, 2));
    }
  }
  if (c.friction) {
    require_friction(member_place(place, "friction"), *c.friction);
  }
  if (c.point) {
    if (!all_finite_in(*c.point)) {
      refuse(member_place(place, "point"),
             "must be finite, got " + show(*c.point, scene.dimension));
    }
  } else {
    for (const Body* body : {&bumper, &wedge}) {
      if (body->kind == BodyKind::rigid) {
        refuse(place,
               "missing \"point\": it is needed because " + in_quotes(body->name) + " is rigid");
      }
    }
  }
}

// Where a body's elasticity comes from: its own key, else the scene's default.
std::string elasticity_place(const Scene& scene, std::size_t body) {
  return scene.bodies[body].elasticity ? member_place(element_place("bodies", body), "elasticity")
                                       : std::string("elasticity");
}

// Beyond the paper: the exact single-contact rule takes one elasticity per contact, from 1
// (it follows the impulse through compression and cannot stop before it), to 2 for the
// energetic law (a fraction of the stored energy given back).
void validate_contact_law(const Scene& scene, std::size_t v) {
  const Contact& c = scene.contacts[v];
  std::vector<std::size_t> movable;
  for (const std::size_t body : {c.bumper, c.wedge}) {
    if (scene.bodies[body].kind != BodyKind::static_body) {
      movable.push_back(body);
    }
  }
  const auto elasticity_of = [&](std::size_t body) {
    return scene.elasticity_of(scene.bodies[body]);
  };
  const std::string why = "with friction or solver.restitution other than \"newton\"";
  if (movable.size() == 2 && elasticity_of(movable[0]) != elasticity_of(movable[1])) {
    refuse(element_place("contacts", v),
           "its bodies collide at different elasticities (" +
               format_number(elasticity_of(movable[0])) + " and " +
               format_number(elasticity_of(movable[1])) + "), but " + why +
               " a contact takes one elasticity: give both bodies the same");
  }
  const double e = elasticity_of(movable.front());
  if (e < 1.0) {
    refuse(elasticity_place(scene, movable.front()),
           "must be at least 1 " + why +
               " (the rule follows the impulse through compression), got " + format_number(e));
  }
  if (e > 2.0 && scene.restitution == friction::RestitutionLaw::energetic) {
    refuse(elasticity_place(scene, movable.front()),
           "must be at most 2 with solver.restitution \"energetic\" (it gives back a fraction "
           "of the energy stored in compression), got " +
               format_number(e));
  }
}

// Coulomb's coefficient at each contact: its own `friction`, else the scene's, else 0.
std::vector<double> frictions(const Scene& scene) {
  std::vector<double> mu;
  for (const Contact& c : scene.contacts) {
    mu.push_back(c.friction.value_or(scene.friction.value_or(0.0)));
  }
  return mu;
}

// With a contact law beyond the paper's, each contact's elasticity as the exact rule takes it.
void validate_contact_laws(const Scene& scene) {
  if (methods::has_contact_law(frictions(scene), scene.restitution)) {
    for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
      validate_contact_law(scene, v);
    }
  }
}

// Every rule of the scene format, each with its place.
void validate_scene(const Scene& scene) {
  if (scene.dimension != 1 && scene.dimension != 2) {
    refuse("dimension", "must be 1 or 2, got " + std::to_string(scene.dimension));
  }
  if (scene.elasticity) {
    require_elasticity("elasticity", *scene.elasticity);
  }
  if (scene.bodies.empty()) {
    refuse("bodies", "must hold at least one body, got none");
  }
  if (scene.contacts.empty()) {
    refuse("contacts", "must hold at least one contact, got none");
  }
  if (scene.serial.max_collisions < 0) {
    refuse("solver.max_collisions",
           "must be at least 1, got " + std::to_string(scene.serial.max_collisions));
  }
  if (scene.serial.max_collisions > methods::most_collisions) {
    refuse("solver.max_collisions", "must be at most " + std::to_string(methods::most_collisions) +
                                        ", got " + std::to_string(scene.serial.max_collisions));
  }
  if (scene.friction) {
    require_friction("friction", *scene.friction);
  }
  validate_names(scene.bodies);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    validate_body(scene, i);
  }
  for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
    validate_contact(scene, v);
  }
  validate_contact_laws(scene);
  try {
    require_dense_fits(static_cast<Eigen::Index>(scene.contacts.size()), scene.solver);
  } catch (const InvalidInput& e) {
    refuse("contacts", e.what());
  }
}

// The elasticity each body collides with: its own, else the scene's default (static bodies,
// which contribute nothing, get 1).
std::vector<Elasticity> elasticities_of(const Scene& scene) {
  std::vector<Elasticity> result;
  result.reserve(scene.bodies.size());
  for (const Body& body : scene.bodies) {
    if (body.kind == BodyKind::static_body) {
      result.emplace_back();  // unused: a static body contributes nothing
    } else {
      result.emplace_back(scene.elasticity_of(body));
    }
  }
  return result;
}

// The scene's bodies as the multipoint module takes them (1D embedded on the x axis).
std::vector<multipoint::Body> bodies_of(const Scene& scene) {
  std::vector<multipoint::Body> result;
  result.reserve(scene.bodies.size());
  for (const Body& body : scene.bodies) {
    const Vector2d p =
        body.linear_given == Given::velocity ? Vector2d(body.mass * body.linear) : body.linear;
    switch (body.kind) {
      case BodyKind::material:
        result.emplace_back(material_2d::PointMass{body.mass, p});
        break;
      case BodyKind::rigid: {
        const double L =
            body.angular_given == Given::velocity ? body.inertia * body.angular : body.angular;
        result.emplace_back(rigid_2d::RigidBody{body.mass, body.inertia, body.position, p, L});
        break;
      }
      case BodyKind::static_body:
        result.emplace_back(multipoint::StaticBody{});
        break;
    }
  }
  return result;
}

// The scene's contacts as the multipoint module takes them: unit normals (a normal not of unit
// length within the tolerance is divided by its length, and noted), a missing point at the
// origin (only rigid bodies use it, and they always have one).
std::vector<multipoint::Contact> contacts_of(const Scene& scene, std::vector<std::string>& notes) {
  std::vector<multipoint::Contact> result;
  result.reserve(scene.contacts.size());
  for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
    const Contact& c = scene.contacts[v];
    const UnitNormal n(c.normal);
    if (n.rescaled()) {
      // As given (every digit), then the length and the normal used as the report prints numbers.
      // (The text is appended piece by piece: GCC 12 warns falsely, -Wrestrict, on
      // "[" + std::string&& once this function is inlined into a unity build; GCC bug 105329.)
      const Vector2d& used = n.vector();
      std::string note = member_place(element_place("contacts", v), "normal");
      note += ' ';
      note += show(c.normal, scene.dimension);
      note += " is not of unit length (length ";
      note += number_text(n.given_length());
      note += "): used as ";
      if (scene.dimension == 1) {
        note += number_text(used.x());
      } else {
        note += '[';
        note += number_text(used.x());
        note += ", ";
        note += number_text(used.y());
        note += ']';
      }
      notes.push_back(std::move(note));
    }
    result.push_back({c.bumper, c.wedge, n.vector(), c.point.value_or(Vector2d::Zero())});
  }
  return result;
}

Motion motion_of(const multipoint::Body& body) {
  Motion m;
  if (const auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    m.velocity = material_2d::velocity(*mass);
    m.momentum = mass->p;
  } else if (const auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    m.velocity = rigid_2d::velocity(*rigid);
    m.momentum = rigid->p;
    m.angular_velocity = rigid_2d::angular_velocity(*rigid);
    m.angular_momentum = rigid->L;
  }
  return m;  // a static body: all zero
}

bool finite(const Motion& m) {
  return all_finite_in(m.velocity) && all_finite_in(m.momentum) &&
         std::isfinite(m.angular_velocity) && std::isfinite(m.angular_momentum);
}

bool all_finite(const Result& r) {
  bool ok = std::isfinite(r.energy_before) && std::isfinite(r.energy_after) &&
            std::isfinite(r.energy_change) && all_finite_in(r.momentum_before) &&
            all_finite_in(r.momentum_after) && all_finite_in(r.outcome.Fdt) &&
            std::isfinite(r.outcome.residual);
  for (const BodyReport& b : r.bodies) {
    ok = ok && finite(b.before) && finite(b.after) && std::isfinite(b.energy_before) &&
         std::isfinite(b.energy_after);
  }
  for (const ImpulseReport& i : r.impulses) {
    ok = ok && all_finite_in(i.on_bumper);
  }
  for (const ContactReport& c : r.contacts) {
    ok = ok && std::isfinite(c.approach_before) && std::isfinite(c.approach_after);
  }
  return ok;
}

// The report of one method's outcome: each body before and after, energies, momenta, the
// impulses with the bodies' names and each contact's approach speed before and after.
Result report(const World& world, const Solution& paper, methods::Outcome outcome) {
  const Scene& scene = world.scene();
  const multipoint::Configuration& configuration = world.configuration();
  const std::span<const multipoint::Body> before = configuration.bodies();
  const std::span<const multipoint::Contact> contacts = configuration.contacts();
  Result result;
  result.dimension = scene.dimension;
  result.method = outcome.method;
  result.system = paper;
  result.notes.assign(world.notes().begin(), world.notes().end());
  if (outcome.after.empty()) {
    outcome.after.assign(before.begin(), before.end());  // no state after: the numbers overflowed
  }
  if (outcome.Fdt.size() != static_cast<Eigen::Index>(contacts.size())) {
    outcome.Fdt = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(contacts.size()),
                                            std::numeric_limits<double>::quiet_NaN());
  }
  const std::vector<multipoint::Body>& after = outcome.after;
  for (std::size_t k = 0; k < before.size(); ++k) {
    result.bodies.push_back({scene.bodies[k].name, scene.bodies[k].kind, motion_of(before[k]),
                             motion_of(after[k]), multipoint::kinetic_energy(before[k]),
                             multipoint::kinetic_energy(after[k])});
    if (scene.bodies[k].kind != BodyKind::static_body) {
      result.bodies.back().own_elasticity = scene.bodies[k].elasticity.has_value();
      result.bodies.back().elasticity = scene.elasticity_of(scene.bodies[k]);
    }
  }
  result.energy_before = multipoint::kinetic_energy(before);
  result.energy_after = multipoint::kinetic_energy(after);
  result.energy_change = result.energy_after - result.energy_before;
  result.momentum_before = multipoint::momentum(before);
  result.momentum_after = multipoint::momentum(after);

  const Eigen::VectorXd approach_before = configuration.approach(before);
  const Eigen::VectorXd approach_after = configuration.approach(after);
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const auto row = static_cast<Eigen::Index>(v);
    const double Fdt = outcome.Fdt(row);
    const Vector2d on_bumper = v < outcome.on_bumper.size()
                                   ? outcome.on_bumper[v]
                                   : material_2d::impulse_vector(contacts[v].normal, Fdt);
    result.impulses.push_back({v, scene.bodies[contacts[v].bumper].name,
                               scene.bodies[contacts[v].wedge].name, Fdt, on_bumper});
    result.contacts.push_back({v, approach_before(row), approach_after(row)});
  }
  result.status = outcome.finite && paper.status == SolveStatus::success ? SolveStatus::success
                                                                         : SolveStatus::non_finite;
  result.outcome = std::move(outcome);
  if (!all_finite(result)) {
    result.status = SolveStatus::non_finite;
  }
  return result;
}

}  // namespace

void validate_names(std::span<const Body> bodies) {
  std::unordered_map<std::string_view, std::size_t> names;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::string place = member_place(element_place("bodies", i), "name");
    if (bodies[i].name.empty()) {
      refuse(place, "must not be empty");
    }
    const auto [seen, fresh] = names.emplace(bodies[i].name, i);
    if (!fresh) {
      refuse(place, in_quotes(bodies[i].name) + " is already the name of " +
                        element_place("bodies", seen->second));
    }
  }
}

namespace {
// The scene checked, then its model: what the lower layers trust.
multipoint::Configuration checked_model(const Scene& scene, std::vector<std::string>& notes) {
  validate_scene(scene);
  return {multipoint::Configuration::Trusted{}, bodies_of(scene), elasticities_of(scene),
          contacts_of(scene, notes)};
}
}  // namespace

World::World(Scene scene)
    : scene_(std::move(scene)), configuration_(checked_model(scene_, notes_)) {}

World::World(Scene scene, std::vector<std::string> notes, multipoint::Configuration configuration)
    : scene_(std::move(scene)),
      notes_(std::move(notes)),
      configuration_(std::move(configuration)) {}

std::string World::contact_name(Eigen::Index v) const {
  const Contact& c = scene_.contacts[static_cast<std::size_t>(v)];
  std::string text("contact ");
  text.append(std::to_string(v)).append(" (").append(scene_.bodies[c.bumper].name);
  text.append("\u2013").append(scene_.bodies[c.wedge].name).append(")");
  return text;
}

methods::Options World::options() const {
  methods::Options options;
  options.solver = scene_.solver;
  options.complementarity = scene_.complementarity;
  options.serial = scene_.serial;
  options.contact_name = [this](Eigen::Index v) { return contact_name(v); };
  std::vector<double> mu = frictions(scene_);
  if (methods::has_contact_law(mu, scene_.restitution)) {  // else the paper's contacts
    options.friction = std::move(mu);
    options.restitution = scene_.restitution;
  }
  return options;
}

World World::with_elasticity(double value) const {
  require_elasticity("elasticity", value);
  Scene scene = scene_;
  scene.elasticity = value;
  for (Body& body : scene.bodies) {
    body.elasticity.reset();
  }
  validate_contact_laws(scene);
  multipoint::Configuration configuration(
      multipoint::Configuration::Trusted{},
      {configuration_.bodies().begin(), configuration_.bodies().end()}, elasticities_of(scene),
      {configuration_.contacts().begin(), configuration_.contacts().end()});
  return {std::move(scene), notes_, std::move(configuration)};
}

namespace {

// The paper's system, assembled and solved once for every method; a method that cannot take the
// scene refused before any method runs (friction with several contacts, say).
methods::Paper checked_paper(const World& world, std::span<const methods::Method> methods) {
  methods::Paper paper = methods::paper(world.configuration(), world.scene().solver);
  for (const methods::Method method : methods) {
    if (const std::string why = unsupported(world, method); !why.empty()) {
      refuse("contacts", why);
    }
  }
  return paper;
}

// A method's outcome on the solved system; none can start from numbers beyond doubles.
methods::Outcome outcome_of(const World& world, const methods::Paper& paper,
                            const methods::Options& options, methods::Method method) {
  methods::Outcome outcome;
  outcome.method = method;
  if (paper.solution.status == SolveStatus::success) {
    outcome = methods::resolve(method, world.configuration(), paper, options);
  } else {
    outcome.finite = false;
  }
  return outcome;
}

}  // namespace

std::vector<Result> resolve(const World& world, std::span<const methods::Method> methods) {
  const methods::Paper paper = checked_paper(world, methods);
  const methods::Options options = world.options();
  std::vector<Result> results;
  for (const methods::Method method : methods) {
    results.push_back(report(world, paper.solution, outcome_of(world, paper, options, method)));
  }
  return results;
}

struct Resolving::State {
  State(const World& w, methods::Method m)
      : world(w),
        method(m),
        paper(checked_paper(world, std::span<const methods::Method>(&method, 1))),
        options(world.options()) {
    if (method == methods::Method::serial && paper.solution.status == SolveStatus::success) {
      serial.emplace(world.configuration(), paper, options);
    }
  }
  const World& world;
  methods::Method method;
  methods::Paper paper;
  methods::Options options;
  std::optional<methods::SerialMethod> serial;  // the serial method's collisions, in slices
};

Resolving::Resolving(const World& world, methods::Method method)
    : state_(std::make_unique<State>(world, method)) {}

Resolving::~Resolving() = default;
Resolving::Resolving(Resolving&&) noexcept = default;
Resolving& Resolving::operator=(Resolving&&) noexcept = default;

bool Resolving::advance(std::int64_t collisions) {
  return !state_->serial || state_->serial->advance(collisions);
}

std::int64_t Resolving::collisions() const {
  return state_->serial ? state_->serial->collisions() : 0;
}

std::int64_t Resolving::bound() const {
  return state_->serial ? state_->serial->bound() : 0;
}

Result Resolving::finish() {
  const State& s = *state_;
  return report(s.world, s.paper.solution,
                state_->serial ? state_->serial->finish()
                               : outcome_of(s.world, s.paper, s.options, s.method));
}

Result resolve(const World& world, methods::Method method) {
  Resolving resolving(world, method);
  resolving.advance(std::numeric_limits<std::int64_t>::max());
  return resolving.finish();
}

Result resolve(const World& world) {
  return resolve(world, world.scene().method);
}

Result solve(const Scene& scene) {
  return resolve(World(scene));
}

std::string unsupported(const World& world, methods::Method method) {
  return row_of(method).unsupported(world.configuration(), world.options());
}

}  // namespace impulse::scene
