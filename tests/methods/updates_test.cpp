// SPDX-License-Identifier: GPL-3.0-or-later
// The active-set method as it now runs (a QR factorisation of its columns updated at each pivot,
// started from the paper's solution) against a different method on the same problems: Lemke's
// pivoting on A and B. Every solution of the complementarity problem gives the same G F (the
// velocities after), and where both report the least-norm solution it is unique; those are the
// comparisons. Random scenes, degenerate hand-made factors (equal, zero and dependent columns,
// more contacts than degrees of freedom), and the friction problem's pivoting on modes against
// Lemke's method.
#include <Eigen/QR>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "impulse/core/solve.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "multipoint/random_scene.hpp"
#include "scenes.hpp"

using Eigen::MatrixXd;
using Eigen::VectorXd;
using impulse::Elasticity;
namespace mp = impulse::multipoint;
namespace me = impulse::methods;
namespace t = impulse::test;

namespace {

// G F of each answer against the size of G's terms: |G F1 - G F2| <= tol (|G| |F| + |g|).
void same_motion(const MatrixXd& G, const VectorXd& g, const VectorXd& F1, const VectorXd& F2,
                 double tolerance) {
  const double scale =
      (G.cwiseAbs() * (F1.cwiseAbs() + F2.cwiseAbs())).maxCoeff() + g.cwiseAbs().maxCoeff();
  CAPTURE(F1.transpose(), F2.transpose());
  CHECK((G * (F1 - F2)).cwiseAbs().maxCoeff() <= tolerance * scale);
}

}  // namespace

TEST_CASE("Active set on the factor, from zero, and Lemke's pivoting agree on random factors",
          "[methods][property]") {
  // Random G (3 to 9 rows, 1 to 12 columns: often more contacts than rows, so dependent) and g,
  // with some columns repeated, some zero, some the sum of two others: the degenerate cases of
  // scenes (parallel contacts, a contact no body can move along, a box on two boxes).
  t::Sampler sample("updates random factors");
  int dependent = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto m = static_cast<Eigen::Index>(sample.integer(3, 9));
    const auto n = static_cast<Eigen::Index>(sample.integer(1, 12));
    MatrixXd G(m, n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const int kind = sample.integer(0, 9);
      if (kind == 0 && k > 0) {
        G.col(k) = G.col(sample.integer(0, static_cast<int>(k) - 1));  // a repeated column
      } else if (kind == 1) {
        G.col(k).setZero();  // a contact that nothing can move along
      } else if (kind == 2 && k > 1) {
        G.col(k) = G.col(k - 1) + G.col(k - 2);  // a dependent one
      } else {
        for (Eigen::Index r = 0; r < m; ++r) {
          G(r, k) = sample.uniform(-1.0, 1.0);
        }
      }
    }
    VectorXd g(m);
    for (Eigen::Index r = 0; r < m; ++r) {
      g(r) = sample.uniform(-2.0, 2.0);
    }
    const MatrixXd A = G.transpose() * G;
    const VectorXd B = G.transpose() * g;
    Eigen::ColPivHouseholderQR<MatrixXd> qr(G);
    dependent += qr.rank() < n ? 1 : 0;
    CAPTURE(i, m, n);
    const auto active = me::active_set(G, g);
    const auto lemke = me::lemke(A, B);
    REQUIRE(active.status == me::LcpStatus::solved);
    if (lemke.status != me::LcpStatus::solved) {
      continue;  // rounding left Lemke's tableau inaccurate: nothing to compare with
    }
    CHECK(active.Fdt.minCoeff() >= 0.0);
    CHECK(active.residual <= 1e-10 * active.scale);
    same_motion(G, g, active.Fdt, lemke.Fdt, 1e-9);
    if (active.least_norm && lemke.least_norm) {
      const double size = active.Fdt.cwiseAbs().maxCoeff() + lemke.Fdt.cwiseAbs().maxCoeff();
      CHECK((active.Fdt - lemke.Fdt).cwiseAbs().maxCoeff() <= 1e-8 * size + 1e-300);
    }
  }
  CHECK(dependent > t::configurations / 4);
}

TEST_CASE("Started from the paper's solution: the same answer as Lemke's pivoting",
          "[methods][property]") {
  // Random scenes at random elasticities: where the paper's impulses all push the method returns
  // them without a pivot, where they pull it pivots from them. Either way the velocities after
  // are Lemke's, and so are the impulses where both are the least-norm ones.
  t::Sampler sample("updates warm start");
  int pulled = 0;
  int compared = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    std::vector<Elasticity> es;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      es.emplace_back(sample.uniform(1.0, 2.0));
    }
    const mp::Configuration c(scene.bodies, es, scene.contacts);
    const impulse::ContactSystem system = c.assemble();
    const impulse::Solution paper = impulse::solve(system);
    if (paper.status != impulse::SolveStatus::success || paper.condition_estimate > 1e8) {
      continue;
    }
    CAPTURE(i, scene.bodies.size(), scene.contacts.size(), paper.Fdt.transpose());
    pulled += paper.Fdt.minCoeff() < 0.0 ? 1 : 0;
    const auto warm = me::solve_complementarity(system, paper, {});
    me::ComplementarityOptions pivot;
    pivot.algorithm = me::LcpAlgorithm::lemke;
    const auto lemke = me::solve_complementarity(system, pivot);
    REQUIRE(warm.status == me::LcpStatus::solved);
    CHECK(warm.algorithm == me::LcpAlgorithm::active_set);
    if (lemke.status != me::LcpStatus::solved) {
      continue;
    }
    ++compared;
    MatrixXd G;
    VectorXd g;
    system.factor(G, g);
    same_motion(G, g, warm.Fdt, lemke.Fdt, 1e-9);
    if (warm.least_norm && lemke.least_norm) {
      const double size = warm.Fdt.cwiseAbs().maxCoeff() + lemke.Fdt.cwiseAbs().maxCoeff();
      CHECK((warm.Fdt - lemke.Fdt).cwiseAbs().maxCoeff() <= 1e-8 * size + 1e-300);
    }
    if (paper.Fdt.minCoeff() >= 0.0) {
      CHECK(warm.iterations == 0);  // the paper's answer, taken as it is
    }
  }
  CHECK(pulled > t::configurations / 10);
  CHECK(compared > t::configurations / 2);
}

TEST_CASE("The page's scenes of 100 contacts: the paper's answer, with no pivot",
          "[methods][section5]") {
  // A stack of 50 boxes, a pyramid and a cradle of 101 balls (bench/scenes.hpp): the paper's
  // impulses all push, so complementarity returns them (the least-norm solution) as they are;
  // Lemke's pivoting reaches the same impulses after about 100 pivots.
  for (const char* kind : {"stack", "pyramid", "cradle"}) {
    CAPTURE(kind);
    const auto scene = impulse::scenes::generate(kind, 100, 1);
    const mp::Configuration c = impulse::scenes::configuration(scene);
    const impulse::ContactSystem system = c.assemble();
    const impulse::Solution paper = impulse::solve(system);
    REQUIRE(paper.Fdt.minCoeff() > 0.0);
    const auto warm = me::solve_complementarity(system, paper, {});
    CHECK(warm.iterations == 0);
    CHECK(warm.least_norm);
    CHECK(warm.Fdt == paper.Fdt);
    me::ComplementarityOptions pivot;
    pivot.algorithm = me::LcpAlgorithm::lemke;
    const auto lemke = me::solve_complementarity(system, pivot);
    REQUIRE(lemke.status == me::LcpStatus::solved);
    CHECK(lemke.iterations >= 100);
    CHECK((warm.Fdt - lemke.Fdt).cwiseAbs().maxCoeff() <= 1e-10 * paper.Fdt.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("Friction: pivoting on modes and Lemke's method reach the same bodies after",
          "[methods][friction]") {
  // Stacks of boxes landing with and without a sideways speed, mu = 0.5 (where the pivoting on
  // modes ends at a solution): its impulses meet the conditions, and Lemke's method alone (no
  // least-norm choice, so no pivoting on modes) gives the same velocities after.
  for (const std::size_t contacts : {std::size_t{4}, std::size_t{10}, std::size_t{40}}) {
    for (const bool sliding : {false, true}) {
      CAPTURE(contacts, sliding);
      auto scene = impulse::scenes::stack(contacts, 1);
      if (sliding) {
        for (mp::Body& body : scene.bodies) {
          if (auto* box = std::get_if<impulse::rigid_2d::RigidBody>(&body)) {
            box->p.x() += box->mass;
          }
        }
      }
      const mp::Configuration c(scene.bodies,
                                std::vector<Elasticity>(scene.bodies.size(), scene.elasticity),
                                scene.contacts);
      const std::vector<double> mu(contacts, 0.5);
      const auto modes = me::resolve_friction_complementarity(c, mu);
      const auto lemke = me::resolve_friction_complementarity(c, mu, 1e-10, false);
      REQUIRE(modes.solution.status == me::LcpStatus::solved);
      REQUIRE(lemke.solution.status == me::LcpStatus::solved);
      CHECK(modes.solution.algorithm == me::FrictionAlgorithm::modes);
      CHECK(lemke.solution.algorithm == me::FrictionAlgorithm::lemke);
      const VectorXd u_modes = modes.solution.u_after;
      const VectorXd u_lemke = lemke.solution.u_after;
      const double scale = u_modes.cwiseAbs().maxCoeff() + u_lemke.cwiseAbs().maxCoeff();
      CHECK((u_modes - u_lemke).cwiseAbs().maxCoeff() <= 1e-9 * scale);
      CHECK((modes.solution.normal - lemke.solution.normal).cwiseAbs().maxCoeff() <=
            1e-9 * modes.solution.normal.cwiseAbs().maxCoeff());
    }
  }
}
