// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab solve SCENE.json [--format text|json] [--output FILE]
#pragma once

#include <CLI/CLI.hpp>

namespace impulselab {

/// Adds the `solve` verb: solves one scene and reports it as text or JSON.
/// @param app the program's command line
void add_solve_command(CLI::App& app);

}  // namespace impulselab
