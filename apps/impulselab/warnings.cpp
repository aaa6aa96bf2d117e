// SPDX-License-Identifier: GPL-3.0-or-later
#include "warnings.hpp"

#include <array>
#include <cstdio>
#include <limits>

namespace impulselab {

namespace {

// Two significant digits: an order of magnitude is what the reader needs.
std::string rounded(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.2g", value);
  return text.data();
}

}  // namespace

std::vector<std::string> solve_warnings(const impulse::scene::Result& result,
                                        std::string_view source) {
  std::vector<std::string> warnings;
  const impulse::Solution& s = result.system;
  // Infinity means A = 0 (no body can move along any normal): nothing is solved, nothing to warn.
  if (s.condition_estimate > ill_conditioned &&
      s.condition_estimate < std::numeric_limits<double>::infinity()) {
    const double relative = s.condition_estimate * std::numeric_limits<double>::epsilon();
    std::string line(source);
    line.append(": the system A·Fdt = B is ill-conditioned: condition estimate ")
        .append(rounded(s.condition_estimate))
        .append(s.rank_estimated ? " (estimated)" : "")
        .append(", above ")
        .append(rounded(ill_conditioned))
        .append("; rounding may change the impulses by about ")
        .append(relative < 1.0 ? rounded(relative) + " of their size" : "as much as their size")
        .append(" (the velocities after are less affected)");
    warnings.push_back(std::move(line));
  }
  // A system assembled from bodies always has a solution (B lies in the range of A); a residual
  // beyond the consistency tolerance means rounding lost part of it.
  if (!s.consistent) {
    std::string line(source);
    line.append(": the impulses found do not satisfy A·Fdt = B (residual ")
        .append(rounded(s.residual))
        .append(" against |B| = ")
        .append(rounded(s.B.stableNorm()))
        .append(
            "): the scene's numbers are beyond what double precision resolves (masses or "
            "moments of inertia too far apart); do not trust this report");
    warnings.push_back(std::move(line));
  }
  return warnings;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "impulselab: warning: %s\n", warning.c_str());
  }
}

}  // namespace impulselab
