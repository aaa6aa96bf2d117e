// SPDX-License-Identifier: GPL-3.0-or-later
// A vector written out in a test: vec({1.5, 0, -2}).
#pragma once

#include <Eigen/Core>
#include <initializer_list>

namespace impulse::test {

inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double x : values) {
    v(i++) = x;
  }
  return v;
}

}  // namespace impulse::test
