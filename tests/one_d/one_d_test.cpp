// SPDX-License-Identifier: GPL-3.0-or-later
// Section 1: two material bodies on a line.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/error.hpp"
#include "impulse/one_d/one_d.hpp"
#include "support/sampling.hpp"

using impulse::Elasticity;
using impulse::InvalidInput;
namespace one_d = impulse::one_d;

namespace {

// The physics, computed from the raw fields so that the tests do not lean on the library's own
// helpers.
double energy(const one_d::Body& a, const one_d::Body& b) {
  return a.momentum * a.momentum / (2 * a.mass) + b.momentum * b.momentum / (2 * b.mass);
}
// Closing speed of `first` (outward direction `normal`) and `second` (outward -normal).
double approach(const one_d::Body& first, const one_d::Body& second, double normal) {
  return normal * (first.momentum / first.mass - second.momentum / second.mass);
}

struct Pair {
  one_d::Body first, second;
  double normal;
};

Pair random_pair(impulse::test::Sampler& sample) {
  const double m1 = sample.mass();
  const double m2 = sample.mass();
  return {{m1, m1 * sample.uniform(-10, 10)},
          {m2, m2 * sample.uniform(-10, 10)},
          sample.coin() ? 1.0 : -1.0};
}

}  // namespace

TEST_CASE("Equal masses exchange velocities in an elastic collision", "[section1]") {
  // m = 1 at 1.5 hits m = 1 at rest. (1.1): Fdt (1 + 1) = 2*1.5 + 2*0, so Fdt = 1.5; then
  // p1' = 1.5 - 1.5 = 0 and p2' = 0 + 1.5: the velocities are exchanged.
  const auto r = one_d::collide(one_d::from_velocity(1, 1.5), Elasticity::elastic(),
                                one_d::from_velocity(1, 0), Elasticity::elastic());
  CHECK(r.solution.Fdt == 1.5);
  CHECK(r.solution.A == 2.0);
  CHECK(r.solution.B == 3.0);
  CHECK(one_d::velocity(r.first) == 0.0);
  CHECK(one_d::velocity(r.second) == 1.5);
}

TEST_CASE("Unequal masses against the textbook formulas", "[section1]") {
  // m1 = 1 at 2 hits m2 = 3 at rest. Elastic, textbook: v1' = (m1 - m2)/(m1 + m2) v1 = -1,
  // v2' = 2 m1/(m1 + m2) v1 = 1, so Fdt = m1 (v1 - v1') = 3.
  // Inelastic: common velocity m1 v1/(m1 + m2) = 0.5, Fdt = 1 * (2 - 0.5) = 1.5.
  const auto a = one_d::from_velocity(1, 2);
  const auto b = one_d::from_velocity(3, 0);
  const auto elastic = one_d::collide(a, Elasticity::elastic(), b, Elasticity::elastic());
  CHECK(elastic.solution.Fdt == Approx(3.0).epsilon(1e-15));
  CHECK(one_d::velocity(elastic.first) == Approx(-1.0).epsilon(1e-15));
  CHECK(one_d::velocity(elastic.second) == Approx(1.0).epsilon(1e-15));
  const auto inelastic = one_d::collide(a, Elasticity::inelastic(), b, Elasticity::inelastic());
  CHECK(inelastic.solution.Fdt == Approx(1.5).epsilon(1e-15));
  CHECK(one_d::velocity(inelastic.first) == Approx(0.5).epsilon(1e-15));
  CHECK(one_d::velocity(inelastic.second) == Approx(0.5).epsilon(1e-15));
}

TEST_CASE("The mirror image: the first body on the right", "[section1]") {
  // Same collision seen in a mirror: positions and velocities change sign, the impulse does not.
  const auto r = one_d::collide(one_d::from_velocity(1, -2), Elasticity::elastic(),
                                one_d::from_velocity(3, 0), Elasticity::elastic(), -1.0);
  CHECK(r.solution.Fdt == Approx(3.0).epsilon(1e-15));
  CHECK(one_d::velocity(r.first) == Approx(1.0).epsilon(1e-15));
  CHECK(one_d::velocity(r.second) == Approx(-1.0).epsilon(1e-15));
}

TEST_CASE("A ball against a static wall", "[section1]") {
  // Ball m = 2 at v = 3 towards a wall on its right (outward +1). The wall contributes nothing:
  // A = 1/2, B = e * 3. Elastic: Fdt = 12, p' = 6 - 12 = -6, v' = -3 (reversed).
  // Inelastic: Fdt = 6, v' = 0 (stuck to the wall).
  const auto ball = one_d::from_velocity(2, 3);
  const auto elastic = impulse::solve(one_d::contribution(ball, 1.0, Elasticity::elastic()));
  CHECK(elastic.Fdt == 12.0);
  CHECK(one_d::velocity(one_d::apply_impulse(ball, 1.0, elastic.Fdt)) == -3.0);
  const auto inelastic = impulse::solve(one_d::contribution(ball, 1.0, Elasticity::inelastic()));
  CHECK(one_d::velocity(one_d::apply_impulse(ball, 1.0, inelastic.Fdt)) == 0.0);
}

TEST_CASE("Elasticity 2 conserves kinetic energy", "[section1][property]") {
  impulse::test::Sampler sample("one_d energy");
  impulse::test::Worst worst("section1 energy (e=2), relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    CAPTURE(i, first.mass, first.momentum, second.mass, second.momentum, normal);
    const auto r =
        one_d::collide(first, Elasticity::elastic(), second, Elasticity::elastic(), normal);
    const double before = energy(first, second);
    const double error = impulse::test::relative_error(energy(r.first, r.second), before, before);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Elasticity 1 equalises the velocities", "[section1][property]") {
  impulse::test::Sampler sample("one_d equalise");
  impulse::test::Worst worst("section1 approach after (e=1) / velocity scale");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    CAPTURE(i, first.mass, first.momentum, second.mass, second.momentum, normal);
    const auto r =
        one_d::collide(first, Elasticity::inelastic(), second, Elasticity::inelastic(), normal);
    const double scale =
        std::max(std::abs(first.momentum / first.mass), std::abs(second.momentum / second.mass));
    const double error = std::abs(approach(r.first, r.second, normal)) / scale;
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Any elasticities conserve momentum", "[section1][property]") {
  impulse::test::Sampler sample("one_d momentum");
  impulse::test::Worst worst("section1 momentum, relative");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    CAPTURE(i, first.mass, first.momentum, second.mass, second.momentum, normal, e1.value(),
            e2.value());
    const auto r = one_d::collide(first, e1, second, e2, normal);
    const double scale =
        std::abs(first.momentum) + std::abs(second.momentum) + std::abs(r.solution.Fdt);
    const double error = impulse::test::relative_error(r.first.momentum + r.second.momentum,
                                                       first.momentum + second.momentum, scale);
    worst.see(error);
    REQUIRE(error <= 1e-12);
  }
}

TEST_CASE("An elasticity in (1, 2) loses the restitution law's share of energy",
          "[section1][property]") {
  // Physical law: with restitution c = e - 1 the loss is (1 - c^2) * (1/2) mu u^2, mu the
  // reduced mass and u the approach speed; it is positive for c in (0, 1).
  impulse::test::Sampler sample("one_d intermediate");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    const Elasticity e(sample.uniform(1.01, 1.99));
    CAPTURE(i, first.mass, first.momentum, second.mass, second.momentum, normal, e.value());
    const auto r = one_d::collide(first, e, second, e, normal);
    const double before = energy(first, second);
    const double loss = before - energy(r.first, r.second);
    const double mu = first.mass * second.mass / (first.mass + second.mass);
    const double u = approach(first, second, normal);
    const double c = e.restitution();
    REQUIRE(loss > 0.0);
    REQUIRE(loss == Approx((1 - c * c) * 0.5 * mu * u * u).margin(1e-12 * before));
  }
}

TEST_CASE("Elasticity 0 gives no impulse", "[section1][property]") {
  impulse::test::Sampler sample("one_d zero");
  for (int i = 0; i < 100; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    const auto r = one_d::collide(first, Elasticity(0), second, Elasticity(0), normal);
    REQUIRE(r.solution.Fdt == 0.0);
    REQUIRE(r.first.momentum == first.momentum);
    REQUIRE(r.second.momentum == second.momentum);
  }
}

TEST_CASE("The residual of A Fdt = B is at round-off", "[section1][property]") {
  impulse::test::Sampler sample("one_d residual");
  for (int i = 0; i < impulse::test::configurations; ++i) {
    const auto [first, second, normal] = random_pair(sample);
    const auto r = one_d::collide(first, Elasticity(sample.uniform(0, 3)), second,
                                  Elasticity(sample.uniform(0, 3)), normal);
    REQUIRE(r.solution.residual <=
            4 * std::numeric_limits<double>::epsilon() * std::abs(r.solution.B));
  }
}

TEST_CASE("Bad bodies and directions are refused with the value", "[section1][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto ok = one_d::from_velocity(1, 1);
  CHECK_THROWS_MATCHES(one_d::from_velocity(-1, 0), InvalidInput,
                       Catch::Matchers::Message("mass must be positive and finite, got -1"));
  CHECK_THROWS_WITH(one_d::from_velocity(0, 0), "mass must be positive and finite, got 0");
  CHECK_THROWS_WITH(one_d::from_velocity(1, std::numeric_limits<double>::infinity()),
                    "velocity must be finite, got inf");
  CHECK_THROWS_WITH(one_d::collide({nan, 0}, Elasticity(), ok, Elasticity()),
                    "first.mass must be positive and finite, got nan");
  CHECK_THROWS_WITH(one_d::collide(ok, Elasticity(), {1, nan}, Elasticity()),
                    "second.momentum must be finite, got nan");
  CHECK_THROWS_WITH(one_d::collide(ok, Elasticity(), ok, Elasticity(), 0.5),
                    "normal must be +1 or -1, got 0.5");
  CHECK_THROWS_WITH(one_d::contribution(ok, 0.0, Elasticity()),
                    "outward direction must be +1 or -1, got 0");
}
