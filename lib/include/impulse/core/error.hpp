// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Bad input: the exception type and the checks that throw it.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
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

/// @brief Whether @p value is finite and strictly positive (a mass, a moment of inertia).
/// @param value the value to test
/// @return true when require_positive() would accept it
[[nodiscard]] inline bool is_positive(double value) {
  return (value > 0.0) & (value <= std::numeric_limits<double>::max());  // NaN fails both
}

/// @brief A quick test, one comparison, that all of @p values are finite.
///
/// Each value minus itself is zero when it is finite and NaN when it is NaN or infinite; their
/// sum cannot overflow.
/// @param values the numbers to test
/// @return true exactly when every value is finite
template <typename... Values>
[[nodiscard]] inline bool all_finite(Values... values) {
  return ((values - values) + ...) == 0.0;
}

/// @brief Whether @p normal is of unit length within unit_normal_tolerance, without a square
/// root: @f$ (1 - t)^2 \le \|n\|^2 \le (1 + t)^2 @f$. NaN and infinite coordinates fail.
///
/// This is the rule require_unit_normal() applies (its message gives the length found).
/// @param normal the vector to test
/// @return true when @p normal is a unit normal
[[nodiscard]] inline bool is_unit_normal(const Eigen::Vector2d& normal) {
  constexpr double low = (1.0 - unit_normal_tolerance) * (1.0 - unit_normal_tolerance);
  constexpr double high = (1.0 + unit_normal_tolerance) * (1.0 + unit_normal_tolerance);
  const double squared = normal.squaredNorm();
  return (squared >= low) & (squared <= high);  // NaN fails both; one branch for the caller
}

namespace detail {
// The out-of-line, cold halves of the checks below: they build the message and throw. Keeping
// them apart leaves the accepting path a few inlined comparisons, with no string built.
[[noreturn]] void refuse_positive(std::string_view what, double value);
[[noreturn]] void refuse_finite(std::string_view what, double value);
[[noreturn]] void refuse_finite(std::string_view what, const Eigen::Vector2d& value);
[[noreturn]] void refuse_unit_direction(std::string_view what, double direction);
[[noreturn]] void refuse_unit_normal(std::string_view what, const Eigen::Vector2d& normal);
}  // namespace detail

/// @brief Throws InvalidInput unless @p value is finite and strictly positive.
/// @param what the quantity's name as the message should show it ("mass", "bodies[2].inertia")
/// @param value the value to check
inline void require_positive(std::string_view what, double value) {
  if (!is_positive(value)) [[unlikely]] {
    detail::refuse_positive(what, value);
  }
}

/// @brief Throws InvalidInput unless @p value is finite.
/// @param what the quantity's name as the message should show it
/// @param value the value to check
inline void require_finite(std::string_view what, double value) {
  if (!std::isfinite(value)) [[unlikely]] {
    detail::refuse_finite(what, value);
  }
}

/// @brief Throws InvalidInput unless both coordinates of @p value are finite.
/// @param what the quantity's name as the message should show it
/// @param value the vector to check
inline void require_finite(std::string_view what, const Eigen::Vector2d& value) {
  if (!(std::isfinite(value.x()) && std::isfinite(value.y()))) [[unlikely]] {
    detail::refuse_finite(what, value);
  }
}

/// @brief Throws InvalidInput unless @p normal is finite and of length 1 within
/// unit_normal_tolerance.
///
/// The test computes no square root (see is_unit_normal()); the message, built only when the
/// normal is refused, gives the length found.
/// @param what the quantity's name as the message should show it
/// @param normal the vector to check
inline void require_unit_normal(std::string_view what, const Eigen::Vector2d& normal) {
  if (!is_unit_normal(normal)) [[unlikely]] {
    detail::refuse_unit_normal(what, normal);
  }
}

/// @brief Throws InvalidInput unless @p direction is +1 or -1 (a normal on a line).
/// @param what the quantity's name as the message should show it
/// @param direction the value to check
inline void require_unit_direction(std::string_view what, double direction) {
  if (direction != 1.0 && direction != -1.0) [[unlikely]] {
    detail::refuse_unit_direction(what, direction);
  }
}

}  // namespace impulse
