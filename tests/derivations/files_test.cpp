// SPDX-License-Identifier: GPL-3.0-or-later
// Derivation files with pinned verdicts: the test files of tests/derivations/files/, the examples
// of tutorials/derivations/ and lab 8's derivations. Each file ends with its pins (pins.hpp gives
// their form). The pins were written from the mathematics of each file (the comment next to a
// slip says what it is), not copied from the checker's output.
#include <catch2/catch.hpp>
#include <filesystem>

#include "derivations/pins.hpp"

namespace fs = std::filesystem;
using impulse::derivations::pins::check_pins;
using impulse::derivations::pins::files_in;

TEST_CASE("Derivation test files: every verdict as pinned", "[derivations][files]") {
  const auto files = files_in(IMPULSELAB_DERIVATION_FILES_DIR);
  std::size_t with_slip = 0;
  for (const fs::path& path : files) {
    with_slip += check_pins(path) ? std::size_t{1} : std::size_t{0};
  }
  // The goal of the issue: at least 30 files, at least half with a slip at a known line.
  CHECK(files.size() >= 30);
  CHECK(2 * with_slip >= files.size());
}

TEST_CASE("The tutorials' derivations: every verdict as pinned", "[derivations][files]") {
  for (const char* folder : {"derivations", "08-find-the-slip"}) {
    const auto files = files_in(fs::path(IMPULSELAB_TUTORIALS_DIR) / folder);
    CHECK(!files.empty());
    for (const fs::path& path : files) {
      check_pins(path);
    }
  }
}
