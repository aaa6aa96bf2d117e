// SPDX-License-Identifier: GPL-3.0-or-later
// The facts of `assume:` (signs of symbols) and what they prove about an expression's sign: a
// product of non-zero factors is non-zero, a sum of positive terms is positive, an even power of
// a non-zero quantity is positive. Nothing else is inferred: a fact the rules cannot show is
// "unknown", never assumed.
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <string>

namespace impulse::derivations::file {

/// What is known of a quantity's sign.
enum class Sign {
  unknown,
  positive,     ///< > 0
  negative,     ///< < 0
  nonnegative,  ///< ≥ 0
  nonpositive,  ///< ≤ 0
  nonzero,      ///< ≠ 0
  zero,         ///< = 0 (numbers only)
};

/// The LaTeX relation of a sign fact about @p what ("m_1 > 0").
[[nodiscard]] std::string relation_latex(const std::string& what, Sign sign);

/// Facts on the signs of symbols.
class Facts {
 public:
  /// Adds a fact; facts on one symbol combine (≥ 0 and ≠ 0 give > 0). Returns false when the
  /// new fact contradicts an earlier one (x > 0 then x < 0).
  bool add(const GiNaC::ex& symbol, Sign sign);
  /// The fact on a symbol (unknown if none).
  [[nodiscard]] Sign of_symbol(const GiNaC::ex& symbol) const;
  /// What the facts prove about the sign of @p e.
  [[nodiscard]] Sign sign(const GiNaC::ex& e) const;
  /// Whether the facts prove @p e ≠ 0.
  [[nodiscard]] bool nonzero(const GiNaC::ex& e) const;
  /// Whether a number satisfies the fact on @p symbol.
  [[nodiscard]] bool satisfied(const GiNaC::ex& symbol, const GiNaC::numeric& value) const;
  /// Every fact, by symbol.
  [[nodiscard]] const std::map<GiNaC::ex, Sign, GiNaC::ex_is_less>& all() const { return signs_; }

 private:
  std::map<GiNaC::ex, Sign, GiNaC::ex_is_less> signs_;
};

}  // namespace impulse::derivations::file
