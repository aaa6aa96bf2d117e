// SPDX-License-Identifier: GPL-3.0-or-later
// Equal masses, one at rest, perfectly elastic: they exchange velocities, so the impulse is
// m * v = 1 * 1.5 and the first body stops. Exit status 0 only if the installed library says so.
#include <cmath>
#include <cstdio>
#include <impulse/impulse.hpp>

int main() {
  using namespace impulse;
  const auto result = one_d::collide(one_d::from_velocity(1.0, 1.5), Elasticity::elastic(),
                                     one_d::from_velocity(1.0, 0.0), Elasticity::elastic());
  std::printf("Fdt = %g, v1' = %g, v2' = %g\n", result.solution.Fdt, one_d::velocity(result.first),
              one_d::velocity(result.second));
  const bool ok = std::abs(result.solution.Fdt - 1.5) < 1e-12 &&
                  std::abs(one_d::velocity(result.first)) < 1e-12 &&
                  std::abs(one_d::velocity(result.second) - 1.5) < 1e-12;
  return ok ? 0 : 1;
}
