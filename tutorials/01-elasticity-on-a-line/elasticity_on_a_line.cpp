// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 1: elasticity on a line (section 1). Two bodies collide head-on; the elasticity of both is
// swept from 0 to 3 and the kinetic energy and the relative velocity after are recorded.
//
// Usage: lab01_elasticity_on_a_line [OUTPUT_DIR]   writes elasticity.csv there.
#include <cstdio>
#include <impulse/impulse.hpp>

#include "lab.hpp"

namespace one_d = impulse::one_d;

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);

  // The bodies of tutorials/scenes/elastic-1d.json: body 1 on the left moves right at 3, body 2
  // on its right moves left at 1. Turn these to see what depends on them.
  const double m1 = 2.0;
  const double v1 = 3.0;
  const double m2 = 1.0;
  const double v2 = -1.0;
  const one_d::Body first = one_d::from_velocity(m1, v1);
  const one_d::Body second = one_d::from_velocity(m2, v2);
  const double energy_before = one_d::kinetic_energy(first) + one_d::kinetic_energy(second);

  lab::Csv csv(out / "elasticity.csv",
               {"elasticity", "impulse", "v1_after", "v2_after", "energy_before", "energy_after",
                "energy_change", "relative_velocity_before", "relative_velocity_after"});
  constexpr int steps = 60;  // 0 to 3 in steps of 0.05
  for (int i = 0; i <= steps; ++i) {
    const impulse::Elasticity e(3.0 * i / steps);
    // (1.3) with elasticity_1 = elasticity_2 = e; body 1 is on the left, so its normal is +1.
    const one_d::Collision c = one_d::collide(first, e, second, e, 1.0);
    const double energy_after = one_d::kinetic_energy(c.first) + one_d::kinetic_energy(c.second);
    // Positive when the bodies separate: v2' - v1'.
    const double relative_after = one_d::velocity(c.second) - one_d::velocity(c.first);
    csv.row({e.value(), c.solution.Fdt, one_d::velocity(c.first), one_d::velocity(c.second),
             energy_before, energy_after, energy_after - energy_before, v2 - v1, relative_after});
  }

  std::printf("Lab 1: m1 = %g at %g, m2 = %g at %g; kinetic energy before %g\n", m1, v1, m2, v2,
              energy_before);
  std::printf("wrote %s\n", (out / "elasticity.csv").c_str());
  return 0;
}
