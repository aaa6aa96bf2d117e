// SPDX-License-Identifier: GPL-3.0-or-later
// The one door from the derivation page into the checker (embind): a derivation file's text in,
// the engine's own answer out. It calls what `impulselab check NOTES.md --format json` calls
// (impulse::derivations::check_derivation, then render with Format::json), so that the page's
// verdicts are the command line's; nothing of the checker is written again in JavaScript.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <exception>
#include <new>
#include <string>

#include "derivations/derivation.hpp"

namespace {

using emscripten::val;
namespace check = impulse::derivations;

// The options, a JavaScript object: {file, stepSeconds}. `file` names the file in the report (the
// command line names it by its path; "check.html" when left out). `stepSeconds` is each step's
// time budget (--step-seconds; DerivationOptions::step_seconds, 2 s when left out). The
// other settings are the command line's defaults (its seed and number of random points).
std::string file_from(const val& options) {
  if (!options.isUndefined() && !options.isNull() && options["file"].isString()) {
    return options["file"].as<std::string>();
  }
  return "check.html";
}

// The settings of @p options, or the caller's mistake in @p error.
check::DerivationOptions settings_from(const val& options, std::string& error) {
  check::DerivationOptions settings;
  if (!options.isUndefined() && !options.isNull() && !options["stepSeconds"].isUndefined()) {
    const val seconds = options["stepSeconds"];
    const double value = seconds.isNumber() ? seconds.as<double>() : 0.0;
    if (!(value > 0.0) || value > 3600.0) {  // the command line's --step-seconds takes these
      error = "stepSeconds: expected a time from 0 to 3600 seconds";
    }
    settings.step_seconds = value;
  }
  return settings;
}

// Checks the derivation whose text is @p text (a string or, for bytes that are not UTF-8, a
// Uint8Array) and returns {result, error, line, column, status}:
//  - result: what `impulselab check FILE --format json` prints, or "" when it refuses the file;
//  - error:  its refusal "LINE:COLUMN: what was expected" (the command line's message without
//            the file's name), or "";
//  - line, column: the place of the refusal (0 when there is none);
//  - status: the command line's exit status (0, 1 when a step does not pass, 2 refused).
val check_derivation(const std::string& text, const val& options) {
  val out = val::object();
  std::string result;
  std::string error;
  std::size_t line = 0;
  std::size_t column = 0;
  int status = 2;
  const check::DerivationOptions settings = settings_from(options, error);
  if (error.empty()) {  // else the caller's option is refused
    try {
      const check::DerivationReport report =
          check::check_derivation(text, file_from(options), settings);
      result = check::render(report, check::Format::json);
      status = check::exit_status(report);
    } catch (const check::DerivationError& e) {
      line = e.line();
      column = e.column();
      error = std::to_string(line) + ":" + std::to_string(column) + ": " + e.what();
    } catch (const std::bad_alloc&) {
      error = "internal error (please report it): out of memory";
    } catch (const std::exception& e) {
      error = std::string("internal error (please report it): ") + e.what();
    }
  }
  out.set("result", result);
  out.set("error", error);
  out.set("line", line);
  out.set("column", column);
  out.set("status", status);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(impulselab_check) {
  emscripten::function("checkDerivation", &check_derivation);
}
