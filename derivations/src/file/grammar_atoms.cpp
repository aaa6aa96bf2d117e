// SPDX-License-Identifier: GPL-3.0-or-later
// The grammar's atoms: numbers, groups and their delimiters (\left … \right, \bigl( … \bigr)),
// fractions and derivatives, roots, functions, determinants, norms, and a name before a
// parenthesised list (F(t)).
#include <algorithm>

#include "file/grammar.hpp"

namespace impulse::derivations::file {

bool is_plain_d(const Node& n) {
  return n.kind == NodeKind::symbol && n.symbol.base == "d" && n.symbol.subscript.empty() &&
         n.symbol.primes == 0 && !n.symbol.delta && !n.symbol.accent;
}

namespace {

// The order written on a d or a variable: d^2 is 2, d is 1; 0 when it is not a whole power.
int order_of(const Node& exponent) {
  if (exponent.kind == NodeKind::number && exponent.text.size() == 1 && exponent.text[0] >= '1' &&
      exponent.text[0] <= '9') {
    return exponent.text[0] - '0';
  }
  return 0;
}

}  // namespace

// atom := number | symbol [call] | group | command
Node Grammar::atom(std::size_t depth) {
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
      // 0{,}5: the decimal comma as LaTeX writes it (the braces keep TeX from spacing it as a
      // separator), read as 0.5.
      const std::size_t i = position_;
      if (number.text.find('.') == std::string::npos && is_char(token(i), '{') &&
          is_char(token(i + 1), ',') && is_char(token(i + 2), '}') &&
          token(i + 3).kind == Tok::number && !token(i + 3).space_before &&
          token(i + 3).text.find('.') == std::string::npos) {
        position_ += 3;
        const Token fraction = take();
        n.text += "." + fraction.text;
        n.end = last_end_;
      }
      return n;
    }
    case Tok::letter: {
      Node symbol = symbol_atom(depth);
      if (!call_ahead()) {
        return symbol;
      }
      skip_spacing();
      return call(depth, std::move(symbol));
    }
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

// group := '(' expression ')' | brace-group | '[' expression [',' expression] ']'
//        | '|' expression '|'
Node Grammar::bracket(std::size_t depth) {
  const Token open = take();
  if (is_char(open, '(')) {
    return group_inside(depth, open, ')');
  }
  if (is_char(open, '{')) {
    return brace_group(depth, open);
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
    if (is_char(peek_raw(), '_')) {  // [ … ]_a^b: an evaluation bar
      Node held = std::move(first);
      --position_;  // read the subscript as a bar's: '|' stands for the closing bracket
      tokens_[position_].kind = Tok::character;
      tokens_[position_].text = "|";
      Node evaluated = bar(depth, std::move(held));
      evaluated.enclosed = true;
      return evaluated;
    }
    first.enclosed = true;
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
  if (is_char(open, '!')) {
    throw error(open, "expected a whole number before '!' (a factorial)");
  }
  throw error(open, "expected a term, found " + describe(open));
}

Node Grammar::group_inside(std::size_t depth, const Token& open, char close) {
  if (is_char(peek(), close)) {
    throw error(peek(),
                "expected an expression inside " + describe(open) + "…" + std::string(1, close));
  }
  Node inner = expression(depth + 1);
  expect_char(close, open, close == '}' ? "group {…}" : "parenthesis");
  inner.enclosed = close == ')';
  return inner;
}

// brace-group := '{' expression ['\over' expression] '}' [primes]
// ({a \over b} is \frac{a}{b}; {v_1}' is v_1')
Node Grammar::brace_group(std::size_t depth, const Token& open) {
  if (is_char(peek(), '}')) {
    throw error(peek(), "expected an expression inside '{'…'}'");
  }
  Node inner = expression(depth + 1);
  if (is_command(peek(), "\\over")) {
    take();
    Node bottom = expression(depth + 1);
    expect_char('}', open, "group {… \\over …}");
    Node n = make(NodeKind::fraction, open.offset);
    n.children.push_back(std::move(inner));
    n.children.push_back(std::move(bottom));
    return n;
  }
  expect_char('}', open, "group {…}");
  if (inner.kind == NodeKind::symbol && (is_char(peek_raw(), '\'') || primes_follow())) {
    return decorate(depth, std::move(inner));
  }
  return inner;
}

// delimited := ('\left' | size) opener expression [',' expression] ('\right' | size) closer
//              ['_' bar-limits]
// opener := '(' | '[' | '|' | '\|' | '\{' | '.' | '\vert' | '\lvert' | '\Vert' | '\lVert'
// (\left. … \right|_a^b and \left[ … \right]_a^b are evaluation bars)
Node Grammar::delimited(std::size_t depth) {
  const Token left = take();
  const bool sized = left.text != "\\left";
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
  } else if (is_command(open, "\\|") || is_command(open, "\\Vert") || is_command(open, "\\lVert")) {
    closer = "\\|";
    kind = NodeKind::norm;
  } else if (is_char(open, '.') && !sized) {
    closer = "";
  } else {
    throw error(open, "expected a delimiter after " + left.text + " ('(', '[', '|', '\\|', '\\{'" +
                          (sized ? "" : " or '.'") + "), found " + describe(open));
  }
  if (kind == NodeKind::abs) {
    ++abs_depth_;
  }
  if (kind == NodeKind::norm) {
    ++norm_depth_;
  }
  sized_depth_ += sized ? 1 : 0;
  Node first = expression(depth + 1);
  Node second;
  bool pair = false;
  if (closer == "]" && is_char(peek(), ',')) {
    take();
    second = expression(depth + 1);
    pair = true;
  }
  sized_depth_ -= sized ? 1 : 0;
  if (kind == NodeKind::abs) {
    --abs_depth_;
  }
  if (kind == NodeKind::norm) {
    --norm_depth_;
  }
  const bool closes = sized ? in(peek(), commands::sizes) : is_command(peek(), "\\right");
  if (!closes) {
    throw error(
        peek(),
        "expected " +
            std::string(sized ? "a sized delimiter (" + left.text + "r)" : std::string("\\right")) +
            " to close the " + left.text + " at " + where(left) + ", found " + describe(peek()));
  }
  const Token right = take();
  const Token close = take();
  const bool matches =
      closer.empty() || (is_char(close, '.') && !sized) || (closer == ")" && is_char(close, ')')) ||
      (closer == "]" && is_char(close, ']')) || (closer == "\\}" && is_command(close, "\\}")) ||
      (closer == "|" &&
       (is_char(close, '|') || is_command(close, "\\vert") || is_command(close, "\\rvert"))) ||
      (closer == "\\|" &&
       (is_command(close, "\\|") || is_command(close, "\\Vert") || is_command(close, "\\rVert")));
  if (!matches) {
    throw error(close, "expected " + right.text +
                           (closer.empty() ? std::string(" and a delimiter") : closer) +
                           " to match the " + left.text + open.text + " at " + where(left) +
                           ", found " + describe(close));
  }
  if (pair) {
    Node vec = make(NodeKind::vector, left.offset);
    vec.children.push_back(std::move(first));
    vec.children.push_back(std::move(second));
    return vec;
  }
  const bool evaluation =
      is_char(peek_raw(), '_') &&
      ((closer.empty() && (is_char(close, '|') || is_command(close, "\\vert"))) || closer == "]");
  if (evaluation) {
    --position_;  // the closing delimiter stands for the bar
    tokens_[position_].kind = Tok::character;
    tokens_[position_].text = "|";
    Node evaluated = bar(depth, std::move(first));
    evaluated.enclosed = true;
    return evaluated;
  }
  if (closer.empty() && !is_char(close, '.')) {
    throw error(close, "expected \\right. to close \\left. (or an evaluation bar \\right|_a^b)");
  }
  if (kind == NodeKind::abs || kind == NodeKind::norm) {
    Node n = make(kind, left.offset);
    n.children.push_back(std::move(first));
    return n;
  }
  first.enclosed = closer == ")" || closer == "]";
  return first;
}

// argument := '{' expression '}' | digit | symbol
Node Grammar::argument(std::size_t depth, const Token& before, const std::string& what) {
  const Token& next = peek();
  if (is_char(next, '{')) {
    const Token open = take();
    return group_inside(depth, open, '}');
  }
  if (next.kind == Tok::number) {
    return single_digit(next, is_char(before, '^') || is_char(before, '_'));
  }
  if (next.kind == Tok::letter ||
      (next.kind == Tok::command && commands::greek.contains(next.text))) {
    return symbol_atom(depth);
  }
  if (next.kind == Tok::command &&
      (commands::fractions.contains(next.text) || next.text == "\\pi")) {
    return command(depth);  // x^\frac{1}{2}: the command takes its own arguments
  }
  throw error(next, "expected " + (what.empty() ? "an argument after " + before.text : what) +
                        " at " + where(before) + " (a digit, a letter or {…}), found " +
                        describe(next));
}

// command := symbol | '\pi' | fraction | root | function | det | delimited | norm | abs | big
Node Grammar::command(std::size_t depth) {
  const Token& t = peek();
  const std::string name = t.text;
  if (commands::greek.contains(name) || name == "\\Delta" || commands::accents.contains(name) ||
      commands::modifiers.contains(name) || commands::names.contains(name)) {
    Node symbol = symbol_atom(depth);
    return call_ahead() && symbol.kind == NodeKind::symbol ? call(depth, std::move(symbol))
                                                           : symbol;
  }
  if (name == "\\pi") {
    const Token pi = take();
    return make(NodeKind::pi, pi.offset);
  }
  if (commands::fractions.contains(name)) {
    return fraction(depth);
  }
  if (name == "\\sqrt") {
    return root(depth);
  }
  if (commands::functions.contains(name)) {
    return function(depth);
  }
  if (name == "\\det") {
    return determinant(depth);
  }
  if (name == "\\left" || (commands::sizes.contains(name) && starts_atom(t))) {
    return delimited(depth);
  }
  if (name == "\\|" || name == "\\lVert" || name == "\\Vert") {
    return norm(depth);
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
  if (big_operator(t)) {
    return big(depth);
  }
  return refused_command(t);
}

// What is not read, refused with the reason and what to write instead.
Node Grammar::refused_command(const Token& t) {
  const std::string& name = t.text;
  if (name == "\\approx" || name == "\\simeq" || name == "\\sim" || name == "\\cong") {
    throw error(t, "expected '=', found " + name +
                       ": an approximation is not a step that follows or not (write the exact "
                       "equation, or the approximation as a definition with let:)");
  }
  if (name == "\\pm" || name == "\\mp") {
    throw error(t, "expected + or - (" + name + " stands for two equations: write each)");
  }
  if (commands::relations.contains(name)) {
    throw error(
        t, "expected a term, found the relation " + name + " (this checker reads equations: =)");
  }
  if (name == "\\cdot" || name == "\\times" || name == "\\div") {
    throw error(t, "expected a term before " + name);
  }
  if (name == "\\right") {
    throw error(t, "expected a term, found \\right without its \\left");
  }
  if (commands::sizes.contains(name)) {
    throw error(t, "expected a term, found the closing delimiter " + name +
                       " without its "
                       "opening one");
  }
  if (name == "\\partial") {
    throw error(t,
                "expected no partial derivative: \\partial is not read by this checker "
                "(functions of one variable and their derivatives d/dt are)");
  }
  if (name == "\\iint" || name == "\\oint" || name == "\\iiint") {
    throw error(t, "expected an expression without " + name +
                       " (multiple and closed integrals are not read by this checker)");
  }
  if (name == "\\infty") {
    throw error(t,
                "expected a number or a symbol, found \\infty (limits and infinite sums and "
                "integrals are not read by this checker)");
  }
  if (name == "\\lim") {
    throw error(t, "expected an expression without \\lim (limits are not read by this checker)");
  }
  if (name == "\\over") {
    throw error(t, "expected \\over inside braces, {a \\over b}");
  }
  if (name == "\\rm") {
    throw error(t,
                "expected \\mathrm{…} for an upright name here: {\\rm …} is read where it opens "
                "a group of its own ({\\rm d}t, K_{\\rm i}), not inside a command's argument "
                "(\\frac{\\mathrm{d}x}{\\mathrm{d}t}) or after the group's first part");
  }
  if (name == "\\cancel" || name == "\\bcancel" || name == "\\xcancel" || name == "\\cancelto" ||
      name == "\\sout") {
    throw error(t, "expected an expression without " + name +
                       ": the struck-out part still stands (cancelled against another) or is "
                       "dropped from the equation? Write the equation that is left, as a step");
  }
  if (name == "\\underbrace" || name == "\\overbrace") {
    throw error(t, "expected an expression without " + name +
                       ": its note is not read, and under a product the brace reads two ways "
                       "(2\\underbrace{a + b} is 2a + b or 2(a + b)); write the equation without "
                       "it and the note as prose");
  }
  if (name == "\\nabla" || name == "\\mathcal" || name == "\\mathbb") {
    throw error(t, "expected an expression without " + name + " (not read by this checker)");
  }
  throw error(t, "expected a command this checker reads, found the unknown command " + name +
                     " (the LaTeX read here: numbers, symbols, + - \\cdot \\times / ^, "
                     "\\frac, \\sqrt, \\sin, \\cos, \\tan, \\exp, \\ln, \\det, \\| \\|, "
                     "| |, \\left( \\right), \\vec, \\sum, \\int)");
}

// fraction := frac-cmd argument argument          (a derivative when it is one, see below)
Node Grammar::fraction(std::size_t depth) {
  const Token frac = take();
  Node numerator = argument(depth + 1, frac);
  Node denominator = argument(depth + 1, frac);
  refuse_digits_left(frac);
  if (auto derivative = as_derivative(numerator, denominator, frac.offset, depth)) {
    return std::move(*derivative);
  }
  Node n = make(NodeKind::fraction, frac.offset);
  n.children.push_back(std::move(numerator));
  n.children.push_back(std::move(denominator));
  return n;
}

// derivative := frac-cmd '{' d ['^' n] [operand] '}' '{' d variable ['^' n] '}' [factor]
// (d is the letter d or \mathrm{d}; dt is d and t; the operand may stand in parentheses, d(x^2);
// without an operand in the numerator, the factor after the fraction is differentiated:
// \frac{d}{dt}(…)). A fraction whose denominator is
// not d and a variable is a fraction.
std::optional<Node> Grammar::as_derivative(const Node& top, const Node& bottom, std::size_t offset,
                                           std::size_t depth) {
  // The denominator: dt, dt^2, d t, d t^2, \mathrm{d}x …
  SymbolName variable;
  int order = 0;
  const auto differential_of = [&](const Node& n, int power) -> bool {
    if (n.kind == NodeKind::symbol && n.symbol.base == "dt" && n.symbol.subscript.empty() &&
        !n.symbol.delta && !n.symbol.differential) {
      variable = SymbolName{"t", "", n.symbol.primes, false};
      order = power;
      return true;
    }
    return false;
  };
  bool found = false;
  if (bottom.kind == NodeKind::power && order_of(bottom.children[1]) > 0) {
    found = differential_of(bottom.children[0], order_of(bottom.children[1]));
  } else {
    found = differential_of(bottom, 1);
  }
  if (!found && bottom.kind == NodeKind::product && bottom.children.size() == 2 &&
      is_plain_d(bottom.children[0]) && bottom.ops == "  ") {
    const Node& v = bottom.children[1];
    if (v.kind == NodeKind::symbol) {
      variable = v.symbol;
      order = 1;
      found = true;
    } else if (v.kind == NodeKind::power && v.children[0].kind == NodeKind::symbol &&
               order_of(v.children[1]) > 0) {
      variable = v.children[0].symbol;
      order = order_of(v.children[1]);
      found = true;
    }
  }
  if (!found) {
    return std::nullopt;
  }
  // The numerator: d alone, d^2 alone, d X, d^2 X, dt (the derivative of t).
  Node derivative = make(NodeKind::derivative, offset);
  derivative.symbol = variable;
  derivative.text = std::to_string(order);
  std::optional<Node> operand;
  int top_order = 0;
  if (is_plain_d(top)) {
    top_order = 1;
  } else if (top.kind == NodeKind::power && is_plain_d(top.children[0])) {
    top_order = order_of(top.children[1]);
  } else if (top.kind == NodeKind::symbol && top.symbol.base == "dt" &&
             top.symbol.subscript.empty()) {
    top_order = 1;  // d t over d x: the derivative of t
    Node t = top;
    t.symbol = SymbolName{"t", "", top.symbol.primes, false};
    operand = std::move(t);
  } else if (top.kind == NodeKind::product && top.ops[1] == ' ' &&
             (is_plain_d(top.children[0]) || (top.children[0].kind == NodeKind::power &&
                                              is_plain_d(top.children[0].children[0])))) {
    top_order = is_plain_d(top.children[0]) ? 1 : order_of(top.children[0].children[1]);
    Node rest = top;
    rest.children.erase(rest.children.begin());
    rest.ops.erase(rest.ops.begin());
    rest.ops[0] = ' ';
    rest.offset = rest.children[0].offset;
    operand = rest.children.size() == 1 ? std::move(rest.children[0]) : std::move(rest);
  } else if (top.kind == NodeKind::call && top.children.size() == 2 &&
             is_plain_d(top.children[0])) {
    // d(x^2) over dt: the derivative of x^2 (read as d times x^2 over a differential dt, the
    // step d(x^2)/dt = x d(x)/dt followed from x = t^3, where the left side is 6 t^5).
    top_order = 1;
    operand = top.children[1];
    operand->enclosed = true;
  } else {
    // d over a differential, the numerator no differential: a plain fraction (F\,dt over dt)
    return std::nullopt;
  }
  if (top_order != order) {
    throw error_at(offset, "expected the same order above and below the derivative (d^" +
                               std::to_string(top_order) + " over d" + variable.latex() + "^" +
                               std::to_string(order) + ")");
  }
  if (!operand) {
    // \frac{d}{dt} applies to the factor that follows it.
    if (!starts_atom(peek()) || is_char(peek(), '|')) {
      throw error(peek(), "expected what \\frac{d}{d" + variable.latex() +
                              "} differentiates after it, e.g. \\frac{d}{d" + variable.latex() +
                              "}\\left(m v\\right)");
    }
    operand = factor(depth + 1);
    if (!operand->enclosed && starts_atom(peek()) && !is_char(peek(), '|')) {
      // \frac{d}{dt} t x: of t alone, then times x, or of t x? (d(tx)/dt = t^3 followed from
      // x = t^3, where d(tx)/dt = 4 t^3.)
      throw error(peek(), "expected parentheses around what \\frac{d}{d" + variable.latex() +
                              "} differentiates: followed by a product, it could be the first "
                              "factor alone or the whole product; write \\frac{d}{d" +
                              variable.latex() + "}\\left(t x\\right) or x \\frac{d t}{d" +
                              variable.latex() + "}");
    }
  }
  derivative.children.push_back(std::move(*operand));
  derivative.end = last_end_;
  return derivative;
}

// root := '\sqrt' ['[' expression ']'] argument
Node Grammar::root(std::size_t depth) {
  const Token sqrt = take();
  std::optional<Node> index;
  if (is_char(peek(), '[')) {
    const Token open = take();
    index = expression(depth + 1);
    expect_char(']', open, "root index");
  }
  Node radicand = argument(depth + 1, sqrt);
  refuse_digits_left(sqrt);
  Node n = make(NodeKind::root, sqrt.offset);
  n.children.push_back(std::move(radicand));
  if (index) {
    n.children.push_back(std::move(*index));
  }
  return n;
}

// function := fname ['^' script] ['_' script] (group | delimited | bare-argument)
// (the power of \sin^2 x applies to the value; a subscript only on \log, its base; \log alone
// is refused: natural or decimal?)
Node Grammar::function(std::size_t depth) {
  const Token f = take();
  std::optional<Node> power;
  std::optional<Node> base;
  for (int k = 0; k < 2; ++k) {
    if (is_char(peek_raw(), '^') && !power) {
      const Token caret = take();
      power = script(depth + 1, caret);
      if (power->kind == NodeKind::sum && power->ops == "-") {
        throw error_at(power->offset, "expected a positive power on " + f.text + " (" + f.text +
                                          "^{-1} could be the inverse function or one over the "
                                          "value: write \\arc… or 1/…)");
      }
    } else if (is_char(peek_raw(), '_') && !base) {
      const Token underscore = take();
      if (f.text != "\\log") {
        throw error(underscore, "expected no subscript on " + f.text);
      }
      base = script(depth + 1, underscore);
    }
  }
  if (f.text == "\\log" && !base) {
    throw error(f,
                "expected \\log_b with its base, or \\ln: \\log alone could be the natural or "
                "the decimal logarithm");
  }
  Node argument_node;
  const Token& next = peek();
  if (is_char(next, '(') || is_char(next, '[') || is_char(next, '{') ||
      is_command(next, "\\left") || (in(next, commands::sizes) && starts_atom(next))) {
    argument_node = atom(depth + 1);
  } else if (starts_atom(next) && !big_operator(next)) {
    argument_node = bare_argument(depth, f);
  } else {
    throw error(next, "expected the argument of " + f.text + ", found " + describe(next));
  }
  Node n = make(NodeKind::function, f.offset);
  n.text = f.text.substr(1);
  n.children.push_back(std::move(argument_node));
  if (base) {
    n.children.push_back(std::move(*base));
  }
  n.end = last_end_;
  if (power) {
    Node p = make(NodeKind::power, f.offset);
    p.children.push_back(std::move(n));
    p.children.push_back(std::move(*power));
    return p;
  }
  return n;
}

// bare-argument := term-of-factors   (to the next '+', '-', relation or function: \sin 2\theta;
// \sin a \cos b is sin(a) cos(b); \sin \cos \theta is sin(cos(theta)))
Node Grammar::bare_argument(std::size_t depth, const Token& function_token) {
  ++bare_argument_;
  bare_functions_.push_back(function_token);
  Node argument_node;
  if (in(peek(), commands::functions)) {
    argument_node = function(depth + 1);  // \sin \cos \theta
  } else {
    argument_node = term(depth + 1);
  }
  bare_functions_.pop_back();
  --bare_argument_;
  return argument_node;
}

// det := '\det' ('(' | '\left(') expression ',' expression (')' | '\right)')
Node Grammar::determinant(std::size_t depth) {
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

// norm := ('\|' | '\lVert' | '\Vert') expression ('\|' | '\rVert' | '\Vert')
Node Grammar::norm(std::size_t depth) {
  const Token open = take();
  ++norm_depth_;
  Node inner = expression(depth + 1);
  --norm_depth_;
  const Token& close = peek();
  if (!(is_command(close, "\\|") || is_command(close, "\\rVert") || is_command(close, "\\Vert"))) {
    throw error(close, "expected \\| to close the norm opened at " + where(open) + ", found " +
                           describe(close));
  }
  take();
  Node n = make(NodeKind::norm, open.offset);
  n.children.push_back(std::move(inner));
  return n;
}

bool Grammar::call_ahead() const {
  std::size_t i = position_;
  while (token(i).kind == Tok::spacing) {
    ++i;
  }
  return is_char(token(i), '(') || (is_command(token(i), "\\left") && is_char(token(i + 1), '('));
}

// call := symbol ('(' | '\left(') expression {',' expression} (')' | '\right)')
Node Grammar::call(std::size_t depth, Node name) {
  const Token open = take();
  const bool left = is_command(open, "\\left");
  if (left) {
    take();  // (
  }
  Node n = make(NodeKind::call, name.offset);
  n.spaced = open.space_before;
  if (bare_argument_ > 0) {
    n.text = bare_call;  // \sin\theta(1 + x): a product here would be ambiguous
  }
  n.children.push_back(std::move(name));
  if (is_char(peek(), ')')) {
    throw error(peek(), "expected an expression inside the parentheses");
  }
  while (true) {
    n.children.push_back(expression(depth + 1));
    if (!is_char(peek(), ',')) {
      break;
    }
    take();
  }
  if (left) {
    if (!is_command(peek(), "\\right")) {
      throw error(peek(), "expected \\right) to close the \\left( at " + where(open) + ", found " +
                              describe(peek()));
    }
    take();
  }
  expect_char(')', open, "parenthesis");
  n.end = last_end_;
  return n;
}

}  // namespace impulse::derivations::file
