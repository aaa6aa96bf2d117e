// SPDX-License-Identifier: GPL-3.0-or-later
// The grammar of the big operators: sums and products over an index, and integrals with their
// limits and their differential. Each takes the rest of its term as its argument.
#include "file/grammar.hpp"

#include <optional>

namespace impulse::derivations::file {

namespace {

// The symbol dt, dt', dt'': the differential of t, t', t''.
bool is_dt(const Node& n) {
  return n.kind == NodeKind::symbol && n.symbol.base == "dt" && n.symbol.subscript.empty() &&
         !n.symbol.delta && !n.symbol.differential && !n.symbol.accent;
}

}  // namespace

// big := sum-op | integral
Node Grammar::big(std::size_t depth) {
  const Token op = take();
  if (is_command(op, "\\sum") || is_command(op, "\\prod")) {
    return sum_over(depth, op);
  }
  return integral(depth, op);
}

// sum-op := ('\sum' | '\prod') '_' index-spec ['^' script] term
//         | ('\sum' | '\prod') '^' script '_' index-spec term
// index-spec := letter | '{' letter ['=' expression] '}'
// (\sum_i runs over the range index: declares; \sum_{i=1}^{N} from 1 to N)
Node Grammar::sum_over(std::size_t depth, const Token& op) {
  const std::string word = op.text;
  Node n = make(op.text == "\\sum" ? NodeKind::sum_over : NodeKind::product_over, op.offset);
  std::optional<Node> lower;
  std::optional<Node> upper;
  bool index_read = false;
  for (int k = 0; k < 2; ++k) {
    if (is_char(peek(), '_') && !index_read) {
      take();
      index_read = true;
      const Token& at = peek_raw();
      if (at.kind == Tok::letter) {
        n.text = take().text;
        continue;
      }
      if (!is_char(at, '{')) {
        throw error(at, "expected one letter as the index of " + word + ", found " + describe(at));
      }
      const Token open = take();
      if (peek().kind != Tok::letter) {
        throw error(peek(),
                    "expected one letter as the index of " + word + ", found " + describe(peek()));
      }
      n.text = take().text;
      if (is_char(peek(), '=')) {
        take();
        lower = expression(depth + 1);
      } else if (!is_char(peek(), '}')) {
        throw error(peek(), "expected '}' or '= start' after the index " + n.text + " of " + word +
                                " (\\sum_{i=1}^{N}), found " + describe(peek()));
      }
      expect_char('}', open, "index of " + word);
    } else if (is_char(peek(), '^') && !upper) {
      const Token mark = take();
      upper = script(depth + 1, mark);
    }
  }
  if (!index_read) {
    throw error(peek(),
                "expected " + word + "_i or " + word + "_{i=1}^{N}: a subscript naming the index");
  }
  if (lower.has_value() != upper.has_value()) {
    throw error(op, "expected both limits of " + word + ", " + word + "_{" + n.text +
                        "=1}^{N}, or none (" + word + "_" + n.text +
                        ": the range declared with index:)");
  }
  if (!starts_atom(peek()) && !big_operator(peek())) {
    throw error(peek(), "expected what " + word + "_" + n.text + " runs over after it");
  }
  const Token first = peek();
  n.children.push_back(term(depth + 1));
  const Node& body = n.children.back();
  if (n.kind == NodeKind::product_over && body.kind == NodeKind::product &&
      body.children.size() > 1 &&
      (body.children.back().kind == NodeKind::product_over ||
       body.children.back().kind == NodeKind::sum_over)) {
    // \prod_i i \prod_j j: the second inside the first (its value to the N-th power: 72 for
    // 2! 3!, which followed) or beside it? (A sum may hold another: the value is the same.)
    throw error(first,
                "expected parentheses around the first product: " + word + "_" + n.text +
                    " takes the rest of the term, so the " +
                    (body.children.back().kind == NodeKind::product_over ? "product" : "sum") +
                    " after it would be inside it, and count once for each " + n.text +
                    "; write \\left(\\prod_i a_i\\right) \\prod_j b_j for two "
                    "products side by side");
  }
  if (lower) {
    n.children.push_back(std::move(*lower));
    n.children.push_back(std::move(*upper));
    n.ops = "lu";
  }
  n.end = last_end_;
  return n;
}

// integral := '\int' ['_' (path | script)] ['^' script] integrand
// integrand := term ending in its differential: dt, d u, \mathrm{d}u (taken from the term, the
// variable noted); without one the term is a 1-form that holds dt (the paper's files)
Node Grammar::integral(std::size_t depth, const Token& op) {
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
  std::optional<Token> minus;  // \int_{x_1}^{x_2} -k x\, dx
  if (is_char(peek(), '-')) {
    minus = take();
  }
  if (!starts_atom(peek()) && !big_operator(peek())) {
    throw error(peek(),
                "expected the integrand after \\int (ending in its differential: dt, dx, …)");
  }
  if (is_command(peek(), "\\int")) {
    // \int_0^T \int_0^s 1\,dt\,ds: the inner integral took the last differential, ds, and the
    // outer one none, which read s T for T²/2.
    throw error(peek(),
                "expected the inner integral in parentheses: \\int_0^T \\left(\\int_0^s f\\,dt"
                "\\right) ds; written one after the other, which differential belongs to which "
                "integral is not read");
  }
  ++integrand_;
  n.children.push_back(term(depth + 1));
  --integrand_;
  if (path) {
    if (upper) {
      throw error(op, "expected no upper limit on an integral along a path (\\int_{\\mathcal{A}})");
    }
    n.ops += 'p';
  } else {
    take_differential(n);
  }
  if (minus) {
    Node negated = make(NodeKind::sum, minus->offset);
    negated.children.push_back(std::move(n.children[0]));
    negated.ops.push_back('-');
    negated.end = negated.children[0].end;
    n.children[0] = std::move(negated);
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

// The differential at the end of an integrand, taken from it: its variable goes to the node.
void Grammar::take_differential(Node& n) {
  Node& integrand = n.children[0];
  const auto one = [&](std::size_t offset) {
    Node unit = make(NodeKind::number, offset);
    unit.text = "1";
    return unit;
  };
  if (is_dt(integrand)) {  // \int_0^T dt
    n.symbol = SymbolName{"t", "", integrand.symbol.primes, false};
    n.ops += 'd';
    integrand = one(integrand.offset);
    return;
  }
  if (integrand.kind != NodeKind::product || integrand.ops.back() != ' ') {
    return;
  }
  const std::size_t count = integrand.children.size();
  if (is_dt(integrand.children.back())) {
    n.symbol = SymbolName{"t", "", integrand.children.back().symbol.primes, false};
    integrand.children.pop_back();
    integrand.ops.pop_back();
  } else if (count >= 2 && is_plain_d(integrand.children[count - 2]) &&
             integrand.children.back().kind == NodeKind::symbol &&
             integrand.ops[count - 2] == ' ') {
    n.symbol = integrand.children.back().symbol;
    integrand.children.resize(count - 2);
    integrand.ops.resize(count - 2);
  } else {
    return;
  }
  n.ops += 'd';
  if (integrand.children.empty()) {
    integrand = one(n.offset);
  } else if (integrand.children.size() == 1) {
    Node only = std::move(integrand.children[0]);
    integrand = std::move(only);
  }
}

// path := '\mathcal' '{' letter '}' | '{' '\mathcal' '{' letter '}' '}'
// (the path a point travels during the contact, the paper's \int_{\mathcal{A}})
bool Grammar::path_domain() {
  skip_spacing();
  std::size_t at = position_;
  const bool braced = is_char(token(at), '{');
  if (braced) {
    ++at;
    while (token(at).kind == Tok::spacing) {
      ++at;
    }
  }
  if (!is_command(token(at), "\\mathcal")) {
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

}  // namespace impulse::derivations::file
