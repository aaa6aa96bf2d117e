// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files: reading (all or nothing, every refusal named) and the JSON report.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "support/sampling.hpp"
#include "support/scene_files.hpp"

using Catch::Matchers::Contains;
using Eigen::Vector2d;
using impulse::InvalidInput;
using impulse::scene::BodyKind;
using impulse::scene::Given;
namespace sc = impulse::scene;

namespace {

const std::string worked_example_text = R"({
  "dimension": 2,
  "elasticity": 2,
  "bodies": [
    {"name": "a", "kind": "material", "mass": 1, "velocity": [1.5, 0]},
    {"name": "b", "kind": "material", "mass": 1, "velocity": [0, 0]}
  ],
  "contacts": [{"bumper": "a", "wedge": "b", "normal": [1, 0]}]
})";

std::vector<std::filesystem::path> example_scenes() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSELAB_SCENES_DIR)) {
    if (entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("A scene file is read field by field", "[scene][json]") {
  const sc::Scene s = sc::parse_scene(worked_example_text, "worked.json");
  CHECK(s.dimension == 2);
  CHECK(s.elasticity == 2.0);
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].name == "a");
  CHECK(s.bodies[0].kind == BodyKind::material);
  CHECK(s.bodies[0].mass == 1.0);
  CHECK(s.bodies[0].linear_given == Given::velocity);
  CHECK(s.bodies[0].linear == Vector2d(1.5, 0));
  REQUIRE(s.contacts.size() == 1);
  CHECK(s.contacts[0].bumper == 0);
  CHECK(s.contacts[0].wedge == 1);
  CHECK(s.contacts[0].normal == Vector2d(1, 0));
  CHECK_FALSE(s.contacts[0].point.has_value());
  CHECK(s.solver.dependent == impulse::DependentPolicy::minimum_norm);
}

TEST_CASE("A normal may be given as an angle in degrees", "[scene][json]") {
  // "normal_angle": 90 is the normal [0, 1] exactly (not [6e-17, 1]), 210 is
  // [cos 210°, sin 210°] = [-sqrt(3)/2, -1/2].
  const auto with_contact = [](const std::string& contact) {
    return R"({"dimension": 2, "elasticity": 2,
      "bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": [0, 1]},
                 {"name": "b", "kind": "material", "mass": 1, "velocity": [0, 0]}],
      "contacts": [)" +
           contact + "]}";
  };
  const sc::Scene up = sc::parse_scene(
      with_contact(R"({"bumper": "a", "wedge": "b", "normal_angle": 90})"), "s.json");
  CHECK(up.contacts[0].normal == Vector2d(0, 1));
  const sc::Scene down = sc::parse_scene(
      with_contact(R"({"bumper": "a", "wedge": "b", "normal_angle": 210})"), "s.json");
  CHECK(down.contacts[0].normal.x() == Approx(-std::sqrt(3.0) / 2).epsilon(1e-15));
  CHECK(down.contacts[0].normal.y() == Approx(-0.5).epsilon(1e-15));
  // The same collision as the normal [0, 1]: a (velocity (0, 1)) stops, b leaves at (0, 1).
  const auto r = sc::solve(up);
  CHECK((r.bodies[1].after.velocity - Vector2d(0, 1)).norm() < 1e-15);
  CHECK(r.notes.empty());
  CHECK_THROWS_WITH(sc::parse_scene(with_contact(R"({"bumper": "a", "wedge": "b", "normal": [0, 1],
                                       "normal_angle": 90})"),
                                    "s.json"),
                    "s.json: contacts[0]: give either \"normal\" or \"normal_angle\", not both");
  CHECK_THROWS_WITH(sc::parse_scene(with_contact(R"({"bumper": "a", "wedge": "b"})"), "s.json"),
                    "s.json: contacts[0]: missing \"normal\" (or \"normal_angle\"), which every "
                    "contact needs");
  CHECK_THROWS_WITH(sc::parse_scene(R"({"dimension": 1, "elasticity": 2,
      "bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": 1},
                 {"name": "b", "kind": "material", "mass": 1, "velocity": 0}],
      "contacts": [{"bumper": "a", "wedge": "b", "normal_angle": 0}]})",
                                    "s.json"),
                    "s.json: contacts[0].normal_angle: does not apply in dimension 1 (give "
                    "\"normal\": +1 or -1)");
}

TEST_CASE("A normal not of unit length is made unit, and the JSON report notes it",
          "[scene][json]") {
  std::string text = worked_example_text;
  text.replace(text.find("[1, 0]}]"), 6, "[3, 0]");
  const auto json = sc::to_json(sc::solve(sc::parse_scene(text, "s.json")));
  REQUIRE(json.contains("notes"));
  CHECK(json["notes"][0] ==
        "contacts[0].normal [3, 0] is not of unit length (length 3): used as [1, 0]");
  // [3, 0] / 3 is [1, 0] exactly: the worked example's impulse to the last digit.
  const auto plain = sc::to_json(sc::solve(sc::parse_scene(worked_example_text, "s.json")));
  CHECK(json["impulses"][0]["magnitude"] == plain["impulses"][0]["magnitude"]);
  // Without a change, no "notes": the scene format's report exactly.
  CHECK_FALSE(plain.contains("notes"));
}

TEST_CASE("A 1D scene lies on the x axis, rigid bodies read their rotation", "[scene][json]") {
  const sc::Scene line = sc::parse_scene(R"({"dimension": 1, "bodies": [
      {"name": "p", "kind": "material", "mass": 2, "momentum": -3, "elasticity": 1.5},
      {"name": "q", "kind": "static"}],
    "contacts": [{"bumper": "q", "wedge": "p", "normal": -1, "point": 4}],
    "solver": {"dependent": "basic", "inconsistent": "drop-equation"}})",
                                         "line.json");
  CHECK(line.bodies[0].linear == Vector2d(-3, 0));
  CHECK(line.bodies[0].linear_given == Given::momentum);
  CHECK(line.bodies[0].elasticity == 1.5);
  CHECK(line.bodies[1].kind == BodyKind::static_body);
  CHECK(line.contacts[0].normal == Vector2d(-1, 0));
  CHECK(line.solver.dependent == impulse::DependentPolicy::basic);
  CHECK(line.solver.inconsistent == impulse::InconsistentPolicy::drop_equation);

  const sc::Scene plane = sc::parse_scene(R"({"dimension": 2, "elasticity": 1, "bodies": [
      {"name": "r", "kind": "rigid", "mass": 2, "inertia": 0.5, "position": [1, 2],
       "velocity": [0, -1], "angular_momentum": 0.25},
      {"name": "g", "kind": "static"}],
    "contacts": [{"bumper": "g", "wedge": "r", "normal": [0, 1], "point": [1, 1]}]})",
                                          "plane.json");
  CHECK(plane.bodies[0].inertia == 0.5);
  CHECK(plane.bodies[0].position == Vector2d(1, 2));
  CHECK(plane.bodies[0].angular_given == Given::momentum);
  CHECK(plane.bodies[0].angular == 0.25);
  CHECK(plane.contacts[0].point == Vector2d(1, 1));
}

TEST_CASE("Syntax errors name the line and the column", "[scene][json][errors]") {
  // Line 3 is `  "bodies": [,`; the stray comma is its 14th character.
  const std::string text = "{\n  \"dimension\": 2,\n  \"bodies\": [,\n}";
  CHECK_THROWS_WITH(sc::parse_scene(text, "bad.json"),
                    Catch::Matchers::StartsWith("bad.json: line 3, column 14: syntax error"));
  // The end of the input: line 2 is `{"dimension": 2` (no newline after it), 15 characters, so
  // the missing brace is sought at column 16.
  CHECK_THROWS_WITH(sc::parse_scene("\n{\"dimension\": 2", "cut.json"),
                    Catch::Matchers::StartsWith("cut.json: line 2, column 16:"));
  CHECK_THROWS_WITH(sc::parse_scene("", "empty.json"),
                    Catch::Matchers::StartsWith("empty.json: line 1, column 1:"));
}

TEST_CASE("Refusals found while parsing name the place", "[scene][json][errors]") {
  CHECK_THROWS_WITH(
      sc::parse_scene(R"({"bodies": [{"name": "a", "mass": 1, "mass": 2}]})", "dup.json"),
      "dup.json: bodies[0].mass: key repeated in the same object");
  CHECK_THROWS_WITH(sc::parse_scene(R"({"bodies": [{}, {"velocity": [1, 1e999]}]})", "big.json"),
                    Contains("big.json: bodies[1].velocity[1]: number overflow parsing '1e999'"));
}

TEST_CASE("Refusals of the reader name the file, the place and what was expected",
          "[scene][json][errors]") {
  // One edit of the worked example each; the message fragment is what a student must see.
  const auto edited = [](const std::string& from, const std::string& to) {
    std::string text = worked_example_text;
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
  };
  const auto message = [](const std::string& text) {
    try {
      (void)sc::parse_scene(text, "s.json");
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  CHECK_THAT(
      message(edited("\"mass\": 1, \"velocity\": [0, 0]", "\"mas\": 1, \"velocity\": [0, 0]")),
      Contains("s.json: bodies[1].mas: unknown key (did you mean \"mass\"?)"));
  CHECK_THAT(
      message(edited("\"mass\": 1, \"velocity\": [0, 0]", "\"mass\": \"1\", \"velocity\": [0, 0]")),
      Contains("s.json: bodies[1].mass: expected a number, got the string \"1\""));
  CHECK_THAT(
      message(edited("\"mass\": 1, \"velocity\": [0, 0]", "\"mass\": -1, \"velocity\": [0, 0]")),
      Contains("s.json: bodies[1].mass: must be positive and finite, got -1"));
  CHECK_THAT(
      message(edited("\"wedge\": \"b\"", "\"wedge\": \"c\"")),
      Contains("s.json: contacts[0].wedge: no body is named \"c\" (the bodies are \"a\", \"b\")"));
  CHECK_THAT(message(edited("\"velocity\": [1.5, 0]", "\"velocity\": [1.5, 0], \"inertia\": 2")),
             Contains("s.json: bodies[0].inertia: does not apply to a material body"));
  CHECK_THAT(message(edited("\"dimension\": 2", "\"dimension\": 3")),
             Contains("s.json: dimension: expected 1 or 2, got the number 3"));
  CHECK_THAT(message(edited("\"normal\": [1, 0]", "\"normal\": [1, 0, 0]")),
             Contains("s.json: contacts[0].normal: expected [x, y], an array of 2 numbers"));
  CHECK_THAT(
      message(edited("\"kind\": \"material\", \"mass\": 1, \"velocity\": [0, 0]",
                     "\"kind\": \"plastic\", \"mass\": 1, \"velocity\": [0, 0]")),
      Contains("s.json: bodies[1].kind: expected one of \"material\", \"rigid\", \"static\""));
  CHECK(message(worked_example_text) == "(accepted)");
}

TEST_CASE("Whatever the bytes, a scene is read whole or refused", "[scene][json][property]") {
  // Every cut of every example scene and random byte changes: each is either a valid scene or
  // an InvalidInput (any other exception fails the test), and a valid one solves.
  impulse::test::Sampler sample("scene json mutations");
  const std::string bytes = "{}[]\":,.-+0123456789eEtrufalsn \n\\x";
  int accepted = 0;
  int refused = 0;
  for (const auto& path : example_scenes()) {
    const std::string text = impulselab::test::read_scene_text(path.string());
    REQUIRE_NOTHROW(sc::parse_scene(text, path.string()));
    std::vector<std::string> variants;
    for (std::size_t cut = 0; cut < text.size(); ++cut) {
      variants.push_back(text.substr(0, cut));
    }
    for (int i = 0; i < 300; ++i) {
      std::string changed = text;
      const auto at =
          static_cast<std::size_t>(sample.integer(0, static_cast<int>(text.size()) - 1));
      changed[at] =
          bytes[static_cast<std::size_t>(sample.integer(0, static_cast<int>(bytes.size()) - 1))];
      variants.push_back(changed);
    }
    for (const std::string& variant : variants) {
      CAPTURE(path.filename().string(), variant);
      try {
        const sc::Scene s = sc::parse_scene(variant, "variant.json");
        const sc::Result r = sc::solve(s);
        (void)r;
        ++accepted;
      } catch (const InvalidInput& e) {
        REQUIRE(std::string(e.what()).starts_with("variant.json: "));
        ++refused;
      }
    }
  }
  CHECK(refused > 1000);
  CHECK(accepted > 0);
}

TEST_CASE("The JSON report has the scene format's keys and numbers", "[scene][json]") {
  const auto r = sc::solve(sc::parse_scene(worked_example_text, "worked.json"));
  const auto j = sc::to_json(r);
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) {
    keys.push_back(key);
  }
  CHECK(keys ==
        std::vector<std::string>{"impulses", "bodies", "energy", "momentum", "contacts", "system"});
  CHECK(j["impulses"][0]["magnitude"].get<double>() == Approx(1.5).epsilon(1e-14));
  // -[1, 0] * 1.5: the y coordinate is -0 in arithmetic and written as 0.
  CHECK_FALSE(std::signbit(j["impulses"][0]["on_bumper"][1].get<double>()));
  CHECK(j["bodies"][0].contains("angular_velocity") == false);
  CHECK(j["system"]["A"][0][0].get<double>() == Approx(2.0).epsilon(1e-15));
  CHECK(j["system"]["policy"] == "minimum-norm");

  // Without A (a solver that does not form it) "A" is null and B stays.
  sc::Result without_A = r;
  without_A.system.A.resize(0, 0);
  const auto k = sc::to_json(without_A);
  CHECK(k["system"]["A"].is_null());
  CHECK(k["system"]["B"][0].get<double>() == Approx(3.0).epsilon(1e-15));
}

TEST_CASE("The JSON report of a 1D scene writes plain numbers, rigid bodies add rotation",
          "[scene][json]") {
  const auto line = sc::to_json(sc::solve(sc::parse_scene(
      R"({"dimension": 1, "elasticity": 1, "bodies": [
        {"name": "p", "kind": "material", "mass": 1, "velocity": 2},
        {"name": "q", "kind": "material", "mass": 1, "velocity": 0}],
      "contacts": [{"bumper": "p", "wedge": "q", "normal": 1}]})",
      "line.json")));
  // Inelastic, equal masses: both leave at 1, the impulse is 1.
  CHECK(line["bodies"][0]["velocity"].is_number());
  CHECK(line["bodies"][0]["velocity"].get<double>() == Approx(1.0).epsilon(1e-14));
  CHECK(line["momentum"]["after"].is_number());
  CHECK(line["impulses"][0]["on_bumper"].get<double>() == Approx(-1.0).epsilon(1e-14));

  const auto plane = sc::to_json(sc::solve(
      impulselab::test::load_scene(std::string(IMPULSELAB_SCENES_DIR) + "/rod-hits-ground.json")));
  CHECK(plane["bodies"][0].contains("angular_velocity") == false);  // the ground
  CHECK(plane["bodies"][1].contains("angular_velocity"));
  CHECK(plane["bodies"][1].contains("angular_momentum"));
  CHECK(plane["system"].contains("condition_estimate"));
}
