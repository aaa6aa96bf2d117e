// SPDX-License-Identifier: GPL-3.0-or-later
#include "verdict.hpp"

#include <algorithm>

namespace impulse::derivations {

Finding symbolic(bool holds, std::string detail) {
  return {Method::symbolic, holds, std::nullopt, 0, std::move(detail), true};
}

Finding numeric(Method method, const num::Errors& errors, double holds_below, std::string detail) {
  Finding f{method, false, errors.worst, errors.samples, std::move(detail), true};
  if (errors.samples == 0) {
    f.conclusive = false;  // nothing was compared: no verdict either way
    f.detail += f.detail.empty() ? "no samples" : " (no samples)";
    return f;
  }
  if (errors.worst <= holds_below) {
    f.holds = true;
  } else if (errors.worst < num::fails_above) {
    f.conclusive = false;
  }
  return f;
}

Finding search(std::size_t tried, std::size_t failures, std::string detail) {
  std::string text = std::to_string(failures) + " of " + std::to_string(tried) + " cases fail";
  if (!detail.empty()) {
    text += ", " + detail;
  }
  // A search that tried nothing proves nothing.
  return {Method::search, failures == 0, std::nullopt, tried, std::move(text), tried > 0};
}

namespace {

void collect(const std::vector<Finding>& findings, Outcome& outcome) {
  for (const Finding& f : findings) {
    if (std::find(outcome.methods.begin(), outcome.methods.end(), f.method) ==
        outcome.methods.end()) {
      outcome.methods.push_back(f.method);
    }
  }
}

// The printed statement's worst error and sample count are what the report shows.
void numbers(const std::vector<Finding>& findings, Outcome& outcome) {
  for (const Finding& f : findings) {
    if (f.error) {
      outcome.max_relative_error = std::max(outcome.max_relative_error.value_or(0.0), *f.error);
    }
    if (f.samples > 0) {
      outcome.samples = std::max(outcome.samples.value_or(0), f.samples);
    }
  }
}

std::string details(const std::vector<Finding>& findings, const std::string& label) {
  std::string text;
  for (const Finding& f : findings) {
    if (f.detail.empty() && f.conclusive) {
      continue;
    }
    if (!text.empty()) {
      text += " ";
    }
    text += label + std::string(to_string(f.method)) + ": ";
    text += f.conclusive ? (f.holds ? "holds" : "does not hold") : "inconclusive";
    if (f.error) {
      text += " (worst relative error " + num::brief(*f.error) + ")";
    }
    text += f.detail.empty() ? "." : ", " + f.detail + (f.detail.back() == '.' ? "" : ".");
  }
  return text;
}

std::string join(const std::string& a, const std::string& b) {
  if (a.empty())
    return b;
  if (b.empty())
    return a;
  return a + " " + b;
}

bool all_hold(const std::vector<Finding>& findings) {
  return !findings.empty() && std::all_of(findings.begin(), findings.end(),
                                          [](const Finding& f) { return f.conclusive && f.holds; });
}

bool all_fail(const std::vector<Finding>& findings) {
  return !findings.empty() && std::all_of(findings.begin(), findings.end(), [](const Finding& f) {
    return f.conclusive && !f.holds;
  });
}

}  // namespace

Outcome judge(const EquationVerdict& verdict) {
  Outcome outcome;
  collect(verdict.printed, outcome);
  collect(verdict.corrected, outcome);
  numbers(verdict.printed, outcome);
  outcome.note = join(verdict.note, details(verdict.printed, ""));
  if (all_hold(verdict.printed)) {
    outcome.status = Status::verified;
    return outcome;
  }
  if (all_fail(verdict.printed) && all_hold(verdict.corrected) && !verdict.correction.empty()) {
    outcome.status = Status::erratum;
    outcome.correction = verdict.correction;
    outcome.explanation = verdict.explanation;
    outcome.note = join(outcome.note, details(verdict.corrected, "correction, "));
    return outcome;
  }
  outcome.status = Status::failed;
  outcome.explanation = "The methods disagree or the correction does not hold.";
  outcome.note = join(outcome.note, details(verdict.corrected, "correction, "));
  return outcome;
}

Outcome judge(const ClaimVerdict& verdict) {
  Outcome outcome;
  collect(verdict.findings, outcome);
  numbers(verdict.findings, outcome);
  outcome.note = join(verdict.note, details(verdict.findings, ""));
  // One counterexample refutes a claim, even if another search found none; only a proof (a
  // symbolic finding that it holds) contradicts it.
  const bool proved = std::any_of(
      verdict.findings.begin(), verdict.findings.end(),
      [](const Finding& f) { return f.method == Method::symbolic && f.conclusive && f.holds; });
  const bool some_fail = std::any_of(verdict.findings.begin(), verdict.findings.end(),
                                     [](const Finding& f) { return f.conclusive && !f.holds; });
  if (verdict.counterexample && !proved && some_fail) {
    outcome.status = Status::refuted;
    outcome.counterexample = *verdict.counterexample;
    outcome.explanation = verdict.explanation;
    return outcome;
  }
  if (!verdict.counterexample && all_hold(verdict.findings)) {
    outcome.status = Status::verified;
    return outcome;
  }
  outcome.status = Status::failed;
  outcome.explanation = "The methods disagree about the claim.";
  return outcome;
}

}  // namespace impulse::derivations
