// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Bad input: the exception type and the checks that throw it.
#pragma once

#include <Eigen/Core>
#include <cfenv>
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
///
/// The comparisons are the quiet ones (std::isgreater, std::islessequal): a NaN fails both
/// without raising the invalid-operation exception, which `<` and `>` raise for a NaN (GCC
/// compiles them to the signalling `comisd` on x86-64). A caller that traps floating-point
/// exceptions thus gets the refusal, not a SIGFPE.
/// @param value the value to test
/// @return true when require_positive() would accept it
[[nodiscard]] inline bool is_positive(double value) {
  const bool above_zero = std::isgreater(value, 0.0);
  const bool not_infinite = std::islessequal(value, std::numeric_limits<double>::max());
  return above_zero & not_infinite;  // NaN fails both; one branch for the caller
}

/// @brief A quick test, without a branch, that all of @p values are finite.
///
/// std::isfinite looks at the exponent (or compares quietly): no floating-point exception is
/// raised for a NaN or an infinity, unlike the arithmetic test `x - x == 0`, whose
/// `inf - inf` raises the invalid-operation exception.
/// @param values the numbers to test
/// @return true exactly when every value is finite
template <typename... Values>
[[nodiscard]] inline bool all_finite(Values... values) {
  return (static_cast<unsigned>(std::isfinite(values)) & ...) != 0U;
}

/// @brief Whether every coefficient of @p values is finite, raising no floating-point exception.
///
/// Eigen's `allFinite()` tests `x - x == 0`, which raises the invalid-operation exception for an
/// infinity; this tests each coefficient with std::isfinite instead, so that a caller that traps
/// floating-point exceptions gets the library's refusal or its non_finite status.
/// @param values a vector, matrix or array expression
/// @return true when no coefficient is a NaN or an infinity
template <typename Derived>
[[nodiscard]] inline bool all_finite_in(const Eigen::DenseBase<Derived>& values) {
  return values.derived().array().isFinite().all();
}

/// @brief Whether @p normal is of unit length within unit_normal_tolerance, without a square
/// root: @f$ (1 - t)^2 \le \|n\|^2 \le (1 + t)^2 @f$. NaN and infinite coordinates fail
/// (without raising a floating-point exception).
///
/// This is the rule require_unit_normal() applies (its message gives the length found).
/// @param normal the vector to test
/// @return true when @p normal is a unit normal
[[nodiscard]] inline bool is_unit_normal(const Eigen::Vector2d& normal) {
  constexpr double low = (1.0 - unit_normal_tolerance) * (1.0 - unit_normal_tolerance);
  constexpr double high = (1.0 + unit_normal_tolerance) * (1.0 + unit_normal_tolerance);
  const double squared = normal.squaredNorm();
  // Quiet comparisons, as in is_positive(): a NaN fails both without raising an exception.
  const bool long_enough = std::isgreaterequal(squared, low);
  const bool short_enough = std::islessequal(squared, high);
  return long_enough & short_enough;  // one branch for the caller
}

namespace detail {
// The out-of-line, cold halves of the checks below: they build the message and throw. Keeping
// them apart leaves the accepting path a few inlined comparisons, with no string built.
[[noreturn]] void refuse_positive(std::string_view what, double value);
[[noreturn]] void refuse_finite(std::string_view what, double value);
[[noreturn]] void refuse_finite(std::string_view what, const Eigen::Vector2d& value);
[[noreturn]] void refuse_unit_direction(std::string_view what, double direction);
[[noreturn]] void refuse_unit_normal(std::string_view what, const Eigen::Vector2d& normal);
/// While it lives, floating-point exceptions do not trap and raise no flag that outlives it:
/// the environment before is restored when it goes. For the few places that compute a value in
/// order to find out whether it overflows (m·v of a scene's body, strtod in the JSON parser), so
/// that a caller who traps floating-point exceptions gets the refusal, not a SIGFPE.
class HeldFloatingPointExceptions {
 public:
  HeldFloatingPointExceptions() { std::feholdexcept(&saved_); }
  ~HeldFloatingPointExceptions() { std::fesetenv(&saved_); }
  HeldFloatingPointExceptions(const HeldFloatingPointExceptions&) = delete;
  HeldFloatingPointExceptions& operator=(const HeldFloatingPointExceptions&) = delete;
  HeldFloatingPointExceptions(HeldFloatingPointExceptions&&) = delete;
  HeldFloatingPointExceptions& operator=(HeldFloatingPointExceptions&&) = delete;

 private:
  std::fenv_t saved_{};
};
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
