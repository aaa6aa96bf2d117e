// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes: named bodies and contacts, checked, solved and reported.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/one_d/one_d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "impulse/scene/scene.hpp"
#include "support/fp_traps.hpp"
#include "support/sampling.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::scene::Body;
using impulse::scene::BodyKind;
using impulse::scene::Contact;
using impulse::scene::Given;
using impulse::scene::Scene;
namespace sc = impulse::scene;
namespace t = impulse::test;

namespace {

Body material(const std::string& name, double mass, Vector2d velocity) {
  Body b;
  b.name = name;
  b.kind = BodyKind::material;
  b.mass = mass;
  b.linear = velocity;
  return b;
}

Body fixed(const std::string& name) {
  Body b;
  b.name = name;
  b.kind = BodyKind::static_body;
  return b;
}

Body rigid(const std::string& name, double mass, double inertia, Vector2d position,
           Vector2d velocity, double omega) {
  Body b = material(name, mass, velocity);
  b.kind = BodyKind::rigid;
  b.inertia = inertia;
  b.position = position;
  b.angular = omega;
  return b;
}

// The scene format's worked example: a (m 1, velocity [1.5, 0]) hits b (m 1, at rest), normal
// [1, 0] outward from a, elasticity 2.
Scene worked_example() {
  Scene s;
  s.dimension = 2;
  s.elasticity = 2.0;
  s.bodies = {material("a", 1, {1.5, 0}), material("b", 1, {0, 0})};
  s.contacts = {Contact{0, 1, {1, 0}, std::nullopt}};
  return s;
}

// A box 2 wide and 1 high (m 1, I = (2^2 + 1^2)/12 = 5/12) falling at (0, -1) onto the ground at
// its two lower corners; the ground is the bumper with normal (0, 1).
Scene box_on_ground(double e) {
  Scene s;
  s.elasticity = e;
  s.bodies = {fixed("ground"), rigid("box", 1, 5.0 / 12.0, {0, 0.5}, {0, -1}, 0)};
  s.contacts = {Contact{0, 1, {0, 1}, Vector2d(-1, 0)}, Contact{0, 1, {0, 1}, Vector2d(1, 0)}};
  return s;
}

}  // namespace

TEST_CASE("The scene format's worked example, by hand", "[scene]") {
  // (1.1) with m = 1, 1: Fdt (1 + 1) = 2 * 1.5 + 2 * 0, so A = 2, B = 3 and Fdt = 1.5. The bumper
  // receives -[1, 0] * 1.5 and stops; b leaves at 1.5. Energy 1.5^2 / 2 = 1.125 before and after.
  // Approach: a's normal velocity 1.5 + b's 0 before; 0 + (1.5 . -1) = -1.5 after.
  const auto r = sc::solve(worked_example());
  REQUIRE(r.status == impulse::SolveStatus::success);
  REQUIRE(r.impulses.size() == 1);
  CHECK(r.impulses[0].bumper == "a");
  CHECK(r.impulses[0].wedge == "b");
  CHECK(r.impulses[0].magnitude == Approx(1.5).epsilon(1e-14));
  CHECK((r.impulses[0].on_bumper - Vector2d(-1.5, 0)).norm() < 1e-14);
  CHECK(r.bodies[0].after.velocity.norm() < 1e-14);
  CHECK((r.bodies[1].after.velocity - Vector2d(1.5, 0)).norm() < 1e-14);
  CHECK((r.bodies[0].before.velocity - Vector2d(1.5, 0)).norm() == 0.0);
  CHECK(r.energy_before == 1.125);
  CHECK(r.energy_after == Approx(1.125).epsilon(1e-14));
  CHECK(std::abs(r.energy_change) < 1e-14);
  CHECK((r.momentum_before - Vector2d(1.5, 0)).norm() == 0.0);
  CHECK((r.momentum_after - Vector2d(1.5, 0)).norm() < 1e-14);
  CHECK(r.contacts[0].approach_before == 1.5);
  CHECK(r.contacts[0].approach_after == Approx(-1.5).epsilon(1e-14));
  CHECK(r.system.A(0, 0) == Approx(2.0).epsilon(1e-15));
  CHECK(r.system.B(0) == Approx(3.0).epsilon(1e-15));
  CHECK(r.system.rank == 1);
  CHECK_FALSE(r.system.dependent);
  CHECK(r.system.consistent);
}

TEST_CASE("A one-dimensional scene is section 1", "[scene][section1][property]") {
  // Two routes: the scene (embedded on the x axis, solved by the many-contact module) and the
  // section 1 module on the same bodies.
  t::Sampler sample("scene 1d");
  for (int i = 0; i < t::configurations; ++i) {
    const double m1 = sample.mass();
    const double m2 = sample.mass();
    const double v1 = sample.uniform(-10, 10);
    const double v2 = sample.uniform(-10, 10);
    const double e1 = sample.uniform(0, 3);
    const double e2 = sample.uniform(0, 3);
    const double normal = sample.coin() ? 1.0 : -1.0;
    Scene s;
    s.dimension = 1;
    s.bodies = {material("one", m1, {v1, 0}), material("two", m2, {v2, 0})};
    s.bodies[0].elasticity = e1;
    s.bodies[1].elasticity = e2;
    s.contacts = {Contact{0, 1, {normal, 0}, std::nullopt}};
    const auto r = sc::solve(s);
    const auto expected =
        impulse::one_d::collide(impulse::one_d::from_velocity(m1, v1), Elasticity(e1),
                                impulse::one_d::from_velocity(m2, v2), Elasticity(e2), normal);
    CAPTURE(i, m1, m2, v1, v2, e1, e2, normal);
    const double scale = std::abs(v1) + std::abs(v2);
    REQUIRE(r.bodies[0].after.velocity.x() ==
            Approx(impulse::one_d::velocity(expected.first)).margin(1e-12 * scale));
    REQUIRE(r.bodies[1].after.velocity.x() ==
            Approx(impulse::one_d::velocity(expected.second)).margin(1e-12 * scale));
    REQUIRE(r.bodies[0].after.velocity.y() == 0.0);
    REQUIRE(r.impulses[0].on_bumper.y() == 0.0);
  }
}

TEST_CASE("One contact in 2D is section 2 or section 3", "[scene][property]") {
  // Two routes again: the scene against the single-contact modules of sections 2 and 3.
  t::Sampler sample("scene single contact");
  for (int i = 0; i < t::configurations; ++i) {
    const Vector2d n = sample.unit_vector();
    const Vector2d point = sample.vector(2);
    const double e1 = sample.uniform(0, 3);
    const double e2 = sample.uniform(0, 3);
    const double m1 = sample.mass();
    const double m2 = sample.mass();
    const Vector2d v1 = sample.vector(10);
    const Vector2d v2 = sample.vector(10);
    Scene s;
    const bool rigid_pair = sample.coin();
    CAPTURE(i, rigid_pair, e1, e2, m1, m2);
    Vector2d expected1;
    Vector2d expected2;
    double expected_omega1 = 0;
    // The sizes of the terms whose sum is the result: the speeds of both contact points (both
    // routes round them alike), and for the spin the same over the radius of gyration squared
    // times the arm (a unit of speed change at the point turns the body by arm / k^2).
    double speed_terms = v1.norm() + v2.norm();
    double spin_terms = 0;
    if (rigid_pair) {
      // Radii of gyration comparable with the arms, as real bodies have (see random_scene.hpp).
      const Vector2d c1 = sample.vector(1);
      const Vector2d c2 = sample.vector(1);
      const double I1 = m1 * std::max(0.1, (point - c1).squaredNorm()) * sample.uniform(0.2, 1);
      const double I2 = m2 * std::max(0.1, (point - c2).squaredNorm()) * sample.uniform(0.2, 1);
      const double w1 = sample.uniform(-5, 5);
      const double w2 = sample.uniform(-5, 5);
      s.bodies = {rigid("one", m1, I1, c1, v1, w1), rigid("two", m2, I2, c2, v2, w2)};
      const auto r =
          impulse::rigid_2d::collide({m1, I1, c1, m1 * v1, I1 * w1}, Elasticity(e1),
                                     {m2, I2, c2, m2 * v2, I2 * w2}, Elasticity(e2), point, n);
      expected1 = impulse::rigid_2d::velocity(r.bumper);
      expected2 = impulse::rigid_2d::velocity(r.wedge);
      expected_omega1 = impulse::rigid_2d::angular_velocity(r.bumper);
      speed_terms += std::abs(w1) * (point - c1).norm() + std::abs(w2) * (point - c2).norm();
      spin_terms = std::abs(w1) + speed_terms * (point - c1).norm() / (I1 / m1);
    } else {
      s.bodies = {material("one", m1, v1), material("two", m2, v2)};
      const auto r = impulse::material_2d::collide(
          impulse::material_2d::from_velocity(m1, v1), Elasticity(e1),
          impulse::material_2d::from_velocity(m2, v2), Elasticity(e2), n);
      expected1 = impulse::material_2d::velocity(r.bumper);
      expected2 = impulse::material_2d::velocity(r.wedge);
    }
    s.bodies[0].elasticity = e1;
    s.bodies[1].elasticity = e2;
    s.contacts = {Contact{0, 1, n, point}};
    const auto r = sc::solve(s);
    REQUIRE(r.status == impulse::SolveStatus::success);
    REQUIRE((r.bodies[0].after.velocity - expected1).norm() <= 1e-12 * speed_terms);
    REQUIRE((r.bodies[1].after.velocity - expected2).norm() <= 1e-12 * speed_terms);
    REQUIRE(std::abs(r.bodies[0].after.angular_velocity - expected_omega1) <= 1e-12 * spin_terms);
  }
}

TEST_CASE("Velocity or momentum, angular velocity or angular momentum: the same body", "[scene]") {
  // p = m v and L = I omega: a body given either way collides the same.
  Scene by_velocity;
  by_velocity.elasticity = 1.7;
  by_velocity.bodies = {rigid("wheel", 2, 0.5, {0, 0}, {1, 0.25}, 3), fixed("wall")};
  by_velocity.contacts = {Contact{0, 1, {1, 0}, Vector2d(0.5, 0.5)}};
  Scene by_momentum = by_velocity;
  by_momentum.bodies[0].linear_given = Given::momentum;
  by_momentum.bodies[0].linear = Vector2d(2, 0.5);  // 2 * (1, 0.25)
  by_momentum.bodies[0].angular_given = Given::momentum;
  by_momentum.bodies[0].angular = 1.5;  // 0.5 * 3
  const auto a = sc::solve(by_velocity);
  const auto b = sc::solve(by_momentum);
  CHECK(a.system.Fdt.isApprox(b.system.Fdt, 1e-15));
  CHECK(a.bodies[0].before.momentum == Vector2d(2, 0.5));
  CHECK(b.bodies[0].before.velocity == Vector2d(1, 0.25));
  CHECK(b.bodies[0].before.angular_velocity == 3.0);
  CHECK(a.bodies[0].before.angular_momentum == 1.5);
}

TEST_CASE("A box landing flat on two points, by hand", "[scene][section5]") {
  // The box's own normal at both corners is (0, -1); its arms from the centre (0, 0.5) are
  // (-1, -0.5) and (1, -0.5), so det(r, n) = 1 and -1. (5.3): A = [[1/I + 1, 1 - 1/I],
  // [1 - 1/I, 1/I + 1]] with 1/I = 12/5, i.e. [[3.4, -1.4], [-1.4, 3.4]]; B = e (1, 1). By symmetry
  // the two impulses are equal, F (3.4 - 1.4) = e: F = e / 2, and the box leaves at e - 1 upwards,
  // without spin. The static ground is left out of the momentum totals.
  for (const double e : {1.0, 1.5, 2.0}) {
    CAPTURE(e);
    const auto r = sc::solve(box_on_ground(e));
    CHECK(r.system.A.isApprox(Eigen::Matrix2d{{3.4, -1.4}, {-1.4, 3.4}}, 1e-14));
    CHECK(r.system.B.isApprox(Vector2d(e, e), 1e-14));
    CHECK(r.system.Fdt.isApprox(Vector2d(e / 2, e / 2), 1e-14));
    CHECK((r.bodies[1].after.velocity - Vector2d(0, e - 1)).norm() < 1e-14);
    CHECK(std::abs(r.bodies[1].after.angular_velocity) < 1e-14);
    CHECK(r.bodies[0].after.velocity == Vector2d::Zero());  // static: listed with zero velocity
    CHECK((r.momentum_after - Vector2d(0, e - 1)).norm() < 1e-14);
    CHECK(r.momentum_before == Vector2d(0, -1));
    // Energy: 1/2 before, (e - 1)^2 / 2 after.
    CHECK(r.energy_after == Approx((e - 1) * (e - 1) / 2).margin(1e-14));
    CHECK(r.energy_change == Approx((e - 1) * (e - 1) / 2 - 0.5).margin(1e-14));
    // (0, 1) . (upward velocity e - 1) of the box's corner on its own normal (0, -1): 1 - e.
    CHECK(r.contacts[0].approach_after == Approx(1 - e).margin(1e-14));
  }
}

TEST_CASE("A dependent system: equal impulses, or all on one contact", "[scene][section4]") {
  // A bead (m 1) falls at 1 onto two supports with the same normal (0, 1). Its own normal at both
  // is (0, -1), its normal velocity 1: A = [[1, 1], [1, 1]] (rank 1), B = (e, e). Any F1 + F2 = e
  // solves it; minimum norm takes e/2 each, "basic" puts e on one contact.
  Scene s;
  s.elasticity = 1.0;
  s.bodies = {material("bead", 1, {0, -1}), fixed("left"), fixed("right")};
  s.contacts = {Contact{1, 0, {0, 1}, std::nullopt}, Contact{2, 0, {0, 1}, std::nullopt}};
  const auto equal = sc::solve(s);
  CHECK(equal.system.rank == 1);
  CHECK(equal.system.dependent);
  CHECK(equal.system.consistent);
  CHECK(equal.system.Fdt.isApprox(Vector2d(0.5, 0.5), 1e-14));
  s.solver.dependent = impulse::DependentPolicy::basic;
  const auto basic = sc::solve(s);
  CHECK(basic.system.Fdt.sum() == Approx(1.0).epsilon(1e-14));
  CHECK(basic.system.Fdt.minCoeff() == Approx(0.0).margin(1e-14));
  // Either way the bead stops: the same motion after.
  CHECK(equal.bodies[0].after.velocity.norm() < 1e-14);
  CHECK(basic.bodies[0].after.velocity.norm() < 1e-14);
}

TEST_CASE("with_elasticity overrides every body's own elasticity", "[scene]") {
  Scene s = worked_example();
  s.elasticity.reset();
  s.bodies[0].elasticity = 2.0;
  s.bodies[1].elasticity = 1.0;
  // (1.3): Fdt (1 + 1) = 2 * 1.5 + 1 * 0 = 3 with the bodies' own values, 1 * 1.5 at e = 1.
  CHECK(sc::solve(s).system.Fdt(0) == Approx(1.5).epsilon(1e-14));
  const sc::World at_one = sc::World(s).with_elasticity(1.0);
  CHECK(sc::resolve(at_one).system.Fdt(0) == Approx(0.75).epsilon(1e-14));
  CHECK_FALSE(at_one.scene().bodies[0].elasticity.has_value());
  CHECK(at_one.scene().elasticity == 1.0);
}

TEST_CASE("A world at another elasticity is the scene at that elasticity", "[scene]") {
  // What sweep does: only the elasticities change (the bodies and contacts were checked once).
  Scene s = worked_example();
  s.elasticity.reset();
  s.bodies[0].elasticity = 2.0;
  s.bodies[1].elasticity = 1.0;
  const sc::World world(s);
  for (const double e : {0.0, 0.5, 1.0, 1.7, 2.0, 3.0}) {
    CAPTURE(e);
    const auto by_world = sc::resolve(world.with_elasticity(e));
    // The same scene checked afresh at that elasticity.
    Scene at_e = s;
    at_e.elasticity = e;
    for (sc::Body& body : at_e.bodies) {
      body.elasticity.reset();
    }
    CHECK(by_world.impulses[0].magnitude == sc::solve(at_e).impulses[0].magnitude);
    // (1.3) at one elasticity: Fdt (1 + 1) = e 1.5, so Fdt = 0.75 e.
    CHECK(by_world.impulses[0].magnitude == Approx(0.75 * e).margin(1e-15));
  }
  CHECK_THROWS_WITH(world.with_elasticity(-1), "elasticity: must be finite and at least 0, got -1");
}

TEST_CASE("Bad scenes are refused with the place, the rule and the value", "[scene][errors]") {
  using Catch::Matchers::Contains;
  const auto refused = [](Scene s) { return sc::solve(s); };
  {
    Scene s = worked_example();
    s.dimension = 3;
    CHECK_THROWS_MATCHES(refused(s), InvalidInput,
                         Catch::Matchers::Message("dimension: must be 1 or 2, got 3"));
  }
  {
    Scene s = worked_example();
    s.bodies[1].mass = -1;
    CHECK_THROWS_WITH(refused(s), "bodies[1].mass: must be positive and finite, got -1");
  }
  {
    Scene s = worked_example();
    s.bodies[0].mass = 1e-310;  // positive and finite, but 1/m is not a double
    CHECK_THROWS_WITH(refused(s), Contains("bodies[0].mass: is too small"));
  }
  {
    Scene s = worked_example();
    s.bodies[1].name = std::string("a");  // (assigning the literal trips GCC 12 bug 105329)
    CHECK_THROWS_WITH(refused(s), "bodies[1].name: \"a\" is already the name of bodies[0]");
  }
  {
    Scene s = worked_example();
    s.bodies[0].name.clear();
    CHECK_THROWS_WITH(refused(s), "bodies[0].name: must not be empty");
  }
  {
    Scene s = worked_example();
    s.dimension = 1;
    s.contacts[0].normal = {1, 0};
    s.bodies[0] = rigid("a", 1, 1, {0, 0}, {1.5, 0}, 0);
    CHECK_THROWS_WITH(refused(s), Contains("bodies[0].kind: a rigid body needs dimension 2"));
  }
  {
    Scene s = worked_example();
    s.bodies[0].linear = {std::numeric_limits<double>::infinity(), 0};
    CHECK_THROWS_WITH(refused(s), "bodies[0].velocity: must be finite, got [inf, 0]");
  }
  {
    Scene s = worked_example();
    s.bodies[0].mass = 1e200;
    s.bodies[0].linear = {1e200, 0};
    CHECK_THROWS_WITH(refused(s), Contains("bodies[0].velocity: mass times velocity overflows"));
  }
  {
    Scene s = worked_example();
    s.bodies[0].elasticity = -0.5;
    CHECK_THROWS_WITH(refused(s), "bodies[0].elasticity: must be finite and at least 0, got -0.5");
  }
  {
    Scene s = worked_example();
    s.elasticity.reset();
    s.bodies[0].elasticity = 2.0;
    CHECK_THROWS_WITH(refused(s), Contains("bodies[1]: needs an elasticity"));
  }
  {
    Scene s = worked_example();
    s.contacts[0].wedge = 0;
    CHECK_THROWS_WITH(refused(s),
                      "contacts[0]: bumper and wedge are the same body \"a\": a body "
                      "cannot be in contact with itself");
  }
  {
    Scene s = worked_example();
    s.contacts[0].wedge = 7;
    CHECK_THROWS_WITH(refused(s), "contacts[0].wedge: must name one of the 2 bodies, got index 7");
  }
  {
    Scene s = worked_example();
    s.contacts[0].normal = {0, 0};
    CHECK_THROWS_WITH(refused(s),
                      "contacts[0].normal: must be a finite non-zero vector, got [0, 0]");
  }
  {
    Scene s = worked_example();
    s.dimension = 1;
    s.contacts[0].normal = {0, 0};
    s.bodies[0].linear = {1.5, 0};
    CHECK_THROWS_WITH(refused(s),
                      "contacts[0].normal: must be a non-zero number (+1 or -1: its "
                      "sign is the direction), got 0");
  }
  {
    Scene s = worked_example();
    s.serial.max_collisions = 2'000'000'000;
    CHECK_THROWS_WITH(refused(s),
                      "solver.max_collisions: must be at most 1000000000, got 2000000000");
  }
  {
    // The dense method's limit is the library's rule: a scene built in C++ is refused as a file
    // is, before any matrix is made (3,000 contacts with "basic" would need 72 MB matrices; at
    // 100,000, 80 GB).
    Scene s = worked_example();
    s.contacts.assign(3'000, s.contacts[0]);
    s.solver.dependent = impulse::DependentPolicy::basic;
    CHECK_THROWS_WITH(refused(s), Catch::Matchers::StartsWith(
                                      "contacts: 3000 contacts with the policies \"basic\""));
  }
  {
    Scene s = box_on_ground(1.5);
    s.contacts[1].point.reset();
    CHECK_THROWS_WITH(refused(s),
                      "contacts[1]: missing \"point\": it is needed because \"box\" is rigid");
  }
  {
    Scene s = box_on_ground(1.5);
    s.bodies.push_back(fixed("wall"));
    s.contacts[1].wedge = 2;
    CHECK_THROWS_WITH(refused(s), Contains("contacts[1]: joins two static bodies"));
  }
  {
    Scene s = worked_example();
    s.contacts.clear();
    CHECK_THROWS_WITH(refused(s), "contacts: must hold at least one contact, got none");
  }
}

TEST_CASE("A normal of any length is made unit, and the report says so", "[scene]") {
  // [2, 0] is the worked example's normal at twice the length: the same collision, exactly
  // (2 / 2 is exact), and a note that names the place, the length and the normal used.
  Scene doubled = worked_example();
  doubled.contacts[0].normal = {2, 0};
  const auto r = sc::solve(doubled);
  const auto reference = sc::solve(worked_example());
  CHECK(r.impulses[0].magnitude == reference.impulses[0].magnitude);
  CHECK(r.bodies[1].after.velocity == reference.bodies[1].after.velocity);
  REQUIRE(r.notes.size() == 1);
  CHECK(r.notes[0] == "contacts[0].normal [2, 0] is not of unit length (length 2): used as [1, 0]");
  CHECK(reference.notes.empty());
  // A student's [0.7071, 0.7071] (length 0.99998, off by 2e-5): the diagonal, as if typed to
  // every digit. The puck a (m 1, velocity (1.5, 0)) hits b at rest along n = (1, 1)/sqrt(2):
  // (1.3) on the cast, u = 1.5/sqrt(2), Fdt = 2 u / 2 = 1.5/sqrt(2), and a keeps (0.75, -0.75).
  Scene oblique = worked_example();
  oblique.contacts[0].normal = {0.7071, 0.7071};
  const auto o = sc::solve(oblique);
  CHECK(o.impulses[0].magnitude == Approx(1.5 / std::sqrt(2.0)).epsilon(1e-15));
  CHECK((o.bodies[0].after.velocity - Vector2d(0.75, -0.75)).norm() < 1e-15);
  CHECK_THAT(o.notes.at(0), Catch::Matchers::StartsWith(
                                "contacts[0].normal [0.7071, 0.7071] is not of unit length"));
  // On a line, 0.5 is the direction +1.
  Scene line = worked_example();
  line.dimension = 1;
  line.contacts[0].normal = {0.5, 0};
  const auto l = sc::solve(line);
  CHECK(l.impulses[0].magnitude == reference.impulses[0].magnitude);
  CHECK(l.notes.at(0) == "contacts[0].normal 0.5 is not of unit length (length 0.5): used as 1");
  // Within 1e-9 of unit length: kept as given, no note (the scene format's unit normals).
  Scene almost = worked_example();
  almost.contacts[0].normal = {1 + 0.5e-9, 0};
  CHECK(sc::solve(almost).notes.empty());
}

TEST_CASE("Numbers beyond doubles give a non-finite status, not a wrong number", "[scene]") {
  // m = 1e200 at 1e100: p = 1e300 is a double, but the energy p^2 / 2m needs p^2 = 1e600.
  Scene s = worked_example();
  s.bodies[0].mass = 1e200;
  s.bodies[0].linear = {1e100, 0};
  // The overflow is the point of the test: solve() computes with the numbers and reports the
  // infinity it gets as a status. Its traps (Debug runs) are off for this call only.
  const auto r = [&] {
    const impulselab::test::FpTrapsOff overflow_on_purpose;
    return sc::solve(s);
  }();
  CHECK(r.status == impulse::SolveStatus::non_finite);
}
