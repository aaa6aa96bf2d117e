// SPDX-License-Identifier: GPL-3.0-or-later
// Rigid bodies without the paper's formulas: a body made of point masses (energy and momenta
// summed point by point, its response to impulses by Gauss's principle, the velocity of a point
// by a complex-step derivative of its motion), and a rod falling on a tilted ground, held by a
// penalty spring or damper while its end is below the ground (GSL rk8pd).
#include <Eigen/Geometry>
#include <cmath>
#include <complex>

#include "models/catalogue.hpp"
#include "models/cloud.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

using Eigen::Vector2d;

double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The velocity of the point at arm r of a body moving at V and turning at w, as the derivative
// at t = 0 of its position V t + R(w t) r, by the complex step: exact to rounding, no
// difference of nearby values.
Vector2d point_velocity(const Vector2d& V, double w, const Vector2d& r) {
  using Complex = std::complex<double>;
  const double h = 1e-30;
  const Complex t(0.0, h);
  const Complex angle = w * t;
  const Complex x = V.x() * t + std::cos(angle) * r.x() - std::sin(angle) * r.y();
  const Complex y = V.y() * t + std::sin(angle) * r.x() + std::cos(angle) * r.y();
  return {x.imag() / h, y.imag() / h};
}

}  // namespace

std::vector<Point> point_cloud_rigid_body(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    const cloud::Cloud body = cloud::sample(r);
    const auto k = static_cast<std::size_t>(r.integer(0, static_cast<int>(body.m.size()) - 1));
    const Vector2d arm = body.r[k];
    const Vector2d n = r.unit_vector();
    const double F = r.uniform(-10, 10) * body.mass();
    const double dt = r.log_uniform(0.1, 1.0);
    const cloud::Cloud after = cloud::after(body, {{k, -n * F * dt}});
    Point p;
    p.set("m", body.mass()).set("I", body.inertia()).set("\\vec{p}", body.momentum());
    p.set("L", body.angular_momentum()).set("E_k", body.energy()).set("E_k'", after.energy());
    p.set("\\vec{r}", arm).set("\\vec{n}", n).set("F", F).set("dt", dt).set("\\vec{F}", -n * F);
    const Vector2d v_point = point_velocity(body.V, body.w, arm);
    p.set("\\vec{v_v}", v_point).set("\\vec{v_v'}", point_velocity(after.V, after.w, arm));
    p.set("\\omega", body.w).set("\\vec{v}", body.V);
    p.set("\\vec{v_r}", v_point - body.V).set("\\vec{v_t}", body.V);
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> point_cloud_hit_at_several_points(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    cloud::Cloud body = cloud::sample(r);
    while (body.m.size() < 4) {
      body = cloud::sample(r);
    }
    // Impulses -n_k F_k dt at three of its points; the point v is a fourth.
    std::vector<cloud::Kick> kicks;
    Point p;
    const double dt = r.log_uniform(0.1, 1.0);
    for (std::size_t k = 1; k <= 3; ++k) {
      const Vector2d n = r.unit_vector();
      const double F = r.uniform(-10, 10) * body.mass();
      kicks.push_back({k - 1, -n * F * dt});
      const std::string index = std::to_string(k);
      p.set("\\vec{r_" + index + "}", body.r[k - 1]).set("\\vec{n_" + index + "}", n);
      p.set("F_" + index, F).set("\\vec{F_" + index + "}", -n * F);
    }
    const cloud::Cloud after = cloud::after(body, kicks);
    p.set("m", body.mass()).set("I", body.inertia()).set("\\vec{p}", body.momentum());
    p.set("L", body.angular_momentum()).set("dt", dt);
    p.set("\\mathrm{d}L", after.angular_momentum() - body.angular_momentum());
    const Vector2d arm = body.r[3];
    const Vector2d v_after = after.velocity(3);
    p.set("\\vec{r_v}", arm);
    p.set("\\vec{v_{vt}'}", after.V).set("\\vec{v_{vr}'}", v_after - after.V);
    p.set("\\vec{v_{vt}}", body.V).set("\\vec{v_{vr}}", body.velocity(3) - body.V);
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> point_cloud_pinned(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    // Point masses turning at w about a pin O: energy, angular momentum and inertia about O
    // summed point by point, and the inertia about the centre of mass.
    const int count = r.integer(3, 6);
    std::vector<double> m;
    std::vector<Vector2d> x;
    Vector2d centre = Vector2d::Zero();
    double M = 0;
    for (int k = 0; k < count; ++k) {
      m.push_back(r.mass());
      x.push_back(r.vector(3));
      centre += m.back() * x.back();
      M += m.back();
    }
    centre /= M;
    const Vector2d O = r.vector(3);
    const double w = r.uniform(-10, 10);
    double E = 0, L = 0, I_O = 0, I = 0;
    for (int k = 0; k < count; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const Vector2d arm = x[kk] - O;
      const Vector2d v = w * Vector2d(-arm.y(), arm.x());
      E += 0.5 * m[kk] * v.squaredNorm();
      L += m[kk] * cross(arm, v);
      I_O += m[kk] * arm.squaredNorm();
      I += m[kk] * (x[kk] - centre).squaredNorm();
    }
    Point p;
    p.set("E", E).set("L_O", L).set("I_O", I_O).set("I", I).set("m", M).set("\\omega", w);
    p.set("d", (centre - O).norm());
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> turned_point(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    // A material point at arm r turned by a small angle: its displacement along n per unit of
    // angle, the complex-step derivative of R(α) r at α = 0.
    const Vector2d arm = r.vector(3), n = r.unit_vector();
    const Vector2d along = point_velocity(Vector2d::Zero(), 1.0, arm);
    const double angle = r.log_uniform(1e-3, 1.0);
    Point p;
    p.set("\\vec{r_v}", arm).set("\\vec{n_v}", n);
    p.set("\\mathrm{d}\\alpha", angle).set("\\mathrm{d}S_v", along.dot(n) * angle);
    points.push_back(std::move(p));
  }
  return points;
}

// ---- a rod on a tilted ground -----------------------------------------------------------------

namespace {

Point rod_on_ground(num::Random& r, bool spring) {
  // A uniform rod of mass m and length 2l (I = m l^2 / 3 about its centre, at the origin); its
  // lower end touches the ground at t = 0. The ground's normal g is tilted by up to 0.3 rad; the
  // rod falls onto it and turns.
  const double m = r.log_uniform(0.1, 10.0);
  const double l = r.uniform(0.5, 2.0);
  const double I = m * l * l / 3;
  const double theta = r.uniform(0.3, 1.2);
  const double tilt = r.uniform(-0.3, 0.3);
  const Vector2d g(std::sin(tilt), std::cos(tilt));
  const Vector2d tangent(g.y(), -g.x());
  const auto end_of = [&](double angle) {
    return Vector2d(-l * std::cos(angle), -l * std::sin(angle));
  };
  const Vector2d touch = end_of(theta);
  Vector2d v0 = -r.uniform(0.5, 3.0) * g + r.uniform(-1.0, 1.0) * tangent;
  double w0 = r.uniform(-1.0, 1.0);
  if ((v0 + w0 * Vector2d(-touch.y(), touch.x())).dot(g) > -0.2) {
    w0 = 0.0;  // the end must approach the ground
  }
  const double k = spring ? 1e14 * m : 0.0;
  const double c = spring ? 0.0 : 1e8 * m;
  // y = [x, y, turn, vx, vy, w]: the centre's displacement and the angle turned since t = 0.
  // The depth (about 1e-8) is the small displacement of the end, written without subtracting
  // numbers of size l: end_of(theta + d) - end_of(theta) by the sum-to-product identities. As a
  // difference of the end's coordinates its rounding (1e-16 of l) would be 1e-8 of the force,
  // noise the ODE solver's error control chases with tiny steps.
  const auto depth_of = [&](const double* y, double& sinking) {
    const Vector2d arm = end_of(theta + y[2]);
    const double half = std::sin(y[2] / 2);
    const Vector2d moved(2 * l * std::sin(theta + y[2] / 2) * half,
                         -2 * l * std::cos(theta + y[2] / 2) * half);
    const Vector2d velocity = Vector2d(y[3], y[4]) + y[5] * Vector2d(-arm.y(), arm.x());
    sinking = -velocity.dot(g);
    return -(Vector2d(y[0], y[1]) + moved).dot(g);
  };
  const auto push = [&](const double* y) {  // along g, on the rod
    double sinking = 0.0;
    const double depth = depth_of(y, sinking);
    return depth > 0 || !spring ? k * std::max(depth, 0.0) + c * sinking : 0.0;
  };
  const num::OdeRhs rhs = [&](double, const double* y, double* dy) {
    const Vector2d f = push(y) * g;
    const Vector2d arm = end_of(theta + y[2]);
    dy[0] = y[3];
    dy[1] = y[4];
    dy[2] = y[5];
    dy[3] = f.x() / m;
    dy[4] = f.y() / m;
    dy[5] = cross(arm, f) / I;
  };
  const std::vector<double> start{0, 0, 0, v0.x(), v0.y(), w0};
  const double scale = spring ? std::sqrt(1.0 / 1e14) : 1.0 / 1e8;
  const num::OdeEvent ended = [&](double t, const double* y) {
    if (t <= 0) {
      return 1.0;
    }
    double sinking = 0.0;
    const double depth = depth_of(y, sinking);
    return spring ? depth : sinking - 1e-12 * v0.norm();
  };
  const num::OdeResult end =
      num::integrate_until(rhs, start, ended, scale / 50, 1e4 * scale, 1e-13 * scale);
  const double duration = end.t;
  // The impulse: the force's integral along the motion (Gauss–Legendre on the sampled push).
  const double magnitude = num::gauss_legendre(
      [&](const std::vector<double>& times) {
        std::vector<double> f;
        for (const auto& y : num::integrate_to(rhs, start, times, scale / 50)) {
          f.push_back(push(y.data()));
        }
        return f;
      },
      0.0, duration, 16);
  const Vector2d p0 = m * v0;
  const Vector2d p1(m * end.y[3], m * end.y[4]);
  Point p;
  p.set("m", m).set("I", I).set("\\vec{p}", p0).set("L", I * w0);
  p.set("\\vec{r}", touch).set("\\vec{n}", -g);
  p.set("F", magnitude / duration).set("dt", duration).set("\\vec{F}", g * magnitude / duration);
  p.set("E_k", p0.squaredNorm() / (2 * m) + I * w0 * w0 / 2);
  p.set("E_k'", p1.squaredNorm() / (2 * m) + I * end.y[5] * end.y[5] / 2);
  p.set("E_o", 0.0).set("E_o'", 0.0);
  return p;
}

}  // namespace

std::vector<Point> rod_on_a_penalty_spring(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < std::max<std::size_t>(3, s.share(1000)); ++i) {
    points.push_back(rod_on_ground(r, true));
  }
  return points;
}

std::vector<Point> rod_on_a_penalty_damper(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < std::max<std::size_t>(3, s.share(1000)); ++i) {
    points.push_back(rod_on_ground(r, false));
  }
  return points;
}

std::vector<Model> rigid_models() {
  return {
      {Method::numeric, "point cloud rigid body",
       "A rigid body made of 3 to 6 point masses: its mass, inertia, momentum, angular "
       "momentum and kinetic energy summed point by point; an impulse -n F dt at one of its "
       "points (arm r), the body's response by Gauss's principle (the rigid motion nearest, in "
       "the mass metric, to the points' free response); the point's velocity before and after "
       "by a complex-step derivative of its motion, and its parts: v_t the centre's velocity, "
       "v_r the rest.",
       point_cloud_rigid_body},
      {Method::numeric, "point cloud rigid body hit at several points",
       "The body of point masses receiving impulses -n_k F_k dt at three of its points (arms "
       "r_1, r_2, r_3): its angular momentum's change dL summed point by point after Gauss's "
       "principle, and the velocity of a fourth point (arm r_v) before and after, split into "
       "the centre's v_vt, v'_vt and the rest v_vr, v'_vr.",
       point_cloud_hit_at_several_points},
      {Method::numeric, "point cloud pinned",
       "Point masses turning together about a pin O: the kinetic energy E, angular momentum "
       "L_O and inertia I_O about O summed point by point, the inertia I about the centre of "
       "mass, the mass m, the distance d from O to the centre and the rate of turning omega.",
       point_cloud_pinned},
      {Method::numeric, "turned point",
       "A material point at arm r_v turned by a small angle d alpha: its displacement along a "
       "unit normal n_v, d S_v, from the complex-step derivative of its rotation.",
       turned_point},
      {Method::ode, "rigid rod on a penalty spring",
       "A uniform rod falls, turning, onto a ground tilted by up to 0.3 rad; while its end is "
       "below the ground a stiff linear spring (1e14 times its mass) pushes it out along the "
       "ground's normal (GSL rk8pd). The impulse is the push's integral sampled along the "
       "motion; r is the end's arm when it touches, n the rod's outward normal there (minus "
       "the ground's); the ground does not move (E_o = E_o' = 0). The rod turns a little while "
       "it is pushed, so the instant impulse is matched to about 1e-7.",
       rod_on_a_penalty_spring, 1e-6, 1e-3},
      {Method::ode, "rigid rod on a penalty damper",
       "As the rod on a spring, held by a damper (1e8 times its mass) that stops its end: the "
       "contact ends when the end stops sinking.",
       rod_on_a_penalty_damper, 1e-6, 1e-3},
  };
}

}  // namespace impulse::derivations::models
