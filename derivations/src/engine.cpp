// SPDX-License-Identifier: GPL-3.0-or-later
#include "derivations/check.hpp"

namespace impulse::derivations {

bool in_section(std::string_view section, std::string_view filter) {
  if (filter.empty()) {
    return true;
  }
  return section == filter || (section.size() > filter.size() && section.starts_with(filter) &&
                               section[filter.size()] == '.');
}

std::uint64_t check_seed(std::uint64_t run_seed, std::string_view id) {
  // FNV-1a of the id, mixed with the run's seed by a SplitMix64 step.
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : id) {
    h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  }
  std::uint64_t z = run_seed + 0x9E3779B97F4A7C15ULL + h;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::string anchor(std::string_view id) {
  std::string result = "check-";
  for (const char c : id) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    result += plain ? c : '-';
  }
  return result;
}

}  // namespace impulse::derivations
