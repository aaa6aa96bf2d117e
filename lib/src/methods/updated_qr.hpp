// SPDX-License-Identifier: GPL-3.0-or-later
// A QR factorisation of some columns of the factor G, kept up to date as columns enter and leave:
// the active-set method's least squares without a new factorisation at each pivot.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace impulse::methods::detail {

// G_P = Q R for a set P of the columns of G (m rows), in the order they entered: Q has
// orthonormal columns (m x k), R is k x k upper triangular, and c = Q^T g is kept beside them,
// so that the least-squares solution of G_P z ~ g is R^-1 c and its residual g - Q c.
//
// A column enters by classical Gram-Schmidt against Q, done twice ("twice is enough": Q stays
// orthonormal to rounding), O(m k); a column leaves by Givens rotations that restore R to
// triangular form and turn Q and c alike, O((m + k) k). A new factorisation of G_P would cost
// O(m k^2) each time.
class UpdatedQR {
 public:
  // `dependence`: a column whose part outside the span of those in P is at most this fraction of
  // the largest column norm of P (itself included) is taken as dependent and refused, as a
  // column-pivoted QR with that threshold would leave it out of the rank.
  UpdatedQR(const Eigen::MatrixXd& G, const Eigen::VectorXd& g, double dependence);

  // Appends column j of G to P. Returns false, changing nothing, if it is dependent.
  bool insert(Eigen::Index j);
  // Removes the column at `position` of columns().
  void remove(std::size_t position);

  // The columns of G in P, in the order of the factorisation.
  [[nodiscard]] const std::vector<Eigen::Index>& columns() const { return columns_; }
  // The least-squares solution z of G_P z ~ g, one entry per column of P in that order.
  [[nodiscard]] Eigen::VectorXd solve() const;
  // g - G_P z for that z: the part of g outside the span of G_P.
  [[nodiscard]] Eigen::VectorXd residual() const;

 private:
  const Eigen::MatrixXd& G_;
  const Eigen::VectorXd& g_;
  double dependence_;
  Eigen::MatrixXd Q_;  // m x capacity: the first k columns are Q
  Eigen::MatrixXd R_;  // capacity x capacity: the top-left k x k block is R
  Eigen::VectorXd c_;  // the first k entries are Q^T g
  std::vector<Eigen::Index> columns_;
  std::vector<double> norms_;  // each column's norm, for the dependence test
};

}  // namespace impulse::methods::detail
