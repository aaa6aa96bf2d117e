// SPDX-License-Identifier: GPL-3.0-or-later
// Three ways to resolve many contacts, on scenes whose answers are worked by hand: the
// paper's simultaneous system, the complementarity problem (impulses only push) and serial
// collisions (one contact at a time, the fastest-approaching first).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "support/vectors.hpp"

using Eigen::Vector2d;
using Eigen::VectorXd;
using impulse::Elasticity;
using impulse::material_2d::PointMass;
using impulse::multipoint::Body;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
using impulse::rigid_2d::RigidBody;
using impulse::test::vec;
namespace mp = impulse::multipoint;
namespace me = impulse::methods;

namespace {

// Balls of mass 1 on the x axis, each touching the next: contact i joins ball i (bumper, normal
// +x) and ball i + 1.
std::vector<Body> balls(const std::vector<double>& velocities) {
  std::vector<Body> result;
  for (const double v : velocities) {
    result.emplace_back(PointMass{1, {v, 0}});
  }
  return result;
}

std::vector<Contact> row_of(std::size_t count) {
  std::vector<Contact> result;
  for (std::size_t i = 0; i + 1 < count; ++i) {
    result.push_back({i, i + 1, Vector2d::UnitX(), Vector2d::Zero()});
  }
  return result;
}

VectorXd x_velocities(const std::vector<Body>& bodies) {
  VectorXd v(static_cast<Eigen::Index>(bodies.size()));
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto& b = std::get<PointMass>(bodies[i]);
    v(static_cast<Eigen::Index>(i)) = b.p.x() / b.mass;
  }
  return v;
}

void check_equal(const VectorXd& got, const VectorXd& expected, double margin = 1e-12) {
  REQUIRE(got.size() == expected.size());
  for (Eigen::Index i = 0; i < got.size(); ++i) {
    CAPTURE(i);
    CHECK(got(i) == Approx(expected(i)).margin(margin));
  }
}

// A rod of mass 1 and length 2 (I = m L^2 / 12 = 1/3) lying on a static ground, centre at the
// origin, touching it at x = -1 (contact 0) and x = +1 (contact 1). It falls at 1 and spins at
// omega (counter-clockwise: the right end rises when omega > 1). The ground is the bumper with
// normal +y, so the rod's own normal is -y.
struct Rod {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

Rod rod(double omega) {
  constexpr double inertia = 1.0 / 3;
  return {{StaticBody{}, RigidBody{1, inertia, {0, 0}, {0, -1}, inertia * omega}},
          {{0, 1, Vector2d::UnitY(), Vector2d(-1, 0)}, {0, 1, Vector2d::UnitY(), Vector2d(1, 0)}}};
}

}  // namespace

TEST_CASE("Newton's cradle of three at (3, 0, 0): simultaneous (-1, 2, 2), serial (0, 0, 3)",
          "[methods][section4]") {
  // By hand. Contacts 0 (balls 0-1) and 1 (balls 1-2), normal +x; the blocks (4.5) give
  // A = [[2, -1], [-1, 2]] (ball 1 touches both, its normals -x and +x: -1 off the diagonal) and
  // B = 2 (3 - 0, 0 - 0) = (6, 0). Fdt = A^-1 B = (1/3) [[2, 1], [1, 2]] (6, 0) = (4, 2), both
  // positive, so the complementarity problem has the same answer (w = 0). Velocities after:
  // 3 - 4 = -1, 0 + 4 - 2 = 2, 0 + 2 = 2.
  // Serial: contact 0 approaches at 3, contact 1 at 0. Contact 0 alone: equal masses exchange
  // velocities (Fdt = 2 * 3 / 2 = 3): (0, 3, 0). Then contact 1 at 3 (Fdt = 3): (0, 0, 3). No
  // contact approaches any more: two collisions in one pass, total impulses (3, 3).
  const auto bodies = balls({3, 0, 0});
  const auto contacts = row_of(3);
  const auto e = Elasticity::elastic();

  const auto simultaneous = mp::resolve(bodies, e, contacts);
  check_equal(simultaneous.solution.Fdt, vec({4, 2}));
  check_equal(x_velocities(simultaneous.after), vec({-1, 2, 2}));

  const auto lcp = me::resolve_complementarity(bodies, e, contacts);
  REQUIRE(lcp.solution.status == me::LcpStatus::solved);
  CHECK(lcp.solution.algorithm == me::LcpAlgorithm::active_set);
  check_equal(lcp.solution.Fdt, vec({4, 2}));
  check_equal(lcp.solution.w, vec({0, 0}));
  check_equal(x_velocities(lcp.after), vec({-1, 2, 2}));

  const auto serial = me::resolve_serial(bodies, e, contacts);
  REQUIRE(serial.diagnostics.status == me::SerialStatus::finished);
  check_equal(x_velocities(serial.after), vec({0, 0, 3}));
  check_equal(serial.Fdt, vec({3, 3}));
  CHECK(serial.diagnostics.order == std::vector<Eigen::Index>{0, 1});
  CHECK(serial.diagnostics.passes == 1);
}

TEST_CASE("Two balls hitting one at (3, 0, -1.5): simultaneous (-2, 1, 2.5), serial (-1.5, 0, 3)",
          "[methods][section4]") {
  // By hand. Approach speeds u = (3 - 0, 0 + 1.5) = (3, 1.5), A = [[2, -1], [-1, 2]], B = 2u =
  // (6, 3). Fdt = (1/3) [[2, 1], [1, 2]] (6, 3) = (5, 4) >= 0, so complementarity agrees.
  // Velocities: 3 - 5 = -2, 0 + 5 - 4 = 1, -1.5 + 4 = 2.5.
  // Serial: contact 0 first (3 > 1.5), Fdt 3: (0, 3, -1.5). Contact 1 now approaches at 4.5,
  // Fdt 4.5: (0, -1.5, 3). Contact 0 approaches again at 1.5, Fdt 1.5: (-1.5, 0, 3). Order 0, 1,
  // 0: contact 0 comes up a second time, so two passes. Totals (3 + 1.5, 4.5) = (4.5, 4.5).
  // Energies: 1/2 (9 + 2.25) = 5.625 before; 1/2 (4 + 1 + 6.25) and 1/2 (2.25 + 9) after: both
  // keep it, and both keep the momentum 1.5.
  const auto bodies = balls({3, 0, -1.5});
  const auto contacts = row_of(3);
  const auto e = Elasticity::elastic();

  const auto simultaneous = mp::resolve(bodies, e, contacts);
  check_equal(simultaneous.solution.Fdt, vec({5, 4}));
  check_equal(x_velocities(simultaneous.after), vec({-2, 1, 2.5}));

  const auto lcp = me::resolve_complementarity(bodies, e, contacts);
  REQUIRE(lcp.solution.status == me::LcpStatus::solved);
  check_equal(lcp.solution.Fdt, vec({5, 4}));
  check_equal(x_velocities(lcp.after), vec({-2, 1, 2.5}));

  const auto serial = me::resolve_serial(bodies, e, contacts);
  REQUIRE(serial.diagnostics.status == me::SerialStatus::finished);
  check_equal(x_velocities(serial.after), vec({-1.5, 0, 3}));
  check_equal(serial.Fdt, vec({4.5, 4.5}));
  CHECK(serial.diagnostics.order == std::vector<Eigen::Index>{0, 1, 0});
  CHECK(serial.diagnostics.passes == 2);

  for (const auto* after : {&simultaneous.after, &lcp.after, &serial.after}) {
    CHECK(mp::kinetic_energy(*after) == Approx(5.625).epsilon(1e-14));
    CHECK(mp::momentum(*after).x() == Approx(1.5).epsilon(1e-14));
  }
}

TEST_CASE("A last ball moving away fast: the paper's system pulls it back, the others do not",
          "[methods][section4]") {
  // (1, 0, 5): u = (1, 0 - 5) = (1, -5), B = (2, -10), Fdt = (1/3) [[2, 1], [1, 2]] (2, -10) =
  // (-2, -6): both negative, both contacts pull. Velocities 1 + 2 = 3, 0 - 2 + 6 = 4, 5 - 6 = -1:
  // ball 2 is dragged back through ball 1.
  // Complementarity: with F_1 = 0, F_0 = B_0 / A_00 = 1 and w_1 = A_10 F_0 - B_1 = -1 + 10 = 9
  // >= 0: F = (1, 0), velocities (0, 1, 5). Serial: contact 0 alone (Fdt 1) gives the same, and
  // contact 1 then separates at 4.
  const auto bodies = balls({1, 0, 5});
  const auto contacts = row_of(3);
  const auto e = Elasticity::elastic();
  const auto simultaneous = mp::resolve(bodies, e, contacts);
  check_equal(simultaneous.solution.Fdt, vec({-2, -6}));
  check_equal(x_velocities(simultaneous.after), vec({3, 4, -1}));
  const auto lcp = me::resolve_complementarity(bodies, e, contacts);
  check_equal(lcp.solution.Fdt, vec({1, 0}));
  check_equal(lcp.solution.w, vec({0, 9}));
  check_equal(x_velocities(lcp.after), vec({0, 1, 5}));
  const auto serial = me::resolve_serial(bodies, e, contacts);
  check_equal(serial.Fdt, vec({1, 0}));
  check_equal(x_velocities(serial.after), vec({0, 1, 5}));
}

TEST_CASE(
    "A rod rotating away from one of its two contacts: negative simultaneous impulse, zero "
    "complementarity impulse there",
    "[methods][section5]") {
  // The rod's block (5.3): its normal is n = (0, -1) at both points, det(r, n) = r_x n_y = -x, so
  // a_vk = n_k.n_v / m + det_k det_v / I = 1 + 3 x_k x_v: A = [[4, -2], [-2, 4]]. The approach
  // speeds are u = 1 - omega x (the rod point's velocity (0, -1 + omega x) cast on -y):
  // u = (1 + omega, 1 - omega), and B = e u.
  // Simultaneous: Fdt = A^-1 e u = (e / 12) (6 + 2 omega, 6 - 2 omega): the rising end's impulse
  // is negative once omega > 3.
  // Complementarity with F_1 = 0: F_0 = e (1 + omega) / 4 and w_1 = A_10 F_0 - B_1 =
  // e (omega - 3) / 2, non-negative exactly when omega >= 3: the impulse at the rising end is 0
  // from where the paper's turns negative.
  const double omega = 5;
  const auto [bodies, contacts] = rod(omega);

  SECTION("elasticity 1: no contact is left approaching") {
    // e = 1: simultaneous (1/12)(6 + 10, 6 - 10) = (4/3, -1/3); complementarity
    // F = (6/4, 0) = (1.5, 0), w = (0, (5 - 3) / 2) = (0, 1). At e = 1, w = -u' (the approach
    // after with a minus sign): u' = u - A F = (6 - 6, -4 + 3) = (0, -1), no contact approaches.
    // Serial: contact 0 (approach 6) alone, Fdt 6 / 4 = 1.5; contact 1 then separates at 1.
    const auto e = Elasticity::inelastic();
    const auto simultaneous = mp::resolve(bodies, e, contacts);
    check_equal(simultaneous.solution.Fdt, vec({4.0 / 3, -1.0 / 3}));
    const auto lcp = me::resolve_complementarity(bodies, e, contacts);
    REQUIRE(lcp.solution.status == me::LcpStatus::solved);
    check_equal(lcp.solution.Fdt, vec({1.5, 0}));
    check_equal(lcp.solution.w, vec({0, 1}));
    CHECK(lcp.solution.Fdt.minCoeff() >= 0.0);
    CHECK(lcp.solution.w.minCoeff() >= -1e-15);
    check_equal(mp::approach(lcp.after, contacts), vec({0, -1}));
    const auto serial = me::resolve_serial(bodies, e, contacts);
    check_equal(serial.Fdt, vec({1.5, 0}));
    CHECK(serial.diagnostics.order == std::vector<Eigen::Index>{0});
  }

  SECTION("elasticity 2: the zero impulse, and what w >= 0 means then") {
    // e = 2: simultaneous (2/12)(16, -4) = (8/3, -2/3); complementarity (3, 0) with
    // w = (0, 5 - 3) = (0, 2). Here w = -u' - u: the approach after is u' = u - A F =
    // (6 - 12, -4 + 6) = (-6, 2). The rising end, free of impulse, is pushed down by the spin
    // that contact 0's impulse reverses (omega' = -4) and approaches the ground at 2 after: at
    // e = 2 the conditions ask every contact to separate at least as fast as it approached, and
    // a contact that was separating (u = -4) may end up approaching at up to 4.
    // Serial resolves that approach with a second collision: Fdt = 2 * 2 / 4 = 1, u'' =
    // (-6 + 2, 2 - 4) = (-4, -2). Totals (3, 1).
    const auto e = Elasticity::elastic();
    const auto simultaneous = mp::resolve(bodies, e, contacts);
    check_equal(simultaneous.solution.Fdt, vec({8.0 / 3, -2.0 / 3}));
    const auto lcp = me::resolve_complementarity(bodies, e, contacts);
    REQUIRE(lcp.solution.status == me::LcpStatus::solved);
    check_equal(lcp.solution.Fdt, vec({3, 0}));
    check_equal(lcp.solution.w, vec({0, 2}));
    check_equal(mp::approach(lcp.after, contacts), vec({-6, 2}));
    const auto serial = me::resolve_serial(bodies, e, contacts);
    check_equal(serial.Fdt, vec({3, 1}));
    check_equal(mp::approach(serial.after, contacts), vec({-4, -2}));
    // All three keep the energy: 1/2 (1 + 25/3) = 14/3 before.
    for (const auto* after : {&simultaneous.after, &lcp.after, &serial.after}) {
      CHECK(mp::kinetic_energy(*after) == Approx(14.0 / 3).epsilon(1e-14));
    }
  }

  SECTION(
      "spinning slower (omega = 2): every simultaneous impulse pushes, and complementarity "
      "agrees") {
    // e = 2, omega = 2: (2/12)(10, 2) = (5/3, 1/3), both positive.
    const auto [slow_bodies, slow_contacts] = rod(2);
    const auto simultaneous = mp::resolve(slow_bodies, Elasticity::elastic(), slow_contacts);
    const auto lcp = me::resolve_complementarity(slow_bodies, Elasticity::elastic(), slow_contacts);
    check_equal(simultaneous.solution.Fdt, vec({5.0 / 3, 1.0 / 3}));
    check_equal(lcp.solution.Fdt, vec({5.0 / 3, 1.0 / 3}));
  }
}

TEST_CASE("A dependent system: a point mass on two parallel contacts", "[methods][section4]") {
  // m = 1 falls at (0, -1) onto the floor at two points: A = [[1, 1], [1, 1]], B = (2, 2). Every
  // F >= 0 with F_0 + F_1 = 2 solves the complementarity problem (w = 0), and all bounce the
  // mass at (0, 1). Which one each method returns:
  //  - complementarity, minimum-norm (the default): the least-norm solution (1, 1), the paper's
  //    equal impulses;
  //  - complementarity, basic: the vertex the pivoting reaches. The active-set method (used for
  //    systems assembled from bodies) adds the contact with the most negative slack, the first
  //    of equal ones, contact 0, whose least squares give it F_0 = 2; contact 1's slack is then
  //    0 and it stays out: (2, 0). Lemke's method on A and B alone ends at (0, 2): its first
  //    pivot takes the row of the most negative q = -B, the last of equal ones (contact 1), then
  //    z_1 enters and z0 leaves;
  //  - projected Gauss-Seidel from zero: contact 0 first, F_0 = 2, after which contact 1 needs
  //    nothing: (2, 0);
  //  - serial: equal approach speeds, the lower index first (Fdt 2), then contact 1 no longer
  //    approaches: (2, 0).
  const std::vector<Body> bodies{PointMass{1, {0, -1}}, StaticBody{}};
  const std::vector<Contact> contacts{{0, 1, {0, -1}, {-1, 0}}, {0, 1, {0, -1}, {1, 0}}};
  const auto e = Elasticity::elastic();

  const auto least = me::resolve_complementarity(bodies, e, contacts);
  check_equal(least.solution.Fdt, vec({1, 1}));
  CHECK(least.solution.least_norm);

  me::ComplementarityOptions basic;
  basic.dependent = impulse::DependentPolicy::basic;
  const auto vertex = me::resolve_complementarity(bodies, e, contacts, basic);
  CHECK(vertex.solution.algorithm == me::LcpAlgorithm::active_set);
  check_equal(vertex.solution.Fdt, vec({2, 0}));
  CHECK_FALSE(vertex.solution.least_norm);
  basic.algorithm = me::LcpAlgorithm::lemke;
  const auto lemke_vertex = me::resolve_complementarity(bodies, e, contacts, basic);
  check_equal(lemke_vertex.solution.Fdt, vec({0, 2}));
  basic.dependent = impulse::DependentPolicy::minimum_norm;
  check_equal(me::resolve_complementarity(bodies, e, contacts, basic).solution.Fdt, vec({1, 1}));

  me::ComplementarityOptions iterate;
  iterate.algorithm = me::LcpAlgorithm::projected_gauss_seidel;
  iterate.warm_start = false;
  const auto pgs = me::resolve_complementarity(bodies, e, contacts, iterate);
  check_equal(pgs.solution.Fdt, vec({2, 0}));

  const auto serial = me::resolve_serial(bodies, e, contacts);
  check_equal(serial.Fdt, vec({2, 0}));

  for (const auto* after :
       {&least.after, &vertex.after, &lemke_vertex.after, &pgs.after, &serial.after}) {
    const Vector2d v = std::get<PointMass>((*after)[0]).p;
    CHECK(v.isApprox(Vector2d(0, 1), 1e-14));
  }
}
