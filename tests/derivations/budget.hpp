// SPDX-License-Identifier: GPL-3.0-or-later
// The options of the tests that pin verdicts. A verdict must not depend on how fast the build
// runs: the AddressSanitizer build runs the checker about twelve times slower than the Release
// build (a step of 0.14 s took 1.8 s there, near the default budget of 2 s, and turned undecided
// when the machine was busy). So these tests give each step 60 s of processor time; what the
// budget itself does is tested apart (check --step-seconds; files that would run for minutes).
#pragma once

#include "derivations/derivation.hpp"

namespace impulse::test {

/// The default options with a step budget of 60 s.
inline derivations::DerivationOptions pinned_options() {
  derivations::DerivationOptions options;
  options.step_seconds = 60.0;
  return options;
}

}  // namespace impulse::test
