// SPDX-License-Identifier: GPL-3.0-or-later
// SymPy's parse_latex test corpus as derivation files (tests/derivations/sympy-latex/, written
// by its make.py from sympy/parsing/tests/test_latex.py, each value checked there against
// SymPy's): `w = <string>` then `w = <its value>`. The manifest says what the checker must do
// with each: `follows` (notation the contract lists: read right), `refused` (outside the
// contract, or one of SymPy's bad strings: a DerivationError, never a verdict) or `either`
// (outside the contract but unambiguous: read right or refused, never misread).
#include <catch2/catch.hpp>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "derivations/pins.hpp"

namespace fs = std::filesystem;
namespace d = impulse::derivations;
namespace pins = impulse::derivations::pins;

namespace {

const fs::path corpus = IMPULSELAB_SYMPY_LATEX_DIR;

struct Entry {
  std::string file;
  std::string expect;  // follows, refused or either
  std::string reason;
  std::string latex;
};

std::vector<Entry> manifest() {
  std::vector<Entry> out;
  for (const auto& cells : pins::read_tsv(corpus / "manifest.tsv", 4)) {
    out.push_back({cells[0], cells[1], cells[2], cells[3]});
  }
  return out;
}

// The verdicts of a file that was read, against its pins (premise, then follows).
void check_read_right(const fs::path& path, const d::DerivationReport& report) {
  const auto pinned = pins::pins_of(pins::read(path));
  REQUIRE(report.equations.size() == pinned.size());
  for (const d::EquationResult& e : report.equations) {
    INFO("line " << e.line << ": " << e.latex << "\n  how: " << e.how
                 << "\n  residual: " << e.residual_text);
    const auto pin = pinned.find(e.line);
    REQUIRE(pin != pinned.end());
    REQUIRE(pin->second.verdicts.size() == 1);
    CHECK(std::string(d::to_string(e.verdict)) == pin->second.verdicts[0]);
  }
}

}  // namespace

TEST_CASE("SymPy's LaTeX corpus: nothing misread, every bad string refused",
          "[derivations][sympy-latex]") {
  const std::vector<Entry> entries = manifest();
  std::map<std::string, std::size_t> counts;
  for (const Entry& entry : entries) {
    ++counts[entry.expect];
    const fs::path path = corpus / entry.file;
    INFO(entry.file << " (" << entry.expect << ": " << entry.reason << "): " << entry.latex);
    const std::string text = pins::read(path);
    REQUIRE(!text.empty());
    if (entry.expect == "refused") {
      CHECK_THROWS_AS((void)d::check_derivation(text, entry.file), d::DerivationError);
      continue;
    }
    REQUIRE((entry.expect == "follows" || entry.expect == "either"));
    try {
      const d::DerivationReport report = d::check_derivation(text, entry.file);
      check_read_right(path, report);
    } catch (const d::DerivationError& e) {
      INFO("refused at " << e.line() << ":" << e.column() << ": " << e.what());
      CHECK(entry.expect == "either");
    } catch (const std::exception& e) {
      FAIL_CHECK("neither a verdict nor a DerivationError: " << e.what());
    }
  }
  // The corpus as make.py writes it: 142 of SymPy's 179 strings kept (37 left out: limits,
  // infinite sums, factorials of symbols, \mathit names, bare f(x), ...) and its 38 bad strings.
  CHECK(entries.size() == 180);
  CHECK(counts["follows"] == 76);
  CHECK(counts["either"] == 33);
  CHECK(counts["refused"] == 71);
}
