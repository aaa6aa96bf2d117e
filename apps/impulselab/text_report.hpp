// SPDX-License-Identifier: GPL-3.0-or-later
// The report of a solved scene for people: aligned tables, 6 significant digits.
#pragma once

#include <Eigen/Core>
#include <string>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// A number with 6 significant digits ("1.5", "-0.333333", "1e-20"); negative zero prints as 0.
/// @param value the number
/// @return its text
std::string number_text(double value);

/// Rounding noise: a value below this fraction of the largest of its kind in a report (e.g. a
/// velocity of 4e-16 next to velocities of 1.5) is shown as 0. At 6 significant digits it could
/// not be told apart from 0 anyway; `--format json` keeps every digit.
inline constexpr double rounding_noise = 1e-12;

/// number_text(), or "0" when |@p value| is at most rounding_noise times @p scale.
/// @param value the number
/// @param scale the largest value of its kind in the report
/// @return its text
std::string chopped(double value, double scale);

/// A vector as chopped() numbers: "x" in 1D, "[x, y]" in 2D.
/// @param v the vector
/// @param dimension 1 or 2
/// @param scale the largest value of its kind in the report
/// @return its text
std::string vector_text(const Eigen::Vector2d& v, int dimension, double scale);

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
