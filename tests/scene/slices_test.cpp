// SPDX-License-Identifier: GPL-3.0-or-later
// A run in slices (scene::RunInSlices, what the page advances between frames): whatever the
// slice, the report, the warnings, why a method did not finish and the refusals are run()'s.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/run.hpp"
#include "support/scene_files.hpp"

namespace sc = impulse::scene;
namespace me = impulse::methods;

namespace {

// The run advanced @p slice collisions at a time; the number of collisions checked on the way.
sc::Run in_slices(const sc::World& world, const sc::Request& request, std::int64_t slice) {
  sc::RunInSlices run(world, "scene.json", request);
  std::int64_t calls = 0;
  while (!run.advance(slice)) {
    ++calls;
    REQUIRE(run.collisions() == calls * slice);
    REQUIRE(run.collisions() < run.bound());
  }
  return run.finish();
}

void require_same(const sc::Run& a, const sc::Run& b) {
  CHECK(sc::report_json(a, "scene.json") == sc::report_json(b, "scene.json"));
  CHECK(a.warnings == b.warnings);
  CHECK(a.unfinished == b.unfinished);
}

// Three balls on a line, the middle one light between two heavy ones closing on it: serial
// collisions go back and forth (Galperin's billiard); a bound of 12 stops them unfinished.
const char* const billiard = R"({"dimension": 1, "elasticity": 2,
  "bodies": [{"name": "a", "kind": "material", "mass": 100, "velocity": 1},
             {"name": "b", "kind": "material", "mass": 1, "velocity": 0},
             {"name": "c", "kind": "material", "mass": 100, "velocity": -1}],
  "contacts": [{"bumper": "a", "wedge": "b", "normal": 1},
               {"bumper": "b", "wedge": "c", "normal": 1}],
  "solver": {"method": "serial", "max_collisions": 12}})";

}  // namespace

TEST_CASE("A run in slices gives run()'s report for every example scene and method",
          "[scene][methods]") {
  std::vector<std::string> texts{billiard};
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSELAB_SCENES_DIR)) {
    if (entry.path().extension() == ".json") {
      texts.push_back(impulselab::test::read_scene_text(entry.path().string()));
    }
  }
  REQUIRE(texts.size() > 10);
  std::size_t serial_runs = 0;
  for (const std::string& text : texts) {
    const sc::World world = sc::parse_world(text, "scene.json");
    for (const me::Method method : me::all_methods) {
      CAPTURE(text, impulse::name_of(method));
      const sc::Request request{.method = method};
      if (!sc::unsupported(world, method).empty()) {
        continue;  // refused alike: the next test
      }
      const sc::Run whole = sc::run(world, "scene.json", request);
      for (const std::int64_t slice : {1, 5}) {
        require_same(in_slices(world, request, slice), whole);
      }
      serial_runs += method == me::Method::serial ? 1 : 0;
    }
    // A row of a sweep, and a comparison (which runs whole when finished).
    const sc::Request row{.elasticity = 1.5};
    require_same(in_slices(world, row, 1), sc::run(world, "scene.json", row));
    const sc::Request compare{.compare = sc::Request::Compare::methods};
    require_same(in_slices(world, compare, 1), sc::run(world, "scene.json", compare));
  }
  CHECK(serial_runs == texts.size());
}

TEST_CASE("A run in slices refuses what run() refuses, with the same words", "[scene][errors]") {
  // Friction at two contacts: the paper's simultaneous method cannot take it.
  const std::string rough = R"({"dimension": 2, "elasticity": 1.5,
    "bodies": [{"name": "floor", "kind": "static"},
               {"name": "rod", "kind": "rigid", "mass": 1, "inertia": 0.1,
                "position": [0, 0.5], "velocity": [1, -1]}],
    "contacts": [{"bumper": "rod", "wedge": "floor", "point": [-0.5, 0], "normal": [0, -1],
                  "friction": 0.5},
                 {"bumper": "rod", "wedge": "floor", "point": [0.5, 0], "normal": [0, -1],
                  "friction": 0.5}]})";
  const sc::World world = sc::parse_world(rough, "scene.json");
  const sc::Request request{.method = me::Method::simultaneous};
  std::string whole;
  try {
    (void)sc::run(world, "scene.json", request);
  } catch (const impulse::InvalidInput& e) {
    whole = e.what();
  }
  REQUIRE_FALSE(whole.empty());
  CHECK_THROWS_WITH(sc::RunInSlices(world, "scene.json", request), whole);
  // The serial method takes it, and its collisions with friction in slices end alike.
  const sc::Request serial{.method = me::Method::serial};
  require_same(in_slices(world, serial, 1), sc::run(world, "scene.json", serial));
}
