// SPDX-License-Identifier: GPL-3.0-or-later
// The clock of the checker's time budgets: a step's (--step-seconds) and the short searches of
// the facts and premises that must agree.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>

namespace impulse::derivations::file {

/// The clock of the checker's time budgets (a step's, --step-seconds): the processor time the
/// checking thread has used, so that a verdict does not depend on what else the machine runs (on
/// a machine busy with other work, wall-clock time ran out on steps that take a tenth of their
/// budget alone). In WebAssembly, which has no such clock, the browser's monotonic time.
struct WorkClock {
  using duration = std::chrono::nanoseconds;
  using rep = duration::rep;
  using period = duration::period;
  using time_point = std::chrono::time_point<WorkClock>;
  static constexpr bool is_steady = true;
  [[nodiscard]] static time_point now() noexcept {
#if defined(__EMSCRIPTEN__) || !defined(CLOCK_THREAD_CPUTIME_ID)
    return time_point(
        std::chrono::duration_cast<duration>(std::chrono::steady_clock::now().time_since_epoch()));
#else
    timespec used{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &used);  // (cannot fail for the calling thread)
    return time_point(std::chrono::seconds(used.tv_sec) + std::chrono::nanoseconds(used.tv_nsec));
#endif
  }
};

/// Whether @p deadline has passed.
[[nodiscard]] inline bool past(WorkClock::time_point deadline) {
  return WorkClock::now() > deadline;
}

/// The point @p seconds of the checking thread's processor time from now.
[[nodiscard]] inline WorkClock::time_point after(double seconds) {
  return WorkClock::now() + std::chrono::duration_cast<WorkClock::duration>(
                                std::chrono::duration<double>(std::max(seconds, 0.0)));
}

}  // namespace impulse::derivations::file
