// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 2: casting onto the normal (section 2). Two pucks collide obliquely; the contact normal is
// turned through every angle from -90 to 90 degrees and the velocities after are recorded, in the
// plane's x and y and along the normal and the tangent.
//
// Usage: lab02 [OUTPUT_DIR]   writes oblique.csv there.
#include <cmath>
#include <cstdio>
#include <impulse/impulse.hpp>
#include <numbers>

#include "lab.hpp"

namespace m2 = impulse::material_2d;

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);

  // Puck A moves right at 1; puck B comes towards it at 0.5. Equal masses, elasticity 2.
  const m2::PointMass a = m2::from_velocity(1.0, {1.0, 0.0});
  const m2::PointMass b = m2::from_velocity(1.0, {-0.5, 0.0});
  const impulse::Elasticity e = impulse::Elasticity::elastic();

  lab::Csv csv(out / "oblique.csv",
               {"angle", "impulse", "a_vx", "a_vy", "b_vx", "b_vy", "a_normal_before",
                "a_normal_after", "b_normal_before", "b_normal_after", "a_tangent_before",
                "a_tangent_after", "b_tangent_before", "b_tangent_after", "energy_before",
                "energy_after", "momentum_x_after", "momentum_y_after"});
  for (int i = -36; i <= 36; ++i) {
    const double degrees = 2.5 * i;
    const double phi = degrees * std::numbers::pi / 180.0;
    // The normal at the contact, outward from A (the bumper): A's side of the contact faces B.
    const Eigen::Vector2d n(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d t = impulse::quarter_turn(n);  // the tangent
    const m2::Collision c = m2::collide(a, e, b, e, n);
    const Eigen::Vector2d va = m2::velocity(a);
    const Eigen::Vector2d vb = m2::velocity(b);
    const Eigen::Vector2d va_after = m2::velocity(c.bumper);
    const Eigen::Vector2d vb_after = m2::velocity(c.wedge);
    // Components along one common basis (n, t) for both pucks, so that they can be compared.
    csv.row({degrees, c.solution.Fdt, va_after.x(), va_after.y(), vb_after.x(), vb_after.y(),
             m2::cast(va, n), m2::cast(va_after, n), m2::cast(vb, n), m2::cast(vb_after, n),
             m2::cast(va, t), m2::cast(va_after, t), m2::cast(vb, t), m2::cast(vb_after, t),
             m2::kinetic_energy(a) + m2::kinetic_energy(b),
             m2::kinetic_energy(c.bumper) + m2::kinetic_energy(c.wedge),
             c.bumper.p.x() + c.wedge.p.x(), c.bumper.p.y() + c.wedge.p.y()});
  }
  std::printf("Lab 2: puck A (mass 1) at (1, 0), puck B (mass 1) at (-0.5, 0), elasticity 2\n");
  std::printf("wrote %s\n", (out / "oblique.csv").c_str());
  return 0;
}
