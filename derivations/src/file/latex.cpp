// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/latex.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <functional>
#include <set>

namespace impulse::derivations::file {

// ---- symbol names ------------------------------------------------------------------------------

namespace {

bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

std::string SymbolName::latex() const {
  std::string out = delta ? "\\Delta " : differential ? "\\mathrm{d}" : "";
  out += arrow ? "\\vec{" + base + "}" : base;
  if (!subscript.empty()) {
    out += subscript.size() == 1 ? "_" + subscript : "_{" + subscript + "}";
  }
  out += std::string(static_cast<std::size_t>(primes), '\'');
  return out;
}

std::string SymbolName::plain() const {
  std::string out = delta ? "Delta " : differential ? "d" : "";
  if (arrow) {
    out += "vec ";
  }
  const auto strip = [](const std::string& s) {
    std::string r;
    for (const char c : s) {
      if (c != '\\' && c != '{' && c != '}') {
        r += c;
      }
    }
    return r;
  };
  out += strip(base);
  if (!subscript.empty()) {
    out += "_" + strip(subscript);
  }
  out += std::string(static_cast<std::size_t>(primes), '\'');
  return out;
}

SymbolName SymbolName::unprimed() const {
  SymbolName name = *this;
  name.primes = 0;
  return name;
}

namespace {

// ---- tokens ------------------------------------------------------------------------------------

enum class Tok { command, letter, number, character, spacing, end };

struct Token {
  Tok kind = Tok::end;
  std::string text;
  std::size_t offset = 0;
  std::size_t end = 0;
  bool space_before = false;
};

const std::set<std::string, std::less<>> greek{
    "\\alpha",  "\\beta",   "\\gamma",    "\\delta",  "\\epsilon", "\\varepsilon", "\\zeta",
    "\\eta",    "\\theta",  "\\vartheta", "\\iota",   "\\kappa",   "\\lambda",     "\\mu",
    "\\nu",     "\\xi",     "\\rho",      "\\varrho", "\\sigma",   "\\tau",        "\\upsilon",
    "\\phi",    "\\varphi", "\\chi",      "\\psi",    "\\omega",   "\\Gamma",      "\\Theta",
    "\\Lambda", "\\Xi",     "\\Pi",       "\\Sigma",  "\\Upsilon", "\\Phi",        "\\Psi",
    "\\Omega",  "\\ell"};
const std::set<std::string, std::less<>> spacing_commands{"\\,",
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
const std::set<std::string, std::less<>> functions{"\\sin", "\\cos", "\\tan", "\\exp", "\\ln"};
const std::set<std::string, std::less<>> fractions{"\\frac", "\\dfrac", "\\tfrac", "\\cfrac"};
const std::set<std::string, std::less<>> accents{"\\vec",    "\\hat",        "\\overrightarrow",
                                                 "\\mathbf", "\\boldsymbol", "\\bm"};
const std::set<std::string, std::less<>> modifiers{"\\bar",      "\\dot",   "\\ddot", "\\tilde",
                                                   "\\overline", "\\breve", "\\check"};
const std::set<std::string, std::less<>> names{"\\mathrm", "\\text",   "\\mathit",
                                               "\\textit", "\\textrm", "\\operatorname",
                                               "\\mathsf", "\\textsf"};
const std::set<std::string, std::less<>> sizes{"\\big",   "\\Big",   "\\bigg",  "\\Bigg", "\\bigl",
                                               "\\Bigl",  "\\biggl", "\\Biggl", "\\bigr", "\\Bigr",
                                               "\\biggr", "\\Biggr", "\\bigm",  "\\Bigm"};
const std::set<std::string, std::less<>> relations{"<",
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
                                                   "\\mapsto"};
const std::set<std::string, std::less<>> environments{
    "aligned", "align",    "align*",    "split",     "gathered", "gather",
    "gather*", "cases",    "equation",  "equation*", "multline", "multline*",
    "alignat", "alignat*", "alignedat", "eqnarray",  "eqnarray*"};

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
        while (j < text_.size() && is_letter(text_[j])) {
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
        if (spacing_commands.contains(token.text)) {
          token.kind = Tok::spacing;
        } else if (token.text == "\\hspace" || token.text == "\\hspace*" ||
                   token.text == "\\mspace") {
          token.kind = Tok::spacing;
          i = skip_argument(i, token.offset);
        }
      } else if (is_letter(c)) {
        token.kind = Tok::letter;
        token.text = std::string(1, c);
        ++i;
      } else if (is_digit(c) || (c == '.' && i + 1 < text_.size() && is_digit(text_[i + 1]))) {
        std::size_t j = i;
        while (j < text_.size() && is_digit(text_[j])) {
          ++j;
        }
        if (j < text_.size() && text_[j] == '.' && j + 1 < text_.size() && is_digit(text_[j + 1])) {
          ++j;
          while (j < text_.size() && is_digit(text_[j])) {
            ++j;
          }
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

  // A few characters that people paste from documents, read as their LaTeX.
  std::size_t unicode(std::size_t i, Token& token) const {
    const std::array<std::pair<std::string_view, std::pair<Tok, std::string_view>>, 6> known{{
        {"\u2032", {Tok::character, "'"}},      // prime
        {"\u00B7", {Tok::command, "\\cdot"}},   // middle dot
        {"\u22C5", {Tok::command, "\\cdot"}},   // dot operator
        {"\u2212", {Tok::character, "-"}},      // minus sign
        {"\u00D7", {Tok::command, "\\times"}},  // multiplication sign
        {"\u00A0", {Tok::end, ""}},             // no-break space
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
    throw source_.error(base_ + i, "expected LaTeX, found the character '" +
                                       std::string(text_.substr(i, j - i)) +
                                       "' (write Greek letters and symbols as commands, e.g. "
                                       "\\omega)");
  }

  const Source& source_;
  std::size_t base_;
  std::string_view text_;
};

bool is(const Token& t, Tok kind, std::string_view text) {
  return t.kind == kind && t.text == text;
}
bool is_char(const Token& t, char c) {
  return t.kind == Tok::character && t.text.size() == 1 && t.text[0] == c;
}
bool is_command(const Token& t, std::string_view name) {
  return is(t, Tok::command, name);
}

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::end:
      return "the end of the expression";
    case Tok::number:
      return "the number " + t.text;
    default:
      return "'" + t.text + "'";
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
    const bool command_before = previous != nullptr && previous->text.size() > 1 &&
                                previous->text[0] == '\\' && is_letter(previous->text.back());
    if (previous != nullptr &&
        (t.space_before || (command_before && (t.kind == Tok::letter || t.kind == Tok::number)))) {
      out += ' ';
    }
    out += t.text;
    previous = &t;
  }
  return out;
}

// ---- the parser of one expression -------------------------------------------------------------

class Parser {
 public:
  Parser(const Source& source, std::vector<Token> tokens, const Limits& limits)
      : source_(source), tokens_(std::move(tokens)), limits_(limits) {}

  Node whole_expression() {
    skip_spacing();
    if (peek().kind == Tok::end) {
      throw error(peek(), "expected an expression");
    }
    Node node = expression(0);
    if (peek().kind != Tok::end) {
      throw error(peek(),
                  "expected an operator or the end of the expression, found " + describe(peek()));
    }
    return node;
  }

  SymbolName whole_symbol() {
    skip_spacing();
    const Token& first = peek();
    Node node = atom(0);
    if (node.kind != NodeKind::symbol) {
      throw error(first, "expected a symbol (a letter with an optional subscript and primes)");
    }
    skip_spacing();
    if (peek().kind != Tok::end) {
      throw error(peek(), "expected one symbol, found more after it: " + describe(peek()));
    }
    return node.symbol;
  }

 private:
  // ---- token access ----
  const Token& peek() {
    skip_spacing();
    return tokens_[position_];
  }
  const Token& peek_raw() const { return tokens_[position_]; }
  Token take() {
    skip_spacing();
    Token t = tokens_[position_];
    if (t.kind != Tok::end) {
      ++position_;
    }
    last_end_ = t.end;
    return t;
  }
  void skip_spacing() {
    while (tokens_[position_].kind == Tok::spacing) {
      ++position_;
    }
  }
  ReadError error(const Token& at, const std::string& message) const {
    return source_.error(at.offset, message);
  }
  void expect_char(char c, const Token& opener, const std::string& what) {
    if (!is_char(peek(), c)) {
      throw error(peek(), "expected '" + std::string(1, c) + "' to close the " + what +
                              " opened at " + where(opener) + ", found " + describe(peek()));
    }
    take();
  }
  std::string where(const Token& t) const {
    const Place p = source_.place(t.offset);
    return "line " + std::to_string(p.line) + ", column " + std::to_string(p.column);
  }
  void enter(std::size_t depth, const Token& at) const {
    if (depth > limits_.nesting) {
      throw error(at, "expected at most " + std::to_string(limits_.nesting) +
                          " levels of nesting (this checker's limit)");
    }
  }

  Node make(NodeKind kind, std::size_t offset) const {
    Node n;
    n.kind = kind;
    n.offset = offset;
    n.end = last_end_;
    return n;
  }

  // ---- grammar ----
  // expression := [+|-] term {(+|-) term}
  Node expression(std::size_t depth) {
    enter(depth, peek());
    const std::size_t start = peek().offset;
    Node sum = make(NodeKind::sum, start);
    char sign = '+';
    if (is_char(peek(), '+') || is_char(peek(), '-')) {
      sign = take().text[0];
    }
    sum.children.push_back(sum_term(depth + 1));
    sum.ops += sign;
    while (is_char(peek(), '+') || is_char(peek(), '-') || is_command(peek(), "\\oplus")) {
      const Token op = take();
      sign = op.kind == Tok::character ? op.text[0] : '+';  // the paper's ⊕ adds padded blocks
      sum.children.push_back(sum_term(depth + 1));
      sum.ops += sign;
    }
    for (std::size_t i = 0; i < sum.children.size(); ++i) {
      if (sum.children[i].kind == NodeKind::dots &&
          (i == 0 || i + 1 == sum.children.size() || sum.ops[i] != '+')) {
        throw error_at(sum.children[i].offset,
                       "expected \\cdots between two terms added to each other (A_1 + \\cdots + "
                       "A_M)");
      }
    }
    if (sum.children.size() == 1 && sum.ops[0] == '+') {
      return std::move(sum.children[0]);
    }
    sum.end = last_end_;
    return sum;
  }

  // A term of a sum, or \cdots standing for the terms between its neighbours.
  Node sum_term(std::size_t depth) {
    const Token& t = peek();
    if (is_command(t, "\\cdots") || is_command(t, "\\dots") || is_command(t, "\\ldots") ||
        is_command(t, "\\dotsb")) {
      const Token dots = take();
      return make(NodeKind::dots, dots.offset);
    }
    return term(depth);
  }

  static bool big_operator(const Token& t) {
    return is_command(t, "\\sum") || is_command(t, "\\int");
  }

  // \sum_i and \int_a^b take the rest of the term as their argument (accepted beyond the
  // contract, for the paper's files).
  Node big(std::size_t depth) {
    const Token op = take();
    if (is_command(op, "\\sum")) {
      if (!is_char(peek_raw(), '_')) {
        throw error(peek(),
                    "expected \\sum_i: a subscript naming the index (its range is "
                    "declared with index:)");
      }
      take();
      const Token& at = peek_raw();
      std::string index;
      if (at.kind == Tok::letter) {
        index = take().text;
      } else if (is_char(at, '{')) {
        const Token open = take();
        if (peek().kind != Tok::letter) {
          throw error(peek(), "expected one letter as the index of \\sum");
        }
        index = take().text;
        expect_char('}', open, "index of \\sum");
      } else {
        throw error(at, "expected one letter as the index of \\sum, found " + describe(at));
      }
      if (is_char(peek(), '^')) {
        throw error(peek(), "expected \\sum_" + index + " without an upper limit: the range of " +
                                index + " is declared with index:");
      }
      if (!starts_atom(peek()) && !big_operator(peek())) {
        throw error(peek(), "expected what \\sum_" + index + " adds up after it");
      }
      Node n = make(NodeKind::sum_over, op.offset);
      n.text = index;
      n.children.push_back(term(depth + 1));
      n.end = last_end_;
      return n;
    }
    Node n = make(NodeKind::integral, op.offset);
    std::optional<Node> lower;
    std::optional<Node> upper;
    bool path = false;
    for (int k = 0; k < 2; ++k) {
      if (is_char(peek(), '_') && !lower && !path) {
        const Token mark = take();
        if (path_domain()) {
          path = true;
          continue;
        }
        lower = script(depth + 1, mark);
      } else if (is_char(peek(), '^') && !upper) {
        const Token mark = take();
        upper = script(depth + 1, mark);
      }
    }
    if (!starts_atom(peek()) && !big_operator(peek())) {
      throw error(peek(), "expected the integrand after \\int (ending in its differential, dt)");
    }
    n.children.push_back(term(depth + 1));
    if (path) {
      if (upper) {
        throw error(op,
                    "expected no upper limit on an integral along a path (\\int_{\\mathcal{A}})");
      }
      n.ops += 'p';
    }
    if (lower) {
      n.children.push_back(std::move(*lower));
      n.ops += 'l';
    }
    if (upper) {
      n.children.push_back(std::move(*upper));
      n.ops += 'u';
    }
    n.end = last_end_;
    return n;
  }

  // After \int's '_': a path written as a calligraphic letter, \mathcal{A} or {\mathcal{A}}
  // (the path a point travels during the contact), taken whole; false (nothing taken) otherwise.
  bool path_domain() {
    skip_spacing();
    std::size_t at = position_;
    const bool braced = is_char(tokens_[at], '{');
    if (braced) {
      ++at;
      while (tokens_[at].kind == Tok::spacing) {
        ++at;
      }
    }
    if (!is_command(tokens_[at], "\\mathcal")) {
      return false;
    }
    position_ = at;
    const Token command = take();
    if (!is_char(peek(), '{')) {
      throw error(peek(), "expected {a letter} after \\mathcal");
    }
    const Token open = take();
    if (peek().kind != Tok::letter) {
      throw error(peek(), "expected one letter naming the path in \\mathcal{}");
    }
    take();
    expect_char('}', open, "path after \\mathcal");
    if (braced) {
      expect_char('}', command, "limit of \\int");
    }
    return true;
  }

  ReadError error_at(std::size_t offset, const std::string& message) const {
    return source_.error(offset, message);
  }

  bool explicit_product(const Token& t) const {
    return is_command(t, "\\cdot") || is_command(t, "\\times") || is_char(t, '*') ||
           is_char(t, '/') || is_command(t, "\\div") || is_command(t, "\\ast");
  }

  // term := factor {op factor | factor}   (juxtaposition is a product)
  Node term(std::size_t depth) {
    enter(depth, peek());
    const std::size_t start = peek().offset;
    Node product = make(NodeKind::product, start);
    if (big_operator(peek())) {
      return big(depth + 1);
    }
    product.children.push_back(factor(depth + 1));
    product.ops += ' ';
    while (true) {
      const Token& next = peek();
      if (big_operator(next)) {
        product.children.push_back(big(depth + 1));
        product.ops += ' ';
        break;  // a sum or an integral takes the rest of the term
      }
      if (explicit_product(next)) {
        const Token op = take();
        const char code = is_command(op, "\\cdot")                        ? '.'
                          : is_command(op, "\\times")                     ? 'x'
                          : (is_char(op, '/') || is_command(op, "\\div")) ? '/'
                                                                          : '*';
        if (peek().kind == Tok::end || is_char(peek(), '=')) {
          throw error(peek(), "expected a factor after " + describe(op));
        }
        if (big_operator(peek())) {
          product.children.push_back(big(depth + 1));
          product.ops += code;
          break;
        }
        product.children.push_back(factor(depth + 1));
        product.ops += code;
      } else if (starts_atom(next)) {
        if (next.kind == Tok::number && !product.children.empty() &&
            product.children.back().kind == NodeKind::number) {
          throw error(next, "expected an operator between two numbers (write \\cdot or \\times)");
        }
        product.children.push_back(factor(depth + 1));
        product.ops += ' ';
      } else {
        break;
      }
    }
    if (product.children.size() == 1) {
      return std::move(product.children[0]);
    }
    product.end = last_end_;
    return product;
  }

  // factor := [-|+] factor | atom [^ script]
  Node factor(std::size_t depth) {
    enter(depth, peek());
    if (is_char(peek(), '-') || is_char(peek(), '+')) {
      const Token sign = take();
      Node inner = factor(depth + 1);
      if (sign.text[0] == '+') {
        return inner;
      }
      Node negated = make(NodeKind::sum, sign.offset);
      negated.children.push_back(std::move(inner));
      negated.ops = "-";
      negated.end = last_end_;
      return negated;
    }
    Node base = atom(depth + 1);
    if (is_char(peek(), '^')) {
      const Token caret = take();
      Node exponent = script(depth + 1, caret);
      Node power = make(NodeKind::power, base.offset);
      power.children.push_back(std::move(base));
      power.children.push_back(std::move(exponent));
      power.end = last_end_;
      if (is_char(peek(), '^')) {
        throw error(peek(), "expected one exponent, found a second '^' (write {x^a}^b)");
      }
      if (is_char(peek(), '\'')) {
        throw error(peek(), "expected primes on a symbol before its exponent (p'^2)");
      }
      base = std::move(power);
    }
    while (bar_ahead()) {
      base = bar(depth, std::move(base));
    }
    return base;
  }

  // An evaluation bar X\Big|_a^b (or X|_{x=a}) after a factor: accepted beyond the contract.
  bool bar_ahead() {
    skip_spacing();
    std::size_t i = position_;
    if (tokens_[i].kind == Tok::command && sizes.contains(tokens_[i].text)) {
      ++i;
    } else if (abs_depth_ != 0) {
      return false;
    }
    return is_char(tokens_[i], '|') && is_char(tokens_[i + 1], '_');
  }

  Node bar(std::size_t depth, Node base) {
    if (peek_raw().kind == Tok::command) {
      take();  // \Big
    }
    take();  // |
    const Token underscore = take();
    Node n = make(NodeKind::bar, base.offset);
    n.children.push_back(std::move(base));
    std::optional<Node> variable;
    if (is_char(peek(), '{')) {
      const Token open = take();
      Node first = expression(depth + 1);
      if (is_char(peek(), '=')) {
        take();
        if (first.kind != NodeKind::symbol) {
          throw error_at(first.offset, "expected a symbol before '=' in the bar's subscript");
        }
        variable = std::move(first);
        first = expression(depth + 1);
      }
      expect_char('}', open, "bar's subscript");
      n.children.push_back(std::move(first));
    } else {
      n.children.push_back(script(depth + 1, underscore));
    }
    if (is_char(peek(), '^')) {
      const Token caret = take();
      n.children.push_back(script(depth + 1, caret));
      n.ops += 'u';
    }
    if (variable) {
      n.children.push_back(std::move(*variable));
      n.ops += 'v';
    }
    n.end = last_end_;
    return n;
  }

  // The argument of ^: a braced group, or one character or command.
  Node script(std::size_t depth, const Token& caret) {
    return argument(depth, caret, "an exponent after '^'");
  }

  // LaTeX takes one character from a number after ^ or _ : x^23 is x^2 times 3.
  Node single_digit(const Token& t) {
    Token& token = tokens_[position_];
    Node n = make(NodeKind::number, t.offset);
    n.text = token.text.substr(0, 1);
    n.end = t.offset + 1;
    if (token.text.size() == 1) {
      take();
    } else {
      token.text = token.text.substr(1);
      token.offset += 1;
      token.space_before = false;
      if (token.text[0] == '.') {
        throw error(token, "expected a digit after the exponent's digit, found '.'");
      }
    }
    last_end_ = n.end;
    return n;
  }

  bool starts_atom(const Token& t) const {
    switch (t.kind) {
      case Tok::number:
      case Tok::letter:
        return true;
      case Tok::character:
        return is_char(t, '(') || is_char(t, '[') || is_char(t, '{') ||
               (is_char(t, '|') && abs_depth_ == 0);
      case Tok::command:
        return greek.contains(t.text) || functions.contains(t.text) || fractions.contains(t.text) ||
               accents.contains(t.text) || modifiers.contains(t.text) || names.contains(t.text) ||
               sizes.contains(t.text) || t.text == "\\Delta" || t.text == "\\pi" ||
               t.text == "\\sqrt" || t.text == "\\det" || t.text == "\\left" ||
               t.text == "\\lVert" || t.text == "\\lvert" || t.text == "\\{" ||
               ((t.text == "\\|" || t.text == "\\Vert") && norm_depth_ == 0) ||
               (t.text == "\\vert" && abs_depth_ == 0);
      default:
        return false;
    }
  }

  Node atom(std::size_t depth) {
    enter(depth, peek());
    const Token& t = peek();
    switch (t.kind) {
      case Tok::number: {
        if (t.text.size() > limits_.number_digits) {
          throw error(t, "expected a number of at most " + std::to_string(limits_.number_digits) +
                             " characters (this checker's limit)");
        }
        const Token number = take();
        Node n = make(NodeKind::number, number.offset);
        n.text = number.text;
        return n;
      }
      case Tok::letter:
        return symbol_atom(depth);
      case Tok::character:
        return bracket(depth);
      case Tok::command:
        return command(depth);
      case Tok::end:
        throw error(t, "expected a term, found the end of the expression");
      default:
        throw error(t, "expected a term, found " + describe(t));
    }
  }

  Node bracket(std::size_t depth) {
    const Token open = take();
    if (is_char(open, '(')) {
      Node inner = group_inside(depth, open, ')');
      return inner;
    }
    if (is_char(open, '{')) {
      return group_inside(depth, open, '}');
    }
    if (is_char(open, '[')) {
      if (is_char(peek(), ']')) {
        throw error(peek(), "expected an expression or [x, y] inside the brackets");
      }
      Node first = expression(depth + 1);
      if (is_char(peek(), ',')) {
        take();
        Node second = expression(depth + 1);
        expect_char(']', open, "vector [x, y]");
        Node vec = make(NodeKind::vector, open.offset);
        vec.children.push_back(std::move(first));
        vec.children.push_back(std::move(second));
        return vec;
      }
      expect_char(']', open, "bracket");
      return first;
    }
    if (is_char(open, '|')) {
      ++abs_depth_;
      Node inner = expression(depth + 1);
      --abs_depth_;
      expect_char('|', open, "absolute value |…|");
      Node n = make(NodeKind::abs, open.offset);
      n.children.push_back(std::move(inner));
      return n;
    }
    if (is_char(open, '}')) {
      throw error(open, "expected a term, found '}' that closes no '{'");
    }
    if (is_char(open, ')') || is_char(open, ']')) {
      throw error(open, "expected a term, found " + describe(open) + " that closes nothing");
    }
    if (is_char(open, '=')) {
      throw error(open, "expected a term, found '='");
    }
    if (is_char(open, '_')) {
      throw error(open, "expected a symbol before the subscript '_'");
    }
    if (is_char(open, '\'')) {
      throw error(open, "expected a symbol before the prime");
    }
    if (is_char(open, '&')) {
      throw error(open, "expected a term, found '&'");
    }
    throw error(open, "expected a term, found " + describe(open));
  }

  Node group_inside(std::size_t depth, const Token& open, char close) {
    if (is_char(peek(), close)) {
      throw error(peek(),
                  "expected an expression inside " + describe(open) + "…" + std::string(1, close));
    }
    Node inner = expression(depth + 1);
    expect_char(close, open, close == '}' ? "group {…}" : "parenthesis");
    return inner;
  }

  // \left( … \right), \left[ … \right], \left| … \right|, \left\| … \right\|, \left. … \right…
  Node left_right(std::size_t depth) {
    const Token left = take();
    const Token open = take();
    std::string closer;
    NodeKind kind = NodeKind::sum;  // sum stands for "a plain group" here
    if (is_char(open, '(')) {
      closer = ")";
    } else if (is_char(open, '[')) {
      closer = "]";
    } else if (is_command(open, "\\{")) {
      closer = "\\}";
    } else if (is_char(open, '|') || is_command(open, "\\vert") || is_command(open, "\\lvert")) {
      closer = "|";
      kind = NodeKind::abs;
    } else if (is_command(open, "\\|") || is_command(open, "\\Vert") ||
               is_command(open, "\\lVert")) {
      closer = "\\|";
      kind = NodeKind::norm;
    } else if (is_char(open, '.')) {
      closer = "";
    } else {
      throw error(open,
                  "expected a delimiter after \\left ('(', '[', '|', '\\|', '\\{' or '.'), "
                  "found " +
                      describe(open));
    }
    if (kind == NodeKind::abs) {
      ++abs_depth_;
    }
    Node first = expression(depth + 1);
    Node second;
    bool pair = false;
    if (closer == "]" && is_char(peek(), ',')) {
      take();
      second = expression(depth + 1);
      pair = true;
    }
    if (kind == NodeKind::abs) {
      --abs_depth_;
    }
    if (!is_command(peek(), "\\right")) {
      throw error(peek(), "expected \\right to close the \\left at " + where(left) + ", found " +
                              describe(peek()));
    }
    take();
    const Token close = take();
    const bool matches =
        closer.empty() || is_char(close, '.') || (closer == ")" && is_char(close, ')')) ||
        (closer == "]" && is_char(close, ']')) || (closer == "\\}" && is_command(close, "\\}")) ||
        (closer == "|" &&
         (is_char(close, '|') || is_command(close, "\\vert") || is_command(close, "\\rvert"))) ||
        (closer == "\\|" &&
         (is_command(close, "\\|") || is_command(close, "\\Vert") || is_command(close, "\\rVert")));
    if (!matches) {
      throw error(close, "expected \\right" +
                             (closer.empty() ? std::string(" and a delimiter") : closer) +
                             " to match the \\left" + open.text + " at " + where(left) +
                             ", found " + describe(close));
    }
    if (pair) {
      Node vec = make(NodeKind::vector, left.offset);
      vec.children.push_back(std::move(first));
      vec.children.push_back(std::move(second));
      return vec;
    }
    if (kind == NodeKind::abs || kind == NodeKind::norm) {
      Node n = make(kind, left.offset);
      n.children.push_back(std::move(first));
      return n;
    }
    return first;
  }

  // A braced argument of a command or of ^ ({…}), or a single token (\frac12, x^2).
  Node argument(std::size_t depth, const Token& before, const std::string& what = "") {
    const Token& next = peek();
    if (is_char(next, '{')) {
      const Token open = take();
      return group_inside(depth, open, '}');
    }
    if (next.kind == Tok::number) {
      return single_digit(next);
    }
    if (next.kind == Tok::letter || (next.kind == Tok::command && greek.contains(next.text))) {
      return symbol_atom(depth);
    }
    throw error(next, "expected " + (what.empty() ? "an argument after " + before.text : what) +
                          " at " + where(before) + " (a digit, a letter or {…}), found " +
                          describe(next));
  }

  Node command(std::size_t depth) {
    const Token& t = peek();
    const std::string name = t.text;
    if (greek.contains(name) || name == "\\Delta" || accents.contains(name) ||
        modifiers.contains(name) || names.contains(name)) {
      return symbol_atom(depth);
    }
    if (name == "\\pi") {
      const Token pi = take();
      return make(NodeKind::pi, pi.offset);
    }
    if (fractions.contains(name)) {
      const Token frac = take();
      Node numerator = argument(depth + 1, frac);
      Node denominator = argument(depth + 1, frac);
      Node n = make(NodeKind::fraction, frac.offset);
      n.children.push_back(std::move(numerator));
      n.children.push_back(std::move(denominator));
      return n;
    }
    if (name == "\\sqrt") {
      const Token sqrt = take();
      std::optional<Node> index;
      if (is_char(peek(), '[')) {
        const Token open = take();
        index = expression(depth + 1);
        expect_char(']', open, "root index");
      }
      Node radicand = argument(depth + 1, sqrt);
      Node n = make(NodeKind::root, sqrt.offset);
      n.children.push_back(std::move(radicand));
      if (index) {
        n.children.push_back(std::move(*index));
      }
      return n;
    }
    if (functions.contains(name)) {
      return function(depth);
    }
    if (name == "\\det") {
      return determinant(depth);
    }
    if (name == "\\left") {
      return left_right(depth);
    }
    if (sizes.contains(name)) {
      take();
      const Token& delimiter = peek();
      if (!starts_atom(delimiter) && !is_char(delimiter, '|')) {
        throw error(delimiter,
                    "expected a delimiter after " + name + ", found " + describe(delimiter));
      }
      return atom(depth + 1);
    }
    if (name == "\\|" || name == "\\lVert" || name == "\\Vert") {
      const Token open = take();
      ++norm_depth_;
      Node inner = expression(depth + 1);
      --norm_depth_;
      const Token& close = peek();
      if (!(is_command(close, "\\|") || is_command(close, "\\rVert") ||
            is_command(close, "\\Vert"))) {
        throw error(close, "expected \\| to close the norm opened at " + where(open) + ", found " +
                               describe(close));
      }
      take();
      Node n = make(NodeKind::norm, open.offset);
      n.children.push_back(std::move(inner));
      return n;
    }
    if (name == "\\lvert" || name == "\\vert") {
      const Token open = take();
      ++abs_depth_;
      Node inner = expression(depth + 1);
      --abs_depth_;
      const Token& close = peek();
      if (!(is_command(close, "\\rvert") || is_command(close, "\\vert"))) {
        throw error(close, "expected \\rvert to close the absolute value opened at " + where(open) +
                               ", found " + describe(close));
      }
      take();
      Node n = make(NodeKind::abs, open.offset);
      n.children.push_back(std::move(inner));
      return n;
    }
    if (name == "\\{") {
      const Token open = take();
      Node inner = expression(depth + 1);
      if (!is_command(peek(), "\\}")) {
        throw error(peek(), "expected \\} to close the \\{ opened at " + where(open));
      }
      take();
      return inner;
    }
    if (relations.contains(name)) {
      throw error(
          t, "expected a term, found the relation " + name + " (this checker reads equations: =)");
    }
    if (name == "\\cdot" || name == "\\times" || name == "\\div") {
      throw error(t, "expected a term before " + name);
    }
    if (name == "\\right") {
      throw error(t, "expected a term, found \\right without its \\left");
    }
    if (name == "\\log") {
      throw error(t, "expected \\ln for the natural logarithm (\\log is ambiguous here)");
    }
    if (name == "\\pm" || name == "\\mp") {
      throw error(t, "expected + or - (" + name + " stands for two equations: write each)");
    }
    if (name == "\\sum" || name == "\\int") {
      return big(depth);
    }
    if (name == "\\prod" || name == "\\iint" || name == "\\oint") {
      throw error(t, "expected an expression without " + name +
                         " (products and multiple integrals are not read by this checker)");
    }
    if (name == "\\infty") {
      throw error(t, "expected a number or a symbol, found \\infty");
    }
    if (name == "\\text" || name == "\\mathrm") {
      return symbol_atom(depth);
    }
    throw error(t, "expected a command this checker reads, found the unknown command " + name +
                       " (the LaTeX read here: numbers, symbols, + - \\cdot \\times / ^, "
                       "\\frac, \\sqrt, \\sin, \\cos, \\tan, \\exp, \\ln, \\det, \\| \\|, "
                       "| |, \\left( \\right), \\vec)");
  }

  Node function(std::size_t depth) {
    const Token f = take();
    std::optional<Node> power;
    if (is_char(peek(), '^')) {
      const Token caret = take();
      power = script(depth + 1, caret);
    }
    Node argument_node;
    const Token& next = peek();
    if (is_char(next, '(') || is_char(next, '[') || is_char(next, '{') ||
        is_command(next, "\\left") || sizes.contains(next.text)) {
      argument_node = atom(depth + 1);
    } else if (next.kind == Tok::number || next.kind == Tok::letter ||
               (next.kind == Tok::command &&
                (greek.contains(next.text) || next.text == "\\Delta" || next.text == "\\pi" ||
                 accents.contains(next.text) || names.contains(next.text) ||
                 modifiers.contains(next.text) || fractions.contains(next.text)))) {
      // \sin 2\theta: the argument runs over the numbers and symbols that follow.
      Node product = make(NodeKind::product, next.offset);
      product.children.push_back(atom(depth + 1));
      product.ops += ' ';
      while (true) {
        const Token& more = peek();
        const bool simple = more.kind == Tok::number || more.kind == Tok::letter ||
                            (more.kind == Tok::command &&
                             (greek.contains(more.text) || more.text == "\\pi" ||
                              accents.contains(more.text) || names.contains(more.text)));
        if (!simple) {
          break;
        }
        product.children.push_back(atom(depth + 1));
        product.ops += ' ';
      }
      product.end = last_end_;
      argument_node =
          product.children.size() == 1 ? std::move(product.children[0]) : std::move(product);
    } else {
      throw error(next, "expected the argument of " + f.text + ", found " + describe(next));
    }
    Node n = make(NodeKind::function, f.offset);
    n.text = f.text.substr(1);
    n.children.push_back(std::move(argument_node));
    n.end = last_end_;
    if (power) {
      Node p = make(NodeKind::power, f.offset);
      p.children.push_back(std::move(n));
      p.children.push_back(std::move(*power));
      return p;
    }
    return n;
  }

  Node determinant(std::size_t depth) {
    const Token det = take();
    const Token& open = peek();
    bool left = false;
    if (is_command(open, "\\left")) {
      take();
      left = true;
      if (!is_char(peek(), '(')) {
        throw error(peek(), "expected \\left( after \\det");
      }
    } else if (!is_char(open, '(')) {
      throw error(open, "expected ( after \\det: \\det(\\vec a, \\vec b)");
    }
    const Token paren = take();
    Node a = expression(depth + 1);
    if (!is_char(peek(), ',')) {
      throw error(peek(), "expected ',' between the two vectors of \\det opened at " + where(det) +
                              ", found " + describe(peek()));
    }
    take();
    Node b = expression(depth + 1);
    if (left) {
      if (!is_command(peek(), "\\right")) {
        throw error(peek(), "expected \\right) to close \\det's \\left(");
      }
      take();
    }
    expect_char(')', paren, "\\det(…, …)");
    Node n = make(NodeKind::det, det.offset);
    n.children.push_back(std::move(a));
    n.children.push_back(std::move(b));
    return n;
  }

  // ---- symbols ----
  // A symbol: a letter, a Greek letter, \Delta X, \vec{x}, \bar{x}, \mathrm{name}, then an
  // optional subscript and primes in either order.
  Node symbol_atom(std::size_t depth) {
    enter(depth, peek());
    const Token first = peek();
    SymbolName name;
    if (is_command(first, "\\Delta")) {
      take();
      if (starts_symbol(peek())) {
        Node inner = symbol_atom(depth + 1);
        if (inner.kind != NodeKind::symbol || inner.symbol.delta) {
          throw error(first, "expected a symbol after \\Delta");
        }
        inner.symbol.delta = true;
        inner.offset = first.offset;
        return decorate(depth, std::move(inner));
      }
      name.base = "\\Delta";
    } else if (first.kind == Tok::letter) {
      take();
      name.base = first.text;
      // The letters dt, together, are one symbol (the collision's duration).
      if (first.text == "d" && peek_raw().kind == Tok::letter && peek_raw().text == "t" &&
          !peek_raw().space_before) {
        take();
        name.base = "dt";
      }
    } else if (first.kind == Tok::command && greek.contains(first.text)) {
      take();
      name.base = first.text;
    } else if (accents.contains(first.text)) {
      take();
      Node inner = argument(depth + 1, first);  // \vec{p}, \vec p, \vec{F dt}
      if (inner.kind == NodeKind::symbol) {
        inner.offset = first.offset;
        inner.symbol.accent = true;
        return decorate(depth, std::move(inner));
      }
      // An accent over an expression is a group; over a product (\vec{F dt}) its first symbol
      // carries the accent, which an `arrow:` letter needs (the paper's \vec{Fdt}).
      if (inner.kind == NodeKind::product && inner.children[0].kind == NodeKind::symbol) {
        inner.children[0].symbol.accent = true;
      }
      return inner;
    } else if (modifiers.contains(first.text)) {
      take();
      Node inner = argument(depth + 1, first);
      if (inner.kind != NodeKind::symbol || !inner.symbol.subscript.empty() ||
          inner.symbol.primes != 0 || inner.symbol.delta) {
        throw error(first, "expected a single letter under " + first.text);
      }
      name.base = first.text + "{" + inner.symbol.base + "}";
    } else if (names.contains(first.text)) {
      take();
      name.base = name_group(first);
      if (name.base == "d" && peek_raw().kind == Tok::letter && peek_raw().text == "t") {
        take();
        name.base = "dt";
      }
    } else {
      throw error(first, "expected a symbol, found " + describe(first));
    }
    Node n = make(NodeKind::symbol, first.offset);
    n.symbol = name;
    return decorate(depth, std::move(n));
  }

  bool starts_symbol(const Token& t) const {
    return t.kind == Tok::letter ||
           (t.kind == Tok::command && (greek.contains(t.text) || accents.contains(t.text) ||
                                       modifiers.contains(t.text) || names.contains(t.text)));
  }

  // The letters of \mathrm{…} or \text{…}: one name.
  std::string name_group(const Token& command_token) {
    if (!is_char(peek(), '{')) {
      throw error(peek(), "expected {name} after " + command_token.text);
    }
    const Token open = take();
    std::string text;
    while (true) {
      const Token& t = peek_raw();
      if (t.kind == Tok::letter || t.kind == Tok::number) {
        if (t.space_before && !text.empty()) {
          throw error(t, "expected one name in " + command_token.text +
                             "{…}, found words: prose belongs outside the display block");
        }
        text += t.text;
        take();
      } else if (is_char(t, '}')) {
        take();
        break;
      } else if (t.kind == Tok::end) {
        throw error(open, "expected '}' to close this '{'");
      } else {
        throw error(t, "expected letters and digits in " + command_token.text +
                           "{…} (a name), found " + describe(t));
      }
    }
    if (text.empty()) {
      throw error(open, "expected a name inside " + command_token.text + "{}");
    }
    return text;
  }

  // Subscript and primes after a symbol, in either order: p_1', p'_1, p_{1}'.
  Node decorate(std::size_t depth, Node n) {
    while (true) {
      const Token& t = peek_raw();
      if (is_char(t, '_')) {
        if (!n.symbol.subscript.empty()) {
          throw error(t, "expected one subscript, found a second '_'");
        }
        take();
        n.symbol.subscript = subscript(depth);
      } else if (is_char(t, '\'')) {
        take();
        ++n.symbol.primes;
      } else if (is_char(t, '^') && primes_follow()) {
        take();
        n.symbol.primes += read_prime_script();
      } else {
        break;
      }
    }
    n.end = last_end_;
    return n;
  }

  bool primes_follow() const {
    const Token& next = tokens_[position_ + 1];
    if (is_command(next, "\\prime")) {
      return true;
    }
    if (is_char(next, '{')) {
      std::size_t k = position_ + 2;
      bool any = false;
      while (is_command(tokens_[k], "\\prime") || tokens_[k].kind == Tok::spacing) {
        any = any || is_command(tokens_[k], "\\prime");
        ++k;
      }
      return any && is_char(tokens_[k], '}');
    }
    return false;
  }

  int read_prime_script() {
    if (is_command(peek_raw(), "\\prime")) {
      take();
      return 1;
    }
    take();  // {
    int count = 0;
    while (is_command(peek(), "\\prime")) {
      take();
      ++count;
    }
    take();  // }
    return count;
  }

  std::string subscript(std::size_t depth) {
    const Token& t = peek_raw();
    if (t.kind == Tok::letter) {
      return take().text;
    }
    if (t.kind == Tok::number) {
      return single_digit(t).text;
    }
    if (t.kind == Tok::command && greek.contains(t.text)) {
      return take().text;
    }
    if (!is_char(t, '{')) {
      throw error(
          t, "expected a subscript after '_' (a letter, a digit or {…}), found " + describe(t));
    }
    const Token open = take();
    std::string text;
    bool after_command = false;
    while (true) {
      const Token& s = peek();
      if (s.kind == Tok::letter || s.kind == Tok::number) {
        if (after_command) {
          text += ' ';
        }
        text += take().text;
        after_command = false;
      } else if (s.kind == Tok::command && greek.contains(s.text)) {
        text += take().text;
        after_command = true;
      } else if (s.kind == Tok::command && names.contains(s.text)) {
        const Token command_token = take();
        if (after_command) {
          text += ' ';
        }
        text += name_group(command_token);
        after_command = false;
      } else if (is_char(s, ',') || is_char(s, '(') || is_char(s, ')')) {
        // a_{vi(elastic)}: the paper's names of its coefficients carry a word in parentheses
        text += take().text;
        after_command = false;
      } else if (is_char(s, '}')) {
        take();
        break;
      } else if (s.kind == Tok::end) {
        throw error(open, "expected '}' to close the subscript opened here");
      } else {
        throw error(s, "expected letters and digits in the subscript, found " + describe(s));
      }
    }
    (void)depth;
    if (text.empty()) {
      throw error(open, "expected a subscript inside the braces");
    }
    return text;
  }

  const Source& source_;
  std::vector<Token> tokens_;
  const Limits& limits_;
  std::size_t position_ = 0;
  std::size_t last_end_ = 0;
  int abs_depth_ = 0;   // inside |…|: a '|' closes
  int norm_depth_ = 0;  // inside \|…\|: a '\|' closes
};

// ---- a display block: environments, rows, tags, sides ------------------------------------------

struct RowTokens {
  std::vector<Token> tokens;
  std::optional<std::string> tag;
  std::optional<std::string> label;
  std::size_t offset = 0;
};

std::string environment_name(const Source& source, std::vector<Token>& tokens, std::size_t& i) {
  const Token& command = tokens[i];
  ++i;
  while (tokens[i].kind == Tok::spacing) {
    ++i;
  }
  if (!is_char(tokens[i], '{')) {
    throw source.error(tokens[i].offset, "expected {name} after " + command.text);
  }
  const std::size_t open = tokens[i].offset;
  ++i;
  std::string name;
  while (tokens[i].kind == Tok::letter || is_char(tokens[i], '*')) {
    name += tokens[i].text;
    ++i;
  }
  if (!is_char(tokens[i], '}')) {
    throw source.error(open, "expected '}' to close the environment's name");
  }
  ++i;
  return name;
}

// Removes \begin{…} and \end{…} of the environments that only arrange equations, checking that
// they pair up.
std::vector<Token> strip_environments(const Source& source, std::vector<Token> tokens) {
  std::vector<Token> kept;
  std::vector<std::pair<std::string, std::size_t>> open;
  for (std::size_t i = 0; i < tokens.size();) {
    const Token& t = tokens[i];
    if (is_command(t, "\\begin")) {
      const std::size_t at = t.offset;
      const std::string name = environment_name(source, tokens, i);
      if (!environments.contains(name)) {
        throw source.error(at,
                           "expected an environment that arranges equations (aligned, "
                           "align*, split, gathered, cases, equation), found {" +
                               name + "}");
      }
      // Optional arguments: aligned[t], alignat{2}.
      if (is_char(tokens[i], '[')) {
        while (tokens[i].kind != Tok::end && !is_char(tokens[i], ']')) {
          ++i;
        }
        if (tokens[i].kind == Tok::end) {
          throw source.error(at, "expected ']' to close the environment's option");
        }
        ++i;
      }
      if (name.starts_with("alignat") && is_char(tokens[i], '{')) {
        while (tokens[i].kind != Tok::end && !is_char(tokens[i], '}')) {
          ++i;
        }
        ++i;
      }
      open.emplace_back(name, at);
      continue;
    }
    if (is_command(t, "\\end")) {
      const std::size_t at = t.offset;
      const std::string name = environment_name(source, tokens, i);
      if (open.empty()) {
        throw source.error(at, "expected no \\end{" + name + "}: no environment is open");
      }
      if (open.back().first != name) {
        throw source.error(at, "expected \\end{" + open.back().first + "} to close the \\begin{" +
                                   open.back().first + "} at " +
                                   std::to_string(source.place(open.back().second).line) + ":" +
                                   std::to_string(source.place(open.back().second).column) +
                                   ", found \\end{" + name + "}");
      }
      open.pop_back();
      continue;
    }
    kept.push_back(t);
    ++i;
  }
  if (!open.empty()) {
    throw source.error(open.back().second,
                       "expected \\end{" + open.back().first + "} to close this environment");
  }
  return kept;
}

// Checks that braces pair up in the whole block, so that an unbalanced brace is reported where
// it stands, not where a row happens to end.
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

std::vector<RowTokens> split_rows(const Source& source, const std::vector<Token>& tokens) {
  std::vector<RowTokens> rows(1);
  int braces = 0;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Tok::end) {
      break;
    }
    braces += is_char(t, '{') ? 1 : is_char(t, '}') ? -1 : 0;
    if (is_command(t, "\\\\") && braces == 0) {
      // \\[2pt]: the optional spacing belongs to the line break.
      if (i + 1 < tokens.size() && is_char(tokens[i + 1], '[')) {
        std::size_t k = i + 1;
        while (tokens[k].kind != Tok::end && !is_char(tokens[k], ']')) {
          ++k;
        }
        if (tokens[k].kind != Tok::end) {
          i = k;
        }
      }
      rows.emplace_back();
      continue;
    }
    if (is_char(t, '&')) {
      continue;
    }
    if (is_command(t, "\\tag")) {
      std::size_t k = i + 1;
      if (is_char(tokens[k], '*')) {
        ++k;
      }
      if (!is_char(tokens[k], '{')) {
        throw source.error(t.offset, "expected \\tag{label}");
      }
      const std::size_t open = tokens[k].offset;
      std::size_t close = k + 1;
      while (tokens[close].kind != Tok::end && !is_char(tokens[close], '}')) {
        ++close;
      }
      if (tokens[close].kind == Tok::end) {
        throw source.error(open, "expected '}' to close the tag");
      }
      std::string label(source.text().substr(open + 1, tokens[close].offset - open - 1));
      while (!label.empty() && label.back() == ' ') {
        label.pop_back();
      }
      while (!label.empty() && label.front() == ' ') {
        label.erase(label.begin());
      }
      if (label.empty()) {
        throw source.error(open, "expected a label inside \\tag{}");
      }
      if (rows.back().tag) {
        throw source.error(t.offset, "expected one \\tag per row, found a second");
      }
      rows.back().tag = label;
      i = close;
      continue;
    }
    if (is_command(t, "\\label")) {
      std::size_t close = i + 1;
      while (tokens[close].kind != Tok::end && !is_char(tokens[close], '}')) {
        ++close;
      }
      if (is_char(tokens[i + 1], '{') && tokens[close].kind != Tok::end) {
        std::string label(source.text().substr(tokens[i + 1].offset + 1,
                                               tokens[close].offset - tokens[i + 1].offset - 1));
        while (!label.empty() && label.back() == ' ') {
          label.pop_back();
        }
        while (!label.empty() && label.front() == ' ') {
          label.erase(label.begin());
        }
        if (!label.empty()) {
          rows.back().label = label;
        }
      }
      i = close;
      continue;
    }
    if (is_command(t, "\\nonumber") || is_command(t, "\\notag")) {
      continue;
    }
    if (rows.back().tokens.empty() && t.kind != Tok::spacing) {
      rows.back().offset = t.offset;
    }
    rows.back().tokens.push_back(t);
  }
  // Rows of spacing alone are nothing; trailing punctuation ends a sentence, not an equation.
  std::vector<RowTokens> kept;
  for (RowTokens& row : rows) {
    while (!row.tokens.empty() &&
           (row.tokens.back().kind == Tok::spacing || is_char(row.tokens.back(), ',') ||
            is_char(row.tokens.back(), '.') || is_char(row.tokens.back(), ';'))) {
      row.tokens.pop_back();
    }
    if (row.tokens.empty()) {
      if (row.tag) {
        throw source.error(source.text().size(), "expected an equation with the \\tag");
      }
      continue;
    }
    kept.push_back(std::move(row));
  }
  return kept;
}

// Which tokens stand outside every group: braces, parentheses, brackets and \left … \right
// (whose delimiters belong to them).
std::vector<bool> top_level(const std::vector<Token>& tokens) {
  std::vector<bool> top(tokens.size(), false);
  int depth = 0;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (is_command(t, "\\left") || is_command(t, "\\right")) {
      depth += is_command(t, "\\left") ? 1 : -1;
      if (i + 1 < tokens.size()) {
        ++i;  // the delimiter
      }
      continue;
    }
    if (is_char(t, '}') || is_char(t, ')') || is_char(t, ']')) {
      --depth;
      continue;
    }
    if (is_char(t, '{') || is_char(t, '(') || is_char(t, '[')) {
      ++depth;
      continue;
    }
    top[i] = depth <= 0;
  }
  return top;
}

Side parse_side(const Source& source, std::vector<Token> tokens, std::size_t fallback_offset,
                const Limits& limits) {
  Side side;
  std::size_t first = 0;
  while (first < tokens.size() && tokens[first].kind == Tok::spacing) {
    ++first;
  }
  side.offset = first < tokens.size() ? tokens[first].offset : fallback_offset;
  side.latex = join(tokens);
  Token end;
  end.offset = end.end = tokens.empty() ? fallback_offset : tokens.back().end;
  tokens.push_back(end);
  side.expression = Parser(source, std::move(tokens), limits).whole_expression();
  return side;
}

}  // namespace

std::vector<Row> read_block(const Source& source, std::size_t content_offset,
                            std::string_view content, const Limits& limits) {
  std::vector<Token> tokens = Tokenizer(source, content_offset, content).run();
  check_braces(source, tokens);
  tokens = strip_environments(source, std::move(tokens));
  std::vector<RowTokens> token_rows = split_rows(source, tokens);
  if (token_rows.empty()) {
    throw source.error(content_offset > 2 ? content_offset - 2 : 0,
                       "expected an equation in the display block, found nothing");
  }

  // A row without '=' that begins with + or - continues the last side of the row before.
  std::vector<RowTokens> merged;
  for (RowTokens& row : token_rows) {
    bool has_equals = false;
    const std::vector<bool> top = top_level(row.tokens);
    for (std::size_t k = 0; k < row.tokens.size(); ++k) {
      const Token& t = row.tokens[k];
      if (top[k] && (is_char(t, '=') || is_char(t, '<') || is_char(t, '>') ||
                     (t.kind == Tok::command && relations.contains(t.text)))) {
        has_equals = true;
      }
    }
    const Token& first = *std::find_if(row.tokens.begin(), row.tokens.end(),
                                       [](const Token& t) { return t.kind != Tok::spacing; });
    if (!has_equals && !merged.empty() && (is_char(first, '+') || is_char(first, '-'))) {
      merged.back().tokens.insert(merged.back().tokens.end(), row.tokens.begin(), row.tokens.end());
      if (row.tag) {
        if (merged.back().tag) {
          throw source.error(row.offset, "expected one \\tag per equation, found a second");
        }
        merged.back().tag = row.tag;
      }
      if (row.label) {
        merged.back().label = row.label;
      }
      continue;
    }
    if (!has_equals) {
      throw source.error(row.offset,
                         "expected an equation (… = …), found an expression without '='");
    }
    merged.push_back(std::move(row));
  }

  std::vector<Row> rows;
  for (RowTokens& row_tokens : merged) {
    Row row;
    row.tag = row_tokens.tag;
    row.label = row_tokens.label;
    row.offset = row_tokens.offset;
    std::vector<std::vector<Token>> sides(1);
    const std::vector<bool> top = top_level(row_tokens.tokens);
    for (std::size_t k = 0; k < row_tokens.tokens.size(); ++k) {
      const Token& t = row_tokens.tokens[k];
      if (top[k] && (is_char(t, '<') || is_char(t, '>') ||
                     (t.kind == Tok::command && relations.contains(t.text)))) {
        throw source.error(t.offset, "expected '=', found the relation " + t.text +
                                         ": this checker reads equations (facts such as x > 0 "
                                         "go in an assume: line)");
      }
      if (top[k] && is_char(t, '=')) {
        sides.emplace_back();
        continue;
      }
      sides.back().push_back(t);
    }
    const bool first_empty = std::all_of(sides[0].begin(), sides[0].end(),
                                         [](const Token& t) { return t.kind == Tok::spacing; });
    row.continues = first_empty;
    for (std::size_t k = 0; k < sides.size(); ++k) {
      if (k == 0 && row.continues) {
        Side empty;
        empty.offset = row.offset;
        row.sides.push_back(std::move(empty));
        continue;
      }
      const bool empty_side = std::all_of(sides[k].begin(), sides[k].end(),
                                          [](const Token& t) { return t.kind == Tok::spacing; });
      if (empty_side) {
        const std::size_t at = sides[k].empty() ? row.offset : sides[k].front().offset;
        throw source.error(
            at, k == 0 ? "expected an expression before '='" : "expected an expression after '='");
      }
      row.sides.push_back(parse_side(source, std::move(sides[k]), row.offset, limits));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

namespace {

bool is_relation_token(const Token& t) {
  return is_char(t, '=') || is_char(t, '<') || is_char(t, '>') ||
         (t.kind == Tok::command &&
          (t.text == "\\le" || t.text == "\\leq" || t.text == "\\leqslant" || t.text == "\\ge" ||
           t.text == "\\geq" || t.text == "\\geqslant" || t.text == "\\neq" || t.text == "\\ne" ||
           t.text == "\\lt" || t.text == "\\gt" || t.text == "\\in"));
}

Relation::Kind relation_kind(const Token& t) {
  using K = Relation::Kind;
  if (is_char(t, '=')) {
    return K::equal;
  }
  if (is_char(t, '<') || is_command(t, "\\lt")) {
    return K::less;
  }
  if (is_char(t, '>') || is_command(t, "\\gt")) {
    return K::greater;
  }
  if (is_command(t, "\\neq") || is_command(t, "\\ne")) {
    return K::not_equal;
  }
  if (is_command(t, "\\in")) {
    return K::in_range;
  }
  if (t.text.starts_with("\\le")) {
    return K::less_equal;
  }
  return K::greater_equal;
}

// Depth of every token, counting braces, parentheses, brackets, \{ \} and \left … \right.
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
                                          std::vector<Token>* separators = nullptr) {
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

bool blank_tokens(const std::vector<Token>& tokens) {
  return std::all_of(tokens.begin(), tokens.end(),
                     [](const Token& t) { return t.kind == Tok::spacing; });
}

std::size_t first_offset(const std::vector<Token>& tokens, std::size_t fallback) {
  for (const Token& t : tokens) {
    if (t.kind != Tok::spacing) {
      return t.offset;
    }
  }
  return fallback;
}

std::vector<Token> trimmed_tokens(std::vector<Token> tokens) {
  while (!tokens.empty() && tokens.back().kind == Tok::spacing) {
    tokens.pop_back();
  }
  std::size_t i = 0;
  while (i < tokens.size() && tokens[i].kind == Tok::spacing) {
    ++i;
  }
  tokens.erase(tokens.begin(), tokens.begin() + static_cast<std::ptrdiff_t>(i));
  return tokens;
}

// The right side of \in: (a, b), [a, b], (a, \infty) or \{a, b, …\}.
void read_membership(const Source& source, std::vector<Token> tokens, std::size_t at, Relation& r,
                     const Limits& limits) {
  tokens = trimmed_tokens(std::move(tokens));
  if (tokens.size() >= 2 && is_command(tokens.front(), "\\left")) {
    tokens.erase(tokens.begin());
  }
  if (tokens.size() >= 2 && is_command(tokens[tokens.size() - 2], "\\right")) {
    tokens.erase(tokens.end() - 2);
  }
  if (tokens.size() < 3) {
    throw source.error(at, "expected an interval (a, b) or a set \\{a, b\\} after \\in");
  }
  const Token open = tokens.front();
  const Token close = tokens.back();
  std::vector<Token> inside(tokens.begin() + 1, tokens.end() - 1);
  std::vector<std::vector<Token>> parts =
      split_top(inside, [](const Token& t) { return is_char(t, ','); });
  const auto side = [&](std::vector<Token> part) {
    if (blank_tokens(part)) {
      throw source.error(open.offset, "expected a value between the commas after \\in");
    }
    return parse_side(source, std::move(part), open.offset, limits);
  };
  if (is_command(open, "\\{")) {
    if (!is_command(close, "\\}")) {
      throw source.error(close.offset, "expected \\} to close the set after \\in");
    }
    r.kind = Relation::Kind::in_set;
    for (auto& part : parts) {
      r.members.push_back(side(std::move(part)));
    }
    return;
  }
  if (!(is_char(open, '(') || is_char(open, '[')) ||
      !(is_char(close, ')') || is_char(close, ']')) || parts.size() != 2) {
    throw source.error(open.offset,
                       "expected an interval (a, b), [a, b] or (a, \\infty) after \\in");
  }
  r.kind = Relation::Kind::in_range;
  r.low_closed = is_char(open, '[');
  r.high_closed = is_char(close, ']');
  const auto infinite = [](const std::vector<Token>& part, bool negative) {
    std::vector<Token> t = trimmed_tokens(part);
    if (negative) {
      return t.size() == 2 && is_char(t[0], '-') && is_command(t[1], "\\infty");
    }
    return (t.size() == 1 && is_command(t[0], "\\infty")) ||
           (t.size() == 2 && is_char(t[0], '+') && is_command(t[1], "\\infty"));
  };
  if (!infinite(parts[0], true)) {
    r.low = side(std::move(parts[0]));
  }
  if (!infinite(parts[1], false)) {
    r.high = side(std::move(parts[1]));
  }
}

std::vector<Relation> read_relations(const Source& source, const std::vector<Token>& tokens,
                                     std::size_t fallback, const Limits& limits) {
  std::vector<Relation> found;
  for (std::vector<Token>& chain :
       split_top(tokens, [](const Token& t) { return is_char(t, ','); })) {
    std::vector<Token> marks;
    std::vector<std::vector<Token>> sides = split_top(chain, is_relation_token, &marks);
    const std::size_t at = first_offset(chain, fallback);
    if (marks.empty()) {
      throw source.error(at, "expected a relation (=, \\neq, <, >, \\leq, \\geq, \\in)");
    }
    for (std::size_t k = 0; k < marks.size(); ++k) {
      if (blank_tokens(sides[k]) || blank_tokens(sides[k + 1])) {
        throw source.error(marks[k].offset,
                           "expected an expression on both sides of " + describe(marks[k]));
      }
      Relation r;
      r.offset = marks[k].offset;
      r.kind = relation_kind(marks[k]);
      r.left = parse_side(source, sides[k], at, limits);
      if (r.kind == Relation::Kind::in_range) {
        if (k + 1 != marks.size()) {
          throw source.error(marks[k + 1].offset,
                             "expected nothing after the set or interval of "
                             "\\in");
        }
        read_membership(source, sides[k + 1], marks[k].offset, r, limits);
      } else {
        r.right = parse_side(source, sides[k + 1], marks[k].offset, limits);
      }
      found.push_back(std::move(r));
    }
  }
  return found;
}

}  // namespace

std::vector<ClaimRow> read_claim_block(const Source& source, std::size_t content_offset,
                                       std::string_view content, const Limits& limits) {
  std::vector<Token> tokens = Tokenizer(source, content_offset, content).run();
  check_braces(source, tokens);
  tokens = strip_environments(source, std::move(tokens));
  std::vector<ClaimRow> rows;
  for (RowTokens& row_tokens : split_rows(source, tokens)) {
    if (row_tokens.tag) {
      throw source.error(row_tokens.offset,
                         "expected a claim without \\tag (claims are "
                         "unnumbered)");
    }
    ClaimRow row;
    row.offset = row_tokens.offset;
    std::vector<Token> body = trimmed_tokens(row_tokens.tokens);
    row.latex = join(body);
    if (!body.empty() && is_command(body.front(), "\\exists")) {
      row.exists = true;
      body.erase(body.begin());
    }
    std::vector<Token> arrows;
    std::vector<std::vector<Token>> parts = split_top(
        body,
        [](const Token& t) {
          return is_command(t, "\\Rightarrow") || is_command(t, "\\implies") ||
                 is_command(t, "\\Longrightarrow");
        },
        &arrows);
    if (parts.size() > 2) {
      throw source.error(arrows[1].offset, "expected one \\Rightarrow in a claim's row");
    }
    if (parts.size() == 2) {
      if (row.exists) {
        throw source.error(row.offset, "expected \\exists or \\Rightarrow, not both");
      }
      row.hypotheses = read_relations(source, parts[0], row.offset, limits);
    }
    row.conclusions = read_relations(source, parts.back(), row.offset, limits);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) {
    throw source.error(content_offset, "expected a claim in the display block, found nothing");
  }
  return rows;
}

Side read_expression(const Source& source, std::size_t offset, std::string_view text,
                     const Limits& limits) {
  std::vector<Token> tokens = Tokenizer(source, offset, text).run();
  check_braces(source, tokens);
  tokens.pop_back();  // the end token; parse_side adds its own
  for (const Token& t : tokens) {
    if (is_char(t, '=') || is_char(t, '&') || is_command(t, "\\\\")) {
      throw source.error(t.offset, "expected one expression, found " + describe(t));
    }
  }
  if (tokens.empty()) {
    throw source.error(offset, "expected an expression");
  }
  return parse_side(source, std::move(tokens), offset, limits);
}

SymbolName read_symbol(const Source& source, std::size_t offset, std::string_view text,
                       const Limits& limits) {
  std::vector<Token> tokens = Tokenizer(source, offset, text).run();
  check_braces(source, tokens);
  return Parser(source, std::move(tokens), limits).whole_symbol();
}

SymbolName read_symbol_or_differential(const Source& source, std::size_t offset,
                                       std::string_view text, const Limits& limits) {
  constexpr std::string_view d = "\\mathrm{d}";
  if (!text.starts_with(d) || text.size() == d.size()) {
    return read_symbol(source, offset, text, limits);
  }
  SymbolName name = read_symbol(source, offset + d.size(), text.substr(d.size()), limits);
  if (name.differential || name.delta) {
    throw source.error(offset, "expected one symbol after \\mathrm{d}");
  }
  name.differential = true;
  return name;
}

}  // namespace impulse::derivations::file
