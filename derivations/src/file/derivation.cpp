// SPDX-License-Identifier: GPL-3.0-or-later
// A derivation file, end to end: its Markdown read into blocks and directives, the blocks into
// equations (rows, chains, tags), each step given the equations it must follow from, and each
// decided exactly first and numerically as a second opinion.
#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "derivations/derivation.hpp"
#include "file/reader.hpp"
#include "file/step.hpp"
#include "file/task.hpp"
#include "impulse/core/error.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

int exit_status(const DerivationReport& report) {
  const bool failing = std::any_of(report.equations.begin(), report.equations.end(),
                                   [](const EquationResult& e) { return fails(e.verdict); });
  return failing || (report.task && !report.task->target_reached) ? 1 : 0;
}

namespace {

// Reads and checks a file; with a task, judges the submission against it too.
DerivationReport checked(std::string text, const std::string& file_name,
                         const DerivationOptions& options, const Task* task) {
  const auto start = std::chrono::steady_clock::now();
  num::quiet_gsl();
  // The numeric method evaluates a student's expressions at random points, where they may divide
  // by zero or overflow: that is its business (it discards such points), never a SIGFPE for a
  // caller that traps floating-point exceptions (the Debug test programs do).
  const impulse::detail::HeldFloatingPointExceptions held;
  file::Limits limits;
  limits.bytes = max_derivation_bytes;
  try {
    const file::Source source(std::move(text), limits);
    file::Reader reader(source, limits);
    file::ReadFile read = reader.read();
    const std::vector<file::Equation> equations = std::move(read.equations);
    DerivationReport report;
    report.file = file_name;
    for (const file::LoneInline& lone : read.lone_inline) {
      const file::Place place = source.place(lone.offset);
      report.notes.push_back(
          {place.line, place.column, std::string(lone.written),
           "not checked: inline math is not read, so this equation is neither a premise nor a "
           "step; write it between $$ and $$ to have it checked"});
    }
    file::Checker checker(reader.symbols(), options);
    for (std::size_t i = 0; i < equations.size(); ++i) {
      const auto begin = std::chrono::steady_clock::now();
      report.equations.push_back(checker.check(equations, i, source));
      const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - begin;
      report.equations.back().seconds = spent.count();
      ++report.counts[static_cast<std::size_t>(report.equations.back().verdict)];
    }
    if (task != nullptr) {
      report.task = file::judge_task(*task, equations, reader.symbols(), checker, report, options);
    }
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    report.seconds = took.count();
    return report;
  } catch (const file::ReadError& e) {
    throw DerivationError(e.place().line, e.place().column, e.what());
  }
}

}  // namespace

DerivationReport check_derivation(std::string text, const std::string& file_name,
                                  const DerivationOptions& options) {
  return checked(std::move(text), file_name, options, nullptr);
}

DerivationReport check_derivation(std::string text, const std::string& file_name, const Task& task,
                                  const DerivationOptions& options) {
  return checked(std::move(text), file_name, options, &task);
}

}  // namespace impulse::derivations
