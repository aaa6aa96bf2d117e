// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers and tables as the text reports print them.
#include <catch2/catch.hpp>
#include <string>

#include "impulse/core/text.hpp"

TEST_CASE("Numbers with 6 significant digits, rounding noise as 0", "[core][text]") {
  CHECK(impulse::number_text(1.5) == "1.5");
  CHECK(impulse::number_text(-1.0 / 3.0) == "-0.333333");
  CHECK(impulse::number_text(-0.0) == "0");
  CHECK(impulse::number_text(1e-20) == "1e-20");
  // 4e-16 next to values of 1.5 is below 1e-12 of them: shown as 0; 1e-11 is not.
  CHECK(impulse::chopped(4e-16, 1.5) == "0");
  CHECK(impulse::chopped(1e-11, 1.5) == "1e-11");
  CHECK(impulse::vector_text({1.5, -4e-16}, 2, 1.5) == "[1.5, 0]");
  CHECK(impulse::vector_text({1.5, 7}, 1, 1.5) == "1.5");
  CHECK(impulse::counted(1, "pass", "passes") == "1 pass");
  CHECK(impulse::counted(3, "pass", "passes") == "3 passes");
}

TEST_CASE("Table columns are as wide as their widest cell in characters, not bytes",
          "[core][text]") {
  // "b–c" is 3 characters and 5 bytes (the en dash takes 3): it pads like "abc" would.
  CHECK(impulse::characters("b\u2013c") == 3);
  impulse::TextTable table({"pair", "x"}, {true});
  table.add({"b\u2013c", "1"});
  table.add({"ab", "22"});
  // Column 0 is 4 characters wide (left-aligned), column 1 is 2 (right-aligned).
  CHECK(table.render() == "  pair   x\n  b\u2013c    1\n  ab    22\n");
}
