// SPDX-License-Identifier: GPL-3.0-or-later
// The library as a reference (section 5): a rigid body of impulse::rigid_2d hit at several of its
// points, one impulse at a time by rigid_2d::apply_impulse, and a point's velocity before and
// after by rigid_2d::point_velocity. A second witness next to the bodies of point masses, as the
// C++ check of (5.4) had.
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "models/catalogue.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

std::vector<Point> library_rigid_body_hit_at_several_points(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    const double m = r.mass();
    const double gyration = r.log_uniform(0.1, 10);
    const double I = m * gyration * gyration;
    const Eigen::Vector2d p = m * r.vector(10);
    const double L = I * r.uniform(-10, 10) / gyration;
    const double dt = r.log_uniform(0.1, 1.0);
    const rigid_2d::RigidBody before{m, I, {0, 0}, p, L};
    rigid_2d::RigidBody body = before;
    Point point;
    for (std::size_t k = 1; k <= 3; ++k) {
      const Eigen::Vector2d arm = r.vector(2) * gyration;
      const Eigen::Vector2d n = r.unit_vector();
      const double F = r.uniform(-10, 10) * m;
      body = rigid_2d::apply_impulse(body, arm, n, F * dt);
      const std::string index = std::to_string(k);
      point.set("\\vec{r_" + index + "}", arm).set("\\vec{n_" + index + "}", n);
      point.set("F_" + index, F).set("\\vec{F_" + index + "}", -n * F);
    }
    const Eigen::Vector2d rv = r.vector(2) * gyration;
    point.set("m", m).set("I", I).set("\\vec{p}", p).set("L", L).set("dt", dt);
    point.set("\\vec{r_v}", rv);
    const Eigen::Vector2d v_before = rigid_2d::point_velocity(before, rv);
    const Eigen::Vector2d v_after = rigid_2d::point_velocity(body, rv);
    // Split as the paper does: the centre's velocity, and the rest (the turning).
    const Eigen::Vector2d centre_before = rigid_2d::velocity(before);
    const Eigen::Vector2d centre_after = rigid_2d::velocity(body);
    point.set("\\vec{v_{vt}}", centre_before).set("\\vec{v_{vr}}", v_before - centre_before);
    point.set("\\vec{v_{vt}'}", centre_after).set("\\vec{v_{vr}'}", v_after - centre_after);
    points.push_back(std::move(point));
  }
  return points;
}

std::vector<Model> library_models() {
  return {
      {Method::numeric, "the library's rigid body hit at several points",
       "A rigid body of impulse::rigid_2d (masses 1e-3 to 1e3, radii of gyration 0.1 to 10) "
       "receiving impulses -n_k F_k dt at three arms r_k, one at a time by "
       "rigid_2d::apply_impulse; the velocity of the point at arm r_v before and after by "
       "rigid_2d::point_velocity, split into the centre's (v_vt, v'_vt) and the rest (v_vr, "
       "v'_vr).",
       library_rigid_body_hit_at_several_points},
  };
}

}  // namespace impulse::derivations::models
