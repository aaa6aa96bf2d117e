// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes and the other methods: solver.method and solver.max_collisions read and
// refused like the other keys, the result of each method, and its JSON report.
#include <catch2/catch.hpp>
#include <string>
#include <variant>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/report.hpp"

using impulse::InvalidInput;
namespace sc = impulse::scene;
namespace me = impulse::methods;

namespace {

// Two balls hitting one on a line: (3, 0, -1.5), masses 1, elasticity 2; `solver` is spliced in.
std::string two_hit_one(const std::string& solver) {
  return R"({"dimension": 1, "elasticity": 2,
    "bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": 3},
               {"name": "b", "kind": "material", "mass": 1, "velocity": 0},
               {"name": "c", "kind": "material", "mass": 1, "velocity": -1.5}],
    "contacts": [{"bumper": "a", "wedge": "b", "normal": 1},
                 {"bumper": "b", "wedge": "c", "normal": 1}])" +
         (solver.empty() ? std::string() : ", \"solver\": " + solver) + "}";
}

std::vector<double> velocities(const sc::Result& r) {
  std::vector<double> v;
  for (const auto& b : r.bodies) {
    v.push_back(b.after.velocity.x());
  }
  return v;
}

std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> result;
  for (const auto& [key, value] : j.items()) {
    result.push_back(key);
  }
  return result;
}

}  // namespace

TEST_CASE("solver.method and solver.max_collisions are read", "[scene][json][methods]") {
  CHECK(sc::parse_scene(two_hit_one(""), "s.json").method == me::Method::simultaneous);
  CHECK(sc::parse_scene(two_hit_one(""), "s.json").serial.max_collisions == 0);
  const auto serial =
      sc::parse_scene(two_hit_one(R"({"method": "serial", "max_collisions": 5})"), "s.json");
  CHECK(serial.method == me::Method::serial);
  CHECK(serial.serial.max_collisions == 5);
  CHECK(sc::parse_scene(two_hit_one(R"({"method": "complementarity", "dependent": "basic"})"),
                        "s.json")
            .method == me::Method::complementarity);
}

TEST_CASE("Bad methods and bounds are refused with the place", "[scene][json][methods][errors]") {
  CHECK_THROWS_MATCHES(
      sc::parse_scene(two_hit_one(R"({"method": "sequential"})"), "s.json"), InvalidInput,
      Catch::Matchers::Message("s.json: solver.method: expected one of \"simultaneous\", "
                               "\"complementarity\", \"serial\", got \"sequential\""));
  CHECK_THROWS_WITH(sc::parse_scene(two_hit_one(R"({"method": 2})"), "s.json"),
                    "s.json: solver.method: expected a string, got the number 2");
  for (const std::string bad : {"0", "-3", "1.5", "2e9", "\"10\""}) {
    CAPTURE(bad);
    CHECK_THROWS_WITH(
        sc::parse_scene(two_hit_one("{\"max_collisions\": " + bad + "}"), "s.json"),
        Catch::Matchers::StartsWith("s.json: solver.max_collisions: expected a whole number "
                                    "from 1 to 1000000000, got"));
  }
  CHECK_THROWS_WITH(
      sc::parse_scene(two_hit_one(R"({"metod": "serial"})"), "s.json"),
      Catch::Matchers::StartsWith("s.json: solver.metod: unknown key (did you mean \"method\"?)"));
  sc::Scene scene = sc::parse_scene(two_hit_one(""), "s.json");
  scene.serial.max_collisions = -1;
  CHECK_THROWS_WITH(sc::World(scene), "solver.max_collisions: must be at least 1, got -1");
}

TEST_CASE("Each method's result: the impulses, the bodies after, the system's diagnostics",
          "[scene][methods]") {
  // Hand-worked in tests/methods/three_ways_test.cpp: simultaneous (-2, 1, 2.5) with Fdt (5, 4);
  // serial (-1.5, 0, 3) with Fdt (4.5, 4.5) in the order 0, 1, 0; complementarity = simultaneous.
  const auto simultaneous = sc::solve(sc::parse_scene(two_hit_one(""), "s.json"));
  CHECK(simultaneous.method == me::Method::simultaneous);
  const auto lcp =
      sc::solve(sc::parse_scene(two_hit_one(R"({"method": "complementarity"})"), "s.json"));
  const auto serial = sc::solve(sc::parse_scene(two_hit_one(R"({"method": "serial"})"), "s.json"));
  for (const auto* r : {&simultaneous, &lcp, &serial}) {
    REQUIRE(r->status == impulse::SolveStatus::success);
    CHECK(r->outcome.finished);
    CHECK(r->energy_change == Approx(0.0).margin(1e-14));
    CHECK(r->momentum_after.x() == Approx(1.5).epsilon(1e-14));
    // The system is the paper's whatever the method: A = [[2, -1], [-1, 2]], B = (6, 3), rank 2.
    CHECK(r->system.rank == 2);
    CHECK(r->system.B.isApprox(Eigen::Vector2d(6, 3)));
  }
  CHECK_THAT(velocities(lcp), Catch::Matchers::Approx(std::vector<double>{-2, 1, 2.5}));
  CHECK(lcp.method == me::Method::complementarity);
  CHECK(std::get<me::ComplementaritySolution>(lcp.outcome.solution).status ==
        me::LcpStatus::solved);
  CHECK(lcp.outcome.residual == Approx(0.0).margin(1e-13));
  CHECK_THAT(velocities(serial), Catch::Matchers::Approx(std::vector<double>{-1.5, 0, 3}));
  CHECK(serial.impulses[0].magnitude == Approx(4.5));
  CHECK(std::get<me::SerialDiagnostics>(serial.outcome.solution).order ==
        std::vector<Eigen::Index>{0, 1, 0});
  // Serial's impulses do not solve the paper's system: |A F - B| = |(9 - 4.5 - 6, -4.5 + 9 - 3)|
  // = |(-1.5, 1.5)| = 1.5 sqrt 2. The system itself keeps the paper's own solution, F = (5, 4),
  // whose residual is 0: rank, consistency and residual describe the same vector.
  CHECK(serial.outcome.residual == Approx(1.5 * std::sqrt(2.0)).epsilon(1e-14));
  CHECK(serial.outcome.Fdt.isApprox(Eigen::Vector2d(4.5, 4.5), 1e-14));
  CHECK(serial.system.Fdt.isApprox(Eigen::Vector2d(5, 4), 1e-14));
  CHECK(serial.system.residual == Approx(0.0).margin(1e-13));
  // The approach after of serial: (-1.5 - 0, 0 - 3) = (-1.5, -3).
  CHECK(serial.contacts[0].approach_after == Approx(-1.5));
  CHECK(serial.contacts[1].approach_after == Approx(-3));

  // A bound below the 3 collisions it needs: the method did not finish.
  const auto cut = sc::solve(
      sc::parse_scene(two_hit_one(R"({"method": "serial", "max_collisions": 2})"), "s.json"));
  CHECK_FALSE(cut.outcome.finished);
  const auto& diagnostics = std::get<me::SerialDiagnostics>(cut.outcome.solution);
  CHECK(diagnostics.status == me::SerialStatus::collision_limit);
  CHECK(diagnostics.still_approaching == 0);
  CHECK(diagnostics.approach_left == Approx(1.5));
  // The method's sentence names the contact as the scene does.
  CHECK_THAT(sc::unfinished_message(cut, "s.json"),
             Catch::Matchers::StartsWith("s.json: serial collisions did not end: after 2 "
                                         "collisions (the bound: solver.max_collisions, by "
                                         "default 100 per contact, at least 10000), contact 0 "
                                         "(a\u2013b) still "
                                         "approaches at 1.5"));
}

TEST_CASE("One system for every method: --compare assembles and solves it once",
          "[scene][methods]") {
  const sc::World world(sc::parse_scene(two_hit_one(""), "s.json"));
  const std::vector<sc::Result> all = sc::resolve(world, me::all_methods);
  REQUIRE(all.size() == 3);
  for (std::size_t k = 0; k < all.size(); ++k) {
    CHECK(all[k].method == me::all_methods[k]);
    // The same solved system in each: the paper's impulses (5, 4).
    CHECK(all[k].system.Fdt.isApprox(Eigen::Vector2d(5, 4), 1e-14));
  }
  CHECK(all[2].outcome.Fdt.isApprox(Eigen::Vector2d(4.5, 4.5), 1e-14));
}

TEST_CASE("A method's per-contact values reach both reports without a switch on the method",
          "[scene][json][methods]") {
  // What Coulomb friction will add: a tangential impulse and how each contact ended. Added here
  // by hand to a solved result, they must appear in each entry of "impulses" and as columns of
  // the text report's table of impulses.
  sc::Result r = sc::solve(sc::parse_scene(two_hit_one(""), "s.json"));
  r.outcome.per_contact.push_back({"tangential", "tangential", std::vector<double>{0.25, -0.5}});
  r.outcome.per_contact.push_back({"slip", "ends", std::vector<std::string>{"stick", "slip"}});
  const auto json = sc::to_json(r);
  CHECK(json["impulses"][0]["tangential"] == 0.25);
  CHECK(json["impulses"][1]["slip"] == "slip");
  CHECK(keys(json["impulses"][0]) == std::vector<std::string>{"contact", "bumper", "wedge",
                                                              "magnitude", "on_bumper",
                                                              "tangential", "slip"});
  const std::string text = sc::text_report(r, "s.json", false);
  CHECK_THAT(text, Catch::Matchers::Contains("on bumper  tangential  ends"));
  CHECK_THAT(text, Catch::Matchers::Contains("0.25  stick"));
}

TEST_CASE("The JSON report names the method and adds its diagnostics", "[scene][json][methods]") {
  // The paper's method: exactly the specified keys, no "method".
  const auto plain = sc::to_json(sc::solve(sc::parse_scene(two_hit_one(""), "s.json")));
  CHECK(keys(plain) ==
        std::vector<std::string>{"impulses", "bodies", "energy", "momentum", "contacts", "system"});

  const auto lcp = sc::to_json(
      sc::solve(sc::parse_scene(two_hit_one(R"({"method": "complementarity"})"), "s.json")));
  CHECK(keys(lcp) == std::vector<std::string>{"impulses", "bodies", "energy", "momentum",
                                              "contacts", "system", "method", "complementarity"});
  CHECK(lcp["method"] == "complementarity");
  CHECK(keys(lcp["complementarity"]) ==
        std::vector<std::string>{"algorithm", "iterations", "complementarity_residual", "converged",
                                 "least_norm", "slack"});
  CHECK(lcp["complementarity"]["algorithm"] == "active-set");
  CHECK(lcp["complementarity"]["converged"] == true);
  CHECK(lcp["complementarity"]["slack"].size() == 2);

  const auto serial =
      sc::to_json(sc::solve(sc::parse_scene(two_hit_one(R"({"method": "serial"})"), "s.json")));
  CHECK(serial["method"] == "serial");
  CHECK(keys(serial["serial"]) ==
        std::vector<std::string>{"collisions", "passes", "order", "max_collisions", "finished"});
  CHECK(serial["serial"]["collisions"] == 3);
  CHECK(serial["serial"]["passes"] == 2);
  CHECK(serial["serial"]["order"] == nlohmann::json::array({0, 1, 0}));
  CHECK(serial["serial"]["max_collisions"] == 10000);  // 2 contacts: at least 10000
  CHECK(serial["serial"]["finished"] == true);
}
