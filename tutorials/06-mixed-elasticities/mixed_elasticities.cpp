// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 6: mixed elasticities (section 1.3). Body 1 collides with elasticity 2, body 2 with
// elasticity 1. The lab maps the energy change over all approaching velocities, and collides one
// pair as seen from observers moving at different speeds (Galilean boosts).
//
// Usage: lab06 [OUTPUT_DIR]   writes gain-map.csv and frames.csv there.
#include <cmath>
#include <cstdio>
#include <impulse/impulse.hpp>

#include "lab.hpp"

namespace one_d = impulse::one_d;

namespace {

constexpr double m1 = 1.0;
constexpr double m2 = 1.0;

struct Outcome {
  double impulse = 0.0;
  double v1 = 0.0;  // velocities after
  double v2 = 0.0;
  double energy_change = 0.0;
};

// Body 1 on the left at v1, body 2 on its right at v2, each with its own elasticity: (1.3).
Outcome collide(double v1, double v2, double e1, double e2) {
  const one_d::Body first = one_d::from_velocity(m1, v1);
  const one_d::Body second = one_d::from_velocity(m2, v2);
  const one_d::Collision c =
      one_d::collide(first, impulse::Elasticity(e1), second, impulse::Elasticity(e2), 1.0);
  const double before = one_d::kinetic_energy(first) + one_d::kinetic_energy(second);
  const double after = one_d::kinetic_energy(c.first) + one_d::kinetic_energy(c.second);
  return {c.solution.Fdt, one_d::velocity(c.first), one_d::velocity(c.second), after - before};
}

}  // namespace

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);

  // 1. Every pair of velocities from -3 to 3: the energy change at elasticities (2, 1), in units
  //    of the energy of the relative motion (mu u^2 / 2), so that an ordinary collision lies in
  //    [-1, 0]. Pairs that do not approach do not collide: NaN.
  {
    lab::Csv csv(out / "gain-map.csv",
                 {"v1", "v2", "energy_change", "relative_energy_change", "impulse"});
    const double mu = m1 * m2 / (m1 + m2);
    for (int i = -60; i <= 60; ++i) {
      for (int j = -60; j <= 60; ++j) {
        const double v1 = 0.05 * i;
        const double v2 = 0.05 * j;
        const double u = v1 - v2;  // closing speed
        if (u <= 0) {
          csv.row({v1, v2, std::nan(""), std::nan(""), std::nan("")});
          continue;
        }
        const Outcome o = collide(v1, v2, 2.0, 1.0);
        csv.row({v1, v2, o.energy_change, o.energy_change / (0.5 * mu * u * u), o.impulse});
      }
      csv.blank();
    }
  }

  // 2. One collision, body 1 at 2 and body 2 at 1 (moving away from it, but slower), seen by
  //    observers moving at w: in their frame the velocities are v - w. Each observer applies (1.3)
  //    in their own frame; the velocities after are moved back to the ground frame (v' + w) to
  //    compare. Mixed elasticities (2, 1) against equal ones (1.5, 1.5) and (2, 2).
  {
    lab::Csv csv(out / "frames.csv",
                 {"boost", "mixed_energy_change", "mixed_v1_after", "mixed_v2_after",
                  "equal_1.5_energy_change", "equal_1.5_v1_after", "equal_1.5_v2_after",
                  "equal_2_energy_change", "equal_2_v1_after", "equal_2_v2_after"});
    const double v1 = 2.0;
    const double v2 = 1.0;
    for (int k = -20; k <= 60; ++k) {
      const double w = 0.05 * k;  // from -1 to 3
      const Outcome mixed = collide(v1 - w, v2 - w, 2.0, 1.0);
      const Outcome half = collide(v1 - w, v2 - w, 1.5, 1.5);
      const Outcome elastic = collide(v1 - w, v2 - w, 2.0, 2.0);
      csv.row({w, mixed.energy_change, mixed.v1 + w, mixed.v2 + w, half.energy_change, half.v1 + w,
               half.v2 + w, elastic.energy_change, elastic.v1 + w, elastic.v2 + w});
    }
    const Outcome ground = collide(v1, v2, 2.0, 1.0);
    std::printf("Lab 6: m1 = m2 = 1, body 1 at %g (elasticity 2), body 2 at %g (elasticity 1):\n",
                v1, v2);
    std::printf("  Fdt = %g, velocities after %g and %g, energy change %+g\n", ground.impulse,
                ground.v1, ground.v2, ground.energy_change);
  }
  std::printf("wrote gain-map.csv and frames.csv in %s\n", out.c_str());
  return 0;
}
