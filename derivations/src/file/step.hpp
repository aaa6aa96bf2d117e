// SPDX-License-Identifier: GPL-3.0-or-later
// Deciding one equation of a derivation file: its dimensions, then the exact method (does it
// follow from the equations before, under the facts?) with the numeric method as a second
// opinion, into a verdict with its condition, residual or counterexample. Each step has a time
// budget; past it the step is undecided, with the reason.
#pragma once

#include <ginac/ginac.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "derivations/derivation.hpp"
#include "file/calculus.hpp"
#include "file/decide.hpp"
#include "file/reader.hpp"
#include "file/sample.hpp"

namespace impulse::derivations::file {

/// Calls @p each with the two sides of every scalar equation @p e stands for: each entry of a
/// block, both components of a vector, or the one scalar.
void for_each_scalar(const Equation& e,
                     const std::function<void(const GiNaC::ex&, const GiNaC::ex&)>& each);

/// The scalar equations an equation stands for (one per component or entry), each with the size
/// of its terms, read exactly (forces constant over the contact), and the denominators written
/// (with the LaTeX the file wrote them in).
struct Scalars {
  std::vector<GiNaC::ex> differences;  ///< each = 0
  std::vector<GiNaC::ex> scales;
  std::vector<GiNaC::ex> denominators;
  std::vector<std::string> written;  ///< each denominator as written ("" when unknown)
  void append(const Scalars& other);
};
[[nodiscard]] Scalars scalars_of(const Equation& e, const GiNaC::exmap& substitutions);

/// LaTeX of an expression, trimmed.
[[nodiscard]] std::string latex_of(const GiNaC::ex& e);
/// Plain text of an expression over one denominator ("4*p_2/m_2").
[[nodiscard]] std::string plain_of(const GiNaC::ex& e);

/// Decides equations.
class Checker {
 public:
  Checker(Symbols& symbols, const DerivationOptions& options)
      : symbols_(symbols), options_(options) {}

  /// The verdict on equations[index], checked against its own premises, or against
  /// @p premises when given (a correction's variant of an evidence step).
  EquationResult check(const std::vector<Equation>& equations, std::size_t index,
                       const Source& source, const std::vector<std::size_t>* premises = nullptr);

  /// Whether @p target follows from @p premises (under @p facts, within @p seconds); with
  /// @p both, whether they also follow from it (an equivalent equation: a task's target).
  [[nodiscard]] bool follows(const std::vector<const Equation*>& premises, const Equation& target,
                             const Facts& facts, double seconds, bool both);

 private:
  struct Forward {
    Implication implication;
    std::string instance;  ///< the functions' formulas under which it fails ("F(u) = u")
  };
  void decide(const std::vector<Equation>& equations, const Equation& e, std::size_t index,
              EquationResult& r);
  Forward exact(const Scalars& before, const Scalars& step, const Facts& facts,
                const Budget& budget);
  Forward instance_failure(const Scalars& before, const Scalars& step, const Facts& facts,
                           const Budget& budget);
  bool domain_reading(const Scalars& before, const Scalars& step, const Facts& facts,
                      std::size_t index, const Budget& budget, Forward& forward,
                      NumericOpinion& opinion);
  bool root_reading(const Scalars& before, const Scalars& step, const Facts& facts,
                    std::size_t index, const Budget& budget, Forward& forward,
                    NumericOpinion& opinion);
  NumericOpinion numeric(const Scalars& before, const Scalars& step, const Forward& forward,
                         const Facts& facts, std::size_t index, const Budget& budget);
  std::optional<Implication> converse(const Scalars& before, const Scalars& step,
                                      const Facts& facts, const Budget& budget);
  void premises_agree(const std::vector<Equation>& equations, std::size_t index,
                      const Source& source);
  void equivalence_if(const Scalars& before, const Scalars& step, const Implication& forward,
                      const Facts& facts, EquationResult& r) const;
  void drop_given_conditions(Implication& forward, const Scalars& before, const Scalars& step,
                             const Facts& facts, const Budget& budget) const;
  void conclude(const Scalars& before, const Scalars& step, const Forward& forward,
                const NumericOpinion& numeric, const Facts& facts, const Budget& budget,
                EquationResult& r);
  void condition(const Implication& forward, const Scalars& before, const Scalars& step,
                 EquationResult& r) const;
  void residual(const GiNaC::ex& e, EquationResult& r) const;
  template <typename Value>
  void point(const std::vector<std::pair<GiNaC::ex, Value>>& values, EquationResult& r,
             const std::function<double(const Value&)>& to_double,
             const std::function<std::string(const Value&)>& exact) const;
  void exact_point(const GiNaC::exmap& values, EquationResult& r) const;
  void numeric_point(const std::vector<std::pair<GiNaC::ex, double>>& values,
                     EquationResult& r) const;
  [[nodiscard]] AtIndex at_index(std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& renamed);
  void sums_in_one_form(Scalars& before, Scalars& step, Facts& facts);
  [[nodiscard]] GiNaC::ex instantiated(const GiNaC::ex& e, const Instance& instance,
                                       std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& renamed);

  /// Whether a symbol is a declared variable of a function: only there does an equation that
  /// writes the function's value hold at every value (a rule).
  [[nodiscard]] IsVariable is_variable() const {
    return [this](unsigned serial, const GiNaC::ex& symbol) {
      return symbols_.is_variable_of(serial, symbol);
    };
  }

  Symbols& symbols_;
  const DerivationOptions& options_;
};

}  // namespace impulse::derivations::file
