// SPDX-License-Identifier: GPL-3.0-or-later
// A derivation report as text (for people at a terminal), Markdown (for notes and the docs) and
// JSON (the contract of spec/derivation-format.md, plus keys of our own).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <iterator>
#include <sstream>

#include "derivations/derivation.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

std::string task_verdict(const TaskResult& t) {
  if (t.target_reached) {
    return "the target is reached at line " + std::to_string(t.line.value_or(0)) + ".";
  }
  std::string lines;
  for (const std::size_t l : t.extra_premises) {
    lines += (lines.empty() ? "" : ", ") + std::to_string(l);
  }
  if (t.reason == "target-assumed") {
    return "the target is assumed, not derived (the premise at line " + lines + " is the target).";
  }
  if (t.reason == "extra-premise") {
    return std::string("a premise the task does not give (line") +
           (t.extra_premises.size() == 1 ? " " : "s ") + lines + ").";
  }
  if (t.reason == "step-fails") {
    return "a step before the target does not pass.";
  }
  return "the target is not reached (no step is equivalent to " + t.target + ").";
}

namespace {

std::string value_text(double x, const std::string& exact) {
  return exact.empty() ? num::brief(x, 6) : exact;
}

std::string point_text(const EquationResult& e) {
  std::string text;
  for (const CounterexampleValue& v : e.counterexample) {
    text += (text.empty() ? "" : ", ") + v.symbol + " = ";
    if (v.vector) {
      text += '[';
      text += value_text(v.x, v.exact_x);
      text += ", ";
      text += value_text(v.y, v.exact_y);
      text += ']';
    } else {
      text += value_text(v.x, v.exact_x);
    }
  }
  return text;
}

std::string lines_text(const std::vector<std::size_t>& lines) {
  std::string text;
  for (const std::size_t l : lines) {
    text += (text.empty() ? "" : ", ") + std::to_string(l);
  }
  return text;
}

std::string summary_text(const DerivationReport& r) {
  std::string text;
  for (const Verdict v : all_verdicts) {
    if (r.count(v) == 0) {
      continue;
    }
    text +=
        (text.empty() ? "" : ", ") + std::to_string(r.count(v)) + " " + std::string(to_string(v));
  }
  return text;
}

// The steps that follow only under a condition the facts do not give, named.
std::string conditional_text(const DerivationReport& r) {
  std::string lines;
  std::size_t count = 0;
  for (const EquationResult& e : r.equations) {
    if (e.verdict == Verdict::follows_if) {
      lines += (lines.empty() ? "" : "; ") + std::string("line ") + std::to_string(e.line) +
               " only where " + e.condition_text;
      ++count;
    }
  }
  return std::string(count == 1 ? "one step holds" : std::to_string(count) + " steps hold") +
         " only under a condition the facts do not give: " + lines + ".";
}

std::string task_text(const TaskResult& t) {
  return "Task " + t.task + ": " + task_verdict(t);
}

std::string pad(std::string text, std::size_t width) {
  if (text.size() < width) {
    text.append(width - text.size(), ' ');
  }
  return text;
}

// The report's notes, a line each, and a blank line after them.
std::string notes_text(const DerivationReport& r, bool colour) {
  std::string text;
  for (const FileNote& n : r.notes) {
    const std::string head = "Note, line " + std::to_string(n.line) + ": ";
    text += (colour ? "\033[33m" + head + "\033[0m" : head) + n.written + " is " + n.text + "\n";
  }
  return text.empty() ? text : text + "\n";
}

std::string render_text(const DerivationReport& r, bool colour) {
  const auto paint = [&](const std::string& text, const char* code) {
    return colour ? std::string(code) + text + "\033[0m" : text;
  };
  const auto colour_of = [](Verdict v) {
    switch (v) {
      case Verdict::follows:
      case Verdict::follows_one_way:
        return "\033[32m";
      case Verdict::follows_if:
        return "\033[33m";
      case Verdict::premise:
        return "\033[36m";
      default:
        return "\033[1;31m";
    }
  };
  std::ostringstream out;
  out << r.file << ": " << r.equations.size() << " equation" << (r.equations.size() == 1 ? "" : "s")
      << " (" << summary_text(r) << ")\n\n";
  out << "  line  verdict          by       equation\n";
  std::optional<std::size_t> first_failure;
  const std::string indent(34, ' ');
  for (const EquationResult& e : r.equations) {
    const bool fails = derivations::fails(e.verdict);
    const bool first = fails && !first_failure;
    if (first) {
      first_failure = e.line;
    }
    const std::string number = std::to_string(e.line);
    const std::string line = std::string(first   ? ">>"
                                         : fails ? " x"
                                                 : "  ") +
                             std::string(number.size() < 4 ? 4 - number.size() : 0, ' ') + number;
    out << (fails ? paint(line, colour_of(e.verdict)) : line) << "  "
        << paint(pad(std::string(to_string(e.verdict)), 16), colour_of(e.verdict)) << " "
        << pad(e.decided_by, 7) << "  " << e.latex << (e.tag ? "  (" + *e.tag + ")" : "") << "\n";
    switch (e.verdict) {
      case Verdict::follows_if:
        out << indent << "where " << e.condition << "   [" << e.condition_text << "]\n";
        break;
      case Verdict::does_not_follow:
        if (!e.equivalence_note.empty()) {
          out << indent << e.equivalence_note << "\n";
        }
        out << indent << "from line" << (e.from.size() == 1 ? " " : "s ") << lines_text(e.from)
            << ": what is left of the step is\n"
            << indent << "  LaTeX:  " << e.residual << "\n"
            << indent << "  plain:  " << e.residual_text << "\n"
            << indent << "counterexample" << (e.counterexample_exact ? "" : " (numeric)") << ": "
            << point_text(e)
            << (e.counterexample_functions.empty() ? "" : "; " + e.counterexample_functions)
            << "\n";
        break;
      case Verdict::dimensions:
        out << indent << e.dimension_what << "\n";
        break;
      case Verdict::undecided:
        out << indent << e.how << "\n";
        break;
      default:
        break;
    }
  }
  out << "\n";
  out << notes_text(r, colour);
  if (first_failure) {
    out << paint("First failing line: " + std::to_string(*first_failure), "\033[1;31m") << "\n";
  } else if (r.count(Verdict::follows_if) > 0) {
    out << paint("Every step follows, but " + conditional_text(r), "\033[33m") << "\n";
  } else {
    out << paint("Every step follows.", "\033[32m") << "\n";
  }
  if (r.task) {
    out << task_text(*r.task) << "\n";
  }
  return out.str();
}

// A table cell cannot hold '|': the LaTeX norm \| becomes \Vert, a bar \vert.
std::string escape_markdown(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '|') {
      out += "\\Vert ";
      ++i;
    } else if (text[i] == '|') {
      out += "\\vert ";
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string render_markdown(const DerivationReport& r) {
  std::ostringstream out;
  out << "**" << r.file << "**: " << r.equations.size() << " equations (" << summary_text(r)
      << ").\n\n";
  out << "| line | verdict | equation | details |\n|---:|---|---|---|\n";
  for (const EquationResult& e : r.equations) {
    std::string details;
    switch (e.verdict) {
      case Verdict::follows_if:
        details = "where $" + e.condition + "$";
        break;
      case Verdict::does_not_follow:
        details = "left over: $" + e.residual + "$; counterexample: " + point_text(e);
        break;
      case Verdict::dimensions:
        details = e.dimension_what;
        break;
      case Verdict::undecided:
        details = e.how;
        break;
      default:
        details = e.decided_by;
        break;
    }
    const bool fails = derivations::fails(e.verdict);
    out << "| " << e.line << " | " << (fails ? "**" : "") << to_string(e.verdict)
        << (fails ? "**" : "") << " | $" << escape_markdown(e.latex) << "$ | "
        << escape_markdown(details) << " |\n";
  }
  for (const FileNote& n : r.notes) {
    out << "\n- Note, line " << n.line << ": `" << n.written << "` is " << n.text << "\n";
  }
  if (r.count(Verdict::follows_if) > 0 && exit_status(r) == 0) {
    out << "\nEvery step follows, but " << conditional_text(r) << "\n";
  }
  if (r.task) {
    out << "\n" << task_text(*r.task) << "\n";
  }
  return out.str();
}

nlohmann::ordered_json task_json(const TaskResult& t) {
  nlohmann::ordered_json j;
  j["target_reached"] = t.target_reached;
  j["line"] = t.line ? nlohmann::ordered_json(*t.line) : nlohmann::ordered_json(nullptr);
  j["extra_premises"] = t.extra_premises;
  j["reason"] = t.reason;
  j["file"] = t.task;
  return j;
}

std::string render_json(const DerivationReport& r) {
  using nlohmann::ordered_json;
  ordered_json root;
  root["file"] = r.file;
  ordered_json equations = ordered_json::array();
  for (const EquationResult& e : r.equations) {
    ordered_json j;
    j["line"] = e.line;
    j["tag"] = e.tag ? ordered_json(*e.tag) : ordered_json(nullptr);
    j["latex"] = e.latex;
    j["verdict"] = std::string(to_string(e.verdict));
    switch (e.verdict) {
      case Verdict::follows_if:
        j["condition"] = e.condition;
        j["condition_text"] = e.condition_text;
        j["condition_needed"] = e.condition_needed;
        break;
      case Verdict::does_not_follow: {
        j["residual"] = e.residual;
        j["residual_text"] = e.residual_text;
        ordered_json point = ordered_json::object();
        ordered_json exact = ordered_json::object();
        for (const CounterexampleValue& v : e.counterexample) {
          point[v.symbol] = v.vector ? ordered_json::array({v.x, v.y}) : ordered_json(v.x);
          exact[v.symbol] =
              v.vector ? ordered_json::array({v.exact_x, v.exact_y}) : ordered_json(v.exact_x);
        }
        j["counterexample"] = point;
        if (e.counterexample_exact) {
          j["counterexample_exact"] = exact;
        }
        if (!e.counterexample_functions.empty()) {
          j["counterexample_functions"] = e.counterexample_functions;
        }
        break;
      }
      case Verdict::dimensions:
        j["dimensions"] = ordered_json::array({e.dimension_first, e.dimension_second});
        j["dimensions_text"] = e.dimension_what;
        break;
      default:
        break;
    }
    j["column"] = e.column;
    j["decided_by"] = e.decided_by.empty() ? ordered_json(nullptr) : ordered_json(e.decided_by);
    j["from"] = e.from;
    if (e.verdict == Verdict::follows || e.verdict == Verdict::follows_one_way) {
      j["converse"] = e.converse ? ordered_json(*e.converse) : ordered_json(nullptr);
    }
    if (!e.how.empty()) {
      j["how"] = e.how;
    }
    j["seconds"] = e.seconds;
    if (e.verdict != Verdict::premise && e.verdict != Verdict::dimensions) {
      j["numeric"] = {{"points", e.numeric_points},
                      {"worst_relative_residual", num::reported_residual(e.numeric_worst)}};
    }
    equations.push_back(std::move(j));
  }
  root["equations"] = std::move(equations);
  // The key only where there are notes: reports without them stay as they were.
  if (!r.notes.empty()) {
    ordered_json notes = ordered_json::array();
    for (const FileNote& n : r.notes) {
      notes.push_back(
          {{"line", n.line}, {"column", n.column}, {"written", n.written}, {"text", n.text}});
    }
    root["notes"] = std::move(notes);
  }
  ordered_json summary;
  for (const Verdict v : all_verdicts) {
    summary[std::string(to_string(v))] = r.count(v);
  }
  root["summary"] = summary;
  if (r.task) {
    root["task"] = task_json(*r.task);
  }
  root["seconds"] = r.seconds;
  return root.dump(2) + "\n";
}

// ---- several files -----------------------------------------------------------------------------

std::optional<std::size_t> first_failing(const DerivationReport& r) {
  for (const EquationResult& e : r.equations) {
    if (fails(e.verdict)) {
      return e.line;
    }
  }
  return std::nullopt;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text) {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

std::string render_rows_csv(const std::vector<FileRow>& rows) {
  std::ostringstream out;
  out << "file,exit,equations";
  for (const Verdict v : all_verdicts) {
    out << ',' << to_string(v);
  }
  out << ",first_failing_line,target_reached,target_line,extra_premises,error\n";
  for (const FileRow& row : rows) {
    out << csv_field(row.file) << ',' << row.exit << ',';
    if (row.report) {
      const DerivationReport& r = *row.report;
      out << r.equations.size();
      for (const Verdict v : all_verdicts) {
        out << ',' << r.count(v);
      }
      const auto first = first_failing(r);
      out << ',' << (first ? std::to_string(*first) : "");
      if (r.task) {
        std::string extra;
        for (const std::size_t l : r.task->extra_premises) {
          extra += (extra.empty() ? "" : " ") + std::to_string(l);
        }
        out << ',' << (r.task->target_reached ? "true" : "false") << ','
            << (r.task->line ? std::to_string(*r.task->line) : "") << ',' << extra;
      } else {
        out << ",,,";
      }
      out << ",\n";
    } else {
      out << ',';
      for (std::size_t k = 0; k < std::size(all_verdicts); ++k) {
        out << ',';
      }
      out << ",,,," << csv_field(row.error) << "\n";
    }
  }
  return out.str();
}

std::string render_rows_json(const std::vector<FileRow>& rows) {
  using nlohmann::ordered_json;
  ordered_json files = ordered_json::array();
  int worst = 0;
  for (const FileRow& row : rows) {
    ordered_json j;
    j["file"] = row.file;
    j["exit"] = row.exit;
    if (row.report) {
      j["report"] = ordered_json::parse(render_json(*row.report));
    } else {
      j["error"] = row.error;
    }
    worst = std::max(worst, row.exit);
    files.push_back(std::move(j));
  }
  ordered_json root;
  root["files"] = std::move(files);
  root["exit"] = worst;
  return root.dump(2) + "\n";
}

std::string render_rows_text(const std::vector<FileRow>& rows, bool markdown) {
  std::ostringstream out;
  if (markdown) {
    out << "| file | equations | verdicts | first failing line | task |\n|---|---:|---|---:|---|\n";
  } else {
    out << "Summary of " << rows.size() << " files:\n\n";
  }
  for (const FileRow& row : rows) {
    std::string verdicts;
    std::string equations;
    std::string first;
    std::string task;
    if (row.report) {
      verdicts = summary_text(*row.report);
      equations = std::to_string(row.report->equations.size());
      const auto f = first_failing(*row.report);
      first = f ? std::to_string(*f) : "-";
      if (!row.report->notes.empty()) {
        std::vector<std::size_t> lines;
        for (const FileNote& n : row.report->notes) {
          lines.push_back(n.line);
        }
        verdicts += "; not checked: inline math at line" +
                    std::string(lines.size() == 1 ? " " : "s ") + lines_text(lines);
      }
      if (row.report->task) {
        task = row.report->task->target_reached
                   ? "target reached at line " + std::to_string(row.report->task->line.value_or(0))
                   : row.report->task->reason;
      }
    } else {
      verdicts = "refused: " + row.error;
    }
    if (markdown) {
      out << "| " << row.file << " | " << equations << " | " << verdicts << " | " << first << " | "
          << task << " |\n";
    } else {
      out << "  "
          << (row.exit == 0   ? "ok  "
              : row.exit == 1 ? "FAIL"
                              : "BAD ")
          << "  " << row.file << ": " << (equations.empty() ? "" : equations + " equations (")
          << verdicts << (equations.empty() ? "" : ")")
          << (first.empty() || first == "-" ? "" : "; first failing line " + first)
          << (task.empty() ? "" : "; task: " + task) << "\n";
    }
  }
  return out.str();
}

}  // namespace

std::string render_rows(const std::vector<FileRow>& rows, Format format) {
  switch (format) {
    case Format::csv:
      return render_rows_csv(rows);
    case Format::json:
      return render_rows_json(rows);
    case Format::markdown:
      return render_rows_text(rows, true);
    case Format::text:
      break;
  }
  return render_rows_text(rows, false);
}

std::string render(const DerivationReport& report, Format format, bool colour) {
  switch (format) {
    case Format::json:
      return render_json(report);
    case Format::markdown:
      return render_markdown(report);
    case Format::csv:
      return render_rows({FileRow{report.file, report, "", exit_status(report)}}, Format::csv);
    case Format::text:
      break;
  }
  return render_text(report, colour);
}

}  // namespace impulse::derivations
