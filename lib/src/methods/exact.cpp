// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: contacts with Coulomb friction and any of the three restitution laws,
// resolved by the exact single-contact rule (friction::collide) inside the pipeline.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/methods/resolve.hpp"

namespace impulse::methods {

namespace {

double friction_at(const Options& options, std::size_t v) {
  return v < options.friction.size() ? options.friction[v] : 0.0;
}

bool is_static(const multipoint::Body& body) {
  return std::holds_alternative<multipoint::StaticBody>(body);
}

// "slip until Fdt = 0.2, stick until 0.925; compression ended at Fdt = 0.3625"
std::string phases_text(const friction::ContactImpulse& p) {
  if (p.status == friction::ContactStatus::not_approaching) {
    return "not approaching: no impulse (" + std::string(friction::to_string(p.outcome)) + ")";
  }
  std::string text;
  for (const friction::Phase& phase : p.phases()) {
    const bool first = text.empty();
    text.append(first ? "" : ", ").append(friction::to_string(phase.regime));
    text.append(first ? " until Fdt = " : " until ").append(number_text(phase.end));
  }
  text.append("; compression ended at Fdt = ").append(number_text(p.compression));
  return text;
}

}  // namespace

friction::ContactLaw detail::contact_law(const multipoint::Configuration& configuration,
                                         const Options& options, std::size_t v) {
  const multipoint::Contact& c = configuration.contacts()[v];
  // The elasticity of the movable bodies (a static one has none; World checks two agree).
  const std::size_t body = is_static(configuration.bodies()[c.bumper]) ? c.wedge : c.bumper;
  return {friction_at(options, v), configuration.elasticities()[body], options.restitution};
}

bool detail::energy_gained(double before, double after) {
  return after - before > 1e-12 * before;
}

std::string detail::energy_gained_warning(friction::RestitutionLaw law) {
  if (law == friction::RestitutionLaw::newton) {
    return "energy gained: Newton's restitution with friction; see the docs page on friction";
  }
  return "energy gained: " + std::string(row_of(law).words) +
         " with friction (a case beyond the single-contact results); see the docs page on "
         "friction";
}

friction::Slip detail::slip_of(const multipoint::Body& bumper, const multipoint::Body& wedge,
                               const Eigen::Vector2d& point, const Eigen::Vector2d& normal) {
  const Eigen::Vector2d relative =
      multipoint::point_velocity(bumper, point) - multipoint::point_velocity(wedge, point);
  return relative.dot(friction::tangent(normal)) != 0.0 ? friction::Slip::slip
                                                        : friction::Slip::stick;
}

std::vector<ContactColumn> detail::friction_columns(const Eigen::VectorXd& tangential,
                                                    std::vector<std::string> slip) {
  return {{"tangential", "tangential Fdt",
           std::vector<double>(tangential.data(), tangential.data() + tangential.size())},
          {"slip", "ends", std::move(slip)}};
}

std::string detail::law_words(const multipoint::Configuration& configuration,
                              const Options& options) {
  std::string mu;
  const std::size_t n = configuration.contacts().size();
  const bool same = std::all_of(options.friction.begin(), options.friction.end(),
                                [&](double x) { return x == friction_at(options, 0); });
  if (n == 1 || same) {
    mu = "friction " + number_text(friction_at(options, 0));
  } else {
    mu = "friction per contact";
  }
  return mu + ", " + std::string(row_of(options.restitution).words);
}

Outcome exact_single(Method method, const multipoint::Configuration& configuration,
                     const Paper& paper, const Options& options) {
  const std::span<const multipoint::Body> bodies = configuration.bodies();
  const multipoint::Contact& c = configuration.contacts()[0];
  const friction::ContactLaw law = detail::contact_law(configuration, options, 0);
  const friction::Collision one =
      friction::collide(bodies[c.bumper], bodies[c.wedge], c.point, c.normal, law);
  const friction::ContactImpulse& p = one.impulse;
  Outcome o;
  o.method = method;
  o.after.assign(bodies.begin(), bodies.end());
  o.finite = p.status != friction::ContactStatus::non_finite && std::isfinite(p.normal) &&
             std::isfinite(p.tangential);
  if (p.status == friction::ContactStatus::resolved) {
    o.after[c.bumper] = one.after.bumper;
    o.after[c.wedge] = one.after.wedge;
  }
  o.Fdt = Eigen::VectorXd::Constant(1, p.normal);
  o.on_bumper = {friction::on_bumper(c.normal, p)};
  o.per_contact = detail::friction_columns(Eigen::VectorXd::Constant(1, p.tangential),
                                           {std::string(friction::to_string(p.outcome))});
  if (!o.finite) {
    return o;
  }
  o.residual = paper.system.residual(o.Fdt);
  if (p.status == friction::ContactStatus::cannot_stop) {
    o.finished = false;
    o.unfinished = detail::contact_name(options, 0) +
                   ": the exact single-contact rule cannot stop the approach (the contact's "
                   "inverse mass matrix is singular)";
  }
  o.details.push_back(
      "one contact, by the exact single-contact rule (followed through the "
      "normal impulse): " +
      detail::law_words(configuration, options) + ", elasticity " +
      number_text(law.elasticity.value()));
  o.details.push_back(detail::contact_name(options, 0) + ": " + phases_text(p));
  o.summary = "exact rule: " + phases_text(p);
  std::vector<double> ends;
  std::string regimes;
  for (const friction::Phase& phase : p.phases()) {
    ends.push_back(phase.end);
    regimes.append(regimes.empty() ? "" : ", ").append(friction::to_string(phase.regime));
  }
  o.diagnostics = {{"restitution", std::string(name_of(law.restitution))},
                   {"friction", law.friction},
                   {"elasticity", law.elasticity.value()},
                   {"phases", regimes},
                   {"phase_ends", ends},
                   {"compression", p.compression},
                   {"work_compression", p.work_compression},
                   {"work_restitution", p.work_restitution},
                   {"work_tangential", p.work_tangential}};
  const double before = multipoint::kinetic_energy(bodies);
  const double after = multipoint::kinetic_energy(o.after);
  if (law.elasticity.value() <= 2.0 && detail::energy_gained(before, after)) {
    o.warnings.push_back(detail::energy_gained_warning(law.restitution));
  }
  return o;
}

}  // namespace impulse::methods
