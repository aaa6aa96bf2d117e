// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Derivation files: a student's derivation, in Markdown and LaTeX, checked line by line
/// (`impulselab check NOTES.md`; the contract is spec/derivation-format.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/check.hpp"
#include "impulse/core/names.hpp"

namespace impulse::derivations {

/// @brief What became of one display equation.
enum class Verdict {
  premise,          ///< not checked: the first equation, or one after `given:`
  follows,          ///< follows from the equation(s) before, and they follow from it
  follows_one_way,  ///< follows, but the equation(s) before do not follow from it
  follows_if,       ///< follows only where a condition holds that the facts do not give
  does_not_follow,  ///< fails: a point satisfies the equation(s) before and the facts, not it
  dimensions,       ///< its terms do not have the same dimensions (only with `units:`)
  undecided,        ///< neither the exact nor the numeric method could decide
};

/// @brief A verdict's row of its table: its name in the report, and whether it fails the step.
struct VerdictName {
  Verdict value;          ///< the verdict
  std::string_view name;  ///< "follows-one-way"
  bool fails;             ///< the step does not pass: `check` exits with status 1
};

}  // namespace impulse::derivations

namespace impulse {
/// @brief The verdicts' names and which of them fail a step.
template <>
struct EnumNames<derivations::Verdict> {
  /// one row per verdict
  static constexpr std::array<derivations::VerdictName, 7> table{{
      {derivations::Verdict::premise, "premise", false},
      {derivations::Verdict::follows, "follows", false},
      {derivations::Verdict::follows_one_way, "follows-one-way", false},
      {derivations::Verdict::follows_if, "follows-if", false},
      {derivations::Verdict::does_not_follow, "does-not-follow", true},
      {derivations::Verdict::dimensions, "dimensions", true},
      {derivations::Verdict::undecided, "undecided", true},
  }};
};
}  // namespace impulse

namespace impulse::derivations {

/// @brief The report name of a verdict ("follows-one-way", …).
/// @param verdict the verdict
/// @return its name in the report
[[nodiscard]] constexpr std::string_view to_string(Verdict verdict) {
  return name_of(verdict);
}

/// @brief Whether a step with this verdict does not pass (does-not-follow, dimensions,
/// undecided).
/// @param verdict the verdict
/// @return whether it fails
[[nodiscard]] constexpr bool fails(Verdict verdict) {
  return row_of(verdict).fails;
}

/// @brief Every verdict, in the order of the report's summary.
inline constexpr Verdict all_verdicts[] = {
    Verdict::premise,         Verdict::follows,    Verdict::follows_one_way, Verdict::follows_if,
    Verdict::does_not_follow, Verdict::dimensions, Verdict::undecided};

/// @brief One symbol's value in a counterexample.
struct CounterexampleValue {
  std::string symbol;   ///< the symbol as LaTeX ("m_1", "p_{1}'", "\\omega")
  bool vector = false;  ///< a vector [x, y]
  double x = 0.0;       ///< its value, or the x component
  double y = 0.0;       ///< the y component of a vector
  std::string exact_x;  ///< the exact value ("1/3") when the point is exact
  std::string exact_y;  ///< the exact y component
};

/// @brief The outcome for one display equation.
struct EquationResult {
  std::size_t line = 0;                ///< the 1-based line where the equation begins
  std::size_t column = 0;              ///< its column
  std::optional<std::string> tag;      ///< its `\tag{k}`
  std::string latex;                   ///< the equation as written
  Verdict verdict = Verdict::premise;  ///< the verdict
  std::string decided_by;              ///< "exact" or "numeric"; empty for premises and undecided
  std::string how;                     ///< how it was decided, or what was tried
  std::vector<std::size_t> from;       ///< the lines of the equations it was checked against
  std::string condition;               ///< follows-if: the condition, LaTeX ("F \\neq 0")
  std::string condition_text;          ///< the same in plain text
  bool condition_needed = true;        ///< follows-if: the step was shown to fail without it
  std::string residual;                ///< does-not-follow: what is left of the step, LaTeX
  std::string residual_text;           ///< the same in plain text
  /// does-not-follow, written as an equivalence (\\iff): which way it fails, in a sentence
  std::string equivalence_note;
  std::vector<CounterexampleValue> counterexample;  ///< does-not-follow: values that break it
  bool counterexample_exact = false;  ///< the values are exact (checked with exact arithmetic)
  /// does-not-follow with functions or sums: the formulas or counts the counterexample takes
  /// ("F(u) = u^2, N = 2")
  std::string counterexample_functions;
  std::optional<bool> converse;    ///< follows: whether the step before follows from it
  std::string dimension_first;     ///< dimensions: the one dimension ("M L T^-1")
  std::string dimension_second;    ///< dimensions: the other one
  std::string dimension_what;      ///< dimensions: which terms disagree
  std::size_t numeric_points = 0;  ///< points of the numeric method
  double numeric_worst = 0.0;      ///< the worst relative residual it saw
  double seconds = 0.0;            ///< wall time of its check
};

/// @brief What a submission made of its task (`impulselab check --task TASK.md FILE.md`).
struct TaskResult {
  std::string task;                 ///< how the task file was named
  std::string target;               ///< the task's target, LaTeX
  bool target_reached = false;      ///< a step equivalent to the target, and no premise the task
                                    ///< does not give
  std::optional<std::size_t> line;  ///< the first step equivalent to the target
  std::vector<std::size_t> extra_premises;  ///< lines of premises the task does not give
  /// "reached", "target-assumed" (an extra premise is the target), "extra-premise" or
  /// "not-reached"
  std::string reason;
};

/// @brief Something the file holds that is not checked and that its writer may have meant to be:
/// an equation in inline math on a line of its own.
struct FileNote {
  std::size_t line = 0;    ///< 1-based line in the file
  std::size_t column = 0;  ///< 1-based column (characters) where it begins
  std::string written;     ///< what stands there, as written
  std::string text;        ///< what the checker did with it, and how to have it checked
};

/// @brief A checked derivation file.
struct DerivationReport {
  std::string file;                       ///< how the file was named
  std::vector<EquationResult> equations;  ///< in the file's order
  std::vector<FileNote> notes;            ///< in the file's order
  std::size_t counts[7] = {};             ///< per verdict, in the order of all_verdicts
  double seconds = 0.0;                   ///< wall time of the check
  std::optional<TaskResult> task;         ///< checked against a task: what it made of it
  /// @brief How many equations got @p verdict.
  /// @param verdict the verdict
  /// @return the count
  [[nodiscard]] std::size_t count(Verdict verdict) const {
    return counts[static_cast<std::size_t>(verdict)];
  }
};

/// @brief Settings of a check.
struct DerivationOptions {
  std::uint64_t seed = 1;    ///< the numeric method's random points
  std::size_t samples = 24;  ///< points per step for the numeric method
  /// Each step's time budget, in seconds of the checking thread's processor time (WebAssembly:
  /// the browser's clock): past it, the step is undecided.
  double step_seconds = 2.0;
};

/// @brief The largest derivation file read (4 MiB): a longer one is refused with its place.
inline constexpr std::size_t max_derivation_bytes = std::size_t{4} << 20;

/// @brief A place in a file that cannot be read, and what was expected there (the base of
/// DerivationError and TaskError, which say whose file it is).
class FileError : public std::runtime_error {
 public:
  /// @brief An error at a place.
  /// @param line 1-based line
  /// @param column 1-based column (characters)
  /// @param message what was expected there
  FileError(std::size_t line, std::size_t column, const std::string& message)
      : std::runtime_error(message), line_(line), column_(column) {}
  /// @brief The line of the error.
  /// @return 1-based
  [[nodiscard]] std::size_t line() const { return line_; }
  /// @brief The column of the error.
  /// @return 1-based, in characters
  [[nodiscard]] std::size_t column() const { return column_; }

 private:
  std::size_t line_;
  std::size_t column_;
};

/// @brief A derivation file that cannot be read: printed as `FILE:LINE:COLUMN: what was
/// expected`.
class DerivationError : public FileError {
 public:
  using FileError::FileError;
};

/// @brief Checks a derivation file: every display equation, in order.
/// @param text the file's contents
/// @param file how reports and errors name the file
/// @param options seed and samples of the numeric method
/// @return the verdicts
/// @throws DerivationError when the file cannot be read (nothing is checked then)
[[nodiscard]] DerivationReport check_derivation(std::string text, const std::string& file,
                                                const DerivationOptions& options = {});

/// @brief A lecturer's task: a derivation file whose `given:` premises a submission may use and
/// whose `target:` equation it must reach.
struct Task {
  std::string text;  ///< the task file's contents
  std::string file;  ///< how errors name it
};

/// @brief Checks a submission against a task: every equation as check_derivation does, and
/// also each premise it states must be one of the task's or follow from them, and one of its
/// steps must be equivalent to the target (under the task's facts).
/// @param text the submission's contents
/// @param file how reports and errors name the submission
/// @param task the task
/// @param options seed, samples, time budget
/// @return the verdicts and the task's result
/// @throws DerivationError when the submission cannot be read; TaskError when the task cannot
[[nodiscard]] DerivationReport check_derivation(std::string text, const std::string& file,
                                                const Task& task,
                                                const DerivationOptions& options = {});

/// @brief A task file that cannot be read (or has no target): its place and what was expected.
class TaskError : public FileError {
 public:
  using FileError::FileError;
};

/// @brief The exit status the contract gives a report: 1 when an equation does not follow, has
/// mismatched dimensions or is undecided, or the task's target is not reached, else 0.
/// @param report the checked file
/// @return 0 or 1
[[nodiscard]] int exit_status(const DerivationReport& report);

/// @brief What a submission made of its task, as a sentence: "the target is reached at line 9.",
/// "a premise the task does not give (line 7).", "the target is assumed, not derived (…)." …
/// @param task the task's result
/// @return the sentence (the text report prints it after "Task TASK.md: ")
[[nodiscard]] std::string task_verdict(const TaskResult& task);

/// @brief One file of a run over several: its report, or why it could not be read.
struct FileRow {
  std::string file;                        ///< how it was named
  std::optional<DerivationReport> report;  ///< when it was read
  std::string error;                       ///< when it was not: FILE:LINE:COLUMN: message
  int exit = 0;                            ///< its exit status: 0, 1 or 2
};

/// @brief The summary of a run over several files, one row each: text, markdown, json or csv.
/// @param rows the files, in the order they were checked
/// @param format the format
/// @return the rendered summary
[[nodiscard]] std::string render_rows(const std::vector<FileRow>& rows, Format format);

/// @brief Renders a derivation report.
/// @param report the checked file
/// @param format text (for people), markdown (for notes and docs) or json (the contract)
/// @param colour ANSI colours in the text format
/// @return the rendered report
[[nodiscard]] std::string render(const DerivationReport& report, Format format,
                                 bool colour = false);

}  // namespace impulse::derivations
