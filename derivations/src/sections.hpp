// SPDX-License-Identifier: GPL-3.0-or-later
// What the section files share, and what the tests reach into: the transcriptions of a few
// printed statements and the functions that judge a candidate statement, so that a test can hand
// them a deliberately wrong one.
#pragma once

#include <ginac/ginac.h>

#include <vector>

#include "derivations/check.hpp"
#include "many.hpp"
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

/// The numeric findings on a system assembled from printed coefficients (sections 4 and 5), over
/// random scenes (with rigid bodies when `rigid`, and static bodies): solved, it keeps the energy
/// (elastic) or equalises every contact (inelastic); it equals A = J M^-1 J^T and B = J (e v)
/// built from the contact Jacobian; and the library's multipoint::assemble gives the same.
std::vector<Finding> printed_system_findings(
    const Context& context, bool rigid, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::string& scenes);

/// Shorthand to build checks.
Check make_check(std::string id, std::string section, std::optional<std::string> equation,
                 Kind kind, std::string statement, std::function<Outcome(const Context&)> evaluate);

}  // namespace impulse::derivations
