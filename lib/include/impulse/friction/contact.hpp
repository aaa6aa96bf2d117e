// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Beyond the paper: one contact with Coulomb friction, followed exactly through the
/// normal impulse (Routh's method), with three laws of restitution.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/names.hpp"

/// @brief Beyond the paper: Coulomb friction at a contact and three laws of restitution.
///
/// The paper keeps only the normal impulse. Here a contact also carries a tangential impulse,
/// at most μ times the normal one and opposing slip (Coulomb's law), and the collision is
/// followed through the normal impulse @f$ P_n @f$ as Routh and Keller did (the formulation of
/// Stronge, *Impact Mechanics*): the contact's relative velocity changes linearly with the
/// impulse, @f$ u(P) = u_0 + W P @f$, so that between two changes of the friction regime
/// everything is linear in @f$ P_n @f$. The regimes are slip, stick and slip the other way
/// (reversed); compression ends where the normal approach reaches zero, and restitution ends
/// where the chosen law says (RestitutionLaw).
///
/// The core (resolve_contact()) works on the contact's 2×2 matrix W and velocity u0
/// (ContactDynamics); bodies.hpp builds them from any section's bodies and applies the result.
///
/// **Frame and signs.** The bumper's outward normal is @f$ \vec{n} @f$, the tangent
/// @f$ \vec{t} = [-n_y, n_x] @f$ (impulse::quarter_turn). The impulse on the bumper is
/// @f$ -\vec{n}\,P_n + \vec{t}\,P_t @f$ (the scene format's: `-normal * Fdt`, and the
/// tangential impulse on the bumper along the tangent); the wedge receives the opposite.
/// The relative velocity is the bumper's point velocity minus the wedge's, cast on the same two
/// directions, @f$ u = (-\vec{n}\cdot\Delta\vec{v},\ \vec{t}\cdot\Delta\vec{v}) @f$: its normal
/// component is the separation speed (minus the paper's approach speed: negative while the
/// bodies approach), its tangential component the bumper's slip along @f$ \vec{t} @f$.
namespace impulse::friction {

/// @brief How the elasticity ends the collision once compression is over.
///
/// In each, @f$ e @f$ is the paper's elasticity (1 + the coefficient of restitution). The three
/// agree without friction (and whenever the normal and tangential motions are uncoupled,
/// @f$ W_{nt} = 0 @f$); with friction they may differ.
enum class RestitutionLaw {
  /// Newton's (the paper's): the separation speed after is @f$ (e - 1) @f$ times the approach
  /// speed before. With friction it can make a collision gain kinetic energy.
  newton,
  /// Poisson's: the normal impulse of restitution is @f$ (e - 1) @f$ times that of compression,
  /// so the whole normal impulse is @f$ e @f$ times the compression impulse.
  poisson,
  /// Stronge's energetic law: the work of the normal impulse during restitution is
  /// @f$ (e - 1)^2 @f$ times (in magnitude) its work during compression. It never gains energy.
  energetic,
};

/// @brief A restitution law's row of its table: the scene format's name, and its words.
struct LawWords {
  RestitutionLaw value;         ///< the law
  std::string_view name;        ///< `solver.restitution`: "newton", "poisson", "energetic"
  std::string_view words;       ///< in a sentence: "Poisson's restitution"
  std::string_view definition;  ///< in the legend of `--compare restitution`
};

}  // namespace impulse::friction

namespace impulse {
/// @brief The restitution laws, in the order `--compare restitution` shows them.
template <>
struct EnumNames<friction::RestitutionLaw> {
  /// one row per law
  static constexpr std::array<friction::LawWords, 3> table{{
      {friction::RestitutionLaw::newton, "newton", "Newton's restitution",
       "Newton's (the paper's): approach speed after = -(elasticity - 1) x before"},
      {friction::RestitutionLaw::poisson, "poisson", "Poisson's restitution",
       "Poisson's: restitution impulse = (elasticity - 1) x compression impulse"},
      {friction::RestitutionLaw::energetic, "energetic", "the energetic restitution law",
       "energetic (Stronge's): restitution work = (elasticity - 1)^2 x |compression work|"},
  }};
};
}  // namespace impulse

namespace impulse::friction {

/// @brief A friction regime of the contact: one phase of the collision, or how it ended.
enum class Slip {
  slip,      ///< the contact slides; friction is @f$ \mu\,dP_n @f$ against the slip
  stick,     ///< the contact does not slide; friction is what keeps it so (within μ)
  reversed,  ///< the contact slid, stopped, and slides the other way
};

/// @brief The scene format's name of a regime ("slip", "stick", "reversed").
/// @param regime the regime
/// @return its name
[[nodiscard]] std::string_view to_string(Slip regime);

/// @brief The laws that apply at a contact: Coulomb's coefficient, the elasticity and how it is
/// applied.
struct ContactLaw {
  /// μ, finite and @f$ \ge 0 @f$: the tangential impulse is at most μ times the normal one.
  double friction = 0.0;
  /// The paper's elasticity, at least 1 (the rule follows the impulse through compression, so
  /// it cannot stop before it); at most 2 for RestitutionLaw::energetic (whose coefficient
  /// @f$ (e - 1)^2 @f$ is a fraction of the energy stored in compression).
  Elasticity elasticity = Elasticity::inelastic();
  RestitutionLaw restitution = RestitutionLaw::newton;  ///< how the elasticity is applied
};

/// @brief Throws InvalidInput, naming the bad value, unless @p law is acceptable (see its
/// fields).
/// @param law the law to check
void validate(const ContactLaw& law);

/// @brief What the collision needs to know about the contact: how its relative velocity
/// answers an impulse, and what it is before.
///
/// @f$ u(P) = u_0 + W P @f$ with @f$ P = (P_n, P_t) @f$ (see the namespace for the frame).
/// W is the contact's inverse effective mass, @f$ \sum_k J_k M_k^{-1} J_k^T @f$ over the two
/// bodies: symmetric and positive semi-definite. @f$ W_{nn} @f$ is the paper's A at this
/// contact ((3.6)/(3.10) for rigid bodies, (4.5)/(4.8) for point masses), and
/// @f$ -u_{0,n} @f$ its approach speed (B at elasticity 1).
struct ContactDynamics {
  /// @brief No contact: W and u0 zero.
  ContactDynamics() = default;
  /// @brief A contact of the given W and u0.
  /// @param W_ W, symmetric positive semi-definite
  /// @param u0_ the relative velocity before
  /// @param determinant_ det W computed without cancellation, if the caller has it
  ContactDynamics(const Eigen::Matrix2d& W_, const Eigen::Vector2d& u0_,
                  std::optional<double> determinant_ = std::nullopt)
      : W(W_), u0(u0_), determinant(determinant_) {}

  /// @f$ W @f$, 2×2, rows and columns (normal, tangent); symmetric positive semi-definite.
  Eigen::Matrix2d W = Eigen::Matrix2d::Zero();
  /// @f$ u_0 @f$: (separation speed, slip along the tangent) before the impulse.
  Eigen::Vector2d u0 = Eigen::Vector2d::Zero();
  /// @f$ \det W @f$, when the caller can compute it without cancellation (dynamics() does, from
  /// the bodies); empty: @f$ W_{nn} W_{tt} - W_{nt}^2 @f$. While the contact sticks the approach
  /// slows at @f$ \det W / W_{tt} @f$ per unit normal impulse; for a nearly singular W (a heavy
  /// body with a small moment of inertia) the difference of products loses the digits that the
  /// bodies' own form keeps.
  std::optional<double> determinant;
  /// @brief The paper's approach speed before: @f$ -u_{0,n} @f$, positive when closing.
  /// @return the approach speed
  [[nodiscard]] double approach() const { return -u0.x(); }
};

/// @brief Throws InvalidInput, naming the bad value, unless @p contact is acceptable: every
/// number finite, W symmetric (within a relative @f$ 10^{-12} @f$) and positive semi-definite
/// (@f$ W_{nn}, W_{tt} \ge 0 @f$, @f$ |W_{nt}| \le \sqrt{W_{nn} W_{tt}}\,(1 + 10^{-12}) @f$),
/// and the determinant, if given, not negative and within @f$ 10^{-12} @f$ of
/// @f$ W_{nn} W_{tt} - W_{nt}^2 @f$ relative to @f$ W_{nn} W_{tt} + W_{nt}^2 @f$.
/// @param contact the contact to check
void validate(const ContactDynamics& contact);

/// @brief One friction phase of a collision, and where it ended.
///
/// Between two ends everything is linear in @f$ P_n @f$, so the ends are the corners of Routh's
/// diagrams (the slip @f$ u_t @f$, or the separation @f$ u_n @f$, against @f$ P_n @f$), which
/// start at @f$ (0, u_0) @f$.
struct Phase {
  Slip regime = Slip::slip;  ///< slip, stick or reversed slip
  /// The direction of the slip along the tangent, +1 or -1 (0 while sticking).
  double direction = 0.0;
  double end = 0.0;         ///< the normal impulse @f$ P_n @f$ at which the phase ended
  double tangential = 0.0;  ///< the tangential impulse @f$ P_t @f$ there
  Eigen::Vector2d u = Eigen::Vector2d::Zero();  ///< (separation, slip) there
};

/// @brief Whether resolve_contact() found impulses.
enum class ContactStatus {
  /// The collision ran to the end of restitution.
  resolved,
  /// The bodies do not approach (@f$ u_{0,n} \ge 0 @f$): no impulse.
  not_approaching,
  /// No impulse ends the collision: W cannot slow the approach (or cannot bring restitution to
  /// its end), which happens only for a singular W (e.g. two immovable bodies, or a hand-made
  /// W). The impulses and velocities are those of the last end reached (a slip's stop or the
  /// end of compression); the phase that would not end is not listed, but is the outcome.
  cannot_stop,
  /// A number of the collision went beyond doubles (inputs near the largest double): the
  /// impulses are not meaningful.
  non_finite,
};

/// @brief The name of a status ("resolved", "not-approaching", "cannot-stop", "non-finite").
/// @param status the status
/// @return its name
[[nodiscard]] std::string_view to_string(ContactStatus status);

/// @brief At most this many friction phases: slip, then stick or reversed slip (neither ends).
inline constexpr std::size_t max_phases = 2;

/// @brief The impulse of a collision with friction, followed through the normal impulse.
struct ContactImpulse {
  ContactStatus status = ContactStatus::resolved;  ///< resolved, or why not
  /// @f$ P_n \ge 0 @f$: the impulse on the bumper has normal part @f$ -\vec{n} P_n @f$ (the
  /// paper's Fdt).
  double normal = 0.0;
  /// @f$ P_t @f$: the impulse on the bumper has tangential part @f$ \vec{t} P_t @f$.
  double tangential = 0.0;
  Eigen::Vector2d u_before = Eigen::Vector2d::Zero();  ///< (separation, slip) before
  Eigen::Vector2d u_after = Eigen::Vector2d::Zero();   ///< (separation, slip) after
  std::array<Phase, max_phases> phase_list{};          ///< the phases; phase_count are used
  std::size_t phase_count = 0;                         ///< how many phases (0: no impulse)
  /// How the contact ended: the last phase's regime (with no impulse: slip if it slides, else
  /// stick).
  Slip outcome = Slip::stick;
  /// The normal impulse at which compression ended (the approach reached zero).
  double compression = 0.0;
  /// @f$ \int u_n\,dP_n @f$ over compression, @f$ \le 0 @f$.
  double work_compression = 0.0;
  /// @f$ \int u_n\,dP_n @f$ over restitution, @f$ \ge 0 @f$.
  double work_restitution = 0.0;
  /// @f$ \int u_t\,dP_t @f$: the work of friction, @f$ \le 0 @f$.
  double work_tangential = 0.0;

  /// @brief The phases, in order.
  /// @return a view of the used part of phase_list
  [[nodiscard]] std::span<const Phase> phases() const {
    return std::span<const Phase>(phase_list).first(phase_count);
  }
  /// @brief The change of kinetic energy: the sum of the three works (the energy of the two
  /// bodies changes by @f$ \int u \cdot dP @f$).
  /// @return work_compression + work_restitution + work_tangential
  [[nodiscard]] double energy_change() const {
    return work_compression + work_restitution + work_tangential;
  }
};

/// @brief Follows a collision through the normal impulse (Routh's method).
///
/// From @f$ u_0 @f$ the contact slips along @f$ \operatorname{sign}(u_{0,t}) @f$ with
/// @f$ dP_t = -\mu\,s\,dP_n @f$, or, if it does not slip, sticks when it can. A slip stops where
/// @f$ u_t @f$ reaches zero; the contact then sticks if the stick ratio allows,
/// @f$ |W_{tn}| \le \mu W_{tt} @f$ (with @f$ dP_t = -W_{tn}/W_{tt}\,dP_n @f$), and else slips
/// the other way. Compression ends where @f$ u_n @f$ reaches zero, and restitution where the law
/// is met. Every phase is linear in @f$ P_n @f$, so each end is found exactly; the works are
/// integrated exactly too.
/// @param contact W and u0 (validated: InvalidInput)
/// @param law μ, the elasticity and the law of restitution (validated: InvalidInput)
/// @return the impulses, the velocities after, the phases and the works
[[nodiscard]] ContactImpulse resolve_contact(const ContactDynamics& contact, const ContactLaw& law);

}  // namespace impulse::friction
