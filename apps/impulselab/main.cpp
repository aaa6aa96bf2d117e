// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab: the program's verbs are added in commands.cpp.
#include "commands.hpp"
#include "fixed_addresses.hpp"

int main(int argc, char** argv) {
  impulselab::check_at_fixed_addresses(argc, argv);
  return impulselab::program(argc, argv);
}
