// SPDX-License-Identifier: GPL-3.0-or-later
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/error.hpp"
#include "impulse/core/solve.hpp"

using impulse::ContactSystem;
using impulse::DependentPolicy;
using impulse::InconsistentPolicy;
using impulse::ScalarContribution;
using impulse::SolverOptions;
using impulse::SolveStatus;

namespace {
SolverOptions policies(DependentPolicy dependent, InconsistentPolicy inconsistent) {
  SolverOptions options;
  options.dependent = dependent;
  options.inconsistent = inconsistent;
  return options;
}
}  // namespace

TEST_CASE("A regular system has one solution whatever the policy", "[solve]") {
  // [2 1; 1 3] x = [3; 5]: by Cramer, det = 5, x1 = (9 - 5)/5 = 0.8, x2 = (10 - 3)/5 = 1.4.
  const ContactSystem system(Eigen::Matrix2d{{2, 1}, {1, 3}}, Eigen::Vector2d{3, 5});
  for (const auto dependent : {DependentPolicy::minimum_norm, DependentPolicy::basic}) {
    const auto s = impulse::solve(system, policies(dependent, InconsistentPolicy::least_squares));
    REQUIRE(s.status == SolveStatus::success);
    CHECK(s.Fdt(0) == Approx(0.8).epsilon(1e-14));
    CHECK(s.Fdt(1) == Approx(1.4).epsilon(1e-14));
    CHECK(s.rank == 2);
    CHECK_FALSE(s.dependent);
    CHECK(s.consistent);
    CHECK(s.residual < 1e-14);
    CHECK(s.A == system.A());
    CHECK(s.B == system.B());
  }
}

TEST_CASE("A dependent system: equal impulses under minimum-norm, one under basic", "[solve]") {
  // x1 + x2 = 2 twice (a body on two parallel contacts). Every (t, 2 - t) solves it; the least
  // norm is t = 1, a basic solution puts everything on one unknown.
  const ContactSystem system(Eigen::Matrix2d{{1, 1}, {1, 1}}, Eigen::Vector2d{2, 2});
  const auto equal = impulse::solve(system);
  CHECK(equal.rank == 1);
  CHECK(equal.dependent);
  CHECK(equal.consistent);
  CHECK(equal.Fdt(0) == Approx(1.0).epsilon(1e-14));
  CHECK(equal.Fdt(1) == Approx(1.0).epsilon(1e-14));
  CHECK(equal.residual < 1e-14);

  const auto basic =
      impulse::solve(system, policies(DependentPolicy::basic, InconsistentPolicy::least_squares));
  CHECK(basic.Fdt.sum() == Approx(2.0).epsilon(1e-14));
  CHECK(basic.Fdt.cwiseAbs().minCoeff() == 0.0);  // one unknown is exactly zero
  CHECK(basic.residual < 1e-14);
}

TEST_CASE("An inconsistent system under both policies", "[solve]") {
  // x1 + x2 = 1 and x1 + x2 = 3 cannot both hold.
  const ContactSystem system(Eigen::Matrix2d{{1, 1}, {1, 1}}, Eigen::Vector2d{1, 3});

  SECTION("least-squares: x1 + x2 = 2 (the mean), minimum norm (1, 1), residual sqrt(2)") {
    const auto s = impulse::solve(system);
    CHECK_FALSE(s.consistent);
    CHECK(s.dropped.empty());
    CHECK(s.Fdt(0) == Approx(1.0).epsilon(1e-14));
    CHECK(s.Fdt(1) == Approx(1.0).epsilon(1e-14));
    CHECK(s.residual == Approx(std::sqrt(2.0)).epsilon(1e-14));
  }
  SECTION("drop-equation: the second equation contradicts the first and is ignored") {
    const auto s = impulse::solve(
        system, policies(DependentPolicy::minimum_norm, InconsistentPolicy::drop_equation));
    CHECK_FALSE(s.consistent);
    REQUIRE(s.dropped == std::vector<Eigen::Index>{1});
    // x1 + x2 = 1 with least norm: (0.5, 0.5); the whole system's residual is |1 - 3| = 2.
    CHECK(s.Fdt(0) == Approx(0.5).epsilon(1e-14));
    CHECK(s.Fdt(1) == Approx(0.5).epsilon(1e-14));
    CHECK(s.residual == Approx(2.0).epsilon(1e-14));
  }
  SECTION("drop-equation with a basic solution: all of x1 + x2 = 1 on one unknown") {
    const auto s =
        impulse::solve(system, policies(DependentPolicy::basic, InconsistentPolicy::drop_equation));
    CHECK(s.dropped == std::vector<Eigen::Index>{1});
    CHECK(s.Fdt.sum() == Approx(1.0).epsilon(1e-14));
    CHECK(s.Fdt.cwiseAbs().minCoeff() == 0.0);
  }
}

TEST_CASE("drop-equation keeps the equations that agree", "[solve]") {
  // Three equations over two unknowns' sums: x1 + x2 = 1, 2(x1 + x2) = 2 (same), x1 + x2 = 5.
  // The third contradicts the first two; the first two are kept.
  const ContactSystem system(Eigen::Matrix3d{{1, 1, 0}, {2, 2, 0}, {1, 1, 0}},
                             Eigen::Vector3d{1, 2, 5});
  const auto s = impulse::solve(
      system, policies(DependentPolicy::minimum_norm, InconsistentPolicy::drop_equation));
  CHECK(s.dropped == std::vector<Eigen::Index>{2});
  CHECK(s.Fdt(0) + s.Fdt(1) == Approx(1.0).epsilon(1e-14));
  CHECK(s.Fdt(2) == 0.0);
}

TEST_CASE("The condition estimate follows the pivots", "[solve]") {
  // diag(1, 1e-6): the pivots are 1 and 1e-6, the condition number exactly 1e6.
  const ContactSystem system(Eigen::Vector2d(1.0, 1e-6).asDiagonal().toDenseMatrix(),
                             Eigen::Vector2d(1, 1));
  const auto s = impulse::solve(system);
  CHECK(s.condition_estimate == Approx(1e6).epsilon(1e-12));
  CHECK(s.Fdt(1) == Approx(1e6).epsilon(1e-12));
}

TEST_CASE("A prescribed rank tolerance changes what counts as dependent", "[solve]") {
  const ContactSystem system(Eigen::Vector2d(1.0, 1e-6).asDiagonal().toDenseMatrix(),
                             Eigen::Vector2d(1, 0));
  SolverOptions loose;
  loose.rank_tolerance = 1e-3;  // 1e-6 is below 1e-3 of the largest pivot: rank 1
  const auto s = impulse::solve(system, loose);
  CHECK(s.rank == 1);
  CHECK(s.dependent);
  CHECK(s.Fdt(1) == 0.0);
}

TEST_CASE("Non-finite numbers are a returned status, not an exception", "[solve]") {
  const double inf = std::numeric_limits<double>::infinity();
  const auto s =
      impulse::solve(ContactSystem(Eigen::Matrix2d{{inf, 0}, {0, 1}}, Eigen::Vector2d{1, 1}));
  CHECK(s.status == SolveStatus::non_finite);
  CHECK(s.Fdt.hasNaN());

  const auto scalar = impulse::solve(ScalarContribution{1.0, std::nan("")});
  CHECK(scalar.status == SolveStatus::non_finite);
}

TEST_CASE("The empty system solves to no impulses", "[solve]") {
  const auto s = impulse::solve(ContactSystem(0));
  CHECK(s.status == SolveStatus::success);
  CHECK(s.Fdt.size() == 0);
  CHECK(s.rank == 0);
  CHECK_FALSE(s.dependent);
}

TEST_CASE("The scalar path: Fdt = B / A, and A = 0 when no body can move", "[solve]") {
  const auto s = impulse::solve(ScalarContribution{0.5, 3.0});
  CHECK(s.Fdt == 6.0);  // 3 / 0.5, exact in binary
  CHECK(s.residual == 0.0);
  CHECK_FALSE(s.dependent);

  const auto stuck = impulse::solve(ScalarContribution{0.0, 0.0});
  CHECK(stuck.dependent);
  CHECK(stuck.consistent);
  CHECK(stuck.Fdt == 0.0);

  const auto impossible = impulse::solve(ScalarContribution{0.0, 1.0});
  CHECK_FALSE(impossible.consistent);
  CHECK(impossible.residual == 1.0);
}

TEST_CASE("Policies print as the scene format names them, and read back", "[solve]") {
  CHECK(impulse::name_of(DependentPolicy::minimum_norm) == "minimum-norm");
  CHECK(impulse::name_of(DependentPolicy::basic) == "basic");
  CHECK(impulse::name_of(InconsistentPolicy::least_squares) == "least-squares");
  CHECK(impulse::name_of(InconsistentPolicy::drop_equation) == "drop-equation");
  CHECK(impulse::value_named<DependentPolicy>("basic") == DependentPolicy::basic);
  CHECK(impulse::value_named<InconsistentPolicy>("drop-equation") ==
        InconsistentPolicy::drop_equation);
  CHECK_FALSE(impulse::value_named<DependentPolicy>("least-squares").has_value());
  CHECK(impulse::quoted_names<DependentPolicy>() == "\"minimum-norm\", \"basic\"");
}

TEST_CASE("Policies that only the dense method serves are refused beyond its limit",
          "[solve][errors]") {
  // 2,049 contacts with "basic": the dense method alone serves it, and its N x N matrices would
  // take 8 N^2 bytes (32 MiB at the limit, 80 GB at 100,000 contacts); refused before any is made.
  impulse::SolverOptions basic;
  basic.dependent = DependentPolicy::basic;
  CHECK_NOTHROW(impulse::require_dense_fits(impulse::dense_limit, basic));
  CHECK_THROWS_WITH(impulse::require_dense_fits(impulse::dense_limit + 1, basic),
                    Catch::Matchers::StartsWith(
                        "2049 contacts with the policies \"basic\" and \"least-squares\", which "
                        "only the dense method serves: it takes at most 2048"));
  CHECK_NOTHROW(impulse::require_dense_fits(100'000, impulse::SolverOptions{}));
  // impulse::solve itself refuses such a system (a sparse one of 2,049 contacts, empty).
  const impulse::ContactSystem many(impulse::dense_limit + 1, impulse::Storage::sparse);
  CHECK_THROWS_AS(impulse::solve(many, basic), impulse::InvalidInput);
}
