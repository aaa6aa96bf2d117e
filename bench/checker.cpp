// SPDX-License-Identifier: GPL-3.0-or-later
// Goal 3 (issue 7): the derivation checker's speed. `check_full` is `impulselab check` at its
// defaults (10,000 samples per numeric method, seed 1) without the rendering; `check_section/N`
// is section N alone, which says where the time goes.
#include <benchmark/benchmark.h>

#include <string>

#include "derivations/check.hpp"

namespace {

namespace check = impulse::derivations;

void check_full(benchmark::State& state) {
  for (auto _ : state) {
    const check::Report report = check::run({"", 10000, 1});
    benchmark::DoNotOptimize(report.summary.verified);
    if (report.summary.failed != 0) {
      state.SkipWithError("a check failed");
    }
  }
}
BENCHMARK(check_full)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void check_section(benchmark::State& state) {
  const std::string section = std::to_string(state.range(0));
  for (auto _ : state) {
    const check::Report report = check::run({section, 10000, 1});
    benchmark::DoNotOptimize(report.summary.verified);
  }
}
BENCHMARK(check_section)
    ->DenseRange(1, 5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
