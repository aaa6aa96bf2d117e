// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/solve.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "shifted_factor.hpp"

namespace impulse {

void require_dense_fits(Eigen::Index contacts, const SolverOptions& options) {
  const bool dense_only = options.dependent != DependentPolicy::minimum_norm ||
                          options.inconsistent != InconsistentPolicy::least_squares;
  if (!dense_only || contacts <= dense_limit) {
    return;
  }
  std::string message(std::to_string(contacts));
  message.append(" contacts with the policies \"")
      .append(name_of(options.dependent))
      .append("\" and \"")
      .append(name_of(options.inconsistent))
      .append("\", which only the dense method serves: it takes at most ")
      .append(std::to_string(dense_limit))
      .append(
          " (its matrices grow as the square of the contacts); the default policies solve "
          "large scenes with the sparse method");
  throw InvalidInput(message);
}

Eigen::VectorXd detail::least_norm(const Eigen::MatrixXd& M, const Eigen::VectorXd& rhs,
                                   double threshold) {
  if (M.rows() == 0 || M.isZero(0.0)) {
    return Eigen::VectorXd::Zero(M.cols());  // every x acts the same: the least is zero
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  if (threshold > 0.0) {
    cod.setThreshold(threshold);
  }
  cod.compute(M);
  return cod.solve(rhs);
}

Eigen::VectorXd detail::least_norm_on(const Eigen::MatrixXd& A, const Eigen::VectorXd& B,
                                      const Eigen::MatrixXd* G, const Eigen::VectorXd* w,
                                      const std::vector<Eigen::Index>& contacts,
                                      double rank_tolerance) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(B.size());
  if (contacts.empty()) {
    return F;
  }
  if (G != nullptr) {
    // A = G^T G: a pivot threshold t on A is one of sqrt(t) on G.
    const double threshold = rank_tolerance > 0.0 ? std::sqrt(rank_tolerance) : 0.0;
    F(contacts) = least_norm((*G)(Eigen::all, contacts), *w, threshold);
  } else {
    F(contacts) = least_norm(A(contacts, contacts), B(contacts), rank_tolerance);
  }
  return F;
}

// The 2-norm of finite numbers, without overflow or underflow in its squares and without raising
// a floating-point exception: the entries are scaled by a power of two (exactly) so that the
// largest is near 1. Entries of A near 1e300 (an inertia near 1e-300) would make the plain sum of
// squares infinite, and an infinite tolerance would call any residual consistent; entries below
// 1e-154 would square to 0. (Eigen's stableNorm() does the same job but divides 1 by the largest
// entry, which overflows, and traps in a caller that traps exceptions, for a subnormal one.)
double detail::quiet_norm(const Eigen::Ref<const Eigen::VectorXd>& v) {
  if (v.size() == 0) {
    return 0.0;
  }
  const double largest = v.cwiseAbs().maxCoeff();
  if (!std::isgreater(largest, 0.0) || !std::isfinite(largest)) {
    return largest;
  }
  const int exponent = std::ilogb(largest);
  const int half = exponent / 2;  // two steps: 2^-exponent itself overflows for a subnormal
  // Scaled as it is summed, without a copy: A's values at 100,000 contacts are 11 MB of fresh
  // memory, and its page faults cost more than the sum itself.
  const double norm = ((v * std::ldexp(1.0, -half)) * std::ldexp(1.0, half - exponent)).norm();
  return std::ldexp(std::ldexp(norm, half), exponent - half);
}

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using PivotedQR = Eigen::ColPivHouseholderQR<MatrixXd>;

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
    result.x = detail::least_norm(M, rhs, threshold);
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

double quiet_matrix_norm(const MatrixXd& A) {
  return detail::quiet_norm(Eigen::Map<const VectorXd>(A.data(), A.size()));
}

// The absolute part of the consistency test: (N + 1)² times the smallest subnormal. Numbers that
// small (a scene of elasticity 5e-323) round in absolute steps, which no relative tolerance sees.
double underflow_allowance(Index n) {
  const auto terms = static_cast<double>(n + 1);
  return terms * terms * std::numeric_limits<double>::denorm_min();
}

// The consistency test of SolverOptions::consistency_tolerance, dense or sparse: the residual's
// norm against the norms of the terms it is the difference of, plus the underflow allowance.
bool residual_within(double residual, double A_norm, const VectorXd& x, const VectorXd& B,
                     double tolerance) {
  return residual <= tolerance * (A_norm * detail::quiet_norm(x) + detail::quiet_norm(B)) +
                         underflow_allowance(B.size());
}

bool within_tolerance(const MatrixXd& A, const VectorXd& B, const VectorXd& x, double tolerance) {
  const VectorXd r = A * x - B;
  return residual_within(detail::quiet_norm(r), quiet_matrix_norm(A), x, B, tolerance);
}

// A = 0: no body at any contact can move along its normal, so every Fdt acts the same; the least,
// zero, is the answer (and a QR of a matrix without rows would divide 0 by 0).
void solve_zero_system(Solution& solution, Index n) {
  solution.Fdt = VectorXd::Zero(n);
  solution.rank = 0;
  solution.dependent = true;
  solution.condition_estimate = std::numeric_limits<double>::infinity();
  solution.consistent = solution.B.isZero(0.0);
  solution.residual = detail::quiet_norm(solution.B);
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

// ---- The sparse method ---------------------------------------------------------------------

using SparseMatrix = Eigen::SparseMatrix<double>;

// The shift of A + lambda I, relative to A's largest diagonal entry. Small enough that the
// preconditioner is nearly A's inverse on its range (conjugate gradients then converge in a few
// steps up to condition numbers near 1e10), large enough that A + lambda I factors stably.
constexpr double shift = 1e-10;
// LDLT pivots of A + lambda I up to this many lambdas count as A's null space in the rank
// estimate (a dependent direction leaves a pivot of about lambda).
constexpr double null_pivot = 1e3;

// The largest step length the conjugate gradients below accept. Their preconditioned operators
// have eigenvalues s / (s + lambda) (or its square) in (0, 1] on the range they work in, so in
// exact arithmetic every step length is at least 1 and it exceeds 100 only along directions
// where s < lambda / 99, about 1e-12 of A's largest diagonal entry: numerically the null space.
// A longer step comes from rounding that the preconditioner amplified (by 1/lambda) along the
// null space; taking it would throw the impulses far along it, so the iteration stops there.
constexpr double largest_step = 100.0;

struct Shifted {
  detail::ShiftedFactor factor;  // CHOLMOD's or Eigen's, as the library was built
  double lambda = 0.0;
};

// The factorisation of M + lambda I with lambda = shift * max diag(M). Returns false if it failed.
bool factor_shifted(const SparseMatrix& M, Shifted& shifted) {
  shifted.lambda = shift * M.diagonal().maxCoeff();
  return shifted.factor.compute(M, shifted.lambda);
}

// y = M v and y = M^T v, compiled once for every product of the sparse method: each copy of
// Eigen's product inlined where it is used costs the page's WebAssembly module about a kilobyte.
[[gnu::noinline]] void product(const SparseMatrix& M, const VectorXd& v, VectorXd& y) {
  y.noalias() = M * v;
}
[[gnu::noinline]] void transposed_product(const SparseMatrix& M, const VectorXd& v, VectorXd& y) {
  y.noalias() = M.transpose() * v;
}

// |K| |x| into sizes: the size of the terms each entry of K x sums (without a copy of K).
void absolute_product(const SparseMatrix& K, const VectorXd& x, VectorXd& sizes) {
  sizes.setZero(K.rows());
  for (Index j = 0; j < K.outerSize(); ++j) {
    const double xj = std::abs(x(j));
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      sizes(it.row()) += std::abs(it.value()) * xj;
    }
  }
}

// Restarted, preconditioned conjugate gradients on K T p-steps, started from x = 0.
//
// `step(p, dx)` puts in dx the step a search direction p (one entry per row of K) makes in the
// unknowns x: p itself when K = M is the consistent positive semi-definite system itself
// (conjugate_gradients), G^T p when K = G and the unknowns are x = G^T y of G G^T y = g
// (range_solution). Each step then adds alpha dx to x and removes alpha K dx from the residual;
// the curvature p^T K dx is p^T M p, or |G^T p|^2. `precondition(r, z)` puts the preconditioned
// residual in z. Every vector is allocated once, before the steps (see ShiftedFactor::solve).
//
// It stops when |rhs - K x| <= tolerance (| |K| |x| | + |rhs|): the residual against the size
// of the terms it is the sum of, the level at which rounding leaves it (a residual relative to
// |rhs| alone can be out of reach when the impulses are much larger than the right-hand side,
// e.g. at the foot of a tall stack). That size is taken at each restart; in between, the last
// one (smaller, as x grows) makes the test stricter. With Sizes::every_step it is taken after
// each step: a preconditioner that does not amplify rounding along the null space leaves no step
// longer than largest_step when the residual reaches its rounding level, and the recursive
// residual would go on chasing rounding below a stricter test. When the recursive residual passes
// the test, the true one is computed; if it fails, the iteration restarts from it, unless the last
// restart gained less than a factor 2 (rounding level). A step longer than largest_step, or a
// curvature that is not positive, means rounding has taken over: it stops before that step.
// Returns the number of steps.
enum class Sizes { at_restarts, every_step };

// A linear map applied into a vector kept by the caller (the step and the preconditioner
// below): a reference to a callable, so that the iteration is compiled once for its three uses
// rather than once for each (a template), and without std::function's copying machinery for
// each callable: both would put the page's WebAssembly module over its budget.
class Apply {
 public:
  template <typename F>
  Apply(const F& f)  // NOLINT(google-explicit-constructor): a lambda stands for it
      : object_(&f), call_([](const void* object, const VectorXd& v, VectorXd& out) {
          (*static_cast<const F*>(object))(v, out);
        }) {}
  void operator()(const VectorXd& v, VectorXd& out) const { call_(object_, v, out); }

 private:
  const void* object_;
  void (*call_)(const void*, const VectorXd&, VectorXd&);
};

int restarted_conjugate_gradients(const SparseMatrix& K, const VectorXd& rhs, const Apply& step,
                                  const Apply& precondition, double tolerance, int max_iterations,
                                  VectorXd& x, Sizes measured = Sizes::at_restarts) {
  x = VectorXd::Zero(K.cols());
  const double rhs_norm = rhs.norm();
  double terms = rhs_norm;  // | |K| |x| | + |rhs| at the last restart
  const auto reached = [&](double residual) { return residual <= tolerance * terms; };
  VectorXd r = rhs;
  VectorXd z(K.rows());
  VectorXd p(K.rows());
  VectorXd dx(K.cols());
  VectorXd Kdx(K.rows());
  VectorXd sizes(K.rows());
  int steps = 0;
  double rz = 0.0;
  double last_true = std::numeric_limits<double>::infinity();
  bool restart = true;
  while (steps < max_iterations) {
    if (restart) {
      const double true_residual = r.norm();
      absolute_product(K, x, sizes);
      terms = sizes.norm() + rhs_norm;
      if (reached(true_residual) || !(true_residual < 0.5 * last_true)) {
        break;
      }
      last_true = true_residual;
      precondition(r, z);
      p = z;
      rz = r.dot(z);
      restart = false;
    }
    step(p, dx);
    product(K, dx, Kdx);
    const double curvature = p.dot(Kdx);
    const double alpha = rz / curvature;
    if (!(curvature > 0.0) || !(rz > 0.0) || !(alpha <= largest_step)) {
      break;  // rounding has taken over the direction (see largest_step): stop before the step
    }
    x += alpha * dx;
    r -= alpha * Kdx;
    ++steps;
    if (measured == Sizes::every_step) {
      absolute_product(K, x, sizes);
      terms = sizes.norm() + rhs_norm;
    }
    if (reached(r.norm())) {
      r = rhs;
      r.noalias() -= K * x;  // the true residual
      restart = true;
      continue;
    }
    precondition(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return steps;
}

// Conjugate gradients on the consistent positive semi-definite system M x = rhs, preconditioned
// by (M + lambda I)^-1 (`precondition(r, z)`, which must be an approximation of a function of M, so
// that every iterate stays in the range of M, up to rounding): on a dependent system they
// converge to the minimum-norm solution, as unpreconditioned CG would, only in far fewer steps.
int conjugate_gradients(const SparseMatrix& M, const VectorXd& rhs, const Apply& precondition,
                        double tolerance, int max_iterations, VectorXd& x,
                        Sizes measured = Sizes::at_restarts) {
  const auto same = [](const VectorXd& p, VectorXd& dx) { dx = p; };
  return restarted_conjugate_gradients(M, rhs, same, precondition, tolerance, max_iterations, x,
                                       measured);
}

// Conjugate gradients on G G^T y = g (g in the range of G), preconditioned by
// `precondition`, carried out on x = G^T y instead of y: every step adds alpha G^T p to x and
// the residual is g - G x. y itself, which the preconditioner may fill with large parts along
// the null space of G^T (directions no contact constrains, amplified by 1/lambda), is never
// accumulated, and G^T removes those parts from each step. x stays in the range of G^T: it is
// the minimum-norm solution of G x = g.
int range_solution(const SparseMatrix& G, const VectorXd& g, const Apply& precondition,
                   double tolerance, int max_iterations, VectorXd& x) {
  const auto transposed = [&G](const VectorXd& p, VectorXd& dx) { transposed_product(G, p, dx); };
  return restarted_conjugate_gradients(G, g, transposed, precondition, tolerance, max_iterations,
                                       x);
}

// The steps of the Lanczos process behind lanczos_spectrum(): each costs a product with A and a
// reorthogonalisation against the steps before, 20 to 30 ms for all twelve at 100,000 contacts,
// 4 to 20 % of the sparse solve (bench/README.md); they resolve a spectrum of up to about twelve
// clusters.
constexpr int lanczos_steps = 12;

// A lower bound of the condition number of A on its range that sees eigenvalues of any size: a
// few steps of the Lanczos process on A, fully reorthogonalised, started from a vector
// of the range of A (A times a fixed vector, whose entries are an integer hash: the same on
// every machine). The Ritz values lie between A's smallest eigenvalue on the Krylov space, hence
// on its range, and its largest, so their extreme ratio never exceeds the true one; a cluster of
// eigenvalues (the 998 equal ones of 1,000 balls around a body of mass 1e-9) is found in as many
// steps as there are clusters. Ritz values within 1e3 ε of the largest are rounding (a start
// vector carries rounding along the null space) and do not count. Returns {1, 1} for A = 0.
struct Spectrum {
  double largest = 1.0;   // the largest Ritz value: at most A's largest eigenvalue
  double smallest = 1.0;  // the smallest one above rounding: at least A's smallest on its range
};

Spectrum lanczos_spectrum(const SparseMatrix& A) {
  const Index n = A.rows();
  VectorXd z(n);
  for (Index i = 0; i < n; ++i) {
    const auto hash = (static_cast<std::uint64_t>(i) + 1) * 2654435761U % 4294967296U;
    z(i) = static_cast<double>(hash) / 4294967296.0 - 0.5;
  }
  VectorXd q;
  product(A, z, q);
  double beta = q.norm();
  if (!(beta > 0.0)) {
    return {};
  }
  // The rounding level of a product A q: a few ε times A's largest absolute row sum (which
  // bounds its eigenvalues). A step whose new direction is no longer than that has found an
  // invariant subspace: what is left is rounding, and normalising it would spoil the basis.
  double row_sum = 0.0;
  {
    VectorXd sums = VectorXd::Zero(n);
    for (Index k = 0; k < A.outerSize(); ++k) {
      for (SparseMatrix::InnerIterator it(A, k); it; ++it) {
        sums(it.row()) += std::abs(it.value());
      }
    }
    row_sum = sums.maxCoeff();
  }
  const double breakdown = 1e3 * std::numeric_limits<double>::epsilon() * row_sum;
  const Index steps = std::min<Index>(lanczos_steps, n);
  MatrixXd Q(n, steps);
  VectorXd alpha(steps);
  VectorXd off(steps);
  Index k = 0;
  q /= beta;
  VectorXd w(n);
  while (k < steps) {
    Q.col(k) = q;
    product(A, q, w);
    alpha(k) = q.dot(w);
    // Full reorthogonalisation against every Lanczos vector so far, twice ("twice is enough"):
    // they stay orthogonal to rounding. Once is not: on 1,000 balls around a body of mass 1e9
    // (κ = 1 + 5e-7) a single pass lets rounding build a Ritz value of 42.
    for (int pass = 0; pass < 2; ++pass) {
      const VectorXd coefficients = Q.leftCols(k + 1).transpose() * w;
      w.noalias() -= Q.leftCols(k + 1) * coefficients;
    }
    beta = w.norm();
    off(k) = beta;
    ++k;
    if (!(beta > breakdown)) {
      break;  // an invariant subspace: its Ritz values are eigenvalues
    }
    q = w / beta;
  }
  MatrixXd T = MatrixXd::Zero(k, k);
  for (Index i = 0; i < k; ++i) {
    T(i, i) = alpha(i);
    if (i + 1 < k) {
      T(i, i + 1) = off(i);
      T(i + 1, i) = off(i);
    }
  }
  const VectorXd ritz =
      Eigen::SelfAdjointEigenSolver<MatrixXd>(T, Eigen::EigenvaluesOnly).eigenvalues();
  Spectrum spectrum;
  spectrum.largest = 0.0;
  for (Index i = 0; i < ritz.size(); ++i) {
    spectrum.largest = std::max(spectrum.largest, ritz(i));
  }
  spectrum.smallest = spectrum.largest;
  for (Index i = 0; i < ritz.size(); ++i) {
    if (ritz(i) > 1e3 * std::numeric_limits<double>::epsilon() * spectrum.largest) {
      spectrum.smallest = std::min(spectrum.smallest, ritz(i));
    }
  }
  return spectrum.largest > 0.0 ? spectrum : Spectrum{};
}

// How many rows of G some contact moves (a nonzero entry). The others are velocities no contact
// changes (the sideways motion of a box on horizontal contacts), which add nothing to A.
Index moved_rows(const SparseMatrix& G) {
  std::vector<char> moved(static_cast<std::size_t>(G.rows()), 0);
  for (Index j = 0; j < G.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(G, j); it; ++it) {
      moved[static_cast<std::size_t>(it.row())] |= static_cast<char>(it.value() != 0.0);
    }
  }
  return static_cast<Index>(std::count(moved.begin(), moved.end(), 1));
}

// The lower triangle of G G^T (all the factorisation reads), as the sum over contacts of their
// columns' outer products, without G's stored zeros: a row no contact moves stays empty, and
// its pivot is lambda, which counts as null space.
SparseMatrix lower_product(const SparseMatrix& G) {
  std::size_t count = 0;
  for (Index j = 0; j < G.outerSize(); ++j) {
    const auto k = static_cast<std::size_t>(G.col(j).nonZeros());
    count += k * (k + 1) / 2;
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(count);
  for (Index j = 0; j < G.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator below(G, j); below; ++below) {
      for (SparseMatrix::InnerIterator above(G, j); above && above.row() <= below.row(); ++above) {
        const double product = below.value() * above.value();
        if (product != 0.0) {
          entries.emplace_back(below.row(), above.row(), product);
        }
      }
    }
  }
  SparseMatrix C(G.rows(), G.rows());
  const auto& summed = entries;  // the same const iterators as ContactSystem::sparse_A()
  C.setFromTriplets(summed.begin(), summed.end());
  return C;
}

// z = outer(F^-2 inner(r)), F the shifted factor: G^T F^-2 G r or G F^-2 G^T r, the
// preconditioners of both ways of iterating, with the work vectors kept between calls.
class TwoSolves {
 public:
  TwoSolves(const detail::ShiftedFactor& factor, Apply inner, Apply outer)
      : factor_(factor), inner_(inner), outer_(outer) {}
  void operator()(const VectorXd& r, VectorXd& z) const {
    inner_(r, inside_);
    factor_.solve(inside_, once_);
    factor_.solve(once_, twice_);
    outer_(twice_, z);
  }

 private:
  const detail::ShiftedFactor& factor_;
  Apply inner_;
  Apply outer_;
  mutable VectorXd inside_;
  mutable VectorXd once_;
  mutable VectorXd twice_;
};

// The sparse method's iterations, after its factorisation (of G G^T + lambda I when
// `by_velocities`, else of A + lambda I): the minimum-norm solution x of A x = B. Returns the
// number of steps.
int iterate(const SparseMatrix& A, const VectorXd& B, const SparseMatrix& G,
            const detail::ShiftedFactor& factor, bool by_velocities, const SolverOptions& options,
            VectorXd& x) {
  const auto by_G = [&G](const VectorXd& v, VectorXd& out) { product(G, v, out); };
  const auto by_G_transposed = [&G](const VectorXd& v, VectorXd& out) {
    transposed_product(G, v, out);
  };
  if (by_velocities) {
    // One run of conjugate gradients on A x = B, preconditioned by
    // G^T (G G^T + lambda I)^-2 G = (A + lambda I)^-2 A: a function of A, so that every iterate
    // lies in the range of A = range of G^T and the solution is the minimum-norm one without the
    // second step below; on that range it is nearly A's inverse (eigenvalues s^2 / (s^2 + lambda)^2
    // for s^2 of A). The rounding the two solves amplify by 1/lambda^2 lies in the null space of
    // G^T, which the product with G^T removes; so no step grows long when the residual reaches
    // rounding, and the sizes are taken at every step.
    const TwoSolves precondition(factor, by_G, by_G_transposed);
    return conjugate_gradients(A, B, precondition, options.sparse_tolerance, options.max_iterations,
                               x, Sizes::every_step);
  }
  // 1. Any solution x of A x = B (the minimum-norm one when A is regular).
  const auto shifted_inverse = [&factor](const VectorXd& r, VectorXd& z) { factor.solve(r, z); };
  int steps = conjugate_gradients(A, B, shifted_inverse, options.sparse_tolerance,
                                  options.max_iterations, x);
  // 2. x may carry a part in the null space of A = null space of G (the preconditioner
  // amplifies rounding there by 1/lambda). The minimum-norm solution has the same G x and
  // lies in the range of G^T: it is G^T y with G G^T y = G x, solved by conjugate gradients
  // too, with the preconditioner G (G^T G + lambda I)^-2 G^T from the factorisation already
  // made. On the range of G it is nearly (G G^T)^-1 (eigenvalues s^2 / (s^2 + lambda)^2 for
  // s^2 of G G^T) and, being G times something, it adds nothing along the null space of G^T:
  // the rounding it amplifies by 1/lambda^2 lies in the null space of G, which the product
  // with G removes. The step runs on every system, not only on those whose pivots show a
  // dependency: the pivot of a dependent direction is about lambda only when the direction is
  // well separated from the others, so the rank estimate can miss one in an ill-conditioned
  // system; on a regular system the step returns the same x for a few more iterations.
  const TwoSolves range_preconditioner(factor, by_G_transposed, by_G);
  VectorXd Gx(G.rows());
  product(G, x, Gx);
  // Judged against |G x| alone, the velocity change (not |G G^T| |y|).
  steps += range_solution(G, Gx, range_preconditioner, options.sparse_tolerance,
                          options.max_iterations, x);
  return steps;
}

// Solves a system that carries its factor with sparse factorisations only. Leaves solution.A
// empty and fills sparse_A. Returns false when a factorisation failed (the caller then solves
// densely). Sets `doubtful` when A has eigenvalues on its range below the level the shifted
// pivots resolve (null_pivot lambda): the pivots then take them for null space, the rank and
// the iterations' accuracy are estimates that can be far off (docs/pages/accuracy.md).
bool solve_sparse(const ContactSystem& system, const SolverOptions& options, Solution& solution,
                  bool& doubtful) {
  solution.method = SolveMethod::sparse;
  solution.rank_estimated = true;
  solution.sparse_A = system.sparse_A();
  const SparseMatrix& A = solution.sparse_A;
  const VectorXd& B = solution.B;
  const Index n = system.size();
  SparseMatrix G;
  VectorXd w;
  system.factor(G, w);
  const bool finite = all_finite_in(Eigen::Map<const VectorXd>(A.valuePtr(), A.nonZeros())) &&
                      all_finite_in(Eigen::Map<const VectorXd>(G.valuePtr(), G.nonZeros())) &&
                      all_finite_in(B) && all_finite_in(w);
  if (!finite) {
    mark_non_finite(solution);
    return true;
  }
  if (n == 0) {
    solution.Fdt = VectorXd(0);
    return true;
  }
  if (!(A.diagonal().maxCoeff() > 0.0)) {  // A is positive semi-definite: zero diagonal, A = 0
    solve_zero_system(solution, n);
    return true;
  }

  // The factorisation: of A + lambda I (one row per contact), or of G G^T + lambda I (one row
  // per velocity) when fewer velocities are moved by a contact than there are contacts, as on a
  // pyramid of boxes (four contacts and two moved velocities a box): its nonzero eigenvalues are
  // A's, and it is the smaller and sparser system (bench/README.md).
  const bool by_velocities = moved_rows(G) < n;
  Shifted shifted;
  if (!(by_velocities ? factor_shifted(lower_product(G), shifted) : factor_shifted(A, shifted))) {
    return false;
  }
  solution.factored_velocities = by_velocities;
  const VectorXd pivots = shifted.factor.pivots();
  const double null_level = null_pivot * shifted.lambda;
  Index retained = 0;
  double largest = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < pivots.size(); ++i) {
    if (pivots(i) > null_level) {
      ++retained;
      largest = std::max(largest, pivots(i));
      smallest = std::min(smallest, pivots(i));
    }
  }
  solution.rank = retained;
  solution.dependent = retained < n;
  // The pivots of the shifted matrix cannot see eigenvalues below about 1e3 lambda (1e-7 of the
  // largest diagonal entry): those count as null space. The ratio of A's largest to its smallest
  // diagonal entry is a lower bound of the condition number of a regular A (its extreme
  // eigenvalues enclose the diagonal), and it sees contacts of very different scales (masses
  // 1e-9 and 1e9) that the pivots take for a dependency. The estimate is the larger of the two.
  const VectorXd diagonal = A.diagonal();
  double smallest_diagonal = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < diagonal.size(); ++i) {
    if (diagonal(i) > 0.0) {
      smallest_diagonal = std::min(smallest_diagonal, diagonal(i));
    }
  }
  // The pivots and the diagonal miss eigenvalues hidden under the shift: a few Lanczos steps see
  // them, and say whether the pivots' picture can be trusted.
  const Spectrum spectrum = lanczos_spectrum(A);
  solution.condition_estimate =
      std::max({largest / smallest, diagonal.maxCoeff() / smallest_diagonal,
                spectrum.largest / spectrum.smallest});
  doubtful = spectrum.smallest < null_level;
  VectorXd x;
  solution.iterations = iterate(A, B, G, shifted.factor, by_velocities, options, x);
  solution.Fdt = std::move(x);
  VectorXd residual = B;
  residual.noalias() -= A * solution.Fdt;
  solution.residual = detail::quiet_norm(residual);
  const double A_norm = detail::quiet_norm(Eigen::Map<const VectorXd>(A.valuePtr(), A.nonZeros()));
  solution.consistent =
      residual_within(solution.residual, A_norm, solution.Fdt, B, options.consistency_tolerance);
  return true;
}

}  // namespace

Solution solve(const ContactSystem& system, const SolverOptions& options) {
  require_dense_fits(system.size(), options);
  Solution solution;
  solution.B = system.B();
  solution.options = options;
  // The sparse method gives the minimum-norm least-squares solution of a system built from
  // bodies (always consistent: B = G^T w); the other policies need the dense pivoted QR.
  const bool default_policies = options.dependent == DependentPolicy::minimum_norm &&
                                options.inconsistent == InconsistentPolicy::least_squares;
  const bool sparse = system.has_factor() && default_policies &&
                      (options.method == SolveMethod::sparse ||
                       (options.method == SolveMethod::automatic && system.is_sparse()));
  bool doubtful = false;
  double sparse_estimate = 1.0;
  if (sparse && solve_sparse(system, options, solution, doubtful)) {
    // A sparse answer in doubt (eigenvalues the pivots cannot see) gets the dense method's second
    // opinion while its matrices stay small; beyond, the estimate at least says how doubtful.
    if (!doubtful || options.method != SolveMethod::automatic || system.size() > dense_limit) {
      return solution;
    }
    sparse_estimate = solution.condition_estimate;
  }
  solution = Solution{};
  solution.B = system.B();
  solution.options = options;
  solution.A = system.is_sparse() ? MatrixXd(system.sparse_A()) : system.A();
  const MatrixXd& A = solution.A;
  const VectorXd& B = solution.B;
  const Index n = system.size();

  if (!all_finite_in(A) || !all_finite_in(B)) {
    mark_non_finite(solution);
    return solution;
  }
  if (n == 0) {
    solution.Fdt = VectorXd(0);
    return solution;
  }

  if (A.isZero(0.0)) {
    solve_zero_system(solution, n);
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
    if (!all_finite_in(G) || !all_finite_in(w)) {
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
  // With the sparse method's Lanczos estimate when it asked for this second opinion: the larger
  // of two lower bounds.
  solution.condition_estimate = std::max(f.pivot_ratio, sparse_estimate);
  solution.Fdt = std::move(f.x);
  solution.consistent = within_tolerance(A, B, solution.Fdt, options.consistency_tolerance);
  if (!solution.consistent && options.inconsistent == InconsistentPolicy::drop_equation) {
    solution.Fdt = drop_contradicting_equations(solution, options);
  }
  solution.residual = detail::quiet_norm(VectorXd(A * solution.Fdt - B));
  return solution;
}

}  // namespace impulse
