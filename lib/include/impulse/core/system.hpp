// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The system A·Fdt = B and how bodies' contributions are summed into it (the paper's ⊕).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace impulse {

/// @brief One body's share (a, b) of a single-contact system @f$ A\,F\,dt = B @f$.
///
/// Sections 1-3 of the paper: every body at the contact brings an @f$ a @f$ (dimension
/// 1/mass) and a @f$ b @f$ (dimension velocity); they are summed,
/// @f$ F\,dt\,(a_1 + a_2) = b_1 + b_2 @f$, and the impulse magnitude is @f$ B / A @f$.
/// Summing is `operator+`. A static body contributes the zero value.
struct ScalarContribution {
  double a = 0.0;  ///< the body's addition to A (inverse mass along the normal)
  double b = 0.0;  ///< the body's addition to B (elasticity times its normal velocity)
};

/// @brief The single-contact ⊕: @f$ (a_1, b_1) \oplus (a_2, b_2) = (a_1 + a_2, b_1 + b_2) @f$.
/// @param first one body's contribution
/// @param second the other body's contribution
/// @return the summed system (A, B)
[[nodiscard]] constexpr ScalarContribution operator+(ScalarContribution first,
                                                     ScalarContribution second) {
  return {first.a + second.a, first.b + second.b};
}

/// @brief One body's block of a many-contact system (sections 4 and 5).
///
/// `contacts[v]` is the global index of the v-th contact the body touches; `a(v, k)` is the
/// paper's @f$ a_{vk} @f$ between the body's v-th and k-th contacts and `b(v)` its @f$ b_v @f$.
/// Indices must be distinct.
///
/// A body's block is a Gram matrix: @f$ a = G^T G @f$ and @f$ b = G^T w @f$, where column v of
/// @f$ G @f$ is the body's generalised normal at contact v scaled by @f$ M^{-1/2} @f$ (one row per
/// degree of freedom) and @f$ w = e\,M^{1/2}\,\text{velocity} @f$. When a block carries `G` and
/// `w`, the solver can factor the stacked @f$ G @f$ instead of @f$ A @f$, which halves the digits
/// that an ill-conditioned system loses (see impulse::solve). Hand-made blocks may leave them
/// empty.
struct BlockContribution {
  std::vector<Eigen::Index> contacts;  ///< global contact indices, one per row/column of `a`
  Eigen::MatrixXd a;                   ///< the body's @f$ a_{vk} @f$, square
  Eigen::VectorXd b;                   ///< the body's @f$ b_v @f$
  Eigen::MatrixXd G;  ///< optional factor, one column per contact: @f$ a = G^T G @f$
  Eigen::VectorXd w;  ///< optional, with `G`: @f$ b = G^T w @f$
};

/// @brief How a ContactSystem keeps its matrix A.
enum class Storage {
  /// Dense up to sparse_threshold contacts, sparse above.
  automatic,
  /// An N×N dense matrix: N² numbers, whatever the scene.
  dense,
  /// Only the entries that bodies add: a body touching k contacts adds k² of them, so the
  /// storage grows with the number of contacts, not its square.
  sparse,
};

/// @brief Above this many contacts, Storage::automatic keeps A sparse and
/// SolveMethod::automatic solves it with the sparse method.
///
/// Up to it, the dense method is kept for what it gives: the complete orthogonal decomposition
/// of the factor G loses half the digits that factoring A does, decides the rank exactly and
/// serves every policy. Its cost is cubic: on the generated scenes of bench/ it takes about
/// 1 ms at 100 contacts, 4-13 ms at 256 and 0.2-0.8 s at 1,000 (the sparse method: 0.2-0.3 ms
/// at 256), and its N² storage is 0.5 MiB at 256 but 80 GB at 100,000. 256 keeps the dense cost
/// at a few milliseconds (bench/README.md).
inline constexpr Eigen::Index sparse_threshold = 256;

/// @brief The linear system @f$ \mathbf{A}\,\vec{F}dt = \vec{B} @f$ over N contacts.
///
/// Built empty (all zeros) for N contacts, then each body's BlockContribution is added at the
/// rows and columns of the contacts it touches: the paper's
/// @f$ \mathbf{A_1} \oplus \mathbf{A_2} \oplus \cdots @f$ (section 4.5). While every block
/// added carries its factor, the system keeps the stacked factor too
/// (@f$ A = G^T G @f$, @f$ B = G^T w @f$).
///
/// A is kept dense or sparse (see Storage); A() gives the dense matrix and sparse_A() a sparse
/// copy. A system kept sparse has no dense matrix: its A() is empty (0×0).
class ContactSystem {
 public:
  /// @brief An empty (zero) system over @p contacts contacts.
  /// @param contacts N, at least 0
  /// @param storage how to keep A; automatic: sparse above sparse_threshold contacts
  explicit ContactSystem(Eigen::Index contacts, Storage storage = Storage::automatic);

  /// @brief A system given directly, e.g. one worked by hand. It carries no factor.
  /// @param A square N×N matrix
  /// @param B vector of N; a size mismatch throws InvalidInput
  ContactSystem(Eigen::MatrixXd A, Eigen::VectorXd B);

  /// @brief The ⊕: adds @p block at the rows and columns of its contacts.
  /// @param block one body's contribution; its indices must be distinct and below size(),
  ///        its `a` square of the size of its index list, and its factor, if any, of matching
  ///        sizes (else InvalidInput, and the system is left unchanged)
  /// @return this system
  ContactSystem& operator+=(const BlockContribution& block);

  /// @brief The ⊕ of a block that is no longer needed: its factor is moved, not copied.
  /// @param block as for the other overload
  /// @return this system
  ContactSystem& operator+=(BlockContribution&& block);

  /// @brief The single-contact ⊕ on a 1×1 system (the system then carries no factor).
  /// @param contribution one body's (a, b); the system must have exactly one contact
  /// @return this system
  ContactSystem& operator+=(const ScalarContribution& contribution);

  /// @brief Room for the blocks to come, before they are added (it changes no value): one
  /// allocation where growing one block at a time reallocates, which on 100,000 contacts costs
  /// more in fresh memory than the adding itself.
  /// @param blocks how many blocks will be added
  /// @param entries the sum of the squares of their contact counts (the entries of A they add)
  void reserve(std::size_t blocks, std::size_t entries);

  /// @brief Number of contacts N.
  /// @return N
  [[nodiscard]] Eigen::Index size() const { return B_.size(); }
  /// @brief Whether A is kept sparse (then A() is empty).
  /// @return true for sparse storage
  [[nodiscard]] bool is_sparse() const { return sparse_; }
  /// @brief The matrix A, when it is kept dense.
  /// @return A, N×N; empty (0×0) when is_sparse()
  [[nodiscard]] const Eigen::MatrixXd& A() const { return A_; }
  /// @brief The matrix A as a sparse matrix, built from either storage (duplicates summed).
  /// @return A, N×N, compressed
  [[nodiscard]] Eigen::SparseMatrix<double> sparse_A() const;
  /// @brief The right-hand side B.
  /// @return B, N
  [[nodiscard]] const Eigen::VectorXd& B() const { return B_; }

  /// @brief @f$ \|A\,F\,dt - B\| @f$ for any impulses, computed without overflow or underflow
  /// of its squares (as impulse::solve computes its residual).
  /// @param Fdt one impulse magnitude per contact (a size mismatch throws InvalidInput)
  /// @return the 2-norm of the residual
  [[nodiscard]] double residual(const Eigen::Ref<const Eigen::VectorXd>& Fdt) const;

  /// @brief Whether every contribution so far carried its factor, so that factor() is complete.
  /// @return true when @f$ A = G^T G @f$ and @f$ B = G^T w @f$ hold for the stacked factor
  [[nodiscard]] bool has_factor() const { return factored_; }

  /// @brief The stacked factor: every block's rows, its columns placed at its contacts.
  /// @param G receives the matrix, one row per degree of freedom, N columns
  /// @param w receives the scaled velocities, one per row of G
  /// @pre has_factor()
  void factor(Eigen::MatrixXd& G, Eigen::VectorXd& w) const;

  /// @brief The stacked factor as a sparse matrix (the same rows as the dense overload).
  /// @param G receives the matrix, one row per degree of freedom, N columns
  /// @param w receives the scaled velocities, one per row of G
  /// @pre has_factor()
  void factor(Eigen::SparseMatrix<double>& G, Eigen::VectorXd& w) const;

 private:
  struct FactorRows {
    std::vector<Eigen::Index> contacts;
    Eigen::MatrixXd G;
    Eigen::VectorXd w;
  };
  // Checks a block before anything is added; throws InvalidInput.
  void check(const BlockContribution& block) const;
  // Adds a block's a and b (checked) to A and B.
  void add_matrix(const BlockContribution& block);
  Eigen::MatrixXd A_;                            // dense storage (empty when sparse_)
  std::vector<Eigen::Triplet<double>> entries_;  // sparse storage: every entry added
  Eigen::VectorXd B_;
  std::vector<FactorRows> factor_rows_;
  bool factored_ = true;
  bool sparse_ = false;
};

}  // namespace impulse
