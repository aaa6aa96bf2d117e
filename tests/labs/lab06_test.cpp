// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 6, mixed elasticities: energy gained, and an outcome that depends on the observer.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's bodies: masses 1 and 1; body 1 (left) has elasticity 2, body 2 (right) 1.
// (1.3) with body 1's normal +1 and body 2's -1: Fdt (1 + 1) = 2 v1 + 1 (-v2), so
// Fdt = (2 v1 - v2) / 2; the closing speed is u = v1 - v2 and the energy change
// Fdt^2 (1/m1 + 1/m2) / 2 - Fdt u = Fdt^2 - Fdt u.
double impulse(double v1, double v2) {
  return (2 * v1 - v2) / 2;
}
double energy_change(double v1, double v2) {
  const double F = impulse(v1, v2);
  return F * F - F * (v1 - v2);
}

}  // namespace

TEST_CASE("lab 6: the worked example gains energy: 2.5 before, 3.25 after") {
  // Body 1 at 2 catches body 2, which moves away at 1 (the paper's p2 = -1): Fdt = (4 - 1)/2 = 1.5,
  // velocities after 2 - 1.5 = 0.5 and 1 + 1.5 = 2.5, energy 2 + 0.5 = 2.5 before and
  // 0.125 + 3.125 = 3.25 after.
  const labtest::Table t(output / "frames.csv");
  const std::size_t ground = 20;  // w = 0
  REQUIRE(t["boost"][ground] == Approx(0.0).margin(1e-12));
  CHECK(t["mixed_energy_change"][ground] == Approx(0.75));
  CHECK(t["mixed_v1_after"][ground] == Approx(0.5));
  CHECK(t["mixed_v2_after"][ground] == Approx(2.5));
}

TEST_CASE("lab 6: the gains found in the map are where the hand calculation puts them") {
  // A gain means Fdt outside [0, 2u/A] = [0, u]: 2 v1 - v2 > 2 (v1 - v2), i.e. v2 > 0 (body 2
  // moving away from body 1), or 2 v1 - v2 < 0, i.e. v2 > 2 v1 (an impulse that pulls).
  const labtest::Table t(output / "gain-map.csv");
  REQUIRE(t.rows() == 121 * 121);
  std::size_t approaching = 0;
  std::size_t gains = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double v1 = t["v1"][i];
    const double v2 = t["v2"][i];
    CAPTURE(v1, v2);
    if (v1 - v2 <= 1e-9) {
      CHECK(std::isnan(t["energy_change"][i]));  // no collision
      continue;
    }
    ++approaching;
    const double change = t["energy_change"][i];
    CHECK(change == Approx(energy_change(v1, v2)).margin(1e-12));
    CHECK(t["impulse"][i] == Approx(impulse(v1, v2)).margin(1e-12));
    // In units of the relative motion's energy u^2/4 it is e(e - 2) with the effective
    // elasticity e = Fdt A / u, as in lab 1.
    const double e = 2 * impulse(v1, v2) / (v1 - v2);
    CHECK(t["relative_energy_change"][i] == Approx(e * (e - 2)).margin(1e-9));
    const bool on_boundary = std::abs(v2) < 1e-9 || std::abs(v2 - 2 * v1) < 1e-9;
    if (!on_boundary) {
      const bool gain = v2 > 0 || v2 > 2 * v1;
      CHECK((change > 0) == gain);
      gains += change > 0 ? 1 : 0;
    }
  }
  CHECK(approaching == 7260);  // the cells strictly below the diagonal: 121 * 120 / 2
  CHECK(gains > 0);
}

TEST_CASE(
    "lab 6: with mixed elasticities the outcome depends on the observer, with equal ones not") {
  // An observer moving at w sees v - w. Mixed: Fdt = (2 (2 - w) - (1 - w)) / 2 = (3 - w) / 2,
  // which depends on w; back in the ground frame the velocities after are 2 - Fdt = (1 + w)/2 and
  // 1 + Fdt = (5 - w)/2. Elastic for the observer moving with body 2 (w = 1: Fdt = 1 = u, energy
  // kept), perfectly inelastic for the one moving with body 1 (w = 2: Fdt = 1/2, the common
  // velocity, energy change -u^2/4). Equal elasticities e: Fdt = e u / 2 for every observer.
  const labtest::Table t(output / "frames.csv");
  REQUIRE(t.rows() == 81);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double w = t["boost"][i];
    CAPTURE(w);
    CHECK(w == Approx(-1.0 + 0.05 * static_cast<double>(i)).margin(1e-12));
    const double F = (3 - w) / 2;
    CHECK(t["mixed_energy_change"][i] == Approx(F * F - F).margin(1e-12));
    CHECK(t["mixed_v1_after"][i] == Approx((1 + w) / 2).margin(1e-12));
    CHECK(t["mixed_v2_after"][i] == Approx((5 - w) / 2).margin(1e-12));
    // Equal elasticities: the same outcome for everyone.
    CHECK(t["equal_1.5_energy_change"][i] == Approx(0.75 * 0.75 - 0.75).margin(1e-12));
    CHECK(t["equal_1.5_v1_after"][i] == Approx(1.25).margin(1e-12));
    CHECK(t["equal_1.5_v2_after"][i] == Approx(1.75).margin(1e-12));
    CHECK(t["equal_2_energy_change"][i] == Approx(0.0).margin(1e-12));
    CHECK(t["equal_2_v1_after"][i] == Approx(1.0).margin(1e-12));
    CHECK(t["equal_2_v2_after"][i] == Approx(2.0).margin(1e-12));
  }
  CHECK(t["mixed_energy_change"][40] == Approx(0.0).margin(1e-12));  // w = 1, with body 2
  CHECK(t["mixed_energy_change"][60] == Approx(-0.25));              // w = 2, with body 1
}

TEST_CASE("lab 6: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
