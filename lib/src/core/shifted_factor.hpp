// SPDX-License-Identifier: GPL-3.0-or-later
// The sparse method's one factorisation: M + lambda I = L D L^T (M is A, or G G^T), by
// CHOLMOD's simplicial LDL^T with its choice of ordering (AMD here) when the library is built with
// SuiteSparse (IMPULSELAB_SUITESPARSE), by Eigen's simplicial LDL^T with an approximate minimum
// degree ordering otherwise. Either gives the same factor up to rounding and the ordering; the
// sparse method's results agree within its stated tolerances (tests/multipoint/sparse_test.cpp
// runs in both builds).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace impulse::detail {

class ShiftedFactor {
 public:
  ShiftedFactor();
  ~ShiftedFactor();
  ShiftedFactor(const ShiftedFactor&) = delete;
  ShiftedFactor& operator=(const ShiftedFactor&) = delete;

  // Factors M + lambda I (M symmetric positive semi-definite, lambda > 0). False if it failed.
  bool compute(const Eigen::SparseMatrix<double>& M, double lambda);
  // (M + lambda I)^-1 r into x (resized to fit), with the factorisation's workspace kept from
  // one call to the next: conjugate gradients call it at every step, and an allocation of a
  // vector of every contact at each call (CHOLMOD's solution and workspace, Eigen's result) cost
  // more on 100,000 contacts than the triangular solves themselves, the allocator handing the
  // memory back to the system and faulting it in again. NaN everywhere if the solve failed.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
  // The pivots D of L D L^T (for a Cholesky factor L L^T, the squares of L's diagonal), in the
  // order of elimination.
  [[nodiscard]] Eigen::VectorXd pivots() const;

 private:
  struct Backend;
  std::unique_ptr<Backend> backend_;
};

}  // namespace impulse::detail
