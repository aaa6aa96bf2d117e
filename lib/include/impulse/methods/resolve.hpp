// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief One step of the pipeline, three ways: a checked configuration and the paper's solved
/// system in, a method's Outcome out.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/methods.hpp"
#include "impulse/methods/outcome.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::methods {

/// @brief The paper's system of a configuration, assembled and solved once and handed to every
/// method that starts from it.
struct Paper {
  ContactSystem system;  ///< A·Fdt = B, the ⊕ of the bodies' blocks (sections 4.5 and 5)
  Solution solution;     ///< its solution under the scene's policies
};

/// @brief Assembles (multipoint::Configuration::assemble) and solves (impulse::solve).
/// @param configuration the checked bodies and contacts
/// @param options the policies (InvalidInput beyond impulse::dense_limit, see
///        impulse::require_dense_fits)
/// @return the system and its solution
[[nodiscard]] Paper paper(const multipoint::Configuration& configuration,
                          const SolverOptions& options);

/// @brief Everything the methods may be asked for.
struct Options {
  /// The paper's policies and tolerances; the complementarity method takes its dependent policy
  /// and rank tolerance from here too.
  SolverOptions solver;
  ComplementarityOptions complementarity;  ///< algorithm, tolerance, sweeps, warm start
  SerialOptions serial;                    ///< the bound on collisions and the tolerance
  /// How the methods' sentences name contact v; empty: "contact v". (A scene names its bodies:
  /// "contact 2 (a–b)".)
  std::function<std::string(Eigen::Index)> contact_name;
};

/// @brief The paper's method: its impulses are the paper's solution, applied to the bodies.
/// @param configuration the checked bodies and contacts
/// @param paper its system, solved
/// @return the outcome
[[nodiscard]] Outcome simultaneous(const multipoint::Configuration& configuration,
                                   const Paper& paper);

/// @brief Impulses that only push: solve_complementarity() on the paper's system (projected
/// Gauss-Seidel warm-started from the paper's solution when it was solved with the default
/// policies), applied to the bodies.
/// @param configuration the checked bodies and contacts
/// @param paper its system, solved
/// @param options the complementarity options, with the solver's dependent policy and rank
///        tolerance
/// @return the outcome
[[nodiscard]] Outcome complementarity(const multipoint::Configuration& configuration,
                                      const Paper& paper, const Options& options);

/// @brief Serial collisions (resolve_serial()); the paper's system gives the residual of their
/// summed impulses.
/// @param configuration the checked bodies and contacts
/// @param paper its system
/// @param options the bound and the tolerance
/// @return the outcome
[[nodiscard]] Outcome serial(const multipoint::Configuration& configuration, const Paper& paper,
                             const Options& options);

/// @brief The one place that picks a method: simultaneous(), complementarity() or serial().
/// @param method the method
/// @param configuration the checked bodies and contacts
/// @param paper its system, assembled and solved once
/// @param options the methods' options
/// @return the method's outcome
[[nodiscard]] Outcome resolve(Method method, const multipoint::Configuration& configuration,
                              const Paper& paper, const Options& options);

namespace detail {
// How the sentences of a method name contact v: options.contact_name, else "contact v".
std::string contact_name(const Options& options, Eigen::Index v);
}  // namespace detail

}  // namespace impulse::methods
