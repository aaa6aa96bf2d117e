// SPDX-License-Identifier: GPL-3.0-or-later
// Pulses of force on a body (section 4) and on a turning body (section 5): forces that rise and
// fall over the contact in a given shape, the body's motion integrated in time (GSL
// rk8pd), and what it gives: the path, the momentum, the angle, the work. Nothing here is one of
// the paper's formulas: the velocity comes from integrating the force, the path from integrating
// the velocity, the work from integrating force times the point's speed along the normal.
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "models/catalogue.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

using Eigen::Vector2d;

// The shapes a contact force takes over its duration, on [0, 1], each of mean 1: a constant force,
// a half-sine, a triangle and a pulse that peaks early, in that order.
const std::vector<file::PulseShape>& pulse_shapes() {
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

// 25 points of each shape, in turn.
std::size_t count_of(const Settings& s) {
  return std::max<std::size_t>(8, s.share(100));
}

// The states at the increasing times among t (inside the contact), dt / 2 (the triangle's kink)
// and dt: the state at t and the one at dt.
std::pair<std::vector<double>, std::vector<double>> at_instant_and_end(const num::OdeRhs& rhs,
                                                                       std::vector<double> y0,
                                                                       double t, double dt) {
  const std::vector<double> times =
      t < dt / 2 ? std::vector<double>{t, dt / 2, dt} : std::vector<double>{dt / 2, t, dt};
  const auto states = num::integrate_to(rhs, std::move(y0), times, dt / 64);
  return {states[t < dt / 2 ? 0 : 1], states.back()};
}

}  // namespace

std::vector<Point> pulses_on_a_body(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  const std::size_t count = count_of(s);
  for (std::size_t n = 0; n < count; ++n) {
    const file::PulseShape& shape = pulse_shapes()[n % pulse_shapes().size()];
    // A point mass m of momentum p; mean forces F_1, F_2, F_3 over the contact's duration dt,
    // each shaped by the pulse; the contact v with the body's outward normal n_v. The motion
    // along n_v is followed: y = [s, q], s' = q / m (the path), q' = the forces along n_v (the
    // momentum).
    const double m = r.mass();
    const Vector2d p = m * r.vector(10);
    const double dt = r.log_uniform(0.1, 1.0);
    const Vector2d nv = r.unit_vector();
    Point point;
    double along = 0.0;  // the mean forces' sum along n_v
    for (std::size_t k = 1; k <= 3; ++k) {
      const Vector2d F = r.vector(10) * m / dt;
      along += F.dot(nv);
      point.set("\\vec{F_" + std::to_string(k) + "}", F);
    }
    const num::OdeRhs rhs = [&](double t, const double* y, double* dy) {
      dy[0] = y[1] / m;
      dy[1] = along * shape.f(t / dt);
    };
    const double before = p.dot(nv);
    const double t = r.uniform(0.05, 0.95) * dt;  // an instant of the contact
    const auto [now, end] = at_instant_and_end(rhs, {0.0, before}, t, dt);
    std::array<double, 2> rate{};
    rhs(t, now.data(), rate.data());
    point.set("m", m).set("\\vec{p}", p).set("dt", dt).set("\\vec{n_v}", nv);
    // At the instant t: the path along n_v so far, and the rates of the path, the momentum and
    // the velocity along n_v (their differentials per dt); v_v the velocity along n_v before.
    point.set("t", t).set("S_v", now[0]).set("\\mathrm{d}S_v", rate[0]);
    point.set("\\mathrm{d}p_v", rate[1]).set("\\mathrm{d}v_v", rate[1] / m);
    point.set("v_v", before / m);
    // Over the whole contact: the change of the kinetic energy of the motion along n_v.
    point.set("\\Delta E_{vt}", (end[1] * end[1] - before * before) / (2 * m));
    point.pulse = &shape;
    points.push_back(std::move(point));
  }
  return points;
}

std::vector<Point> pulses_on_a_turning_body(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  const std::size_t count = count_of(s);
  for (std::size_t n = 0; n < count; ++n) {
    const file::PulseShape& shape = pulse_shapes()[n % pulse_shapes().size()];
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
    // y = [w, W, a]: w' = torque(t) / I; W' = the pair's force along n_v times the point's speed
    // along n_v from the turning, (F . n_v) f det(r_v, n_v) w; a' = w, the angle turned.
    const double lever = rv.x() * nv.y() - rv.y() * nv.x();
    const num::OdeRhs rhs = [&](double t, const double* y, double* dy) {
      const double f = shape.f(t / dt);
      dy[0] = torque * f / I;
      dy[1] = pair.dot(nv) * f * lever * y[0];
      dy[2] = y[0];
    };
    const double t = r.uniform(0.05, 0.95) * dt;  // an instant of the contact
    const auto [now, end] = at_instant_and_end(rhs, {L / I, 0.0, 0.0}, t, dt);
    std::array<double, 3> rate{};
    rhs(t, now.data(), rate.data());
    p.set("I", I).set("L", L).set("dt", dt).set("\\vec{r_v}", rv).set("\\vec{n_v}", nv);
    // Over the whole contact: the work on the turning.
    p.set("\\Delta E_{vr}", end[1]);
    // At the instant t: the angle turned so far, and the rates of the angle, the rate of turning
    // and the angular momentum (their differentials per dt); omega the rate of turning before.
    p.set("t", t).set("\\alpha", now[2]).set("\\omega", L / I);
    p.set("\\mathrm{d}\\alpha", rate[2]).set("\\mathrm{d}\\omega", rate[0]);
    p.set("\\mathrm{d}L", I * rate[0]);
    p.pulse = &shape;
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Model> pulses_models() {
  return {
      {Method::quadrature, "pulses of force on a body",
       "A point mass m of momentum p receiving three mean forces F_1, F_2, F_3 over a contact "
       "of duration dt, all shaped by one pulse (constant, half-sine, triangular, or peaking "
       "early, in turn); its motion along the normal n_v integrated in time (GSL rk8pd). At an "
       "instant t of the contact: the path S_v along n_v so far, and the rates of the path, of "
       "the momentum and of the velocity along n_v (d S_v, d p_v, d v_v per dt); over the "
       "whole contact, Delta E_vt the change of the kinetic energy of the motion along n_v; "
       "v_v the velocity along n_v before.",
       pulses_on_a_body, 1e-9, 1e-6, true},
      {Method::quadrature, "pulses of force on a turning body",
       "Three mean forces F_1, F_2, F_3 at arms r_1, r_2, r_3 of a body of inertia I and "
       "angular momentum L, over a contact of duration dt, all shaped by one pulse (constant, "
       "half-sine, triangular, or peaking early, in turn); the body's turning integrated in "
       "time (GSL rk8pd) from the torque, and Delta E_vr the work of the first force along n_v "
       "on the rotational motion of the point at arm r_v, integrated with it; at an instant t "
       "of the contact, the angle alpha turned so far and the rates of the angle, of the rate "
       "of turning and of the angular momentum (d alpha, d omega, d L per dt); omega the rate "
       "of turning before.",
       pulses_on_a_turning_body, 1e-9, 1e-6, true},
  };
}

}  // namespace impulse::derivations::models
