// SPDX-License-Identifier: GPL-3.0-or-later
// The reports of a resolved scene for people: the warnings about the system, and tables that
// stay aligned whatever the names.
#include <catch2/catch.hpp>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/text.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/report.hpp"

namespace sc = impulse::scene;
using Catch::Matchers::Contains;

TEST_CASE("The warning starts above the threshold and not for A = 0", "[scene][warnings]") {
  impulse::scene::Result result;
  result.system.condition_estimate = impulse::ill_conditioned;  // at it: no warning
  CHECK(sc::system_warnings(result, "s.json").empty());
  result.system.condition_estimate = 1e12;
  const auto warnings = sc::system_warnings(result, "s.json");
  REQUIRE(warnings.size() == 1);
  // 1e12 * 2.2e-16 = 2.2e-4 of the impulses' size.
  CHECK(warnings[0] ==
        "s.json: the system A·Fdt = B is ill-conditioned: condition estimate 1e+12, above "
        "1e+08; rounding may change the impulses by about 0.00022 of their size (the velocities "
        "after are less affected)");
  result.system.rank_estimated = true;  // the sparse method's estimate says so
  result.system.condition_estimate = 1e17;
  CHECK_THAT(sc::system_warnings(result, "s.json")[0],
             Contains("condition estimate 1e+17 (estimated), above 1e+08; rounding may change "
                      "the impulses by about as much as their size"));
  CHECK_THAT(sc::system_warnings(result, "s.json")[0],
             Contains("the sparse method's estimate can be far below the true condition"));
  result.system.condition_estimate = std::numeric_limits<double>::infinity();  // A = 0
  CHECK(sc::system_warnings(result, "s.json").empty());
}

TEST_CASE("Names that are not ASCII keep the text report's columns aligned", "[scene][text]") {
  // "Kugel-\u00e4" is 7 characters in 8 bytes, "\u00e9t\u00e9" 3 in 5: counted in bytes, their
  // rows would end one and two columns short of the others'. Every row of the bodies table must
  // put the kind's column at the same character.
  const auto r = sc::solve(sc::parse_scene(R"({"dimension": 1, "elasticity": 2,
    "bodies": [{"name": "Kugel-\u00e4", "kind": "material", "mass": 1, "velocity": 1},
               {"name": "\u00e9t\u00e9", "kind": "material", "mass": 2, "velocity": 0},
               {"name": "plain", "kind": "material", "mass": 3, "velocity": 0}],
    "contacts": [{"bumper": "Kugel-\u00e4", "wedge": "\u00e9t\u00e9", "normal": 1},
                 {"bumper": "\u00e9t\u00e9", "wedge": "plain", "normal": 1}]})",
                                           "s.json"));
  const std::string text = sc::text_report(r, "s.json", false);
  std::vector<std::size_t> kind_at;
  std::size_t start = 0;
  while ((start = text.find("material", start)) != std::string::npos) {
    const std::size_t line = text.rfind('\n', start) + 1;
    kind_at.push_back(impulse::characters(text.substr(line, start - line)));
    start += 8;
  }
  REQUIRE(kind_at.size() == 3);
  CHECK(kind_at[0] == kind_at[1]);
  CHECK(kind_at[1] == kind_at[2]);
}
