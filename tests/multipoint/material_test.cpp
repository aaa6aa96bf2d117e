// SPDX-License-Identifier: GPL-3.0-or-later
// Section 4: point masses, many bodies, many contact points.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/error.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "impulse/one_d/one_d.hpp"
#include "multipoint/random_scene.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::material_2d::PointMass;
using impulse::multipoint::Body;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
namespace mp = impulse::multipoint;
namespace t = impulse::test;

namespace {
Vector2d velocity(const Body& b) {
  return std::get<PointMass>(b).p / std::get<PointMass>(b).mass;
}

// Whether two states of the same bodies are equal to the last bit.
bool same(const std::vector<Body>& a, const std::vector<Body>& b) {
  if (a.size() != b.size()) {
    return false;
  }
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (const auto* p = std::get_if<PointMass>(&a[k])) {
      const auto& q = std::get<PointMass>(b[k]);
      if (!(p->mass == q.mass && p->p == q.p)) {
        return false;
      }
    } else if (const auto* r = std::get_if<impulse::rigid_2d::RigidBody>(&a[k])) {
      const auto& s = std::get<impulse::rigid_2d::RigidBody>(b[k]);
      if (!(r->p == s.p && r->L == s.L && r->mass == s.mass && r->position == s.position)) {
        return false;
      }
    }
  }
  return true;
}

std::vector<Elasticity> random_elasticities(t::Sampler& sample, std::size_t count, double low,
                                            double high) {
  std::vector<Elasticity> result;
  for (std::size_t i = 0; i < count; ++i) {
    result.emplace_back(sample.uniform(low, high));
  }
  return result;
}
}  // namespace

TEST_CASE("Newton's cradle of three: the simultaneous answer", "[section4]") {
  // Three unit balls in a row, velocities (1, 0, 0), contacts 0-1 and 1-2 with normal +x.
  // Blocks (4.5): ball 0 gives [1] at contact 0 and b = 2 * 1; ball 1, with normals -x at
  // contact 0 and +x at contact 1, gives [[1, -1], [-1, 1]] and b = 0; ball 2 gives [1] at
  // contact 1. A = [[2, -1], [-1, 2]], B = (2, 0), so Fdt = (4/3, 2/3) and the velocities after
  // are 1 - 4/3 = -1/3, 4/3 - 2/3 = 2/3 and 2/3.
  const std::vector<Body> balls{PointMass{1, {1, 0}}, PointMass{1, {0, 0}}, PointMass{1, {0, 0}}};
  const std::vector<Contact> contacts{{0, 1, {1, 0}, {0, 0}}, {1, 2, {1, 0}, {0, 0}}};
  const auto r = mp::resolve(balls, Elasticity::elastic(), contacts);
  CHECK(r.solution.A.isApprox(Eigen::Matrix2d{{2, -1}, {-1, 2}}, 1e-15));
  CHECK(r.solution.B.isApprox(Vector2d(2, 0), 1e-15));
  CHECK(r.solution.Fdt.isApprox(Vector2d(4.0 / 3, 2.0 / 3), 1e-14));
  CHECK(velocity(r.after[0]).isApprox(Vector2d(-1.0 / 3, 0), 1e-14));
  CHECK(velocity(r.after[1]).isApprox(Vector2d(2.0 / 3, 0), 1e-14));
  CHECK(velocity(r.after[2]).isApprox(Vector2d(2.0 / 3, 0), 1e-14));
}

TEST_CASE("A point mass on two parallel contacts: a dependent system", "[section4]") {
  // m = 1 falls at (0, -1) onto the floor at two points; its outward normal at both is (0, -1).
  // A = [[1, 1], [1, 1]] (rank 1), B = e (1, 1). Any F1 + F2 = e acts the same; the least norm
  // splits it equally (the paper's equal impulses), a basic solution puts all of it on one point.
  const std::vector<Body> bodies{PointMass{1, {0, -1}}, StaticBody{}};
  const std::vector<Contact> contacts{{0, 1, {0, -1}, {-1, 0}}, {0, 1, {0, -1}, {1, 0}}};
  const auto equal = mp::resolve(bodies, Elasticity::elastic(), contacts);
  CHECK(equal.solution.dependent);
  CHECK(equal.solution.rank == 1);
  CHECK(equal.solution.Fdt.isApprox(Vector2d(1, 1), 1e-14));

  impulse::SolverOptions basic;
  basic.dependent = impulse::DependentPolicy::basic;
  const auto one = mp::resolve(bodies, Elasticity::elastic(), contacts, basic);
  CHECK(one.solution.Fdt.sum() == Approx(2.0).epsilon(1e-14));
  CHECK(one.solution.Fdt.cwiseAbs().minCoeff() == 0.0);
  // The same motion either way: the ball bounces at (0, 1).
  CHECK(velocity(equal.after[0]).isApprox(Vector2d(0, 1), 1e-14));
  CHECK(velocity(one.after[0]).isApprox(Vector2d(0, 1), 1e-14));
}

TEST_CASE("On a line, section 4 gives section 1's impulse", "[section4]") {
  t::Sampler sample("multipoint line");
  for (int i = 0; i < t::configurations; ++i) {
    const double m1 = sample.mass();
    const double m2 = sample.mass();
    const double v1 = sample.uniform(-10, 10);
    const double v2 = sample.uniform(-10, 10);
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    CAPTURE(m1, m2, v1, v2, e1.value(), e2.value());
    const auto line = impulse::one_d::collide(impulse::one_d::from_velocity(m1, v1), e1,
                                              impulse::one_d::from_velocity(m2, v2), e2);
    const std::vector<Body> bodies{PointMass{m1, {m1 * v1, 0}}, PointMass{m2, {m2 * v2, 0}}};
    const std::vector<Elasticity> es{e1, e2};
    const std::vector<Contact> contacts{{0, 1, {1, 0}, {0, 0}}};
    const auto plane = mp::resolve(bodies, es, contacts);
    REQUIRE(plane.solution.Fdt(0) ==
            Approx(line.solution.Fdt).epsilon(1e-12).margin(1e-14 * std::abs(line.solution.B)));
  }
}

TEST_CASE("Elasticity 2 conserves energy over many bodies and contacts", "[section4][property]") {
  t::Sampler sample("section4 energy");
  t::Worst worst("section4 energy (e=2), relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material, true);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto r = mp::resolve(scene.bodies, Elasticity::elastic(), scene.contacts);
    REQUIRE(r.solution.status == impulse::SolveStatus::success);
    const double before = t::energy(scene.bodies);
    if (before == 0.0) {
      continue;  // only static bodies moved: nothing to conserve
    }
    const double error = t::relative_error(t::energy(r.after), before, before);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Elasticity 1 equalises the normal velocities at every contact", "[section4][property]") {
  t::Sampler sample("section4 equalise");
  t::Worst worst("section4 approach after (e=1) / approach scale");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material, true);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    if (t::speed_scale(scene) == 0.0) {
      continue;  // nothing moves
    }
    const auto r = mp::resolve(scene.bodies, Elasticity::inelastic(), scene.contacts);
    const double error =
        t::worst_approach(r.after, scene.contacts) / t::approach_scale(scene, r.solution);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Per-body elasticities conserve momentum", "[section4][property]") {
  t::Sampler sample("section4 momentum");
  t::Worst worst("section4 momentum, relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material, false);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto r = mp::resolve(scene.bodies, es, scene.contacts);
    const double error = (t::momentum(r.after) - t::momentum(scene.bodies)).norm() /
                         t::momentum_scale(scene.bodies, r.solution.Fdt);
    worst.see(error);
    REQUIRE(error <= 1e-12);
  }
}

TEST_CASE("A uniform elasticity in (1, 2) loses energy and 0 gives no impulse",
          "[section4][property]") {
  t::Sampler sample("section4 intermediate");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material, true);
    const Elasticity e(sample.uniform(1.01, 1.99));
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), e.value());
    const double before = t::energy(scene.bodies);
    if (t::speed_scale(scene) == 0.0) {
      continue;
    }
    const auto r = mp::resolve(scene.bodies, e, scene.contacts);
    REQUIRE(t::energy(r.after) < before);
    const auto none = mp::resolve(scene.bodies, Elasticity(0), scene.contacts);
    REQUIRE(none.solution.Fdt.isZero(0.0));
  }
}

TEST_CASE("The residual of A Fdt = B is at round-off", "[section4][property]") {
  t::Sampler sample("section4 residual");
  t::Worst worst("section4 residual / (|A| |Fdt| + |B|)");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material, true);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    const auto s = mp::resolve(scene.bodies, es, scene.contacts).solution;
    const double scale = s.A.norm() * s.Fdt.norm() + s.B.norm();
    if (scale == 0.0) {
      continue;
    }
    worst.see(s.residual / scale);
    REQUIRE(s.consistent);  // B = J e v always lies in the range of A = J M^-1 J^T
    // Systems assembled from bodies are solved through their factor G (A = G^T G), which
    // minimises |G Fdt - w| rather than |A Fdt - B| itself: the residual in A is G^T times a
    // rounded least-squares residual, at most 7.4e-13 of the scale over 20,000 scenes.
    REQUIRE(s.residual <= 1e-11 * scale);
  }
}

TEST_CASE("Bad scenes are refused with the place and the value", "[section4][errors]") {
  const std::vector<Body> two{PointMass{1, {1, 0}}, PointMass{1, {0, 0}}};
  const std::vector<Contact> ok{{0, 1, {1, 0}, {0, 0}}};
  const auto e = Elasticity::elastic();
  CHECK_THROWS_MATCHES(
      mp::resolve(std::vector<Body>{PointMass{-1, {0, 0}}, PointMass{1, {0, 0}}}, e, ok),
      InvalidInput, Catch::Matchers::Message("bodies[0].mass must be positive and finite, got -1"));
  CHECK_THROWS_WITH(mp::resolve(two, e, std::vector<Contact>{{0, 2, {1, 0}, {0, 0}}}),
                    "contacts[0].wedge must name one of the 2 bodies, got index 2");
  CHECK_THROWS_WITH(
      mp::resolve(two, e, std::vector<Contact>{{1, 1, {1, 0}, {0, 0}}}),
      "contacts[0] must join two different bodies, got body 1 in contact with itself");
  CHECK_THROWS_WITH(mp::resolve(two, e, std::vector<Contact>{{0, 1, {0.6, 0.6}, {0, 0}}}),
                    Catch::Matchers::StartsWith("contacts[0].normal must be a unit vector"));
  CHECK_THROWS_WITH(mp::resolve(two, e, std::vector<Contact>{{0, 1, {1, 0}, {std::nan(""), 0}}}),
                    "contacts[0].point must be finite, got [nan, 0]");
  CHECK_THROWS_WITH(mp::resolve(two, std::vector<Elasticity>{e}, ok),
                    "elasticities must give one value per body (2), got 1");
  CHECK_THROWS_WITH(mp::apply_impulses(two, ok, Eigen::VectorXd::Zero(3)),
                    "Fdt must give one impulse per contact (1), got 3");
}

TEST_CASE("A configuration is checked once; what it computes is what the free functions compute",
          "[section4]") {
  // The free functions check their arguments, then do the work of a Configuration's members:
  // the same system, approach speeds and bodies after, to the last bit.
  t::Sampler sample("configuration");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    const mp::Configuration configuration(scene.bodies, es, scene.contacts);
    const auto system = configuration.assemble();
    const auto free = mp::assemble(scene.bodies, es, scene.contacts);
    CAPTURE(i);
    REQUIRE(system.B() == free.B());
    REQUIRE(system.A() == free.A());
    REQUIRE(configuration.approach(scene.bodies) == mp::approach(scene.bodies, scene.contacts));
    const Eigen::VectorXd Fdt =
        Eigen::VectorXd::Ones(static_cast<Eigen::Index>(scene.contacts.size()));
    const auto after = configuration.after(Fdt);
    REQUIRE(same(after, mp::apply_impulses(scene.bodies, scene.contacts, Fdt)));
    // One contact's impulse at a time, in contact order: the same bodies after.
    std::vector<Body> stepwise(scene.bodies.begin(), scene.bodies.end());
    for (Eigen::Index v = 0; v < Fdt.size(); ++v) {
      configuration.apply(stepwise, v, 1.0);
    }
    REQUIRE(same(stepwise, after));
  }
  // Bad input is refused when the configuration is made, with the free functions' messages.
  const std::vector<Body> two{PointMass{1, {1, 0}}, PointMass{1, {0, 0}}};
  CHECK_THROWS_WITH(mp::Configuration(two, {Elasticity::elastic(), Elasticity::elastic()},
                                      {{0, 1, {0.6, 0.6}, {0, 0}}}),
                    Catch::Matchers::StartsWith("contacts[0].normal must be a unit vector"));
  CHECK_THROWS_WITH(mp::Configuration(two, {Elasticity::elastic()}, {{0, 1, {1, 0}, {0, 0}}}),
                    "elasticities must give one value per body (2), got 1");
}

TEST_CASE("Factoring G or factoring A gives the same impulses", "[section4][property]") {
  // Two routes to one answer: the solver works on the factor G of a system built from bodies;
  // the same A and B entered by hand carry no factor and are solved from A itself. Where the
  // system is well conditioned both minimum-norm solutions must agree.
  t::Sampler sample("section4 routes");
  int compared = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    const auto system = mp::assemble(scene.bodies, es, scene.contacts);
    REQUIRE(system.has_factor());
    const auto factored = impulse::solve(system);
    const auto plain = impulse::solve(impulse::ContactSystem(system.A(), system.B()));
    if (factored.condition_estimate > 1e6) {
      continue;
    }
    ++compared;
    CAPTURE(i, factored.condition_estimate, factored.Fdt.transpose(), plain.Fdt.transpose());
    REQUIRE(factored.rank == plain.rank);
    REQUIRE((factored.Fdt - plain.Fdt).norm() <= 1e-8 * std::max(1.0, plain.Fdt.norm()));
  }
  REQUIRE(compared > t::configurations * 9 / 10);
}
