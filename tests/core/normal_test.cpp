// SPDX-License-Identifier: GPL-3.0-or-later
// Unit normals made once: any finite non-zero vector (scaled to unit length), or an angle.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"

using Catch::Matchers::WithinAbs;
using Eigen::Vector2d;
using impulse::UnitNormal;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}

TEST_CASE("A unit vector is kept as given, digit for digit", "[core][normal]") {
  // 0.6 and 0.8 are not exact in binary: their squares sum to 1 within an ulp, not exactly.
  const UnitNormal n(Vector2d(0.6, 0.8));
  CHECK(n.vector() == Vector2d(0.6, 0.8));
  CHECK_FALSE(n.rescaled());
  // Within the scene format's tolerance 1e-9 of length 1: kept too (the result stays the one
  // the format specifies for such a normal).
  const Vector2d almost(0.6 * (1 + 0.5e-9), 0.8 * (1 + 0.5e-9));
  CHECK(UnitNormal(almost).vector() == almost);
  CHECK_FALSE(UnitNormal(almost).rescaled());
}

TEST_CASE("Any other finite non-zero vector is divided by its length", "[core][normal]") {
  // [3, 4] has length 5: the normal is [3/5, 4/5].
  const UnitNormal n(Vector2d(3, 4));
  CHECK(n.rescaled());
  CHECK(n.given_length() == 5.0);
  CHECK_THAT(n.vector().x(), WithinAbs(0.6, eps));
  CHECK_THAT(n.vector().y(), WithinAbs(0.8, eps));
  // A student's [0.7071, 0.7071]: length 0.7071 * sqrt(2) = 0.99998... (off by 2e-5, far beyond
  // 1e-9); the normal is the diagonal [1/sqrt(2), 1/sqrt(2)].
  const UnitNormal diagonal(Vector2d(0.7071, 0.7071));
  CHECK(diagonal.rescaled());
  CHECK_THAT(diagonal.given_length(), WithinAbs(0.7071 * std::sqrt(2.0), 4 * eps));
  CHECK_THAT(diagonal.vector().x(), WithinAbs(std::sqrt(0.5), eps));
  CHECK_THAT(diagonal.vector().y(), WithinAbs(std::sqrt(0.5), eps));
  // The same direction at any scale, from subnormal to near the largest double: the scaling by a
  // power of two keeps every bit of the ratio 3 : 4.
  for (const double scale : {1e-320, 1e-300, 1e-9, 1e9, 1e300}) {
    CAPTURE(scale);
    const UnitNormal scaled(Vector2d(3 * scale, 4 * scale));
    CHECK_THAT(scaled.vector().x(), WithinAbs(0.6, 2 * eps));
    CHECK_THAT(scaled.vector().y(), WithinAbs(0.8, 2 * eps));
    CHECK(std::abs(scaled.vector().norm() - 1.0) <= impulse::unit_normal_tolerance);
  }
  // On a line: any non-zero number is its sign.
  CHECK(UnitNormal(Vector2d(-0.5, 0)).vector() == Vector2d(-1, 0));
}

TEST_CASE("A zero or non-finite normal is refused with the value", "[core][normal][errors]") {
  CHECK_THROWS_MATCHES(
      UnitNormal(Vector2d(0, 0)), impulse::InvalidInput,
      Catch::Matchers::Message("normal must be a finite non-zero vector, got [0, 0]"));
  CHECK_THROWS_WITH(UnitNormal("contacts[1].normal", Vector2d(std::nan(""), 1)),
                    "contacts[1].normal must be a finite non-zero vector, got [nan, 1]");
  CHECK_THROWS_WITH(UnitNormal(Vector2d(std::numeric_limits<double>::infinity(), 0)),
                    "normal must be a finite non-zero vector, got [inf, 0]");
  CHECK_THROWS_WITH(UnitNormal::from_degrees(std::numeric_limits<double>::infinity()),
                    "normal_angle must be finite, got inf");
}

TEST_CASE("A normal from an angle in degrees: exact at multiples of 90", "[core][normal]") {
  CHECK(UnitNormal::from_degrees(0).vector() == Vector2d(1, 0));
  CHECK(UnitNormal::from_degrees(90).vector() == Vector2d(0, 1));
  CHECK(UnitNormal::from_degrees(180).vector() == Vector2d(-1, 0));
  CHECK(UnitNormal::from_degrees(270).vector() == Vector2d(0, -1));
  CHECK(UnitNormal::from_degrees(-90).vector() == Vector2d(0, -1));
  CHECK(UnitNormal::from_degrees(450).vector() == Vector2d(0, 1));
  CHECK(UnitNormal::from_degrees(-720).vector() == Vector2d(1, 0));
  // 30 degrees: (cos, sin) = (sqrt(3)/2, 1/2); 135 degrees: (-1/sqrt(2), 1/sqrt(2)).
  const Vector2d thirty = UnitNormal::from_degrees(30).vector();
  CHECK_THAT(thirty.x(), WithinAbs(std::sqrt(3.0) / 2, eps));
  CHECK_THAT(thirty.y(), WithinAbs(0.5, eps));
  const Vector2d one_thirty_five = UnitNormal::from_degrees(135).vector();
  CHECK_THAT(one_thirty_five.x(), WithinAbs(-std::sqrt(0.5), eps));
  CHECK_THAT(one_thirty_five.y(), WithinAbs(std::sqrt(0.5), eps));
  CHECK_FALSE(UnitNormal::from_degrees(30).rescaled());
}

TEST_CASE("The opposite normal is the other body's", "[core][normal]") {
  const UnitNormal n(Vector2d(3, 4));
  CHECK((-n).vector() == -n.vector());
  CHECK((-n).rescaled());
}
