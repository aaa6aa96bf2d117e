// SPDX-License-Identifier: GPL-3.0-or-later
// The inputs the fuzzer (fuzz/scene_fuzzer.cpp) found wrong, kept in fuzz/regressions/ (which
// is also part of its seed corpus): each must now be refused with a message naming the file, or
// solved with a finite result whose diagnostics tell the truth about it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "support/scene_files.hpp"

namespace sc = impulse::scene;

namespace {

std::vector<std::filesystem::path> regressions() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSELAB_FUZZ_REGRESSIONS_DIR)) {
    if (entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string path_of(const std::string& name) {
  return std::string(IMPULSELAB_FUZZ_REGRESSIONS_DIR) + "/" + name;
}

}  // namespace

TEST_CASE("Every input the fuzzer found is refused, or solved with honest diagnostics",
          "[scene][fuzz]") {
  const auto files = regressions();
  CHECK_FALSE(files.empty());
  for (const auto& file : files) {
    CAPTURE(file.filename().string());
    const std::string text = impulselab::test::read_scene_text(file.string());
    sc::Scene scene;
    try {
      scene = sc::parse_scene(text, "found.json");
    } catch (const impulse::InvalidInput& e) {
      CHECK_THAT(e.what(), Catch::Matchers::StartsWith("found.json: "));
      continue;
    }
    const sc::Result r = sc::solve(scene);
    if (r.status != impulse::SolveStatus::success) {
      continue;  // beyond doubles: impulselab refuses it
    }
    CHECK(r.system.Fdt.allFinite());
    CHECK(std::isfinite(r.system.residual));
    // The reported residual is that of the reported impulses: recomputed here from A, B and
    // Fdt (not taken from the solver), it must agree to rounding.
    const impulse::Solution& s = r.system;
    const Eigen::VectorXd residual = s.A.size() > 0 ? Eigen::VectorXd(s.A * s.Fdt - s.B)
                                                    : Eigen::VectorXd(s.sparse_A * s.Fdt - s.B);
    const double recomputed = impulse::detail::quiet_norm(residual);
    CHECK(recomputed == Approx(s.residual).epsilon(1e-6).margin(1e-300));
  }
}

TEST_CASE("An inertia of 4e-301 in a stack: the solver says that it lost part of the system",
          "[scene][fuzz]") {
  // Found by the fuzzer: box-stack.json with the bottom box's inertia 0.41666666661e-300. Its
  // rotation puts 1/I = 2.4e300 into A, so the plain Frobenius norm of A overflowed, the
  // consistency test compared the residual with infinity and called the solution consistent,
  // with a condition estimate of 1. But the column-pivoted QR (pivots below N ε of the largest
  // count as zero) kept rank 1: contacts 4 and 5, between the middle and the top box, whose A
  // is of order 1, got no impulse and the residual is of the order of |B|. Doubles cannot
  // resolve both scales in one factorisation; the diagnostics must say so.
  const sc::Result r =
      sc::solve(impulselab::test::load_scene(path_of("stack-inertia-1e-300.json")));
  REQUIRE(r.status == impulse::SolveStatus::success);
  CHECK(r.system.rank == 1);
  CHECK_FALSE(r.system.consistent);
  CHECK(r.system.residual > 0.5 * r.system.B.norm());
}

TEST_CASE("Masses 7.8e7 and 1 on a line: the error grows with the square root of their ratio",
          "[scene][fuzz]") {
  // Found by the first long fuzzing run (the fuzzer's residual law then had no mass-ratio term):
  // M = 77777770.577..., m = 1, velocities 3 and -1, elasticity 2. By hand (1.1):
  // u = 3 - (-1) = 4, A = 1/M + 1/m, B = 2 u = 8, Fdt = 8 / (1 + 1/M). The solver fits G Fdt to
  // w through the factor G, whose rows are 1/√M and 1/√m and whose target carries √M times the
  // velocity (about 2.6e4 here): its QR is accurate relative to those, so Fdt carries an error of
  // about ε √(M/m) = 2e-12 relative to 8 — not the ε of a division. The bound the fuzzer now
  // uses, 64 (N + K + 2) ε (1 + √κ + √s) (|A||Fdt| + |B|) with s = M/m, holds it.
  const sc::Scene scene = impulselab::test::load_scene(path_of("mass-ratio-residual.json"));
  const double M = scene.bodies[0].mass;
  const sc::Result r = sc::solve(scene);
  REQUIRE(r.status == impulse::SolveStatus::success);
  const double exact = 8.0 / (1.0 + 1.0 / M);
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound = 64.0 * 5.0 * eps * (2.0 + std::sqrt(M)) * (r.system.A(0, 0) * 8.0 + 8.0);
  CHECK(std::abs(r.system.Fdt(0) - exact) * r.system.A(0, 0) <= bound);
  CHECK(r.system.residual <= bound);
  // Energy is kept at elasticity 2 to the same relative accuracy: 1/2 M 3² + 1/2 (-1)².
  CHECK(r.energy_after == Approx(r.energy_before).epsilon(1e-11));
}

TEST_CASE("Elasticity 5e-323: impulses of subnormal size, the motion unchanged", "[scene][fuzz]") {
  // Found by the second long fuzzing run: a row of five balls whose elasticity, 50e-324, is a
  // subnormal number. B = e u is subnormal, so are the impulses (A's entries are 1/m of order 1,
  // Fdt of order e), and each velocity changes by less than 1e-300 — which rounds to no change
  // at all for the moving ball (1 ± 1e-322 is 1). The fuzzer's bound had no absolute term for
  // underflow and refused an approach speed one subnormal (4.9e-324) off; it now has one.
  const sc::Scene scene = impulselab::test::load_scene(path_of("subnormal-elasticity.json"));
  REQUIRE(scene.elasticity.value_or(1.0) < std::numeric_limits<double>::min());  // subnormal
  const sc::Result r = sc::solve(scene);
  REQUIRE(r.status == impulse::SolveStatus::success);
  for (const auto& impulse : r.impulses) {
    CHECK(std::abs(impulse.magnitude) < 1e-300);
  }
  CHECK(r.system.consistent);  // within the absolute allowance for subnormal rounding
  for (std::size_t k = 0; k < r.bodies.size(); ++k) {
    CHECK(r.bodies[k].after.velocity.x() ==
          Approx(r.bodies[k].before.velocity.x()).epsilon(0).margin(1e-300));
  }
}

TEST_CASE("Elasticity 2.1e-299: every number tiny, nothing lost to underflow", "[scene][fuzz]") {
  // Found by the third long fuzzing run: five balls of mass 1 whose contacts close a loop (ball
  // 4 touches ball 2 again: a dependent system), elasticity 2.1e-299, so B and the impulses are
  // of order 1e-299. The harness measured them with Eigen's norm(), whose squares underflow to
  // 0 below 1e-154, and its tolerance vanished; it now uses stableNorm(). The solver was right:
  // it is consistent, and the residual is rounding relative to B.
  const sc::Scene scene =
      impulselab::test::load_scene(path_of("tiny-elasticity-norm-underflow.json"));
  const sc::Result r = sc::solve(scene);
  REQUIRE(r.status == impulse::SolveStatus::success);
  CHECK(r.system.consistent);
  CHECK(impulse::detail::quiet_norm(r.system.B) > 1e-300);  // not lost to underflow
  CHECK(r.system.residual <= 1e-12 * impulse::detail::quiet_norm(r.system.B));
  // Each velocity changes by an amount of order 1e-299: not at all for the moving balls (1 and
  // 2 absorb it), by that much for those at rest.
  for (const auto& body : r.bodies) {
    CHECK(body.after.velocity.x() == Approx(body.before.velocity.x()).epsilon(0).margin(1e-290));
  }
}
