// SPDX-License-Identifier: GPL-3.0-or-later
// The reader's resource limits through the program: a file or a standard input without end, too
// many contacts, too many contacts for the dense method. Each is bad input (exit 2) with a
// message naming the limit; the inputs are generated here. (Too deep a nesting is one of the
// malformed scenes.)
#include <catch2/catch.hpp>
#include <string>

#include "cli/program.hpp"
#include "output.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;

namespace {

void check_refused(const t::Run& run, const std::string& message) {
  CHECK(run.status == 2);
  CHECK_FALSE(run.signalled);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains(message));
}

}  // namespace

TEST_CASE("Input without end is refused at the size limit", "[cli][limits]") {
  const std::string limit =
      "holds more than 67108864 bytes (64 MiB), the most a scene file may hold";
  check_refused(t::run("solve /dev/zero"), "/dev/zero: " + limit);
  check_refused(t::run("solve -", "/dev/zero"), "<stdin>: " + limit);
  check_refused(t::run("sweep - --elasticity 0:2:1", "/dev/zero"), "<stdin>: " + limit);
}

TEST_CASE("A file without end is read no further than the limit", "[cli][limits]") {
  // /dev/zero never ends: read_file stops one byte past the limit, which is how a huge file or
  // a device costs at most the limit in memory (the reader then refuses it: the test above).
  CHECK(impulselab::read_file("/dev/zero", 1000).size() == 1001);
}

TEST_CASE("Too many contacts, and too many for the dense method, are refused", "[cli][limits]") {
  const auto folder = t::fresh_folder("limits");

  std::string zeros(R"({"dimension": 1, "contacts": [0)");
  for (int v = 0; v < 1'000'000; ++v) {
    zeros.append(",0");
  }
  t::write_text(folder / "many.json", zeros.append("]}"));
  check_refused(t::run("solve " + t::quote((folder / "many.json").string())),
                "many.json: contacts: more than 1000000 contacts, the most a scene may hold");

  // A row of 2,050 bodies on a line, each touching the next: 2,049 contacts, with the policy
  // "basic", which the dense method alone serves.
  std::string row(
      R"({"dimension": 1, "elasticity": 1, "solver": {"dependent": "basic"}, "bodies": [)");
  for (int k = 0; k < 2'050; ++k) {
    row.append(k == 0 ? "" : ",").append(R"({"name": "b)").append(std::to_string(k));
    row.append(R"(", "kind": "material", "mass": 1, "velocity": 0})");
  }
  row.append(R"(], "contacts": [)");
  for (int k = 0; k < 2'049; ++k) {
    row.append(k == 0 ? "" : ",").append(R"({"bumper": "b)").append(std::to_string(k));
    row.append(R"(", "wedge": "b)").append(std::to_string(k + 1)).append(R"(", "normal": 1})");
  }
  t::write_text(folder / "dense.json", row.append("]}"));
  check_refused(t::run("solve " + t::quote((folder / "dense.json").string())),
                "dense.json: contacts: 2049 contacts with the policies \"basic\" and "
                "\"least-squares\", which only the dense method serves: it takes at most 2048");
}
