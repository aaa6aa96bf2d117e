// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 7, three ways to resolve many contacts: the lab's answers checked against values worked by
// hand (the worksheet gives the same derivations) and against the conservation of energy.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

void check_column(const labtest::Table& t, const std::string& name,
                  const std::vector<double>& expected) {
  CAPTURE(name);
  const std::vector<double>& got = t[name];
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    CAPTURE(i);
    CHECK(got[i] == Approx(expected[i]).margin(1e-12));
  }
}

}  // namespace

TEST_CASE("lab 7: Newton's cradle at (3, 0, 0): (-1, 2, 2) at once, (0, 0, 3) in turn") {
  // A = [[2, -1], [-1, 2]], B = 2 (3, 0): Fdt = (4, 2) >= 0, so complementarity agrees.
  // Serial: equal masses exchange velocities, contact 0 then contact 1.
  const labtest::Table t(output / "cradle.csv");
  check_column(t, "simultaneous", {-1, 2, 2});
  check_column(t, "complementarity", {-1, 2, 2});
  check_column(t, "serial", {0, 0, 3});
}

TEST_CASE(
    "lab 7: two balls hitting one at (3, 0, -1.5): (-2, 1, 2.5) at once, (-1.5, 0, 3) in "
    "turn") {
  // B = 2 (3, 1.5) = (6, 3), Fdt = (1/3) [[2, 1], [1, 2]] (6, 3) = (5, 4). Serial: contact 0
  // (3 > 1.5) gives (0, 3, -1.5), contact 1 (4.5) gives (0, -1.5, 3), contact 0 (1.5) gives
  // (-1.5, 0, 3).
  const labtest::Table t(output / "two-hit-one.csv");
  check_column(t, "simultaneous", {-2, 1, 2.5});
  check_column(t, "complementarity", {-2, 1, 2.5});
  check_column(t, "serial", {-1.5, 0, 3});
}

TEST_CASE("lab 7: the spinning rod, at every spin, against the formulas of the worksheet") {
  // A = [[4, -2], [-2, 4]], approach speeds u = (1 + w, 1 - w), B = e u. With the rising end's
  // contact 1:
  //  simultaneous Fdt_1 = e (6 - 2w) / 12, and its approach after -(e - 1) u_1 = (e - 1)(w - 1);
  //  complementarity: the same while w <= 3, then Fdt_1 = 0 with Fdt_0 = e (1 + w) / 4, and
  //    the approach after u_1 - A_10 Fdt_0 = (1 - w) + e (1 + w) / 2: 2 at e = 2, (3 - w) / 2
  //    at e = 1;
  //  serial at e = 2: Fdt_1 = 1 at every spin (contact 1 always ends with one collision at
  //    approach 2), leaving it at -2 for w >= 1 and at -(1 + w) below (a third collision at
  //    contact 0); at e = 1 serial collisions converge to the complementarity answer.
  // All keep the energy 1/2 + w^2 / 6 at e = 2.
  const labtest::Table t(output / "rod.csv");
  REQUIRE(t.rows() == 81);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double w = t["omega"][i];
    CAPTURE(w);
    const double simultaneous_2 = (6 - 2 * w) / 6;
    CHECK(t["simultaneous_impulse_e2"][i] == Approx(simultaneous_2).margin(1e-12));
    CHECK(t["complementarity_impulse_e2"][i] ==
          Approx(w <= 3 ? simultaneous_2 : 0.0).margin(1e-12));
    CHECK(t["serial_impulse_e2"][i] == Approx(1.0).margin(1e-12));
    CHECK(t["simultaneous_approach_e2"][i] == Approx(w - 1).margin(1e-12));
    CHECK(t["complementarity_approach_e2"][i] == Approx(w <= 3 ? w - 1 : 2.0).margin(1e-12));
    CHECK(t["serial_approach_e2"][i] == Approx(w < 1 ? -(1 + w) : -2.0).margin(1e-12));
    const double energy = 0.5 + w * w / 6;
    CHECK(t["energy_before"][i] == Approx(energy).epsilon(1e-14));
    for (const char* method : {"simultaneous", "complementarity", "serial"}) {
      CAPTURE(method);
      CHECK(t[std::string(method) + "_energy_e2"][i] == Approx(energy).epsilon(1e-12));
    }
    const double simultaneous_1 = (6 - 2 * w) / 12;
    CHECK(t["simultaneous_impulse_e1"][i] == Approx(simultaneous_1).margin(1e-12));
    CHECK(t["complementarity_impulse_e1"][i] ==
          Approx(w <= 3 ? simultaneous_1 : 0.0).margin(1e-12));
    CHECK(t["serial_impulse_e1"][i] == Approx(w <= 3 ? simultaneous_1 : 0.0).margin(1e-10));
    CHECK(t["simultaneous_approach_e1"][i] == Approx(0.0).margin(1e-12));
    CHECK(t["complementarity_approach_e1"][i] == Approx(w <= 3 ? 0.0 : (3 - w) / 2).margin(1e-12));
    CHECK(t["serial_approach_e1"][i] == Approx(w <= 3 ? 0.0 : (3 - w) / 2).margin(1e-10));
  }
}

TEST_CASE("lab 7: serial collisions: N - 1 for a cradle at elasticity 2, 40 at elasticity 1") {
  // At e = 2 the speed is handed down the row, one collision per contact. At e = 1, for three
  // balls at (1, 0, 0), each collision equalises one pair and leaves the other approaching at
  // half the speed: after k collisions 2^-k, first below the tolerance 1e-12 (of the speed 1)
  // at k = 40.
  const labtest::Table t(output / "collisions.csv");
  REQUIRE(t.rows() == 101);
  CHECK(t["elasticity"][0] == Approx(1.0));
  CHECK(t["cradle_3"][0] == 40);
  const std::size_t last = t.rows() - 1;
  CHECK(t["elasticity"][last] == Approx(2.0));
  CHECK(t["cradle_3"][last] == 2);
  CHECK(t["cradle_5"][last] == 4);
  CHECK(t["rod_omega_2"][last] == 2);
  // Below 2 never fewer collisions than at 2, for each scene.
  for (std::size_t i = 0; i < t.rows(); ++i) {
    CHECK(t["cradle_3"][i] >= 2);
    CHECK(t["cradle_5"][i] >= 4);
  }
}

TEST_CASE("lab 7: a light ball between a wall and a heavy one counts the digits of pi") {
  // Galperin (2003): mass ratios 100^k give the first k + 1 digits of pi as the number of
  // elastic collisions.
  const labtest::Table t(output / "galperin.csv");
  check_column(t, "mass_ratio", {1, 100, 1e4, 1e6});
  check_column(t, "collisions", {3, 31, 314, 3141});
}

TEST_CASE("lab 7: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
