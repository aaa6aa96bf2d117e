// SPDX-License-Identifier: GPL-3.0-or-later
// The impulselab program as one function, so that main.cpp reads no CLI11 header (it compiles in
// a moment, last, after the libraries of a first build).
#pragma once

namespace impulselab {

/// @brief The impulselab program: its verbs (check, solve, sweep) on the command line.
/// @param argc as main() receives it
/// @param argv as main() receives it
/// @return the exit status
int program(int argc, char** argv);

}  // namespace impulselab
