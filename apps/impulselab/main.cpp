// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab: the program's verbs are added in commands.cpp.
#include "commands.hpp"

int main(int argc, char** argv) {
  return impulselab::program(argc, argv);
}
