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
#include <array>
#include <cmath>
#include <numbers>

#include "impulse/multipoint/multipoint.hpp"
#include "numeric.hpp"
#include "pulses.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using GiNaC::ex;
using sym::Equation;

// A body's momentum along n_v, p_v, receiving the impulse J along n_v with pulse shape f over a
// collision lasting one time unit.
struct Push {
  double m, p, J;
  [[nodiscard]] double energy_change() const { return ((p + J) * (p + J) - p * p) / (2 * m); }
};

Push sample_push(num::Random& r) {
  const double m = r.mass();
  return {m, m * r.uniform(-10, 10), m * r.uniform(-10, 10)};
}

// ---- work integrals ---------------------------------------------------------------------------

Outcome equation_4_1(const Context& c) {
  // The work along n_v with dS = v_v dt equals the change of the kinetic energy of the motion
  // along n_v, for every pulse shape (the work-energy theorem).
  num::Random r(c.seed);
  num::Errors errors;
  const std::size_t runs = c.share(50);
  for (std::size_t i = 0; i < runs; ++i) {
    const Push x = sample_push(r);
    for (const Pulse& pulse : pulses()) {
      const double work =
          over_pulse([&](double t) { return x.J * pulse.f(t) * (x.p + x.J * pulse.g(t)) / x.m; },
                     (std::abs(x.p) * std::abs(x.J) + x.J * x.J) / x.m);
      errors.add(work, x.energy_change(), (std::abs(x.p) * std::abs(x.J) + x.J * x.J) / x.m);
    }
  }
  return judge(EquationVerdict{{numeric(Method::quadrature, errors, num::holds_below,
                                        "rectangular, half-sine, triangular and skewed pulses")},
                               {},
                               {},
                               {},
                               {}});
}

Outcome force_reading(const Context& c) {
  // F_v = (sum of impulses along n_v) / dt, read as the mean force over the collision time dt:
  // for every pulse shape the mean force is the impulse over the duration.
  num::Random r(c.seed);
  num::Errors errors;
  for (int i = 0; i < 20; ++i) {
    const Push x = sample_push(r);
    for (const Pulse& pulse : pulses()) {
      errors.add(over_pulse([&](double t) { return x.J * pulse.f(t); }, x.J), x.J);
    }
  }
  return judge(EquationVerdict{{numeric(Method::quadrature, errors)},
                               {},
                               {},
                               {},
                               "Read as the mean force over the collision time; it is the force "
                               "at every instant only for a constant force."});
}

Outcome path_step(const Context& c) {
  // Printed: S_v = v_v t. With the velocity changing during the contact, the displacement at the
  // end, S(1), is the integral of v, not v(1) * 1.
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (int i = 0; i < 50; ++i) {
    const Push x = sample_push(r);
    for (const Pulse& pulse : pulses()) {
      const double displacement =
          over_pulse([&](double t) { return (x.p + x.J * pulse.g(t)) / x.m; },
                     (std::abs(x.p) + std::abs(x.J)) / x.m);
      printed.add((x.p + x.J) / x.m * 1.0, displacement, (std::abs(x.p) + std::abs(x.J)) / x.m);
      // The correction S(t) = integral of v: against the motion integrated as an ODE.
      const auto end = num::integrate_until(
          [&](double t, const double* y, double* dy) {
            dy[0] = y[1];
            dy[1] = x.J * pulse.f(t) / x.m;
          },
          {0.0, x.p / x.m}, [](double t, const double*) { return 1.0 - t; }, 1.0 / 64, 2.0, 1e-12);
      corrected.add(end.y[0], displacement, (std::abs(x.p) + std::abs(x.J)) / x.m);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::quadrature, printed, num::holds_below, "v(1) against the integral of v")},
      {numeric(Method::ode, corrected, 1e-8, "the motion integrated as an ODE")},
      R"(S_v(t) = \int_0^t v_v\,\mathrm{d}t' = \int_0^t \frac{p_v(t')}{m}\,\mathrm{d}t')",
      "S_v = v_v t is the path of a uniform motion; during the collision the velocity changes, "
      "so the path is the integral of the velocity.",
      {}});
}

Outcome equation_4_2(const Context& c) {
  // Printed dS_v = dp_v t / m + p_v dt / m, with p_v the momentum before the collision (as the
  // integration that follows treats it) and dp_v = F_v dt. Its work integral against the energy
  // change, for each pulse shape; the correction dS_v = v_v(t) dt for the same pulses.
  num::Random r(c.seed);
  num::Errors printed, corrected, rectangle;
  const std::size_t runs = c.share(50);
  for (std::size_t i = 0; i < runs; ++i) {
    const Push x = sample_push(r);
    if (std::abs(x.J) < 1e-3 * (std::abs(x.p) + 1e-300))
      continue;
    const double scale = (std::abs(x.p) * std::abs(x.J) + x.J * x.J) / x.m;
    for (const Pulse& pulse : pulses()) {
      const auto F = [&](double t) { return x.J * pulse.f(t); };
      const double paper =
          over_pulse([&](double t) { return F(t) * (F(t) * t + x.p) / x.m; }, scale);
      const double correct =
          over_pulse([&](double t) { return F(t) * (x.p + x.J * pulse.g(t)) / x.m; }, scale);
      if (std::string(pulse.name) == "rectangle") {
        rectangle.add(paper, x.energy_change(), scale);
      } else {
        printed.add(paper, x.energy_change(), scale);
      }
      corrected.add(correct, x.energy_change(), scale);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::quadrature, printed, num::holds_below,
               "half-sine, triangular and skewed pulses (a constant force, the rectangle, gives "
               "a worst error of " +
                   num::brief(rectangle.worst, 2) + ")")},
      {numeric(Method::quadrature, corrected, num::holds_below, "all four pulses")},
      R"(\mathrm{d}S_v = v_v(t)\,\mathrm{d}t = \frac{p_v + \int_0^t F_v\,\mathrm{d}t'}{m}\,\mathrm{d}t)",
      "The product rule is applied to S_v = v_v t, which is not the path when the velocity "
      "changes; the printed integrand is right only for a constant force.",
      "p_v is read as the momentum before the collision, as the integration that follows does."});
}

Outcome integration_chain(const Context&) {
  // The chain of integrals, under the constant force F over [0, T] it assumes, ends in
  // (J^2 + 2 p_v J) / 2m with J = F T.
  const GiNaC::realsymbol t("t"), F("F"), p("p"), T("T");
  const GiNaC::possymbol m("m");
  const ex integrand = t * F * F / m + p * F / m;
  const ex integral = GiNaC::integral(t, 0, T, integrand).eval_integ();
  const ex J = F * T;
  const bool exact = sym::simplify(integral - (J * J + 2 * p * J) / (2 * m)).is_zero();
  return judge(EquationVerdict{{symbolic(exact, "integrated exactly for a constant force")},
                               {},
                               {},
                               {},
                               "The lines between the first and the last are a chain of equal "
                               "integrals; the last one is checked."});
}

Outcome energy_closed_form(const Context& c) {
  // dE_vt = ((sum F_i dt . n_v)^2 + 2 p_v sum F_i dt . n_v) / 2m against the work integral with
  // dS = v dt for each pulse shape: the result must not depend on the shape.
  num::Random r(c.seed);
  num::Errors errors;
  const std::size_t runs = c.share(50);
  const GiNaC::realsymbol J("J"), p("p");
  const GiNaC::possymbol m("m");
  const auto printed = sym::compile((J * J + 2 * p * J) / (2 * m), {J, p, m});
  for (std::size_t i = 0; i < runs; ++i) {
    const Push x = sample_push(r);
    for (const Pulse& pulse : pulses()) {
      const double work =
          over_pulse([&](double t) { return x.J * pulse.f(t) * (x.p + x.J * pulse.g(t)) / x.m; },
                     (std::abs(x.p) * std::abs(x.J) + x.J * x.J) / x.m);
      errors.add(printed({x.J, x.p, x.m}), work, (std::abs(x.p) * std::abs(x.J) + x.J * x.J) / x.m);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::quadrature, errors, num::holds_below, "the same for all four pulse shapes")},
      {},
      {},
      {},
      {}});
}

}  // namespace

std::vector<CodedCheck> section4_checks() {
  std::vector<CodedCheck> c;
  c.push_back(make_check("eq-4.1", "4.1", "(4.1)", Kind::equation,
                         R"(\Delta E_{vt} = \int_{\mathcal{A}} F_v \, \mathrm{d}S_v)",
                         equation_4_1));
  c.push_back(make_check(
      "s4.1-force", "4.1", std::nullopt, Kind::step,
      R"(F_v = \frac{\mathrm{d}p_v}{\mathrm{d}t} = \frac{\sum_i \vec{F_i} dt \cdot \vec{n_v}}{\mathrm{d}t})",
      force_reading));
  c.push_back(make_check("s4.1-path", "4.1", std::nullopt, Kind::step,
                         R"(S_v = v_v t = \frac{\vec{p} \cdot \vec{n_v} t}{m} = \frac{p_v t}{m})",
                         path_step));
  c.push_back(make_check("eq-4.2", "4.1", "(4.2)", Kind::equation,
                         R"(dS_v = dv_v t + v_v dt = \frac{dp_v t}{m} + \frac{p_v dt}{m})",
                         equation_4_2));
  c.push_back(make_check(
      "s4.1-integration", "4.1", std::nullopt, Kind::step,
      R"(\int_{0}^{\mathrm{d}t} \frac{t (\sum_{i} \vec{F}_{i} \cdot \vec{n_{v}})^{2}}{m} \, \mathrm{d}t + \int_{0}^{\mathrm{d}t} \frac{p_{v} \sum_{i} \vec{F}_{i} \cdot \vec{n_{v}}}{m} \, \mathrm{d}t = \frac{t^{2} (\sum_{i} \vec{F}_{i} \cdot \vec{n_{v}})^{2}}{2m} \Big|_{0}^{\mathrm{d}t} + \frac{p_{v} t \sum_{i} \vec{F}_{i} \cdot \vec{n_{v}}}{m} \Big|_{0}^{\mathrm{d}t})",
      integration_chain));
  c.push_back(make_check(
      "s4.1-energy", "4.1", std::nullopt, Kind::step,
      R"(\Delta E_{vt} = \frac{(\sum_{i} \vec{F_i} dt \cdot \vec{n_v})^2 + 2p_v \sum_{i} \vec{F_i} dt \cdot \vec{n_v}}{2m})",
      energy_closed_form));
  return c;
}

}  // namespace impulse::derivations
