// SPDX-License-Identifier: GPL-3.0-or-later
// The command line: the scene format's worked example, text and JSON output, standard input,
// usage errors and their exit statuses.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/program.hpp"
#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using nlohmann::json;
using t::worked;

namespace {

// The scene format's "Result" for its worked example, as the specification prints it.
const char* const specified_result = R"({
  "impulses": [{"contact": 0, "bumper": "a", "wedge": "b", "magnitude": 1.5,
                "on_bumper": [-1.5, 0.0]}],
  "bodies": [{"name": "a", "velocity": [0.0, 0.0], "momentum": [0.0, 0.0]},
             {"name": "b", "velocity": [1.5, 0.0], "momentum": [1.5, 0.0]}],
  "energy": {"before": 1.125, "after": 1.125, "change": 0.0},
  "momentum": {"before": [1.5, 0.0], "after": [1.5, 0.0]},
  "contacts": [{"contact": 0, "approach_before": 1.5, "approach_after": -1.5}],
  "system": {"A": [[2.0]], "B": [3.0], "rank": 1, "residual": 0.0,
             "dependent": false, "consistent": true,
             "policy": "minimum-norm"}
})";

// Same structure, same keys (apart from `allowed_extra` in objects), same strings and booleans,
// numbers within 1e-12.
void require_matches(const json& got, const json& expected, const std::string& path) {
  CAPTURE(path);
  if (expected.is_number()) {
    REQUIRE(got.is_number());
    REQUIRE(std::abs(got.get<double>() - expected.get<double>()) <= 1e-12);
  } else if (expected.is_object()) {
    REQUIRE(got.is_object());
    for (const auto& [key, value] : got.items()) {
      CAPTURE(key);
      REQUIRE((expected.contains(key) || (path == "system" && key == "condition_estimate")));
    }
    for (const auto& [key, value] : expected.items()) {
      REQUIRE(got.contains(key));
      require_matches(got[key], value, path.empty() ? key : path + "." + key);
    }
  } else if (expected.is_array()) {
    REQUIRE(got.is_array());
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      require_matches(got[i], expected[i], path + "[" + std::to_string(i) + "]");
    }
  } else {
    REQUIRE(got == expected);
  }
}

}  // namespace

TEST_CASE("The worked example's JSON is the specification's, to 1e-12", "[cli]") {
  const auto run = t::run("solve " + t::quote(worked) + " --format json");
  REQUIRE(run.status == 0);
  CHECK(run.err.empty());
  require_matches(json::parse(run.out), json::parse(specified_result), "");
}

TEST_CASE("Standard input: '-' reads the scene from it, messages call it <stdin>", "[cli]") {
  const auto from_file = t::run("solve " + t::quote(worked) + " --format json");
  const auto from_stdin = t::run("solve - --format json", worked);
  REQUIRE(from_stdin.status == 0);
  CHECK(from_stdin.out == from_file.out);
  const auto bad = t::run("solve -", t::cli_tests_path("malformed/negative-mass.json"));
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Contains("<stdin>: bodies[1].mass: must be positive and finite, got -1"));
}

TEST_CASE("The text report shows the tables a student reads", "[cli]") {
  const auto run = t::run("solve " + t::quote(worked));
  REQUIRE(run.status == 0);
  // Hand values of the worked example (see the library's scene tests): Fdt 1.5, the bumper gets
  // [-1.5, 0], a stops and b leaves at 1.5, energy 1.125 kept, approach 1.5 then -1.5, A = 2,
  // B = 3.
  const auto text = run.out;
  CHECK_THAT(text, Contains("Scene " + worked + ": dimension 2, 2 bodies, 1 contact"));
  CHECK(t::has_row(text, {"0", "a", "b", "1.5", "[-1.5, 0]"}));
  CHECK(t::has_row(text, {"a", "material", "[1.5, 0]", "[0, 0]", "[1.5, 0]", "[0, 0]"}));
  CHECK(t::has_row(text, {"b", "material", "[0, 0]", "[1.5, 0]", "[0, 0]", "[1.5, 0]"}));
  CHECK(t::has_row(text, {"kinetic energy", "1.125", "1.125", "0"}));
  CHECK(t::has_row(text, {"momentum", "[1.5, 0]", "[1.5, 0]", "[0, 0]"}));
  CHECK(t::has_row(text, {"0", "a", "b", "1.5", "-1.5"}));
  CHECK_THAT(text, Contains("1 equation, rank 1"));
  CHECK(t::has_row(text, {"2", "|", "1.5", "|", "3"}));
  CHECK(text.find('\033') == std::string::npos);  // not a terminal: no colour
}

TEST_CASE("Help, version and usage errors", "[cli]") {
  const auto help = t::run("--help");
  CHECK(help.status == 0);
  CHECK_THAT(help.out, Contains("solve") && Contains("sweep"));
  const auto solve_help = t::run("solve --help");
  CHECK(solve_help.status == 0);
  CHECK_THAT(solve_help.out, Contains("--format") && Contains("--output"));
  const auto sweep_help = t::run("sweep --help");
  CHECK(sweep_help.status == 0);
  CHECK_THAT(sweep_help.out, Contains("overridden"));
  const auto version = t::run("--version");
  CHECK(version.status == 0);
  CHECK(version.out == std::string("impulselab ") + IMPULSELAB_VERSION + "\n");

  // Every command-line error: exit 2, a message, nothing on standard output.
  for (const std::string& arguments : std::vector<std::string>{
           "", "frobnicate", "solve", "solve " + t::quote(worked) + " --format xml",
           "solve " + t::quote(worked) + " --bogus", "solve " + t::quote(worked) + " extra",
           "sweep " + t::quote(worked), "sweep " + t::quote(worked) + " --elasticity"}) {
    CAPTURE(arguments);
    const auto run = t::run(arguments);
    CHECK(run.status == 2);
    CHECK_FALSE(run.signalled);
    CHECK_FALSE(run.err.empty());
    CHECK(run.out.empty());
  }
}

TEST_CASE("Scene files that cannot be read: exit 2, the file named", "[cli]") {
  const auto missing = t::run("solve /nonexistent/scene.json");
  CHECK(missing.status == 2);
  CHECK_THAT(missing.err,
             Contains("/nonexistent/scene.json: cannot read: No such file or directory"));
  const auto folder = t::run("solve " + t::quote(IMPULSELAB_SCENES_DIR));
  CHECK(folder.status == 2);
  CHECK_THAT(folder.err, Contains("cannot read: it is a directory"));
}

TEST_CASE("The library's entry point prints what solve --format json prints, and warns alike",
          "[cli]") {
  // impulse::scene::solve_to_json is what a page running the library in a browser calls: for
  // every example scene, every method, its JSON must be the program's standard output byte for
  // byte, its warnings the program's standard error, and a scene the program refuses must be
  // refused with the program's message.
  namespace sc = impulse::scene;
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSELAB_SCENES_DIR)) {
    if (entry.path().extension() == ".json") {
      scenes.push_back(entry.path().string());
    }
  }
  scenes.push_back(t::cli_tests_path("scenes/ill-conditioned.json"));
  std::sort(scenes.begin(), scenes.end());
  for (const std::string& scene : scenes) {
    for (const auto method : impulse::methods::all_methods) {
      const std::string name(impulse::name_of(method));
      CAPTURE(scene, name);
      const sc::JsonRun library = sc::solve_to_json(t::read_text(scene), scene, {.method = method});
      const auto program = t::run("solve " + t::quote(scene) + " --format json --method " + name);
      std::string warnings;
      for (const std::string& line : library.run.warnings) {
        warnings.append("impulselab: warning: ").append(line).append("\n");
      }
      if (library.run.unfinished.empty()) {
        CHECK(program.status == 0);
        CHECK(library.report == program.out);
        CHECK(warnings == program.err);
      } else {
        CHECK(program.status == 1);
        CHECK_THAT(program.err, Contains(library.run.unfinished));
      }
    }
  }
  const std::string malformed = t::cli_tests_path("malformed/negative-mass.json");
  const auto refused = t::run("solve " + t::quote(malformed) + " --format json");
  CHECK(refused.status == 2);
  try {
    (void)sc::solve_to_json(t::read_text(malformed), malformed);
    FAIL("the library accepted a scene the program refuses");
  } catch (const impulse::InvalidInput& e) {
    CHECK(refused.err == "impulselab: error: " + std::string(e.what()) + "\n");
  }
}
