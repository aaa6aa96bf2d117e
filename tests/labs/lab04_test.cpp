// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 4, many contact points: the box's lever rule, the bead's dependent system and its two
// solutions, and the split in a shallow V.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <numbers>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's landings: mass 1, falling at v = 1, elasticity 1.5, contacts at x = -1 and +1.
constexpr double m = 1.0;
constexpr double v = 1.0;
constexpr double e = 1.5;

}  // namespace

TEST_CASE("lab 4: the box's impulses follow the lever rule and it leaves without spin") {
  // By hand: each contact's normal velocity after is (1 - e) times the one before (that is what
  // the system says row by row when A is regular, B = e u and u - A Fdt is the velocity after).
  // Both corners then leave upwards at (e - 1) v, so the box does not spin and its centre leaves
  // at (e - 1) v. Momentum: j1 + j2 = m (e - 1) v + m v = e m v. No spin: the angular impulses
  // about the centre cancel, (-1 - c) j1 + (1 - c) j2 = 0. Hence j1 = e m v (1 - c) / 2 and
  // j2 = e m v (1 + c) / 2, the lever rule of a beam on two supports; I does not enter.
  const labtest::Table t(output / "lever.csv");
  REQUIRE(t.rows() == 41);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double c = t["offset"][i];
    CAPTURE(c);
    CHECK(t["box_rank"][i] == 2);
    CHECK(t["box_j1"][i] == Approx(e * m * v * (1 - c) / 2).margin(1e-12));
    CHECK(t["box_j2"][i] == Approx(e * m * v * (1 + c) / 2).margin(1e-12));
    CHECK(t["box_vy_after"][i] == Approx((e - 1) * v));
    CHECK(t["box_spin_after"][i] == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("lab 4: the bead's system is dependent, and both of its solutions move it the same way") {
  // A point mass has two degrees of freedom, but both normals are (0, 1): A = [[1, 1], [1, 1]] / m,
  // rank 1. Only j1 + j2 is fixed: e m v, as for one contact. The least-norm split is equal,
  // e m v / 2 each; a basic solution puts it all on one contact. Either way the bead leaves at
  // (e - 1) v, as the box did.
  const labtest::Table t(output / "lever.csv");
  for (std::size_t i = 0; i < t.rows(); ++i) {
    CAPTURE(t["offset"][i]);
    CHECK(t["bead_rank"][i] == 1);
    CHECK(t["bead_dependent"][i] == 1);
    CHECK(t["bead_min_norm_j1"][i] == Approx(e * m * v / 2));
    CHECK(t["bead_min_norm_j2"][i] == Approx(e * m * v / 2));
    const double j1 = t["bead_basic_j1"][i];
    const double j2 = t["bead_basic_j2"][i];
    CHECK(j1 + j2 == Approx(e * m * v));
    CHECK(std::min(std::abs(j1), std::abs(j2)) == Approx(0.0).margin(1e-12));
    CHECK(t["bead_min_norm_vy_after"][i] == Approx((e - 1) * v));
    CHECK(t["bead_basic_vy_after"][i] == Approx((e - 1) * v));
    CHECK(t["bead_min_norm_vy_after"][i] == Approx(t["box_vy_after"][i]));
  }
}

TEST_CASE("lab 4: in a V the split is fixed by the tilts, and every split is the limit of one") {
  // By hand: with normals (sin a1, cos a1) and (-sin a2, cos a2) the two normal velocities after
  // are (1 - e) times those before; two independent normals fix the whole velocity, so it is
  // (1 - e) (0, -v) and the impulse is e m v upwards. Horizontally j1 sin a1 = j2 sin a2, so the
  // left support carries sin a2 / (sin a1 + sin a2), close to 1 - a1/(a1 + a2) for small tilts.
  const labtest::Table t(output / "tilt.csv");
  REQUIRE(t.rows() == 21);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double f = t["left_fraction"][i];
    CAPTURE(f);
    CHECK(f == Approx(0.05 * static_cast<double>(i)));
    for (const double tilt : {2.0, 30.0}) {
      const double a1 = f * tilt * std::numbers::pi / 180;
      const double a2 = (1 - f) * tilt * std::numbers::pi / 180;
      const char* share = tilt == 2.0 ? "share_tilt_2" : "share_tilt_30";
      const char* rank = tilt == 2.0 ? "rank_tilt_2" : "rank_tilt_30";
      const char* vy = tilt == 2.0 ? "vy_after_tilt_2" : "vy_after_tilt_30";
      CAPTURE(tilt);
      CHECK(t[share][i] == Approx(std::sin(a2) / (std::sin(a1) + std::sin(a2))).margin(1e-9));
      CHECK(t[rank][i] == 2);
      CHECK(t[vy][i] == Approx((e - 1) * v));
    }
  }
  // The symmetric V gives the minimum-norm split of the flat supports, tilting only one support
  // gives a basic one (all on the other): the flat case alone cannot choose.
  const labtest::Table flat(output / "lever.csv");
  CHECK(t["share_tilt_2"][10] == Approx(flat["bead_min_norm_j1"][0] / (e * m * v)));
  const double basic = flat["bead_basic_j1"][0] / (e * m * v);
  CHECK((basic == Approx(t["share_tilt_2"][0]).margin(1e-12) ||
         basic == Approx(t["share_tilt_2"][20]).margin(1e-12)));
}

TEST_CASE("lab 4: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
