// SPDX-License-Identifier: GPL-3.0-or-later
// Section 3: rigid bodies in the plane, one contact point.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "impulse/core/error.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "support/random_bodies.hpp"
#include "support/sampling.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::rigid_2d::RigidBody;
namespace r2 = impulse::rigid_2d;

namespace {

// The physics from the definitions, independently of the library's helpers.
double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
double energy(const RigidBody& b) {
  return b.p.squaredNorm() / (2 * b.mass) + b.L * b.L / (2 * b.inertia);
}
// Velocity of the material point at `x`: v + omega x r, with omega x r = omega [-r_y, r_x].
Vector2d velocity_at(const RigidBody& b, const Vector2d& x) {
  const Vector2d r = x - b.position;
  return b.p / b.mass + b.L / b.inertia * Vector2d(-r.y(), r.x());
}
double angular_momentum(const RigidBody& b) {
  return b.L + cross(b.position, b.p);
}

struct Hit {
  RigidBody bumper, wedge;
  Vector2d point, n;
};

Hit random_hit(impulse::test::Sampler& sample) {
  return {impulse::test::random_rigid_body(sample), impulse::test::random_rigid_body(sample),
          sample.vector(5), sample.unit_vector()};
}

double speed_scale(const Hit& h) {
  return std::max(velocity_at(h.bumper, h.point).norm(), velocity_at(h.wedge, h.point).norm());
}

}  // namespace

TEST_CASE("A rod hitting the ground at one end", "[section3]") {
  // Uniform rod, length 2, mass 1, I = m l^2 / 12 = 1/3, lying horizontal and falling at 2;
  // its left end (arm r = (-1, 0)) touches the ground; the rod's outward normal there is (0, -1).
  // det(r, n) = (-1)(-1) - 0 = 1, so A = 1^2 / (1/3) + 1/1 = 4 and B = e * 2 (no spin).
  // Elastic: Fdt = 4 / 4 = 1. After: p = (0, -2) + (0, 1) = (0, -1);
  // L = det(r, -n Fdt) = det((-1, 0), (0, 1)) = -1, so omega = -3 and the end moves at
  // (0, -1) + (-3) [-r_y, r_x] = (0, -1) + (-3)(0, -1) = (0, 2): it bounces back at 2.
  RigidBody rod{1.0, 1.0 / 3.0, {0, 0}, {0, -2}, 0.0};
  const Vector2d end(-1, 0);
  const Vector2d n(0, -1);
  const auto s = impulse::solve(r2::contribution(rod, end, n, Elasticity::elastic()));
  CHECK(s.A == Approx(4.0).epsilon(1e-15));
  CHECK(s.B == 4.0);
  CHECK(s.Fdt == Approx(1.0).epsilon(1e-15));
  const RigidBody after = r2::apply_impulse(rod, end, n, s.Fdt);
  CHECK(after.p.isApprox(Vector2d(0, -1), 1e-15));
  CHECK(after.L == Approx(-1.0).epsilon(1e-15));
  CHECK(r2::point_velocity(after, end).isApprox(Vector2d(0, 2), 1e-15));
  // Energy: 1/2 * 2^2 = 2 before; 1/2 * 1 + 1/2 * 1 / (1/3) = 2 after.
  CHECK(r2::kinetic_energy(after) == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("A tilted rod: the uniform-rod closed form", "[section3]") {
  // For a uniform rod at angle theta, hit at its lower end while falling at v without spin,
  // the lever arm is (l/2) cos(theta), so A = (1 + 3 cos^2 theta) / m and Fdt = e m v / (1 + 3
  // cos^2).
  const double m = 2.5;
  const double l = 3.0;
  const double v = 1.7;
  for (double theta : {0.0, 0.3, 0.9, 1.4, std::numbers::pi / 2}) {
    CAPTURE(theta);
    RigidBody rod{m, m * l * l / 12, {0, 0}, {0, -m * v}, 0.0};
    const Vector2d end(-l / 2 * std::cos(theta), -l / 2 * std::sin(theta));
    const auto s = impulse::solve(r2::contribution(rod, end, {0, -1}, Elasticity(1.6)));
    const double c = std::cos(theta);
    CHECK(s.Fdt == Approx(1.6 * m * v / (1 + 3 * c * c)).epsilon(1e-14));
  }
}

TEST_CASE("Point velocity: spin about the origin plus translation", "[section3]") {
  // omega = L / I = 2 / 4 = 0.5; the point at arm (0, 2) moves at 0.5 * (-2, 0) + p/m = (-1, 0) +
  // (1, 1).
  RigidBody b{2.0, 4.0, {1, 1}, {2, 2}, 2.0};
  CHECK(r2::point_velocity(b, {1, 3}) == Vector2d(0, 1));
  CHECK(r2::angular_momentum_about_origin(b) == 2.0 + (1 * 2 - 1 * 2));
}

TEST_CASE("Elasticity 2 conserves energy", "[section3][property]") {
  impulse::test::Sampler sample("rigid_2d energy");
  impulse::test::Worst worst("section3 energy (e=2), relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto h = random_hit(sample);
    CAPTURE(i, h.bumper.mass, h.bumper.inertia, h.bumper.position, h.bumper.p, h.bumper.L,
            h.wedge.mass, h.wedge.inertia, h.wedge.position, h.wedge.p, h.wedge.L, h.point, h.n);
    const auto r =
        r2::collide(h.bumper, Elasticity::elastic(), h.wedge, Elasticity::elastic(), h.point, h.n);
    const double before = energy(h.bumper) + energy(h.wedge);
    const double error =
        impulse::test::relative_error(energy(r.bumper) + energy(r.wedge), before, before);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Elasticity 1 equalises the normal velocities of the contact points",
          "[section3][property]") {
  impulse::test::Sampler sample("rigid_2d equalise");
  impulse::test::Worst worst("section3 approach after (e=1) / velocity scale");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto h = random_hit(sample);
    CAPTURE(i, h.bumper.mass, h.bumper.inertia, h.bumper.position, h.bumper.p, h.bumper.L,
            h.wedge.mass, h.wedge.inertia, h.wedge.position, h.wedge.p, h.wedge.L, h.point, h.n);
    const auto r = r2::collide(h.bumper, Elasticity::inelastic(), h.wedge, Elasticity::inelastic(),
                               h.point, h.n);
    const double after = (velocity_at(r.bumper, h.point) - velocity_at(r.wedge, h.point)).dot(h.n);
    const double error = std::abs(after) / speed_scale(h);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Any elasticities conserve linear and angular momentum", "[section3][property]") {
  impulse::test::Sampler sample("rigid_2d momentum");
  impulse::test::Worst linear("section3 linear momentum, relative");
  impulse::test::Worst angular("section3 angular momentum about origin, relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto h = random_hit(sample);
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    CAPTURE(i, h.point, h.n, e1.value(), e2.value());
    const auto r = r2::collide(h.bumper, e1, h.wedge, e2, h.point, h.n);
    const double F = std::abs(r.solution.Fdt);
    const double p_scale = h.bumper.p.norm() + h.wedge.p.norm() + F;
    const double p_error = ((r.bumper.p + r.wedge.p) - (h.bumper.p + h.wedge.p)).norm() / p_scale;
    // Scale of angular momentum: the spins, the orbital terms and the impulse's moment.
    const double L_scale = std::abs(h.bumper.L) + std::abs(h.wedge.L) +
                           h.bumper.position.norm() * h.bumper.p.norm() +
                           h.wedge.position.norm() * h.wedge.p.norm() + h.point.norm() * F;
    const double L_error = std::abs((angular_momentum(r.bumper) + angular_momentum(r.wedge)) -
                                    (angular_momentum(h.bumper) + angular_momentum(h.wedge))) /
                           L_scale;
    linear.see(p_error);
    angular.see(L_error);
    REQUIRE(p_error <= 1e-12);
    REQUIRE(L_error <= 1e-12);
  }
}

TEST_CASE("An elasticity in (1, 2) loses energy as the restitution law says",
          "[section3][property]") {
  // With the effective inverse mass A = A1 + A2 of the contact, the loss is
  // (1 - c^2) * u^2 / (2 A), u the approach speed of the two material points.
  impulse::test::Sampler sample("rigid_2d intermediate");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto h = random_hit(sample);
    const Elasticity e(sample.uniform(1.01, 1.99));
    CAPTURE(i, h.point, h.n, e.value());
    const auto r = r2::collide(h.bumper, e, h.wedge, e, h.point, h.n);
    const double before = energy(h.bumper) + energy(h.wedge);
    const double loss = before - (energy(r.bumper) + energy(r.wedge));
    const auto arm = [&](const RigidBody& b, const Vector2d& n) {
      return cross(h.point - b.position, n);
    };
    const double A = 1 / h.bumper.mass + 1 / h.wedge.mass +
                     std::pow(arm(h.bumper, h.n), 2) / h.bumper.inertia +
                     std::pow(arm(h.wedge, h.n), 2) / h.wedge.inertia;
    const double u = (velocity_at(h.bumper, h.point) - velocity_at(h.wedge, h.point)).dot(h.n);
    const double c = e.restitution();
    REQUIRE(loss > 0.0);
    REQUIRE(loss == Approx((1 - c * c) * u * u / (2 * A)).margin(1e-11 * before));
  }
}

TEST_CASE("Elasticity 0 gives no impulse, and the residual is at round-off",
          "[section3][property]") {
  impulse::test::Sampler sample("rigid_2d zero");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto h = random_hit(sample);
    REQUIRE(
        r2::collide(h.bumper, Elasticity(0), h.wedge, Elasticity(0), h.point, h.n).solution.Fdt ==
        0.0);
    const auto r = r2::collide(h.bumper, Elasticity(sample.uniform(0, 3)), h.wedge,
                               Elasticity(sample.uniform(0, 3)), h.point, h.n);
    REQUIRE(r.solution.residual <=
            4 * std::numeric_limits<double>::epsilon() * std::abs(r.solution.B));
  }
}

TEST_CASE("Bad rigid bodies are refused with the value", "[section3][errors]") {
  const RigidBody ok{1, 1, {0, 0}, {0, 0}, 0};
  RigidBody no_inertia = ok;
  no_inertia.inertia = 0;
  RigidBody bad_position = ok;
  bad_position.position = {std::numeric_limits<double>::infinity(), 0};
  RigidBody bad_spin = ok;
  bad_spin.L = std::nan("");
  CHECK_THROWS_MATCHES(
      r2::collide(no_inertia, Elasticity(), ok, Elasticity(), {0, 0}, {1, 0}), InvalidInput,
      Catch::Matchers::Message("bumper.inertia must be positive and finite, got 0"));
  CHECK_THROWS_WITH(r2::collide(ok, Elasticity(), bad_position, Elasticity(), {0, 0}, {1, 0}),
                    "wedge.position must be finite, got [inf, 0]");
  CHECK_THROWS_WITH(r2::contribution(bad_spin, {0, 0}, {1, 0}, Elasticity()),
                    "body.L must be finite, got nan");
  CHECK_THROWS_WITH(r2::contribution(ok, {std::nan(""), 0}, {1, 0}, Elasticity()),
                    "point must be finite, got [nan, 0]");
  CHECK_THROWS_WITH(r2::contribution(ok, {0, 0}, {0, 2}, Elasticity()),
                    Catch::Matchers::Contains("normal must be a unit vector"));
}
