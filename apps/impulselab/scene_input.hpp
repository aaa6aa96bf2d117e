// SPDX-License-Identifier: GPL-3.0-or-later
// A scene file for the verbs that solve (solve, sweep): read and checked by the scene reader.
#pragma once

#include <string>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// The scene in @p path, or in standard input when @p path is "-" (messages then name
/// "<stdin>"), checked. Throws impulse::InvalidInput naming the file and the place.
/// @param path a file or "-"
/// @return the checked scene
impulse::scene::World read_world(const std::string& path);

}  // namespace impulselab
