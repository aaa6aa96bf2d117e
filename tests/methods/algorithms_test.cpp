// SPDX-License-Identifier: GPL-3.0-or-later
// The two new methods' machinery on problems with known answers: Lemke's pivoting and projected
// Gauss-Seidel on hand-made systems (degenerate, singular, infeasible, zero rows), and serial
// collisions' order, passes and bound (Galperin's billiard counts the digits of pi).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/resolve.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "support/vectors.hpp"

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;
using impulse::Elasticity;
using impulse::InvalidInput;
using impulse::material_2d::PointMass;
using impulse::multipoint::Body;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
using impulse::test::vec;
namespace mp = impulse::multipoint;
namespace me = impulse::methods;

namespace {
Eigen::SparseMatrix<double> sparse(const MatrixXd& A) {
  return A.sparseView();
}
}  // namespace

TEST_CASE("Method names", "[methods]") {
  for (const auto m : me::all_methods) {
    CHECK(impulse::value_named<me::Method>(impulse::name_of(m)) == m);
  }
  CHECK(impulse::name_of(me::Method::complementarity) == "complementarity");
  CHECK_FALSE(impulse::value_named<me::Method>("sequential").has_value());
  CHECK(impulse::name_of(me::LcpAlgorithm::projected_gauss_seidel) == "projected-gauss-seidel");
  CHECK(impulse::name_of(me::LcpStatus::iteration_limit) == "iteration-limit");
  CHECK(impulse::name_of(me::SerialStatus::collision_limit) == "collision-limit");
}

TEST_CASE("Lemke: a positive definite system with one contact released", "[methods]") {
  // A = [[2, 1], [1, 2]], B = (1, -4). F_1 = 0, F_0 = 1/2: w_1 = A_10 F_0 - B_1 = 1/2 + 4 = 4.5.
  // (Both positive would need A^-1 B = (1/3)(2 + 4, -1 - 8) = (2, -3): not allowed.)
  const MatrixXd A{{2, 1}, {1, 2}};
  const auto s = me::lemke(A, vec({1, -4}));
  REQUIRE(s.status == me::LcpStatus::solved);
  CHECK(s.Fdt.isApprox(vec({0.5, 0}), 1e-15));
  CHECK(s.w.isApprox(vec({0, 4.5}), 1e-15));
  CHECK(s.residual == 0.0);
  // Projected Gauss-Seidel reaches it in one sweep: F_0 = 1/2, then F_1 = max(0, -(4.5)/2) = 0.
  const auto g = me::projected_gauss_seidel(sparse(A), vec({1, -4}));
  REQUIRE(g.status == me::LcpStatus::solved);
  CHECK(g.iterations == 1);
  CHECK(g.Fdt.isApprox(vec({0.5, 0}), 1e-15));
}

TEST_CASE("Lemke: nothing approaches, nothing pushes", "[methods]") {
  // B <= 0: F = 0 gives w = -B >= 0 at once, without a pivot.
  const MatrixXd A{{1, 0}, {0, 1}};
  const auto s = me::lemke(A, vec({-1, 0}));
  REQUIRE(s.status == me::LcpStatus::solved);
  CHECK(s.Fdt.isZero(0.0));
  CHECK(s.iterations == 0);
  CHECK(s.w.isApprox(vec({1, 0})));
}

TEST_CASE("Lemke: three equal parallel contacts, degenerate at every step", "[methods]") {
  // A point mass on three parallel contacts: A = all ones (rank 1), B = (2, 2, 2). Every ratio
  // test ties; the lexicographic rule must still end. Least norm: (2/3, 2/3, 2/3); basic: one
  // contact carries 2.
  const MatrixXd A = MatrixXd::Ones(3, 3);
  const VectorXd B = vec({2, 2, 2});
  const auto least = me::lemke(A, B);
  REQUIRE(least.status == me::LcpStatus::solved);
  CHECK(least.least_norm);
  CHECK(least.Fdt.isApprox(VectorXd::Constant(3, 2.0 / 3), 1e-14));
  const auto basic = me::lemke(A, B, impulse::DependentPolicy::basic);
  REQUIRE(basic.status == me::LcpStatus::solved);
  CHECK(basic.Fdt.sum() == Approx(2.0));
  CHECK((basic.Fdt.array() > 0.0).count() == 1);
}

TEST_CASE("Lemke: when the least-norm split would pull, a vertex is returned", "[methods]") {
  // A point mass (m = 1) with three contacts whose outward normals (the columns of N) are
  // n_0 = (0, 1), n_1 = (-c, 1/2), n_2 = (c, 1/2), c = cos 30 degrees; n_1 + n_2 = n_0, so
  // A = N^T N has rank 2. B = N^T y with y = (1, 1): the velocity change the impulses must
  // give (N F = y, which lies inside the cone of the normals, between 30 and 150 degrees).
  // N N^T = 1.5 I, so the least-norm solution of N F = y is N^T y / 1.5 =
  // (2/3, (1/2 - c)/1.5, (1/2 + c)/1.5) = (0.667, -0.244, 0.911): it pulls at contact 1.
  // The solutions that only push are F = (a + t, -t, b - t) with a = 1 - 1/(2c) = 0.4226,
  // b = 1/c = 1.1547 and -a <= t <= 0, with two vertices: (a, 0, b), the least-norm one (the
  // squared norm (a + t)^2 + t^2 + (b - t)^2 has the derivative 6t + 2(a - b) < 0 on [-a, 0],
  // so it is least at t = 0), and (0, a, b - a). The least-norm split needs clipping, which
  // the method does not attempt: it returns Lemke's vertex, whichever it is, with least_norm
  // false. Either vertex satisfies the conditions and gives the same velocity change y.
  const double c = std::cos(M_PI / 6);
  Eigen::Matrix<double, 2, 3> N;
  N << 0, -c, c, 1, 0.5, 0.5;
  const MatrixXd A = N.transpose() * N;
  const Vector2d y(1, 1);
  const VectorXd B = N.transpose() * y;
  const auto s = me::lemke(A, B);
  REQUIRE(s.status == me::LcpStatus::solved);
  CHECK_FALSE(s.least_norm);
  CHECK(s.Fdt.minCoeff() >= 0.0);
  CHECK(s.residual <= 1e-14 * s.scale);
  CHECK((N * s.Fdt).isApprox(y, 1e-14));
  const double a = 1 - 1 / (2 * c);
  const double b = 1 / c;
  const bool first = s.Fdt.isApprox(vec({a, 0, b}), 1e-14);
  const bool second = s.Fdt.isApprox(vec({0, a, b - a}), 1e-14);
  CAPTURE(s.Fdt.transpose());
  CHECK((first || second));
}

TEST_CASE("Infeasible and zero rows: reported, not thrown", "[methods]") {
  // A contact with a zero row (no body can move along its normal) and B > 0: no F helps.
  const MatrixXd A{{0, 0}, {0, 1}};
  const auto s = me::lemke(A, vec({1, 1}));
  CHECK(s.status == me::LcpStatus::infeasible);
  const auto g = me::projected_gauss_seidel(sparse(A), vec({1, 1}));
  CHECK(g.status == me::LcpStatus::infeasible);
  // With B_0 = 0 the zero row is satisfied by F_0 = 0 (the least), and PGS never divides by 0.
  const auto zero = me::projected_gauss_seidel(sparse(A), vec({0, 1}));
  REQUIRE(zero.status == me::LcpStatus::solved);
  CHECK(zero.Fdt.isApprox(vec({0, 1})));
  const auto pivoted = me::lemke(A, vec({0, 1}));
  REQUIRE(pivoted.status == me::LcpStatus::solved);
  CHECK(pivoted.Fdt.isApprox(vec({0, 1})));
  // Non-finite input is a status too. (The sparse copy is built entry by entry: a sparse view
  // would compare the NaN with zero.)
  const MatrixXd bad{{std::nan(""), 0}, {0, 1}};
  CHECK(me::lemke(bad, vec({1, 1})).status == me::LcpStatus::non_finite);
  Eigen::SparseMatrix<double> bad_sparse(2, 2);
  bad_sparse.insert(0, 0) = std::nan("");
  bad_sparse.insert(1, 1) = 1.0;
  CHECK(me::projected_gauss_seidel(bad_sparse, vec({1, 1})).status == me::LcpStatus::non_finite);
}

TEST_CASE("Bad arguments are refused with the value", "[methods][errors]") {
  const MatrixXd A{{1, 0}, {0, 1}};
  CHECK_THROWS_MATCHES(me::lemke(A, vec({1})), InvalidInput,
                       Catch::Matchers::Message("A must be square and B of its size, got A 2x2 "
                                                "and B of 1"));
  CHECK_THROWS_WITH(me::lemke(A, vec({1, 1}), impulse::DependentPolicy::minimum_norm, 0.0),
                    "the complementarity tolerance must lie in (0, 1), got 0");
  CHECK_THROWS_WITH(me::projected_gauss_seidel(sparse(A), vec({1, 1}), 1e-10, 0),
                    "projected Gauss-Seidel needs at least 1 sweep, got 0");
  const std::vector<Body> two{PointMass{1, {1, 0}}, PointMass{1, {0, 0}}};
  const std::vector<Contact> one{{0, 1, {1, 0}, {0, 0}}};
  me::SerialOptions negative;
  negative.max_collisions = -1;
  CHECK_THROWS_WITH(
      me::resolve_serial(two, Elasticity::elastic(), one, negative),
      "max_collisions must be at least 1 (or 0 for 100 per contact, at least 10000), got -1");
  CHECK_THROWS_WITH(me::resolve_serial(two, std::vector<Elasticity>{}, one),
                    "elasticities must give one value per body (2), got 0");
}

TEST_CASE("Passes: the order cut where a contact repeats", "[methods]") {
  using Order = std::vector<Eigen::Index>;
  CHECK(me::count_passes(Order{}) == 0);
  CHECK(me::count_passes(Order{0, 1}) == 1);
  CHECK(me::count_passes(Order{0, 1, 0}) == 2);
  CHECK(me::count_passes(Order{0, 0, 0}) == 3);
  CHECK(me::count_passes(Order{0, 1, 2, 1, 0}) == 2);
  CHECK(me::count_passes(Order{1, 0, 1, 0, 1}) == 3);
}

TEST_CASE("Galperin's billiard: serial collisions count the digits of pi", "[methods][section4]") {
  // A ball of mass 1 at rest between a wall and a ball of mass M = 100^k moving at 1 towards
  // it, every collision elastic. G. Galperin (2003): the number of collisions is the integer
  // made of the first k + 1 digits of pi, 31 for M = 100 and 314 for M = 10^4 (the velocities,
  // scaled by the square roots of the masses, turn on a circle by a fixed angle per collision,
  // 2 arctan(1/10^k)). In one instant, with all contacts touching, serial collisions take them
  // in the same order. For M = 10^8, 31415 collisions exceed the default bound (100 per contact,
  // at least 10000): the method stops and says so.
  const auto run = [](double M, std::int64_t bound) {
    const std::vector<Body> bodies{StaticBody{}, PointMass{1, {0, 0}}, PointMass{M, {-M, 0}}};
    const std::vector<Contact> contacts{{0, 1, {1, 0}, {0, 0}}, {1, 2, {1, 0}, {0, 0}}};
    me::SerialOptions options;
    options.max_collisions = bound;
    return me::resolve_serial(bodies, Elasticity::elastic(), contacts, options);
  };
  const auto hundred = run(100, 0);
  REQUIRE(hundred.diagnostics.status == me::SerialStatus::finished);
  CHECK(hundred.diagnostics.order.size() == 31);
  CHECK(hundred.diagnostics.order.front() == 1);  // the heavy ball hits first
  CHECK(hundred.diagnostics.passes == 16);        // the contacts alternate: 1, 0, 1, 0, …
  const auto ten_thousand = run(1e4, 0);
  REQUIRE(ten_thousand.diagnostics.status == me::SerialStatus::finished);
  CHECK(ten_thousand.diagnostics.order.size() == 314);

  const auto million = run(1e6, 0);
  REQUIRE(million.diagnostics.status == me::SerialStatus::finished);
  CHECK(million.diagnostics.order.size() == 3141);

  const auto hundred_million = run(1e8, 0);
  CHECK(hundred_million.diagnostics.status == me::SerialStatus::collision_limit);
  CHECK(hundred_million.diagnostics.max_collisions == 10000);
  CHECK(hundred_million.diagnostics.order.size() == 10000);
  CHECK(hundred_million.diagnostics.still_approaching >= 0);
  CHECK(hundred_million.diagnostics.approach_left > 0.0);
  const auto raised = run(1e8, 40000);
  REQUIRE(raised.diagnostics.status == me::SerialStatus::finished);
  CHECK(raised.diagnostics.order.size() == 31415);
}

TEST_CASE(
    "Serial collisions below elasticity 2 repeat, and at 1 they approach the simultaneous "
    "answer",
    "[methods][section4]") {
  // Newton's cradle of three at (1, 0, 0), elasticity 1: each collision equalises one pair, the
  // other pair then approaches at half the speed it had. In exact arithmetic that never ends;
  // the approach speeds halve at each collision, so the tolerance (1e-12 of the speeds) is
  // reached after about log2(1e12) = 40 collisions. The limit is the perfectly inelastic answer
  // of all contacts at once: (1/3, 1/3, 1/3).
  const std::vector<Body> bodies{PointMass{1, {1, 0}}, PointMass{1, {0, 0}}, PointMass{1, {0, 0}}};
  const std::vector<Contact> contacts{{0, 1, {1, 0}, {0, 0}}, {1, 2, {1, 0}, {0, 0}}};
  const auto serial = me::resolve_serial(bodies, Elasticity::inelastic(), contacts);
  REQUIRE(serial.diagnostics.status == me::SerialStatus::finished);
  CHECK(serial.diagnostics.order.size() >= 30);
  CHECK(serial.diagnostics.order.size() <= 50);
  for (const Body& b : serial.after) {
    CHECK(std::get<PointMass>(b).p.x() == Approx(1.0 / 3).margin(1e-11));
  }
  // A cap below that count stops it, with the contact still approaching named.
  me::SerialOptions capped;
  capped.max_collisions = 5;
  const auto stopped = me::resolve_serial(bodies, Elasticity::inelastic(), contacts, capped);
  CHECK(stopped.diagnostics.status == me::SerialStatus::collision_limit);
  CHECK(stopped.diagnostics.order.size() == 5);
  CHECK(stopped.diagnostics.approach_left > 0.0);
}

TEST_CASE("A contact that no movable body touches: a zero row, a zero impulse", "[methods]") {
  // Scene files refuse a contact between two static bodies, the library's own types do not: its
  // row and column of A are zero and its B is 0 (nothing moves there). The ball (m = 2, moving
  // at -1 into the wall, which is the bumper with normal +x) gets A_11 = 1/2, B_1 = 2 * 1:
  // F_1 = 4, and contact 0 keeps the least impulse, 0, by every algorithm.
  const std::vector<Body> bodies{StaticBody{}, StaticBody{}, PointMass{2, {-2, 0}}};
  const std::vector<Contact> contacts{{0, 1, {1, 0}, {0, 0}}, {1, 2, {1, 0}, {0, 0}}};
  const auto system =
      mp::assemble(bodies, std::vector<Elasticity>(3, Elasticity::elastic()), contacts);
  CHECK(system.A()(0, 0) == 0.0);
  for (const auto algorithm : {me::LcpAlgorithm::active_set, me::LcpAlgorithm::lemke,
                               me::LcpAlgorithm::projected_gauss_seidel}) {
    for (const bool warm : {true, false}) {
      CAPTURE(impulse::name_of(algorithm), warm);
      me::ComplementarityOptions options;
      options.algorithm = algorithm;
      options.warm_start = warm;
      const auto s = me::solve_complementarity(system, options);
      REQUIRE(s.status == me::LcpStatus::solved);
      CHECK(s.Fdt.isApprox(vec({0, 4}), 1e-15));
    }
  }
  const auto serial = me::resolve_serial(bodies, Elasticity::elastic(), contacts);
  CHECK(serial.Fdt.isApprox(vec({0, 4}), 1e-15));
  CHECK(serial.diagnostics.order == std::vector<Eigen::Index>{1});
}

TEST_CASE("No contact: nothing to do, by every method", "[methods]") {
  const std::vector<Body> one{PointMass{1, {1, 0}}};
  const std::vector<Contact> none;
  for (const auto algorithm : {me::LcpAlgorithm::automatic, me::LcpAlgorithm::lemke,
                               me::LcpAlgorithm::projected_gauss_seidel}) {
    me::ComplementarityOptions options;
    options.algorithm = algorithm;
    const auto s = me::resolve_complementarity(one, Elasticity::elastic(), none, options);
    CHECK(s.solution.status == me::LcpStatus::solved);
    CHECK(s.solution.Fdt.size() == 0);
  }
  const auto serial = me::resolve_serial(one, Elasticity::elastic(), none);
  CHECK(serial.diagnostics.status == me::SerialStatus::finished);
  CHECK(serial.diagnostics.order.empty());
  CHECK(serial.diagnostics.passes == 0);
}
