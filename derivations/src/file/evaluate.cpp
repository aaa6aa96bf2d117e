// SPDX-License-Identifier: GPL-3.0-or-later
// What a tree means: a GiNaC expression (or a vector, or a block) for each kind of node, one
// method each, with the denominators the expression divides by. The variables of the integrals,
// derivatives and sums a node stands inside are bound: F(t) inside an integral over t is F of
// t when F is a declared function, and refused otherwise (F times t, or F of t?).
#include <algorithm>

#include "file/calculus.hpp"
#include "file/meaning.hpp"
#include "file/time.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

numeric decimal(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) {
    return numeric(text.c_str());
  }
  const std::string digits = text.substr(0, dot) + text.substr(dot + 1);
  const std::string integer = digits.find_first_not_of('0') == std::string::npos
                                  ? "0"
                                  : digits.substr(digits.find_first_not_of('0'));
  return numeric(integer.c_str()) /
         GiNaC::pow(numeric(10), numeric(static_cast<long>(text.size() - dot - 1)));
}

std::string kind_name(const Value& v) {
  if (v.block()) {
    return v.cols > 1 ? "a matrix" : "a column";
  }
  return v.vector ? "a vector" : "a scalar";
}

Value negated(Value v) {
  v.x = -v.x;
  v.y = -v.y;
  for (ex& e : v.entries) {
    e = -e;
  }
  return v;
}

Value scaled_value(const Value& v, const ex& k) {
  Value r = v;
  r.x = v.x * k;
  r.y = v.vector ? v.y * k : ex(0);
  for (ex& e : r.entries) {
    e = e * k;
  }
  return r;
}

// Applies f to each scalar of a value (both components of a vector).
Value each_component(const Value& v, const std::function<ex(const ex&)>& f) {
  Value r = v;
  r.x = f(v.x);
  if (v.vector) {
    r.y = f(v.y);
  }
  for (ex& e : r.entries) {
    e = f(e);
  }
  return r;
}

bool all_digits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool whole(const ex& e) {
  return GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_integer();
}

}  // namespace

std::vector<std::pair<Node, char>> Symbols::factors(const Node& product) const {
  std::vector<std::pair<Node, char>> factors;
  for (std::size_t i = 0; i < product.children.size(); ++i) {
    const Node& c = product.children[i];
    const bool d = c.kind == NodeKind::symbol && c.symbol.base == "d" &&
                   c.symbol.subscript.empty() && c.symbol.primes == 0 && !c.symbol.delta;
    const bool upright = d && c.text == upright_d;
    const Node* next = i + 1 < product.children.size() && product.ops[i + 1] == ' ' &&
                               product.children[i + 1].kind == NodeKind::symbol &&
                               !product.children[i + 1].symbol.differential
                           ? &product.children[i + 1]
                           : nullptr;
    if (upright && next == nullptr) {
      throw error(c.offset,
                  "expected a symbol after \\mathrm{d}: the differential of a symbol "
                  "(\\mathrm{d}p) is one symbol, of an expression it is not read; name the "
                  "expression with let: and take the differential of that name");
    }
    if (upright && function(next->symbol) != nullptr) {
      const std::string f = resolve(next->symbol).latex();
      throw error(next->offset,
                  "expected a symbol that is not a function after \\mathrm{d}: " + f +
                      " is declared a function, and \\mathrm{d}" + f +
                      " would be a symbol unrelated to it; write its derivative times the "
                      "differential, \\frac{\\mathrm{d}" +
                      f + "}{\\mathrm{d}t}\\,\\mathrm{d}t");
    }
    const bool merged =
        d && next != nullptr &&
        (upright ? !is_vector(resolve(next->symbol))
                 : differentials_.contains(resolve(next->symbol).unprimed().latex()));
    if (merged) {
      Node differential = *next;
      differential.symbol.differential = true;
      differential.offset = c.offset;
      // The differential of t written apart ({\mathrm{d}}t, \mathrm{d}\,t) is dt, the symbol
      // that \mathrm{d}t and dt written together are.
      const SymbolName& t = next->symbol;
      if (t.base == "t" && t.subscript.empty() && !t.delta && !t.arrow) {
        differential.symbol = SymbolName{"dt", "", t.primes, false};
      }
      factors.emplace_back(std::move(differential), product.ops[i]);
      ++i;
      continue;
    }
    factors.emplace_back(c, product.ops[i]);
  }
  return factors;
}

std::vector<std::pair<Node, char>> Symbols::expanded_terms(const Node& sum) {
  std::vector<std::pair<Node, char>> terms;
  for (std::size_t i = 0; i < sum.children.size(); ++i) {
    terms.emplace_back(sum.children[i], sum.ops[i]);
  }
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (terms[i].first.kind != NodeKind::dots) {
      continue;
    }
    // A_2 + \cdots + A_M: the terms A_3 … A_{M-1}, M a number or a symbol defined as one.
    const std::size_t at = terms[i].first.offset;
    Node& left = terms[i - 1].first;
    Node& right = terms[i + 1].first;
    if (left.kind != NodeKind::symbol || right.kind != NodeKind::symbol ||
        left.symbol.base != right.symbol.base) {
      throw error(at,
                  "expected \\cdots between two terms of one name with numbered subscripts "
                  "(A_2 + \\cdots + A_M)");
    }
    const auto number = [&](const std::string& sub) -> std::optional<long> {
      if (all_digits(sub) && sub.size() < 6) {
        return std::stol(sub);
      }
      if (sub.size() == 1) {
        const ex v = scalar(SymbolName{sub, "", 0, false}).subs(substitutions_);
        if (GiNaC::is_a<numeric>(v) && GiNaC::ex_to<numeric>(v).is_integer() &&
            GiNaC::abs(GiNaC::ex_to<numeric>(v)) < 1000) {
          return GiNaC::ex_to<numeric>(v).to_long();
        }
      }
      return std::nullopt;
    };
    const auto from = number(left.symbol.subscript);
    const auto to = number(right.symbol.subscript);
    if (!from || !to || *to <= *from) {
      throw error(at,
                  "expected \\cdots between numbered terms (A_2 + \\cdots + A_M, with M "
                  "a number or defined by let: as one, larger than 2)");
    }
    right.symbol.subscript = std::to_string(*to);
    std::vector<std::pair<Node, char>> between;
    for (long k = *from + 1; k < *to; ++k) {
      Node term = left;
      term.symbol.subscript = std::to_string(k);
      term.offset = at;
      between.emplace_back(std::move(term), '+');
    }
    terms.erase(terms.begin() + static_cast<std::ptrdiff_t>(i));
    terms.insert(terms.begin() + static_cast<std::ptrdiff_t>(i), between.begin(), between.end());
    i += between.size();
  }
  return terms;
}

Value Symbols::block_product(const Value& a, const Value& b, char op, std::size_t offset,
                             std::vector<ex>& denominators) const {
  if (op == '/') {
    if (b.vector || b.block()) {
      throw error(offset, "expected a number to divide by, found " + kind_name(b));
    }
    denominators.push_back(b.x);
    return scaled_value(a, 1 / b.x);
  }
  if (a.vector || b.vector) {
    throw error(offset, "expected a number or a block with a block, found a vector");
  }
  if (!a.block()) {
    return scaled_value(b, a.x);
  }
  if (!b.block()) {
    return scaled_value(a, b.x);
  }
  if (a.cols != b.rows) {
    throw error(offset, "expected blocks that multiply: " + std::to_string(a.rows) + " by " +
                            std::to_string(a.cols) + " times " + std::to_string(b.rows) + " by " +
                            std::to_string(b.cols));
  }
  Value r;
  r.rows = a.rows;
  r.cols = b.cols;
  for (std::size_t i = 0; i < a.rows; ++i) {
    for (std::size_t j = 0; j < b.cols; ++j) {
      ex sum = 0;
      for (std::size_t k = 0; k < a.cols; ++k) {
        sum += a.entries[i * a.cols + k] * b.entries[k * b.cols + j];
      }
      r.entries.push_back(sum);
    }
  }
  return r;
}

namespace {

// \dot x or \ddot x of a declared function x: the declaration and the order of the derivative.
std::optional<std::pair<const FunctionDeclaration*, unsigned>> dotted_of(const Symbols& symbols,
                                                                         const SymbolName& name) {
  const bool dot = name.base.starts_with("\\dot{");
  const bool ddot = name.base.starts_with("\\ddot{");
  if (!dot && !ddot) {
    return std::nullopt;
  }
  SymbolName under = name;
  under.base = name.base.substr(dot ? 5 : 6, name.base.size() - (dot ? 6 : 7));
  const FunctionDeclaration* f = symbols.function(under);
  if (f == nullptr) {
    return std::nullopt;
  }
  return std::pair{f, dot ? 1U : 2U};
}

// The letter alone: no subscript, prime, accent, Δ or differential (e, i).
bool plain_letter(const Node& n, std::string_view letter) {
  return n.kind == NodeKind::symbol && n.symbol.base == letter && n.symbol.subscript.empty() &&
         n.symbol.primes == 0 && !n.symbol.accent && !n.symbol.delta && !n.symbol.differential;
}

}  // namespace

class Evaluator {
 public:
  explicit Evaluator(Symbols& symbols) : s_(symbols) {}

  Meaning run(const Node& node) {
    Value value = eval(node);
    return {std::move(value), std::move(denominators_), std::move(written_)};
  }

 private:
  // A variable bound by an enclosing integral, derivative or sum: its name, and what it stands
  // for inside (the file's symbol, or a value of a sum's index).
  struct Bound {
    std::string key;
    ex value;
  };

  ReadError error(std::size_t offset, const std::string& message) const {
    return s_.error(offset, message);
  }

  Value unblocked(Value v, std::size_t at) const {
    if (v.block()) {
      throw error(at, "expected a number or a vector here, found " + kind_name(v));
    }
    return v;
  }

  ex scalar_of(const Node& n) {
    const Value v = unblocked(eval(n), n.offset);
    if (v.vector) {
      throw error(n.offset, "expected a number here, found a vector");
    }
    return v.x;
  }

  // A denominator no one wrote (the cosine under a tangent): shown as computed.
  void divides_by(const ex& d) {
    denominators_.push_back(d);
    written_.emplace_back();
  }

  void divides_by(const ex& d, const Node& written) {
    denominators_.push_back(d);
    written_.push_back(s_.written(written));
  }

  // The denominators written inside an integral (or a sum) that hold its variable: the
  // variable is bound there, so they are no condition on the step's symbols (whether the
  // integrand is finite between the limits is integrate()'s question).
  void forget_denominators(std::size_t from, const ex& variable) {
    for (std::size_t k = denominators_.size(); k-- > from;) {
      if (denominators_[k].has(variable)) {
        denominators_.erase(denominators_.begin() + static_cast<std::ptrdiff_t>(k));
        written_.erase(written_.begin() + static_cast<std::ptrdiff_t>(k));
      }
    }
  }

  const Bound* bound(const SymbolName& name) const {
    const std::string key = s_.resolve(name).latex();
    for (auto b = bound_.rbegin(); b != bound_.rend(); ++b) {
      if (b->key == key) {
        return &*b;
      }
    }
    return nullptr;
  }

  struct Binding {
    Evaluator& evaluator;
    Binding(Evaluator& e, const SymbolName& name, const ex& value) : evaluator(e) {
      e.bound_.push_back({e.s_.resolve(name).latex(), value});
    }
    ~Binding() { evaluator.bound_.pop_back(); }
    Binding(const Binding&) = delete;
    Binding& operator=(const Binding&) = delete;
  };

  Value eval(const Node& n) {
    try {
      return dispatch(n);
    } catch (const ReadError&) {
      throw;
    } catch (const std::exception& e) {
      // GiNaC refuses 1/0 and the like when it builds the expression.
      const std::string what = e.what();
      throw error(n.offset, what.find("division by zero") != std::string::npos
                                ? "expected an expression that can be evaluated, found a "
                                  "division by zero"
                                : "expected an expression that can be evaluated (" + what + ")");
    }
  }

  Value dispatch(const Node& n) {
    switch (n.kind) {
      case NodeKind::number:
        return {false, decimal(n.text), 0};
      case NodeKind::pi:
        return {false, GiNaC::Pi, 0};
      case NodeKind::symbol:
        return symbol(n);
      case NodeKind::sum:
        return sum(n);
      case NodeKind::product:
        return product(n);
      case NodeKind::fraction:
        return fraction(n);
      case NodeKind::power:
        return power(n);
      case NodeKind::function:
        return function(n);
      case NodeKind::root:
        return root(n);
      case NodeKind::norm:
      case NodeKind::abs:
        return size(n);
      case NodeKind::det:
        return det(n);
      case NodeKind::vector:
        return vector(n);
      case NodeKind::sum_over:
      case NodeKind::product_over:
        return over_index(n);
      case NodeKind::integral:
        return integral(n);
      case NodeKind::bar:
        return bar(n);
      case NodeKind::call:
        return call(n);
      case NodeKind::derivative:
        return derivative(n);
      case NodeKind::factorial:
        return factorial(n);
      case NodeKind::dots:
        throw error(n.offset, "expected \\cdots between two terms of a sum");
    }
    throw error(n.offset, "expected an expression");
  }

  // ---- symbols and functions ----

  Value symbol(const Node& n) {
    const SymbolName name = s_.resolve(n.symbol);
    if (const Bound* b = bound(name)) {
      return {false, b->value, 0};
    }
    if (const auto block = s_.blocks_.find(name.unprimed().latex()); block != s_.blocks_.end()) {
      return s_.block_value(block->second, n.offset, [this](const Node& x) { return eval(x); });
    }
    if (const FunctionDeclaration* f = s_.function(name)) {
      // F alone is F of its variable: F(t).
      std::vector<ex> arguments;
      for (const SymbolName& v : f->variables) {
        const Bound* b = bound(v);
        arguments.push_back(b != nullptr ? b->value : s_.scalar(v));
      }
      return {false, GiNaC::function(f->serial, GiNaC::exvector(arguments)), 0};
    }
    if (const auto dotted = dotted_function(name)) {
      return {false, *dotted, 0};
    }
    if ((name.base.starts_with("\\dot{") || name.base.starts_with("\\ddot{")) &&
        !s_.is_quantity(name)) {
      // \dot E of an E not declared a function was a symbol unrelated to E: E = m \dot x^2 / 2
      // then \dot E = m \dot x \ddot x failed.
      const std::string under =
          name.base.substr(name.base.find('{') + 1, name.base.size() - name.base.find('{') - 2);
      throw error(n.offset, "expected " + under + " declared a function (function: " + under +
                                ") under " + name.latex() + ": its derivative in t; as it is, " +
                                name.latex() + " would be a symbol of its own, unrelated to " +
                                under);
    }
    if (plain_letter(n, "e") && n.text == upright_e) {
      return {false, GiNaC::exp(ex(1)), 0};  // \mathrm{e}: Euler's number
    }
    if (plain_letter(n, "i") && !s_.is_quantity(name)) {
      // A real i times b would pass |a + i b|^2 = (a + i b)^2, which no complex number obeys.
      throw error(n.offset,
                  "expected real numbers: i could be the imaginary unit, which this checker does "
                  "not read (write a complex equation as two, its real and imaginary parts), or "
                  "a real quantity i (then say so with a fact, assume: i > 0, or name it "
                  "otherwise)");
    }
    refuse_accent_and_bare(n);
    refuse_two_forms(n);
    return s_.symbol_value(n.symbol);
  }

  // \epsilon and \varepsilon (\theta and \vartheta, \phi and \varphi, \rho and \varrho) in one
  // file: two symbols as read, one letter as a student means it (F dt = \epsilon B then
  // F dt = \varepsilon B failed at \epsilon = 1, \varepsilon = -1). Refused where the second
  // form stands.
  void refuse_two_forms(const Node& n) {
    static const std::map<std::string, std::string, std::less<>> plain{
        {"\\varepsilon", "\\epsilon"},
        {"\\vartheta", "\\theta"},
        {"\\varphi", "\\phi"},
        {"\\varrho", "\\rho"},
        {"\\varsigma", "\\sigma"}};
    SymbolName letter = n.symbol;
    if (const auto found = plain.find(letter.base); found != plain.end()) {
      letter.base = found->second;
    }
    const auto [first, fresh] = s_.letter_forms_.try_emplace(letter.latex(), n.symbol.base);
    if (!fresh && first->second != n.symbol.base) {
      throw error(n.offset, "expected one form of the letter: " + first->second + " and " +
                                n.symbol.base +
                                " are two symbols as read, though they are one letter; write "
                                "one of them throughout");
    }
  }

  // \vec v and v of a v not declared a vector are one number here: is v the magnitude of \vec v?
  // (\vec v = \vec u + \vec w then v = u + w followed.) Refused where the second form stands.
  void refuse_accent_and_bare(const Node& n) {
    const SymbolName name = s_.resolve(n.symbol);
    if (name.arrow || s_.is_vector(name) || s_.component_of(name)) {
      return;
    }
    const auto [first, fresh] = s_.accented_.try_emplace(name.latex(), n.symbol.accent);
    if (!fresh && first->second != n.symbol.accent) {
      throw error(n.offset,
                  "expected " + name.latex() +
                      " written one way: it stands with an accent (\\vec, \\hat, \\mathbf) "
                      "and without, and is not declared a vector, so both are one number; if "
                      "the bare letter is the vector's magnitude, declare vector: " +
                      name.latex() + " and write \\|\\vec{" + name.latex() + "}\\| for it");
    }
  }

  // \dot x and \ddot x of a declared function x: its derivatives in t; at @p at when given
  // (\dot x(0)).
  std::optional<ex> dotted_function(const SymbolName& name, const std::optional<ex>& at = {}) {
    const auto dotted = dotted_of(s_, name);
    if (!dotted) {
      return std::nullopt;  // \dot x of a number x is a symbol of its own
    }
    const FunctionDeclaration* f = dotted->first;
    if (f->variables.size() != 1 || f->variables[0].latex() != "t") {
      throw error(0, "expected " + name.base + " of a function of t alone");
    }
    const ex t = s_.scalar(f->variables[0]);
    const ex value =
        GiNaC::function(f->serial, t).diff(GiNaC::ex_to<GiNaC::symbol>(t), dotted->second);
    return at ? value.subs(t == *at) : value;
  }

  // F(t), f(a, b): a declared function's value; m(v_1 - v_2): a product; F(t) with t the
  // variable of an enclosing integral, derivative or sum, F not declared: refused.
  Value call(const Node& n) {
    const Node& name_node = n.children[0];
    const SymbolName name = s_.resolve(name_node.symbol);
    const std::size_t count = n.children.size() - 1;
    if (const FunctionDeclaration* f = s_.function(name)) {
      if (count != f->variables.size()) {
        throw error(n.offset, "expected " + std::to_string(f->variables.size()) +
                                  " argument(s) of " + name.latex() +
                                  ", as function: declares, "
                                  "found " +
                                  std::to_string(count));
      }
      GiNaC::exvector arguments;
      for (std::size_t k = 1; k < n.children.size(); ++k) {
        arguments.push_back(scalar_of(n.children[k]));
      }
      return {false, GiNaC::function(f->serial, arguments), 0};
    }
    if (count == 1) {
      if (const auto value = dotted_function(name, scalar_of(n.children[1]))) {
        return {false, *value, 0};  // \dot x(0): the derivative at 0
      }
    }
    if (name.primes > 0) {
      SymbolName plain = name;
      plain.primes = 0;
      if (s_.function(plain) != nullptr) {
        throw error(name_node.offset,
                    "expected " + plain.latex() + "(…) or its derivative \\frac{d" + plain.latex() +
                        "}{dt}: " + name.latex() + "(…) could be the derivative of " +
                        plain.latex() +
                        " or another function (declare it with function: to mean that)");
      }
    }
    throw error(n.offset, "expected " + name.latex() + " to be a declared function");
  }

  // ---- sums, products, fractions ----

  Value sum(const Node& n) {
    Value total;
    const std::vector<std::pair<Node, char>> terms = s_.expanded_terms(n);
    for (std::size_t i = 0; i < terms.size(); ++i) {
      Value term = eval(terms[i].first);
      if (terms[i].second == '-') {
        term = negated(std::move(term));
      }
      if (i == 0) {
        total = term;
      } else if (term.vector != total.vector || term.rows != total.rows ||
                 term.cols != total.cols) {
        throw error(terms[i].first.offset, "expected " + kind_name(total) +
                                               " here, as the terms before it, found " +
                                               kind_name(term));
      } else {
        total.x = total.x + term.x;
        total.y = total.y + term.y;
        for (std::size_t k = 0; k < total.entries.size(); ++k) {
          total.entries[k] += term.entries[k];
        }
      }
    }
    if (!total.vector) {
      total.y = 0;
    }
    return total;
  }

  // f^2(t) of a declared function f, and \frac{dx}{dt}(2): (f(t))² or f(f(t)), the derivative at 2
  // or times 2? Read as products they were f(t)² t and 2 dx/dt, and f^2(t) = t^5 followed from
  // f(t) = t^2.
  void refuse_value_after(const Node& before, const Node& group) const {
    if (!group.enclosed) {
      return;
    }
    const bool power_of_function = before.kind == NodeKind::power &&
                                   before.children[0].kind == NodeKind::symbol &&
                                   s_.function(before.children[0].symbol) != nullptr;
    if (power_of_function) {
      throw error(group.offset,
                  "expected parentheses around the function's value before its power: f^2(t) "
                  "could be (f(t))^2 or f(f(t)), and f^{-1}(t) the inverse function; write "
                  "\\left(f(t)\\right)^2");
    }
    if (before.kind == NodeKind::derivative) {
      throw error(group.offset,
                  "expected \\cdot or \\left. … \\right|_{t=2} after a derivative: "
                  "\\frac{dx}{dt}(2) could be the derivative at 2 or the derivative times 2");
    }
    if (before.kind == NodeKind::symbol && s_.function(before.symbol) != nullptr) {
      // f[2] of a declared f: read as f(t) times 2, f(t) = t^2 gave f[2] = 2 t^2.
      const std::string f = before.symbol.latex();
      throw error(group.offset,
                  "expected parentheses for " + f + "'s value, or \\cdot for a product: " + f +
                      " before brackets could be its value at what they hold or " + f +
                      "(t) times it; write " + f + "(2) or " + f + "(t) \\cdot 2");
    }
  }

  Value product(const Node& n) {
    const auto factors = s_.factors(n);
    Value acc = eval(factors[0].first);
    for (std::size_t i = 1; i < factors.size(); ++i) {
      if (factors[i].second == ' ') {
        refuse_value_after(factors[i - 1].first, factors[i].first);
      }
      const Value next = eval(factors[i].first);
      const char op = factors[i].second;
      const std::size_t at = factors[i].first.offset;
      if (acc.block() || next.block()) {
        std::vector<ex> denominators;
        acc = s_.block_product(acc, next, op, at, denominators);
        for (const ex& d : denominators) {
          divides_by(d, factors[i].first);
        }
        continue;
      }
      if (op == '/') {
        if (next.vector) {
          throw error(at, "expected a scalar to divide by, found a vector");
        }
        undeclared_vector(factors[i].first, "as a divisor");
        divides_by(next.x, factors[i].first);
        acc = {acc.vector, acc.x / next.x, acc.vector ? acc.y / next.x : ex(0)};
      } else if (!acc.vector && !next.vector) {
        if (op == '.' || op == 'x') {
          const std::string beside = op == '.' ? "beside \\cdot" : "beside \\times";
          undeclared_vector(factors[i - 1].first, beside);
          undeclared_vector(factors[i].first, beside);
        } else if (op == ' ' && accented(factors[i - 1].first)) {
          undeclared_vector(factors[i].first, "beside another such symbol");  // \vec u \vec a
        }
        acc = {false, acc.x * next.x, 0};
      } else if (acc.vector != next.vector) {
        const Value& scalar = acc.vector ? next : acc;
        const Value& v = acc.vector ? acc : next;
        if (op == 'x' && !GiNaC::is_a<numeric>(scalar.x)) {
          // \omega \times \vec r (the contact point's velocity v + ω × r) was read as ω r: in the
          // plane, ω × r is ω [-r_y, r_x].
          throw error(at,
                      "expected \\cdot or nothing between a scalar and a vector, found "
                      "\\times: the product of the two, or the plane's cross product of an "
                      "angular velocity about the normal to the plane (\\omega \\times \\vec r "
                      "= \\omega [-r_y, r_x])? Write \\omega \\vec r for the one and the "
                      "components for the other");
        }
        acc = {true, scalar.x * v.x, scalar.x * v.y};
      } else if (op == '.') {
        acc = {false, acc.x * next.x + acc.y * next.y, 0};
      } else if (op == 'x') {
        acc = {false, acc.x * next.y - acc.y * next.x, 0};
      } else {
        throw error(at,
                    "expected \\cdot (the dot product) or \\det(\\vec a, \\vec b) "
                    "between two vectors, found them side by side");
      }
    }
    return acc;
  }

  // A symbol written as a vector (\vec a, \hat n, \mathbf a) but not declared one: a number
  // there would stand in silence for a vector where a vector makes the reading another one or
  // none. Beside \cdot or \times, (\vec a \cdot \vec b)^2 = a^2 b^2 would follow; divided by,
  // \vec F = m \vec a would give m = \vec F / \vec a; beside another, \vec u \vec a would be a
  // product of numbers.
  bool accented(const Node& n) const {
    return n.kind == NodeKind::symbol && n.symbol.accent &&
           !s_.component_of(s_.resolve(n.symbol)) && !s_.is_quantity(n.symbol);
  }

  void undeclared_vector(const Node& n, const std::string& where) const {
    if (!accented(n)) {
      return;
    }
    const std::string name = s_.resolve(n.symbol).latex();
    throw error(n.offset, "expected a vector declared with vector:, found " + s_.written(n) + " " +
                              where +
                              ", written as a vector but not declared one (so it would be read "
                              "as a number); declare it (vector: " +
                              name + ")");
  }

  void refuse_accented_inside(const Node& n, const std::string& where) const {
    undeclared_vector(n, where);
    for (const Node& child : n.children) {
      refuse_accented_inside(child, where);
    }
  }

  Value fraction(const Node& n) {
    const Value top = eval(n.children[0]);
    const Value bottom = eval(n.children[1]);
    undeclared_vector(n.children[1], "as a divisor");
    if (bottom.vector || bottom.block()) {
      throw error(n.children[1].offset,
                  "expected a scalar denominator, found " + kind_name(bottom));
    }
    divides_by(bottom.x, n.children[1]);
    return scaled_value(top, 1 / bottom.x);
  }

  Value power(const Node& n) {
    const Node& written_base = n.children[0];
    const bool letter_e = plain_letter(written_base, "e") && bound(written_base.symbol) == nullptr;
    const Value base = unblocked(eval(written_base), written_base.offset);
    const Value exponent = unblocked(eval(n.children[1]), n.children[1].offset);
    if (exponent.vector) {
      throw error(n.children[1].offset, "expected a scalar exponent, found a vector");
    }
    const ex e = exponent.x;
    if (letter_e && written_base.text == upright_e) {
      return {false, GiNaC::exp(e), 0};  // \mathrm{e}^{x}: the exponential
    }
    if (letter_e && !GiNaC::is_a<numeric>(e) && !s_.is_quantity(written_base.symbol)) {
      // e^{-t/\tau} read as a letter to a power: its derivative held ln(e), and right steps
      // failed with e = 1 as the counterexample.
      throw error(written_base.offset,
                  "e^{…}: Euler's number to a power (the exponential), or a quantity e (a "
                  "coefficient of restitution) to a power? Write \\exp(…) or \\mathrm{e}^{…} "
                  "for the exponential; for the quantity, give a fact of it (assume: 0 \\le e "
                  "\\le 1)");
    }
    if (GiNaC::is_a<numeric>(e)) {
      const numeric k = GiNaC::ex_to<numeric>(e);
      if (k.is_integer() && GiNaC::abs(k) > s_.limits_.exponent) {
        throw error(n.children[1].offset, "expected an exponent of at most " +
                                              std::to_string(s_.limits_.exponent) +
                                              " (this checker's limit)");
      }
      if (GiNaC::is_a<numeric>(base.x) && k.is_integer()) {
        const numeric b = GiNaC::ex_to<numeric>(base.x);
        const long bits = b.numer().int_length() + b.denom().int_length();
        if (GiNaC::abs(k).to_long() * bits > 40000) {
          throw error(n.offset,
                      "expected a number of at most about 12,000 digits "
                      "(this checker's limit)");
        }
      }
      // x^0 is 1 only where x ≠ 0 (0^0 is not defined), as x^{-1} is defined there alone.
      if ((k.is_negative() || k.is_zero()) && !base.vector) {
        divides_by(base.x, n.children[0]);
      }
    }
    if (base.vector) {
      if (!(GiNaC::is_a<numeric>(e) && e == 2)) {
        throw error(n.children[1].offset,
                    "expected the power 2 of a vector (its dot product with itself)");
      }
      return {false, base.x * base.x + base.y * base.y, 0};
    }
    return {false, GiNaC::pow(base.x, e), 0};
  }

  Value function(const Node& n) {
    const ex a = scalar_of(n.children[0]);
    const std::string& f = n.text;
    if (f == "sin") {
      return {false, GiNaC::sin(a), 0};
    }
    if (f == "cos") {
      return {false, GiNaC::cos(a), 0};
    }
    if (f == "tan") {
      divides_by(GiNaC::cos(a));
      return {false, GiNaC::tan(a), 0};
    }
    if (f == "cot" || f == "csc") {
      divides_by(GiNaC::sin(a));
      return {false, f == "cot" ? GiNaC::cos(a) / GiNaC::sin(a) : 1 / GiNaC::sin(a), 0};
    }
    if (f == "sec") {
      divides_by(GiNaC::cos(a));
      return {false, 1 / GiNaC::cos(a), 0};
    }
    if (f == "arcsin" || f == "arccsc") {
      if (f == "arccsc") {
        divides_by(a, n.children[0]);
      }
      return {false, GiNaC::asin(f == "arcsin" ? a : 1 / a), 0};
    }
    if (f == "arccos" || f == "arcsec") {
      if (f == "arcsec") {
        divides_by(a, n.children[0]);
      }
      return {false, GiNaC::acos(f == "arccos" ? a : 1 / a), 0};
    }
    if (f == "arctan") {
      return {false, GiNaC::atan(a), 0};
    }
    if (f == "arccot") {
      divides_by(a, n.children[0]);
      return {false, GiNaC::atan(1 / a), 0};
    }
    if (f == "sinh") {
      return {false, GiNaC::sinh(a), 0};
    }
    if (f == "cosh") {
      return {false, GiNaC::cosh(a), 0};
    }
    if (f == "tanh") {
      return {false, GiNaC::tanh(a), 0};
    }
    if (f == "exp") {
      return {false, GiNaC::exp(a), 0};
    }
    if (f == "log") {
      const ex base = scalar_of(n.children[1]);
      divides_by(GiNaC::log(base));
      return {false, GiNaC::log(a) / GiNaC::log(base), 0};
    }
    return {false, GiNaC::log(a), 0};
  }

  Value root(const Node& n) {
    const Value radicand = unblocked(eval(n.children[0]), n.children[0].offset);
    if (radicand.vector) {
      throw error(n.children[0].offset, "expected a scalar under the root, found a vector");
    }
    if (n.children.size() == 1) {
      return {false, GiNaC::sqrt(radicand.x), 0};
    }
    const Value index = unblocked(eval(n.children[1]), n.children[1].offset);
    if (index.vector || !GiNaC::is_a<numeric>(index.x) ||
        !GiNaC::ex_to<numeric>(index.x).is_pos_integer() || index.x == 1 ||
        GiNaC::ex_to<numeric>(index.x) > 1000) {
      throw error(n.children[1].offset,
                  "expected a whole number from 2 to 1000 as the index of the root");
    }
    return {false, GiNaC::pow(radicand.x, 1 / index.x), 0};
  }

  // \|v\| and |x| (|v| of a vector is its length too).
  Value size(const Node& n) {
    const Value v = unblocked(eval(n.children[0]), n.children[0].offset);
    if (!v.vector) {
      // |\vec v| of an undeclared \vec v = 3\hat i + 4\hat j: the size of a number, 5 failing.
      refuse_accented_inside(n.children[0], "inside |…|");
    }
    if (n.kind == NodeKind::norm && !v.vector) {
      throw error(n.offset, "expected a vector inside \\| \\| (for a scalar write |x|)");
    }
    if (v.vector) {
      return {false, GiNaC::sqrt(v.x * v.x + v.y * v.y), 0};
    }
    return {false, GiNaC::abs(v.x), 0};
  }

  Value det(const Node& n) {
    const Value a = unblocked(eval(n.children[0]), n.children[0].offset);
    const Value b = unblocked(eval(n.children[1]), n.children[1].offset);
    if (!a.vector || !b.vector) {
      throw error(a.vector ? n.children[1].offset : n.children[0].offset,
                  "expected two vectors in \\det(\\vec a, \\vec b), found a scalar");
    }
    return {false, a.x * b.y - a.y * b.x, 0};
  }

  Value vector(const Node& n) {
    const Value a = unblocked(eval(n.children[0]), n.children[0].offset);
    const Value b = unblocked(eval(n.children[1]), n.children[1].offset);
    if (a.vector || b.vector) {
      throw error(a.vector ? n.children[0].offset : n.children[1].offset,
                  "expected scalar components in [x, y], found a vector");
    }
    return {true, a.x, b.x};
  }

  Value factorial(const Node& n) {
    const ex v = scalar_of(n.children[0]);
    if (!whole(v) || GiNaC::ex_to<numeric>(v).is_negative() || GiNaC::ex_to<numeric>(v) > 1000) {
      throw error(n.offset, "expected the factorial of a whole number from 0 to 1000");
    }
    return {false, GiNaC::factorial(v), 0};
  }

  // ---- calculus ----

  // \sum_i over a declared index, or \sum_{i=a}^{b}: written out when a and b are whole
  // numbers, else kept as a sum over the index (its terms that do not depend on it taken out).
  Value over_index(const Node& n) {
    const bool sum = n.kind == NodeKind::sum_over;
    const std::string word = sum ? "\\sum" : "\\prod";
    if (n.ops.empty()) {
      const auto range = s_.indices_.find(n.text);
      if (range == s_.indices_.end()) {
        throw error(n.offset, "expected the index " + n.text + " of " + word +
                                  " to be declared (index: " + n.text +
                                  " \\in \\{1, 2\\}), or its limits: " + word + "_{" + n.text +
                                  "=1}^{N}");
      }
      return written_out(n, range->second);
    }
    const ex lower = scalar_of(n.children[1]);
    const ex upper = scalar_of(n.children[2]);
    if (whole(lower) && whole(upper)) {
      const long from = GiNaC::ex_to<numeric>(lower).to_long();
      const long to = GiNaC::ex_to<numeric>(upper).to_long();
      if (to - from > 1000) {
        throw error(n.offset, "expected at most 1000 terms in " + word + " (this checker's limit)");
      }
      std::vector<long> values;
      for (long k = from; k <= to; ++k) {
        values.push_back(k);
      }
      return written_out(n, values);
    }
    const bool letter_plus_number = GiNaC::is_a<GiNaC::add>(upper) && upper.nops() == 2 &&
                                    GiNaC::is_a<GiNaC::symbol>(upper.op(0)) && whole(upper.op(1));
    if (!GiNaC::is_a<GiNaC::symbol>(upper) && !whole(upper) && !letter_plus_number) {
      throw error(n.children[2].offset,
                  "expected a whole number, a symbol (the number of terms, N) or a symbol plus "
                  "a whole number (N - 1) as the upper limit of " +
                      word);
    }
    if (!whole(lower) && !GiNaC::is_a<GiNaC::symbol>(lower)) {
      throw error(n.children[1].offset,
                  "expected a whole number or a symbol as the lower limit of " + word);
    }
    s_.counts_.emplace_back(upper, lower);
    const SymbolName index_name{n.text, "", 0, false};
    const ex index = s_.scalar(index_name);
    Value body;
    {
      const Binding binding(*this, index_name, index);
      const std::size_t before = denominators_.size();
      body = unblocked(eval(n.children[0]), n.children[0].offset);
      forget_denominators(before, index);
    }
    const auto depends = [&](const ex& e) {
      for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (GiNaC::is_a<GiNaC::symbol>(*i) && (i->is_equal(index) || s_.indexed_by(*i, index))) {
          return true;
        }
      }
      return false;
    };
    return each_component(body, [&](const ex& b) {
      return sum ? sum_over(b, index, lower, upper, depends)
                 : file::product_over(b, index, lower, upper, depends);
    });
  }

  Value written_out(const Node& n, const std::vector<long>& values) {
    const bool sum = n.kind == NodeKind::sum_over;
    const SymbolName index_name{n.text, "", 0, false};
    Value total;
    for (std::size_t k = 0; k < values.size(); ++k) {
      Value term;
      {
        const Binding binding(*this, index_name, values[k]);
        term = eval(with_index(n.children[0], n.text, values[k]));
      }
      if (k == 0) {
        total = term;
        continue;
      }
      if (term.vector != total.vector || term.rows != total.rows) {
        throw error(n.offset, "expected the terms of the sum to be of one kind");
      }
      if (!sum) {
        if (term.vector || term.block()) {
          throw error(n.offset, "expected numbers as the factors of \\prod");
        }
        total.x *= term.x;
        continue;
      }
      total.x += term.x;
      total.y += term.y;
      for (std::size_t e = 0; e < total.entries.size(); ++e) {
        total.entries[e] += term.entries[e];
      }
    }
    if (values.empty()) {
      total = {false, sum ? ex(0) : ex(1), 0};
    }
    return total;
  }

  // \frac{dF}{dt}, \frac{d}{dt}(…): the derivative of what it holds in the variable; of a
  // symbol declared with `differentials:` (the paper's rates), the quotient of differentials.
  Value derivative(const Node& n) {
    const Node& operand = n.children[0];
    const SymbolName variable_name = n.symbol;
    const auto order = static_cast<unsigned>(std::stoul(n.text));
    if (operand.kind == NodeKind::symbol && order == 1 &&
        s_.differentials_.contains(s_.resolve(operand.symbol).unprimed().latex())) {
      SymbolName d = s_.resolve(operand.symbol);
      d.differential = true;
      const SymbolName dt{"dt", "", variable_name.primes, false};
      if (variable_name.base != "t" || !variable_name.subscript.empty()) {
        throw error(n.offset,
                    "expected a rate in t of the differential d" + operand.symbol.latex());
      }
      const Value top = s_.symbol_value(d);
      const ex bottom = s_.symbol_value(dt).x;
      divides_by(bottom, n);
      return scaled_value(top, 1 / bottom);
    }
    const ex variable = s_.scalar(variable_name);
    Value value;
    {
      const Binding binding(*this, variable_name, variable);
      value = unblocked(eval(operand), operand.offset);
    }
    const auto& x = GiNaC::ex_to<GiNaC::symbol>(variable);
    bool varies = false;
    const auto differentiate = [&](const ex& e) {
      const ex defined = e.subs(s_.substitutions_);
      // (a function of t under d/dx does not vary: dy/dx of y(t) and x(t) would be 0)
      varies = varies || defined.has(variable);
      return defined.diff(x, order);
    };
    Value result = each_component(value, differentiate);
    const bool constant = GiNaC::is_a<numeric>(value.x) && !value.vector && !value.block();
    if (!varies && !constant) {
      throw error(
          n.offset,
          "expected a function of " + variable_name.latex() + " under d/d" + variable_name.latex() +
              ": nothing in " +
              std::string(s_.source_.text().substr(operand.offset, operand.end - operand.offset)) +
              " holds " + variable_name.latex() +
              ", as a symbol or as the variable of a declared function, so its derivative would "
              "be 0; declare the function, e.g. function: " +
              (operand.kind == NodeKind::symbol ? operand.symbol.latex() : std::string("x")) +
              (variable_name.latex() == "t"
                   ? std::string()
                   : "(" + variable_name.latex() +
                         "), or, of functions of t, write the derivatives in t: "
                         "\\frac{dy/dt}{dx/dt}"));
    }
    return result;
  }

  // \int_a^b f du: the integral in the variable of its differential (the paper's time integrals:
  // the forces declared with forces: shaped by the contact's pulse).
  Value integral(const Node& n) {
    const bool differential = n.ops.find('d') != std::string::npos;
    if (!differential) {
      return {false, one_form_integral(n), 0};
    }
    const SymbolName variable_name = n.symbol;
    const ex variable = s_.scalar(variable_name);
    const bool lower_written = n.ops.find('l') != std::string::npos;
    const bool upper_written = n.ops.find('u') != std::string::npos;
    const bool time = variable_name.base == "t" && variable_name.subscript.empty();
    if (!lower_written || (!upper_written && !time)) {
      throw error(n.offset,
                  "expected the limits of the integral, \\int_a^b (an integral without limits "
                  "holds an unknown constant: it is not one side of an equation)");
    }
    s_.integration_variable_ = variable_name;
    Value integrand;
    {
      const Binding binding(*this, variable_name, variable);
      const std::size_t before = denominators_.size();
      integrand = unblocked(eval(n.children[0]), n.children[0].offset);
      forget_denominators(before, variable);
    }
    ex lower = scalar_of(n.children[1]).subs(s_.substitutions_);
    ex upper = 0;
    if (upper_written) {
      upper = scalar_of(n.children[2]).subs(s_.substitutions_);
    } else {
      upper = lower;  // \int_{dt}: over the contact, from 0 to dt
      lower = 0;
    }
    // Inside the contact a force is its mean times the pulse's shape.
    GiNaC::exmap shaped;
    if (time) {
      for (const ex& f : s_.forces_) {
        shaped[f] = f * contact_pulse(variable / pulse_duration());
      }
    }
    return each_component(integrand, [&](const ex& f) {
      const ex form = shaped_outside_integrals(f.subs(s_.substitutions_), shaped);
      return GiNaC::integral(variable, lower, upper, form);
    });
  }

  // An integrand that holds its differential dt (the paper's 1-forms).
  ex one_form_integral(const Node& n) {
    const Value integrand = eval(n.children[0]);
    if (integrand.vector || integrand.block()) {
      throw error(n.offset, "expected a number to integrate, found " + kind_name(integrand));
    }
    ex form = integrand.x.subs(s_.substitutions_);
    // The differential: dt, or dt', dt'' for a variable t', t''.
    std::optional<std::pair<ex, int>> differential;
    for (const auto& [key, symbol] : s_.symbols_) {
      const SymbolInfo& info = s_.infos_.at(symbol);
      if (info.name.base == "dt" && info.name.subscript.empty() && !info.name.delta &&
          !info.name.differential && form.has(symbol)) {
        if (differential) {
          throw error(n.offset,
                      "expected one differential in the integrand (dt or dt'), found two");
        }
        differential = std::pair{symbol, info.name.primes};
      }
    }
    if (!differential && n.ops.find('p') != std::string::npos) {
      throw error(n.offset,
                  "expected the element of the path (\\mathrm{d}S) defined through dt by a let: "
                  "before an integral along a path");
    }
    if (!differential) {
      throw error(n.offset,
                  "expected the integrand to end in its differential (dt, \\mathrm{d}x, d u)");
    }
    const ex delta = differential->first;
    const ex variable = s_.scalar(SymbolName{"t", "", differential->second, false});
    GiNaC::exmap shaped;
    for (const ex& f : s_.forces_) {
      shaped[f] = f * contact_pulse(variable / pulse_duration());
    }
    form = shaped_outside_integrals(form, shaped);  // a nested integral shapes its own
    const ex coefficient = form.diff(GiNaC::ex_to<GiNaC::symbol>(delta));
    if (coefficient.has(delta) || !GiNaC::normal(form - coefficient * delta).is_zero()) {
      throw error(n.offset, "expected an integrand linear in its differential (… dt)");
    }
    const bool lower_written = n.ops.find('l') != std::string::npos;
    const bool upper_written = n.ops.find('u') != std::string::npos;
    if (n.ops.find('p') != std::string::npos) {
      // Along the path the point travels during the contact, \int_{\mathcal{A}} … dS_v: its
      // element, once the definitions are in, holds dt; the path is travelled from 0 to dt.
      return GiNaC::integral(variable, 0, s_.scalar(SymbolName{"dt", "", 0, false}), coefficient);
    }
    if (!lower_written) {
      throw error(n.offset,
                  "expected the limits of the integral: \\int_0^{dt} or \\int_{dt} (over the "
                  "contact)");
    }
    ex lower = eval(n.children[1]).x.subs(s_.substitutions_);
    ex upper = 0;
    if (upper_written) {
      upper = eval(n.children[2]).x.subs(s_.substitutions_);
    } else {
      upper = lower;
      lower = 0;
    }
    return GiNaC::integral(variable, lower, upper, coefficient);
  }

  // X\Big|_a^b: X at b minus X at a, in the bar's variable: the one it names (|_{x = a}^{b}),
  // else t where X holds t, else the variable of the integral read last where X holds it.
  Value bar(const Node& n) {
    const Value base = eval(n.children[0]);
    if (base.vector || base.block()) {
      throw error(n.offset, "expected a number before the bar |");
    }
    const bool has_upper = n.ops.find('u') != std::string::npos;
    const bool has_variable = n.ops.find('v') != std::string::npos;
    const ex inner = base.x.subs(s_.substitutions_);
    ex variable = s_.symbol_value(SymbolName{"t", "", 0, false}).x;
    if (has_variable) {
      variable = s_.symbol_value(n.children.back().symbol).x;
    } else if (!inner.has(variable) && s_.integration_variable_ &&
               inner.has(s_.scalar(*s_.integration_variable_))) {
      variable = s_.scalar(*s_.integration_variable_);
    }
    const ex lower = scalar_of(n.children[1]);
    if (has_upper && !inner.has(variable) && !has_atoms(inner)) {
      throw error(n.offset,
                  "expected the bar's variable in what stands before it: " +
                      std::string(has_variable ? "the variable it names"
                                               : "t (or the variable of the integral before)") +
                      " does not appear, so the difference would be 0 (name the variable: "
                      "\\Big|_{x = a}^{b})");
    }
    if (!has_upper) {
      return {false, inner.subs(variable == lower), 0};
    }
    const ex upper = scalar_of(n.children[2]);
    return {false, inner.subs(variable == upper) - inner.subs(variable == lower), 0};
  }

  Symbols& s_;
  std::vector<Bound> bound_;
  std::vector<ex> denominators_;
  std::vector<std::string> written_;
};

// Names before parentheses, F(t) and m(v_1 - v_2), resolved once the declarations are known:
// a declared function's value stays a call; anything else is a product, and a power after the
// parentheses belongs to them (m(v_1 - v_2)^2 is m times the square). Refused: a list in the
// parentheses after a name that is no function, and a name before the variable of an enclosing
// integral, derivative or sum (F(t): F times t, or F of t?).
class CallResolver {
 public:
  explicit CallResolver(const Symbols& symbols) : s_(symbols) {}

  Node run(const Node& n) {
    switch (n.kind) {
      case NodeKind::integral:
        return bound_inside(n, n.ops.find('d') != std::string::npos ? n.symbol.latex() : "t");
      case NodeKind::derivative:
        return bound_inside(n, n.symbol.latex());
      case NodeKind::sum_over:
      case NodeKind::product_over:
        return bound_inside(n, n.text);
      case NodeKind::call:
        return call(n, nullptr);
      case NodeKind::power:
        if (n.children[0].kind == NodeKind::call) {
          return call(n.children[0], &n);
        }
        break;
      default:
        break;
    }
    Node copy = n;
    for (Node& child : copy.children) {
      child = run(child);
    }
    return copy;
  }

 private:
  // The node with its variable bound in its first child (the integrand, the operand, the body).
  Node bound_inside(const Node& n, const std::string& variable) {
    Node copy = n;
    for (std::size_t k = 0; k < copy.children.size(); ++k) {
      if (k == 0) {
        bound_.push_back(variable);
      }
      copy.children[k] = run(copy.children[k]);
      if (k == 0) {
        bound_.pop_back();
      }
    }
    return copy;
  }

  bool is_bound(const SymbolName& name) const {
    const std::string key = s_.resolve(name).latex();
    return std::find(bound_.begin(), bound_.end(), key) != bound_.end();
  }

  Node call(const Node& n, const Node* power) {
    const SymbolName name = s_.resolve(n.children[0].symbol);
    Node copy = n;
    for (std::size_t k = 1; k < copy.children.size(); ++k) {
      copy.children[k] = run(copy.children[k]);
    }
    if (s_.function(name) != nullptr || (dotted_of(s_, name) && n.children.size() == 2)) {
      if (power == nullptr) {
        return copy;
      }
      Node p = *power;
      p.children[0] = std::move(copy);
      p.children[1] = run(p.children[1]);
      return p;
    }
    if (name.primes > 0) {
      SymbolName plain = name;
      plain.primes = 0;
      if (s_.function(plain) != nullptr) {
        throw s_.error(n.offset, "expected " + plain.latex() + "(…) or its derivative \\frac{d" +
                                     plain.latex() + "}{dt}: " + name.latex() +
                                     "(…) could be the derivative of " + plain.latex() +
                                     " or another function (declare it with function: to mean "
                                     "that)");
      }
    }
    if (n.children.size() > 2) {
      throw s_.error(n.offset, "expected one factor in the parentheses after " + name.latex() +
                                   ": a list (a, b) is the arguments of a function (declare it "
                                   "with function: " +
                                   name.latex() + "), and for a vector write [a, b]");
    }
    const Node& argument = n.children[1];
    const auto single = [](const Node& a) {
      return a.kind == NodeKind::number || a.kind == NodeKind::symbol;
    };
    const bool lone =
        single(argument) || (argument.kind == NodeKind::sum && argument.children.size() == 1 &&
                             single(argument.children[0]));
    if (lone && !n.spaced && !(argument.kind == NodeKind::symbol && is_bound(argument.symbol))) {
      // x(0), v(t), \omega(T) of a name not declared a function: nobody writes a product so; the
      // value of a function is meant (x(t) = x_0 + v_0 t then x(0) = 0 followed, as x times 0).
      // With a space, m_1 (v_1')^2, the product is meant, as part two of the contract reads it.
      const std::string inside = s_.written(argument);
      throw s_.error(n.offset, name.latex() + "(" + inside + "): " + name.latex() + " at " +
                                   inside + " (a function's value), or " + name.latex() +
                                   " times " + inside + "? Declare it with function: " +
                                   name.latex() + " for the function, or write " + name.latex() +
                                   " \\cdot " + inside + " for the product");
    }
    if (argument.kind == NodeKind::symbol && is_bound(argument.symbol)) {
      throw s_.error(n.offset, name.latex() + "(" + argument.symbol.latex() + "): " + name.latex() +
                                   " times " + argument.symbol.latex() + ", or " + name.latex() +
                                   " as a function of " + argument.symbol.latex() +
                                   "? Declare it with function: " + name.latex() +
                                   " for the function, or write " + name.latex() + " \\cdot " +
                                   argument.symbol.latex() + " for the product");
    }
    if (n.text == bare_call) {
      // \cos\theta(v_1 + v_2) was cos(θ (v_1 + v_2)), \sin\theta (1 + 1) sin 2θ.
      throw s_.error(n.children[1].offset, std::string(runs_into_group));
    }
    // A product: the name times the parentheses (to the power, if one follows them).
    Node product = copy;
    product.kind = NodeKind::product;
    product.ops = "  ";
    if (power != nullptr) {
      Node p = *power;
      p.children[0] = std::move(product.children[1]);
      p.children[1] = run(p.children[1]);
      p.offset = p.children[0].offset;
      product.children[1] = std::move(p);
    }
    return product;
  }

  const Symbols& s_;
  std::vector<std::string> bound_;
};

Node Symbols::resolved(const Node& node) const {
  return CallResolver(*this).run(node);
}

Meaning Symbols::meaning(const Node& node) {
  return Evaluator(*this).run(resolved(node));
}

}  // namespace impulse::derivations::file
