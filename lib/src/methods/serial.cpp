// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/serial.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>
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

namespace {

using Eigen::Index;
using multipoint::Body;
using multipoint::Contact;
using multipoint::Touch;

void require_options(const SerialOptions& options) {
  if (options.max_collisions < 0) {
    throw InvalidInput("max_collisions must be at least 1 (or 0 for " +
                       std::to_string(collisions_per_contact) + " per contact), got " +
                       std::to_string(options.max_collisions));
  }
  if (!(options.approach_tolerance >= 0.0 && std::isfinite(options.approach_tolerance))) {
    throw InvalidInput("approach_tolerance must be finite and at least 0, got " +
                       format_number(options.approach_tolerance));
  }
}

// The approaching contacts by approach speed, fastest first, the lowest index among equal speeds:
// a heap of (speed, contact) entries of the contacts faster than the threshold (no other can be
// chosen). A contact whose speed changes gets a new entry if it approaches; its old one stays
// behind and is skipped when it comes up (its speed is no longer the contact's). The heap is
// rebuilt from the speeds when stale entries outnumber the contacts.
class Fastest {
 public:
  Fastest(const Eigen::VectorXd& speeds, double threshold)
      : speeds_(speeds), threshold_(threshold) {
    rebuild();
  }

  // Contact v's speed is now `speed`.
  void update(Index v, double speed) {
    speeds_(v) = speed;
    if (speed > threshold_) {
      heap_.push({speed, v});
      if (heap_.size() > 4 * static_cast<std::size_t>(speeds_.size()) + 64) {
        rebuild();
      }
    }
  }

  // The fastest approaching contact (the first of equal speeds) and its speed, or nothing when
  // no contact approaches.
  [[nodiscard]] std::optional<std::pair<Index, double>> top() {
    while (!heap_.empty() && heap_.top().speed != speeds_(heap_.top().contact)) {
      heap_.pop();  // a stale entry
    }
    if (heap_.empty()) {
      return std::nullopt;
    }
    return std::pair{heap_.top().contact, heap_.top().speed};
  }

 private:
  struct Entry {
    double speed;
    Index contact;
    // The heap's top is its largest entry: the larger speed, then the smaller contact index.
    bool operator<(const Entry& other) const {
      return speed < other.speed || (speed == other.speed && contact > other.contact);
    }
  };

  void rebuild() {
    std::vector<Entry> entries;
    for (Index v = 0; v < speeds_.size(); ++v) {
      if (speeds_(v) > threshold_) {
        entries.push_back({speeds_(v), v});
      }
    }
    heap_ = std::priority_queue<Entry>(std::less<Entry>(), std::move(entries));
  }

  Eigen::VectorXd speeds_;
  double threshold_;
  std::priority_queue<Entry> heap_;
};

}  // namespace

namespace {

// The serial loop, once: the fastest-approaching contact collides (collide(v, state) changes the
// state and returns the normal impulse, or nothing when a number overflowed), then the contacts
// of its two bodies are measured again, until none approaches or the bound is reached.
template <typename Collide>
SerialResolution run_serial(const multipoint::Configuration& configuration,
                            const SerialOptions& options, Collide&& collide) {
  require_options(options);
  const std::span<const Body> bodies = configuration.bodies();
  const std::span<const Contact> contacts = configuration.contacts();
  const auto n = static_cast<Index>(contacts.size());
  SerialResolution r;
  r.after.assign(bodies.begin(), bodies.end());
  r.Fdt = Eigen::VectorXd::Zero(n);
  SerialDiagnostics& d = r.diagnostics;
  d.max_collisions = options.max_collisions > 0
                         ? options.max_collisions
                         : collisions_per_contact * std::max<std::int64_t>(1, n);

  double speed = 0.0;  // the largest speed of a body's point at a contact, before
  for (const Contact& c : contacts) {
    speed = std::max(speed, multipoint::point_velocity(bodies[c.bumper], c.point).norm() +
                                multipoint::point_velocity(bodies[c.wedge], c.point).norm());
  }
  d.approach_threshold = options.approach_tolerance * speed;
  const Eigen::VectorXd u = configuration.approach(r.after);
  if (!all_finite_in(u) || !std::isfinite(speed)) {
    d.status = SerialStatus::non_finite;
    return r;
  }
  if (n == 0) {
    return r;
  }

  Fastest fastest(u, d.approach_threshold);
  while (true) {
    const std::optional<std::pair<Index, double>> next = fastest.top();
    if (!next) {
      break;  // no contact approaches
    }
    const auto [v, approach] = *next;
    if (static_cast<std::int64_t>(d.order.size()) >= d.max_collisions) {
      d.status = SerialStatus::collision_limit;
      d.still_approaching = v;
      d.approach_left = approach;
      break;
    }
    const Contact& c = contacts[static_cast<std::size_t>(v)];
    const std::optional<double> Fdt = collide(v, r.after);
    if (!Fdt) {
      d.status = SerialStatus::non_finite;
      break;
    }
    r.Fdt(v) += *Fdt;
    d.order.push_back(v);
    bool finite = true;
    for (const std::size_t body : {c.bumper, c.wedge}) {
      for (const Touch& t : configuration.touches(body)) {
        const double changed = configuration.approach(r.after, t.contact);
        finite = finite && std::isfinite(changed);
        fastest.update(t.contact, changed);
      }
    }
    if (!finite) {
      d.status = SerialStatus::non_finite;
      break;
    }
  }
  d.passes = count_passes(d.order);
  return r;
}

}  // namespace

SerialResolution resolve_serial(const multipoint::Configuration& configuration,
                                const SerialOptions& options) {
  const std::span<const Contact> contacts = configuration.contacts();
  const std::span<const Elasticity> elasticities = configuration.elasticities();
  return run_serial(
      configuration, options, [&](Index v, std::vector<Body>& state) -> std::optional<double> {
        const Contact& c = contacts[static_cast<std::size_t>(v)];
        const ScalarSolution one = solve(
            multipoint::share(state[c.bumper], Touch{v, c.normal, c.point},
                              elasticities[c.bumper]) +
            multipoint::share(state[c.wedge], Touch{v, -c.normal, c.point}, elasticities[c.wedge]));
        if (one.status != SolveStatus::success || !std::isfinite(one.Fdt)) {
          return std::nullopt;
        }
        configuration.apply(state, v, one.Fdt);  // -n Fdt on the bumper, +n Fdt on the wedge
        return one.Fdt;
      });
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
        std::to_string(collisions_per_contact) + " per contact), " +
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
  o.diagnostics = {{"collisions", static_cast<std::int64_t>(d.order.size())},
                   {"passes", d.passes},
                   {"order", std::vector<std::int64_t>(d.order.begin(), d.order.end())},
                   {"max_collisions", d.max_collisions},
                   {"finished", d.status == SerialStatus::finished}};
  o.solution = std::move(s.diagnostics);
  return o;
}

}  // namespace

Outcome serial(const multipoint::Configuration& configuration, const Paper& paper,
               const Options& options) {
  return serial_outcome(resolve_serial(configuration, options.serial), paper, options);
}

Outcome serial_exact(const multipoint::Configuration& configuration, const Paper& paper,
                     const Options& options) {
  const std::span<const Contact> contacts = configuration.contacts();
  const auto n = static_cast<Index>(contacts.size());
  Eigen::VectorXd tangential = Eigen::VectorXd::Zero(n);
  std::vector<std::optional<friction::Slip>> ended(contacts.size());
  double most_gained = 0.0;  // the largest gain of kinetic energy by one collision
  SerialResolution s = run_serial(
      configuration, options.serial,
      [&](Index v, std::vector<Body>& state) -> std::optional<double> {
        const auto k = static_cast<std::size_t>(v);
        const Contact& c = contacts[k];
        const double before = multipoint::kinetic_energy(state[c.bumper]) +
                              multipoint::kinetic_energy(state[c.wedge]);
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
        const double after = multipoint::kinetic_energy(state[c.bumper]) +
                             multipoint::kinetic_energy(state[c.wedge]);
        if (law.elasticity.value() <= 2.0 && detail::energy_gained(before, after)) {
          most_gained = std::max(most_gained, after - before);
        }
        tangential(v) += p.tangential;
        ended[k] = p.outcome;
        return p.normal;
      });
  const std::vector<Body> after = s.after;
  Outcome o = serial_outcome(std::move(s), paper, options);
  if (!o.finite) {
    return o;
  }
  std::vector<std::string> slip;
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const Contact& c = contacts[v];
    // A contact that never collided ends as it is: sliding or not.
    const friction::Slip how =
        ended[v].value_or(detail::slip_of(after[c.bumper], after[c.wedge], c.point, c.normal));
    slip.emplace_back(friction::to_string(how));
    o.on_bumper.push_back(c.normal * -o.Fdt(static_cast<Index>(v)) +
                          friction::tangent(c.normal) * tangential(static_cast<Index>(v)));
  }
  o.per_contact = detail::friction_columns(tangential, std::move(slip));
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

}  // namespace impulse::methods
