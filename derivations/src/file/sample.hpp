// SPDX-License-Identifier: GPL-3.0-or-later
// The numeric method: random points that satisfy the equations before and the facts (GSL: the
// free symbols drawn at random, one symbol per equation solved for by root finding), at which
// the step is evaluated. It is the second opinion on what the exact method decided, and the
// deciding one when the exact method could not: a point where the step fails is a
// counterexample; points where it holds prove nothing, and are never reported as "follows".
#pragma once

#include <ginac/ginac.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "file/clock.hpp"
#include "file/facts.hpp"
#include "numeric.hpp"

namespace impulse::derivations::file {

/// Premises and a target, each equal to zero, with the sizes their terms are measured against.
struct NumericProblem {
  std::vector<GiNaC::ex> premises;
  std::vector<GiNaC::ex> premise_scales;  ///< the sum of the absolute values of each one's terms
  std::vector<GiNaC::ex> denominators;    ///< must not vanish at a point
  GiNaC::ex target;
  GiNaC::ex target_scale;
  std::size_t premise_denominators = 0;  ///< the first this many denominators are the premises'
};

/// What the numeric method saw.
struct NumericOpinion {
  std::size_t points = 0;  ///< points on the premises where the target was evaluated
  double worst = 0.0;      ///< the worst relative residual of the target there
  /// A point where the target fails (relative residual above 1e-6), every symbol's value.
  std::optional<std::vector<std::pair<GiNaC::ex, double>>> counterexample;
  double counterexample_residual = 0.0;
  /// Points on the premises where the target has no real value (√x at x < 0), and the first.
  std::size_t not_real = 0;
  std::optional<std::vector<std::pair<GiNaC::ex, double>>> not_real_point;
  std::string how;  ///< what was done, or why no point could be found
};

/// A relative residual below this is rounding: the step holds at the point.
inline constexpr double numeric_holds_below = 1e-9;
/// A relative residual above this shows the step failing at the point.
inline constexpr double numeric_fails_above = 1e-6;

/// Solves equations (each = 0, compiled over a list of symbols) for some of the symbols, the
/// others held at their values: one equation by its polynomial roots or by Brent's method along
/// the unknown, several at once by Powell's hybrid method with the exact Jacobian. A root that
/// breaks a fact is not a solution.
class Solver {
 public:
  /// @param equations each = 0
  /// @param unknowns the symbol each equation is solved for (one each, distinct)
  /// @param symbols every symbol, in the order of the values
  /// @param facts the signs a solution must keep
  /// @param random where a random root is chosen among several (kept by the caller)
  Solver(const std::vector<GiNaC::ex>& equations, const std::vector<GiNaC::ex>& unknowns,
         const std::vector<GiNaC::ex>& symbols, const Facts& facts, num::Random& random);
  ~Solver();
  Solver(Solver&&) noexcept;
  Solver& operator=(Solver&&) noexcept;
  /// Solves in place: @p values holds every symbol's value, the unknowns' as a first guess.
  [[nodiscard]] bool solve(std::vector<double>& values);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Evaluates @p problem at up to @p points random points (seeded), stopping at @p deadline (a
/// counterexample found by then is kept; fewer points only make a verdict less likely).
[[nodiscard]] NumericOpinion sample(const NumericProblem& problem, const Facts& facts,
                                    std::uint64_t seed, std::size_t points,
                                    WorkClock::time_point deadline = WorkClock::time_point::max());

/// The size a residual of an expression is measured against: its sums add the absolute values
/// of their terms, its products multiply them (the terms that cancel in floating point).
[[nodiscard]] GiNaC::ex term_scale(const GiNaC::ex& e);

/// @brief A sample value of a symbol: a magnitude drawn log-uniformly in [0.2, 5], with the sign
/// the facts give it (either sign, at random, when they give none).
/// @param random the generator
/// @param sign what the facts say of the symbol's sign
/// @return the value
double draw_with_sign(num::Random& random, Sign sign);

}  // namespace impulse::derivations::file
