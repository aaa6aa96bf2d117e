// SPDX-License-Identifier: GPL-3.0-or-later
// What `solve` and `sweep` say on standard error about a result besides the report: impulses
// that pull, answers that are only approximate, methods that did not finish, and systems too
// ill-conditioned to trust every printed digit. None of them changes the exit status.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// The warnings about a solved scene, one line each, without the "impulselab: warning: " that
/// print_impulse_warnings() puts in front: every negative impulse, whatever the method
/// ("contact 1 (b–c): negative impulse -0.666667 (the contact pulls)"; an impulse within 1e-12
/// of the largest one's size from 0 is rounding, not a pull), and an approximate answer of the
/// complementarity method (projected Gauss-Seidel out of sweeps, or pivoting left above its
/// tolerance by rounding).
/// @param result a solved scene
/// @param prefix put in front of each line, e.g. "serial: " when several methods are shown
/// @return the lines, in contact order
std::vector<std::string> impulse_warnings(const impulse::scene::Result& result,
                                          std::string_view prefix = "");

/// Writes impulse_warnings() to standard error, each as "impulselab: warning: LINE". They do not
/// change the exit status.
/// @param result a solved scene
/// @param prefix put in front of each line
void print_impulse_warnings(const impulse::scene::Result& result, std::string_view prefix = "");

/// Why the method did not finish (serial collisions stopped at their bound, a complementarity
/// problem without solution), or "" when it did (impulse::scene::finished()).
/// @param result a solved scene
/// @param source how to name the scene ("scene.json", "<stdin>")
/// @return the message, naming the scene, the bound and what to do
std::string unfinished_message(const impulse::scene::Result& result, const std::string& source);

/// Throws WorkFailed (exit status 1) with unfinished_message() when the method did not finish.
/// @param result a solved scene
/// @param source how to name the scene
void require_finished(const impulse::scene::Result& result, const std::string& source);

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
