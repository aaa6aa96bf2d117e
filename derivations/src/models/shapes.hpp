// SPDX-License-Identifier: GPL-3.0-or-later
// The shapes a contact force takes over its duration, for the models of pulses of force
// (pulses.cpp): on [0, 1], each of mean 1.
#pragma once

#include <vector>

#include "file/time.hpp"

namespace impulse::derivations::models {

/// A constant force, a half-sine, a triangle and a pulse that peaks early, in that order.
[[nodiscard]] const std::vector<file::PulseShape>& pulse_shapes();

}  // namespace impulse::derivations::models
