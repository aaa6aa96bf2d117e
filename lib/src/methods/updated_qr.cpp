// SPDX-License-Identifier: GPL-3.0-or-later
#include "updated_qr.hpp"

#include <Eigen/Jacobi>
#include <algorithm>

namespace impulse::methods::detail {

using Eigen::Index;
using Eigen::VectorXd;

UpdatedQR::UpdatedQR(const Eigen::MatrixXd& G, const Eigen::VectorXd& g, double dependence)
    : G_(G), g_(g), dependence_(dependence) {
  const Index capacity = std::min(G.rows(), G.cols());
  Q_.resize(G.rows(), capacity);
  R_ = Eigen::MatrixXd::Zero(capacity, capacity);
  c_ = VectorXd::Zero(capacity);
  columns_.reserve(static_cast<std::size_t>(capacity));
}

bool UpdatedQR::insert(Index j) {
  const auto k = static_cast<Index>(columns_.size());
  if (k == Q_.cols()) {
    return false;  // P spans the whole column space: every other column lies in it
  }
  const auto Qk = Q_.leftCols(k);
  VectorXd a = G_.col(j);
  const double norm = a.norm();
  // Gram-Schmidt twice: the second pass removes what rounding left of the first.
  VectorXd h = VectorXd::Zero(k);
  for (int pass = 0; pass < 2; ++pass) {
    const VectorXd coefficients = Qk.transpose() * a;
    a.noalias() -= Qk * coefficients;
    h += coefficients;
  }
  const double rho = a.norm();
  double largest = norm;
  for (const double n : norms_) {
    largest = std::max(largest, n);
  }
  if (!(rho > dependence_ * largest)) {
    return false;
  }
  Q_.col(k) = a / rho;
  R_.col(k).head(k) = h;
  R_(k, k) = rho;
  c_(k) = Q_.col(k).dot(g_);
  columns_.push_back(j);
  norms_.push_back(norm);
  return true;
}

void UpdatedQR::remove(std::size_t position) {
  const auto k = static_cast<Index>(columns_.size());
  const auto p = static_cast<Index>(position);
  // Without column p, the columns after it are upper Hessenberg: one rotation per column
  // zeroes its entry below the diagonal, turning the rows of R and c and the columns of Q
  // alike (Q R and Q^T g unchanged).
  for (Index i = p; i + 1 < k; ++i) {
    R_.col(i).head(i + 2) = R_.col(i + 1).head(i + 2);
  }
  R_.col(k - 1).setZero();
  for (Index i = p; i + 1 < k; ++i) {
    Eigen::JacobiRotation<double> rotation;
    rotation.makeGivens(R_(i, i), R_(i + 1, i));
    R_.block(i, i, 2, k - 1 - i).applyOnTheLeft(0, 1, rotation.adjoint());
    R_(i + 1, i) = 0.0;
    c_.segment(i, 2).applyOnTheLeft(0, 1, rotation.adjoint());
    Q_.middleCols(i, 2).applyOnTheRight(0, 1, rotation);
  }
  R_.row(k - 1).setZero();
  c_(k - 1) = 0.0;
  columns_.erase(columns_.begin() + static_cast<std::ptrdiff_t>(position));
  norms_.erase(norms_.begin() + static_cast<std::ptrdiff_t>(position));
}

VectorXd UpdatedQR::solve() const {
  const auto k = static_cast<Index>(columns_.size());
  return R_.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(c_.head(k));
}

VectorXd UpdatedQR::residual() const {
  const auto k = static_cast<Index>(columns_.size());
  VectorXd r = g_;
  r.noalias() -= Q_.leftCols(k) * c_.head(k);
  return r;
}

}  // namespace impulse::methods::detail
