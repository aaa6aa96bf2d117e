// SPDX-License-Identifier: GPL-3.0-or-later
// The impulselab-check program as one function: the program with the one verb `check`, defined
// in check_command.cpp beside the verb, so that it links without the other verbs (solve, sweep)
// and check_main.cpp reads no CLI11 header.
#pragma once

namespace impulselab {

/// @brief The program with the one verb `check` (impulselab-check).
/// @param argc as main() receives it
/// @param argv as main() receives it
/// @return the exit status
int check_program(int argc, char** argv);

}  // namespace impulselab
