// SPDX-License-Identifier: GPL-3.0-or-later
// Time in a derivation file (accepted beyond the contract, for the paper's §4 and §5): integrals
// over the contact, the shape of the contact force, and the two readings of an expression that
// holds them. The exact reading holds every force constant over the contact, as the paper's
// integrations do, so that an integral of a polynomial in t is done by computer algebra. The
// quadrature reading gives the force a shape (a pulse, chosen by a model) and integrates
// numerically: what holds for a constant force only fails there.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "symbolic.hpp"

namespace impulse::derivations::file {

/// The shape of a contact force: u = t / duration, mean 1 over [0, 1], zero outside.
DECLARE_FUNCTION_1P(contact_pulse)

/// The contact's duration inside a pulse's argument: a hidden symbol, given the value of dt when
/// an expression is evaluated numerically.
[[nodiscard]] const GiNaC::symbol& pulse_duration();

/// Whether @p e holds an integral or a pulse (it then has two readings).
[[nodiscard]] bool timed(const GiNaC::ex& e);

/// The exact reading: every pulse is 1 (forces constant over the contact) and the integrals are
/// done where a formula is known (calculus.hpp: polynomials, sines, cosines and exponentials of
/// linear arguments, …); an integral of anything else stays an integral.
[[nodiscard]] GiNaC::ex exact_reading(const GiNaC::ex& e);

/// @p e with the symbols of @p shaped replaced by their values, except inside integrals (a
/// force inside an integral is shaped at that integral's own variable).
[[nodiscard]] GiNaC::ex shaped_outside_integrals(const GiNaC::ex& e, const GiNaC::exmap& shaped);

/// A pulse shape for the quadrature reading.
struct PulseShape {
  std::string name;               ///< "half-sine"
  double (*f)(double) = nullptr;  ///< the shape on [0, 1], mean 1
  std::vector<double> kinks;      ///< where it is not smooth, in (0, 1)
};

/// An expression with integrals and pulses, compiled to evaluate numerically (Gauss–Legendre
/// quadrature on each smooth piece). Sums, products, powers, sin, cos, tan, exp, log, abs.
class TimedExpression {
 public:
  TimedExpression() = default;
  /// Compiles @p e over @p symbols (every free symbol must be one of them; the pulse's duration
  /// may be among them). Throws std::invalid_argument on anything else.
  TimedExpression(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols);
  /// Compiles several expressions together, for their values at the same points: a part they
  /// share outside integrals (an integral in a difference and in the size of its terms) is
  /// evaluated once.
  TimedExpression(const std::vector<GiNaC::ex>& expressions, const std::vector<GiNaC::ex>& symbols);
  /// The value at @p values (one per symbol), the pulses shaped by @p shape (a constant force
  /// when null): the first expression's.
  [[nodiscard]] double operator()(std::span<const double> values, const PulseShape* shape) const;
  /// The value of every expression, in their order, into @p out (one per expression).
  void operator()(std::span<const double> values, const PulseShape* shape,
                  std::span<double> out) const;
  /// How many expressions it evaluates.
  [[nodiscard]] std::size_t size() const { return roots_.size(); }

 private:
  struct Op {
    enum Kind {
      constant,
      variable,
      add,
      mul,
      power,
      sin,
      cos,
      tan,
      exp,
      log,
      abs,
      pulse,
      integral
    };
    Kind kind = constant;
    double value = 0.0;             // constant
    std::size_t index = 0;          // variable slot; integral: the slot of its variable
    std::vector<std::size_t> kids;  // operands; integral: lower, upper, integrand
    std::size_t begin = 0;          // integral: the first operation of its integrand
    bool whole = false;             // power: a constant whole exponent
  };
  std::size_t compile(const GiNaC::ex& e, std::vector<GiNaC::ex>& slots);
  // The operations from @p begin to @p end, in order (operands come before their operation), into
  // @p results; an integral's integrand among them is run by the integral, at each of its nodes.
  void run(std::size_t begin, std::size_t end, double* slots, const PulseShape* shape,
           double* results) const;
  // An integral's value, its limits among @p results.
  double integral(const Op& op, double* slots, const PulseShape* shape, double* results) const;
  // One operation, its operands' values at hand.
  double apply(const Op& op, const double* operands, const PulseShape* shape) const;

  std::vector<Op> ops_;
  // For the first operation of an integrand, the integral's (a run over operations skips the
  // integrand there); zero for the others.
  std::vector<std::size_t> integrand_of_;
  std::vector<std::size_t> roots_;
  // While compiling: how many integrals enclose the expression, and the operations compiled
  // outside every integral, by expression (one operation for a part that recurs there).
  std::size_t depth_ = 0;
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> outside_;
  // While compiling: the canonical forms of the parts, which order a sum's or a product's
  // operands (each part's form is made once, not again for every sum above it).
  sym::CanonicalForms canonical_;
  std::size_t slots_ = 0;
  std::size_t duration_slot_ = static_cast<std::size_t>(-1);
};

}  // namespace impulse::derivations::file
