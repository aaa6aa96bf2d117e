// SPDX-License-Identifier: GPL-3.0-or-later
// The documentation site's own steps around Doxygen (target `docs`, docs/CMakeLists.txt):
//
//   impulselab-site pages --source DIR --docs DIR --report DIR --derivation-reports DIR
//                         [--web-pages collide.html,check.html]
//     writes Doxygen's input: docs/pages/*.md and tutorials/**/README.md with their placeholders
//     filled in from the checker's report, each section page and lab with the ways to the pages
//     around it, a page per derivation file of the paper with its numbered lines, and the menu
//     (DoxygenLayout.xml);
//   impulselab-site index --site DIR
//     writes DIR/search-index.js: the text of every page of the built site, cut at its headings,
//     for the search page (docs/pages/search.md, docs/search.js).
//
// The placeholders of a page (docs/pages/*.md, tutorials/**/README.md):
//   {{check:ID}}      under an equation: the verdict linked to the report, the methods, the line
//                     of the paper's file; the statement checked unless {{statement:ID}} shows it
//                     on the same page; a claim's words as the file puts them before it; an
//                     erratum's printed form and correction, the terms that differ boxed; a
//                     refutation's counterexample, or the argument it rests on
//   {{verdict:ID}}    the verdict alone, linked, for a sentence or a table cell
//   {{statement:ID}}  the check's statement as the checker read it from its file
//   {{errata}}        every erratum and refuted claim of the paper's checks
//   {{labs}}          the labs (tutorials/NN-name/README.md)
//   {{summary}}       the counts of each outcome
//   {{derivation:P}}  the derivation file tutorials/P.md as written, then its report as
//                     `impulselab check --format markdown` wrote it during the build ({{file:P}}
//                     and {{report:P}} give each alone; P without a folder is derivations/P)
//   {{code:(N)}}      the lines of the library's sources whose comment carries the label (N),
//                     linked to Doxygen's listing of the file
// Every check of the report must appear on some page, and every id on a page must be in the report.
// A failure is a message on standard error and exit status 1 (the build stops).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "html.hpp"
#include "typeset.hpp"

namespace {

namespace fs = std::filesystem;
namespace ts = impulse::derivations::typeset;
using nlohmann::json;

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw Failure("cannot read " + file.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) {
    throw Failure("cannot write " + file.string());
  }
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

std::string replace_all(const std::string& text, std::string_view from, std::string_view to) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t found = text.find(from); found != std::string::npos;
       found = text.find(from, at)) {
    out.append(text, at, found - at);
    out.append(to);
    at = found + from.size();
  }
  out.append(text, at);
  return out;
}

std::string html_escape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// A display formula with rows but no environment of its own, gathered (MathJax 2 shows \\ only
// inside one).
std::string gathered(const std::string& latex) {
  if (latex.find("\\\\") != std::string::npos && latex.find("\\begin{") == std::string::npos) {
    return "\\begin{gathered} " + latex + " \\end{gathered}";
  }
  return latex;
}

std::string display(const std::string& latex) {
  return "\\f[ " + gathered(latex) + " \\f]";
}

// --- The report --------------------------------------------------------------------------------

struct Source {
  std::string file;     // "derivations/paper/section3.md"
  std::string listing;  // the page of its numbered lines, "paper_section3"
  std::size_t line = 0;
  std::string words;  // the prose just before the check, when it is a claim
};

struct CheckInfo {
  std::string id, section, kind, status, display, correction, counterexample, explanation;
  std::optional<std::string> equation;
  std::vector<std::string> methods;
  std::string anchor;  // of its entry in the report
  bool paper = true;   // false: beyond the paper
  Source source;
};

std::string member(const json& check, const char* name) {
  const auto it = check.find(name);
  return it != check.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// The sections' pages: "3.1" → section3, "friction.2" → friction.
std::string page_of_section(const std::string& section) {
  const std::string top = section.substr(0, section.find('.'));
  return std::all_of(top.begin(), top.end(), [](char c) { return std::isdigit(c) != 0; })
             ? "section" + top
             : top;
}

// The prose paragraph a check's directive follows, as Doxygen Markdown (its $…$ as \f$…\f$).
// Between them may stand directives and the displays of `given:`; any other display, a heading or
// another check ends the search. Raw LaTeX outside $…$ would reach the reader as such: an error.
std::string words_before(const std::vector<std::string>& lines, std::size_t directive,
                         const std::string& place) {
  static const std::regex is_directive(
      R"(^(let|check|claim|given|from|model|section|explanation|search|correction|ode|evidence|)"
      R"(assume|index|test|quadrature|column|matrix|vector|arrow|also|forces|differentials|itself|)"
      R"(units):( |$))");
  static const std::regex is_check(R"(^(check|claim):)");
  const auto previous_nonblank = [&](std::size_t k) {
    while (k-- > 0) {
      if (!lines[k].empty()) {
        return k;
      }
    }
    return lines.size();
  };
  std::vector<std::string> paragraph;
  std::size_t k = directive;
  while (k-- > 0) {
    const std::string& line = lines[k];
    if (line.empty()) {
      if (!paragraph.empty()) {
        break;
      }
      continue;
    }
    const bool display_end = line.size() >= 2 && line.compare(line.size() - 2, 2, "$$") == 0;
    if (paragraph.empty() && (line.starts_with("$$") || display_end)) {
      // A display: skipped when it is given (a premise of the check), else the end.
      std::size_t start = k;
      while (start > 0 && !lines[start].starts_with("$$")) {
        --start;
      }
      const std::size_t before = previous_nonblank(start);
      if (before < lines.size() && lines[before] == "given:") {
        k = before;
        continue;
      }
      break;
    }
    if (std::regex_search(line, is_directive)) {
      if (!paragraph.empty() || std::regex_search(line, is_check)) {
        break;
      }
      continue;
    }
    if (line.starts_with("$$") || line.starts_with("#") || line.starts_with("<!--")) {
      break;
    }
    paragraph.insert(paragraph.begin(), line);
  }
  std::string text;
  for (const std::string& line : paragraph) {
    text += (text.empty() ? "" : " ") + line;
  }
  // $…$ → \f$…\f$; outside them, characters Doxygen would read as commands or tags are escaped.
  std::string out;
  bool math = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '$') {
      out += math ? " \\f$" : "\\f$ ";
      math = !math;
      continue;
    }
    if (math) {
      out += c;
      continue;
    }
    if (c == '\\') {
      throw Failure(place + ": the prose before this check writes LaTeX outside $…$ (\"" +
                    text.substr(i, 20) + "\"): the site shows the prose as words");
    }
    out += c == '<'   ? "&lt;"
           : c == '>' ? "&gt;"
           : c == '@' ? "\\@"
           : c == '%' ? "\\%"
                      : std::string(1, c);
  }
  if (math) {
    throw Failure(place + ": the prose before this check leaves a $ open");
  }
  return out;
}

struct Report {
  std::vector<CheckInfo> checks;
  std::map<std::string, std::size_t> index;
  json summary;

  const CheckInfo* find(const std::string& id) const {
    const auto it = index.find(id);
    return it == index.end() ? nullptr : &checks[it->second];
  }
};

Report read_report(const fs::path& report_dir, const fs::path& source_dir) {
  Report report;
  const json root = json::parse(read(report_dir / "check.json"));
  report.summary = root.at("summary");
  // Anchors as the Markdown report gives its headings ("### eq-3.5 (3.5) {#check-eq-3-5}").
  std::map<std::string, std::string> anchors;
  static const std::regex heading(R"(^#+ (\S+) .*\{#([^}]+)\}$)");
  for (const std::string& line : lines_of(read(report_dir / "check_report.md"))) {
    std::smatch m;
    if (std::regex_match(line, m, heading)) {
      anchors[m[1].str()] = m[2].str();
    }
  }
  const auto add = [&](const json& checks, bool paper) {
    for (const json& c : checks) {
      CheckInfo info;
      info.id = c.at("id").get<std::string>();
      info.section = c.at("section").get<std::string>();
      info.kind = c.at("kind").get<std::string>();
      info.status = c.at("status").get<std::string>();
      info.display = member(c, "display");
      info.correction = member(c, "correction");
      info.counterexample = member(c, "counterexample");
      info.explanation = member(c, "explanation");
      if (c.at("equation").is_string()) {
        info.equation = c.at("equation").get<std::string>();
      }
      for (const json& m : c.at("methods")) {
        info.methods.push_back(m.get<std::string>());
      }
      info.paper = paper;
      const auto a = anchors.find(info.id);
      if (a == anchors.end()) {
        throw Failure("check " + info.id + " has no heading in the Markdown report");
      }
      info.anchor = a->second;
      if (info.status == "failed") {
        throw Failure("check " + info.id + " failed; the site shows no failed check");
      }
      report.index[info.id] = report.checks.size();
      report.checks.push_back(std::move(info));
    }
  };
  add(root.at("checks"), true);
  if (root.contains("beyond_the_paper")) {
    add(root.at("beyond_the_paper").at("checks"), false);
  }
  // Where each check is in its file, and a claim's words.
  static const std::regex directive(R"(^(check|claim): (\S+))");
  for (const auto& [folder, prefix] : {std::pair{"paper", "paper_"}, {"beyond", "beyond_"}}) {
    const fs::path dir = source_dir / "derivations" / folder;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".md") {
        files.push_back(entry.path());
      }
    }
    for (const fs::path& file : files) {
      const std::vector<std::string> lines = lines_of(read(file));
      const std::string shown =
          "derivations/" + std::string(folder) + "/" + file.filename().string();
      for (std::size_t k = 0; k < lines.size(); ++k) {
        std::smatch m;
        if (!std::regex_search(lines[k], m, directive)) {
          continue;
        }
        const auto it = report.index.find(m[2].str());
        if (it == report.index.end()) {
          continue;  // a check of a run that was filtered, or not in this report
        }
        Source& s = report.checks[it->second].source;
        s.file = shown;
        s.listing = prefix + file.stem().string();
        s.line = k + 1;
        if (m[1].str() == "claim" && std::string(folder) == "paper") {
          s.words = words_before(lines, k, shown + ":" + std::to_string(k + 1));
        }
      }
    }
  }
  return report;
}

// --- The pieces of a page ----------------------------------------------------------------------

std::string verdict(const CheckInfo& c) {
  return "<span class=\"verdict " + c.status + "\">\\ref " + c.anchor + " \"" + c.status +
         "\"</span>";
}

std::string source_link(const CheckInfo& c) {
  if (c.source.file.empty()) {
    return "";
  }
  const std::string name = c.source.file.substr(c.source.file.rfind('/') + 1);
  return "<a class=\"source-line\" href=\"" + c.source.listing + ".html#L" +
         std::to_string(c.source.line) + "\">" + name + ", line " + std::to_string(c.source.line) +
         "</a>";
}

std::string methods_text(const CheckInfo& c) {
  std::string text;
  for (const std::string& m : c.methods) {
    text += (text.empty() ? "" : ", ") + m;
  }
  return text;
}

// What an erratum's or a refutation's evidence shows, after its verdict.
std::string evidence(const CheckInfo& c) {
  std::string out;
  if (!c.correction.empty()) {
    const ts::Marked marked = ts::mark_changes(c.display, c.correction);
    out += "<div class=\"printed\">As printed, the terms that change boxed:\n" +
           display(marked.printed) + "\n</div>\n<div class=\"corrected\">What holds instead:\n" +
           display(marked.corrected) + "\n</div>\n";
  }
  if (!c.counterexample.empty()) {
    if (ts::refuted_by_argument(c.counterexample)) {
      out += "<div class=\"argument\"><b>Refuted by argument</b>, not by a case: " +
             html_escape(c.explanation) + " The search agrees: <span class=\"counterexample\">" +
             ts::counterexample_markdown(c.counterexample) + "</span>.</div>\n";
    } else {
      out += "<div class=\"counterexample-line\">Counterexample: <span class=\"counterexample\">" +
             ts::counterexample_markdown(c.counterexample) + "</span>.</div>\n";
    }
  }
  return out;
}

std::string check_block(const CheckInfo& c, bool statement_on_page) {
  std::string out = "<div class=\"check " + c.status + "\" id=\"" + c.anchor +
                    "\">\n<b>Check</b> <code>" + c.id + "</code> (" + c.kind +
                    (c.equation ? " " + *c.equation : "") + "): " + verdict(c) + " by " +
                    methods_text(c) + ".";
  if (const std::string link = source_link(c); !link.empty()) {
    out += " <span class=\"source\">In the checker's file: " + link + ".</span>";
  }
  out += "\n";
  if (!c.source.words.empty()) {
    out += "<div class=\"words\"><b>The claim, in our words:</b> " + c.source.words +
           "</div>\n<div class=\"formalised\">Formalised as:\n" + display(c.display) + "\n</div>\n";
  } else if (!statement_on_page) {
    out += "<div class=\"statement\">Checked:\n" + display(c.display) + "\n</div>\n";
  }
  out += evidence(c);
  out += "</div>";
  return out;
}

std::string errata_list(const Report& report) {
  std::string out;
  for (const CheckInfo& c : report.checks) {
    if (!c.paper || (c.status != "erratum" && c.status != "refuted")) {
      continue;
    }
    const std::string label = c.equation ? *c.equation : c.id;
    out += "\n### " + label + ", section " + c.section + ": " + c.status + " {#errata-" + c.anchor +
           "}\n\n";
    out += "Check " + verdict(c) + " <code>" + c.id + "</code> (" + c.kind + ") <a href=\"" +
           page_of_section(c.section) + ".html#" + c.anchor + "\">on its section's page</a>";
    if (const std::string link = source_link(c); !link.empty()) {
      out += ", " + link;
    }
    out += ".\n\n";
    if (!c.source.words.empty()) {
      out +=
          "<div class=\"words\"><b>The claim, in our words:</b> " + c.source.words + "</div>\n\n";
    }
    if (c.correction.empty()) {
      out += "<div class=\"formalised\">Formalised as:\n" + display(c.display) + "\n</div>\n\n";
    }
    out += "What goes wrong: " + html_escape(c.explanation) + "\n\n" + evidence(c) + "\n";
  }
  return out.empty() ? "The checker found no erratum and no refuted claim.\n" : out;
}

// --- Labs and sections -------------------------------------------------------------------------

struct Lab {
  int number = 0;
  std::string title;
  std::string label;  // lab_N
  fs::path readme;
  std::vector<std::string> sections;  // "3", "4"
};

struct SectionPage {
  std::string name;   // section3
  std::string title;  // "3 A rigid body, one contact"
};

std::vector<Lab> read_labs(const fs::path& source_dir) {
  std::vector<Lab> labs;
  static const std::regex first(R"(^# Lab ([0-9]+): (.+) \{#(lab_[0-9]+)\}$)");
  static const std::regex sections(R"(<!-- paper sections: ([0-9, ]+))");
  std::vector<fs::path> readmes;
  for (const auto& entry : fs::directory_iterator(source_dir / "tutorials")) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.size() > 3 && std::isdigit(name[0]) != 0 &&
        std::isdigit(name[1]) != 0 && name[2] == '-' && fs::exists(entry.path() / "README.md")) {
      readmes.push_back(entry.path() / "README.md");
    }
  }
  std::sort(readmes.begin(), readmes.end());
  for (const fs::path& readme : readmes) {
    const std::string text = read(readme);
    const std::vector<std::string> lines = lines_of(text);
    std::smatch m;
    if (lines.empty() || !std::regex_match(lines[0], m, first)) {
      throw Failure(readme.string() + ": the first line must read \"# Lab N: Title {#lab_N}\"");
    }
    Lab lab{std::stoi(m[1].str()), m[2].str(), m[3].str(), readme, {}};
    if (std::regex_search(text, m, sections)) {
      std::string list = m[1].str();
      std::istringstream in(replace_all(list, ",", " "));
      for (std::string s; in >> s;) {
        lab.sections.push_back(s);
      }
    }
    labs.push_back(std::move(lab));
  }
  return labs;
}

std::string labs_list(const std::vector<Lab>& labs) {
  std::string out;
  for (const Lab& lab : labs) {
    out += "- \\subpage " + lab.label + " \"Lab " + std::to_string(lab.number) + ": " + lab.title +
           "\"\n";
  }
  return out.empty() ? "No lab has been written yet.\n" : out;
}

std::string section_short(const SectionPage& s) {
  return "§" + s.title;  // "§3 A rigid body, one contact"
}

// The ways around a section page: previous and next section, its labs, its report, its file.
std::string section_nav(const std::vector<SectionPage>& sections, std::size_t k,
                        const std::vector<Lab>& labs, bool top) {
  const SectionPage& s = sections[k];
  const std::string number = s.name.substr(std::string("section").size());
  std::string out = "<div class=\"pager\">";
  out += k > 0 ? "\\ref " + sections[k - 1].name + " \"← " + section_short(sections[k - 1]) + "\""
               : "\\ref index \"← Contents\"";
  out += " <span class=\"pager-sep\">|</span> ";
  out += k + 1 < sections.size()
             ? "\\ref " + sections[k + 1].name + " \"" + section_short(sections[k + 1]) + " →\""
             : "\\ref notation \"Notation →\"";
  out += "</div>\n";
  if (!top) {
    return out;
  }
  out += "<div class=\"section-links\">";
  std::string lab_links;
  for (const Lab& lab : labs) {
    if (std::find(lab.sections.begin(), lab.sections.end(), number) != lab.sections.end()) {
      lab_links += (lab_links.empty() ? "" : ", ") + std::string("\\ref ") + lab.label + " \"Lab " +
                   std::to_string(lab.number) + ": " + lab.title + "\"";
    }
  }
  if (!lab_links.empty()) {
    out += "<b>Labs:</b> " + lab_links + ". ";
  }
  out += "<b>Every check of this section:</b> \\ref check_report_" + number +
         " \"the report\", <a href=\"paper_" + s.name +
         ".html\">the checker's file</a>. \\ref notation \"Notation\", \\ref errata \"errata\"."
         "</div>\n";
  return out;
}

std::string lab_nav(const std::vector<Lab>& labs, std::size_t k,
                    const std::vector<SectionPage>& sections, bool top) {
  const Lab& lab = labs[k];
  std::string out;
  if (top) {
    out += "<div class=\"breadcrumbs\">\\ref index \"ImpulseLab\" › \\ref labs \"Labs\" › Lab " +
           std::to_string(lab.number) + "</div>\n";
  }
  out += "<div class=\"pager\">";
  out += k > 0 ? "\\ref " + labs[k - 1].label + " \"← Lab " + std::to_string(labs[k - 1].number) +
                     ": " + labs[k - 1].title + "\""
               : "\\ref labs \"← Labs\"";
  out += " <span class=\"pager-sep\">|</span> ";
  std::string back;
  for (const std::string& number : lab.sections) {
    const auto it = std::find_if(sections.begin(), sections.end(), [&](const SectionPage& s) {
      return s.name == "section" + number;
    });
    if (it != sections.end()) {
      back += (back.empty() ? "" : ", ") + std::string("\\ref ") + it->name + " \"" +
              section_short(*it) + "\"";
    }
  }
  if (!back.empty()) {
    out += "The paper: " + back + " <span class=\"pager-sep\">|</span> ";
  }
  out += k + 1 < labs.size()
             ? "\\ref " + labs[k + 1].label + " \"Lab " + std::to_string(labs[k + 1].number) +
                   ": " + labs[k + 1].title + " →\""
             : "\\ref labs \"Labs →\"";
  out += "</div>\n";
  return out;
}

// The page's text with the ways around it after its first line (the title) and at its end.
std::string framed(const std::string& text, const std::string& top, const std::string& bottom) {
  const std::size_t eol = text.find('\n');
  if (eol == std::string::npos) {
    return text + "\n\n" + top + "\n" + bottom;
  }
  return text.substr(0, eol + 1) + "\n" + top + "\n" + text.substr(eol + 1) + "\n\n" + bottom;
}

// --- "In code": the lines of the library that carry an equation's label
// ---------------------------

// Doxygen's name of a file's listing (escapeCharsInString: '_' → "__", '.' → "_8", '-' kept).
std::string doxygen_source_page(const std::string& file_name) {
  std::string out;
  for (const char c : file_name) {
    out += c == '_' ? std::string("__") : c == '.' ? std::string("_8") : std::string(1, c);
  }
  return out + "_source.html";
}

struct CodeLine {
  std::string file_name;  // "rigid_2d.hpp"
  std::string path;       // "lib/include/impulse/rigid_2d/rigid_2d.hpp"
  std::size_t line;
};

// A source of the library that Doxygen does not list (a .cpp) is listed on a page of the site's
// own: "lib/src/multipoint/multipoint.cpp" → code_lib_src_multipoint_multipoint_cpp.
std::string code_listing_page(const std::string& path) {
  std::string page = "code_";
  for (const char c : path) {
    page += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  }
  return page;
}

std::string code_line_url(const CodeLine& l) {
  if (l.path.ends_with(".hpp")) {
    char anchor[16];
    std::snprintf(anchor, sizeof anchor, "l%05zu", l.line);
    return doxygen_source_page(l.file_name) + "#" + anchor;
  }
  return code_listing_page(l.path) + ".html#L" + std::to_string(l.line);
}

std::map<std::string, std::vector<CodeLine>> code_lines(const fs::path& source_dir) {
  std::map<std::string, std::vector<CodeLine>> found;
  static const std::regex label(R"(\(([0-9]+\.[0-9]+)\))");
  std::set<std::string> names;
  for (const char* folder : {"lib/include", "lib/src"}) {
    for (const auto& entry : fs::recursive_directory_iterator(source_dir / folder)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) {
        continue;
      }
      const std::string name = entry.path().filename().string();
      if (!names.insert(name).second) {
        throw Failure("two sources of the library are named " + name +
                      ": Doxygen's listings would not be named after the file alone");
      }
      const std::vector<std::string> lines = lines_of(read(entry.path()));
      for (std::size_t k = 0; k < lines.size(); ++k) {
        // A comment that is not documentation (// but not ///) and names a label.
        const std::size_t comment = lines[k].find("//");
        if (comment == std::string::npos || lines[k].compare(comment, 3, "///") == 0) {
          continue;
        }
        const std::string text = lines[k].substr(comment);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), label);
             it != std::sregex_iterator(); ++it) {
          found[(*it)[1].str()].push_back(
              {name, fs::relative(entry.path(), source_dir).generic_string(), k + 1});
        }
      }
    }
  }
  return found;
}

std::string code_links(const std::map<std::string, std::vector<CodeLine>>& lines,
                       const std::string& label, const std::string& place) {
  const auto it = lines.find(label);
  if (it == lines.end()) {
    throw Failure(place + ": {{code:(" + label + ")}}: no line of lib/ carries // (" + label + ")");
  }
  std::string out = "<span class=\"in-code\">the line" +
                    std::string(it->second.size() > 1 ? "s" : "") + " marked (" + label + "): ";
  bool first = true;
  for (const CodeLine& l : it->second) {
    out += (first ? "" : ", ") + std::string("<a href=\"") + code_line_url(l) + "\">" +
           l.file_name + ", line " + std::to_string(l.line) + "</a>";
    first = false;
  }
  return out + "</span>";
}

// --- The listing of a derivation file ----------------------------------------------------------

std::string listing_page(const fs::path& file, const std::string& page, const std::string& title,
                         const std::string& intro, const Report& report) {
  static const std::regex directive(R"(^(check|claim): (\S+)(.*)$)");
  std::string out = "# " + title + " {#" + page + "}\n\n" + intro +
                    "\n\n\\htmlonly[block]\n<pre class=\"listing\">";
  const std::vector<std::string> lines = lines_of(read(file));
  const std::size_t width = std::to_string(lines.size()).size();
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string number = std::to_string(k + 1);
    std::string text = html_escape(lines[k]);
    std::smatch m;
    if (std::regex_match(lines[k], m, directive)) {
      if (const CheckInfo* c = report.find(m[2].str())) {
        const std::string number_of_section = c->section.substr(0, c->section.find('.'));
        text = m[1].str() + ": <a class=\"check-link " + c->status + "\" href=\"check_report_" +
               number_of_section + ".html#" + c->anchor + "\">" + html_escape(m[2].str()) + "</a>" +
               html_escape(m[3].str());
      }
    }
    out += "<span class=\"line\" id=\"L" + number + "\"><a class=\"lineno\" href=\"#L" + number +
           "\">" + std::string(width - number.size(), ' ') + number + "</a> " + text + "</span>\n";
  }
  out += "</pre>\n\\endhtmlonly\n";
  return out;
}

// --- A page's placeholders ---------------------------------------------------------------------

struct Context {
  const Report& report;
  const std::vector<Lab>& labs;
  fs::path source_dir;
  fs::path derivation_reports;
  std::map<std::string, std::vector<CodeLine>> code;
  std::set<std::string> used;
};

// An example derivation file tutorials/P.md as written (\verbatim: a <pre>, in which neither
// Doxygen's commands nor MathJax's $$ are read), and its report as the build wrote it.
std::string derivation_file(Context& context, const std::string& path, const std::string& place) {
  const fs::path file = context.source_dir / "tutorials" / (path + ".md");
  if (!fs::exists(file)) {
    throw Failure(place + ": no file tutorials/" + path + ".md");
  }
  std::string source = read(file);
  if (const std::size_t pins = source.find("<!-- expect"); pins != std::string::npos) {
    source = source.substr(0, pins);  // the test's pins are not for readers
  }
  while (!source.empty() && (source.back() == '\n' || source.back() == ' ')) {
    source.pop_back();
  }
  return "The file `tutorials/" + path + ".md`:\n\n\\verbatim\n" + source + "\n\\endverbatim\n";
}

std::string derivation_report(Context& context, const std::string& path, const std::string& place) {
  const fs::path checked =
      context.derivation_reports / (fs::path(path).filename().string() + ".md");
  if (!fs::exists(checked)) {
    throw Failure(place + ": no report of tutorials/" + path + ".md in " +
                  context.derivation_reports.string());
  }
  static const std::regex inline_math(R"(\$([^$]+)\$)");
  return std::regex_replace(read(checked), inline_math, "\\f$$$1\\f$$") + "\n";
}

std::string derivation_example(Context& context, const std::string& path,
                               const std::string& place) {
  return derivation_file(context, path, place) + "\nWhat `impulselab check` reports for it:\n\n" +
         derivation_report(context, path, place);
}

std::string fill(Context& context, const std::string& text, const std::string& place) {
  static const std::regex placeholder(R"(\{\{([a-z]+)(:([^}]*))?\}\})");
  std::set<std::string> statements_here;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), placeholder);
       it != std::sregex_iterator(); ++it) {
    if ((*it)[1].str() == "statement") {
      statements_here.insert((*it)[3].str());
    }
  }
  std::string out;
  std::size_t at = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), placeholder);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += text.substr(at, static_cast<std::size_t>(m.position()) - at);
    at = static_cast<std::size_t>(m.position() + m.length());
    const std::string what = m[1].str();
    const std::string id = m[3].str();
    const CheckInfo* c = context.report.find(id);
    if ((what == "check" || what == "verdict" || what == "statement") && c != nullptr) {
      context.used.insert(id);
      out += what == "check"     ? check_block(*c, statements_here.contains(id))
             : what == "verdict" ? verdict(*c)
                                 : display(c->display);
    } else if (what == "errata" && id.empty()) {
      out += errata_list(context.report);
    } else if (what == "labs" && id.empty()) {
      out += labs_list(context.labs);
    } else if (what == "summary" && id.empty()) {
      const json& s = context.report.summary;
      out += std::to_string(s.at("verified").get<int>()) + " verified, " +
             std::to_string(s.at("erratum").get<int>()) + " errata, " +
             std::to_string(s.at("refuted").get<int>()) + " refuted, " +
             std::to_string(s.at("failed").get<int>()) + " failed";
    } else if ((what == "derivation" || what == "file" || what == "report") && !id.empty()) {
      const std::string path = id.find('/') == std::string::npos ? "derivations/" + id : id;
      out += what == "derivation" ? derivation_example(context, path, place)
             : what == "file"     ? derivation_file(context, path, place)
                                  : derivation_report(context, path, place);
    } else if (what == "code" && id.size() > 2 && id.front() == '(' && id.back() == ')') {
      out += code_links(context.code, id.substr(1, id.size() - 2), place);
    } else {
      throw Failure(place + ": " + m.str() +
                    " names no check of the report (or no placeholder: {{check:ID}}, "
                    "{{verdict:ID}}, {{statement:ID}}, {{errata}}, {{labs}}, {{summary}}, "
                    "{{derivation:PATH}}, {{file:PATH}}, {{report:PATH}}, {{code:(N)}})");
    }
  }
  return out + text.substr(at);
}

// --- The menu ------------------------------------------------------------------------------------

std::string layout(const std::vector<SectionPage>& sections, const std::vector<Lab>& labs,
                   const std::vector<std::string>& web_pages) {
  std::string out =
      "<doxygenlayout version=\"1.0\">\n"
      "  <!-- Written by docs/tools/site.cpp: the menu of every page. -->\n"
      "  <navindex>\n"
      "    <tab type=\"mainpage\" visible=\"yes\" title=\"Home\"/>\n";
  for (const SectionPage& s : sections) {
    out += "    <tab type=\"user\" url=\"@ref " + s.name + "\" title=\"§" +
           s.name.substr(std::string("section").size()) + "\"/>\n";
  }
  out +=
      "    <tab type=\"user\" url=\"@ref notation\" title=\"Notation\"/>\n"
      "    <tab type=\"user\" url=\"@ref errata\" title=\"Errata\"/>\n"
      "    <tab type=\"user\" url=\"@ref check_report\" title=\"Report\"/>\n"
      "    <tab type=\"user\" url=\"@ref derivations\" title=\"Check your own derivation\"/>\n"
      "    <tab type=\"usergroup\" url=\"@ref labs\" title=\"Labs\">\n";
  for (const Lab& lab : labs) {
    out += "      <tab type=\"user\" url=\"@ref " + lab.label + "\" title=\"Lab " +
           std::to_string(lab.number) + ": " + html_escape(lab.title) + "\"/>\n";
  }
  out += "    </tab>\n";
  static const std::map<std::string, std::string> web_titles{{"collide.html", "Collide"},
                                                             {"check.html", "Check"}};
  for (const auto& [file, title] : web_titles) {
    if (std::find(web_pages.begin(), web_pages.end(), file) != web_pages.end()) {
      out += "    <tab type=\"user\" url=\"" + file + "\" title=\"" + title + "\"/>\n";
    }
  }
  out +=
      "    <tab type=\"usergroup\" url=\"[none]\" title=\"More\">\n"
      "      <tab type=\"user\" url=\"@ref methods\" title=\"Three ways to resolve contacts\"/>\n"
      "      <tab type=\"user\" url=\"@ref friction\" title=\"Friction\"/>\n"
      "      <tab type=\"user\" url=\"@ref accuracy\" title=\"Accuracy\"/>\n"
      "      <tab type=\"user\" url=\"@ref scenes\" title=\"Scene files\"/>\n"
      "      <tab type=\"user\" url=\"namespaces.html\" title=\"API: namespaces\"/>\n"
      "      <tab type=\"user\" url=\"annotated.html\" title=\"API: classes\"/>\n"
      "      <tab type=\"user\" url=\"files.html\" title=\"API: files\"/>\n"
      "      <tab type=\"user\" url=\"pages.html\" title=\"All pages\"/>\n"
      "    </tab>\n"
      "    <tab type=\"user\" url=\"@ref search\" title=\"Search\"/>\n"
      "    <tab type=\"pages\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "    <tab type=\"modules\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "    <tab type=\"namespaces\" visible=\"no\" title=\"\">\n"
      "      <tab type=\"namespacelist\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "      <tab type=\"namespacemembers\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "    </tab>\n"
      "    <tab type=\"classes\" visible=\"no\" title=\"\">\n"
      "      <tab type=\"classlist\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "      <tab type=\"classindex\" visible=\"no\" title=\"\"/>\n"
      "      <tab type=\"hierarchy\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "      <tab type=\"classmembers\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "    </tab>\n"
      "    <tab type=\"files\" visible=\"no\" title=\"\">\n"
      "      <tab type=\"filelist\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "      <tab type=\"globals\" visible=\"no\" title=\"\" intro=\"\"/>\n"
      "    </tab>\n"
      "  </navindex>\n"
      "</doxygenlayout>\n";
  return out;
}

// --- pages ---------------------------------------------------------------------------------------

std::map<std::string, std::string> options(int argc, char** argv, int first) {
  std::map<std::string, std::string> result;
  for (int k = first; k < argc; k += 2) {
    const std::string key = argv[k];
    if (!key.starts_with("--") || k + 1 >= argc) {
      throw Failure("usage: expected --option VALUE, got " + key);
    }
    result[key.substr(2)] = argv[k + 1];
  }
  return result;
}

std::string required(const std::map<std::string, std::string>& o, const std::string& key) {
  const auto it = o.find(key);
  if (it == o.end()) {
    throw Failure("missing --" + key);
  }
  return it->second;
}

// tutorials/**/README.md, the labs with their ways around.
void write_tutorial_pages(Context& context, const std::vector<SectionPage>& sections,
                          const fs::path& tutorials_out) {
  const fs::path& source_dir = context.source_dir;
  const std::vector<Lab>& labs = context.labs;
  for (const auto& entry : fs::recursive_directory_iterator(source_dir / "tutorials")) {
    if (entry.path().filename() != "README.md") {
      continue;
    }
    const fs::path relative = fs::relative(entry.path(), source_dir / "tutorials");
    if (relative.begin()->string() == "derivations" ||
        entry.path().string().find("/solutions/") != std::string::npos) {
      continue;
    }
    const std::string place = "tutorials/" + relative.string();
    std::string text = fill(context, read(entry.path()), place);
    const auto k = std::find_if(labs.begin(), labs.end(),
                                [&](const Lab& lab) { return lab.readme == entry.path(); });
    if (k != labs.end()) {
      const auto index = static_cast<std::size_t>(k - labs.begin());
      text =
          framed(text, lab_nav(labs, index, sections, true), lab_nav(labs, index, sections, false));
    } else if (relative == "README.md" || relative == "scenes/README.md") {
      text =
          framed(text,
                 "<div class=\"breadcrumbs\">\\ref index \"ImpulseLab\" › " +
                     std::string(relative == "README.md" ? "Labs"
                                                         : "\\ref labs \"Labs\" › Example scenes") +
                     "</div>\n",
                 "");
    }
    write(tutorials_out / relative, text);
  }
}

// A page per derivation file of the paper (and beyond it), its lines numbered; and the library's
// sources that carry an equation's number and that Doxygen does not list.
void write_listings(const Context& context, const fs::path& pages_out) {
  const fs::path& source_dir = context.source_dir;
  const Report& report = context.report;
  for (const auto& [folder, prefix] : {std::pair{"paper", "paper_"}, {"beyond", "beyond_"}}) {
    for (const auto& entry : fs::directory_iterator(source_dir / "derivations" / folder)) {
      if (entry.path().extension() != ".md") {
        continue;
      }
      const std::string stem = entry.path().stem().string();
      const std::string shown = "derivations/" + std::string(folder) + "/" + stem + ".md";
      const std::string page = prefix + stem;
      const std::string& section_page = stem;  // section3; beyond, the page of its name (friction)
      std::string intro = "<div class=\"breadcrumbs\">\\ref index \"ImpulseLab\" › \\ref " +
                          section_page + " › " + shown +
                          "</div>\n\nThe file the checker reads for this part (the format: \\ref "
                          "derivations \"Check your own derivation\"). Each `check:` and `claim:` "
                          "below links to its entry in the report; the section's page shows each "
                          "statement with its verdict.";
      write(pages_out / ("listing_" + page + ".md"),
            listing_page(entry.path(), page, shown, intro, report));
    }
  }
  std::set<std::string> listed;
  for (const auto& [label, lines] : context.code) {
    for (const CodeLine& l : lines) {
      if (l.path.ends_with(".cpp") && listed.insert(l.path).second) {
        const std::string intro =
            "<div class=\"breadcrumbs\">\\ref index \"ImpulseLab\" › " + l.path +
            "</div>\n\nA source of the library, line by line: a line that computes one of the "
            "paper's equations says so in a comment with the equation's number, e.g. `// (5.3)`.";
        write(pages_out / ("listing_" + code_listing_page(l.path) + ".md"),
              listing_page(source_dir / l.path, code_listing_page(l.path), l.path, intro, report));
      }
    }
  }
}

void pages(const std::map<std::string, std::string>& o) {
  const fs::path source_dir = required(o, "source");
  const fs::path docs_dir = required(o, "docs");
  const Report report = read_report(required(o, "report"), source_dir);
  std::vector<std::string> web_pages;
  if (o.contains("web-pages")) {
    std::istringstream in(replace_all(o.at("web-pages"), ",", " "));
    for (std::string page; in >> page;) {
      web_pages.push_back(page);
    }
  }
  const std::vector<Lab> labs = read_labs(source_dir);
  Context context{
      report, labs, source_dir, required(o, "derivation-reports"), code_lines(source_dir), {}};

  const fs::path pages_out = docs_dir / "pages";
  const fs::path tutorials_out = docs_dir / "tutorials";
  fs::remove_all(pages_out);
  fs::remove_all(tutorials_out);

  // The section pages, in order, with their titles.
  std::vector<SectionPage> sections;
  static const std::regex section_title(R"(^# (.+) \{#(section[0-9]+)\}$)");
  for (int n = 1; fs::exists(source_dir / "docs/pages" / ("section" + std::to_string(n) + ".md"));
       ++n) {
    const fs::path page = source_dir / "docs/pages" / ("section" + std::to_string(n) + ".md");
    const std::vector<std::string> lines = lines_of(read(page));
    std::smatch m;
    if (lines.empty() || !std::regex_match(lines[0], m, section_title)) {
      throw Failure(page.string() + ": the first line must read \"# N Title {#sectionN}\"");
    }
    sections.push_back({m[2].str(), m[1].str()});
  }

  // docs/pages/*.md; tutorials/README.md is the labs index when it carries {#labs}.
  const bool labs_index_in_tutorials =
      fs::exists(source_dir / "tutorials/README.md") &&
      read(source_dir / "tutorials/README.md").find("{#labs}") != std::string::npos;
  for (const auto& entry : fs::directory_iterator(source_dir / "docs/pages")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".md" || (name == "labs.md" && labs_index_in_tutorials)) {
      continue;
    }
    const std::string place = "docs/pages/" + name;
    std::string text = fill(context, read(entry.path()), place);
    const auto k = std::find_if(sections.begin(), sections.end(),
                                [&](const SectionPage& s) { return s.name + ".md" == name; });
    if (k != sections.end()) {
      const auto index = static_cast<std::size_t>(k - sections.begin());
      text = framed(text, section_nav(sections, index, labs, true),
                    section_nav(sections, index, labs, false));
    }
    write(pages_out / name, text);
  }

  write_tutorial_pages(context, sections, tutorials_out);
  write_listings(context, pages_out);

  // Every check on some page, every page's id in the report.
  std::string missing;
  for (const CheckInfo& c : report.checks) {
    if (!context.used.contains(c.id)) {
      missing += (missing.empty() ? "" : ", ") + c.id;
    }
  }
  if (!missing.empty()) {
    throw Failure("no page of docs/pages shows these checks: " + missing);
  }
  write(docs_dir / "DoxygenLayout.xml", layout(sections, labs, web_pages));
}

// --- index ---------------------------------------------------------------------------------------

struct Record {
  std::string title;    // the page's
  std::string heading;  // the part's, when the page is cut
  std::string url;
  std::string text;
};

// Math as MathJax's source in the page: \( … \), \[ … \]. Only an equation's number is kept, as
// the reader sees it: "(3.6)".
std::string without_math(const std::string& text) {
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t inline_open = text.find("\\(", at);
    const std::size_t display_open = text.find("\\[", at);
    const std::size_t open = std::min(inline_open, display_open);
    if (open == std::string::npos) {
      out += text.substr(at);
      break;
    }
    out += text.substr(at, open - at);
    const std::string close = open == inline_open ? "\\)" : "\\]";
    const std::size_t end = text.find(close, open + 2);
    const std::string math =
        text.substr(open + 2, (end == std::string::npos ? text.size() : end) - open - 2);
    static const std::regex tag(R"(\\tag\{([^}]*)\})");
    for (auto it = std::sregex_iterator(math.begin(), math.end(), tag);
         it != std::sregex_iterator(); ++it) {
      out += " (" + (*it)[1].str() + ") ";
    }
    out += ' ';
    at = end == std::string::npos ? text.size() : end + 2;
  }
  return out;
}

std::string squeezed(const std::string& text) {
  std::string out;
  bool space = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const bool nbsp =
        c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0xA0;
    if (std::isspace(c) != 0 || nbsp) {
      if (!space) {
        out += ' ';
      }
      space = true;
      i += nbsp ? 1 : 0;
    } else {
      out += text[i];
      space = false;
    }
  }
  if (!out.empty() && out.back() == ' ') {
    out.pop_back();
  }
  return out;
}

std::vector<Record> records_of(const std::string& file, const std::string& html) {
  using impulse::site::Tag;
  std::vector<Record> records;
  std::string title;
  bool in_title = false;
  bool doxygen = html.find("<div class=\"header\">") != std::string::npos;
  bool collecting = !doxygen;
  bool in_heading = false;
  int skip_depth = 0;  // inside the navigation of an interactive page
  std::string last_id;
  Record current{"", "", file, ""};
  const auto flush = [&] {
    current.text = squeezed(without_math(current.text));
    if (!current.text.empty() || !current.heading.empty()) {
      records.push_back(current);
    }
  };
  impulse::site::walk(
      html,
      [&](const Tag& tag) {
        if (tag.name == "title") {
          in_title = true;
        } else if (tag.name == "/title") {
          in_title = false;
        }
        if (doxygen && tag.name == "div" && tag.has_class("header")) {
          collecting = true;
        }
        if (tag.name == "hr" && tag.has_class("footer")) {
          collecting = false;
        }
        if (!collecting) {
          return;
        }
        if (tag.name == "nav" || tag.name == "/nav") {
          skip_depth += tag.name == "nav" ? 1 : -1;
        }
        if (const std::string id = tag.attribute("id"); !id.empty()) {
          last_id = id;
          if (tag.name == "div" && tag.has_class("check")) {
            flush();
            current = {title, "", file + "#" + id, ""};
          }
        }
        const bool heading =
            tag.name.size() == 2 && tag.name[0] == 'h' && tag.name[1] >= '1' && tag.name[1] <= '4';
        if (heading && !tag.has_class("groupheader")) {
          flush();
          current = {title, "", last_id.empty() ? file : file + "#" + last_id, ""};
          in_heading = true;
        } else if (tag.name.size() == 3 && tag.name[0] == '/' && tag.name[1] == 'h') {
          in_heading = false;
        }
      },
      [&](std::string_view raw) {
        const std::string text = impulse::site::decode_entities(raw);
        if (in_title) {
          title += text;
          return;
        }
        if (!collecting || skip_depth > 0) {
          return;
        }
        if (in_heading) {
          current.heading += text;
        }
        current.text += text;
        current.text += ' ';
      });
  flush();
  title = squeezed(title);
  if (title.starts_with("ImpulseLab: ")) {
    title = title.substr(std::string("ImpulseLab: ").size());
  }
  if (!doxygen) {
    // An interactive page: named as the menu names it ("collide.html" → "Collide").
    std::string name = file.substr(0, file.find('.'));
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    title = name + ", the interactive page: " + title;
  }
  for (Record& r : records) {
    r.title = title;
    r.heading = squeezed(without_math(r.heading));
    if (r.heading.find("◆") == 0) {
      r.heading = r.heading.substr(std::string("◆").size());
    }
    r.heading = squeezed(r.heading);
  }
  return records;
}

void index(const std::map<std::string, std::string>& o) {
  const fs::path site = required(o, "site");
  std::vector<fs::path> pages;
  for (const auto& entry : fs::directory_iterator(site)) {
    const std::string name = entry.path().filename().string();
    // The listings of the library's sources are code, reached from the pages that name them.
    if (entry.path().extension() == ".html" && !name.ends_with("_source.html") &&
        !name.starts_with("dir_") && name != "search.html") {
      pages.push_back(entry.path());
    }
  }
  std::sort(pages.begin(), pages.end());
  json records = json::array();
  for (const fs::path& page : pages) {
    for (const Record& r : records_of(page.filename().string(), read(page))) {
      records.push_back({{"t", r.title}, {"h", r.heading}, {"u", r.url}, {"x", r.text}});
    }
  }
  write(site / "search-index.js",
        "// The site's text for its search page (docs/tools/site.cpp index).\n"
        "window.IMPULSELAB_SEARCH = " +
            records.dump(-1, ' ', false, json::error_handler_t::replace) + ";\n");
  std::cout << "search index: " << records.size() << " parts of " << pages.size() << " pages\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string verb = argc > 1 ? argv[1] : "";
    if (verb == "pages") {
      pages(options(argc, argv, 2));
    } else if (verb == "index") {
      index(options(argc, argv, 2));
    } else {
      throw Failure("usage: impulselab-site pages|index --option VALUE ...");
    }
  } catch (const std::exception& e) {
    std::cerr << "impulselab-site: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
