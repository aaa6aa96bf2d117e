// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/solve.hpp"

#include <Eigen/QR>
#include <cmath>
#include <limits>

namespace impulse {

std::string_view to_string(DependentPolicy policy) {
  switch (policy) {
    case DependentPolicy::minimum_norm:
      return "minimum-norm";
    case DependentPolicy::basic:
      return "basic";
  }
  return "?";
}

std::string_view to_string(InconsistentPolicy policy) {
  switch (policy) {
    case InconsistentPolicy::least_squares:
      return "least-squares";
    case InconsistentPolicy::drop_equation:
      return "drop-equation";
  }
  return "?";
}

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using PivotedQR = Eigen::ColPivHouseholderQR<MatrixXd>;
using Orthogonal = Eigen::CompleteOrthogonalDecomposition<MatrixXd>;

// What one factorisation of M x ~ rhs tells: the rank, the pivot ratio and the solution that
// the dependent-system policy asks for (least squares when rhs is outside the range of M).
struct Factored {
  Index rank = 0;
  double pivot_ratio = 1.0;
  VectorXd x;
};

Factored factor_and_solve(const MatrixXd& M, const VectorXd& rhs, double threshold,
                          DependentPolicy policy) {
  Factored result;
  PivotedQR qr;
  if (threshold > 0.0) {
    qr.setThreshold(threshold);
  }
  qr.compute(M);
  result.rank = qr.rank();
  const auto pivots = qr.matrixQR().diagonal().cwiseAbs();
  result.pivot_ratio = result.rank == 0 ? std::numeric_limits<double>::infinity()
                                        : pivots(0) / pivots(result.rank - 1);
  if (policy == DependentPolicy::minimum_norm) {
    // The least-squares solution of least norm, from the complete orthogonal decomposition.
    Orthogonal cod;
    if (threshold > 0.0) {
      cod.setThreshold(threshold);
    }
    cod.compute(M);
    result.x = cod.solve(rhs);
  } else {
    // A basic solution: R11 y = (Q^T rhs) on the retained pivots, the free unknowns zero.
    // (Eigen's ColPivHouseholderQR::solve picks its pivots with a fixed threshold of its own.)
    VectorXd c = rhs;
    c.applyOnTheLeft(qr.householderQ().adjoint());
    VectorXd y = VectorXd::Zero(M.cols());
    y.head(result.rank) = qr.matrixQR()
                              .topLeftCorner(result.rank, result.rank)
                              .triangularView<Eigen::Upper>()
                              .solve(c.head(result.rank));
    result.x = qr.colsPermutation() * y;
  }
  return result;
}

bool within_tolerance(const MatrixXd& A, const VectorXd& B, const VectorXd& x, double tolerance) {
  return (A * x - B).norm() <= tolerance * (A.norm() * x.norm() + B.norm());
}

bool is_consistent(const MatrixXd& A, const VectorXd& B, const SolverOptions& options) {
  const Factored f = factor_and_solve(A, B, options.rank_tolerance, DependentPolicy::minimum_norm);
  return within_tolerance(A, B, f.x, options.consistency_tolerance);
}

MatrixXd rows_of(const MatrixXd& M, const std::vector<Index>& rows) {
  return M(rows, Eigen::all);
}
VectorXd rows_of(const VectorXd& v, const std::vector<Index>& rows) {
  return v(rows);
}

// The paper's rule for an inconsistent system: keep the equations, in contact order, that agree
// with those kept so far; solve the kept ones.
VectorXd drop_contradicting_equations(Solution& solution, const SolverOptions& options) {
  const MatrixXd& A = solution.A;
  const VectorXd& B = solution.B;
  std::vector<Index> kept;
  for (Index v = 0; v < A.rows(); ++v) {
    kept.push_back(v);
    if (!is_consistent(rows_of(A, kept), rows_of(B, kept), options)) {
      kept.pop_back();
      solution.dropped.push_back(v);
    }
  }
  if (kept.empty()) {
    return VectorXd::Zero(A.cols());
  }
  return factor_and_solve(rows_of(A, kept), rows_of(B, kept), options.rank_tolerance,
                          options.dependent)
      .x;
}

void mark_non_finite(Solution& solution) {
  solution.status = SolveStatus::non_finite;
  solution.Fdt = VectorXd::Constant(solution.B.size(), std::numeric_limits<double>::quiet_NaN());
  solution.residual = std::numeric_limits<double>::quiet_NaN();
  solution.consistent = false;
  solution.condition_estimate = std::numeric_limits<double>::infinity();
}

}  // namespace

Solution solve(const ContactSystem& system, const SolverOptions& options) {
  Solution solution;
  solution.A = system.A();
  solution.B = system.B();
  solution.options = options;
  const MatrixXd& A = solution.A;
  const VectorXd& B = solution.B;
  const Index n = system.size();

  if (!A.allFinite() || !B.allFinite()) {
    mark_non_finite(solution);
    return solution;
  }
  if (n == 0) {
    solution.Fdt = VectorXd(0);
    return solution;
  }

  Factored f;
  if (system.has_factor()) {
    // A = G^T G and B = G^T w: the impulses are the least-squares solution of G Fdt ~ w, and
    // factoring G rather than A keeps twice the digits (the condition number of A is that of G
    // squared). A pivot threshold t on A is one of sqrt(t) on G.
    MatrixXd G;
    VectorXd w;
    system.factor(G, w);
    if (!G.allFinite() || !w.allFinite()) {
      mark_non_finite(solution);
      return solution;
    }
    const double threshold = options.rank_tolerance > 0.0 ? std::sqrt(options.rank_tolerance) : 0.0;
    f = factor_and_solve(G, w, threshold, options.dependent);
    f.pivot_ratio *= f.pivot_ratio;
  } else {
    f = factor_and_solve(A, B, options.rank_tolerance, options.dependent);
  }
  solution.rank = f.rank;
  solution.dependent = f.rank < n;
  solution.condition_estimate = f.pivot_ratio;
  solution.Fdt = std::move(f.x);
  solution.consistent = within_tolerance(A, B, solution.Fdt, options.consistency_tolerance);
  if (!solution.consistent && options.inconsistent == InconsistentPolicy::drop_equation) {
    solution.Fdt = drop_contradicting_equations(solution, options);
  }
  solution.residual = (A * solution.Fdt - B).norm();
  return solution;
}

}  // namespace impulse
