// SPDX-License-Identifier: GPL-3.0-or-later
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "derivations/check.hpp"
#include "models/model.hpp"
#include "numeric.hpp"
#include "typeset.hpp"

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
      {"friction.5", "A rod whose end slides on a rough floor"},
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
  if (!o.max_relative_error) {
    return "-";
  }
  return *o.max_relative_error < num::rounding_level ? "<" + num::brief(num::rounding_level, 2)
                                                     : num::brief(*o.max_relative_error, 2);
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

// --- Markdown: the report as the documentation shows it -----------------------------------------

// A verdict in the colour of its status (docs/impulselab.css).
std::string mark(Status status) {
  const std::string name(to_string(status));
  return "<span class=\"verdict " + name + "\">" + name + "</span>";
}

// The top-level part a check belongs to: "3" for "3.1", "friction" for "friction.2".
std::string part_of(const std::string& section) {
  return section.substr(0, section.find('.'));
}

// Our own short titles of the report's pages, one per top-level section.
std::string part_title(const std::string& part) {
  static const std::map<std::string, std::string, std::less<>> t{
      {"1", "Bodies on a line"},
      {"2", "Point masses in the plane"},
      {"3", "A rigid body, one contact"},
      {"4", "Point masses, many contacts"},
      {"5", "Rigid bodies, many contacts"},
      {"friction", "Friction"}};
  const auto it = t.find(part);
  return it == t.end() ? part : it->second;
}

bool numbered(const std::string& part) {
  return !part.empty() &&
         std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The page of the site that explains a part, and the page of its report.
std::string site_page(const std::string& part) {
  return numbered(part) ? "section" + part : part;
}
std::string report_page(const std::string& part) {
  return "check_report_" + part;
}
std::string part_label(const std::string& part) {
  return (numbered(part) ? "§" + part + " " : "") + part_title(part);
}

// The page of the site that lists a derivation file's lines ("section1.md" → paper_section1,
// "beyond/friction.md" → beyond_friction).
std::string listing_page(const std::string& file) {
  std::string stem = file.substr(0, file.rfind('.'));
  if (stem.starts_with("beyond/")) {
    return "beyond_" + stem.substr(std::string("beyond/").size());
  }
  return "paper_" + stem;
}
std::string file_path(const std::string& file) {
  return file.starts_with("beyond/") ? "derivations/" + file : "derivations/paper/" + file;
}
std::string line_link(const Check& check, std::size_t line) {
  return "<a href=\"" + listing_page(check.file) + ".html#L" + std::to_string(line) + "\">line " +
         std::to_string(line) + "</a>";
}

// A note with each "line N" it names linked to that line of the check's file.
std::string linked_note(const Check& check, const std::string& note) {
  static const std::regex line(R"(\bline ([0-9]+)\b)");
  if (check.file.empty()) {
    return note;
  }
  std::string out;
  std::size_t at = 0;
  for (auto it = std::sregex_iterator(note.begin(), note.end(), line); it != std::sregex_iterator();
       ++it) {
    out += note.substr(at, static_cast<std::size_t>(it->position()) - at);
    out += line_link(check, std::stoul((*it)[1].str()));
    at = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + note.substr(at);
}

// What the statuses, the methods and the tolerances mean, with each model's thresholds.
void legend(std::ostringstream& out) {
  out << "## How to read it {#check_report_legend}\n\n"
      << "Each check is a numbered equation of the paper (*equation*), a line of one of its "
         "derivations that must follow from the lines before (*step*), or a statement of its "
         "prose (*claim*). Its outcome is one of\n\n"
      << "- " << mark(Status::verified) << ": it holds;\n"
      << "- " << mark(Status::erratum)
      << ": it does not hold as printed; the corrected form "
         "shown with it does;\n"
      << "- " << mark(Status::refuted)
      << ": a claim that does not hold, with a counterexample "
         "(or, where no case can exist, the argument);\n"
      << "- " << mark(Status::failed)
      << ": none of these, a defect of the checker (the site is "
         "not built when one fails).\n\n"
      << "The methods:\n\n"
      << "- **symbolic**: exact computer algebra (GiNaC): the statement is reduced to zero, or to "
         "a condition, with the definitions and facts of its file;\n"
      << "- **numeric**: random configurations (GSL's random numbers) on which the statement is "
         "evaluated in floating point, from the file's premises or from a model of the physics;\n"
      << "- **quadrature**: the work a force does during the contact, integrated (GSL's "
         "Gauss-Legendre rule) along the body's motion over forces shaped as pulses: constant, "
         "half-sine, triangle, and one that peaks early;\n"
      << "- **ode**: an independent continuous-time contact (springs, dampers, a rod on a penalty "
         "spring) integrated by GSL's Runge-Kutta-Prince-Dormand 8(9);\n"
      << "- **search**: a hunt for a counterexample over small whole numbers first, then random "
         "values.\n\n"
      << "**What verified means numerically.** At each point a statement's two sides are "
         "compared relative to the size of its terms: |left − right| / size. The worst of these "
         "over all points is the *max. relative error* of the tables. A statement holds on a "
         "model when the worst is below the model's first threshold, and fails at a point above "
         "its second; in between lies rounding, which decides nothing. A step of a file without "
         "a model holds below 1e-09 and fails above 1e-06 (the same band). The models and their "
         "thresholds:\n\n"
      << "| method | model | holds below | fails above |\n|---|---|---|---|\n";
  for (const models::Model& m : models::all()) {
    out << "| " << name_of(m.method) << " | " << m.name << " | " << num::brief(m.holds_below, 2)
        << " | " << num::brief(m.fails_above, 2) << " |\n";
  }
  out << "\nA check is verified when its exact method proves it, or, where algebra cannot reach "
         "(integrals over pulses, a simulated contact), when every model it names holds; an exact "
         "proof that a random point then contradicts is a failure, never a pass.\n\n";
}

// The table of a list of checks.
void check_table(std::ostringstream& out, const std::vector<const Result*>& results) {
  out << "| check | equation | kind | status | methods | max. relative error |\n"
      << "|---|---|---|---|---|---|\n";
  for (const Result* r : results) {
    out << "| \\ref " << anchor(r->check.id) << " \"" << r->check.id << "\" | "
        << r->check.equation.value_or("") << " | " << to_string(r->check.kind) << " | "
        << mark(r->outcome.status) << " | " << methods_list(r->outcome.methods) << " | "
        << error_text(r->outcome) << " |\n";
  }
}

// One check's entry: its statement, outcome, methods, file line, evidence.
void check_entry(std::ostringstream& out, const Result& r, const std::string& level) {
  out << "\n"
      << level << " " << r.check.id << (r.check.equation ? " " + *r.check.equation : "") << " {#"
      << anchor(r.check.id) << "}\n\n"
      << "\\f[ " << displayed(r.check) << " \\f]\n\n"
      << "- kind: " << to_string(r.check.kind) << "\n"
      << "- status: " << mark(r.outcome.status) << "\n"
      << "- methods: " << methods_list(r.outcome.methods) << "\n";
  if (!r.check.file.empty()) {
    out << "- in the checker's file: <a href=\"" << listing_page(r.check.file) << ".html#L"
        << r.check.line << "\">" << file_path(r.check.file) << ", line " << r.check.line
        << "</a>\n";
  }
  if (r.outcome.max_relative_error) {
    out << "- worst relative error: " << error_text(r.outcome) << " over "
        << r.outcome.samples.value_or(0) << " samples\n";
  }
  if (!r.outcome.explanation.empty()) {
    out << "- what goes wrong: " << r.outcome.explanation << "\n";
  }
  if (!r.outcome.correction.empty()) {
    const typeset::Marked marked = typeset::mark_changes(r.check.statement, r.outcome.correction);
    std::string corrected = marked.corrected;
    if (corrected.find("\\\\") != std::string::npos &&
        corrected.find("\\begin{") == std::string::npos) {
      corrected = "\\begin{gathered} " + corrected + " \\end{gathered}";
    }
    out << "- correction, the terms that change boxed: \\f[ " << corrected << " \\f]\n";
  }
  if (!r.outcome.counterexample.empty()) {
    out << (typeset::refuted_by_argument(r.outcome.counterexample)
                ? "- refuted by the argument of what goes wrong; the search agrees: "
                : "- counterexample: ")
        << "<span class=\"counterexample\">"
        << typeset::counterexample_markdown(r.outcome.counterexample) << "</span>\n";
  }
  if (!r.outcome.note.empty()) {
    out << "- note: " << linked_note(r.check, r.outcome.note) << "\n";
  }
}

void part_page(std::ostringstream& out, const std::string& part,
               const std::vector<const Result*>& results, const std::string& previous,
               const std::string& next) {
  out << "\n\\page " << report_page(part) << " Report: " << part_label(part) << "\n\n"
      << "<div class=\"breadcrumbs\">\\ref index \"ImpulseLab\" › \\ref check_report \"Report\" › "
      << part_label(part) << "</div>\n\n"
      << "<div class=\"pager\">"
      << (previous.empty()
              ? "\\ref check_report \"← The report\""
              : "\\ref " + report_page(previous) + " \"← " + part_label(previous) + "\"")
      << " <span class=\"pager-sep\">|</span> \\ref " << site_page(part) << " \""
      << part_label(part) << " on the site\" <span class=\"pager-sep\">|</span> "
      << (next.empty() ? "\\ref errata \"Errata →\""
                       : "\\ref " + report_page(next) + " \"" + part_label(next) + " →\"")
      << "</div>\n\n"
      << "Every check of " << part_label(part) << " (\\ref check_report_legend \"how to read "
      << "them\"); the statements as \\ref " << site_page(part)
      << " \"the section's page\" explains them.\n\n";
  check_table(out, results);
  std::string current;
  for (const Result* r : results) {
    if (r->check.section != current) {
      current = r->check.section;
      out << "\n## " << current << " " << title(current) << " {#report-"
          << anchor(current).substr(std::string("check-").size()) << "}\n";
    }
    check_entry(out, *r, "###");
  }
}

// Markdown for the Doxygen site: the report's first page (summary, legend, the parts), then a
// page per top-level section (\page), math in \f[ \f], each check a heading with an anchor.
std::string render_markdown(const Report& report) {
  std::ostringstream out;
  const auto grouped = [](const std::vector<Result>& results) {
    std::vector<std::pair<std::string, std::vector<const Result*>>> parts;
    for (const Result& r : results) {
      const std::string part = part_of(r.check.section);
      if (parts.empty() || parts.back().first != part) {
        parts.push_back({part, {}});
      }
      parts.back().second.push_back(&r);
    }
    return parts;
  };
  const auto paper = grouped(report.results);
  const auto beyond = grouped(report.beyond.results);
  const auto part_rows =
      [&](const std::vector<std::pair<std::string, std::vector<const Result*>>>& parts) {
        out << "| part | checks | verified | errata | refuted | failed "
               "|\n|---|---:|---:|---:|---:|---:|\n";
        for (const auto& [part, results] : parts) {
          Summary s;
          for (const Result* r : results) {
            (r->outcome.status == Status::verified  ? s.verified
             : r->outcome.status == Status::erratum ? s.erratum
             : r->outcome.status == Status::refuted ? s.refuted
                                                    : s.failed)++;
          }
          out << "| \\subpage " << report_page(part) << " \"" << part_label(part) << "\" | "
              << results.size() << " | " << s.verified << " | " << s.erratum << " | " << s.refuted
              << " | " << s.failed << " |\n";
        }
      };
  out << "# Derivation check report {#check_report}\n\n"
      << "Every numbered equation, derivation step and claim of the paper, checked by "
         "`impulselab check` (seed "
      << report.options.seed << ", " << report.options.samples
      << " samples per numeric method).\n\n"
      << "**Summary:** " << summary_line(report.summary) << ".\n\n";
  if (!paper.empty()) {
    out << "One page per section of the paper:\n\n";
    part_rows(paper);
    out << "\n";
  }
  legend(out);
  if (!report.beyond.results.empty()) {
    out << "\n## " << beyond_title(report.beyond) << " {#check_beyond_the_paper}\n\n"
        << "Our own derivations beyond the paper (derivations/beyond/), checked by the same "
           "engine and counted apart from the paper's checks.\n\n"
        << "**Summary beyond the paper:** " << summary_line(report.beyond.summary) << ".\n\n";
    part_rows(beyond);
  }
  std::vector<std::pair<std::string, std::vector<const Result*>>> all = paper;
  all.insert(all.end(), beyond.begin(), beyond.end());
  for (std::size_t k = 0; k < all.size(); ++k) {
    part_page(out, all[k].first, all[k].second, k > 0 ? all[k - 1].first : "",
              k + 1 < all.size() ? all[k + 1].first : "");
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
    // Below the rounding level the digits change from run to run (num::rounding_level): the
    // level itself is written, an upper bound, as the text writes "<1e-15".
    c["max_relative_error"] =
        r.outcome.max_relative_error
            ? ordered_json(num::reported_residual(*r.outcome.max_relative_error))
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
