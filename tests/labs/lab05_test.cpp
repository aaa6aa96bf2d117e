// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 5, Newton's cradle: the three methods' answers, checked against hand calculations and the
// conservation laws.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// Balls of mass 1; ball 1 arrives at speed 1, so the momentum is 1 and the energy 1/2 throughout.
constexpr double momentum_before = 1.0;
constexpr double energy_before = 0.5;

std::vector<double> row(const labtest::Table& t, const std::string& prefix, std::size_t i) {
  return {t[prefix + "_v1"][i], t[prefix + "_v2"][i], t[prefix + "_v3"][i]};
}

double momentum(const std::vector<double>& v) {
  double p = 0.0;
  for (double x : v) {
    p += x;
  }
  return p;
}

double energy(const std::vector<double>& v) {
  double e = 0.0;
  for (double x : v) {
    e += 0.5 * x * x;
  }
  return e;
}

void check_near(const std::vector<double>& actual, const std::vector<double>& expected,
                double margin) {
  REQUIRE(actual.size() == expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    CAPTURE(i);
    CHECK(actual[i] == Approx(expected[i]).margin(margin));
  }
}

// The largest difference between two answers.
double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max(d, std::abs(a[i] - b[i]));
  }
  return d;
}

// Serial collisions of equal masses at elasticity 2 exchange velocities pair by pair: the whole
// speed is handed down the row to the last ball.
const std::vector<double> serial_3{0.0, 0.0, 1.0};
const std::vector<double> serial_5{0.0, 0.0, 0.0, 0.0, 1.0};

// Simultaneous, 3 balls, by hand: the contacts' rows of (4.5) are A = [[2, -1], [-1, 2]] and
// B = 2 (1, 0) (each ball brings 1/m on its diagonal, -1/m where its two contacts' normals are
// opposite, and 2 v.n / m). So Fdt = A^-1 B = (4/3, 2/3), and the velocities after are
// 1 - 4/3 = -1/3, 4/3 - 2/3 = 2/3 and 2/3.
const std::vector<double> simultaneous_3{-1.0 / 3, 2.0 / 3, 2.0 / 3};
// 5 balls: A is tridiagonal (2 on the diagonal, -1 beside it), whose inverse's first column is
// (N - i) / N for i = 1..4, N = 5; so Fdt = 2 (4, 3, 2, 1) / 5, and the velocities after are
// 1 - 8/5 = -3/5 and 2/5 for each of the other four. As if ball 1 bounced elastically off one body
// of mass 4: (1 - 4) / (1 + 4) = -3/5 and 2 / (1 + 4) = 2/5.
const std::vector<double> simultaneous_5{-3.0 / 5, 2.0 / 5, 2.0 / 5, 2.0 / 5, 2.0 / 5};

std::vector<double> column(const labtest::Table& t, const std::string& name) {
  return t[name];
}

}  // namespace

TEST_CASE(
    "lab 5: the simultaneous answer is (-1/3, 2/3, 2/3) for 3 balls and (-3/5, 2/5, ...) for 5") {
  check_near(column(labtest::Table(output / "cradle-3.csv"), "simultaneous"), simultaneous_3,
             1e-12);
  check_near(column(labtest::Table(output / "cradle-5.csv"), "simultaneous"), simultaneous_5,
             1e-12);
  // Both keep the momentum and the energy, and yet they are not what a cradle does.
  for (const auto& v : {simultaneous_3, simultaneous_5}) {
    CHECK(momentum(v) == Approx(momentum_before));
    CHECK(energy(v) == Approx(energy_before));
  }
}

TEST_CASE("lab 5: serial collisions hand the whole speed to the last ball") {
  check_near(column(labtest::Table(output / "cradle-3.csv"), "serial"), serial_3, 1e-12);
  check_near(column(labtest::Table(output / "cradle-5.csv"), "serial"), serial_5, 1e-12);
}

TEST_CASE("lab 5: the spring chains keep momentum and energy") {
  // The springs only store energy while compressed and give it all back; at the end none is
  // compressed. So every continuous answer must keep both (up to the integration's error).
  for (const char* file : {"cradle-3.csv", "cradle-5.csv"}) {
    const labtest::Table t(output / file);
    for (const char* method : {"linear_touching", "hertz_touching", "linear_gapped"}) {
      CAPTURE(file, method);
      const std::vector<double> v = t[method];
      CHECK(momentum(v) == Approx(momentum_before).margin(1e-9));
      CHECK(energy(v) == Approx(energy_before).margin(1e-9));
    }
  }
  const labtest::Table s(output / "stiffness.csv");
  const labtest::Table r(output / "stiffness-ratio.csv");
  REQUIRE(s.rows() == 17);
  REQUIRE(r.rows() == 25);
  for (std::size_t i = 0; i < s.rows(); ++i) {
    for (const char* method :
         {"linear_touching", "hertz_touching", "linear_gapped", "hertz_gapped"}) {
      CAPTURE(s["stiffness"][i], method);
      CHECK(momentum(row(s, method, i)) == Approx(momentum_before).margin(1e-9));
      CHECK(energy(row(s, method, i)) == Approx(energy_before).margin(1e-9));
    }
  }
  for (std::size_t i = 0; i < r.rows(); ++i) {
    const std::vector<double> v{r["v1"][i], r["v2"][i], r["v3"][i]};
    CAPTURE(r["ratio"][i]);
    CHECK(momentum(v) == Approx(momentum_before).margin(1e-9));
    CHECK(energy(v) == Approx(energy_before).margin(1e-9));
  }
}

TEST_CASE("lab 5: touching balls give the same answer at every stiffness") {
  // Dimensional analysis: with force k d^a, the only length is (m v^2 / k)^(1/(a+1)) and the only
  // time that length over v. Changing k rescales both, so the velocities after, in units of v, do
  // not depend on k: stiffer springs do not bring touching balls closer to either answer.
  const labtest::Table s(output / "stiffness.csv");
  for (const char* method : {"linear_touching", "hertz_touching"}) {
    const std::vector<double> first = row(s, method, 0);
    for (std::size_t i = 1; i < s.rows(); ++i) {
      CAPTURE(method, s["stiffness"][i]);
      check_near(row(s, method, i), first, 1e-8);
    }
    // And that one answer is neither of the two impulse methods (the lab's measured finding).
    CAPTURE(method);
    CHECK(distance(first, simultaneous_3) > 0.25);
    CHECK(distance(first, serial_3) > 0.005);
  }
}

TEST_CASE("lab 5: with small gaps, stiff springs give the serial answer") {
  // When a contact presses in much less than the gap, ball 2 has left ball 1 before it reaches
  // ball 3: two separate two-ball collisions, each elastic between equal masses, which exchange
  // the velocities exactly. The sweep's stiffest springs press in 2% (linear) and 20% (Hertz)
  // of the gap.
  const labtest::Table s(output / "stiffness.csv");
  const std::size_t stiffest = s.rows() - 1;
  REQUIRE(s["linear_depth_over_gap"][stiffest] < 0.05);
  REQUIRE(s["hertz_depth_over_gap"][stiffest] < 0.25);
  check_near(row(s, "linear_gapped", stiffest), serial_3, 1e-6);
  check_near(row(s, "hertz_gapped", stiffest), serial_3, 1e-6);
  // With the softest springs the same gaps hardly matter: the answer is near the touching one.
  CHECK(distance(row(s, "linear_gapped", 0), row(s, "linear_touching", 0)) < 0.01);
}

TEST_CASE("lab 5: the stiffness ratio moves the chain from the serial to the simultaneous answer") {
  // Limits by hand. A very soft second contact: ball 1 and ball 2 finish their (fast) collision
  // before the second spring has pressed in at all, then ball 2 hands its speed to ball 3 slowly:
  // serial. A very stiff second contact: balls 2 and 3 move as one body of mass 2 while the soft
  // first spring pushes, which is the simultaneous answer (ball 1 bounces off mass 2 at -1/3 and
  // the pair leaves at 2/3). At a ratio of 1000 either way the answers are within 1% of the limits.
  const labtest::Table r(output / "stiffness-ratio.csv");
  const auto velocities = [&](std::size_t i) {
    return std::vector<double>{r["v1"][i], r["v2"][i], r["v3"][i]};
  };
  CHECK(r["ratio"][0] == Approx(1e-3));
  CHECK(r["ratio"][r.rows() - 1] == Approx(1e3));
  check_near(velocities(0), serial_3, 0.01);
  check_near(velocities(r.rows() - 1), simultaneous_3, 0.01);
}

TEST_CASE("lab 5: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
