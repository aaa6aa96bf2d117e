// SPDX-License-Identifier: GPL-3.0-or-later
// What every lab program shares: where it writes, and its CSV files. Local to the labs: it is not
// part of the library.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lab {

/// The folder a lab writes into: its first argument, or the current folder. Created if missing.
inline std::filesystem::path output_dir(int argc, char** argv) {
  std::filesystem::path dir = argc > 1 ? std::filesystem::path(argv[1]) : ".";
  std::filesystem::create_directories(dir);
  return dir;
}

/// A CSV file with a header line; numbers are written so that they read back to the same double.
/// A missing value (a point gnuplot should leave blank) is written as NaN.
class Csv {
 public:
  Csv(const std::filesystem::path& file, std::initializer_list<std::string_view> columns)
      : file_(std::fopen(file.c_str(), "w")), columns_(columns.size()) {
    if (!file_) {
      throw std::runtime_error("cannot write " + file.string());
    }
    std::string header;
    for (std::string_view c : columns) {
      header.append(header.empty() ? "" : ",").append(c);
    }
    std::fprintf(file_.get(), "%s\n", header.c_str());
  }

  /// One row; it must have one value per column.
  void row(std::initializer_list<double> values) {
    if (values.size() != columns_) {
      throw std::logic_error("a CSV row needs one value per column");
    }
    bool first = true;
    for (double v : values) {
      if (!first) {
        std::fputc(',', file_.get());
      }
      if (std::isfinite(v)) {
        std::fprintf(file_.get(), "%.17g", v);
      } else {
        std::fputs("NaN", file_.get());
      }
      first = false;
    }
    std::fprintf(file_.get(), "\n");
  }

  /// An empty line: gnuplot reads it as the end of one scan of a grid (for `with image`).
  void blank() { std::fprintf(file_.get(), "\n"); }

 private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::size_t columns_;
};

}  // namespace lab
