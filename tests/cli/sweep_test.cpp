// SPDX-License-Identifier: GPL-3.0-or-later
// sweep: the CSV header, one row per elasticity of the range, strict FROM:TO:STEP.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "app.hpp"
#include "cli/program.hpp"
#include "sweep_command.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using impulselab::parse_range;

TEST_CASE("A sweep writes the header and one row per elasticity", "[cli][sweep]") {
  // box-lands-flat has 2 contacts: 3 + 2 + 2 columns. 0:3:0.05 is 60 steps, so 61 rows.
  const auto run =
      t::run("sweep " + t::quote(t::scene_path("box-lands-flat.json")) + " --elasticity 0:3:0.05");
  REQUIRE(run.status == 0);
  const auto rows = t::lines(run.out);
  REQUIRE(rows.size() == 1 + 61);
  CHECK(rows[0] ==
        "elasticity,energy_after,energy_change,impulse_0,impulse_1,approach_after_0,"
        "approach_after_1");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    CAPTURE(i, rows[i]);
    const auto cells = t::fields(rows[i]);
    REQUIRE(cells.size() == 7);
    const double e = std::stod(cells[0]);
    CHECK(e == Approx(0.05 * static_cast<double>(i - 1)).margin(1e-12));
    // The box (m 1, I 5/12) lands flat at 1 on two corners: by symmetry each takes e/2, the box
    // leaves at e - 1, its energy (e - 1)^2 / 2 from 1/2 (see the library's scene tests).
    CHECK(std::stod(cells[3]) == Approx(e / 2).margin(1e-12));
    CHECK(std::stod(cells[4]) == Approx(e / 2).margin(1e-12));
    CHECK(std::stod(cells[1]) == Approx((e - 1) * (e - 1) / 2).margin(1e-12));
    CHECK(std::stod(cells[2]) == Approx((e - 1) * (e - 1) / 2 - 0.5).margin(1e-12));
    CHECK(std::stod(cells[5]) == Approx(1 - e).margin(1e-12));  // approach: 1 before, 1 - e after
  }
  CHECK(t::fields(rows.back())[0] == "3");  // TO itself, not 3.0000000000000004
}

TEST_CASE("A sweep overrides the bodies' own elasticities", "[cli][sweep]") {
  // mixed-elasticities-1d has elasticities 2 and 1 of its own; swept at 2 it is elastic-1d at 2:
  // masses 2 and 1 at 3 and -1, Fdt (1/2 + 1) = 2 (3 + 1), Fdt = 16/3.
  const auto run = t::run("sweep " + t::quote(t::scene_path("mixed-elasticities-1d.json")) +
                          " --elasticity 2:2:1");
  REQUIRE(run.status == 0);
  const auto rows = t::lines(run.out);
  REQUIRE(rows.size() == 2);
  CHECK(std::stod(t::fields(rows[1])[3]) == Approx(16.0 / 3.0).epsilon(1e-14));
}

TEST_CASE("FROM:TO:STEP is parsed strictly", "[cli][sweep]") {
  const auto r = parse_range("0:3:0.05");
  CHECK(r.count == 61);
  CHECK(r.at(0) == 0.0);
  CHECK(r.at(60) == 3.0);
  CHECK(r.at(20) == Approx(1.0).epsilon(1e-15));
  CHECK(parse_range("0:1:0.3").count == 4);  // 0, 0.3, 0.6, 0.9: 1 is not on the grid
  CHECK(parse_range("0:1:0.3").at(3) == Approx(0.9).epsilon(1e-15));
  CHECK(parse_range("2:2:1").count == 1);
  CHECK(parse_range("0:0.3:0.1").count == 4);  // 0.3 / 0.1 = 2.9999999999999996: on the grid
  CHECK(parse_range("0:0.3:0.1").at(3) == 0.3);
  // The cap: 0.999999 / 1e-6 steps is 1,000,000 values, the most a sweep writes; one more is
  // refused.
  CHECK(parse_range("0:0.999999:1e-6").count == impulselab::max_sweep_rows);
  CHECK_THROWS_AS(parse_range("0:1:1e-6"), impulselab::UsageError);
}

TEST_CASE("Bad ranges: exit 2 and what was wrong", "[cli][sweep]") {
  const std::string scene = t::quote(t::scene_path("elastic-1d.json"));
  for (const auto& [range, message] : std::initializer_list<std::pair<std::string, std::string>>{
           {"3:0:0.1", "FROM must not be greater than TO"},
           {"0:3:0", "STEP must be positive"},
           {"0:3:-1", "STEP must be positive"},
           {"0:3", "expected FROM:TO:STEP"},
           {"0:3:1:2", "expected FROM:TO:STEP"},
           {"a:3:1", "FROM must be a number, got \"a\""},
           {"0:3:0.05x", "STEP must be a number, got \"0.05x\""},
           {"0::1", "TO must be a number, got \"\""},
           {"0:inf:1", "TO must be finite"},
           {"-1:2:0.5", "FROM must be at least 0"},
           {"0:1:1e-9", "gives 1000000001 values; a sweep writes at most 1000000"},
           {"0:1e300:1e-300", "gives too many values"}}) {
    CAPTURE(range);
    const auto run = t::run("sweep " + scene + " --elasticity " + t::quote(range));
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("--elasticity " + range + ": " + message));
  }
}
