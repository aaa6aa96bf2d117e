// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene_input.hpp"

#include <cstddef>

#include "impulse/scene/json.hpp"
#include "output.hpp"

namespace impulselab {

impulse::scene::World read_world(const std::string& path) {
  constexpr std::size_t max_bytes = impulse::scene::ReadLimits{}.max_bytes;
  // Read up to one byte past the limit: the reader then refuses the scene as too large.
  return impulse::scene::parse_world(read_input(path, max_bytes), scene_name(path));
}

}  // namespace impulselab
