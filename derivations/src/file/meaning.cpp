// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/meaning.hpp"

#include <algorithm>
#include <functional>
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

bool Symbols::is_vector(const SymbolName& name) const {
  return vectors_.contains(name.unprimed().latex());
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
    return std::nullopt;
  }
  return std::pair{parent, last == 'x' ? 0 : 1};
}

void Symbols::declare_vector(const SymbolName& name) {
  vectors_[name.unprimed().latex()] = true;
}

void Symbols::declare_units(const SymbolName& name, const Dimension& dimension, std::size_t) {
  units_[name.latex()] = dimension;
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

Value Symbols::symbol_value(const SymbolName& name) {
  if (is_vector(name)) {
    return {true, scalar(component_name(name, 0), name, 0),
            scalar(component_name(name, 1), name, 1)};
  }
  if (const auto parent = component_of(name)) {
    return {false, scalar(name, parent->first, parent->second), 0};
  }
  return {false, scalar(name), 0};
}

void Symbols::define(const SymbolName& name, const Side& definition, std::size_t offset) {
  each_symbol(definition.expression, [&](const Node& n) {
    const SymbolName& used = n.symbol;
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
  return v.vector ? "a vector" : "a scalar";
}

}  // namespace

Meaning Symbols::meaning(const Node& node) {
  std::vector<ex> denominators;
  std::function<Value(const Node&)> eval = [&](const Node& n) -> Value {
    try {
      switch (n.kind) {
        case NodeKind::number:
          return {false, decimal(n.text), 0};
        case NodeKind::pi:
          return {false, GiNaC::Pi, 0};
        case NodeKind::symbol:
          return symbol_value(n.symbol);
        case NodeKind::sum: {
          Value total;
          for (std::size_t i = 0; i < n.children.size(); ++i) {
            Value term = eval(n.children[i]);
            if (n.ops[i] == '-') {
              term.x = -term.x;
              term.y = -term.y;
            }
            if (i == 0) {
              total = term;
            } else if (term.vector != total.vector) {
              throw error(n.children[i].offset, "expected " + kind_name(total) +
                                                    " here, as the terms before it, found " +
                                                    kind_name(term));
            } else {
              total.x = total.x + term.x;
              total.y = total.y + term.y;
            }
          }
          if (!total.vector) {
            total.y = 0;
          }
          return total;
        }
        case NodeKind::product: {
          Value acc = eval(n.children[0]);
          for (std::size_t i = 1; i < n.children.size(); ++i) {
            const Value next = eval(n.children[i]);
            const char op = n.ops[i];
            const std::size_t at = n.children[i].offset;
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
          const Value top = eval(n.children[0]);
          const Value bottom = eval(n.children[1]);
          if (bottom.vector) {
            throw error(n.children[1].offset, "expected a scalar denominator, found a vector");
          }
          denominators.push_back(bottom.x);
          return {top.vector, top.x / bottom.x, top.vector ? top.y / bottom.x : ex(0)};
        }
        case NodeKind::power: {
          const Value base = eval(n.children[0]);
          const Value exponent = eval(n.children[1]);
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
          const Value argument = eval(n.children[0]);
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
          const Value radicand = eval(n.children[0]);
          if (radicand.vector) {
            throw error(n.children[0].offset, "expected a scalar under the root, found a vector");
          }
          if (n.children.size() == 1) {
            return {false, GiNaC::sqrt(radicand.x), 0};
          }
          const Value index = eval(n.children[1]);
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
          const Value v = eval(n.children[0]);
          if (!v.vector) {
            throw error(n.offset, "expected a vector inside \\| \\| (for a scalar write |x|)");
          }
          return {false, GiNaC::sqrt(v.x * v.x + v.y * v.y), 0};
        }
        case NodeKind::abs: {
          const Value v = eval(n.children[0]);
          if (v.vector) {
            return {false, GiNaC::sqrt(v.x * v.x + v.y * v.y), 0};
          }
          return {false, GiNaC::abs(v.x), 0};
        }
        case NodeKind::det: {
          const Value a = eval(n.children[0]);
          const Value b = eval(n.children[1]);
          if (!a.vector || !b.vector) {
            throw error(a.vector ? n.children[1].offset : n.children[0].offset,
                        "expected two vectors in \\det(\\vec a, \\vec b), found a scalar");
          }
          return {false, a.x * b.y - a.y * b.x, 0};
        }
        case NodeKind::vector: {
          const Value a = eval(n.children[0]);
          const Value b = eval(n.children[1]);
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

std::optional<Dimension> Symbols::symbol_dimension(const SymbolName& name) const {
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
        for (std::size_t i = 0; i < n.children.size(); ++i) {
          const auto d = walk(n.children[i]);
          if (!d || !total) {
            total = std::nullopt;
            continue;
          }
          total = n.ops[i] == '/' ? *total - *d : *total + *d;
        }
        return total;
      }
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
