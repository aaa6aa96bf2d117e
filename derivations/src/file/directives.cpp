// SPDX-License-Identifier: GPL-3.0-or-later
// The directives of a derivation file, one handler each: the contract's (assume:, let:, given:,
// from:, vector:, units:), part two's (function:, unit:, target:), and those accepted beyond it
// for the paper's files (also:, index:, arrow:, differentials:, forces:, matrix:, column:).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <map>
#include <optional>

#include "file/decide.hpp"
#include "file/reader.hpp"
#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;

std::vector<std::pair<std::size_t, std::string_view>> split_commas(std::string_view text,
                                                                   std::size_t offset) {
  std::vector<std::pair<std::size_t, std::string_view>> pieces;
  int depth = 0;
  std::size_t start = 0;
  const auto push = [&](std::size_t end) {
    std::size_t a = start;
    std::size_t b = end;
    const auto trim = [&] {
      while (a < b && (text[a] == ' ' || text[a] == '\t')) {
        ++a;
      }
      while (b > a && (text[b - 1] == ' ' || text[b - 1] == '\t')) {
        --b;
      }
    };
    trim();
    if (b - a >= 2 && text[a] == '$' && text[b - 1] == '$') {  // assume: $m > 0$, $v > 0$
      ++a;
      --b;
      trim();
    }
    pieces.emplace_back(offset + a, text.substr(a, b - a));
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '{' || c == '[' || c == '(') {
      ++depth;
    } else if (c == '}' || c == ']' || c == ')') {
      --depth;
    } else if (c == ',' && depth == 0 && !(i > 0 && text[i - 1] == '\\')) {
      push(i);
      start = i + 1;
    }
  }
  push(text.size());
  return pieces;
}

void Reader::read_directive(const Directive& d) {
  using Handler = void (Reader::*)(const Directive&);
  static const std::map<DirectiveKind, Handler> handlers{
      {DirectiveKind::assume, &Reader::on_assume},
      {DirectiveKind::unit, &Reader::on_unit},
      {DirectiveKind::let, &Reader::on_let},
      {DirectiveKind::given, &Reader::on_given},
      {DirectiveKind::target, &Reader::on_target},
      {DirectiveKind::from, &Reader::on_from},
      {DirectiveKind::also, &Reader::on_also},
      {DirectiveKind::vector, &Reader::on_vector},
      {DirectiveKind::function, &Reader::on_function},
      {DirectiveKind::units, &Reader::on_units},
      {DirectiveKind::index, &Reader::on_index},
      {DirectiveKind::arrow, &Reader::on_arrow},
      {DirectiveKind::differentials, &Reader::on_differentials},
      {DirectiveKind::forces, &Reader::on_forces},
      {DirectiveKind::matrix, &Reader::on_block},
      {DirectiveKind::column, &Reader::on_block},
      {DirectiveKind::section, &Reader::on_section},
      {DirectiveKind::check, &Reader::on_check},
      {DirectiveKind::claim, &Reader::on_check},
      {DirectiveKind::correction, &Reader::on_correction},
      {DirectiveKind::evidence, &Reader::on_evidence},
      {DirectiveKind::test, &Reader::on_test},
      {DirectiveKind::explanation, &Reader::on_explanation},
      {DirectiveKind::model, &Reader::on_model},
      {DirectiveKind::ode, &Reader::on_model},
      {DirectiveKind::quadrature, &Reader::on_model},
      {DirectiveKind::search, &Reader::on_model},
  };
  (this->*handlers.at(d.kind))(d);
}

void Reader::on_given(const Directive& d) {
  // given: $$|x| = 3$$ on one line was read as given: alone, the next block taken as the premises
  // and |x| = 3 never read.
  if (!d.content.empty()) {
    throw source_.error(d.content_offset,
                        "expected nothing after given: (the premises are the equations of the "
                        "next display block, $$ … $$ on the lines below it)");
  }
  given_ = d.offset;
}

void Reader::on_target(const Directive& d) {
  if (!d.content.empty()) {
    throw source_.error(d.content_offset,
                        "expected nothing after target: (the target is the next display block)");
  }
  target_ = d.offset;
}

void Reader::on_from(const Directive& d) {
  from_ = std::pair{d.offset, named(d)};
}

void Reader::on_also(const Directive& d) {
  also_ = std::pair{d.offset, named(d)};
}

void Reader::on_vector(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    if (piece.empty()) {
      throw source_.error(at, "expected a symbol name in vector:");
    }
    const SymbolName name = read_symbol(source_, at, piece, limits_);
    if (used_scalar(name)) {
      throw source_.error(at, "expected " + name.latex() +
                                  " to be declared a vector before it is used: an "
                                  "equation above already uses it as a number");
    }
    symbols_.declare_vector(name);
  }
}

void Reader::on_arrow(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    const SymbolName name = read_symbol(source_, at, piece, limits_);
    if (!name.subscript.empty() || name.primes != 0 || name.delta) {
      throw source_.error(at, "expected a letter after arrow: (e.g. arrow: p, F)");
    }
    symbols_.declare_arrow(name.base);
  }
}

void Reader::on_differentials(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    symbols_.declare_differential(read_symbol(source_, at, piece, limits_));
  }
}

void Reader::on_forces(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    const SymbolName name = read_symbol(source_, at, piece, limits_);
    Node node;
    node.kind = NodeKind::symbol;
    node.symbol = name;
    const std::vector<std::string> free = symbols_.free_indices(node);
    if (free.empty()) {
      symbols_.declare_force(name);
    } else if (free.size() == 1) {
      for (const long v : symbols_.indices().at(free[0])) {
        symbols_.declare_force(with_index(node, free[0], v).symbol);
      }
    } else {
      throw source_.error(at, "expected a force with at most one index");
    }
  }
}

void Reader::on_index(const Directive& d) {
  // i, k \in \{1, 2\}
  const std::size_t in = d.content.find("\\in");
  const std::size_t open = d.content.find("\\{");
  const std::size_t close = d.content.rfind("\\}");
  if (in == std::string_view::npos || open == std::string_view::npos ||
      close == std::string_view::npos || close < open || open < in) {
    throw source_.error(d.content_offset,
                        "expected index: i \\in \\{1, 2\\} (letters, then the values they take)");
  }
  std::vector<long> values;
  std::string_view list = d.content.substr(open + 2, close - open - 2);
  std::size_t at = d.content_offset + open + 2;
  for (const auto& [where, piece] : split_commas(list, at)) {
    if (piece.empty() || piece.size() > 4 || !std::all_of(piece.begin(), piece.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c));
        })) {
      throw source_.error(where, "expected whole numbers as the values of an index");
    }
    values.push_back(std::stol(std::string(piece)));
  }
  for (const auto& [where, piece] : split_commas(d.content.substr(0, in), d.content_offset)) {
    if (piece.size() != 1 || !std::isalpha(static_cast<unsigned char>(piece[0]))) {
      throw source_.error(where, "expected one letter per index (index: i, k \\in \\{1, 2\\})");
    }
    symbols_.declare_index(std::string(piece), values);
  }
}

void Reader::on_block(const Directive& d) {
  const bool matrix = d.kind == DirectiveKind::matrix;
  const std::size_t equals = d.content.find('=');
  if (equals == std::string_view::npos) {
    throw source_.error(d.content_offset,
                        std::string("expected ") +
                            (matrix ? "matrix: \\mathbf{A} = a_{vi}" : "column: \\vec{B} = b_v") +
                            " (the block, then its entry)");
  }
  std::string_view name_text = d.content.substr(0, equals);
  while (!name_text.empty() && name_text.back() == ' ') {
    name_text.remove_suffix(1);
  }
  std::size_t start = equals + 1;
  while (start < d.content.size() && d.content[start] == ' ') {
    ++start;
  }
  const SymbolName name = read_symbol(source_, d.content_offset, name_text, limits_);
  const Side entry =
      read_expression(source_, d.content_offset + start, d.content.substr(start), limits_);
  symbols_.declare_block(name, entry, matrix, d.content_offset);
}

void Reader::on_let(const Directive& d) {
  // name = expression: split at the first '=' outside braces.
  int depth = 0;
  std::size_t equals = std::string_view::npos;
  for (std::size_t i = 0; i < d.content.size(); ++i) {
    const char c = d.content[i];
    depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (c == '=' && depth == 0) {
      equals = i;
      break;
    }
  }
  if (equals == std::string_view::npos) {
    throw source_.error(d.content_offset, "expected a definition after let: (x = expression)");
  }
  std::string_view name_text = d.content.substr(0, equals);
  while (!name_text.empty() && name_text.back() == ' ') {
    name_text.remove_suffix(1);
  }
  if (name_text.empty()) {
    throw source_.error(d.content_offset, "expected the symbol to define before '='");
  }
  const SymbolName name =
      read_symbol_or_differential(source_, d.content_offset, name_text, limits_);
  if (group_open_ && awaiting_ == Awaiting::statement && !outer_definitions_) {
    outer_definitions_ = symbols_.substitutions();
  }
  std::size_t start = equals + 1;
  while (start < d.content.size() && d.content[start] == ' ') {
    ++start;
  }
  if (start >= d.content.size()) {
    throw source_.error(d.content_offset + equals, "expected an expression after '='");
  }
  const Side definition =
      read_expression(source_, d.content_offset + start, d.content.substr(start), limits_);
  symbols_.define(name, definition, d.content_offset);
  note_used(definition.expression);
}

std::vector<std::size_t> Reader::named(const Directive& d) {
  std::vector<std::size_t> premises;
  std::size_t i = 0;
  const std::string_view text = d.content;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == ',') {
      ++i;
      continue;
    }
    if (text[i] != '(') {
      // Accepted beyond the contract: a check's id names its statement (or its correction).
      std::size_t end = i;
      while (end < text.size() && text[end] != ',' && text[end] != ' ') {
        ++end;
      }
      const std::string id(text.substr(i, end - i));
      const auto named =
          std::find_if(groups_.begin(), groups_.end(), [&](const Group& g) { return g.id == id; });
      if (named == groups_.end() || named->kind == Kind::claim) {
        throw source_.error(d.content_offset + i,
                            "expected tags in parentheses after from:, e.g. from: (2), (3), or "
                            "the id of a check above, found " +
                                id);
      }
      const auto& use = named->correction_equations.empty() ? named->statement_equations
                                                            : named->correction_equations;
      premises.insert(premises.end(), use.begin(), use.end());
      i = end;
      continue;
    }
    const std::size_t close = text.find(')', i);
    if (close == std::string_view::npos) {
      throw source_.error(d.content_offset + i, "expected ')' to close the tag");
    }
    std::string_view label = text.substr(i + 1, close - i - 1);
    while (!label.empty() && label.front() == ' ') {
      label.remove_prefix(1);
    }
    while (!label.empty() && label.back() == ' ') {
      label.remove_suffix(1);
    }
    const auto tagged = tags_.find(std::string(label));
    if (tagged == tags_.end()) {
      throw source_.error(d.content_offset + i,
                          "expected the tag of an equation above, found (" + std::string(label) +
                              "): no equation before this line carries \\tag{" +
                              std::string(label) + "}");
    }
    premises.insert(premises.end(), tagged->second.begin(), tagged->second.end());
    i = close + 1;
  }
  if (premises.empty()) {
    throw source_.error(d.content_offset, "expected tags after " + std::string(to_string(d.kind)) +
                                              ":, e.g. (2), (3)");
  }
  return premises;
}

void Reader::on_units(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    const std::size_t open = piece.find('[');
    const std::size_t close = piece.rfind(']');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
      throw source_.error(at,
                          "expected a symbol and its dimension in brackets, e.g. "
                          "p [M L T^-1]");
    }
    std::string_view name_text = piece.substr(0, open);
    while (!name_text.empty() && name_text.back() == ' ') {
      name_text.remove_suffix(1);
    }
    if (name_text.empty()) {
      throw source_.error(at, "expected a symbol before the dimension");
    }
    if (close + 1 != piece.size()) {
      throw source_.error(at + close + 1, "expected ',' or the end of the line after ']'");
    }
    const SymbolName name = read_symbol(source_, at, name_text, limits_);
    const Dimension dimension =
        read_dimension(source_, at + open + 1, piece.substr(open + 1, close - open - 1));
    symbols_.declare_units(name, dimension, at);
  }
}

void Reader::symbol_fact(std::size_t at, const SymbolName& name, Sign sign) {
  const ex symbol = symbols_.scalar_of(name);
  if (symbol.is_zero()) {
    throw source_.error(at, "expected a scalar symbol in assume:, found " + name.latex() +
                                ", a vector (facts are about numbers: give them for its "
                                "components)");
  }
  if (const auto defined = symbols_.substitutions().find(symbol);
      defined != symbols_.substitutions().end()) {
    facts_.add_relation(defined->second, sign);  // a fact on what the symbol stands for
    return;
  }
  if (!facts_.add(symbol, sign)) {
    throw source_.error(at, "expected facts that agree: " + relation_latex(name.latex(), sign) +
                                " contradicts " +
                                relation_latex(name.latex(), facts_.of_symbol(symbol)));
  }
}

namespace {

const char* const fact_forms =
    "expected facts of the forms x > 0, m_1, m_2 > 0 (symbols before one relation), "
    "m_1 + m_2 > 0, a < b (relations between expressions), 0 \\le e \\le 1 (a range), "
    "e \\in [0, 1], or \\|\\vec n\\| = 1 (a unit vector)";

bool holds_relation(std::string_view piece) {
  for (const char* r :
       {"<", ">", "=", "\\le", "\\ge", "\\ne", "\\lt", "\\gt", "\\in", "\u2264", "\u2265"}) {
    if (piece.find(r) != std::string_view::npos) {
      return true;
    }
  }
  return false;
}

Sign sign_of(Relation::Kind kind) {
  switch (kind) {
    case Relation::Kind::greater:
      return Sign::positive;
    case Relation::Kind::less:
      return Sign::negative;
    case Relation::Kind::greater_equal:
      return Sign::nonnegative;
    case Relation::Kind::less_equal:
      return Sign::nonpositive;
    case Relation::Kind::not_equal:
      return Sign::nonzero;
    default:
      return Sign::unknown;
  }
}

}  // namespace

// assume := fact {',' fact}; fact := symbol {',' symbol} relation expression
//         | expression relation expression {relation expression} | expression '\in' interval
namespace {

// Where a word of prose stands in a directive's LaTeX, if one does: three letters or more between
// spaces or parentheses, not a command's name nor a subscript (assume: x > 1 (for safety) read
// "for safety" as a product of letters, and the fact x > 1 was lost).
std::optional<std::size_t> word_in(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    if (!std::isalpha(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && std::isalpha(static_cast<unsigned char>(text[end]))) {
      ++end;
    }
    const bool before = i == 0 || text[i - 1] == ' ' || text[i - 1] == '(';
    const bool after = end == text.size() || text[end] == ' ' || text[end] == ')' ||
                       text[end] == ',' || text[end] == '.';
    if (end - i >= 3 && before && after) {
      return i;
    }
    i = end;
  }
  return std::nullopt;
}

}  // namespace

void Reader::on_assume(const Directive& d) {
  if (d.content.empty()) {
    throw source_.error(d.content_offset, "expected facts after assume: (e.g. m_1, m_2 > 0)");
  }
  if (const auto word = word_in(d.content)) {
    throw source_.error(d.content_offset + *word,
                        "expected facts without words: words belong on a line of their own, "
                        "outside the directive (read as letters, they would be a product)");
  }
  std::vector<std::pair<std::size_t, SymbolName>> pending;
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    if (piece.empty()) {
      throw source_.error(at, fact_forms);
    }
    if (!holds_relation(piece)) {
      try {
        pending.emplace_back(at, read_symbol(source_, at, piece, limits_));
      } catch (const ReadError& e) {
        throw ReadError(e.place(), std::string(fact_forms) + "; " + e.what());
      }
      continue;
    }
    const std::vector<Relation> relations = read_relation_list(source_, at, piece, limits_);
    if (!pending.empty()) {
      // m_1, m_2 > 0: each symbol before the relation takes it.
      const Relation& first = relations.front();
      if (first.left.expression.kind != NodeKind::symbol) {
        throw source_.error(first.left.offset,
                            std::string(fact_forms) + "; a list of symbols takes one relation");
      }
      for (const auto& [where, name] : pending) {
        Relation r = first;
        r.left.expression.symbol = name;
        r.left.latex = name.latex();
        r.offset = where;
        fact(where, r);
      }
      pending.clear();
    }
    for (const Relation& r : relations) {
      fact(r.left.offset, r);
    }
  }
  if (!pending.empty()) {
    throw source_.error(pending.back().first,
                        std::string(fact_forms) + "; this symbol has no relation after it");
  }
}

// One relation of assume:, as facts: the sign of a symbol, of an expression, an equality.
void Reader::fact(std::size_t at, const Relation& r) {
  for (const Side* side : {&r.left, &r.right}) {
    symbols_.note_quantities(side->expression);
  }
  const auto value = [&](const Side& side) {
    note_used(side.expression);
    const Meaning m = symbols_.meaning(side.expression);
    if (m.value.vector || m.value.block()) {
      throw source_.error(side.offset,
                          "expected a number in assume:, found a vector (facts are about "
                          "numbers: give them for its components, or its length \\|\\vec n\\|)");
    }
    return m.value.x.subs(symbols_.substitutions());
  };
  if (r.kind == Relation::Kind::in_set) {
    throw source_.error(at, std::string(fact_forms) + "; a set of values is not a fact read here");
  }
  if (r.kind == Relation::Kind::in_range) {
    const ex x = value(r.left);
    const auto bound = [&](const ex& difference, bool closed) {
      const Sign sign = closed ? Sign::nonnegative : Sign::positive;
      relation_agrees(at, difference, sign);
      facts_.add_relation(difference, sign);
    };
    if (r.low) {
      bound(x - value(*r.low), r.low_closed);
    }
    if (r.high) {
      bound(value(*r.high) - x, r.high_closed);
    }
    return;
  }
  if (r.left.expression.kind == NodeKind::symbol && r.right.latex == "0" &&
      r.kind != Relation::Kind::equal) {
    symbol_fact(at, r.left.expression.symbol, sign_of(r.kind));
    return;
  }
  const ex difference = value(r.left) - value(r.right);
  if (r.kind == Relation::Kind::equal) {
    // \|\vec n\| = 1 is n_x^2 + n_y^2 = 1, read without the root.
    const bool norm = r.left.expression.kind == NodeKind::norm ||
                      (r.left.expression.kind == NodeKind::abs &&
                       symbols_.meaning(r.left.expression.children[0]).value.vector);
    if (norm) {
      const Value v = symbols_.meaning(r.left.expression.children[0]).value;
      const ex right = value(r.right);
      facts_.add_equality(v.x * v.x + v.y * v.y - right * right);
      facts_.add_relation(right, Sign::nonnegative);
      equalities_agree(at);
      return;
    }
    facts_.add_equality(difference);
    equalities_agree(at);
    return;
  }
  if (GiNaC::is_a<GiNaC::numeric>(difference)) {
    throw source_.error(at, "expected a fact about symbols, found one about numbers alone");
  }
  relation_agrees(at, difference, sign_of(r.kind));
  facts_.add_relation(difference, sign_of(r.kind));
}

// A relation the facts before it already contradict (a, b > 0 then a + b < 0; 0 ≤ e ≤ 1 then
// e > 2): no values satisfy them together, and every step would follow from them.
void Reader::relation_agrees(std::size_t at, const ex& difference, Sign sign) const {
  const Sign known = facts_.sign(difference);
  if (opposite(sign) != Sign::unknown && gives(known, opposite(sign))) {
    throw source_.error(
        at, "expected facts that agree: " + relation_latex(sym::latex(difference), sign) +
                " contradicts the facts before it, which give " +
                relation_latex(sym::latex(difference), known) +
                " (no values satisfy them together, and every step would "
                "follow from them)");
  }
}

// The facts' equalities have real values that satisfy them with the other facts: z^2 + 1 = 0,
// x = 1 with x = 2, or n_x = 2 of a unit vector have none, and every step would follow.
void Reader::equalities_agree(std::size_t at) const {
  Budget quick;
  quick.attempts = 0;
  quick.deadline = after(0.5);
  const Implication none = implies({facts_.equalities(), {}, 1, {}}, facts_, quick);
  if (none.outcome == Implication::Outcome::holds) {
    throw source_.error(at,
                        "expected facts that agree: no real values satisfy this equality "
                        "together with the facts before it (every step would follow from them)");
  }
}

// unit: n, m — unit vectors (\|\vec n\| = 1).
void Reader::on_unit(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    if (piece.empty()) {
      throw source_.error(at, "expected a vector's name in unit:");
    }
    const SymbolName name = read_symbol(source_, at, piece, limits_);
    const Value v = symbols_.value_of(name);
    if (!v.vector) {
      throw source_.error(
          at, "expected a vector in unit: (declare it with vector: " + name.latex() + " first)");
    }
    facts_.add_equality(v.x * v.x + v.y * v.y - 1);
    equalities_agree(at);
  }
}

// function: F, x(t), u(x, t) — functions of one variable (t unless written) or of several.
void Reader::on_function(const Directive& d) {
  for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
    if (piece.empty()) {
      throw source_.error(at, "expected a function's name in function:");
    }
    const std::size_t open = piece.find('(');
    std::vector<SymbolName> variables;
    std::string_view name_text = piece;
    if (open != std::string_view::npos) {
      if (piece.back() != ')') {
        throw source_.error(at + piece.size(), "expected ')' to close the variables of " +
                                                   std::string(piece.substr(0, open)));
      }
      name_text = piece.substr(0, open);
      const std::string_view inside = piece.substr(open + 1, piece.size() - open - 2);
      for (const auto& [where, v] : split_commas(inside, at + open + 1)) {
        variables.push_back(read_symbol(source_, where, v, limits_));
      }
    }
    while (!name_text.empty() && name_text.back() == ' ') {
      name_text.remove_suffix(1);
    }
    const SymbolName name = read_symbol(source_, at, name_text, limits_);
    if (used_scalar(name)) {
      throw source_.error(at, "expected " + name.latex() +
                                  " to be declared a function before it is used: an equation "
                                  "above already uses it as a number");
    }
    symbols_.declare_function(name, std::move(variables), at);
  }
}

}  // namespace impulse::derivations::file
