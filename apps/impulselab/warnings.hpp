// SPDX-License-Identifier: GPL-3.0-or-later
// Warnings about a solved scene: the result is reported as usual (exit status 0), and a line on
// standard error tells the reader why to trust it less.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// Above this condition estimate of A, `solve` and `sweep` warn that the system is
/// ill-conditioned.
///
/// Rounding changes the impulses by up to about κ·ε of their size (κ the condition estimate,
/// ε = 2.2e-16, times a small factor measured on the hostile scenes, see
/// docs/pages/accuracy.md). At κ = 1e8 that is about 2e-8: half of the 16 digits of a double
/// are rounding, and with the measured factor the error reaches the sixth significant digit,
/// the last one the text report prints. The sparse method's κ is an estimate from the pivots of
/// a factorisation, which the threshold's margin allows for.
inline constexpr double ill_conditioned = 1e8;

/// The warnings for @p result, each a sentence without the program's prefix: the condition
/// estimate above ill_conditioned, and a solution that the solver found inconsistent (which
/// never happens to a scene in exact arithmetic: it means that rounding lost part of the system).
/// @param result a solved scene (status success)
/// @param source how messages name the scene ("scene.json", "<stdin>")
/// @return one line per warning; empty when there is nothing to warn about
std::vector<std::string> solve_warnings(const impulse::scene::Result& result,
                                        std::string_view source);

/// Prints each warning on standard error as `impulselab: warning: <warning>`.
/// @param warnings the lines from solve_warnings
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace impulselab
