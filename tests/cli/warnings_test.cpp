// SPDX-License-Identifier: GPL-3.0-or-later
// The warning about an ill-conditioned system: a line on standard error, the normal report on
// standard output, exit status 0.
#include <catch2/catch.hpp>
#include <limits>
#include <nlohmann/json.hpp>
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

TEST_CASE("solve warns about an elasticity below 1 or above 2, once with --compare",
          "[cli][warnings]") {
  // Lab 1's tunnelling scene: left (m = 2, v = 3) hits right (m = 1, v = -1) at elasticity 0.5.
  // A = 1/2 + 1 = 1.5, B = 0.5 (3 + 1) = 2, Fdt = 4/3: left goes on at 3 - (4/3)/2 = 7/3 and
  // right at -1 + 4/3 = 1/3, still approaching at 2 (what the warning says).
  const std::string scene = t::scene_path("tunnelling-1d.json");
  const std::string warning = "impulselab: warning: " + scene +
                              ": elasticity: 0.5 is below 1 (perfectly inelastic): bodies that "
                              "collide at it still approach each other after the impulse (the "
                              "elasticity is 1 + the coefficient of restitution)";
  const auto solved = t::run("solve " + t::quote(scene) + " --format json");
  CHECK(solved.status == 0);
  CHECK(nlohmann::json::parse(solved.out)["contacts"][0]["approach_after"].get<double>() ==
        Approx(2.0));
  CHECK(t::lines(solved.err) == std::vector<std::string>{warning});
  const auto text = t::run("solve " + t::quote(scene));
  CHECK(t::lines(text.err) == std::vector<std::string>{warning});
  const auto compared = t::run("solve " + t::quote(scene) + " --compare --format json");
  CHECK(compared.status == 0);
  CHECK(t::lines(compared.err) == std::vector<std::string>{warning});

  // Above 2, on standard input: the place of the scene's default, "<stdin>" for the file.
  // A = 2, B = 5, Fdt = 2.5: a leaves at -1.5 and b at 2.5, kinetic energy 0.5 -> 4.25.
  const auto input = t::scratch() / "elasticity-5.json";
  t::write_text(input, R"({"dimension": 1, "elasticity": 5, "bodies": [
        {"name": "a", "kind": "material", "mass": 1, "velocity": 1},
        {"name": "b", "kind": "material", "mass": 1, "velocity": 0}],
        "contacts": [{"bumper": "a", "wedge": "b", "normal": 1}]})");
  const auto gained = t::run("solve - --format json", input.string());
  CHECK(nlohmann::json::parse(gained.out)["energy"]["after"].get<double>() == Approx(4.25));
  CHECK(gained.status == 0);
  CHECK(t::lines(gained.err) ==
        std::vector<std::string>{"impulselab: warning: <stdin>: elasticity: 5 is above 2 "
                                 "(perfectly elastic): a collision at it creates kinetic energy"});
}
