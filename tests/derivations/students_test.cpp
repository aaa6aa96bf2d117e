// SPDX-License-Identifier: GPL-3.0-or-later
// The students' corpus (tests/derivations/students/): derivations of textbook collision problems
// written as students write them, half of them with one slip at a known line. Every verdict is
// pinned from SymPy (students/judge.py decides each step independently of this checker, and its
// --check keeps the pins and students/sympy-verdicts.txt equal to what it computes), and the
// seeded random slips of students/slips.tsv (made by students/slips.py, each confirmed wrong by
// SymPy) must all be caught.
#include <catch2/catch.hpp>
#include <cstddef>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "derivations/pins.hpp"

namespace fs = std::filesystem;
namespace d = impulse::derivations;
namespace pins = impulse::derivations::pins;

namespace {

const fs::path students = IMPULSELAB_STUDENTS_DIR;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) {
    out.push_back(cur);
  }
  return out;
}

struct Slip {
  std::string file;
  std::size_t line = 0;
  std::size_t index = 0;  // among the equations of the line
  std::string latex;      // the line as the corpus has it
  std::string mutated;    // the line with the slip
  std::string kind;
};

std::vector<Slip> read_slips() {
  std::vector<Slip> slips;
  for (const auto& cells : pins::read_tsv(students / "slips.tsv", 7)) {
    slips.push_back(
        {cells[0], std::stoul(cells[1]), std::stoul(cells[2]), cells[3], cells[4], cells[5]});
  }
  return slips;
}

// The text of a corpus file with one line replaced.
std::string with_line(const std::string& text, std::size_t line, const std::string& was,
                      const std::string& becomes) {
  std::vector<std::string> lines = split(text, '\n');
  REQUIRE(line >= 1);
  REQUIRE(line <= lines.size());
  REQUIRE(lines[line - 1] == was);
  lines[line - 1] = becomes;
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    out += lines[k] + (k + 1 < lines.size() || text.back() == '\n' ? "\n" : "");
  }
  return out;
}

}  // namespace

TEST_CASE("Students' corpus: no file is refused", "[derivations][students]") {
  for (const fs::path& path : pins::files_in(students)) {
    INFO(path.filename().string());
    CHECK_NOTHROW((void)d::check_derivation(pins::read(path), path.filename().string()));
  }
}

TEST_CASE("Students' corpus: every verdict as SymPy decided it", "[derivations][students]") {
  // One section per file: a file the checker refuses fails its section, and the others still run.
  for (const fs::path& path : pins::files_in(students)) {
    DYNAMIC_SECTION(path.filename().string()) {
      (void)pins::check_pins(path);
    }
  }
}

TEST_CASE("Students' corpus: 64 files, half of them with a slip", "[derivations][students]") {
  const auto files = pins::files_in(students);
  std::size_t with_slip = 0;
  for (const fs::path& path : files) {
    bool slip = false;
    for (const auto& [line, pin] : pins::pins_of(pins::read(path))) {
      for (const std::string& v : pin.verdicts) {
        slip = slip || pins::is_slip(v);
      }
    }
    with_slip += slip ? std::size_t{1} : std::size_t{0};
  }
  // The goal of the issue: at least 60 files (64 written), at least half with one slip.
  CHECK(files.size() >= 64);
  CHECK(2 * with_slip >= files.size());
}

TEST_CASE("Students' corpus: no random slip passes", "[derivations][students][slips]") {
  const std::vector<Slip> all_slips = read_slips();
  REQUIRE(all_slips.size() >= 1000);
  // Every slip in an optimised build; every tenth in a Debug build (the asan preset), where the
  // unoptimised checker under the sanitizers takes minutes for all of them and the sanitizers,
  // not the count, are the point of the run (as tests/support/sampling.hpp does for properties).
#ifdef NDEBUG
  constexpr std::size_t every = 1;
#else
  constexpr std::size_t every = 10;
#endif
  std::vector<Slip> slips;
  for (std::size_t k = 0; k < all_slips.size(); k += every) {
    slips.push_back(all_slips[k]);
  }
  // A slip may be reported undecided (never as following), but rarely: at most 1 % of them.
  const std::size_t max_undecided = 10 / every;  // 10 of the 1,130, under 1 %
  std::size_t undecided = 0;
  std::size_t passed = 0;
  std::size_t refused = 0;
  std::map<std::string, std::string> texts;
  for (const Slip& s : slips) {
    if (!texts.contains(s.file)) {
      texts[s.file] = pins::read(students / s.file);
    }
    INFO(s.file << ":" << s.line << " (" << s.kind << ")\n  was:    " << s.latex
                << "\n  became: " << s.mutated);
    const std::string text = with_line(texts[s.file], s.line, s.latex, s.mutated);
    d::DerivationReport report;
    try {
      // The pinned budget (budget.hpp): a slip's verdict must not depend on how busy the machine
      // is. With the default 2 s, the sanitizers' build once found 2 undecided of its 113 slips
      // where 1 is allowed, in a CI run beside other tests; run alone, 1 (an honest one).
      report = d::check_derivation(text, s.file, impulse::test::pinned_options());
    } catch (const d::DerivationError& e) {
      FAIL_CHECK("refused at " << e.line() << ":" << e.column() << ": " << e.what());
      ++refused;
      continue;
    }
    std::vector<const d::EquationResult*> at_line;
    for (const d::EquationResult& e : report.equations) {
      if (e.line == s.line) {
        at_line.push_back(&e);
      }
    }
    REQUIRE(s.index < at_line.size());
    const d::EquationResult& e = *at_line[s.index];
    INFO("verdict " << d::to_string(e.verdict) << "\n  how: " << e.how);
    const bool passes = e.verdict == d::Verdict::follows ||
                        e.verdict == d::Verdict::follows_one_way ||
                        e.verdict == d::Verdict::follows_if || e.verdict == d::Verdict::premise;
    CHECK(!passes);
    passed += passes ? std::size_t{1} : std::size_t{0};
    undecided += e.verdict == d::Verdict::undecided ? std::size_t{1} : std::size_t{0};
  }
  INFO(slips.size() << " slips: " << passed << " passed, " << refused << " refused, " << undecided
                    << " undecided");
  CHECK(passed == 0);
  CHECK(refused == 0);
  CHECK(undecided <= max_undecided);
}
