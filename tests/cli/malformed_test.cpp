// SPDX-License-Identifier: GPL-3.0-or-later
// Malformed scenes: each gives exit 2, nothing on standard output, and a message on standard
// error that names the file, the place and the problem. The expected fragments live here, not in
// the scene files (which cannot hold comments anyway).
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/program.hpp"

namespace t = impulselab::test;

namespace {

// file in tests/cli/malformed/ → what its message must say (after "<path>: ").
const std::map<std::string, std::string> expected_messages{
    // Syntax: the line and the column (counted by hand in each file).
    {"syntax-trailing-comma.json", "line 4, column 1: syntax error"},  // the } after "2,"
    {"syntax-unclosed.json",
     "line 6, column 1: syntax error while parsing array - unexpected "
     "end of input; expected ']'"},                                   // the end, after 5 full lines
    {"syntax-single-quotes.json", "line 1, column 2: syntax error"},  // the ' after {
    {"empty.json", "line 1, column 1: syntax error while parsing value - unexpected end of input"},
    {"invalid-utf8.json",
     "line 3, column 24: syntax error while parsing value - invalid string: "
     "ill-formed UTF-8 byte"},                                  // the byte 0xFF inside "name"
    {"two-documents.json", "line 1, column 18: syntax error"},  // the second {
    // Parsing, placed by path.
    {"duplicate-key.json", "bodies[0].mass: key repeated in the same object"},
    {"number-overflow.json", "bodies[0].velocity[0]: number overflow parsing '1e400'"},
    // Structure and types.
    {"top-level-array.json",
     "(top level): expected the scene, an object, got an array of 2 "
     "elements"},
    {"unknown-top-key.json", "elastcity: unknown key (did you mean \"elasticity\"?)"},
    {"unknown-body-key.json", "bodies[1].mas: unknown key (did you mean \"mass\"?)"},
    {"unknown-contact-key.json", "contacts[0].norml: unknown key (did you mean \"normal\"?)"},
    {"missing-dimension.json", "(top level): missing \"dimension\""},
    {"missing-contacts.json", "(top level): missing \"contacts\""},
    {"dimension-3.json", "dimension: expected 1 or 2, got the number 3"},
    {"dimension-true.json", "dimension: expected 1 or 2, got true"},
    {"mass-is-string.json", "bodies[1].mass: expected a number, got the string \"1\""},
    {"mass-null.json", "bodies[1].mass: expected a number, got null"},
    {"name-not-string.json", "bodies[0].name: expected a string, got the number 7"},
    {"bodies-not-array.json", "bodies: expected an array of bodies, got an object"},
    {"body-not-object.json", "bodies[0]: expected a body, an object, got the string \"a\""},
    {"unknown-kind.json",
     "bodies[0].kind: expected one of \"material\", \"rigid\", \"static\", "
     "got \"plastic\""},
    {"unknown-policy.json",
     "solver.dependent: expected one of \"minimum-norm\", \"basic\", got "
     "\"equal\""},
    {"velocity-and-momentum.json", "bodies[0]: give either \"velocity\" or \"momentum\", not both"},
    {"no-velocity.json", "bodies[1]: missing \"velocity\" (or \"momentum\")"},
    {"vector-too-long.json",
     "bodies[0].velocity: expected [x, y], an array of 2 numbers (the scene "
     "has dimension 2), got an array of 3 elements"},
    {"scalar-in-2d.json",
     "bodies[0].velocity: expected [x, y], an array of 2 numbers (the scene "
     "has dimension 2), got the number 1.5"},
    {"vector-in-1d.json",
     "contacts[0].normal: expected a number (the scene has dimension 1), got "
     "an array of 2 elements"},
    {"angular-on-material.json", "bodies[0].angular_velocity: does not apply to a material body"},
    {"static-with-mass.json", "bodies[0].mass: does not apply to a static body"},
    // Values and references.
    {"negative-mass.json", "bodies[1].mass: must be positive and finite, got -1"},
    {"zero-inertia.json", "bodies[1].inertia: must be positive and finite, got 0"},
    {"negative-elasticity.json", "bodies[0].elasticity: must be finite and at least 0, got -0.5"},
    {"no-elasticity.json", "bodies[1]: needs an elasticity"},
    {"zero-normal.json", "contacts[0].normal: must be a finite non-zero vector, got [0, 0]"},
    {"normal-zero-1d.json",
     "contacts[0].normal: must be a non-zero number (+1 or -1: its sign is the direction), got 0"},
    {"unknown-body-name.json",
     "contacts[0].wedge: no body is named \"c\" (the bodies are \"a\", "
     "\"b\")"},
    {"duplicate-body-name.json", "bodies[1].name: \"a\" is already the name of bodies[0]"},
    {"rigid-in-1d.json",
     "bodies[0].kind: a rigid body needs dimension 2, this scene has "
     "dimension 1"},
    {"self-contact.json",
     "contacts[0]: bumper and wedge are the same body \"a\": a body cannot be "
     "in contact with itself"},
    {"two-static-bodies.json", "contacts[0]: joins two static bodies, \"ground\" and \"wall\""},
    {"missing-point-rigid.json",
     "contacts[0]: missing \"point\": it is needed because \"rod\" is "
     "rigid"},
    {"empty-bodies.json", "bodies: must hold at least one body, got none"},
    // Numbers beyond doubles.
    {"momentum-overflow.json", "bodies[0].velocity: mass times velocity overflows a double"},
    {"energy-overflow.json", "the numbers overflow"},  // m 1e200 at 1e100: p^2 = 1e600
    // Resource limits (the others are generated in limits_test.cpp): the scene's { is level 1,
    // the 64th [ of line 3 (column 13 + 63) is level 65.
    {"nesting-too-deep.json",
     "line 3, column 76: arrays and objects nested more than 64 deep (a scene needs 4)"},
};

}  // namespace

TEST_CASE("Every malformed scene has its expected message, and there are at least 20",
          "[cli][malformed]") {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(t::cli_tests_path("malformed"))) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> listed;
  for (const auto& [file, message] : expected_messages) {
    listed.push_back(file);
  }
  CHECK(files == listed);  // no file without its expectation, no expectation without its file
  CHECK(files.size() >= 20);
}

TEST_CASE("Malformed scenes: exit 2, the file, the place and the problem on stderr",
          "[cli][malformed]") {
  for (const auto& [file, message] : expected_messages) {
    const std::string path = t::cli_tests_path("malformed/" + file);
    CAPTURE(file);
    for (const std::string& verb : std::vector<std::string>{"solve", "sweep"}) {
      CAPTURE(verb);
      const auto run = t::run(verb + " " + t::quote(path) +
                              (verb == "sweep" ? " --elasticity 0:2:1" : " --format json"));
      CHECK(run.status == 2);
      CHECK_FALSE(run.signalled);
      CHECK(run.out.empty());  // never a result from a half-read scene
      CHECK_THAT(run.err, Catch::Matchers::Contains(path + ": " + message));
    }
  }
}
