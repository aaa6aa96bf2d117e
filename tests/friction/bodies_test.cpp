// SPDX-License-Identifier: GPL-3.0-or-later
// W and u0 from any section's bodies, and the impulse applied to them.
#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <span>

#include "impulse/core/error.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "physics.hpp"
#include "support/sampling.hpp"

using Catch::Matchers::Contains;
using Eigen::Matrix2d;
using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::multipoint::Body;
using impulse::multipoint::StaticBody;
using namespace impulse::test::friction;
namespace friction = impulse::friction;

namespace {

constexpr Pairing pairings[] = {Pairing::material, Pairing::rigid, Pairing::material_static,
                                Pairing::rigid_static, Pairing::mixed};

// The paper's single-contact (a, b) of one body at elasticity 1, from its section's module:
// (4.5)/(4.8) for a point mass (material_2d), (3.6)/(3.10) for a rigid body (rigid_2d); a static
// body brings nothing.
impulse::ScalarContribution paper_share(const Body& body, const Vector2d& point,
                                        const Vector2d& own_normal) {
  if (const auto* m = std::get_if<impulse::material_2d::PointMass>(&body)) {
    return impulse::material_2d::contribution(*m, own_normal, Elasticity::inelastic());
  }
  if (const auto* b = std::get_if<impulse::rigid_2d::RigidBody>(&body)) {
    return impulse::rigid_2d::contribution(*b, point, own_normal, Elasticity::inelastic());
  }
  return {};
}

// (separation, slip) measured from the bodies' point velocities, by the definition.
Vector2d measured_u(const Hit& h) {
  const Vector2d relative = velocity_at(h.bumper, h.point) - velocity_at(h.wedge, h.point);
  return {-h.normal.dot(relative), friction::tangent(h.normal).dot(relative)};
}

}  // namespace

TEST_CASE("The tangent is the normal turned a quarter counter-clockwise", "[friction]") {
  // The scene format's [-n_y, n_x].
  CHECK(friction::tangent(Vector2d(0, -1)) == Vector2d(1, 0));
  CHECK(friction::tangent(Vector2d(1, 0)) == Vector2d(0, 1));
  CHECK(friction::tangent(Vector2d(0.6, 0.8)) == Vector2d(-0.8, 0.6));
}

TEST_CASE("W_nn is the paper's A and -u0_n the library's approach speed, for every section",
          "[friction]") {
  for (const Pairing pairing : pairings) {
    CAPTURE(name(pairing));
    impulse::test::Sampler sample(std::string("friction W_nn ") + name(pairing));
    impulse::test::Worst worst(std::string("friction: W_nn vs A, ") + name(pairing));
    for (int i = 0; i < impulse::test::configurations; ++i) {
      const Hit h = random_hit(sample, pairing);
      CAPTURE(i, h.point, h.normal);
      const auto contact = friction::dynamics(h.bumper, h.wedge, h.point, h.normal);
      // The paper's A = a_1 + a_2 and B = b_1 + b_2 (elasticity 1: the approach speed), each
      // body with its own outward normal.
      const impulse::ScalarContribution paper =
          paper_share(h.bumper, h.point, h.normal) + paper_share(h.wedge, h.point, -h.normal);
      const double error = std::abs(contact.W(0, 0) - paper.a) / paper.a;
      worst.see(error);
      CHECK(error <= 1e-14);
      // multipoint::approach: the sum of both bodies' point velocities on their own normals.
      const std::array<Body, 2> bodies{h.bumper, h.wedge};
      const impulse::multipoint::Contact c{0, 1, h.normal, h.point};
      const double approach = impulse::multipoint::approach(bodies, std::span(&c, 1))(0);
      const double scale = speed_scale(h);
      CHECK(std::abs(contact.approach() - approach) <= 1e-14 * scale);
      CHECK(std::abs(contact.approach() - paper.b) <= 1e-14 * scale);
    }
  }
}

TEST_CASE("W is how the contact's velocity answers a unit impulse (measured on the bodies)",
          "[friction]") {
  // A different method: push the bodies by a unit normal impulse, then by a unit tangential one
  // (p += J, L += det(r, J), from the definitions), and measure the contact's (separation,
  // slip) before and after from the point velocities. The change is W's column.
  for (const Pairing pairing : pairings) {
    CAPTURE(name(pairing));
    impulse::test::Sampler sample(std::string("friction W probe ") + name(pairing));
    impulse::test::Worst worst(std::string("friction: W vs unit impulses, ") + name(pairing));
    for (int i = 0; i < impulse::test::configurations; ++i) {
      const Hit h = random_hit(sample, pairing);
      CAPTURE(i, h.point, h.normal);
      const auto contact = friction::dynamics(h.bumper, h.wedge, h.point, h.normal);
      const Vector2d u0 = measured_u(h);
      CHECK((contact.u0 - u0).norm() <= 1e-14 * speed_scale(h));
      const Vector2d t = friction::tangent(h.normal);
      Matrix2d probed;
      for (int j = 0; j < 2; ++j) {
        // The impulse on the bumper for P = e_j: -n P_n + t P_t; the wedge gets the opposite.
        const Vector2d J = j == 0 ? Vector2d(-h.normal) : t;
        Hit pushed = h;
        push(pushed.bumper, h.point, J);
        push(pushed.wedge, h.point, -J);
        probed.col(j) = measured_u(pushed) - u0;
      }
      const double scale = probed.cwiseAbs().maxCoeff();
      // The subtraction of speeds up to ~20 loses digits against W's size: the measured
      // column is good to about (speed / W) * 1e-16.
      const double tolerance = 1e-12 * std::max(scale, speed_scale(h));
      const double error = (contact.W - probed).cwiseAbs().maxCoeff();
      worst.see(error / std::max(scale, speed_scale(h)));
      CHECK(error <= tolerance);
      // Symmetric positive semi-definite, as an inverse effective mass is.
      CHECK(contact.W(0, 1) == contact.W(1, 0));
      const Eigen::SelfAdjointEigenSolver<Matrix2d> eigen(contact.W);
      CHECK(eigen.eigenvalues().minCoeff() >= -1e-14 * scale);
    }
  }
}

TEST_CASE("det W from the bodies keeps the digits that W's entries lose", "[friction]") {
  // A rigid body on a static floor: W = (1/m) I + g g^T / I with g = (det(r, n), -det(r, t)),
  // |g| = |r| (n and t are orthonormal), so det W = (1/m)(1/m + |r|^2 / I) by the matrix
  // determinant lemma. A heavy body (m = 1000) with a small moment of inertia (I = 1e-6) at the
  // arm r = (-0.6, -0.8) from a floor of normal (0, -1): g = (0.6, -0.8), so W is near
  // 1e6 [[0.36, -0.48], [-0.48, 0.64]], W_nn W_tt near 2.3e11, and det W is
  // 1e-3 (1e-3 + 1e6) = 1000.000001. The difference of the products would keep about
  // 16 - 8 = 8 digits of it; the bodies' form keeps them all.
  const impulse::rigid_2d::RigidBody heavy{1000.0, 1e-6, {0.6, 0.8}, {100.0, -50.0}, 0.0};
  const auto contact = friction::dynamics(heavy, StaticBody{}, Vector2d(0, 0), Vector2d(0, -1));
  const double expected = 1e-3 * (1e-3 + 1.0 / 1e-6);
  REQUIRE(contact.determinant.has_value());
  CHECK(*contact.determinant == Approx(expected).epsilon(1e-14));
  CHECK(contact.W(0, 0) * contact.W(1, 1) > 1e8 * expected);  // the cancellation it avoids
}

TEST_CASE("apply gives the bumper -n P_n + t P_t and the wedge the opposite", "[friction]") {
  for (const Pairing pairing : pairings) {
    CAPTURE(name(pairing));
    impulse::test::Sampler sample(std::string("friction apply ") + name(pairing));
    for (int i = 0; i < impulse::test::configurations; ++i) {
      const Hit h = random_hit(sample, pairing);
      friction::ContactImpulse impulse;
      impulse.normal = sample.uniform(0, 10);
      impulse.tangential = sample.uniform(-10, 10);
      CAPTURE(i, impulse.normal, impulse.tangential);
      const Vector2d J =
          -h.normal * impulse.normal + friction::tangent(h.normal) * impulse.tangential;
      CHECK(friction::on_bumper(h.normal, impulse) == J);
      Hit expected = h;
      push(expected.bumper, h.point, J);
      push(expected.wedge, h.point, -J);
      const friction::Pair after = friction::apply(h.bumper, h.wedge, h.point, h.normal, impulse);
      for (const auto& [got, want] :
           {std::pair{&after.bumper, &expected.bumper}, std::pair{&after.wedge, &expected.wedge}}) {
        CHECK(got->index() == want->index());
        const double p_scale = momentum(*want).norm() + J.norm();
        CHECK((momentum(*got) - momentum(*want)).norm() <= 1e-14 * p_scale);
        if (const auto* rigid = std::get_if<impulse::rigid_2d::RigidBody>(got)) {
          const auto& other = std::get<impulse::rigid_2d::RigidBody>(*want);
          CHECK(std::abs(rigid->L - other.L) <=
                1e-14 * (std::abs(other.L) + J.norm() * (h.point - other.position).norm()));
        }
      }
    }
  }
}

TEST_CASE("Bad bodies, points and normals are refused by name", "[friction]") {
  const impulse::material_2d::PointMass ball{1.0, {0, -1}};
  const impulse::material_2d::PointMass bad{-1.0, {0, -1}};
  const friction::ContactLaw law{0.5, Elasticity(2.0), friction::RestitutionLaw::newton};
  CHECK_THROWS_MATCHES(friction::collide(bad, StaticBody{}, Vector2d(0, 0), down, law),
                       InvalidInput,
                       Catch::Message("bumper.mass must be positive and finite, got -1"));
  CHECK_THROWS_WITH(friction::collide(ball, bad, Vector2d(0, 0), down, law),
                    Contains("wedge.mass") && Contains("got -1"));
  CHECK_THROWS_WITH(friction::collide(ball, StaticBody{}, Vector2d(0, 0), Vector2d(0, -2), law),
                    Contains("normal must be a unit vector") && Contains("of length 2"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(friction::collide(ball, StaticBody{}, Vector2d(nan, 0), down, law),
                    Contains("point must be finite"));
  friction::ContactImpulse infinite;
  infinite.normal = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(friction::apply(ball, StaticBody{}, Vector2d(0, 0), down, infinite),
                    Contains("impulse must be finite"));
}

TEST_CASE("A collision that is not resolved leaves the bodies as they were", "[friction]") {
  // Moving apart (the ball rises from the floor): no impulse, nothing applied.
  const impulse::material_2d::PointMass rising{1.0, {0.3, 1.0}};
  const auto c = friction::collide(rising, StaticBody{}, Vector2d(0, 0), Vector2d(0, -1),
                                   {0.5, Elasticity(2.0), friction::RestitutionLaw::newton});
  CHECK(c.impulse.status == friction::ContactStatus::not_approaching);
  CHECK(std::get<impulse::material_2d::PointMass>(c.after.bumper).p == rising.p);
}
