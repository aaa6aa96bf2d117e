// SPDX-License-Identifier: GPL-3.0-or-later
// The three methods on random scenes (tests/multipoint/random_scene.hpp): the complementarity
// conditions, agreement with the paper where its impulses all push, and the conservation laws,
// judged with physics computed independently from the bodies' fields.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "impulse/core/solve.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "multipoint/random_scene.hpp"

using Eigen::VectorXd;
using impulse::Elasticity;
namespace mp = impulse::multipoint;
namespace me = impulse::methods;
namespace t = impulse::test;

namespace {

std::vector<Elasticity> random_elasticities(t::Sampler& sample, std::size_t count, double low,
                                            double high) {
  std::vector<Elasticity> result;
  for (std::size_t i = 0; i < count; ++i) {
    result.emplace_back(sample.uniform(low, high));
  }
  return result;
}

// Each contact's approach speed, from the bodies' own fields: (v_bumper - v_wedge) . n.
VectorXd approach(const std::vector<mp::Body>& bodies, const std::vector<mp::Contact>& contacts) {
  VectorXd u(static_cast<Eigen::Index>(contacts.size()));
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const auto& c = contacts[v];
    u(static_cast<Eigen::Index>(v)) =
        (t::velocity_at(bodies[c.bumper], c.point) - t::velocity_at(bodies[c.wedge], c.point))
            .dot(c.normal);
  }
  return u;
}

}  // namespace

TEST_CASE(
    "Complementarity: impulses push, no contact is left wanting one, and each pushes only "
    "where it must",
    "[methods][property]") {
  // The conditions themselves: F >= 0, w = A F - B >= 0 and min(A_vv F_v, w_v) = 0 at every
  // contact, within 1e-10 of the size of the terms that make up w (any method that rounds its
  // sums can only be that exact). Random elasticities 0..3 per body, material and rigid bodies,
  // static ones too.
  t::Sampler sample("methods lcp conditions");
  t::Worst worst("complementarity residual / scale");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto system = mp::assemble(scene.bodies, es, scene.contacts);
    const auto s = me::solve_complementarity(system);
    REQUIRE(s.status == me::LcpStatus::solved);
    REQUIRE(s.algorithm == me::LcpAlgorithm::active_set);
    REQUIRE(s.Fdt.minCoeff() >= 0.0);
    // w recomputed here from the system's A and B, not taken from the solver.
    const VectorXd w = system.A() * s.Fdt - system.B();
    const VectorXd terms = system.A().cwiseAbs() * s.Fdt.cwiseAbs() + system.B().cwiseAbs();
    const double scale = terms.maxCoeff();
    if (scale == 0.0) {
      continue;
    }
    double residual = 0.0;
    for (Eigen::Index v = 0; v < w.size(); ++v) {
      residual = std::max(residual, std::abs(std::min(system.A()(v, v) * s.Fdt(v), w(v))));
    }
    worst.see(residual / scale);
    REQUIRE(w.minCoeff() >= -1e-10 * scale);
    REQUIRE(residual <= 1e-10 * scale);
  }
}

TEST_CASE("Where the paper's impulses all push, complementarity returns the same",
          "[methods][property]") {
  // If the minimum-norm solution of A F = B has no negative entry it satisfies the conditions
  // with w = 0, and it is the least-norm solution of the complementarity problem (every
  // solution has the same A F). The motion after must then agree (to the rounding of the
  // approach speeds' terms, see t::approach_scale); the impulses too, where A is well
  // conditioned enough for the two routes to round alike.
  t::Sampler sample("methods agree");
  t::Worst motion("complementarity vs simultaneous, approach after / approach scale");
  int agreeing = 0;
  int pulling = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const Elasticity e(sample.uniform(1, 2));
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), e.value());
    const auto simultaneous = mp::resolve(scene.bodies, e, scene.contacts);
    const VectorXd& F = simultaneous.solution.Fdt;
    if (F.minCoeff() < -1e-12 * F.cwiseAbs().maxCoeff()) {
      ++pulling;
      continue;
    }
    ++agreeing;
    const auto lcp = me::resolve_complementarity(scene.bodies, e, scene.contacts);
    REQUIRE(lcp.solution.status == me::LcpStatus::solved);
    const double scale = t::approach_scale(scene, simultaneous.solution);
    if (scale == 0.0) {
      continue;
    }
    const double difference =
        (approach(lcp.after, scene.contacts) - approach(simultaneous.after, scene.contacts))
            .cwiseAbs()
            .maxCoeff();
    motion.see(difference / scale);
    REQUIRE(difference <= 1e-10 * scale);
    if (simultaneous.solution.condition_estimate <= 1e6) {
      CHECK(lcp.solution.least_norm);
      REQUIRE((lcp.solution.Fdt - F).cwiseAbs().maxCoeff() <=
              1e-9 * F.cwiseAbs().maxCoeff() + 1e-300);
    }
  }
  // Both kinds of scene occur often enough for the test to mean something.
  // (About 14% and 86% of them; at least 5% each, whatever the count of configurations.)
  CHECK(agreeing > t::configurations / 20);
  CHECK(pulling > t::configurations / 20);
}

TEST_CASE("Every method keeps the momentum", "[methods][property]") {
  // Each impulse acts on the bumper and, opposite, on the wedge: whatever the impulses, the
  // total momentum of the movable bodies cannot change when no static body takes part.
  t::Sampler sample("methods momentum");
  t::Worst worst("methods momentum, relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, false);
    // Per-body elasticities up to 2: above, serial collisions can gain energy at every bounce
    // and run to overflow before their bound.
    const auto es = random_elasticities(sample, scene.bodies.size(), 1, 2);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const Eigen::Vector2d before = t::momentum(scene.bodies);
    const auto simultaneous = mp::resolve(scene.bodies, es, scene.contacts);
    const auto lcp = me::resolve_complementarity(scene.bodies, es, scene.contacts);
    const auto serial = me::resolve_serial(scene.bodies, es, scene.contacts);
    const std::vector<std::pair<const std::vector<mp::Body>*, const VectorXd*>> answers{
        {&simultaneous.after, &simultaneous.solution.Fdt},
        {&lcp.after, &lcp.solution.Fdt},
        {&serial.after, &serial.Fdt}};
    for (const auto& [after, Fdt] : answers) {
      const double error =
          (t::momentum(*after) - before).norm() / t::momentum_scale(scene.bodies, *Fdt);
      worst.see(error);
      REQUIRE(error <= 1e-12);
    }
  }
}

TEST_CASE("At elasticity 2, complementarity and serial collisions keep the kinetic energy",
          "[methods][property]") {
  // The energy change of any impulses F is dE = -F^T u + 1/2 F^T A F (u the approach speeds
  // before; each body's dE is p.dp / m + dp^2 / 2m summed over bodies). Complementarity gives
  // F^T w = 0, i.e. F^T A F = F^T B = e F^T u, so dE = (e - 2) / (2e) F^T A F: zero at e = 2.
  // Serial: each collision is a single-contact collision at e = 2, which keeps the energy
  // (section 1.1), so the sequence does. Static bodies take part (they absorb momentum, not
  // energy).
  t::Sampler sample("methods energy");
  t::Worst worst("methods energy (e=2), relative");
  int limited = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const double before = t::energy(scene.bodies);
    if (before == 0.0) {
      continue;
    }
    const auto lcp =
        me::resolve_complementarity(scene.bodies, Elasticity::elastic(), scene.contacts);
    REQUIRE(lcp.solution.status == me::LcpStatus::solved);
    const double lcp_error = t::relative_error(t::energy(lcp.after), before, before);
    worst.see(lcp_error);
    REQUIRE(lcp_error <= 1e-10);
    const auto serial = me::resolve_serial(scene.bodies, Elasticity::elastic(), scene.contacts);
    if (serial.diagnostics.status == me::SerialStatus::collision_limit) {
      ++limited;
    }
    REQUIRE(serial.diagnostics.status != me::SerialStatus::non_finite);
    // Even a sequence cut off by the bound keeps the energy: every collision in it did.
    const double serial_error = t::relative_error(t::energy(serial.after), before, before);
    worst.see(serial_error);
    REQUIRE(serial_error <= 1e-10);
  }
  // Serial collisions need not end at all. Two contacts between the same two bodies with
  // opposite normals (a bead that fits a tube exactly) take turns for ever at elasticity 2, each
  // reversing the approach the other then sees; a light body between heavy ones needs thousands
  // (Galperin's count, masses here span 1e6). The random scenes pair bodies at random, so about
  // one in ten has such contacts: the bound stops them, and the energy is kept all the same.
  CHECK(limited < t::configurations / 5);
}

TEST_CASE("The energy law dE = 1/2 F^T (B - 2u) for the paper's system and for complementarity",
          "[methods][property]") {
  // For both, F^T A F = F^T B: complementarity because F^T w = 0; the paper's solution because
  // A F = B (or, inconsistent, A F is B's projection on the range of A, in which F lies). Then
  // dE = 1/2 F^T A F - F^T u = 1/2 F^T (B - 2u). With every body at elasticity e, B = e u and
  // F^T u = F^T A F / e >= 0: energy is lost for e < 2, kept at 2, gained above. With mixed
  // elasticities B - 2u has either sign and so may dE (lab 6's gain). dE is measured here from
  // the energies of the bodies, u from their velocities.
  t::Sampler sample("methods energy law");
  t::Worst worst("dE - 1/2 F^T (B - 2u), relative");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const auto es = random_elasticities(sample, scene.bodies.size(), 0, 3);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto system = mp::assemble(scene.bodies, es, scene.contacts);
    const VectorXd u = approach(scene.bodies, scene.contacts);
    const double before = t::energy(scene.bodies);
    const auto simultaneous = mp::resolve(scene.bodies, es, scene.contacts);
    const auto lcp = me::resolve_complementarity(scene.bodies, es, scene.contacts);
    for (const auto& [after, F] : {std::pair{&simultaneous.after, &simultaneous.solution.Fdt},
                                   std::pair{&lcp.after, &lcp.solution.Fdt}}) {
      const double change = t::energy(*after) - before;
      const double law = 0.5 * F->dot(system.B() - 2 * u);
      const double scale = before + t::energy(*after) +
                           0.5 * F->cwiseAbs().dot(system.B().cwiseAbs() + 2 * u.cwiseAbs());
      if (scale == 0.0) {
        continue;
      }
      const double error = std::abs(change - law) / scale;
      worst.see(error);
      REQUIRE(error <= 1e-9);
    }
  }
}

TEST_CASE("Below elasticity 2 every method loses energy", "[methods][property]") {
  // Simultaneous and complementarity: dE = (e - 2) / (2e) F^T A F < 0 unless F is inert. Serial:
  // each collision loses (2 - e) / (2e) A_vv F_k^2 of its own, so the sequence loses too.
  t::Sampler sample("methods energy loss");
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const Elasticity e(sample.uniform(1.2, 1.9));
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), e.value());
    const double before = t::energy(scene.bodies);
    const auto simultaneous = mp::resolve(scene.bodies, e, scene.contacts);
    const auto lcp = me::resolve_complementarity(scene.bodies, e, scene.contacts);
    const auto serial = me::resolve_serial(scene.bodies, e, scene.contacts);
    REQUIRE(t::energy(simultaneous.after) <= before * (1 + 1e-12));
    REQUIRE(t::energy(lcp.after) <= before * (1 + 1e-12));
    REQUIRE(t::energy(serial.after) <= before * (1 + 1e-12));
    if (!serial.diagnostics.order.empty()) {
      REQUIRE(t::energy(serial.after) < before);
    }
  }
}

TEST_CASE("Serial collisions end with no contact approaching", "[methods][property]") {
  t::Sampler sample("methods serial ends");
  int finished = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const Elasticity e(sample.uniform(1.5, 2));
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), e.value());
    const auto serial = me::resolve_serial(scene.bodies, e, scene.contacts);
    if (serial.diagnostics.status != me::SerialStatus::finished) {
      continue;
    }
    ++finished;
    // Every impulse pushes (each collision's Fdt = e u_v / A_vv with u_v > 0) and, at the end,
    // no contact approaches beyond the threshold.
    REQUIRE(serial.Fdt.minCoeff() >= 0.0);
    REQUIRE(approach(serial.after, scene.contacts).maxCoeff() <=
            serial.diagnostics.approach_threshold * (1 + 1e-9) + 1e-15 * t::speed_scale(scene));
    REQUIRE(serial.diagnostics.passes >= (serial.diagnostics.order.empty() ? 0 : 1));
    REQUIRE(serial.diagnostics.passes <=
            static_cast<std::int64_t>(serial.diagnostics.order.size()));
  }
  CHECK(finished >= t::configurations * 4 / 5);  // the others: see the energy test above
}

TEST_CASE("Projected Gauss-Seidel and both pivoting methods reach the same motion",
          "[methods][property]") {
  // Two algorithms, one problem: where both converge, the motion after (A F, unique among all
  // solutions) must agree, whichever split of a dependent system each one picks.
  t::Sampler sample("methods pgs");
  t::Worst worst("PGS vs active set, approach after / approach scale");
  int compared = 0;
  me::ComplementarityOptions iterate;
  iterate.algorithm = me::LcpAlgorithm::projected_gauss_seidel;
  iterate.tolerance = 1e-12;
  iterate.warm_start = false;  // from zero: the sweeps must do the work
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    CAPTURE(i, scene.bodies.size(), scene.contacts.size());
    const auto simultaneous = mp::resolve(scene.bodies, Elasticity::elastic(), scene.contacts);
    if (simultaneous.solution.condition_estimate > 1e3) {
      continue;  // PGS converges at a rate set by the conditioning: keep it quick
    }
    const auto pgs =
        me::resolve_complementarity(scene.bodies, Elasticity::elastic(), scene.contacts, iterate);
    if (pgs.solution.status != me::LcpStatus::solved) {
      continue;
    }
    ++compared;
    const auto active =
        me::resolve_complementarity(scene.bodies, Elasticity::elastic(), scene.contacts);
    me::ComplementarityOptions pivot;
    pivot.algorithm = me::LcpAlgorithm::lemke;
    const auto lemke =
        me::resolve_complementarity(scene.bodies, Elasticity::elastic(), scene.contacts, pivot);
    REQUIRE(active.solution.status == me::LcpStatus::solved);
    REQUIRE(lemke.solution.status == me::LcpStatus::solved);
    const double scale = t::approach_scale(scene, simultaneous.solution);
    if (scale == 0.0) {
      continue;
    }
    const VectorXd reference = approach(active.after, scene.contacts);
    const double difference =
        (approach(pgs.after, scene.contacts) - reference).cwiseAbs().maxCoeff();
    const double pivoting_difference =
        (approach(lemke.after, scene.contacts) - reference).cwiseAbs().maxCoeff();
    worst.see(difference / scale);
    REQUIRE(difference <= 1e-8 * scale);
    REQUIRE(pivoting_difference <= 1e-10 * scale);
  }
  CHECK(compared > t::configurations / 5);  // about three quarters of them
}
