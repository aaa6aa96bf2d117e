// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab-generate: writes a generated scene as a scene file, for `impulselab solve` and labs.
//
//   impulselab-generate stack|pyramid|cradle CONTACTS [SEED] > scene.json
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string_view>

#include "impulse/core/error.hpp"
#include "scenes.hpp"

namespace {

template <typename Number>
bool parse(std::string_view text, Number& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} && end == text.data() + text.size();
}

int usage() {
  std::cerr << "usage: impulselab-generate stack|pyramid|cradle CONTACTS [SEED]\n"
               "Writes a scene with exactly CONTACTS contacts as JSON (scene-format.md) to "
               "standard output.\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    return usage();
  }
  std::size_t contacts = 0;
  std::uint64_t seed = 1;
  if (!parse(argv[2], contacts) || (argc == 4 && !parse(argv[3], seed))) {
    return usage();
  }
  try {
    std::cout << impulse::scenes::to_json(impulse::scenes::generate(argv[1], contacts, seed));
  } catch (const impulse::InvalidInput& error) {
    std::cerr << "impulselab-generate: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
