// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/meaning.hpp"

#include "file/calculus.hpp"
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
  if (name.delta) {
    // The change of a vector is a vector: \Delta p, \Delta \vec p of a declared p.
    SymbolName changed = name;
    changed.delta = false;
    if (is_vector(changed)) {
      return true;
    }
  }
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
  // v_{1x}, v_{1 x} and v_{1,x} are the x component of \vec v_1.
  SymbolName parent = name;
  parent.subscript.pop_back();
  while (!parent.subscript.empty() &&
         (parent.subscript.back() == ' ' || parent.subscript.back() == ',')) {
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

void Symbols::note_quantities(const Node& node) {
  if (node.kind == NodeKind::symbol) {
    quantities_.insert(resolve(node.symbol).latex());
  }
  for (const Node& child : node.children) {
    note_quantities(child);
  }
}

bool Symbols::is_variable_of(unsigned serial, const GiNaC::ex& symbol) const {
  const FunctionDeclaration* f = function_of(serial);
  if (f == nullptr) {
    return false;
  }
  return std::any_of(f->variables.begin(), f->variables.end(), [&](const SymbolName& v) {
    const auto found = symbols_.find(resolve(v).latex());
    return found != symbols_.end() && found->second.is_equal(symbol);
  });
}

const FunctionDeclaration* Symbols::function_of(unsigned serial) const {
  for (const auto& [key, f] : functions_) {
    if (f.serial == serial) {
      return &f;
    }
  }
  return nullptr;
}

bool Symbols::is_quantity(const SymbolName& name) const {
  const std::string key = resolve(name).latex();
  if (quantities_.contains(key) || units_.contains(key) || is_vector(name) ||
      function(name) != nullptr) {
    return true;
  }
  const auto symbol = symbols_.find(key);
  return symbol != symbols_.end() && substitutions_.contains(symbol->second);
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
  return with_index_text(node, index, std::to_string(value));
}

Node with_index_text(const Node& node, const std::string& index, const std::string& value) {
  Node copy = node;
  if (copy.kind == NodeKind::symbol) {
    std::string& sub = copy.symbol.subscript;
    const std::size_t plain = index_part(sub);
    if (plain > 0 && sub.substr(0, plain).find(index[0]) != std::string::npos) {
      std::string out;
      for (const char c : sub.substr(0, plain)) {
        out += c == index[0] ? value : std::string(1, c);
      }
      sub = out + sub.substr(plain);
    }
    return copy;
  }
  if ((copy.kind == NodeKind::sum_over || copy.kind == NodeKind::product_over) &&
      copy.text == index) {
    return copy;  // the inner sum binds the index again
  }
  for (Node& child : copy.children) {
    child = with_index_text(child, index, value);
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
  if (substitutions_.contains(target.x)) {
    // The lines before read the name by its definition when a step is decided: a second one
    // would change what they say (J = m(v - v') then J = m(v' - v) turned a slip into a step).
    throw error(offset, "expected a name not defined yet: " + name.latex() +
                            " is defined by an earlier let:, and a second definition would "
                            "change what the lines before it say; give the new one another name");
  }
  GiNaC::exmap added;
  added[target.x] = m.value.x.subs(substitutions_);
  if (target.vector) {
    added[target.y] = m.value.y.subs(substitutions_);
  }
  for (const auto& [symbol, value] : added) {
    if (value.has(symbol)) {
      // let: a = b + c, then let: b = a - c: b's definition is b itself, through a's.
      throw error(offset, "expected a definition of " + name.latex() +
                              " that does not use it, also through earlier definitions (" +
                              name.latex() + " would stand for itself)");
    }
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

// ---- functions and sums over an index ---------------------------------------------------------

void Symbols::declare_function(const SymbolName& written, std::vector<SymbolName> variables,
                               std::size_t offset) {
  const SymbolName name = resolve(written);
  if (is_vector(name) || blocks_.contains(name.unprimed().latex())) {
    throw error(offset, "expected a scalar function: " + name.latex() + " is a vector or a block");
  }
  if (substitutions_.count(scalar(name)) != 0) {
    throw error(offset,
                "expected " + name.latex() + " to be declared a function before a let: defines it");
  }
  const bool written_variables = !variables.empty();
  if (!written_variables) {
    variables.push_back(SymbolName{"t", "", 0, false});
  }
  for (const SymbolName& v : variables) {
    if (v == name) {
      throw error(offset, "expected a function of another symbol than " + name.latex());
    }
  }
  FunctionDeclaration f;
  f.name = name;
  f.variables = std::move(variables);
  f.variable_written = written_variables;
  f.serial =
      abstract_function(name.plain(), name.latex(), static_cast<unsigned>(f.variables.size()));
  functions_[name.latex()] = std::move(f);
}

const FunctionDeclaration* Symbols::function(const SymbolName& name) const {
  const auto found = functions_.find(resolve(name).latex());
  return found == functions_.end() ? nullptr : &found->second;
}

bool Symbols::indexed_by(const ex& s, const ex& index) const {
  const SymbolInfo* i = info(s);
  const SymbolInfo* letter = info(index);
  if (i == nullptr || letter == nullptr || letter->name.base.size() != 1) {
    return false;
  }
  const SymbolName& name = i->of ? *i->of : i->name;
  const std::size_t plain = index_part(name.subscript);
  return plain > 0 &&
         name.subscript.substr(0, plain).find(letter->name.base[0]) != std::string::npos;
}

ex Symbols::at_index(const ex& body, const ex& index, long value,
                     std::vector<std::pair<ex, ex>>* renamed) {
  return at_index(body, index, ex(value), renamed);
}

std::optional<std::string> Symbols::index_text(const ex& value) const {
  if (GiNaC::is_a<GiNaC::numeric>(value)) {
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(value);
    if (!n.is_integer()) {
      return std::nullopt;
    }
    std::ostringstream text;
    text << n;
    return text.str();
  }
  // A letter (N, j) or a letter plus a whole number (N - 1).
  ex letter = value;
  long k = 0;
  if (GiNaC::is_a<GiNaC::add>(value) && value.nops() == 2 &&
      GiNaC::is_a<GiNaC::numeric>(value.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(value.op(1)).is_integer()) {
    letter = value.op(0);
    k = GiNaC::ex_to<GiNaC::numeric>(value.op(1)).to_long();
  }
  const SymbolInfo* i = info(letter);
  if (!GiNaC::is_a<GiNaC::symbol>(letter) || i == nullptr || i->of || !i->name.subscript.empty() ||
      i->name.primes != 0 || i->name.base.size() != 1) {
    return std::nullopt;
  }
  return k == 0 ? i->name.base : i->name.base + (k > 0 ? "+" : "") + std::to_string(k);
}

ex Symbols::at_index(const ex& body, const ex& index, const ex& value,
                     std::vector<std::pair<ex, ex>>* renamed) {
  const SymbolInfo* letter = info(index);
  const std::optional<std::string> text = index_text(value);
  if (letter == nullptr || !text) {
    return body.subs(index == value);
  }
  GiNaC::exmap map{{index, value}};
  for (auto i = body.preorder_begin(); i != body.preorder_end(); ++i) {
    if (!GiNaC::is_a<GiNaC::symbol>(*i) || map.count(*i) != 0 || !indexed_by(*i, index)) {
      continue;
    }
    const SymbolInfo* s = info(*i);
    if (s == nullptr) {
      continue;
    }
    Node node;
    node.kind = NodeKind::symbol;
    node.symbol = s->of ? *s->of : s->name;
    const SymbolName moved = with_index_text(node, letter->name.base, *text).symbol;
    const Value v = symbol_value(moved);
    const ex target = s->of ? (s->component == 0 ? v.x : v.y) : v.x;
    map[*i] = target;
    if (renamed != nullptr) {
      renamed->emplace_back(*i, target);
    }
  }
  return body.subs(map);
}

}  // namespace impulse::derivations::file
