// SPDX-License-Identifier: GPL-3.0-or-later
// Section 5: rigid bodies, many contact points, many bodies.
//
// The physics: as in section 4, with rotation: a rigid body of mass m and moment of inertia I
// about its centre; the impulse -n_k F_k at the material point at arm r_k changes p by it and
// L by det(r_k, -n_k F_k). Elastic: total kinetic energy kept; inelastic: at each contact the
// two material points move alike along the normal.
#include <cmath>
#include <complex>
#include <numbers>

#include "impulse/multipoint/multipoint.hpp"
#include "models/cloud.hpp"
#include "numeric.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using GiNaC::ex;
using sym::Equation;

double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// ---- the printed (5.3)/(5.5) coefficients, compiled, and the paper's ⊕ over rigid bodies ----

struct RigidCoefficients {
  sym::Compiled a;  // (rkx, rky, nkx, nky, rvx, rvy, nvx, nvy, m, I)
  sym::Compiled b;  // (rvx, rvy, nvx, nvy, px, py, L, m, I)
};

RigidCoefficients printed_rigid(bool elastic) {
  const GiNaC::possymbol m("m"), I("I");
  const GiNaC::realsymbol rkx("rkx"), rky("rky"), nkx("nkx"), nky("nky"), rvx("rvx"), rvy("rvy"),
      nvx("nvx"), nvy("nvy"), px("px"), py("py"), L("L");
  const ex dk = rkx * nky - rky * nkx;
  const ex dv = rvx * nvy - rvy * nvx;
  const ex a = dk * dv / I + (nkx * nvx + nky * nvy) / m;
  const ex b = (elastic ? 2 : 1) * (L * dv / I + (px * nvx + py * nvy) / m);
  return {sym::compile(a, {rkx, rky, nkx, nky, rvx, rvy, nvx, nvy, m, I}),
          sym::compile(b, {rvx, rvy, nvx, nvy, px, py, L, m, I})};
}

using many::System;

// Each movable body's block at its contacts with its own normals, the paper's ⊕. Point masses
// use the same formula with no rotation (their 1/I term left out).
System assemble_printed(const many::Scene& s, const RigidCoefficients& k, double scale_b = 1.0) {
  const auto N = static_cast<Eigen::Index>(s.contacts.size());
  System sys{MatrixXd::Zero(N, N), VectorXd::Zero(N)};
  for (std::size_t body = 0; body < s.bodies.size(); ++body) {
    const many::Body& b = s.bodies[body];
    if (b.is_static())
      continue;
    struct Touch {
      Eigen::Index v;
      Vector2d n, r;
    };
    std::vector<Touch> touches;
    for (std::size_t v = 0; v < s.contacts.size(); ++v) {
      const auto& c = s.contacts[v];
      if (c.a == body)
        touches.push_back({static_cast<Eigen::Index>(v), c.n, c.point - b.position});
      if (c.b == body)
        touches.push_back({static_cast<Eigen::Index>(v), -c.n, c.point - b.position});
    }
    // A point mass has no rotation: an infinite moment of inertia removes the 1/I terms.
    const double I = b.rigid() ? b.I : std::numeric_limits<double>::infinity();
    const double L = b.rigid() ? b.L : 0.0;
    for (const Touch& v : touches) {
      sys.B(v.v) +=
          scale_b * k.b({v.r.x(), v.r.y(), v.n.x(), v.n.y(), b.p.x(), b.p.y(), L, b.m, I});
      for (const Touch& kk : touches) {
        sys.A(v.v, kk.v) += k.a(
            {kk.r.x(), kk.r.y(), kk.n.x(), kk.n.y(), v.r.x(), v.r.y(), v.n.x(), v.n.y(), b.m, I});
      }
    }
  }
  return sys;
}

// ---- the checks -----------------------------------------------------------------------------

// Rigid scenes solved from the printed coefficients.
struct Solved {
  many::Scene scene;
  System system;
  VectorXd F;
};

Solved solve_scene(num::Random& r, bool elastic, bool with_static, int bodies, int contacts,
                   bool pairs_only = false) {
  many::Scene s = pairs_only ? many::random_scene(r, true, false, 2, contacts)
                             : many::random_scene(r, true, with_static, bodies, contacts);
  const System sys = assemble_printed(s, printed_rigid(elastic));
  return {s, sys, many::solve(sys.A, sys.B)};
}

Outcome energy_balance(const Context& c) {
  // dE_vr + dE_vt + dE_vo = 0 at every contact of two bodies (rigid or point masses), at the
  // impulses of the summed (5.3); the per-contact energies are the paper's closed forms.
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const Solved x = solve_scene(r, true, false, 2, 4, true);
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const auto mine = contact_energy(x.scene, x.F, x.scene.contacts[v].a, v);
      const auto other = contact_energy(x.scene, x.F, x.scene.contacts[v].b, v);
      const double sum =
          mine.translational + mine.rotational + other.translational + other.rotational;
      // The balance is (J_i / 2) (B_v - (A F)_v): its rounding scales with those summands.
      const auto row = static_cast<Eigen::Index>(v);
      const double summands =
          std::abs(mine.pair_impulse) / 2 *
          (std::abs(x.system.B(row)) + x.system.A.row(row).cwiseAbs().dot(x.F.cwiseAbs()));
      errors.add(
          sum, 0.0,
          std::max(summands, std::abs(mine.translational) + std::abs(mine.rotational) +
                                 std::abs(other.translational) + std::abs(other.rotational)));
    }
  }
  return judge(EquationVerdict{{numeric(Method::numeric, errors, 1e-8,
                                        "two bodies (rigid or point masses) at 1 to 4 contacts")},
                               {},
                               {},
                               {},
                               {}});
}

Outcome equation_5_2(const Context& c) {
  // Symbols: P = sum_i F_i n_i . n_v (the pair's, so sum_i F_i dt . n_v = -P), Q = sum_k F_k
  // n_k . n_v and R = sum_k F_k det(r_k, n_k) (all of the body's), d = det(r_v, n_v).
  const GiNaC::realsymbol P("P"), Q("Q"), R("R"), d("d"), p("p"), L("L"), dEo("dEo");
  const GiNaC::possymbol m("m"), I("I");
  const ex Ji = -P;
  const ex translational = Ji * (-Q / 2 + p) / m;
  const ex rotational = d * Ji * (-R / 2 + L) / I;
  const Equation balance{rotational + translational + dEo, 0};
  const Equation printed{R * d / I + Q / m, 2 * L * d / I + 2 * p / m + dEo / (2 * P)};
  const Equation corrected{R * d / I + Q / m, 2 * L * d / I + 2 * p / m - 2 * dEo / P};
  const sym::Assumptions nonzero{{P}};
  const bool printed_follows = sym::nonzero_multiple(printed, balance, nonzero).has_value();
  const bool corrected_follows = sym::nonzero_multiple(corrected, balance, nonzero).has_value();
  // Numbers: two bodies at the impulses of the summed (5.3).
  num::Random r(c.seed);
  num::Errors printed_err, corrected_err;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const Solved x = solve_scene(r, true, false, 2, 4, true);
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const std::size_t body = x.scene.contacts[v].a;
      const many::Body& b = x.scene.bodies[body];
      const Vector2d nv = x.scene.contacts[v].n;
      const double dv = b.rigid() ? cross(x.scene.contacts[v].point - b.position, nv) : 0.0;
      double Pv = 0, lhs = 0;
      for (std::size_t k = 0; k < x.scene.contacts.size(); ++k) {
        const auto& ct = x.scene.contacts[k];
        const Vector2d own = ct.a == body ? ct.n : Vector2d(-ct.n);
        const double Fk = x.F(static_cast<Eigen::Index>(k));
        Pv += Fk * own.dot(nv);  // two bodies: every contact is the pair's
        lhs += Fk * ((b.rigid() ? cross(ct.point - b.position, own) * dv / b.I : 0.0) +
                     own.dot(nv) / b.m);
      }
      if (std::abs(Pv) < 1e-9 * (std::abs(lhs) * b.m + b.p.norm()))
        continue;
      const auto other = contact_energy(x.scene, x.F, x.scene.contacts[v].b, v);
      const double dEov = other.translational + other.rotational;
      const double base = (b.rigid() ? 2 * b.L * dv / b.I : 0.0) + 2 * b.p.dot(nv) / b.m;
      const double scale =
          std::abs(lhs) + std::abs(base) + std::abs(2 * dEov / Pv) +
          x.system.A.row(static_cast<Eigen::Index>(v)).cwiseAbs().dot(x.F.cwiseAbs());
      printed_err.add(lhs, base + dEov / (2 * Pv), scale);
      corrected_err.add(lhs, base - 2 * dEov / Pv, scale);
    }
  }
  return judge(EquationVerdict{
      {symbolic(printed_follows, "from dE_vr + dE_vt + dE_vo = 0 with the closed forms"),
       numeric(Method::numeric, printed_err, num::holds_below,
               "two bodies at the impulses of (5.3)")},
      {symbolic(corrected_follows), numeric(Method::numeric, corrected_err, 1e-8)},
      R"(\sum_{k} F_{k} dt \left(\frac{\det(\vec{r_{k}}, \vec{n_{k}}) \det(\vec{r_{v}}, \vec{n_{v}})}{I} + \frac{\vec{n_{k}} \cdot \vec{n_{v}}}{m} \right) = \frac{2L \det(\vec{r_{v}}, \vec{n_{v}})}{I} + \frac{2\vec{p} \cdot \vec{n_{v}}}{m} - \frac{2\Delta E_{vo}}{\sum_{i} F_{i} dt \, \vec{n_{i}} \cdot \vec{n_{v}}})",
      "The energy term carries (4.4)'s slip: dividing the balance by sum_i F_i dt . n_v = "
      "-sum_i F_i dt n_i . n_v and multiplying by 2 gives -2 dE_vo over the sum.",
      {}});
}

Outcome rigid_equation(const Context& c, bool elastic) {
  std::vector<Finding> findings;
  // Exactly: a rigid body landing on a static floor at two points (normals (0, -1)), arms free.
  {
    const GiNaC::possymbol m("m"), I("I");
    const GiNaC::realsymbol r1x("r1x"), r1y("r1y"), r2x("r2x"), r2y("r2y"), px("px"), py("py"),
        L("L"), F1("F1"), F2("F2");
    const ex nx = 0, ny = -1;
    const ex d1 = r1x * ny - r1y * nx, d2 = r2x * ny - r2y * nx;
    const auto a = [&](const ex& dk, const ex& dv) {
      return dk * dv / I + (nx * nx + ny * ny) / m;
    };
    const double e = elastic ? 2 : 1;
    const auto b = [&](const ex& dv) { return e * (L * dv / I + (px * nx + py * ny) / m); };
    const ex solution = GiNaC::lsolve(GiNaC::lst{a(d1, d1) * F1 + a(d2, d1) * F2 == b(d1),
                                                 a(d1, d2) * F1 + a(d2, d2) * F2 == b(d2)},
                                      GiNaC::lst{F1, F2});
    const ex f1 = solution.op(0).rhs(), f2 = solution.op(1).rhs();
    // The impulses -n F on the body: +F in y, and the moment det(r, -n F).
    const ex qx = px, qy = py + f1 + f2;
    const ex Lq = L + (r1x * f1 - 0) + (r2x * f2 - 0);  // det(r, (0, F)) = r_x F
    if (elastic) {
      const ex change = (qx * qx + qy * qy) / (2 * m) + Lq * Lq / (2 * I) -
                        (px * px + py * py) / (2 * m) - L * L / (2 * I);
      findings.push_back(symbolic(sym::simplify(change).is_zero(),
                                  "a body landing on two points, arms free: energy kept"));
    } else {
      const auto vy = [&](const ex& rx) { return qy / m + Lq / I * rx; };
      findings.push_back(
          symbolic(sym::simplify(vy(r1x)).is_zero() && sym::simplify(vy(r2x)).is_zero(),
                   "a body landing on two points, arms free: both points stop"));
    }
  }
  const auto k = printed_rigid(elastic);
  const auto numbers = printed_system_findings(
      c, true, elastic, [&](const many::Scene& s) { return assemble_printed(s, k); },
      "random scenes of rigid bodies, point masses and static bodies");
  findings.insert(findings.end(), numbers.begin(), numbers.end());
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome equation_5_3(const Context& c) {
  return rigid_equation(c, true);
}
Outcome equation_5_5(const Context& c) {
  return rigid_equation(c, false);
}

Outcome equalisation_sign(const Context& c) {
  // Printed: v'_vr . n_v + v'_vt . n_v = -v'_vo . n_v, v'_vo the other body's point velocity.
  // At the impulses of the summed (5.5) the two points move alike along n_v: the right side is
  // +v'_vo . n_v.
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const Solved x = solve_scene(r, false, false, 2, 3, true);
    const many::Scene after = many::after(x.scene, x.F);
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const auto& ct = x.scene.contacts[v];
      const double own = after.bodies[ct.a].velocity_at(ct.point).dot(ct.n);
      const double other = after.bodies[ct.b].velocity_at(ct.point).dot(ct.n);
      // The speeds before, and the terms sum_k |A_vk F_k| of the change the impulses bring.
      const auto row = static_cast<Eigen::Index>(v);
      const double scale = x.scene.bodies[ct.a].velocity_at(ct.point).norm() +
                           x.scene.bodies[ct.b].velocity_at(ct.point).norm() +
                           x.system.A.row(row).cwiseAbs().dot(x.F.cwiseAbs());
      printed.add(own, -other, scale);
      corrected.add(own, other, scale);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, printed, num::holds_below, "two bodies at the impulses of (5.5)")},
      {numeric(Method::numeric, corrected)},
      R"(\vec{v_{vr}'} \cdot \vec{n_v} + \vec{v_{vt}'} \cdot \vec{n_v} = \vec{v_{vo}'} \cdot \vec{n_v})",
      "Equal normal velocities means equal components along the same n_v; the minus sign would "
      "belong to the other body's velocity cast on its own normal -n_v.",
      {}});
}

Outcome substituted_sign(const Context& c) {
  // Printed: sum_k F_k (...) = p . n_v / m + L det / I + v'_vo . n_v. It follows from the
  // printed line before it, and inherits its sign.
  const GiNaC::realsymbol S("S"), base("b"), w("w");
  const Equation condition{base - S, w};  // own normal velocity after = v'_vo . n_v
  const Equation printed{S, base + w};
  const Equation corrected{S, base - w};
  const bool printed_follows = sym::nonzero_multiple(printed, condition, {}).has_value();
  const bool corrected_follows = sym::nonzero_multiple(corrected, condition, {}).has_value();
  num::Random r(c.seed);
  num::Errors printed_err, corrected_err;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const Solved x = solve_scene(r, false, false, 2, 3, true);
    const many::Scene after = many::after(x.scene, x.F);
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const auto& ct = x.scene.contacts[v];
      // The body's own part of row v: its block times the impulses.
      const many::Body& b = x.scene.bodies[ct.a];
      double own_lhs = 0, own_terms = 0;
      const double dv = b.rigid() ? cross(ct.point - b.position, ct.n) : 0.0;
      for (std::size_t k = 0; k < x.scene.contacts.size(); ++k) {
        const auto& c2 = x.scene.contacts[k];
        if (c2.a != ct.a && c2.b != ct.a)
          continue;
        const Vector2d own = c2.a == ct.a ? c2.n : Vector2d(-c2.n);
        const double term = x.F(static_cast<Eigen::Index>(k)) *
                            ((b.rigid() ? cross(c2.point - b.position, own) * dv / b.I : 0.0) +
                             own.dot(ct.n) / b.m);
        own_lhs += term;
        own_terms += std::abs(term);
      }
      const double base_v = b.p.dot(ct.n) / b.m + (b.rigid() ? b.L * dv / b.I : 0.0);
      const double w_v = after.bodies[ct.b].velocity_at(ct.point).dot(ct.n);
      const double scale =
          own_terms + std::abs(base_v) + std::abs(w_v) +
          x.system.A.row(static_cast<Eigen::Index>(v)).cwiseAbs().dot(x.F.cwiseAbs());
      printed_err.add(own_lhs, base_v + w_v, scale);
      corrected_err.add(own_lhs, base_v - w_v, scale);
    }
  }
  return judge(EquationVerdict{
      {symbolic(printed_follows, "from equal normal velocities"),
       numeric(Method::numeric, printed_err, num::holds_below,
               "two bodies at the impulses of (5.5)")},
      {symbolic(corrected_follows), numeric(Method::numeric, corrected_err, 1e-8)},
      R"(\sum_{k} F_k dt \left(\frac{\det(\vec{r_k}, \vec{n_k}) \det(\vec{r_v}, \vec{n_v})}{I} + \frac{\vec{n_k} \cdot \vec{n_v}}{m} \right) = \frac{\vec{p} \cdot \vec{n_v}}{m} + \frac{L \det(\vec{r_v}, \vec{n_v})}{I} - \vec{v_{vo}'} \cdot \vec{n_v})",
      "It follows from the line before it and keeps that line's sign slip; (4.7) has the same "
      "one, (3.9) not.",
      {}});
}

Outcome claim_elasticity(const Context& c) {
  // The printed (5.3) with its factor 2 replaced by an elasticity e: at e = 2 energy is kept, at
  // e = 1 every contact's approach speed is zero, in between energy is lost.
  const auto k = printed_rigid(true);
  num::Random r(c.seed);
  num::Errors kept, stopped;
  std::size_t gained = 0, tried = 0;
  for (std::size_t i = 0; i < c.share(8); ++i) {
    const many::Scene s = many::random_scene(r, true, true, 5, 6);
    const double E = many::energy(s);
    if (E == 0)
      continue;
    for (const double e : {2.0, 1.0, r.uniform(1.01, 1.99)}) {
      const System sys = assemble_printed(s, k, e / 2);
      const VectorXd F = many::solve(sys.A, sys.B);
      const many::Scene after = many::after(s, F);
      if (e == 2.0) {
        kept.add(many::energy(after), E, many::energy_scale(E, sys.A, F));
      } else if (e == 1.0) {
        stopped.add(many::approach(after).cwiseAbs().maxCoeff(), 0.0,
                    many::approach_scale(s, sys.A, F));
      } else {
        ++tried;
        gained += many::energy(after) > E * (1 + 1e-12) ? 1U : 0U;
      }
    }
  }
  return judge(
      ClaimVerdict{{numeric(Method::numeric, kept, 1e-8, "elasticity 2: energy kept"),
                    numeric(Method::numeric, stopped, 1e-8, "elasticity 1: approach speeds zero"),
                    search(tried, gained, "elasticities in (1, 2): no energy gained")},
                   std::nullopt,
                   {},
                   {}});
}

}  // namespace

const std::vector<std::string>& section5_order() {
  static const std::vector<std::string> order{"claim-5-pinned",
                                              "s5.1-balance",
                                              "s5.1-rotation-path",
                                              "s5.1-angle",
                                              "s5.1-dalpha",
                                              "s5.1-angular-impulse",
                                              "eq-5.1",
                                              "eq-5.2",
                                              "eq-5.3",
                                              "eq-5.4",
                                              "s5.2-equalisation",
                                              "s5.2-substituted",
                                              "eq-5.5",
                                              "claim-5.3-elasticity"};
  return order;
}

std::vector<CodedCheck> section5_checks() {
  std::vector<CodedCheck> c;
  c.push_back(make_check("s5.1-balance", "5.1", std::nullopt, Kind::step,
                         R"(\Delta E_{vr} + \Delta E_{vt} + \Delta E_{vo} = 0)", energy_balance));
  c.push_back(make_check(
      "eq-5.2", "5.1", "(5.2)", Kind::equation,
      R"(\sum_{k} F_{k} dt \left(\frac{\det(\vec{r_{k}}, \vec{n_{k}}) \det(\vec{r_{v}}, \vec{n_{v}})}{I} + \frac{\vec{n_{k}} \cdot \vec{n_{v}}}{m} \right) = \frac{2L \det(\vec{r_{v}}, \vec{n_{v}})}{I} + \frac{2\vec{p} \cdot \vec{n_{v}}}{m} + \frac{\Delta E_{vo}}{2 \sum_{i} F_{i} dt \, \vec{n_{i}} \cdot \vec{n_{v}}})",
      equation_5_2));
  c.push_back(make_check(
      "eq-5.3", "5.1", "(5.3)", Kind::equation,
      R"(a_{vk(elastic)} = \frac{\det(\vec{r_k}, \vec{n_k}) \det(\vec{r_v}, \vec{n_v})}{I} + \frac{\vec{n_k} \cdot \vec{n_v}}{m}, \quad b_{v(elastic)} = \frac{2L \det(\vec{r_v}, \vec{n_v})}{I} + \frac{2\vec{p} \cdot \vec{n_v}}{m})",
      equation_5_3));
  c.push_back(make_check(
      "s5.2-equalisation", "5.2", std::nullopt, Kind::step,
      R"(\vec{v_{vr}} \cdot \vec{n_v} + \vec{v_{vt}} \cdot \vec{n_v} = -\vec{v_{vo}} \cdot \vec{n_v})",
      equalisation_sign));
  c.push_back(make_check(
      "s5.2-substituted", "5.2", std::nullopt, Kind::step,
      R"(\sum_{k} F_k dt \left(\frac{\det(\vec{r_k}, \vec{n_k}) \det(\vec{r_v}, \vec{n_v})}{I} + \frac{\vec{n_k} \cdot \vec{n_v}}{m} \right) = \frac{\vec{p} \cdot \vec{n_v}}{m} + \frac{L \det(\vec{r_v}, \vec{n_v})}{I} + \vec{v_{vo}'} \cdot \vec{n_v})",
      substituted_sign));
  c.push_back(make_check(
      "eq-5.5", "5.2", "(5.5)", Kind::equation,
      R"(a_{vk(inelastic)} = \frac{\det(\vec{r_k}, \vec{n_k}) \det(\vec{r_v}, \vec{n_v})}{I} + \frac{\vec{n_k} \cdot \vec{n_v}}{m}, \quad b_{v(inelastic)} = \frac{L \det(\vec{r_v}, \vec{n_v})}{I} + \frac{\vec{p} \cdot \vec{n_v}}{m})",
      equation_5_5));
  c.push_back(make_check(
      "claim-5.3-elasticity", "5.3", std::nullopt, Kind::claim,
      R"(b_v \to elasticity \cdot b_{v(inelastic)}:\ 1 \text{ inelastic},\ 2 \text{ elastic})",
      claim_elasticity));
  return c;
}

}  // namespace impulse::derivations
