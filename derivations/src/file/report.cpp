// SPDX-License-Identifier: GPL-3.0-or-later
// A derivation report as text (for people at a terminal), Markdown (for notes and the docs) and
// JSON (the contract of spec/derivation-format.md, plus keys of our own).
#include <nlohmann/json.hpp>

#include <sstream>

#include "derivations/derivation.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

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

std::string pad(std::string text, std::size_t width) {
  if (text.size() < width) {
    text.append(width - text.size(), ' ');
  }
  return text;
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
        out << indent << "from line" << (e.from.size() == 1 ? " " : "s ") << lines_text(e.from)
            << ": what is left of the step is\n"
            << indent << "  LaTeX:  " << e.residual << "\n"
            << indent << "  plain:  " << e.residual_text << "\n"
            << indent << "counterexample" << (e.counterexample_exact ? "" : " (numeric)") << ": "
            << point_text(e) << "\n";
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
  if (first_failure) {
    out << paint("First failing line: " + std::to_string(*first_failure), "\033[1;31m") << "\n";
  } else {
    out << paint("Every step follows.", "\033[32m") << "\n";
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
  return out.str();
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
      j["numeric"] = {{"points", e.numeric_points}, {"worst_relative_residual", e.numeric_worst}};
    }
    equations.push_back(std::move(j));
  }
  root["equations"] = std::move(equations);
  ordered_json summary;
  for (const Verdict v : all_verdicts) {
    summary[std::string(to_string(v))] = r.count(v);
  }
  root["summary"] = summary;
  root["seconds"] = r.seconds;
  return root.dump(2) + "\n";
}

}  // namespace

std::string render(const DerivationReport& report, Format format, bool colour) {
  switch (format) {
    case Format::json:
      return render_json(report);
    case Format::markdown:
      return render_markdown(report);
    case Format::text:
      break;
  }
  return render_text(report, colour);
}

}  // namespace impulse::derivations
