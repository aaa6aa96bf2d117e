// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: Coulomb friction at many contacts as one complementarity problem
// (impulse/methods/friction_complementarity.hpp), and Lemke's method on a general problem. Every
// expected value is worked by hand in the comment above it, or is a law checked on the bodies.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "friction/physics.hpp"
#include "impulse/core/error.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
#include "support/sampling.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::Message;
using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::methods::friction_residual;
using impulse::methods::friction_system;
using impulse::methods::LcpStatus;
using impulse::methods::lemke_lcp;
using impulse::methods::LemkeEnd;
using impulse::methods::resolve_friction_complementarity;
using impulse::multipoint::Body;
using impulse::multipoint::Configuration;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
using impulse::rigid_2d::RigidBody;
namespace tf = impulse::test::friction;

namespace {

Configuration configuration(std::vector<Body> bodies, double e, std::vector<Contact> contacts) {
  const std::vector<Elasticity> elasticities(bodies.size(), Elasticity(e));
  return {std::move(bodies), elasticities, std::move(contacts)};
}

// The box of tutorials/scenes/box-lands-flat.json: 2 wide, 1 high, m = 1, I = (4 + 1)/12 = 5/12,
// centre (0, 0.5), corners on the ground at (-1, 0) and (1, 0). The ground is the bumper, its
// outward normal n = (0, 1), so t = [-n_y, n_x] = (-1, 0) and the box (the wedge) receives
// -(-n P_n + t P_t) = (P_t, P_n) at each corner.
Configuration box(const Vector2d& velocity, double e = 1.5) {
  RigidBody b;
  b.mass = 1.0;
  b.inertia = 5.0 / 12.0;
  b.position = {0.0, 0.5};
  b.p = velocity;
  return configuration({StaticBody{}, b}, e,
                       {{0, 1, {0.0, 1.0}, {-1.0, 0.0}}, {0, 1, {0.0, 1.0}, {1.0, 0.0}}});
}

const RigidBody& rigid(const std::vector<Body>& bodies, std::size_t i) {
  return std::get<RigidBody>(bodies[i]);
}

}  // namespace

TEST_CASE("Lemke on a general problem: a solution, a ray, degenerate rows, bad input",
          "[methods][friction]") {
  SECTION("a skew M: w1 = z2 - 1, w2 = 2 - z1") {
    // w1 >= 0 needs z2 >= 1 > 0, so w2 = 0 and z1 = 2 > 0, so w1 = 0 and z2 = 1: the only
    // solution is z = (2, 1), w = 0.
    MatrixXd M(2, 2);
    M << 0, 1, -1, 0;
    const auto r = lemke_lcp(M, Eigen::Vector2d(-1, 2));
    REQUIRE(r.end == LemkeEnd::solution);
    CHECK(r.z(0) == Approx(2.0).margin(1e-14));
    CHECK(r.z(1) == Approx(1.0).margin(1e-14));
    CHECK(r.w.cwiseAbs().maxCoeff() < 1e-14);
  }
  SECTION("no solution: w = -z - 1 < 0 for every z >= 0, so Lemke ends on a ray") {
    const auto r = lemke_lcp(MatrixXd::Constant(1, 1, -1.0), VectorXd::Constant(1, -1.0));
    CHECK(r.end == LemkeEnd::ray);
  }
  SECTION("degenerate rows (q_i = 0, as the friction rows are) end at a solution") {
    // w = z + q with q = (-1, 0, 0): z = (1, 0, 0), w = 0 (every row degenerate at the end).
    const auto r = lemke_lcp(MatrixXd::Identity(3, 3), Eigen::Vector3d(-1, 0, 0));
    REQUIRE(r.end == LemkeEnd::solution);
    CHECK(r.z(0) == Approx(1.0));
    CHECK(r.z.tail(2).cwiseAbs().maxCoeff() == 0.0);
  }
  SECTION("q >= 0: z = 0 without a pivot") {
    const auto r = lemke_lcp(MatrixXd::Identity(2, 2), Eigen::Vector2d(0, 1));
    CHECK(r.end == LemkeEnd::solution);
    CHECK(r.pivots == 0);
    CHECK(r.z.isZero());
  }
  SECTION("bad input") {
    CHECK_THROWS_AS(lemke_lcp(MatrixXd::Identity(2, 3), Eigen::Vector2d(0, 1)), InvalidInput);
    MatrixXd M = MatrixXd::Identity(2, 2);
    M(0, 1) = std::numeric_limits<double>::infinity();
    CHECK(lemke_lcp(M, Eigen::Vector2d(-1, 1)).end == LemkeEnd::non_finite);
  }
}

TEST_CASE("Friction LCP: one point mass on a rough floor agrees with the exact rule",
          "[methods][friction]") {
  // A point mass (m = 1) is the bumper, its outward normal n = (0, -1), t = (1, 0); W = I,
  // u0 = (-1, v_x) (separation -1, slip v_x), e = 1.5, Newton: a pushing contact leaves at
  // separation 0.5, so P_n = 1.5.
  const auto ball = [](double vx) {
    return configuration({impulse::material_2d::PointMass{1.0, {vx, -1.0}}, StaticBody{}}, 1.5,
                         {{0, 1, {0.0, -1.0}, {0.0, 0.0}}});
  };
  SECTION("sliding throughout: v = (1, -1), μ = 0.2") {
    // Slides forwards: P_t = -0.2 * 1.5 = -0.3, slip after 1 - 0.3 = 0.7 > 0 (still forwards).
    const std::vector<double> mu{0.2};
    const auto r = resolve_friction_complementarity(ball(1.0), mu);
    REQUIRE(r.solution.status == LcpStatus::solved);
    CHECK(r.solution.normal(0) == Approx(1.5));
    CHECK(r.solution.tangential(0) == Approx(-0.3));
    const auto exact = impulse::friction::collide(
        ball(1.0).bodies()[0], StaticBody{}, Vector2d::Zero(), {0.0, -1.0}, {0.2, Elasticity(1.5)});
    CHECK(r.solution.normal(0) == Approx(exact.impulse.normal));
    CHECK(r.solution.tangential(0) == Approx(exact.impulse.tangential));
    CHECK(tf::velocity_at(r.after[0], Vector2d::Zero()).isApprox(Vector2d(0.7, 0.5)));
  }
  SECTION("sticking: v = (0.5, -1), μ = 1") {
    // Stick: slip after 0.5 + P_t = 0, P_t = -0.5, |P_t| <= 1 * 1.5. (The exact rule: the slip
    // stops at P_n = 0.5, then it sticks; the same totals.)
    const std::vector<double> mu{1.0};
    const auto r = resolve_friction_complementarity(ball(0.5), mu);
    REQUIRE(r.solution.status == LcpStatus::solved);
    CHECK(r.solution.normal(0) == Approx(1.5));
    CHECK(r.solution.tangential(0) == Approx(-0.5));
    const auto exact = impulse::friction::collide(
        ball(0.5).bodies()[0], StaticBody{}, Vector2d::Zero(), {0.0, -1.0}, {1.0, Elasticity(1.5)});
    CHECK(exact.impulse.outcome == impulse::friction::Slip::stick);
    CHECK(r.solution.tangential(0) == Approx(exact.impulse.tangential));
    CHECK(tf::velocity_at(r.after[0], Vector2d::Zero()).isApprox(Vector2d(0.0, 0.5)));
  }
}

TEST_CASE("Friction LCP: W from the paper's blocks, as the friction core has it for one contact",
          "[methods][friction]") {
  impulse::test::Sampler sample("friction-lcp-W");
  for (int k = 0; k < 100; ++k) {
    const tf::Hit h = tf::random_hit(sample, tf::Pairing::rigid_static);
    const Configuration c({h.bumper, h.wedge}, {Elasticity(1.5), Elasticity(1.5)},
                          {{0, 1, h.normal, h.point}});
    const std::vector<double> mu{0.3};
    const auto s = friction_system(c, mu);
    const auto d = impulse::friction::dynamics(h.bumper, h.wedge, h.point, h.normal);
    CHECK((s.W - d.W).cwiseAbs().maxCoeff() <= 1e-12 * d.W.cwiseAbs().maxCoeff());
    CHECK((s.u0 - d.u0).cwiseAbs().maxCoeff() <= 1e-12 * (1 + d.u0.cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("Friction LCP: one contact, random, agrees with the exact rule unless it reverses",
          "[methods][friction]") {
  // The exact rule's Newton impulse solves the problem when the contact ends sticking (the
  // slip 0 after, |P_t| <= μ P_n) or slides one way throughout (P_t = -s μ P_n); after a reversal
  // |P_t| < μ P_n while it slides, which the problem forbids. For one contact with W positive
  // definite the two agree on the others.
  impulse::test::Sampler sample("friction-lcp-one");
  int compared = 0;
  for (int k = 0; k < impulse::test::configurations; ++k) {
    const auto pairing = sample.coin() ? tf::Pairing::rigid_static : tf::Pairing::rigid;
    const tf::Hit h = tf::random_hit(sample, pairing);
    const double mu = sample.uniform(0.0, 2.0);
    const double e = sample.uniform(1.0, 2.0);
    const auto exact =
        impulse::friction::collide(h.bumper, h.wedge, h.point, h.normal, {mu, Elasticity(e)});
    if (exact.impulse.status != impulse::friction::ContactStatus::resolved ||
        exact.impulse.outcome == impulse::friction::Slip::reversed) {
      continue;
    }
    const Configuration c({h.bumper, h.wedge}, {Elasticity(e), Elasticity(e)},
                          {{0, 1, h.normal, h.point}});
    const std::vector<double> mus{mu};
    const auto r = resolve_friction_complementarity(c, mus);
    CAPTURE(k, mu, e);
    REQUIRE(r.solution.status == LcpStatus::solved);
    const double scale = std::abs(exact.impulse.normal) + std::abs(exact.impulse.tangential);
    CHECK(std::abs(r.solution.normal(0) - exact.impulse.normal) <= 1e-8 * scale);
    CHECK(std::abs(r.solution.tangential(0) - exact.impulse.tangential) <= 1e-8 * scale);
    ++compared;
  }
  CHECK(compared > impulse::test::configurations / 3);
}

TEST_CASE("Friction LCP: the box landing flat on two corners, no tangential speed",
          "[methods][friction]") {
  // Frictionless, by the paper: the box's own normal at each corner is (0, -1), arms
  // r = (∓1, -0.5), det(r, n) = ±1, so A = [[1 + 12/5, 1 - 12/5], [1 - 12/5, 1 + 12/5]] =
  // [[3.4, -1.4], [-1.4, 3.4]], B = 1.5 (1, 1): F = 1.5 / 2 = 0.75 each. The box leaves at
  // (0, -1 + 1.5) = (0, 0.5) without spin, so neither corner slips: P_t = 0 satisfies Coulomb's
  // law at every μ, and the frictionless answer is a solution with μ = 0.5.
  const Configuration c = box({0.0, -1.0});
  const std::vector<double> mu{0.5, 0.5};
  const auto r = resolve_friction_complementarity(c, mu);
  REQUIRE(r.solution.status == LcpStatus::solved);
  CHECK(r.solution.least_norm);
  CHECK(r.solution.normal(0) == Approx(0.75));
  CHECK(r.solution.normal(1) == Approx(0.75));
  CHECK(r.solution.tangential.cwiseAbs().maxCoeff() < 1e-12);
  CHECK(rigid(r.after, 1).p.isApprox(Vector2d(0.0, 0.5)));
  CHECK(std::abs(rigid(r.after, 1).L) < 1e-12);

  // The squeeze: equal and opposite friction ±f at the corners gives the box the force 0 and
  // the torque det((-1, -0.5), (f, 0)) + det((1, -0.5), (-f, 0)) = 0.5 f - 0.5 f = 0, so every
  // |f| <= μ 0.75 = 0.375 solves the problem too, with the same bodies after.
  const auto system = friction_system(c, mu);
  double scale = 0.0;
  for (const double f : {0.1, 0.375}) {
    CHECK(friction_residual(system, Eigen::Vector2d(0.75, 0.75), Eigen::Vector2d(f, -f), scale) <
          1e-14);
  }
  CHECK(friction_residual(system, Eigen::Vector2d(0.75, 0.75), Eigen::Vector2d(0.4, -0.4),
                          scale) > 0.01);  // beyond μ P_n: Coulomb's bound broken

  // Lemke's own vertex (no least-norm choice) may report a squeeze; the bodies after are the
  // same.
  const auto vertex = resolve_friction_complementarity(c, mu, 1e-10, false);
  REQUIRE(vertex.solution.status == LcpStatus::solved);
  CHECK(std::abs(vertex.solution.tangential(0) + vertex.solution.tangential(1)) < 1e-12);
  CHECK(rigid(vertex.after, 1).p.isApprox(rigid(r.after, 1).p, 1e-12));
  CHECK(std::abs(rigid(vertex.after, 1).L - rigid(r.after, 1).L) < 1e-12);
}

TEST_CASE("Friction LCP: the box landing flat and stopping to stick: the least-norm share",
          "[methods][friction]") {
  // Velocity (0.2, -1), μ = 0.5. Suppose both corners push and stick: the corners' horizontal
  // velocity v_x' + 0.5 ω' = 0 and vertical v_y' ∓ ω' = 0.5 give ω' = 0, v' = (0, 0.5), so
  // P_t,0 + P_t,1 = -0.2 and P_n,0 + P_n,1 = 1.5; no torque: -P_n0 + 0.5 P_t0 + P_n1 + 0.5 P_t1 =
  // 0, P_n1 - P_n0 = 0.1: P_n = (0.7, 0.8). Coulomb allows any split of -0.2 with |P_t0| <= 0.35,
  // |P_t1| <= 0.4 (the squeeze again): the least-norm one is (-0.1, -0.1). KE 0.52 -> 0.125.
  const Configuration c = box({0.2, -1.0});
  const std::vector<double> mu{0.5, 0.5};
  const auto r = resolve_friction_complementarity(c, mu);
  REQUIRE(r.solution.status == LcpStatus::solved);
  CHECK(r.solution.least_norm);
  CHECK(r.solution.normal(0) == Approx(0.7));
  CHECK(r.solution.normal(1) == Approx(0.8));
  CHECK(r.solution.tangential(0) == Approx(-0.1));
  CHECK(r.solution.tangential(1) == Approx(-0.1));
  CHECK(rigid(r.after, 1).p.isApprox(Vector2d(0.0, 0.5)));
  CHECK(std::abs(rigid(r.after, 1).L) < 1e-12);
  CHECK(impulse::multipoint::kinetic_energy(r.after) == Approx(0.125));
  // Lemke's own vertex shares it otherwise (all at one corner, as pivoting does); the same
  // normal impulses, the same sum of friction, the same bodies after.
  const auto vertex = resolve_friction_complementarity(c, mu, 1e-10, false);
  REQUIRE(vertex.solution.status == LcpStatus::solved);
  CHECK(vertex.solution.normal.isApprox(r.solution.normal, 1e-12));
  CHECK(vertex.solution.tangential.sum() == Approx(-0.2));
  CHECK(rigid(vertex.after, 1).p.isApprox(rigid(r.after, 1).p, 1e-12));
  CHECK(std::abs(rigid(vertex.after, 1).L - rigid(r.after, 1).L) < 1e-12);
}

TEST_CASE("Friction LCP: the box sliding flat on two corners", "[methods][friction]") {
  // Velocity (1, -1), no spin, μ = 0.5, e = 1.5. Suppose both corners push and slide forwards
  // (+x): the box gets (P_t,v, P_n,v) at corner v with P_t,v = -μ P_n,v. Newton at both corners
  // (vertical corner velocities v_y' ∓ ω' both 0.5): ω' = 0, v_y' = 0.5, so
  // P_n,0 + P_n,1 = 1.5. Torque: det((-1, -0.5), (P_t0, P_n0)) + det((1, -0.5), (P_t1, P_n1)) =
  // -P_n0 - 0.5 μ P_n0 + P_n1 - 0.5 μ P_n1 = 0, so P_n1 - P_n0 = 0.5 μ 1.5 = 0.375:
  // P_n = (0.5625, 0.9375), P_t = (-0.28125, -0.46875). Then v_x' = 1 - 0.75 = 0.25 > 0: both
  // still slide forwards, as supposed; every condition holds. KE 1 -> (0.0625 + 0.25)/2.
  const Configuration c = box({1.0, -1.0});
  const std::vector<double> mu{0.5, 0.5};
  const auto r = resolve_friction_complementarity(c, mu);
  REQUIRE(r.solution.status == LcpStatus::solved);
  CHECK(r.solution.normal(0) == Approx(0.5625));
  CHECK(r.solution.normal(1) == Approx(0.9375));
  CHECK(r.solution.tangential(0) == Approx(-0.28125));
  CHECK(r.solution.tangential(1) == Approx(-0.46875));
  CHECK(rigid(r.after, 1).p.isApprox(Vector2d(0.25, 0.5)));
  CHECK(std::abs(rigid(r.after, 1).L) < 1e-12);
  CHECK(impulse::multipoint::kinetic_energy(r.after) == Approx(0.15625));
}

TEST_CASE("Friction LCP: bad input is refused", "[methods][friction]") {
  const Configuration c = box({0.0, -1.0});
  CHECK_THROWS_MATCHES(friction_system(c, std::vector<double>{0.5}), InvalidInput,
                       Message("friction needs one coefficient per contact (2), got 1"));
  CHECK_THROWS_MATCHES(friction_system(c, std::vector<double>{0.5, -1.0}), InvalidInput,
                       Message("friction[1] must be finite and at least 0, got -1"));
  auto s = friction_system(c, std::vector<double>{0.5, 0.5});
  CHECK_THROWS_WITH(impulse::methods::solve_friction(s, 0.0), Contains("tolerance"));
  s.u0.resize(3);
  CHECK_THROWS_WITH(impulse::methods::solve_friction(s), Contains("needs W 2N x 2N"));
}

namespace {

// A random scene of several contacts: a rigid body resting on a static floor at 2 or 3 points
// (normal up), and sometimes a second body (rigid or a point mass) striking it at a point of its
// top. Velocities random; every body at elasticity e.
struct Scene {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

Scene random_scene(impulse::test::Sampler& sample) {
  Scene s;
  RigidBody box;
  box.mass = sample.log_uniform(0.1, 10.0);
  box.inertia = sample.log_uniform(0.01, 10.0);
  box.position = {sample.uniform(-0.5, 0.5), sample.uniform(0.2, 1.0)};
  box.p = box.mass * Vector2d(sample.uniform(-2.0, 2.0), sample.uniform(-2.0, 0.0));
  box.L = box.inertia * sample.uniform(-2.0, 2.0);
  s.bodies = {StaticBody{}, box};
  const int corners = sample.integer(2, 3);
  for (int k = 0; k < corners; ++k) {
    s.contacts.push_back({0, 1, {0.0, 1.0}, {sample.uniform(-1.5, 1.5), 0.0}});
  }
  if (sample.coin()) {
    const Vector2d top = box.position + Vector2d(sample.uniform(-0.5, 0.5), 0.5);
    const Vector2d n = Vector2d(sample.uniform(-0.7, 0.7), -1.0).normalized();  // out of it, down
    if (sample.coin()) {
      s.bodies.push_back(
          impulse::material_2d::PointMass{sample.log_uniform(0.1, 10.0), sample.vector(2.0)});
    } else {
      RigidBody other;
      other.mass = sample.log_uniform(0.1, 10.0);
      other.inertia = sample.log_uniform(0.01, 10.0);
      other.position = top + Vector2d(sample.uniform(-0.5, 0.5), 0.5);
      other.p = other.mass * sample.vector(2.0);
      other.L = other.inertia * sample.uniform(-2.0, 2.0);
      s.bodies.push_back(other);
    }
    s.contacts.push_back({2, 1, n, top});
  }
  return s;
}

}  // namespace

TEST_CASE("Friction LCP: Coulomb's law, Newton's law and the momenta on random scenes",
          "[methods][friction]") {
  impulse::test::Sampler sample("friction-lcp-random");
  impulse::test::Worst worst("friction LCP conditions on the bodies");
  int gained = 0;
  int solved = 0;
  for (int k = 0; k < impulse::test::configurations; ++k) {
    const Scene scene = random_scene(sample);
    const double e = sample.coin() ? 1.0 : sample.uniform(1.0, 2.0);
    const Configuration c = configuration(scene.bodies, e, scene.contacts);
    std::vector<double> mu;
    for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
      mu.push_back(sample.coin() ? sample.uniform(0.0, 2.0) : 0.5);
    }
    CAPTURE(k, e, mu);
    const auto r = resolve_friction_complementarity(c, mu);
    REQUIRE(r.solution.status == LcpStatus::solved);
    ++solved;
    const VectorXd& Pn = r.solution.normal;
    const VectorXd& Pt = r.solution.tangential;
    const VectorXd before = c.approach(c.bodies());
    const VectorXd after = c.approach(r.after);
    // Speeds and impulses are measured on the bodies, from the definitions (physics.hpp).
    double speed = before.cwiseAbs().maxCoeff();
    // The size of impulses: those found, and the bodies' momenta (an impulse that stops one).
    double impulse = Pn.cwiseAbs().maxCoeff() + Pt.cwiseAbs().maxCoeff();
    for (const Body& b : c.bodies()) {
      impulse += tf::momentum(b).norm();
    }
    for (const Contact& ct : scene.contacts) {
      speed = std::max(speed, tf::speed_scale(c.bodies()[ct.bumper], ct.point) +
                                  tf::speed_scale(c.bodies()[ct.wedge], ct.point) +
                                  tf::speed_scale(r.after[ct.bumper], ct.point) +
                                  tf::speed_scale(r.after[ct.wedge], ct.point));
    }
    std::vector<Body> pushed(c.bodies().begin(), c.bodies().end());
    for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
      const auto i = static_cast<Eigen::Index>(v);
      const Contact& ct = scene.contacts[v];
      const Vector2d t(-ct.normal.y(), ct.normal.x());
      // Coulomb's bound.
      CHECK(std::abs(Pt(i)) <= mu[v] * Pn(i) + 1e-9 * impulse);
      CHECK(Pn(i) >= 0.0);
      // Newton's law: separation after at least (e - 1) times the approach before, exactly so
      // where the contact pushes.
      const double excess = -after(i) - (e - 1.0) * before(i);
      CHECK(excess >= -1e-9 * speed);
      if (Pn(i) > 1e-9 * impulse) {
        CHECK(std::abs(excess) <= 1e-9 * speed);
      }
      worst.see(std::abs(std::min(excess, Pn(i))) / speed);
      // Friction: sticks below the bound; slides only at it, against the slip.
      const double slip = (tf::velocity_at(r.after[ct.bumper], ct.point) -
                           tf::velocity_at(r.after[ct.wedge], ct.point))
                              .dot(t);
      if (std::abs(Pt(i)) < mu[v] * Pn(i) - 1e-9 * impulse) {
        CHECK(std::abs(slip) <= 1e-9 * speed);
      }
      if (std::abs(slip) > 1e-9 * speed) {
        CHECK(std::abs(Pt(i)) >= mu[v] * Pn(i) - 1e-9 * impulse);
        CHECK(Pt(i) * slip <= 0.0);
      }
      // The impulse on each body, from the definitions: p += J, L += det(r, J).
      const Vector2d J = -ct.normal * Pn(i) + t * Pt(i);
      tf::push(pushed[ct.bumper], ct.point, J);
      tf::push(pushed[ct.wedge], ct.point, -J);
    }
    // Each body's momentum and angular momentum changed by exactly its impulses.
    for (std::size_t b = 1; b < pushed.size(); ++b) {
      const double p_scale = tf::momentum(c.bodies()[b]).norm() + impulse;
      CHECK((tf::momentum(pushed[b]) - tf::momentum(r.after[b])).norm() <= 1e-12 * p_scale);
      CHECK(std::abs(tf::angular_momentum_about(pushed[b], Vector2d::Zero()) -
                     tf::angular_momentum_about(r.after[b], Vector2d::Zero())) <=
            1e-12 * (p_scale * 10 +
                     std::abs(tf::angular_momentum_about(c.bodies()[b], Vector2d::Zero()))));
    }
    // Energy. At e = 1 it is never gained: with u' the velocities after,
    // ΔE = P·u0 + ½ PᵀWP = P·u' - ½ PᵀWP, and P·u' = Σ P_n u'_n + P_t u'_t = 0 - Σ μ P_n |u'_t|
    // (a pushing contact leaves at separation 0; friction opposes the slip), so ΔE <= 0. Above
    // e = 1 Newton's law may gain (Kane and Levinson's paradox); counted, not forbidden.
    const double E0 = impulse::multipoint::kinetic_energy(c.bodies());
    const double E1 = impulse::multipoint::kinetic_energy(r.after);
    if (e == 1.0) {
      CHECK(E1 <= E0 * (1 + 1e-12) + 1e-15);
    } else if (E1 > E0 * (1 + 1e-12)) {
      ++gained;
    }
  }
  CHECK(solved == impulse::test::configurations);
  WARN("Newton's law gained energy in " << gained << " of " << solved << " random scenes");
}

TEST_CASE("Friction LCP: with μ = 0 the bodies after are the frictionless complementarity's",
          "[methods][friction]") {
  // With μ = 0 the bound row forces λ+ = λ- = 0 and the normal rows are the frictionless problem
  // w = A F - B; that problem's bodies after are unique (A F is), whichever impulses give them.
  impulse::test::Sampler sample("friction-lcp-mu0");
  for (int k = 0; k < impulse::test::configurations; ++k) {
    const Scene scene = random_scene(sample);
    const double e = sample.uniform(1.0, 2.0);
    const Configuration c = configuration(scene.bodies, e, scene.contacts);
    const std::vector<double> mu(scene.contacts.size(), 0.0);
    const auto r = resolve_friction_complementarity(c, mu);
    // The frictionless method by its default algorithm (the active-set method on the factor: a
    // different algorithm on a different problem).
    const auto frictionless =
        impulse::methods::resolve_complementarity(c.bodies(), Elasticity(e), c.contacts());
    CAPTURE(k, e, r.solution.residual, r.solution.scale);
    REQUIRE(frictionless.solution.status == LcpStatus::solved);
    REQUIRE(r.solution.status == LcpStatus::solved);
    CHECK(r.solution.tangential.isZero());
    for (std::size_t b = 1; b < r.after.size(); ++b) {
      const double scale = tf::speed_scale(c.bodies()[b], Vector2d::Zero()) +
                           tf::speed_scale(r.after[b], Vector2d::Zero()) + 1.0;
      const Vector2d x = scene.contacts.front().point;
      CHECK((tf::velocity_at(r.after[b], x) - tf::velocity_at(frictionless.after[b], x)).norm() <=
            1e-9 * scale);
      CHECK(std::abs(tf::energy(r.after[b]) - tf::energy(frictionless.after[b])) <=
            1e-9 * (tf::energy(c.bodies()[b]) + 1.0));
    }
  }
}
