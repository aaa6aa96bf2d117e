// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/complementarity.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"
#include "impulse/methods/resolve.hpp"
#include "updated_qr.hpp"

namespace impulse::methods {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double>;

void require_sizes(Index rows, Index cols, Index size) {
  if (rows != cols || rows != size) {
    throw InvalidInput("A must be square and B of its size, got A " + std::to_string(rows) + "x" +
                       std::to_string(cols) + " and B of " + std::to_string(size));
  }
}

void require_tolerance(double tolerance) {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InvalidInput("the complementarity tolerance must lie in (0, 1), got " +
                       format_number(tolerance));
  }
}

// The slack w = A F - B, the size of its terms and the residual of the conditions. The residual
// compares the impulse and the slack in the same units, velocities: A_vv F_v is the change of
// contact v's approach speed that its own impulse makes (max|min(F, w)| would compare an impulse
// with a speed, and change with the unit of mass).
template <typename Matrix>
void measure(const Matrix& A, const VectorXd& B, ComplementaritySolution& s) {
  s.w = A * s.Fdt - B;
  const VectorXd terms = A.cwiseAbs() * s.Fdt.cwiseAbs() + B.cwiseAbs();
  s.scale = terms.size() == 0 ? 0.0 : terms.maxCoeff();
  const VectorXd diagonal = A.diagonal();
  const VectorXd own = diagonal.cwiseProduct(s.Fdt);
  s.residual = 0.0;
  for (Index v = 0; v < s.w.size(); ++v) {
    s.residual = std::max(s.residual, std::abs(std::min(own(v), s.w(v))));
  }
}

bool meets(const ComplementaritySolution& s, double tolerance) {
  return (s.Fdt.size() == 0 || s.Fdt.minCoeff() >= 0.0) && s.residual <= tolerance * s.scale;
}

// No contact: nothing to solve.
ComplementaritySolution nothing(LcpAlgorithm algorithm) {
  ComplementaritySolution s;
  s.algorithm = algorithm;
  s.least_norm = true;
  return s;
}

ComplementaritySolution not_finite(Index n, LcpAlgorithm algorithm) {
  ComplementaritySolution s;
  s.status = LcpStatus::non_finite;
  s.algorithm = algorithm;
  s.Fdt = VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  s.w = s.Fdt;
  s.residual = std::numeric_limits<double>::quiet_NaN();
  s.scale = s.residual;
  return s;
}

// ---- Lemke's complementary pivoting -------------------------------------------------------------
//
// The tableau holds w - M z - d z0 = q (M = A, q = -B, covering vector d = 1), one row per
// contact, columns [w_1 … w_N | z_1 … z_N | z0], every row kept as "its basic variable plus the
// others = rhs". The first pivot brings z0 in so that every w is non-negative; from then on the
// variable that enters is the complement of the one that left, and the ratio test keeps every
// basic variable non-negative, until z0 leaves (a solution) or no row limits the entering
// variable (a ray). Ties in the ratio test are broken by the rows of the basis inverse (the w
// columns) divided by the pivot column, the lexicographic rule: every row of [rhs | B^-1] stays
// lexicographically positive, no basis repeats, and the method ends.

struct Pivoted {
  bool solved = false;
  bool ray = false;  // ended on a ray (else, if not solved, out of pivots)
  int pivots = 0;
  VectorXd z;                  // the impulses of the final basis
  std::vector<Index> support;  // the z that are basic at the end (their columns are independent)
  // z is already the least-squares solution on its support's columns of the factor (the
  // active-set method solves them from an orthogonal factorisation of G's columns): settle()
  // need not solve them again.
  bool settled = false;
};

// Lexicographic comparison of rows a and b of [rhs | T(:, 0..n-1)], each divided by its entry in
// the pivot column: is row a smaller? Entries within `tie` are taken as equal.
bool lexicographically_smaller(const MatrixXd& T, const VectorXd& rhs, Index a, Index b, Index c,
                               Index n, double tie) {
  const double ratio_a = rhs(a) / T(a, c);
  const double ratio_b = rhs(b) / T(b, c);
  if (std::abs(ratio_a - ratio_b) >
      tie * std::max(1.0, std::max(std::abs(ratio_a), std::abs(ratio_b)))) {
    return ratio_a < ratio_b;
  }
  for (Index k = 0; k < n; ++k) {
    const double x = T(a, k) / T(a, c);
    const double y = T(b, k) / T(b, c);
    if (std::abs(x - y) > tie * std::max(1.0, std::max(std::abs(x), std::abs(y)))) {
      return x < y;
    }
  }
  return a < b;
}

// `tie`: ratios (and the lexicographic rows) closer than this, relative, count as equal.
Pivoted pivot(const MatrixXd& A, const VectorXd& B, int max_pivots, double tie = 1e-11) {
  const Index n = B.size();
  Pivoted result;
  result.z = VectorXd::Zero(n);
  // Scaled so that the largest entries of M and q are 1: the tolerances below are then absolute.
  const double alpha = A.cwiseAbs().maxCoeff();
  const double beta = B.cwiseAbs().maxCoeff();
  if (beta == 0.0 || B.maxCoeff() <= 0.0) {
    result.solved = true;  // q = -B >= 0: no impulse, and no contact is left wanting one
    return result;
  }
  if (alpha == 0.0) {
    result.ray = true;  // B has a positive entry that nothing can meet: a ray at once
    return result;
  }
  const VectorXd q = -B / beta;
  const Index z0 = 2 * n;
  MatrixXd T(n, 2 * n + 1);
  T.leftCols(n).setIdentity();
  T.middleCols(n, n) = -A / alpha;
  T.col(z0).setConstant(-1.0);
  VectorXd rhs = q;
  std::vector<Index> basis(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    basis[static_cast<std::size_t>(i)] = i;
  }
  constexpr double pivot_tolerance = 1e-12;

  const auto do_pivot = [&](Index r, Index c) {
    const double p = T(r, c);
    T.row(r) /= p;
    rhs(r) /= p;
    VectorXd column = T.col(c);
    column(r) = 0.0;
    const Eigen::RowVectorXd pivot_row = T.row(r);
    T.noalias() -= column * pivot_row;
    rhs -= column * rhs(r);
    T.col(c).setZero();
    T(r, c) = 1.0;
    const Index left = basis[static_cast<std::size_t>(r)];
    basis[static_cast<std::size_t>(r)] = c;
    ++result.pivots;
    return left;
  };

  // The first pivot: z0 enters at the row of the most negative q (the largest index among equal
  // ones, which keeps every row lexicographically positive after the pivot).
  Index r = 0;
  for (Index i = 1; i < n; ++i) {
    if (q(i) <= q(r) + tie) {
      r = i;
    }
  }
  Index entering = n + do_pivot(r, z0);  // w_r left: z_r enters

  while (result.pivots < max_pivots) {
    const double largest = T.col(entering).cwiseAbs().maxCoeff();
    Index row = -1;
    for (Index i = 0; i < n; ++i) {
      if (!(T(i, entering) > pivot_tolerance * largest)) {
        continue;
      }
      if (row < 0 || lexicographically_smaller(T, rhs, i, row, entering, n, tie)) {
        row = i;
      }
    }
    if (row < 0) {
      result.ray = true;  // nothing limits the entering variable
      return result;
    }
    // If z0 can leave at the same ratio, let it: the basis is then a solution.
    const double best = rhs(row) / T(row, entering);
    for (Index i = 0; i < n; ++i) {
      if (basis[static_cast<std::size_t>(i)] == z0 && T(i, entering) > pivot_tolerance * largest &&
          std::abs(rhs(i) / T(i, entering) - best) <= tie * std::max(1.0, std::abs(best))) {
        row = i;
      }
    }
    const Index left = do_pivot(row, entering);
    if (left == z0) {
      for (Index i = 0; i < n; ++i) {
        const Index variable = basis[static_cast<std::size_t>(i)];
        if (variable >= n && variable < 2 * n) {
          result.z(variable - n) = std::max(0.0, rhs(i)) * beta / alpha;
          result.support.push_back(variable - n);
        }
      }
      std::sort(result.support.begin(), result.support.end());
      result.solved = true;
      return result;
    }
    entering = left < n ? left + n : left - n;  // the complement of the variable that left
  }
  return result;  // too many pivots (not expected: the lexicographic rule rules out cycling)
}

// The factor of A when the system carries one: A = G^T G, B = G^T g.
struct Factor {
  const MatrixXd* G = nullptr;
  const VectorXd* g = nullptr;
};

// The least-norm impulses on the contacts `on` (zero elsewhere) that satisfy those contacts'
// equations (A F)_v = B_v: the choice impulse::solve makes, from the factor's columns when the
// system carries it (half the digits lost), else from A's block.
VectorXd on_contacts(const MatrixXd& A, const VectorXd& B, const Factor& factor,
                     const std::vector<Index>& on, double rank_tolerance) {
  return impulse::detail::least_norm_on(A, B, factor.G, factor.g, on, rank_tolerance);
}

ComplementaritySolution candidate(const MatrixXd& A, const VectorXd& B, VectorXd F) {
  ComplementaritySolution s;
  // Rounding can leave an impulse that should be 0 at -1e-17 or so: impulses only push.
  s.Fdt = F.cwiseMax(0.0);
  measure(A, B, s);
  return s;
}

// The impulses of a pivoting's final basis, settled: recomputed from the equations of the
// contacts in its support, then (minimum_norm) replaced by the least-norm solution when that
// needs no clipping, and judged against the tolerance.
ComplementaritySolution settle(const MatrixXd& A, const VectorXd& B, const Factor& factor,
                               const Pivoted& p, const ComplementarityOptions& options,
                               LcpAlgorithm algorithm) {
  const double tolerance = options.tolerance;
  const Index n = B.size();
  // The pivoting found which contacts carry an impulse; their impulses are recomputed from their
  // equations, more accurately than a tableau's updates leave them.
  ComplementaritySolution chosen =
      candidate(A, B,
                !p.solved   ? VectorXd::Zero(n)
                : p.settled ? p.z
                            : on_contacts(A, B, factor, p.support, options.rank_tolerance));
  if (!meets(chosen, tolerance) && p.solved) {
    ComplementaritySolution raw = candidate(A, B, p.z);
    if (raw.residual < chosen.residual) {
      chosen = std::move(raw);
    }
  }
  if (p.solved && options.dependent == DependentPolicy::minimum_norm && meets(chosen, tolerance)) {
    // Every solution gives the same A F (it minimises the convex 1/2 F^T A F - B^T F over
    // F >= 0, and for A = G^T G that fixes G F), hence the same slack w. So the solutions are
    // the F >= 0 that carry impulse only where w = 0 and satisfy those contacts' equations; the
    // least-norm solution of those equations is the least-norm solution of the problem if it
    // needs no clipping.
    std::vector<Index> tight;
    for (Index v = 0; v < n; ++v) {
      if (chosen.w(v) <= tolerance * chosen.scale) {
        tight.push_back(v);
      }
    }
    // When the tight contacts are those of the support and its columns are independent, the
    // least-norm solution on them is the only one: the support's.
    const VectorXd F = p.settled && tight == p.support
                           ? chosen.Fdt
                           : on_contacts(A, B, factor, tight, options.rank_tolerance);
    const double allowed =
        tolerance * std::max(chosen.Fdt.cwiseAbs().maxCoeff(), F.cwiseAbs().maxCoeff());
    if (F.minCoeff() >= -allowed) {
      ComplementaritySolution least = candidate(A, B, F);
      if (meets(least, tolerance)) {
        chosen = std::move(least);
        chosen.least_norm = true;
      }
    }
  }
  chosen.algorithm = algorithm;
  chosen.iterations = p.pivots;
  if (p.ray) {
    chosen.status = LcpStatus::infeasible;  // for a positive semi-definite A: no solution exists
  } else if (!p.solved) {
    chosen.status = LcpStatus::inaccurate;  // out of pivots (not expected)
  } else {
    chosen.status = meets(chosen, tolerance) ? LcpStatus::solved : LcpStatus::inaccurate;
  }
  return chosen;
}

ComplementaritySolution lemke_with(const MatrixXd& A, const VectorXd& B, const Factor& factor,
                                   const ComplementarityOptions& options) {
  require_sizes(A.rows(), A.cols(), B.size());
  require_tolerance(options.tolerance);
  const Index n = B.size();
  if (n > pivoting_limit) {
    throw InvalidInput("Lemke's pivoting takes at most " + std::to_string(pivoting_limit) +
                       " contacts (its tableau is dense), got " + std::to_string(n));
  }
  if (n == 0) {
    return nothing(LcpAlgorithm::lemke);
  }
  if (!all_finite_in(A) || !all_finite_in(B)) {
    return not_finite(n, LcpAlgorithm::lemke);
  }
  const int max_pivots = static_cast<int>(std::min<Index>(100 * (n + 1), 1000000));
  return settle(A, B, factor, pivot(A, B, max_pivots), options, LcpAlgorithm::lemke);
}

// ---- The active-set method (Lawson and Hanson, "Solving Least Squares Problems", 1974, ch. 23) --
//
// min |G F - g| over F >= 0. Its optimality conditions: F >= 0, s = G^T (G F - g) = A F - B >= 0
// and F_v s_v = 0, the complementarity problem. P is the set of contacts allowed an impulse; the
// least squares on P's columns come from a QR factorisation of them that is updated as a contact
// enters or leaves P (detail::UpdatedQR), never computed anew.
//
// It may start from given impulses (the paper's): P is then their support, taken column by
// column in the order of the largest impulse first and leaving out the columns that depend on
// those before; while the least squares on P give an impulse that is not positive, its contact
// leaves P. What remains is a feasible start (positive impulses on independent columns) from which
// the method proceeds as from zero: the objective falls at every step, no set repeats, and it
// ends as it does from zero, in fewer pivots when the start is close.

// The pivot threshold of the least squares on P, as impulse::solve uses it on G: sqrt of
// rank_tolerance, or (0) Eigen's default for a column-pivoted QR of G's size.
double dependence_threshold(const MatrixXd& G, double rank_tolerance) {
  return rank_tolerance > 0.0 ? std::sqrt(rank_tolerance)
                              : static_cast<double>(std::min(G.rows(), G.cols())) *
                                    std::numeric_limits<double>::epsilon();
}

// The state of the active-set method: the impulses x, the set P (the QR factorisation of its
// columns and a flag per contact), the contacts refused until a step succeeds, and the pivots.
class ActiveSet {
 public:
  ActiveSet(const MatrixXd& G, const VectorXd& g, double rank_tolerance, int max_pivots)
      : qr_(G, g, dependence_threshold(G, rank_tolerance)),
        x_(VectorXd::Zero(G.cols())),
        passive_(static_cast<std::size_t>(G.cols()), false),
        refused_(static_cast<std::size_t>(G.cols()), false),
        max_pivots_(max_pivots) {}

  [[nodiscard]] bool may_pivot() const { return result_.pivots < max_pivots_; }

  // P the support of `start`, taken column by column, the largest impulse first (a column that
  // depends on those before is left out); then, while the least squares on P give an impulse that
  // is not positive, its contact leaves P.
  void start_from(const VectorXd& start) {
    std::vector<Index> order;
    for (Index j = 0; j < start.size(); ++j) {
      if (start(j) > 0.0) {
        order.push_back(j);
      }
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](Index a, Index b) { return start(a) > start(b); });
    for (const Index j : order) {
      at(passive_, j) = qr_.insert(j);
    }
    while (!qr_.columns().empty() && may_pivot()) {
      const VectorXd z = qr_.solve();
      if (z.minCoeff() > 0.0) {
        x_(qr_.columns()) = z;
        break;
      }
      drop_not_positive(z);
    }
  }

  // The contact that most wants an impulse: the most negative slack among those without one
  // (-1: none, the method has ended).
  [[nodiscard]] Index entering(const MatrixXd& G, const VectorXd& g, const MatrixXd& A_abs,
                               const VectorXd& B_abs, double tolerance) const {
    const VectorXd want = G.transpose() * (g - G * x_);  // -(A F - B)
    const double scale = (A_abs * x_.cwiseAbs() + B_abs).maxCoeff();
    Index t = -1;
    for (Index j = 0; j < x_.size(); ++j) {
      if (!passive_[static_cast<std::size_t>(j)] && !refused_[static_cast<std::size_t>(j)] &&
          want(j) > 0.5 * tolerance * scale && (t < 0 || want(j) > want(t))) {
        t = j;
      }
    }
    return t;
  }

  // Contact t enters P, and the least squares on P are followed until every impulse is
  // positive.
  void bring_in(Index t) {
    ++result_.pivots;
    if (!qr_.insert(t)) {
      // Its column lies in the span of P's (to the pivot threshold): in exact arithmetic its
      // slack would then be 0; rounding left it negative. Refuse t until a step succeeds.
      at(refused_, t) = true;
      return;
    }
    at(passive_, t) = true;
    bool first = true;
    while (may_pivot()) {
      const std::vector<Index>& set = qr_.columns();
      if (set.empty()) {
        break;  // not expected: t keeps a positive impulse through its first step
      }
      const VectorXd z = qr_.solve();
      if (first && !(z(z.size() - 1) > 0.0)) {
        // In exact arithmetic impossible (a contact with negative slack gets a positive
        // impulse); rounding did it: refuse t until a step succeeds.
        at(passive_, t) = false;
        at(refused_, t) = true;
        qr_.remove(set.size() - 1);
        break;
      }
      first = false;
      if (z.minCoeff() > 0.0) {
        x_(set) = z;
        std::fill(refused_.begin(), refused_.end(), false);
        break;
      }
      move_towards(z);
    }
  }

  // The result: the impulses of the final set, from its factorisation (a step cut short by the
  // pivot limit leaves x between two sets: then they are settled from the equations instead).
  [[nodiscard]] Pivoted finish(bool solved) {
    result_.solved = solved;
    result_.support = qr_.columns();
    std::sort(result_.support.begin(), result_.support.end());
    result_.z = x_;
    if (result_.solved && !qr_.columns().empty()) {
      result_.z.setZero();
      result_.z(qr_.columns()) = qr_.solve();
      result_.settled = true;
    } else {
      result_.settled = result_.solved;
    }
    return result_;
  }

 private:
  static std::vector<bool>::reference at(std::vector<bool>& flags, Index j) {
    return flags[static_cast<std::size_t>(j)];
  }

  // Removes from P every contact whose least-squares impulse in z (P's order) is not positive.
  void drop_not_positive(const VectorXd& z) {
    for (auto k = static_cast<Index>(z.size()); k-- > 0;) {
      if (!(z(k) > 0.0)) {
        const Index j = qr_.columns()[static_cast<std::size_t>(k)];
        at(passive_, j) = false;
        x_(j) = 0.0;
        qr_.remove(static_cast<std::size_t>(k));
        ++result_.pivots;
      }
    }
  }

  // Moves from x towards z (P's least squares) as far as every impulse stays non-negative, and
  // drops those at zero from P.
  void move_towards(const VectorXd& z) {
    const std::vector<Index>& set = qr_.columns();
    double alpha = 1.0;
    Index blocking = -1;
    for (std::size_t k = 0; k < set.size(); ++k) {
      const Index j = set[k];
      const double zj = z(static_cast<Index>(k));
      if (zj <= 0.0) {
        const double step = x_(j) > 0.0 ? x_(j) / (x_(j) - zj) : 0.0;  // no 0/0
        if (blocking < 0 || step < alpha) {
          alpha = step;
          blocking = j;
        }
      }
    }
    for (std::size_t k = 0; k < set.size(); ++k) {
      const Index j = set[k];
      x_(j) += alpha * (z(static_cast<Index>(k)) - x_(j));
    }
    for (auto k = static_cast<Index>(set.size()); k-- > 0;) {
      const Index j = set[static_cast<std::size_t>(k)];
      if (j == blocking || x_(j) <= 0.0) {
        x_(j) = 0.0;
        at(passive_, j) = false;
        qr_.remove(static_cast<std::size_t>(k));
        ++result_.pivots;
      }
    }
  }

  detail::UpdatedQR qr_;
  VectorXd x_;
  std::vector<bool> passive_;
  std::vector<bool> refused_;
  int max_pivots_;
  Pivoted result_;
};

Pivoted lawson_hanson(const MatrixXd& G, const VectorXd& g, const MatrixXd& A, const VectorXd& B,
                      double tolerance, double rank_tolerance, int max_pivots,
                      const VectorXd& start) {
  const Index n = G.cols();
  if (G.rows() == 0) {
    Pivoted result;
    result.z = VectorXd::Zero(n);
    result.solved = true;  // nothing can move: no impulse does anything, and none is wanted
    return result;
  }
  ActiveSet active(G, g, rank_tolerance, max_pivots);
  if (start.size() == n) {
    active.start_from(start);
  }
  const MatrixXd A_abs = A.cwiseAbs();
  const VectorXd B_abs = B.cwiseAbs();
  while (active.may_pivot()) {
    const Index t = active.entering(G, g, A_abs, B_abs, tolerance);
    if (t < 0) {
      return active.finish(true);
    }
    active.bring_in(t);
  }
  return active.finish(false);
}

// The active-set method on the factor G, g of the system A, B (A = G^T G, B = G^T g), started
// from `start` (empty: from zero).
ComplementaritySolution active_set_with(const MatrixXd& G, const VectorXd& g, const MatrixXd& A,
                                        const VectorXd& B, const ComplementarityOptions& options,
                                        const VectorXd& start = VectorXd()) {
  const double tolerance = options.tolerance;
  if (G.rows() != g.size()) {
    throw InvalidInput("G must have one row per entry of g, got G " + std::to_string(G.rows()) +
                       "x" + std::to_string(G.cols()) + " and g of " + std::to_string(g.size()));
  }
  require_tolerance(tolerance);
  const Index n = G.cols();
  if (n == 0) {
    return nothing(LcpAlgorithm::active_set);
  }
  if (!all_finite_in(G) || !all_finite_in(g)) {
    return not_finite(n, LcpAlgorithm::active_set);
  }
  if (start.size() == n && options.dependent == DependentPolicy::minimum_norm &&
      all_finite_in(start)) {
    // The start is the least-norm solution of A F = B (of G F ~ g). If it only pushes (but for
    // rounding), it solves the complementarity problem with w = 0, and it is the least-norm
    // solution of the problem: every solution F gives the same G F (see settle()), so all of
    // them solve G F ~ g, and among those the start has the least norm.
    const double allowed = tolerance * start.cwiseAbs().maxCoeff();
    if (start.minCoeff() >= -allowed) {
      ComplementaritySolution s = candidate(A, B, start);
      if (meets(s, tolerance)) {
        s.algorithm = LcpAlgorithm::active_set;
        s.least_norm = true;
        return s;
      }
    }
  }
  const int max_pivots = static_cast<int>(std::min<Index>(10 * (n + 1), 1000000));
  const Pivoted p = lawson_hanson(G, g, A, B, tolerance, options.rank_tolerance, max_pivots, start);
  return settle(A, B, Factor{&G, &g}, p, options, LcpAlgorithm::active_set);
}

}  // namespace

ComplementaritySolution lemke(const Eigen::Ref<const Eigen::MatrixXd>& A,
                              const Eigen::Ref<const Eigen::VectorXd>& B, DependentPolicy dependent,
                              double tolerance) {
  ComplementarityOptions options;
  options.dependent = dependent;
  options.tolerance = tolerance;
  return lemke_with(MatrixXd(A), VectorXd(B), Factor{}, options);
}

LemkeLcp lemke_lcp(const Eigen::Ref<const Eigen::MatrixXd>& M,
                   const Eigen::Ref<const Eigen::VectorXd>& q, double tie) {
  if (!(tie > 0.0 && tie < 1e-3)) {
    throw InvalidInput("Lemke's tie tolerance must lie in (0, 1e-3), got " + format_number(tie));
  }
  require_sizes(M.rows(), M.cols(), q.size());
  const Index n = q.size();
  if (n > pivoting_limit) {
    throw InvalidInput("Lemke's pivoting takes at most " + std::to_string(pivoting_limit) +
                       " unknowns (its tableau is dense), got " + std::to_string(n));
  }
  LemkeLcp result;
  if (n == 0) {
    return result;  // nothing to solve: the empty z solves it
  }
  if (!all_finite_in(M) || !all_finite_in(q)) {
    result.end = LemkeEnd::non_finite;
    result.z = VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
    result.w = result.z;
    return result;
  }
  // pivot() solves w = A F - B: A = M, B = -q. Nothing in it assumes A symmetric or positive
  // semi-definite; only what a ray means does.
  const int max_pivots = static_cast<int>(std::min<Index>(100 * (n + 1), 1000000));
  const Pivoted p = pivot(M, -q, max_pivots, tie);
  result.pivots = p.pivots;
  result.end = p.solved ? LemkeEnd::solution : p.ray ? LemkeEnd::ray : LemkeEnd::pivot_limit;
  result.z = p.z;
  result.w = M * p.z + q;
  return result;
}

ComplementaritySolution active_set(const Eigen::Ref<const Eigen::MatrixXd>& G,
                                   const Eigen::Ref<const Eigen::VectorXd>& g,
                                   DependentPolicy dependent, double tolerance) {
  ComplementarityOptions options;
  options.dependent = dependent;
  options.tolerance = tolerance;
  const MatrixXd G_own(G);
  const VectorXd g_own(g);
  return active_set_with(G_own, g_own, G_own.transpose() * G_own, G_own.transpose() * g_own,
                         options);
}

ComplementaritySolution projected_gauss_seidel(const SparseMatrix& A, const VectorXd& B,
                                               double tolerance, int max_sweeps,
                                               const VectorXd& start) {
  require_sizes(A.rows(), A.cols(), B.size());
  if (start.size() != 0 && start.size() != B.size()) {
    throw InvalidInput("the start of projected Gauss-Seidel must give one impulse per contact (" +
                       std::to_string(B.size()) + "), got " + std::to_string(start.size()));
  }
  require_tolerance(tolerance);
  if (max_sweeps < 1) {
    throw InvalidInput("projected Gauss-Seidel needs at least 1 sweep, got " +
                       std::to_string(max_sweeps));
  }
  const Index n = B.size();
  bool finite = all_finite_in(B);
  for (Index k = 0; k < A.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) {
      finite = finite && std::isfinite(it.value());
    }
  }
  if (!finite) {
    return not_finite(n, LcpAlgorithm::projected_gauss_seidel);
  }
  const SparseMatrix columns = A.isCompressed() ? A : SparseMatrix(A);
  const VectorXd diagonal = columns.diagonal();
  ComplementaritySolution s;
  s.algorithm = LcpAlgorithm::projected_gauss_seidel;
  s.Fdt =
      start.size() == n && all_finite_in(start) ? VectorXd(start.cwiseMax(0.0)) : VectorXd::Zero(n);
  bool feasible = true;
  for (Index v = 0; v < n; ++v) {
    // A zero diagonal means a zero row (A is positive semi-definite): the contact's impulse moves
    // nothing, so it stays 0, the least; its slack is -B_v, which must not be negative.
    feasible = feasible && (diagonal(v) > 0.0 || B(v) <= 0.0);
    if (!(diagonal(v) > 0.0)) {
      s.Fdt(v) = 0.0;
    }
  }
  measure(columns, B, s);
  while (feasible && !meets(s, tolerance) && s.iterations < max_sweeps) {
    for (Index v = 0; v < n; ++v) {
      if (!(diagonal(v) > 0.0)) {
        continue;
      }
      // Row v of A is its column v (A is symmetric): w_v from the latest impulses.
      const double w = columns.col(v).dot(s.Fdt) - B(v);
      s.Fdt(v) = std::max(0.0, s.Fdt(v) - w / diagonal(v));
    }
    ++s.iterations;
    measure(columns, B, s);
  }
  if (!feasible) {
    s.status = LcpStatus::infeasible;
  } else {
    s.status = meets(s, tolerance) ? LcpStatus::solved : LcpStatus::iteration_limit;
  }
  return s;
}

namespace {
// The work of both solve_complementarity overloads; `paper` is the warm start's solution, or
// null to solve the system for it when it is needed.
ComplementaritySolution solve_with(const ContactSystem& system, const Solution* paper,
                                   const ComplementarityOptions& options) {
  require_tolerance(options.tolerance);
  const Index n = system.size();
  LcpAlgorithm algorithm = options.algorithm;
  if (algorithm == LcpAlgorithm::automatic) {
    algorithm = n > pivoting_threshold ? LcpAlgorithm::projected_gauss_seidel
                : system.has_factor()  ? LcpAlgorithm::active_set
                                       : LcpAlgorithm::lemke;
  }
  // Projected Gauss-Seidel, started from the paper's impulses (see warm_start).
  const auto iterate = [&]() {
    VectorXd start;
    if (options.warm_start) {
      const Solution own = paper == nullptr ? solve(system) : Solution{};
      const Solution& warm = paper == nullptr ? own : *paper;
      if (warm.status == SolveStatus::success && warm.Fdt.size() == n) {
        start = warm.Fdt;
      }
    }
    return projected_gauss_seidel(system.sparse_A(), system.B(), options.tolerance,
                                  options.max_sweeps, start);
  };
  if (algorithm == LcpAlgorithm::projected_gauss_seidel) {
    return iterate();
  }
  if (n > pivoting_limit) {
    throw InvalidInput("pivoting takes at most " + std::to_string(pivoting_limit) +
                       " contacts (it works on dense matrices), got " + std::to_string(n));
  }
  MatrixXd G;
  VectorXd g;
  if (system.has_factor()) {
    system.factor(G, g);
  }
  ComplementaritySolution pivoted;
  if (algorithm == LcpAlgorithm::active_set && !system.has_factor()) {
    throw InvalidInput(
        "the active-set method needs the system's factor G (A = G^T G), which systems "
        "assembled from bodies carry and systems given as A and B do not");
  }
  const MatrixXd A = system.is_sparse() ? MatrixXd(system.sparse_A()) : system.A();
  if (algorithm == LcpAlgorithm::active_set) {
    // Started from the paper's impulses when they are the least-norm solution of the system
    // (the default policies) and the least-norm answer is asked for.
    const bool warm = options.warm_start && paper != nullptr &&
                      options.dependent == DependentPolicy::minimum_norm &&
                      paper->status == SolveStatus::success && paper->Fdt.size() == n &&
                      paper->options.dependent == DependentPolicy::minimum_norm &&
                      paper->options.inconsistent == InconsistentPolicy::least_squares;
    pivoted = active_set_with(G, g, A, system.B(), options, warm ? paper->Fdt : VectorXd());
  } else {
    pivoted = lemke_with(A, system.B(), system.has_factor() ? Factor{&G, &g} : Factor{}, options);
  }
  if (pivoted.status != LcpStatus::inaccurate || options.algorithm != LcpAlgorithm::automatic) {
    return pivoted;
  }
  // Rounding kept the pivoting's answer above the tolerance: iterate instead, and keep whichever
  // answer is closer.
  ComplementaritySolution iterated = iterate();
  return iterated.residual < pivoted.residual ? iterated : pivoted;
}
}  // namespace

ComplementaritySolution solve_complementarity(const ContactSystem& system,
                                              const ComplementarityOptions& options) {
  return solve_with(system, nullptr, options);
}

ComplementaritySolution solve_complementarity(const ContactSystem& system, const Solution& paper,
                                              const ComplementarityOptions& options) {
  return solve_with(system, &paper, options);
}

ComplementarityResolution resolve_complementarity(std::span<const multipoint::Body> bodies,
                                                  std::span<const Elasticity> elasticities,
                                                  std::span<const multipoint::Contact> contacts,
                                                  const ComplementarityOptions& options) {
  const multipoint::Configuration configuration({bodies.begin(), bodies.end()},
                                                {elasticities.begin(), elasticities.end()},
                                                {contacts.begin(), contacts.end()});
  ComplementarityResolution resolution;
  resolution.solution = solve_complementarity(configuration.assemble(), options);
  resolution.after = resolution.solution.status == LcpStatus::non_finite
                         ? std::vector<multipoint::Body>(bodies.begin(), bodies.end())
                         : configuration.after(resolution.solution.Fdt);
  return resolution;
}

ComplementarityResolution resolve_complementarity(std::span<const multipoint::Body> bodies,
                                                  Elasticity elasticity,
                                                  std::span<const multipoint::Contact> contacts,
                                                  const ComplementarityOptions& options) {
  const std::vector<Elasticity> elasticities(bodies.size(), elasticity);
  return resolve_complementarity(bodies, elasticities, contacts, options);
}

namespace {
// "active-set pivoting, 3 pivots": the algorithm and its count of steps.
std::string algorithm_phrase(const ComplementaritySolution& c) {
  const auto steps = static_cast<std::size_t>(c.iterations);
  switch (c.algorithm) {
    case LcpAlgorithm::lemke:
      return "Lemke's pivoting, " + counted(steps, "pivot", "pivots");
    case LcpAlgorithm::projected_gauss_seidel:
      return "projected Gauss-Seidel, " + counted(steps, "sweep", "sweeps");
    case LcpAlgorithm::active_set:
    case LcpAlgorithm::automatic:
      break;
  }
  return "active-set pivoting, " + counted(steps, "pivot", "pivots");
}
}  // namespace

Outcome complementarity(const multipoint::Configuration& configuration, const Paper& paper,
                        const Options& options) {
  ComplementarityOptions own = options.complementarity;
  own.dependent = options.solver.dependent;
  own.rank_tolerance = options.solver.rank_tolerance;
  // The warm start is the paper's minimum-norm solution: the one already solved, when the scene
  // asked for the default policies.
  const bool default_policies = options.solver.dependent == DependentPolicy::minimum_norm &&
                                options.solver.inconsistent == InconsistentPolicy::least_squares;
  ComplementaritySolution c = default_policies
                                  ? solve_complementarity(paper.system, paper.solution, own)
                                  : solve_complementarity(paper.system, own);
  Outcome o;
  o.method = Method::complementarity;
  o.finite = c.status != LcpStatus::non_finite;
  if (!o.finite) {
    o.Fdt = c.Fdt;
    o.solution = std::move(c);
    return o;
  }
  o.Fdt = c.Fdt;
  o.after = configuration.after(c.Fdt);
  o.residual = paper.system.residual(c.Fdt);
  o.finished = c.status != LcpStatus::infeasible;
  if (!o.finished) {
    o.unfinished =
        "complementarity: no impulses that only push satisfy A·Fdt >= B (Lemke's pivoting ended "
        "on a ray)";
  }
  const bool approximate = c.status != LcpStatus::solved;
  const std::string residual = number_text(c.residual);
  o.details.push_back(algorithm_phrase(c) + (approximate ? " (approximate)" : "") +
                      ", complementarity residual " + residual +
                      (c.least_norm ? ", the least-norm solution" : ""));
  std::string slack("slack A·Fdt - B (0 where a contact pushes):");
  for (Eigen::Index v = 0; v < c.w.size(); ++v) {
    slack.append(v == 0 ? " " : ", ").append(chopped(c.w(v), c.scale));
  }
  o.details.push_back(std::move(slack));
  o.summary = algorithm_phrase(c) + ", complementarity residual " + residual +
              (approximate ? " (approximate)" : "");
  const std::string against =
      " against a scale of " + number_text(c.scale) + ": the impulses are approximate";
  if (c.status == LcpStatus::iteration_limit) {
    o.warnings.push_back("complementarity: projected Gauss-Seidel stopped after " +
                         std::to_string(c.iterations) +
                         " sweeps with the complementarity residual " + residual + against);
  } else if (c.status == LcpStatus::inaccurate) {
    o.warnings.push_back(
        "complementarity: rounding left Lemke's pivoting at the complementarity residual " +
        residual + against);
  }
  o.diagnostics = {{"algorithm", std::string(name_of(c.algorithm))},
                   {"iterations", std::int64_t{c.iterations}},
                   {"complementarity_residual", c.residual},
                   {"converged", c.status == LcpStatus::solved},
                   {"least_norm", c.least_norm},
                   {"slack", std::vector<double>(c.w.begin(), c.w.end())}};
  o.solution = std::move(c);
  return o;
}

}  // namespace impulse::methods
