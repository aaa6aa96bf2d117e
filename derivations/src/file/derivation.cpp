// SPDX-License-Identifier: GPL-3.0-or-later
// A derivation file, end to end: its Markdown read into blocks and directives, the blocks into
// equations (rows, chains, tags), each step given the equations it must follow from, and each
// decided exactly first and numerically as a second opinion.
#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "derivations/derivation.hpp"
#include "impulse/core/error.hpp"
#include "file/decide.hpp"
#include "file/facts.hpp"
#include "file/latex.hpp"
#include "file/markdown.hpp"
#include "file/meaning.hpp"
#include "file/sample.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

std::string_view to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::premise:
      return "premise";
    case Verdict::follows:
      return "follows";
    case Verdict::follows_one_way:
      return "follows-one-way";
    case Verdict::follows_if:
      return "follows-if";
    case Verdict::does_not_follow:
      return "does-not-follow";
    case Verdict::dimensions:
      return "dimensions";
    case Verdict::undecided:
      return "undecided";
  }
  return "?";
}

int exit_status(const DerivationReport& report) {
  return report.count(Verdict::does_not_follow) + report.count(Verdict::dimensions) +
                     report.count(Verdict::undecided) >
                 0
             ? 1
             : 0;
}

namespace {

using GiNaC::ex;
using namespace file;

// ---- the equations of the file -----------------------------------------------------------------

// One equation as it will be checked: for a link of a chain a = b = c, "a = c".
struct Equation {
  std::size_t offset = 0;
  std::optional<std::string> tag;
  std::string latex;
  bool premise = false;
  Meaning lhs;
  Meaning rhs;
  std::vector<std::size_t> premises;  // indices of the equations it must follow from
  Facts facts;                        // the facts in force at its line
  GiNaC::exmap substitutions;         // the definitions in force at its line
  std::optional<DimensionIssue> dimension_issue;
};

// The pieces of a directive's LaTeX separated by commas outside braces and brackets.
std::vector<std::pair<std::size_t, std::string_view>> split_commas(std::string_view text,
                                                                   std::size_t offset) {
  std::vector<std::pair<std::size_t, std::string_view>> pieces;
  int depth = 0;
  std::size_t start = 0;
  const auto push = [&](std::size_t end) {
    std::size_t a = start;
    std::size_t b = end;
    while (a < b && (text[a] == ' ' || text[a] == '\t')) {
      ++a;
    }
    while (b > a && (text[b - 1] == ' ' || text[b - 1] == '\t')) {
      --b;
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

class Reader {
 public:
  Reader(const Source& source, const Limits& limits)
      : source_(source), limits_(limits), symbols_(source, limits) {}

  std::vector<Equation> read() {
    for (const Item& item : read_markdown(source_, limits_)) {
      if (const auto* directive = std::get_if<Directive>(&item)) {
        read_directive(*directive);
      } else {
        read_block(std::get<Block>(item));
      }
    }
    if (given_) {
      throw source_.error(*given_, "expected a display block after given:");
    }
    if (from_) {
      throw source_.error(from_->first, "expected a display equation after from:");
    }
    if (equations_.empty()) {
      throw source_.error(source_.text().size(),
                          "expected a display equation ($$ … $$): the file has none");
    }
    return std::move(equations_);
  }

  Symbols& symbols() { return symbols_; }

 private:
  // ---- directives ----
  void read_directive(const Directive& d) {
    switch (d.kind) {
      case DirectiveKind::assume:
        assume(d);
        break;
      case DirectiveKind::let:
        let(d);
        break;
      case DirectiveKind::given:
        given_ = d.offset;
        break;
      case DirectiveKind::from:
        from(d);
        break;
      case DirectiveKind::vector:
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
        break;
      case DirectiveKind::units:
        units(d);
        break;
    }
  }

  bool used_scalar(const SymbolName& name) const { return used_.contains(name.unprimed().latex()); }

  void assume(const Directive& d) {
    if (d.content.empty()) {
      throw source_.error(d.content_offset, "expected facts after assume: (e.g. m_1, m_2 > 0)");
    }
    static const std::pair<std::string_view, Sign> relations[] = {
        {"\\geqslant", Sign::nonnegative},
        {"\\leqslant", Sign::nonpositive},
        {"\\geq", Sign::nonnegative},
        {"\\leq", Sign::nonpositive},
        {"\\neq", Sign::nonzero},
        {"\\ge", Sign::nonnegative},
        {"\\le", Sign::nonpositive},
        {"\\ne", Sign::nonzero},
        {"\\gt", Sign::positive},
        {"\\lt", Sign::negative},
        {">=", Sign::nonnegative},
        {"<=", Sign::nonpositive},
        {"!=", Sign::nonzero},
        {">", Sign::positive},
        {"<", Sign::negative},
    };
    const char* const forms =
        "expected facts of the forms x > 0, x < 0, x \\geq 0, x \\leq 0, x \\neq 0 (a symbol "
        "or a list of symbols before one relation to 0)";
    std::vector<std::pair<std::size_t, SymbolName>> pending;
    for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
      if (piece.empty()) {
        throw source_.error(at, forms);
      }
      // Find the relation in the piece.
      std::optional<std::pair<std::size_t, std::pair<std::string_view, Sign>>> found;
      for (std::size_t i = 0; i < piece.size() && !found; ++i) {
        for (const auto& r : relations) {
          if (piece.substr(i, r.first.size()) == r.first &&
              !(r.first[0] == '\\' && i + r.first.size() < piece.size() &&
                std::isalpha(static_cast<unsigned char>(piece[i + r.first.size()])))) {
            found = std::pair{i, r};
            break;
          }
        }
      }
      std::string_view name_text = found ? piece.substr(0, found->first) : piece;
      while (!name_text.empty() && name_text.back() == ' ') {
        name_text.remove_suffix(1);
      }
      if (name_text.empty()) {
        throw source_.error(at, forms);
      }
      try {
        pending.emplace_back(at, read_symbol(source_, at, name_text, limits_));
      } catch (const ReadError& e) {
        throw ReadError(e.place(), std::string(forms) + "; " + e.what());
      }
      if (!found) {
        continue;
      }
      std::string_view rest = piece.substr(found->first + found->second.first.size());
      while (!rest.empty() && rest.front() == ' ') {
        rest.remove_prefix(1);
      }
      if (rest != "0") {
        throw source_.error(at + found->first, std::string(forms) + "; found a relation to " +
                                                   (rest.empty() ? "nothing" : std::string(rest)));
      }
      for (const auto& [where, name] : pending) {
        fact(where, name, found->second.second);
      }
      pending.clear();
    }
    if (!pending.empty()) {
      throw source_.error(pending.back().first,
                          std::string(forms) + "; this symbol has no relation after it");
    }
  }

  void fact(std::size_t at, const SymbolName& name, Sign sign) {
    const ex symbol = symbols_.scalar_of(name);
    if (symbol.is_zero()) {
      throw source_.error(at, "expected a scalar symbol in assume:, found " + name.latex() +
                                  ", a vector (facts are about numbers: give them for its "
                                  "components)");
    }
    if (symbols_.substitutions().count(symbol) != 0) {
      throw source_.error(at, "expected a symbol that is not defined by let: (" + name.latex() +
                                  " stands for its definition, whose sign is what it is)");
    }
    if (!facts_.add(symbol, sign)) {
      throw source_.error(at, "expected facts that agree: " + relation_latex(name.latex(), sign) +
                                  " contradicts " +
                                  relation_latex(name.latex(), facts_.of_symbol(symbol)));
    }
  }

  void let(const Directive& d) {
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
    const SymbolName name = read_symbol(source_, d.content_offset, name_text, limits_);
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

  void from(const Directive& d) {
    std::vector<std::size_t> premises;
    std::size_t i = 0;
    const std::string_view text = d.content;
    while (i < text.size()) {
      if (text[i] == ' ' || text[i] == ',') {
        ++i;
        continue;
      }
      if (text[i] != '(') {
        throw source_.error(d.content_offset + i,
                            "expected tags in parentheses after from:, e.g. from: (2), (3)");
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
      throw source_.error(d.content_offset, "expected tags after from:, e.g. from: (2), (3)");
    }
    from_ = std::pair{d.offset, premises};
  }

  void units(const Directive& d) {
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

  // ---- blocks ----
  void note_used(const Node& node) {
    if (node.kind == NodeKind::symbol) {
      used_.insert(node.symbol.unprimed().latex());
    }
    for (const Node& child : node.children) {
      note_used(child);
    }
  }

  void read_block(const Block& block) {
    const bool given = given_.has_value();
    given_.reset();
    if (given) {
      if (from_) {
        throw source_.error(from_->first,
                            "expected a step after from:, found the premises of "
                            "a given: block");
      }
      block_premises_.clear();
    }
    const std::vector<Row> rows = read_block_rows(block);
    for (const Row& row : rows) {
      std::vector<std::size_t> of_row;
      if (row.continues && equations_.empty()) {
        throw source_.error(row.offset,
                            "expected an equation before this row that begins with "
                            "'=' (it continues the equation before)");
      }
      for (std::size_t k = 1; k < row.sides.size(); ++k) {
        const Side& right = row.sides[k];
        note_used(right.expression);
        Equation e;
        const bool first_link = k == 1 && !row.continues;
        if (first_link) {
          const Side& left = row.sides[0];
          note_used(left.expression);
          e.offset = left.offset;
          e.latex = left.latex + " = " + right.latex;
          e.lhs = meaning(left.expression);
          chain_start_ = e.lhs;
          chain_start_node_ = left.expression;
          last_right_latex_ = left.latex;
          dimension(e, left.expression, right.expression);
        } else {
          // a = b = c: the link b = c is checked as a = c, from a = b.
          e.offset = row.continues && k == 1 ? row.offset : row.sides[k - 1].offset;
          e.latex = (row.continues && k == 1 ? last_right_latex_ : row.sides[k - 1].latex) + " = " +
                    right.latex;
          e.lhs = chain_start_;
          if (row.continues && k == 1) {
            dimension(e, last_right_node_, right.expression);
          } else {
            dimension(e, row.sides[k - 1].expression, right.expression);
          }
        }
        e.rhs = meaning(right.expression);
        if (e.lhs.value.vector != e.rhs.value.vector) {
          throw source_.error(right.offset, std::string("expected ") +
                                                (e.lhs.value.vector ? "a vector" : "a scalar") +
                                                " on this side, as on the other, found " +
                                                (e.rhs.value.vector ? "a vector" : "a scalar"));
        }
        last_right_latex_ = right.latex;
        last_right_node_ = right.expression;
        e.facts = facts_;
        e.substitutions = symbols_.substitutions();
        const bool premise = given || equations_.empty();
        e.premise = premise;
        if (!premise) {
          if (first_link && from_) {
            e.premises = from_->second;
            from_.reset();
          } else if (first_link) {
            e.premises = previous_;
          } else {
            e.premises = {equations_.size() - 1};
          }
        }
        const std::size_t index = equations_.size();
        equations_.push_back(std::move(e));
        of_row.push_back(index);
        if (given) {
          block_premises_.push_back(index);
        }
      }
      if (row.tag) {
        equations_[of_row.back()].tag = row.tag;
        if (tags_.contains(*row.tag)) {
          throw source_.error(row.offset, "expected a new tag, found \\tag{" + *row.tag +
                                              "} that an equation above already carries");
        }
        // A tagged chain stands for its last link, which carries the whole chain (a = c).
        tags_[*row.tag] = {of_row.back()};
      }
      previous_ = given ? block_premises_ : std::vector<std::size_t>{equations_.size() - 1};
    }
  }

  std::vector<Row> read_block_rows(const Block& block) {
    return file::read_block(source_, block.content_offset, block.content, limits_);
  }

  Meaning meaning(const Node& node) { return symbols_.meaning(node); }

  void dimension(Equation& e, const Node& left, const Node& right) {
    const auto l = symbols_.dimension(left);
    if (l.issue) {
      e.dimension_issue = l.issue;
      return;
    }
    const auto r = symbols_.dimension(right);
    if (r.issue) {
      e.dimension_issue = r.issue;
      return;
    }
    if (l.dimension && r.dimension && !(*l.dimension == *r.dimension)) {
      e.dimension_issue = DimensionIssue{right.offset, *l.dimension, *r.dimension,
                                         "the left side has dimension " + l.dimension->text() +
                                             ", the right side " + r.dimension->text()};
    }
  }

  const Source& source_;
  const Limits& limits_;
  Symbols symbols_;
  Facts facts_;
  std::vector<Equation> equations_;
  std::map<std::string, std::vector<std::size_t>> tags_;
  std::set<std::string> used_;
  std::optional<std::size_t> given_;
  std::optional<std::pair<std::size_t, std::vector<std::size_t>>> from_;
  std::vector<std::size_t> previous_;
  std::vector<std::size_t> block_premises_;
  Meaning chain_start_;
  Node chain_start_node_;
  std::string last_right_latex_;
  Node last_right_node_;
};

// ---- deciding ----------------------------------------------------------------------------------

std::string trimmed(std::string text) {
  const std::size_t first = text.find_first_not_of(' ');
  const std::size_t last = text.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

std::string latex_of(const ex& e) {
  std::ostringstream out;
  out << GiNaC::latex << e;
  return trimmed(out.str());
}

std::string plain_of(const ex& e) {
  // Over one denominator, printed as numerator/denominator: "4*p_2/m_2", not "4*m_2^(-1)*p_2".
  const auto print = [](const ex& x) {
    std::ostringstream out;
    out << GiNaC::dflt << x;
    return out.str();
  };
  const auto grouped = [&](const ex& x, bool denominator) {
    const std::string t = print(x);
    const bool group = GiNaC::is_a<GiNaC::add>(x) || (denominator && GiNaC::is_a<GiNaC::mul>(x));
    return group ? "(" + t + ")" : t;
  };
  ex parts;
  try {
    parts = GiNaC::normal(e).numer_denom();
  } catch (const std::exception&) {
    return print(e);
  }
  const ex numerator = parts.op(0);
  const ex denominator = parts.op(1);
  if (denominator.is_equal(1)) {
    return print(numerator);
  }
  return grouped(numerator, false) + "/" + grouped(denominator, true);
}

// A residual as a person reads it: over one denominator, factored when that is cheap.
ex readable(const ex& e) {
  const ex n = GiNaC::normal(e);
  if (!factorable(n.numer()) || !factorable(n.denom())) {
    return n;  // shown over one denominator, unfactored
  }
  try {
    return GiNaC::factor(n.numer()) / GiNaC::factor(n.denom());
  } catch (const std::exception&) {
    return n;
  }
}

std::string number_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

struct Scalars {
  std::vector<ex> differences;  // each = 0
  std::vector<ex> scales;
  std::vector<ex> denominators;
};

Scalars scalars_of(const Equation& e, const GiNaC::exmap& substitutions) {
  Scalars s;
  const auto add = [&](const ex& l, const ex& r) {
    const ex difference = (l - r).subs(substitutions);
    s.differences.push_back(difference);
    s.scales.push_back(term_scale(l.subs(substitutions)) + term_scale(r.subs(substitutions)));
  };
  add(e.lhs.value.x, e.rhs.value.x);
  if (e.lhs.value.vector) {
    add(e.lhs.value.y, e.rhs.value.y);
  }
  for (const ex& d : e.lhs.denominators) {
    s.denominators.push_back(d.subs(substitutions));
  }
  for (const ex& d : e.rhs.denominators) {
    s.denominators.push_back(d.subs(substitutions));
  }
  return s;
}

class Checker {
 public:
  Checker(Symbols& symbols, const DerivationOptions& options)
      : symbols_(symbols), options_(options) {}

  EquationResult check(const std::vector<Equation>& equations, std::size_t index,
                       const Source& source) {
    const Equation& e = equations[index];
    EquationResult r;
    const Place place = source.place(e.offset);
    r.line = place.line;
    r.column = place.column;
    r.tag = e.tag;
    r.latex = e.latex;
    for (const std::size_t p : e.premises) {
      r.from.push_back(source.place(equations[p].offset).line);
    }
    if (e.dimension_issue) {
      r.verdict = Verdict::dimensions;
      r.dimension_first = e.dimension_issue->first.text();
      r.dimension_second = e.dimension_issue->second.text();
      r.dimension_what = e.dimension_issue->what;
      r.how = "units: " + e.dimension_issue->what;
      return r;
    }
    if (e.premise) {
      r.verdict = Verdict::premise;
      return r;
    }
    decide(equations, e, index, r);
    return r;
  }

 private:
  void decide(const std::vector<Equation>& equations, const Equation& e, std::size_t index,
              EquationResult& r) {
    const Scalars step = scalars_of(e, e.substitutions);
    Scalars before;
    for (const std::size_t p : e.premises) {
      const Scalars s = scalars_of(equations[p], e.substitutions);
      before.differences.insert(before.differences.end(), s.differences.begin(),
                                s.differences.end());
      before.scales.insert(before.scales.end(), s.scales.begin(), s.scales.end());
      before.denominators.insert(before.denominators.end(), s.denominators.begin(),
                                 s.denominators.end());
    }

    // The exact method, component by component.
    Implication forward;
    forward.outcome = Implication::Outcome::holds;
    for (const ex& target : step.differences) {
      Implication one =
          implies({before.differences, before.denominators, target, step.denominators}, e.facts);
      merge(forward, one);
    }

    // The numeric method, as a second opinion. Where the exact method found conditions, the
    // points where one of them is zero are left out like those where a denominator is.
    NumericOpinion numeric;
    for (std::size_t k = 0; k < step.differences.size(); ++k) {
      std::vector<ex> denominators = before.denominators;
      denominators.insert(denominators.end(), step.denominators.begin(), step.denominators.end());
      if (forward.outcome == Implication::Outcome::holds_if) {
        denominators.insert(denominators.end(), forward.conditions.begin(),
                            forward.conditions.end());
      }
      NumericProblem problem{before.differences, before.scales, denominators, step.differences[k],
                             step.scales[k]};
      const NumericOpinion one =
          sample(problem, e.facts, options_.seed * 7919 + index * 31 + k, options_.samples);
      numeric.points += one.points;
      numeric.worst = std::max(numeric.worst, one.worst);
      if (!numeric.counterexample && one.counterexample) {
        numeric.counterexample = one.counterexample;
        numeric.counterexample_residual = one.counterexample_residual;
      }
      numeric.how = one.how;
    }
    r.numeric_points = numeric.points;
    r.numeric_worst = numeric.worst;

    using O = Implication::Outcome;
    const std::string numeric_note = numeric.points == 0 ? "numeric: " + numeric.how
                                                         : "numeric: " + numeric.how +
                                                               ", worst relative residual " +
                                                               num::brief(numeric.worst, 2);
    switch (forward.outcome) {
      case O::holds:
      case O::holds_if: {
        if (numeric.counterexample) {
          r.verdict = Verdict::undecided;
          r.how = "the exact method finds that it follows (" + forward.how +
                  "), but the numeric method finds a point where it fails (relative residual " +
                  num::brief(numeric.counterexample_residual, 2) +
                  "): the two disagree, so no verdict is given";
          numeric_point(*numeric.counterexample, r);
          return;
        }
        r.decided_by = "exact";
        if (forward.outcome == O::holds_if) {
          r.verdict = Verdict::follows_if;
          ex product = 1;
          std::string text;
          for (const ex& c : forward.conditions) {
            product *= c;
          }
          r.condition = latex_of(product) + " \\neq 0";
          r.condition_text = plain_of(product) + " != 0";
          r.condition_needed = forward.conditions_needed;
          r.how = "exact: " + forward.how + "; " + numeric_note;
          if (!forward.conditions_needed) {
            r.how += "; whether the condition is needed was not decided";
          }
          return;
        }
        const std::optional<bool> converse = converse_holds(before, step, e.facts);
        r.converse = converse;
        r.verdict = converse.value_or(false) ? Verdict::follows : Verdict::follows_one_way;
        r.how = "exact: " + (forward.how.empty() ? std::string("it holds once the equations "
                                                               "before are used")
                                                 : forward.how);
        if (!converse) {
          r.how += "; whether the equations before follow from it was not decided";
        } else if (!*converse) {
          r.how += "; the equations before do not follow from it";
        }
        r.how += "; " + numeric_note;
        return;
      }
      case O::fails: {
        r.verdict = Verdict::does_not_follow;
        r.decided_by = "exact";
        residual(forward.residual, r);
        exact_point(*forward.point, r);
        r.how = "exact: " +
                (forward.how.empty() ? std::string("what is left of the step does "
                                                   "not vanish")
                                     : forward.how) +
                "; the counterexample satisfies the equations before and the facts exactly";
        return;
      }
      case O::unknown:
        break;
    }
    if (numeric.counterexample) {
      r.verdict = Verdict::does_not_follow;
      r.decided_by = "numeric";
      residual(forward.residual, r);
      numeric_point(*numeric.counterexample, r);
      r.how = "exact: undecided (" + forward.how +
              "); numeric: a point on the equations before "
              "where the step fails (relative residual " +
              num::brief(numeric.counterexample_residual, 2) + ")";
      return;
    }
    r.verdict = Verdict::undecided;
    r.how = "exact: " + forward.how + "; " + numeric_note +
            " (agreement at random points is not a proof)";
  }

  static void merge(Implication& total, const Implication& one) {
    using O = Implication::Outcome;
    if (total.outcome == O::fails) {
      return;
    }
    if (one.outcome == O::fails) {
      total = one;
      return;
    }
    if (one.outcome == O::unknown) {
      total.outcome = O::unknown;
      total.residual = one.residual;
      total.how = one.how;
      return;
    }
    if (total.outcome == O::unknown) {
      return;
    }
    if (one.outcome == O::holds_if) {
      total.outcome = O::holds_if;
      total.conditions.insert(total.conditions.end(), one.conditions.begin(), one.conditions.end());
      total.conditions_needed = total.conditions_needed && one.conditions_needed;
    }
    if (total.how.empty()) {
      total.how = one.how;
    } else if (!one.how.empty() && one.how != total.how) {
      total.how += "; " + one.how;
    }
  }

  static std::optional<bool> converse_holds(const Scalars& before, const Scalars& step,
                                            const Facts& facts) {
    using O = Implication::Outcome;
    // Only whether the converse fails matters here, not the nicest point that shows it.
    Budget budget;
    budget.attempts = 48;
    budget.candidates = 1;
    bool all = true;
    for (const ex& target : before.differences) {
      const Implication back = implies(
          {step.differences, step.denominators, target, before.denominators}, facts, budget);
      if (back.outcome == O::fails || back.outcome == O::holds_if) {
        return false;
      }
      if (back.outcome == O::unknown) {
        all = false;
      }
    }
    return all ? std::optional<bool>(true) : std::nullopt;
  }

  void residual(const ex& e, EquationResult& r) const {
    const ex shown = readable(e);
    r.residual = latex_of(shown);
    r.residual_text = plain_of(shown);
  }

  // A point of symbol values, grouped into the file's vectors.
  template <typename Value>
  void point(const std::vector<std::pair<ex, Value>>& values, EquationResult& r,
             const std::function<double(const Value&)>& to_double,
             const std::function<std::string(const Value&)>& exact) const {
    std::map<std::string, CounterexampleValue> entries;
    for (const auto& [symbol, value] : values) {
      const SymbolInfo* info = symbols_.info(symbol);
      if (info == nullptr) {
        continue;
      }
      if (info->of) {
        CounterexampleValue& v = entries[info->of->latex()];
        v.symbol = info->of->latex();
        v.vector = true;
        (info->component == 0 ? v.x : v.y) = to_double(value);
        (info->component == 0 ? v.exact_x : v.exact_y) = exact(value);
      } else {
        CounterexampleValue& v = entries[info->name.latex()];
        v.symbol = info->name.latex();
        v.x = to_double(value);
        v.exact_x = exact(value);
      }
    }
    for (auto& [name, value] : entries) {
      r.counterexample.push_back(std::move(value));
    }
  }

  void exact_point(const GiNaC::exmap& values, EquationResult& r) const {
    std::vector<std::pair<ex, ex>> list(values.begin(), values.end());
    point<ex>(
        list, r,
        [](const ex& v) {
          const ex f = GiNaC::evalf(v);
          return GiNaC::is_a<GiNaC::numeric>(f) ? GiNaC::ex_to<GiNaC::numeric>(f).to_double() : 0.0;
        },
        [](const ex& v) {
          return GiNaC::is_a<GiNaC::numeric>(v) ? number_text(GiNaC::ex_to<GiNaC::numeric>(v))
                                                : plain_of(v);
        });
    r.counterexample_exact = true;
  }

  void numeric_point(const std::vector<std::pair<ex, double>>& values, EquationResult& r) const {
    point<double>(
        values, r, [](const double& v) { return v; }, [](const double&) { return std::string(); });
    r.counterexample_exact = false;
  }

  Symbols& symbols_;
  const DerivationOptions& options_;
};

}  // namespace

DerivationReport check_derivation(std::string text, const std::string& file_name,
                                  const DerivationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  num::quiet_gsl();
  // The numeric method evaluates a student's expressions at random points, where they may divide
  // by zero or overflow: that is its business (it discards such points), never a SIGFPE for a
  // caller that traps floating-point exceptions (the Debug test programs do).
  const impulse::detail::HeldFloatingPointExceptions held;
  Limits limits;
  limits.bytes = max_derivation_bytes;
  try {
    const Source source(std::move(text), limits);
    Reader reader(source, limits);
    const std::vector<Equation> equations = reader.read();
    DerivationReport report;
    report.file = file_name;
    Checker checker(reader.symbols(), options);
    for (std::size_t i = 0; i < equations.size(); ++i) {
      const auto begin = std::chrono::steady_clock::now();
      report.equations.push_back(checker.check(equations, i, source));
      const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - begin;
      report.equations.back().seconds = spent.count();
      ++report.counts[static_cast<std::size_t>(report.equations.back().verdict)];
    }
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    report.seconds = took.count();
    return report;
  } catch (const ReadError& e) {
    throw DerivationError(e.place().line, e.place().column, e.what());
  }
}

}  // namespace impulse::derivations
