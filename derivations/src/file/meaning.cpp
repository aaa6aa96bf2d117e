// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/meaning.hpp"

#include "file/time.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::numeric;

// ---- dimensions --------------------------------------------------------------------------------

std::string Dimension::text() const {
  std::string out;
  const auto part = [&](const char* letter, const numeric& power) {
    if (power.is_zero()) {
      return;
    }
    if (!out.empty()) {
      out += ' ';
    }
    out += letter;
    if (power != 1) {
      std::ostringstream p;
      p << power;
      out += '^';
      out += p.str();
    }
  };
  part("M", mass);
  part("L", length);
  part("T", time);
  return out.empty() ? "1" : out;
}

namespace {

Dimension operator+(const Dimension& a, const Dimension& b) {
  return {a.mass + b.mass, a.length + b.length, a.time + b.time};
}
Dimension operator-(const Dimension& a, const Dimension& b) {
  return {a.mass - b.mass, a.length - b.length, a.time - b.time};
}
Dimension scaled(const Dimension& a, const numeric& k) {
  return {a.mass * k, a.length * k, a.time * k};
}
bool dimensionless(const Dimension& a) {
  return a.mass.is_zero() && a.length.is_zero() && a.time.is_zero();
}

}  // namespace

Dimension read_dimension(const Source& source, std::size_t offset, std::string_view text) {
  Dimension d;
  std::size_t i = 0;
  bool any = false;
  const auto skip = [&] {
    while (i < text.size() &&
           (text[i] == ' ' || text[i] == '\t' || text[i] == '\\' || text[i] == ',' ||
            text[i] == ';' || text[i] == '*' || text[i] == '.')) {
      // "M\,L" and "M·L" spacing; a trailing "." is punctuation
      if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == ',' || text[i + 1] == ';')) {
        ++i;
      } else if (text[i] == '\\') {
        break;
      }
      ++i;
    }
  };
  skip();
  if (text.substr(i) == "1") {
    return d;
  }
  while (i < text.size()) {
    const char letter = text[i];
    if (letter != 'M' && letter != 'L' && letter != 'T') {
      throw source.error(offset + i,
                         "expected a dimension made of M, L and T with powers "
                         "(e.g. M L T^-1), or 1; found '" +
                             std::string(1, letter) + "'");
    }
    ++i;
    numeric power = 1;
    if (i < text.size() && text[i] == '^') {
      ++i;
      const bool braced = i < text.size() && text[i] == '{';
      if (braced) {
        ++i;
      }
      const std::size_t start = i;
      if (i < text.size() && (text[i] == '-' || text[i] == '+')) {
        ++i;
      }
      while (i < text.size() && ((text[i] >= '0' && text[i] <= '9') || text[i] == '/')) {
        ++i;
      }
      const std::string digits(text.substr(start, i - start));
      const std::size_t slash = digits.find('/');
      const std::string top = digits.substr(0, slash);
      const bool valid =
          !top.empty() && top != "-" && top != "+" && top.size() < 6 &&
          (slash == std::string::npos || (slash + 1 < digits.size() && digits.size() - slash < 6 &&
                                          digits.find('/', slash + 1) == std::string::npos));
      if (!valid) {
        throw source.error(offset + start, "expected a whole power after '^' (e.g. T^-1, L^{2})");
      }
      power = numeric(std::stol(top));
      if (slash != std::string::npos) {
        const long bottom = std::stol(digits.substr(slash + 1));
        if (bottom == 0) {
          throw source.error(offset + start, "expected a power without division by zero");
        }
        power = power / numeric(bottom);
      }
      if (braced) {
        if (i >= text.size() || text[i] != '}') {
          throw source.error(offset + i, "expected '}' to close the power");
        }
        ++i;
      }
    }
    (letter == 'M' ? d.mass : letter == 'L' ? d.length : d.time) += power;
    any = true;
    skip();
  }
  if (!any) {
    throw source.error(offset, "expected a dimension made of M, L and T (e.g. M L T^-1), or 1");
  }
  return d;
}

// ---- symbols -----------------------------------------------------------------------------------

ex Symbols::scalar(const SymbolName& name, std::optional<SymbolName> of, int component) {
  const std::string key = name.latex();
  if (const auto found = symbols_.find(key); found != symbols_.end()) {
    return found->second;
  }
  // A name of several parts is braced in LaTeX output, so that a power applies to all of it.
  const std::string tex = name.delta ? "{" + key + "}" : key;
  const ex symbol = GiNaC::realsymbol(name.plain(), tex);
  symbols_.emplace(key, symbol);
  infos_.emplace(symbol, SymbolInfo{name, std::move(of), component});
  return symbol;
}

const SymbolInfo* Symbols::info(const ex& symbol) const {
  const auto found = infos_.find(symbol);
  return found == infos_.end() ? nullptr : &found->second;
}

SymbolName Symbols::resolve(SymbolName name) const {
  if (name.accent && arrows_.contains(name.base) && !name.delta) {
    name.arrow = true;
  }
  return name;
}

bool Symbols::is_vector(const SymbolName& name) const {
  const std::string key = name.unprimed().latex();
  return vectors_.contains(key) || (name.arrow && !blocks_.contains(key));
}

std::optional<std::pair<SymbolName, int>> Symbols::component_of(const SymbolName& name) const {
  if (name.subscript.empty()) {
    return std::nullopt;
  }
  const char last = name.subscript.back();
  if (last != 'x' && last != 'y') {
    return std::nullopt;
  }
  SymbolName parent = name;
  parent.subscript.pop_back();
  while (!parent.subscript.empty() && parent.subscript.back() == ' ') {
    parent.subscript.pop_back();
  }
  if (!is_vector(parent)) {
    // The components of \vec F are F_x and F_y when F is an `arrow:` letter.
    SymbolName arrowed = parent;
    arrowed.arrow = true;
    if (parent.arrow || !arrows_.contains(parent.base) || !is_vector(arrowed)) {
      return std::nullopt;
    }
    return std::pair{arrowed, last == 'x' ? 0 : 1};
  }
  return std::pair{parent, last == 'x' ? 0 : 1};
}

void Symbols::declare_vector(const SymbolName& name) {
  vectors_[resolve(name).unprimed().latex()] = true;
}

void Symbols::declare_units(const SymbolName& name, const Dimension& dimension, std::size_t) {
  units_[resolve(name).latex()] = dimension;
}

void Symbols::declare_force(const SymbolName& name) {
  const Value v = symbol_value(resolve(name));
  forces_.push_back(v.x);
  if (v.vector) {
    forces_.push_back(v.y);
  }
}

std::size_t index_part(const std::string& sub) {
  const auto alnum = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
  };
  const std::size_t open = sub.find('(');
  const std::size_t plain = open == std::string::npos ? sub.size() : open;
  if (plain == 0 || plain > 3 ||
      !std::all_of(sub.begin(), sub.begin() + static_cast<std::ptrdiff_t>(plain), alnum)) {
    return 0;
  }
  if (open != std::string::npos && sub.back() != ')') {
    return 0;
  }
  return plain;
}

std::vector<std::string> Symbols::indices_in(const Node& node) const {
  std::vector<std::string> found;
  std::function<void(const Node&, const std::set<std::string>&)> walk =
      [&](const Node& n, const std::set<std::string>& bound) {
        if (n.kind == NodeKind::symbol) {
          const std::string& sub = n.symbol.subscript;
          if (const std::size_t plain = index_part(sub); plain > 0) {
            for (const char c : sub.substr(0, plain)) {
              const std::string letter(1, c);
              if (indices_.contains(letter) && !bound.contains(letter) &&
                  std::find(found.begin(), found.end(), letter) == found.end()) {
                found.push_back(letter);
              }
            }
          }
        }
        if (n.kind == NodeKind::sum_over) {
          std::set<std::string> inner = bound;
          inner.insert(n.text);
          walk(n.children[0], inner);
          return;
        }
        for (const Node& child : n.children) {
          walk(child, bound);
        }
      };
  walk(node, {});
  return found;
}

std::vector<std::string> Symbols::free_indices(const Node& node) const {
  return indices_in(node);
}

void Symbols::declare_block(const SymbolName& name, const Side& entry, bool matrix,
                            std::size_t offset) {
  Block block{entry, indices_in(entry.expression)};
  const std::size_t wanted = matrix ? 2 : 1;
  if (block.indices.size() != wanted) {
    throw error(entry.offset, std::string("expected the entry of a ") +
                                  (matrix ? "matrix to hold two indices (row, column)"
                                          : "column to hold one index (its row)") +
                                  " declared with index:, found " +
                                  std::to_string(block.indices.size()));
  }
  const std::string key = resolve(name).unprimed().latex();
  if (vectors_.contains(key)) {
    throw error(offset, "expected " + key + " to be a vector or a block, not both");
  }
  blocks_[key] = std::move(block);
}

Value Symbols::block_value(const Block& block, std::size_t offset,
                           const std::function<Value(const Node&)>& eval) const {
  const std::vector<long>& rows = indices_.at(block.indices[0]);
  const std::vector<long> one{0};
  const std::vector<long>& cols = block.indices.size() > 1 ? indices_.at(block.indices[1]) : one;
  Value v;
  v.rows = rows.size();
  v.cols = cols.size();
  for (const long r : rows) {
    for (const long c : cols) {
      Node entry = with_index(block.entry.expression, block.indices[0], r);
      if (block.indices.size() > 1) {
        entry = with_index(entry, block.indices[1], c);
      }
      const Value e = eval(entry);
      if (e.vector || e.block()) {
        throw error(offset, "expected the entries of a block to be numbers");
      }
      v.entries.push_back(e.x);
    }
  }
  return v;
}

Node with_index(const Node& node, const std::string& index, long value) {
  Node copy = node;
  if (copy.kind == NodeKind::symbol) {
    std::string& sub = copy.symbol.subscript;
    const std::size_t plain = index_part(sub);
    if (plain > 0 && sub.substr(0, plain).find(index[0]) != std::string::npos) {
      std::string out;
      for (const char c : sub.substr(0, plain)) {
        out += c == index[0] ? std::to_string(value) : std::string(1, c);
      }
      sub = out + sub.substr(plain);
    }
    return copy;
  }
  if (copy.kind == NodeKind::sum_over && copy.text == index) {
    return copy;  // the inner sum binds the index again
  }
  for (Node& child : copy.children) {
    child = with_index(child, index, value);
  }
  return copy;
}

namespace {

SymbolName component_name(const SymbolName& vector, int component) {
  SymbolName name = vector;
  name.subscript += component == 0 ? "x" : "y";
  return name;
}

void each_symbol(const Node& node, const std::function<void(const Node&)>& visit) {
  if (node.kind == NodeKind::symbol) {
    visit(node);
  }
  for (const Node& child : node.children) {
    each_symbol(child, visit);
  }
}

}  // namespace

Value Symbols::symbol_value(const SymbolName& written) {
  const SymbolName name = resolve(written);
  if (is_vector(name)) {
    return {true, scalar(component_name(name, 0), name, 0),
            scalar(component_name(name, 1), name, 1)};
  }
  if (const auto parent = component_of(name)) {
    // The component's one name: p_x of \vec p (an `arrow:` letter) is \vec{p}_x.
    return {false,
            scalar(component_name(parent->first, parent->second), parent->first, parent->second),
            0};
  }
  return {false, scalar(name), 0};
}

void Symbols::define(const SymbolName& written, const Side& definition, std::size_t offset) {
  const SymbolName name = resolve(written);
  if (blocks_.contains(name.unprimed().latex())) {
    throw error(offset, "expected a symbol, not a block (matrix:, column:), after let:");
  }
  each_symbol(definition.expression, [&](const Node& n) {
    const SymbolName used = resolve(n.symbol);
    const auto parent = component_of(used);
    if (used == name || (parent && parent->first == name)) {
      throw error(n.offset, "expected a definition of " + name.latex() + " that does not use " +
                                name.latex() + " itself");
    }
  });
  const Meaning m = meaning(definition.expression);
  const bool declared_vector = is_vector(name);
  if (declared_vector && !m.value.vector) {
    throw error(definition.offset, "expected a vector: " + name.latex() +
                                       " is declared a vector (vector:), its definition is a "
                                       "scalar");
  }
  if (!declared_vector && m.value.vector) {
    if (component_of(name)) {
      throw error(definition.offset,
                  "expected a scalar: " + name.latex() + " is a component of a vector");
    }
    declare_vector(name);
  }
  const Value target = symbol_value(name);
  GiNaC::exmap added;
  added[target.x] = m.value.x.subs(substitutions_);
  if (target.vector) {
    added[target.y] = m.value.y.subs(substitutions_);
  }
  // Earlier definitions that used this name now carry its value.
  for (auto& [symbol, value] : substitutions_) {
    value = value.subs(added);
  }
  for (const auto& [symbol, value] : added) {
    substitutions_[symbol] = value;
  }
  const DimensionResult d = dimension(definition.expression);
  if (d.issue) {
    throw error(d.issue->offset,
                "expected a definition whose terms have one dimension: " + d.issue->what);
  }
  if (const auto declared = units_.find(name.latex());
      declared != units_.end() && d.dimension && !(declared->second == *d.dimension)) {
    throw error(offset, "expected the definition of " + name.latex() + " to have dimension " +
                            declared->second.text() + " (units:), it has " + d.dimension->text());
  }
  defined_dimensions_[name.latex()] = d.dimension;
}

// ---- meaning -----------------------------------------------------------------------------------

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

bool all_digits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

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

ex Symbols::integral_value(const Node& n, const std::function<Value(const Node&)>& eval) {
  const Value integrand = eval(n.children[0]);
  if (integrand.vector || integrand.block()) {
    throw error(n.offset, "expected a number to integrate, found " + kind_name(integrand));
  }
  ex form = integrand.x.subs(substitutions_);
  // The differential: dt, or dt', dt'' for a variable t', t''.
  std::optional<std::pair<ex, int>> differential;
  for (const auto& [key, symbol] : symbols_) {
    const SymbolInfo& info = infos_.at(symbol);
    if (info.name.base == "dt" && info.name.subscript.empty() && !info.name.delta &&
        !info.name.differential && form.has(symbol)) {
      if (differential) {
        throw error(n.offset, "expected one differential in the integrand (dt or dt'), found two");
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
    throw error(n.offset, "expected the integrand to hold its differential (dt, or dt' for t')");
  }
  const ex delta = differential->first;
  const ex variable = scalar(SymbolName{"t", "", differential->second, false});
  // Inside the contact a force is its mean times the pulse's shape.
  GiNaC::exmap shaped;
  for (const ex& f : forces_) {
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
    return GiNaC::integral(variable, 0, scalar(SymbolName{"dt", "", 0, false}), coefficient);
  }
  if (!lower_written) {
    throw error(n.offset,
                "expected the limits of the integral: \\int_0^{dt} or \\int_{dt} (over the "
                "contact)");
  }
  ex lower = eval(n.children[1]).x.subs(substitutions_);
  ex upper = 0;
  if (upper_written) {
    upper = eval(n.children[2]).x.subs(substitutions_);
  } else {
    upper = lower;  // \int_{dt}: over the contact, from 0 to dt
    lower = 0;
  }
  return GiNaC::integral(variable, lower, upper, coefficient);
}

namespace {

// d followed by a symbol declared with `differentials:` is that symbol's differential.
std::vector<std::pair<Node, char>> merged_factors(
    const Node& product, const std::function<bool(const SymbolName&)>& differential) {
  std::vector<std::pair<Node, char>> factors;
  for (std::size_t i = 0; i < product.children.size(); ++i) {
    const Node& c = product.children[i];
    const bool d = c.kind == NodeKind::symbol && c.symbol.base == "d" &&
                   c.symbol.subscript.empty() && c.symbol.primes == 0 && !c.symbol.delta;
    if (d && i + 1 < product.children.size() && product.ops[i + 1] == ' ' &&
        product.children[i + 1].kind == NodeKind::symbol &&
        !product.children[i + 1].symbol.differential &&
        differential(product.children[i + 1].symbol)) {
      Node merged = product.children[i + 1];
      merged.symbol.differential = true;
      merged.offset = c.offset;
      factors.emplace_back(std::move(merged), product.ops[i]);
      ++i;
      continue;
    }
    factors.emplace_back(c, product.ops[i]);
  }
  return factors;
}

}  // namespace

Meaning Symbols::meaning(const Node& node) {
  std::vector<ex> denominators;
  const auto unblocked = [&](Value v, std::size_t at) {
    if (v.block()) {
      throw error(at, "expected a number or a vector here, found " + kind_name(v));
    }
    return v;
  };
  std::function<Value(const Node&)> eval = [&](const Node& n) -> Value {
    try {
      switch (n.kind) {
        case NodeKind::number:
          return {false, decimal(n.text), 0};
        case NodeKind::pi:
          return {false, GiNaC::Pi, 0};
        case NodeKind::symbol: {
          const SymbolName name = resolve(n.symbol);
          if (const auto block = blocks_.find(name.unprimed().latex()); block != blocks_.end()) {
            return block_value(block->second, n.offset, eval);
          }
          return symbol_value(n.symbol);
        }
        case NodeKind::sum: {
          Value total;
          const std::vector<std::pair<Node, char>> terms = expanded_terms(n);
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
        case NodeKind::product: {
          const auto factors = merged_factors(n, [&](const SymbolName& name) {
            return differentials_.contains(resolve(name).unprimed().latex());
          });
          Value acc = eval(factors[0].first);
          for (std::size_t i = 1; i < factors.size(); ++i) {
            const Value next = eval(factors[i].first);
            const char op = factors[i].second;
            const std::size_t at = factors[i].first.offset;
            if (acc.block() || next.block()) {
              acc = block_product(acc, next, op, at, denominators);
              continue;
            }
            if (op == '/') {
              if (next.vector) {
                throw error(at, "expected a scalar to divide by, found a vector");
              }
              denominators.push_back(next.x);
              acc = {acc.vector, acc.x / next.x, acc.vector ? acc.y / next.x : ex(0)};
            } else if (!acc.vector && !next.vector) {
              acc = {false, acc.x * next.x, 0};
            } else if (acc.vector != next.vector) {
              const Value& s = acc.vector ? next : acc;
              const Value& v = acc.vector ? acc : next;
              acc = {true, s.x * v.x, s.x * v.y};
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
        case NodeKind::fraction: {
          // dy/dx with d a plain letter would be read as the product d y over d x, which
          // cancels to y/x: a derivative silently misread. Refused instead.
          const auto plain_d = [&](const Node& x) {
            const auto is_d = [](const Node& c) {
              return c.kind == NodeKind::symbol && c.symbol.base == "d" &&
                     c.symbol.subscript.empty() && c.symbol.primes == 0 && !c.symbol.delta &&
                     !c.symbol.accent;
            };
            if (is_d(x)) {
              return true;
            }
            return x.kind == NodeKind::product && x.children.size() >= 2 && is_d(x.children[0]) &&
                   x.ops.size() >= 2 && x.ops[1] == ' ' && x.children[1].kind == NodeKind::symbol &&
                   !differentials_.contains(resolve(x.children[1].symbol).unprimed().latex());
          };
          if (plain_d(n.children[0]) && plain_d(n.children[1])) {
            throw error(n.offset,
                        "expected no derivative: the checker does not read \\frac{d…}{d…} (it "
                        "would be d times … over d times …); write the relation between the "
                        "quantities themselves, or declare small changes with differentials:");
          }
          const Value top = eval(n.children[0]);
          const Value bottom = eval(n.children[1]);
          if (bottom.vector || bottom.block()) {
            throw error(n.children[1].offset,
                        "expected a scalar denominator, found " + kind_name(bottom));
          }
          denominators.push_back(bottom.x);
          return scaled_value(top, 1 / bottom.x);
        }
        case NodeKind::sum_over: {
          const auto range = indices_.find(n.text);
          if (range == indices_.end()) {
            throw error(n.offset, "expected the index " + n.text +
                                      " of \\sum to be declared (index: " + n.text +
                                      " \\in \\{1, 2\\})");
          }
          Value total;
          for (std::size_t k = 0; k < range->second.size(); ++k) {
            Value term = eval(with_index(n.children[0], n.text, range->second[k]));
            if (k == 0) {
              total = term;
              continue;
            }
            if (term.vector != total.vector || term.rows != total.rows) {
              throw error(n.offset, "expected the terms of the sum to be of one kind");
            }
            total.x += term.x;
            total.y += term.y;
            for (std::size_t e = 0; e < total.entries.size(); ++e) {
              total.entries[e] += term.entries[e];
            }
          }
          return total;
        }
        case NodeKind::integral:
          return {false, integral_value(n, eval), 0};
        case NodeKind::bar: {
          const Value base = eval(n.children[0]);
          if (base.vector || base.block()) {
            throw error(n.offset, "expected a number before the bar |");
          }
          const bool has_upper = n.ops.find('u') != std::string::npos;
          const bool has_variable = n.ops.find('v') != std::string::npos;
          const ex variable = has_variable ? symbol_value(n.children.back().symbol).x
                                           : symbol_value(SymbolName{"t", "", 0, false}).x;
          const ex inner = base.x.subs(substitutions_);
          const ex lower = eval(n.children[1]).x;
          if (!has_upper) {
            return {false, inner.subs(variable == lower), 0};
          }
          const ex upper = eval(n.children[2]).x;
          return {false, inner.subs(variable == upper) - inner.subs(variable == lower), 0};
        }
        case NodeKind::dots:
          throw error(n.offset, "expected \\cdots between two terms of a sum");
        case NodeKind::power: {
          const Value base = unblocked(eval(n.children[0]), n.children[0].offset);
          const Value exponent = unblocked(eval(n.children[1]), n.children[1].offset);
          if (exponent.vector) {
            throw error(n.children[1].offset, "expected a scalar exponent, found a vector");
          }
          const ex e = exponent.x;
          if (GiNaC::is_a<numeric>(e)) {
            const numeric k = GiNaC::ex_to<numeric>(e);
            if (k.is_integer() && GiNaC::abs(k) > limits_.exponent) {
              throw error(n.children[1].offset, "expected an exponent of at most " +
                                                    std::to_string(limits_.exponent) +
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
            if (k.is_negative() && !base.vector) {
              denominators.push_back(base.x);
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
        case NodeKind::function: {
          const Value argument = unblocked(eval(n.children[0]), n.children[0].offset);
          if (argument.vector) {
            throw error(n.children[0].offset,
                        "expected a scalar argument of \\" + n.text + ", found a vector");
          }
          const ex& a = argument.x;
          if (n.text == "sin") {
            return {false, GiNaC::sin(a), 0};
          }
          if (n.text == "cos") {
            return {false, GiNaC::cos(a), 0};
          }
          if (n.text == "tan") {
            denominators.push_back(GiNaC::cos(a));
            return {false, GiNaC::tan(a), 0};
          }
          if (n.text == "exp") {
            return {false, GiNaC::exp(a), 0};
          }
          return {false, GiNaC::log(a), 0};
        }
        case NodeKind::root: {
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
                        "expected a whole number from 2 to 1000 as the "
                        "index of the root");
          }
          return {false, GiNaC::pow(radicand.x, 1 / index.x), 0};
        }
        case NodeKind::norm: {
          const Value v = unblocked(eval(n.children[0]), n.children[0].offset);
          if (!v.vector) {
            throw error(n.offset, "expected a vector inside \\| \\| (for a scalar write |x|)");
          }
          return {false, GiNaC::sqrt(v.x * v.x + v.y * v.y), 0};
        }
        case NodeKind::abs: {
          const Value v = unblocked(eval(n.children[0]), n.children[0].offset);
          if (v.vector) {
            return {false, GiNaC::sqrt(v.x * v.x + v.y * v.y), 0};
          }
          return {false, GiNaC::abs(v.x), 0};
        }
        case NodeKind::det: {
          const Value a = unblocked(eval(n.children[0]), n.children[0].offset);
          const Value b = unblocked(eval(n.children[1]), n.children[1].offset);
          if (!a.vector || !b.vector) {
            throw error(a.vector ? n.children[1].offset : n.children[0].offset,
                        "expected two vectors in \\det(\\vec a, \\vec b), found a scalar");
          }
          return {false, a.x * b.y - a.y * b.x, 0};
        }
        case NodeKind::vector: {
          const Value a = unblocked(eval(n.children[0]), n.children[0].offset);
          const Value b = unblocked(eval(n.children[1]), n.children[1].offset);
          if (a.vector || b.vector) {
            throw error(a.vector ? n.children[0].offset : n.children[1].offset,
                        "expected scalar components in [x, y], found a vector");
          }
          return {true, a.x, b.x};
        }
      }
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
    throw error(n.offset, "expected an expression");
  };
  Value value = eval(node);
  return {std::move(value), std::move(denominators)};
}

std::optional<Dimension> Symbols::symbol_dimension(const SymbolName& written) const {
  const SymbolName name = resolve(written);
  if (name.differential) {  // dX has the dimension of X
    SymbolName base = name;
    base.differential = false;
    return symbol_dimension(base);
  }
  if (const auto found = units_.find(name.latex()); found != units_.end()) {
    return found->second;
  }
  if (const auto found = defined_dimensions_.find(name.latex());
      found != defined_dimensions_.end()) {
    return found->second;
  }
  if (name.primes > 0) {
    return symbol_dimension(name.unprimed());
  }
  if (name.delta) {
    SymbolName base = name;
    base.delta = false;
    return symbol_dimension(base);
  }
  if (const auto parent = component_of(name)) {
    return symbol_dimension(parent->first);
  }
  if (name.base == "dt" && name.subscript.empty() && has_units()) {
    return Dimension{0, 0, 1};
  }
  return std::nullopt;
}

Symbols::DimensionResult Symbols::dimension(const Node& node) {
  std::optional<DimensionIssue> issue;
  std::function<std::optional<Dimension>(const Node&)> walk =
      [&](const Node& n) -> std::optional<Dimension> {
    if (issue) {
      return std::nullopt;
    }
    const auto must_be_dimensionless = [&](const Node& child, const std::string& where) {
      const auto d = walk(child);
      if (d && !dimensionless(*d) && !issue) {
        issue = DimensionIssue{child.offset, Dimension{}, *d,
                               where + " has dimension " + d->text() + ", expected 1"};
      }
    };
    switch (n.kind) {
      case NodeKind::number:
        // Zero has every dimension: "… = 0" and "+ 0" agree with any term.
        if (n.text.find_first_not_of("0.") == std::string::npos) {
          return std::nullopt;
        }
        return Dimension{};
      case NodeKind::pi:
        return Dimension{};
      case NodeKind::symbol:
        return symbol_dimension(n.symbol);
      case NodeKind::sum: {
        std::optional<Dimension> known;
        std::size_t known_at = 0;
        for (std::size_t i = 0; i < n.children.size(); ++i) {
          const auto d = walk(n.children[i]);
          if (issue) {
            return std::nullopt;
          }
          if (!d) {
            continue;
          }
          if (!known) {
            known = d;
            known_at = i;
          } else if (!(*known == *d)) {
            issue = DimensionIssue{n.children[i].offset, *known, *d,
                                   "a term of dimension " + d->text() + " is added to one of " +
                                       known->text() + " (term " + std::to_string(known_at + 1) +
                                       " of the sum)"};
            return std::nullopt;
          }
        }
        return known;
      }
      case NodeKind::product: {
        std::optional<Dimension> total = Dimension{};
        const auto factors = merged_factors(n, [&](const SymbolName& name) {
          return differentials_.contains(resolve(name).unprimed().latex());
        });
        for (const auto& [factor, op] : factors) {
          const auto d = walk(factor);
          if (!d || !total) {
            total = std::nullopt;
            continue;
          }
          total = op == '/' ? *total - *d : *total + *d;
        }
        return total;
      }
      case NodeKind::sum_over: {
        const auto range = indices_.find(n.text);
        if (range == indices_.end() || range->second.empty()) {
          return std::nullopt;
        }
        return walk(with_index(n.children[0], n.text, range->second.front()));
      }
      case NodeKind::integral:  // a 1-form: its differential carries the time
      case NodeKind::bar:
        return walk(n.children[0]);
      case NodeKind::dots:
        return std::nullopt;
      case NodeKind::fraction: {
        const auto top = walk(n.children[0]);
        const auto bottom = walk(n.children[1]);
        if (!top || !bottom) {
          return std::nullopt;
        }
        return *top - *bottom;
      }
      case NodeKind::power: {
        const auto base = walk(n.children[0]);
        must_be_dimensionless(n.children[1], "an exponent");
        if (!base) {
          return std::nullopt;
        }
        if (dimensionless(*base)) {
          return Dimension{};
        }
        const ex e = meaning(n.children[1]).value.x;
        if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) {
          return scaled(*base, GiNaC::ex_to<numeric>(e));
        }
        if (!issue) {
          issue = DimensionIssue{n.offset, Dimension{}, *base,
                                 "a quantity of dimension " + base->text() +
                                     " is raised to a power that is not a number"};
        }
        return std::nullopt;
      }
      case NodeKind::function:
        must_be_dimensionless(n.children[0], "the argument of \\" + n.text);
        return Dimension{};
      case NodeKind::root: {
        const auto d = walk(n.children[0]);
        if (!d) {
          return std::nullopt;
        }
        numeric index = 2;
        if (n.children.size() == 2) {
          const ex e = meaning(n.children[1]).value.x;
          index = GiNaC::ex_to<numeric>(e);
        }
        return scaled(*d, 1 / index);
      }
      case NodeKind::norm:
      case NodeKind::abs:
        return walk(n.children[0]);
      case NodeKind::det: {
        const auto a = walk(n.children[0]);
        const auto b = walk(n.children[1]);
        if (!a || !b) {
          return std::nullopt;
        }
        return *a + *b;
      }
      case NodeKind::vector: {
        const auto a = walk(n.children[0]);
        const auto b = walk(n.children[1]);
        if (a && b && !(*a == *b) && !issue) {
          issue = DimensionIssue{
              n.children[1].offset, *a, *b,
              "the components of the vector have dimensions " + a->text() + " and " + b->text()};
          return std::nullopt;
        }
        return a ? a : b;
      }
    }
    return std::nullopt;
  };
  auto d = walk(node);
  return {issue ? std::nullopt : d, issue};
}

}  // namespace impulse::derivations::file
