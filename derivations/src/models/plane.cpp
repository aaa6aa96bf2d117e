// SPDX-License-Identifier: GPL-3.0-or-later
// Point masses in the plane: a base turned to a direction (coordinates found by rotating, not by
// a dot product), and searches over momenta, normals and pairs of pucks.
//
// A unit normal n = (cos θ, sin θ) is also given as τ = tan(θ/2), for files that write it as
// ((1 - τ²) / (1 + τ²), 2τ / (1 + τ²)) to keep their algebra rational.
#include <Eigen/Geometry>
#include <cmath>

#include "models/catalogue.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

void set_normal(Point& p, const Eigen::Vector2d& n) {
  p.set("\\vec{n}", n).set("\\tau", std::tan(std::atan2(n.y(), n.x()) / 2));
}

// A direction drawn at random, away from θ = ±π (where τ = tan(θ/2) is unbounded).
Eigen::Vector2d random_normal(num::Random& r) {
  const double angle = r.uniform(-0.95, 0.95) * 3.141592653589793;
  return {std::cos(angle), std::sin(angle)};
}

// The coordinate of x along v: x expressed in the base turned by v's angle.
double coordinate_along(const Eigen::Vector2d& x, const Eigen::Vector2d& v) {
  const Eigen::Matrix2d to_base = Eigen::Rotation2Dd(-std::atan2(v.y(), v.x())).toRotationMatrix();
  return (to_base * x).x();
}

}  // namespace

std::vector<Point> base_turned_to_a_vector(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    const Eigen::Vector2d x = r.vector(10), v = r.vector(10), p = r.vector(10);
    const Eigen::Vector2d n = random_normal(r);
    Point point;
    point.set("\\vec{x}", x).set("\\vec{v}", v).set("\\mathrm{cast}_v", coordinate_along(x, v));
    point.set("\\vec{p}", p).set("p_n", coordinate_along(p, n));
    set_normal(point, n);
    points.push_back(std::move(point));
  }
  return points;
}

std::vector<Point> momenta_and_normals_in_the_plane(Probe&, const Settings& s) {
  std::vector<Point> points;
  // The case to check by hand first: moving along the y axis against the normal (1, 0).
  Point first;
  first.set("\\vec{p}", Eigen::Vector2d(0, 2));
  set_normal(first, Eigen::Vector2d(1, 0));
  points.push_back(std::move(first));
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.samples; ++i) {
    const Eigen::Vector2d n = random_normal(r);
    // Every fourth body slides along the contact's tangent.
    const Eigen::Vector2d p =
        i % 4 == 0 ? r.uniform(0.5, 2.0) * Eigen::Vector2d(-n.y(), n.x()) : r.vector(10);
    Point point;
    point.set("\\vec{p}", p);
    set_normal(point, n);
    points.push_back(std::move(point));
  }
  return points;
}

std::vector<Point> pucks(Probe&, const Settings& s) {
  std::vector<Point> points;
  const auto add = [&](double m1, const Eigen::Vector2d& p1, double m2, const Eigen::Vector2d& p2,
                       const Eigen::Vector2d& n, double e1, double e2) {
    Point point;
    point.set("m_1", m1).set("m_2", m2).set("\\vec{p_1}", p1).set("\\vec{p_2}", p2);
    set_normal(point, n);
    point.set("\\mathit{elasticity}_1", e1).set("\\mathit{elasticity}_2", e2).set("dt", 1.0);
    points.push_back(std::move(point));
  };
  // The case to check by hand first: the bumper (outward normal (1, 0)) drifts away at 1 and the
  // wedge catches up from behind at 3; both of mass 1.
  add(1, {-1, 0}, 1, {-3, 0}, {1, 0}, 2, 2);
  add(1, {-1, 0}, 1, {-3, 0}, {1, 0}, 1, 1);
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.share(2); ++i) {
    const double m1 = r.mass(), m2 = r.mass();
    const double e = i % 3 == 0 ? 2.0 : i % 3 == 1 ? 1.0 : r.uniform(0.0, 3.0);
    add(m1, m1 * r.vector(10), m2, m2 * r.vector(10), random_normal(r), e, e);
  }
  return points;
}

std::vector<Model> plane_models() {
  return {
      {Method::numeric, "a base turned to a vector",
       "Vectors of the plane and their coordinates in a base turned to a direction: the "
       "rotation of Eigen::Rotation2D by minus the direction's angle, not a dot product. The "
       "coordinate of x along v is cast_v, that of p along the unit normal n (also given as "
       "tau = tan(angle/2)) is p_n.",
       base_turned_to_a_vector},
      {Method::search, "momenta and normals in the plane",
       "A momentum and a unit normal (with tau = tan(angle/2)): first p = (0, 2) against n = "
       "(1, 0), then random ones, every fourth along the contact's tangent.",
       momenta_and_normals_in_the_plane},
      {Method::search, "pucks",
       "Two point masses in the plane (masses 1e-3 to 1e3, any momenta), the bumper's outward "
       "normal n (and tau), one elasticity for both (2, 1 or from 0 to 3); first the bumper at "
       "(-1, 0) caught up by the wedge at (-3, 0) against n = (1, 0).",
       pucks},
  };
}

}  // namespace impulse::derivations::models
