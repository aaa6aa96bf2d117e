// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab: one program, one verb per file. A new verb is two lines here: its header, and the
// call that adds it to the command line.
#include "app.hpp"
#include "check_command.hpp"
#include "solve_command.hpp"
#include "sweep_command.hpp"

int main(int argc, char** argv) {
  return impulselab::run(argc, argv, [](CLI::App& app) {
    impulselab::add_check_command(app);
    impulselab::add_solve_command(app);
    impulselab::add_sweep_command(app);
  });
}
