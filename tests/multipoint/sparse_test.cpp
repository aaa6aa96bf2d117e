// SPDX-License-Identifier: GPL-3.0-or-later
// Sections 4 and 5 at scale: the sparse storage and the sparse method against the
// dense complete orthogonal decomposition, on generated stacks, pyramids and cradles, and on
// dependent systems whose minimum-norm impulses are worked by hand.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "impulse/core/solve.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "multipoint/random_scene.hpp"
#include "scenes.hpp"

using Eigen::Vector2d;
using impulse::BlockContribution;
using impulse::ContactSystem;
using impulse::Elasticity;
using impulse::SolveMethod;
using impulse::SolverOptions;
using impulse::Storage;
using impulse::material_2d::PointMass;
using impulse::multipoint::Body;
using impulse::multipoint::Contact;
using impulse::multipoint::StaticBody;
using impulse::rigid_2d::RigidBody;
namespace mp = impulse::multipoint;
namespace t = impulse::test;

namespace {

SolverOptions with(SolveMethod method) {
  SolverOptions options;
  options.method = method;
  return options;
}

std::vector<Elasticity> everyone(const impulse::scenes::Scene& scene) {
  return std::vector<Elasticity>(scene.bodies.size(), scene.elasticity);
}

}  // namespace

TEST_CASE("Sparse storage holds the same A and B as dense storage", "[section4][sparse]") {
  // The block of "A block lands at the rows and columns of its contacts" (system_test.cpp),
  // added to a system kept sparse: (v, k) of the block lands at (contact v, contact k), and the
  // entries of a second body sharing contact 0 are summed.
  BlockContribution first;
  first.contacts = {2, 0};
  first.a = Eigen::Matrix2d{{1, 2}, {3, 4}};
  first.b = Eigen::Vector2d{5, 6};
  BlockContribution second;
  second.contacts = {0};
  second.a = Eigen::MatrixXd::Constant(1, 1, 10.0);
  second.b = Eigen::VectorXd::Constant(1, 1.0);
  ContactSystem sparse(3, Storage::sparse);
  sparse += first;
  sparse += second;
  REQUIRE(sparse.is_sparse());
  CHECK(sparse.A().size() == 0);  // no dense matrix is kept
  const Eigen::Matrix3d expected_A{{14, 0, 3}, {0, 0, 0}, {2, 0, 1}};
  CHECK(Eigen::MatrixXd(sparse.sparse_A()) == expected_A);
  CHECK(sparse.B() == Eigen::Vector3d(7, 0, 5));

  // Automatic storage: dense up to sparse_threshold contacts, sparse above.
  CHECK_FALSE(ContactSystem(impulse::sparse_threshold).is_sparse());
  CHECK(ContactSystem(impulse::sparse_threshold + 1).is_sparse());
}

TEST_CASE("Sparse storage builds A and the stacked factor G as dense storage does, entry for entry",
          "[section4][sparse]") {
  // Three blocks over 60 contacts, sharing contacts, in an order that is not sorted: a body
  // touching 40 contacts (its columns hold more than the 32 entries sorted by insertion), one of
  // 20 and one of 5, with random a, b, G, w (a need not be G^T G for the storage). The dense
  // storage adds each entry into its place in the order added; the sparse one sorts and sums
  // them column by column. Both sum a place's entries in the order added, so they agree exactly.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Index> order(60);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), random);
  const auto block = [&](std::size_t first, std::size_t count, Eigen::Index rows) {
    BlockContribution b;
    b.contacts.assign(order.begin() + static_cast<std::ptrdiff_t>(first),
                      order.begin() + static_cast<std::ptrdiff_t>(first + count));
    const auto n = static_cast<Eigen::Index>(count);
    b.a = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return value(random); });
    b.b = Eigen::VectorXd::NullaryExpr(n, [&] { return value(random); });
    b.G = Eigen::MatrixXd::NullaryExpr(rows, n, [&] { return value(random); });
    b.w = Eigen::VectorXd::NullaryExpr(rows, [&] { return value(random); });
    return b;
  };
  const std::vector<BlockContribution> blocks{block(0, 40, 3), block(30, 20, 2), block(35, 5, 3)};
  ContactSystem sparse(60, Storage::sparse);
  ContactSystem dense(60, Storage::dense);
  for (const BlockContribution& b : blocks) {
    sparse += b;
    dense += b;
  }
  CHECK(Eigen::MatrixXd(sparse.sparse_A()) == dense.A());
  CHECK(sparse.sparse_A().nonZeros() == 40 * 40 + 20 * 20 - 10 * 10);  // overlaps counted once
  Eigen::SparseMatrix<double> G_sparse;
  Eigen::VectorXd w_sparse;
  sparse.factor(G_sparse, w_sparse);
  Eigen::MatrixXd G_dense;
  Eigen::VectorXd w_dense;
  dense.factor(G_dense, w_dense);
  CHECK(Eigen::MatrixXd(G_sparse) == G_dense);
  CHECK(w_sparse == w_dense);
}

TEST_CASE("Sparse method: a point mass on two parallel contacts gets equal impulses",
          "[section4][sparse][dependent]") {
  // m = 2 falling at (0, -1) onto the ground at two points, both with its outward normal
  // (0, -1), elasticity 1. (4.5): A = [[1/2, 1/2], [1/2, 1/2]], B = (p.n / m) (1, 1) = (1, 1).
  // Every F1 + F2 = 2 stops it; the least norm is F1 = F2 = 1.
  const std::vector<Body> bodies{PointMass{2.0, {0, -2}}, StaticBody{}};
  const std::vector<Contact> contacts{{0, 1, {0, -1}, {-1, 0}}, {0, 1, {0, -1}, {1, 0}}};
  const std::vector<Elasticity> es(2, Elasticity::inelastic());
  for (const auto storage : {Storage::dense, Storage::sparse}) {
    const auto system = mp::assemble(bodies, es, contacts, storage);
    const auto s = impulse::solve(system, with(SolveMethod::sparse));
    CAPTURE(system.is_sparse());
    REQUIRE(s.method == SolveMethod::sparse);
    CHECK(s.A.size() == 0);  // the sparse method gives A as sparse_A
    CHECK(s.sparse_A.nonZeros() == 4);
    CHECK(s.rank_estimated);
    CHECK(s.factored_velocities);  // one velocity (the vertical) moved by two contacts
    CHECK(s.rank == 1);
    CHECK(s.dependent);
    CHECK(s.consistent);
    CHECK(s.Fdt(0) == Approx(1.0).epsilon(1e-12));
    CHECK(s.Fdt(1) == Approx(1.0).epsilon(1e-12));
  }
}

TEST_CASE("Sparse method: a box landing flat on three points shares the impulse equally",
          "[section5][sparse][dependent]") {
  // Box of mass 1 (any I), no spin, falling at (0, -1) onto points at x = -1, 0, 1 under its
  // bottom face (y = -0.5), elasticity 1. Stopping it needs F1 + F2 + F3 = 1 (momentum) and,
  // for no spin, arms det(r, n) = -x: F1 - F3 = 0. Among (a, b, a) with 2a + b = 1 the least
  // norm minimises 2a^2 + b^2: a = b = 1/3. Three contacts on two free directions: rank 2.
  const RigidBody box{1.0, 5.0 / 12.0, {0, 0}, {0, -1}, 0.0};
  const std::vector<Body> bodies{box, StaticBody{}};
  std::vector<Contact> contacts;
  for (const double x : {-1.0, 0.0, 1.0}) {
    contacts.push_back({0, 1, {0, -1}, {x, -0.5}});
  }
  const std::vector<Elasticity> es(2, Elasticity::inelastic());
  const auto system = mp::assemble(bodies, es, contacts, Storage::sparse);
  const auto s = impulse::solve(system, with(SolveMethod::sparse));
  REQUIRE(s.method == SolveMethod::sparse);
  CHECK(s.factored_velocities);  // two velocities (vertical, spin) moved by three contacts
  CHECK(s.rank == 2);
  CHECK(s.dependent);
  for (Eigen::Index v = 0; v < 3; ++v) {
    CHECK(s.Fdt(v) == Approx(1.0 / 3.0).epsilon(1e-12));
  }
  // The dense method finds the same.
  const auto dense = impulse::solve(system, with(SolveMethod::dense));
  CHECK(dense.method == SolveMethod::dense);
  CHECK(dense.A.rows() == 3);
  CHECK((dense.Fdt - s.Fdt).norm() <= 1e-12);
}

TEST_CASE("Dense and sparse methods agree on generated scenes", "[section4][section5][sparse]") {
  // The same assembled system solved both ways: the dense complete orthogonal decomposition of
  // G and the sparse method. Both return the minimum-norm least-squares impulses, so they must
  // agree to within the rounding that the conditioning allows; the issue asks for 1e-8.
  t::Worst worst("dense vs sparse impulses, relative (max norm)");
#ifdef NDEBUG
  constexpr std::size_t largest = 1000;
#else
  // Unoptimised Eigen (the asan preset's Debug build) is about a hundred times slower: the dense
  // method at 400 and 1,000 contacts took seven minutes there. The sanitizers look for memory
  // errors and undefined behaviour, which the smaller scenes reach through the same code.
  constexpr std::size_t largest = 256;
#endif
  for (const std::string kind : {"stack", "pyramid", "cradle"}) {
    for (const std::size_t contacts : {1u, 2u, 7u, 10u, 33u, 100u, 256u, 400u, 1000u}) {
      for (const std::uint64_t seed : {1u, 2u, 3u}) {
        if (contacts > largest) {
          continue;
        }
        if (contacts > 400 && seed > 1) {
          continue;  // the dense method's cubic cost: one scene of each kind at 1,000
        }
        const auto scene = impulse::scenes::generate(kind, contacts, seed);
        REQUIRE(scene.contacts.size() == contacts);
        const auto system = mp::assemble(scene.bodies, everyone(scene), scene.contacts);
        const auto dense = impulse::solve(system, with(SolveMethod::dense));
        const auto sparse = impulse::solve(system, with(SolveMethod::sparse));
        REQUIRE(dense.method == SolveMethod::dense);
        REQUIRE(sparse.method == SolveMethod::sparse);
        const double scale = dense.Fdt.cwiseAbs().maxCoeff();
        const double error = (sparse.Fdt - dense.Fdt).cwiseAbs().maxCoeff() / scale;
        CAPTURE(kind, contacts, seed, dense.rank, sparse.rank, sparse.iterations, error,
                dense.condition_estimate);
        worst.see(error);
        REQUIRE(error <= 1e-8);
        CHECK(sparse.consistent);
        CHECK(sparse.rank == dense.rank);  // the estimate is right on these scenes
        if (contacts >= 100) {
          // A pyramid's boxes have four contacts and two moved velocities (vertical, spin) each:
          // the sparse method factors those; a stack (two contacts, two velocities a box) and a
          // cradle (one contact, one velocity a ball) keep A.
          CHECK(sparse.factored_velocities == (kind == "pyramid"));
        }
      }
    }
  }
}

TEST_CASE("Large scenes take the sparse path and keep the physical laws",
          "[section4][section5][sparse][property]") {
  SECTION("a cradle of 2,000 elastic balls conserves energy and momentum") {
    // Elasticity 2 conserves kinetic energy (section 1.3), and the impulses are internal:
    // the total momentum (1, 0) of the first ball is kept.
    const auto scene = impulse::scenes::cradle(2000);
    const auto r = mp::resolve(scene.bodies, scene.elasticity, scene.contacts);
    REQUIRE(r.solution.method == SolveMethod::sparse);
    CHECK(r.solution.A.size() == 0);
    CHECK(r.solution.sparse_A.rows() == 2000);
    CHECK(r.solution.iterations > 0);
    CHECK(t::energy(r.after) == Approx(t::energy(scene.bodies)).epsilon(1e-10));
    CHECK((t::momentum(r.after) - Vector2d(1, 0)).norm() <= 1e-10);
  }
  SECTION("a stack and a pyramid at elasticity 1 end with equal normal velocities") {
    // Elasticity 1 equalises the normal velocities at every contact (section 1.3). Scale: the
    // velocity changes A_vk Fdt_k that sum to each approach after, as in random_scene.hpp.
    for (const auto& scene : {impulse::scenes::stack(1000), impulse::scenes::pyramid(1000)}) {
      const auto r = mp::resolve(scene.bodies, Elasticity::inelastic(), scene.contacts);
      REQUIRE(r.solution.method == SolveMethod::sparse);
      const Eigen::VectorXd terms =
          Eigen::SparseMatrix<double>(r.solution.sparse_A.cwiseAbs()) * r.solution.Fdt.cwiseAbs();
      const double scale =
          std::max(t::speed_scale({scene.bodies, scene.contacts}), terms.maxCoeff());
      CAPTURE(r.solution.iterations, r.solution.rank);
      CHECK(t::worst_approach(r.after, scene.contacts) <= 1e-10 * scale);
      CHECK(r.solution.consistent);
    }
  }
}

TEST_CASE("Generated scenes: exact contact counts and scene files", "[section4][section5]") {
  // Counts: a stack of 5 contacts is 3 boxes (2 + 2 + 1), a pyramid of 10 is a base of 3 (6 on
  // the ground) and one box on two (4), a cradle of 4 has 5 balls.
  CHECK(impulse::scenes::stack(5).bodies.size() == 1 + 3);
  CHECK(impulse::scenes::pyramid(10).bodies.size() == 1 + 4);
  CHECK(impulse::scenes::cradle(4).bodies.size() == 5);
  const std::string json = impulse::scenes::to_json(impulse::scenes::cradle(1));
  CHECK(
      json ==
      "{\n  \"dimension\": 2,\n  \"elasticity\": 2,\n  \"bodies\": [\n"
      "    {\"name\": \"ball0\", \"kind\": \"material\", \"mass\": 1, \"velocity\": [1, 0]},\n"
      "    {\"name\": \"ball1\", \"kind\": \"material\", \"mass\": 1, \"velocity\": [0, 0]}\n"
      "  ],\n  \"contacts\": [\n"
      "    {\"bumper\": \"ball0\", \"wedge\": \"ball1\", \"normal\": [1, 0], \"point\": [0.5, 0]}\n"
      "  ]\n}\n");
  CHECK_THROWS_WITH(impulse::scenes::generate("tower", 3),
                    "scene kind must be stack, pyramid or cradle, got tower");
}

TEST_CASE("Dense and sparse methods agree on random small scenes", "[section5][sparse][property]") {
  // The random scenes of the section 4 and 5 property tests (2 to 6 bodies, 1 to 8 contacts,
  // masses over six orders of magnitude, many dependent): solved by both methods. Where the
  // system is well conditioned both minimum-norm solutions must agree (as the dense method does
  // with itself when it factors A instead of G, material_test.cpp).
  t::Sampler sample("sparse routes");
  t::Worst worst("dense vs sparse on random scenes, relative");
  int compared = 0;
  int dependent = 0;
  for (int i = 0; i < t::configurations; ++i) {
    const auto scene = t::random_scene(sample, t::Kinds::material_and_rigid, true);
    const std::vector<Elasticity> es(scene.bodies.size(), Elasticity(sample.uniform(0, 3)));
    const auto system = mp::assemble(scene.bodies, es, scene.contacts);
    const auto dense = impulse::solve(system, with(SolveMethod::dense));
    const auto sparse = impulse::solve(system, with(SolveMethod::sparse));
    if (dense.condition_estimate > 1e6) {
      continue;
    }
    ++compared;
    dependent += dense.dependent ? 1 : 0;
    const double error = (sparse.Fdt - dense.Fdt).norm() / std::max(1.0, dense.Fdt.norm());
    CAPTURE(i, dense.condition_estimate, dense.rank, sparse.rank, sparse.iterations,
            dense.Fdt.transpose(), sparse.Fdt.transpose());
    worst.see(error);
    REQUIRE(error <= 1e-8);
  }
  REQUIRE(compared > t::configurations * 9 / 10);
  REQUIRE(dependent > 0);
}
