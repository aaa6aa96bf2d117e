// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 7: Three ways to resolve many contacts. The same scenes resolved by the paper's
// simultaneous system (multipoint::resolve), by impulses that only push (the complementarity
// problem, methods::resolve_complementarity) and by serial collisions, one contact at a time
// (methods::resolve_serial):
//   a Newton's cradle of three at (3, 0, 0) and two balls hitting one at (3, 0, -1.5);
//   a rod landing on two points while it spins, for spins from 0 to 8, at elasticities 2 and 1;
//   the number of serial collisions as the elasticity goes from 2 down to 1;
//   a light ball between a wall and a heavy ball, whose serial collisions count the digits of pi.
//
// Usage: lab07 [OUTPUT_DIR]   writes cradle.csv, two-hit-one.csv, rod.csv, collisions.csv and
// galperin.csv there.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <impulse/impulse.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "lab.hpp"

namespace {

namespace mp = impulse::multipoint;
namespace me = impulse::methods;
using Eigen::Vector2d;
using impulse::Elasticity;

// --- balls on a line: contact i joins ball i (bumper, normal +x) and ball i + 1 --------------

std::vector<mp::Body> balls(const std::vector<double>& velocities) {
  std::vector<mp::Body> bodies;
  for (const double v : velocities) {
    bodies.emplace_back(impulse::material_2d::from_velocity(1.0, {v, 0.0}));
  }
  return bodies;
}

std::vector<mp::Contact> row(std::size_t balls) {
  std::vector<mp::Contact> contacts;
  for (std::size_t i = 0; i + 1 < balls; ++i) {
    contacts.push_back({i, i + 1, Vector2d::UnitX(), Vector2d::Zero()});
  }
  return contacts;
}

std::vector<double> x_velocities(const std::vector<mp::Body>& bodies) {
  std::vector<double> v;
  for (const mp::Body& b : bodies) {
    v.push_back(mp::point_velocity(b, Vector2d::Zero()).x());
  }
  return v;
}

// The three answers for one scene.
struct Answers {
  mp::Resolution simultaneous;
  me::ComplementarityResolution complementarity;
  me::SerialResolution serial;
};

Answers three_ways(const std::vector<mp::Body>& bodies, const std::vector<mp::Contact>& contacts,
                   Elasticity e) {
  Answers a{mp::resolve(bodies, e, contacts), me::resolve_complementarity(bodies, e, contacts),
            me::resolve_serial(bodies, e, contacts)};
  if (a.simultaneous.solution.status != impulse::SolveStatus::success ||
      a.complementarity.solution.status != me::LcpStatus::solved ||
      a.serial.diagnostics.status != me::SerialStatus::finished) {
    throw std::runtime_error("a method did not finish");
  }
  return a;
}

void print(const char* what, const std::vector<double>& v) {
  std::printf("  %-34s", what);
  for (const double x : v) {
    std::printf(" %8.4f", x + 0.0);
  }
  std::printf("\n");
}

void line_of_balls(const std::filesystem::path& out, const char* name, const char* title,
                   const std::vector<double>& before) {
  const std::vector<mp::Body> bodies = balls(before);
  const std::vector<mp::Contact> contacts = row(before.size());
  const Answers a = three_ways(bodies, contacts, Elasticity::elastic());
  const auto simultaneous = x_velocities(a.simultaneous.after);
  const auto complementarity = x_velocities(a.complementarity.after);
  const auto serial = x_velocities(a.serial.after);
  lab::Csv csv(out / (std::string(name) + ".csv"),
               {"ball", "before", "simultaneous", "complementarity", "serial"});
  for (std::size_t i = 0; i < before.size(); ++i) {
    csv.row(
        {static_cast<double>(i + 1), before[i], simultaneous[i], complementarity[i], serial[i]});
  }
  std::printf("%s, velocities after at elasticity 2:\n", title);
  print("simultaneous (the paper)", simultaneous);
  print("complementarity (only push)", complementarity);
  std::string serial_label = "serial (" + std::to_string(a.serial.diagnostics.order.size()) +
                             " collisions, " + std::to_string(a.serial.diagnostics.passes) +
                             (a.serial.diagnostics.passes == 1 ? " pass)" : " passes)");
  print(serial_label.c_str(), serial);
}

// --- the rod: mass 1, length 2 (I = 1/3), on a static ground at x = -1 and x = +1 -------------

struct Rod {
  std::vector<mp::Body> bodies;
  std::vector<mp::Contact> contacts;
};

// Falling at 1 and spinning at omega, counter-clockwise: the right end (contact 1) rises when
// omega > 1.
Rod rod(double omega) {
  constexpr double inertia = 1.0 / 3;
  return {{mp::StaticBody{},
           impulse::rigid_2d::RigidBody{1, inertia, {0, 0}, {0, -1}, inertia * omega}},
          {{0, 1, Vector2d::UnitY(), Vector2d(-1, 0)}, {0, 1, Vector2d::UnitY(), Vector2d(1, 0)}}};
}

}  // namespace

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);
  std::printf("Lab 7: three ways to resolve many contacts (balls of mass 1)\n");
  line_of_balls(out, "cradle", "Newton's cradle, (3, 0, 0)", {3, 0, 0});
  line_of_balls(out, "two-hit-one", "Two balls hitting one, (3, 0, -1.5)", {3, 0, -1.5});

  // The rod, spun from 0 to 8: the impulse at the rising end and its approach speed after.
  {
    lab::Csv csv(
        out / "rod.csv",
        {"omega", "simultaneous_impulse_e2", "complementarity_impulse_e2", "serial_impulse_e2",
         "simultaneous_approach_e2", "complementarity_approach_e2", "serial_approach_e2",
         "serial_collisions_e2", "energy_before", "simultaneous_energy_e2",
         "complementarity_energy_e2", "serial_energy_e2", "simultaneous_impulse_e1",
         "complementarity_impulse_e1", "serial_impulse_e1", "simultaneous_approach_e1",
         "complementarity_approach_e1", "serial_approach_e1", "serial_collisions_e1"});
    for (int i = 0; i <= 80; ++i) {
      const double omega = 0.1 * i;
      const Rod r = rod(omega);
      const Answers e2 = three_ways(r.bodies, r.contacts, Elasticity::elastic());
      const Answers e1 = three_ways(r.bodies, r.contacts, Elasticity::inelastic());
      const auto rising = [&](const std::vector<mp::Body>& after) {
        return mp::approach(after, r.contacts)(1);
      };
      csv.row({omega, e2.simultaneous.solution.Fdt(1), e2.complementarity.solution.Fdt(1),
               e2.serial.Fdt(1), rising(e2.simultaneous.after), rising(e2.complementarity.after),
               rising(e2.serial.after), static_cast<double>(e2.serial.diagnostics.order.size()),
               mp::kinetic_energy(r.bodies), mp::kinetic_energy(e2.simultaneous.after),
               mp::kinetic_energy(e2.complementarity.after), mp::kinetic_energy(e2.serial.after),
               e1.simultaneous.solution.Fdt(1), e1.complementarity.solution.Fdt(1),
               e1.serial.Fdt(1), rising(e1.simultaneous.after), rising(e1.complementarity.after),
               rising(e1.serial.after), static_cast<double>(e1.serial.diagnostics.order.size())});
      if (i == 50) {
        std::printf("Rod spinning at 5, impulses at (falling end, rising end), elasticity 2:\n");
        print("simultaneous (the paper)",
              {e2.simultaneous.solution.Fdt(0), e2.simultaneous.solution.Fdt(1)});
        print("complementarity (only push)",
              {e2.complementarity.solution.Fdt(0), e2.complementarity.solution.Fdt(1)});
        print("serial", {e2.serial.Fdt(0), e2.serial.Fdt(1)});
      }
    }
  }

  // Serial collisions as the elasticity falls from 2 to 1: cradles of 3 and 5 at (1, 0, ...).
  {
    lab::Csv csv(out / "collisions.csv",
                 {"elasticity", "cradle_3", "cradle_5", "rod_omega_2", "cradle_3_passes"});
    for (int i = 0; i <= 100; ++i) {
      const Elasticity e(1.0 + 0.01 * i);
      const auto three = me::resolve_serial(balls({1, 0, 0}), e, row(3));
      const auto five = me::resolve_serial(balls({1, 0, 0, 0, 0}), e, row(5));
      const Rod r = rod(2);
      const auto spun = me::resolve_serial(r.bodies, e, r.contacts);
      for (const auto* s : {&three, &five, &spun}) {
        if (s->diagnostics.status != me::SerialStatus::finished) {
          throw std::runtime_error("serial collisions did not end");
        }
      }
      csv.row({e.value(), static_cast<double>(three.diagnostics.order.size()),
               static_cast<double>(five.diagnostics.order.size()),
               static_cast<double>(spun.diagnostics.order.size()),
               static_cast<double>(three.diagnostics.passes)});
    }
  }

  // A light ball (mass 1) at rest between a wall and a heavy ball of mass M arriving at 1.
  {
    lab::Csv csv(out / "galperin.csv", {"mass_ratio", "collisions"});
    std::printf("Light ball between a wall and a heavy ball, serial collisions:\n");
    for (const double M : {1.0, 100.0, 1e4, 1e6}) {
      const std::vector<mp::Body> bodies{mp::StaticBody{},
                                         impulse::material_2d::from_velocity(1, {0, 0}),
                                         impulse::material_2d::from_velocity(M, {-1, 0})};
      const std::vector<mp::Contact> contacts{{0, 1, Vector2d::UnitX(), Vector2d::Zero()},
                                              {1, 2, Vector2d::UnitX(), Vector2d::Zero()}};
      me::SerialOptions options;
      options.max_collisions = 100000;
      const auto s = me::resolve_serial(bodies, Elasticity::elastic(), contacts, options);
      csv.row({M, static_cast<double>(s.diagnostics.order.size())});
      std::printf("  M/m = %-8g %zu collisions\n", M, s.diagnostics.order.size());
    }
  }
  std::printf("wrote cradle.csv, two-hit-one.csv, rod.csv, collisions.csv, galperin.csv in %s\n",
              out.c_str());
  return 0;
}
