// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 1, elasticity on a line: what the students should find in elasticity.csv and the plots.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's bodies: m1 = 2 at 3 on the left, m2 = 1 at -1 on the right.
constexpr double m1 = 2.0;
constexpr double v1 = 3.0;
constexpr double m2 = 1.0;
constexpr double v2 = -1.0;
// By hand: reduced mass mu = m1 m2 / (m1 + m2) = 2/3, closing speed u = v1 - v2 = 4.
constexpr double mu = m1 * m2 / (m1 + m2);
constexpr double u = v1 - v2;
constexpr double energy_before = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;  // 9.5
constexpr double step = 0.05;  // the sweep's step in elasticity

// Independently of the library: (1.3) with equal elasticities gives Fdt = e u / (1/m1 + 1/m2)
// = e mu u, so the velocity of body 2 relative to body 1 goes from -u to -u + Fdt (1/m1 + 1/m2)
// = (e - 1) u. The centre of mass keeps its velocity and the energy of the relative motion is
// mu w^2 / 2, so the change of kinetic energy is mu u^2 ((e - 1)^2 - 1) / 2 = mu u^2 e (e - 2) / 2.
double energy_change(double e) {
  return 0.5 * mu * u * u * e * (e - 2.0);
}
double relative_after(double e) {
  return (e - 1.0) * u;
}

}  // namespace

TEST_CASE(
    "lab 1: the energy change is the parabola mu u^2 e(e-2)/2 and the relative velocity (e-1)u") {
  const labtest::Table t(output / "elasticity.csv");
  REQUIRE(t.rows() == 61);  // 0 to 3 in steps of 0.05
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double e = t["elasticity"][i];
    CAPTURE(e);
    CHECK(e == Approx(static_cast<double>(i) * step).margin(1e-12));
    CHECK(t["energy_before"][i] == Approx(energy_before));
    CHECK(t["energy_change"][i] == Approx(energy_change(e)).margin(1e-12));
    CHECK(t["energy_after"][i] == Approx(energy_before + energy_change(e)).margin(1e-12));
    CHECK(t["relative_velocity_before"][i] == Approx(-u));
    CHECK(t["relative_velocity_after"][i] == Approx(relative_after(e)).margin(1e-12));
    // Momentum is kept whatever the elasticity.
    CHECK(m1 * t["v1_after"][i] + m2 * t["v2_after"][i] == Approx(m1 * v1 + m2 * v2));
  }
}

TEST_CASE("lab 1: the largest loss is at elasticity 1, the zeros at 0 and 2, a gain above 2") {
  const labtest::Table t(output / "elasticity.csv");
  const auto& e = t["elasticity"];
  const auto& change = t["energy_change"];
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    lowest = change[i] < change[lowest] ? i : lowest;
  }
  CHECK(std::abs(e[lowest] - 1.0) <= step);
  CHECK(change[lowest] == Approx(-0.5 * mu * u * u));  // -16/3: the relative motion is all lost
  for (std::size_t i = 0; i < t.rows(); ++i) {
    CAPTURE(e[i]);
    const double tolerance = 1e-9 * energy_before;
    if (std::abs(e[i]) < 1e-12 || std::abs(e[i] - 2.0) < 1e-12) {
      CHECK(std::abs(change[i]) < tolerance);  // the zeros of the parabola
    } else if (e[i] < 2.0) {
      CHECK(change[i] < -tolerance);  // energy lost
    } else {
      CHECK(change[i] > tolerance);  // energy gained
    }
  }
}

TEST_CASE("lab 1: below elasticity 1 the bodies still approach, and elasticity = 1 + restitution") {
  const labtest::Table t(output / "elasticity.csv");
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double e = t["elasticity"][i];
    const double w = t["relative_velocity_after"][i];
    CAPTURE(e, w);
    if (e < 1.0 - 1e-12) {
      CHECK(w < 0.0);  // body 1 is still faster than body 2: they pass through each other
    } else if (e > 1.0 + 1e-12) {
      CHECK(w > 0.0);  // they separate
    }
    // The measured coefficient of restitution, separation speed over closing speed.
    CHECK(w / u == Approx(e - 1.0).margin(1e-12));
  }
}

#ifdef LAB_SWEEP
TEST_CASE("lab 1: impulselab sweep on elastic-1d.json gives the same parabola") {
  const labtest::Table t(output / "sweep.csv");
  REQUIRE(t.rows() == 31);  // 0:3:0.1
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double e = t["elasticity"][i];
    CAPTURE(e);
    CHECK(t["energy_change"][i] == Approx(energy_change(e)).margin(1e-12));
    CHECK(t["energy_after"][i] == Approx(energy_before + energy_change(e)).margin(1e-12));
  }
}
#endif

TEST_CASE("lab 1: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
