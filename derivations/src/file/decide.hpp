// SPDX-License-Identifier: GPL-3.0-or-later
// The exact method: does an equation follow from others, under sign facts? Each equation is an
// expression equal to zero. The premises are brought to polynomials; a premise that factors is
// split into its cases (F·(…) = 0: F = 0 or … = 0), one that is linear in a symbol is solved for
// it and substituted; what is left of the step must vanish. A verdict of failure always carries
// a point (exact numbers) that satisfies the premises and the facts but not the step; a needed
// condition (a factor that may be zero) is tested by adding "it is zero" as a premise.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

#include "file/clock.hpp"
#include "file/facts.hpp"

namespace impulse::derivations::file {

/// Premises and one target, each an expression equal to zero.
struct Problem {
  std::vector<GiNaC::ex> premises;
  std::vector<GiNaC::ex> premise_denominators;  ///< must not vanish where the premises are read
  GiNaC::ex target;
  std::vector<GiNaC::ex> target_denominators;  ///< must not vanish where the step is read
};

/// What the exact method found.
struct Implication {
  enum class Outcome {
    holds,     ///< the target vanishes wherever the premises do (and the facts hold)
    holds_if,  ///< … wherever, besides, each condition ≠ 0
    fails,     ///< a point satisfies the premises and the facts, not the target
    unknown,   ///< none of the above could be shown
  };
  Outcome outcome = Outcome::unknown;
  std::vector<GiNaC::ex> conditions;  ///< holds_if: each must not be zero
  /// holds_if: signs that symbols must have besides, which the facts do not give (where the rules
  /// of roots and logarithms need them: \ln(a b) = \ln a + \ln b for a, b > 0)
  std::vector<std::pair<GiNaC::ex, Sign>> signs;
  bool conditions_needed = true;  ///< whether every condition was shown to be needed
  GiNaC::ex residual;             ///< fails, unknown: the target once the premises are used
  /// fails: exact values of every symbol; holds_if, when one was found: values where a
  /// condition is zero, the premises and the facts hold and the target does not
  std::optional<GiNaC::exmap> point;
  std::string how;  ///< a sentence for the report
};

/// The exact method's work limits: beyond them it answers "unknown", never a guess.
struct Budget {
  std::size_t frames = 96;     ///< cases and substitutions explored
  double terms = 4000;         ///< terms of an expanded polynomial
  std::size_t attempts = 160;  ///< candidate points for a counterexample
  std::size_t candidates = 6;  ///< counterexamples found before the simplest is chosen
  /// When the step's time runs out: past it, the search answers "unknown".
  WorkClock::time_point deadline = WorkClock::time_point::max();
};

/// @p e simplified where the facts allow it: \sqrt{V^2} is V when V > 0 (-V when V < 0, |V|
/// otherwise), (b^k)^n is b^{k n} and \ln(a b^k) is \ln a + k \ln b for positive a and b.
[[nodiscard]] GiNaC::ex by_facts(const GiNaC::ex& e, const Facts& facts);

/// The numerator of @p e over one denominator, or @p e itself when bringing it over one
/// denominator would expand more than @p terms terms (then @p e is taken as it stands).
[[nodiscard]] GiNaC::ex safe_numerator(const GiNaC::ex& e, double terms = 4000);

/// Whether @p point shows @p problem's target failing, as a counterexample of implies() must:
/// the facts and the premises hold there, nothing is divided by zero, and the target is
/// certainly not zero (values taken exactly, or in 40 digits).
[[nodiscard]] bool fails_at(const Problem& problem, const Facts& facts, const GiNaC::exmap& point);

/// Decides whether @p problem's target follows from its premises under @p facts.
[[nodiscard]] Implication implies(const Problem& problem, const Facts& facts,
                                  const Budget& budget = {});

/// An upper estimate of the terms of @p e once expanded (for the size guard).
[[nodiscard]] double expanded_terms(const GiNaC::ex& e);
/// The most terms an expression may expand into for the work around a verdict (a residual brought
/// over one denominator, a function's rule read from an equation); a larger one is left as it is.
inline constexpr double most_expanded_terms = 4000;

/// @p e with π as a symbol: GiNaC's polynomial algorithms (factor, divide, rem) take rational
/// coefficients only, and π, transcendental, factors and divides as a symbol does.
[[nodiscard]] GiNaC::ex pi_as_symbol(const GiNaC::ex& e);
/// @p e with the symbol of pi_as_symbol() as π again.
[[nodiscard]] GiNaC::ex symbol_as_pi(const GiNaC::ex& e);
/// The quotient @p dividend / @p divisor when it is a polynomial (π taken as a symbol); none when
/// the division leaves a remainder or either is not a polynomial (a root, a function).
[[nodiscard]] std::optional<GiNaC::ex> exact_quotient(const GiNaC::ex& dividend,
                                                      const GiNaC::ex& divisor);

/// Whether @p e is small enough to factor: few terms, symbols and degrees (factoring a
/// polynomial of many symbols and high degrees can take minutes).
[[nodiscard]] bool factorable(const GiNaC::ex& e);

/// GiNaC's factorisation of @p e, each factor expanded: GiNaC 1.8 can leave terms that cancel
/// inside a factor of several variables ((e v + v) m - 10 (1 + e) m + 10 e m + 10 m - J), which
/// a reader would be shown and which hide the factor's sign from the facts. Throws as
/// GiNaC::factor does.
[[nodiscard]] GiNaC::ex factored(const GiNaC::ex& e);

/// The factors of @p e (a polynomial) that the facts do not show to be non-zero, each once,
/// without numeric factors. Empty when @p e is a non-zero constant.
[[nodiscard]] std::vector<GiNaC::ex> doubtful_factors(const GiNaC::ex& e, const Facts& facts);

}  // namespace impulse::derivations::file
