// SPDX-License-Identifier: GPL-3.0-or-later
// What the reader of the Markdown report and of the documentation site sees of an outcome: a
// counterexample (plain words in Outcome::counterexample) with its values and relations set as
// math, and an erratum's printed form and correction with the terms that differ marked. The
// Markdown report (render.cpp) and the site's pages (docs/tools/site.cpp) show the same thing.
#pragma once

#include <string>
#include <string_view>

namespace impulse::derivations::typeset {

/// @brief LaTeX of math written in plain words as a counterexample writes it ("E_k1 + E_k2 - E_k'",
/// "F̄ = 0.5", "exists rho > 10^-9", "a_v1(elastic)", "1.24643e-17"): subscripts braced, Greek
/// letters and ≤ ≥ ≠ · ⇒ × as commands, a combining macron, tilde or hat as \\bar, \\tilde, \\hat,
/// names of several letters as \\mathit (sum, exists, det and Greek names as commands), numbers
/// in e-notation as powers of ten.
/// @param plain the plain text of a formula
/// @return its LaTeX
[[nodiscard]] std::string latex_of_plain(std::string_view plain);

/// @brief A counterexample as Doxygen Markdown: each value and relation in its own inline formula
/// (\\f$ … \\f$, so that a long list wraps between them), the words between them as words. The
/// shapes the checker writes ("VALUES gives RELATION fails (its sides: A and B)", "none of N cases
/// searched satisfies RELATION; e.g. …", "VALUES (exact)") are recognised; any other text is
/// returned as it is.
/// @param plain Outcome::counterexample
/// @return the Markdown
[[nodiscard]] std::string counterexample_markdown(std::string_view plain);

/// @brief Whether a counterexample only reports a search that found no case of an existence claim
/// ("none of N cases searched satisfies …"): the refutation then rests on the argument of the
/// check's explanation, not on a case.
/// @param plain Outcome::counterexample
/// @return whether it is a search that found nothing
[[nodiscard]] bool refuted_by_argument(std::string_view plain);

/// @brief An erratum's printed form and its correction with the terms that differ marked.
struct Marked {
  std::string printed;    ///< the printed form, the terms the correction does not keep boxed
  std::string corrected;  ///< the correction, the terms the printed form does not have boxed
  bool changed = false;   ///< whether any term was marked
};

/// @brief Compares two formulas term by term (the terms between relations, row breaks, column
/// separators and the signs + and - outside any bracket) and boxes (\\boxed) the terms that are in
/// one and not in the other. Two terms are the same when they differ only in spacing, in braces
/// around a single symbol, in \\operatorname{…} or \\mathrm{d} around a name, or in
/// \\left/\\right.
/// @param printed LaTeX of the printed form (its \\tag is kept, never marked)
/// @param corrected LaTeX of the correction
/// @return both, marked
[[nodiscard]] Marked mark_changes(std::string_view printed, std::string_view corrected);

}  // namespace impulse::derivations::typeset
