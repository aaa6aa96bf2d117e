// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Numbers and tables as the text reports print them: 6 significant digits, rounding
/// noise shown as 0, columns aligned by characters (UTF-8), not by bytes.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace impulse {

/// @brief Rounding noise: a value below this fraction of the largest of its kind in a report (a
/// velocity of 4e-16 next to velocities of 1.5) is shown as 0. At 6 significant digits it could
/// not be told apart from 0 anyway; the JSON report keeps every digit. The warnings about
/// impulses that pull use the same fraction.
inline constexpr double rounding_noise = 1e-12;

/// @brief A number with 6 significant digits ("1.5", "-0.333333", "1e-20"); -0 prints as 0.
/// @param value the number
/// @return its text
[[nodiscard]] std::string number_text(double value);

/// @brief Two significant digits ("1.1e-04" style of `%.2g`): an order of magnitude, for the
/// warnings.
/// @param value the number
/// @return its text
[[nodiscard]] std::string rounded_text(double value);

/// @brief number_text(), or "0" when |@p value| is at most rounding_noise times @p scale.
/// @param value the number
/// @param scale the largest value of its kind in the report
/// @return its text
[[nodiscard]] std::string chopped(double value, double scale);

/// @brief A vector as chopped() numbers: "x" in 1D, "[x, y]" in 2D.
/// @param v the vector
/// @param dimension 1 or 2
/// @param scale the largest value of its kind in the report
/// @return its text
[[nodiscard]] std::string vector_text(const Eigen::Vector2d& v, int dimension, double scale);

/// @brief A count and its noun: "1 pivot", "3 pivots", "2 passes".
/// @param count how many
/// @param one the noun for one ("pass")
/// @param many the noun for any other count ("passes")
/// @return the text
[[nodiscard]] std::string counted(std::size_t count, std::string_view one, std::string_view many);

/// @brief A place of a scene file as messages name it: @p key in the object at @p path,
/// "bodies[1].mass" (just @p key at the top level, where @p path is empty).
/// @param path the object's place
/// @param key the member
/// @return the place
[[nodiscard]] std::string member_place(std::string_view path, std::string_view key);

/// @brief The element @p index of the array at @p path: "bodies[1]".
/// @param path the array's place
/// @param index the element
/// @return the place
[[nodiscard]] std::string element_place(std::string_view path, std::size_t index);

/// @brief Text in double quotes, for a message: "a" for a.
/// @param text the text
/// @return it, quoted
[[nodiscard]] std::string in_quotes(std::string_view text);

/// @brief The number of characters of UTF-8 text (its bytes that are not continuation bytes):
/// "b–c" is 3 characters, 5 bytes.
/// @param text UTF-8 text
/// @return its width in characters
[[nodiscard]] std::size_t characters(std::string_view text);

/// @brief A table of text cells, for people: each column as wide as its widest cell (counted in
/// characters), cells two spaces apart, numbers right-aligned and text left-aligned, no
/// trailing spaces.
class TextTable {
 public:
  /// @brief A table whose first row is @p header.
  /// @param header the column headings (may be empty strings; no heading at all: an empty row,
  ///        which is not printed)
  /// @param left one flag per column: true for text (left-aligned); columns beyond it are
  ///        right-aligned
  TextTable(std::vector<std::string> header, std::vector<bool> left);

  /// @brief Adds a row.
  /// @param row its cells (a row may have fewer cells than the header)
  void add(std::vector<std::string> row);

  /// @brief The table as lines, each after @p indent and ending with a newline (rows without
  /// cells are left out).
  /// @param indent put in front of every line
  /// @return the text
  [[nodiscard]] std::string render(std::string_view indent = "  ") const;

 private:
  std::vector<bool> left_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace impulse
