// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 3, spin after impact: a uniform rod landing on one end, against the closed forms for a rod.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <numbers>
#include <string>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's rod: m = 1, l = 1, I = m l^2 / 12, falling at v = 1 without spin.
constexpr double m = 1.0;
constexpr double l = 1.0;
constexpr double I = m * l * l / 12;
constexpr double v = 1.0;
constexpr double degree = std::numbers::pi / 180.0;

// By hand: the landing end sits at r = (l/2 cos(a), -l/2 sin(a)) from the centre and the rod's
// outward normal there is (0, -1), so det(r, n) = -l/2 cos(a) and (3.6)/(3.10) give
// A = det^2 / I + 1/m = (1 + 3 cos^2 a) / m and B = e v (no spin, p.n / m = v). Hence
// j = e m v / (1 + 3 cos^2 a), with e = 1 + restitution.
double impulse(double e, double a) {
  const double c = std::cos(a);
  return e * m * v / (1 + 3 * c * c);
}
// The upward impulse j at arm r turns the rod by det(r, (0, j)) = r_x j = l/2 cos(a) j.
double spin(double e, double a) {
  return 0.5 * l * std::cos(a) * impulse(e, a) / I;
}
double centre_vy(double e, double a) {
  return -v + impulse(e, a) / m;
}

const char* const suffixes[] = {"e1", "e1.5", "e2"};
const double elasticities[] = {1.0, 1.5, 2.0};

std::size_t row_of_largest(const labtest::Table& t, const std::string& column) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    best = t[column][i] > t[column][best] ? i : best;  // NaN never wins
  }
  return best;
}

}  // namespace

TEST_CASE("lab 3: the impulse is e m v / (1 + 3 cos^2) and the spin 6 j cos / (m l)") {
  const labtest::Table t(output / "rod.csv");
  REQUIRE(t.rows() == 91);  // 0 to 90 degrees
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double a = t["angle"][i] * degree;
    for (int k = 0; k < 3; ++k) {
      const std::string s = suffixes[k];
      const double e = elasticities[k];
      CAPTURE(t["angle"][i], e);
      CHECK(t["impulse_" + s][i] == Approx(impulse(e, a)).margin(1e-12));
      CHECK(t["spin_" + s][i] == Approx(spin(e, a)).margin(1e-12));
      CHECK(t["centre_vy_" + s][i] == Approx(centre_vy(e, a)).margin(1e-12));
      // The landing end leaves the ground at restitution times the speed it arrived with: the
      // elasticity acts on the contact point's normal velocity, not on the centre's.
      CHECK(t["contact_vy_" + s][i] == Approx((e - 1) * v).margin(1e-12));
      const double rotation = 0.5 * I * spin(e, a) * spin(e, a);
      const double translation = 0.5 * m * centre_vy(e, a) * centre_vy(e, a);
      CHECK(t["energy_" + s][i] == Approx(rotation + translation).margin(1e-12));
      if (rotation + translation > 1e-9) {
        CHECK(t["rotation_share_" + s][i] ==
              Approx(rotation / (rotation + translation)).margin(1e-9));
      }
    }
    // At elasticity 2 the kinetic energy is kept, whatever share goes into the spin.
    CHECK(t["energy_e2"][i] == Approx(0.5 * m * v * v));
  }
}

TEST_CASE("lab 3: flat, upright, and the largest spin at cos^2 = 1/3") {
  const labtest::Table t(output / "rod.csv");
  for (int k = 0; k < 3; ++k) {
    const std::string s = suffixes[k];
    const double e = elasticities[k];
    CAPTURE(e);
    // Flat (0 degrees): a quarter of the upright impulse; upright (90): no lever arm, no spin.
    CHECK(t["impulse_" + s][0] == Approx(e * m * v / 4));
    CHECK(t["impulse_" + s][90] == Approx(e * m * v));
    CHECK(t["spin_" + s][90] == Approx(0.0).margin(1e-12));
    // The spin goes as cos(a) / (1 + 3 cos^2 a); with c = cos(a), d/dc [c / (1 + 3c^2)] = 0 at
    // c^2 = 1/3, so the largest spin is at arccos(1/sqrt(3)) = 54.74 degrees, for every e.
    const double peak = std::acos(1 / std::sqrt(3.0)) / degree;
    CHECK(std::abs(t["angle"][row_of_largest(t, "spin_" + s)] - peak) <= 1.0);
    // The centre stops, and all the energy left is rotation, where j = m v: cos^2 = (e - 1)/3.
    if (e > 1) {
      const double stops = std::acos(std::sqrt((e - 1) / 3)) / degree;  // 54.74 and 65.91
      CHECK(std::abs(t["angle"][row_of_largest(t, "rotation_share_" + s)] - stops) <= 1.0);
    }
  }
}

TEST_CASE("lab 3: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
