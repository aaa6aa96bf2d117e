// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 3: spin after impact (section 3). A uniform rod falls without spinning and lands on one end,
// tilted by an angle from 0 (flat) to 90 degrees (upright). The impulse sets it spinning; the lab
// records the impulse, the spin, and how the kinetic energy after is shared between rotation and
// translation, at three elasticities.
//
// Usage: lab03 [OUTPUT_DIR]   writes rod.csv there.
#include <cmath>
#include <cstdio>
#include <impulse/impulse.hpp>
#include <numbers>
#include <stdexcept>

#include "lab.hpp"

namespace rigid = impulse::rigid_2d;

namespace {

struct Landing {
  double impulse = 0.0;
  double spin = 0.0;            // angular velocity after (counter-clockwise positive)
  double centre_vy = 0.0;       // vertical velocity of the centre after
  double contact_vy = 0.0;      // vertical velocity of the landing end after
  double rotation_share = 0.0;  // rotational energy over kinetic energy after
  double energy = 0.0;          // kinetic energy after
};

}  // namespace

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);

  // A uniform rod of mass 1 and length 1 (I = m l^2 / 12 about its centre), falling at 1.
  const double m = 1.0;
  const double l = 1.0;
  const double v = 1.0;
  const double elasticities[] = {1.0, 1.5, 2.0};

  const auto land = [&](double theta, double e) {
    // The centre is l/2 sin(theta) above the ground, the lower end at (l/2 cos(theta), 0).
    rigid::RigidBody rod;
    rod.mass = m;
    rod.inertia = m * l * l / 12;
    rod.position = {0.0, 0.5 * l * std::sin(theta)};
    rod.p = {0.0, -m * v};
    rod.L = 0.0;
    const Eigen::Vector2d point(0.5 * l * std::cos(theta), 0.0);
    // The ground is the bumper with outward normal up; the rod's own outward normal points down.
    const Eigen::Vector2d rod_normal(0.0, -1.0);
    // Section 3.4: Fdt (A1 + A2) = B1 + B2. The static ground adds nothing, so the rod's (3.6) /
    // (3.10) joined by its elasticity is the whole system.
    const impulse::ScalarContribution system =
        rigid::contribution(rod, point, rod_normal, impulse::Elasticity(e));
    const impulse::ScalarSolution s = impulse::solve(system);
    if (s.status != impulse::SolveStatus::success) {
      throw std::runtime_error("the rod's impulse could not be solved");
    }
    const rigid::RigidBody after = rigid::apply_impulse(rod, point, rod_normal, s.Fdt);
    Landing r;
    r.impulse = s.Fdt;
    r.spin = rigid::angular_velocity(after);
    r.centre_vy = rigid::velocity(after).y();
    r.contact_vy = rigid::point_velocity(after, point).y();
    r.energy = rigid::kinetic_energy(after);
    // (3.1): E_r / E_k. Undefined when nothing is left (upright at e = 1): NaN, a gap in the plot.
    const double energy_before = rigid::kinetic_energy(rod);
    r.rotation_share = r.energy > 1e-12 * energy_before
                           ? (after.L * after.L / (2 * after.inertia)) / r.energy
                           : std::nan("");
    return r;
  };

  lab::Csv csv(out / "rod.csv",
               {"angle", "impulse_e1", "impulse_e1.5", "impulse_e2", "spin_e1", "spin_e1.5",
                "spin_e2", "centre_vy_e1", "centre_vy_e1.5", "centre_vy_e2", "contact_vy_e1",
                "contact_vy_e1.5", "contact_vy_e2", "rotation_share_e1", "rotation_share_e1.5",
                "rotation_share_e2", "energy_e1", "energy_e1.5", "energy_e2"});
  for (int degrees = 0; degrees <= 90; ++degrees) {
    const double theta = degrees * std::numbers::pi / 180.0;
    Landing r[3];
    for (int k = 0; k < 3; ++k) {
      r[k] = land(theta, elasticities[k]);
    }
    csv.row({static_cast<double>(degrees), r[0].impulse, r[1].impulse, r[2].impulse, r[0].spin,
             r[1].spin, r[2].spin, r[0].centre_vy, r[1].centre_vy, r[2].centre_vy, r[0].contact_vy,
             r[1].contact_vy, r[2].contact_vy, r[0].rotation_share, r[1].rotation_share,
             r[2].rotation_share, r[0].energy, r[1].energy, r[2].energy});
  }
  std::printf("Lab 3: a uniform rod, m = %g, l = %g, falls at %g and lands on one end\n", m, l, v);
  std::printf("wrote %s\n", (out / "rod.csv").c_str());
  return 0;
}
