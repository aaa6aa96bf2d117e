// SPDX-License-Identifier: GPL-3.0-or-later
// Pulses of force on a turning body (section 5): forces that rise and fall over the contact in a
// given shape, the body's rotation integrated in time (GSL rk8pd), and the work they do. Nothing
// here is one of the paper's formulas: the angular velocity comes from integrating the torque,
// the work from integrating force times the point's speed along the normal.
#include <cmath>
#include <numbers>

#include "models/catalogue.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

using Eigen::Vector2d;

// The shapes on [0, 1], each of mean 1: a constant force, a half-sine, a triangle, a pulse that
// peaks early.
const std::vector<file::PulseShape>& shapes() {
  static const std::vector<file::PulseShape> all{
      {"constant", [](double) { return 1.0; }, {}},
      {"half-sine",
       [](double u) { return std::numbers::pi / 2 * std::sin(std::numbers::pi * u); },
       {}},
      {"triangle", [](double u) { return u < 0.5 ? 4 * u : 4 * (1 - u); }, {0.5}},
      {"skewed", [](double u) { return 12 * u * (1 - u) * (1 - u); }, {}},
  };
  return all;
}

}  // namespace

std::vector<Point> pulses_on_a_turning_body(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  const std::size_t count = std::max<std::size_t>(8, s.share(100));  // 25 of each shape
  for (std::size_t n = 0; n < count; ++n) {
    const file::PulseShape& shape = shapes()[n % shapes().size()];
    // A body (its mass does not matter: only its turning is followed) with inertia I and
    // angular momentum L about its centre; mean forces F_k at arms r_k over the contact's
    // duration dt, each shaped by the pulse; the contact v at arm r_v with the outward normal
    // n_v, where the first force is the one exchanged with the other body.
    const double I = r.mass() * r.log_uniform(0.1, 10.0);
    const double L = I * r.uniform(-10, 10);
    const double dt = r.log_uniform(0.1, 1.0);
    Point p;
    double torque = 0.0;  // of the mean forces
    Vector2d pair = Vector2d::Zero();
    for (std::size_t k = 1; k <= 3; ++k) {
      const Vector2d arm = r.vector(2);
      const Vector2d F = r.vector(10) * I / dt;
      torque += arm.x() * F.y() - arm.y() * F.x();
      if (k == 1) {
        pair = F;
      }
      p.set("\\vec{r_" + std::to_string(k) + "}", arm).set("\\vec{F_" + std::to_string(k) + "}", F);
    }
    const Vector2d rv = r.vector(2);
    const Vector2d nv = r.unit_vector();
    // y = [w, W]: w' = torque(t) / I; W' = the pair's force along n_v times the point's speed
    // along n_v from the turning, (F . n_v) f det(r_v, n_v) w.
    const double lever = rv.x() * nv.y() - rv.y() * nv.x();
    const num::OdeRhs rhs = [&](double t, const double* y, double* dy) {
      const double f = shape.f(t / dt);
      dy[0] = torque * f / I;
      dy[1] = pair.dot(nv) * f * lever * y[0];
    };
    const auto end = num::integrate_to(rhs, {L / I, 0.0}, {dt}, dt / 64).back();
    p.set("I", I).set("L", L).set("dt", dt).set("\\vec{r_v}", rv).set("\\vec{n_v}", nv);
    p.set("\\Delta E_{vr}", end[1]);
    p.pulse = &shape;
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace impulse::derivations::models
