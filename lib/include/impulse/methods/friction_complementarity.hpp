// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Beyond the paper: many contacts with Coulomb friction at once, as one linear
/// complementarity problem solved by Lemke's method, with Newton's restitution as the paper's
/// elasticity.
///
/// In the plane the friction cone of a contact has exactly two edges, so Coulomb's law is exact
/// here (no polygonal approximation). Contact v has a normal impulse @f$ P_{n,v} \ge 0 @f$ and a
/// tangential one @f$ P_{t,v} = \lambda^+_v - \lambda^-_v @f$ (on the bumper along the tangent
/// @f$ t_v = [-n_y, n_x] @f$, as the scene format says); with W the contacts' inverse mass matrix
/// over all normals and tangents and @f$ u' = u_0 + W P @f$ the velocities after (separation and
/// slip), the unknowns @f$ z = (P_n, \lambda^+, \lambda^-, \beta) \ge 0 @f$ and their slacks
/// @f$ w \ge 0 @f$, @f$ z^T w = 0 @f$ are
/// @f[
///   w_n = (W P)_n - B, \quad w^+ = u'_t + \beta, \quad w^- = -u'_t + \beta, \quad
///   w_\beta = \mu P_n - \lambda^+ - \lambda^-
/// @f]
/// (Stewart and Trinkle 1996; Anitescu and Potra 1997, at the level of velocities). B is the
/// paper's right-hand side, so @f$ w_n = -u'_n - (e - 1)\,u @f$ in the paper's approach speeds:
/// every contact that pushes separates e - 1 times as fast as it approached (Newton's law), and
/// with every @f$ \mu = 0 @f$ the normal rows are the frictionless problem
/// (complementarity.hpp). β is the slip speed after: where it is positive the contact slides and
/// its friction is @f$ \mu P_n @f$ against the slip; where the bound is not reached, β = 0 and the
/// contact sticks.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "impulse/methods/complementarity.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::methods {

/// @brief The most contacts the friction problem takes: its 4N unknowns must fit Lemke's dense
/// tableau (pivoting_limit).
inline constexpr Eigen::Index friction_pivoting_limit = pivoting_limit / 4;

/// @brief The contacts' dynamics with friction: everything the complementarity problem needs.
///
/// W and u0 are the paper's own A and (minus) B at elasticity 1 of a configuration with 2N
/// contacts: contact v with its normal, and contact N + v at the same point between the same
/// bodies with "normal" @f$ -t_v @f$ (an impulse @f$ P_t @f$ on it gives the bumper
/// @f$ t_v P_t @f$), as impulse::friction::dynamics() does for one contact. So
/// @f$ W_{nn} @f$ is the paper's A.
struct FrictionSystem {
  Eigen::MatrixXd W;         ///< 2N × 2N: the normals' rows and columns, then the tangents'
  Eigen::VectorXd u0;        ///< 2N: separation (minus the approach) and slip before
  Eigen::VectorXd B;         ///< N: the paper's right-hand side (elasticity × approach)
  Eigen::VectorXd friction;  ///< N: Coulomb's μ of each contact, all @f$ \ge 0 @f$
  /// Optional factor, @f$ W = G^T G @f$ (one row per degree of freedom), or empty: it decides
  /// the null space of the tangential impulses exactly (see FrictionSolution::least_norm).
  Eigen::MatrixXd G;
};

/// @brief Builds the FrictionSystem of a configuration.
/// @param configuration the bodies and contacts (any section's bodies, static ones too)
/// @param friction μ of each contact (one per contact, each finite and @f$ \ge 0 @f$, else
///        InvalidInput)
/// @return W, u0, B, μ and the factor
[[nodiscard]] FrictionSystem friction_system(const multipoint::Configuration& configuration,
                                             std::span<const double> friction);

/// @brief Which algorithm found the impulses of the friction problem.
enum class FrictionAlgorithm {
  /// Pivoting on the contacts' modes: each contact separates, sticks or slides one way or the
  /// other, contacts that the bodies cannot tell apart (equal tangential columns of W) sharing
  /// one friction; each set of modes is one sparse linear system, and the contacts whose
  /// conditions it breaks change mode, all at once, then (when that stops helping) one at a
  /// time. Started from the normal impulses without friction. Fast, but with no guarantee of
  /// ending: solve_friction() tries it first and goes to Lemke's method when it does not end at
  /// impulses that meet the conditions.
  modes,
  /// Lemke's method on the whole problem (lemke_lcp()).
  lemke,
};

/// @brief The impulses of the friction problem and how they were found.
struct FrictionSolution {
  /// solved; inaccurate (the residual above the tolerance); infeasible (Lemke's method ended on a
  /// ray, or ran out of pivots: no impulses); non_finite (a NaN or infinity in the input)
  LcpStatus status = LcpStatus::solved;
  Eigen::VectorXd normal;      ///< P_n of each contact, the paper's Fdt, @f$ \ge 0 @f$
  Eigen::VectorXd tangential;  ///< P_t of each contact, on the bumper along @f$ t_v @f$
  Eigen::VectorXd u_after;     ///< 2N: separation and slip after, @f$ u_0 + W P @f$
  int pivots = 0;              ///< Lemke's pivots, or the changes of mode of the pivoting on modes
  /// How far the conditions are from holding, in velocities: the largest over the contacts of
  /// @f$ |\min(W_{nn} P_n, w_n)| @f$, @f$ W_{tt} \max(0, |P_t| - \mu P_n) @f$,
  /// @f$ \min(W_{tt} (\mu P_n - |P_t|), |u'_t|) @f$ (slides only at the bound) and, where
  /// @f$ P_t u'_t > 0 @f$, @f$ \min(W_{tt} |P_t|, |u'_t|) @f$ (friction against the slip).
  double residual = 0.0;
  double scale = 0.0;  ///< the size of the terms: the largest of @f$ |W|\,|P| + |u_0| + |B| @f$
  /// Whether the tangential impulses are the least-norm ones. Where the bodies cannot tell some
  /// tangential impulses apart (a box on two corners: equal and opposite friction at the corners
  /// squeezes it and changes nothing), the problem has many solutions with the same bodies after.
  /// The method keeps Lemke's normal impulses and takes the tangential impulses of least norm
  /// that leave every velocity as Lemke's answer has it, when they still meet the conditions
  /// (true); otherwise Lemke's own vertex (false).
  bool least_norm = false;
  /// The algorithm that found the impulses.
  FrictionAlgorithm algorithm = FrictionAlgorithm::lemke;
  /// Whether Lemke's method was left out because the problem has more than
  /// lemke_friction_limit contacts (then `infeasible` means that the pivoting on modes did not
  /// end, `pivots` its changes of mode).
  bool lemke_too_large = false;
};

/// @brief The most contacts for which solve_friction() falls back on Lemke's method: its dense
/// tableau holds 4N × (8N + 1) numbers (16 MiB at 256 contacts, 1 GiB at 2,048) and each pivot
/// costs as many operations, so that beyond this a fallback would run for hours.
inline constexpr std::size_t lemke_friction_limit = 256;

/// @brief Solves the friction problem of @p system by pivoting on the contacts' modes or, where
/// that does not end at a solution, by Lemke's method (lemke_lcp()), then chooses
/// the least-norm tangential impulses among those that change nothing (see
/// FrictionSolution::least_norm) and measures the conditions.
///
/// Why Lemke's method ends at a solution here: M is copositive
/// (@f$ z^T M z = P^T W P + \beta^T \mathrm{diag}(\mu) P_n \ge 0 @f$ for z ≥ 0), and when W is
/// positive definite a ray would need a direction @f$ z^h = (0, 0, 0, \beta^h) @f$, for which
/// the condition along the ray reads @f$ \beta^{hT} \mathrm{diag}(\mu) P_n + z_0 \sum \beta^h =
/// 0 @f$ with @f$ z_0 > 0 @f$: impossible. A singular W (more directions than the bodies' degrees
/// of freedom) may let it end on a ray when pushes within the friction cones move nothing (the
/// contacts wedge); the status is then infeasible, never a silent number.
/// @param system W, u0, B and μ (sizes 2N × 2N, 2N, N, N, and G empty or with 2N columns, else
///        InvalidInput; at most friction_pivoting_limit contacts)
/// @param tolerance the conditions count as met when the residual is at most tolerance × scale
///        (in (0, 1), else InvalidInput)
/// @param least_norm true: the least-norm tangential impulses when they meet the conditions;
///        false: Lemke's vertex as it is (to compare the two; Lemke's method only)
/// @return the impulses and the diagnostics
[[nodiscard]] FrictionSolution solve_friction(const FrictionSystem& system,
                                              double tolerance = 1e-10, bool least_norm = true);

/// @brief The conditions' residual and scale (FrictionSolution::residual) of impulses @p normal,
/// @p tangential on @p system: an independent check of any answer.
/// @param system the problem
/// @param normal P_n, one per contact
/// @param tangential P_t, one per contact
/// @param[out] scale the size of the terms
/// @return the residual
[[nodiscard]] double friction_residual(const FrictionSystem& system, const Eigen::VectorXd& normal,
                                       const Eigen::VectorXd& tangential, double& scale);

/// @brief The friction solution of a configuration and the bodies after.
struct FrictionResolution {
  FrictionSolution solution;            ///< impulses and diagnostics
  std::vector<multipoint::Body> after;  ///< the bodies after (before, unless solved/inaccurate)
};

/// @brief friction_system(), solved, and the impulses applied to the bodies (each contact's
/// normal and tangential impulse, multipoint::apply_impulses). The pivoting on the contacts'
/// modes starts from the paper's impulses without friction (methods::paper), as the command line
/// and the page do; from zero where those are not found (the paper's system beyond the dense
/// limit, or not solved). From zero, on a stack sliding as it lands, the modes can go back and
/// forth where from the paper's impulses they settle.
/// @param configuration the bodies and contacts
/// @param friction μ of each contact
/// @param tolerance as solve_friction()
/// @param least_norm as solve_friction()
/// @return the solution and the bodies after
[[nodiscard]] FrictionResolution resolve_friction_complementarity(
    const multipoint::Configuration& configuration, std::span<const double> friction,
    double tolerance = 1e-10, bool least_norm = true);

}  // namespace impulse::methods

namespace impulse {
/// @brief The names of the friction problem's algorithms as reports print them.
template <>
struct EnumNames<methods::FrictionAlgorithm> {
  /// "mode-pivoting", "lemke"
  static constexpr std::array<Named<methods::FrictionAlgorithm>, 2> table{
      {{methods::FrictionAlgorithm::modes, "mode-pivoting"},
       {methods::FrictionAlgorithm::lemke, "lemke"}}};
};
}  // namespace impulse
