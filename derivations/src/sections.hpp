// SPDX-License-Identifier: GPL-3.0-or-later
// Sections 4 and 5, still written in C++ (sections 1 to 3 are derivation files in
// derivations/paper/): each check is data plus a function that evaluates it. run() and
// all_checks() (file/paper.cpp) put them after the files' checks, in the paper's order.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <vector>

#include "derivations/check.hpp"
#include "models/scene.hpp"
#include "symbolic.hpp"
#include "verdict.hpp"

namespace impulse::derivations {

/// The run's settings as a C++ check sees them.
struct Context {
  std::size_t samples = 10000;  ///< random samples per numeric method
  std::uint64_t seed = 1;       ///< this check's seed (check_seed of the run's seed and the id)
  /// A share of the samples for a costlier method: samples / divisor, at least 1.
  [[nodiscard]] std::size_t share(std::size_t divisor) const {
    return samples / divisor > 0 ? samples / divisor : 1;
  }
};

/// A check of a section not yet written as a file: the check and the function that evaluates it.
struct CodedCheck {
  Check check;
  std::function<Outcome(const Context&)> evaluate;
};

/// Shorthand to build checks.
CodedCheck make_check(std::string id, std::string section, std::optional<std::string> equation,
                      Kind kind, std::string statement,
                      std::function<Outcome(const Context&)> evaluate);

/// Runs a check's function; an exception is a failed verdict with its message, never a crash.
Outcome evaluate(const CodedCheck& check, const Context& context);

/// The checks of sections 4 and 5, in the paper's order.
std::vector<CodedCheck> section4_checks();
std::vector<CodedCheck> section5_checks();
/// Section 5's ids in the paper's order: part of it is a file (derivations/paper/section5.md),
/// the rest still C++, and run() and all_checks() interleave the two in this order.
const std::vector<std::string>& section5_order();

/// The numeric findings on a system assembled from printed coefficients (sections 4 and 5), over
/// random scenes (with rigid bodies when `rigid`, and static bodies): solved, it keeps the energy
/// (elastic) or equalises every contact (inelastic); it equals A = J M^-1 J^T and B = J (e v)
/// built from the contact Jacobian; and the library's multipoint::assemble gives the same.
std::vector<Finding> printed_system_findings(
    const Context& context, bool rigid, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::string& scenes);
/// The same on scenes that @p draw produces, @p count of them.
std::vector<Finding> printed_system_findings(
    const Context& context, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::function<many::Scene(num::Random&)>& draw, const std::string& scenes,
    std::size_t count);

/// The paper's per-contact energies of body k at contact v (sections 4.1 and 5.1): with J_i the
/// impulses exchanged with the other body of contact v, K all of body k's impulses, both cast on
/// k's own normal at v: translational J_i (K/2 + p_v)/m, rotational d_v J_i (dL/2 + L)/I.
struct ContactEnergy {
  double translational = 0;
  double rotational = 0;
  double pair_impulse = 0;  ///< J_i, the impulses exchanged with the other body, cast on n_v
};
ContactEnergy contact_energy(const many::Scene& scene, const Eigen::VectorXd& F, std::size_t body,
                             std::size_t contact);

}  // namespace impulse::derivations
