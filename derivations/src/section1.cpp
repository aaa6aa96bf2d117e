// SPDX-License-Identifier: GPL-3.0-or-later
// Section 1: two material bodies on a line.
//
// The physics the statements are checked against: along the axis pointing from body 1 to
// body 2, body 1's momentum is p1 and body 2's is -p2 (the paper lets p2 point towards body 1);
// the impulse takes Fdt from body 1 and gives it to body 2 along that axis; kinetic energy is
// P^2 / 2m; "elastic" means the total kinetic energy is unchanged, "inelastic" that the two
// velocities are equal afterwards.
#include <cmath>
#include <limits>
#include <numbers>

#include "impulse/one_d/one_d.hpp"
#include "numeric.hpp"
#include "sections.hpp"

namespace impulse::derivations {

const LineSymbols& line_symbols() {
  static const LineSymbols symbols;
  return symbols;
}

Check make_check(std::string id, std::string section, std::optional<std::string> equation,
                 Kind kind, std::string statement,
                 std::function<Outcome(const Context&)> evaluate) {
  return {std::move(id), std::move(section),   std::move(equation),
          kind,          std::move(statement), std::move(evaluate)};
}

namespace {

using GiNaC::ex;
using sym::Equation;

// ---- definitions -------------------------------------------------------------------------

ex energy(const ex& P, const ex& m) {
  return P * P / (2 * m);
}

// Total kinetic energy after minus before, for an impulse F (symbolic).
ex energy_change(const LineSymbols& s, const ex& F) {
  const ex P1 = s.p1;
  const ex P2 = -s.p2;
  return energy(P1 - F, s.m1) + energy(P2 + F, s.m2) - energy(P1, s.m1) - energy(P2, s.m2);
}

// Body 1's velocity minus body 2's along the axis after an impulse F (zero: equalised).
ex velocity_gap(const LineSymbols& s, const ex& F) {
  return (s.p1 - F) / s.m1 - (-s.p2 + F) / s.m2;
}

struct LineSample {
  double m1, m2, p1, p2;
  // The closing speed: both momenta point towards the other body when positive.
  [[nodiscard]] double approach() const { return p1 / m1 + p2 / m2; }
  [[nodiscard]] double energy() const { return p1 * p1 / (2 * m1) + p2 * p2 / (2 * m2); }
  // Energy after the impulse F, from the momenta after (p1 - F and, towards body 1, p2 - F).
  [[nodiscard]] double energy_after(double F) const {
    return (p1 - F) * (p1 - F) / (2 * m1) + (p2 - F) * (p2 - F) / (2 * m2);
  }
  [[nodiscard]] double approach_after(double F) const { return (p1 - F) / m1 + (p2 - F) / m2; }
};

LineSample sample_line(num::Random& r, bool approaching = false) {
  LineSample s{r.mass(), r.mass(), 0, 0};
  s.p1 = s.m1 * r.uniform(-10, 10);
  s.p2 = s.m2 * r.uniform(-10, 10);
  if (approaching && s.approach() < 0) {
    s.p1 = -s.p1;
    s.p2 = -s.p2;
  }
  return s;
}

std::vector<ex> line_arguments(const LineSymbols& s) {
  return {s.m1, s.m2, s.p1, s.p2};
}

// The library's impulse for the same two bodies: body 2's momentum along the axis is -p2.
double library_impulse(const LineSample& x, double e1, double e2) {
  return one_d::collide({x.m1, x.p1}, Elasticity(e1), {x.m2, -x.p2}, Elasticity(e2)).solution.Fdt;
}

// The size of the terms an impulse is computed from, to measure errors of cancelling sums.
double impulse_scale(const LineSample& x, double e1, double e2) {
  return (std::abs(e1 * x.p1 / x.m1) + std::abs(e2 * x.p2 / x.m2)) / (1 / x.m1 + 1 / x.m2);
}

Finding library_agreement(const sym::Compiled& printed_F, double e1, double e2, const Context& c,
                          const std::string& function) {
  num::Random r(c.seed + 7);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    errors.add(library_impulse(x, e1, e2), printed_F({x.m1, x.m2, x.p1, x.p2}),
               impulse_scale(x, e1, e2));
  }
  return numeric(Method::numeric, errors, num::holds_below,
                 "the library's " + function + " gives the same impulse");
}

// ---- an independent continuous-time contact: two bodies joined by a spring-damper while
// they overlap (force k d + c d', d the overlap), integrated until the contact ends ----------

struct ContactRun {
  double impulse = 0;  // the integral of the contact force
  double approach_after = 0;
  double momentum_1 = 0;  // body 1's momentum along the axis at the end, as integrated
  double momentum_2 = 0;  // body 2's
};

ContactRun spring_damper(const LineSample& x, double k, double c) {
  // y = [overlap, P1 along the axis, P2 along the axis, integral of the force]
  const auto rhs = [&](double, const double* y, double* dy) {
    const double closing = y[1] / x.m1 - y[2] / x.m2;
    // The contact pushes only while the bodies overlap (a damper alone acts from the touch on).
    const double force = k > 0 && y[0] <= 0 ? 0.0 : k * y[0] + c * closing;
    dy[0] = closing;
    dy[1] = -force;
    dy[2] = force;
    dy[3] = force;
  };
  const double A = 1 / x.m1 + 1 / x.m2;
  // Only the step size uses the contact's time scale; the result does not depend on it.
  const double time_scale = k > 0 ? 1 / std::sqrt(k * A) : 1 / (c * A);
  const auto ended = [&](double t, const double* y) {
    if (t <= 0) {
      return 1.0;
    }
    // A spring contact ends when the overlap is gone; a pure damper when the bodies stop closing.
    // (The closing speed is a difference of the two velocities: it is known to the rounding of
    // those, so the damper's contact ends when it is within 1e-12 of their size.)
    return k > 0 ? y[0]
                 : (y[1] / x.m1 - y[2] / x.m2) -
                       1e-12 * (std::abs(x.p1 / x.m1) + std::abs(x.p2 / x.m2));
  };
  const auto end = num::integrate_until(rhs, {0.0, x.p1, -x.p2, 0.0}, ended, time_scale / 50,
                                        1e4 * time_scale, 1e-12 * time_scale);
  return {end.y[3], end.y[1] / x.m1 - end.y[2] / x.m2, end.y[1], end.y[2]};
}

// ---- the checks ------------------------------------------------------------------------------

Outcome momentum_update(const Context& c) {
  // p1' = p1 - F, p2' = p2 + F as vectors: the total is the same for any F.
  const GiNaC::realsymbol p1x("p1x"), p2x("p2x"), F("F");
  const bool exact = sym::simplify((p1x - F) + (p2x + F) - (p1x + p2x)).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (int i = 0; i < 20; ++i) {
    // An independent model of the same collision: a spring-damper contact, integrated. The
    // momenta it ends with must differ from the ones before by -J and +J, J the integral of the
    // contact force (integrated as a separate quantity of the same ODE).
    const LineSample x = sample_line(r, true);
    const ContactRun run = spring_damper(x, 1e4, 10.0 * (i % 3));
    const double scale = std::abs(x.p1) + std::abs(x.p2) + std::abs(run.impulse);
    errors.add(run.momentum_1, x.p1 - run.impulse, scale);
    errors.add(run.momentum_2, -x.p2 + run.impulse, scale);
  }
  return judge(EquationVerdict{{symbolic(exact), numeric(Method::ode, errors, 1e-9,
                                                         "spring-damper contacts: the momenta "
                                                         "change by minus and plus the "
                                                         "integrated force")},
                               {},
                               {},
                               {},
                               "Vectors along the line; Fdt is the impulse on body 2."});
}

Outcome momentum_preserved(const Context& c) {
  const auto& s = line_symbols();
  // Along the axis: (p1 - F) + (-p2 + F) = p1 - p2 whatever F is.
  const bool exact = sym::simplify((s.p1 - s.F) + (-s.p2 + s.F) - (s.p1 - s.p2)).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    const double F = r.uniform(-1, 1) * std::pow(10.0, r.uniform(-6, 6));
    errors.add((x.p1 - F) + (-x.p2 + F), x.p1 - x.p2,
               std::abs(x.p1) + std::abs(x.p2) + std::abs(F));
  }
  return judge(ClaimVerdict{
      {symbolic(exact), numeric(Method::search, errors, 1e-12, "any impulse from -1e6 to 1e6")},
      std::nullopt,
      {},
      "By the paper's own footnote, preserved would mean constant at every "
      "instant of the contact too; with equal and opposite contact forces "
      "that holds as well."});
}

// Line 1 of section 1.1: E_k1' + E_k2' = E_k1 + E_k2. Line 2 writes it with E = p^2/2m and
// body 2's momentum -p2; line 3 substitutes p1' = p1 - Fdt, p2' = -p2 + Fdt.
Outcome elastic_line_2(const Context&) {
  const auto& s = line_symbols();
  const GiNaC::realsymbol q1("q1", "p_1'"), q2("q2", "p_2'");
  // The definition: kinetic energies of the momenta along the axis (q2 = body 2's, after).
  const Equation line1{energy(q1, s.m1) + energy(q2, s.m2),
                       energy(s.p1, s.m1) + energy(-s.p2, s.m2)};
  const Equation printed{q1 * q1 / (2 * s.m1) + q2 * q2 / (2 * s.m2),
                         s.p1 * s.p1 / (2 * s.m1) + GiNaC::pow(-s.p2, 2) / (2 * s.m2)};
  return judge(EquationVerdict{{symbolic(sym::nonzero_multiple(printed, line1, {}).has_value(),
                                         "the same equation as energy conservation")},
                               {},
                               {},
                               {},
                               {}});
}

Equation elastic_line_3_printed() {
  const auto& s = line_symbols();
  return {GiNaC::pow(s.p1 - s.F, 2) / (2 * s.m1) + GiNaC::pow(-s.p2 + s.F, 2) / (2 * s.m2),
          s.p1 * s.p1 / (2 * s.m1) + s.p2 * s.p2 / (2 * s.m2)};
}

Outcome elastic_line_3(const Context&) {
  const auto& s = line_symbols();
  const Equation conservation{energy_change(s, s.F), 0};
  return judge(EquationVerdict{
      {symbolic(sym::nonzero_multiple(elastic_line_3_printed(), conservation, {}).has_value(),
                "energy conservation with p1' = p1 - Fdt and p2' = -p2 + Fdt")},
      {},
      {},
      {},
      {}});
}

Outcome equation_1_1(const Context& c) {
  const auto& s = line_symbols();
  auto findings = elastic_line_findings(printed_1_1(), c);
  // (1.1) from the line before it: dividing by Fdt/2, which needs Fdt != 0.
  const sym::Assumptions nonzero_impulse{{s.F}};
  findings.push_back(symbolic(
      sym::nonzero_multiple(printed_1_1(), elastic_line_3_printed(), nonzero_impulse).has_value(),
      "follows from the line before it when Fdt is not zero"));
  const ex F = sym::solve_for(printed_1_1(), s.F);
  findings.push_back(
      library_agreement(sym::compile(F, line_arguments(s)), 2.0, 2.0, c, "one_d::collide"));
  // The independent contact model: a linear spring returns all the energy it stores.
  num::Random r(c.seed + 11);
  num::Errors ode;
  const auto printed_F = sym::compile(F, line_arguments(s));
  std::string figures;
  for (const double k : {1e2, 1e4, 1e6}) {
    for (int i = 0; i < 4; ++i) {
      const LineSample x = sample_line(r, true);
      const ContactRun run = spring_damper(x, k, 0.0);
      ode.add(run.impulse, printed_F({x.m1, x.m2, x.p1, x.p2}), impulse_scale(x, 2, 2));
    }
  }
  findings.push_back(numeric(Method::ode, ode, 1e-8,
                             "linear spring contacts of stiffness 1e2, 1e4 and 1e6 give the same "
                             "impulse"));
  return judge(EquationVerdict{std::move(findings),
                               {},
                               {},
                               {},
                               "The quadratic in Fdt has a second root, Fdt = 0 (no collision), "
                               "which the division by Fdt removes."});
}

Outcome inelastic_line_step(const Context&) {
  const auto& s = line_symbols();
  const Equation printed{(s.p1 - s.F) / s.m1, (-s.p2 + s.F) / s.m2};
  return judge(EquationVerdict{
      {symbolic(sym::nonzero_multiple(printed, {velocity_gap(s, s.F), 0}, {}).has_value(),
                "v = p/m with the momenta after the impulse")},
      {},
      {},
      {},
      {}});
}

Outcome equation_1_2(const Context& c) {
  const auto& s = line_symbols();
  const Equation printed{s.F * (1 / s.m1 + 1 / s.m2), s.p1 / s.m1 + s.p2 / s.m2};
  const ex F = sym::solve_for(printed, s.F);
  std::vector<Finding> findings;
  findings.push_back(symbolic(sym::simplify(velocity_gap(s, F)).is_zero(),
                              "substituted, the velocities after are equal"));
  const auto printed_F = sym::compile(F, line_arguments(s));
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    const double v1 = (x.p1 - printed_F({x.m1, x.m2, x.p1, x.p2})) / x.m1;
    const double v2 = (-x.p2 + printed_F({x.m1, x.m2, x.p1, x.p2})) / x.m2;
    errors.add(v1, v2, std::abs(x.p1 / x.m1) + std::abs(x.p2 / x.m2));
  }
  findings.push_back(numeric(Method::numeric, errors));
  findings.push_back(library_agreement(printed_F, 1.0, 1.0, c, "one_d::collide"));
  // A dissipative contact (a damper alone) that ends when the bodies stop closing.
  num::Errors ode;
  num::Random rr(c.seed + 11);
  for (const double damping : {1e2, 1e4}) {
    for (int i = 0; i < 4; ++i) {
      const LineSample x = sample_line(rr, true);
      ode.add(spring_damper(x, 0.0, damping).impulse, printed_F({x.m1, x.m2, x.p1, x.p2}),
              impulse_scale(x, 1, 1));
    }
  }
  findings.push_back(numeric(Method::ode, ode, 1e-8,
                             "a damper contact stopped when the bodies no longer close gives the "
                             "same impulse"));
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Equation printed_1_3() {
  const auto& s = line_symbols();
  return {s.F * (1 / s.m1 + 1 / s.m2), s.e1 * s.p1 / s.m1 + s.e2 * s.p2 / s.m2};
}

Outcome equation_1_3(const Context& c) {
  const auto& s = line_symbols();
  const Equation printed = printed_1_3();
  std::vector<Finding> findings;
  // Both elasticities 2 give (1.1), both 1 give (1.2).
  const GiNaC::exmap two{{s.e1, 2}, {s.e2, 2}};
  const GiNaC::exmap one{{s.e1, 1}, {s.e2, 1}};
  findings.push_back(
      symbolic(sym::nonzero_multiple(printed.subs(two), printed_1_1(), {}).has_value(),
               "elasticity 2 gives (1.1)"));
  findings.push_back(
      symbolic(sym::nonzero_multiple(printed.subs(one),
                                     {s.F * (1 / s.m1 + 1 / s.m2), s.p1 / s.m1 + s.p2 / s.m2}, {})
                   .has_value(),
               "elasticity 1 gives (1.2)"));
  // One elasticity e for both: the approach speed after is (1 - e) times the one before, the
  // law of restitution with coefficient e - 1.
  const GiNaC::realsymbol e("e");
  const ex F = sym::solve_for(printed.subs(GiNaC::exmap{{s.e1, e}, {s.e2, e}}), s.F);
  const ex approach = s.p1 / s.m1 + s.p2 / s.m2;
  const ex approach_after = (s.p1 - F) / s.m1 + (s.p2 - F) / s.m2;
  findings.push_back(symbolic(sym::simplify(approach_after - (1 - e) * approach).is_zero(),
                              "with one elasticity e the bodies part at (e - 1) times the speed "
                              "they met at"));
  const auto printed_F =
      sym::compile(sym::solve_for(printed, s.F), {s.m1, s.m2, s.p1, s.p2, s.e1, s.e2});
  num::Random r(c.seed);
  num::Errors errors;
  num::Errors library;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    const double e1 = r.uniform(0, 3);
    const double e2 = r.uniform(0, 3);
    const double Fp = printed_F({x.m1, x.m2, x.p1, x.p2, e1, e2});
    library.add(library_impulse(x, e1, e2), Fp, impulse_scale(x, e1, e2));
    if (i % 2 == 0) {
      const double e_same = e1;
      const double F_same = printed_F({x.m1, x.m2, x.p1, x.p2, e_same, e_same});
      errors.add(x.approach_after(F_same), (1 - e_same) * x.approach(),
                 std::abs(x.p1 / x.m1) + std::abs(x.p2 / x.m2));
    }
  }
  findings.push_back(numeric(Method::numeric, errors, num::holds_below,
                             "restitution law on random bodies and elasticities 0..3"));
  findings.push_back(numeric(Method::numeric, library, num::holds_below,
                             "the library's one_d::collide gives the same impulse for any pair of "
                             "elasticities"));
  // Intermediate collisions from physics: a linear spring-damper of damping ratio z has the
  // textbook coefficient of restitution exp(-z pi / sqrt(1 - z^2)); (1.3) with elasticity
  // 1 + that coefficient must give the contact's impulse.
  num::Random rr(c.seed + 13);
  num::Errors ode;
  for (const double z : {0.05, 0.2, 0.5}) {
    for (int i = 0; i < 3; ++i) {
      const LineSample x = sample_line(rr, true);
      const double reduced = 1 / (1 / x.m1 + 1 / x.m2);
      const double k = 1e4 / reduced;
      const double damping = 2 * z * std::sqrt(k * reduced);
      const double restitution = std::exp(-z * std::numbers::pi / std::sqrt(1 - z * z));
      const double elasticity = 1 + restitution;
      ode.add(spring_damper(x, k, damping).impulse,
              printed_F({x.m1, x.m2, x.p1, x.p2, elasticity, elasticity}),
              impulse_scale(x, elasticity, elasticity));
    }
  }
  findings.push_back(
      numeric(Method::ode, ode, 1e-8, "spring-damper contacts of damping ratio 0.05, 0.2, 0.5"));
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome generic_form(const Context&) {
  // F (a1 + a2) = b1 + b2 with a_i = 1/m_i and b_i = elasticity_i p_i / m_i is (1.3); and
  // F = B / A solves A F = B whenever A != 0, which positive masses guarantee.
  const auto& s = line_symbols();
  const GiNaC::realsymbol a1("a1"), a2("a2"), b1("b1"), b2("b2");
  const Equation generic{s.F * (a1 + a2), b1 + b2};
  const GiNaC::exmap coefficients{
      {a1, 1 / s.m1}, {a2, 1 / s.m2}, {b1, s.e1 * s.p1 / s.m1}, {b2, s.e2 * s.p2 / s.m2}};
  const bool is_1_3 =
      sym::nonzero_multiple(generic.subs(coefficients), printed_1_3(), {}).has_value();
  const GiNaC::realsymbol A("A"), B("B");
  const bool quotient = sym::simplify(sym::solve_for({A * s.F, B}, s.F) - B / A).is_zero();
  const bool A_positive = sym::definitely_positive(1 / s.m1 + 1 / s.m2, {});
  return judge(EquationVerdict{{symbolic(is_1_3, "with a = 1/m and b = elasticity p/m it is (1.3)"),
                                symbolic(quotient, "Fdt = B/A solves A Fdt = B"),
                                symbolic(A_positive, "A = 1/m1 + 1/m2 > 0")},
                               {},
                               {},
                               {},
                               {}});
}

// Energy change for one elasticity e on both bodies, in closed form.
struct EnergyLaw {
  ex change;     // total kinetic energy after minus before
  ex loss_at_1;  // the loss of the perfectly inelastic collision
};

EnergyLaw energy_law(const GiNaC::realsymbol& e) {
  const auto& s = line_symbols();
  const ex F = sym::solve_for(printed_1_3().subs(GiNaC::exmap{{s.e1, e}, {s.e2, e}}), s.F);
  const ex change = sym::simplify(energy_change(s, F));
  return {change, -change.subs(e == 1)};
}

// Searches random approaching bodies, one elasticity for both drawn from [low, high], for a case
// where `holds` fails; the first one found becomes the counterexample.
template <typename Predicate>
Finding search_line(const Context& c, double low, double high, Predicate holds,
                    std::optional<std::string>& counterexample, const std::string& detail = {}) {
  num::Random r(c.seed);
  std::size_t failures = 0;
  const auto& s = line_symbols();
  const auto printed_F =
      sym::compile(sym::solve_for(printed_1_3(), s.F), {s.m1, s.m2, s.p1, s.p2, s.e1, s.e2});
  for (std::size_t i = 0; i < c.samples; ++i) {
    // In the centre-of-mass frame: with one elasticity for both bodies the impulse depends only
    // on the closing speed, and there the energies are those of the relative motion alone, not
    // small differences of the centre's energy that no impulse changes.
    const LineSample y = sample_line(r, true);
    const double centre = (y.p1 - y.p2) / (y.m1 + y.m2);  // velocity of the centre along the axis
    const LineSample x{y.m1, y.m2, y.p1 - y.m1 * centre, y.p2 + y.m2 * centre};
    const double e = r.uniform(low, high);
    const double F = printed_F({x.m1, x.m2, x.p1, x.p2, e, e});
    if (!holds(x, e, F)) {
      ++failures;
      if (!counterexample) {
        counterexample = "m1 = " + num::brief(x.m1) + ", m2 = " + num::brief(x.m2) +
                         ", p1 = " + num::brief(x.p1) + ", p2 = " + num::brief(x.p2) +
                         ", elasticity = " + num::brief(e);
      }
    }
  }
  return search(c.samples, failures, detail);
}

Outcome claim_edges(const Context& c) {
  const GiNaC::realsymbol e("e");
  const auto& s = line_symbols();
  const EnergyLaw law = energy_law(e);
  const bool elastic = sym::simplify(law.change.subs(e == 2)).is_zero();
  const ex F1 = sym::solve_for(printed_1_3().subs(GiNaC::exmap{{s.e1, 1}, {s.e2, 1}}), s.F);
  const bool inelastic = sym::simplify(velocity_gap(s, F1)).is_zero();
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, 0, 1,
      [](const LineSample& x, double, double) {
        // At e = 2 energy is kept; at e = 1 the approach after is zero.
        const double F2 = 2 * x.approach() / (1 / x.m1 + 1 / x.m2);
        const double F1n = x.approach() / (1 / x.m1 + 1 / x.m2);
        return num::relative_error(x.energy_after(F2), x.energy()) < 1e-9 &&
               std::abs(x.approach_after(F1n)) <=
                   1e-9 * (std::abs(x.p1 / x.m1) + std::abs(x.p2 / x.m2));
      },
      counterexample);
  return judge(
      ClaimVerdict{{symbolic(elastic, "at elasticity 2 the energy change is zero"),
                    symbolic(inelastic, "at elasticity 1 the velocities are equal"), searched},
                   counterexample,
                   {},
                   {}});
}

Outcome claim_intermediate(const Context& c) {
  // The energy change is u^2 e (e - 2) / (2A) (u the closing speed, A = 1/m1 + 1/m2): between
  // 0 and the loss at e = 1 exactly when e is in (0, 2) \ {1}; in (1, 2) it is intermediate.
  const GiNaC::realsymbol e("e");
  const auto& s = line_symbols();
  const EnergyLaw law = energy_law(e);
  const ex u = s.p1 / s.m1 + s.p2 / s.m2;
  const ex A = 1 / s.m1 + 1 / s.m2;
  const bool closed_form = sym::simplify(law.change - u * u * e * (e - 2) / (2 * A)).is_zero();
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, 1, 2,
      [](const LineSample& x, double, double impulse) {
        const double loss = x.energy() - x.energy_after(impulse);
        const double loss_1 = x.approach() * x.approach() / (2 * (1 / x.m1 + 1 / x.m2));
        return loss > 0 && loss < loss_1 * (1 + 1e-12);
      },
      counterexample);
  return judge(ClaimVerdict{{symbolic(closed_form, "energy change u^2 e (e - 2) / (2A)"), searched},
                            counterexample,
                            {},
                            "Intermediate read as: some energy is lost, less than at elasticity "
                            "1, for bodies that approach."});
}

Outcome claim_gain(const Context& c) {
  const GiNaC::realsymbol e("e");
  const auto& s = line_symbols();
  const EnergyLaw law = energy_law(e);
  const ex u = s.p1 / s.m1 + s.p2 / s.m2;
  const ex A = 1 / s.m1 + 1 / s.m2;
  // For e > 2, e (e - 2) > 0: write e = 2 + d with d > 0 and the factor is (2 + d) d > 0.
  const GiNaC::possymbol d("d");
  const bool positive =
      sym::definitely_positive(sym::simplify(law.change.subs(e == 2 + d) * 2 * A / (u * u)), {});
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, 2, 10,
      [](const LineSample& x, double, double impulse) {
        return x.energy_after(impulse) > x.energy();
      },
      counterexample, "elasticities 2..10");
  return judge(ClaimVerdict{
      {symbolic(positive, "energy change u^2 (2 + d) d / (2A) with e = 2 + d"), searched},
      counterexample,
      {},
      {}});
}

Outcome claim_tunnel(const Context& c) {
  // One elasticity e in (0, 1): the closing speed after is (1 - e) u > 0, so the bodies keep
  // moving into each other.
  const GiNaC::realsymbol e("e");
  const auto& s = line_symbols();
  const ex F = sym::solve_for(printed_1_3().subs(GiNaC::exmap{{s.e1, e}, {s.e2, e}}), s.F);
  const ex u = s.p1 / s.m1 + s.p2 / s.m2;
  const ex after = (s.p1 - F) / s.m1 + (s.p2 - F) / s.m2;
  const bool law = sym::simplify(after / u - (1 - e)).is_zero();
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, 1e-9, 1 - 1e-9,
      [](const LineSample& x, double, double impulse) { return x.approach_after(impulse) > 0; },
      counterexample);
  return judge(ClaimVerdict{{symbolic(law, "closing speed after = (1 - e) times before"), searched},
                            counterexample,
                            {},
                            "Tunnelling read as: after the impulse the bodies still approach."});
}

Outcome claim_zero(const Context& c) {
  const auto& s = line_symbols();
  const ex F = sym::solve_for(printed_1_3().subs(GiNaC::exmap{{s.e1, 0}, {s.e2, 0}}), s.F);
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, 0, 0, [](const LineSample&, double, double F0) { return F0 == 0.0; }, counterexample);
  return judge(ClaimVerdict{{symbolic(F.is_zero(), "Fdt = 0"), searched}, counterexample, {}, {}});
}

Outcome claim_negative(const Context& c) {
  // For approaching bodies the impulse at e > 0 pushes them apart (Fdt > 0); at e < 0 it pulls.
  const GiNaC::realsymbol e("e");
  const auto& s = line_symbols();
  const ex F = sym::solve_for(printed_1_3().subs(GiNaC::exmap{{s.e1, e}, {s.e2, e}}), s.F);
  const ex u = s.p1 / s.m1 + s.p2 / s.m2;
  const ex A = 1 / s.m1 + 1 / s.m2;
  const bool proportional = sym::simplify(F - e * u / A).is_zero();
  std::optional<std::string> counterexample;
  const Finding searched = search_line(
      c, -3, -1e-9, [](const LineSample&, double, double F0) { return F0 < 0; }, counterexample,
      "elasticities -3..0");
  return judge(ClaimVerdict{{symbolic(proportional, "Fdt = e u / A changes sign with e"), searched},
                            counterexample,
                            {},
                            {}});
}

Outcome claim_mixed(const Context& c) {
  // Claim: unequal elasticities give a collision between the elastic and the inelastic ones:
  // energy lost, but less than at elasticity 1. Searched over small whole-number bodies with
  // elasticities 2 and 1 (either way round), then over random ones.
  const auto& s = line_symbols();
  const auto printed_F =
      sym::compile(sym::solve_for(printed_1_3(), s.F), {s.m1, s.m2, s.p1, s.p2, s.e1, s.e2});
  const auto intermediate = [&](const LineSample& x, double e1, double e2) {
    const double F = printed_F({x.m1, x.m2, x.p1, x.p2, e1, e2});
    const double loss = x.energy() - x.energy_after(F);
    const double loss_1 = x.approach() * x.approach() / (2 * (1 / x.m1 + 1 / x.m2));
    return loss >= 0 && loss <= loss_1 * (1 + 1e-12);
  };
  std::optional<std::string> counterexample;
  for (int m1 = 1; m1 <= 2 && !counterexample; ++m1) {
    for (int v1 = 1; v1 <= 3 && !counterexample; ++v1) {
      for (int v2 = -3; v2 <= 3 && !counterexample; ++v2) {
        const LineSample x{static_cast<double>(m1), 1.0, static_cast<double>(m1 * v1),
                           static_cast<double>(v2)};
        if (x.approach() <= 0 || intermediate(x, 2, 1)) {
          continue;
        }
        const double F = printed_F({x.m1, x.m2, x.p1, x.p2, 2, 1});
        // The same two bodies seen from a frame moving with body 2 (a Galilean boost).
        const double boost = -x.p2 / x.m2;  // body 2's velocity along the axis
        const LineSample y{x.m1, x.m2, x.m1 * (x.p1 / x.m1 - boost),
                           -x.m2 * (-x.p2 / x.m2 - boost)};
        const double Fy = printed_F({y.m1, y.m2, y.p1, y.p2, 2, 1});
        counterexample =
            "m1 = " + num::number(x.m1) + ", m2 = 1, p1 = " + num::number(x.p1) +
            ", p2 = " + num::number(x.p2) + " (body 2 " +
            (x.p2 < 0 ? "moving away" : "approaching") +
            "), elasticity_1 = 2, elasticity_2 = 1: "
            "Fdt = " +
            num::number(F) + ", kinetic energy " + num::number(x.energy()) + " before, " +
            num::number(x.energy_after(F)) + " after (" +
            (x.energy_after(F) > x.energy() ? "gained" : "more lost than at elasticity 1") +
            "); the bodies part at " + num::number(-x.approach_after(F)) + " after closing at " +
            num::number(x.approach()) +
            ". Seen from a frame moving with body 2 the same collision gives Fdt = " +
            num::number(Fy) + " and keeps the energy: the outcome depends on the frame.";
      }
    }
  }
  num::Random r(c.seed);
  std::size_t outside = 0;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r, true);
    const double e1 = r.uniform(1, 2);
    const double e2 = r.uniform(1, 2);
    outside += intermediate(x, e1, e2) ? 0U : 1U;
  }
  return judge(ClaimVerdict{
      {search(1, counterexample ? 1 : 0, "the worked counterexample"),
       search(c.samples, outside, "random approaching bodies with elasticities drawn from [1, 2]")},
      counterexample,
      "Each body's elasticity multiplies its own velocity, so the outcome depends on how the "
      "closing speed is shared between the bodies, which a change of frame alters: with "
      "elasticities 2 and 1, energy can be gained, or more lost than at elasticity 1.",
      {}});
}

Outcome claim_maximal_loss(const Context& c) {
  // Among all impulses, the energy change F^2 A / 2 - F u is least at F = u / A, (1.2)'s impulse,
  // where the velocities are equal: a parabola opening upwards (A > 0).
  const auto& s = line_symbols();
  const ex change = sym::simplify(energy_change(s, s.F));
  const ex stationary = GiNaC::lsolve(GiNaC::diff(change, s.F) == 0, s.F);
  const bool at_1_2 = sym::simplify(velocity_gap(s, stationary)).is_zero();
  const bool minimum = sym::definitely_positive(sym::simplify(GiNaC::diff(change, s.F, 2)), {});
  // Search: no impulse leaves less energy than (1.2)'s.
  num::Random r(c.seed);
  std::size_t lower = 0;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r, true);
    const double F12 = x.approach() / (1 / x.m1 + 1 / x.m2);
    const double F = F12 * (1 + (i % 2 == 0 ? r.uniform(-2, 2) : r.uniform(-1e-6, 1e-6)));
    // Each energy is two rounded squares summed: a few ulp of error; 16 ulp separates rounding
    // from a real counterexample, which would be lower by a share of the relative motion's energy.
    constexpr double rounding = 16 * std::numeric_limits<double>::epsilon();
    lower += x.energy_after(F) < x.energy_after(F12) * (1 - rounding) ? 1U : 0U;
  }
  // Over elasticities: GSL's Brent minimiser of the energy after finds elasticity 1. It runs in
  // the centre-of-mass frame, where the energy of the centre of mass (which no impulse changes,
  // and which would make the minimum too flat to locate in floating point) is zero; with one
  // elasticity for both bodies the impulse depends only on the closing speed, not on the frame.
  num::Errors errors;
  for (int i = 0; i < 50; ++i) {
    const LineSample y = sample_line(r, true);
    const double centre = (y.p1 - y.p2) / (y.m1 + y.m2);  // velocity of the centre along the axis
    const LineSample x{y.m1, y.m2, y.p1 - y.m1 * centre, y.p2 + y.m2 * centre};
    const double found = num::minimise(
        [&](double e) { return x.energy_after(e * x.approach() / (1 / x.m1 + 1 / x.m2)); }, 0.0,
        2.0, r.uniform(0.2, 1.8));
    errors.add(found, 1.0);
  }
  return judge(ClaimVerdict{
      {symbolic(at_1_2 && minimum,
                "the stationary impulse equalises the velocities and is "
                "a minimum"),
       search(c.samples, lower, "impulses around (1.2)'s"),
       numeric(Method::search, errors, 1e-6, "GSL's Brent minimiser over the elasticity finds 1")},
      std::nullopt,
      {},
      {}});
}

Outcome claim_dimensions(const Context& c) {
  // Scale the units: mass by M, length by X, time by T. Masses scale by M and momenta by
  // M X / T; A = 1/m1 + 1/m2 must scale by 1/M and B by X / T (a velocity).
  const auto& s = line_symbols();
  const GiNaC::possymbol M("M"), X("X"), T("T");
  const GiNaC::exmap scale{
      {s.m1, M * s.m1}, {s.m2, M * s.m2}, {s.p1, M * X / T * s.p1}, {s.p2, M * X / T * s.p2}};
  const ex A = 1 / s.m1 + 1 / s.m2;
  const ex B = s.e1 * s.p1 / s.m1 + s.e2 * s.p2 / s.m2;
  const bool exact = sym::simplify(A.subs(scale) - A / M).is_zero() &&
                     sym::simplify(B.subs(scale) - B * X / T).is_zero();
  const auto a = sym::compile(A, {s.m1, s.m2});
  const auto b = sym::compile(B, {s.m1, s.m2, s.p1, s.p2, s.e1, s.e2});
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    const double e1 = r.uniform(0, 2), e2 = r.uniform(0, 2);
    const double Ms = r.log_uniform(1e-3, 1e3), Xs = r.log_uniform(1e-3, 1e3),
                 Ts = r.log_uniform(1e-3, 1e3);
    errors.add(a({Ms * x.m1, Ms * x.m2}), a({x.m1, x.m2}) / Ms);
    errors.add(b({Ms * x.m1, Ms * x.m2, Ms * Xs / Ts * x.p1, Ms * Xs / Ts * x.p2, e1, e2}),
               b({x.m1, x.m2, x.p1, x.p2, e1, e2}) * Xs / Ts,
               (std::abs(e1 * x.p1 / x.m1) + std::abs(e2 * x.p2 / x.m2)) * Xs / Ts);
  }
  return judge(ClaimVerdict{{symbolic(exact), numeric(Method::numeric, errors)},
                            std::nullopt,
                            {},
                            "Checked by changing the units of mass, length and time."});
}

}  // namespace

sym::Equation printed_1_1() {
  const auto& s = line_symbols();
  return {s.F * (1 / s.m1 + 1 / s.m2), 2 * s.p1 / s.m1 + 2 * s.p2 / s.m2};
}

std::vector<Finding> elastic_line_findings(const sym::Equation& candidate, const Context& c) {
  const auto& s = line_symbols();
  std::vector<Finding> findings;
  ex F;
  try {
    F = sym::solve_for(candidate, s.F);
  } catch (const std::exception&) {
    return {symbolic(false, "not an equation linear in Fdt")};
  }
  findings.push_back(symbolic(sym::simplify(energy_change(s, F)).is_zero(),
                              "substituted into the energy balance"));
  const auto candidate_F = sym::compile(F, line_arguments(s));
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const LineSample x = sample_line(r);
    errors.add(x.energy_after(candidate_F({x.m1, x.m2, x.p1, x.p2})), x.energy());
  }
  findings.push_back(numeric(Method::numeric, errors, num::holds_below,
                             "kinetic energy after against before on random bodies"));
  return findings;
}

std::vector<Check> section1_checks() {
  std::vector<Check> c;
  c.push_back(make_check(
      "s1-momentum-update", "1", std::nullopt, Kind::step,
      R"(\begin{cases} \vec{p_1'} = \vec{p_1} - \vec{F} dt \\ \vec{p_2'} = \vec{p_2} + \vec{F} dt \end{cases})",
      momentum_update));
  c.push_back(make_check("claim-1-momentum", "1", std::nullopt, Kind::claim,
                         R"(\vec{p_1'} + \vec{p_2'} = \vec{p_1} + \vec{p_2} \quad \forall\, F\,dt)",
                         momentum_preserved));
  c.push_back(
      make_check("claim-1-inelastic-loss", "1", std::nullopt, Kind::claim,
                 R"(\arg\min_{F\,dt} (E_k' - E_k) \text{ is the } F\,dt \text{ with } v_1' = v_2')",
                 claim_maximal_loss));
  c.push_back(make_check(
      "s1.1-energy-momenta", "1.1", std::nullopt, Kind::step,
      R"(\frac{{p_1'}^2}{2m_1} + \frac{{p_2'}^2}{2m_2} = \frac{p_1^2}{2m_1} + \frac{(-p_2)^2}{2m_2})",
      elastic_line_2));
  c.push_back(make_check(
      "s1.1-energy-impulse", "1.1", std::nullopt, Kind::step,
      R"(\frac{(p_1 - F dt)^2}{2m_1} + \frac{(-p_2 + F dt)^2}{2m_2} = \frac{p_1^2}{2m_1} + \frac{p_2^2}{2m_2})",
      elastic_line_3));
  c.push_back(make_check(
      "eq-1.1", "1.1", "(1.1)", Kind::equation,
      R"(Fdt\left(\frac{1}{m_1} + \frac{1}{m_2}\right) = \frac{2p_1}{m_1} + \frac{2p_2}{m_2})",
      equation_1_1));
  c.push_back(make_check("s1.2-velocities", "1.2", std::nullopt, Kind::step,
                         R"(\frac{p_1 - F dt}{m_1} = \frac{-p_2 + F dt}{m_2})",
                         inelastic_line_step));
  c.push_back(make_check(
      "eq-1.2", "1.2", "(1.2)", Kind::equation,
      R"(Fdt\left(\frac{1}{m_1} + \frac{1}{m_2}\right) = \frac{p_1}{m_1} + \frac{p_2}{m_2})",
      equation_1_2));
  c.push_back(make_check(
      "eq-1.3", "1.3", "(1.3)", Kind::equation,
      R"(Fdt\left(\frac{1}{m_1} + \frac{1}{m_2}\right) = \frac{elasticity_1 \ p_1}{m_1} + \frac{elasticity_2 \ p_2}{m_2})",
      equation_1_3));
  c.push_back(make_check(
      "s1.3-generic-form", "1.3", std::nullopt, Kind::step,
      R"(Fdt (a_1 + a_2) = b_1 + b_2, \quad A F dt = B, \quad F dt = \frac{B}{A})", generic_form));
  c.push_back(make_check(
      "claim-1.3-edges", "1.3", std::nullopt, Kind::claim,
      R"(elasticity = 2 \Rightarrow E_k' = E_k, \qquad elasticity = 1 \Rightarrow v_1' = v_2')",
      claim_edges));
  c.push_back(make_check(
      "claim-1.3-intermediate", "1.3", std::nullopt, Kind::claim,
      R"(elasticity \in (1,2) \Rightarrow 0 < E_k - E_k' < (E_k - E_k')\big|_{elasticity=1})",
      claim_intermediate));
  c.push_back(make_check("claim-1.3-gain", "1.3", std::nullopt, Kind::claim,
                         R"(elasticity \in (2,\infty) \Rightarrow E_k' > E_k)", claim_gain));
  c.push_back(make_check(
      "claim-1.3-tunnel", "1.3", std::nullopt, Kind::claim,
      R"(elasticity \in (0,1) \Rightarrow \text{the bodies still approach after } F\,dt)",
      claim_tunnel));
  c.push_back(make_check("claim-1.3-zero", "1.3", std::nullopt, Kind::claim,
                         R"(elasticity = 0 \Rightarrow F\,dt = 0)", claim_zero));
  c.push_back(make_check(
      "claim-1.3-negative", "1.3", std::nullopt, Kind::claim,
      R"(elasticity < 0 \Rightarrow \operatorname{sign} F\,dt = -\operatorname{sign} F\,dt\big|_{elasticity>0})",
      claim_negative));
  c.push_back(make_check(
      "claim-1.3-mixed", "1.3", std::nullopt, Kind::claim,
      R"(elasticity_1 \neq elasticity_2 \Rightarrow 0 \le E_k - E_k' \le (E_k - E_k')\big|_{elasticity=1})",
      claim_mixed));
  c.push_back(make_check("claim-1.3-dimensions", "1.3", std::nullopt, Kind::claim,
                         R"([A] = [1/m_{ass}], \qquad [B] = [velocity])", claim_dimensions));
  return c;
}

}  // namespace impulse::derivations
