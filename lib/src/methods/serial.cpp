// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/serial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/core/text.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/methods/resolve.hpp"

namespace impulse::methods {

std::int64_t count_passes(std::span<const Eigen::Index> order) {
  // The pass in which each contact last collided: a contact that comes up again in the same
  // pass ends it.
  Eigen::Index contacts = 0;
  for (const Eigen::Index v : order) {
    contacts = std::max(contacts, v + 1);
  }
  std::vector<std::int64_t> last_pass(static_cast<std::size_t>(contacts), 0);
  std::int64_t passes = 0;
  for (const Eigen::Index v : order) {
    std::int64_t& last = last_pass[static_cast<std::size_t>(v)];
    if (passes == 0 || last == passes) {
      ++passes;
    }
    last = passes;
  }
  return passes;
}

std::string default_collision_bound_words() {
  return std::to_string(collisions_per_contact) + " per contact, at least " +
         std::to_string(least_collisions);
}

namespace {

using Eigen::Index;
using multipoint::Body;
using multipoint::Contact;
using multipoint::Touch;

void require_options(const SerialOptions& options) {
  if (options.max_collisions < 0) {
    throw InvalidInput("max_collisions must be at least 1 (or 0 for " +
                       default_collision_bound_words() + "), got " +
                       std::to_string(options.max_collisions));
  }
  if (!(options.approach_tolerance >= 0.0 && std::isfinite(options.approach_tolerance))) {
    throw InvalidInput("approach_tolerance must be finite and at least 0, got " +
                       format_number(options.approach_tolerance));
  }
}

}  // namespace

// Not in an anonymous namespace: SerialCollisions::State holds one (and a unity build would
// warn of a member whose type has internal linkage).
namespace serial_detail {

using Eigen::Index;

// The approaching contacts by approach speed, fastest first, the lowest index among equal speeds:
// a tournament over the contacts (a complete binary tree whose leaves are the contacts and whose
// every node holds the better of its two children), so that the fastest is at the root and a
// change of speeds costs a walk from their leaves to the root, each node above them settled once
// (the contacts of two touching bodies share most of that walk). A contact not faster than the
// threshold (no other can be chosen) takes part as slower than every other, and so do the leaves
// beyond the last contact.
class Fastest {
 public:
  Fastest(const Eigen::VectorXd& speeds, double threshold) : threshold_(threshold) {
    while (leaves_ < speeds.size()) {
      leaves_ *= 2;
    }
    key_.assign(static_cast<std::size_t>(leaves_), slower);
    node_.assign(2 * static_cast<std::size_t>(leaves_), 0);
    round_of_.assign(node_.size(), 0);
    path_.assign(static_cast<std::size_t>(leaves_), 0);
    for (Index v = 0; v < leaves_; ++v) {
      if (v < speeds.size()) {
        key_[static_cast<std::size_t>(v)] = key(speeds(v));
      }
      node_[static_cast<std::size_t>(leaves_ + v)] = v;
    }
    for (Index at = leaves_ - 1; at >= 1; --at) {
      settle(at);
    }
  }

  // A change of speeds: begin(), then set() for each contact whose speed changed, then settle().
  void begin() {
    ++round_;
    waiting_ = 0;
  }

  // Whether contact v has not been set since begin().
  [[nodiscard]] bool unset(Index v) const {
    return round_of_[static_cast<std::size_t>(leaves_ + v)] != round_;
  }

  // Contact v's speed is now `speed`.
  void set(Index v, double speed) {
    key_[static_cast<std::size_t>(v)] = key(speed);
    round_of_[static_cast<std::size_t>(leaves_ + v)] = round_;
    wait((leaves_ + v) / 2);
  }

  // The nodes above the contacts set, level by level.
  void settle() {
    while (waiting_ > 0) {
      const std::size_t level = std::exchange(waiting_, 0);
      for (std::size_t k = 0; k < level; ++k) {
        const Index at = path_[k];
        settle(at);
        if (at > 1) {
          wait(at / 2);
        }
      }
    }
  }

  // The fastest approaching contact (the first of equal speeds) and its speed, or nothing when
  // no contact approaches.
  [[nodiscard]] std::optional<std::pair<Index, double>> top() const {
    const Index v = node_[1];
    if (key_[static_cast<std::size_t>(v)] == slower) {
      return std::nullopt;
    }
    return std::pair{v, key_[static_cast<std::size_t>(v)]};
  }

 private:
  static constexpr double slower = -std::numeric_limits<double>::infinity();

  // A speed as the tournament compares it: itself when faster than the threshold.
  [[nodiscard]] double key(double speed) const { return speed > threshold_ ? speed : slower; }

  // Node `at` is to settle in this round (once).
  void wait(Index at) {
    if (std::exchange(round_of_[static_cast<std::size_t>(at)], round_) != round_) {
      path_[waiting_++] = at;
    }
  }

  // Node `at` holds the better of its children: the faster, the left one (lower indices) on a tie.
  void settle(Index at) {
    const Index left = node_[static_cast<std::size_t>(2 * at)];
    const Index right = node_[static_cast<std::size_t>(2 * at + 1)];
    const bool faster =
        key_[static_cast<std::size_t>(right)] > key_[static_cast<std::size_t>(left)];
    node_[static_cast<std::size_t>(at)] = faster ? right : left;
  }

  double threshold_;
  std::vector<double> key_;  // each contact's key()
  // The leaves, a power of two and at least two (so that the root is not a leaf): contact v at
  // node leaves_ + v.
  Index leaves_ = 2;
  std::vector<Index> node_;  // node 1 the root, node k's children 2k and 2k + 1; `none` if empty
  std::vector<std::uint64_t> round_of_;  // the last round in which each node was set or waited
  std::uint64_t round_ = 0;              // begin()'s count
  std::vector<Index> path_;              // the nodes waiting to settle, one level's
  std::size_t waiting_ = 0;              // how many
};

}  // namespace serial_detail

namespace {

// The paper's single-contact formula at contact v: the 1×1 system of the two bodies' shares, and
// its impulse applied to them; nothing when a number overflowed.
std::optional<double> paper_collision(const multipoint::Configuration& configuration, Index v,
                                      std::vector<Body>& state) {
  const Contact& c = configuration.contacts()[static_cast<std::size_t>(v)];
  const std::span<const Elasticity> elasticities = configuration.elasticities();
  const ScalarSolution one = solve(
      multipoint::share(state[c.bumper], Touch{v, c.normal, c.point}, elasticities[c.bumper]) +
      multipoint::share(state[c.wedge], Touch{v, -c.normal, c.point}, elasticities[c.wedge]));
  if (one.status != SolveStatus::success || !std::isfinite(one.Fdt)) {
    return std::nullopt;
  }
  configuration.apply(state, v, one.Fdt);  // -n Fdt on the bumper, +n Fdt on the wedge
  return one.Fdt;
}

}  // namespace

// The serial loop, once: the fastest-approaching contact collides (collide(v, state), or the
// paper's formula when there is none, changes the state and returns the normal impulse, or
// nothing when a number overflowed), then the contacts of its two bodies are measured again,
// until none approaches or the bound is reached.
struct SerialCollisions::State {
  State(const multipoint::Configuration& c, const SerialOptions& options, Collide how)
      : configuration(c), collide(std::move(how)) {
    require_options(options);
    const std::span<const Body> bodies = configuration.bodies();
    const std::span<const Contact> contacts = configuration.contacts();
    const auto n = static_cast<Index>(contacts.size());
    r.after.assign(bodies.begin(), bodies.end());
    for (const Body& body : bodies) {
      motions.push_back(multipoint::motion(body));
    }
    r.Fdt = Eigen::VectorXd::Zero(n);
    SerialDiagnostics& d = r.diagnostics;
    d.max_collisions =
        options.max_collisions > 0 ? options.max_collisions : default_collision_bound(n);
    double speed = 0.0;  // the largest speed of a body's point at a contact, before
    for (const Contact& contact : contacts) {
      speed = std::max(speed,
                       multipoint::point_velocity(bodies[contact.bumper], contact.point).norm() +
                           multipoint::point_velocity(bodies[contact.wedge], contact.point).norm());
    }
    d.approach_threshold = options.approach_tolerance * speed;
    const Eigen::VectorXd u = configuration.approach(r.after);
    if (!all_finite_in(u) || !std::isfinite(speed)) {
      d.status = SerialStatus::non_finite;
      ended = true;
    } else if (n == 0) {
      ended = true;
    } else {
      fastest.emplace(u, d.approach_threshold);
    }
  }

  // Whether the collisions end before the next one: no contact approaches, or the bound is
  // reached (what still approaches recorded). Otherwise the next contact is in `next`.
  bool ends_here() {
    SerialDiagnostics& d = r.diagnostics;
    next = fastest->top();
    if (!next) {
      return true;
    }
    if (static_cast<std::int64_t>(d.order.size()) >= d.max_collisions) {
      d.status = SerialStatus::collision_limit;
      d.still_approaching = next->first;
      d.approach_left = next->second;
      return true;
    }
    return false;
  }

  // The next contact collides and its two bodies' contacts are measured again; false when a
  // number overflowed (recorded).
  bool collide_next() {
    const Index v = next->first;
    const Contact& c = configuration.contacts()[static_cast<std::size_t>(v)];
    const std::optional<double> Fdt =
        collide ? collide(v, r.after) : paper_collision(configuration, v, r.after);
    if (!Fdt) {
      r.diagnostics.status = SerialStatus::non_finite;
      return false;
    }
    r.Fdt(v) += *Fdt;
    r.diagnostics.order.push_back(v);
    motions[c.bumper] = multipoint::motion(r.after[c.bumper]);
    motions[c.wedge] = multipoint::motion(r.after[c.wedge]);
    bool finite = true;
    fastest->begin();
    for (const std::size_t body : {c.bumper, c.wedge}) {
      for (const Touch& t : configuration.touches(body)) {
        if (fastest->unset(t.contact)) {  // (a contact between the two is in both lists)
          const double changed = configuration.approach(motions, t.contact);
          finite = finite && std::isfinite(changed);
          fastest->set(t.contact, changed);
        }
      }
    }
    fastest->settle();
    if (!finite) {
      r.diagnostics.status = SerialStatus::non_finite;
    }
    return finite;
  }

  const multipoint::Configuration& configuration;
  Collide collide;
  SerialResolution r;
  // Each body's motion in r.after, which the approach speeds measure: a collision changes two.
  std::vector<multipoint::Motion> motions;
  std::optional<serial_detail::Fastest> fastest;
  std::optional<std::pair<Index, double>> next;  // the contact to collide next, its speed
  bool ended = false;
};

namespace {

// Every collision at once.
SerialResolution run_serial(const multipoint::Configuration& configuration,
                            const SerialOptions& options, SerialCollisions::Collide collide) {
  SerialCollisions collisions(configuration, options, std::move(collide));
  collisions.advance(std::numeric_limits<std::int64_t>::max());
  return std::move(collisions).take();
}

}  // namespace

SerialCollisions::SerialCollisions(const multipoint::Configuration& configuration,
                                   const SerialOptions& options)
    : SerialCollisions(configuration, options, Collide{}) {}

SerialCollisions::SerialCollisions(const multipoint::Configuration& configuration,
                                   const SerialOptions& options, Collide collide)
    : state_(std::make_unique<State>(configuration, options, std::move(collide))) {}

SerialCollisions::~SerialCollisions() = default;
SerialCollisions::SerialCollisions(SerialCollisions&&) noexcept = default;
SerialCollisions& SerialCollisions::operator=(SerialCollisions&&) noexcept = default;

bool SerialCollisions::advance(std::int64_t collisions) {
  if (collisions < 1) {
    throw InvalidInput("advance: collisions must be at least 1, got " + std::to_string(collisions));
  }
  State& s = *state_;
  if (s.ended) {
    return true;
  }
  // Each collision only after asking whether they end here, and once more after the slice, so
  // that a caller sees the end without another call.
  for (std::int64_t k = 0; k < collisions && !s.ended; ++k) {
    s.ended = s.ends_here() || !s.collide_next();
  }
  s.ended = s.ended || s.ends_here();
  if (s.ended) {
    s.r.diagnostics.passes = count_passes(s.r.diagnostics.order);
  }
  return s.ended;
}

bool SerialCollisions::ended() const {
  return state_->ended;
}

std::int64_t SerialCollisions::collisions() const {
  return static_cast<std::int64_t>(state_->r.diagnostics.order.size());
}

const SerialResolution& SerialCollisions::resolution() const {
  return state_->r;
}

SerialResolution SerialCollisions::take() && {
  return std::move(state_->r);
}

SerialResolution resolve_serial(const multipoint::Configuration& configuration,
                                const SerialOptions& options) {
  return run_serial(configuration, options, SerialCollisions::Collide{});
}

SerialResolution resolve_serial(std::span<const Body> bodies,
                                std::span<const Elasticity> elasticities,
                                std::span<const Contact> contacts, const SerialOptions& options) {
  require_options(options);
  const multipoint::Configuration configuration({bodies.begin(), bodies.end()},
                                                {elasticities.begin(), elasticities.end()},
                                                {contacts.begin(), contacts.end()});
  return resolve_serial(configuration, options);
}

SerialResolution resolve_serial(std::span<const Body> bodies, Elasticity elasticity,
                                std::span<const Contact> contacts, const SerialOptions& options) {
  const std::vector<Elasticity> elasticities(bodies.size(), elasticity);
  return resolve_serial(bodies, elasticities, contacts, options);
}

namespace {

// What serial collisions report of themselves, whichever rule each collision follows.
Outcome serial_outcome(SerialResolution s, const Paper& paper, const Options& options) {
  const SerialDiagnostics& d = s.diagnostics;
  Outcome o;
  o.method = Method::serial;
  o.finite = d.status != SerialStatus::non_finite;
  o.Fdt = std::move(s.Fdt);
  o.after = std::move(s.after);  // the state the last collision left
  if (!o.finite) {
    o.solution = std::move(s.diagnostics);
    return o;
  }
  o.residual = paper.system.residual(o.Fdt);
  o.finished = d.status == SerialStatus::finished;
  if (!o.finished) {
    o.unfinished =
        "serial collisions did not end: after " + std::to_string(d.order.size()) +
        " collisions (the bound: solver.max_collisions, by default " +
        default_collision_bound_words() + "), " +
        (d.still_approaching >= 0 ? detail::contact_name(options, d.still_approaching) +
                                        " still approaches at " + number_text(d.approach_left)
                                  : std::string("a contact still approaches")) +
        ". Below elasticity 2 the same contacts can collide again and again without "
        "end (inelastic collapse), and a light body between heavy ones needs many "
        "collisions: raise \"max_collisions\" in the scene's \"solver\", or choose "
        "another method";
  }
  const std::string counts = counted(d.order.size(), "collision", "collisions") + " in " +
                             counted(static_cast<std::size_t>(d.passes), "pass", "passes");
  std::string details = counts + " (bound " + std::to_string(d.max_collisions) + ")";
  if (!d.order.empty()) {
    details.append("; contacts in turn:");
    constexpr std::size_t shown = 40;
    for (std::size_t k = 0; k < d.order.size() && k < shown; ++k) {
      details.append(k == 0 ? " " : ", ").append(std::to_string(d.order[k]));
    }
    if (d.order.size() > shown) {
      details.append(", … (--format json lists all)");
    }
  }
  o.details.push_back(std::move(details));
  o.summary = counts;
  if (!d.order.empty() && d.order.size() <= 12) {
    o.summary.append(", order");
    for (std::size_t k = 0; k < d.order.size(); ++k) {
      o.summary.append(k == 0 ? " " : ", ").append(std::to_string(d.order[k]));
    }
  }
  // Moved in one by one: a list's fields are copied, and the order may hold a million entries.
  o.diagnostics.push_back({"collisions", static_cast<std::int64_t>(d.order.size())});
  o.diagnostics.push_back({"passes", d.passes});
  o.diagnostics.push_back({"order", std::vector<std::int64_t>(d.order.begin(), d.order.end())});
  o.diagnostics.push_back({"max_collisions", d.max_collisions});
  o.diagnostics.push_back({"finished", d.status == SerialStatus::finished});
  o.solution = std::move(s.diagnostics);
  return o;
}

}  // namespace

// The serial method's collisions and what the exact rule's collisions leave besides the impulses.
struct SerialMethod::State {
  State(const multipoint::Configuration& c, const Paper& p, const Options& o, Kind k)
      : configuration(c),
        paper(p),
        options(o),
        kind(k),
        tangential(Eigen::VectorXd::Zero(static_cast<Index>(c.contacts().size()))),
        slip(c.contacts().size()) {
    if (kind == Kind::paper) {
      collisions.emplace(configuration, options.serial);
    } else if (kind == Kind::exact) {
      collisions.emplace(configuration, options.serial,
                         [this](Index v, std::vector<Body>& state) { return collide(v, state); });
    }
  }

  // One collision by the exact single-contact rule (friction::collide), its tangential impulse,
  // how the contact ended and any energy it gained kept.
  std::optional<double> collide(Index v, std::vector<Body>& state) {
    const auto k = static_cast<std::size_t>(v);
    const Contact& c = configuration.contacts()[k];
    const double before =
        multipoint::kinetic_energy(state[c.bumper]) + multipoint::kinetic_energy(state[c.wedge]);
    const friction::ContactLaw law = detail::contact_law(configuration, options, k);
    const friction::Collision one =
        friction::collide(state[c.bumper], state[c.wedge], c.point, c.normal, law);
    const friction::ContactImpulse& p = one.impulse;
    if (p.status != friction::ContactStatus::resolved || !std::isfinite(p.normal) ||
        !std::isfinite(p.tangential)) {
      return std::nullopt;  // the fastest contact approaches: only overflow stops it here
    }
    state[c.bumper] = one.after.bumper;
    state[c.wedge] = one.after.wedge;
    const double after =
        multipoint::kinetic_energy(state[c.bumper]) + multipoint::kinetic_energy(state[c.wedge]);
    if (law.elasticity.value() <= 2.0 && detail::energy_gained(before, after)) {
      most_gained = std::max(most_gained, after - before);
    }
    tangential(v) += p.tangential;
    slip[k] = p.outcome;
    return p.normal;
  }

  // The outcome of the exact rule's collisions: serial_outcome's, with friction's columns, the
  // law in the details and the warning when a collision gained energy.
  Outcome exact_outcome(SerialResolution s) const {
    const std::span<const Contact> contacts = configuration.contacts();
    const std::vector<std::optional<friction::Slip>>& ended = slip;
    const std::vector<Body> after = s.after;
    Outcome o = serial_outcome(std::move(s), paper, options);
    if (!o.finite) {
      return o;
    }
    std::vector<std::string> slips;
    for (std::size_t v = 0; v < contacts.size(); ++v) {
      const Contact& c = contacts[v];
      // A contact that never collided ends as it is: sliding or not.
      const friction::Slip how =
          ended[v].value_or(detail::slip_of(after[c.bumper], after[c.wedge], c.point, c.normal));
      slips.emplace_back(friction::to_string(how));
      o.on_bumper.push_back(c.normal * -o.Fdt(static_cast<Index>(v)) +
                            friction::tangent(c.normal) * tangential(static_cast<Index>(v)));
    }
    o.per_contact = detail::friction_columns(tangential, std::move(slips));
    std::vector<std::string> details{"each collision by the exact single-contact rule: " +
                                     detail::law_words(configuration, options)};
    for (std::string& line : o.details) {
      details.push_back(std::move(line));
    }
    o.details = std::move(details);
    o.diagnostics.push_back({"restitution", std::string(name_of(options.restitution))});
    o.diagnostics.push_back({"friction", options.friction});
    if (most_gained > 0.0) {
      o.warnings.push_back(detail::energy_gained_warning(options.restitution));
    }
    return o;
  }

  const multipoint::Configuration& configuration;
  const Paper& paper;
  const Options& options;
  Kind kind;
  Eigen::VectorXd tangential;
  std::vector<std::optional<friction::Slip>> slip;
  double most_gained = 0.0;  // the largest gain of kinetic energy by one collision
  std::optional<SerialCollisions> collisions;  // none for one contact with a contact law
};

SerialMethod::SerialMethod(const multipoint::Configuration& configuration, const Paper& paper,
                           const Options& options)
    : SerialMethod(configuration, paper, options,
                   !has_contact_law(options.friction, options.restitution) ? Kind::paper
                   : configuration.contacts().size() == 1                  ? Kind::single
                                                                           : Kind::exact) {}

SerialMethod::SerialMethod(const multipoint::Configuration& configuration, const Paper& paper,
                           const Options& options, Kind kind)
    : state_(std::make_unique<State>(configuration, paper, options, kind)) {}

SerialMethod::~SerialMethod() = default;
SerialMethod::SerialMethod(SerialMethod&&) noexcept = default;
SerialMethod& SerialMethod::operator=(SerialMethod&&) noexcept = default;

bool SerialMethod::advance(std::int64_t collisions) {
  return !state_->collisions || state_->collisions->advance(collisions);
}

std::int64_t SerialMethod::collisions() const {
  return state_->collisions ? state_->collisions->collisions() : 0;
}

std::int64_t SerialMethod::bound() const {
  return state_->collisions ? state_->collisions->resolution().diagnostics.max_collisions : 0;
}

Outcome SerialMethod::finish() {
  State& s = *state_;
  switch (s.kind) {
    case Kind::single:
      return exact_single(Method::serial, s.configuration, s.paper, s.options);
    case Kind::paper:
      return serial_outcome(std::move(*s.collisions).take(), s.paper, s.options);
    case Kind::exact:
      break;
  }
  return s.exact_outcome(std::move(*s.collisions).take());
}

namespace {

Outcome all_at_once(SerialMethod method) {
  method.advance(std::numeric_limits<std::int64_t>::max());
  return method.finish();
}

}  // namespace

Outcome serial(const multipoint::Configuration& configuration, const Paper& paper,
               const Options& options) {
  return all_at_once(SerialMethod(configuration, paper, options, SerialMethod::Kind::paper));
}

Outcome serial_exact(const multipoint::Configuration& configuration, const Paper& paper,
                     const Options& options) {
  return all_at_once(SerialMethod(configuration, paper, options, SerialMethod::Kind::exact));
}

}  // namespace impulse::methods
