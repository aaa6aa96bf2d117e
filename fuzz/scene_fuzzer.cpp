// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: arbitrary bytes into the scene reader; an accepted scene is solved and its
// result held to the physical laws that hold whatever the scene.
//
// A refusal (impulse::InvalidInput naming the file) is the expected answer to most inputs. Any
// other exception, a sanitizer report, a refusal after the reader accepted the scene, or a law
// broken beyond its tolerance is a finding: the harness prints what it saw and traps, and
// libFuzzer keeps the input as a crash artifact.
//
// The laws, for an accepted scene whose solution is finite (status success):
//   - every reported number is finite (the condition estimate may be +infinity when A = 0);
//   - momentum is conserved when no body is static (each impulse acts on two bodies, equal and
//     opposite);
//   - whatever the method, the state after is the one its impulses give (check_kinematics);
// and, for the paper's method (simultaneous), only where the system is well conditioned (condition
// estimate at most max_checked_condition) and the solver found it consistent (see
// check_well_conditioned):
//   - the residual |A·Fdt - B| is at the level of rounding;
//   - one elasticity e for every movable body (B = e·u, u the approach speeds before): the
//     energy changes by (e/2 - 1)·uᵀFdt and the approach speeds after are (1 - e)·u. At e = 2
//     the kinetic energy is conserved and each approach speed reverses; at e = 1 each approach
//     speed after is zero.
// Where the solution is exact, energy after minus before is Fdtᵀ(A·Fdt/2 - u) and the approach
// speeds after are u - A·Fdt, which give the laws above when A·Fdt = e·u. A computed solution
// leaves the residual r = A·Fdt - B, so the laws hold up to |Fdt||r|/2 and |r|, plus the
// rounding of the sums that compute energies, momenta and speeds from the bodies. Each law's
// departure and the magnitudes it is measured against come from tests/support/laws.hpp, which the
// hostile tests hold results to as well.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/scene.hpp"
#include "support/laws.hpp"

namespace {

namespace sc = impulse::scene;
namespace laws = impulse::laws;

constexpr double epsilon = std::numeric_limits<double>::epsilon();
// The laws that depend on the solver's accuracy are checked up to the condition estimate above
// which `impulselab solve` warns: beyond it the impulses may carry more rounding than digits.
constexpr double max_checked_condition = impulse::ill_conditioned;
// Rounding allowance per operation summed: each reported quantity is a sum of at most about
// (contacts + bodies) terms, each carrying a few roundings; 64 leaves room for the constant.
constexpr double allowance = 64.0;
// Rounding in the standard model with underflow: each operation's error is at most ε times its
// result plus the smallest subnormal, the absolute part that dominates when every number is
// tiny (the second long run found a scene of elasticity 5e-324 whose approach speed after was
// one subnormal off, beyond a purely relative tolerance of 0: fuzz/regressions/).
constexpr double underflow = std::numeric_limits<double>::denorm_min();

// The rounding allowed for a quantity summed from about `terms` terms of magnitudes `scale`.
double rounding(double terms, double scale) {
  return allowance * terms * (epsilon * scale + underflow);
}

[[noreturn]] void finding(std::string_view what, double found, double tolerance) {
  std::fprintf(stderr, "scene_fuzzer: %.*s: found %.17g, tolerance %.17g\n",
               static_cast<int>(what.size()), what.data(), found, tolerance);
  __builtin_trap();
}

[[noreturn]] void finding(std::string_view what, std::string_view detail) {
  std::fprintf(stderr, "scene_fuzzer: %.*s: %.*s\n", static_cast<int>(what.size()), what.data(),
               static_cast<int>(detail.size()), detail.data());
  __builtin_trap();
}

// A tolerance that overflowed (an infinity, or the NaN of 0 times one) cannot judge anything.
void require_within(std::string_view what, double found, double tolerance) {
  if (!std::isfinite(tolerance)) {
    return;
  }
  if (!(found <= tolerance)) {
    finding(what, found, tolerance);
  }
}

bool finite(const sc::Motion& m) {
  return impulse::all_finite_in(m.velocity) && impulse::all_finite_in(m.momentum) &&
         std::isfinite(m.angular_velocity) && std::isfinite(m.angular_momentum);
}

void require_finite(const sc::Result& r) {
  bool ok = std::isfinite(r.energy_before) && std::isfinite(r.energy_after) &&
            std::isfinite(r.energy_change) && impulse::all_finite_in(r.momentum_before) &&
            impulse::all_finite_in(r.momentum_after) && impulse::all_finite_in(r.outcome.Fdt) &&
            impulse::all_finite_in(r.system.B) && std::isfinite(r.outcome.residual) &&
            !std::isnan(r.system.condition_estimate) && r.system.condition_estimate >= 1.0;
  for (const sc::BodyReport& b : r.bodies) {
    ok = ok && finite(b.before) && finite(b.after) && std::isfinite(b.energy_before) &&
         std::isfinite(b.energy_after);
  }
  for (const sc::ImpulseReport& i : r.impulses) {
    ok = ok && std::isfinite(i.magnitude) && impulse::all_finite_in(i.on_bumper);
  }
  for (const sc::ContactReport& c : r.contacts) {
    ok = ok && std::isfinite(c.approach_before) && std::isfinite(c.approach_after);
  }
  if (!ok) {
    finding("finite", "a result reported as success holds a NaN or an infinity");
  }
}

double terms_of(const sc::Result& r) {
  return static_cast<double>(r.bodies.size() + r.impulses.size() + 2);
}

// Momentum is conserved when no body is static (a static body takes momentum and is left out of
// the totals).
void check_momentum(const sc::Scene& scene, const sc::Result& r) {
  const laws::Departure d = laws::momentum(scene, r);
  require_within("momentum conserved", d.found, rounding(terms_of(r), d.scale));
}

double matrix_norm(const impulse::Solution& s) {
  // Quiet norms: the squares of plain norm() underflow to 0 for entries below 1e-154, and would
  // leave a tolerance of nothing (the third long run: a scene of elasticity 2.1e-299).
  return s.A.size() > 0 ? impulse::detail::quiet_norm(
                              Eigen::Map<const Eigen::VectorXd>(s.A.data(), s.A.size()))
                        : impulse::detail::quiet_norm(Eigen::Map<const Eigen::VectorXd>(
                              s.sparse_A.valuePtr(), s.sparse_A.nonZeros()));
}

// The size of what the solver fits, ‖G‖·‖W‖ (A = GᵀG, B = GᵀW scaled by the elasticities, W the
// velocities times √m and √I): the QR of G solves G·Fdt ≈ W accurately relative to them, and
// ‖G‖² = trace A, ‖W‖² = twice the kinetic energy before. Where a normal stands almost square to
// the velocities, B is far smaller than that (found by the 60 s of fuzzing of a CI run: normal
// (5, 12312308) against a velocity (1.5, 0), B about 1e-6, residual 3.5e-16:
// fuzz/regressions/oblique-normal-residual.json).
double fitted_scale(const sc::Scene& scene, const sc::Result& r) {
  const impulse::Solution& s = r.system;
  const double trace = s.A.size() > 0 ? s.A.trace() : s.sparse_A.diagonal().sum();
  double elasticity = 1.0;
  for (const sc::Body& b : scene.bodies) {
    if (b.kind != sc::BodyKind::static_body) {
      elasticity = std::max(elasticity, scene.elasticity_of(b));
    }
  }
  return elasticity * std::sqrt(std::max(0.0, trace)) *
         std::sqrt(2.0 * std::max(0.0, r.energy_before));
}

// The laws of the paper's system A·Fdt = B, for the paper's method, where the system is well
// conditioned and the solver found it consistent.
void check_well_conditioned(const sc::Scene& scene, const sc::Result& r) {
  const impulse::Solution& s = r.system;
  // A system assembled from bodies is consistent in exact arithmetic (B = GᵀW lies in the range
  // of A = GᵀG): when the solver reports it inconsistent, rounding has lost part of it (bodies
  // whose numbers are beyond what doubles resolve, e.g. an inertia of 1e-300 next to masses of
  // 1), impulselab warns, and the laws cannot hold to rounding.
  if (!(s.condition_estimate <= max_checked_condition) || !s.consistent) {
    return;
  }
  const double terms = terms_of(r);
  const double Fdt_norm = impulse::detail::quiet_norm(s.Fdt);
  // The residual of a backward-stable solution is rounding of the terms A·Fdt and B; solving
  // through the factor G (A = GᵀG) multiplies it by up to the condition number of G, the
  // square root of that of A, and by the square root of the spread s of the bodies' inverse
  // masses and inertias: G's rows carry 1/√m, the vector it is fitted to carries √m times the
  // velocities, and the QR is accurate relative to the largest of them. (The first long fuzzing
  // run found that term: masses 7.8e7 and 1 on a line, κ = 1, residual 5.2e-12 against B = 8,
  // fuzz/regressions/mass-ratio-residual.json; docs/pages/accuracy.md measures it.)
  const double residual_tolerance = rounding(
      terms,
      (1.0 + std::sqrt(s.condition_estimate) + std::sqrt(laws::spread(scene))) *
          (matrix_norm(s) * Fdt_norm + impulse::detail::quiet_norm(s.B) + fitted_scale(scene, r)));
  require_within("residual |A Fdt - B|", s.residual, residual_tolerance);
  const double residual_bound = s.residual + residual_tolerance;

  const std::optional<double> e = laws::common_elasticity(scene);
  if (!e) {
    return;  // bodies of different elasticities: B is not a multiple of u
  }
  // One elasticity e for every movable body: B = e u, so an exact solution changes the energy
  // by (e/2 - 1) uᵀFdt (zero at e = 2) and leaves the approach speeds (1 - e) u (zero at e = 1,
  // reversed at e = 2). The computed one departs from that by Fdtᵀr/2 and by r.
  const laws::Departure energy = laws::energy(scene, r, *e);
  require_within("energy change (e/2 - 1) u.Fdt", energy.found,
                 0.5 * Fdt_norm * residual_bound + rounding(terms, energy.scale));
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    const laws::Departure approach = laws::approach(scene, r, v, *e);
    require_within("approach after (1 - e) u", approach.found,
                   residual_bound + rounding(terms, approach.scale));
  }
}

// Whatever the method, the report's state after must be the one its impulses give: the energy
// changes by Fdtᵀ(A·Fdt/2 - u) and the approach speeds after are u - A·Fdt (the kinematics of
// sections 4 and 5, for any Fdt). This is what the complementarity and serial methods are held
// to; their own optimality (impulses that only push, no contact left approaching) is tested on
// hand-worked and 1,000 random scenes (tests/methods/).
void check_kinematics(const sc::Scene& scene, const sc::Result& r) {
  const impulse::Solution& s = r.system;
  const Eigen::VectorXd& F = r.outcome.Fdt;
  const Eigen::VectorXd AF =
      s.A.size() > 0 ? Eigen::VectorXd(s.A * F) : Eigen::VectorXd(s.sparse_A * F);
  const Eigen::VectorXd AF_terms = s.A.size() > 0
                                       ? Eigen::VectorXd(s.A.cwiseAbs() * F.cwiseAbs())
                                       : Eigen::VectorXd(s.sparse_A.cwiseAbs() * F.cwiseAbs());
  if (!impulse::all_finite_in(AF) || !impulse::all_finite_in(AF_terms)) {
    return;  // the identity's own terms overflow: nothing to compare with
  }
  const double terms = terms_of(r);
  const laws::Kinematics k = laws::kinematics(scene, r, AF, AF_terms);
  for (const laws::Departure& approach : k.approach) {
    require_within("approach after = u - A Fdt", approach.found, rounding(terms, approach.scale));
  }
  require_within("energy change = Fdt.(A Fdt / 2 - u)", k.energy.found,
                 rounding(terms, k.energy.scale));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<sc::World> world;
  try {
    world.emplace(sc::parse_world(text, "fuzz.json"));
  } catch (const impulse::InvalidInput& e) {
    if (!std::string_view(e.what()).starts_with("fuzz.json: ")) {
      finding("a refusal that does not name the file", e.what());
    }
    return 0;  // the expected answer to bad input
  }
  const sc::Scene& scene = world->scene();
  sc::Result result;
  try {
    result = sc::resolve(*world);
  } catch (const impulse::InvalidInput& e) {
    finding("the reader accepted a scene that resolve() refuses", e.what());
  }
  if (result.status != impulse::SolveStatus::success) {
    return 0;  // beyond double precision: impulselab refuses it as overflowing
  }
  require_finite(result);
  check_momentum(scene, result);
  check_kinematics(scene, result);
  if (result.method == impulse::methods::Method::simultaneous) {
    check_well_conditioned(scene, result);  // the laws of the paper's system A·Fdt = B
  }
  const std::string report = sc::to_json(result).dump();
  if (report.empty()) {
    finding("to_json", "an empty report");
  }
  return 0;
}
