// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/resolve.hpp"

#include <string>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"

namespace impulse::methods {

Paper paper(const multipoint::Configuration& configuration, const SolverOptions& options) {
  Paper p{configuration.assemble(), Solution{}};
  p.solution = solve(p.system, options);
  return p;
}

Outcome simultaneous(const multipoint::Configuration& configuration, const Paper& paper) {
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
  if (has_contact_law(options)) {
    // Beyond the paper: friction, or a restitution law other than Newton's.
    if (const std::string why = unsupported(method, configuration, options); !why.empty()) {
      throw InvalidInput(why);
    }
    if (configuration.contacts().size() == 1) {
      return exact_single(method, configuration, paper, options);
    }
    return method == Method::complementarity
               ? complementarity_friction(configuration, paper, options)
               : serial_exact(configuration, paper, options);
  }
  switch (method) {
    case Method::complementarity:
      return complementarity(configuration, paper, options);
    case Method::serial:
      return serial(configuration, paper, options);
    case Method::simultaneous:
      break;
  }
  return simultaneous(configuration, paper);
}

std::string detail::contact_name(const Options& options, Eigen::Index v) {
  return options.contact_name ? options.contact_name(v) : "contact " + std::to_string(v);
}

}  // namespace impulse::methods
