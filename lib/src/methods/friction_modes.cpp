// SPDX-License-Identifier: GPL-3.0-or-later
#include "friction_modes.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "impulse/core/error.hpp"

namespace impulse::methods::detail {

// Contacts whose tangential columns of W are the same (two corners of a box on one face of
// another: the same bodies, the same tangent line) slip alike, and the bodies feel only the sum
// of their friction: only the sum is decided by the equations, and it meets each contact's bound
// exactly when it meets the sum of the bounds (then shared in proportion to the bounds). Such
// contacts form one group, with one friction mode; the first contact of each group stands for
// it. Contacts without friction (mu = 0) stand alone.
std::vector<Eigen::Index> groups_of(const FrictionSystem& s) {
  using Eigen::Index;
  const Index n = s.B.size();
  std::vector<Index> group(static_cast<std::size_t>(n));
  const double size = s.W.cwiseAbs().maxCoeff();
  for (Index v = 0; v < n; ++v) {
    group[static_cast<std::size_t>(v)] = v;
    if (!(s.friction(v) > 0.0)) {
      continue;
    }
    for (Index u = 0; u < v; ++u) {
      if (group[static_cast<std::size_t>(u)] != u || !(s.friction(u) > 0.0) ||
          s.W(n + u, n + u) != s.W(n + v, n + v) || s.u0(n + u) != s.u0(n + v)) {
        continue;
      }
      if ((s.W.col(n + u) - s.W.col(n + v)).cwiseAbs().maxCoeff() <= 1e-14 * size) {
        group[static_cast<std::size_t>(v)] = u;
        break;
      }
    }
  }
  return group;
}

namespace {

using Eigen::Index;
using Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double>;

// How a contact's friction acts. With its normal impulse (pushing, or separating with P_n = 0 and
// no friction) it fixes two of the conditions as equations and leaves the others to check:
//   sticking:  w_n = 0, slip after u'_t = 0;      check P_n >= 0, |P_t| <= mu P_n
//   forwards:  w_n = 0, P_t = -mu P_n (u'_t > 0); check P_n >= 0, u'_t >= 0
//   backwards: w_n = 0, P_t = +mu P_n (u'_t < 0); check P_n >= 0, u'_t <= 0
//   separating (any of the three): P_n = 0, P_t = 0; check w_n >= 0
enum class Friction : std::uint8_t { sticking, forwards, backwards };

// The friction's sign for a sliding contact: P_t = sign mu P_n.
double sign_of(Friction f) {
  return f == Friction::forwards ? -1.0 : f == Friction::backwards ? 1.0 : 0.0;
}

// An LU factorisation with partial pivoting of a k x k matrix whose nonzeros lie within `lower`
// diagonals below the main one and `upper` above, kept in band storage as LAPACK's dgbtrf keeps
// it (row exchanges widen the upper band by `lower`). The mode systems of a stack, their unknowns
// in the order of the contacts, have a band of a dozen diagonals: factorising the band costs
// k lower (lower + upper) operations and no symbolic analysis, where a general sparse LU spends
// most of its time on its analysis and its workspace.
class BandLU {
 public:
  BandLU(Index k, Index lower, Index upper)
      : k_(k),
        lower_(lower),
        upper_(upper),
        band_(Eigen::MatrixXd::Zero(2 * lower + upper + 1, k)),
        pivots_(static_cast<std::size_t>(k)) {}

  // The entry (i, j) of the matrix, for j - upper <= i <= j + lower (and, after factorise(), of
  // its factors, for j - upper - lower <= i).
  double& at(Index i, Index j) { return band_(lower_ + upper_ + i - j, j); }

  // Factorises in place. Returns false at a pivot of at most `smallest` (a singular or nearly
  // singular matrix).
  bool factorise(double smallest) {
    for (Index j = 0; j < k_; ++j) {
      const Index last = std::min(k_ - 1, j + lower_);
      Index p = j;
      for (Index i = j + 1; i <= last; ++i) {
        if (std::abs(at(i, j)) > std::abs(at(p, j))) {
          p = i;
        }
      }
      pivots_[static_cast<std::size_t>(j)] = p;
      if (!(std::abs(at(p, j)) > smallest)) {
        return false;
      }
      const Index right = std::min(k_ - 1, j + lower_ + upper_);
      if (p != j) {
        for (Index c = j; c <= right; ++c) {
          std::swap(at(j, c), at(p, c));
        }
      }
      const double diagonal = at(j, j);
      for (Index i = j + 1; i <= last; ++i) {
        const double factor = at(i, j) / diagonal;
        at(i, j) = factor;
        if (factor != 0.0) {
          for (Index c = j + 1; c <= right; ++c) {
            at(i, c) -= factor * at(j, c);
          }
        }
      }
    }
    return true;
  }

  // x with A x = rhs, from the factors.
  [[nodiscard]] VectorXd solve(VectorXd x) {
    for (Index j = 0; j < k_; ++j) {
      std::swap(x(j), x(pivots_[static_cast<std::size_t>(j)]));
      for (Index i = j + 1; i <= std::min(k_ - 1, j + lower_); ++i) {
        x(i) -= at(i, j) * x(j);
      }
    }
    for (Index j = k_ - 1; j >= 0; --j) {
      x(j) /= at(j, j);
      for (Index i = std::max<Index>(0, j - lower_ - upper_); i < j; ++i) {
        x(i) -= at(i, j) * x(j);
      }
    }
    return x;
  }

 private:
  Index k_;
  Index lower_;
  Index upper_;
  Eigen::MatrixXd band_;
  std::vector<Index> pivots_;
};

// The widest band (lower + upper diagonals) that solve_modes() factorises as a band; wider ones
// (scenes whose contacts' order is far from their neighbours') go to the general sparse LU.
constexpr Index widest_band = 48;

// A band pivot below this fraction of K's largest entry leaves the system to the general sparse
// LU. On the generated stacks, pyramids and cradles of 10 to 200 contacts (μ from 0.1 to 1) the
// smallest band pivot of a regular mode system was above 1e-4 of it, and of a system with
// dependent equations (a pyramid's) below 1e-9: those keep the sparse LU's own decision, which
// the pivoting took until now, so that the band factorisation changes no path, only rounding.
constexpr double smallest_band_pivot = 1e-7;

struct Modes {
  std::vector<bool> pushing;       // per contact
  std::vector<Friction> friction;  // per group (at its first contact)
  bool operator<(const Modes& other) const {
    return std::tie(pushing, friction) < std::tie(other.pushing, other.friction);
  }
};

// y with K y = rhs: by the band factorisation where K's band is narrow and no pivot small (@p
// largest: K's largest entry), else by the general sparse LU; empty when neither factorises K.
VectorXd factored_solution(const SparseMatrix& K, double largest, const VectorXd& rhs) {
  Index lower = 0;
  Index upper = 0;
  for (Index c = 0; c < K.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
      lower = std::max<Index>(lower, it.row() - it.col());
      upper = std::max<Index>(upper, it.col() - it.row());
    }
  }
  if (lower + upper <= widest_band) {
    BandLU lu(K.rows(), lower, upper);
    for (Index c = 0; c < K.outerSize(); ++c) {
      for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
        lu.at(it.row(), it.col()) = it.value();
      }
    }
    if (lu.factorise(smallest_band_pivot * largest)) {
      return lu.solve(rhs);
    }
  }
  Eigen::SparseLU<SparseMatrix, Eigen::NaturalOrdering<int>> lu;
  lu.compute(K);
  return lu.info() == Eigen::Success ? VectorXd(lu.solve(rhs)) : VectorXd();
}

// The impulses of one set of modes: the equations above, a square system in the normal impulses
// of the contacts that push and the tangential impulse of each sticking group. Returns false
// when it has no solution (within rounding).
bool solve_modes(const FrictionSystem& s, const SparseMatrix& W, const std::vector<Index>& group,
                 const Modes& modes, VectorXd& normal, VectorXd& tangential) {
  const Index n = s.B.size();
  const auto mode_of = [&](Index v) {
    return modes.friction[static_cast<std::size_t>(group[static_cast<std::size_t>(v)])];
  };
  std::vector<Index> pushing;
  std::vector<Index> sticking;  // groups with a pushing contact, by their first contact
  std::vector<bool> listed(static_cast<std::size_t>(n), false);
  for (Index v = 0; v < n; ++v) {
    if (!modes.pushing[static_cast<std::size_t>(v)]) {
      continue;
    }
    pushing.push_back(v);
    const Index g = group[static_cast<std::size_t>(v)];
    if (mode_of(v) == Friction::sticking && !listed[static_cast<std::size_t>(g)]) {
      listed[static_cast<std::size_t>(g)] = true;
      sticking.push_back(g);
    }
  }
  normal = VectorXd::Zero(n);
  tangential = VectorXd::Zero(n);
  // The unknowns, each named by its row of W (the normal impulse of contact v: v; the tangential
  // impulse of group g: n + g), in the order of the contacts: W couples only contacts that share
  // a body, so K is sparse, and in this order banded for a stack (a sparse LU then costs about
  // as much as its nonzeros; a dense one k^3). Equation i is row unknowns[i] of W.
  std::vector<Index> unknowns(pushing);
  unknowns.insert(unknowns.end(), sticking.begin(), sticking.end());
  for (std::size_t j = pushing.size(); j < unknowns.size(); ++j) {
    unknowns[j] += n;
  }
  const auto contact_of = [n](Index row) { return 2 * (row % n) + (row >= n ? 1 : 0); };
  std::sort(unknowns.begin(), unknowns.end(),
            [&](Index a, Index b) { return contact_of(a) < contact_of(b); });
  const auto k = static_cast<Index>(unknowns.size());
  if (k == 0) {
    return true;
  }
  std::vector<Index> position(static_cast<std::size_t>(2 * n), -1);  // -1: not in K
  for (Index r = 0; r < k; ++r) {
    position[static_cast<std::size_t>(unknowns[static_cast<std::size_t>(r)])] = r;
  }
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_column = [&](Index column, Index of, double factor) {
    for (SparseMatrix::InnerIterator it(W, of); it; ++it) {
      const Index r = position[static_cast<std::size_t>(it.row())];
      if (r >= 0) {
        entries.emplace_back(static_cast<int>(r), static_cast<int>(column), factor * it.value());
      }
    }
  };
  VectorXd rhs(k);
  for (Index c = 0; c < k; ++c) {
    const Index unknown = unknowns[static_cast<std::size_t>(c)];
    if (unknown < n) {
      // A pushing contact's normal impulse, with its friction when it slides.
      add_column(c, unknown, 1.0);
      const double slide = sign_of(mode_of(unknown)) * s.friction(unknown);
      if (slide != 0.0) {
        add_column(c, n + unknown, slide);
      }
      rhs(c) = s.B(unknown);
    } else {
      add_column(c, unknown, 1.0);  // a sticking group's tangential impulse
      rhs(c) = -s.u0(unknown);
    }
  }
  SparseMatrix K(k, k);
  K.setFromTriplets(entries.begin(), entries.end());
  const SparseMatrix K_abs = K.cwiseAbs();
  const auto solves = [&](const VectorXd& x) {
    if (x.size() != k || !all_finite_in(x)) {
      return false;
    }
    const double residual = (K * x - rhs).cwiseAbs().maxCoeff();
    const double terms = (K_abs * x.cwiseAbs() + rhs.cwiseAbs()).maxCoeff();
    return residual <= 1e-12 * terms;
  };
  const VectorXd y = factored_solution(K, K_abs.coeffs().maxCoeff(), rhs);
  if (!solves(y)) {
    // Dependent equations (a pyramid's box on two boxes): Lemke's method takes the problem.
    return false;
  }
  VectorXd total = VectorXd::Zero(n);  // each sticking group's tangential impulse
  VectorXd bound = VectorXd::Zero(n);  // and the sum of its contacts' bounds mu P_n
  VectorXd members = VectorXd::Zero(n);
  for (Index c = 0; c < k; ++c) {
    const Index unknown = unknowns[static_cast<std::size_t>(c)];
    if (unknown >= n) {
      total(unknown - n) = y(c);
      continue;
    }
    normal(unknown) = y(c);
    const Index g = group[static_cast<std::size_t>(unknown)];
    bound(g) += s.friction(unknown) * std::max(0.0, y(c));
    members(g) += 1.0;
    tangential(unknown) = sign_of(mode_of(unknown)) * s.friction(unknown) * y(c);
  }
  for (const Index v : pushing) {
    if (mode_of(v) == Friction::sticking) {
      // The group's friction shared in proportion to the bounds (equally when they are 0).
      const Index g = group[static_cast<std::size_t>(v)];
      const double share =
          bound(g) > 0.0 ? s.friction(v) * std::max(0.0, normal(v)) / bound(g) : 1.0 / members(g);
      tangential(v) = total(g) * share;
    }
  }
  return true;
}

// The friction of a group that pushes when its slip after is `slip`: sticking unless it slides
// beyond `tie`, then sliding with friction against the slip. Without friction (mu = 0) sticking
// means nothing: it slides.
Friction friction_for(double slip, double mu, double tie) {
  if (!(mu > 0.0)) {
    return Friction::forwards;  // P_t = -0 P_n = 0, whatever the slip
  }
  return slip > tie ? Friction::forwards : slip < -tie ? Friction::backwards : Friction::sticking;
}

// Full exchanges allowed without fewer violations before single ones (Judice and Pires use 3; on
// stacks of 50 to 100 boxes 8 takes a third fewer steps).
constexpr int stall_limit = 8;

// The start: the contacts that push without friction (`start`; empty: those that approach)
// push, each group sliding against its slip after (or sticking where it does not slip).
Modes starting_modes(const FrictionSystem& s, const SparseMatrix& W, const SparseMatrix& W_abs,
                     const VectorXd& start, double tolerance) {
  const Index n = s.B.size();
  Modes modes{std::vector<bool>(static_cast<std::size_t>(n), false),
              std::vector<Friction>(static_cast<std::size_t>(n), Friction::sticking)};
  VectorXd P = VectorXd::Zero(2 * n);
  if (start.size() == n) {
    P.head(n) = start.cwiseMax(0.0);
  }
  const VectorXd u = s.u0 + W * P;
  const double tie = tolerance * (W_abs * P.cwiseAbs() + s.u0.cwiseAbs()).maxCoeff();
  for (Index v = 0; v < n; ++v) {
    modes.pushing[static_cast<std::size_t>(v)] = start.size() == n ? start(v) > 0.0 : s.B(v) > 0.0;
    modes.friction[static_cast<std::size_t>(v)] = friction_for(u(n + v), s.friction(v), tie);
  }
  return modes;
}

// A violated condition, in velocities (impulses times their W diagonal), with the change that
// meets it: (contact, pushes) for a normal one, (group, friction) for friction.
struct Change {
  double violation;
  Index at;
  bool normal;
  bool pushes;
  Friction friction;
};

// The impulses of one step of the pivoting, and what follows from them.
struct Step {
  const VectorXd& normal;
  const VectorXd& tangential;
  VectorXd u;                      // the velocities after
  double tie;                      // what counts as zero
  std::vector<bool> group_pushes;  // whether a contact of the group (by its first) pushes
};

// The conditions that the step's impulses violate, each with its change.
std::vector<Change> violations(const FrictionSystem& s, const std::vector<Index>& group,
                               const Modes& modes, const Step& step) {
  const Index n = s.B.size();
  // Each group's friction and bound.
  VectorXd total = VectorXd::Zero(n);
  VectorXd bound = VectorXd::Zero(n);
  for (Index v = 0; v < n; ++v) {
    if (modes.pushing[static_cast<std::size_t>(v)]) {
      const Index g = group[static_cast<std::size_t>(v)];
      total(g) += step.tangential(v);
      bound(g) += s.friction(v) * step.normal(v);
    }
  }
  std::vector<Change> changes;
  const VectorXd& u = step.u;
  const double tie = step.tie;
  for (Index v = 0; v < n; ++v) {
    const double Wnn = s.W(v, v) > 0.0 ? s.W(v, v) : 1.0;
    if (!modes.pushing[static_cast<std::size_t>(v)]) {
      const double wn = u(v) - s.u0(v) - s.B(v);
      if (wn < -tie) {
        changes.push_back({-wn, v, true, true, Friction::sticking});
      }
    } else if (Wnn * step.normal(v) < -tie) {
      changes.push_back({-Wnn * step.normal(v), v, true, false, Friction::sticking});
    }
    if (group[static_cast<std::size_t>(v)] != v ||
        !step.group_pushes[static_cast<std::size_t>(v)] || !(s.friction(v) > 0.0)) {
      continue;
    }
    const double Wtt = s.W(n + v, n + v) > 0.0 ? s.W(n + v, n + v) : Wnn;
    const Friction f = modes.friction[static_cast<std::size_t>(v)];
    if (f == Friction::sticking) {
      const double excess = Wtt * (std::abs(total(v)) - bound(v));
      if (excess > tie) {
        changes.push_back(
            {excess, v, false, true, total(v) > 0.0 ? Friction::backwards : Friction::forwards});
      }
    } else if (sign_of(f) * u(n + v) > tie) {
      // Slides against its own friction: it sticks.
      changes.push_back({sign_of(f) * u(n + v), v, false, true, Friction::sticking});
    }
  }
  return changes;
}

// The modes changed as @p changes say.
void change_modes(const FrictionSystem& s, const std::vector<Index>& group,
                  const std::vector<Change>& changes, const Step& step, Modes& modes) {
  const Index n = s.B.size();
  for (const Change& c : changes) {
    if (c.normal) {
      modes.pushing[static_cast<std::size_t>(c.at)] = c.pushes;
      const Index g = group[static_cast<std::size_t>(c.at)];
      if (c.pushes && !step.group_pushes[static_cast<std::size_t>(g)]) {
        // The first contact of its group to push: friction against the slip after.
        modes.friction[static_cast<std::size_t>(g)] =
            friction_for(step.u(n + g), s.friction(g), step.tie);
      }
    } else {
      modes.friction[static_cast<std::size_t>(c.at)] = c.friction;
    }
  }
}

}  // namespace

ModePivoting pivot_modes(const FrictionSystem& s, const std::vector<Index>& group,
                         const VectorXd& start, double tolerance, int max_steps) {
  const Index n = s.B.size();
  ModePivoting result;
  SparseMatrix W = s.W.sparseView();
  W.makeCompressed();
  const SparseMatrix W_abs = W.cwiseAbs();
  Modes modes = starting_modes(s, W, W_abs, start, tolerance);
  std::set<Modes> seen;
  int stalled = 0;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (int step = 0; step < max_steps; ++step) {
    if (!seen.insert(modes).second) {
      return result;  // a set of modes came back: the pivoting cycles
    }
    VectorXd normal;
    VectorXd tangential;
    if (!solve_modes(s, W, group, modes, normal, tangential)) {
      return result;
    }
    VectorXd P(2 * n);
    P << normal, tangential;
    Step now{normal, tangential, s.u0 + W * P, 0.0,
             std::vector<bool>(static_cast<std::size_t>(n), false)};
    const double scale =
        std::max((W_abs * P.cwiseAbs() + s.u0.cwiseAbs()).maxCoeff(), s.B.cwiseAbs().maxCoeff());
    now.tie = tolerance * scale;
    for (Index v = 0; v < n; ++v) {
      if (modes.pushing[static_cast<std::size_t>(v)]) {
        now.group_pushes[static_cast<std::size_t>(group[static_cast<std::size_t>(v)])] = true;
      }
    }
    std::vector<Change> changes = violations(s, group, modes, now);
    if (changes.empty()) {
      double residual_scale = 0.0;
      const double residual = friction_residual(s, normal, tangential, residual_scale);
      result.normal = std::move(normal);
      result.tangential = std::move(tangential);
      result.solved = residual <= tolerance * residual_scale;
      return result;
    }
    // All violated conditions change at once; when that stops reducing their number for
    // stall_limit steps, only the worst one does (the safeguard of block principal pivoting,
    // Judice and Pires 1994).
    if (changes.size() < fewest) {
      fewest = changes.size();
      stalled = 0;
    } else {
      ++stalled;
    }
    if (stalled >= stall_limit) {
      changes = {*std::max_element(
          changes.begin(), changes.end(),
          [](const Change& a, const Change& b) { return a.violation < b.violation; })};
    }
    change_modes(s, group, changes, now, modes);
    result.pivots += static_cast<int>(changes.size());
    ++result.steps;
  }
  return result;
}

}  // namespace impulse::methods::detail
