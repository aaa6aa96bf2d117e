// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 9, a rough floor: the lab's numbers (what it printed and the CSV files it wrote) against
// the rod's collision worked by hand, phase by phase, for every coefficient of friction of the
// sweep, and against the law that the energetic restitution never gains energy.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "lab_files.hpp"

namespace {

const std::filesystem::path output = LAB_OUTPUT_DIR;

// The worksheet's rod: m = 1, L = 1, I = 1/12, at 45 degrees, lower end at the origin, centre at
// (h, h), h = sqrt(2)/4, centre velocity (vx, -1), no spin; elasticity e = 1.9.
//
// By hand (the worksheet's derivation): the rod is the bumper with outward normal (0, -1), so
// the tangent is +x and the impulse on the rod is (P_t, P_n). A unit impulse J at the arm
// r = (-h, -h) moves the end by J/m + q det(r, J)/I with q = [-r_y, r_x] = (h, -h), i.e. by
// K J with K = [[2.5, -1.5], [-1.5, 2.5]] (12 h^2 = 1.5). In the frame (normal, tangent):
// W_nn = 2.5, W_nt = -1.5, W_tt = 2.5, and u0 = (separation, slip) = (-1, vx).
//
// Sliding along +x (dP_t = -mu dP_n): u_n rises at a1 = 2.5 + 1.5 mu, u_t falls at
// 1.5 + 2.5 mu, so the slip stops at P_s = vx / (1.5 + 2.5 mu). Then the contact sticks if
// |W_tn| / W_tt = 0.6 <= mu (dP_t = 0.6 dP_n, u_n rises at 2.5 - 1.5 * 0.6 = 1.6), else it slides
// back (dP_t = +mu dP_n, u_n rises at a2 = 2.5 - 1.5 mu).
constexpr double e = 1.9;
constexpr double energy_before = 0.5 * (0.49 + 1.0);  // |v|^2 / 2 = 0.745, no spin

struct Impulse {
  double normal, tangential;
};

// After the impulse: v' = (vx + P_t, -1 + P_n) and L' = det(r, (P_t, P_n)) = -h (P_n - P_t), so
// E' = |v'|^2 / 2 + L'^2 / (2 I) = |v'|^2 / 2 + (3/4)(P_n - P_t)^2.
double energy_after(Impulse p, double vx = 0.7) {
  const double x = vx + p.tangential;
  const double y = -1.0 + p.normal;
  const double d = p.normal - p.tangential;
  return 0.5 * (x * x + y * y) + 0.75 * d * d;
}

double slip_stop(double mu, double vx = 0.7) {
  return vx / (1.5 + 2.5 * mu);
}

// The slope of u_n after the slip stopped, and the tangential impulse at P_n > P_s.
double slope_after_stop(double mu) {
  return mu >= 0.6 ? 1.6 : 2.5 - 1.5 * mu;
}
double tangential_at(double mu, double P) {
  const double Ps = slip_stop(mu);
  return mu >= 0.6 ? -mu * Ps + 0.6 * (P - Ps) : mu * (P - 2 * Ps);
}

// Newton: restitution ends where u_n = e - 1 = 0.9. The slip always stops first:
// P_s <= 0.7/1.5 = 0.467 while every end below is beyond it.
// Sticking (mu >= 0.6), the end has u = (0.9, 0), so P = W^-1 (u - u0) =
// (1/4) [[2.5, 1.5], [1.5, 2.5]] (1.9, -0.7) = (0.925, 0.275), whatever mu.
// Sliding back (mu < 0.6): P_n = P_s + (1.9 - a1 P_s) / a2 = (1.9 - 3 mu P_s) / (2.5 - 1.5 mu),
// and P_t = -mu P_s + mu (P_n - P_s) = mu (P_n - 2 P_s).
Impulse newton(double mu) {
  if (mu >= 0.6) {
    return {0.925, 0.275};
  }
  const double Pn = (1.9 - 3 * mu * slip_stop(mu)) / (2.5 - 1.5 * mu);
  return {Pn, tangential_at(mu, Pn)};
}

// Compression ends where u_n = 0: in the first slide if 1 / a1 <= P_s, i.e. mu <= 5/29
// (0.7 (2.5 + 1.5 mu) <= 1.5 + 2.5 mu), else after the stop, at P_s + (-u_n(P_s)) / slope.
double compression(double mu) {
  const double a1 = 2.5 + 1.5 * mu;
  const double Ps = slip_stop(mu);
  return a1 * Ps >= 1.0 ? 1.0 / a1 : Ps + (1.0 - a1 * Ps) / slope_after_stop(mu);
}

// Poisson: P_n = e P_c, which is beyond P_s (1.9 / a1 > P_s for every mu).
Impulse poisson(double mu) {
  const double Pn = e * compression(mu);
  return {Pn, tangential_at(mu, Pn)};
}

// Energetic: restitution's work (the integral of u_n dP_n from P_c on) is (e - 1)^2 = 0.81 times
// compression's, in magnitude. u_n is piecewise linear: a1 up to P_s, then the slope after the
// stop; each piece's work is an area of a trapezium. Within a piece starting at speed u0 >= 0 with
// slope a, a work w is done after x with u0 x + a x^2 / 2 = w.
double advance(double u0, double a, double w) {
  return (-u0 + std::sqrt(u0 * u0 + 2 * a * w)) / a;
}
Impulse energetic(double mu) {
  const double a1 = 2.5 + 1.5 * mu;
  const double a = slope_after_stop(mu);
  const double Ps = slip_stop(mu);
  const double Pc = compression(mu);
  const double at_stop = -1.0 + a1 * Ps;  // u_n where the slip stops
  double Pn = 0.0;
  if (Pc <= Ps) {  // compression in the first slide: work -Pc / 2
    const double target = 0.81 * 0.5 * Pc;
    const double first = 0.5 * at_stop * (Ps - Pc);  // restitution's work up to the stop
    Pn = first >= target ? Pc + advance(0.0, a1, target) : Ps + advance(at_stop, a, target - first);
  } else {  // compression: a trapezium to the stop, a triangle after it
    const double work = 0.5 * (-1.0 + at_stop) * Ps + 0.5 * at_stop * (Pc - Ps);
    Pn = Pc + advance(0.0, a, 0.81 * -work);
  }
  return {Pn, Pn <= Ps ? -mu * Pn : tangential_at(mu, Pn)};
}

// Where Newton's energy after first exceeds the energy before, by bisection on the closed form
// above (it rises from 0.707 at mu = 0 to 0.795 at 0.6). Over a common denominator,
// E(mu) - 0.745 has the numerator 25175 mu^4 - 2650 mu^3 + 3712 mu^2 - 2214 mu - 855, whose
// root in (0, 0.6) is 0.481786971960 (worked with computer algebra from the same closed form).
double newton_gain_starts() {
  double lo = 0.0;
  double hi = 0.6;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (energy_after(newton(mid)) > energy_before ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double number(const std::smatch& m, std::size_t i) {
  return std::stod(m[i].str());
}

}  // namespace

TEST_CASE("lab 9: the rod at mu = 0.8, as the lab prints it and writes it to laws.csv") {
  // The closed forms above at mu = 0.8: P_s = 0.7 / 3.5 = 0.2, u_n(P_s) = -1 + 3.7 * 0.2 = -0.26,
  // P_c = 0.2 + 0.26 / 1.6 = 0.3625. Newton (0.925, 0.275), energy 0.795 (a gain of 0.05);
  // Poisson P_n = 1.9 * 0.3625 = 0.68875, P_t = -0.16 + 0.6 * 0.48875 = 0.13325, energy
  // 0.62702625; energetic: 0.8 x^2 = 0.81 * 0.147125, P_n = 0.3625 + x = 0.7484586280,
  // P_t = 0.1690751768, energy 0.66104625.
  const Impulse expected[] = {{0.925, 0.275}, {0.68875, 0.13325}, energetic(0.8)};
  CHECK(expected[2].normal == Approx(0.3625 + std::sqrt(0.1489640625)).epsilon(1e-14));
  const double energies[] = {0.795, 0.62702625, 0.66104625};
  for (int k = 0; k < 3; ++k) {
    CHECK(energy_after(expected[k]) == Approx(energies[k]).epsilon(1e-14));
  }

  const labtest::Table t(output / "laws.csv");
  REQUIRE(t.rows() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CAPTURE(k);
    CHECK(t["mu"][k] == 0.8);
    CHECK(t["normal"][k] == Approx(expected[k].normal).epsilon(1e-13));
    CHECK(t["tangential"][k] == Approx(expected[k].tangential).epsilon(1e-13));
    CHECK(t["compression"][k] == Approx(0.3625).epsilon(1e-13));
    CHECK(t["energy_before"][k] == Approx(energy_before).epsilon(1e-14));
    CHECK(t["energy_after"][k] == Approx(energies[k]).epsilon(1e-13));
    CHECK(t["outcome"][k] == 1.0);  // stick
  }

  // What the lab printed, to its 10 significant digits.
  const std::string summary = labtest::read_text(output / "summary.txt");
  const char* const names[] = {"newton", "poisson", "energetic"};
  for (int k = 0; k < 3; ++k) {
    CAPTURE(names[k]);
    const std::regex line(
        std::string("\\n  ") + names[k] +
        " +(\\S+) +(\\S+) +(\\S+) +(\\S+)  slip until (\\S+), stick until (\\S+)\\n");
    std::smatch m;
    REQUIRE(std::regex_search(summary, m, line));
    CHECK(number(m, 1) == Approx(expected[k].normal).epsilon(1e-9));
    CHECK(number(m, 2) == Approx(expected[k].tangential).epsilon(1e-9));
    CHECK(number(m, 3) == Approx(energies[k]).epsilon(1e-9));
    CHECK(number(m, 4) == Approx(energies[k] - energy_before).epsilon(1e-9));
    CHECK(number(m, 5) == Approx(0.2).epsilon(1e-9));
    CHECK(number(m, 6) == Approx(expected[k].normal).epsilon(1e-9));
  }
  CHECK(summary.find("kinetic energy before: 0.745\n") != std::string::npos);
  CHECK(summary.find("W = [[2.5, -1.5], [-1.5, 2.5]], u0 = (-1, 0.7)\n") != std::string::npos);
  CHECK(summary.find("compression ended at P_n = 0.3625\n") != std::string::npos);

  std::smatch m;
  REQUIRE(std::regex_search(summary, m, std::regex("first gains energy at mu = (\\S+) ")));
  CHECK(number(m, 1) == Approx(newton_gain_starts()).epsilon(1e-9));
  CHECK(newton_gain_starts() == Approx(0.481786971960).epsilon(1e-11));
}

TEST_CASE("lab 9: the sweep over mu against the rod worked by hand, phase by phase") {
  const labtest::Table t(output / "rough-floor.csv");
  REQUIRE(t.rows() == 301);  // 0 to 1.5 in steps of 0.005
  int newton_gains = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double mu = t["mu"][i];
    CAPTURE(mu);
    CHECK(mu == Approx(0.005 * static_cast<double>(i)).margin(1e-15));
    CHECK(t["energy_before"][i] == Approx(energy_before).epsilon(1e-14));
    const Impulse n = newton(mu);
    const Impulse p = poisson(mu);
    const Impulse g = energetic(mu);
    CHECK(t["normal_newton"][i] == Approx(n.normal).margin(1e-12));
    CHECK(t["tangential_newton"][i] == Approx(n.tangential).margin(1e-12));
    CHECK(t["energy_newton"][i] == Approx(energy_after(n)).margin(1e-12));
    CHECK(t["normal_poisson"][i] == Approx(p.normal).margin(1e-12));
    CHECK(t["tangential_poisson"][i] == Approx(p.tangential).margin(1e-12));
    CHECK(t["energy_poisson"][i] == Approx(energy_after(p)).margin(1e-12));
    CHECK(t["normal_energetic"][i] == Approx(g.normal).margin(1e-12));
    CHECK(t["tangential_energetic"][i] == Approx(g.tangential).margin(1e-12));
    CHECK(t["energy_energetic"][i] == Approx(energy_after(g)).margin(1e-12));
    // Coulomb's bound, and the law the energetic restitution is built on: it never gains energy.
    for (const char* law : {"newton", "poisson", "energetic"}) {
      CAPTURE(law);
      const std::string s = law;
      CHECK(std::abs(t["tangential_" + s][i]) <= mu * t["normal_" + s][i] + 1e-15);
    }
    CHECK(t["energy_energetic"][i] <= energy_before);
    // Newton's law ends sticking from mu = 0.6 (the stick ratio) on, sliding back below it.
    if (std::abs(mu - 0.6) > 1e-9) {
      CHECK(t["outcome_newton"][i] == (mu > 0.6 ? 1.0 : 2.0));
    }
    newton_gains += t["energy_newton"][i] > energy_before ? 1 : 0;
  }
  // Without friction every law gives the paper's Fdt = B / A = 1.9 / 2.5 = 0.76.
  CHECK(t["normal_newton"][0] == Approx(0.76).epsilon(1e-14));
  CHECK(t["normal_poisson"][0] == Approx(0.76).epsilon(1e-14));
  CHECK(t["normal_energetic"][0] == Approx(0.76).epsilon(1e-14));
  // The paradox: Newton's law gains energy from mu = 0.4818 on, i.e. at the 204 points
  // mu = 0.485, 0.490, ..., 1.5 of the sweep.
  CHECK(newton_gains == 204);
}

TEST_CASE("lab 9: Routh's diagrams, corner by corner") {
  // Case 1, mu = 0.8: the corners at the start, where the slip stops (0.2, -0.16, u = (-0.26, 0))
  // and at Newton's end (0.925, 0.275, u = (0.9, 0)).
  // Case 2, mu = 0.3: the slip stops at 0.7 / 2.25 = 14/45 with u_n = -1 + 2.95 * 14/45 =
  // -37/450, slides back at du_n = 2.05, du_t = -0.75 per unit P_n; Newton ends at
  // 14/45 + (0.9 + 37/450) / 2.05 = 162/205 with P_t = 0.3 (162/205 - 28/45) = 31/615 and
  // u_t = -0.75 (162/205 - 14/45) = -221/615. Compression ends at 14/45 + (37/450) / 2.05 = 72/205.
  // Case 3, mu = 0.3 and vx = 2: the slip would stop at 2 / 2.25 = 0.889, after every end: one
  // slide, du_n = 2.95, compression at 1 / 2.95, and every law at 1.9 / 2.95 (one linear phase:
  // Newton's end is e times the compression, Poisson's too, and the energetic law's, as its
  // works are then triangles of the same slope). P_t = -0.3 P_n, u_t = 2 - 2.25 P_n.
  struct Corner {
    double normal, tangential, separation, slip;
  };
  const double P3 = 1.9 / 2.95;
  const std::vector<std::vector<Corner>> corners = {
      {{0, 0, -1, 0.7}, {0.2, -0.16, -0.26, 0}, {0.925, 0.275, 0.9, 0}},
      {{0, 0, -1, 0.7},
       {14.0 / 45, -0.3 * 14 / 45, -37.0 / 450, 0},
       {162.0 / 205, 31.0 / 615, 0.9, -221.0 / 615}},
      {{0, 0, -1, 2}, {P3, -0.3 * P3, 0.9, 2 - 2.25 * P3}}};
  const double compressions[] = {0.3625, 72.0 / 205, 1 / 2.95};
  for (std::size_t c = 0; c < 3; ++c) {
    CAPTURE(c + 1);
    const std::string name = "routh-" + std::to_string(c + 1);
    const labtest::Table t(output / (name + ".csv"));
    REQUIRE(t.rows() == corners[c].size());
    for (std::size_t i = 0; i < t.rows(); ++i) {
      CAPTURE(i);
      CHECK(t["normal"][i] == Approx(corners[c][i].normal).margin(1e-13));
      CHECK(t["tangential"][i] == Approx(corners[c][i].tangential).margin(1e-13));
      CHECK(t["separation"][i] == Approx(corners[c][i].separation).margin(1e-13));
      CHECK(t["slip"][i] == Approx(corners[c][i].slip).margin(1e-13));
    }
    const labtest::Table ends(output / (name + "-ends.csv"));
    REQUIRE(ends.rows() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(ends["compression"][k] == Approx(compressions[c]).margin(1e-13));
    }
    // Newton's end is the last corner; its separation is 0.9 times the approach 1.
    CHECK(ends["normal"][0] == Approx(corners[c].back().normal).margin(1e-13));
    CHECK(ends["separation"][0] == Approx(0.9).margin(1e-13));
  }
  // The other laws' ends, cases 1 and 2, from the closed forms; case 3, all at P3.
  const labtest::Table ends1(output / "routh-1-ends.csv");
  CHECK(ends1["normal"][1] == Approx(poisson(0.8).normal).margin(1e-13));
  CHECK(ends1["normal"][2] == Approx(energetic(0.8).normal).margin(1e-13));
  const labtest::Table ends2(output / "routh-2-ends.csv");
  CHECK(ends2["normal"][1] == Approx(poisson(0.3).normal).margin(1e-13));
  CHECK(ends2["normal"][1] == Approx(1.9 * 72 / 205).margin(1e-13));
  CHECK(ends2["normal"][2] == Approx(energetic(0.3).normal).margin(1e-13));
  CHECK(ends2["energy"][0] == Approx(energy_after(newton(0.3))).margin(1e-13));
  const labtest::Table ends3(output / "routh-3-ends.csv");
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(ends3["normal"][k] == Approx(P3).margin(1e-13));
    CHECK(ends3["energy"][k] == Approx(energy_after({P3, -0.3 * P3}, 2.0)).margin(1e-13));
  }
}

TEST_CASE("lab 9: the plots are drawn and the worksheet shows them") {
  labtest::check_plots(output, LAB_SOURCE_DIR, LAB_PLOTS);
}
