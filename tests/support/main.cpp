// SPDX-License-Identifier: GPL-3.0-or-later
// The one Catch2 main shared by every test program. In a Debug build (the asan preset) it traps
// floating-point exceptions first: a NaN or an infinity born anywhere in a test is a SIGFPE,
// which Catch2 reports as a failure of the test case that ran (see fp_traps.hpp).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "fp_traps.hpp"

int main(int argc, char* argv[]) {
#ifndef NDEBUG
  impulselab::test::enable_fp_traps();
#endif
  return Catch::Session().run(argc, argv);
}
