// SPDX-License-Identifier: GPL-3.0-or-later
// What the section files share, and what the tests reach into: the transcriptions of a few
// printed statements and the functions that judge a candidate statement, so that a test can hand
// them a deliberately wrong one.
#pragma once

#include <ginac/ginac.h>

#include <vector>

#include "derivations/check.hpp"
#include "symbolic.hpp"
#include "verdict.hpp"

namespace impulse::derivations {

/// Section 1's symbols: body 1 moves towards body 2 with momentum p1; p2 is body 2's momentum
/// towards body 1 (the paper's sign convention); Fdt is the impulse magnitude.
struct LineSymbols {
  GiNaC::possymbol m1{"m1", "m_1"};
  GiNaC::possymbol m2{"m2", "m_2"};
  GiNaC::realsymbol p1{"p1", "p_1"};
  GiNaC::realsymbol p2{"p2", "p_2"};
  GiNaC::realsymbol F{"Fdt", "F\\,dt"};
  GiNaC::realsymbol e1{"e1", "elasticity_1"};
  GiNaC::realsymbol e2{"e2", "elasticity_2"};
};
const LineSymbols& line_symbols();

/// (1.1) as printed, and the findings on any candidate for it: substituted into energy
/// conservation (symbolic), evaluated on random bodies (numeric).
sym::Equation printed_1_1();
std::vector<Finding> elastic_line_findings(const sym::Equation& candidate, const Context& context);

/// Shorthand to build checks.
Check make_check(std::string id, std::string section, std::optional<std::string> equation,
                 Kind kind, std::string statement, std::function<Outcome(const Context&)> evaluate);

}  // namespace impulse::derivations
