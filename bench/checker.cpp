// SPDX-License-Identifier: GPL-3.0-or-later
// Goal 3 (issue 7): the derivation checker's speed. `check_full` is `impulselab check` at its
// defaults (10,000 samples per numeric method, seed 1) without the rendering; `check_section/N`
// is section N alone, which says where the time goes.
// Issue 13: `check_derivation_twenty_steps` is `impulselab check bench/derivations/twenty-steps.md`
// (20 steps, every method: exact, converse, counterexamples, the numeric second opinion) without
// reading the file or rendering the report; bench/sympy_steps.py times the same steps in SymPy.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include "derivations/check.hpp"
#include "derivations/derivation.hpp"

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

void check_derivation_twenty_steps(benchmark::State& state) {
  std::ifstream in(IMPULSELAB_TWENTY_STEPS);
  std::ostringstream text;
  text << in.rdbuf();
  for (auto _ : state) {
    const check::DerivationReport report = check::check_derivation(text.str(), "twenty-steps.md");
    benchmark::DoNotOptimize(report.equations.size());
    if (report.equations.size() - report.count(check::Verdict::premise) != 20 ||
        check::exit_status(report) != 0) {
      state.SkipWithError("the twenty steps are not twenty steps that pass");
    }
  }
}
BENCHMARK(check_derivation_twenty_steps)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
