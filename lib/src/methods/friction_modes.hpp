// SPDX-License-Identifier: GPL-3.0-or-later
// The friction problem by pivoting on the contacts' modes (separating, sticking, sliding one way
// or the other), each mode set solved as one linear system: the fast path of solve_friction(),
// Lemke's method its fallback.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "impulse/methods/friction_complementarity.hpp"

namespace impulse::methods::detail {

// The groups of contacts whose tangential columns of W are the same (friction_modes.cpp says
// why they share one friction): group[v] is the first contact of v's group, v itself for a
// contact alone.
[[nodiscard]] std::vector<Eigen::Index> groups_of(const FrictionSystem& system);

// What the pivoting on modes found.
struct ModePivoting {
  bool solved = false;         // impulses that meet the conditions within the tolerance
  Eigen::VectorXd normal;      // P_n of each contact
  Eigen::VectorXd tangential;  // P_t of each contact
  int pivots = 0;              // contacts whose mode changed, summed over the steps
  int steps = 0;               // the systems solved
};

// Pivots on the modes of the contacts of `system`, their groups `group` (groups_of(system)),
// starting from the modes that `start` (normal impulses without friction, e.g. the paper's; empty:
// none) suggests, for at most `max_steps` steps. `solved` only when friction_residual() is at most
// tolerance times its scale.
[[nodiscard]] ModePivoting pivot_modes(const FrictionSystem& system,
                                       const std::vector<Eigen::Index>& group,
                                       const Eigen::VectorXd& start, double tolerance,
                                       int max_steps);

}  // namespace impulse::methods::detail
