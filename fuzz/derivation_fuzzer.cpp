// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness of derivation files (impulselab check NOTES.md): arbitrary bytes are read
// and checked. Every input must end in a report or in a refusal that names a place in the file;
// never a crash, a hang, a leak or undefined behaviour. An accepted file's report must hold
// together: one verdict per equation, the summary counting them, a counterexample wherever a
// step does not follow and a condition wherever it follows only if, and every format renders.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "derivations/derivation.hpp"

namespace d = impulse::derivations;

namespace {

[[noreturn]] void broken(const char* law) {
  std::fprintf(stderr, "derivation_fuzzer: broken: %s\n", law);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  d::DerivationOptions options;
  options.samples = 4;  // the numeric method's points: enough to run every path
  try {
    const d::DerivationReport report = d::check_derivation(text, "fuzz.md", options);
    if (report.equations.empty()) {
      broken("an accepted file without equations");
    }
    std::size_t counted = 0;
    for (const d::Verdict v : d::all_verdicts) {
      counted += report.count(v);
    }
    if (counted != report.equations.size()) {
      broken("the summary does not count every equation");
    }
    for (const d::EquationResult& e : report.equations) {
      if (e.line == 0 || e.column == 0) {
        broken("an equation without its place");
      }
      if (e.verdict == d::Verdict::does_not_follow && e.counterexample.empty() &&
          e.residual.empty()) {
        broken("a step that does not follow, without what shows it");
      }
      if (e.verdict == d::Verdict::follows_if && e.condition.empty()) {
        broken("follows-if without its condition");
      }
    }
    for (const d::Format f : {d::Format::text, d::Format::markdown, d::Format::json}) {
      if (d::render(report, f).empty()) {
        broken("an empty rendering");
      }
    }
  } catch (const d::DerivationError& e) {
    if (e.line() == 0 || e.column() == 0 || std::string(e.what()).empty()) {
      broken("a refusal without its place or message");
    }
  }
  return 0;
}
