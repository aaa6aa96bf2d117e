// SPDX-License-Identifier: GPL-3.0-or-later
// Deciding one equation of a derivation file: its dimensions, then the exact method (does it
// follow from the equations before, under the facts?) with the numeric method as a second
// opinion, into a verdict with its condition, residual or counterexample.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

#include "derivations/derivation.hpp"
#include "file/reader.hpp"

namespace impulse::derivations::file {

/// Calls @p each with the two sides of every scalar equation @p e stands for: each entry of a
/// block, both components of a vector, or the one scalar.
void for_each_scalar(const Equation& e,
                     const std::function<void(const GiNaC::ex&, const GiNaC::ex&)>& each);

/// The scalar equations an equation stands for (one per component or entry), each with the size
/// of its terms, read exactly (forces constant over the contact), and the denominators written.
struct Scalars {
  std::vector<GiNaC::ex> differences;  ///< each = 0
  std::vector<GiNaC::ex> scales;
  std::vector<GiNaC::ex> denominators;
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

 private:
  void decide(const std::vector<Equation>& equations, const Equation& e, std::size_t index,
              EquationResult& r);
  void residual(const GiNaC::ex& e, EquationResult& r) const;
  template <typename Value>
  void point(const std::vector<std::pair<GiNaC::ex, Value>>& values, EquationResult& r,
             const std::function<double(const Value&)>& to_double,
             const std::function<std::string(const Value&)>& exact) const;
  void exact_point(const GiNaC::exmap& values, EquationResult& r) const;
  void numeric_point(const std::vector<std::pair<GiNaC::ex, double>>& values,
                     EquationResult& r) const;

  Symbols& symbols_;
  const DerivationOptions& options_;
};

}  // namespace impulse::derivations::file
