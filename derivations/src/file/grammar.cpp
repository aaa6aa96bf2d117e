// SPDX-License-Identifier: GPL-3.0-or-later
// The grammar's entry points, its access to tokens, and the productions of sums, products,
// factors, powers and evaluation bars.
#include "file/grammar.hpp"

#include <algorithm>
#include <set>

namespace impulse::derivations::file {

// whole := expression end
Node Grammar::whole_expression() {
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

// whole-symbol := symbol end
SymbolName Grammar::whole_symbol() {
  skip_spacing();
  const Token& first = peek();
  if (!starts_symbol(first) && !is_command(first, "\\Delta")) {
    throw error(first, "expected a symbol (a letter with an optional subscript and primes)");
  }
  Node node = symbol_atom(0);
  if (node.kind != NodeKind::symbol) {
    throw error(first, "expected a symbol (a letter with an optional subscript and primes)");
  }
  skip_spacing();
  if (peek().kind != Tok::end) {
    throw error(peek(), "expected one symbol, found more after it: " + describe(peek()));
  }
  return node.symbol;
}

// ---- token access ------------------------------------------------------------------------------

const Token& Grammar::peek() {
  skip_spacing();
  return tokens_[position_];
}

const Token& Grammar::ahead(std::size_t k) const {
  return token(position_ + k);
}

Token Grammar::take() {
  skip_spacing();
  Token t = tokens_[position_];
  if (t.kind != Tok::end) {
    ++position_;
  }
  last_end_ = t.end;
  return t;
}

void Grammar::skip_spacing() {
  while (tokens_[position_].kind == Tok::spacing) {
    ++position_;
  }
}

void Grammar::expect_char(char c, const Token& opener, const std::string& what) {
  if (!is_char(peek(), c)) {
    throw error(peek(), "expected '" + std::string(1, c) + "' to close the " + what +
                            " opened at " + where(opener) + ", found " + describe(peek()));
  }
  take();
}

std::string Grammar::where(const Token& t) const {
  const Place p = source_.place(t.offset);
  return "line " + std::to_string(p.line) + ", column " + std::to_string(p.column);
}

void Grammar::enter(std::size_t depth, const Token& at) const {
  if (depth > limits_.nesting) {
    throw error(at, "expected at most " + std::to_string(limits_.nesting) +
                        " levels of nesting (this checker's limit)");
  }
}

Node Grammar::make(NodeKind kind, std::size_t offset) const {
  Node n;
  n.kind = kind;
  n.offset = offset;
  n.end = last_end_;
  return n;
}

// ---- sums --------------------------------------------------------------------------------------

// expression := ['+' | '-'] sum-term { ('+' | '-' | '\oplus') sum-term }
Node Grammar::expression(std::size_t depth) {
  enter(depth, peek());
  // A group inside a function's bare argument is read whole: \sin x (a \cos b).
  const int outer_bare = bare_argument_;
  bare_argument_ = 0;
  struct Restore {
    int& value;
    int saved;
    ~Restore() { value = saved; }
  } restore{bare_argument_, outer_bare};
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
    refuse_bar_after_sum(sum);
  }
  if (is_command(peek(), "\\pm") || is_command(peek(), "\\mp")) {
    refused_command(peek());  // between terms too (v_0 \pm \sqrt{…}): two equations, not a '}'
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

// sum-term := '\cdots' | term
Node Grammar::sum_term(std::size_t depth) {
  const Token& t = peek();
  if (is_command(t, "\\cdots") || is_command(t, "\\dots") || is_command(t, "\\ldots") ||
      is_command(t, "\\dotsb")) {
    const Token dots = take();
    return make(NodeKind::dots, dots.offset);
  }
  return term(depth);
}

// ---- products ----------------------------------------------------------------------------------

bool Grammar::big_operator(const Token& t) {
  return is_command(t, "\\sum") || is_command(t, "\\int") || is_command(t, "\\prod");
}

bool Grammar::explicit_product(const Token& t) const {
  return is_command(t, "\\cdot") || is_command(t, "\\times") || is_char(t, '*') ||
         is_char(t, '/') || is_command(t, "\\div") || is_command(t, "\\ast");
}

// The refusal of a function's bare argument that would run on at @p at (the factor, or the
// operator before it), with the two readings in the writer's own text: "write \sin(\theta d) for
// the one, (\sin\theta) d for the other". The factor is read ahead to find where it ends; where
// that fails, or the texts are long, the readings are shown on \cos\theta and d.
ReadError Grammar::runs_on(const Token& at, const std::string& past) {
  const std::string& text = source_.text();
  const std::size_t argument_end = last_end_;
  std::string readings = "\\cos(\\theta d) for the one, (\\cos\\theta) d or d \\cos\\theta";
  try {
    std::string op;
    if (explicit_product(at)) {
      op = take().text + " ";
    }
    const std::size_t factor_start = peek().offset;
    (void)factor(0);
    const Token& f = bare_functions_.back();
    const std::string written = text.substr(f.offset, argument_end - f.offset);
    const std::string argument = trimmed(text.substr(f.end, argument_end - f.end));
    const std::string name = text.substr(f.offset, f.end - f.offset);
    const std::string after = trimmed(text.substr(factor_start, last_end_ - factor_start));
    if (written.size() + after.size() <= 60 && !argument.empty() && !after.empty()) {
      const bool division = is_char(at, '/') || is_command(at, "\\div");
      readings = name + "(" + argument + " " + op + after + ") for the one, (" + written + ") " +
                 op + after + (division ? "" : " or " + after + " " + written);
    }
  } catch (const std::exception&) {
    // the factor could not be read ahead: the readings on an example
  }
  return error(at,
               "expected parentheses around the argument of a function: written without them, "
               "it would run on " +
                   past + "; write " + readings + " for the other");
}

// term := big | factor { [product-op] factor } [big]
// product-op := '\cdot' | '\times' | '*' | '/' | '\div' | '\ast'
// (factors side by side multiply; a big operator takes the rest of the term; inside a
// function's argument written without parentheses, the term stops before the next function)
Node Grammar::term(std::size_t depth) {
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
    if (bare_argument_ > 0 && in(next, commands::functions)) {
      break;  // \sin a \cos b: the argument of \sin ends before \cos
    }
    if (bare_argument_ > 0 && integrand_ > 0 && differential_ahead()) {
      break;  // \int \sin \omega t \, dt: the argument ends before the differential
    }
    if (bare_argument_ > 0 &&
        (explicit_product(next) ||
         (starts_atom(next) && position_ > 0 && tokens_[position_ - 1].kind == Tok::spacing))) {
      // F \cos\theta \cdot d was cos(θ d), \sin\theta/2 sin(θ/2), v_0 \cos\theta\, t_f
      // cos(θ t_f): the writer may have meant the factor outside.
      throw runs_on(next, "past " +
                              describe(explicit_product(next) ? next : tokens_[position_ - 1]) +
                              ", where the factor after may be meant outside");
    }
    if (bare_argument_ > 0 &&
        (is_char(next, '(') || is_char(next, '[') || is_command(next, "\\left") ||
         (in(next, commands::sizes) && starts_atom(next)))) {
      // \cos\theta(v_1 + v_2) was cos(θ (v_1 + v_2)), and \sin\theta (1 + 1) sin 2θ: the
      // writer meant the group outside.
      throw error(next, std::string(runs_into_group));
    }
    if (bare_argument_ > 0 && runs_into_factor(next)) {
      throw runs_on(next, "into " + describe(next) + ", which may be meant outside");
    }
    if (big_operator(next)) {
      if (bare_argument_ > 0) {
        break;
      }
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
      if (is_char(next, '|') && product.children.size() >= 2 &&
          product.children.back().kind != NodeKind::abs &&
          std::any_of(product.children.begin(), product.children.end(),
                      [](const Node& f) { return f.kind == NodeKind::abs; })) {
        // |a|b|c|: |a| b |c|, or |a |b| c|?
        throw error(next,
                    "expected \\left| … \\right| or parentheses: the bars of |a|b|c| pair as "
                    "|a| b |c| or as |a |b| c|");
      }
      if (next.kind == Tok::number && !product.children.empty() &&
          (product.children.back().kind == NodeKind::number ||
           product.children.back().kind == NodeKind::fraction)) {
        // \dfrac 12 3: a half times 3, or twelve thirds?
        throw error(next, "expected an operator between two numbers (write \\cdot or \\times)");
      }
      refuse_number_after_symbol(product, next);
      refuse_written_unit(product, next);
      const Token written = next;
      product.children.push_back(factor(depth + 1));
      product.ops += ' ';
      refuse_mixed_number(product, written);
      refuse_ambiguous_division(product, written);
      refuse_unit(product, written);
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

// m1, v0, m_1 2: a number right after a symbol. m1 v1 = m2 v2 read as m·1 v·1 = m·2 v·2 let a
// slip through (v2 = m2 v1/m1 "followed"), and v = v0 + a t lost v_0: m_1, or m times 1?
void Grammar::refuse_number_after_symbol(const Node& product, const Token& next) const {
  if (next.kind != Tok::number || product.children.empty() ||
      product.children.back().kind != NodeKind::symbol) {
    return;
  }
  const SymbolName& symbol = product.children.back().symbol;
  const std::string name = symbol.latex();
  if (symbol.subscript.empty()) {
    throw error(next, "expected an operator or a subscript between " + name + " and " + next.text +
                          ": " + name + next.text + " could be " + name + "_" + next.text + " or " +
                          name + " times " + next.text + "; write " + name + "_" + next.text +
                          " for the one, " + next.text + " " + name + " for the other");
  }
  throw error(next, "expected an operator between " + name + " and " + next.text + ": write " +
                        next.text + " " + name +
                        " for the product (or braces around a subscript of several characters, "
                        "m_{12})");
}

// a / b c: a over b times c, or a over b c? Refused unless it is a number over a number (1/2 m v^2)
// or what follows is a differential (F/m dt).
void Grammar::refuse_ambiguous_division(const Node& product, const Token& written) const {
  const std::size_t n = product.children.size();
  if (n < 3 || product.ops[n - 2] != '/') {
    return;
  }
  const auto number = [](const Node& x) { return x.kind == NodeKind::number; };
  const Node& after = product.children[n - 1];
  const bool differential =
      after.kind == NodeKind::symbol &&
      (after.symbol.base == "dt" || after.symbol.differential || after.text == upright_d);
  if (number(product.children[n - 3]) && number(product.children[n - 2]) &&
      after.kind == NodeKind::pi) {
    // f = 1/2\pi: one over 2π, as in f = ω/2π, or π/2, as 1/2 m v^2 is ½ m v²?
    throw error(written,
                "expected \\frac after a division before \\pi: 1/2\\pi could be one over 2π or "
                "π over 2; write \\frac{1}{2\\pi} or \\frac{\\pi}{2}");
  }
  if ((number(product.children[n - 3]) && number(product.children[n - 2])) || differential) {
    return;
  }
  throw error(written,
              "expected an operator or \\frac after a division: a/b c could be a over b, times c, "
              "or a over b c; write \\frac{a}{b} c or \\frac{a}{b c} (or a/(b c))");
}

// 2\frac{1}{2}: the mixed number 2½ as a student writes it, or 2 times ½ as part one reads
// juxtaposition (a = 2\frac{1}{2} then a = 1 followed)? Refused when a number stands right before
// a fraction of two numbers.
void Grammar::refuse_mixed_number(const Node& product, const Token& written) const {
  const std::size_t n = product.children.size();
  if (n < 2 || product.children[n - 2].kind != NodeKind::number || product.ops[n - 1] != ' ') {
    return;
  }
  const Node& after = product.children[n - 1];
  if (after.kind == NodeKind::fraction && after.children[0].kind == NodeKind::number &&
      after.children[1].kind == NodeKind::number) {
    throw error(written,
                "expected an operator between a number and a fraction: 2\\frac{1}{2} could be the "
                "mixed number 2½ or 2 times ½; write \\frac{5}{2}, or 2 \\cdot \\frac{1}{2}");
  }
}

// 2\,\mathrm{m}, 3\,\mathrm{kg}: a unit after a number, read as a symbol it would be a quantity
// (the mass m: L = 2 m and I = m L^2 / 12 gave I = m^3 / 3). Refused: units are not read.
void Grammar::refuse_unit(const Node& product, const Token& written) const {
  static const std::set<std::string, std::less<>> units{
      "m",   "s",  "kg", "g", "N", "J", "W",  "Pa", "Hz", "rad", "cm",  "mm",  "km", "h",
      "min", "ms", "K",  "V", "A", "C", "eV", "kN", "kJ", "kW",  "mph", "deg", "L",  "mL"};
  const std::size_t n = product.children.size();
  if (n >= 3 && product.children[n - 3].kind == NodeKind::number && written.kind == Tok::command &&
      commands::names.contains(written.text) && product.children[n - 2].kind == NodeKind::symbol &&
      product.children[n - 2].symbol.base == "\\mu") {
    // 2\,\mu\mathrm{m}: two micrometres, read as 2 μ m (m the mass).
    throw error(written, "expected a number in SI units: \\mu before " + written.text +
                             "{…} after a number is a prefix (micro), which this checker does "
                             "not read; write 2e-6 for 2 \\mu m");
  }
  if (n < 2 || product.children[n - 2].kind != NodeKind::number || written.kind != Tok::command ||
      !commands::names.contains(written.text)) {
    return;
  }
  const Node& after = product.children[n - 1];
  const Node& unit = after.kind == NodeKind::power ? after.children[0] : after;
  if (unit.kind != NodeKind::symbol || !unit.symbol.subscript.empty() ||
      !units.contains(unit.symbol.base)) {
    return;
  }
  throw error(written,
              "expected a number without a unit: " + written.text + "{" + unit.symbol.base +
                  "} after a number is a unit, which this checker does not read (read as a "
                  "symbol, it would be a quantity: \\mathrm{m} the mass m); write the "
                  "equation in numbers alone, with units: for the symbols' dimensions");
}

// A unit written after a number as some books write it, in brackets (L = 2\,[\mathrm{m}]) or as
// a fraction of names (36\,\frac{\text{km}}{\text{h}}): read as a factor, m the mass.
void Grammar::refuse_written_unit(const Node& product, const Token& next) const {
  if (product.children.empty() || product.children.back().kind != NodeKind::number) {
    return;
  }
  if (next.kind == Tok::command && commands::fractions.contains(next.text) &&
      is_char(token(position_ + 1), '{') && token(position_ + 2).kind == Tok::command &&
      commands::names.contains(token(position_ + 2).text)) {
    // 36\,\frac{\text{km}}{\text{h}}: a unit as a fraction, read as the symbols km over h.
    throw error(next, "expected a number in SI units without a unit: a fraction of " +
                          token(position_ + 2).text +
                          "{…} after a number is a unit, which this checker does not read; "
                          "write the number in SI units, with units: for the symbols' "
                          "dimensions");
  }
  if (!(is_char(next, '[') || is_char(next, '('))) {
    return;
  }
  std::size_t k = position_ + 1;
  while (token(k).kind == Tok::spacing) {
    ++k;
  }
  const Token& name = token(k);
  if (name.kind != Tok::command || !commands::names.contains(name.text) ||
      !is_char(token(k + 1), '{')) {
    return;
  }
  // The bracket holds the upright name alone: [\mathrm{m}], (\text{kg}).
  for (k += 2; token(k).kind == Tok::letter || token(k).kind == Tok::spacing; ++k) {
  }
  if (!is_char(token(k), '}')) {
    return;
  }
  for (++k; token(k).kind == Tok::spacing; ++k) {
  }
  if (is_char(token(k), is_char(next, '[') ? ']' : ')')) {
    throw error(next, "expected a number without a unit: " + name.text +
                          "{…} in brackets after a number is a unit, which this checker does "
                          "not read (read as a factor, \\mathrm{m} would be the mass m); write "
                          "the equation in numbers alone, with units: for the symbols' "
                          "dimensions");
  }
}

// factor := ('+' | '-') factor | atom postfix
Node Grammar::factor(std::size_t depth) {
  enter(depth, peek());
  if (is_char(peek(), '-') || is_char(peek(), '+')) {
    const Token sign = take();
    Node inner = factor(depth + 1);
    if (sign.text[0] == '+') {
      return inner;
    }
    Node negated = make(NodeKind::sum, sign.offset);
    negated.children.push_back(std::move(inner));
    negated.ops.push_back('-');
    negated.end = last_end_;
    return negated;
  }
  return postfix(depth, atom(depth + 1));
}

// postfix := ['^' script ['_' subscript]] ['!'] ['\%'] { bar }
// (v^2_1 is (v_1)^2: a subscript after the power belongs to the symbol under it)
Node Grammar::postfix(std::size_t depth, Node base) {
  if (is_char(peek_raw(), '^')) {
    const Token& before = token(position_ - 1);
    const bool grouped = is_char(before, ')') || is_char(before, ']');  // (\Delta v)^2
    if (base.kind == NodeKind::symbol && base.symbol.delta && !grouped) {
      // W = \tfrac12 m \Delta v^2 means the change of v^2 (read as (Δv)^2, a right step failed).
      SymbolName changed = base.symbol;
      changed.delta = false;
      const std::string delta = "\\Delta " + changed.latex();
      throw error(peek_raw(), "expected (" + delta + ")^… for a power of the change: " + delta +
                                  "^… could be the change of the power too; for that one, write "
                                  "the difference (v_f^2 - v_i^2) or name it");
    }
    if (is_char(before, '}') && base.kind == NodeKind::sum && base.ops == "-" &&
        base.children.size() == 1) {
      throw error(peek_raw(),
                  "expected parentheses around a negative base: {-2}^2 shows as "
                  "-2^2, which reads as -(2^2), though the braces make it (-2)^2; "
                  "write (-2)^2 or -2^2");
    }
    const Token caret = take();
    base = degrees_follow() ? degrees(std::move(base), caret)
                            : power_of(depth, std::move(base), caret);
    if (is_char(peek_raw(), '^')) {
      throw error(peek_raw(), "expected one exponent, found a second '^' (write {x^a}^b)");
    }
    if (is_char(peek_raw(), '\'')) {
      throw error(peek_raw(), "expected primes on a symbol before its exponent (p'^2)");
    }
  }
  if (is_char(peek_raw(), '!')) {
    const Token bang = take();
    if (base.kind != NodeKind::number) {
      throw error(bang,
                  "expected the factorial of a whole number written as digits (5!); the "
                  "factorial of anything else is not read by this checker");
    }
    Node f = make(NodeKind::factorial, base.offset);
    f.children.push_back(std::move(base));
    f.end = last_end_;
    base = std::move(f);
  }
  if (is_command(peek_raw(), "\\%")) {
    // 80\% is 80/100.
    const Token percent = take();
    if (base.kind != NodeKind::number) {
      throw error(percent,
                  "expected a number before \\% (80\\% is read as 80/100); a percentage "
                  "of anything else is not read: write it as a fraction");
    }
    Node hundred = make(NodeKind::number, percent.offset);
    hundred.text = "100";
    Node share = make(NodeKind::fraction, base.offset);
    share.children.push_back(std::move(base));
    share.children.push_back(std::move(hundred));
    share.end = last_end_;
    base = std::move(share);
  }
  while (bar_ahead()) {
    base = bar(depth, std::move(base));
  }
  return base;
}

// ---- evaluation bars ---------------------------------------------------------------------------

// a - b \Big|_0^h: the bar stands on b alone as read, on the whole sum as a student writes it
// (\frac{1}{2} k x^2 - m g x \Big|_0^h gave ½kx² - mgh). Refused in a term after one without a
// bar of its own; a bar on every term (the paper's A \Big|_0^{dt} + B \Big|_0^{dt}) is read.
void Grammar::refuse_bar_after_sum(const Node& sum) const {
  const auto bar_of = [](const Node& term) -> const Node* {
    const Node* last = &term;
    while (last->kind == NodeKind::product && !last->children.empty()) {
      last = &last->children.back();
    }
    return last->kind == NodeKind::bar && !last->enclosed ? last : nullptr;
  };
  const Node* bar = bar_of(sum.children.back());
  if (bar == nullptr || std::all_of(sum.children.begin(), sum.children.end() - 1,
                                    [&](const Node& term) { return bar_of(term) != nullptr; })) {
    return;
  }
  throw error_at(bar->children[0].end,
                 "expected \\left[ … \\right]_a^b (or \\left. … \\right|_a^b) around a sum "
                 "before an evaluation bar: after a + b it stands on b alone as read, on the "
                 "whole sum as meant");
}

// The power after '^' (already taken): its exponent read, x^2; v^2_1 is (v_1)^2.
Node Grammar::power_of(std::size_t depth, Node base, const Token& caret) {
  if (is_char(token(position_), '{') && is_char(token(position_ + 1), '(') &&
      (token(position_ + 2).kind == Tok::number || token(position_ + 2).kind == Tok::letter) &&
      is_char(token(position_ + 3), ')') && is_char(token(position_ + 4), '}')) {
    // x^{(2)}: the second derivative, or a label (the second of a series), more often than
    // the square (x^{(1)} = x followed).
    throw error(token(position_ + 1),
                "expected an exponent without parentheses: x^{(2)} is the second derivative "
                "or a label more often than a power; write x^2 for the power, \\ddot x or x_2 "
                "for the others");
  }
  Node exponent = script(depth + 1, caret);
  if (is_char(peek_raw(), '_') && base.kind == NodeKind::symbol && base.symbol.subscript.empty()) {
    take();
    base.symbol.subscript = subscript(depth + 1);
    base.end = last_end_;
  }
  Node power = make(NodeKind::power, base.offset);
  power.children.push_back(std::move(base));
  power.children.push_back(std::move(exponent));
  power.end = last_end_;
  return power;
}

// 30^\circ or 30^{\circ} (degrees) after '^', before the exponent is read.
bool Grammar::degrees_follow() const {
  return is_command(token(position_), "\\circ") ||
         (is_char(token(position_), '{') && is_command(token(position_ + 1), "\\circ") &&
          is_char(token(position_ + 2), '}'));
}

// A number of degrees, 30^\circ, read as the angle in radians it is, 30π/180 (a degree sign has
// no other reading); after anything but a number it is refused: θ^\circ could name the angle θ
// in degrees or be θ, an angle in radians, times π/180.
Node Grammar::degrees(Node number, const Token& caret) {
  if (number.kind != NodeKind::number) {
    throw error(caret,
                "expected a number before ^\\circ (30^\\circ is read as 30\\pi/180): "
                "an angle in degrees written as a symbol is not read; write the angle in "
                "radians, or as a number of degrees");
  }
  const bool braced = is_char(token(position_), '{');
  take();  // \circ, or {
  if (braced) {
    take();  // \circ
    take();  // }
  }
  Node turn = make(NodeKind::product, number.offset);
  turn.children.push_back(std::move(number));
  turn.children.push_back(make(NodeKind::pi, caret.offset));
  turn.ops = "  ";
  Node half_turn = make(NodeKind::number, caret.offset);
  half_turn.text = "180";
  Node angle = make(NodeKind::fraction, turn.offset);
  angle.children.push_back(std::move(turn));
  angle.children.push_back(std::move(half_turn));
  angle.end = last_end_;
  return angle;
}

bool Grammar::bar_ahead() {
  skip_spacing();
  std::size_t i = position_;
  if (in(token(i), commands::sizes)) {
    ++i;
  } else if (abs_depth_ != 0) {
    return false;
  }
  return is_char(token(i), '|') && is_char(token(i + 1), '_');
}

// bar := [size] '|' '_' (script | '{' [symbol '='] expression '}') ['^' script]
Node Grammar::bar(std::size_t depth, Node base) {
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

// script := '{' expression '}' | digit | symbol
Node Grammar::script(std::size_t depth, const Token& caret) {
  return argument(depth, caret,
                  is_char(caret, '_') ? "a limit after '_'" : "an exponent after '^'");
}

// LaTeX takes one character from a number after \frac, ^ or _: \frac12 is a half. After ^ or _
// (`script`) a number of several digits is refused: x^23 shows x squared, then 3, but the writer
// of x^10 meant the tenth power.
Node Grammar::single_digit(const Token& t, bool script) {
  Token& digits = tokens_[position_];
  if (script && digits.text.size() > 1 && digits.text[1] != '.') {
    throw error(digits, "expected one digit, or braces, after '^' or '_': LaTeX takes only the " +
                            digits.text.substr(0, 1) + " (it shows the power or limit " +
                            digits.text.substr(0, 1) + ", then " + digits.text.substr(1) +
                            "); write {" + digits.text + "} for " + digits.text);
  }
  Node n = make(NodeKind::number, t.offset);
  n.text = digits.text.substr(0, 1);
  n.end = t.offset + 1;
  if (digits.text.size() == 1) {
    take();
  } else {
    digits.text = digits.text.substr(1);
    digits.offset += 1;
    digits.space_before = false;
    split_digits_at_ = digits.offset;
    if (digits.text[0] == '.') {
      throw error(digits, "expected a digit after the exponent's digit, found '.'");
    }
  }
  last_end_ = n.end;
  return n;
}

// \frac 1 10, \frac123, \sqrt 12, \sqrt[3]27: LaTeX takes one digit of a number as the argument,
// and the rest of the number follows as a factor ((1/1)·0, (1/2)·3, √1·2), where the writer meant
// 1/10 and √12 (\frac12, whose second digit is the second argument, is a half). Refused, as x^10
// is.
void Grammar::refuse_digits_left(const Token& command) const {
  const Token& next = token(position_);
  if (next.kind == Tok::number && next.offset == split_digits_at_) {
    throw error(next, "expected braces around the arguments of " + command.text +
                          ": LaTeX takes one digit of a number as an argument, and the rest of "
                          "it follows as a factor (\\frac 1 10 is 1/1 times 0, \\sqrt 12 is "
                          "the root of 1 times 2); write \\frac{1}{10}, \\sqrt{12}");
  }
}

// Inside a function's argument written without parentheses (\cos\theta …), a factor that begins
// another kind of term: a root, bars, a fraction, braces, a number, an upright name. \cos\theta
// \sqrt{m} was cos(θ √m) where k \cos\theta \sqrt{m} means cos θ times √m.
bool Grammar::runs_into_factor(const Token& next) const {
  // Inside |…| a '|' closes it (|\sin x|): no factor starts there.
  return next.kind == Tok::number || (is_char(next, '|') && abs_depth_ == 0) ||
         (next.kind == Tok::command &&
          (next.text == "\\sqrt" || next.text == "\\lvert" || next.text == "\\vert" ||
           next.text == "\\|" || next.text == "\\lVert" || next.text == "\\Vert" ||
           next.text == "\\{" || commands::fractions.contains(next.text) ||
           commands::names.contains(next.text)));
}

bool Grammar::starts_atom(const Token& t) const {
  switch (t.kind) {
    case Tok::number:
    case Tok::letter:
      return true;
    case Tok::character:
      return is_char(t, '(') || is_char(t, '[') || is_char(t, '{') ||
             (is_char(t, '|') && abs_depth_ == 0);
    case Tok::command:
      if (in(t, commands::sizes)) {
        // \bigl( opens a group; \bigr) and, inside a sized group, \big) close one
        const auto at = static_cast<std::size_t>(&t - tokens_.data());
        const Token& next = token(at + 1);
        const bool closing = t.text.ends_with("r") || is_char(next, ')') || is_char(next, ']') ||
                             is_command(next, "\\}") || is_command(next, "\\rvert") ||
                             is_command(next, "\\rVert") ||
                             ((is_char(next, '|') || is_command(next, "\\|")) && sized_depth_ > 0);
        return !closing;
      }
      return commands::greek.contains(t.text) || commands::functions.contains(t.text) ||
             commands::fractions.contains(t.text) || commands::accents.contains(t.text) ||
             commands::modifiers.contains(t.text) || commands::names.contains(t.text) ||
             t.text == "\\Delta" || t.text == "\\pi" || t.text == "\\sqrt" || t.text == "\\det" ||
             t.text == "\\left" || t.text == "\\lVert" || t.text == "\\lvert" || t.text == "\\{" ||
             ((t.text == "\\|" || t.text == "\\Vert") && norm_depth_ == 0) ||
             (t.text == "\\vert" && abs_depth_ == 0);
    default:
      return false;
  }
}

// Whether the next tokens are a differential: dt, d x, \mathrm{d}x (inside an integrand).
bool Grammar::differential_ahead() const {
  std::size_t i = position_;
  while (token(i).kind == Tok::spacing) {
    ++i;
  }
  const Token& t = token(i);
  if (t.kind == Tok::letter && t.text == "d") {
    std::size_t k = i + 1;
    while (token(k).kind == Tok::spacing) {
      ++k;
    }
    return token(k).kind == Tok::letter ||
           (token(k).kind == Tok::command && commands::greek.contains(token(k).text));
  }
  return (is_command(t, "\\mathrm") || is_command(t, "\\text") ||
          is_command(t, "\\operatorname")) &&
         is_char(token(i + 1), '{') && token(i + 2).kind == Tok::letter &&
         token(i + 2).text == "d" && is_char(token(i + 3), '}');
}

}  // namespace impulse::derivations::file
