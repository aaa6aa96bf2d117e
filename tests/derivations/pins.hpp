// SPDX-License-Identifier: GPL-3.0-or-later
// Pinned verdicts of derivation files, shared by the tests that check files against them
// (files_test.cpp: the test files and the tutorials; students_test.cpp: the students' corpus).
// Each file ends with its pins, an HTML comment the reader skips:
//
//   <!-- expect
//   12 premise
//   16 follows
//   20 follows-if where: F dt      (symbols that the condition must name)
//   24 does-not-follow             (why, in words: the slip the file makes)
//   28 premise follows             (a chain a = b = c on one line: one verdict per link)
//   -->
//
// Every display equation of the file has a pin, so a slip is reported at exactly its line and
// nowhere earlier.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "budget.hpp"
#include "derivations/derivation.hpp"

namespace impulse::derivations::pins {

namespace fs = std::filesystem;

struct Pin {
  std::vector<std::string> verdicts;         // one per equation of the line
  std::vector<std::string> condition_names;  // follows-if: what the condition must mention
};

inline bool is_verdict(const std::string& word) {
  return std::any_of(std::begin(all_verdicts), std::end(all_verdicts),
                     [&](Verdict v) { return word == to_string(v); });
}

inline std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The pins of a file: line → verdict (and condition names).
inline std::map<std::size_t, Pin> pins_of(const std::string& text) {
  std::map<std::size_t, Pin> pins;
  const std::size_t start = text.find("<!-- expect");
  if (start == std::string::npos) {
    return pins;
  }
  const std::size_t end = text.find("-->", start);
  std::istringstream lines(text.substr(start, end - start));
  std::string line;
  std::getline(lines, line);  // "<!-- expect"
  const std::regex pin(R"(^\s*(\d+)\s+(.*)$)");
  while (std::getline(lines, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, pin)) {
      continue;
    }
    Pin p;
    std::istringstream words(m[2].str());
    std::string word;
    while (words >> word && is_verdict(word)) {
      p.verdicts.push_back(word);
    }
    const std::string rest = m[2].str();
    const std::size_t where = rest.find("where:");
    if (where != std::string::npos) {
      std::istringstream names(rest.substr(where + 6));
      for (std::string name; names >> name;) {
        if (name.front() == '(') {
          break;
        }
        p.condition_names.push_back(name);
      }
    }
    pins[static_cast<std::size_t>(std::stoul(m[1].str()))] = p;
  }
  return pins;
}

// A pin that marks a step as wrong, or as holding only under a condition.
inline bool is_slip(const std::string& verdict) {
  return verdict == "does-not-follow" || verdict == "dimensions" || verdict == "follows-if" ||
         verdict == "undecided";
}

// The Markdown files of a folder and its subfolders (not README.md), sorted.
inline std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.path().extension() == ".md" && entry.path().filename() != "README.md") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The rows of a table of tab-separated cells after its header line (slips.tsv, manifest.tsv);
// every row must have `columns` cells.
inline std::vector<std::vector<std::string>> read_tsv(const fs::path& path, std::size_t columns) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string row;
  std::getline(in, row);  // the header
  while (std::getline(in, row)) {
    std::vector<std::string> cells;
    std::istringstream cols(row);
    for (std::string cell; std::getline(cols, cell, '\t');) {
      cells.push_back(cell);
    }
    INFO(path.filename().string() << ": " << row);
    REQUIRE(cells.size() == columns);
    rows.push_back(std::move(cells));
  }
  return rows;
}

// Checks one file against its pins; returns whether it pins a slip.
inline bool check_pins(const fs::path& path) {
  const std::string text = read(path);
  const auto pins = pins_of(text);
  INFO(path.string());
  REQUIRE(!pins.empty());
  const DerivationReport report =
      check_derivation(text, path.filename().string(), impulse::test::pinned_options());
  std::map<std::size_t, std::vector<const EquationResult*>> by_line;
  for (const EquationResult& e : report.equations) {
    by_line[e.line].push_back(&e);
  }
  bool slip = false;
  for (const auto& [line, equations] : by_line) {
    const auto pin = pins.find(line);
    INFO("the pins of line " << line);
    REQUIRE(pin != pins.end());
    REQUIRE(pin->second.verdicts.size() == equations.size());
    for (std::size_t k = 0; k < equations.size(); ++k) {
      const EquationResult& e = *equations[k];
      INFO("line " << e.line << ": " << e.latex << "\n  verdict " << to_string(e.verdict)
                   << "\n  how: " << e.how << "\n  condition: " << e.condition_text
                   << "\n  residual: " << e.residual_text);
      CHECK(std::string(to_string(e.verdict)) == pin->second.verdicts[k]);
      if (e.verdict == Verdict::follows_if) {
        for (const std::string& name : pin->second.condition_names) {
          CHECK((e.condition_text.find(name) != std::string::npos ||
                 e.condition.find(name) != std::string::npos));
        }
      }
      slip = slip || is_slip(pin->second.verdicts[k]);
    }
  }
  for (const auto& [line, pin] : pins) {
    INFO("pinned line " << line << " holds no equation");
    CHECK(by_line.contains(line));
  }
  return slip;
}

}  // namespace impulse::derivations::pins
