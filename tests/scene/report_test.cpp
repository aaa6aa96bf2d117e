// SPDX-License-Identifier: GPL-3.0-or-later
// The reports of a resolved scene for people: the warnings about the system, and tables that
// stay aligned whatever the names.
#include <catch2/catch.hpp>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
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

TEST_CASE("An elasticity above 2 or below 1 is warned about at its place", "[scene][warnings]") {
  // Balls of mass 1 on a line, each hitting the next at speed 1 (contact normal +x): "fast" at
  // its own elasticity 5, the others at the scene's 0.5; the wall at 2 (no warning at 1 or 2).
  const auto scene = [](double fast, double scene_default) {
    return sc::parse_scene(R"({"dimension": 1, "elasticity": )" +
                               impulse::format_number(scene_default) +
                               R"(, "bodies": [
      {"name": "fast", "kind": "material", "mass": 1, "velocity": 1, "elasticity": )" +
                               impulse::format_number(fast) + R"(},
      {"name": "slow", "kind": "material", "mass": 1, "velocity": 0},
      {"name": "third", "kind": "material", "mass": 1, "velocity": -1},
      {"name": "wall", "kind": "static"}],
      "contacts": [{"bumper": "fast", "wedge": "slow", "normal": 1},
                   {"bumper": "third", "wedge": "wall", "normal": -1}]})",
                           "s.json");
  };
  const sc::Result r = sc::solve(scene(5, 0.5));
  CHECK(sc::elasticity_warnings(r, "s.json") ==
        std::vector<std::string>{
            "s.json: bodies[0].elasticity: 5 is above 2 (perfectly elastic): a collision at it "
            "creates kinetic energy",
            "s.json: elasticity: 0.5 is below 1 (perfectly inelastic): bodies that collide at it "
            "still approach each other after the impulse (the elasticity is 1 + the coefficient "
            "of restitution)"});
  // What the words say, worked by hand. Contact 0: A = 1/1 + 1/1 = 2, B = 5·1 + 0.5·0 = 5,
  // Fdt = 2.5: "fast" leaves at 1 - 2.5 = -1.5 and "slow" at 2.5, kinetic energy 1/2 → 4.25.
  // Contact 1 ("third" into the wall at 1, normal -x outward from "third"): A = 1, B = 0.5,
  // Fdt = 0.5: "third" goes on at -0.5 towards the wall, an approach of 0.5 after.
  CHECK(r.bodies[0].energy_before + r.bodies[1].energy_before == Approx(0.5));
  CHECK(r.bodies[0].energy_after + r.bodies[1].energy_after == Approx(4.25));
  CHECK(r.contacts[1].approach_after == Approx(0.5));
  // At 1 and 2, the ends of the paper's range: nothing to say.
  CHECK(sc::elasticity_warnings(sc::solve(scene(2, 1)), "s.json").empty());
  // The scene's default named once, for the three bodies that collide at it; a body's own
  // elasticity in range is not named.
  const sc::Result all_default = sc::solve(scene(1.5, 2.5));
  REQUIRE(sc::elasticity_warnings(all_default, "s.json").size() == 1);
  CHECK_THAT(sc::elasticity_warnings(all_default, "s.json")[0],
             Catch::Matchers::StartsWith("s.json: elasticity: 2.5 is above 2"));
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
