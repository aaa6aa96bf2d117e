// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/tokens.hpp"

#include <algorithm>
#include <array>

namespace impulse::derivations::file {

namespace commands {

const Set greek{"\\alpha",  "\\beta",  "\\gamma",   "\\delta",    "\\epsilon", "\\varepsilon",
                "\\zeta",   "\\eta",   "\\theta",   "\\vartheta", "\\iota",    "\\kappa",
                "\\lambda", "\\mu",    "\\nu",      "\\xi",       "\\rho",     "\\varrho",
                "\\sigma",  "\\tau",   "\\upsilon", "\\phi",      "\\varphi",  "\\chi",
                "\\psi",    "\\omega", "\\Gamma",   "\\Theta",    "\\Lambda",  "\\Xi",
                "\\Pi",     "\\Sigma", "\\Upsilon", "\\Phi",      "\\Psi",     "\\Omega",
                "\\ell"};
const Set spacing{"\\,",
                  "\\;",
                  "\\:",
                  "\\!",
                  "\\>",
                  "\\ ",
                  "\\quad",
                  "\\qquad",
                  "\\enspace",
                  "\\thinspace",
                  "\\medspace",
                  "\\thickspace",
                  "\\negthinspace",
                  "\\displaystyle",
                  "\\textstyle",
                  "\\scriptstyle",
                  "\\limits",
                  "\\nolimits"};
const Set functions{"\\sin",    "\\cos",    "\\tan",    "\\cot",    "\\sec",    "\\csc",
                    "\\arcsin", "\\arccos", "\\arctan", "\\exp",    "\\ln",     "\\log",
                    "\\sinh",   "\\cosh",   "\\tanh",   "\\arccot", "\\arcsec", "\\arccsc"};
const Set fractions{"\\frac", "\\dfrac", "\\tfrac", "\\cfrac"};
const Set accents{"\\vec", "\\hat", "\\overrightarrow", "\\mathbf", "\\boldsymbol", "\\bm"};
const Set modifiers{"\\bar", "\\dot", "\\ddot", "\\tilde", "\\overline", "\\breve", "\\check"};
const Set names{"\\mathrm",       "\\text",   "\\mathit", "\\textit", "\\textrm",
                "\\operatorname", "\\mathsf", "\\textsf", "\\mbox",   "\\textnormal"};
const Set sizes{"\\big",  "\\Big",  "\\bigg",  "\\Bigg",  "\\bigl", "\\Bigl", "\\biggl", "\\Biggl",
                "\\bigr", "\\Bigr", "\\biggr", "\\Biggr", "\\bigm", "\\Bigm", "\\biggm", "\\Biggm"};
const Set relations{"<",
                    ">",
                    "\\lt",
                    "\\gt",
                    "\\le",
                    "\\ge",
                    "\\leq",
                    "\\geq",
                    "\\neq",
                    "\\ne",
                    "\\approx",
                    "\\equiv",
                    "\\sim",
                    "\\simeq",
                    "\\propto",
                    "\\cong",
                    "\\leqslant",
                    "\\geqslant",
                    "\\Rightarrow",
                    "\\implies",
                    "\\iff",
                    "\\Leftrightarrow",
                    "\\to",
                    "\\rightarrow",
                    "\\Longrightarrow",
                    "\\Longleftrightarrow",
                    "\\mapsto",
                    "\\therefore"};
const Set arrows{"\\Rightarrow", "\\implies", "\\therefore", "\\Longrightarrow"};
const Set equivalences{"\\iff", "\\Leftrightarrow", "\\Longleftrightarrow"};
const Set environments{"aligned", "align",    "align*",    "split",     "gathered", "gather",
                       "gather*", "cases",    "equation",  "equation*", "multline", "multline*",
                       "alignat", "alignat*", "alignedat", "eqnarray",  "eqnarray*"};
const Set text_commands{"\\text", "\\mbox", "\\textrm", "\\textit", "\\textnormal", "\\textsf"};

}  // namespace commands

namespace {

bool letter_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool digit_char(char c) {
  return c >= '0' && c <= '9';
}

class Tokenizer {
 public:
  Tokenizer(const Source& source, std::size_t base, std::string_view text)
      : source_(source), base_(base), text_(text) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    bool space = false;
    std::size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        space = true;
        ++i;
        continue;
      }
      if (c == '%' && i > 0 && text_[i - 1] >= '0' && text_[i - 1] <= '9') {
        // 50% m g: a percentage to the writer, a comment to TeX (which hides m g).
        throw source_.error(base_ + i,
                            "expected a number for a percentage: % after a number starts a TeX "
                            "comment, which hides the rest of the line; write 0.5 for 50%");
      }
      if (c == '%') {  // a LaTeX comment runs to the end of the line
        while (i < text_.size() && text_[i] != '\n') {
          ++i;
        }
        continue;
      }
      Token token;
      token.offset = base_ + i;
      token.space_before = space;
      space = false;
      if (c == '\\') {
        std::size_t j = i + 1;
        while (j < text_.size() && letter_char(text_[j])) {
          ++j;
        }
        if (j == i + 1) {
          if (j >= text_.size()) {
            throw source_.error(base_ + i, "expected a command name after the backslash");
          }
          j = i + 2;
          if (static_cast<unsigned char>(text_[i + 1]) >= 0x80U) {
            throw source_.error(base_ + i + 1, "expected a command name after the backslash");
          }
        }
        token.kind = Tok::command;
        token.text = std::string(text_.substr(i, j - i));
        i = j;
        if (commands::spacing.contains(token.text)) {
          token.kind = Tok::spacing;
        } else if (token.text == "\\hspace" || token.text == "\\hspace*" ||
                   token.text == "\\mspace") {
          token.kind = Tok::spacing;
          i = skip_argument(i, token.offset);
        }
      } else if (letter_char(c)) {
        token.kind = Tok::letter;
        token.text = std::string(1, c);
        ++i;
      } else if (digit_char(c) || (c == '.' && i + 1 < text_.size() && digit_char(text_[i + 1]))) {
        std::size_t j = i;
        while (j < text_.size() && digit_char(text_[j])) {
          ++j;
        }
        if (j < text_.size() && text_[j] == '.' && j + 1 < text_.size() &&
            digit_char(text_[j + 1])) {
          ++j;
          while (j < text_.size() && digit_char(text_[j])) {
            ++j;
          }
        }
        if (j + 1 < text_.size() && (text_[j] == 'e' || text_[j] == 'E') &&
            (digit_char(text_[j + 1]) || ((text_[j + 1] == '-' || text_[j + 1] == '+') &&
                                          j + 2 < text_.size() && digit_char(text_[j + 2])))) {
          throw source_.error(base_ + i,
                              "expected a number without an exponent in e: " +
                                  std::string(text_.substr(i, j + 2 - i)) +
                                  "… could be a number in scientific notation or a product with "
                                  "the symbol e; write 1.5 \\times 10^{3} for the number, 1.5\\, e "
                                  "for the product");
        }
        token.kind = Tok::number;
        token.text = std::string(text_.substr(i, j - i));
        i = j;
      } else if (static_cast<unsigned char>(c) >= 0x80U) {
        i = unicode(i, token);
        if (token.kind == Tok::end) {
          space = true;  // a no-break space
          continue;
        }
      } else if (c == '~') {  // LaTeX's space that does not break a line
        token.kind = Tok::spacing;
        token.text = "~";
        ++i;
      } else {
        token.kind = Tok::character;
        token.text = std::string(1, c);
        ++i;
      }
      token.end = base_ + i;
      tokens.push_back(std::move(token));
    }
    Token end;
    end.offset = end.end = base_ + text_.size();
    tokens.push_back(end);
    return tokens;
  }

 private:
  std::size_t skip_argument(std::size_t i, std::size_t command) const {
    while (i < text_.size() && (text_[i] == ' ' || text_[i] == '*')) {
      ++i;
    }
    if (i >= text_.size() || text_[i] != '{') {
      throw source_.error(command, "expected {…} after the spacing command");
    }
    const std::size_t close = text_.find('}', i);
    if (close == std::string_view::npos) {
      throw source_.error(base_ + i, "expected '}' to close this '{'");
    }
    return close + 1;
  }

  // A few characters that people paste from documents, read as their LaTeX: the Greek letters
  // as unicode-math writes them (ε is \\varepsilon and ϵ \\epsilon, φ \\varphi and ϕ \\phi, the
  // micro sign µ \\mu), ≤ and ≥.
  std::size_t unicode(std::size_t i, Token& token) const {
    using Meaning = std::pair<Tok, std::string_view>;
    static constexpr std::array<std::pair<std::string_view, Meaning>, 46> known{{
        {"\u2032", {Tok::character, "'"}},      // prime
        {"\u00B7", {Tok::command, "\\cdot"}},   // middle dot
        {"\u22C5", {Tok::command, "\\cdot"}},   // dot operator
        {"\u2212", {Tok::character, "-"}},      // minus sign
        {"\u00D7", {Tok::command, "\\times"}},  // multiplication sign
        {"\u00A0", {Tok::end, ""}},             // no-break space
        {"\u2264", {Tok::command, "\\le"}},     // less-than or equal to
        {"\u2265", {Tok::command, "\\ge"}},     // greater-than or equal to
        {"\u00B5", {Tok::command, "\\mu"}},     // micro sign
        {"\u03B1", {Tok::command, "\\alpha"}},
        {"\u03B2", {Tok::command, "\\beta"}},
        {"\u03B3", {Tok::command, "\\gamma"}},
        {"\u03B4", {Tok::command, "\\delta"}},
        {"\u03B5", {Tok::command, "\\varepsilon"}},
        {"\u03F5", {Tok::command, "\\epsilon"}},
        {"\u03B6", {Tok::command, "\\zeta"}},
        {"\u03B7", {Tok::command, "\\eta"}},
        {"\u03B8", {Tok::command, "\\theta"}},
        {"\u03D1", {Tok::command, "\\vartheta"}},
        {"\u03B9", {Tok::command, "\\iota"}},
        {"\u03BA", {Tok::command, "\\kappa"}},
        {"\u03BB", {Tok::command, "\\lambda"}},
        {"\u03BC", {Tok::command, "\\mu"}},
        {"\u03BD", {Tok::command, "\\nu"}},
        {"\u03BE", {Tok::command, "\\xi"}},
        {"\u03C0", {Tok::command, "\\pi"}},
        {"\u03C1", {Tok::command, "\\rho"}},
        {"\u03C3", {Tok::command, "\\sigma"}},
        {"\u03C4", {Tok::command, "\\tau"}},
        {"\u03C5", {Tok::command, "\\upsilon"}},
        {"\u03C6", {Tok::command, "\\varphi"}},
        {"\u03D5", {Tok::command, "\\phi"}},
        {"\u03C7", {Tok::command, "\\chi"}},
        {"\u03C8", {Tok::command, "\\psi"}},
        {"\u03C9", {Tok::command, "\\omega"}},
        {"\u0393", {Tok::command, "\\Gamma"}},
        {"\u0394", {Tok::command, "\\Delta"}},
        {"\u0398", {Tok::command, "\\Theta"}},
        {"\u039B", {Tok::command, "\\Lambda"}},
        {"\u039E", {Tok::command, "\\Xi"}},
        {"\u03A0", {Tok::command, "\\Pi"}},
        {"\u03A3", {Tok::command, "\\Sigma"}},
        {"\u03A5", {Tok::command, "\\Upsilon"}},
        {"\u03A6", {Tok::command, "\\Phi"}},
        {"\u03A8", {Tok::command, "\\Psi"}},
        {"\u03A9", {Tok::command, "\\Omega"}},
    }};
    for (const auto& [text, meaning] : known) {
      if (text_.substr(i, text.size()) == text) {
        token.kind = meaning.first;
        token.text = std::string(meaning.second);
        return i + text.size();
      }
    }
    std::size_t j = i + 1;
    while (j < text_.size() && (static_cast<unsigned char>(text_[j]) & 0xC0U) == 0x80U) {
      ++j;
    }
    const std::string_view found = text_.substr(i, j - i);
    throw source_.error(base_ + i,
                        "expected LaTeX, found the character '" + std::string(found) +
                            (found == "\u00B0" ? "' (write degrees as 30^\\circ)"
                                               : "' (write Greek letters and symbols as commands, "
                                                 "e.g. \\omega)"));
  }

  const Source& source_;
  std::size_t base_;
  std::string_view text_;
};

}  // namespace

std::vector<Token> tokenize(const Source& source, std::size_t base, std::string_view text) {
  std::vector<Token> tokens = Tokenizer(source, base, text).run();
  // {\rm d}t and K_{\rm i}: plain TeX's upright group, read as \mathrm{d} and K_\mathrm{i}. Only
  // where \rm opens a group of its own: in a command's argument (\frac{\rm d}{…}, whose braces
  // the argument needs) or after its first token it stays refused (Grammar::refused_command).

  // Whether a brace after t may open an argument: of t, or of the command whose argument t ends
  // (\frac{a}{\rm b}, \sqrt[3]{\rm x}).
  const auto argument_of = [](const Token& t) {
    return (t.kind == Tok::character && (t.text == "^" || t.text == "}" || t.text == "]")) ||
           (t.kind == Tok::command &&
            (commands::fractions.contains(t.text) || commands::accents.contains(t.text) ||
             commands::modifiers.contains(t.text) || commands::names.contains(t.text) ||
             commands::text_commands.contains(t.text) || t.text == "\\sqrt" ||
             t.text == "\\boxed"));
  };
  for (std::size_t k = 0; k + 1 < tokens.size(); ++k) {
    if (!(k > 0 && argument_of(tokens[k - 1])) && tokens[k].kind == Tok::character &&
        tokens[k].text == "{" && tokens[k + 1].kind == Tok::command &&
        tokens[k + 1].text == "\\rm") {
      tokens[k + 1].written = "\\rm";
      tokens[k + 1].text = "{";
      tokens[k + 1].kind = Tok::character;
      tokens[k].written = "{";
      tokens[k].text = "\\mathrm";
      tokens[k].kind = Tok::command;
    }
  }
  return tokens;
}

namespace {
const std::string& as_written(const Token& t) {
  return t.written.empty() ? t.text : t.written;
}
}  // namespace

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::end:
      return "the end of the expression";
    case Tok::number:
      return "the number " + t.text;
    default:
      return "'" + as_written(t) + "'";
  }
}

// The LaTeX of a run of tokens as written: their texts, with a space where the file had one (and
// where a command name would otherwise run into a letter: \cdot m).
std::string join(const std::vector<Token>& tokens) {
  std::string out;
  const Token* previous = nullptr;
  for (const Token& t : tokens) {
    if (t.kind == Tok::end) {
      continue;
    }
    const std::string& before = previous == nullptr ? t.text : as_written(*previous);
    const bool command_before =
        previous != nullptr && before.size() > 1 && before[0] == '\\' && letter_char(before.back());
    if (previous != nullptr &&
        (t.space_before || (command_before && (t.kind == Tok::letter || t.kind == Tok::number)))) {
      out += ' ';
    }
    out += as_written(t);
    previous = &t;
  }
  return out;
}
bool blank_tokens(const std::vector<Token>& tokens) {
  return std::all_of(tokens.begin(), tokens.end(),
                     [](const Token& t) { return t.kind == Tok::spacing || t.kind == Tok::end; });
}

std::vector<Token> trimmed_tokens(std::vector<Token> tokens) {
  while (!tokens.empty() &&
         (tokens.back().kind == Tok::spacing || tokens.back().kind == Tok::end)) {
    tokens.pop_back();
  }
  std::size_t i = 0;
  while (i < tokens.size() && tokens[i].kind == Tok::spacing) {
    ++i;
  }
  tokens.erase(tokens.begin(), tokens.begin() + static_cast<std::ptrdiff_t>(i));
  return tokens;
}

std::size_t first_offset(const std::vector<Token>& tokens, std::size_t fallback) {
  for (const Token& t : tokens) {
    if (t.kind != Tok::spacing && t.kind != Tok::end) {
      return t.offset;
    }
  }
  return fallback;
}

void check_braces(const Source& source, const std::vector<Token>& tokens) {
  std::vector<std::size_t> open;
  for (const Token& t : tokens) {
    if (is_char(t, '{')) {
      open.push_back(t.offset);
    } else if (is_char(t, '}')) {
      if (open.empty()) {
        throw source.error(t.offset, "expected no '}' here: it closes no '{'");
      }
      open.pop_back();
    }
  }
  if (!open.empty()) {
    throw source.error(open.back(), "expected '}' to close this '{'");
  }
}

std::vector<int> depths(const std::vector<Token>& tokens) {
  std::vector<int> d(tokens.size(), 0);
  int depth = 0;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    const bool close = is_char(t, '}') || is_char(t, ')') || is_char(t, ']') ||
                       is_command(t, "\\}") || is_command(t, "\\right");
    if (close) {
      --depth;
    }
    d[i] = depth;
    if (is_char(t, '{') || is_char(t, '(') || is_char(t, '[') || is_command(t, "\\{") ||
        is_command(t, "\\left")) {
      ++depth;
    }
  }
  return d;
}

std::vector<std::vector<Token>> split_top(const std::vector<Token>& tokens,
                                          const std::function<bool(const Token&)>& separator,
                                          std::vector<Token>* separators) {
  std::vector<std::vector<Token>> parts(1);
  const std::vector<int> d = depths(tokens);
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (d[i] == 0 && separator(tokens[i])) {
      if (separators != nullptr) {
        separators->push_back(tokens[i]);
      }
      parts.emplace_back();
      continue;
    }
    parts.back().push_back(tokens[i]);
  }
  return parts;
}

}  // namespace impulse::derivations::file
