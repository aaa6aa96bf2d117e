// SPDX-License-Identifier: GPL-3.0-or-later
// Display blocks read into equations: each row's sides, one equation per link of a chain (a = b
// = c is a = b, then a = c from it), one row per value of a free index, each equation with the
// equations it must follow from, the facts and definitions in force, and its dimensions.
#include "file/reader.hpp"

#include "file/calculus.hpp"

#include <algorithm>

namespace impulse::derivations::file {

using GiNaC::ex;

namespace {

// `function: F` makes F a function of t, and a premise F(x) = 3x, written with F's value on one
// side and x free on the other, is F's rule for every x to one reader and its value at one x to
// another (F(T) = 2J/T). Two readings: refused, naming the declaration that says which. A value
// at a point whose other side holds the point only in an integral's limit (p(T) = p_0 +
// \int_0^T F dt), or not at all (p(T) = p_0 + J), is read as the value there.
void refuse_rule_at(const Symbols& symbols, const Source& source, std::size_t offset, const ex& one,
                    const ex& other) {
  if (!is_abstract(one) || one.nops() != 1 || !GiNaC::is_a<GiNaC::symbol>(one.op(0))) {
    return;
  }
  const unsigned serial = GiNaC::ex_to<GiNaC::function>(one).get_serial();
  const FunctionDeclaration* f = symbols.function_of(serial);
  const ex point = one.op(0);
  if (f == nullptr || f->variable_written || symbols.is_variable_of(serial, point) ||
      !other.has(point)) {
    return;
  }
  for (auto i = other.preorder_begin(); i != other.preorder_end(); ++i) {
    if (GiNaC::is_a<GiNaC::integral>(*i)) {
      return;
    }
  }
  const SymbolInfo* x = symbols.info(point);
  const std::string name = f->name.latex();
  const std::string at = x != nullptr ? x->name.latex() : "its argument";
  throw source.error(offset, "expected " + name + "'s variable declared: `function: " + name +
                                 "` makes " + name + " a function of t, and " + name + "(" + at +
                                 ") = ... is either its rule for every " + at +
                                 " (declare `function: " + name + "(" + at +
                                 ")`) or its value at one " + at + " (declare `function: " + name +
                                 "(t)`)");
}

// Either side of a scalar premise.
void refuse_rule_at_another_variable(const Symbols& symbols, const Source& source,
                                     const Equation& e) {
  refuse_rule_at(symbols, source, e.offset, e.lhs.value.x, e.rhs.value.x);
  refuse_rule_at(symbols, source, e.offset, e.rhs.value.x, e.lhs.value.x);
}

// The two sides of an equation are of one shape: scalars, vectors, columns or matrices alike.
void refuse_other_shape(const Source& source, const Equation& e, std::size_t offset) {
  const auto shape = [](const Value& v) {
    return v.block() ? (v.cols > 1 ? "a matrix" : "a column") : v.vector ? "a vector" : "a scalar";
  };
  if (e.lhs.value.vector != e.rhs.value.vector || e.lhs.value.rows != e.rhs.value.rows ||
      e.lhs.value.cols != e.rhs.value.cols) {
    throw source.error(offset, std::string("expected ") + shape(e.lhs.value) +
                                   " on this side, as on the other, found " + shape(e.rhs.value));
  }
}

}  // namespace

Reader::Reader(const Source& source, const Limits& limits)
    : source_(source), limits_(limits), symbols_(source, limits) {}

ReadFile Reader::read() {
  for (const Item& item : read_markdown(source_, limits_)) {
    if (const auto* directive = std::get_if<Directive>(&item)) {
      read_directive(*directive);
    } else if (const auto* lone = std::get_if<LoneInline>(&item)) {
      lone_inline_.push_back(*lone);
    } else if (group_open_ && groups_.back().kind == Kind::claim &&
               awaiting_ == Awaiting::statement) {
      read_claim(std::get<Block>(item));
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
  if (also_) {
    throw source_.error(also_->first, "expected a display block after also:");
  }
  if (evidence_ || test_) {
    throw source_.error(evidence_ ? *evidence_ : *test_, "expected a display block after it");
  }
  if (target_) {
    throw source_.error(*target_, "expected a display block after target:");
  }
  close_group();
  if (equations_.empty() && groups_.empty()) {
    throw source_.error(source_.text().size(),
                        "expected a display equation ($$ … $$): the file has none");
  }
  return {std::move(equations_), std::move(groups_), std::move(targets_), std::move(lone_inline_)};
}

bool Reader::used_scalar(const SymbolName& name) const {
  return used_.contains(name.unprimed().latex());
}

void Reader::note_used(const Node& node) {
  if (node.kind == NodeKind::symbol) {
    used_.insert(node.symbol.unprimed().latex());
  }
  for (const Node& child : node.children) {
    note_used(child);
  }
}

// What a block is to the file: a check's statement, correction, evidence or test, or plain;
// premises (after given:, or a test), and from what the next step follows.
Reader::BlockRole Reader::block_role(const Block& block) {
  BlockRole how;
  if (group_open_) {
    how.role = awaiting_ == Awaiting::statement    ? Role::statement
               : awaiting_ == Awaiting::correction ? Role::correction
               : evidence_                         ? Role::evidence
               : test_                             ? Role::test
                                                   : Role::plain;
    if (how.role == Role::plain) {
      close_group();  // a block that is not the check's: the check ends before it
    }
  }
  evidence_.reset();
  test_.reset();
  how.given = given_.has_value();
  given_.reset();
  if (how.role == Role::test) {
    if (how.given || from_) {
      throw source_.error(block.offset,
                          "expected a test without given: or from: (it is tested "
                          "by the models, with the check's equations)");
    }
    how.given = true;  // not derived: the models test it
  }
  if (how.role == Role::correction) {
    if (how.given) {
      throw source_.error(block.offset,
                          "expected the correction without given: (it is read as "
                          "the statement is)");
    }
    if (from_) {
      throw source_.error(from_->first,
                          "expected the correction without from: (it follows from "
                          "what the statement follows from)");
    }
    // Read as the statement was: a premise if it was one, else from what it followed from.
    how.given = statement_given_;
    if (!how.given) {
      from_ = std::pair{block.offset, statement_premises_};
    }
  }
  if (how.role == Role::statement) {
    statement_given_ = how.given;
    statement_premises_ = from_ ? from_->second : previous_;
  }
  if (how.given) {
    if (from_) {
      throw source_.error(from_->first,
                          "expected a step after from:, found the premises of "
                          "a given: block");
    }
    block_premises_.clear();
  }
  return how;
}

void Reader::read_block(const Block& block) {
  if (target_) {
    read_target(block);
    return;
  }
  const BlockRole how = block_role(block);
  const std::size_t first_equation = equations_.size();
  for (const Row& row : file::read_block(source_, block.content_offset, block.content, limits_)) {
    if (how.given && (row.join == Join::arrow || row.join == Join::equivalence)) {
      // given: v' = -e v \Rightarrow J = m(1 - e) v: the step after the arrow was read as a
      // premise, unchecked.
      throw source_.error(row.offset,
                          "expected premises in a given: block, found an equation after an arrow "
                          "(\\Rightarrow, \\implies, \\iff): the arrow makes it a step, given: "
                          "a premise; write the step in a block after the given: one");
    }
    read_row(row, how);
  }
  also_.reset();
  if (group_open_) {
    finish_group_block(block, how.role, first_equation);
  }
}

// The block after target: (a task file): what a submission must reach; not a step here.
void Reader::read_target(const Block& block) {
  if (given_ || from_ || group_open_) {
    throw source_.error(*target_,
                        "expected target: alone before its block (not with given:, "
                        "from: or inside a check)");
  }
  target_.reset();
  if (!targets_.empty()) {
    throw source_.error(block.offset, "expected one target: in a task file");
  }
  for (const Row& row : file::read_block(source_, block.content_offset, block.content, limits_)) {
    if (row.continues || row.sides.size() != 2) {
      throw source_.error(row.offset, "expected the target as one equation a = b");
    }
    Equation e;
    e.offset = row.sides[0].offset;
    e.latex = row.sides[0].latex + " = " + row.sides[1].latex;
    e.lhs = symbols_.meaning(row.sides[0].expression);
    e.rhs = symbols_.meaning(row.sides[1].expression);
    e.facts = facts_;
    e.substitutions = symbols_.substitutions();
    e.premise = true;
    targets_.push_back(std::move(e));
  }
}

// A row whose symbols carry a free index stands for one row per value (per combination).
std::vector<Reader::IndexValues> Reader::index_copies(const Row& row) const {
  std::vector<std::string> free;
  for (const Side& side : row.sides) {
    for (const std::string& letter : symbols_.free_indices(side.expression)) {
      if (std::find(free.begin(), free.end(), letter) == free.end()) {
        free.push_back(letter);
      }
    }
  }
  std::vector<IndexValues> copies{{}};
  for (const std::string& letter : free) {
    std::vector<IndexValues> more;
    for (const auto& copy : copies) {
      for (const long v : symbols_.indices().at(letter)) {
        auto c = copy;
        c.emplace_back(letter, v);
        more.push_back(std::move(c));
      }
    }
    copies = std::move(more);
  }
  return copies;
}

void Reader::read_row(const Row& row, const BlockRole& how) {
  if (row.continues && equations_.empty()) {
    throw source_.error(row.offset,
                        "expected an equation before this row that begins with "
                        "'=' (it continues the equation before)");
  }
  const std::vector<IndexValues> copies = index_copies(row);
  if (row.continues && chains_.size() != copies.size()) {
    throw source_.error(row.offset,
                        "expected a row that continues a chain to have the "
                        "indices of the row before");
  }
  const bool given = how.given;
  const Role role = how.role;
  const std::vector<std::size_t> first_premises =
      given ? std::vector<std::size_t>{} : (from_ ? from_->second : previous_);
  from_.reset();
  std::vector<Chain> chains(copies.size());
  std::vector<std::size_t> last_links;
  for (std::size_t c = 0; c < copies.size(); ++c) {
    const auto substituted = [&](const Node& n) {
      Node out = n;
      for (const auto& [letter, value] : copies[c]) {
        out = with_index(out, letter, value);
      }
      return out;
    };
    std::string suffix;
    for (const auto& [letter, value] : copies[c]) {
      suffix += (suffix.empty() ? " \\quad (" : ", ") + letter + " = " + std::to_string(value);
    }
    if (!suffix.empty()) {
      suffix += ")";
    }
    Chain chain = row.continues ? chains_[c] : Chain{};
    for (std::size_t k = 1; k < row.sides.size(); ++k) {
      const Node right = substituted(row.sides[k].expression);
      note_used(right);
      Equation e;
      const bool first_link = k == 1 && !row.continues;
      if (first_link) {
        const Node left = substituted(row.sides[0].expression);
        note_used(left);
        e.offset = row.sides[0].offset;
        e.latex = row.sides[0].latex + " = " + row.sides[k].latex + suffix;
        e.lhs = symbols_.meaning(left);
        chain.start = e.lhs;
        chain.last_latex = row.sides[0].latex;
        dimension(e, left, right);
      } else {
        // a = b = c: the link b = c is checked as a = c, from a = b.
        e.offset = row.continues && k == 1 ? row.offset : row.sides[k - 1].offset;
        e.latex = (row.continues && k == 1 ? chain.last_latex : row.sides[k - 1].latex) + " = " +
                  row.sides[k].latex + suffix;
        e.lhs = chain.start;
        if (row.continues && k == 1) {
          dimension(e, chain.last_node, right);
        } else {
          dimension(e, substituted(row.sides[k - 1].expression), right);
        }
      }
      e.rhs = symbols_.meaning(right);
      refuse_other_shape(source_, e, row.sides[k].offset);
      chain.last_latex = row.sides[k].latex;
      chain.last_node = right;
      e.facts = facts_;
      e.substitutions = symbols_.substitutions();
      e.equivalence = first_link && row.join == Join::equivalence;
      // A given chain a = b = c in a check's statement that no model tests: only a = b is
      // given; b = c must follow from it (nothing else would test that the links agree).
      const bool untested_link = given && !first_link &&
                                 (role == Role::statement || role == Role::correction) &&
                                 groups_.back().models.empty();
      const bool premise = (given && !untested_link) || (equations_.empty() && role == Role::plain);
      e.premise = premise;
      if (premise && !e.lhs.value.vector && !e.lhs.value.block()) {
        refuse_rule_at_another_variable(symbols_, source_, e);
      }
      if (!premise) {
        e.premises = first_link ? first_premises : std::vector<std::size_t>{equations_.size() - 1};
        if (also_) {
          for (const std::size_t q : also_->second) {
            if (std::find(e.premises.begin(), e.premises.end(), q) == e.premises.end()) {
              e.premises.push_back(q);
            }
          }
        }
        if (first_link && e.premises.empty()) {
          e.premise = true;  // nothing before it to follow from
        }
      }
      if (group_open_) {
        e.group = groups_.size() - 1;
        e.role = role;
      }
      equations_.push_back(std::move(e));
      if (given) {
        block_premises_.push_back(equations_.size() - 1);
      }
    }
    last_links.push_back(equations_.size() - 1);
    chains[c] = std::move(chain);
  }
  chains_ = std::move(chains);
  name_row(row, role, last_links);
  // A test is what a check's models test, not a line of the derivation: what comes after
  // does not follow from it.
  if (role != Role::test) {
    previous_ = given ? block_premises_ : last_links;
  }
}

// A row's \tag and \label name its last links (a tagged chain stands for its last link, which
// carries the whole chain, a = c).
void Reader::name_row(const Row& row, Role role, const std::vector<std::size_t>& last_links) {
  if (row.tag) {
    if (tags_.contains(*row.tag)) {
      throw source_.error(row.offset, "expected a new tag, found \\tag{" + *row.tag +
                                          "} that an equation above already carries");
    }
    for (const std::size_t i : last_links) {
      equations_[i].tag = row.tag;
    }
    tags_[*row.tag] = last_links;
    if (role == Role::statement) {
      Group& g = groups_.back();
      if (g.label) {
        throw source_.error(row.offset, "expected one \\tag in a check's statement");
      }
      g.label = "(" + *row.tag + ")";
    }
  }
  if (row.label) {
    if (tags_.contains(*row.label)) {
      throw source_.error(row.offset, "expected a new label, found \\label{" + *row.label +
                                          "}: an equation above already carries that name");
    }
    tags_[*row.label] = last_links;
  }
}

void Reader::dimension(Equation& e, const Node& left, const Node& right) {
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
  } else if (!(l.logarithms == r.logarithms)) {
    // ln h_n = ln h_0 + 2 n ln e: the logarithms of lengths cancel across the sides.
    const Dimension left_over = l.logarithms - r.logarithms;
    e.dimension_issue = DimensionIssue{
        l.logarithm_at ? *l.logarithm_at : r.logarithm_at.value_or(left.offset), Dimension{},
        left_over,
        "the arguments of \\ln have dimensions that do not cancel (" + left_over.text() +
            " is left): the logarithm of a quantity with a dimension stands only in a "
            "difference of logarithms of the same dimension, ln(a/b)"};
  }
}

}  // namespace impulse::derivations::file
