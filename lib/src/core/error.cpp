// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/error.hpp"

#include <array>
#include <charconv>
#include <cmath>

namespace impulse {

std::string format_number(double value) {
  std::array<char, 32> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (error != std::errc{}) {
    return "?";
  }
  return {buffer.data(), end};
}

namespace {
[[noreturn]] void refuse(std::string_view what, std::string_view rule, const std::string& got) {
  throw InvalidInput(std::string(what) + " must be " + std::string(rule) + ", got " + got);
}

std::string format_vector(const Eigen::Vector2d& v) {
  // Built with append: GCC 12 warns falsely (-Wrestrict, its bug 105329) on "[" + std::string.
  std::string text("[");
  text.append(format_number(v.x())).append(", ").append(format_number(v.y())).append("]");
  return text;
}
}  // namespace

namespace detail {

void refuse_positive(std::string_view what, double value) {
  refuse(what, "positive and finite", format_number(value));
}

void refuse_finite(std::string_view what, double value) {
  refuse(what, "finite", format_number(value));
}

void refuse_finite(std::string_view what, const Eigen::Vector2d& value) {
  refuse(what, "finite", format_vector(value));
}

void refuse_unit_normal(std::string_view what, const Eigen::Vector2d& normal) {
  if (!all_finite_in(normal)) {
    refuse(what, "a finite unit vector", format_vector(normal));
  }
  refuse(what, "a unit vector (length 1 within " + format_number(unit_normal_tolerance) + ")",
         format_vector(normal) + " of length " + format_number(normal.norm()));
}

void refuse_unit_direction(std::string_view what, double direction) {
  refuse(what, "+1 or -1", format_number(direction));
}

}  // namespace detail

}  // namespace impulse
