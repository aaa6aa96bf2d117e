// SPDX-License-Identifier: GPL-3.0-or-later
// What `solve` says on standard error about a result besides the report: impulses that pull,
// answers that are only approximate, and methods that did not finish.
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

}  // namespace impulselab
