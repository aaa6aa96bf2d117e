// SPDX-License-Identifier: GPL-3.0-or-later
// Calculus in a derivation file: the functions a file declares (`function: F`) as GiNaC
// functions without a formula, their derivatives, sums and products over an index whose limits
// are not numbers, and integrals done where a formula is known (polynomials, sines, cosines and
// exponentials of linear arguments times polynomials, one over a linear expression, the
// derivative of a function: the fundamental theorem). What cannot be done stays an integral: an
// unknown quantity the exact method reasons about as a whole (calculus.cpp's atoms), never a
// guess.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impulse::derivations::file {

/// Σ over an index whose limits are not both numbers: body, index symbol, lower, upper.
DECLARE_FUNCTION_4P(indexed_sum)
/// Π likewise.
DECLARE_FUNCTION_4P(indexed_product)

/// The GiNaC function that stands for a file's function @p name of @p arguments arguments
/// (registered once per name and count, printed as @p latex).
[[nodiscard]] unsigned abstract_function(const std::string& name, const std::string& latex,
                                         unsigned arguments);
/// Whether @p e is a declared function's value F(a) or one of its derivatives.
[[nodiscard]] bool is_abstract(const GiNaC::ex& e);
/// Whether @p e holds a declared function, an integral left undone, or a sum or product over
/// an index with limits that are not numbers.
[[nodiscard]] bool has_atoms(const GiNaC::ex& e);

/// Σ_{index = lower}^{upper} body for limits that are not both whole numbers (those are written
/// out by the meaning layer): indexed_sum, with the terms that do not depend on the index taken
/// out, Σ (c a_i + b) = c Σ a_i + (upper - lower + 1) b. @p depends says whether an expression
/// depends on the index.
[[nodiscard]] GiNaC::ex sum_over(const GiNaC::ex& body, const GiNaC::ex& index,
                                 const GiNaC::ex& lower, const GiNaC::ex& upper,
                                 const std::function<bool(const GiNaC::ex&)>& depends);
/// Π likewise (factors that do not depend on the index come out as powers of the count).
[[nodiscard]] GiNaC::ex product_over(const GiNaC::ex& body, const GiNaC::ex& index,
                                     const GiNaC::ex& lower, const GiNaC::ex& upper,
                                     const std::function<bool(const GiNaC::ex&)>& depends);

/// The sign of an expression as far as it is known: 1, -1, or 0 when unknown.
using SignOf = std::function<int(const GiNaC::ex&)>;

/// ∫_a^b f dx where a formula is known, else the integral left undone (GiNaC::integral). A pole
/// between limits that are not numbers is ruled out by @p sign when given (the base of 1/m
/// positive at both limits m_f and m_0 > 0).
[[nodiscard]] GiNaC::ex integrate(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::ex& a,
                                  const GiNaC::ex& b, const SignOf& sign = {});
/// @p e with each integral left undone done again where @p sign rules out a pole.
[[nodiscard]] GiNaC::ex integrals_by_sign(const GiNaC::ex& e, const SignOf& sign);

/// A declared function written out by an equation: F(v) = value (v its variable), from an
/// equation that holds for every v (it names F at its variable: F(t) = m \frac{dv}{dt}).
struct Rule {
  unsigned serial = 0;
  std::size_t order = 0;  ///< 0: F itself; 1: its derivative F' (\dot x = v_0 - g t), …
  GiNaC::ex variable;
  GiNaC::ex value;
};

/// Whether a symbol is a declared variable of the function with this serial.
using IsVariable = std::function<bool(unsigned serial, const GiNaC::ex& symbol)>;

/// The rules the equations give: each equation linear in one function's value at its variable,
/// with a number as the coefficient, defines that function.
[[nodiscard]] std::vector<Rule> rules_of(const std::vector<GiNaC::ex>& equations,
                                         const IsVariable& is_variable);

/// @p e with every value and derivative of a function a rule defines replaced by the rule's
/// value there, and its integrals done again.
[[nodiscard]] GiNaC::ex rewritten(const GiNaC::ex& e, const std::vector<Rule>& rules);

/// The variables at which @p e names a declared function (F(t): t, a declared variable of F),
/// where it holds for every value of them. (p(T) names p at T alone.)
[[nodiscard]] std::vector<GiNaC::ex> function_variables(const GiNaC::ex& e,
                                                        const IsVariable& is_variable);

/// Every atom of @p e (declared functions' values and derivatives, integrals left undone,
/// indexed sums and products) replaced by a symbol of its own, one per distinct atom, and back.
class Atoms {
 public:
  /// @p e with its atoms replaced.
  [[nodiscard]] GiNaC::ex hide(const GiNaC::ex& e);
  /// @p e with the atoms' symbols replaced by the atoms again.
  [[nodiscard]] GiNaC::ex show(const GiNaC::ex& e) const;
  /// Whether any atom was replaced.
  [[nodiscard]] bool any() const { return !forward_.empty(); }
  /// The atoms' symbols and the atoms.
  [[nodiscard]] const GiNaC::exmap& back() const { return backward_; }

 private:
  // The symbol of the atom @p e, found by @p key (e itself, or an integral's one form).
  GiNaC::ex hide_as(const GiNaC::ex& key, const GiNaC::ex& e);

  GiNaC::exmap forward_;   // atom → its symbol
  GiNaC::exmap backward_;  // symbol → the atom
};

/// A choice of formulas for a file's functions (F(u) = 1 + 2u, …) and of values for the limits
/// of its indexed sums, under which an expression is an ordinary one: what the exact method
/// tries to show that a step with functions or sums fails (a counterexample must be a real one).
struct Instance {
  std::map<unsigned, GiNaC::ex> formulas;  ///< function serial → formula in instance_variable()
  GiNaC::exmap limits;                     ///< a sum's limit symbol → a whole number
  std::string text;                        ///< "F(u) = 1 + 2 u, N = 3", for the report
};

/// The variable of an instance's formulas.
[[nodiscard]] const GiNaC::symbol& instance_variable();

/// The instances to try, at most @p most, in order: small polynomial formulas for each function
/// of @p expressions (1, u, u^2, 1 + u, …) and the values 2, 3, 1 for each symbol that is the
/// limit of an indexed sum.
[[nodiscard]] std::vector<Instance> instances(const std::vector<GiNaC::ex>& expressions,
                                              std::size_t most);

/// Writes out an indexed sum's body at a value of its index (the symbols indexed by it renamed:
/// m_i at i = 2 is m_2).
using AtIndex = std::function<GiNaC::ex(const GiNaC::ex& body, const GiNaC::ex& index, long value)>;

/// @p e under an instance: each function its formula (derivatives differentiated), each sum
/// with whole limits written out by @p at_index, integrals done.
[[nodiscard]] GiNaC::ex instantiate(const GiNaC::ex& e, const Instance& instance,
                                    const AtIndex& at_index);

}  // namespace impulse::derivations::file
