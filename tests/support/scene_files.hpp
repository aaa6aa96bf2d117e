// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files for the tests of the scene reader: a file's text, and the scene it holds (the
// program reads files itself: apps/impulselab/output.hpp).
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "impulse/scene/json.hpp"

namespace impulselab::test {

inline std::string read_scene_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline impulse::scene::Scene load_scene(const std::string& path) {
  return impulse::scene::parse_scene(read_scene_text(path), path);
}

}  // namespace impulselab::test
