// SPDX-License-Identifier: GPL-3.0-or-later
// The grammar of symbols: a letter, a Greek letter, \Delta X, an accent or a modifier over a
// letter, a name in \mathrm{…}, then a subscript and primes in either order.
#include "file/grammar.hpp"

#include <optional>
#include <string>

namespace impulse::derivations::file {

// symbol := letter-part {'_' subscript | "'" | '^' primes}
// letter-part := letter | greek | '\Delta' (symbol | '{' symbol '}') | accent argument
//              | modifier argument | name-command '{' name '}'
// (the letters d and t side by side are one symbol, dt)
Node Grammar::symbol_atom(std::size_t depth) {
  enter(depth, peek());
  const Token first = peek();
  SymbolName name;
  if (is_command(first, "\\Delta")) {
    return delta_symbol(depth);
  }
  if (first.kind == Tok::letter) {
    take();
    name.base = first.text;
    // The letters dt, together, are one symbol (the collision's duration).
    if (first.text == "d" && peek_raw().kind == Tok::letter && peek_raw().text == "t" &&
        !peek_raw().space_before) {
      take();
      name.base = "dt";
    }
  } else if (first.kind == Tok::command && commands::greek.contains(first.text)) {
    take();
    name.base = first.text;
  } else if (commands::accents.contains(first.text)) {
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
  } else if (commands::modifiers.contains(first.text)) {
    if (first.text == "\\overline") {
      throw error(first,
                  "expected \\bar x for a symbol of its own: \\overline could be a mean "
                  "or a complex conjugate (or a line over several symbols)");
    }
    take();
    Node inner = argument(depth + 1, first);
    if (inner.kind != NodeKind::symbol || !inner.symbol.subscript.empty() ||
        inner.symbol.primes != 0 || inner.symbol.delta) {
      throw error(first, "expected a single letter under " + first.text);
    }
    name.base = first.text + "{" + inner.symbol.base + "}";
  } else if (commands::names.contains(first.text)) {
    take();
    name.base = name_group(first);
    if (name.base == "d" && peek_raw().kind == Tok::letter && peek_raw().text == "t") {
      take();
      name.base = "dt";
    } else if ((name.base == "d" || name.base == "e") && first.text != "\\mathit" &&
               first.text != "\\textit") {
      Node n = make(NodeKind::symbol, first.offset);
      n.symbol = name;
      n.text = name.base == "d" ? upright_d : upright_e;
      return decorate(depth, std::move(n));
    }
  } else {
    throw error(first, "expected a symbol, found " + describe(first));
  }
  Node n = make(NodeKind::symbol, first.offset);
  n.symbol = name;
  return decorate(depth, std::move(n));
}

// '\Delta' (symbol | '{' symbol '}'): one symbol, the change of the symbol. \Delta alone is the
// letter; \Delta before anything else (\Delta(m v)) is refused: the change of what?
Node Grammar::delta_symbol(std::size_t depth) {
  const Token first = take();
  std::optional<Node> inner;
  if (starts_symbol(peek())) {
    inner = symbol_atom(depth + 1);
  } else if (is_char(peek(), '{')) {
    const Token open = take();
    if (!starts_symbol(peek())) {
      throw error(peek(),
                  "expected a symbol inside \\Delta{…} (\\Delta{p}), found " + describe(peek()));
    }
    inner = symbol_atom(depth + 1);
    expect_char('}', open, "\\Delta{…}");
  } else if (is_char(peek(), '(') || is_command(peek(), "\\left") ||
             (in(peek(), commands::sizes) && starts_atom(peek()))) {
    throw error(peek(),
                "expected a symbol after \\Delta: \\Delta(…) could be the change of "
                "what the parentheses hold or \\Delta times it; write the change as a "
                "difference (m v' - m v), or name it (\\Delta p with let: or a step)");
  }
  if (!inner) {
    Node n = make(NodeKind::symbol, first.offset);
    n.symbol.base = "\\Delta";
    return decorate(depth, std::move(n));
  }
  if (inner->kind != NodeKind::symbol || inner->symbol.delta) {
    throw error(first, "expected a symbol after \\Delta");
  }
  inner->symbol.delta = true;
  inner->offset = first.offset;
  return decorate(depth, std::move(*inner));
}

bool Grammar::starts_symbol(const Token& t) const {
  return t.kind == Tok::letter ||
         (t.kind == Tok::command &&
          (commands::greek.contains(t.text) || commands::accents.contains(t.text) ||
           commands::modifiers.contains(t.text) || commands::names.contains(t.text)));
}

// name := '{' letter-or-digit {letter-or-digit} '}'      (the letters of \mathrm{…}: one name)
std::string Grammar::name_group(const Token& command_token) {
  if (!is_char(peek(), '{')) {
    throw error(peek(), "expected {name} after " + command_token.text);
  }
  const Token open = take();
  // as written: \mathrm{…}, or {\rm …} (which the tokens read as \mathrm{…})
  const auto group = [&] {  // for the messages only
    return command_token.written.empty() ? command_token.text + "{…}" : std::string("{\\rm …}");
  };
  std::string text;
  while (true) {
    const Token& t = peek_raw();
    if (t.kind == Tok::letter || t.kind == Tok::number) {
      if (t.space_before && !text.empty()) {
        throw error(t, "expected one name in " + group() +
                           ", found words: prose belongs outside the display block");
      }
      text += t.text;
      take();
    } else if (is_char(t, '}')) {
      take();
      break;
    } else if (t.kind == Tok::end) {
      throw error(open, "expected '}' to close this '{'");
    } else {
      const bool unit = is_char(t, '/') || is_char(t, '^') || is_char(t, '.') ||
                        is_command(t, "\\cdot") || t.kind == Tok::spacing;  // m\,s^{-1}
      throw error(t, "expected letters and digits in " + group() + " (a name), found " +
                         describe(t) +
                         (unit ? ": units (m/s, m\\cdot s^{-1}) are not read; write the equation "
                                 "in numbers alone, with units: for the symbols' dimensions"
                               : ""));
    }
  }
  if (text.empty()) {
    throw error(open, "expected a name inside " + group());
  }
  if (text[0] >= '0' && text[0] <= '9') {
    throw error(open, "expected a name beginning with a letter inside " + group() + ", found " +
                          text + " (a number is written without it)");
  }
  return text;
}

// decorations := {'_' subscript | ["\,"] "'" | '^' ('\prime' | '{' prime {prime} '}')}
// prime := '\prime' | "'"   (v^{'} as v^{\prime})
// ("\," before a prime of an accented symbol only: \vec p\,')
// (subscript and primes in either order: p_1', p'_1, p_{1}')
Node Grammar::decorate(std::size_t depth, Node n) {
  while (true) {
    const Token& t = peek_raw();
    if (is_char(t, '_')) {
      if (!n.symbol.subscript.empty()) {
        throw error(t, "expected one subscript, found a second '_'");
      }
      take();
      n.symbol.subscript = subscript(depth);
    } else if (n.symbol.accent && is(t, Tok::spacing, "\\,") &&
               is_char(token(position_ + 1), '\'')) {
      skip_spacing();  // \vec p\,': the thin space keeps the prime off the arrow
    } else if (is_char(t, '\'')) {
      take();
      ++n.symbol.primes;
    } else if (is_char(t, '^') && primes_follow()) {
      take();
      n.symbol.primes += read_prime_script();
    } else if (is_char(t, '^') && is_char(token(position_ + 1), '{') &&
               (is_command(token(position_ + 2), "\\prime") ||
                is_char(token(position_ + 2), '\''))) {
      throw error(token(position_ + 2),
                  "expected only primes in ^{…} after a symbol: a prime and a power in one "
                  "superscript (v^{\\prime 2}); write {v'}^{2} for the square of v'");
    } else {
      break;
    }
  }
  n.end = last_end_;
  return n;
}

bool Grammar::primes_follow() const {
  const Token& next = token(position_ + 1);
  if (is_command(next, "\\prime")) {
    return true;
  }
  if (is_char(next, '{')) {
    std::size_t k = position_ + 2;
    bool any = false;
    while (is_command(token(k), "\\prime") || is_char(token(k), '\'') ||
           token(k).kind == Tok::spacing) {
      any = any || token(k).kind != Tok::spacing;
      ++k;
    }
    return any && is_char(token(k), '}');
  }
  return false;
}

int Grammar::read_prime_script() {
  if (is_command(peek_raw(), "\\prime")) {
    take();
    return 1;
  }
  take();  // {
  int count = 0;
  while (is_command(peek(), "\\prime") || is_char(peek(), '\'')) {
    take();
    ++count;
  }
  take();  // }
  return count;
}

namespace {

// \max and \min, which LaTeX sets upright as operator names, read in a subscript as the words
// they print (v_{\max} is v_\text{max}); nothing else.
std::optional<std::string> subscript_word(const Token& t) {
  if (t.kind == Tok::command && (t.text == "\\max" || t.text == "\\min")) {
    return t.text.substr(1);
  }
  return std::nullopt;
}

}  // namespace

// subscript := letter | digit | greek | '\perp' | '\parallel' | '\max' | '\min'
//            | name-command '{' name '}'
//            | '{' {letter | digit | greek | '\max' | '\min' | name-command '{' name '}' | ','
//                   | '(' | ')'} '}'
std::string Grammar::subscript(std::size_t depth) {
  const Token& t = peek_raw();
  if (t.kind == Tok::letter) {
    return take().text;
  }
  if (const std::optional<std::string> word = subscript_word(t)) {
    take();
    return *word;
  }
  if (t.kind == Tok::number) {
    return single_digit(t, true).text;
  }
  if (t.kind == Tok::command &&
      (commands::greek.contains(t.text) || t.text == "\\perp" || t.text == "\\parallel")) {
    return take().text;
  }
  if (t.kind == Tok::command && commands::names.contains(t.text)) {
    const Token command_token = take();  // v_\text{rel}
    return name_group(command_token);
  }
  if (!is_char(t, '{')) {
    throw error(t,
                "expected a subscript after '_' (a letter, a digit or {…}), found " + describe(t));
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
    } else if (s.kind == Tok::command &&
               (commands::greek.contains(s.text) || s.text == "\\perp" || s.text == "\\parallel")) {
      text += take().text;
      after_command = true;
    } else if (s.kind == Tok::command && commands::names.contains(s.text)) {
      const Token command_token = take();
      if (after_command) {
        text += ' ';
      }
      text += name_group(command_token);
      after_command = false;
    } else if (const std::optional<std::string> word = subscript_word(s)) {
      take();
      if (after_command) {
        text += ' ';
      }
      text += *word;
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

}  // namespace impulse::derivations::file
