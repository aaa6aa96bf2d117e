// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The derivation checker: every equation, step and claim of the paper as a check.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "impulse/core/names.hpp"

/// @brief The checker of the paper *Collision handling* (`impulselab check`).
///
/// Each numbered equation, each step of a derivation and each factual claim of the prose is a
/// check of a paper file (derivations/paper/sectionN.md, a derivation file with checks): its
/// statement as printed, the evidence in our own words and the models it is tested on. The same
/// engine that checks a student's derivation (derivation.hpp) decides it.
namespace impulse::derivations {

/// @brief What a check is about.
enum class Kind {
  equation,  ///< a numbered result
  step,      ///< a line of a derivation that must follow from the one before
  claim,     ///< a statement of the prose
};

/// @brief How a check was evaluated.
enum class Method {
  symbolic,    ///< exact computer algebra (GiNaC)
  numeric,     ///< random physical configurations (GSL random numbers)
  quadrature,  ///< GSL numerical integration of a work integral
  ode,         ///< an independent continuous-time contact simulation (GSL ODE)
  search,      ///< looking for a counterexample
};

/// @brief The outcome.
enum class Status {
  verified,  ///< holds
  erratum,   ///< does not hold as printed; the correction holds
  refuted,   ///< a claim that does not hold; a counterexample is given
  failed,    ///< none of these: a defect of the checker or an unresolved finding
};

/// @brief A method's row of its table: its name in the report, and the directive that names a
/// model of it in a file.
struct MethodName {
  Method value;           ///< the method
  std::string_view name;  ///< "symbolic", "numeric", …
  std::string_view
      directive;  ///< `ode:`, `quadrature:`, `model:` (numeric), `search:`; "" for none
};

}  // namespace impulse::derivations

namespace impulse {
/// @brief The kinds of check, by their names in the report.
template <>
struct EnumNames<derivations::Kind> {
  /// one row per kind
  static constexpr std::array<Named<derivations::Kind>, 3> table{
      {{derivations::Kind::equation, "equation"},
       {derivations::Kind::step, "step"},
       {derivations::Kind::claim, "claim"}}};
};
/// @brief The methods of a check, by their names in the report and in a file.
template <>
struct EnumNames<derivations::Method> {
  /// one row per method
  static constexpr std::array<derivations::MethodName, 5> table{
      {{derivations::Method::symbolic, "symbolic", ""},
       {derivations::Method::numeric, "numeric", "model"},
       {derivations::Method::quadrature, "quadrature", "quadrature"},
       {derivations::Method::ode, "ode", "ode"},
       {derivations::Method::search, "search", "search"}}};
};
/// @brief The statuses of a check, by their names in the report.
template <>
struct EnumNames<derivations::Status> {
  /// one row per status
  static constexpr std::array<Named<derivations::Status>, 4> table{
      {{derivations::Status::verified, "verified"},
       {derivations::Status::erratum, "erratum"},
       {derivations::Status::refuted, "refuted"},
       {derivations::Status::failed, "failed"}}};
};
}  // namespace impulse

namespace impulse::derivations {

/// @brief The report name of a kind, a method or a status ("equation", "symbolic", "verified").
/// @tparam Enum Kind, Method or Status
/// @param value the value
/// @return its name
template <typename Enum>
[[nodiscard]] constexpr std::string_view to_string(Enum value) requires
    std::is_same_v<Enum, Kind> || std::is_same_v<Enum, Method> || std::is_same_v<Enum, Status> {
  return name_of(value);
}

/// @brief What evaluating a check found.
struct Outcome {
  Status status = Status::failed;            ///< the verdict
  std::vector<Method> methods;               ///< the methods that were run
  std::optional<double> max_relative_error;  ///< worst disagreement of the numeric methods
  std::optional<std::size_t> samples;        ///< random samples drawn
  std::string correction;                    ///< LaTeX of the corrected form (erratum)
  std::string counterexample;                ///< inputs and what happens (refuted)
  std::string explanation;                   ///< what goes wrong (erratum, refuted)
  std::string note;                          ///< assumptions, reading of garbled print, figures
};

/// @brief One check of the paper, as its file states it.
struct Check {
  std::string id;                       ///< stable and unique, e.g. "eq-1.1"
  std::string section;                  ///< the paper's (sub)section, e.g. "1.1"
  std::optional<std::string> equation;  ///< "(1.1)", or nothing for steps and claims
  Kind kind = Kind::equation;           ///< equation, step or claim
  std::string statement;  ///< the statement as the file writes it (the text the engine reads)
  std::string file;       ///< the file it is in ("section1.md", "beyond/friction.md")
  std::size_t line = 0;   ///< the line of its statement in that file
};

/// @brief A check with its outcome and how long it took.
struct Result {
  Check check;           ///< what was checked
  Outcome outcome;       ///< what was found
  double seconds = 0.0;  ///< wall time of the evaluation
};

/// @brief Options of a run (the `check` verb's flags).
struct Options {
  std::string section;          ///< only checks whose section is this or below it ("4", "1.3")
  std::size_t samples = 10000;  ///< random samples per numeric method
  std::uint64_t seed = 1;       ///< the run's seed
};

/// @brief Counts of each status.
struct Summary {
  std::size_t verified = 0;  ///< holds
  std::size_t erratum = 0;   ///< corrected
  std::size_t refuted = 0;   ///< counterexample
  std::size_t failed = 0;    ///< defects
};

/// @brief The checker's own sections beyond the paper (derivations/beyond/, e.g. friction): our
/// derivations, checked by the same engine and reported apart from the paper's checks.
struct Beyond {
  std::vector<Result> results;  ///< in the files' order
  Summary summary;              ///< their counts (not in the paper's summary)
  double seconds = 0.0;         ///< wall time of these checks
};

/// @brief A whole run.
struct Report {
  Options options;              ///< how it was run
  std::vector<Result> results;  ///< in the paper's order
  Summary summary;              ///< the counts
  double seconds = 0.0;         ///< wall time of the run
  Beyond beyond;                ///< the checks beyond the paper that the section filter selects
};

/// @brief A file of the paper: its name and its text (derivations/paper/sectionN.md).
struct PaperFile {
  std::string name;  ///< "section1.md"
  std::string text;  ///< its contents
};

/// @brief The paper's files as this program was built with them (derivations/paper/).
/// @return the files, in the paper's order
[[nodiscard]] const std::vector<PaperFile>& paper_files();

/// @brief The checker's own derivation files beyond the paper as this program was built with them
/// (derivations/beyond/; each named "beyond/NAME.md").
/// @return the files, in the order of their names
[[nodiscard]] const std::vector<PaperFile>& beyond_files();

/// @brief Every check of the files beyond the paper, in their order, without evaluating them.
/// @return the checks
/// @throws DerivationError (derivation.hpp) when a file cannot be read
[[nodiscard]] std::vector<Check> beyond_checks();

/// @brief Every check of the paper's files, in the paper's order, without evaluating them.
/// @return the checks
/// @throws DerivationError (derivation.hpp) when a file cannot be read
[[nodiscard]] std::vector<Check> all_checks();

/// @brief Whether @p section is @p filter or a subsection of it ("4.4" is in "4", not in "4.1").
/// @param section a check's section
/// @param filter the --section value; empty selects everything
/// @return whether the check is selected
[[nodiscard]] bool in_section(std::string_view section, std::string_view filter);

/// @brief The seed a check gets: the run's seed mixed with the check's id, so that a check's
/// samples do not depend on which other checks run.
/// @param run_seed the run's seed
/// @param id the check's id
/// @return the check's seed
[[nodiscard]] std::uint64_t check_seed(std::uint64_t run_seed, std::string_view id);

/// @brief Runs the selected checks of the paper's files (`impulselab check`), and those of the
/// files beyond the paper into Report::beyond.
/// @param options section filter, samples, seed
/// @return the report
/// @throws DerivationError when a file cannot be read (a malformed file is a defect of the build)
[[nodiscard]] Report run(const Options& options);

/// @brief Runs the selected checks of the given files: the same engine as run(), on other files
/// (the tests feed it the paper's files with a change).
/// @param files derivation files with checks
/// @param options section filter, samples, seed
/// @param only when not empty, the one check to run (by id)
/// @return the report
/// @throws DerivationError with the file's place when a file cannot be read
[[nodiscard]] Report run(const std::vector<PaperFile>& files, const Options& options,
                         std::string_view only = {});

/// @brief The report formats.
enum class Format {
  text,      ///< for people at a terminal
  markdown,  ///< for the documentation
  json,      ///< for programs (the contract of spec/cli-and-report.md)
  csv,       ///< one row per derivation file (several files checked in one run)
};

/// @brief Renders a report.
/// @param report the run
/// @param format text, markdown or json
/// @param colour ANSI colours for the text format (only when writing to a terminal)
/// @return the rendered report
[[nodiscard]] std::string render(const Report& report, Format format, bool colour = false);

/// @brief The anchor of a check in the markdown report ("check-eq-1-1" for "eq-1.1").
/// @param id the check's id
/// @return an identifier made of letters, digits and hyphens
[[nodiscard]] std::string anchor(std::string_view id);

}  // namespace impulse::derivations
