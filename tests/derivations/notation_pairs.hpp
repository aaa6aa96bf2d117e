// SPDX-License-Identifier: GPL-3.0-or-later
// Two writings checked against each other, for the tests of the notation (notation_test.cpp,
// students_notation_test.cpp): "$$left = c$$ then $$right = c$$". A pair the contract calls the
// same must give "follows" and can fail: were the two read as different symbols or values, the
// step would not follow and a counterexample would show it.
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "budget.hpp"
#include "derivations/derivation.hpp"

namespace impulse::test {

/// The verdicts of a derivation file's equations, in order.
inline std::vector<std::string> verdicts(const std::string& text) {
  const derivations::DerivationReport report =
      derivations::check_derivation(text, "notation.md", pinned_options());
  std::vector<std::string> list;
  for (const auto& e : report.equations) {
    list.push_back(std::string(derivations::to_string(e.verdict)));
  }
  return list;
}

/// The second writing follows from the first, and back.
inline void same(const std::string& left, const std::string& right, const std::string& setup = "") {
  INFO(left << "  vs  " << right);
  CHECK(verdicts(setup + "\n$$" + left + " = c$$\n\n$$" + right + " = c$$\n") ==
        std::vector<std::string>{"premise", "follows"});
}

/// The second writing does not follow from the first.
inline void different(const std::string& left, const std::string& right,
                      const std::string& setup = "") {
  INFO(left << "  vs  " << right);
  CHECK(verdicts(setup + "\n$$" + left + " = c$$\n\n$$" + right + " = c$$\n") ==
        std::vector<std::string>{"premise", "does-not-follow"});
}

}  // namespace impulse::test
