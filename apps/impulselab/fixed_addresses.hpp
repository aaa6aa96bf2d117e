// SPDX-License-Identifier: GPL-3.0-or-later
// `check` at the same addresses on every run, for both programs that check (impulselab and
// impulselab-check).
#pragma once

#include <cstring>

#ifdef __linux__
#include <sys/personality.h>
#include <unistd.h>
#endif

namespace impulselab {

/// `check` runs again, once, at the same addresses every time. GiNaC orders the terms of a sum
/// and the factors of a product by hashes that follow the addresses of its types, which the
/// system places at random on each run; an order can decide which rewriting the checker finds, so
/// a step could pass in one run and be undecided in the next. The same program now gives the
/// same report on every run. Where the system refuses (a container without the call), it goes on
/// as it is.
/// @param argc as main() receives it
/// @param argv as main() receives it
inline void check_at_fixed_addresses([[maybe_unused]] int argc, [[maybe_unused]] char** argv) {
#ifdef __linux__
  if (argc < 2 || std::strcmp(argv[1], "check") != 0) {
    return;
  }
  const int current = personality(0xffffffff);
  if (current == -1 || (current & ADDR_NO_RANDOMIZE) != 0) {
    return;
  }
  if (personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1) {
    return;
  }
  execv("/proc/self/exe", argv);
  personality(static_cast<unsigned long>(current));  // not run again: as it was
#endif
}

}  // namespace impulselab
