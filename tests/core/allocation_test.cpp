// SPDX-License-Identifier: GPL-3.0-or-later
// The single-contact path allocates nothing: a counting global operator new watches every
// allocation the program makes while the collisions of sections 1-3 are computed.
//
// This file is its own test program: replacing operator new changes it for the whole program.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>

#include "impulse/core/checked.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/one_d/one_d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "support/sampling.hpp"

namespace {
// Counted only while `counting` is set, so that Catch2's own allocations do not enter.
bool counting = false;
std::size_t allocations = 0;

void* allocate(std::size_t size) {
  if (counting) {
    ++allocations;
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}

// Counts the allocations made while `work` runs.
template <typename Work>
std::size_t allocations_during(Work&& work) {
  allocations = 0;
  counting = true;
  work();
  counting = false;
  return allocations;
}
}  // namespace

void* operator new(std::size_t size) {
  return allocate(size);
}
void* operator new[](std::size_t size) {
  return allocate(size);
}
// The nothrow forms too (Catch2 uses them): every form of new here must pair with the free()
// of the deletes below (AddressSanitizer checks the pairing).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

using Eigen::Vector2d;
using impulse::Elasticity;
namespace t = impulse::test;

TEST_CASE("The counter sees an allocation", "[allocation]") {
  // The check of the check: a string too long for the small-string buffer allocates once.
  const std::size_t seen = allocations_during([] {
    const std::string text(100, 'x');
    REQUIRE(text.size() == 100);
  });
  CHECK(seen == 1);
}

TEST_CASE("Single contacts of sections 1-3 allocate nothing",
          "[allocation][section1][section2]"
          "[section3]") {
  t::Sampler sample("no allocation");
  for (int i = 0; i < t::configurations; ++i) {
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    const double m1 = sample.mass();
    const double m2 = sample.mass();
    const Vector2d n = sample.unit_vector();
    const Vector2d point = sample.vector(2);
    const impulse::one_d::Body a{m1, sample.uniform(-10, 10)};
    const impulse::one_d::Body b{m2, sample.uniform(-10, 10)};
    const impulse::material_2d::PointMass pa{m1, sample.vector(10)};
    const impulse::material_2d::PointMass pb{m2, sample.vector(10)};
    const impulse::rigid_2d::RigidBody ra{m1, sample.mass(), sample.vector(1), sample.vector(10),
                                          sample.uniform(-10, 10)};
    const impulse::rigid_2d::RigidBody rb{m2, sample.mass(), sample.vector(1), sample.vector(10),
                                          sample.uniform(-10, 10)};
    double sink = 0.0;
    const std::size_t seen = allocations_during([&] {
      // The whole public paths: collide, and the pieces contribution + ⊕ + solve + apply.
      sink += impulse::one_d::collide(a, e1, b, e2, sample.coin() ? 1.0 : -1.0).solution.Fdt;
      sink += impulse::material_2d::collide(pa, e1, pb, e2, n).solution.Fdt;
      sink += impulse::rigid_2d::collide(ra, e1, rb, e2, point, n).solution.Fdt;
      const auto s = impulse::solve(impulse::rigid_2d::contribution(ra, point, n, e1) +
                                    impulse::rigid_2d::contribution(rb, point, -n, e2));
      sink += impulse::rigid_2d::apply_impulse(ra, point, n, s.Fdt).L;
      sink += impulse::material_2d::apply_impulse(pa, n, s.Fdt).p.x();
      sink += impulse::one_d::apply_impulse(a, 1.0, s.Fdt).momentum;
      // Bodies and a normal checked when made, and the collisions that take them.
      const impulse::Checked checked_a(a);
      const impulse::Checked checked_ra(ra);
      const impulse::Checked checked_rb(rb);
      const impulse::UnitNormal unit(n);
      sink += impulse::one_d::collide(checked_a, e1, impulse::Checked(b), e2).solution.Fdt;
      sink +=
          impulse::material_2d::collide(impulse::Checked(pa), e1, impulse::Checked(pb), e2, unit)
              .solution.Fdt;
      sink += impulse::rigid_2d::collide(checked_ra, e1, checked_rb, e2, point, unit).solution.Fdt;
    });
    CAPTURE(i, sink);
    REQUIRE(seen == 0);
  }
}

TEST_CASE("Bad input is still refused with the value and the same message",
          "[allocation][errors]") {
  // The same checks still throw; only the throwing path builds a string.
  const impulse::material_2d::PointMass ok{1, {1, 0}};
  CHECK_THROWS_WITH(impulse::material_2d::collide(ok, Elasticity(), ok, Elasticity(), {1, 1}),
                    Catch::Matchers::Contains("of length 1.414213562373095"));
  CHECK_THROWS_WITH(
      impulse::material_2d::collide({-1, {0, 0}}, Elasticity(), ok, Elasticity(), {1, 0}),
      "bumper.mass must be positive and finite, got -1");
}

TEST_CASE("Checked bodies: refused when made, with the message; then the same collision",
          "[allocation][errors][section1][section2][section3]") {
  using impulse::Checked;
  CHECK_THROWS_WITH(Checked(impulse::one_d::Body{0, 1}, "first"),
                    "first.mass must be positive and finite, got 0");
  CHECK_THROWS_WITH(Checked(impulse::material_2d::PointMass{1, {std::nan(""), 0}}, "wedge"),
                    "wedge.p must be finite, got [nan, 0]");
  CHECK_THROWS_WITH(Checked(impulse::rigid_2d::RigidBody{1, -2, {0, 0}, {0, 0}, 0}, "bumper"),
                    "bumper.inertia must be positive and finite, got -2");
  const impulse::rigid_2d::RigidBody rod{1, 1.0 / 3.0, {0, 0}, {0, -1}, 0};
  const impulse::rigid_2d::RigidBody ground_like{1e6, 1e6, {0, -1}, {0, 0}, 0};
  CHECK_THROWS_WITH(
      impulse::rigid_2d::collide(Checked(rod), Elasticity(), Checked(ground_like), Elasticity(),
                                 {std::nan(""), 0}, impulse::UnitNormal(Vector2d(0, -1))),
      "point must be finite, got [nan, 0]");
  CHECK_THROWS_WITH(impulse::one_d::collide(Checked(impulse::one_d::Body{1, 1}), Elasticity(),
                                            Checked(impulse::one_d::Body{1, 0}), Elasticity(), 0.5),
                    "normal must be +1 or -1, got 0.5");
  // The checked path is the same formula as the path that checks at each collision: the same
  // impulse and bodies to the last bit, on random configurations.
  t::Sampler sample("checked bodies");
  for (int i = 0; i < t::configurations; ++i) {
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    const Vector2d n = sample.unit_vector();
    const Vector2d point = sample.vector(2);
    const impulse::rigid_2d::RigidBody ra{sample.mass(), sample.mass(), sample.vector(1),
                                          sample.vector(10), sample.uniform(-10, 10)};
    const impulse::rigid_2d::RigidBody rb{sample.mass(), sample.mass(), sample.vector(1),
                                          sample.vector(10), sample.uniform(-10, 10)};
    const auto each_time = impulse::rigid_2d::collide(ra, e1, rb, e2, point, n);
    const auto once =
        impulse::rigid_2d::collide(Checked(ra), e1, Checked(rb), e2, point, impulse::UnitNormal(n));
    CAPTURE(i);
    REQUIRE(once.solution.Fdt == each_time.solution.Fdt);
    REQUIRE(once.bumper.p == each_time.bumper.p);
    REQUIRE(once.wedge.L == each_time.wedge.L);
  }
}

TEST_CASE("The unit-normal rule without a square root is |length - 1| <= 1e-9",
          "[allocation][errors]") {
  // Lengths just inside and just outside 1 +- 1e-9 (far from the rounding of either form),
  // zero and 1.5; the squared-length test and the length test must agree on each.
  for (const double length :
       {1.0, 1.0 + 0.999e-9, 1.0 - 0.999e-9, 1.0 + 1.001e-9, 1.0 - 1.001e-9, 0.0, 1.5}) {
    CAPTURE(length);
    const Vector2d n(length * 0.6, length * 0.8);
    const bool by_length = std::abs(n.norm() - 1.0) <= impulse::unit_normal_tolerance;
    CHECK(impulse::is_unit_normal(n) == by_length);
    if (by_length) {
      CHECK_NOTHROW(impulse::require_unit_normal("normal", n));
    } else {
      CHECK_THROWS_AS(impulse::require_unit_normal("normal", n), impulse::InvalidInput);
    }
  }
  CHECK_FALSE(impulse::is_unit_normal(Vector2d(std::nan(""), 1.0)));
  CHECK_FALSE(impulse::is_unit_normal(Vector2d(std::numeric_limits<double>::infinity(), 0.0)));
}

TEST_CASE("The one-branch finiteness test", "[allocation][errors]") {
  // x - x is 0 for finite x, NaN otherwise, and a sum of zeros cannot overflow.
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(impulse::all_finite(1.0, -2.0, 1e308, 1e308));  // would overflow as a plain sum
  CHECK_FALSE(impulse::all_finite(1.0, inf));
  CHECK_FALSE(impulse::all_finite(-inf, 1.0));
  CHECK_FALSE(impulse::all_finite(std::nan(""), 1.0));
}
