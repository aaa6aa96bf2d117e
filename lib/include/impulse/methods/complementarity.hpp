// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Impulses that only push: the paper's A and B as a linear complementarity problem.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/names.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::methods {

/// @brief Which algorithm solves the complementarity problem.
enum class LcpAlgorithm {
  /// Up to pivoting_threshold contacts, pivoting: the active-set method when the system carries
  /// its factor (as systems assembled from bodies do), Lemke's otherwise; above, projected
  /// Gauss-Seidel, which also takes over when rounding leaves a pivoting answer inaccurate.
  automatic,
  /// Lemke's complementary pivoting with a lexicographic ratio test: exact, finite, and for a
  /// positive semi-definite A it finds a solution whenever one exists. Works on A and B alone.
  lemke,
  /// The active-set method of Lawson and Hanson for @f$ \min \|G F - g\| @f$ over
  /// @f$ F \ge 0 @f$, whose optimality conditions are the complementarity problem when
  /// @f$ A = G^T G @f$ and @f$ B = G^T g @f$: it pivots one contact at a time into or out of the
  /// set that carries impulse, and solves each set's least squares by a QR factorisation of G's
  /// columns. Exact and finite like Lemke's, and stable where A is nearly singular (it never
  /// forms A). Needs the system's factor.
  active_set,
  /// Projected Gauss-Seidel: sweeps over the contacts, each impulse set so that its own row
  /// holds, then clipped at zero. Iterative: it stops at a residual or at a number of sweeps.
  projected_gauss_seidel,
};

/// @brief How a complementarity problem ended. Bad input is an exception instead.
enum class LcpStatus {
  solved,           ///< Fdt satisfies the conditions within the tolerance
  iteration_limit,  ///< projected Gauss-Seidel used its sweeps: Fdt is its last, approximate,
                    ///< iterate
  inaccurate,       ///< the pivoting ended, but rounding left the residual above the tolerance
  infeasible,       ///< no impulses can satisfy the conditions (not for an assembled scene)
  non_finite,       ///< A or B held a NaN or an infinity; Fdt is all NaN
};

/// @brief Up to this many contacts LcpAlgorithm::automatic pivots; above, it iterates
/// (projected Gauss-Seidel). It is impulse::sparse_threshold, one policy: below it A is dense,
/// and a whole pivoting solve takes a few milliseconds at 256 contacts.
inline constexpr Eigen::Index pivoting_threshold = sparse_threshold;

/// @brief The most contacts the pivoting methods accept: they work on dense matrices (Lemke's
/// tableau holds @f$ N\,(2N + 1) @f$ numbers, 256 MiB at this size).
inline constexpr Eigen::Index pivoting_limit = 4096;

/// @brief How to solve the complementarity problem.
struct ComplementarityOptions {
  LcpAlgorithm algorithm = LcpAlgorithm::automatic;  ///< pivoting, iterating, or by size
  /// Which solution of a dependent system: minimum_norm, the least-norm impulses among all that
  /// satisfy the conditions (where they need no clipping, the paper's equal impulses); basic,
  /// the vertex the pivoting reaches (as few contacts as possible carry impulse).
  DependentPolicy dependent = DependentPolicy::minimum_norm;
  /// The pivot threshold of the least-squares solves that settle a pivoting's impulses, as
  /// SolverOptions::rank_tolerance (0: Eigen's default).
  double rank_tolerance = 0.0;
  /// The conditions count as met when
  /// @f$ \max_v |\min(F_v, w_v)| \le \tau \max_v \left(\sum_k |A_{vk}|\,|F_k| + |B_v|\right) @f$
  /// with this @f$ \tau @f$: the residual against the size of the terms that make up w.
  double tolerance = 1e-10;
  /// Projected Gauss-Seidel stops after this many sweeps if the tolerance is not met.
  int max_sweeps = 10000;
  /// Projected Gauss-Seidel starts from the paper's impulses (impulse::solve, minimum norm)
  /// clipped at zero, instead of from zero. Its sweeps converge at a rate set by the
  /// conditioning of A, which on a row of 300 balls or a stack of 150 boxes leaves the residual
  /// near 1e-5 after 10,000 sweeps from zero; started from the paper's answer they need none
  /// where that answer already only pushes, and few where it pulls at a few contacts.
  bool warm_start = true;
};

/// @brief The impulses of the complementarity problem and how they were found.
///
/// The problem: @f$ F \ge 0 @f$, @f$ w = A F - B \ge 0 @f$, @f$ F_v\,w_v = 0 @f$ for every
/// contact v. For a scene at one elasticity e, @f$ B = e\,u @f$ with u the approach speeds
/// before, and the approach after is @f$ u' = u - A F @f$, so
/// @f$ w = -u' - (e - 1)\,u @f$: every contact separates at least e - 1 times as fast as it
/// approached, and a contact that carries an impulse does so exactly.
struct ComplementaritySolution {
  LcpStatus status = LcpStatus::solved;  ///< whether Fdt is meaningful, and how exact
  Eigen::VectorXd Fdt;                   ///< impulse magnitude at each contact, all @f$ \ge 0 @f$
  Eigen::VectorXd w;                     ///< the slack @f$ A\,F\,dt - B @f$ at each contact
  /// The algorithm that produced Fdt, never automatic.
  LcpAlgorithm algorithm = LcpAlgorithm::lemke;
  /// Pivots (Lemke's, or the active-set method's contacts moved in or out of the set that
  /// carries impulse), or projected Gauss-Seidel's sweeps.
  int iterations = 0;
  double residual = 0.0;  ///< @f$ \max_v |\min(F_v, w_v)| @f$: 0 when the conditions hold
  /// The size the residual is measured against:
  /// @f$ \max_v \left(\sum_k |A_{vk}|\,|F_k| + |B_v|\right) @f$.
  double scale = 0.0;
  /// Whether Fdt is the least-norm solution. A pivoting solve under DependentPolicy::minimum_norm
  /// gives it unless the least-norm impulses of the contacts that can carry one would have to
  /// pull (Fdt is then the pivoting's vertex); projected Gauss-Seidel never claims it.
  bool least_norm = false;
};

/// @brief Lemke's complementary pivoting on @f$ w = A F - B @f$, @f$ F, w \ge 0 @f$,
/// @f$ F^T w = 0 @f$.
///
/// The covering vector is all ones; ties in the ratio test are broken lexicographically by the
/// rows of the basis inverse, which rules out cycling on degenerate problems (a body on parallel
/// contacts). For a positive semi-definite A the method ends either at a solution or on a ray,
/// and a ray means that no solution exists (LcpStatus::infeasible). Once the pivoting has found
/// which contacts carry an impulse, the impulses are recomputed from those contacts' equations
/// by a complete orthogonal decomposition, which is more accurate than the tableau.
/// @param A the system's matrix, square, symmetric positive semi-definite, at most
///        pivoting_limit contacts (else InvalidInput)
/// @param B the right-hand side (a size mismatch throws InvalidInput)
/// @param dependent minimum_norm: the least-norm solution when it needs no clipping (see
///        ComplementaritySolution::least_norm); basic: the vertex the pivoting reaches
/// @param tolerance as ComplementarityOptions::tolerance
/// @return the impulses, the slack and the diagnostics
[[nodiscard]] ComplementaritySolution lemke(
    const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::VectorXd>& B,
    DependentPolicy dependent = DependentPolicy::minimum_norm, double tolerance = 1e-10);

/// @brief How Lemke's method ended on a general problem (lemke_lcp()).
enum class LemkeEnd {
  solution,     ///< z0 left the basis: z solves the problem (up to the tableau's rounding)
  ray,          ///< the entering variable was unbounded: the method stopped without a solution
  pivot_limit,  ///< out of pivots (not expected: the lexicographic rule rules out cycling)
  non_finite,   ///< M or q held a NaN or an infinity
};

/// @brief What Lemke's method found on a general problem @f$ w = M z + q @f$.
struct LemkeLcp {
  LemkeEnd end = LemkeEnd::solution;  ///< how it ended; z and w mean something only at solution
  Eigen::VectorXd z;                  ///< the unknowns of the final basis, all @f$ \ge 0 @f$
  Eigen::VectorXd w;                  ///< @f$ M z + q @f$ for that z
  int pivots = 0;                     ///< pivots made
};

/// @brief Lemke's complementary pivoting on a general linear complementarity problem:
/// @f$ w = M z + q @f$, @f$ z, w \ge 0 @f$, @f$ z^T w = 0 @f$, with M not necessarily symmetric
/// or positive semi-definite (the problem of Coulomb friction, friction_complementarity.hpp).
///
/// The same pivoting as lemke(): covering vector all ones, the lexicographic ratio test (no
/// cycling on degenerate problems, such as rows with @f$ q_i = 0 @f$), z0 leaving at the first
/// tie. For a general M an end on a ray does not prove that no solution exists (it does for a
/// positive semi-definite or copositive-plus M); the caller must report it, never use z.
/// @param M the matrix, square, at most pivoting_limit rows (else InvalidInput)
/// @param q the right-hand side, of M's size (else InvalidInput)
/// @param tie ratios closer than this (relative) count as tied and go to the lexicographic rule;
///        lemke() uses 1e-11. A looser tie follows exact arithmetic's path through degenerate
///        pivots that rounding would otherwise split (in (0, 1e-3), else InvalidInput)
/// @return how it ended, z, w and the pivots
[[nodiscard]] LemkeLcp lemke_lcp(const Eigen::Ref<const Eigen::MatrixXd>& M,
                                 const Eigen::Ref<const Eigen::VectorXd>& q, double tie = 1e-11);

/// @brief The active-set method (Lawson and Hanson's non-negative least squares) on the factor:
/// the complementarity problem of @f$ A = G^T G @f$, @f$ B = G^T g @f$.
///
/// Starting with no contact in the set P that carries impulse, it adds the contact whose slack
/// is most negative (@f$ -w_t = (G^T (g - G F))_t @f$ largest), solves
/// @f$ \min \|G_P z - g\| @f$ on P's columns, and if some impulse of z is not positive it moves
/// back from F towards z only as far as every impulse stays non-negative and drops the contacts
/// that reach zero; it stops when no contact outside P has a negative slack beyond the
/// tolerance. The columns of P stay independent (a column in their span has zero slack and is
/// never added), so a dependent system gets a basic solution, which the least-norm step then
/// spreads as under lemke().
/// @param G the factor, one row per degree of freedom, one column per contact
/// @param g the scaled velocities, one per row of G (a size mismatch throws InvalidInput)
/// @param dependent minimum_norm or basic, as for lemke()
/// @param tolerance as ComplementarityOptions::tolerance
/// @return the impulses, the slack and the diagnostics
[[nodiscard]] ComplementaritySolution active_set(
    const Eigen::Ref<const Eigen::MatrixXd>& G, const Eigen::Ref<const Eigen::VectorXd>& g,
    DependentPolicy dependent = DependentPolicy::minimum_norm, double tolerance = 1e-10);

/// @brief Projected Gauss-Seidel, started from @p start (zero impulses when it is empty): for
/// v = 1 … N in turn,
/// @f$ F_v \leftarrow \max\left(0,\ F_v - w_v / A_{vv}\right) @f$ with w from the latest impulses,
/// until the residual meets the tolerance or the sweeps run out.
///
/// On a symmetric positive semi-definite A this is coordinate descent on the convex function
/// @f$ \tfrac12 F^T A F - B^T F @f$ over @f$ F \ge 0 @f$, whose minimisers are exactly the
/// solutions; it converges, slowly when A is ill-conditioned. A contact with @f$ A_{vv} = 0 @f$
/// (no body can move along its normal: then its whole row is zero) keeps @f$ F_v = 0 @f$; if
/// its @f$ B_v > 0 @f$ nothing can satisfy it and the status is LcpStatus::infeasible.
/// @param A the system's matrix, square, symmetric positive semi-definite
/// @param B the right-hand side (a size mismatch throws InvalidInput)
/// @param tolerance as ComplementarityOptions::tolerance
/// @param max_sweeps the limit on sweeps, at least 1 (else InvalidInput)
/// @param start the impulses to start from, clipped at zero (empty: zero; else of B's size, or
///        InvalidInput)
/// @return the impulses, the slack and the diagnostics
[[nodiscard]] ComplementaritySolution projected_gauss_seidel(
    const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& B, double tolerance = 1e-10,
    int max_sweeps = 10000, const Eigen::VectorXd& start = Eigen::VectorXd());

/// @brief Solves the complementarity problem of an assembled system, projected Gauss-Seidel
/// starting from @p paper's impulses (the solution of A·Fdt = B that the caller already has)
/// instead of solving the system again for its warm start.
/// @param system the paper's system A·Fdt = B
/// @param paper its solution by impulse::solve with the default policies (used when its status
///        is success and it has one impulse per contact)
/// @param options algorithm, policy, tolerance and limit
/// @return the impulses, the slack and the diagnostics
[[nodiscard]] ComplementaritySolution solve_complementarity(const ContactSystem& system,
                                                            const Solution& paper,
                                                            const ComplementarityOptions& options);

/// @brief Solves the complementarity problem of an assembled system with the algorithm the
/// options ask for (LcpAlgorithm::automatic: by its size and whether it carries its factor, and
/// projected Gauss-Seidel as well when pivoting ends LcpStatus::inaccurate, keeping the closer
/// answer). LcpAlgorithm::active_set on a system without its factor throws InvalidInput.
///
/// Lemke's method, too, recomputes its final impulses from the factor when the system carries
/// one, as impulse::solve does, so that they lose half the digits.
/// @param system the paper's system A·Fdt = B
/// @param options algorithm, policy, tolerance and limit
/// @return the impulses, the slack and the diagnostics
[[nodiscard]] ComplementaritySolution solve_complementarity(
    const ContactSystem& system, const ComplementarityOptions& options = {});

/// @brief The complementarity solution of a scene's bodies and the bodies after it.
struct ComplementarityResolution {
  ComplementaritySolution solution;     ///< impulses and diagnostics
  std::vector<multipoint::Body> after;  ///< the bodies after (the bodies before if not finite)
};

/// @brief Assembles the paper's system (multipoint::assemble), solves its complementarity
/// problem and applies the impulses (multipoint::apply_impulses).
/// @param bodies the bodies
/// @param elasticities one per body
/// @param contacts the contacts
/// @param options algorithm, policy, tolerance and limit
/// @return the solution and the bodies after
[[nodiscard]] ComplementarityResolution resolve_complementarity(
    std::span<const multipoint::Body> bodies, std::span<const Elasticity> elasticities,
    std::span<const multipoint::Contact> contacts, const ComplementarityOptions& options = {});

/// @brief As the other overload, every body with the same elasticity.
/// @param bodies the bodies
/// @param elasticity everyone's elasticity
/// @param contacts the contacts
/// @param options algorithm, policy, tolerance and limit
/// @return the solution and the bodies after
[[nodiscard]] ComplementarityResolution resolve_complementarity(
    std::span<const multipoint::Body> bodies, Elasticity elasticity,
    std::span<const multipoint::Contact> contacts, const ComplementarityOptions& options = {});

}  // namespace impulse::methods

namespace impulse {
/// @brief The names of the algorithms as reports print them.
template <>
struct EnumNames<methods::LcpAlgorithm> {
  /// "automatic", "lemke", "active-set", "projected-gauss-seidel"
  static constexpr std::array<Named<methods::LcpAlgorithm>, 4> table{
      {{methods::LcpAlgorithm::automatic, "automatic"},
       {methods::LcpAlgorithm::lemke, "lemke"},
       {methods::LcpAlgorithm::active_set, "active-set"},
       {methods::LcpAlgorithm::projected_gauss_seidel, "projected-gauss-seidel"}}};
};

/// @brief The names of the complementarity statuses.
template <>
struct EnumNames<methods::LcpStatus> {
  /// "solved", "iteration-limit", "inaccurate", "infeasible", "non-finite"
  static constexpr std::array<Named<methods::LcpStatus>, 5> table{
      {{methods::LcpStatus::solved, "solved"},
       {methods::LcpStatus::iteration_limit, "iteration-limit"},
       {methods::LcpStatus::inaccurate, "inaccurate"},
       {methods::LcpStatus::infeasible, "infeasible"},
       {methods::LcpStatus::non_finite, "non-finite"}}};
};

/// @brief The names of the ends of Lemke's method on a general problem.
template <>
struct EnumNames<methods::LemkeEnd> {
  /// "solution", "ray", "pivot-limit", "non-finite"
  static constexpr std::array<Named<methods::LemkeEnd>, 4> table{
      {{methods::LemkeEnd::solution, "solution"},
       {methods::LemkeEnd::ray, "ray"},
       {methods::LemkeEnd::pivot_limit, "pivot-limit"},
       {methods::LemkeEnd::non_finite, "non-finite"}}};
};
}  // namespace impulse
