// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Bad input: the exception type and the checks that throw it.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <string_view>

namespace impulse {

/// @brief Thrown for input a caller can correct (a non-positive mass, a non-unit normal, …).
///
/// The message names the quantity and the value that was refused, e.g.
/// `"mass must be positive and finite, got -1"`. Internal assumptions are asserts,
/// numerical failure is a returned status (see impulse::SolveStatus); only bad input throws.
class InvalidInput : public std::invalid_argument {
 public:
  /// @param message the full message, naming the quantity and its bad value
  explicit InvalidInput(const std::string& message) : std::invalid_argument(message) {}
};

/// @brief Shortest text that reads back as the same double ("0.1", "-1", "1e+300", "nan").
/// @param value the number to print
/// @return its shortest round-trip decimal form
[[nodiscard]] std::string format_number(double value);

/// @brief How far a normal's length may be from 1 before it is refused (the scene format's rule).
inline constexpr double unit_normal_tolerance = 1e-9;

/// @brief Throws InvalidInput unless @p value is finite and strictly positive.
/// @param what the quantity's name as the message should show it ("mass", "bodies[2].inertia")
/// @param value the value to check
void require_positive(std::string_view what, double value);

/// @brief Throws InvalidInput unless @p value is finite.
/// @param what the quantity's name as the message should show it
/// @param value the value to check
void require_finite(std::string_view what, double value);

/// @brief Throws InvalidInput unless both coordinates of @p value are finite.
/// @param what the quantity's name as the message should show it
/// @param value the vector to check
void require_finite(std::string_view what, const Eigen::Vector2d& value);

/// @brief Throws InvalidInput unless @p normal is finite and of length 1 within
/// unit_normal_tolerance.
/// @param what the quantity's name as the message should show it
/// @param normal the vector to check
void require_unit_normal(std::string_view what, const Eigen::Vector2d& normal);

/// @brief Throws InvalidInput unless @p direction is +1 or -1 (a normal on a line).
/// @param what the quantity's name as the message should show it
/// @param direction the value to check
void require_unit_direction(std::string_view what, double direction);

}  // namespace impulse
