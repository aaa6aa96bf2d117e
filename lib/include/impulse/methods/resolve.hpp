// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief One step of the pipeline, three ways: a checked configuration and the paper's solved
/// system in, a method's Outcome out.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/friction/contact.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
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
  /// Beyond the paper (issue 17): Coulomb's coefficient μ of each contact. Empty, or all zero
  /// with Newton's law: the paper's frictionless contacts, and every method as it always was.
  std::vector<double> friction;
  /// How the elasticity is applied once the bodies stop approaching (with friction::collide).
  friction::RestitutionLaw restitution = friction::RestitutionLaw::newton;
};

/// @brief Whether @p options ask for a contact law beyond the paper's (some μ > 0, or a law
/// other than Newton's): then the methods resolve a contact by the exact single-contact rule.
/// @param options the methods' options
/// @return whether the exact rule applies
[[nodiscard]] bool has_contact_law(const Options& options);

/// @brief Why @p method cannot resolve @p configuration with the contact law of @p options, or
/// empty when it can. One contact: every method (the exact rule). Several contacts: the serial
/// method (the exact rule at each collision, every law); the complementarity method with
/// Newton's law only (one problem for all contacts has no end of compression, which Poisson's
/// and the energetic law need) and at most friction_pivoting_limit contacts; not the paper's
/// simultaneous system, which has no friction and no law but Newton's.
/// @param method the method
/// @param configuration the checked bodies and contacts
/// @param options the methods' options
/// @return a sentence, or empty
[[nodiscard]] std::string unsupported(Method method, const multipoint::Configuration& configuration,
                                      const Options& options);

/// @brief One contact with friction and any restitution law, whatever the method: the exact
/// single-contact rule (friction::collide), followed through the normal impulse, with its
/// phases in the details, the tangential impulse and how the contact ended as columns, and the
/// warning when the collision gained energy.
/// @param method the method asked for (the outcome carries its name)
/// @param configuration the checked bodies and one contact
/// @param paper its system (for the residual of the normal impulse)
/// @param options μ, the law and the contact's name
/// @return the outcome
[[nodiscard]] Outcome exact_single(Method method, const multipoint::Configuration& configuration,
                                   const Paper& paper, const Options& options);

/// @brief Several contacts with Coulomb friction and Newton's restitution, all at once: the
/// friction complementarity problem (friction_complementarity.hpp) solved by Lemke's method, the
/// least-norm tangential impulses where the bodies cannot tell them apart. The outcome is
/// unfinished, with a sentence, when Lemke's method ends on a ray; warned when its answer is
/// approximate or the collision gained energy at elasticities of at most 2.
/// @param configuration the checked bodies and contacts
/// @param paper its system (for the residual of the normal impulses)
/// @param options μ per contact, the law (Newton's: unsupported() refuses the others), the
///        complementarity tolerance
/// @return the outcome
[[nodiscard]] Outcome complementarity_friction(const multipoint::Configuration& configuration,
                                               const Paper& paper, const Options& options);

/// @brief Serial collisions with friction: the fastest-approaching contact first, each collision
/// by the exact single-contact rule (friction::collide), until none approaches.
/// @param configuration the checked bodies and contacts
/// @param paper its system (for the residual of the summed normal impulses)
/// @param options μ, the law, the bound and the tolerance
/// @return the outcome
[[nodiscard]] Outcome serial_exact(const multipoint::Configuration& configuration,
                                   const Paper& paper, const Options& options);

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

/// @brief The one place that picks a method: simultaneous(), complementarity() or serial(); with
/// a contact law beyond the paper's (has_contact_law()), exact_single() for one contact, and for
/// several serial_exact() or complementarity_friction() (InvalidInput with unsupported()'s
/// sentence for the others).
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
// The exact rule's law at contact v: its μ, the options' restitution law, and the elasticity of
// its movable bodies (World checks that they agree).
friction::ContactLaw contact_law(const multipoint::Configuration& configuration,
                                 const Options& options, std::size_t v);
// Whether kinetic energy went from before to after by more than rounding (1e-12 of before).
bool energy_gained(double before, double after);
// The warning for a collision that gained energy at an elasticity of at most 2.
std::string energy_gained_warning(friction::RestitutionLaw law);
// How a contact that did not collide ends: sliding (its bodies' points slip) or sticking.
friction::Slip slip_of(const multipoint::Body& bumper, const multipoint::Body& wedge,
                       const Eigen::Vector2d& point, const Eigen::Vector2d& normal);
// The per-contact columns of friction: "tangential" and "slip".
std::vector<ContactColumn> friction_columns(const Eigen::VectorXd& tangential,
                                            std::vector<std::string> slip);
// The law in words, for the details: "friction 0.8, Newton's restitution".
std::string law_words(const multipoint::Configuration& configuration, const Options& options);
}  // namespace detail

}  // namespace impulse::methods
