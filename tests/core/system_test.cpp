// SPDX-License-Identifier: GPL-3.0-or-later
#include <catch2/catch.hpp>

#include "impulse/core/error.hpp"
#include "impulse/core/system.hpp"

using impulse::BlockContribution;
using impulse::ContactSystem;
using impulse::InvalidInput;
using impulse::ScalarContribution;

namespace {
// A hand-made block without a factor.
BlockContribution block(std::vector<Eigen::Index> contacts, Eigen::MatrixXd a, Eigen::VectorXd b) {
  BlockContribution result;
  result.contacts = std::move(contacts);
  result.a = std::move(a);
  result.b = std::move(b);
  return result;
}
}  // namespace

TEST_CASE("The single-contact sum adds a's and b's", "[system]") {
  // Section 1.3: Fdt (a1 + a2) = b1 + b2.
  constexpr ScalarContribution sum = ScalarContribution{0.5, 3.0} + ScalarContribution{0.25, -1.0};
  STATIC_REQUIRE(sum.a == 0.75);
  STATIC_REQUIRE(sum.b == 2.0);
}

TEST_CASE("A block lands at the rows and columns of its contacts", "[system]") {
  // A body touching contacts 2 and 0 (in that order) of a 3-contact system: its a(0,0) is the
  // global (2,2), its a(0,1) the global (2,0), and so on. Contact 1 is untouched.
  ContactSystem system(3);
  system += block({2, 0}, Eigen::Matrix2d{{1, 2}, {3, 4}}, Eigen::Vector2d{5, 6});
  const Eigen::Matrix3d expected_A{{4, 0, 3}, {0, 0, 0}, {2, 0, 1}};
  const Eigen::Vector3d expected_B{6, 0, 5};
  CHECK(system.A() == expected_A);
  CHECK(system.B() == expected_B);

  // A second body sharing contact 0 adds on top (the ⊕).
  system += block({0}, Eigen::Matrix<double, 1, 1>{10}, Eigen::Matrix<double, 1, 1>{1});
  CHECK(system.A()(0, 0) == 14);
  CHECK(system.B()(0) == 7);
}

TEST_CASE("A malformed block is refused", "[system][errors]") {
  ContactSystem system(2);
  CHECK_THROWS_MATCHES(
      system += block({0, 2}, Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero()), InvalidInput,
      Catch::Matchers::Message("contact index must be in [0, 2), got 2"));
  CHECK_THROWS_WITH(system += block({1, 1}, Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero()),
                    "a block must list each contact once, got contact 1 twice");
  CHECK_THROWS_WITH(system += block({0, 1}, Eigen::Matrix3d::Identity(), Eigen::Vector2d::Zero()),
                    Catch::Matchers::Contains("got 3x3 and 2"));
  CHECK_THROWS_WITH(system += (ScalarContribution{1, 1}),
                    "a single-contact contribution needs a system of 1 contact, got 2");
  CHECK_THROWS_WITH(ContactSystem(-1), "number of contacts must be at least 0, got -1");
  const auto wrong_shape = [] {
    return ContactSystem(Eigen::MatrixXd::Zero(2, 3), Eigen::VectorXd::Zero(2));
  };
  CHECK_THROWS_WITH(wrong_shape(), "A must be square and match B, got A 2x3 and B of size 2");
  // Nothing half-added: the failed calls left the system as it was.
  CHECK(system.A().isZero());
}

TEST_CASE("Blocks that carry their factor keep the system factored", "[system]") {
  // Body 1 touches contacts 0 and 1 with factor G1 (2 rows), body 2 touches contact 1 with G2
  // (1 row). The stacked factor has 3 rows, each block's columns at its contacts, and it
  // reproduces the summed A = G^T G and B = G^T w.
  const Eigen::Matrix2d G1{{1, 2}, {0, 3}};
  const Eigen::Vector2d w1{1, -1};
  const Eigen::Matrix<double, 1, 1> G2{4};
  const Eigen::Matrix<double, 1, 1> w2{2};
  ContactSystem system(2);
  system += BlockContribution{{0, 1}, G1.transpose() * G1, G1.transpose() * w1, G1, w1};
  system += BlockContribution{{1}, G2.transpose() * G2, G2.transpose() * w2, G2, w2};
  REQUIRE(system.has_factor());
  Eigen::MatrixXd G;
  Eigen::VectorXd w;
  system.factor(G, w);
  const Eigen::Matrix<double, 3, 2> expected_G{{1, 2}, {0, 3}, {0, 4}};
  CHECK(G == expected_G);
  CHECK(w == Eigen::Vector3d(1, -1, 2));
  CHECK(G.transpose() * G == system.A());
  CHECK(G.transpose() * w == system.B());

  // A block without a factor ends it: the solver then works on A.
  system += block({0}, Eigen::Matrix<double, 1, 1>{1}, Eigen::Matrix<double, 1, 1>{0});
  CHECK_FALSE(system.has_factor());
  CHECK_FALSE(ContactSystem(Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero()).has_factor());
}

TEST_CASE("A factor of the wrong shape is refused", "[system][errors]") {
  ContactSystem system(2);
  const Eigen::Matrix<double, 2, 3> G = Eigen::Matrix<double, 2, 3>::Zero();
  CHECK_THROWS_WITH(
      system += (BlockContribution{
          {0, 1}, Eigen::Matrix2d::Zero(), Eigen::Vector2d::Zero(), G, Eigen::Vector2d::Zero()}),
      "a block's factor must have 2 columns and one scaled velocity per row, got 2x3 and 2");
}
