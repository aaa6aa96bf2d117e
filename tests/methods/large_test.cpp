// SPDX-License-Identifier: GPL-3.0-or-later
// The methods above the pivoting threshold, on bench/'s generated scenes (300 contacts): the
// complementarity problem by projected Gauss-Seidel, and serial collisions that a tall stack
// keeps going until their bound.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "scenes.hpp"

using Eigen::VectorXd;
namespace mp = impulse::multipoint;
namespace me = impulse::methods;

namespace {
impulse::ContactSystem system_of(const impulse::scenes::Scene& s) {
  return mp::assemble(s.bodies, std::vector<impulse::Elasticity>(s.bodies.size(), s.elasticity),
                      s.contacts);
}
}  // namespace

TEST_CASE("Above 256 contacts: projected Gauss-Seidel, started from the paper's impulses",
          "[methods][section5]") {
  for (const std::string kind : {"stack", "pyramid", "cradle"}) {
    CAPTURE(kind);
    const auto scene = impulse::scenes::generate(kind, 300);
    const auto system = system_of(scene);
    REQUIRE(system.size() > me::pivoting_threshold);
    const auto s = me::solve_complementarity(system);
    CHECK(s.algorithm == me::LcpAlgorithm::projected_gauss_seidel);
    REQUIRE(s.status == me::LcpStatus::solved);
    // w recomputed from the system (not the solver's own residual): no contact wants more than
    // the tolerance, and where an impulse pushes, its contact's slack is zero within it.
    const VectorXd w = system.sparse_A() * s.Fdt - system.B();
    CHECK(w.minCoeff() >= -1e-10 * s.scale);
    CHECK(s.Fdt.cwiseProduct(w).cwiseAbs().maxCoeff() <= 1e-10 * s.scale * s.Fdt.maxCoeff());
    // Every impulse acts on two bodies with opposite signs; the ground (static) of the stack and
    // the pyramid absorbs momentum, the cradle has none.
    const auto after = mp::apply_impulses(scene.bodies, scene.contacts, s.Fdt);
    if (kind == "cradle") {
      // Elasticity 2 and only pushes: every impulse of the paper's solution, (N - i) 2 / N,
      // is positive, so nothing was clipped; energy and momentum are kept.
      CHECK(s.iterations == 0);
      CHECK(mp::kinetic_energy(after) == Approx(mp::kinetic_energy(scene.bodies)).epsilon(1e-12));
      CHECK((mp::momentum(after) - mp::momentum(scene.bodies)).norm() <= 1e-12 * 300);
    }
  }
}

TEST_CASE("From zero, projected Gauss-Seidel stalls on a long cradle and says so",
          "[methods][section4]") {
  // A row of 301 balls: A is tridiagonal (2, -1), its condition number about (2N / pi)^2 =
  // 3.6e4, and Gauss-Seidel's error shrinks by about 1 - pi^2 / N^2 per sweep: 10,000 sweeps
  // gain a factor e^-1.1 only. The answer is returned with its residual and the status.
  const auto scene = impulse::scenes::generate("cradle", 300);
  me::ComplementarityOptions cold;
  cold.warm_start = false;
  const auto s = me::solve_complementarity(system_of(scene), cold);
  CHECK(s.status == me::LcpStatus::iteration_limit);
  CHECK(s.iterations == cold.max_sweeps);
  CHECK(s.residual > 1e-10 * s.scale);
  CHECK(s.Fdt.minCoeff() >= 0.0);
}

TEST_CASE("Serial collisions on a stack of 150 boxes reach their bound", "[methods][section5]") {
  // Each box rests on the one below at two corners; at elasticity 1.5 every collision sends part
  // of the speed back down and up the stack, and 1000 collisions per contact are not enough.
  // The cradle of the same size needs exactly one collision per contact (300).
  const auto stack = impulse::scenes::generate("stack", 300);
  const auto serial = me::resolve_serial(stack.bodies, stack.elasticity, stack.contacts);
  CHECK(serial.diagnostics.status == me::SerialStatus::collision_limit);
  CHECK(serial.diagnostics.order.size() == 300000);
  const auto cradle = impulse::scenes::generate("cradle", 300);
  const auto passed = me::resolve_serial(cradle.bodies, cradle.elasticity, cradle.contacts);
  CHECK(passed.diagnostics.status == me::SerialStatus::finished);
  CHECK(passed.diagnostics.order.size() == 300);
  CHECK(passed.diagnostics.passes == 1);
}
