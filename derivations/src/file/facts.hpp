// SPDX-License-Identifier: GPL-3.0-or-later
// The facts of `assume:` and what they prove about an expression's sign. A fact is the sign of
// a symbol (m > 0), the sign of an expression (m_1 + m_2 > 0, b - a > 0 for a < b; a range
// 0 \le e \le 1 is two of them and bounds e), or an equality (a unit vector: n_x^2 + n_y^2 = 1).
// What they prove: a product of non-zero factors is non-zero, a sum of positive terms is
// positive, an even power of a non-zero quantity is positive, an expression that is a fact has
// its sign, and the range of an expression computed from the bounds of its symbols (sines and
// cosines between -1 and 1) decides where it excludes zero. Nothing else is inferred: what the
// rules cannot show is "unknown", never assumed.
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

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

/// The same in plain text ("m_1 >= 0").
[[nodiscard]] std::string relation_text(const std::string& what, Sign sign);

/// Whether a quantity of sign @p known has sign @p needed too (> 0 gives ≥ 0 and ≠ 0).
[[nodiscard]] bool gives(Sign known, Sign needed);

/// The sign a quantity has where it has not @p sign (> 0: ≤ 0); unknown for ≠ 0 and = 0.
[[nodiscard]] Sign opposite(Sign sign);

/// Facts on the signs of symbols and expressions, and equalities.
class Facts {
 public:
  /// Adds a fact; facts on one symbol combine (≥ 0 and ≠ 0 give > 0). Returns false when the
  /// new fact contradicts an earlier one (x > 0 then x < 0).
  bool add(const GiNaC::ex& symbol, Sign sign);
  /// Adds a fact on an expression (e > 0, e ≥ 0, e ≠ 0, …). A fact on a symbol plus or minus
  /// a number also bounds the symbol (e - 1 \leq 0: e \leq 1).
  void add_relation(const GiNaC::ex& e, Sign sign);
  /// Adds an equality e = 0 (a unit vector's n_x^2 + n_y^2 - 1).
  void add_equality(const GiNaC::ex& e);

  /// The fact on a symbol (unknown if none).
  [[nodiscard]] Sign of_symbol(const GiNaC::ex& symbol) const;
  /// What the facts prove about the sign of @p e.
  [[nodiscard]] Sign sign(const GiNaC::ex& e) const;
  /// Whether the facts prove @p e ≠ 0.
  [[nodiscard]] bool nonzero(const GiNaC::ex& e) const;
  /// Whether @p symbol's lower bound (or, with @p high, its upper bound) is strict: x > 0, not
  /// x ≥ 0. False when it has none.
  [[nodiscard]] bool strict_bound(const GiNaC::ex& symbol, bool high) const;
  /// Whether a number satisfies the facts on @p symbol (its sign and its bounds).
  [[nodiscard]] bool satisfied(const GiNaC::ex& symbol, const GiNaC::numeric& value) const;
  /// Whether a point (every symbol of the facts it names) satisfies the facts on expressions
  /// and the equalities; symbols the point does not give are not judged.
  [[nodiscard]] bool satisfied(const GiNaC::exmap& point) const;
  /// The same at a point of doubles (equalities within a relative 1e-9), and the sign of each
  /// symbol of the point.
  [[nodiscard]] bool satisfied_numerically(const std::vector<GiNaC::ex>& symbols,
                                           const std::vector<double>& values) const;
  /// The bounds of a symbol as the facts write them (π/6, not its double), [low, high] (either
  /// may be absent): from ranges.
  [[nodiscard]] std::pair<std::optional<GiNaC::ex>, std::optional<GiNaC::ex>> exact_bounds(
      const GiNaC::ex& symbol) const;
  /// The bounds of a symbol, [low, high] (either may be absent): from ranges.
  [[nodiscard]] std::pair<std::optional<double>, std::optional<double>> bounds(
      const GiNaC::ex& symbol) const;
  /// An end of a symbol's values, exact: where it is, and whether it is left out (x > a).
  struct End {
    GiNaC::ex at;
    bool strict = false;
  };
  /// The ends of a symbol's values, [low, high] (either may be absent): of each side, the tighter
  /// of its bound as written and 0 from its sign (θ ≥ 0 with θ > -π/6 has the low end 0).
  [[nodiscard]] std::pair<std::optional<End>, std::optional<End>> exact_ends(
      const GiNaC::ex& symbol) const;

  /// Every fact on a symbol.
  [[nodiscard]] const std::map<GiNaC::ex, Sign, GiNaC::ex_is_less>& all() const { return signs_; }
  /// Every fact on an expression.
  [[nodiscard]] const std::vector<std::pair<GiNaC::ex, Sign>>& relations() const {
    return relations_;
  }
  /// Every equality.
  [[nodiscard]] const std::vector<GiNaC::ex>& equalities() const { return equalities_; }

  /// A copy where the facts on symbols named in @p renamed (a symbol, the symbol it came from)
  /// hold for the new symbols too (m_i > 0 gives m_2 > 0).
  [[nodiscard]] Facts carried(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& renamed) const;

 private:
  [[nodiscard]] Sign structural(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_relation(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_range(const GiNaC::ex& e) const;
  /// sin, cos or tan (@p function: 's', 'c', 't') at the ends @p low_end and @p high_end of the
  /// range of @p argument, a symbol with bounds or a rational multiple of one, where they are
  /// numbers a double holds exactly (sin π/6 = 1/2, tan π/4 = 1).
  [[nodiscard]] std::pair<std::optional<double>, std::optional<double>> exact_wave_ends(
      const GiNaC::ex& argument, char function, double low_end, double high_end) const;
  [[nodiscard]] Sign through_relation(const GiNaC::ex& x) const;
  [[nodiscard]] Sign of_linear_facts(const GiNaC::ex& e) const;
  [[nodiscard]] Sign derived_sign(const GiNaC::ex& symbol) const;
  [[nodiscard]] Sign of_quadratic(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_zeros(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_roots_outside(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_zero_only_at_origin(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_increasing_difference(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_power_difference(const GiNaC::ex& e) const;
  [[nodiscard]] Sign of_wave_zeros(const GiNaC::ex& e) const;
  /// Whether every relation that can be judged at @p at holds (and, with @p all_judged, every
  /// relation can be).
  [[nodiscard]] bool relations_hold(const GiNaC::exmap& at, bool all_judged) const;
  /// Whether values of the symbols of the relations that @p point does not give (at most two)
  /// make every relation hold with it.
  [[nodiscard]] bool extends(const GiNaC::exmap& point) const;

  std::map<GiNaC::ex, Sign, GiNaC::ex_is_less> signs_;
  std::vector<std::pair<GiNaC::ex, Sign>> relations_;
  std::vector<GiNaC::ex> equalities_;
  std::map<GiNaC::ex, std::pair<std::optional<double>, std::optional<double>>, GiNaC::ex_is_less>
      bounds_;
  // Whether each bound is strict (a < b), by symbol: low, high.
  std::map<GiNaC::ex, std::pair<bool, bool>, GiNaC::ex_is_less> strict_;
  // exact_wave_ends' values by argument and function, each with where it is (the argument's end
  // as a double): the same sines of the same bounds are asked for again and again.
  struct WaveEnds {
    GiNaC::ex argument;
    char function;                                  // 's', 'c' or 't'
    std::optional<std::pair<double, double>> low;   // at, value
    std::optional<std::pair<double, double>> high;  // at, value
  };
  mutable std::vector<WaveEnds> wave_ends_;
  // derived_sign's answers, by symbol, until a fact is added.
  mutable std::map<GiNaC::ex, Sign, GiNaC::ex_is_less> derived_signs_;
  // Each bound as the fact writes it (π/6, not its double), by symbol: low, high.
  std::map<GiNaC::ex, std::pair<std::optional<GiNaC::ex>, std::optional<GiNaC::ex>>,
           GiNaC::ex_is_less>
      exact_bounds_;
};

/// @p value, a number or an expression in constants only (1 - π/2), as a number: itself, or
/// evaluated in 40 digits; nothing when it is not a number there.
[[nodiscard]] std::optional<GiNaC::numeric> value_in_40_digits(const GiNaC::ex& value);
/// Whether @p value (as value_in_40_digits takes it) is certainly a real number other than 0: a
/// rational other than 0, or beyond 1e-20 in 40 digits (a value in between is neither shown to be
/// 0 nor shown not to be).
[[nodiscard]] bool certainly_nonzero(const GiNaC::ex& value);

/// The symbols of an expression, in a stable order (by name).
[[nodiscard]] std::vector<GiNaC::ex> symbols_of(const GiNaC::ex& e);
/// The symbols of several expressions, each once, in a stable order (by name).
[[nodiscard]] std::vector<GiNaC::ex> symbols_of(const std::vector<GiNaC::ex>& expressions);

/// Whether a number has a sign (unknown: any number has it).
[[nodiscard]] bool has_sign(const GiNaC::numeric& v, Sign sign);

/// A definite quadratic form in two symbols, a x^2 + b x y + c y^2 with numbers b^2 - 4 a c < 0
/// (x^2 + x y + y^2, a factor of x^3 - y^3): 0 only where x = y = 0, elsewhere of the sign of a.
struct DefiniteForm {
  GiNaC::ex x;
  GiNaC::ex y;
  bool positive = true;
};
/// @p e as a definite quadratic form; else nothing.
[[nodiscard]] std::optional<DefiniteForm> definite_form(const GiNaC::ex& e);

/// @p argument as c x, a rational c ≠ 0 times a symbol x; else nothing.
[[nodiscard]] std::optional<std::pair<GiNaC::ex, GiNaC::numeric>> multiple_of_symbol(
    const GiNaC::ex& argument);

/// An argument c x + d: a rational c ≠ 0 times a symbol x, plus a real constant d (0, 1/2, -π/3).
struct Affine {
  GiNaC::ex symbol;
  GiNaC::numeric c;
  GiNaC::ex d;
};
/// @p argument as c x + d (Affine); else nothing.
[[nodiscard]] std::optional<Affine> affine_in_symbol(const GiNaC::ex& argument);

}  // namespace impulse::derivations::file
