// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/resolve.hpp"

#include <algorithm>
#include <cassert>
#include <string>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"

namespace impulse::methods {

namespace {

// "the method "simultaneous" cannot resolve 3 contacts with friction (contacts[0] has 0.5) and
// Poisson's restitution: WHY; the serial method … resolves each collision by the exact rule".
std::string cannot_resolve(Method method, const multipoint::Configuration& configuration,
                           const Options& options, std::string_view why) {
  std::string what;
  for (std::size_t v = 0; v < options.friction.size(); ++v) {
    if (options.friction[v] > 0.0) {
      what = "friction (contacts[" + std::to_string(v) + "] has " +
             number_text(options.friction[v]) + ")";
      break;
    }
  }
  if (options.restitution != friction::RestitutionLaw::newton) {
    what.append(what.empty() ? "" : " and ").append(row_of(options.restitution).words);
  }
  std::string text = "the method \"" + std::string(name_of(method)) + "\" cannot resolve " +
                     std::to_string(configuration.contacts().size()) + " contacts with " + what +
                     ": ";
  return text.append(why).append(
      "; the serial method (solver.method \"serial\", or --method serial) resolves each "
      "collision by the exact single-contact rule");
}

// Whether the exact rule is needed at more than one contact.
bool law_at_several(const multipoint::Configuration& configuration, const Options& options) {
  return configuration.contacts().size() > 1 &&
         has_contact_law(options.friction, options.restitution);
}

}  // namespace

Paper paper(const multipoint::Configuration& configuration, const SolverOptions& options) {
  Paper p{configuration.assemble(), Solution{}};
  p.solution = solve(p.system, options);
  return p;
}

bool has_contact_law(std::span<const double> friction, friction::RestitutionLaw law) {
  return law != friction::RestitutionLaw::newton ||
         std::any_of(friction.begin(), friction.end(), [](double mu) { return mu > 0.0; });
}

std::string detail::simultaneous_unsupported(const multipoint::Configuration& configuration,
                                             const Options& options) {
  if (!law_at_several(configuration, options)) {
    return {};
  }
  return cannot_resolve(Method::simultaneous, configuration, options,
                        "the paper's simultaneous system has no friction and only Newton's law");
}

std::string detail::complementarity_unsupported(const multipoint::Configuration& configuration,
                                                const Options& options) {
  if (!law_at_several(configuration, options)) {
    return {};
  }
  const std::size_t n = configuration.contacts().size();
  if (options.restitution != friction::RestitutionLaw::newton) {
    return cannot_resolve(Method::complementarity, configuration, options,
                          "the complementarity method applies Newton's law only (it solves all "
                          "contacts at once, with no end of compression, which " +
                              std::string(row_of(options.restitution).words) + " needs)");
  }
  if (static_cast<Eigen::Index>(n) <= friction_pivoting_limit) {
    return {};
  }
  return "the method \"complementarity\" with friction pivots on 4 unknowns per contact, at most " +
         std::to_string(friction_pivoting_limit) + " contacts, got " + std::to_string(n) +
         "; the serial method (solver.method \"serial\", or --method serial) resolves each "
         "collision by the exact single-contact rule";
}

std::string detail::always_supported(const multipoint::Configuration& /*configuration*/,
                                     const Options& /*options*/) {
  return {};
}

Outcome simultaneous(const multipoint::Configuration& configuration, const Paper& paper,
                     const Options& /*options*/) {
  const Solution& s = paper.solution;
  Outcome o;
  o.method = Method::simultaneous;
  o.finite = s.status == SolveStatus::success;
  o.Fdt = s.Fdt;
  o.residual = s.residual;
  o.after = o.finite ? configuration.after(s.Fdt)
                     : std::vector<multipoint::Body>(configuration.bodies().begin(),
                                                     configuration.bodies().end());
  o.summary = "rank " + std::to_string(s.rank) + " of " + std::to_string(s.B.size()) +
              ", residual |A·Fdt - B| " + number_text(s.residual);
  return o;
}

Outcome resolve(Method method, const multipoint::Configuration& configuration, const Paper& paper,
                const Options& options) {
  const MethodRow& row = row_of(method);
  if (!has_contact_law(options.friction, options.restitution)) {
    return row.resolve(configuration, paper, options);
  }
  if (configuration.contacts().size() == 1) {
    return exact_single(method, configuration, paper, options);
  }
  assert(row.resolve_with_law != nullptr);  // the row's `unsupported` refuses the rest
  return row.resolve_with_law(configuration, paper, options);
}

std::string detail::contact_name(const Options& options, Eigen::Index v) {
  return options.contact_name ? options.contact_name(v) : "contact " + std::to_string(v);
}

}  // namespace impulse::methods
