// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/system.hpp"

#include <algorithm>
#include <cassert>
#include <string>
#include <utility>

#include "impulse/core/error.hpp"
#include "impulse/core/solve.hpp"

namespace impulse {

ContactSystem::ContactSystem(Eigen::Index contacts, Storage storage) {
  if (contacts < 0) {
    throw InvalidInput("number of contacts must be at least 0, got " + std::to_string(contacts));
  }
  sparse_ =
      storage == Storage::sparse || (storage == Storage::automatic && contacts > sparse_threshold);
  if (!sparse_) {
    A_ = Eigen::MatrixXd::Zero(contacts, contacts);
  }
  B_ = Eigen::VectorXd::Zero(contacts);
}

ContactSystem::ContactSystem(Eigen::MatrixXd A, Eigen::VectorXd B)
    : A_(std::move(A)), B_(std::move(B)), factored_(false) {
  if (A_.rows() != A_.cols() || A_.rows() != B_.size()) {
    throw InvalidInput("A must be square and match B, got A " + std::to_string(A_.rows()) + "x" +
                       std::to_string(A_.cols()) + " and B of size " + std::to_string(B_.size()));
  }
}

void ContactSystem::reserve(std::size_t blocks, std::size_t entries) {
  factor_rows_.reserve(factor_rows_.size() + blocks);
  if (sparse_) {
    entries_.reserve(entries_.size() + entries);
  }
}

void ContactSystem::check(const BlockContribution& block) const {
  const auto n = static_cast<Eigen::Index>(block.contacts.size());
  if (block.a.rows() != n || block.a.cols() != n || block.b.size() != n) {
    throw InvalidInput("a block over " + std::to_string(n) + " contacts must have a " +
                       std::to_string(n) + "x" + std::to_string(n) + " matrix and " +
                       std::to_string(n) + " right-hand sides, got " +
                       std::to_string(block.a.rows()) + "x" + std::to_string(block.a.cols()) +
                       " and " + std::to_string(block.b.size()));
  }
  const bool carries_factor = block.G.size() > 0 || block.w.size() > 0;
  if (carries_factor && (block.G.cols() != n || block.w.size() != block.G.rows())) {
    throw InvalidInput("a block's factor must have " + std::to_string(n) +
                       " columns and one scaled velocity per row, got " +
                       std::to_string(block.G.rows()) + "x" + std::to_string(block.G.cols()) +
                       " and " + std::to_string(block.w.size()));
  }
  for (Eigen::Index v = 0; v < n; ++v) {
    const Eigen::Index row = block.contacts[static_cast<std::size_t>(v)];
    if (row < 0 || row >= size()) {
      throw InvalidInput("contact index must be in [0, " + std::to_string(size()) + "), got " +
                         std::to_string(row));
    }
    const auto first = block.contacts.begin();
    if (std::find(first, first + v, row) != first + v) {
      throw InvalidInput("a block must list each contact once, got contact " + std::to_string(row) +
                         " twice");
    }
  }
}

void ContactSystem::add_matrix(const BlockContribution& block) {
  // The ⊕ of section 4.5: the block's (v, k) entry lands at the global (contact v, contact k).
  const auto n = static_cast<Eigen::Index>(block.contacts.size());
  for (Eigen::Index v = 0; v < n; ++v) {
    const Eigen::Index row = block.contacts[static_cast<std::size_t>(v)];
    B_(row) += block.b(v);
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::Index column = block.contacts[static_cast<std::size_t>(k)];
      if (sparse_) {
        entries_.emplace_back(row, column, block.a(v, k));  // summed by sparse_A()
      } else {
        A_(row, column) += block.a(v, k);
      }
    }
  }
}

ContactSystem& ContactSystem::operator+=(const BlockContribution& block) {
  BlockContribution copy;  // only the factor is kept: copied here, moved by the other overload
  copy.contacts = block.contacts;
  copy.a = block.a;
  copy.b = block.b;
  copy.G = block.G;
  copy.w = block.w;
  return *this += std::move(copy);
}

ContactSystem& ContactSystem::operator+=(BlockContribution&& block) {
  check(block);
  if (block.contacts.empty() && block.a.size() == 0 && block.b.size() == 0) {
    return *this;  // a body touching no contact (or a static one) adds nothing
  }
  add_matrix(block);
  const bool carries_factor = block.G.size() > 0 || block.w.size() > 0;
  if (!carries_factor) {
    factored_ = false;
  }
  if (factored_) {
    factor_rows_.push_back({std::move(block.contacts), std::move(block.G), std::move(block.w)});
  } else {
    factor_rows_.clear();
  }
  return *this;
}

Eigen::SparseMatrix<double> ContactSystem::sparse_A() const {
  Eigen::SparseMatrix<double> A(size(), size());
  if (sparse_) {
    A.setFromTriplets(entries_.begin(), entries_.end());  // sums the entries of shared contacts
  } else {
    A = A_.sparseView();
  }
  A.makeCompressed();
  return A;
}

double ContactSystem::residual(const Eigen::Ref<const Eigen::VectorXd>& Fdt) const {
  if (Fdt.size() != size()) {
    throw InvalidInput("Fdt must give one impulse per contact (" + std::to_string(size()) +
                       "), got " + std::to_string(Fdt.size()));
  }
  Eigen::VectorXd r(size());
  if (sparse_) {
    r.noalias() = sparse_A() * Fdt;
  } else {
    r.noalias() = A_ * Fdt;
  }
  r -= B_;
  return detail::quiet_norm(r);
}

void ContactSystem::factor(Eigen::MatrixXd& G, Eigen::VectorXd& w) const {
  assert(factored_);
  Eigen::Index rows = 0;
  for (const FactorRows& part : factor_rows_) {
    rows += part.G.rows();
  }
  G = Eigen::MatrixXd::Zero(rows, size());
  w.resize(rows);
  Eigen::Index top = 0;
  for (const FactorRows& part : factor_rows_) {
    for (std::size_t k = 0; k < part.contacts.size(); ++k) {
      G.col(part.contacts[k]).segment(top, part.G.rows()) =
          part.G.col(static_cast<Eigen::Index>(k));
    }
    w.segment(top, part.G.rows()) = part.w;
    top += part.G.rows();
  }
}

void ContactSystem::factor(Eigen::SparseMatrix<double>& G, Eigen::VectorXd& w) const {
  assert(factored_);
  // Column by column: a contact's column holds the rows of each block it is in, the blocks in
  // the order they were added (so its rows ascend); no two blocks share a row.
  using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;
  const auto n = static_cast<std::size_t>(size());
  Eigen::Index rows = 0;
  std::vector<std::size_t> start(n + 1, 0);
  for (const FactorRows& part : factor_rows_) {
    rows += part.G.rows();
    for (const Eigen::Index contact : part.contacts) {
      start[static_cast<std::size_t>(contact) + 1] += static_cast<std::size_t>(part.G.rows());
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    start[j + 1] += start[j];
  }
  G.resize(rows, size());
  G.resizeNonZeros(static_cast<Eigen::Index>(start[n]));
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  w.resize(rows);
  Eigen::Index top = 0;
  for (const FactorRows& part : factor_rows_) {
    for (std::size_t k = 0; k < part.contacts.size(); ++k) {
      std::size_t& at = next[static_cast<std::size_t>(part.contacts[k])];
      for (Eigen::Index i = 0; i < part.G.rows(); ++i, ++at) {
        G.innerIndexPtr()[at] = static_cast<StorageIndex>(top + i);
        G.valuePtr()[at] = part.G(i, static_cast<Eigen::Index>(k));
      }
    }
    w.segment(top, part.G.rows()) = part.w;
    top += part.G.rows();
  }
  for (std::size_t j = 0; j <= n; ++j) {
    G.outerIndexPtr()[j] = static_cast<StorageIndex>(start[j]);
  }
}

ContactSystem& ContactSystem::operator+=(const ScalarContribution& contribution) {
  if (size() != 1) {
    throw InvalidInput("a single-contact contribution needs a system of 1 contact, got " +
                       std::to_string(size()));
  }
  if (sparse_) {
    entries_.emplace_back(0, 0, contribution.a);
  } else {
    A_(0, 0) += contribution.a;
  }
  B_(0) += contribution.b;
  factored_ = false;
  factor_rows_.clear();
  return *this;
}

}  // namespace impulse
