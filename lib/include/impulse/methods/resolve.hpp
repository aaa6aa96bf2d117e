// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief One step of the pipeline, three ways: a checked configuration and the paper's solved
/// system in, a method's Outcome out.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/names.hpp"
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
  /// Beyond the paper: Coulomb's coefficient μ of each contact. Empty, or all zero with Newton's
  /// law: the paper's frictionless contacts, and every method as the paper has it.
  std::vector<double> friction;
  /// How the elasticity is applied once the bodies stop approaching (with friction::collide).
  friction::RestitutionLaw restitution = friction::RestitutionLaw::newton;
};

/// @brief Whether contacts with these coefficients of friction and this restitution law go
/// beyond the paper (some μ > 0, or a law other than Newton's): then a contact is resolved by
/// the exact single-contact rule (friction::collide), and not every method can take several.
/// @param friction μ of each contact
/// @param law the restitution law
/// @return whether a contact law beyond the paper's applies
[[nodiscard]] bool has_contact_law(std::span<const double> friction, friction::RestitutionLaw law);

/// @brief A method's row of the table of methods: its names and words, whether it can take a
/// configuration with a contact law, and how it resolves one.
///
/// One contact with a contact law beyond the paper's is resolved by exact_single() whatever the
/// method; the rest is the row's: `resolve` for the paper's frictionless contacts under
/// Newton's law, `resolve_with_law` for several contacts with friction or another law (null
/// where `unsupported` always refuses them).
struct MethodRow {
  Method value;                  ///< the method
  std::string_view name;         ///< the scene format's (`solver.method`, `--method`)
  std::string_view description;  ///< after its name in the text report ("Method: serial (…)")
  std::string_view brief;        ///< after its name in the legend of `--compare`
  /// Why the method cannot resolve the configuration with the options' contact law, or "".
  std::string (*unsupported)(const multipoint::Configuration&, const Options&);
  /// The method on the paper's frictionless contacts.
  Outcome (*resolve)(const multipoint::Configuration&, const Paper&, const Options&);
  /// The method on several contacts with friction or another restitution law.
  Outcome (*resolve_with_law)(const multipoint::Configuration&, const Paper&, const Options&);
};

/// @brief The paper's method: its impulses are the paper's solution, applied to the bodies.
/// @param configuration the checked bodies and contacts
/// @param paper its system, solved
/// @param options unused: the paper's method has no options of its own
/// @return the outcome
[[nodiscard]] Outcome simultaneous(const multipoint::Configuration& configuration,
                                   const Paper& paper, const Options& options);

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

/// @brief The serial method in slices: its collisions (SerialCollisions) a bounded number at a
/// time, then exactly the outcome that serial() or serial_exact() gives. The constructor picks
/// as resolve() does for the serial method: the paper's formula at each collision on the paper's
/// contacts, the exact rule with a contact law beyond them, and one contact with such a law by
/// exact_single() (no collisions to run).
///
/// The configuration, the paper's system and the options must outlive this object.
class SerialMethod {
 public:
  /// @brief Which rule the collisions follow.
  enum class Kind {
    paper,   ///< the paper's single-contact formula (serial())
    exact,   ///< the exact rule with friction or another law (serial_exact())
    single,  ///< one contact with a contact law: exact_single() when finished
  };
  /// @brief The serial method as resolve() picks it.
  /// @param configuration the checked bodies and contacts
  /// @param paper its system (for the residual of the summed impulses)
  /// @param options μ, the law, the bound and the tolerance (checked: InvalidInput)
  SerialMethod(const multipoint::Configuration& configuration, const Paper& paper,
               const Options& options);
  /// @brief The serial method by the rule @p kind.
  /// @param configuration the checked bodies and contacts
  /// @param paper its system
  /// @param options μ, the law, the bound and the tolerance (checked: InvalidInput)
  /// @param kind the rule
  SerialMethod(const multipoint::Configuration& configuration, const Paper& paper,
               const Options& options, Kind kind);
  /// @brief Frees its state.
  ~SerialMethod();
  /// @brief Takes over another method in slices (which is left without state).
  /// @param other the one taken over
  SerialMethod(SerialMethod&& other) noexcept;
  /// @brief Takes over another method in slices (which is left without state).
  /// @param other the one taken over
  /// @return this one
  SerialMethod& operator=(SerialMethod&& other) noexcept;

  /// @brief Runs at most @p collisions more collisions.
  /// @param collisions how many at most (at least 1)
  /// @return whether the collisions have ended (then finish() gives the outcome)
  bool advance(std::int64_t collisions);
  /// @brief The collisions so far.
  /// @return their number
  [[nodiscard]] std::int64_t collisions() const;
  /// @brief The bound on collisions that applies (0 for one contact with a contact law).
  /// @return the bound
  [[nodiscard]] std::int64_t bound() const;
  /// @brief The outcome, once advance() has returned true.
  /// @return serial()'s or serial_exact()'s outcome (exact_single()'s for one contact)
  [[nodiscard]] Outcome finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

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
/// @param options μ per contact, the law (Newton's: the row refuses the others), the
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

namespace detail {
// The rows' `unsupported`. One contact takes every contact law (the exact rule). Several: serial
// collisions take every law (the exact rule at each collision); the complementarity method
// Newton's law only (one problem for all contacts has no end of compression, which Poisson's and
// the energetic law need) at up to friction_pivoting_limit contacts; the paper's simultaneous
// system neither friction nor a law but Newton's.
std::string simultaneous_unsupported(const multipoint::Configuration& configuration,
                                     const Options& options);
std::string complementarity_unsupported(const multipoint::Configuration& configuration,
                                        const Options& options);
std::string always_supported(const multipoint::Configuration& configuration,
                             const Options& options);
}  // namespace detail

}  // namespace impulse::methods

namespace impulse {
/// @brief The table of methods, in the order `--compare` shows them: the scene format's names,
/// read both ways, and each method's words, support and resolution.
template <>
struct EnumNames<methods::Method> {
  /// one row per method
  static constexpr std::array<methods::MethodRow, 3> table{{
      {methods::Method::simultaneous, "simultaneous",
       "the paper's: every contact at once, A·Fdt = B",
       "the paper's, every contact at once (A·Fdt = B)", &methods::detail::simultaneous_unsupported,
       &methods::simultaneous, nullptr},
      {methods::Method::complementarity, "complementarity",
       "impulses only push: Fdt >= 0 and A·Fdt - B >= 0, one of them 0 at each contact",
       "impulses only push (Fdt >= 0, A·Fdt - B >= 0, one of them 0)",
       &methods::detail::complementarity_unsupported, &methods::complementarity,
       &methods::complementarity_friction},
      {methods::Method::serial, "serial",
       "one contact at a time, the fastest-approaching first, until none approaches",
       "one contact at a time, the fastest-approaching first", &methods::detail::always_supported,
       &methods::serial, &methods::serial_exact},
  }};
};
}  // namespace impulse

namespace impulse::methods {

/// @brief Every method, in the order `--compare` shows them (the table's).
inline constexpr std::array<Method, 3> all_methods{EnumNames<Method>::table[0].value,
                                                   EnumNames<Method>::table[1].value,
                                                   EnumNames<Method>::table[2].value};

/// @brief The method's outcome, as its row of the table resolves it: the paper's contacts by
/// its `resolve`; with a contact law beyond the paper's, one contact by exact_single() and
/// several by its `resolve_with_law`. The caller has asked the row's `unsupported` first: a
/// method that cannot take the contact law is not resolved.
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
