// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation checker's speed. `check_full` is `impulselab check` at its
// defaults (10,000 samples per numeric method, seed 1) without the rendering; `check_section/N`
// is section N alone, which says where the time goes.
// `check_derivation_twenty_steps` is `impulselab check bench/derivations/twenty-steps.md`
// (20 steps, every method: exact, converse, counterexamples, the numeric second opinion) without
// reading the file or rendering the report; bench/sympy_steps.py times the same steps in SymPy.
// A checker for homework: `check_student_corpus` is every file of tests/derivations/students/
// checked as `impulselab check tests/derivations/students/` checks them (without reading the files
// or rendering); `check_power_pair/N` is the pair (a+b+c)^N then (c+b+a)^{N-1}(a+b+c), which
// the structure and the evaluation at rational points decide before anything is expanded.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void check_student_corpus(benchmark::State& state) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSELAB_STUDENTS)) {
    if (entry.path().extension() == ".md" && entry.path().filename() != "README.md") {
      files.emplace_back(entry.path().filename().string(), read_text(entry.path()));
    }
  }
  std::sort(files.begin(), files.end());
  std::size_t steps = 0;
  for (auto _ : state) {
    steps = 0;
    for (const auto& [name, text] : files) {
      const check::DerivationReport report = check::check_derivation(text, name);
      steps += report.equations.size() - report.count(check::Verdict::premise);
      if (report.count(check::Verdict::undecided) != 0) {
        state.SkipWithError(("a step of " + name + " is undecided").c_str());
      }
    }
  }
  state.counters["files"] = static_cast<double>(files.size());
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(check_student_corpus)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void check_power_pair(benchmark::State& state) {
  const std::string n = std::to_string(state.range(0));
  const std::string m = std::to_string(state.range(0) - 1);
  const std::string text = "$$x = (a+b+c)^{" + n + "}$$\n\n$$x = (c+b+a)^{" + m + "}(a+b+c)$$\n";
  for (auto _ : state) {
    const check::DerivationReport report = check::check_derivation(text, "power.md");
    if (report.equations.size() != 2 || report.equations[1].verdict != check::Verdict::follows) {
      state.SkipWithError("the pair is not decided as following");
    }
  }
}
BENCHMARK(check_power_pair)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
