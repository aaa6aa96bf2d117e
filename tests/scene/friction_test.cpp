// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes with friction and the three restitution laws: the keys `friction` and
// `solver.restitution` read, checked with their place, and resolved through the pipeline by the
// exact single-contact rule (impulse::friction::collide). Every expected value is worked by hand
// in the comment above it.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/report.hpp"
#include "support/scene_files.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::Message;
using impulse::InvalidInput;
using nlohmann::json;
namespace sc = impulse::scene;

namespace {

// A point mass (mass 1) dropping onto a static floor; the ball is the bumper and its outward
// normal points down, n = (0, -1), so the tangent is t = [-n_y, n_x] = (1, 0) and the impulse on
// the ball is -n P_n + t P_t = (P_t, P_n).
std::string ball_scene(double vx, double mu, const std::string& law) {
  return R"({"dimension": 2, "elasticity": 1.5, "friction": )" + std::to_string(mu) +
         R"(, "bodies": [{"name": "ball", "kind": "material", "mass": 1, "velocity": [)" +
         std::to_string(vx) + R"(, -1]}, {"name": "floor", "kind": "static"}],
  "contacts": [{"bumper": "ball", "wedge": "floor", "normal": [0, -1]}],
  "solver": {"restitution": ")" +
         law + R"("}})";
}

// The issue's rod: m = 1, L = 1, I = 1/12, at 45°, its lower end at the origin on a static floor,
// centre at (√2/4, √2/4) (it leans the way it moves), centre velocity (0.7, -1), no spin.
std::string rod_scene(const std::string& law, const std::string& method = "simultaneous") {
  return R"({"dimension": 2, "elasticity": 1.9, "friction": 0.8,
  "bodies": [{"name": "rod", "kind": "rigid", "mass": 1, "inertia": 0.08333333333333333,
              "position": [0.3535533905932738, 0.3535533905932738], "velocity": [0.7, -1]},
             {"name": "floor", "kind": "static"}],
  "contacts": [{"bumper": "rod", "wedge": "floor", "normal": [0, -1], "point": [0, 0]}],
  "solver": {"restitution": ")" +
         law + R"(", "method": ")" + method + R"("}})";
}

sc::Result solved(const std::string& text) {
  return sc::resolve(sc::parse_world(text, "s.json"));
}

const std::vector<double>& numbers(const sc::Result& r, const std::string& key) {
  for (const auto& column : r.outcome.per_contact) {
    if (column.key == key) {
      return std::get<std::vector<double>>(column.values);
    }
  }
  FAIL("no column " << key);
  throw;
}

const std::vector<std::string>& words(const sc::Result& r, const std::string& key) {
  for (const auto& column : r.outcome.per_contact) {
    if (column.key == key) {
      return std::get<std::vector<std::string>>(column.values);
    }
  }
  FAIL("no column " << key);
  throw;
}

void refused(const std::string& text, const std::string& message) {
  CHECK_THROWS_MATCHES(sc::parse_world(text, "s.json"), InvalidInput, Message(message));
}

}  // namespace

TEST_CASE("Friction: a point mass sliding on a rough floor throughout, every law",
          "[scene][friction]") {
  // v = (1, -1), μ = 0.2, elasticity 1.5. W = I (mass 1), u0 = (-1, 1). Sliding forwards:
  // dP_t = -0.2 dP_n, slip 1 - 0.2 P_n. Compression ends at P_n = 1; Newton: separation 0.5
  // after, so P_n = 1.5; Poisson: 1.5 × 1 = 1.5; energetic: the normal motion is decoupled, work
  // of compression -1/2, of restitution 0.25 × 1/2, separation 0.5: 1.5. Slip at 1.5: 0.7 > 0,
  // it slides throughout; P_t = -0.3; the ball leaves at (0.7, 0.5).
  for (const std::string law : {"newton", "poisson", "energetic"}) {
    INFO(law);
    const sc::Result r = solved(ball_scene(1.0, 0.2, law));
    REQUIRE(r.status == impulse::SolveStatus::success);
    CHECK(r.impulses[0].magnitude == Approx(1.5).epsilon(1e-14));
    CHECK(numbers(r, "tangential")[0] == Approx(-0.3).epsilon(1e-14));
    CHECK(words(r, "slip")[0] == "slip");
    CHECK(r.impulses[0].on_bumper.x() == Approx(-0.3).epsilon(1e-14));
    CHECK(r.impulses[0].on_bumper.y() == Approx(1.5).epsilon(1e-14));
    CHECK(r.bodies[0].after.velocity.x() == Approx(0.7).epsilon(1e-14));
    CHECK(r.bodies[0].after.velocity.y() == Approx(0.5).epsilon(1e-14));
    // KE 1 before, (0.49 + 0.25)/2 = 0.37 after: lost.
    CHECK(r.energy_after == Approx(0.37).epsilon(1e-14));
    CHECK(r.outcome.warnings.empty());
  }
}

TEST_CASE("Friction: a point mass stopping to stick on a rough floor, every law",
          "[scene][friction]") {
  // v = (0.5, -1), μ = 1: slip 0.5 - P_n stops at P_n = 0.5, before compression ends (at 1); a
  // point mass has W_tn = 0 <= μ W_tt, so it sticks: P_t stays -0.5. P_n = 1.5 for every law (as
  // above); the ball leaves straight up at (0, 0.5).
  for (const std::string law : {"newton", "poisson", "energetic"}) {
    INFO(law);
    const sc::Result r = solved(ball_scene(0.5, 1.0, law));
    CHECK(r.impulses[0].magnitude == Approx(1.5).epsilon(1e-14));
    CHECK(numbers(r, "tangential")[0] == Approx(-0.5).epsilon(1e-14));
    CHECK(words(r, "slip")[0] == "stick");
    CHECK(std::abs(r.bodies[0].after.velocity.x()) <= 1e-15);
    CHECK(r.bodies[0].after.velocity.y() == Approx(0.5).epsilon(1e-14));
    // The phases in the text report: slip until 0.5, stick until 1.5; compression ended at 1.
    CHECK_THAT(sc::text_report(r, "s.json", false),
               Contains("contact 0 (ball\u2013floor): slip until Fdt = 0.5, stick until 1.5; "
                        "compression ended at Fdt = 1"));
  }
}

TEST_CASE("Friction: the issue's rod on a rough floor, the three laws", "[scene][friction]") {
  // W = [[2.5, -1.5], [-1.5, 2.5]] (W_nn = 1/m + det(r, n)²/I = 1 + (1/8)·12), u0 = (-1, 0.7).
  // Slip: du/dP_n = (2.5 + 0.8·1.5, -1.5 - 0.8·2.5) = (3.7, -3.5): slip stops at P_n = 0.2
  // (u_n = -0.26, P_t = -0.16). |W_tn|/W_tt = 0.6 <= 0.8: it sticks, dP_t = 0.6 dP_n and
  // du_n = 1.6 dP_n: compression ends at 0.2 + 0.26/1.6 = 0.3625.
  // Newton: u_n = 0.9 after: 0.2 + (0.9 + 0.26)/1.6 = 0.925; P_t = -0.16 + 0.6·0.725 = 0.275.
  // Poisson: 1.9 × 0.3625 = 0.68875; P_t = -0.16 + 0.6·0.48875 = 0.13325.
  // Energetic: compression's normal work -0.147125 (report17-core); while sticking u_n =
  // 1.6 (P_n - 0.3625), so restitution's work is 0.8 x² with x = P_n - 0.3625; 0.8 x² = 0.9² ·
  // 0.147125 gives x² = 0.1489640625, P_n = 0.3625 + sqrt(0.1489640625) = 0.748458628...,
  // P_t = -0.16 + 0.6 (P_n - 0.2).
  // Energy before: (0.49 + 1)/2 = 0.745. After, E' = |v'|²/2 + (3/4)(P_n - P_t)² (the spin
  // ω' = 12·(√2/4)(P_t - P_n), so I ω'²/2 = (1/24)·144·(1/8)(P_n - P_t)²):
  // Newton: v' = (0.975, -0.075), 0.478125 + 0.75·0.4225 = 0.795 (gains 0.05);
  // Poisson: v' = (0.83325, -0.31125), 0.3955910625 + 0.75·0.5555² = 0.62702625.
  struct Expected {
    std::string law;
    double normal;
    double tangential;
    double energy_after;
  };
  const double energetic_normal = 0.3625 + std::sqrt(0.1489640625);
  const double energetic_tangential = -0.16 + 0.6 * (energetic_normal - 0.2);
  const double energetic_energy =
      0.5 * ((0.7 + energetic_tangential) * (0.7 + energetic_tangential) +
             (-1.0 + energetic_normal) * (-1.0 + energetic_normal)) +
      0.75 * (energetic_normal - energetic_tangential) * (energetic_normal - energetic_tangential);
  for (const Expected& e :
       {Expected{"newton", 0.925, 0.275, 0.795}, Expected{"poisson", 0.68875, 0.13325, 0.62702625},
        Expected{"energetic", energetic_normal, energetic_tangential, energetic_energy}}) {
    for (const std::string method : {"simultaneous", "complementarity", "serial"}) {
      INFO(e.law << " by " << method);
      const sc::Result r = solved(rod_scene(e.law, method));
      REQUIRE(r.status == impulse::SolveStatus::success);
      CHECK(r.impulses[0].magnitude == Approx(e.normal).epsilon(1e-12));
      CHECK(numbers(r, "tangential")[0] == Approx(e.tangential).epsilon(1e-12));
      CHECK(words(r, "slip")[0] == "stick");
      CHECK(r.energy_before == Approx(0.745).epsilon(1e-14));
      CHECK(r.energy_after == Approx(e.energy_after).epsilon(1e-12));
      // The energy warning: Newton's gains (0.05 at elasticity 1.9 <= 2), the others lose.
      if (e.law == "newton") {
        CHECK(r.energy_change == Approx(0.05).epsilon(1e-11));
        REQUIRE(r.outcome.warnings.size() == 1);
        CHECK(r.outcome.warnings[0] ==
              "energy gained: Newton's restitution with friction; see the docs page on friction");
      } else {
        CHECK(r.energy_change < 0.0);
        CHECK(r.outcome.warnings.empty());
      }
    }
  }
  // The energetic law's figure as report17-core worked it by hand.
  CHECK(energetic_normal == Approx(0.748458628).epsilon(1e-9));
  CHECK(energetic_energy == Approx(0.66104625).epsilon(1e-9));
}

TEST_CASE("Friction: the rod's phases and works in the report", "[scene][friction]") {
  const sc::Result r = solved(rod_scene("newton"));
  CHECK_THAT(sc::text_report(r, "s.json", false),
             Contains("contact 0 (rod\u2013floor): slip until Fdt = 0.2, stick until 0.925; "
                      "compression ended at Fdt = 0.3625"));
  const json j = sc::to_json(r);
  CHECK(j["impulses"][0]["tangential"].get<double>() == Approx(0.275).epsilon(1e-12));
  CHECK(j["impulses"][0]["slip"] == "stick");
  // on_bumper is the whole vector -n P_n + t P_t = (P_t, P_n).
  CHECK(j["impulses"][0]["on_bumper"][0].get<double>() == Approx(0.275).epsilon(1e-12));
  CHECK(j["impulses"][0]["on_bumper"][1].get<double>() == Approx(0.925).epsilon(1e-12));
  CHECK(j["simultaneous"]["phases"] == "slip, stick");
  CHECK(j["simultaneous"]["compression"].get<double>() == Approx(0.3625).epsilon(1e-12));
  // The works: compression's -0.147125 and friction's -0.056 (report17-core, by hand).
  CHECK(j["simultaneous"]["work_compression"].get<double>() == Approx(-0.147125).epsilon(1e-12));
}

TEST_CASE("Friction: without the keys, or with friction 0 and Newton's law, nothing changes",
          "[scene][friction]") {
  // The paper's path is taken (no friction path at all), so the JSON is byte-identical.
  const std::string plain = R"({"dimension": 2, "elasticity": 1.9,
  "bodies": [{"name": "rod", "kind": "rigid", "mass": 1, "inertia": 0.08333333333333333,
              "position": [0.3535533905932738, 0.3535533905932738], "velocity": [0.7, -1]},
             {"name": "floor", "kind": "static"}],
  "contacts": [{"bumper": "rod", "wedge": "floor", "normal": [0, -1], "point": [0, 0)";
  const std::string without = plain + "]}]}";
  const std::string with_keys = R"({"friction": 0, "solver": {"restitution": "newton"},)" +
                                plain.substr(1) + R"(], "friction": 0}]})";
  for (const auto method : impulse::methods::all_methods) {
    CHECK(sc::solve_to_json(with_keys, "s.json", {.method = method}).report ==
          sc::solve_to_json(without, "s.json", {.method = method}).report);
  }
  // And the paper's frictionless impulse 1.9/2.5 = 0.76 is what all three laws give at μ = 0.
  for (const std::string law : {"newton", "poisson", "energetic"}) {
    std::string text = rod_scene(law);
    text.replace(text.find("\"friction\": 0.8"), 15, "\"friction\": 0");
    CHECK(solved(text).impulses[0].magnitude == Approx(0.76).epsilon(1e-14));
  }
}

TEST_CASE("Friction: bad keys are refused with their place", "[scene][friction]") {
  auto with = [](const std::string& from, const std::string& to,
                 const std::string& law = "newton") {
    std::string text = ball_scene(1.0, 0.2, law);
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  refused(with("\"friction\": 0.200000", "\"friction\": -0.5"),
          "s.json: friction: must be finite and at least 0, got -0.5");
  refused(with("\"friction\": 0.200000", "\"friction\": \"rough\""),
          "s.json: friction: expected a number, got the string \"rough\"");
  refused(with("\"normal\": [0, -1]", "\"normal\": [0, -1], \"friction\": -1"),
          "s.json: contacts[0].friction: must be finite and at least 0, got -1");
  refused(with("\"normal\": [0, -1]", "\"normal\": [0, -1], \"friction\": [1]"),
          "s.json: contacts[0].friction: expected a number, got an array of 1 element");
  refused(with("\"restitution\": \"newton\"", "\"restitution\": \"hooke\""),
          "s.json: solver.restitution: expected one of \"newton\", \"poisson\", \"energetic\", "
          "got \"hooke\"");
  refused(with("\"restitution\": \"newton\"", "\"restitution\": 2"),
          "s.json: solver.restitution: expected a string, got the number 2");
  // The exact rule needs an elasticity from 1 (and at most 2 for the energetic law).
  refused(with("\"elasticity\": 1.5", "\"elasticity\": 0.5"),
          "s.json: elasticity: must be at least 1 with friction or solver.restitution other than "
          "\"newton\" (the rule follows the impulse through compression), got 0.5");
  refused(with("\"elasticity\": 1.5", "\"elasticity\": 2.5", "energetic"),
          "s.json: elasticity: must be at most 2 with solver.restitution \"energetic\" (it gives "
          "back a fraction of the energy stored in compression), got 2.5");
}

TEST_CASE("Friction: several contacts: serial collisions, the other methods refused",
          "[scene][friction]") {
  // The ball of the sliding case on the floor (contact 0), and a second ball far to the right
  // touching it (contact 1) but moving away: only contact 0 collides, so serial collisions give
  // the single-contact answer (P_n 1.5, P_t -0.3, slip); contact 1 gets no impulse and, as the
  // ball leaves at (0.7, 0.5) and the other rests, its bodies slip past each other (the relative
  // velocity (0.7, 0.5) has a component along its tangent [0, 1]).
  const std::string text = R"({"dimension": 2, "elasticity": 1.5, "friction": 0.2,
  "bodies": [{"name": "ball", "kind": "material", "mass": 1, "velocity": [1, -1]},
             {"name": "floor", "kind": "static"},
             {"name": "other", "kind": "material", "mass": 1, "velocity": [5, 0]}],
  "contacts": [{"bumper": "ball", "wedge": "floor", "normal": [0, -1]},
               {"bumper": "ball", "wedge": "other", "normal": [1, 0]}],
  "solver": {"method": "serial"}})";
  const sc::World world = sc::parse_world(text, "s.json");
  const sc::Result r = sc::resolve(world);
  CHECK(r.impulses[0].magnitude == Approx(1.5).epsilon(1e-14));
  CHECK(r.impulses[1].magnitude == 0.0);
  CHECK(numbers(r, "tangential")[0] == Approx(-0.3).epsilon(1e-14));
  CHECK(numbers(r, "tangential")[1] == 0.0);
  CHECK(words(r, "slip")[0] == "slip");
  CHECK(words(r, "slip")[1] == "slip");
  CHECK(r.outcome.details[0] ==
        "each collision by the exact single-contact rule: friction 0.2, Newton's restitution");
  // The paper's simultaneous method is refused; the complementarity method solves the same
  // contacts at once: contact 1 separates (the other ball leaves at 5), so the answer is contact
  // 0's alone, as above.
  CHECK_THROWS_MATCHES(
      sc::run(world, "s.json", {.method = impulse::methods::Method::simultaneous}), InvalidInput,
      Message("s.json: contacts: the method \"simultaneous\" cannot resolve 2 contacts with "
              "friction (contacts[0] has 0.2): the paper's simultaneous system has no friction "
              "and only Newton's law; the serial method (solver.method \"serial\", or --method "
              "serial) resolves each collision by the exact single-contact rule"));
  const sc::Result c = sc::resolve(world, impulse::methods::Method::complementarity);
  CHECK(c.impulses[0].magnitude == Approx(1.5).epsilon(1e-12));
  CHECK(c.impulses[1].magnitude == 0.0);
  CHECK(numbers(c, "tangential")[0] == Approx(-0.3).epsilon(1e-12));
  CHECK(numbers(c, "tangential")[1] == 0.0);
  CHECK(words(c, "slip")[0] == "slip");
  CHECK(words(c, "slip")[1] == "slip");
  // Poisson's law needs the end of compression, which one problem for all contacts has not.
  std::string poisson = text;
  poisson.replace(poisson.find("\"method\": \"serial\""), 18,
                  "\"method\": \"complementarity\", \"restitution\": \"poisson\"");
  CHECK_THROWS_MATCHES(
      sc::resolve(sc::parse_world(poisson, "s.json")), InvalidInput,
      Message("contacts: the method \"complementarity\" cannot resolve 2 contacts with "
              "friction (contacts[0] has 0.2) and Poisson's restitution: the complementarity "
              "method applies Newton's law only (it solves all contacts at once, with no end of "
              "compression, which Poisson's restitution needs); the serial method "
              "(solver.method \"serial\", or --method serial) resolves each collision by the "
              "exact single-contact rule"));
  // --compare compares the methods that can: serial and complementarity, and says why not the
  // paper's.
  const sc::Run compared = sc::run(world, "s.json", {.compare = sc::Request::Compare::methods});
  const json j = json::parse(sc::report_json(compared, "s.json"));
  CHECK(!j.contains("simultaneous"));
  CHECK(j.contains("complementarity"));
  CHECK(j.contains("serial"));
  CHECK(j["complementarity"]["impulses"][0]["tangential"].get<double>() ==
        Approx(-0.3).epsilon(1e-12));
  REQUIRE(!compared.warnings.empty());
  CHECK_THAT(compared.warnings.back(),
             Contains("simultaneous: not compared: the method \"simultaneous\" cannot resolve"));
}

// The box of tutorials/scenes/box-lands-flat.json (2 wide, 1 high, m = 1, I = 5/12, corners on
// the static ground at (-1, 0) and (1, 0), e = 1.5) with μ = 0.5, by the complementarity method.
sc::Result box_by_complementarity(double vx) {
  json scene = json::parse(impulselab::test::read_scene_text(std::string(IMPULSELAB_SCENES_DIR) +
                                                             "/box-lands-flat.json"));
  scene["friction"] = 0.5;
  scene["bodies"][1]["velocity"] = {vx, -1};
  scene["solver"] = {{"method", "complementarity"}};
  return sc::resolve(sc::parse_world(scene.dump(), "box.json"));
}

TEST_CASE("Friction: the box landing flat on two corners, complementarity with friction",
          "[scene][friction]") {
  // No horizontal speed. The paper's frictionless answer: A = [[3.4, -1.4], [-1.4, 3.4]],
  // B = (1.5, 1.5), F = 0.75 each, the box leaves at (0, 0.5) without spin, so no corner slips
  // and P_t = 0 meets Coulomb's law: it is the friction problem's answer too (the squeeze ±f,
  // |f| <= 0.375, would change nothing; the least-norm choice reports 0). KE 0.5 -> 0.125.
  const sc::Result r = box_by_complementarity(0.0);
  REQUIRE(r.outcome.finished);
  CHECK(r.impulses[0].magnitude == Approx(0.75).epsilon(1e-12));
  CHECK(r.impulses[1].magnitude == Approx(0.75).epsilon(1e-12));
  CHECK(std::abs(numbers(r, "tangential")[0]) < 1e-12);
  CHECK(std::abs(numbers(r, "tangential")[1]) < 1e-12);
  CHECK(words(r, "slip") == std::vector<std::string>{"stick", "stick"});
  CHECK((r.bodies[1].after.momentum - Eigen::Vector2d(0, 0.5)).norm() < 1e-12);
  CHECK(std::abs(r.bodies[1].after.angular_momentum) < 1e-12);
  CHECK(r.energy_before == Approx(0.5));
  CHECK(r.energy_before + r.energy_change == Approx(0.125));
  CHECK(r.outcome.warnings.empty());
}

TEST_CASE("Friction: the box sliding flat on two corners, complementarity with friction",
          "[scene][friction]") {
  // Velocity (1, -1). Both corners push and slide forwards: P_t,v = -μ P_n,v on the ground along
  // t = (-1, 0), i.e. the box gets (P_t,v, P_n,v). Newton at both corners: ω' = 0, v_y' = 0.5,
  // P_n,0 + P_n,1 = 1.5; no torque: P_n,1 - P_n,0 = 0.5 μ 1.5 = 0.375. So P_n = (0.5625, 0.9375),
  // P_t = (-0.28125, -0.46875), v' = (1 - 0.75, 0.5) = (0.25, 0.5) (still sliding forwards),
  // KE 1 -> 0.15625.
  const sc::Result r = box_by_complementarity(1.0);
  REQUIRE(r.outcome.finished);
  CHECK(r.impulses[0].magnitude == Approx(0.5625).epsilon(1e-12));
  CHECK(r.impulses[1].magnitude == Approx(0.9375).epsilon(1e-12));
  CHECK(numbers(r, "tangential")[0] == Approx(-0.28125).epsilon(1e-12));
  CHECK(numbers(r, "tangential")[1] == Approx(-0.46875).epsilon(1e-12));
  CHECK(words(r, "slip") == std::vector<std::string>{"slip", "slip"});
  CHECK((r.bodies[1].after.momentum - Eigen::Vector2d(0.25, 0.5)).norm() < 1e-12);
  CHECK(std::abs(r.bodies[1].after.angular_momentum) < 1e-12);
  CHECK(r.energy_before + r.energy_change == Approx(0.15625));
}

TEST_CASE("Friction: several contacts with friction 0 give today's results, byte for byte",
          "[scene][friction]") {
  // μ = 0 everywhere and Newton's law: no contact law, so the frictionless path runs.
  json scene = json::parse(impulselab::test::read_scene_text(std::string(IMPULSELAB_SCENES_DIR) +
                                                             "/box-lands-flat.json"));
  const std::string without = scene.dump();
  scene["friction"] = 0;
  scene["solver"] = {{"restitution", "newton"}};
  const std::string with_keys = scene.dump();
  for (const auto method : impulse::methods::all_methods) {
    CHECK(sc::solve_to_json(with_keys, "s.json", {.method = method}).report ==
          sc::solve_to_json(without, "s.json", {.method = method}).report);
  }
}

TEST_CASE("Friction: the box landing flat on two corners, serial collisions with friction",
          "[scene][friction]") {
  // Not worked by hand (the order of collisions breaks the symmetry): the laws that hold
  // whatever the order. Each collision keeps |P_t| <= μ P_n, so their sums do too; the box (the
  // wedge of both contacts, the ground static) gains exactly minus the summed impulses on the
  // bumper; the energetic law never gains energy at a collision (tests/friction), so neither does
  // their sequence.
  json scene = json::parse(impulselab::test::read_scene_text(std::string(IMPULSELAB_SCENES_DIR) +
                                                             "/box-lands-flat.json"));
  scene["friction"] = 0.5;
  scene["bodies"][1]["velocity"] = {0.5, -1};
  scene["solver"] = {{"method", "serial"}, {"restitution", "energetic"}};
  const sc::Result r = sc::resolve(sc::parse_world(scene.dump(), "box.json"));
  REQUIRE(r.outcome.finished);
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (std::size_t v = 0; v < r.impulses.size(); ++v) {
    CHECK(std::abs(numbers(r, "tangential")[v]) <= 0.5 * r.impulses[v].magnitude * (1 + 1e-12));
    total += r.impulses[v].on_bumper;
  }
  CHECK(std::abs(numbers(r, "tangential")[0]) + std::abs(numbers(r, "tangential")[1]) > 0.0);
  const sc::BodyReport& box = r.bodies[1];
  CHECK((box.after.momentum - box.before.momentum + total).norm() <= 1e-12);
  CHECK(r.energy_change <= 1e-12 * r.energy_before);
}
