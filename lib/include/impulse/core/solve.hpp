// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Solving A·Fdt = B, with the policies for dependent and inconsistent systems.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "impulse/core/names.hpp"
#include "impulse/core/system.hpp"

namespace impulse {

/// @brief What to do when the system has many solutions (A is singular, B in its range).
enum class DependentPolicy {
  /// The solution of least Euclidean norm. Where the paper asks for equal impulses (a body
  /// resting on parallel contacts) this is that solution.
  minimum_norm,
  /// A basic solution: the free impulses are zero, so the impulse sits on as few contacts as the
  /// rank allows. The contrast to the paper's equal impulses.
  basic,
};

/// @brief What to do when no impulses satisfy every equation (B outside the range of A).
enum class InconsistentPolicy {
  /// Minimise @f$ \|A\,F\,dt - B\| @f$ (then apply the DependentPolicy among the minimisers).
  least_squares,
  /// The paper's rule (4.4): ignore equations until the rest is consistent. Equations are taken
  /// in contact order; one that contradicts those kept before it is dropped.
  drop_equation,
};

/// @brief The scene format's names of the policies for dependent systems (impulse::name_of).
template <>
struct EnumNames<DependentPolicy> {
  /// "minimum-norm", "basic"
  static constexpr std::array<Named<DependentPolicy>, 2> table{
      {{DependentPolicy::minimum_norm, "minimum-norm"}, {DependentPolicy::basic, "basic"}}};
};

/// @brief The scene format's names of the policies for inconsistent systems (impulse::name_of).
template <>
struct EnumNames<InconsistentPolicy> {
  /// "least-squares", "drop-equation"
  static constexpr std::array<Named<InconsistentPolicy>, 2> table{
      {{InconsistentPolicy::least_squares, "least-squares"},
       {InconsistentPolicy::drop_equation, "drop-equation"}}};
};

/// @brief Which method solves a many-contact system.
enum class SolveMethod {
  /// The sparse method for systems kept sparse (ContactSystem::is_sparse(), i.e. above
  /// sparse_threshold contacts) that carry their factor and use the default policies; the
  /// dense one otherwise. A sparse answer in doubt (the Lanczos steps find eigenvalues of A, on
  /// its range, below the level its shifted pivots resolve, which they take for null space) is
  /// solved again by the dense method up to dense_limit contacts; its condition estimate then
  /// keeps the larger of the two methods' estimates.
  automatic,
  /// The complete orthogonal decomposition of G (or of A without a factor): exact rank,
  /// twice the digits, cubic cost and N² storage. The only method for DependentPolicy::basic
  /// and InconsistentPolicy::drop_equation.
  dense,
  /// Sparse factorisations only, for systems that carry their factor (others are solved dense):
  /// conjugate gradients on A preconditioned by a sparse LDLᵀ of @f$ A + \lambda I @f$
  /// (@f$ \lambda = 10^{-10} \max_v A_{vv} @f$), which gives any solution @f$ \hat{x} @f$;
  /// then the minimum-norm one as @f$ G^T y @f$ with @f$ G G^T y = G\,\hat{x} @f$, by
  /// conjugate gradients preconditioned from the same LDLᵀ. Where fewer velocities are moved by
  /// a contact (rows of G with an entry) than there are contacts, as on a pyramid of boxes, it
  /// factors @f$ G G^T + \lambda I @f$ instead (λ from its diagonal), the smaller system with
  /// A's nonzero eigenvalues, and one run of conjugate gradients preconditioned by
  /// @f$ G^T (G G^T + \lambda I)^{-2} G @f$ gives the minimum-norm solution directly
  /// (see Solution::factored_velocities). The rank is an estimate from the pivots of the
  /// factorisation; the condition number an estimate from them, A's diagonal and a few Lanczos
  /// steps on A.
  sparse,
};

/// @brief Above this condition estimate of A, a solution is reported as ill-conditioned
/// (`impulselab solve` and `sweep` warn; the fuzzer and the hostile tests hold the laws of the
/// paper's system only up to it).
///
/// Rounding changes the impulses by up to about κ·ε of their size (κ the condition estimate,
/// ε = 2.2e-16, times a small factor measured on the hostile scenes, see
/// docs/pages/accuracy.md). At κ = 1e8 that is about 2e-8: half of the 16 digits of a double
/// are rounding, and with the measured factor the error reaches the sixth significant digit,
/// the last one the text report prints.
inline constexpr double ill_conditioned = 1e8;

/// @brief The most contacts a system may have when only the dense method can serve it
/// (DependentPolicy::basic or InconsistentPolicy::drop_equation): its N×N matrices take 8·N²
/// bytes each (32 MiB at 2,048; 80 GB at 100,000) and its cost grows as N³ (seconds at 2,048).
/// The same bound limits the dense method's second opinion on a sparse system whose estimate is
/// in doubt (SolveMethod::automatic).
inline constexpr Eigen::Index dense_limit = 2048;

/// @brief How to solve: the two policies and the tolerances behind the diagnostics.
struct SolverOptions {
  DependentPolicy dependent = DependentPolicy::minimum_norm;            ///< many solutions
  InconsistentPolicy inconsistent = InconsistentPolicy::least_squares;  ///< no solution
  /// Pivots of the column-pivoted QR of A below this fraction of the largest one count as zero
  /// when the rank is decided (when the system carries its factor G, pivots of G below the square
  /// root of it). 0 selects Eigen's default: the matrix's size times the machine epsilon.
  double rank_tolerance = 0.0;
  /// The system counts as consistent when
  /// @f$ \|A\,F\,dt - B\| \le \tau\,(\|A\|_F\,\|F\,dt\| + \|B\|) + (N + 1)^2 \eta @f$
  /// with this @f$ \tau @f$ (@f$ \eta @f$ the smallest subnormal double: the absolute rounding
  /// of numbers that small).
  double consistency_tolerance = 1e-9;
  /// Dense or sparse (see SolveMethod).
  SolveMethod method = SolveMethod::automatic;
  /// The sparse method's iterations stop when
  /// @f$ \|B - A\,F\,dt\| \le \tau\,(\|\,|A|\,|F\,dt|\,\| + \|B\|) @f$: the residual
  /// against the size of the terms it sums, the level rounding leaves it at (or earlier, when
  /// rounding stops them from gaining).
  double sparse_tolerance = 1e-13;
  /// The sparse method's limit on iterations, for each of its runs of conjugate gradients (two,
  /// or one where it factors the moved velocities, Solution::factored_velocities).
  int max_iterations = 100;
};

/// @brief Whether the numbers allowed a solution. Bad input is an exception instead.
enum class SolveStatus {
  success,     ///< Fdt holds the impulses
  non_finite,  ///< A or B held a NaN or an infinity (e.g. an overflowing 1/m); Fdt is all NaN
};

/// @brief The impulses, and the system they solve with its diagnostics.
///
/// A system solved by the sparse method (`method == SolveMethod::sparse`) leaves `A` empty
/// (0×0) and gives A in `sparse_A` instead; its `rank` and `condition_estimate` are estimates
/// (`rank_estimated`), `iterations` counts its conjugate-gradient steps.
struct Solution {
  SolveStatus status = SolveStatus::success;  ///< whether Fdt is meaningful
  Eigen::VectorXd Fdt;                        ///< impulse magnitude at each contact
  Eigen::MatrixXd A;                          ///< the system solved (dense method; else 0×0)
  Eigen::VectorXd B;                          ///< its right-hand side
  /// Numerical rank of A. The dense method reads it from the pivoted QR; the sparse method
  /// estimates it as the count of LDLᵀ pivots of @f$ A + \lambda I @f$ (or of
  /// @f$ G G^T + \lambda I @f$, see factored_velocities) above @f$ 10^3 \lambda @f$ (see
  /// rank_estimated).
  Eigen::Index rank = 0;
  double residual = 0.0;   ///< @f$ \|A\,F\,dt - B\|_2 @f$ of the whole system
  bool dependent = false;  ///< rank < N: many impulse vectors act the same
  bool consistent = true;  ///< B lies in the range of A (within tolerance)
  /// Largest over smallest retained pivot of the column-pivoted QR of A (or the square of that
  /// ratio for the factor G, when the system carries one): an estimate of the condition number
  /// of A on its range (1 for the empty system, infinity when A is zero but N > 0). Relative
  /// errors of Fdt are bounded by roughly this times the input's (docs/pages/accuracy.md has the
  /// figures measured on hostile scenes). The sparse method gives the largest of three lower
  /// bounds: the ratio of the largest to the smallest retained LDLᵀ pivot, the ratio of A's
  /// largest to its smallest positive diagonal entry, and the ratio of the extreme Ritz values of
  /// twelve Lanczos steps on A started in its range (which sees eigenvalues the shifted pivots
  /// count as null space; rounding may put it above the truth by about ε times the estimate).
  /// It can still be far below the truth when A's spectrum is spread over more values than
  /// twelve steps resolve (docs/pages/accuracy.md).
  double condition_estimate = 1.0;
  std::vector<Eigen::Index> dropped;  ///< equations ignored under InconsistentPolicy::drop_equation
  SolverOptions options;              ///< the policies and tolerances used
  SolveMethod method = SolveMethod::dense;  ///< the method used: dense or sparse
  Eigen::SparseMatrix<double> sparse_A;     ///< the system solved (sparse method; else 0×0)
  bool rank_estimated = false;  ///< true when rank and condition_estimate are sparse estimates
  int iterations = 0;           ///< conjugate-gradient steps of the sparse method (0: dense)
  /// True when the sparse method factored @f$ G G^T + \lambda I @f$, one row per velocity,
  /// rather than @f$ A + \lambda I @f$: it does where fewer velocities are moved by a contact
  /// than there are contacts (a pyramid of boxes). Rank and pivots are then that matrix's.
  bool factored_velocities = false;
};

/// @brief Throws InvalidInput when @p contacts exceed dense_limit and @p options ask for a policy
/// that only the dense method serves: `"2049 contacts with the policies "basic" and
/// "least-squares", which only the dense method serves: it takes at most 2048 …"`.
/// @param contacts N, the number of contacts
/// @param options the policies
void require_dense_fits(Eigen::Index contacts, const SolverOptions& options);

/// @brief Solves A·Fdt = B under the given policies.
///
/// When the system carries its factor (@f$ A = G^T G @f$, @f$ B = G^T w @f$, as systems
/// assembled from bodies do), the impulses are the least-squares solution of
/// @f$ G\,F\,dt \approx w @f$, which has the same minimum-norm solution but is solved from a
/// QR factorisation of G: the velocities after the collision then carry the rounding of
/// @f$ \sqrt{\kappa(A)} @f$ rather than of @f$ \kappa(A) @f$. Otherwise A itself is factored.
/// Rank, residual and consistency always refer to A and B. Large systems kept sparse are solved
/// by the sparse method (see SolveMethod), which returns the same minimum-norm impulses.
/// @param system the assembled system
/// @param options policies and tolerances (policies that only the dense method serves on more
///        than dense_limit contacts throw InvalidInput, see require_dense_fits())
/// @return the impulses with A, B, rank, residual and the other diagnostics
[[nodiscard]] Solution solve(const ContactSystem& system, const SolverOptions& options = {});

/// @brief The single-contact solution @f$ F\,dt = B / A @f$ (end of section 1.3), no allocation.
struct ScalarSolution {
  SolveStatus status = SolveStatus::success;  ///< whether Fdt is meaningful
  double Fdt = 0.0;                           ///< the impulse magnitude
  double A = 0.0;                             ///< the summed a's
  double B = 0.0;                             ///< the summed b's
  double residual = 0.0;                      ///< @f$ |A\,F\,dt - B| @f$
  bool dependent = false;                     ///< A = 0 (both bodies static): any Fdt acts the same
  bool consistent = true;                     ///< false when A = 0 but B ≠ 0
};

namespace detail {
// The least-squares solution of M x ~ rhs of least norm, from a complete orthogonal
// decomposition whose pivots below `threshold` times the largest count as zero (0: Eigen's
// default); zero when M is zero or has no rows. The dense method and the complementarity
// method's settling of its pivots both solve with it.
Eigen::VectorXd least_norm(const Eigen::MatrixXd& M, const Eigen::VectorXd& rhs, double threshold);
// The least-norm impulses on the contacts `on` (zero elsewhere) that satisfy those contacts'
// equations of A·F = B: from the columns `on` of the factor G (A = GᵀG, B = Gᵀw) when the system
// carries it, with the pivot threshold √rank_tolerance (the one on A, see
// SolverOptions::rank_tolerance, is its square), else from A's block with rank_tolerance. The
// choice that solve() makes for the whole system.
Eigen::VectorXd least_norm_on(const Eigen::MatrixXd& A, const Eigen::VectorXd& B,
                              const Eigen::MatrixXd* G, const Eigen::VectorXd* w,
                              const std::vector<Eigen::Index>& on, double rank_tolerance);
// The 2-norm of finite numbers, scaled by powers of two so that it neither overflows nor
// underflows and raises no floating-point exception (Eigen's stableNorm() overflows computing
// 1 over a subnormal entry). The residuals and tolerances of solve() use it.
double quiet_norm(const Eigen::Ref<const Eigen::VectorXd>& v);
// The common case of the single-contact solve in one branch: A and B finite, A not zero. The
// tests raise no floating-point exception for a NaN or an infinity (std::isfinite and `!=` are
// quiet), so a caller that traps them gets the non_finite status.
inline bool all_finite_and_nonzero(ScalarContribution system) {
  const auto finite = static_cast<unsigned>(std::isfinite(system.a)) &
                      static_cast<unsigned>(std::isfinite(system.b));
  return (finite & static_cast<unsigned>(system.a != 0.0)) != 0U;
}
}  // namespace detail

/// @brief Solves the one-contact system. A = 0 gives Fdt = 0, the minimum-norm choice.
/// @param system the summed contributions (A, B)
/// @return the impulse magnitude and its diagnostics
[[nodiscard]] inline ScalarSolution solve(ScalarContribution system) {
  // Inline: the single-contact path costs no call (see bench/single_contact.cpp).
  ScalarSolution solution;
  solution.A = system.a;
  solution.B = system.b;
  if (detail::all_finite_and_nonzero(system)) [[likely]] {
    solution.Fdt = system.b / system.a;  // end of section 1.3: Fdt = B / A
  } else if (!std::isfinite(system.a) || !std::isfinite(system.b)) {
    solution.status = SolveStatus::non_finite;
    solution.Fdt = std::numeric_limits<double>::quiet_NaN();
    solution.residual = std::numeric_limits<double>::quiet_NaN();
    solution.consistent = false;
    return solution;
  } else {
    // A = 0: neither body can move along the normal: every Fdt acts the same; take the least.
    solution.dependent = true;
    solution.consistent = system.b == 0.0;
    solution.Fdt = 0.0;
  }
  solution.residual = std::abs(system.a * solution.Fdt - system.b);
  return solution;
}

}  // namespace impulse
