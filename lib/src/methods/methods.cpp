// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/methods.hpp"

#include <array>
#include <utility>

namespace impulse::methods {

namespace {
constexpr std::array<std::pair<Method, std::string_view>, 3> names{{
    {Method::simultaneous, "simultaneous"},
    {Method::complementarity, "complementarity"},
    {Method::serial, "serial"},
}};
}  // namespace

std::string_view to_string(Method method) {
  for (const auto& [m, name] : names) {
    if (m == method) {
      return name;
    }
  }
  return "?";
}

std::optional<Method> method_named(std::string_view name) {
  for (const auto& [m, known] : names) {
    if (known == name) {
      return m;
    }
  }
  return std::nullopt;
}

}  // namespace impulse::methods
