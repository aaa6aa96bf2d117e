// SPDX-License-Identifier: GPL-3.0-or-later
// What the lab tests read: the CSV files and plots a lab wrote (its CTest fixture ran it first),
// and the worksheet that shows them.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace labtest {

/// A CSV file with a header line, read into named columns of doubles (NaN stays NaN).
class Table {
 public:
  explicit Table(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) {
      throw std::runtime_error("cannot read " + file.string());
    }
    std::string line;
    std::getline(in, line);
    for (const std::string& name : split(line)) {
      names_.push_back(name);
      columns_[name];
    }
    while (std::getline(in, line)) {
      if (line.empty()) {
        continue;  // the end of one scan of a grid
      }
      const std::vector<std::string> cells = split(line);
      if (cells.size() != names_.size()) {
        throw std::runtime_error(file.string() + ": a row of " + std::to_string(cells.size()) +
                                 " cells under " + std::to_string(names_.size()) + " columns");
      }
      for (std::size_t i = 0; i < cells.size(); ++i) {
        columns_[names_[i]].push_back(std::stod(cells[i]));
      }
    }
  }

  /// The column of that name (a missing column is a test failure, not an empty column).
  [[nodiscard]] const std::vector<double>& operator[](const std::string& name) const {
    const auto found = columns_.find(name);
    if (found == columns_.end()) {
      throw std::runtime_error("no column " + name);
    }
    return found->second;
  }

  [[nodiscard]] std::size_t rows() const {
    return names_.empty() ? 0 : columns_.at(names_.front()).size();
  }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) {
      cells.push_back(cell);
    }
    return cells;
  }
  std::vector<std::string> names_;
  std::map<std::string, std::vector<double>> columns_;
};

/// Width and height from a PNG's IHDR chunk (bytes 16-23, big-endian); {0, 0} if not a PNG.
inline std::pair<std::uint32_t, std::uint32_t> png_size(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) {
    return {0, 0};
  }
  const auto word = [&](int at) {
    return (std::uint32_t{header[at]} << 24) | (std::uint32_t{header[at + 1]} << 16) |
           (std::uint32_t{header[at + 2]} << 8) | std::uint32_t{header[at + 3]};
  };
  return {word(16), word(20)};
}

/// A whole text file.
inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw std::runtime_error("cannot read " + file.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The names a comma-separated list holds ("energy,relative-velocity").
inline std::vector<std::string> names(const std::string& list) {
  std::vector<std::string> result;
  std::stringstream s(list);
  std::string name;
  while (std::getline(s, name, ',')) {
    result.push_back(name);
  }
  return result;
}

/// Every plot the lab names is there as a non-empty 800x500 PNG and a non-empty SVG, and every
/// image the worksheet shows is one of them.
inline void check_plots(const std::filesystem::path& output, const std::filesystem::path& source,
                        const std::string& plot_list) {
  const std::vector<std::string> plots = names(plot_list);
  REQUIRE_FALSE(plots.empty());
  for (const std::string& plot : plots) {
    CAPTURE(plot);
    const auto png = output / (plot + ".png");
    const auto svg = output / (plot + ".svg");
    REQUIRE(std::filesystem::exists(png));
    REQUIRE(std::filesystem::exists(svg));
    CHECK(std::filesystem::file_size(png) > 0);
    CHECK(std::filesystem::file_size(svg) > 0);
    CHECK(png_size(png) == std::pair<std::uint32_t, std::uint32_t>{800, 500});
    CHECK(read_text(svg).find("</svg>") != std::string::npos);  // gnuplot finished the file
  }
  const std::string text = read_text(source / "README.md");
  const std::regex image(R"(!\[[^\]]*\]\(([^)]+)\.png\))");
  int shown = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), image);
       it != std::sregex_iterator(); ++it, ++shown) {
    const std::string name = (*it)[1].str();
    CAPTURE(name);
    CHECK(std::find(plots.begin(), plots.end(), name) != plots.end());
  }
  CHECK(shown == static_cast<int>(plots.size()));  // the worksheet shows every plot
}

}  // namespace labtest
