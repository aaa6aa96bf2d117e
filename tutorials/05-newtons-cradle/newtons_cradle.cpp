// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 5: Newton's cradle (section 4, many bodies). A row of equal balls, the first moving into the
// others, collided three ways:
//   simultaneous  the paper's linear system over all contacts at once (multipoint::resolve);
//   serial        one contact at a time, the fastest-closing first, with the single-contact formula
//                 (impulse::methods::resolve_serial, which lab 7 compares with the other methods);
//   continuous    the balls joined by springs that only push (linear or Hertz), integrated in time
//                 with GSL's ODE solver until no pair is in contact or closing.
//
// Usage: lab05 [OUTPUT_DIR]   writes cradle-3.csv, cradle-5.csv, stiffness.csv and
// stiffness-ratio.csv there.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <impulse/impulse.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lab.hpp"

namespace {

namespace mp = impulse::multipoint;
using Velocities = std::vector<double>;

// Every ball has mass 1 and the first one arrives at speed 1: the other numbers are in these units.
constexpr double mass = 1.0;
constexpr double speed = 1.0;

Velocities initial(std::size_t balls) {
  Velocities v(balls, 0.0);
  v[0] = speed;
  return v;
}

// --- simultaneous: the paper's A Fdt = B over every contact (section 4.5) -----------------------

Velocities simultaneous(std::size_t balls, impulse::Elasticity e) {
  std::vector<mp::Body> bodies;
  for (double v : initial(balls)) {
    bodies.emplace_back(impulse::material_2d::from_velocity(mass, {v, 0.0}));
  }
  std::vector<mp::Contact> contacts;
  for (std::size_t i = 0; i + 1 < balls; ++i) {
    // Ball i is the bumper; its outward normal points at ball i + 1.
    contacts.push_back({i, i + 1, Eigen::Vector2d::UnitX(), Eigen::Vector2d::Zero()});
  }
  const mp::Resolution r = mp::resolve(bodies, e, contacts);
  if (r.solution.status != impulse::SolveStatus::success) {
    throw std::runtime_error("the cradle's system could not be solved");
  }
  Velocities after;
  for (const mp::Body& b : r.after) {
    after.push_back(
        impulse::material_2d::velocity(std::get<impulse::material_2d::PointMass>(b)).x());
  }
  return after;
}

// --- serial: pairwise collisions, one at a time (impulse::methods::resolve_serial, lab 7) -------

struct Serial {
  Velocities v;
  int collisions = 0;
};

// Resolves the contact that closes fastest with the single-contact formula, then looks again,
// until no contact closes. Each step keeps momentum; at elasticity 2 each also keeps the energy.
Serial serial(std::size_t balls, impulse::Elasticity e) {
  std::vector<mp::Body> bodies;
  std::vector<mp::Contact> contacts;
  for (double v : initial(balls)) {
    bodies.emplace_back(impulse::material_2d::from_velocity(mass, {v, 0.0}));
  }
  for (std::size_t i = 0; i + 1 < balls; ++i) {
    contacts.push_back({i, i + 1, Eigen::Vector2d::UnitX(), Eigen::Vector2d::Zero()});
  }
  const impulse::methods::SerialResolution r =
      impulse::methods::resolve_serial(bodies, e, contacts);
  if (r.diagnostics.status != impulse::methods::SerialStatus::finished) {
    throw std::runtime_error("serial collisions did not end");
  }
  Serial s;
  for (const mp::Body& b : r.after) {
    s.v.push_back(impulse::material_2d::velocity(std::get<impulse::material_2d::PointMass>(b)).x());
  }
  s.collisions = static_cast<int>(r.diagnostics.order.size());
  return s;
}

// --- continuous: springs between neighbours, integrated in time ---------------------------------

// The contact force between neighbours i and i + 1 is k_i * overlap^exponent while they overlap
// and 0 otherwise: exponent 1 is a linear spring, 1.5 Hertz's law for elastic spheres.
struct Chain {
  std::vector<double> stiffness;  // one per contact
  double exponent = 1.0;
  double gap = 0.0;  // distance between neighbouring surfaces at the start
};

int chain_rhs(double /*t*/, const double y[], double dydt[], void* params) {
  const Chain& chain = *static_cast<const Chain*>(params);
  const std::size_t n = chain.stiffness.size() + 1;
  // y = (s_0 .. s_{n-2}, v_0 .. v_{n-1}): s_i is the gap between balls i and i + 1 (negative:
  // they overlap), v_i the velocity of ball i.
  for (std::size_t i = 0; i < n; ++i) {
    dydt[n - 1 + i] = 0.0;
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    dydt[i] = y[n + i] - y[n - 1 + i];  // ds_i/dt = v_{i+1} - v_i
    const double overlap = std::max(0.0, -y[i]);
    const double force = chain.stiffness[i] * std::pow(overlap, chain.exponent);
    dydt[n - 1 + i] -= force / mass;
    dydt[n + i] += force / mass;
  }
  return GSL_SUCCESS;
}

// How deep a two-ball contact of stiffness k presses in at the closing speed `speed`: its energy
// (mass / 2) speed^2 / 2 is stored as k d^(exponent + 1) / (exponent + 1).
double depth(double k, double exponent) {
  const double reduced_mass = mass / 2;
  return std::pow((exponent + 1) * reduced_mass * speed * speed / (2 * k), 1 / (exponent + 1));
}

// The velocities once no pair touches or closes any more.
Velocities continuous(std::size_t balls, const Chain& chain) {
  const std::size_t dimension = 2 * balls - 1;
  std::vector<double> y(dimension, chain.gap);
  const Velocities v0 = initial(balls);
  std::copy(v0.begin(), v0.end(), y.begin() + static_cast<std::ptrdiff_t>(balls - 1));

  // Steps of about a tenth of the shortest contact's time, so that no contact is stepped over.
  const double stiffest = *std::max_element(chain.stiffness.begin(), chain.stiffness.end());
  const double step = 0.2 * depth(stiffest, chain.exponent) / speed;
  gsl_odeiv2_system system{chain_rhs, nullptr, dimension, const_cast<Chain*>(&chain)};
  const std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
      gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, step / 10, 1e-12, 1e-12),
      &gsl_odeiv2_driver_free);
  if (!driver) {
    throw std::runtime_error("cannot allocate the ODE driver");
  }

  double t = 0.0;
  constexpr int max_steps = 1000000;
  for (int s = 0; s < max_steps; ++s) {
    const int status = gsl_odeiv2_driver_apply(driver.get(), &t, t + step, y.data());
    if (status != GSL_SUCCESS) {
      throw std::runtime_error(std::string("the ODE solver failed: ") + gsl_strerror(status));
    }
    bool apart = true;
    for (std::size_t i = 0; i + 1 < balls; ++i) {
      const bool touching = y[i] < 0.0;
      const bool closing = y[balls - 1 + i] - y[balls + i] > 1e-9 * speed;
      apart = apart && !touching && !closing;
    }
    if (apart) {
      return Velocities(y.begin() + static_cast<std::ptrdiff_t>(balls - 1), y.end());
    }
  }
  throw std::runtime_error("the balls were still in contact after a million steps");
}

Chain uniform(std::size_t balls, double k, double exponent, double gap) {
  return Chain{std::vector<double>(balls - 1, k), exponent, gap};
}

constexpr double linear = 1.0;
constexpr double hertz = 1.5;
constexpr double small_gap =
    1e-3;  // a thousandth of the distance the first ball moves in unit time

void print(const char* what, const Velocities& v) {
  std::printf("  %-44s", what);
  for (double x : v) {
    std::printf(" %9.5f", x);
  }
  std::printf("\n");
}

// One row per ball: its velocity after, by each method.
void cradle(const std::filesystem::path& out, std::size_t balls) {
  // The impulse methods' elasticity (the springs have none: they give back all they store).
  const impulse::Elasticity elasticity = impulse::Elasticity::elastic();
  const Velocities at_once = simultaneous(balls, elasticity);
  const Serial one_by_one = serial(balls, elasticity);
  // Touching balls: the answer does not depend on the stiffness (see the worksheet), so k = 1.
  const Velocities linear_touching = continuous(balls, uniform(balls, 1.0, linear, 0.0));
  const Velocities hertz_touching = continuous(balls, uniform(balls, 1.0, hertz, 0.0));
  const Velocities linear_gapped = continuous(balls, uniform(balls, 1e8, linear, small_gap));

  const std::string name = "cradle-" + std::to_string(balls) + ".csv";
  lab::Csv csv(out / name, {"ball", "before", "simultaneous", "serial", "linear_touching",
                            "hertz_touching", "linear_gapped"});
  const Velocities before = initial(balls);
  for (std::size_t i = 0; i < balls; ++i) {
    csv.row({static_cast<double>(i + 1), before[i], at_once[i], one_by_one.v[i], linear_touching[i],
             hertz_touching[i], linear_gapped[i]});
  }
  std::printf("%zu balls, velocities after (impulse methods at elasticity %g):\n", balls,
              elasticity.value());
  print("simultaneous (multipoint::resolve)", at_once);
  print(("serial (" + std::to_string(one_by_one.collisions) + " collisions)").c_str(),
        one_by_one.v);
  print("springs, linear, touching", linear_touching);
  print("springs, Hertz, touching", hertz_touching);
  print("springs, linear, k = 1e8, gaps 1e-3", linear_gapped);
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();
  const auto out = lab::output_dir(argc, argv);
  std::printf("Lab 5: Newton's cradle, balls of mass 1, the first arriving at speed 1\n");
  cradle(out, 3);
  cradle(out, 5);

  // The stiffness sweep: 3 balls, springs from soft to stiff, touching or with small gaps.
  {
    lab::Csv csv(out / "stiffness.csv",
                 {"stiffness", "linear_touching_v1", "linear_touching_v2", "linear_touching_v3",
                  "hertz_touching_v1", "hertz_touching_v2", "hertz_touching_v3", "linear_gapped_v1",
                  "linear_gapped_v2", "linear_gapped_v3", "hertz_gapped_v1", "hertz_gapped_v2",
                  "hertz_gapped_v3", "linear_depth_over_gap", "hertz_depth_over_gap"});
    for (int i = 0; i <= 16; ++i) {
      const double k = std::pow(10.0, 1.0 + 0.5 * i);
      const Velocities lt = continuous(3, uniform(3, k, linear, 0.0));
      const Velocities ht = continuous(3, uniform(3, k, hertz, 0.0));
      const Velocities lg = continuous(3, uniform(3, k, linear, small_gap));
      const Velocities hg = continuous(3, uniform(3, k, hertz, small_gap));
      csv.row({k, lt[0], lt[1], lt[2], ht[0], ht[1], ht[2], lg[0], lg[1], lg[2], hg[0], hg[1],
               hg[2], depth(k, linear) / small_gap, depth(k, hertz) / small_gap});
    }
  }

  // The stiffness ratio: 3 touching balls, linear springs, the second contact k2 = ratio * k1.
  {
    lab::Csv csv(out / "stiffness-ratio.csv", {"ratio", "v1", "v2", "v3"});
    for (int i = 0; i <= 24; ++i) {
      const double ratio = std::pow(10.0, -3.0 + 0.25 * i);
      const Velocities r = continuous(3, Chain{{1.0, ratio}, linear, 0.0});
      csv.row({ratio, r[0], r[1], r[2]});
    }
  }
  std::printf("wrote cradle-3.csv, cradle-5.csv, stiffness.csv, stiffness-ratio.csv in %s\n",
              out.c_str());
  return 0;
}
