// SPDX-License-Identifier: GPL-3.0-or-later
// Section 4: point masses, many contact points, many bodies.
//
// The physics: a point mass of mass m and momentum p touches other bodies at contacts v, each
// with the body's own outward normal n_v; the impulse at contact v is -n_v F_v on it (+n_v F_v on
// the other body). Work is the integral of force along the path, dS = v dt; elastic: total
// kinetic energy kept; inelastic: at each contact the two bodies' velocities along n_v are equal.
// The many-body model of models/scene.hpp judges systems assembled from the printed coefficients.
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>

#include "impulse/multipoint/multipoint.hpp"
#include "numeric.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using GiNaC::ex;
using sym::Equation;

// ---- helpers shared by the numeric checks ------------------------------------------------

// The printed (4.5) and (4.8) coefficients of one point mass, compiled, and the paper's ⊕.
struct MaterialCoefficients {
  sym::Compiled a;  // (nix, niy, nvx, nvy, m)
  sym::Compiled b;  // (px, py, nvx, nvy, m)
};

MaterialCoefficients printed_material(bool elastic) {
  const GiNaC::possymbol m("m");
  const GiNaC::realsymbol nix("nix"), niy("niy"), nvx("nvx"), nvy("nvy"), px("px"), py("py");
  const ex a = (nix * nvx + niy * nvy) / m;
  const ex b = (elastic ? 2 : 1) * (px * nvx + py * nvy) / m;
  return {sym::compile(a, {nix, niy, nvx, nvy, m}), sym::compile(b, {px, py, nvx, nvy, m})};
}

// Each body's block from the printed coefficients, at the contacts it touches with its own
// normals, summed by the paper's ⊕ (zero padding to the global contact indices).
using many::System;

System assemble_printed(const many::Scene& s, const MaterialCoefficients& k) {
  const auto N = static_cast<Eigen::Index>(s.contacts.size());
  System sys{MatrixXd::Zero(N, N), VectorXd::Zero(N)};
  for (std::size_t body = 0; body < s.bodies.size(); ++body) {
    const many::Body& b = s.bodies[body];
    if (b.is_static())
      continue;
    std::vector<std::pair<Eigen::Index, Vector2d>> touches;
    for (std::size_t v = 0; v < s.contacts.size(); ++v) {
      const auto& c = s.contacts[v];
      if (c.a == body)
        touches.push_back({static_cast<Eigen::Index>(v), c.n});
      if (c.b == body)
        touches.push_back({static_cast<Eigen::Index>(v), -c.n});
    }
    for (const auto& [v, nv] : touches) {
      sys.B(v) += k.b({b.p.x(), b.p.y(), nv.x(), nv.y(), b.m});
      for (const auto& [i, ni] : touches) {
        sys.A(v, i) += k.a({ni.x(), ni.y(), nv.x(), nv.y(), b.m});
      }
    }
  }
  return sys;
}

// ---- the energy balance per contact, two point masses ------------------------------------

struct PairSolution {
  many::Scene scene;
  VectorXd F;
  System system;
};

PairSolution solve_pair(num::Random& r, bool elastic, int max_contacts) {
  many::Scene s = many::random_pair(r, max_contacts);
  const auto k = printed_material(elastic);
  const System sys = assemble_printed(s, k);
  return {s, many::solve(sys.A, sys.B), sys};
}

Outcome equation_4_3(const Context& c) {
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const PairSolution x = solve_pair(r, true, 4);
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const double mine = contact_energy(x.scene, x.F, 0, v).translational;
      const double other = contact_energy(x.scene, x.F, 1, v).translational;
      errors.add(mine + other, 0.0, std::abs(mine) + std::abs(other));
    }
  }
  return judge(EquationVerdict{{numeric(Method::numeric, errors, 1e-8,
                                        "two point masses touching at 1 to 4 points, at the "
                                        "impulses of the summed (4.5)")},
                               {},
                               {},
                               {},
                               "dE_vt and dE_vo are the paper's per-contact energies of either "
                               "body (section 4.1's closed form)."});
}

Outcome divided_step(const Context&) {
  // (4.3) with dE_vt = (J^2 + 2 p_v J) / 2m, multiplied by 2 / J (J != 0).
  const GiNaC::realsymbol J("J"), p("p"), dEo("dEo");
  const GiNaC::possymbol m("m");
  const Equation balance{(J * J + 2 * p * J) / (2 * m) + dEo, 0};
  const Equation printed{J / m + 2 * p / m + 2 * dEo / J, 0};
  const bool follows = sym::nonzero_multiple(printed, balance, {{J}}).has_value();
  return judge(EquationVerdict{{symbolic(follows, "(4.3) times 2/J, J != 0")}, {}, {}, {}, {}});
}

// (4.4) with S = sum_i F_i dt n_i . n_v (so that sum_i F_i dt . n_v = -S).
struct Symbols44 {
  GiNaC::realsymbol S{"S", "\\sum_i F_i dt\\, \\vec{n_i}\\cdot\\vec{n_v}"};
  GiNaC::realsymbol p{"pv", "\\vec{p}\\cdot\\vec{n_v}"};
  GiNaC::realsymbol dEo{"dEo", "\\Delta E_{vo}"};
  GiNaC::possymbol m{"m"};
};
const Symbols44& s44() {
  static const Symbols44 s;
  return s;
}

Equation printed_4_4() {
  const auto& s = s44();
  return {s.S / s.m, 2 * s.p / s.m + s.dEo / (2 * s.S)};
}

Equation corrected_4_4() {
  const auto& s = s44();
  return {s.S / s.m, 2 * s.p / s.m - 2 * s.dEo / s.S};
}

// The per-contact numbers of two point masses at their solution: S, p_v and m of body 0 at
// contact v, and the other body's dE_vo.
template <typename Visit>
void pair_contacts(const Context& c, int max_contacts, Visit visit) {
  num::Random r(c.seed);
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const PairSolution x = solve_pair(r, true, max_contacts);
    const many::Body& b = x.scene.bodies[0];
    for (std::size_t v = 0; v < x.scene.contacts.size(); ++v) {
      const Vector2d nv = x.scene.contacts[v].n;
      double S = 0;
      for (std::size_t k = 0; k < x.scene.contacts.size(); ++k) {
        S += x.F(static_cast<Eigen::Index>(k)) * x.scene.contacts[k].n.dot(nv);
      }
      const double dEo = contact_energy(x.scene, x.F, 1, v).translational;
      const double terms =
          x.system.A.row(static_cast<Eigen::Index>(v)).cwiseAbs().dot(x.F.cwiseAbs());
      visit(S, b.p.dot(nv), b.m, dEo, terms);
    }
  }
}

Outcome equation_4_4(const Context& c) {
  const auto& s = s44();
  // The line before, with sum F_i dt . n_v = -S: -S/m + 2 p_v / m - 2 dE_vo / S = 0.
  const Equation previous{-s.S / s.m + 2 * s.p / s.m + 2 * s.dEo / (-s.S), 0};
  const sym::Assumptions nonzero{{s.S}};
  const bool printed_follows = sym::nonzero_multiple(printed_4_4(), previous, nonzero).has_value();
  const bool corrected_follows =
      sym::nonzero_multiple(corrected_4_4(), previous, nonzero).has_value();
  const auto lhs = sym::compile(printed_4_4().lhs, {s.S, s.p, s.dEo, s.m});
  const auto rhs_printed = sym::compile(printed_4_4().rhs, {s.S, s.p, s.dEo, s.m});
  const auto rhs_corrected = sym::compile(corrected_4_4().rhs, {s.S, s.p, s.dEo, s.m});
  num::Errors printed, corrected;
  pair_contacts(c, 4, [&](double S, double p, double m, double dEo, double terms) {
    if (std::abs(S) < 1e-9 * (std::abs(p) + 1e-300))
      return;  // no impulse along n_v: nothing to divide by
    const double scale = std::abs(S / m) + std::abs(2 * p / m) + std::abs(2 * dEo / S) + terms;
    printed.add(lhs({S, p, dEo, m}), rhs_printed({S, p, dEo, m}), scale);
    corrected.add(lhs({S, p, dEo, m}), rhs_corrected({S, p, dEo, m}), scale);
  });
  return judge(EquationVerdict{
      {symbolic(printed_follows, "from the line before it with F_i dt = -F_i dt n_i"),
       numeric(Method::numeric, printed, num::holds_below,
               "at the impulses of the summed (4.5), two point masses")},
      {symbolic(corrected_follows), numeric(Method::numeric, corrected, 1e-8)},
      R"(\frac{\sum_{i} F_{i} dt\, \vec{n_{i}} \cdot \vec{n_{v}}}{m} = \frac{2\vec{p} \cdot \vec{n_{v}}}{m} - \frac{2\Delta E_{vo}}{\sum_{i} F_{i} dt\, \vec{n_{i}} \cdot \vec{n_{v}}})",
      "Substituting F_i dt = -F_i dt n_i into the line before turns 2 dE_vo / (sum F_i dt . n_v) "
      "into -2 dE_vo / (sum F_i dt n_i . n_v); the printed term is -1/4 of that. Section 3's (3.5) "
      "has the right form.",
      "The display's label was lost; the text refers to it as (4.4)."});
}

Outcome material_equation(const Context& c, bool elastic) {
  std::vector<Finding> findings;
  // Exactly: two point masses at two contacts with free normals.
  {
    const GiNaC::possymbol m1("m1"), m2("m2");
    const GiNaC::realsymbol ax("ax"), ay("ay"), bx("bx"), by("by");  // the two normals (body 1's)
    const GiNaC::realsymbol p1x("p1x"), p1y("p1y"), p2x("p2x"), p2y("p2y"), F1("F1"), F2("F2");
    const double e = elastic ? 2 : 1;
    // Body 1 has normals a, b; body 2 has -a, -b. Its printed coefficients, summed.
    const auto a = [](const ex& nix, const ex& niy, const ex& nvx, const ex& nvy, const ex& m) {
      return (nix * nvx + niy * nvy) / m;
    };
    const ex A11 = a(ax, ay, ax, ay, m1) + a(-ax, -ay, -ax, -ay, m2);
    const ex A12 = a(bx, by, ax, ay, m1) + a(-bx, -by, -ax, -ay, m2);
    const ex A22 = a(bx, by, bx, by, m1) + a(-bx, -by, -bx, -by, m2);
    const ex B1 = e * (p1x * ax + p1y * ay) / m1 + e * (-p2x * ax - p2y * ay) / m2;
    const ex B2 = e * (p1x * bx + p1y * by) / m1 + e * (-p2x * bx - p2y * by) / m2;
    const ex solution = GiNaC::lsolve(
        GiNaC::lst{A11 * F1 + A12 * F2 == B1, A12 * F1 + A22 * F2 == B2}, GiNaC::lst{F1, F2});
    const ex f1 = solution.op(0).rhs(), f2 = solution.op(1).rhs();
    const ex q1x = p1x - ax * f1 - bx * f2, q1y = p1y - ay * f1 - by * f2;
    const ex q2x = p2x + ax * f1 + bx * f2, q2y = p2y + ay * f1 + by * f2;
    if (elastic) {
      const ex change = (q1x * q1x + q1y * q1y) / (2 * m1) + (q2x * q2x + q2y * q2y) / (2 * m2) -
                        (p1x * p1x + p1y * p1y) / (2 * m1) - (p2x * p2x + p2y * p2y) / (2 * m2);
      findings.push_back(
          symbolic(sym::simplify(change).is_zero(), "two point masses, two contacts: energy kept"));
    } else {
      const ex gap_a = (q1x / m1 - q2x / m2) * ax + (q1y / m1 - q2y / m2) * ay;
      const ex gap_b = (q1x / m1 - q2x / m2) * bx + (q1y / m1 - q2y / m2) * by;
      findings.push_back(symbolic(sym::simplify(gap_a).is_zero() && sym::simplify(gap_b).is_zero(),
                                  "two point masses, two contacts: normal velocities equal"));
    }
  }
  const auto k = printed_material(elastic);
  const auto numbers = printed_system_findings(
      c, false, elastic, [&](const many::Scene& s) { return assemble_printed(s, k); },
      "random scenes of 2 to 5 point masses and static bodies");
  findings.insert(findings.end(), numbers.begin(), numbers.end());
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome equation_4_5(const Context& c) {
  return material_equation(c, true);
}
Outcome equation_4_8(const Context& c) {
  return material_equation(c, false);
}

Outcome equation_4_6(const Context& c) {
  // Printed: v'_vt = v'_vo as vectors. At the impulses of the summed (4.8) only the components
  // along n_v agree; the tangential ones keep their difference.
  const auto k = printed_material(false);
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const PairSolution x = [&] {
      many::Scene s = many::random_pair(r, 1);
      const System sys = assemble_printed(s, k);
      return PairSolution{s, many::solve(sys.A, sys.B), sys};
    }();
    const many::Scene after = many::after(x.scene, x.F);
    const Vector2d va = after.bodies[0].p / after.bodies[0].m;
    const Vector2d vb = after.bodies[1].p / after.bodies[1].m;
    const Vector2d n = x.scene.contacts[0].n;
    const double scale = x.scene.bodies[0].velocity_at(Vector2d::Zero()).norm() +
                         x.scene.bodies[1].velocity_at(Vector2d::Zero()).norm();
    // Both printed lines at once: the velocities equal as vectors, and the velocity update.
    const Vector2d p = x.scene.bodies[0].p;
    const double update_error = ((p - n * x.F(0)) / x.scene.bodies[0].m - va).norm();
    printed.add((va - vb).norm() + update_error, 0.0, scale);
    corrected.add(va.dot(n) + update_error, vb.dot(n), scale);
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, printed, num::holds_below,
               "two point masses at one contact, at the impulse of the summed (4.8)")},
      {numeric(Method::numeric, corrected)},
      R"(\vec{v_{vt}'} \cdot \vec{n_v} = \vec{v_{vo}'} \cdot \vec{n_v}, \qquad \vec{v_{vt}'} = \frac{\vec{p} + \sum_i \vec{F_i} dt}{m})",
      "Impulses along the normals cannot equalise the tangential velocities: only the normal "
      "components become equal (which is what the text goes on to use).",
      {}});
}

Outcome equation_4_7(const Context& c) {
  // The condition: (p - sum F_i n_i) . n_v / m = v'_vo . n_v. Written with S = sum F_i n_i . n_v.
  const GiNaC::realsymbol S("S"), p("p"), w("w");
  const GiNaC::possymbol m("m");
  const Equation condition{(p - S) / m, w};
  const Equation printed{S / m, p / m + w};
  const Equation corrected{S / m, p / m - w};
  const bool printed_follows = sym::nonzero_multiple(printed, condition, {}).has_value();
  const bool corrected_follows = sym::nonzero_multiple(corrected, condition, {}).has_value();
  const auto k = printed_material(false);
  num::Random r(c.seed);
  num::Errors printed_err, corrected_err;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    many::Scene s = many::random_pair(r, 3);
    const System sys = assemble_printed(s, k);
    const VectorXd F = many::solve(sys.A, sys.B);
    const many::Scene after = many::after(s, F);
    for (std::size_t v = 0; v < s.contacts.size(); ++v) {
      const Vector2d nv = s.contacts[v].n;
      double Sv = 0;
      for (std::size_t j = 0; j < s.contacts.size(); ++j)
        Sv += F(static_cast<Eigen::Index>(j)) * s.contacts[j].n.dot(nv);
      const double m0 = s.bodies[0].m;
      const double pv = s.bodies[0].p.dot(nv);
      const double wv = (after.bodies[1].p / after.bodies[1].m).dot(nv);
      const double scale = std::abs(Sv / m0) + std::abs(pv / m0) + std::abs(wv);
      printed_err.add(Sv / m0, pv / m0 + wv, scale);
      corrected_err.add(Sv / m0, pv / m0 - wv, scale);
    }
  }
  return judge(EquationVerdict{
      {symbolic(printed_follows, "from equal normal velocities"),
       numeric(Method::numeric, printed_err, num::holds_below,
               "at the impulses of the summed (4.8)")},
      {symbolic(corrected_follows), numeric(Method::numeric, corrected_err, 1e-8)},
      R"(\frac{\sum_{i} F_{i} dt \, \vec{n_{i}} \cdot \vec{n_{v}}}{m} = \frac{\vec{p} \cdot \vec{n_{v}}}{m} - \vec{v_{vo}'} \cdot \vec{n_{v}})",
      "Moving v'_vo . n_v to the other side of v'_vt . n_v = v'_vo . n_v changes its sign; "
      "(3.9) has it right.",
      {}});
}

Outcome claim_only_b(const Context&) {
  const GiNaC::possymbol m("m");
  const GiNaC::realsymbol nix("nix"), niy("niy"), nvx("nvx"), nvy("nvy"), px("px"), py("py");
  const ex a = (nix * nvx + niy * nvy) / m;
  const ex b_elastic = 2 * (px * nvx + py * nvy) / m;
  const ex b_inelastic = (px * nvx + py * nvy) / m;
  return judge(
      ClaimVerdict{{symbolic(sym::simplify(b_elastic - 2 * b_inelastic).is_zero() && !a.is_zero(),
                             "(4.5) and (4.8) share a_vi; b_v differs by the factor 2")},
                   std::nullopt,
                   {},
                   {}});
}

Outcome two_body_sum(const Context& c) {
  // (A_1 + A_2) Fdt = B_1 + B_2: the two bodies' printed blocks summed, A and B, against the
  // system built from the contact Jacobian (A = J M^-1 J^T, B = J (e v)) and the library's
  // assembly; solved, the impulses keep the kinetic energy (e = 2) or stop every contact's
  // approach (e = 1), judged on the bodies moved by them.
  std::vector<Finding> findings;
  for (const bool elastic : {true, false}) {
    const auto k = printed_material(elastic);
    for (Finding& f : printed_system_findings(
             c, elastic, [&k](const many::Scene& s) { return assemble_printed(s, k); },
             [](num::Random& r) { return many::random_pair(r, 4); },
             std::string("two point masses at 1 to 4 contacts, ") +
                 (elastic ? "elastic" : "inelastic"),
             c.share(8))) {
      findings.push_back(std::move(f));
    }
  }
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome impulse_direction(const Context& c) {
  // Printed: F_v dt (vector) = n_v F_v dt. On the body whose outward normal is n_v, applying
  // +n_v F_v dt with the elastic impulses of (4.5) does not keep the energy; -n_v F_v dt does.
  const auto k = printed_material(true);
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const many::Scene s = many::random_scene(r, false, true, 4, 5);
    const System sys = assemble_printed(s, k);
    const VectorXd F = many::solve(sys.A, sys.B);
    const double E = many::energy(s);
    if (E == 0 || F.cwiseAbs().maxCoeff() < 1e-9)
      continue;
    const double scale = many::energy_scale(E, sys.A, F);
    printed.add(many::energy(many::after(s, -F)), E, scale);  // flipped: +n_v F_v on the bumper
    corrected.add(many::energy(many::after(s, F)), E, scale);
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, printed, num::holds_below,
               "+n_v F_v dt on the body of normal n_v, elastic impulses of (4.5)")},
      {numeric(Method::numeric, corrected, 1e-8)},
      R"(\vec{F_v} dt = -\vec{n_v}\, F_v dt)",
      "Section 4.1 defines the impulse on a body as -F_i dt n_i (its own outward normal); the "
      "printed form drops the sign (it is the impulse on the other body).",
      {}});
}

Outcome claim_dependent(const Context& c) {
  // A point mass with three contacts: A = N^T N / m has rank at most 2 (det A = 0 exactly), and
  // only the resultant impulse moves a point mass.
  const GiNaC::possymbol m("m");
  const GiNaC::realsymbol t1("t1"), t2("t2"), t3("t3");
  const auto unit = [](const GiNaC::realsymbol& t) {
    return std::pair<ex, ex>{(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)};
  };
  const std::array<std::pair<ex, ex>, 3> n{unit(t1), unit(t2), unit(t3)};
  GiNaC::matrix A(3, 3);
  for (unsigned v = 0; v < 3; ++v) {
    for (unsigned i = 0; i < 3; ++i) {
      A(v, i) = (n[i].first * n[v].first + n[i].second * n[v].second) / m;
    }
  }
  const bool singular = sym::simplify(A.determinant()).is_zero();
  // Numbers: two impulse sets with the same resultant leave a point mass in the same state.
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const double mass = r.mass();
    const Vector2d p = mass * r.vector(10);
    const Vector2d n1 = r.unit_vector(), n2 = r.unit_vector(), n3 = r.unit_vector();
    const VectorXd F =
        VectorXd::NullaryExpr(3, [&](Eigen::Index) { return r.uniform(-5, 5) * mass; });
    // Another split of the same resultant: move along the null space of [n1 n2 n3].
    Eigen::Matrix<double, 2, 3> N;
    N << n1, n2, n3;
    const Eigen::FullPivLU<Eigen::Matrix<double, 2, 3>> lu(N);
    const VectorXd G = F + lu.kernel().col(0) * r.uniform(-5, 5) * mass;
    errors.add(((p - N * F) - (p - N * G)).norm(), 0.0, p.norm() + (N * F).norm());
  }
  return judge(ClaimVerdict{{symbolic(singular, "three contacts on one point mass: det A = 0"),
                             numeric(Method::numeric, errors, num::holds_below,
                                     "impulses with the same resultant give the same motion")},
                            std::nullopt,
                            {},
                            {}});
}

Outcome claim_inconsistent(const Context& c) {
  // Claim: the system may be inconsistent. Search for one among random scenes of point masses,
  // rigid and static bodies with per-body elasticities.
  num::Random r(c.seed);
  std::size_t inconsistent = 0;
  double worst = 0;
  const std::size_t tried = c.samples;
  for (std::size_t i = 0; i < tried; ++i) {
    const many::Scene s = many::random_scene(r, true, true, 6, 8);
    const many::Model md = many::model(s);
    VectorXd weighted = md.velocity;  // per-body elasticities in [0, 3]
    Eigen::Index at = 0;
    for (const auto& b : s.bodies) {
      if (b.is_static())
        continue;
      const Eigen::Index dof = b.rigid() ? 3 : 2;
      weighted.segment(at, dof) *= r.uniform(0, 3);
      at += dof;
    }
    const double residual = many::inconsistency(md.A(), md.J * weighted);
    worst = std::max(worst, residual);
    inconsistent += residual > 1e-9 ? 1U : 0U;
  }
  Finding found{Method::search,
                inconsistent > 0,
                std::nullopt,
                tried,
                std::to_string(inconsistent) + " of " + std::to_string(tried) +
                    " random scenes inconsistent (worst relative residual " + num::brief(worst, 2) +
                    ")",
                true};
  std::optional<std::string> counterexample;
  if (inconsistent == 0) {
    counterexample =
        "none exists: B = J (e v) lies in the range of J, which is the range of "
        "A = J M^-1 J^T for positive masses and inertias; " +
        std::to_string(tried) +
        " random scenes of 2 to 6 point masses, rigid and "
        "static bodies with 1 to 8 contacts and elasticities 0 to 3 were all "
        "consistent (worst relative residual " +
        num::brief(worst, 2) + ").";
  }
  return judge(ClaimVerdict{{found},
                            counterexample,
                            "The system can be dependent but never inconsistent, so the rule for "
                            "inconsistent systems (ignore an equation) is never needed.",
                            {}});
}

Outcome claim_equal_impulses(const Context& c) {
  // Claim: when the system has many solutions, one with equal impulses can be taken. A point mass
  // in a corner: walls with outward normals (1, 0), (0, 1) and the diagonal (1, 1)/sqrt(2),
  // moving at (2, 1) towards them, elasticity 2.
  const double h = std::sqrt(0.5);
  many::Scene s;
  s.bodies = {many::Body{1, 0, {0, 0}, {2, 1}, 0}, many::Body{0, 0, {0, 0}, {0, 0}, 0}};
  s.contacts = {{0, 1, {1, 0}, {0, 0}}, {0, 1, {0, 1}, {0, 0}}, {0, 1, {h, h}, {0, 0}}};
  const many::Model md = many::model(s);
  const MatrixXd A = md.A();
  const VectorXd B = md.J * (2 * md.velocity);
  Eigen::ColPivHouseholderQR<MatrixXd> qr(A);
  const bool dependent = qr.rank() < 3;
  const bool consistent = many::inconsistency(A, B) < 1e-12;
  // The best equal split f (1, 1, 1): least squares in f.
  const VectorXd ones = VectorXd::Ones(3);
  const double f = (A * ones).dot(B) / (A * ones).squaredNorm();
  const double miss = (A * ones * f - B).norm() / B.norm();
  const VectorXd minimum_norm = many::solve(A, B);
  // Search: random dependent systems (point masses with three or more contacts) where no equal
  // split solves them.
  num::Random r(c.seed);
  std::size_t failures = 0, tried = 0;
  for (std::size_t i = 0; i < c.share(10); ++i) {
    many::Scene x;
    x.bodies = {many::Body{r.mass(), 0, {0, 0}, {0, 0}, 0}, many::Body{0, 0, {0, 0}, {0, 0}, 0}};
    x.bodies[0].p = x.bodies[0].m * r.vector(10);
    for (int v = 0; v < 3; ++v)
      x.contacts.push_back({0, 1, r.unit_vector(), Vector2d::Zero()});
    const many::Model mx = many::model(x);
    const MatrixXd Ax = mx.A();
    const VectorXd Bx = mx.J * (2 * mx.velocity);
    const VectorXd all = VectorXd::Ones(3);
    const double fx = (Ax * all).dot(Bx) / (Ax * all).squaredNorm();
    ++tried;
    failures += (Ax * all * fx - Bx).norm() > 1e-9 * Bx.norm() ? 1U : 0U;
  }
  std::optional<std::string> counterexample;
  if (dependent && consistent && miss > 1e-6) {
    counterexample =
        "a point mass m = 1 moving at (2, 1) against walls with outward normals (1, 0), (0, 1) "
        "and (1, 1)/sqrt(2), elasticity 2: A has rank " +
        std::to_string(qr.rank()) +
        " and the system is consistent, yet no equal impulses solve it (the best equal split "
        "leaves a relative residual of " +
        num::brief(miss, 2) + "); the least-norm solution is (" + num::brief(minimum_norm(0), 4) +
        ", " + num::brief(minimum_norm(1), 4) + ", " + num::brief(minimum_norm(2), 4) + ").";
  }
  return judge(ClaimVerdict{{search(tried, failures, "random point masses with three contacts")},
                            counterexample,
                            "Equal impulses exist only when the equal split happens to lie on "
                            "the solution set; the minimum-norm solution always exists and gives "
                            "equal impulses in the symmetric cases the rule has in mind.",
                            {}});
}

Outcome many_bodies(const Context& c, bool elastic) {
  // Scenes of up to 6 point masses with static bodies (chains, stacks, random pairs): the
  // printed coefficients summed over all bodies keep energy or equalise every contact.
  const auto k = printed_material(elastic);
  num::Random r(c.seed);
  num::Errors physics;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const many::Scene s = many::random_scene(r, false, true, 6, 8);
    const System sys = assemble_printed(s, k);
    const VectorXd F = many::solve(sys.A, sys.B);
    const many::Scene after = many::after(s, F);
    if (elastic) {
      const double E = many::energy(s);
      if (E > 0)
        physics.add(many::energy(after), E, many::energy_scale(E, sys.A, F));
    } else {
      const double scale = many::approach_scale(s, sys.A, F);
      if (scale > 0)
        physics.add(many::approach(after).cwiseAbs().maxCoeff(), 0.0, scale);
    }
  }
  return judge(
      ClaimVerdict{{numeric(Method::numeric, physics, 1e-8,
                            elastic ? "2 to 6 bodies, 1 to 8 contacts: energy kept"
                                    : "2 to 6 bodies, 1 to 8 contacts: approach speeds zero")},
                   std::nullopt,
                   {},
                   {}});
}

Outcome claim_many_inelastic(const Context& c) {
  return many_bodies(c, false);
}
Outcome claim_many_valid(const Context& c) {
  return many_bodies(c, true);
}

Outcome many_path(const Context& c) {
  // Printed: dS_v = (sum_i F_i dt . n_v + sum_j F_j dt . n_v) / m + p_v dt / m. Change the units
  // (mass M, length X, time T): a path scales by X, so every term must; the first scales by X / T.
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const double m = r.mass(), p = m * r.uniform(-10, 10), Fi = m * r.uniform(-10, 10),
                 Fj = m * r.uniform(-10, 10), t = r.uniform(0, 1), dt = r.log_uniform(1e-6, 1e-3);
    const double M = r.log_uniform(1e-3, 1e3), X = r.log_uniform(1e-3, 1e3),
                 T = r.log_uniform(1e-3, 1e3);
    // Impulses (F dt) scale by M X / T, forces by M X / T^2, momenta by M X / T, times by T.
    const auto paper = [](double m_, double p_, double Ji, double Jj, double, double dt_) {
      return (Ji + Jj) / m_ + p_ * dt_ / m_;
    };
    const auto fixed = [](double m_, double p_, double fi, double fj, double t_, double dt_) {
      return (fi + fj) * t_ * dt_ / m_ + p_ * dt_ / m_;
    };
    const double Ji = Fi * dt, Jj = Fj * dt;
    printed.add(paper(M * m, M * X / T * p, M * X / T * Ji, M * X / T * Jj, T * t, T * dt),
                X * paper(m, p, Ji, Jj, t, dt));
    corrected.add(
        fixed(M * m, M * X / T * p, M * X / (T * T) * Fi, M * X / (T * T) * Fj, T * t, T * dt),
        X * fixed(m, p, Fi, Fj, t, dt),
        X * (std::abs((Fi + Fj) * t * dt / m) + std::abs(p * dt / m)));
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, printed, num::holds_below,
               "the units of mass, length and time changed")},
      {numeric(Method::numeric, corrected)},
      R"(\mathrm{d}S_v = \frac{\left(\sum_i \vec{F_i} + \sum_j \vec{F_j}\right) \cdot \vec{n_v}\; t\,\mathrm{d}t}{m} + \frac{p_v\,\mathrm{d}t}{m})",
      "The first term lost the factor t and shows impulses where (4.2) has dp_v t: a velocity "
      "added to a length. With the factor restored it is (4.2) with every impulse of the body, "
      "and inherits (4.2)'s restriction to a constant force.",
      {}});
}

Outcome many_4_4(const Context& c) {
  // The modified (4.4) with all of the body's impulses (k) on the left and the pair's (i) in the
  // last term; checked at the impulses of the summed (4.5) in scenes of several point masses.
  const auto k = printed_material(true);
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const many::Scene s = many::random_scene(r, false, false, 5, 6);
    const System sys = assemble_printed(s, k);
    const VectorXd F = many::solve(sys.A, sys.B);
    for (std::size_t v = 0; v < s.contacts.size(); ++v) {
      const std::size_t body = s.contacts[v].a, other = s.contacts[v].b;
      const many::Body& b = s.bodies[body];
      const Vector2d nv = s.contacts[v].n;
      double all = 0, pair = 0;  // sum F_k n_k . n_v over all of the body's contacts / the pair's
      for (std::size_t q = 0; q < s.contacts.size(); ++q) {
        const auto& ct = s.contacts[q];
        if (ct.a != body && ct.b != body)
          continue;
        const Vector2d own = ct.a == body ? ct.n : Vector2d(-ct.n);
        const double term = F(static_cast<Eigen::Index>(q)) * own.dot(nv);
        all += term;
        if (ct.a == other || ct.b == other)
          pair += term;
      }
      if (std::abs(pair) < 1e-9 * (std::abs(all) + b.p.norm()))
        continue;
      const double dEo = contact_energy(s, F, other, v).translational;
      const double lhs = all / b.m;
      // Row v of the system is what the balance rests on; its rounding scales with its terms.
      const double scale = std::abs(lhs) + std::abs(2 * b.p.dot(nv) / b.m) +
                           std::abs(2 * dEo / pair) +
                           sys.A.row(static_cast<Eigen::Index>(v)).cwiseAbs().dot(F.cwiseAbs());
      printed.add(lhs, 2 * b.p.dot(nv) / b.m + dEo / (2 * pair), scale);
      corrected.add(lhs, 2 * b.p.dot(nv) / b.m - 2 * dEo / pair, scale);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, printed, num::holds_below, "scenes of 2 to 5 point masses")},
      {numeric(Method::numeric, corrected, 1e-8)},
      R"(\frac{\sum_i F_i \mathrm{d}t\, \vec{n_i} \cdot \vec{n_v} + \sum_j F_j \mathrm{d}t\, \vec{n_j} \cdot \vec{n_v}}{m} = \frac{2\vec{p} \cdot \vec{n_v}}{m} - \frac{2\Delta E_{vo}}{\sum_i F_i \mathrm{d}t\, \vec{n_i} \cdot \vec{n_v}})",
      "The same slip as in (4.4): the energy term's sign and factor.",
      {}});
}

Outcome oplus(const Context& c) {
  // The ⊕ of the bodies' blocks (zero-padded to the global contact indices), A and B, against
  // the system built from the contact Jacobian and the library's assembly; solved, the impulses
  // keep the kinetic energy (elastic blocks) or stop every approach (inelastic), judged on the
  // bodies moved by them.
  std::vector<Finding> findings;
  for (const bool elastic : {true, false}) {
    const auto k = printed_material(elastic);
    for (Finding& f : printed_system_findings(
             c, elastic, [&k](const many::Scene& s) { return assemble_printed(s, k); },
             [](num::Random& r) { return many::random_scene(r, false, true, 6, 8); },
             std::string("2 to 6 bodies, 1 to 8 contacts, ") + (elastic ? "elastic" : "inelastic"),
             c.share(8))) {
      findings.push_back(std::move(f));
    }
  }
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

}  // namespace

std::vector<CodedCheck> section4_checks() {
  std::vector<CodedCheck> c;
  c.push_back(make_check("eq-4.3", "4.1", "(4.3)", Kind::equation,
                         R"(\Delta E_{vt} + \Delta E_{vo} = 0)", equation_4_3));
  c.push_back(make_check(
      "s4.1-divided", "4.1", std::nullopt, Kind::step,
      R"(\frac{\sum_{i} \vec{F_{i}} dt \cdot \vec{n_{v}}}{m} + \frac{2p_{v}}{m} + \frac{2\Delta E_{vo}}{\sum_{i} \vec{F_{i}} dt \cdot \vec{n_{v}}} = 0)",
      divided_step));
  c.push_back(make_check(
      "eq-4.4", "4.1", "(4.4)", Kind::equation,
      R"(\frac{\sum_{i} F_{i} \operatorname{dt} \vec{n_{i}} \cdot \vec{n_{v}}}{m} = \frac{2\vec{p} \cdot \vec{n_{v}}}{m} + \frac{\Delta E_{vo}}{2\sum_{i} F_{i} \operatorname{dt} \vec{n_{i}} \cdot \vec{n_{v}}})",
      equation_4_4));
  c.push_back(make_check(
      "eq-4.5", "4.1", "(4.5)", Kind::equation,
      R"(a_{vi(elastic)} = \frac{\vec{n_i} \cdot \vec{n_v}}{m}, \quad b_{v(elastic)} = \frac{2\vec{p} \cdot \vec{n_v}}{m})",
      equation_4_5));
  c.push_back(make_check(
      "eq-4.6", "4.2", "(4.6)", Kind::equation,
      R"(\vec{v_{vt}'} = \vec{v_{vo}'}, \quad \vec{v_{vt}'} = \frac{\vec{p} + \sum_{i} \vec{F_{i}} dt}{m})",
      equation_4_6));
  c.push_back(make_check(
      "eq-4.7", "4.2", "(4.7)", Kind::equation,
      R"(\frac{\sum_{i} F_{i} \operatorname{d} t \, \vec{n_{i}} \cdot \vec{n_{v}}}{m} = \frac{\vec{p} \cdot \vec{n_{v}}}{m} + \vec{v_{vo}} \cdot \vec{n_{v}})",
      equation_4_7));
  c.push_back(make_check(
      "eq-4.8", "4.2", "(4.8)", Kind::equation,
      R"(a_{vi(inelastic)} = \frac{\vec{n_i} \cdot \vec{n_v}}{m}, \quad b_{v(inelastic)} = \frac{\vec{p} \cdot \vec{n_v}}{m})",
      equation_4_8));
  c.push_back(make_check(
      "claim-4.3-only-b", "4.3", std::nullopt, Kind::claim,
      R"(a_{vi(elastic)} = a_{vi(inelastic)}, \quad b_{v(elastic)} = 2\, b_{v(inelastic)})",
      claim_only_b));
  c.push_back(make_check("s4.4-sum", "4.4", std::nullopt, Kind::step,
                         R"((\mathbf{A_1} + \mathbf{A_2})\vec{F} dt = \vec{B_1} + \vec{B_2})",
                         two_body_sum));
  c.push_back(make_check("s4.4-impulse", "4.4", std::nullopt, Kind::step,
                         R"(\vec{F_v} dt = \vec{n_v} F_v dt)", impulse_direction));
  c.push_back(make_check(
      "claim-4.4-dependent", "4.4", std::nullopt, Kind::claim,
      R"(\operatorname{rank}\mathbf{A} < N \text{ occurs: a point mass moves by the resultant of its impulses only})",
      claim_dependent));
  c.push_back(
      make_check("claim-4.4-inconsistent", "4.4", std::nullopt, Kind::claim,
                 R"(\exists \text{ scenes with } \vec{B} \notin \operatorname{range}\mathbf{A})",
                 claim_inconsistent));
  c.push_back(make_check(
      "claim-4.4-equal", "4.4", std::nullopt, Kind::claim,
      R"(\operatorname{rank}\mathbf{A} < N \Rightarrow \exists f:\ \mathbf{A}\,(f, \dots, f)^T = \vec{B})",
      claim_equal_impulses));
  c.push_back(make_check(
      "claim-4.5-inelastic", "4.5", std::nullopt, Kind::claim,
      R"(\text{(4.8) summed over all bodies gives } \vec{v_{vt}'} \cdot \vec{n_v} = \vec{v_{vo}'} \cdot \vec{n_v} \text{ at every contact})",
      claim_many_inelastic));
  c.push_back(make_check(
      "s4.5-path", "4.5", std::nullopt, Kind::step,
      R"(\mathrm{d}S_v = \frac{\sum_i \vec{F_i} \vec{\mathrm{d}}t \cdot \vec{n_v} + \sum_j \vec{F_j} \vec{\mathrm{d}}t \cdot \vec{n_v}}{m} + \frac{p_v\,\mathrm{d}t}{m})",
      many_path));
  c.push_back(make_check(
      "s4.5-energy-balance", "4.5", std::nullopt, Kind::step,
      R"(\frac{\sum_i F_i \mathrm{d}t\, \vec{n_i} \cdot \vec{n_v} + \sum_j F_j \mathrm{d}t\, \vec{n_j} \cdot \vec{n_v}}{m} = \frac{2\vec{p} \cdot \vec{n_v}}{m} + \frac{\Delta E_{vo}}{2\sum_i F_i \mathrm{d}t\, \vec{n_i} \cdot \vec{n_v}})",
      many_4_4));
  c.push_back(make_check("claim-4.5-valid", "4.5", std::nullopt, Kind::claim,
                         R"(\text{(4.5) summed over all bodies keeps the kinetic energy})",
                         claim_many_valid));
  c.push_back(make_check(
      "s4.5-oplus", "4.5", std::nullopt, Kind::step,
      R"((\mathbf{A_1} \oplus \mathbf{A_2} \oplus \cdots \oplus \mathbf{A_M}) \vec{Fdt} = \vec{B_1} \oplus \vec{B_2} \oplus \cdots \oplus \vec{B_M})",
      oplus));
  return c;
}

}  // namespace impulse::derivations
