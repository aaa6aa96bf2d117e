// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 2, casting onto the normal: the normal components are exchanged, the tangential ones kept.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <numbers>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's pucks: mass 1 each, A at (1, 0), B at (-0.5, 0), elasticity 2.
constexpr double ax = 1.0;
constexpr double bx = -0.5;

}  // namespace

TEST_CASE(
    "lab 2: along the normal the pucks exchange velocities, along the tangent they keep them") {
  const labtest::Table t(output / "oblique.csv");
  REQUIRE(t.rows() == 73);  // -90 to 90 degrees in steps of 2.5
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double degrees = t["angle"][i];
    CAPTURE(degrees);
    CHECK(degrees == Approx(-90.0 + 2.5 * static_cast<double>(i)));
    const double phi = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(phi);
    const double s = std::sin(phi);
    // By hand, with n = (c, s) and t = (-s, c): A has normal component c and tangential -s,
    // B has -c/2 and s/2. The cast reduces the collision to section 1 along n: with equal masses,
    // (1.3) at elasticity 2 gives Fdt (1 + 1) = 2 (c - (-c/2)), so Fdt = 3c/2, and each puck's
    // normal component moves by -+ 3c/2: A gets -c/2 (B's), B gets c (A's).
    CHECK(t["impulse"][i] == Approx(1.5 * c).margin(1e-12));
    CHECK(t["a_normal_before"][i] == Approx(ax * c).margin(1e-12));
    CHECK(t["b_normal_before"][i] == Approx(bx * c).margin(1e-12));
    CHECK(t["a_normal_after"][i] == Approx(bx * c).margin(1e-12));
    CHECK(t["b_normal_after"][i] == Approx(ax * c).margin(1e-12));
    // The impulse is along n, so the tangential components do not change.
    CHECK(t["a_tangent_before"][i] == Approx(-ax * s).margin(1e-12));
    CHECK(t["b_tangent_before"][i] == Approx(-bx * s).margin(1e-12));
    CHECK(t["a_tangent_after"][i] == Approx(-ax * s).margin(1e-12));
    CHECK(t["b_tangent_after"][i] == Approx(-bx * s).margin(1e-12));
    // Back in x and y: v' = (normal) n + (tangential) t. And the x-y columns agree with the cast.
    CHECK(t["a_vx"][i] == Approx(bx * c * c + ax * s * s).margin(1e-12));
    CHECK(t["a_vy"][i] == Approx(bx * c * s - ax * s * c).margin(1e-12));
    CHECK(t["b_vx"][i] == Approx(ax * c * c + bx * s * s).margin(1e-12));
    CHECK(t["b_vy"][i] == Approx(ax * c * s - bx * s * c).margin(1e-12));
    CHECK(t["a_vx"][i] * c + t["a_vy"][i] * s == Approx(t["a_normal_after"][i]).margin(1e-12));
    // Energy and momentum are kept: 1/2 + 1/8 before, (1 - 0.5, 0) momentum.
    CHECK(t["energy_before"][i] == Approx(0.625));
    CHECK(t["energy_after"][i] == Approx(0.625));
    CHECK(t["momentum_x_after"][i] == Approx(ax + bx));
    CHECK(t["momentum_y_after"][i] == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("lab 2: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
