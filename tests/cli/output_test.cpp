// SPDX-License-Identifier: GPL-3.0-or-later
// --output: written atomically (a temporary file in the same folder, renamed when complete); a
// failed run leaves an existing file untouched and no temporary file behind.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "app.hpp"
#include "cli/program.hpp"
#include "impulse/core/error.hpp"
#include "output.hpp"

namespace t = impulselab::test;
using t::worked;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

const std::string precious = "precious contents\n";

std::size_t entries(const fs::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) {
    ++count;
  }
  return count;
}

unsigned mode_of(const fs::path& path) {
  struct stat s {};
  REQUIRE(::stat(path.c_str(), &s) == 0);
  return s.st_mode & 0777U;
}

}  // namespace

TEST_CASE("Output to a file is the same bytes as standard output", "[cli][output]") {
  const fs::path folder = t::fresh_folder("same");
  const fs::path file = folder / "result.json";
  t::write_text(file, precious);
  const auto to_stdout = t::run("solve " + t::quote(worked) + " --format json");
  const auto to_file =
      t::run("solve " + t::quote(worked) + " --format json --output " + t::quote(file.string()));
  REQUIRE(to_file.status == 0);
  CHECK(to_file.out.empty());
  CHECK(t::read_text(file) == to_stdout.out);
  CHECK(entries(folder) == 1);  // no temporary file left
}

TEST_CASE("A bad scene leaves an existing --output untouched", "[cli][output]") {
  const fs::path folder = t::fresh_folder("bad-scene");
  const fs::path file = folder / "result.json";
  t::write_text(file, precious);
  for (const std::string& verb : std::vector<std::string>{"solve", "sweep"}) {
    CAPTURE(verb);
    const auto run =
        t::run(verb + " " + t::quote(t::cli_tests_path("malformed/zero-normal.json")) +
               (verb == "sweep" ? " -e 0:1:0.5" : "") + " --output " + t::quote(file.string()));
    CHECK(run.status == 2);
    CHECK(t::read_text(file) == precious);
    CHECK(entries(folder) == 1);
  }
}

TEST_CASE("A write that fails half-way leaves an existing --output untouched", "[cli][output]") {
  // The file-size limit (ulimit -f, in blocks of at least 512 bytes) stops the write of a 30,001
  // row sweep (over a megabyte) part of the way: the program must report it and remove its
  // temporary file, not die of SIGXFSZ nor replace the file.
  const fs::path folder = t::fresh_folder("half-way");
  const fs::path file = folder / "sweep.csv";
  t::write_text(file, precious);
  const auto run = t::run("sweep " + t::quote(t::scene_path("newton-cradle-5.json")) +
                              " --elasticity 0:3:0.0001 --output " + t::quote(file.string()),
                          "/dev/null", "ulimit -f 8;");
  CHECK_FALSE(run.signalled);
  CHECK(run.status == 2);
  CHECK_THAT(run.err, Contains("cannot write " + file.string()));
  CHECK(t::read_text(file) == precious);
  CHECK(entries(folder) == 1);
}

TEST_CASE("Output into a missing folder or onto a folder is refused", "[cli][output]") {
  const fs::path folder = t::fresh_folder("places");
  const auto missing = t::run("solve " + t::quote(worked) + " --output " +
                              t::quote((folder / "no/such/folder/out.txt").string()));
  CHECK(missing.status == 2);
  CHECK_THAT(missing.err, Contains("cannot create a temporary file in"));
  const auto onto_folder =
      t::run("solve " + t::quote(worked) + " --output " + t::quote(folder.string()));
  CHECK(onto_folder.status == 2);
  CHECK_THAT(onto_folder.err, Contains("it is a directory"));
  CHECK(entries(folder) == 0);
}

TEST_CASE("A new --output gets the usual permissions, a replaced one keeps its own",
          "[cli][output]") {
  const fs::path folder = t::fresh_folder("modes");
  const fs::path fresh = folder / "fresh.txt";
  CHECK(t::run("solve " + t::quote(worked) + " --output " + t::quote(fresh.string()), "/dev/null",
               "umask 022;")
            .status == 0);
  CHECK(mode_of(fresh) == 0644U);  // 0666 less the umask, not mkstemp's 0600
  const fs::path kept = folder / "kept.txt";
  t::write_text(kept, precious);
  fs::permissions(kept, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  CHECK(t::run("solve " + t::quote(worked) + " --output " + t::quote(kept.string())).status == 0);
  CHECK(mode_of(kept) == 0640U);
  CHECK(t::read_text(kept) != precious);
}

TEST_CASE("write_output: an exception from the writer leaves the file and no temporary",
          "[cli][output]") {
  const fs::path folder = t::fresh_folder("in-process");
  const fs::path file = folder / "out.txt";
  t::write_text(file, precious);
  const auto half_then_fail = [](std::FILE* out) {
    std::fputs("half of it", out);
    throw impulse::InvalidInput("scene.json: something was wrong");
  };
  CHECK_THROWS_AS(impulselab::write_output(file.string(), half_then_fail), impulse::InvalidInput);
  CHECK(t::read_text(file) == precious);
  CHECK(entries(folder) == 1);
  impulselab::write_output(file.string(), [](std::FILE* out) { std::fputs("whole\n", out); });
  CHECK(t::read_text(file) == "whole\n");
  CHECK(entries(folder) == 1);
}
