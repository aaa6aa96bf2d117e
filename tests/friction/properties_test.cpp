// SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the contact with friction over random bodies (seeded by Catch's --rng-seed):
// the paper's impulse without friction, Coulomb's bound, the conservation laws, and the energy
// the three laws of restitution give.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "impulse/friction/bodies.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "physics.hpp"
#include "support/sampling.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::friction::ContactLaw;
using impulse::friction::ContactStatus;
using impulse::friction::RestitutionLaw;
using impulse::multipoint::Body;
using namespace impulse::test::friction;
namespace friction = impulse::friction;

namespace {

bool is_static(const Body& body) {
  return std::holds_alternative<impulse::multipoint::StaticBody>(body);
}

// The paper's impulse for the hit at one elasticity, from the section's own module:
// material_2d::collide for two point masses, rigid_2d::collide for two rigid bodies, and the
// many-contact solver with one contact (multipoint::resolve) where a static body takes part.
struct Paper {
  double Fdt;
  Body bumper, wedge;
};

Paper paper(const Hit& h, Elasticity e) {
  using impulse::material_2d::PointMass;
  using impulse::rigid_2d::RigidBody;
  if (const auto* b = std::get_if<PointMass>(&h.bumper)) {
    if (const auto* w = std::get_if<PointMass>(&h.wedge)) {
      const auto c = impulse::material_2d::collide(*b, e, *w, e, h.normal);
      return {c.solution.Fdt, c.bumper, c.wedge};
    }
  }
  if (const auto* b = std::get_if<RigidBody>(&h.bumper)) {
    if (const auto* w = std::get_if<RigidBody>(&h.wedge)) {
      const auto c = impulse::rigid_2d::collide(*b, e, *w, e, h.point, h.normal);
      return {c.solution.Fdt, c.bumper, c.wedge};
    }
  }
  const std::vector<Body> bodies{h.bumper, h.wedge};
  const impulse::multipoint::Contact contact{0, 1, h.normal, h.point};
  const auto r = impulse::multipoint::resolve(bodies, e, std::span(&contact, 1));
  REQUIRE(r.solution.status == impulse::SolveStatus::success);
  return {r.solution.Fdt(0), r.after[0], r.after[1]};
}

// Whether the environment asks for the figures of the report (as impulse::test::Worst).
bool report() {
  return std::getenv("IMPULSELAB_REPORT_WORST") != nullptr;
}

}  // namespace

TEST_CASE("Without friction the three laws give the paper's impulse at a single contact",
          "[friction]") {
  // Without friction nothing couples the normal motion to the tangential one: u_n grows at
  // W_nn = A from -u (u the approach), compression ends at u / A, and each law ends restitution
  // at e u / A: Newton where u_n = (e - 1) u, Poisson at e (u / A), the energetic law where
  // A x^2 / 2 = (e - 1)^2 u^2 / (2 A). That is the paper's Fdt = B / A with B = e u.
  for (const Pairing pairing : {Pairing::material, Pairing::rigid, Pairing::material_static,
                                Pairing::rigid_static, Pairing::mixed}) {
    CAPTURE(name(pairing));
    impulse::test::Sampler sample(std::string("friction paper ") + name(pairing));
    impulse::test::Worst worst(std::string("friction: mu = 0 vs the paper, ") + name(pairing));
    int approaching = 0;
    for (int i = 0; i < impulse::test::configurations; ++i) {
      const Hit h = random_hit(sample, pairing);
      const Elasticity e(sample.uniform(1.0, 2.0));
      CAPTURE(i, h.point, h.normal, e.value());
      const Paper expected = paper(h, e);
      // Velocities are compared against the size of the terms they are made of. Where a static
      // body takes part, the paper's impulse comes from the many-contact solver, a least-squares
      // solve on the factor G (A = G^T G, B = G^T w) whose rounding is of the order of
      // eps |G| |w| = eps sqrt(A) e sqrt(2 E) in A Fdt: a body whose momentum lies mostly
      // away from the normal makes that larger than the speeds.
      const double A = friction::dynamics(h.bumper, h.wedge, h.point, h.normal).W(0, 0);
      const double scale = std::max(
          speed_scale(h), e.value() * std::sqrt(2 * A * (energy(h.bumper) + energy(h.wedge))));
      for (const RestitutionLaw law : all_laws) {
        CAPTURE(impulse::name_of(law));
        const auto c = friction::collide(h.bumper, h.wedge, h.point, h.normal, {0.0, e, law});
        CHECK(c.impulse.tangential == 0.0);
        if (c.impulse.status == ContactStatus::not_approaching) {
          // The paper's impulse would pull (or be zero): B = e u <= 0.
          CHECK(expected.Fdt <= 0.0);
          CHECK(c.impulse.normal == 0.0);
          continue;
        }
        REQUIRE(c.impulse.status == ContactStatus::resolved);
        approaching += law == RestitutionLaw::newton ? 1 : 0;
        // Compared as velocities: A (P - Fdt) against the speeds.
        const double error = A * std::abs(c.impulse.normal - expected.Fdt) / scale;
        worst.see(error);
        CHECK(error <= 1e-13);
        for (const auto& [got, want] : {std::pair{&c.after.bumper, &expected.bumper},
                                        std::pair{&c.after.wedge, &expected.wedge}}) {
          // The impulses agree within the error above, scale / A in impulse units.
          const double p_scale = momentum(*want).norm() + std::abs(expected.Fdt) +
                                 std::abs(c.impulse.normal) + scale / A;
          CHECK((momentum(*got) - momentum(*want)).norm() <= 1e-13 * p_scale);
        }
      }
    }
    // The sample is not all separating contacts: about half approach.
    CHECK(approaching > impulse::test::configurations / 4);
  }
}

TEST_CASE(
    "Coulomb's bound, momentum and energy over random contacts: the energetic law never "
    "gains energy",
    "[friction]") {
  impulse::test::Sampler sample("friction properties");
  impulse::test::Worst worst_energy("friction: energy identity");
  int newton_gains = 0;
  int poisson_gains = 0;
  int energetic_gains = 0;
  int resolved = 0;
  for (const Pairing pairing : {Pairing::material, Pairing::rigid, Pairing::material_static,
                                Pairing::rigid_static, Pairing::mixed}) {
    CAPTURE(name(pairing));
    for (int i = 0; i < impulse::test::configurations; ++i) {
      const Hit h = random_hit(sample, pairing);
      // mu from none to 100 (a quarter of the samples frictionless), elasticity in [1, 2].
      const double mu = sample.integer(0, 3) == 0 ? 0.0 : sample.log_uniform(1e-2, 1e2);
      const Elasticity e(sample.uniform(1.0, 2.0));
      CAPTURE(i, h.point, h.normal, mu, e.value());
      const double energy_before = energy(h.bumper) + energy(h.wedge);
      for (const RestitutionLaw law : all_laws) {
        CAPTURE(impulse::name_of(law));
        const auto c = friction::collide(h.bumper, h.wedge, h.point, h.normal, {mu, e, law});
        const auto& impulse = c.impulse;
        // Bodies of the sections always resolve (W is positive definite with one movable body).
        REQUIRE((impulse.status == ContactStatus::resolved ||
                 impulse.status == ContactStatus::not_approaching));
        if (impulse.status != ContactStatus::resolved) {
          continue;
        }
        resolved += 1;
        const double p_scale = momentum(h.bumper).norm() + momentum(h.wedge).norm() +
                               std::abs(impulse.normal) + std::abs(impulse.tangential);

        // Coulomb: the tangential impulse within mu times the normal one, which pushes.
        CHECK(impulse.normal > 0.0);
        CHECK(std::abs(impulse.tangential) <= mu * impulse.normal * (1 + 1e-12));

        // Momentum: what the bumper gains the wedge loses; against a static body, the movable
        // body gains exactly the impulse on it.
        const Vector2d J = friction::on_bumper(h.normal, impulse);
        const Vector2d bumper_gain = momentum(c.after.bumper) - momentum(h.bumper);
        const Vector2d wedge_gain = momentum(c.after.wedge) - momentum(h.wedge);
        if (!is_static(h.bumper)) {
          CHECK((bumper_gain - J).norm() <= 1e-13 * p_scale);
        }
        if (!is_static(h.wedge)) {
          CHECK((wedge_gain + J).norm() <= 1e-13 * p_scale);
        }
        if (!is_static(h.bumper) && !is_static(h.wedge)) {
          CHECK((bumper_gain + wedge_gain).norm() <= 1e-13 * p_scale);
        }
        // Angular momentum about the contact point: the impulses act there, so no body's
        // changes (a point mass sits at the point: its arm is zero).
        for (const auto& [before, after] :
             {std::pair{&h.bumper, &c.after.bumper}, std::pair{&h.wedge, &c.after.wedge}}) {
          const double L_before = angular_momentum_about(*before, h.point);
          const double L_after = angular_momentum_about(*after, h.point);
          double L_scale = std::abs(L_before);
          if (const auto* b = std::get_if<impulse::rigid_2d::RigidBody>(before)) {
            L_scale += (h.point - b->position).norm() * p_scale + std::abs(b->L);
          }
          CHECK(std::abs(L_after - L_before) <= 1e-13 * L_scale);
        }

        // Energy: the bodies' kinetic energy (from their states) changes by the works the
        // contact reports, int u . dP.
        const double energy_after = energy(c.after.bumper) + energy(c.after.wedge);
        const double change = energy_after - energy_before;
        const double e_scale = energy_before + energy_after + std::abs(impulse.work_compression) +
                               std::abs(impulse.work_tangential);
        worst_energy.see(std::abs(change - impulse.energy_change()) / e_scale);
        CHECK(std::abs(change - impulse.energy_change()) <= 1e-12 * e_scale);
        CHECK(impulse.work_compression <= 0.0);
        CHECK(impulse.work_restitution >= 0.0);
        CHECK(impulse.work_tangential <= 0.0);
        const bool gained = change > 1e-12 * e_scale;
        switch (law) {
          case RestitutionLaw::newton: {
            newton_gains += gained ? 1 : 0;
            // Newton's law itself, measured on the bodies after: the contact separates at
            // (e - 1) times the speed at which it approached.
            const Vector2d relative =
                velocity_at(c.after.bumper, h.point) - velocity_at(c.after.wedge, h.point);
            const double separation = -h.normal.dot(relative);
            // Applying an impulse of size |P| rounds the point velocities by about
            // eps |P| (1/m + |r|^2 / I): a nearly singular W (a heavy body with a small moment
            // of inertia) needs a large impulse, and its terms are then large beside the speeds.
            const double P = std::abs(impulse.normal) + std::abs(impulse.tangential);
            const double scale = speed_scale(h) + speed_scale(c.after.bumper, h.point) +
                                 speed_scale(c.after.wedge, h.point) + P * mobility(h);
            CHECK(std::abs(separation - (e.value() - 1) * -impulse.u_before.x()) <= 1e-12 * scale);
            break;
          }
          case RestitutionLaw::poisson:
            poisson_gains += gained ? 1 : 0;
            break;
          case RestitutionLaw::energetic:
            energetic_gains += gained ? 1 : 0;
            // Stronge's law dissipates: restitution gives back at most compression's work,
            // and friction only takes.
            CHECK(change <= 1e-12 * e_scale);
            break;
        }
      }
    }
  }
  // The same search finds Newton's law gaining energy (Kane and Levinson's paradox).
  CHECK(newton_gains > 0);
  CHECK(energetic_gains == 0);
  if (report()) {
    std::fprintf(stderr,
                 "friction: of %d resolved collisions per law, energy gained by Newton's law %d, "
                 "Poisson's %d, the energetic %d\n",
                 resolved / 3, newton_gains, poisson_gains, energetic_gains);
  }
}
