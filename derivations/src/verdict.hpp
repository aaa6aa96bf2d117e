// SPDX-License-Identifier: GPL-3.0-or-later
// From what each method found to a check's status. The rules are the same for every check:
// nothing here knows which statements are right.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derivations/check.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

/// What one method found about one statement.
struct Finding {
  Method method;
  bool holds = false;
  std::optional<double> error;  ///< worst relative error (numeric methods)
  std::size_t samples = 0;
  std::string detail;      ///< a sentence for the note
  bool conclusive = true;  ///< false when a numeric error fell between the thresholds
};

/// A symbolic finding.
Finding symbolic(bool holds, std::string detail = {});

/// A numeric finding from a run of samples: holds when the worst error is at most `holds_below`
/// (default num::holds_below), fails when it is at least num::fails_above, inconclusive between.
Finding numeric(Method method, const num::Errors& errors, double holds_below = num::holds_below,
                std::string detail = {});

/// A search for counterexamples: holds when none of the `tried` cases failed.
Finding search(std::size_t tried, std::size_t failures, std::string detail = {});

/// An equation or a step: verified when every finding on the printed statement holds; an
/// erratum when every finding on it fails and every finding on the correction holds; failed
/// otherwise (the findings disagree, or a correction is missing or does not hold).
struct EquationVerdict {
  std::vector<Finding> printed;
  std::vector<Finding> corrected;
  std::string correction;   ///< LaTeX of the corrected statement
  std::string explanation;  ///< what goes wrong, for an erratum
  std::string note;
};
Outcome judge(const EquationVerdict& verdict);

/// A claim: refuted when a counterexample was found, some finding fails and no symbolic finding
/// proves the claim; verified when every finding holds and no counterexample was found; failed
/// otherwise.
struct ClaimVerdict {
  std::vector<Finding> findings;
  std::optional<std::string> counterexample;
  std::string explanation;  ///< what goes wrong, for a refuted claim
  std::string note;
};
Outcome judge(const ClaimVerdict& verdict);

}  // namespace impulse::derivations
