// SPDX-License-Identifier: GPL-3.0-or-later
// The reader's resource limits (impulse::scene::ReadLimits): the size of the text, the nesting
// of arrays and objects, the number of bodies and of contacts, and the contacts that the dense
// method serves. Each is refused with a message naming it, at its default value and at a small
// one; inputs are generated here rather than stored.
#include <catch2/catch.hpp>
#include <string>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using impulse::InvalidInput;
namespace sc = impulse::scene;

namespace {

// A valid 1D scene: a row of `bodies` unit masses, each touching the next (bodies - 1 contacts),
// written compactly. `solver` is the text of the solver object, or empty.
std::string row_of(std::size_t bodies, const std::string& solver = "") {
  std::string text(R"({"dimension":1,"elasticity":2,"bodies":[)");
  for (std::size_t k = 0; k < bodies; ++k) {
    text.append(k == 0 ? "" : ",").append(R"({"name":"b)").append(std::to_string(k));
    text.append(R"(","kind":"material","mass":1,"velocity":)").append(k == 0 ? "1" : "0");
    text.append("}");
  }
  text.append(R"(],"contacts":[)");
  for (std::size_t k = 0; k + 1 < bodies; ++k) {
    text.append(k == 0 ? "" : ",").append(R"({"bumper":"b)").append(std::to_string(k));
    text.append(R"(","wedge":"b)").append(std::to_string(k + 1)).append(R"(","normal":1})");
  }
  text.append("]");
  if (!solver.empty()) {
    text.append(R"(,"solver":)").append(solver);
  }
  return text.append("}");
}

std::string refusal(const std::string& text, const sc::ReadLimits& limits = {}) {
  try {
    (void)sc::parse_scene(text, "s.json", limits);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("The default limits are the documented ones", "[scene][json][limits]") {
  const sc::ReadLimits limits;
  CHECK(limits.max_bytes == 64U * 1024U * 1024U);
  CHECK(limits.max_depth == 64);
  CHECK(limits.max_bodies == 1'000'000);
  CHECK(limits.max_contacts == 1'000'000);
  CHECK(limits.max_keys == 64);
  CHECK(impulse::dense_limit == 2'048);  // the library's rule now, for files and C++ alike
  CHECK(refusal(row_of(3)) == "(accepted)");
}

TEST_CASE("A text larger than the limit is refused before it is parsed", "[scene][json][limits]") {
  // A valid scene padded with spaces to 64 MiB and one byte: refused by its size alone.
  const std::string scene = row_of(2);
  std::string text(sc::ReadLimits{}.max_bytes + 1 - scene.size(), ' ');
  text.append(scene);
  CHECK(refusal(text) ==
        "s.json: holds more than 67108864 bytes (64 MiB), the most a scene file may hold");

  // Exactly at a limit is accepted (a small one, which is quick to parse).
  sc::ReadLimits small;
  small.max_bytes = scene.size();
  CHECK(refusal(scene, small) == "(accepted)");
  CHECK(refusal(scene + " ", small) == "s.json: holds more than " + std::to_string(scene.size()) +
                                           " bytes, the most a scene file may hold");
}

TEST_CASE("Nesting deeper than the limit is refused where it happens", "[scene][json][limits]") {
  // One million '[' (what would cost the parser a frame each): refused at the 65th, column 65.
  CHECK(refusal(std::string(1'000'000, '[')) ==
        "s.json: line 1, column 65: arrays and objects nested more than 64 deep (a scene needs 4)");
  // {"x": [[...]]} with the brackets on the second line: the 4th level is the 3rd '['.
  sc::ReadLimits shallow;
  shallow.max_depth = 3;
  CHECK(refusal("{\"x\":\n[[[1]]]}", shallow) ==
        "s.json: line 2, column 3: arrays and objects nested more than 3 deep (a scene needs 4)");
  // At the limit the text goes on to the parser (which refuses the unknown key).
  CHECK_THAT(refusal("{\"x\":\n[[1]]}", shallow), Contains("x: unknown key"));
  // Brackets inside strings are text, not nesting: a body named with 100 of them is valid.
  std::string scene = row_of(2);
  const std::string name(100, '[');
  scene.replace(scene.find("b0"), 2, name);  // the first body's name and the contact's bumper
  scene.replace(scene.find("\"b0\""), 4, "\"" + name + "\"");
  CHECK(refusal(scene) == "(accepted)");
  // An escaped quote does not end a string: the brackets after it are still inside.
  CHECK_THAT(refusal(R"({"x": "\"[[[[[[[[[[[[[[[[[[[["})", shallow), Contains("x: unknown key"));
}

TEST_CASE("Bodies and contacts beyond their limits are refused while parsing",
          "[scene][json][limits]") {
  sc::ReadLimits few;
  few.max_bodies = 3;
  few.max_contacts = 2;
  CHECK(refusal(row_of(3), few) == "(accepted)");  // 3 bodies, 2 contacts
  CHECK(refusal(row_of(4), few) == "s.json: bodies: more than 3 bodies, the most a scene may hold");
  few.max_bodies = 4;
  CHECK(refusal(row_of(4), few) ==
        "s.json: contacts: more than 2 contacts, the most a scene may hold");
  // A key of the same name deeper down is not the scene's list.
  CHECK_THAT(refusal(R"({"x": {"bodies": [1, 2, 3, 4, 5]}})", few), Contains("x: unknown key"));

  // At the default limit: 1,000,001 elements are refused as too many before anything looks at
  // what they are (here plain zeros, which would be refused as contacts later).
  std::string many(R"({"contacts": [0)");
  for (std::size_t v = 1; v <= sc::ReadLimits{}.max_contacts; ++v) {
    many.append(",0");
  }
  many.append("]}");
  CHECK(refusal(many) == "s.json: contacts: more than 1000000 contacts, the most a scene may hold");
}

TEST_CASE("An object with more keys than the limit is refused at the first key too many",
          "[scene][json][limits]") {
  // The parser looks each key up among those before it in its object (it keeps the file's
  // order), so a million keys would take hours: the 65th is refused as it is read.
  std::string body = R"({"bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": 1)";
  for (int k = 5; k <= 200'000; ++k) {
    body.append(", \"k").append(std::to_string(k)).append("\": 0");
  }
  body.append("}]}");
  CHECK(refusal(body) ==
        "s.json: bodies[0].k65: more than 64 keys in one object, the most a scene may hold");
  // At the limit the object goes on to the reader (which refuses the unknown key k5).
  sc::ReadLimits few;
  few.max_keys = 5;
  CHECK_THAT(refusal(R"({"dimension": 1, "bodies": [{"name": "a", "kind": "material",
                                     "mass": 1, "velocity": 1, "k5": 0}]})",
                     few),
             Contains("bodies[0].k5: unknown key"));
  CHECK(refusal(R"({"bodies": [{"name": "a", "kind": "material", "mass": 1, "velocity": 1,
                                "k5": 0, "k6": 0}]})",
                few) ==
        "s.json: bodies[0].k6: more than 5 keys in one object, the most a scene may hold");
}

TEST_CASE("The dense method's policies are refused above their limit of contacts",
          "[scene][json][limits]") {
  // basic and drop-equation need the dense method; the default policies do not.
  const std::string basic = R"({"dependent": "basic"})";
  const std::string drop = R"({"inconsistent": "drop-equation"})";
  CHECK(refusal(row_of(2'049, basic)) == "(accepted)");  // 2,048 contacts
  CHECK_THAT(refusal(row_of(2'050, basic)),
             StartsWith("s.json: contacts: 2049 contacts with the policies \"basic\" and "
                        "\"least-squares\", which only the dense method serves: it takes at most "
                        "2048"));
  CHECK_THAT(refusal(row_of(2'050, drop)),
             Contains("the policies \"minimum-norm\" and \"drop-equation\""));
  CHECK(refusal(row_of(2'050)) == "(accepted)");  // the sparse method serves it
}
