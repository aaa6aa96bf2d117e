// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab solve on scenes with friction: a rod on a rough floor through the program in
// text and JSON, the energy warning on standard error, --compare restitution, refusals (exit 2).
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/program.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

const std::string rod = t::cli_tests_path("scenes/rod-rough-floor.json");
const std::string ball = t::cli_tests_path("scenes/ball-rough-floor.json");
const std::string gained =
    "energy gained: Newton's restitution with friction; see the docs page on friction";

std::string scratch_scene(const std::string& name, const std::string& text) {
  const auto path = t::scratch() / name;
  t::write_text(path, text);
  return path.string();
}

}  // namespace

TEST_CASE("solve: the issue's rod on a rough floor (Newton's law), text and JSON",
          "[cli][friction]") {
  // Worked by hand in tests/scene/friction_test.cpp: slip until 0.2, stick until 0.925
  // (compression ended at 0.3625); P_t = 0.275; energy 0.745 -> 0.795: gained, and warned.
  const auto text = t::run("solve " + t::quote(rod));
  REQUIRE(text.status == 0);
  CHECK_THAT(text.out, Contains("contact 0 (rod\u2013floor): slip until Fdt = 0.2, stick until "
                                "0.925; compression ended at Fdt = 0.3625"));
  CHECK_THAT(text.out, Contains("tangential Fdt") && Contains("0.275") && Contains("stick"));
  CHECK_THAT(text.err, Contains(gained));

  const auto js = t::run("solve " + t::quote(rod) + " --format json");
  REQUIRE(js.status == 0);
  CHECK_THAT(js.err, Contains(gained));
  const json r = json::parse(js.out);
  CHECK(r["impulses"][0]["magnitude"].get<double>() == Approx(0.925).epsilon(1e-12));
  CHECK(r["impulses"][0]["tangential"].get<double>() == Approx(0.275).epsilon(1e-12));
  CHECK(r["impulses"][0]["slip"] == "stick");
  CHECK(r["impulses"][0]["on_bumper"][0].get<double>() == Approx(0.275).epsilon(1e-12));
  CHECK(r["impulses"][0]["on_bumper"][1].get<double>() == Approx(0.925).epsilon(1e-12));
  CHECK(r["energy"]["before"].get<double>() == Approx(0.745).epsilon(1e-14));
  CHECK(r["energy"]["after"].get<double>() == Approx(0.795).epsilon(1e-12));
  // Newton's law leaves the rod's end at (0, 0.9): the separation is 0.9 × the approach 1.
  CHECK(r["contacts"][0]["approach_after"].get<double>() == Approx(-0.9).epsilon(1e-12));
}

TEST_CASE("solve --compare restitution: the rod's three laws side by side", "[cli][friction]") {
  // Normal impulses 0.925, 0.68875, 0.748459 and energies after 0.795, 0.627026, 0.661046
  // (worked by hand in tests/scene/friction_test.cpp); only Newton's gains energy.
  const auto text = t::run("solve " + t::quote(rod) + " --compare restitution");
  REQUIRE(text.status == 0);
  CHECK_THAT(text.out, Contains("three restitution laws side by side"));
  CHECK_THAT(text.out, Contains("0.925") && Contains("0.68875") && Contains("0.748459"));
  CHECK_THAT(text.out, Contains("0.795") && Contains("0.627026") && Contains("0.661046"));
  CHECK_THAT(text.out, Contains("0.275 (stick)"));
  CHECK_THAT(text.err, Contains("newton: " + gained));
  CHECK(text.err.find("poisson: energy") == std::string::npos);
  CHECK(text.err.find("energetic: energy") == std::string::npos);

  const auto js = t::run("solve " + t::quote(rod) + " --compare restitution --format json");
  REQUIRE(js.status == 0);
  const json r = json::parse(js.out);
  CHECK(r["newton"]["restitution"] == "newton");
  CHECK(r["newton"]["impulses"][0]["magnitude"].get<double>() == Approx(0.925).epsilon(1e-12));
  CHECK(r["poisson"]["impulses"][0]["magnitude"].get<double>() == Approx(0.68875).epsilon(1e-12));
  CHECK(r["poisson"]["impulses"][0]["tangential"].get<double>() == Approx(0.13325).epsilon(1e-12));
  CHECK(r["energetic"]["impulses"][0]["magnitude"].get<double>() ==
        Approx(0.3625 + std::sqrt(0.1489640625)).epsilon(1e-12));
  CHECK(r["poisson"]["energy"]["after"].get<double>() == Approx(0.62702625).epsilon(1e-12));
  CHECK(r["energetic"]["energy"]["change"].get<double>() < 0.0);

  // --compare alone (or --compare methods) is still the three methods.
  const auto methods = t::run("solve " + t::quote(rod) + " --compare");
  REQUIRE(methods.status == 0);
  CHECK_THAT(methods.out, Contains("three methods side by side"));
  const auto named = t::run("solve " + t::quote(rod) + " --compare methods");
  CHECK(named.out == methods.out);
  const auto bad = t::run("solve " + t::quote(rod) + " --compare laws");
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Contains("expected methods or restitution"));
}

TEST_CASE("solve: a ball stopping to stick (Poisson's law) from a scene file", "[cli][friction]") {
  // v = (0.5, -1), μ = 1, elasticity 1.5: slip stops at P_n = 0.5, then sticks; P_n = 1.5 × 1 =
  // 1.5, P_t = -0.5; the ball leaves at (0, 0.5) (tests/scene/friction_test.cpp); it loses
  // energy, no warning.
  const auto js = t::run("solve " + t::quote(ball) + " --format json");
  REQUIRE(js.status == 0);
  CHECK(js.err.empty());
  const json r = json::parse(js.out);
  CHECK(r["impulses"][0]["magnitude"].get<double>() == Approx(1.5).epsilon(1e-14));
  CHECK(r["impulses"][0]["tangential"].get<double>() == Approx(-0.5).epsilon(1e-14));
  CHECK(r["impulses"][0]["slip"] == "stick");
  CHECK(std::abs(r["bodies"][0]["velocity"][0].get<double>()) <= 1e-15);
  CHECK(r["bodies"][0]["velocity"][1].get<double>() == Approx(0.5).epsilon(1e-14));
}

TEST_CASE("solve: bad friction keys and unsupported methods exit 2 with the place",
          "[cli][friction]") {
  const std::string negative = scratch_scene("negative-mu.json", R"({"dimension": 2,
    "elasticity": 1.5, "bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": [0, -1]},
    {"name": "floor", "kind": "static"}],
    "contacts": [{"bumper": "a", "wedge": "floor", "normal": [0, -1], "friction": -0.1}]})");
  const auto bad = t::run("solve " + t::quote(negative));
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Contains(negative + ": contacts[0].friction: must be finite and at least 0, "
                                          "got -0.1"));

  const std::string law = scratch_scene("unknown-law.json", R"({"dimension": 2,
    "elasticity": 1.5, "bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": [0, -1]},
    {"name": "floor", "kind": "static"}],
    "contacts": [{"bumper": "a", "wedge": "floor", "normal": [0, -1]}],
    "solver": {"restitution": "stronge"}})");
  const auto unknown = t::run("solve " + t::quote(law));
  CHECK(unknown.status == 2);
  CHECK_THAT(unknown.err, Contains(law + ": solver.restitution: expected one of \"newton\", "
                                         "\"poisson\", \"energetic\", got \"stronge\""));

  // Two contacts with friction: the paper's method has none; serial collisions take it.
  const std::string two = scratch_scene("two-contacts.json", R"({"dimension": 2,
    "elasticity": 1.5, "friction": 0.5,
    "bodies": [{"name": "ground", "kind": "static"},
               {"name": "box", "kind": "rigid", "mass": 1, "inertia": 0.4166666666666667,
                "position": [0, 0.5], "velocity": [0, -1]}],
    "contacts": [{"bumper": "ground", "wedge": "box", "normal": [0, 1], "point": [-1, 0]},
                 {"bumper": "ground", "wedge": "box", "normal": [0, 1], "point": [1, 0]}]})");
  const auto refused = t::run("solve " + t::quote(two));
  CHECK(refused.status == 2);
  CHECK(refused.out.empty());
  CHECK_THAT(refused.err, Contains(two + ": contacts: the method \"simultaneous\" cannot resolve 2 "
                                         "contacts with friction"));
  const auto serial = t::run("solve " + t::quote(two) + " --method serial --format json");
  CHECK(serial.status == 0);
  const json s = json::parse(serial.out);
  CHECK(s["method"] == "serial");
  CHECK(s["impulses"][1].contains("tangential"));
}
