// SPDX-License-Identifier: GPL-3.0-or-later
// Section 5: rigid bodies, many bodies, many contact points.
#include <catch2/catch.hpp>
#include <cmath>

#include "impulse/core/plane.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "multipoint/random_scene.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::multipoint::Body;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
using impulse::rigid_2d::RigidBody;
namespace mp = impulse::multipoint;
namespace t = impulse::test;

namespace {
double angular_momentum(const std::vector<Body>& bodies) {
  double total = 0;
  for (const auto& b : bodies) {
    const auto& r = std::get<RigidBody>(b);
    total += r.L + (r.position.x() * r.p.y() - r.position.y() * r.p.x());
  }
  return total;
}
}  // namespace

TEST_CASE("A box landing flat on two points", "[section5]") {
  // Box 2 wide and 1 high, m = 1, I = m (w^2 + h^2) / 12 = 5/12, falling at (0, -1) without
  // spin onto the floor at its corners (-1, -0.5) and (1, -0.5); its outward normal at both is
  // (0, -1). Arms det(r, n): det((-1, -0.5), (0, -1)) = 1 and det((1, -0.5), (0, -1)) = -1.
  // (5.3): A = [[1/I + 1, -1/I + 1], [-1/I + 1, 1/I + 1]], B = e (1, 1). By symmetry
  // F1 = F2 = F with 2F = e: each corner takes e/2, the box leaves at (e - 1) upwards, no spin.
  const RigidBody box{1.0, 5.0 / 12.0, {0, 0}, {0, -1}, 0.0};
  const std::vector<Body> bodies{box, StaticBody{}};
  const std::vector<Contact> corners{{0, 1, {0, -1}, {-1, -0.5}}, {0, 1, {0, -1}, {1, -0.5}}};
  for (const double e : {1.0, 1.5, 2.0}) {
    CAPTURE(e);
    const auto r = mp::resolve(bodies, Elasticity(e), corners);
    const double I = box.inertia;
    CHECK(r.solution.A.isApprox(Eigen::Matrix2d{{1 / I + 1, 1 - 1 / I}, {1 - 1 / I, 1 / I + 1}},
                                1e-14));
    CHECK_FALSE(r.solution.dependent);  // det A = 4 / I
    CHECK(r.solution.Fdt.isApprox(Vector2d(e / 2, e / 2), 1e-14));
    const auto& after = std::get<RigidBody>(r.after[0]);
    CHECK((after.p - Vector2d(0, e - 1)).norm() < 1e-14);
    CHECK(std::abs(after.L) < 1e-14);
  }
}

TEST_CASE("One contact through section 5 is section 3", "[section5]") {
  t::Sampler sample("section5 single");
  for (int i = 0; i < t::configurations; ++i) {
    auto scene = t::random_scene(sample, t::Kinds::rigid, false);
    scene.bodies.resize(2);
    const Contact c{0, 1, sample.unit_vector(), sample.vector(5)};
    const Elasticity e1(sample.uniform(0, 3));
    const Elasticity e2(sample.uniform(0, 3));
    const auto& a = std::get<RigidBody>(scene.bodies[0]);
    const auto& b = std::get<RigidBody>(scene.bodies[1]);
    const auto single = impulse::rigid_2d::collide(a, e1, b, e2, c.point, c.normal);
    const std::vector<Elasticity> es{e1, e2};
    const auto many = mp::resolve(scene.bodies, es, std::vector<Contact>{c});
    // B sums the two bodies' terms, which may nearly cancel: the rounding scales with the terms.
    const double terms = std::abs(impulse::rigid_2d::contribution(a, c.point, c.normal, e1).b) +
                         std::abs(impulse::rigid_2d::contribution(b, c.point, -c.normal, e2).b);
    CAPTURE(i, single.solution.Fdt, many.solution.Fdt(0), terms);
    REQUIRE(many.solution.Fdt(0) ==
            Approx(single.solution.Fdt).epsilon(1e-12).margin(1e-14 * terms / single.solution.A));
  }
}

TEST_CASE("Elasticity 2 conserves energy with rotation, many contacts", "[section5][property]") {
  t::Sampler sample("section5 energy");
  t::Worst worst("section5 energy (e=2), relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const double before = t::energy(scene.bodies);
    if (before == 0.0) {
      continue;
    }
    const auto r = mp::resolve(scene.bodies, Elasticity::elastic(), scene.contacts);
    const double error = t::relative_error(t::energy(r.after), before, before);
    worst.see(error);
    REQUIRE(error <= 1e-10);
  }
}

TEST_CASE("Elasticity 1 equalises the contact points' normal velocities", "[section5][property]") {
  t::Sampler sample("section5 equalise");
  t::Worst worst("section5 approach after (e=1) / approach scale");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
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

TEST_CASE("Rigid bodies alone conserve linear and angular momentum", "[section5][property]") {
  t::Sampler sample("section5 momentum");
  t::Worst linear("section5 linear momentum, relative");
  t::Worst angular("section5 angular momentum about origin, relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::rigid, false);
    std::vector<Elasticity> es;
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
      es.emplace_back(sample.uniform(0, 3));
    }
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto r = mp::resolve(scene.bodies, es, scene.contacts);
    const double p_error = (t::momentum(r.after) - t::momentum(scene.bodies)).norm() /
                           t::momentum_scale(scene.bodies, r.solution.Fdt);
    // Scale: every spin, orbital term and impulse moment that enters the sum.
    double L_scale = 0;
    for (const auto& b : scene.bodies) {
      const auto& rb = std::get<RigidBody>(b);
      L_scale += std::abs(rb.L) + rb.position.norm() * rb.p.norm();
    }
    for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
      L_scale +=
          scene.contacts[v].point.norm() * std::abs(r.solution.Fdt(static_cast<Eigen::Index>(v)));
    }
    const double L_error =
        std::abs(angular_momentum(r.after) - angular_momentum(scene.bodies)) / L_scale;
    linear.see(p_error);
    angular.see(L_error);
    REQUIRE(p_error <= 1e-12);
    REQUIRE(L_error <= 1e-12);
  }
}

TEST_CASE("A uniform elasticity in (1, 2) loses energy and 0 gives no impulse",
          "[section5][property]") {
  t::Sampler sample("section5 intermediate");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const Elasticity e(sample.uniform(1.01, 1.99));
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), e.value());
    if (t::speed_scale(scene) == 0.0) {
      continue;
    }
    const auto r = mp::resolve(scene.bodies, e, scene.contacts);
    REQUIRE(t::energy(r.after) < t::energy(scene.bodies));
    REQUIRE(mp::resolve(scene.bodies, Elasticity(0), scene.contacts).solution.Fdt.isZero(0.0));
  }
}

TEST_CASE("The residual of A Fdt = B is at round-off, with rotation", "[section5][property]") {
  t::Sampler sample("section5 residual");
  t::Worst worst("section5 residual / (|A| |Fdt| + |B|)");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const auto s =
        mp::resolve(scene.bodies, Elasticity(sample.uniform(0, 3)), scene.contacts).solution;
    const double scale = s.A.norm() * s.Fdt.norm() + s.B.norm();
    if (scale == 0.0) {
      continue;
    }
    worst.see(s.residual / scale);
    REQUIRE(s.consistent);
    // Systems assembled from bodies are solved through their factor G (A = G^T G), which
    // minimises |G Fdt - w| rather than |A Fdt - B| itself: the residual in A is G^T times a
    // rounded least-squares residual, at most 7.4e-13 of the scale over 20,000 scenes.
    REQUIRE(s.residual <= 1e-11 * scale);
  }
}

TEST_CASE("A body's kept motion gives its points' velocities bit for bit", "[section5][property]") {
  // Serial collisions measure approach speeds from each body's motion (ω and the velocity of its
  // origin, kept between collisions) instead of from the body: the same numbers to the last bit
  // are what keeps every report unchanged. Against the body's own velocity at a point
  // (section 3.2), for every kind of body, at the scene's contact points and at random ones.
  t::Sampler sample("section5 motion");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    for (const Contact& c : scene.contacts) {
      for (const Vector2d& x :
           {c.point, Vector2d(sample.uniform(-10, 10), sample.uniform(-10, 10))}) {
        for (const std::size_t k : {c.bumper, c.wedge}) {
          const Body& body = scene.bodies[k];
          const Vector2d from_body = mp::point_velocity(body, x);
          const Vector2d from_motion = mp::point_velocity(mp::motion(body), x);
          REQUIRE(from_motion.x() == from_body.x());
          REQUIRE(from_motion.y() == from_body.y());
        }
      }
    }
    const mp::Configuration configuration(
        scene.bodies, std::vector<Elasticity>(scene.bodies.size(), Elasticity(1.5)),
        scene.contacts);
    std::vector<mp::Motion> motions;
    for (const Body& body : scene.bodies) {
      motions.push_back(mp::motion(body));
    }
    for (Eigen::Index v = 0; v < static_cast<Eigen::Index>(scene.contacts.size()); ++v) {
      REQUIRE(configuration.approach(motions, v) ==
              configuration.approach(configuration.bodies(), v));
    }
  }
}
