// SPDX-License-Identifier: GPL-3.0-or-later
// Floating-point traps for the test programs. In a Debug build the shared main (main.cpp) makes
// division by zero, an invalid operation (a NaN born from numbers, e.g. 0/0 or inf - inf) and
// overflow raise SIGFPE at the instruction that causes them, so that a silent NaN or infinity
// anywhere in a test run is a failure that names its test case. Code that produces them on
// purpose (an overflow test, a library that computes with NaN internally) opts out locally with
// FpTrapsOff, for the statements that need it and no more.
#pragma once

#include <fenv.h>  // feenableexcept, fedisableexcept, fegetexcept: GNU extensions of <cfenv>

#include <cfenv>

namespace impulselab::test {

/// The exceptions a Debug test run traps. Underflow and inexact are not: they are ordinary
/// rounding, which every computation with doubles meets.
inline constexpr int trapped_exceptions = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;

/// Traps trapped_exceptions in the calling thread from now on (their flags cleared first).
inline void enable_fp_traps() {
  std::feclearexcept(FE_ALL_EXCEPT);
  feenableexcept(trapped_exceptions);
}

/// The exceptions that trap in the calling thread now.
inline int fp_traps() {
  return fegetexcept();
}

/// While it lives, @p exceptions do not trap; when it goes, the flags raised meanwhile are
/// cleared and the traps in force before are restored. Scope it to the statements that produce
/// a NaN or an infinity on purpose, with a comment that says why.
class FpTrapsOff {
 public:
  explicit FpTrapsOff(int exceptions = trapped_exceptions) : saved_(fegetexcept()) {
    fedisableexcept(exceptions);
  }
  ~FpTrapsOff() {
    // A flag left raised would not trap by itself on x86-64's SSE, but x87 instructions (long
    // double) trap on a pending unmasked flag: clear them before unmasking.
    std::feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(saved_);
  }
  FpTrapsOff(const FpTrapsOff&) = delete;
  FpTrapsOff& operator=(const FpTrapsOff&) = delete;
  FpTrapsOff(FpTrapsOff&&) = delete;
  FpTrapsOff& operator=(FpTrapsOff&&) = delete;

 private:
  int saved_;
};

}  // namespace impulselab::test
