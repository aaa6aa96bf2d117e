// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab sweep SCENE.json --elasticity FROM:TO:STEP [--output FILE.csv]
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string_view>

namespace impulselab {

/// The most rows a sweep writes.
inline constexpr std::size_t max_sweep_rows = 1'000'000;

/// The values FROM, FROM + STEP, FROM + 2 STEP, … up to TO.
struct Range {
  double from = 0.0;      ///< first value
  double to = 0.0;        ///< last value allowed
  double step = 1.0;      ///< spacing, > 0
  std::size_t count = 1;  ///< how many values

  /// The i-th value: FROM + i STEP, computed afresh (no accumulated rounding); the last value is
  /// TO itself when TO lies on the grid.
  /// @param i index below count
  /// @return the value
  [[nodiscard]] double at(std::size_t i) const;
};

/// Parses FROM:TO:STEP strictly: three finite numbers and nothing else, FROM ≥ 0 (an
/// elasticity), FROM ≤ TO, STEP > 0, at most max_sweep_rows values. TO is included when it lies
/// on the grid within rounding (0:3:0.05 gives 61 values, the last exactly 3). Throws UsageError
/// naming @p option and what was wrong.
/// @param text the option's value
/// @param option the option's name for messages
/// @return the range
Range parse_range(std::string_view text, std::string_view option = "--elasticity");

/// Adds the `sweep` verb: solves the scene at each elasticity of a range and writes CSV.
/// @param app the program's command line
void add_sweep_command(CLI::App& app);

}  // namespace impulselab
