// SPDX-License-Identifier: GPL-3.0-or-later
// Section 2: point masses in the plane, cast onto the contact normal.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/error.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "support/sampling.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
namespace m2 = impulse::material_2d;

namespace {

double energy(const m2::PointMass& a, const m2::PointMass& b) {
  return a.p.squaredNorm() / (2 * a.mass) + b.p.squaredNorm() / (2 * b.mass);
}
// Closing speed along n (outward from the bumper): the bumper's velocity minus the wedge's.
double approach(const m2::PointMass& bumper, const m2::PointMass& wedge, const Vector2d& n) {
  return (bumper.p / bumper.mass - wedge.p / wedge.mass).dot(n);
}
Vector2d tangent(const Vector2d& n) {
  return {-n.y(), n.x()};
}

struct Pair {
  m2::PointMass bumper, wedge;
  Vector2d n;
};

Pair random_pair(impulse::test::Sampler& sample) {
  const double m1 = sample.mass();
  const double m2 = sample.mass();
  return {{m1, m1 * sample.vector(10)}, {m2, m2 * sample.vector(10)}, sample.unit_vector()};
}

}  // namespace

TEST_CASE("The cast is the dot product with the normalised direction", "[section2]") {
  // (3, 4) on the x axis is 3 whatever the direction's length; on -y it is -4.
  CHECK(m2::cast({3, 4}, {2, 0}) == 3.0);
  CHECK(m2::cast({3, 4}, {0, -5}) == -4.0);
  CHECK_THROWS_WITH(m2::cast({3, 4}, {0, 0}), "direction must be non-zero, got [0, 0]");
}

TEST_CASE("The vectorised impulse is minus the normal times Fdt", "[section2]") {
  CHECK(m2::impulse_vector({0.6, 0.8}, 2.0).isApprox(Vector2d(-1.2, -1.6), 1e-15));
}

TEST_CASE("An oblique hit of equal pucks exchanges the normal velocity only", "[section2]") {
  // Puck a (m = 1, v = (1, 1)) hits puck b (m = 1, at rest) with normal (1, 0) from a.
  // Along the normal this is section 1's exchange (Fdt = 1); the tangential 1 stays with a.
  const auto r = m2::collide(m2::from_velocity(1, {1, 1}), Elasticity::elastic(),
                             m2::from_velocity(1, {0, 0}), Elasticity::elastic(), {1, 0});
  CHECK(r.solution.Fdt == 1.0);
  CHECK(m2::velocity(r.bumper) == Vector2d(0, 1));
  CHECK(m2::velocity(r.wedge) == Vector2d(1, 0));
}

TEST_CASE("A ball against a static wall at an angle", "[section2]") {
  // Ball m = 1, v = (3, -4), hits the floor: its outward normal there points down, (0, -1).
  // Normal velocity 4; elastic: Fdt = 2 * 4 / 1 = 8, the impulse -n Fdt = (0, 8), v' = (3, 4).
  const auto ball = m2::from_velocity(1, {3, -4});
  const Vector2d n(0, -1);
  const auto s = impulse::solve(m2::contribution(ball, n, Elasticity::elastic()));
  CHECK(s.Fdt == 8.0);
  CHECK(m2::velocity(m2::apply_impulse(ball, n, s.Fdt)) == Vector2d(3, 4));
}

TEST_CASE("Elasticity 2 conserves energy, and the tangential velocities stay",
          "[section2][property]") {
  impulse::test::Sampler sample("material_2d energy");
  impulse::test::Worst worst("section2 energy (e=2), relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [bumper, wedge, n] = random_pair(sample);
    CAPTURE(i, bumper.mass, bumper.p, wedge.mass, wedge.p, n);
    const auto r = m2::collide(bumper, Elasticity::elastic(), wedge, Elasticity::elastic(), n);
    const double before = energy(bumper, wedge);
    const double error = impulse::test::relative_error(energy(r.bumper, r.wedge), before, before);
    worst.see(error);
    REQUIRE(error <= 1e-10);
    const double speed = bumper.p.norm() / bumper.mass + wedge.p.norm() / wedge.mass;
    REQUIRE(std::abs((r.bumper.p / r.bumper.mass - bumper.p / bumper.mass).dot(tangent(n))) <=
            1e-12 * speed);
    REQUIRE(std::abs((r.wedge.p / r.wedge.mass - wedge.p / wedge.mass).dot(tangent(n))) <=
            1e-12 * speed);
  }
}

TEST_CASE("Elasticity 1 equalises the normal velocities", "[section2][property]") {
  impulse::test::Sampler sample("material_2d equalise");
  impulse::test::Worst worst("section2 approach after (e=1) / velocity scale");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [bumper, wedge, n] = random_pair(sample);
    CAPTURE(i, bumper.mass, bumper.p, wedge.mass, wedge.p, n);
    const auto r = m2::collide(bumper, Elasticity::inelastic(), wedge, Elasticity::inelastic(), n);
    const double scale = std::max(bumper.p.norm() / bumper.mass, wedge.p.norm() / wedge.mass);
    const double error = std::abs(approach(r.bumper, r.wedge, n)) / scale;
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Any elasticities conserve momentum", "[section2][property]") {
  impulse::test::Sampler sample("material_2d momentum");
  impulse::test::Worst worst("section2 momentum, relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [bumper, wedge, n] = random_pair(sample);
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    CAPTURE(i, bumper.mass, bumper.p, wedge.mass, wedge.p, n, e1.value(), e2.value());
    const auto r = m2::collide(bumper, e1, wedge, e2, n);
    const double scale = bumper.p.norm() + wedge.p.norm() + std::abs(r.solution.Fdt);
    const double error = ((r.bumper.p + r.wedge.p) - (bumper.p + wedge.p)).norm() / scale;
    worst.see(error);
    REQUIRE(error <= 1e-12);
  }
}

TEST_CASE("An elasticity in (1, 2) loses the restitution law's share of energy",
          "[section2][property]") {
  // (1 - c^2) * (1/2) mu u^2 with u the approach speed along the normal, c = e - 1.
  impulse::test::Sampler sample("material_2d intermediate");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [bumper, wedge, n] = random_pair(sample);
    const Elasticity e(sample.uniform(1.01, 1.99));
    CAPTURE(i, bumper.mass, bumper.p, wedge.mass, wedge.p, n, e.value());
    const auto r = m2::collide(bumper, e, wedge, e, n);
    const double before = energy(bumper, wedge);
    const double loss = before - energy(r.bumper, r.wedge);
    const double mu = bumper.mass * wedge.mass / (bumper.mass + wedge.mass);
    const double u = approach(bumper, wedge, n);
    const double c = e.restitution();
    REQUIRE(loss > 0.0);
    REQUIRE(loss == Approx((1 - c * c) * 0.5 * mu * u * u).margin(1e-12 * before));
  }
}

TEST_CASE("Elasticity 0 gives no impulse, and the residual is at round-off",
          "[section2][property]") {
  impulse::test::Sampler sample("material_2d zero");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [bumper, wedge, n] = random_pair(sample);
    REQUIRE(m2::collide(bumper, Elasticity(0), wedge, Elasticity(0), n).solution.Fdt == 0.0);
    const auto r = m2::collide(bumper, Elasticity(sample.uniform(0, 3)), wedge,
                               Elasticity(sample.uniform(0, 3)), n);
    REQUIRE(r.solution.residual <=
            4 * std::numeric_limits<double>::epsilon() * std::abs(r.solution.B));
  }
}

TEST_CASE("Bad point masses and normals are refused with the value", "[section2][errors]") {
  const m2::PointMass ok{1, {1, 0}};
  CHECK_THROWS_MATCHES(m2::from_velocity(-2, {0, 0}), InvalidInput,
                       Catch::Matchers::Message("mass must be positive and finite, got -2"));
  CHECK_THROWS_WITH(m2::collide({std::numeric_limits<double>::infinity(), {0, 0}}, Elasticity(), ok,
                                Elasticity(), {1, 0}),
                    "bumper.mass must be positive and finite, got inf");
  CHECK_THROWS_WITH(m2::collide(ok, Elasticity(), {1, {std::nan(""), 0}}, Elasticity(), {1, 0}),
                    "wedge.p must be finite, got [nan, 0]");
  CHECK_THROWS_WITH(m2::collide(ok, Elasticity(), ok, Elasticity(), {0, 0}),
                    "normal must be a unit vector (length 1 within 1e-09), got [0, 0] of length 0");
  CHECK_THROWS_WITH(m2::collide(ok, Elasticity(), ok, Elasticity(), {1, 1}),
                    Catch::Matchers::Contains("of length 1.414213562373095"));
  CHECK_THROWS_WITH(m2::contribution(ok, {std::nan(""), 0}, Elasticity()),
                    "normal must be a finite unit vector, got [nan, 0]");
  // 1e-9 is the scene format's tolerance: just inside passes, just outside does not.
  CHECK_NOTHROW(m2::contribution(ok, {1 + 0.5e-9, 0}, Elasticity()));
  CHECK_THROWS_AS(m2::contribution(ok, {1 + 2e-9, 0}, Elasticity()), InvalidInput);
}
