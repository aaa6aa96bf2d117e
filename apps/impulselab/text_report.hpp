// SPDX-License-Identifier: GPL-3.0-or-later
// The report of a solved scene for people: aligned tables, 6 significant digits.
#pragma once

#include <string>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// A number with 6 significant digits ("1.5", "-0.333333", "1e-20"); negative zero prints as 0.
/// @param value the number
/// @return its text
std::string number_text(double value);

/// The text report of `impulselab solve`: the method (with the diagnostics of the two that are
/// not the paper's), the impulses, each body's motion before and after
/// (and its rotation for rigid bodies), energy and momentum before and after, each contact's
/// approach speed before and after, and the system A·Fdt = B with its rank, residual and
/// diagnostics (A itself is shown up to 10 contacts).
///
/// Rounding noise is shown as 0: a value smaller than 1e-12 times the largest value of its kind
/// in the report (velocities, momenta, energies, impulses, approach speeds, entries of A, of B)
/// could not be told from 0 at 6 significant digits. The residual and the condition estimate
/// are shown as computed; `--format json` keeps every digit of everything.
/// @param result a result whose status is success
/// @param source how to name the scene ("scene.json", "<stdin>")
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline
std::string text_report(const impulse::scene::Result& result, const std::string& source,
                        bool colour);

}  // namespace impulselab
