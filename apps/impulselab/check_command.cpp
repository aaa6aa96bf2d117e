// SPDX-License-Identifier: GPL-3.0-or-later
#include "check_command.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app.hpp"
#include "check_program.hpp"
#include "derivations/check.hpp"
#include "derivations/derivation.hpp"
#include "impulse/core/error.hpp"
#include "output.hpp"

namespace impulselab {

namespace {

namespace check = impulse::derivations;

struct CheckOptions {
  std::vector<std::string> files;  // derivation files or folders of them; empty: the paper
  std::string task;                // a task file the derivation files are submissions to
  double step_seconds = 2.0;       // each step's time budget
  std::string format = "text";
  std::string section;
  std::size_t samples = 10000;
  bool samples_given = false;
  std::uint64_t seed = 1;
  std::string output;
};

check::Format format_named(const std::string& name) {
  return name == "json"       ? check::Format::json
         : name == "markdown" ? check::Format::markdown
         : name == "csv"      ? check::Format::csv
                              : check::Format::text;
}

// A derivation file's text, refused with its place when it is too large.
std::string read_derivation(const std::string& path) {
  // A regular file larger than the limit is refused before it is read; anything else is read
  // up to one byte past the limit, which the reader then refuses with its place.
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error) &&
      std::filesystem::file_size(path, error) > check::max_derivation_bytes && !error) {
    throw PlacedError(path + ":1:1: expected a derivation file of at most " +
                      std::to_string(check::max_derivation_bytes >> 20) + " MiB, this one holds " +
                      std::to_string(std::filesystem::file_size(path, error)) + " bytes");
  }
  return read_file(path, check::max_derivation_bytes);
}

check::DerivationOptions settings_of(const CheckOptions& options) {
  check::DerivationOptions settings;
  settings.seed = options.seed;
  if (options.samples_given) {
    if (options.samples > 1000) {
      throw UsageError("--samples " + std::to_string(options.samples) +
                       ": a derivation file takes at most 1000 random points per step");
    }
    settings.samples = options.samples;
  }
  if (!(options.step_seconds > 0) || options.step_seconds > 3600) {
    throw UsageError("--step-seconds: expected a time from 0 to 3600 seconds");
  }
  settings.step_seconds = options.step_seconds;
  return settings;
}

// The derivation files named: files ending in .md, and the .md files of folders (sorted).
std::vector<std::string> derivation_paths(const std::vector<std::string>& named) {
  std::vector<std::string> paths;
  for (const std::string& path : named) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
      std::vector<std::string> inside;
      for (const auto& entry : std::filesystem::directory_iterator(path, error)) {
        if (entry.path().extension() == ".md" && entry.is_regular_file(error)) {
          inside.push_back(entry.path().string());
        }
      }
      if (inside.empty()) {
        throw UsageError(path + ": expected a folder that holds derivation files (.md)");
      }
      std::sort(inside.begin(), inside.end());
      paths.insert(paths.end(), inside.begin(), inside.end());
      continue;
    }
    if (!path.ends_with(".md")) {
      throw UsageError(path +
                       ": expected a derivation file, whose name ends in .md, or a folder of "
                       "them (without a file, check checks the paper)");
    }
    paths.push_back(path);
  }
  return paths;
}

// One file checked (against the task when there is one): its report, or its refusal.
check::FileRow check_one(const std::string& path, const std::optional<check::Task>& task,
                         const check::DerivationOptions& settings) {
  check::FileRow row;
  row.file = path;
  try {
    std::string text = read_derivation(path);
    row.report = task ? check::check_derivation(std::move(text), path, *task, settings)
                      : check::check_derivation(std::move(text), path, settings);
    row.exit = check::exit_status(*row.report);
  } catch (const check::DerivationError& e) {
    row.error =
        path + ":" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": " + e.what();
    row.exit = exit_usage;
  } catch (const PlacedError& e) {
    row.error = e.what();
    row.exit = exit_usage;
  } catch (const impulse::InvalidInput& e) {
    row.error = e.what();
    row.exit = exit_usage;
  }
  return row;
}

// Why a report fails, for the message on standard error.
std::string failure_of(const check::DerivationReport& report) {
  for (const auto& e : report.equations) {
    if (check::fails(e.verdict)) {
      return report.file + ": line " + std::to_string(e.line) + " " +
             std::string(check::to_string(e.verdict)) + " (the first equation that does not pass)";
    }
  }
  if (report.task && !report.task->target_reached) {
    std::string why = check::task_verdict(*report.task);
    why.pop_back();  // the full stop: the message ends as the others do
    return report.file + ": " + why;
  }
  return report.file + ": fails";
}

// Students' derivations: every display equation of each file, line by line; with several files,
// one summary row each; with a task, each judged against it.
void check_files(const CheckOptions& options) {
  if (!options.section.empty()) {
    throw UsageError(
        "--section selects sections of the paper; it does not apply to derivation "
        "files");
  }
  const check::DerivationOptions settings = settings_of(options);
  std::optional<check::Task> task;
  if (!options.task.empty()) {
    task = check::Task{read_derivation(options.task), options.task};
  }
  const std::vector<std::string> paths = derivation_paths(options.files);
  const check::Format format = format_named(options.format);
  std::vector<check::FileRow> rows;
  for (const std::string& path : paths) {
    try {
      rows.push_back(check_one(path, task, settings));
    } catch (const check::TaskError& e) {
      throw PlacedError(options.task + ":" + std::to_string(e.line()) + ":" +
                        std::to_string(e.column()) + ": " + e.what());
    }
  }
  const bool one = rows.size() == 1 && options.files.size() == 1 &&
                   !std::filesystem::is_directory(options.files[0]);
  if (one && !rows[0].report) {
    throw PlacedError(rows[0].error);
  }
  const bool colour = format == check::Format::text && colour_wanted(options.output);
  std::string rendered;
  if (one) {
    rendered = check::render(*rows[0].report, format, colour);
  } else if (format == check::Format::text || format == check::Format::markdown) {
    for (const check::FileRow& row : rows) {
      if (row.report) {
        rendered += check::render(*row.report, format, colour) + "\n";
      }
    }
    rendered += check::render_rows(rows, format);
  } else {
    rendered = check::render_rows(rows, format);
  }
  write_output(options.output, [&](std::FILE* out) { std::fputs(rendered.c_str(), out); });
  int worst = exit_success;
  std::string why;
  for (const check::FileRow& row : rows) {
    if (row.exit == exit_usage && !one) {
      std::fprintf(stderr, "%s\n", row.error.c_str());
    }
    if (row.exit > worst) {
      worst = row.exit;
      why = row.report ? failure_of(*row.report) : row.error;
    }
  }
  if (worst == exit_usage) {
    throw PlacedError(std::to_string(std::count_if(rows.begin(), rows.end(),
                                                   [](const auto& r) { return r.exit == 2; })) +
                      " of " + std::to_string(rows.size()) +
                      " files could not be read (first: " + why + ")");
  }
  if (worst == exit_failure) {
    throw WorkFailed(
        one ? why
            : std::to_string(std::count_if(rows.begin(), rows.end(),
                                           [](const auto& r) { return r.exit == 1; })) +
                  " of " + std::to_string(rows.size()) + " files fail (first: " + why + ")");
  }
}

// The sections that have checks, for the message when --section selects none.
std::string known_sections() {
  std::set<std::string> sections;
  for (const auto& c : check::all_checks()) {  // the files were read by run() already
    sections.insert(c.section);
  }
  for (const auto& c : check::beyond_checks()) {  // beyond the paper: friction, …
    sections.insert(c.section);
  }
  std::string list;
  for (const auto& s : sections) {
    list += (list.empty() ? "" : ", ") + s;
  }
  return list;
}

void run_checks(const CheckOptions& options) {
  if (!options.files.empty()) {
    check_files(options);
    return;
  }
  if (!options.task.empty()) {
    throw UsageError("--task needs the derivation files to judge against it");
  }
  if (options.format == "csv") {
    throw UsageError("--format csv is for derivation files (one row per file)");
  }
  check::Report report;
  try {
    report = check::run({options.section, options.samples, options.seed});
  } catch (const check::DerivationError& e) {
    // A paper file that cannot be read: a defect of this build, placed in its file.
    throw PlacedError(e.what());
  }
  if (report.results.empty() && report.beyond.results.empty()) {
    throw UsageError("--section " + options.section +
                     ": no check is in that section (the "
                     "paper's sections with checks: " +
                     known_sections() + ")");
  }
  const check::Format format = format_named(options.format);
  const bool colour = format == check::Format::text && colour_wanted(options.output);
  const std::string text = check::render(report, format, colour);
  write_output(options.output, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
  // A failed check beyond the paper fails the run too.
  const std::size_t failed = report.summary.failed + report.beyond.summary.failed;
  if (failed > 0) {
    std::string ids;
    for (const auto* results : {&report.results, &report.beyond.results}) {
      for (const auto& r : *results) {
        if (r.outcome.status == check::Status::failed) {
          ids += (ids.empty() ? "" : ", ") + r.check.id;
        }
      }
    }
    throw WorkFailed(std::to_string(failed) + " check(s) failed: " + ids);
  }
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* verb = app.add_subcommand(
      "check",
      "Check the paper: every numbered equation, every step of its derivations and every claim "
      "of its prose, exactly (computer algebra) and numerically (random samples, quadrature, a "
      "continuous-time contact simulation, searches for counterexamples). Each is verified, an "
      "erratum (with a corrected form that holds) or refuted (with a counterexample). Given a "
      "derivation file (NOTES.md: Markdown with $$ display equations $$), check it instead, line "
      "by line: each step follows, follows one way, follows if a condition holds, or does not "
      "follow (with what is left over and values that break it).");
  verb->add_option("files", options->files,
                   "derivation files to check (their names end in .md) or folders of them; "
                   "without them, the paper");
  verb->add_option("--task", options->task,
                   "a task file (given: premises, target: equation): each derivation file must "
                   "use only its premises and reach its target");
  verb->add_option("--step-seconds", options->step_seconds,
                   "each step's time budget in seconds of processor time (default 2): past it, "
                   "the step is undecided");
  verb->add_option("--format,-f", options->format,
                   "text (the default), markdown, json, or csv (derivation files: one row each)")
      ->check(CLI::IsMember({"text", "markdown", "json", "csv"}));
  verb->add_option("--section,-s", options->section,
                   "only this section of the paper and its subsections, e.g. 4 or 1.3, or friction "
                   "(beyond the paper)");
  verb->add_option("--samples,-n", options->samples,
                   "random samples per numeric method (default 10000; for a derivation file, "
                   "random points per step, default 24)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
      ->each([options](const std::string&) { options->samples_given = true; });
  verb->add_option("--seed", options->seed, "the seed of the random samples (default 1)");
  verb->add_option("--output,-o", options->output,
                   "write here instead of standard output (atomically: all or nothing)");
  verb->callback([options]() { run_checks(*options); });
}

int check_program(int argc, char** argv) {
  return run(argc, argv, [](CLI::App& app) { add_check_command(app); });
}

}  // namespace impulselab
