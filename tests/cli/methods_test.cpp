// SPDX-License-Identifier: GPL-3.0-or-later
// solve with the other methods: --method, --compare (text and JSON), the warning for
// every negative impulse, and serial collisions that reach their bound (exit 1, a clear message).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/program.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

// The scenes of lab 7 (tutorials/07-three-ways/).
std::string lab_scene(const std::string& name) {
  return t::scene_path("../07-three-ways/" + name);
}

std::vector<double> velocities(const json& result) {
  std::vector<double> v;
  for (const json& body : result["bodies"]) {
    v.push_back(body["velocity"].get<double>());
  }
  return v;
}

// A scene file of its own in the scratch folder.
std::string scratch_scene(const std::string& name, const std::string& text) {
  const auto path = t::scratch() / name;
  t::write_text(path, text);
  return path.string();
}

// Galperin's billiard with a heavy ball of mass 1e6: 3141 serial collisions.
const char* const galperin_hundred_million = R"({"dimension": 1, "elasticity": 2,
  "bodies": [{"name": "wall", "kind": "static"},
             {"name": "light", "kind": "material", "mass": 1, "velocity": 0},
             {"name": "heavy", "kind": "material", "mass": 1e8, "velocity": -1}],
  "contacts": [{"bumper": "wall", "wedge": "light", "normal": 1},
               {"bumper": "light", "wedge": "heavy", "normal": 1}],
  "solver": {"method": "serial"}})";

}  // namespace

TEST_CASE("solve --method: each method's answer for two balls hitting one", "[cli][methods]") {
  // Worked by hand in tests/methods/three_ways_test.cpp: (3, 0, -1.5) at elasticity 2 gives
  // (-2, 1, 2.5) at once or with impulses that only push, (-1.5, 0, 3) serially (order 0, 1, 0).
  const std::string scene = t::quote(lab_scene("two-balls-hit-one.json"));
  const auto serial = t::run("solve " + scene + " --method serial --format json");
  REQUIRE(serial.status == 0);
  CHECK(serial.err.empty());
  const json s = json::parse(serial.out);
  CHECK(s["method"] == "serial");
  CHECK_THAT(velocities(s), Catch::Matchers::Approx(std::vector<double>{-1.5, 0, 3}));
  CHECK(s["serial"]["order"] == json::array({0, 1, 0}));
  CHECK(s["serial"]["passes"] == 2);

  const auto lcp = t::run("solve " + scene + " -m complementarity --format json");
  REQUIRE(lcp.status == 0);
  const json c = json::parse(lcp.out);
  CHECK(c["method"] == "complementarity");
  CHECK_THAT(velocities(c), Catch::Matchers::Approx(std::vector<double>{-2, 1, 2.5}));
  CHECK(c["complementarity"]["converged"] == true);

  // The paper's method by default: its report names no method (it is the specified one).
  const auto plain = t::run("solve " + scene + " --format json");
  REQUIRE(plain.status == 0);
  CHECK_FALSE(json::parse(plain.out).contains("method"));

  const auto text = t::run("solve " + scene + " --method serial");
  REQUIRE(text.status == 0);
  CHECK_THAT(text.out, Contains("Method: serial"));
  CHECK_THAT(text.out,
             Contains("3 collisions in 2 passes (bound 10000); contacts in turn: 0, 1, 0"));
  CHECK_THAT(t::run("solve " + scene).out, Contains("Method: simultaneous"));
}

TEST_CASE("solve --compare: the three answers side by side", "[cli][methods]") {
  const std::string scene = t::quote(lab_scene("two-balls-hit-one.json"));
  const auto text = t::run("solve " + scene + " --compare");
  REQUIRE(text.status == 0);
  CHECK(text.err.empty());  // no impulse pulls in this scene
  CHECK(t::has_row(text.out,
                   {"contact", "bumper", "wedge", "simultaneous", "complementarity", "serial"}));
  // Impulses: (5, 4), (5, 4), (4.5, 4.5); velocities (-2, 1, 2.5) twice and (-1.5, 0, 3).
  CHECK(t::has_row(text.out, {"0", "left", "middle", "5", "5", "4.5"}));
  CHECK(t::has_row(text.out, {"1", "middle", "right", "4", "4", "4.5"}));
  CHECK(t::has_row(text.out, {"left", "3", "-2", "-2", "-1.5"}));
  CHECK(t::has_row(text.out, {"right", "-1.5", "2.5", "2.5", "3"}));
  CHECK(t::has_row(text.out, {"kinetic energy", "5.625", "5.625", "5.625", "5.625"}));
  CHECK(t::has_row(text.out, {"serial:", "3 collisions in 2 passes, order 0, 1, 0"}));

  const auto js = t::run("solve " + scene + " --compare --format json");
  REQUIRE(js.status == 0);
  const json j = json::parse(js.out);
  REQUIRE(j.size() == 3);
  for (const char* method : {"simultaneous", "complementarity", "serial"}) {
    CAPTURE(method);
    REQUIRE(j.contains(method));
    CHECK(j[method]["method"] == method);
  }
  CHECK_THAT(velocities(j["simultaneous"]),
             Catch::Matchers::Approx(std::vector<double>{-2, 1, 2.5}));
  CHECK_THAT(velocities(j["complementarity"]),
             Catch::Matchers::Approx(std::vector<double>{-2, 1, 2.5}));
  CHECK_THAT(velocities(j["serial"]), Catch::Matchers::Approx(std::vector<double>{-1.5, 0, 3}));

  // --compare and --method exclude each other; an unknown method is a usage error.
  CHECK(t::run("solve " + scene + " --compare --method serial").status == 2);
  const auto unknown = t::run("solve " + scene + " --method sequential");
  CHECK(unknown.status == 2);
  CHECK(unknown.out.empty());
}

TEST_CASE(
    "Every negative impulse is flagged on stderr, whatever the method; the exit status "
    "stays 0",
    "[cli][methods]") {
  // The spinning rod (tests/methods/three_ways_test.cpp): the paper's impulses are (8/3, -2/3);
  // with impulses that only push (3, 0), serially (3, 1).
  const std::string scene = t::quote(lab_scene("rod-spins-off-ground.json"));
  const auto plain = t::run("solve " + scene + " --format json");
  REQUIRE(plain.status == 0);
  CHECK(plain.err ==
        "impulselab: warning: contact 1 (ground\u2013rod): negative impulse -0.666667 (the "
        "contact pulls)\n");
  CHECK(json::parse(plain.out)["impulses"][1]["magnitude"].get<double>() ==
        Approx(-2.0 / 3).epsilon(1e-14));
  for (const char* method : {"complementarity", "serial"}) {
    CAPTURE(method);
    const auto run = t::run("solve " + scene + " --method " + method);
    REQUIRE(run.status == 0);
    CHECK(run.err.empty());
  }
  const auto compared = t::run("solve " + scene + " --compare");
  REQUIRE(compared.status == 0);
  CHECK(compared.err ==
        "impulselab: warning: simultaneous: contact 1 (ground\u2013rod): negative impulse "
        "-0.666667 (the contact pulls)\n");
  CHECK(t::has_row(compared.out, {"1", "ground", "rod", "-0.666667", "0", "1"}));
  // The rising end after: approaching at 4 (the paper), 2 (complementarity), separating at 2.
  CHECK(t::has_row(compared.out, {"1", "-4", "4", "2", "-2"}));
}

TEST_CASE("Serial collisions at their bound: exit 1 and a message that says what to do",
          "[cli][methods]") {
  // Lab 7's light ball between a wall and a ball 100 times heavier: 31 collisions (pi).
  const auto lab =
      t::run("solve " + t::quote(lab_scene("light-ball-heavy-ball.json")) + " --format json");
  REQUIRE(lab.status == 0);
  CHECK(json::parse(lab.out)["serial"]["collisions"] == 31);

  // 1e8 times heavier: 31415 collisions, above the default bound (100 per contact, at least
  // 10000).
  const std::string galperin =
      scratch_scene("galperin-hundred-million.json", galperin_hundred_million);
  const auto stopped = t::run("solve " + t::quote(galperin));
  CHECK(stopped.status == 1);
  CHECK(stopped.out.empty());
  CHECK_THAT(stopped.err,
             Contains("impulselab: error: " + galperin +
                      ": serial collisions did not end: after 10000 collisions (the bound: "
                      "solver.max_collisions, by default 100 per contact, at least 10000), "
                      "contact ") &&
                 Contains("still approaches at") && Contains("raise \"max_collisions\""));

  // With the bound raised in the scene it finishes: 31415.
  std::string raised(galperin_hundred_million);
  raised.replace(raised.find("\"method\": \"serial\""), 18,
                 "\"method\": \"serial\", \"max_collisions\": 40000");
  const auto enough =
      t::run("solve " + t::quote(scratch_scene("galperin-raised.json", raised)) + " --format json");
  REQUIRE(enough.status == 0);
  CHECK(json::parse(enough.out)["serial"]["collisions"] == 31415);

  // --compare still shows the two other answers, then fails for the third.
  const auto compared = t::run("solve " + t::quote(galperin) + " --compare");
  CHECK(compared.status == 1);
  CHECK(t::has_row(compared.out, {"light", "0", "0", "0", "-"}));
  CHECK_THAT(compared.err, Contains("serial collisions did not end"));
  const auto compared_json = t::run("solve " + t::quote(galperin) + " --compare --format json");
  CHECK(compared_json.status == 1);
  const json j = json::parse(compared_json.out);
  CHECK(j["serial"]["method"] == "serial");
  CHECK_THAT(j["serial"]["error"].get<std::string>(), Contains("did not end"));
  CHECK(j["complementarity"]["method"] == "complementarity");

  // sweep, too, refuses a serial sweep that does not end, and writes nothing.
  const auto sweep = t::run("sweep " + t::quote(galperin) + " --elasticity 1.5:2:0.5");
  CHECK(sweep.status == 1);
  CHECK(sweep.out.empty());
  CHECK_THAT(sweep.err, Contains("at elasticity 1.5") || Contains("at elasticity 2"));
}

TEST_CASE("solve --help names the methods and --compare", "[cli][methods]") {
  const auto help = t::run("solve --help");
  REQUIRE(help.status == 0);
  CHECK_THAT(help.out,
             Contains("--compare") && Contains("--method") && Contains("complementarity"));
}
