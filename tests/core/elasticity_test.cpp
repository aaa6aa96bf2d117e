// SPDX-License-Identifier: GPL-3.0-or-later
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"

using Catch::Matchers::Contains;
using impulse::Elasticity;
using impulse::InvalidInput;

TEST_CASE("The two edge cases of section 1.3 are 1 and 2", "[elasticity]") {
  CHECK(Elasticity::inelastic().value() == 1.0);
  CHECK(Elasticity::elastic().value() == 2.0);
  CHECK(Elasticity().value() == 1.0);  // default: perfectly inelastic
}

TEST_CASE("Elasticity is one plus the coefficient of restitution", "[elasticity]") {
  // Restitution 0 sticks (e = 1), restitution 1 bounces back at full speed (e = 2).
  CHECK(Elasticity::inelastic().restitution() == 0.0);
  CHECK(Elasticity::elastic().restitution() == 1.0);
  CHECK(Elasticity::from_restitution(0.5).value() == 1.5);
  CHECK(Elasticity::from_restitution(-1.0).value() == 0.0);
  CHECK(Elasticity(1.25).restitution() == 0.25);
}

TEST_CASE("Values outside the paper's range stay available for the labs", "[elasticity]") {
  CHECK(Elasticity(0.0).value() == 0.0);  // no collision
  CHECK(Elasticity(0.5).value() == 0.5);  // tunnelling
  CHECK(Elasticity(3.0).value() == 3.0);  // energy gain
}

TEST_CASE("Negative or non-finite elasticities are refused with the value",
          "[elasticity][errors]") {
  CHECK_THROWS_MATCHES(
      Elasticity(-0.5), InvalidInput,
      Catch::Matchers::Message("elasticity must be finite and at least 0, got -0.5"));
  CHECK_THROWS_WITH(Elasticity(std::numeric_limits<double>::quiet_NaN()), Contains("got nan"));
  CHECK_THROWS_WITH(Elasticity(std::numeric_limits<double>::infinity()), Contains("got inf"));
  CHECK_THROWS_WITH(Elasticity::from_restitution(-1.5),
                    "restitution must be finite and at least -1, got -1.5");
  CHECK_THROWS_AS(Elasticity(-1.0), std::invalid_argument);  // derives from std::invalid_argument
}
