// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/system.hpp"

#include <algorithm>
#include <cassert>
#include <string>
#include <utility>

#include "impulse/core/error.hpp"

namespace impulse {

ContactSystem::ContactSystem(Eigen::Index contacts) {
  if (contacts < 0) {
    throw InvalidInput("number of contacts must be at least 0, got " + std::to_string(contacts));
  }
  A_ = Eigen::MatrixXd::Zero(contacts, contacts);
  B_ = Eigen::VectorXd::Zero(contacts);
}

ContactSystem::ContactSystem(Eigen::MatrixXd A, Eigen::VectorXd B)
    : A_(std::move(A)), B_(std::move(B)), factored_(false) {
  if (A_.rows() != A_.cols() || A_.rows() != B_.size()) {
    throw InvalidInput("A must be square and match B, got A " + std::to_string(A_.rows()) + "x" +
                       std::to_string(A_.cols()) + " and B of size " + std::to_string(B_.size()));
  }
}

ContactSystem& ContactSystem::operator+=(const BlockContribution& block) {
  const auto n = static_cast<Eigen::Index>(block.contacts.size());
  if (block.a.rows() != n || block.a.cols() != n || block.b.size() != n) {
    throw InvalidInput("a block over " + std::to_string(n) + " contacts must have a " +
                       std::to_string(n) + "x" + std::to_string(n) + " matrix and " +
                       std::to_string(n) + " right-hand sides, got " +
                       std::to_string(block.a.rows()) + "x" + std::to_string(block.a.cols()) +
                       " and " + std::to_string(block.b.size()));
  }
  if (n == 0 && block.a.size() == 0 && block.b.size() == 0) {
    return *this;  // a body touching no contact (or a static one) adds nothing
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
  // The ⊕ of section 4.5: the block's (v, k) entry lands at the global (contact v, contact k).
  for (Eigen::Index v = 0; v < n; ++v) {
    const Eigen::Index row = block.contacts[static_cast<std::size_t>(v)];
    B_(row) += block.b(v);
    for (Eigen::Index k = 0; k < n; ++k) {
      A_(row, block.contacts[static_cast<std::size_t>(k)]) += block.a(v, k);
    }
  }
  if (!carries_factor) {
    factored_ = false;
  }
  if (factored_) {
    factor_rows_.push_back({block.contacts, block.G, block.w});
  } else {
    factor_rows_.clear();
  }
  return *this;
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

ContactSystem& ContactSystem::operator+=(const ScalarContribution& contribution) {
  if (size() != 1) {
    throw InvalidInput("a single-contact contribution needs a system of 1 contact, got " +
                       std::to_string(size()));
  }
  A_(0, 0) += contribution.a;
  B_(0) += contribution.b;
  factored_ = false;
  factor_rows_.clear();
  return *this;
}

}  // namespace impulse
