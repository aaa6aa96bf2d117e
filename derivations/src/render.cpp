// SPDX-License-Identifier: GPL-3.0-or-later
#include <nlohmann/json.hpp>

#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "derivations/check.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

namespace {

// Our own titles of the paper's (sub)sections.
const std::map<std::string, std::string, std::less<>>& titles() {
  static const std::map<std::string, std::string, std::less<>> t{
      {"1", "Bodies on a line: the setting"},
      {"1.1", "Bodies on a line, elastic"},
      {"1.2", "Bodies on a line, inelastic"},
      {"1.3", "The elasticity parameter"},
      {"2", "Point masses in the plane: the cast onto the normal"},
      {"3", "A rigid body, one contact: the setting"},
      {"3.1", "A rigid body, elastic"},
      {"3.2", "A rigid body, inelastic"},
      {"3.3", "A rigid body: elasticity"},
      {"3.4", "A rigid body: solving"},
      {"4", "Point masses, many contacts: the setting"},
      {"4.1", "Point masses, many contacts, elastic"},
      {"4.2", "Point masses, many contacts, inelastic"},
      {"4.3", "Point masses, many contacts: elasticity"},
      {"4.4", "Solving the many-contact system"},
      {"4.5", "Many bodies"},
      {"5", "Rigid bodies, many contacts: the setting"},
      {"5.1", "Rigid bodies, many contacts, elastic"},
      {"5.2", "Rigid bodies, many contacts, inelastic"},
      {"5.3", "Rigid bodies, many contacts: elasticity"},
      // Beyond the paper (derivations/beyond/).
      {"friction.1", "A contact with friction: its velocity, linear in the impulse"},
      {"friction.2", "Slip, stick and the end of compression"},
      {"friction.3", "Three laws of restitution: where each ends"},
      {"friction.4", "Does a law gain energy?"},
      {"friction.5", "The rod of issue 17"},
  };
  return t;
}

std::string title(const std::string& section) {
  const auto it = titles().find(section);
  return it == titles().end() ? std::string() : it->second;
}

std::string methods_list(const std::vector<Method>& methods) {
  std::string text;
  for (const Method m : methods) {
    text += (text.empty() ? "" : ", ") + std::string(to_string(m));
  }
  return text;
}

std::string error_text(const Outcome& o) {
  return o.max_relative_error ? num::brief(*o.max_relative_error, 2) : "-";
}

std::string pad(std::string text, std::size_t width) {
  // Pads by characters as printed (UTF-8 continuation bytes take no column).
  std::size_t columns = 0;
  for (const char c : text) {
    columns += (static_cast<unsigned char>(c) & 0xC0U) != 0x80U ? 1 : 0;
  }
  if (columns < width) {
    text.append(width - columns, ' ');
  }
  return text;
}

std::string summary_line(const Summary& s) {
  return std::to_string(s.verified) + " verified, " + std::to_string(s.erratum) + " errata, " +
         std::to_string(s.refuted) + " refuted, " + std::to_string(s.failed) + " failed";
}

const char* colour_of(Status status) {
  switch (status) {
    case Status::verified:
      return "\033[32m";
    case Status::erratum:
      return "\033[33m";
    case Status::refuted:
      return "\033[35m";
    case Status::failed:
      return "\033[31;1m";
  }
  return "";
}

// The checks of a list grouped by section, then the summary and the errata, refuted and failed
// checks (the paper's, or those beyond it).
void text_part(std::ostringstream& out, const std::vector<Result>& results, const Summary& summary,
               double seconds, const std::string& summary_name, bool colour) {
  std::string current;
  for (const Result& r : results) {
    if (r.check.section != current) {
      current = r.check.section;
      out << "\n" << current << "  " << title(current) << "\n";
    }
    const std::string status(to_string(r.outcome.status));
    out << "  " << pad(r.check.id, 26) << pad(r.check.equation.value_or(""), 7)
        << pad(std::string(to_string(r.check.kind)), 10);
    if (colour) {
      out << colour_of(r.outcome.status) << pad(status, 10) << "\033[0m";
    } else {
      out << pad(status, 10);
    }
    out << pad(methods_list(r.outcome.methods), 36) << error_text(r.outcome) << "\n";
  }
  out << "\n"
      << summary_name << ": " << summary_line(summary) << " (" << num::brief(seconds, 2) << " s)\n";
  for (const Status wanted : {Status::erratum, Status::refuted, Status::failed}) {
    bool heading = false;
    for (const Result& r : results) {
      if (r.outcome.status != wanted) {
        continue;
      }
      if (!heading) {
        out << "\n"
            << (wanted == Status::erratum   ? "Errata"
                : wanted == Status::refuted ? "Refuted claims"
                                            : "Failed checks")
            << ":\n";
        heading = true;
      }
      out << "  " << r.check.id << (r.check.equation ? " " + *r.check.equation : "") << ": "
          << r.outcome.explanation << "\n";
      if (!r.outcome.correction.empty()) {
        out << "      correction: " << r.outcome.correction << "\n";
      }
      if (!r.outcome.counterexample.empty()) {
        out << "      counterexample: " << r.outcome.counterexample << "\n";
      }
    }
  }
}

// "Beyond the paper: friction": the top-level sections of the checks beyond the paper.
std::string beyond_title(const Beyond& beyond) {
  std::string names;
  for (const Result& r : beyond.results) {
    const std::string top = r.check.section.substr(0, r.check.section.find('.'));
    if (names.find(top) == std::string::npos) {
      names += (names.empty() ? "" : ", ") + top;
    }
  }
  return "Beyond the paper: " + names;
}

std::string render_text(const Report& report, bool colour) {
  std::ostringstream out;
  out << "Collision handling: derivation check (seed " << report.options.seed << ", "
      << report.options.samples << " samples per numeric method";
  if (!report.options.section.empty()) {
    out << ", section " << report.options.section;
  }
  out << ")\n";
  if (!report.results.empty() || report.beyond.results.empty()) {
    text_part(out, report.results, report.summary, report.seconds, "Summary", colour);
  }
  if (!report.beyond.results.empty()) {
    const std::string heading = beyond_title(report.beyond);
    out << "\n"
        << heading << "\n"
        << std::string(heading.size(), '=') << "\n"
        << "Our own derivations, checked by the same engine; not counted in the paper's "
           "summary.\n";
    text_part(out, report.beyond.results, report.beyond.summary, report.beyond.seconds,
              "Summary beyond the paper", colour);
  }
  return out.str();
}

const char* mark(Status status) {
  switch (status) {
    case Status::verified:
      return "verified";
    case Status::erratum:
      return "**erratum**";
    case Status::refuted:
      return "**refuted**";
    case Status::failed:
      return "**FAILED**";
  }
  return "";
}

// A statement as MathJax 2 displays it: the statement keeps its \tag where the paper's file puts
// it (inside a gathered block, say), which MathJax refuses there; the tag goes to the end (the
// check's label when the statement has none), the \labels (names the files give rows for their
// evidence) go, and rows without an environment of their own are gathered. The JSON report gives
// it as "display", which the docs' section pages show (docs/cmake/prepare_site.cmake).
std::string displayed(const Check& check) {
  static const std::regex tag(R"(\\tag\{[^}]*\})");
  static const std::regex tag_or_label(R"(\\(tag|label)\{[^}]*\})");
  std::smatch found;
  std::string shown_tag;
  if (std::regex_search(check.statement, found, tag)) {
    shown_tag = found.str();
  } else if (check.equation && check.equation->size() > 2 && check.equation->front() == '(' &&
             check.equation->back() == ')') {
    shown_tag = "\\tag{";  // piece by piece: GCC 12 warns falsely on "lit" + std::string&&
    shown_tag.append(*check.equation, 1, check.equation->size() - 2);
    shown_tag += '}';
  }
  std::string shown = std::regex_replace(check.statement, tag_or_label, "");
  if (shown.find("\\\\") != std::string::npos && shown.find("\\begin{") == std::string::npos) {
    shown = "\\begin{gathered} " + shown + " \\end{gathered}";
  }
  return shown_tag.empty() ? shown : shown + " " + shown_tag;
}

// The table of a list of checks, then each check under its section's heading (the headings
// one level deeper beyond the paper).
void markdown_part(std::ostringstream& out, const std::vector<Result>& results,
                   const std::string& level) {
  out << "| check | equation | kind | status | methods | max. relative error |\n"
      << "|---|---|---|---|---|---|\n";
  for (const Result& r : results) {
    out << "| \\ref " << anchor(r.check.id) << " \"" << r.check.id << "\" | "
        << r.check.equation.value_or("") << " | " << to_string(r.check.kind) << " | "
        << mark(r.outcome.status) << " | " << methods_list(r.outcome.methods) << " | "
        << error_text(r.outcome) << " |\n";
  }
  std::string current;
  for (const Result& r : results) {
    if (r.check.section != current) {
      current = r.check.section;
      out << "\n" << level << " " << current << " " << title(current);
      // Beyond the paper the section's heading is a Doxygen subsection (it needs an id) around
      // its checks' subsubsections.
      if (level != "##") {
        out << " {#beyond-" << anchor(current).substr(std::string("check-").size()) << "}";
      }
      out << "\n";
    }
    out << "\n"
        << level << "# " << r.check.id << (r.check.equation ? " " + *r.check.equation : "") << " {#"
        << anchor(r.check.id) << "}\n\n"
        << "\\f[ " << displayed(r.check) << " \\f]\n\n"
        << "- kind: " << to_string(r.check.kind) << "\n"
        << "- status: " << mark(r.outcome.status) << "\n"
        << "- methods: " << methods_list(r.outcome.methods) << "\n";
    if (r.outcome.max_relative_error) {
      out << "- worst relative error: " << error_text(r.outcome) << " over "
          << r.outcome.samples.value_or(0) << " samples\n";
    }
    if (!r.outcome.explanation.empty()) {
      out << "- what goes wrong: " << r.outcome.explanation << "\n";
    }
    if (!r.outcome.correction.empty()) {
      out << "- correction: \\f$ " << r.outcome.correction << " \\f$\n";
    }
    if (!r.outcome.counterexample.empty()) {
      out << "- counterexample: " << r.outcome.counterexample << "\n";
    }
    if (!r.outcome.note.empty()) {
      out << "- note: " << r.outcome.note << "\n";
    }
  }
}

// Markdown for the Doxygen site: math in \f[ \f], each check a heading with an anchor.
std::string render_markdown(const Report& report) {
  std::ostringstream out;
  out << "# Derivation check report {#check_report}\n\n"
      << "Every numbered equation, derivation step and claim of the paper, checked by "
         "`impulselab check` (seed "
      << report.options.seed << ", " << report.options.samples
      << " samples per numeric method).\n\n"
      << "**Summary:** " << summary_line(report.summary) << ".\n\n";
  markdown_part(out, report.results, "##");
  if (!report.beyond.results.empty()) {
    out << "\n## " << beyond_title(report.beyond) << " {#check_beyond_the_paper}\n\n"
        << "Our own derivations beyond the paper (derivations/beyond/), checked by the same "
           "engine and counted apart from the paper's checks.\n\n"
        << "**Summary beyond the paper:** " << summary_line(report.beyond.summary) << ".\n\n";
    markdown_part(out, report.beyond.results, "###");
  }
  return out.str();
}

nlohmann::ordered_json summary_json(const Summary& s) {
  return {{"verified", s.verified},
          {"erratum", s.erratum},
          {"refuted", s.refuted},
          {"failed", s.failed}};
}

// The checks of a list, each in the contract's shape.
nlohmann::ordered_json checks_json(const std::vector<Result>& results) {
  using nlohmann::ordered_json;
  ordered_json checks = ordered_json::array();
  for (const Result& r : results) {
    ordered_json c;
    c["id"] = r.check.id;
    c["section"] = r.check.section;
    c["equation"] = r.check.equation ? ordered_json(*r.check.equation) : ordered_json(nullptr);
    c["kind"] = to_string(r.check.kind);
    c["statement"] = r.check.statement;
    c["display"] = displayed(r.check);
    ordered_json methods = ordered_json::array();
    for (const Method m : r.outcome.methods) {
      methods.push_back(to_string(m));
    }
    c["methods"] = methods;
    c["status"] = to_string(r.outcome.status);
    c["max_relative_error"] = r.outcome.max_relative_error
                                  ? ordered_json(*r.outcome.max_relative_error)
                                  : ordered_json(nullptr);
    c["samples"] = r.outcome.samples ? ordered_json(*r.outcome.samples) : ordered_json(nullptr);
    if (!r.outcome.correction.empty()) {
      c["correction"] = r.outcome.correction;
    }
    if (!r.outcome.counterexample.empty()) {
      c["counterexample"] = r.outcome.counterexample;
    }
    if (!r.outcome.explanation.empty()) {
      c["explanation"] = r.outcome.explanation;
    }
    if (!r.outcome.note.empty()) {
      c["note"] = r.outcome.note;
    }
    c["seconds"] = r.seconds;
    checks.push_back(std::move(c));
  }
  return checks;
}

std::string render_json(const Report& report) {
  using nlohmann::ordered_json;
  ordered_json root;
  root["paper"] = "Collision handling";
  root["seed"] = report.options.seed;
  root["samples"] = report.options.samples;
  root["summary"] = summary_json(report.summary);
  root["checks"] = checks_json(report.results);
  root["seconds"] = report.seconds;
  // Beyond the paper: checks of the same shape, apart from the paper's checks and summary.
  if (!report.beyond.results.empty()) {
    ordered_json beyond;
    beyond["title"] = beyond_title(report.beyond);
    beyond["summary"] = summary_json(report.beyond.summary);
    beyond["checks"] = checks_json(report.beyond.results);
    beyond["seconds"] = report.beyond.seconds;
    root["beyond_the_paper"] = std::move(beyond);
  }
  return root.dump(2) + "\n";
}

}  // namespace

std::string render(const Report& report, Format format, bool colour) {
  switch (format) {
    case Format::text:
      return render_text(report, colour);
    case Format::markdown:
      return render_markdown(report);
    case Format::json:
      return render_json(report);
    case Format::csv:
      break;  // rows of derivation files only (render_rows)
  }
  throw std::invalid_argument("the paper's report is text, markdown or json");
}

}  // namespace impulse::derivations
