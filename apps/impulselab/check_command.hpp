// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab check [--format text|markdown|json] [--section S] [--samples N] [--seed K]
//                  [--output FILE]
#pragma once

#include <CLI/CLI.hpp>

namespace impulselab {

/// Adds the `check` verb: runs the derivation checker over the paper and reports every check.
/// Exit status 1 when any check failed (the report is still written).
/// @param app the program's command line
void add_check_command(CLI::App& app);

}  // namespace impulselab
