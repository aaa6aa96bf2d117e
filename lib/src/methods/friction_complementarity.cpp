// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: Coulomb friction at many contacts as one complementarity problem.
#include "impulse/methods/friction_complementarity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "friction_modes.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/text.hpp"
#include "impulse/methods/resolve.hpp"

namespace impulse::methods {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// The configuration with 2N contacts: contact v, then at N + v the same bodies and point with
// "normal" -t_v, every body at elasticity 1 (its B is then the velocity along the directions).
multipoint::Configuration with_tangential_contacts(const multipoint::Configuration& configuration) {
  std::vector<multipoint::Contact> contacts(configuration.contacts().begin(),
                                            configuration.contacts().end());
  const std::size_t n = contacts.size();
  for (std::size_t v = 0; v < n; ++v) {
    multipoint::Contact tangential = contacts[v];
    tangential.normal = -quarter_turn(contacts[v].normal);  // -t_v, t_v = [-n_y, n_x]
    contacts.push_back(tangential);
  }
  return {multipoint::Configuration::Trusted{},
          {configuration.bodies().begin(), configuration.bodies().end()},
          std::vector<Elasticity>(configuration.bodies().size(), Elasticity::inelastic()),
          std::move(contacts)};
}

void require_friction_system(const FrictionSystem& s) {
  const Index n = s.B.size();
  if (s.W.rows() != 2 * n || s.W.cols() != 2 * n || s.u0.size() != 2 * n ||
      s.friction.size() != n || (s.G.size() != 0 && s.G.cols() != 2 * n)) {
    throw InvalidInput(
        "a friction system of N contacts needs W 2N x 2N, u0 of 2N, B and friction "
        "of N, and G empty or with 2N columns; got W " +
        std::to_string(s.W.rows()) + "x" + std::to_string(s.W.cols()) + ", u0 of " +
        std::to_string(s.u0.size()) + ", B of " + std::to_string(n) + ", friction of " +
        std::to_string(s.friction.size()) + ", G with " + std::to_string(s.G.cols()) + " columns");
  }
  if (n > friction_pivoting_limit) {
    throw InvalidInput("complementarity with friction pivots on 4 unknowns per contact: at most " +
                       std::to_string(friction_pivoting_limit) + " contacts, got " +
                       std::to_string(n));
  }
  for (Index v = 0; v < n; ++v) {
    if (!(std::isfinite(s.friction(v)) && s.friction(v) >= 0.0)) {
      throw InvalidInput("friction[" + std::to_string(v) + "] must be finite and at least 0, got " +
                         format_number(s.friction(v)));
    }
  }
}

void require_friction_tolerance(double tolerance) {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InvalidInput("the complementarity tolerance must lie in (0, 1), got " +
                       format_number(tolerance));
  }
}

}  // namespace

FrictionSystem friction_system(const multipoint::Configuration& configuration,
                               std::span<const double> friction) {
  const std::size_t n = configuration.contacts().size();
  if (friction.size() != n) {
    throw InvalidInput("friction needs one coefficient per contact (" + std::to_string(n) +
                       "), got " + std::to_string(friction.size()));
  }
  FrictionSystem s;
  s.friction = Eigen::Map<const VectorXd>(friction.data(), static_cast<Index>(n));
  // W_nn is the paper's A and -u0 its B at elasticity 1 ((4.5)/(4.8), (5.3)/(5.5)); the
  // tangential rows are the same blocks along -t (impulse::friction::dynamics for one contact).
  // Assembled sparse, then made dense once: the dense storage would be zeroed, filled and copied
  // into W (the same sums, in the same order).
  const ContactSystem both = with_tangential_contacts(configuration).assemble(Storage::sparse);
  s.W = MatrixXd(both.sparse_A());
  s.u0 = -both.B();
  if (both.has_factor()) {
    VectorXd g;
    both.factor(s.G, g);
  }
  // The paper's B, with its elasticities (its A, kept sparse, is not summed).
  s.B = configuration.assemble(Storage::sparse).B();
  require_friction_system(s);
  return s;
}

double friction_residual(const FrictionSystem& system, const VectorXd& normal,
                         const VectorXd& tangential, double& scale) {
  const Index n = system.B.size();
  VectorXd P(2 * n);
  P << normal, tangential;
  const VectorXd u = system.u0 + system.W * P;
  const VectorXd terms = system.W.cwiseAbs() * P.cwiseAbs() + system.u0.cwiseAbs();
  scale = 0.0;
  double residual = 0.0;
  for (Index v = 0; v < n; ++v) {
    scale = std::max({scale, terms(v) + std::abs(system.B(v)), terms(n + v)});
    const double Wnn = system.W(v, v) > 0.0 ? system.W(v, v) : 1.0;
    const double Wtt = system.W(n + v, n + v) > 0.0 ? system.W(n + v, n + v) : Wnn;
    const double Pn = normal(v);
    const double Pt = tangential(v);
    const double slip = std::abs(u(n + v));
    const double wn = u(v) - system.u0(v) - system.B(v);  // (W P)_n - B
    const double bound = system.friction(v) * Pn - std::abs(Pt);
    residual = std::max({residual, std::abs(std::min(Wnn * Pn, wn)),  // pushes only, and then tight
                         Wtt * std::max(0.0, -bound),                 // Coulomb's bound
                         std::min(Wtt * std::max(0.0, bound), slip)});  // slides only at it
    if (Pt * u(n + v) > 0.0) {
      residual = std::max(residual, std::min(Wtt * std::abs(Pt), slip));  // against the slip
    }
  }
  return residual;
}

namespace {

// The linear complementarity problem of the friction system: z = (P_n, λ+, λ-, β), w = M z + q
// (see the header).
struct FrictionLcp {
  MatrixXd M;
  VectorXd q;
};

FrictionLcp friction_lcp(const FrictionSystem& system) {
  const Index n = system.B.size();
  const MatrixXd& W = system.W;
  const auto nn = W.topLeftCorner(n, n);
  const auto nt = W.topRightCorner(n, n);
  const auto tn = W.bottomLeftCorner(n, n);
  const auto tt = W.bottomRightCorner(n, n);
  const MatrixXd E = MatrixXd::Identity(n, n);
  FrictionLcp lcp{MatrixXd::Zero(4 * n, 4 * n), VectorXd::Zero(4 * n)};
  MatrixXd& M = lcp.M;
  M.block(0, 0, n, n) = nn;
  M.block(0, n, n, n) = nt;
  M.block(0, 2 * n, n, n) = -nt;
  M.block(n, 0, n, n) = tn;
  M.block(n, n, n, n) = tt;
  M.block(n, 2 * n, n, n) = -tt;
  M.block(n, 3 * n, n, n) = E;
  M.block(2 * n, 0, n, n) = -tn;
  M.block(2 * n, n, n, n) = -tt;
  M.block(2 * n, 2 * n, n, n) = tt;
  M.block(2 * n, 3 * n, n, n) = E;
  M.block(3 * n, 0, n, n) = system.friction.asDiagonal();
  M.block(3 * n, n, n, n) = -E;
  M.block(3 * n, 2 * n, n, n) = -E;
  lcp.q.segment(0, n) = -system.B;
  lcp.q.segment(n, n) = system.u0.tail(n);
  lcp.q.segment(2 * n, n) = -system.u0.tail(n);
  return lcp;
}

// The contacts' order of Lemke attempt @p attempt of 2 * orders, as the unknowns of the
// permuted problem: unknown i of it is unknown unknowns(i) of the problem. Even attempts rotate
// the contacts, odd ones reverse the rotated order.
Eigen::VectorXi permuted_unknowns(Index n, Index attempt, Index orders) {
  Eigen::VectorXi order(n);
  for (Index v = 0; v < n; ++v) {
    const Index rotated = (v + (attempt % orders) / 2) % n;
    order(v) = static_cast<int>((attempt % orders) % 2 == 1 ? n - 1 - rotated : rotated);
  }
  Eigen::VectorXi unknowns(4 * n);
  for (Index b = 0; b < 4; ++b) {
    unknowns.segment(b * n, n) = order.array() + static_cast<int>(b * n);
  }
  return unknowns;
}

// A solution z of the problem settled as the frictionless method settles its own: the unknowns
// that carry a value keep their equations w_i = 0, solved again from M (least norm).
VectorXd settled_solution(const FrictionLcp& lcp, const VectorXd& z) {
  std::vector<Index> on;
  for (Index i = 0; i < z.size(); ++i) {
    if (z(i) > 0.0) {
      on.push_back(i);
    }
  }
  VectorXd settled = VectorXd::Zero(z.size());
  if (!on.empty()) {
    const MatrixXd block = lcp.M(on, on);
    const VectorXd rhs = -lcp.q(on);
    settled(on) = impulse::detail::least_norm(block, rhs, 0.0).cwiseMax(0.0);
  }
  return settled;
}

// Lemke's method in floating point can end on a ray where exact arithmetic would not (none
// exists when W's null space holds no pushes within the friction cones, see the header): the
// problem's degenerate rows (q = 0 in the bound rows, equal tangential columns of contacts on
// one flat floor) send the rounded tableau down another path. The contacts are then taken in
// other orders (reversed, rotated: up to 8 orders), which changes the path and not the
// problem, and then with a looser tie tolerance.
// Each attempt's impulses are then settled (settled_solution); the closer answer is kept in @p s
// (@p found: whether @p s holds one already, and after, whether it holds one). Returns whether
// an attempt met numbers that are not finite.
bool lemke_attempts(const FrictionSystem& system, double tolerance, FrictionSolution& s,
                    bool& found) {
  const Index n = system.B.size();
  const FrictionLcp lcp = friction_lcp(system);
  const Index orders = std::min<Index>(2 * n, 8);
  for (Index attempt = 0; attempt < 2 * orders && !(found && s.residual <= tolerance * s.scale);
       ++attempt) {
    // First every order with lemke()'s tie tolerance, then every order with a looser one, which
    // recognises more rounded ties as the degenerate pivots they are.
    const double tie = attempt < orders ? 1e-11 : 1e-9;
    const Eigen::VectorXi unknowns = permuted_unknowns(n, attempt, orders);
    const LemkeLcp tried = lemke_lcp(lcp.M(unknowns, unknowns), lcp.q(unknowns), tie);
    s.pivots += tried.pivots;
    if (tried.end == LemkeEnd::non_finite) {
      return true;
    }
    if (tried.end != LemkeEnd::solution) {
      continue;
    }
    VectorXd z = VectorXd::Zero(4 * n);
    z(unknowns) = tried.z;
    for (const VectorXd& candidate : {z, settled_solution(lcp, z)}) {
      const VectorXd normal = candidate.head(n).cwiseMax(0.0);
      const VectorXd tangential = candidate.segment(n, n) - candidate.segment(2 * n, n);
      double scale = 0.0;
      const double residual = friction_residual(system, normal, tangential, scale);
      if (all_finite_in(candidate) && (!found || residual < s.residual)) {
        found = true;
        s.normal = normal;
        s.tangential = tangential;
        s.residual = residual;
        s.scale = scale;
      }
    }
  }
  return false;
}

// The impulses found, finished: the least-norm tangential impulses that change nothing, kept if
// the conditions still hold (with @p least_norm; @p group is then detail::groups_of(system)),
// Coulomb's bound clipped, the velocities after and the status.
void finish_solution(const FrictionSystem& system, double tolerance, bool least_norm,
                     const std::vector<Index>& group, FrictionSolution& s) {
  const Index n = system.B.size();
  const auto tt = system.W.bottomRightCorner(n, n);
  // P_t* = P_t - its part in the null space of the tangential columns (of G when the system
  // carries its factor: W_tt = G_t^T G_t, so G_t x = 0 exactly when W_t x = 0).
  constexpr double threshold = 1e-10;
  const MatrixXd columns = system.G.size() != 0 ? MatrixXd(system.G.rightCols(n)) : MatrixXd(tt);
  // Two contacts with the same column C (a group, detail::groups_of) differ by a direction of
  // that null space, so P_t*, orthogonal to it, has one value at all of a group's contacts: it is
  // S z, S with one column per group, 1/sqrt(m) at its m contacts (orthonormal columns), and z
  // the least-norm solution of (C S) z = C P_t. A stack's contacts pair up: half the columns, a
  // quarter of the work of the factorisation.
  VectorXd least;
  if (least_norm) {
    std::vector<Index> column_of(static_cast<std::size_t>(n), -1);
    VectorXd members = VectorXd::Zero(n);
    Index groups = 0;
    for (Index v = 0; v < n; ++v) {
      const auto g = static_cast<std::size_t>(group[static_cast<std::size_t>(v)]);
      if (column_of[g] < 0) {
        column_of[g] = groups++;
      }
      members(static_cast<Index>(g)) += 1.0;
    }
    VectorXd weight(n);  // 1/sqrt(m) of each contact's group
    MatrixXd reduced = MatrixXd::Zero(columns.rows(), groups);
    for (Index v = 0; v < n; ++v) {
      const Index g = group[static_cast<std::size_t>(v)];
      weight(v) = 1.0 / std::sqrt(members(g));
      reduced.col(column_of[static_cast<std::size_t>(g)]) += weight(v) * columns.col(v);
    }
    const VectorXd z = impulse::detail::least_norm(
        reduced, columns * s.tangential, system.G.size() != 0 ? threshold : threshold * threshold);
    least.resize(n);
    for (Index v = 0; v < n; ++v) {
      least(v) =
          weight(v) * z(column_of[static_cast<std::size_t>(group[static_cast<std::size_t>(v)])]);
    }
  }
  double least_scale = 0.0;
  const double least_residual =
      least_norm ? friction_residual(system, s.normal, least, least_scale) : 0.0;
  if (least_norm && all_finite_in(least) &&
      least_residual <= std::max(s.residual, tolerance * least_scale)) {
    s.tangential = least;
    s.residual = least_residual;
    s.scale = least_scale;
    s.least_norm = true;
  }
  // Rounding can leave a tangential impulse of 1e-17 where the normal one is 0 (the tableau, or
  // the least-norm step): Coulomb's bound is clipped exactly, the change far below the residual.
  s.tangential = s.tangential.cwiseMax(-system.friction.cwiseProduct(s.normal))
                     .cwiseMin(system.friction.cwiseProduct(s.normal));
  s.residual = friction_residual(system, s.normal, s.tangential, s.scale);
  VectorXd P(2 * n);
  P << s.normal, s.tangential;
  s.u_after = system.u0 + system.W * P;
  s.status = s.residual <= tolerance * s.scale ? LcpStatus::solved : LcpStatus::inaccurate;
}

// solve_friction(), its pivoting on modes started from the normal impulses `start` (those
// without friction; empty: the contacts that approach), then Lemke's method if that does not
// end at a solution.
FrictionSolution solve_from(const FrictionSystem& system, double tolerance, bool least_norm,
                            const VectorXd& start) {
  require_friction_system(system);
  require_friction_tolerance(tolerance);
  const Index n = system.B.size();
  FrictionSolution s;
  s.normal = VectorXd::Zero(n);
  s.tangential = VectorXd::Zero(n);
  s.u_after = system.u0;
  if (n == 0) {
    s.least_norm = true;
    return s;
  }
  bool found = false;
  // The groups of contacts that share one friction, for the pivoting and the least-norm step.
  const std::vector<Index> group = least_norm ? detail::groups_of(system) : std::vector<Index>();
  if (least_norm && all_finite_in(system.W) && all_finite_in(system.u0) &&
      all_finite_in(system.B)) {
    // First the pivoting on the contacts' modes, started from the normal impulses without
    // friction; Lemke's method only if it does not end at a solution (and has at most
    // lemke_friction_limit contacts). A change of mode travels about one box of a stack per
    // step: stacks of 100 to 200 contacts take 20 to 50 steps, of 700 contacts 358; a problem
    // that takes more than 20 + N (a pyramid's dependent contacts make it cycle) goes on to
    // Lemke's method.
    const detail::ModePivoting modes =
        detail::pivot_modes(system, group, start, tolerance, static_cast<int>(20 + n));
    if (modes.solved) {
      found = true;
      s.algorithm = FrictionAlgorithm::modes;
      s.pivots = modes.pivots;
      s.normal = modes.normal.cwiseMax(0.0);
      s.tangential = modes.tangential;
      s.residual = friction_residual(system, s.normal, s.tangential, s.scale);
    }
  }
  // Lemke's method (its tableau of 4N x (8N + 1) built) only where the pivoting on modes left
  // no answer within the tolerance, and only up to its limit of contacts.
  const bool settled = found && s.residual <= tolerance * s.scale;
  if (!settled && static_cast<std::size_t>(n) > lemke_friction_limit) {
    s.lemke_too_large = true;  // (the pivoting on modes' answer, if any, stays: inaccurate)
  } else if (!settled && lemke_attempts(system, tolerance, s, found)) {
    s.status = LcpStatus::non_finite;
    s.normal.setConstant(std::numeric_limits<double>::quiet_NaN());
    s.tangential = s.normal;
    s.u_after.setConstant(std::numeric_limits<double>::quiet_NaN());
    s.residual = std::numeric_limits<double>::quiet_NaN();
    s.scale = s.residual;
    return s;
  }
  if (!found) {
    // Every order ended on a ray (or, not expected, at the pivot limit): no impulses; the caller
    // says so.
    s.status = LcpStatus::infeasible;
    s.residual = friction_residual(system, s.normal, s.tangential, s.scale);
    return s;
  }
  finish_solution(system, tolerance, least_norm, group, s);
  return s;
}

// The paper's impulses (without friction), which suggest the contacts that push: where it solved
// its system, the start of the pivoting on modes; else none (from zero).
VectorXd paper_start(const multipoint::Configuration& configuration, const Paper& paper) {
  return paper.solution.status == SolveStatus::success &&
                 paper.solution.Fdt.size() == static_cast<Index>(configuration.contacts().size())
             ? paper.solution.Fdt
             : VectorXd();
}

FrictionResolution resolve_from(const multipoint::Configuration& configuration,
                                std::span<const double> friction, double tolerance, bool least_norm,
                                const VectorXd& start) {
  FrictionResolution r;
  r.solution = solve_from(friction_system(configuration, friction), tolerance, least_norm, start);
  const FrictionSolution& s = r.solution;
  if (s.status == LcpStatus::solved || s.status == LcpStatus::inaccurate) {
    VectorXd P(2 * s.normal.size());
    P << s.normal, s.tangential;
    r.after = with_tangential_contacts(configuration).after(P);
  } else {
    r.after.assign(configuration.bodies().begin(), configuration.bodies().end());
  }
  return r;
}

}  // namespace

FrictionSolution solve_friction(const FrictionSystem& system, double tolerance, bool least_norm) {
  return solve_from(system, tolerance, least_norm, VectorXd());
}

FrictionResolution resolve_friction_complementarity(const multipoint::Configuration& configuration,
                                                    std::span<const double> friction,
                                                    double tolerance, bool least_norm) {
  // From the paper's impulses without friction, as the command line and the page start: from
  // zero, the pivoting on modes did not end on a stack of 400 boxes sliding as it lands, which
  // it solves from there (tests/methods/large_test.cpp).
  VectorXd start;
  try {
    start = paper_start(configuration, paper(configuration, SolverOptions{}));
  } catch (const InvalidInput&) {
    // Beyond the dense limit: from zero.
  }
  return resolve_from(configuration, friction, tolerance, least_norm, start);
}

// ---- In the pipeline ----------------------------------------------------------------------------

Outcome complementarity_friction(const multipoint::Configuration& configuration, const Paper& paper,
                                 const Options& options) {
  const std::size_t n = configuration.contacts().size();
  std::vector<double> mu(n, 0.0);
  for (std::size_t v = 0; v < n && v < options.friction.size(); ++v) {
    mu[v] = options.friction[v];
  }
  const FrictionResolution r = resolve_from(configuration, mu, options.complementarity.tolerance,
                                            true, paper_start(configuration, paper));
  const FrictionSolution& s = r.solution;
  Outcome o;
  o.method = Method::complementarity;
  o.finite =
      s.status != LcpStatus::non_finite && all_finite_in(s.normal) && all_finite_in(s.tangential);
  o.Fdt = s.normal;
  o.after = r.after;
  std::vector<std::string> slip;
  for (std::size_t v = 0; v < n; ++v) {
    const auto k = static_cast<Index>(v);
    const multipoint::Contact& c = configuration.contacts()[v];
    o.on_bumper.push_back(-c.normal * s.normal(k) + quarter_turn(c.normal) * s.tangential(k));
    // A contact slides after if its slip speed is more than rounding of the problem's terms.
    const bool slides = std::abs(s.u_after(static_cast<Index>(n) + k)) >
                        options.complementarity.tolerance * s.scale;
    slip.emplace_back(slides ? "slip" : "stick");
  }
  o.per_contact = detail::friction_columns(s.tangential, std::move(slip));
  if (!o.finite) {
    return o;
  }
  o.residual = paper.system.residual(o.Fdt);
  const std::string residual = number_text(s.residual);
  const std::string unknowns = std::to_string(4 * n) + " unknowns";
  if (s.status == LcpStatus::infeasible) {
    o.finished = false;
    o.unfinished =
        s.lemke_too_large
            ? "complementarity with friction: the pivoting on the contacts' modes did not end at "
              "impulses that meet the conditions, and Lemke's method, its fallback, takes at "
              "most " +
                  std::to_string(lemke_friction_limit) + " contacts (its dense tableau of " +
                  unknowns +
                  " would take hours); the serial method (--method serial) resolves one "
                  "collision at a time"
            : "complementarity with friction: Lemke's pivoting ended on a ray after " +
                  counted(static_cast<std::size_t>(s.pivots), "pivot", "pivots") +
                  ", without impulses (the contacts may wedge: pushes within their friction "
                  "cones that move nothing); the serial method (--method serial) resolves one "
                  "collision at a time";
  }
  o.details.push_back("Coulomb friction as one complementarity problem (" + unknowns +
                      "): " + detail::law_words(configuration, options));
  const bool by_modes = s.algorithm == FrictionAlgorithm::modes;
  const std::string pivoting = by_modes ? "pivoting on the contacts' modes" : "Lemke's pivoting";
  const std::string steps =
      by_modes ? counted(static_cast<std::size_t>(s.pivots), "change of mode", "changes of mode")
               : counted(static_cast<std::size_t>(s.pivots), "pivot", "pivots");
  o.details.push_back(pivoting + ", " + steps +
                      (s.status == LcpStatus::solved ? "" : " (approximate)") +
                      ", complementarity residual " + residual +
                      (s.least_norm ? ", the least-norm tangential impulses"
                                    : ", the pivoting's vertex (the least-norm tangential "
                                      "impulses would break the conditions)"));
  o.summary = pivoting + " with friction, " + steps + ", complementarity residual " + residual +
              (s.status == LcpStatus::solved ? "" : " (approximate)");
  if (s.status == LcpStatus::inaccurate) {
    o.warnings.push_back("complementarity: rounding left " + pivoting +
                         " with friction at the complementarity residual " + residual +
                         " against a scale of " + number_text(s.scale) +
                         ": the impulses are approximate");
  }
  const std::span<const Elasticity> e = configuration.elasticities();
  const bool at_most_2 =
      std::all_of(e.begin(), e.end(), [](const Elasticity& x) { return x.value() <= 2.0; });
  const double before = multipoint::kinetic_energy(configuration.bodies());
  const double after = multipoint::kinetic_energy(o.after);
  if (o.finished && at_most_2 && detail::energy_gained(before, after)) {
    o.warnings.push_back(detail::energy_gained_warning(options.restitution));
  }
  o.diagnostics = {
      {"algorithm", std::string(name_of(s.algorithm))},
      {"iterations", std::int64_t{s.pivots}},
      {"complementarity_residual", s.residual},
      {"converged", s.status == LcpStatus::solved},
      {"least_norm", s.least_norm},
      {"restitution", std::string(name_of(options.restitution))},
      {"friction", mu},
      {"slip_after", std::vector<double>(s.u_after.data() + n, s.u_after.data() + 2 * n)}};
  return o;
}

}  // namespace impulse::methods
