// SPDX-License-Identifier: GPL-3.0-or-later
#include "check_command.hpp"

#include <memory>
#include <set>
#include <string>

#include "app.hpp"
#include "derivations/check.hpp"
#include "output.hpp"

namespace impulselab {

namespace {

namespace check = impulse::derivations;

struct CheckOptions {
  std::string format = "text";
  std::string section;
  std::size_t samples = 10000;
  std::uint64_t seed = 1;
  std::string output;
};

// The sections that have checks, for the message when --section selects none.
std::string known_sections() {
  std::set<std::string> sections;
  for (const auto& c : check::all_checks()) {
    sections.insert(c.section);
  }
  std::string list;
  for (const auto& s : sections) {
    list += (list.empty() ? "" : ", ") + s;
  }
  return list;
}

void run_checks(const CheckOptions& options) {
  const check::Report report = check::run({options.section, options.samples, options.seed});
  if (report.results.empty()) {
    throw UsageError("--section " + options.section +
                     ": no check is in that section (the "
                     "paper's sections with checks: " +
                     known_sections() + ")");
  }
  const check::Format format = options.format == "json"       ? check::Format::json
                               : options.format == "markdown" ? check::Format::markdown
                                                              : check::Format::text;
  const bool colour = format == check::Format::text && colour_wanted(options.output);
  const std::string text = check::render(report, format, colour);
  write_output(options.output, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
  if (report.summary.failed > 0) {
    std::string ids;
    for (const auto& r : report.results) {
      if (r.outcome.status == check::Status::failed) {
        ids += (ids.empty() ? "" : ", ") + r.check.id;
      }
    }
    throw WorkFailed(std::to_string(report.summary.failed) + " check(s) failed: " + ids);
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
      "erratum (with a corrected form that holds) or refuted (with a counterexample).");
  verb->add_option("--format,-f", options->format, "text (the default), markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  verb->add_option("--section,-s", options->section,
                   "only this section of the paper and its subsections, e.g. 4 or 1.3");
  verb->add_option("--samples,-n", options->samples,
                   "random samples per numeric method (default 10000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}));
  verb->add_option("--seed", options->seed, "the seed of the random samples (default 1)");
  verb->add_option("--output,-o", options->output,
                   "write here instead of standard output (atomically: all or nothing)");
  verb->callback([options]() { run_checks(*options); });
}

}  // namespace impulselab
