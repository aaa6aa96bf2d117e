// SPDX-License-Identifier: GPL-3.0-or-later
#include "check_command.hpp"

#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "app.hpp"
#include "derivations/check.hpp"
#include "derivations/derivation.hpp"
#include "output.hpp"

namespace impulselab {

namespace {

namespace check = impulse::derivations;

struct CheckOptions {
  std::string file;  // a derivation file (NOTES.md); empty: the paper
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
                              : check::Format::text;
}

// A student's derivation: every display equation of the file, line by line.
void check_file(const CheckOptions& options) {
  const std::string& path = options.file;
  if (!path.ends_with(".md")) {
    throw UsageError(path +
                     ": expected a derivation file, whose name ends in .md (without a "
                     "file, check checks the paper)");
  }
  if (!options.section.empty()) {
    throw UsageError("--section selects sections of the paper; it does not apply to " + path);
  }
  // A regular file larger than the limit is refused before it is read; anything else is read
  // up to one byte past the limit, which the reader then refuses with its place.
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error) &&
      std::filesystem::file_size(path, error) > check::max_derivation_bytes && !error) {
    throw PlacedError(path + ":1:1: expected a derivation file of at most " +
                      std::to_string(check::max_derivation_bytes >> 20) + " MiB, this one holds " +
                      std::to_string(std::filesystem::file_size(path, error)) + " bytes");
  }
  std::string text = read_file(path, check::max_derivation_bytes);
  check::DerivationOptions settings;
  settings.seed = options.seed;
  if (options.samples_given) {
    if (options.samples > 1000) {
      throw UsageError("--samples " + std::to_string(options.samples) +
                       ": a derivation file takes at most 1000 random points per step");
    }
    settings.samples = options.samples;
  }
  check::DerivationReport report;
  try {
    report = check::check_derivation(std::move(text), path, settings);
  } catch (const check::DerivationError& e) {
    throw PlacedError(path + ":" + std::to_string(e.line()) + ":" + std::to_string(e.column()) +
                      ": " + e.what());
  }
  const check::Format format = format_named(options.format);
  const bool colour = format == check::Format::text && colour_wanted(options.output);
  const std::string rendered = check::render(report, format, colour);
  write_output(options.output, [&](std::FILE* out) { std::fputs(rendered.c_str(), out); });
  if (check::exit_status(report) != 0) {
    for (const auto& e : report.equations) {
      if (check::fails(e.verdict)) {
        throw WorkFailed(path + ": line " + std::to_string(e.line) + " " +
                         std::string(check::to_string(e.verdict)) +
                         " (the first equation that does not pass)");
      }
    }
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
  if (!options.file.empty()) {
    check_file(options);
    return;
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
  verb->add_option("file", options->file,
                   "a derivation file to check (its name ends in .md); without it, the paper");
  verb->add_option("--format,-f", options->format, "text (the default), markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
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

}  // namespace impulselab
