// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab: one program, one verb per file. A new verb is two lines here: its header, and the
// call that adds it to the command line.
#include "commands.hpp"

#include "app.hpp"
#include "check_command.hpp"
#include "solve_command.hpp"
#include "sweep_command.hpp"

namespace impulselab {

int program(int argc, char** argv) {
  return run(argc, argv, [](CLI::App& app) {
    add_check_command(app);
    add_solve_command(app);
    add_sweep_command(app);
  });
}

}  // namespace impulselab
