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
#include "pulses.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using GiNaC::ex;
using sym::Equation;

Outcome angle_step(const Context& c) {
  // alpha = w t = L t / I: the angle of a uniform turn. With the angular momentum changing by
  // dL over the collision (pulse g), the angle turned is the integral of w, not w(1) * 1.
  num::Random r(c.seed);
  num::Errors printed, corrected;
  for (int i = 0; i < 50; ++i) {
    const double I = r.mass(), L = I * r.uniform(-10, 10), dL = I * r.uniform(-10, 10);
    for (const Pulse& p : pulses()) {
      const double angle = over_pulse([&](double t) { return (L + dL * p.g(t)) / I; },
                                      (std::abs(L) + std::abs(dL)) / I);
      printed.add((L + dL) / I, angle, (std::abs(L) + std::abs(dL)) / I);
      const auto end = num::integrate_until(
          [&](double t, const double* y, double* dy) {
            dy[0] = y[1];
            dy[1] = dL * p.f(t) / I;
          },
          {0.0, L / I}, [](double t, const double*) { return 1.0 - t; }, 1.0 / 64, 2.0, 1e-12);
      corrected.add(end.y[0], angle, (std::abs(L) + std::abs(dL)) / I);
    }
  }
  return judge(EquationVerdict{
      {numeric(Method::quadrature, printed, num::holds_below, "w(1) against the integral of w")},
      {numeric(Method::ode, corrected, 1e-8, "the turn integrated as an ODE")},
      R"(\alpha(t) = \int_0^t \omega\,\mathrm{d}t' = \int_0^t \frac{L(t')}{I}\,\mathrm{d}t')",
      "alpha = w t is the angle of a uniform turn; while the impulses act, w changes, so the "
      "angle is its integral (the same slip as S_v = v_v t in section 4.1).",
      {}});
}

Outcome dalpha_step(const Context& c) {
  // d(alpha) = dL t / I + L dt / I with L the angular momentum before the collision; the
  // rotational work d_v F_v d(alpha) integrated for each pulse against the closed form.
  num::Random r(c.seed);
  num::Errors printed, corrected, rectangle;
  for (std::size_t i = 0; i < c.share(50); ++i) {
    const double I = r.mass(), L = I * r.uniform(-10, 10), dL = I * r.uniform(-10, 10);
    const double d = r.uniform(-2, 2), J = dL / (std::abs(d) > 1e-3 ? d : 1.0);
    // A single contact: the torque d J f(t) turns the body; the work is the energy change.
    const double change = ((L + dL) * (L + dL) - L * L) / (2 * I);
    const double scale = (std::abs(L * dL) + dL * dL) / I;
    for (std::size_t k = 0; k < pulses().size(); ++k) {
      const Pulse& p = pulses()[k];
      const auto torque = [&](double t) { return dL * p.f(t); };
      const double paper =
          over_pulse([&](double t) { return torque(t) * (torque(t) * t + L) / I; }, scale);
      const double correct =
          over_pulse([&](double t) { return torque(t) * (L + dL * p.g(t)) / I; }, scale);
      (k == 0 ? rectangle : printed).add(paper, change, scale);
      corrected.add(correct, change, scale);
    }
    (void)J;
  }
  return judge(EquationVerdict{
      {numeric(
          Method::quadrature, printed, num::holds_below,
          "half-sine, triangular and skewed pulses (a constant torque gives a worst error of " +
              num::brief(rectangle.worst, 2) + ")")},
      {numeric(Method::quadrature, corrected, num::holds_below, "all four pulses")},
      R"(\mathrm{d}\alpha = \omega(t)\,\mathrm{d}t = \frac{L + \int_0^t \tau\,\mathrm{d}t'}{I}\,\mathrm{d}t)",
      "The rotational twin of (4.2): the product rule on alpha = w t gives the right integrand "
      "only for a constant torque.",
      "L is read as the angular momentum before the collision, as the integration that follows "
      "does."});
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
  c.push_back(make_check("s5.1-angle", "5.1", std::nullopt, Kind::step,
                         R"(\alpha = \omega t = \frac{Lt}{I})", angle_step));
  c.push_back(make_check("s5.1-dalpha", "5.1", std::nullopt, Kind::step,
                         R"(d\alpha = d\omega t + \omega dt = \frac{dLt}{I} + \frac{Ldt}{I})",
                         dalpha_step));
  return c;
}

}  // namespace impulse::derivations
