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

}  // namespace impulse::derivations
