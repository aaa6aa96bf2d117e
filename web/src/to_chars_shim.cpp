// SPDX-License-Identifier: GPL-3.0-or-later
#include "to_chars_shim.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace std {  // NOLINT(cert-dcl58-cpp)

to_chars_result to_chars(char* first, char* last, double value) {
  std::string text;
  if (std::isnan(value)) {
    text = std::signbit(value) ? "-nan" : "nan";
  } else if (std::isinf(value)) {
    text = value < 0 ? "-inf" : "inf";
  } else {
    // The fewest significant digits that read back as the value: printf rounds correctly, so
    // the first precision that round-trips gives the shortest digits, the nearest of that length.
    std::array<char, 40> buffer{};
    for (int precision = 1; precision <= 17; ++precision) {
      std::snprintf(buffer.data(), buffer.size(), "%.*e", precision - 1, value);
      if (std::strtod(buffer.data(), nullptr) == value) {
        break;
      }
    }
    // buffer: [-]d[.ddd]e(+|-)XX
    const std::string scientific(buffer.data());
    const std::size_t e = scientific.find('e');
    const bool negative = scientific[0] == '-';
    std::string digits;
    for (std::size_t i = negative ? 1 : 0; i < e; ++i) {
      if (scientific[i] != '.') {
        digits += scientific[i];
      }
    }
    const int exponent = std::atoi(scientific.c_str() + e + 1);
    const auto count = static_cast<int>(digits.size());
    std::string fixed = negative ? "-" : "";
    if (exponent >= 0) {
      if (count <= exponent + 1) {
        fixed += digits + std::string(static_cast<std::size_t>(exponent + 1 - count), '0');
      } else {
        const auto point = static_cast<std::size_t>(exponent + 1);
        fixed += digits.substr(0, point) + "." + digits.substr(point);
      }
    } else {
      fixed += "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    }
    text = fixed.size() <= scientific.size() ? fixed : scientific;
  }
  if (static_cast<std::size_t>(last - first) < text.size()) {
    return {last, errc::value_too_large};
  }
  std::memcpy(first, text.data(), text.size());
  return {first + text.size(), errc{}};
}

}  // namespace std
