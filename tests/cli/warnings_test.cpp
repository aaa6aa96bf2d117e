// SPDX-License-Identifier: GPL-3.0-or-later
// The warning about an ill-conditioned system: a line on standard error, the normal report on
// standard output, exit status 0.
#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "cli/program.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("solve and sweep warn about an ill-conditioned scene and still report it",
          "[cli][warnings]") {
  // A body of m = 1e-9 between two of M = 1e9: the eigenvalues of A are 1/M and 1/M + 2/m, so
  // its condition number is 1 + 2M/m = 2e18. The solver's estimate is the squared ratio of the
  // pivots of G's QR, a² / det A with a = 1/M + 1/m (the columns' squared norm) and
  // det A = (1/M)(1/M + 2/m): (1e9)² / (1e-9 · 2e9) = 5e17, within the factor 4 such a
  // two-contact estimate can miss by (tests/hostile/hostile_test.cpp).
  const std::string scene = t::cli_tests_path("scenes/ill-conditioned.json");
  const auto solved = t::run("solve " + t::quote(scene) + " --format json");
  CHECK(solved.status == 0);
  CHECK_THAT(solved.out, StartsWith("{"));
  CHECK(t::lines(solved.err) ==
        std::vector<std::string>{
            "impulselab: warning: " + scene +
            ": the system A·Fdt = B is ill-conditioned: condition estimate 5e+17, above 1e+08; "
            "rounding may change the impulses by about as much as their size (the velocities "
            "after are less affected)"});

  // sweep: once, whatever the number of rows (A does not depend on the elasticity).
  const auto swept = t::run("sweep " + t::quote(scene) + " --elasticity 1:2:0.25");
  CHECK(swept.status == 0);
  CHECK(t::lines(swept.out).size() == 6);  // the header and 5 rows
  REQUIRE(t::lines(swept.err).size() == 1);
  CHECK_THAT(swept.err, Contains("impulselab: warning: " + scene + ": the system A·Fdt = B"));

  // A well-conditioned scene: nothing on standard error.
  const auto quiet = t::run("solve " + t::quote(t::scene_path("box-lands-flat.json")));
  CHECK(quiet.status == 0);
  CHECK(quiet.err.empty());
}

TEST_CASE("solve warns when the solution does not satisfy A·Fdt = B", "[cli][warnings]") {
  // The fuzzer's stack with an inertia of 4e-301 (see tests/scene/fuzz_regression_test.cpp):
  // the contacts whose A is of order 1 were lost next to 1/I = 2.4e300.
  const std::string scene =
      std::string(IMPULSELAB_FUZZ_REGRESSIONS_DIR) + "/stack-inertia-1e-300.json";
  const auto run = t::run("solve " + t::quote(scene));
  CHECK(run.status == 0);
  CHECK_FALSE(run.out.empty());
  CHECK_THAT(run.err, Contains("impulselab: warning: " + scene +
                               ": the impulses found do not satisfy A·Fdt = B (residual "));
  CHECK_THAT(run.err, Contains("do not trust this report"));
}
