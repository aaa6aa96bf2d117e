// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: one contact with Coulomb friction, followed through the normal impulse.
// Every expected value below is worked by hand in the comment above it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "impulse/core/error.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/friction/contact.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "physics.hpp"

using Catch::Matchers::Contains;
using Eigen::Matrix2d;
using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::friction::ContactDynamics;
using impulse::friction::ContactImpulse;
using impulse::friction::ContactLaw;
using impulse::friction::ContactStatus;
using impulse::friction::RestitutionLaw;
using impulse::friction::Slip;
using impulse::material_2d::PointMass;
using impulse::multipoint::StaticBody;
using impulse::rigid_2d::RigidBody;
using impulse::test::friction::all_laws;
using impulse::test::friction::down;
namespace friction = impulse::friction;

namespace {

Matrix2d matrix(double nn, double nt, double tt) {
  Matrix2d W;
  W << nn, nt, nt, tt;
  return W;
}

// The uniform rod of the issue: m = 1, L = 1, I = m L^2 / 12 = 1/12, at 45 degrees, its lower
// end at the origin on the floor and its centre up and to the right, at (h, h) with
// h = (L/2) sin 45 = sqrt(2)/4; centre velocity (0.7, -1), no spin. The arm of the contact is
// r = (-h, -h). The rod leans the way it moves.
RigidBody rod() {
  const double h = std::numbers::sqrt2 / 4;
  return {1.0, 1.0 / 12.0, {h, h}, {0.7, -1.0}, 0.0};
}

double energy_of(const impulse::multipoint::Body& body) {
  return impulse::multipoint::kinetic_energy(body);
}

}  // namespace

TEST_CASE("A point mass sliding on a rough floor throughout: the three laws agree", "[friction]") {
  // m = 2, v = (3, -1), mu = 0.2, elasticity 1.5. W = I / m = diag(0.5, 0.5) (no coupling), and
  // u0 = (separation, slip) = (-1, 3). Slipping along +t, dP_t = -0.2 dP_n, so
  // du_n/dP_n = 0.5 and du_t/dP_n = -0.2 * 0.5 = -0.1: the slip would stop only at
  // P_n = 3 / 0.1 = 30, compression ends at P_n = 1 / 0.5 = 2.
  // Newton: the separation 0.5 * 1 = 0.5 is reached 0.5 / 0.5 = 1 later, at P_n = 3.
  // Poisson: 1.5 * 2 = 3. Energetic: compression's work is -(1/2)(1)(2) = -1; restitution's
  // 0.5^2 * 1 = 0.25 = x^2 / 4 after x = 1, again P_n = 3.
  // So P_n = 3 < 30: it slides throughout, P_t = -0.2 * 3 = -0.6, and the velocity after is
  // v + (P_t, P_n) / m = (3 - 0.3, -1 + 1.5) = (2.7, 0.5).
  const PointMass ball{2.0, {6.0, -2.0}};
  for (const RestitutionLaw law : all_laws) {
    CAPTURE(impulse::name_of(law));
    const auto c = friction::collide(ball, StaticBody{}, Vector2d(0, 0), down,
                                     ContactLaw{0.2, Elasticity(1.5), law});
    REQUIRE(c.impulse.status == ContactStatus::resolved);
    CHECK(c.impulse.normal == Approx(3.0).epsilon(1e-14));
    CHECK(c.impulse.tangential == Approx(-0.6).epsilon(1e-14));
    CHECK(c.impulse.compression == Approx(2.0).epsilon(1e-14));
    REQUIRE(c.impulse.phases().size() == 1);
    CHECK(c.impulse.phases()[0].regime == Slip::slip);
    CHECK(c.impulse.phases()[0].direction == 1.0);
    CHECK(c.impulse.outcome == Slip::slip);
    const auto& after = std::get<PointMass>(c.after.bumper);
    CHECK(impulse::material_2d::velocity(after).isApprox(Vector2d(2.7, 0.5), 1e-14));
    // Works: compression -1 (above); restitution (1/2)(0.5)(1) = 0.25; friction: u_t falls
    // linearly from 3 to 3 - 0.1 * 3 = 2.7 while P_t goes to -0.6: -0.6 * 2.85 = -1.71.
    CHECK(c.impulse.work_compression == Approx(-1.0).epsilon(1e-14));
    CHECK(c.impulse.work_restitution == Approx(0.25).epsilon(1e-14));
    CHECK(c.impulse.work_tangential == Approx(-1.71).epsilon(1e-14));
    // Kinetic energy (1/2)(2)(9 + 1) = 10 before, (1/2)(2)(7.29 + 0.25) = 7.54 after: -2.46,
    // the sum of the works.
    CHECK(energy_of(after) == Approx(7.54).epsilon(1e-14));
  }
}

TEST_CASE("A point mass that stops slipping and sticks: the three laws agree", "[friction]") {
  // m = 2, v = (0.5, -1), mu = 1, elasticity 1.5: W = diag(0.5, 0.5), u0 = (-1, 0.5).
  // Slip: du_t/dP_n = -1 * 0.5 = -0.5, so the slip stops at P_n = 1 with P_t = -1. The stick
  // ratio |W_tn| / W_tt = 0 is within mu: it sticks, dP_t = 0 from then on. The normal motion
  // is that of the frictionless case (W_nt = 0): compression ends at 2, every law at 3.
  // Velocity after: (0.5 - 1/2, -1 + 3/2) = (0, 0.5).
  const PointMass ball{2.0, {1.0, -2.0}};
  for (const RestitutionLaw law : all_laws) {
    CAPTURE(impulse::name_of(law));
    const auto c = friction::collide(ball, StaticBody{}, Vector2d(0, 0), down,
                                     ContactLaw{1.0, Elasticity(1.5), law});
    REQUIRE(c.impulse.status == ContactStatus::resolved);
    CHECK(c.impulse.normal == Approx(3.0).epsilon(1e-14));
    CHECK(c.impulse.tangential == Approx(-1.0).epsilon(1e-14));
    REQUIRE(c.impulse.phases().size() == 2);
    CHECK(c.impulse.phases()[0].regime == Slip::slip);
    CHECK(c.impulse.phases()[0].end == Approx(1.0).epsilon(1e-14));
    CHECK(c.impulse.phases()[1].regime == Slip::stick);
    CHECK(c.impulse.phases()[1].end == Approx(3.0).epsilon(1e-14));
    CHECK(c.impulse.outcome == Slip::stick);
    CHECK(c.impulse.u_after.y() == 0.0);
    const auto& after = std::get<PointMass>(c.after.bumper);
    CHECK(impulse::material_2d::velocity(after).isApprox(Vector2d(0.0, 0.5), 1e-14));
  }
}

TEST_CASE("The rod at 45 degrees on a rough floor: slip, stick, and three different impulses",
          "[friction]") {
  // The rod above (m = 1, I = 1/12, r = (-h, -h), h^2 = 1/8), mu = 0.8, elasticity 1.9.
  //
  // W. The contact point moves by K J for an impulse J, K = I/m + q q^T / I with
  // q = [-r_y, r_x] = (h, -h): 12 q q^T = 12/8 [[1, -1], [-1, 1]], K = [[2.5, -1.5], [-1.5, 2.5]].
  // In the frame (-n, t) = ((0, 1), (1, 0)): W_nn = K_yy = 2.5 (the paper's A: 1/m +
  // det(r, n)^2 / I = 1 + 12/8), W_nt = K_yx = -1.5, W_tt = K_xx = 2.5.
  // u0: the end moves at (0.7, -1): separation -1, slip 0.7 along t.
  //
  // Slip along +t, dP_t = -0.8 dP_n: du_n/dP_n = 2.5 + 0.8 * 1.5 = 3.7,
  // du_t/dP_n = -1.5 - 0.8 * 2.5 = -3.5. The slip stops at P_n = 0.7 / 3.5 = 0.2, where
  // u_n = -1 + 0.74 = -0.26 and P_t = -0.16.
  // Stick: the ratio |W_tn| / W_tt = 0.6 is within 0.8, so it sticks with dP_t = 0.6 dP_n;
  // du_n/dP_n = 2.5 - 1.5 * 0.6 = 1.6 (= W_nn - W_nt^2 / W_tt). Compression ends at
  // P_n = 0.2 + 0.26 / 1.6 = 0.3625 (as the issue says).
  // Works of compression: (0.2)(-1 - 0.26)/2 = -0.126 in slip, (0.1625)(-0.26)/2 = -0.021125 in
  // stick: -0.147125. Friction's work: -0.16 * (0.7 + 0)/2 = -0.056 (none while sticking).
  //
  // Newton: separation (1.9 - 1) * 1 = 0.9 after 0.9 / 1.6 = 0.5625 more: P_n = 0.925,
  //   P_t = -0.16 + 0.6 * 0.725 = 0.275; restitution's work 0.5625 * 0.9 / 2 = 0.253125;
  //   energy change -0.147125 + 0.253125 - 0.056 = +0.05: Newton's law GAINS energy.
  // Poisson: P_n = 1.9 * 0.3625 = 0.68875; x = 0.32625 of restitution, P_t = -0.16 +
  //   0.6 * 0.48875 = 0.13325; work 0.8 x^2 = 0.08515125; change -0.11797375.
  // Energetic: restitution's work 0.81 * 0.147125 = 0.11917125 = 0.8 x^2, so
  //   x^2 = 0.1489640625, x = 0.385958627964..., P_n = 0.748458627964...,
  //   P_t = -0.16 + 0.6 (0.1625 + x) = 0.169075176778...; change -0.147125 + 0.11917125 -
  //   0.056 = -0.08395375.
  // Kinetic energy before: (1/2)(0.49 + 1) = 0.745. After, from the rod's own state:
  // v' = (0.7 + P_t, -1 + P_n), L' = det(r, (P_t, P_n)) = -h (P_n - P_t), so
  // E' = |v'|^2 / 2 + 6 L'^2 = |v'|^2 / 2 + (3/4)(P_n - P_t)^2. Newton:
  // (0.975^2 + 0.075^2)/2 + 0.75 * 0.65^2 = 0.478125 + 0.316875 = 0.795 = 0.745 + 0.05.
  struct Expected {
    RestitutionLaw law;
    double normal, tangential, energy_after;
  };
  const double x = std::sqrt(0.1489640625);
  const Expected cases[] = {
      {RestitutionLaw::newton, 0.925, 0.275, 0.745 + 0.05},
      {RestitutionLaw::poisson, 0.68875, 0.13325, 0.745 - 0.11797375},
      {RestitutionLaw::energetic, 0.3625 + x, -0.16 + 0.6 * (0.1625 + x), 0.745 - 0.08395375},
  };
  const RigidBody before = rod();
  const Vector2d end(0, 0);

  const ContactDynamics w = friction::dynamics(before, StaticBody{}, end, down);
  CHECK(w.W(0, 0) == Approx(2.5).epsilon(1e-14));
  CHECK(w.W(0, 1) == Approx(-1.5).epsilon(1e-14));
  CHECK(w.W(1, 0) == Approx(-1.5).epsilon(1e-14));
  CHECK(w.W(1, 1) == Approx(2.5).epsilon(1e-14));
  CHECK(w.u0.isApprox(Vector2d(-1.0, 0.7), 1e-15));

  for (const Expected& expected : cases) {
    CAPTURE(impulse::name_of(expected.law));
    const auto c =
        friction::collide(before, StaticBody{}, end, down, {0.8, Elasticity(1.9), expected.law});
    REQUIRE(c.impulse.status == ContactStatus::resolved);
    REQUIRE(c.impulse.phases().size() == 2);
    CHECK(c.impulse.phases()[0].regime == Slip::slip);
    CHECK(c.impulse.phases()[0].end == Approx(0.2).epsilon(1e-14));
    CHECK(c.impulse.phases()[0].tangential == Approx(-0.16).epsilon(1e-14));
    CHECK(c.impulse.phases()[0].u.isApprox(Vector2d(-0.26, 0), 1e-14));
    CHECK(c.impulse.phases()[1].regime == Slip::stick);
    CHECK(c.impulse.phases()[1].end == Approx(expected.normal).epsilon(1e-14));
    CHECK(c.impulse.phases()[1].tangential == Approx(expected.tangential).epsilon(1e-14));
    CHECK(c.impulse.phases()[1].u == c.impulse.u_after);
    CHECK(c.impulse.outcome == Slip::stick);
    CHECK(c.impulse.compression == Approx(0.3625).epsilon(1e-14));
    CHECK(c.impulse.work_compression == Approx(-0.147125).epsilon(1e-14));
    CHECK(c.impulse.work_tangential == Approx(-0.056).epsilon(1e-14));
    CHECK(c.impulse.normal == Approx(expected.normal).epsilon(1e-14));
    CHECK(c.impulse.tangential == Approx(expected.tangential).epsilon(1e-14));
    const double energy_after = energy_of(c.after.bumper);
    CHECK(energy_after == Approx(expected.energy_after).epsilon(1e-14));
    CHECK(c.impulse.energy_change() == Approx(expected.energy_after - 0.745).epsilon(1e-13));
    if (expected.law == RestitutionLaw::newton) {
      CHECK(energy_after > 0.745);  // the paradox: energy gained at an elasticity below 2
      // The rod's end leaves at (0, 0.9): sticking, and separating at 0.9 * 1.
      const auto& after = std::get<RigidBody>(c.after.bumper);
      CHECK(impulse::rigid_2d::point_velocity(after, end).isApprox(Vector2d(0, 0.9), 1e-14));
    } else {
      CHECK(energy_after < 0.745);
    }
  }
}

TEST_CASE("The rod on a floor of little friction: the slip reverses", "[friction]") {
  // The rod above with mu = 0.3, elasticity 1.9, Newton's law.
  // Slip along +t: du_n/dP_n = 2.5 + 0.3 * 1.5 = 2.95, du_t/dP_n = -1.5 - 0.3 * 2.5 = -2.25.
  // The slip stops at P_n = 0.7 / 2.25 = 14/45, with u_n = -1 + 2.95 * 14/45 = -37/450 and
  // P_t = -0.3 * 14/45. The stick ratio 0.6 exceeds 0.3: the contact slides the other way,
  // dP_t = +0.3 dP_n, du_n/dP_n = 2.5 - 0.3 * 1.5 = 2.05, du_t/dP_n = -1.5 + 0.75 = -0.75.
  // Compression ends at 14/45 + (37/450) / 2.05 = 72/205; the separation 0.9 is reached
  // 0.9 / 2.05 later, at P_n = 162/205. Then P_t = -0.3 * 14/45 + 0.3 (162/205 - 14/45) = 31/615
  // and u_t = -0.75 (162/205 - 14/45) = -221/615.
  const auto c = friction::collide(rod(), StaticBody{}, Vector2d(0, 0), down,
                                   {0.3, Elasticity(1.9), RestitutionLaw::newton});
  REQUIRE(c.impulse.status == ContactStatus::resolved);
  REQUIRE(c.impulse.phases().size() == 2);
  CHECK(c.impulse.phases()[0].regime == Slip::slip);
  CHECK(c.impulse.phases()[0].direction == 1.0);
  CHECK(c.impulse.phases()[0].end == Approx(14.0 / 45.0).epsilon(1e-14));
  CHECK(c.impulse.phases()[0].tangential == Approx(-0.3 * 14.0 / 45.0).epsilon(1e-14));
  CHECK(c.impulse.phases()[0].u.x() == Approx(-37.0 / 450.0).epsilon(1e-13));
  CHECK(c.impulse.phases()[0].u.y() == 0.0);
  CHECK(c.impulse.phases()[1].regime == Slip::reversed);
  CHECK(c.impulse.phases()[1].direction == -1.0);
  CHECK(c.impulse.phases()[1].end == Approx(162.0 / 205.0).epsilon(1e-14));
  CHECK(c.impulse.outcome == Slip::reversed);
  CHECK(c.impulse.compression == Approx(72.0 / 205.0).epsilon(1e-14));
  CHECK(c.impulse.normal == Approx(162.0 / 205.0).epsilon(1e-14));
  CHECK(c.impulse.tangential == Approx(31.0 / 615.0).epsilon(1e-13));
  CHECK(c.impulse.u_after.x() == Approx(0.9).epsilon(1e-14));
  CHECK(c.impulse.u_after.y() == Approx(-221.0 / 615.0).epsilon(1e-14));
}

TEST_CASE("Without friction the rod gets the paper's impulse, and its slip may reverse",
          "[friction]") {
  // mu = 0: no tangential impulse; du_n/dP_n = W_nn = 2.5 throughout, so every law gives the
  // paper's Fdt = B / A = 1.9 * 1 / 2.5 = 0.76 (compression 1 / 2.5 = 0.4). The slip itself
  // changes at du_t/dP_n = W_tn = -1.5: it reaches 0 at P_n = 0.7 / 1.5 = 7/15 and, with no
  // friction to hold it, goes on the other way (reversed).
  for (const RestitutionLaw law : all_laws) {
    CAPTURE(impulse::name_of(law));
    const auto c =
        friction::collide(rod(), StaticBody{}, Vector2d(0, 0), down, {0.0, Elasticity(1.9), law});
    CHECK(c.impulse.normal == Approx(0.76).epsilon(1e-14));
    CHECK(c.impulse.tangential == 0.0);
    CHECK(c.impulse.compression == Approx(0.4).epsilon(1e-14));
    REQUIRE(c.impulse.phases().size() == 2);
    CHECK(c.impulse.phases()[0].end == Approx(7.0 / 15.0).epsilon(1e-14));
    CHECK(c.impulse.outcome == Slip::reversed);
  }
}

TEST_CASE("A huge coefficient of friction: the slip stops at once, without overflow",
          "[friction]") {
  // mu = 1e300: the tangential impulse stops the slip before any normal impulse to speak of:
  // W_tt P_t = -0.7, P_t = -0.28, which moves the separation by W_nt P_t = (-1.5)(-0.28) = 0.42
  // to -0.58. Then it sticks (du_n/dP_n = 1.6): compression ends at 0.58 / 1.6 = 0.3625, where
  // u = 0, so P = -W^-1 u0 = (1/4) [[2.5, 1.5], [1.5, 2.5]] (1, -0.7) = (0.3625, -0.0625) — the
  // same as with mu = 0.8, whose slip also stopped before compression ended. Newton's end, u =
  // (0.9, 0), is then P = W^-1 (u - u0) = (1/4)(2.5 * 1.9 - 1.5 * 0.7, 1.5 * 1.9 - 2.5 * 0.7)
  // = (0.925, 0.275). Compression's work is all in stick: -0.58 * 0.3625 / 2 = -0.105125, and
  // friction's in the jump: -0.28 * 0.7 / 2 = -0.098.
  const auto c = friction::collide(rod(), StaticBody{}, Vector2d(0, 0), down,
                                   {1e300, Elasticity(1.9), RestitutionLaw::newton});
  REQUIRE(c.impulse.status == ContactStatus::resolved);
  REQUIRE(c.impulse.phases().size() == 2);
  CHECK(c.impulse.phases()[0].end < 1e-299);
  CHECK(c.impulse.compression == Approx(0.3625).epsilon(1e-14));
  CHECK(c.impulse.normal == Approx(0.925).epsilon(1e-14));
  CHECK(c.impulse.tangential == Approx(0.275).epsilon(1e-14));
  CHECK(c.impulse.work_compression == Approx(-0.105125).epsilon(1e-14));
  CHECK(c.impulse.work_tangential == Approx(-0.098).epsilon(1e-14));
  CHECK(c.impulse.outcome == Slip::stick);
}

TEST_CASE("With a huge coefficient of friction the energetic law is Poisson's", "[friction]") {
  // As above, the slip stops at once and the whole collision is one stick phase, linear from
  // u_n = -0.58 at slope 1.6. In one linear phase from u_n = -a, the work of compression is
  // -a P_c / 2 and that of restitution 1.6 x^2 / 2 = (a / P_c) x^2 / 2, so the energetic law,
  // (e - 1)^2 a P_c / 2 = (a / P_c) x^2 / 2, gives x = (e - 1) P_c: Poisson's. Both end at
  // 1.9 * 0.3625 = 0.68875.
  for (const RestitutionLaw law : {RestitutionLaw::poisson, RestitutionLaw::energetic}) {
    CAPTURE(impulse::name_of(law));
    const auto c =
        friction::collide(rod(), StaticBody{}, Vector2d(0, 0), down, {1e300, Elasticity(1.9), law});
    CHECK(c.impulse.normal == Approx(0.68875).epsilon(1e-14));
    CHECK(c.impulse.work_restitution == Approx(0.81 * 0.105125).epsilon(1e-14));
  }
}

TEST_CASE("Elasticity 1 ends every law at the end of compression", "[friction]") {
  // Perfectly inelastic: Newton's separation (1 - 1) * 1 = 0 is reached at compression's end,
  // Poisson's 1 * 0.3625 is that impulse, the energetic work 0 * |...| is reached at once.
  for (const RestitutionLaw law : all_laws) {
    CAPTURE(impulse::name_of(law));
    const auto c =
        friction::collide(rod(), StaticBody{}, Vector2d(0, 0), down, {0.8, Elasticity(1.0), law});
    CHECK(c.impulse.normal == Approx(0.3625).epsilon(1e-14));
    CHECK(c.impulse.u_after.isZero(1e-14));
    CHECK(c.impulse.work_restitution == 0.0);
  }
}

TEST_CASE("Degenerate contacts are reported, not guessed", "[friction]") {
  const ContactLaw newton{0.5, Elasticity(2.0), RestitutionLaw::newton};
  SECTION("bodies that do not approach get no impulse") {
    const auto r = friction::resolve_contact({matrix(1, 0, 1), Vector2d(0.5, 1.0)}, newton);
    CHECK(r.status == ContactStatus::not_approaching);
    CHECK(r.normal == 0.0);
    CHECK(r.tangential == 0.0);
    CHECK(r.phases().empty());
    CHECK(r.outcome == Slip::slip);  // it slides at 1 and nothing stops it
    CHECK(r.u_after == r.u_before);
    const auto touching = friction::resolve_contact({matrix(1, 0, 1), Vector2d(0, 0)}, newton);
    CHECK(touching.status == ContactStatus::not_approaching);
    CHECK(touching.outcome == Slip::stick);
  }
  SECTION("two immovable bodies: nothing can stop the approach") {
    const auto r = friction::resolve_contact({Matrix2d::Zero(), Vector2d(-1, 0)}, newton);
    CHECK(r.status == ContactStatus::cannot_stop);
    CHECK(r.normal == 0.0);
  }
  SECTION("a singular W that sticks without slowing the approach") {
    // W = [[1, 1], [1, 1]] (det 0), mu = 2, u0 = (-1, 0.5). Slip along +t with dP_t = -2 dP_n:
    // du/dP_n = (1 - 2, 1 - 2) = (-1, -1): the slip stops at P_n = 0.5 with the approach grown
    // to u_n = -1.5. The ratio 1 is within 2, so it sticks, where du_n/dP_n = 1 - 1 * 1 = 0:
    // the approach never ends. Reported as cannot_stop, at the slip's stop.
    const auto r = friction::resolve_contact({matrix(1, 1, 1), Vector2d(-1, 0.5)},
                                             {2.0, Elasticity(2.0), RestitutionLaw::newton});
    CHECK(r.status == ContactStatus::cannot_stop);
    REQUIRE(r.phases().size() == 1);
    CHECK(r.phases()[0].end == Approx(0.5).epsilon(1e-15));
    CHECK(r.normal == Approx(0.5).epsilon(1e-15));
    CHECK(r.tangential == Approx(-1.0).epsilon(1e-15));
    CHECK(r.u_after.isApprox(Vector2d(-1.5, 0), 1e-15));
    CHECK(r.outcome == Slip::stick);
  }
  SECTION("W_tt = 0: a tangential impulse changes nothing, so the slip never stops") {
    // W = diag(1, 0), u0 = (-1, 2), mu = 0.5, elasticity 2: the normal motion is the
    // frictionless one, P_n = 2, and friction is 0.5 * 2 = 1 against the slip throughout.
    const auto r = friction::resolve_contact({matrix(1, 0, 0), Vector2d(-1, 2)}, newton);
    CHECK(r.status == ContactStatus::resolved);
    CHECK(r.normal == Approx(2.0).epsilon(1e-15));
    CHECK(r.tangential == Approx(-1.0).epsilon(1e-15));
    CHECK(r.u_after.isApprox(Vector2d(1, 2), 1e-15));
    CHECK(r.outcome == Slip::slip);
    // Without slip it sticks, and needs no friction to do so.
    const auto still = friction::resolve_contact({matrix(1, 0, 0), Vector2d(-1, 0)}, newton);
    CHECK(still.outcome == Slip::stick);
    CHECK(still.tangential == 0.0);
    CHECK(still.normal == Approx(2.0).epsilon(1e-15));
  }
  SECTION("from rest, a contact that cannot stick starts slipping the way W_tn drives it") {
    // W = [[2, 1], [1, 1]], u0 = (-1, 0), mu = 0.5: ratio 1 > 0.5, so it slides along
    // sign(W_tn) = +t with dP_t = -0.5 dP_n: du/dP_n = (2 - 0.5, 1 - 0.5) = (1.5, 0.5).
    // Newton, elasticity 2: separation 1 at P_n = 2 / 1.5 = 4/3, P_t = -2/3, u_t = 2/3.
    const auto r = friction::resolve_contact({matrix(2, 1, 1), Vector2d(-1, 0)}, newton);
    REQUIRE(r.phases().size() == 1);
    CHECK(r.phases()[0].regime == Slip::slip);
    CHECK(r.phases()[0].direction == 1.0);
    CHECK(r.normal == Approx(4.0 / 3.0).epsilon(1e-15));
    CHECK(r.tangential == Approx(-2.0 / 3.0).epsilon(1e-15));
    CHECK(r.u_after.isApprox(Vector2d(1, 2.0 / 3.0), 1e-15));
  }
  SECTION("elasticity above 2 is the paper's labs' and Newton's and Poisson's laws take it") {
    // Frictionless, W_nn = 1, approach 1: Newton separates at 1.5; Poisson 2.5 * 1.
    const auto n = friction::resolve_contact({matrix(1, 0, 1), Vector2d(-1, 0)},
                                             {0.0, Elasticity(2.5), RestitutionLaw::newton});
    CHECK(n.normal == Approx(2.5).epsilon(1e-15));
    CHECK(n.energy_change() == Approx(0.5 * 1.5 * 1.5 - 0.5).epsilon(1e-15));
    const auto p = friction::resolve_contact({matrix(1, 0, 1), Vector2d(-1, 0)},
                                             {0.0, Elasticity(2.5), RestitutionLaw::poisson});
    CHECK(p.normal == Approx(2.5).epsilon(1e-15));
  }
}

TEST_CASE("Bad input throws with the bad value", "[friction]") {
  const ContactDynamics fine{matrix(1, 0, 1), Vector2d(-1, 0)};
  const auto law = [](double mu, double e, RestitutionLaw l) {
    return ContactLaw{mu, Elasticity(e), l};
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_MATCHES(friction::resolve_contact(fine, law(-0.1, 2, RestitutionLaw::newton)),
                       InvalidInput,
                       Catch::Message("friction must be finite and at least 0, got -0.1"));
  CHECK_THROWS_WITH(friction::resolve_contact(fine, law(nan, 2, RestitutionLaw::newton)),
                    Contains("friction") && Contains("got nan"));
  CHECK_THROWS_WITH(friction::resolve_contact(fine, law(inf, 2, RestitutionLaw::newton)),
                    Contains("friction") && Contains("got inf"));
  CHECK_THROWS_WITH(friction::resolve_contact(fine, law(0.5, 0.5, RestitutionLaw::poisson)),
                    Contains("elasticity must be at least 1") && Contains("got 0.5"));
  CHECK_THROWS_WITH(friction::resolve_contact(fine, law(0.5, 2.5, RestitutionLaw::energetic)),
                    Contains("at most 2 for the energetic law") && Contains("got 2.5"));
  CHECK_NOTHROW(friction::resolve_contact(fine, law(0.5, 2.0, RestitutionLaw::energetic)));

  const auto dynamics = [](const Matrix2d& W, const Vector2d& u0) {
    return ContactDynamics{W, u0};
  };
  const ContactLaw ok{0.5, Elasticity(2.0), RestitutionLaw::newton};
  CHECK_THROWS_WITH(friction::resolve_contact(dynamics(matrix(1, 2, 1), Vector2d(-1, 0)), ok),
                    Contains("positive semi-definite") && Contains("[[1, 2], [2, 1]]"));
  CHECK_THROWS_WITH(friction::resolve_contact(dynamics(matrix(-1, 0, 1), Vector2d(-1, 0)), ok),
                    Contains("positive semi-definite") && Contains("[[-1, 0], [0, 1]]"));
  Matrix2d skew;
  skew << 1, 0.5, 0, 1;
  CHECK_THROWS_WITH(friction::resolve_contact(dynamics(skew, Vector2d(-1, 0)), ok),
                    Contains("symmetric") && Contains("[[1, 0.5], [0, 1]]"));
  CHECK_THROWS_WITH(friction::resolve_contact(dynamics(matrix(1, 0, nan), Vector2d(-1, 0)), ok),
                    Contains("W must be finite") && Contains("nan"));
  CHECK_THROWS_WITH(friction::resolve_contact(dynamics(matrix(1, 0, 1), Vector2d(-1, inf)), ok),
                    Contains("u0 must be finite") && Contains("inf"));
  // A determinant, if given, must be W's.
  CHECK_THROWS_WITH(
      friction::resolve_contact({matrix(2, 1, 1), Vector2d(-1, 0), 2.0}, ok),
      Contains("determinant of W must be W_nn W_tt - W_nt W_tn = 1") && Contains("got 2"));
  CHECK_THROWS_WITH(friction::resolve_contact({matrix(2, 1, 1), Vector2d(-1, 0), -1.0}, ok),
                    Contains("determinant of W must be finite and at least 0, got -1"));
  CHECK_NOTHROW(friction::resolve_contact({matrix(2, 1, 1), Vector2d(-1, 0), 1.0}, ok));
  // Rounding's worth beyond the semi-definite bound is accepted (and clamped).
  const double edge = 1.0 + 1e-14;
  CHECK_NOTHROW(friction::resolve_contact(dynamics(matrix(1, edge, 1), Vector2d(-1, 0)), ok));
}

TEST_CASE("Names as the scene format spells them", "[friction]") {
  for (const RestitutionLaw law : all_laws) {
    CHECK(impulse::value_named<RestitutionLaw>(impulse::name_of(law)) == law);
  }
  CHECK(impulse::name_of(RestitutionLaw::newton) == "newton");
  CHECK(impulse::name_of(RestitutionLaw::poisson) == "poisson");
  CHECK(impulse::name_of(RestitutionLaw::energetic) == "energetic");
  CHECK_FALSE(impulse::value_named<RestitutionLaw>("Newton").has_value());
  CHECK(friction::to_string(Slip::slip) == "slip");
  CHECK(friction::to_string(Slip::stick) == "stick");
  CHECK(friction::to_string(Slip::reversed) == "reversed");
  CHECK(friction::to_string(ContactStatus::not_approaching) == "not-approaching");
}
