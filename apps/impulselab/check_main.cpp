// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab-check: the impulselab program with its one verb, check (`impulselab-check check ARGS`
// is `impulselab check ARGS`, the same code and the same report). It links the checker and the
// command line's input and output alone, not the solver's methods, the scene reader or the other
// verbs: a newcomer's first report (scripts/check-the-paper) waits for no more compilation than
// the check needs.
#include "check_program.hpp"
#include "fixed_addresses.hpp"

int main(int argc, char** argv) {
  impulselab::check_at_fixed_addresses(argc, argv);
  return impulselab::check_program(argc, argv);
}
