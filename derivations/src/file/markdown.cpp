// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/markdown.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>

namespace impulse::derivations::file {

namespace {

constexpr std::array<std::pair<std::string_view, DirectiveKind>, 27> directive_words{{
    {"assume", DirectiveKind::assume},
    {"let", DirectiveKind::let},
    {"given", DirectiveKind::given},
    {"from", DirectiveKind::from},
    {"vector", DirectiveKind::vector},
    {"units", DirectiveKind::units},
    {"function", DirectiveKind::function},
    {"unit", DirectiveKind::unit},
    {"target", DirectiveKind::target},
    {"also", DirectiveKind::also},
    {"section", DirectiveKind::section},
    {"check", DirectiveKind::check},
    {"claim", DirectiveKind::claim},
    {"correction", DirectiveKind::correction},
    {"evidence", DirectiveKind::evidence},
    {"test", DirectiveKind::test},
    {"explanation", DirectiveKind::explanation},
    {"index", DirectiveKind::index},
    {"arrow", DirectiveKind::arrow},
    {"differentials", DirectiveKind::differentials},
    {"forces", DirectiveKind::forces},
    {"matrix", DirectiveKind::matrix},
    {"column", DirectiveKind::column},
    {"model", DirectiveKind::model},
    {"ode", DirectiveKind::ode},
    {"quadrature", DirectiveKind::quadrature},
    {"search", DirectiveKind::search},
}};

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

class Scanner {
 public:
  Scanner(const Source& source, const Limits& limits)
      : source_(source), text_(source.text()), limits_(limits) {}

  std::vector<Item> run() {
    std::size_t i = 0;
    while (i < text_.size()) {
      i = line(i);
    }
    return std::move(items_);
  }

 private:
  // One line of prose from its start; returns the offset after it (a display block, a comment
  // or a fence may take the scan past several lines).
  std::size_t line(std::size_t start) {
    const std::size_t end = line_end(start);
    if (const auto fence = fence_at(start, end)) {
      if (fence->math) {
        return math_fence(start, end, *fence);
      }
      return skip_fence(start, end, *fence);
    }
    if (directive_at(start, end)) {
      return next_line(end);
    }
    lone_inline(start, end);
    return prose(start);
  }

  // A line that is nothing but inline math holding an equation: `$v = u + a t$` or
  // `\(v = u + a t\)`, perhaps after a list's mark ("- ", "* ", "1. ") and before a full stop,
  // comma, semicolon or colon. Inline math is not read; this one is listed, to be reported.
  void lone_inline(std::size_t start, std::size_t end) {
    std::size_t i = start;
    while (i < end && blank(text_[i])) {
      ++i;
    }
    if (i + 1 < end && (text_[i] == '-' || text_[i] == '*' || text_[i] == '+') &&
        blank(text_[i + 1])) {
      i += 2;
    } else {
      std::size_t digits = i;
      while (digits < end && std::isdigit(static_cast<unsigned char>(text_[digits])) != 0) {
        ++digits;
      }
      if (digits > i && digits + 1 < end && (text_[digits] == '.' || text_[digits] == ')') &&
          blank(text_[digits + 1])) {
        i = digits + 2;
      }
    }
    while (i < end && blank(text_[i])) {
      ++i;
    }
    const std::string_view line = std::string_view(text_).substr(i, end - i);
    const bool dollar = line.starts_with('$') && !line.starts_with("$$");
    if (!dollar && !line.starts_with("\\(")) {
      return;
    }
    const std::string_view closing = dollar ? "$" : "\\)";
    const std::size_t open_length = dollar ? 1 : 2;
    const std::size_t close = line.find(closing, open_length);
    if (close == std::string_view::npos || close == open_length) {
      return;
    }
    const std::string_view math = line.substr(open_length, close - open_length);
    std::string_view rest = line.substr(close + closing.size());
    while (!rest.empty() && blank(rest.back())) {
      rest.remove_suffix(1);
    }
    if (rest.size() > 1 ||
        (rest.size() == 1 && std::string_view(".,;:").find(rest[0]) == std::string_view::npos)) {
      return;
    }
    if (math.find('=') == std::string_view::npos || (dollar && math.back() == '\\')) {
      return;
    }
    if (lone_ < limits_.equations) {  // the first ones, as many as display blocks may be
      items_.push_back(LoneInline{i, line.substr(0, close + closing.size())});
      ++lone_;
    }
  }

  std::size_t line_end(std::size_t i) const {
    const std::size_t newline = text_.find('\n', i);
    return newline == std::string::npos ? text_.size() : newline;
  }
  std::size_t next_line(std::size_t end) const { return end < text_.size() ? end + 1 : end; }

  struct Fence {
    char mark;
    std::size_t length;
    bool math = false;  // ```math: a display block (GitHub's and GitLab's notation)
  };

  // A fenced code block opens with up to three spaces and ``` or ~~~ (three or more).
  std::optional<Fence> fence_at(std::size_t start, std::size_t end) const {
    std::size_t i = start;
    while (i < end && i - start < 3 && text_[i] == ' ') {
      ++i;
    }
    if (i >= end || (text_[i] != '`' && text_[i] != '~')) {
      return std::nullopt;
    }
    const char mark = text_[i];
    std::size_t length = 0;
    while (i + length < end && text_[i + length] == mark) {
      ++length;
    }
    if (length < 3) {
      return std::nullopt;
    }
    std::size_t info = i + length;
    while (info < end && blank(text_[info])) {
      ++info;
    }
    std::size_t info_end = end;
    while (info_end > info && blank(text_[info_end - 1])) {
      --info_end;
    }
    return Fence{mark, length,
                 text_.compare(info, info_end - info, "math") == 0 && info_end - info == 4};
  }

  // A ```math fence: its lines are one display block.
  std::size_t math_fence(std::size_t start, std::size_t end, Fence fence) {
    const std::size_t content = next_line(end);
    std::size_t i = content;
    while (i < text_.size()) {
      const std::size_t e = line_end(i);
      if (const auto close = fence_at(i, e);
          close && close->mark == fence.mark && close->length >= fence.length) {
        add_block(start, content, i);
        return next_line(e);
      }
      i = next_line(e);
    }
    throw source_.error(start, "expected the math block opened here to be closed by " +
                                   std::string(fence.length, fence.mark));
  }

  void add_block(std::size_t open, std::size_t content, std::size_t close) {
    if (items_.size() - lone_ >= limits_.equations) {
      throw source_.error(open, "expected at most " + std::to_string(limits_.equations) +
                                    " display blocks in one file (this checker's limit)");
    }
    if (close - content > limits_.equation_characters) {
      throw source_.error(open, "expected a display block of at most " +
                                    std::to_string(limits_.equation_characters) +
                                    " characters (this checker's limit)");
    }
    items_.push_back(
        Block{open, content, std::string_view(text_).substr(content, close - content)});
  }

  // \[ … \]: a display block; returns the offset of the closing \].
  std::size_t bracket_block(std::size_t open) {
    const std::size_t content = open + 2;
    const std::size_t close = text_.find("\\]", content);
    if (close == std::string::npos) {
      throw source_.error(open, "expected the display block opened here to be closed by \\]");
    }
    add_block(open, content, close);
    return close;
  }

  // The environments that are display blocks outside $$, and the math environments that are
  // not read there (refused rather than skipped).
  static bool display_environment(std::string_view name) {
    for (const char* e : {"equation", "equation*", "align", "align*", "gather", "gather*",
                          "multline", "multline*"}) {
      if (name == e) {
        return true;
      }
    }
    return false;
  }
  static bool other_math_environment(std::string_view name) {
    for (const char* e : {"eqnarray", "eqnarray*", "displaymath", "math", "flalign", "flalign*",
                          "alignat", "alignat*", "dmath", "dmath*", "aligned", "gathered", "split",
                          "array", "cases", "subequations"}) {
      if (name == e) {
        return true;
      }
    }
    return false;
  }

  // \begin{equation} … \end{equation} (and align, gather, multline): a display block; returns
  // the offset after \end{…}, or nothing when the environment is not one of math.
  std::optional<std::size_t> environment_block(std::size_t open) {
    const std::size_t name_start = open + 7;  // after \begin{
    const std::size_t name_end = text_.find('}', name_start);
    if (name_end == std::string::npos) {
      return std::nullopt;
    }
    const std::string_view name = std::string_view(text_).substr(name_start, name_end - name_start);
    if (other_math_environment(name)) {
      throw source_.error(open,
                          "expected a display written as $$ … $$, \\[ … \\] or one of "
                          "the environments equation, align, gather, multline (with or "
                          "without *), found \\begin{" +
                              std::string(name) + "}: it is not read, and would be skipped");
    }
    if (!display_environment(name)) {
      return std::nullopt;
    }
    const std::string end_marker = "\\end{" + std::string(name) + "}";
    const std::size_t close = text_.find(end_marker, name_end + 1);
    if (close == std::string::npos) {
      throw source_.error(
          open, "expected \\end{" + std::string(name) + "} to close the display opened here");
    }
    add_block(open, name_end + 1, close);
    return close + end_marker.size();
  }

  std::size_t skip_fence(std::size_t start, std::size_t end, Fence fence) {
    std::size_t i = next_line(end);
    while (i < text_.size()) {
      const std::size_t e = line_end(i);
      if (const auto close = fence_at(i, e);
          close && close->mark == fence.mark && close->length >= fence.length) {
        return next_line(e);
      }
      i = next_line(e);
    }
    throw source_.error(start, "expected the code block opened here to be closed by " +
                                   std::string(fence.length, fence.mark));
  }

  bool directive_at(std::size_t start, std::size_t end) {
    std::size_t i = start;
    while (i < end && blank(text_[i])) {
      ++i;
    }
    for (const auto& [word, kind] : directive_words) {
      if (text_.compare(i, word.size(), word) == 0 && i + word.size() < end &&
          text_[i + word.size()] == ':') {
        std::size_t content = i + word.size() + 1;
        std::size_t last = end;
        while (content < last && blank(text_[content])) {
          ++content;
        }
        while (last > content && blank(text_[last - 1])) {
          --last;
        }
        // Accepted beyond the contract: the directive's LaTeX wrapped in $…$ (each item of a
        // list may be wrapped too: split_commas takes those).
        if (last - content >= 2 && text_[content] == '$' && text_[last - 1] == '$' &&
            text_[content + 1] != '$' &&
            text_.substr(content + 1, last - content - 2).find('$') == std::string::npos) {
          ++content;
          --last;
          while (content < last && blank(text_[content])) {
            ++content;
          }
          while (last > content && blank(text_[last - 1])) {
            --last;
          }
        }
        items_.push_back(
            Directive{kind, i, content, std::string_view(text_).substr(content, last - content)});
        return true;
      }
    }
    refuse_capitalised(i, end);
    return false;
  }

  // "Assume: $m > 0$" is prose to the letter of the format, and the fact was dropped without a
  // word. A directive word of the equations' own (assume, given, let, vector, function, unit,
  // units) in another case, followed by ':' and LaTeX (or nothing, as given: takes), is refused;
  // followed by words it stays prose ("Given: two balls of equal mass").
  void refuse_capitalised(std::size_t i, std::size_t end) const {
    static constexpr std::array<std::string_view, 7> words{"assume",   "given", "let",  "vector",
                                                           "function", "unit",  "units"};
    for (const std::string_view word : words) {
      if (i + word.size() >= end || text_[i + word.size()] != ':') {
        continue;
      }
      std::string written(text_.substr(i, word.size()));
      std::string lower = written;
      std::transform(lower.begin(), lower.end(), lower.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (lower != word || written == word) {
        continue;
      }
      std::size_t content = i + word.size() + 1;
      while (content < end && blank(text_[content])) {
        ++content;
      }
      const std::string_view rest = std::string_view(text_).substr(content, end - content);
      if (rest.empty() || rest.front() == '$' ||
          rest.find_first_of("<>=\\") != std::string_view::npos) {
        throw source_.error(i, "expected the directive " + std::string(word) +
                                   ": in lower case, found " + written +
                                   ": (as it is written, the line would be prose, and what it "
                                   "says would not be read)");
      }
    }
  }

  // Prose from @p i to the end of its line: looks for $$, skipping code spans, escaped dollars
  // and HTML comments. A comment or a display block may end on a later line; the scan then goes
  // on to the end of that line.
  std::size_t prose(std::size_t i) {
    std::size_t end = line_end(i);
    while (i < end) {
      const char c = text_[i];
      if (text_.compare(i, 2, "\\[") == 0) {
        const std::size_t close = bracket_block(i);
        end = std::max(end, line_end(close));
        i = close + 2;
      } else if (text_.compare(i, 7, "\\begin{") == 0) {
        if (const auto after = environment_block(i)) {
          end = std::max(end, line_end(*after - 1));
          i = *after;
        } else {
          i += 7;  // an environment of prose
        }
      } else if (c == '\\' && i + 1 < end) {
        i += 2;
      } else if (c == '`') {
        i = skip_code_span(i, end);
      } else if (text_.compare(i, 4, "<!--") == 0) {
        const std::size_t close = text_.find("-->", i + 4);
        if (close == std::string::npos) {
          throw source_.error(i, "expected the comment opened here to be closed by -->");
        }
        i = close + 3;
        end = std::max(end, line_end(close));
      } else if (text_.compare(i, 2, "$$") == 0) {
        const std::size_t close = display_block(i);
        end = std::max(end, line_end(close));
        i = close + 2;
      } else {
        ++i;
      }
    }
    return next_line(end);
  }

  std::size_t skip_code_span(std::size_t i, std::size_t end) const {
    std::size_t run = 0;
    while (i + run < end && text_[i + run] == '`') {
      ++run;
    }
    const std::string ticks(run, '`');
    for (std::size_t k = i + run; k < end;) {
      const std::size_t found = text_.find(ticks, k);
      if (found == std::string::npos || found >= end) {
        break;
      }
      std::size_t other = 0;
      while (found + other < end && text_[found + other] == '`') {
        ++other;
      }
      if (other == run) {
        return found + run;
      }
      k = found + other;
    }
    return i + run;  // no closing run: the backticks are literal
  }

  std::size_t display_block(std::size_t open) {
    const std::size_t content = open + 2;
    std::size_t k = content;
    while (true) {
      const std::size_t close = text_.find("$$", k);
      if (close == std::string::npos) {
        throw source_.error(open, "expected the display block opened here to be closed by $$");
      }
      if (close > content && text_[close - 1] == '\\') {  // \$ is a dollar sign
        k = close + 1;
        continue;
      }
      add_block(open, content, close);
      return close;
    }
  }

  const Source& source_;
  const std::string& text_;
  const Limits& limits_;
  std::vector<Item> items_;
  std::size_t lone_ = 0;  // how many of items_ are LoneInline
};

}  // namespace

std::vector<Item> read_markdown(const Source& source, const Limits& limits) {
  return Scanner(source, limits).run();
}

std::string_view to_string(DirectiveKind kind) {
  for (const auto& [word, k] : directive_words) {
    if (k == kind) {
      return word;
    }
  }
  return "?";
}

}  // namespace impulse::derivations::file
