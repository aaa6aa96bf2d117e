// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The names of enum values, as the scene format and the reports spell them: one table
/// per enum, read both ways.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace impulse {

/// @brief One value of an enum and its name ("minimum-norm", "serial").
/// @tparam Enum the enum
template <typename Enum>
struct Named {
  Enum value;             ///< the value
  std::string_view name;  ///< its name
};

/// @brief The table of an enum's names, specialised next to the enum:
/// `template <> struct EnumNames<DependentPolicy> { static constexpr std::array<Named<…>, 2>
/// table{{…}}; };`. Names are unique; the order is the one messages list them in. A row may be
/// any struct with the members `value` and `name`: an enum whose values have more to say (a
/// method's words, a restitution law's) keeps it in the same row.
/// @tparam Enum the enum
template <typename Enum>
struct EnumNames;

/// @brief The name of @p value in its enum's table.
/// @tparam Enum an enum with an EnumNames table
/// @param value the value
/// @return its name, or "?" for a value the table does not list
template <typename Enum>
[[nodiscard]] constexpr std::string_view name_of(Enum value) {
  for (const auto& entry : EnumNames<Enum>::table) {
    if (entry.value == value) {
      return entry.name;
    }
  }
  return "?";
}

/// @brief The value of that name in its enum's table.
/// @tparam Enum an enum with an EnumNames table
/// @param name the name, as the table spells it
/// @return the value, or nothing for a name the table does not list
template <typename Enum>
[[nodiscard]] constexpr std::optional<Enum> value_named(std::string_view name) {
  for (const auto& entry : EnumNames<Enum>::table) {
    if (entry.name == name) {
      return entry.value;
    }
  }
  return std::nullopt;
}

/// @brief Every name of the enum in quotes, for a message: `"a", "b", "c"`.
/// @tparam Enum an enum with an EnumNames table
/// @return the names, comma-separated
template <typename Enum>
[[nodiscard]] std::string quoted_names() {
  std::string text;
  for (const auto& entry : EnumNames<Enum>::table) {
    text.append(text.empty() ? "\"" : ", \"").append(entry.name).append("\"");
  }
  return text;
}

/// @brief The row of @p value in its enum's table, with whatever else the row holds.
/// @tparam Enum an enum with an EnumNames table
/// @param value a value the table lists
/// @return its row (the first row for a value the table does not list)
template <typename Enum>
[[nodiscard]] constexpr const auto& row_of(Enum value) {
  for (const auto& entry : EnumNames<Enum>::table) {
    if (entry.value == value) {
      return entry;
    }
  }
  return EnumNames<Enum>::table.front();
}

}  // namespace impulse
