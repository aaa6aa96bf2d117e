// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/reader.hpp"

#include <algorithm>
#include <cctype>

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

Reader::Reader(const Source& source, const Limits& limits)
    : source_(source), limits_(limits), symbols_(source, limits) {}

ReadFile Reader::read() {
  for (const Item& item : read_markdown(source_, limits_)) {
    if (const auto* directive = std::get_if<Directive>(&item)) {
      read_directive(*directive);
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
  close_group();
  if (equations_.empty() && groups_.empty()) {
    throw source_.error(source_.text().size(),
                        "expected a display equation ($$ … $$): the file has none");
  }
  return {std::move(equations_), std::move(groups_)};
}

Group* Reader::group() {
  return group_open_ ? &groups_.back() : nullptr;
}

bool Reader::used_scalar(const SymbolName& name) const {
  return used_.contains(name.unprimed().latex());
}

void Reader::read_directive(const Directive& d) {
  const auto in_group = [&](const char* word) {
    if (!group_open_) {
      throw source_.error(
          d.offset, std::string("expected ") + word + " inside a check (after check: or claim:)");
    }
  };
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
    case DirectiveKind::also:
      also_ = std::pair{d.offset, named(d)};
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
    case DirectiveKind::section: {
      close_group();
      const std::string_view text = d.content;
      // The paper's numbers (4, 4.1), or a name of a section beyond the paper in lower-case
      // letters, alone or numbered below (friction, friction.2).
      const std::size_t name = text.find_first_not_of("abcdefghijklmnopqrstuvwxyz");
      const std::string_view number =
          name == 0 ? text
          : name == std::string_view::npos || text[name] != '.'
              ? std::string_view(name == std::string_view::npos ? "0" : "")
              : text.substr(name + 1);
      const bool valid =
          !text.empty() && !number.empty() && std::isdigit(static_cast<unsigned char>(number[0])) &&
          std::isdigit(static_cast<unsigned char>(number.back())) &&
          std::all_of(
              number.begin(), number.end(),
              [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }) &&
          number.find("..") == std::string_view::npos;
      if (!valid) {
        throw source_.error(
            d.content_offset,
            "expected a section number after section: (e.g. 4 or 4.1, or friction.1 beyond the "
            "paper)");
      }
      section_ = std::string(text);
      break;
    }
    case DirectiveKind::check:
    case DirectiveKind::claim:
      open_group(d);
      break;
    case DirectiveKind::correction:
      in_group("correction:");
      if (groups_.back().kind == Kind::claim) {
        throw source_.error(d.offset,
                            "expected a correction in a check, not in a claim (a claim "
                            "that does not hold is refuted, with explanation:)");
      }
      if (awaiting_ != Awaiting::nothing || groups_.back().statement_equations.empty()) {
        throw source_.error(d.offset, "expected correction: after the check's statement");
      }
      if (!groups_.back().correction_equations.empty()) {
        throw source_.error(d.offset, "expected one correction in a check");
      }
      if (!d.content.empty()) {
        throw source_.error(d.content_offset,
                            "expected nothing after correction: (the correction is the next "
                            "display block)");
      }
      awaiting_ = Awaiting::correction;
      break;
    case DirectiveKind::evidence:
      in_group("evidence:");
      if (groups_.back().kind == Kind::claim) {
        throw source_.error(d.offset,
                            "expected evidence: in a check, not in a claim (a claim "
                            "is tested by its rows and its searches)");
      }
      if (awaiting_ != Awaiting::nothing) {
        throw source_.error(d.offset, "expected evidence: after the check's statement");
      }
      if (!d.content.empty()) {
        throw source_.error(d.content_offset,
                            "expected nothing after evidence: (the evidence is the next display "
                            "block)");
      }
      evidence_ = d.offset;
      break;
    case DirectiveKind::test:
      in_group("test:");
      if (groups_.back().kind == Kind::claim || awaiting_ != Awaiting::nothing) {
        throw source_.error(d.offset, "expected test: after a check's statement (not in a claim)");
      }
      if (groups_.back().models.empty()) {
        throw source_.error(d.offset,
                            "expected test: in a check that names a model (the models "
                            "test what follows it)");
      }
      if (!d.content.empty()) {
        throw source_.error(d.content_offset, "expected nothing after test:");
      }
      test_ = d.offset;
      break;
    case DirectiveKind::explanation:
      in_group("explanation:");
      if (d.content.empty()) {
        throw source_.error(d.content_offset, "expected a sentence after explanation:");
      }
      groups_.back().explanation +=
          (groups_.back().explanation.empty() ? "" : " ") + std::string(d.content);
      break;
    case DirectiveKind::index:
      index(d);
      break;
    case DirectiveKind::arrow:
      for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
        const SymbolName name = read_symbol(source_, at, piece, limits_);
        if (!name.subscript.empty() || name.primes != 0 || name.delta) {
          throw source_.error(at, "expected a letter after arrow: (e.g. arrow: p, F)");
        }
        symbols_.declare_arrow(name.base);
      }
      break;
    case DirectiveKind::differentials:
      for (const auto& [at, piece] : split_commas(d.content, d.content_offset)) {
        symbols_.declare_differential(read_symbol(source_, at, piece, limits_));
      }
      break;
    case DirectiveKind::forces:
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
      break;
    case DirectiveKind::matrix:
    case DirectiveKind::column:
      block_declaration(d, d.kind == DirectiveKind::matrix);
      break;
    case DirectiveKind::model:
    case DirectiveKind::ode:
    case DirectiveKind::quadrature:
    case DirectiveKind::search: {
      const std::string word(to_string(d.kind));
      in_group((word + ":").c_str());
      if (d.content.empty()) {
        throw source_.error(d.content_offset, "expected the name of a model after " + word + ":");
      }
      groups_.back().models.push_back(
          {d.kind == DirectiveKind::model ? "numeric" : word, std::string(d.content), d.offset});
      break;
    }
  }
}

void Reader::index(const Directive& d) {
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

void Reader::block_declaration(const Directive& d, bool matrix) {
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

void Reader::open_group(const Directive& d) {
  close_group();
  const bool claim = d.kind == DirectiveKind::claim;
  std::string_view text = d.content;
  std::size_t space = text.find(' ');
  const std::string id(text.substr(0, space));
  const bool valid_id = !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) ||
           std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  });
  if (!valid_id) {
    throw source_.error(d.content_offset,
                        std::string("expected an id after ") + (claim ? "claim:" : "check:") +
                            " (lower-case letters, digits, '-' and '.', e.g. eq-1.1)");
  }
  for (const Group& g : groups_) {
    if (g.id == id) {
      throw source_.error(d.content_offset,
                          "expected a new id, found " + id + " that a check above already has");
    }
  }
  if (section_.empty()) {
    throw source_.error(d.offset, "expected section: before the first check");
  }
  Group g;
  g.id = id;
  g.section = section_;
  g.offset = d.offset;
  g.kind = claim ? Kind::claim : Kind::equation;
  std::string kind;
  if (space != std::string_view::npos) {
    kind = std::string(text.substr(space + 1));
    while (!kind.empty() && kind.front() == ' ') {
      kind.erase(kind.begin());
    }
  }
  if (claim && !kind.empty()) {
    throw source_.error(d.content_offset + space + 1, "expected nothing after the claim's id");
  }
  if (!claim) {
    if (kind == "step") {
      g.kind = Kind::step;
    } else if (kind != "equation") {
      throw source_.error(d.content_offset + (space == std::string_view::npos ? 0 : space + 1),
                          "expected the kind of the check after its id: equation (a numbered "
                          "result) or step");
    }
  }
  groups_.push_back(std::move(g));
  group_open_ = true;
  awaiting_ = Awaiting::statement;
}

void Reader::close_group() {
  if (evidence_ || test_) {
    throw source_.error(evidence_ ? *evidence_ : *test_, "expected a display block after it");
  }
  if (!group_open_) {
    return;
  }
  const Group& g = groups_.back();
  if (awaiting_ == Awaiting::statement) {
    throw source_.error(g.offset, "expected the statement of " + g.id + " (a display block)");
  }
  if (awaiting_ == Awaiting::correction) {
    throw source_.error(g.offset, "expected the correction of " + g.id + " (a display block)");
  }
  if (!g.correction_equations.empty() && g.explanation.empty()) {
    throw source_.error(g.offset, "expected explanation: in " + g.id +
                                      ", which has a correction (what goes wrong, in a sentence)");
  }
  if (g.kind == Kind::equation && !g.label) {
    throw source_.error(g.statement_offset,
                        "expected the statement of " + g.id + ", an equation, to carry its \\tag");
  }
  if (g.kind != Kind::equation && g.label) {
    throw source_.error(g.statement_offset, "expected " + g.id +
                                                ", a step, without a \\tag (a numbered result "
                                                "is a check of kind equation)");
  }
  group_open_ = false;
  awaiting_ = Awaiting::nothing;
  if (outer_definitions_) {
    symbols_.restore_substitutions(std::move(*outer_definitions_));
    outer_definitions_.reset();
  }
}

void Reader::note_used(const Node& node) {
  if (node.kind == NodeKind::symbol) {
    used_.insert(node.symbol.unprimed().latex());
  }
  for (const Node& child : node.children) {
    note_used(child);
  }
}

void Reader::read_claim(const Block& block) {
  Group& g = groups_.back();
  if (given_) {
    throw source_.error(*given_, "expected a claim's block without given:");
  }
  g.rows = read_claim_block(source_, block.content_offset, block.content, limits_);
  g.statement = std::string(block.content);
  g.statement_offset = block.offset;
  g.claim_premises = from_ ? from_->second : previous_;
  from_.reset();
  g.claim_facts = facts_;
  g.claim_substitutions = symbols_.substitutions();
  for (const ClaimRow& row : g.rows) {
    for (const auto* list : {&row.hypotheses, &row.conclusions}) {
      for (const Relation& r : *list) {
        note_used(r.left.expression);
        note_used(r.right.expression);
      }
    }
  }
  awaiting_ = Awaiting::nothing;
}

void Reader::read_block(const Block& block) {
  Role role = Role::plain;
  if (group_open_) {
    role = awaiting_ == Awaiting::statement    ? Role::statement
           : awaiting_ == Awaiting::correction ? Role::correction
           : evidence_                         ? Role::evidence
           : test_                             ? Role::test
                                               : Role::plain;
    if (role == Role::plain) {
      close_group();  // a block that is not the check's: the check ends before it
    }
  }
  evidence_.reset();
  test_.reset();
  bool given = given_.has_value();
  given_.reset();
  if (role == Role::test) {
    if (given || from_) {
      throw source_.error(block.offset,
                          "expected a test without given: or from: (it is tested "
                          "by the models, with the check's equations)");
    }
    given = true;  // not derived: the models test it
  }
  if (role == Role::correction) {
    if (given) {
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
    given = statement_given_;
    if (!given) {
      from_ = std::pair{block.offset, statement_premises_};
    }
  }
  if (role == Role::statement) {
    statement_given_ = given;
    statement_premises_ = from_ ? from_->second : previous_;
  }
  if (given) {
    if (from_) {
      throw source_.error(from_->first,
                          "expected a step after from:, found the premises of "
                          "a given: block");
    }
    block_premises_.clear();
  }
  const std::size_t first_equation = equations_.size();
  const std::vector<Row> rows =
      file::read_block(source_, block.content_offset, block.content, limits_);
  for (const Row& row : rows) {
    if (row.continues && equations_.empty()) {
      throw source_.error(row.offset,
                          "expected an equation before this row that begins with "
                          "'=' (it continues the equation before)");
    }
    // A row whose symbols carry a free index stands for one row per value (per combination).
    std::vector<std::string> free;
    for (const Side& side : row.sides) {
      for (const std::string& letter : symbols_.free_indices(side.expression)) {
        if (std::find(free.begin(), free.end(), letter) == free.end()) {
          free.push_back(letter);
        }
      }
    }
    std::vector<std::vector<std::pair<std::string, long>>> copies{{}};
    for (const std::string& letter : free) {
      std::vector<std::vector<std::pair<std::string, long>>> more;
      for (const auto& copy : copies) {
        for (const long v : symbols_.indices().at(letter)) {
          auto c = copy;
          c.emplace_back(letter, v);
          more.push_back(std::move(c));
        }
      }
      copies = std::move(more);
    }
    if (row.continues && chains_.size() != copies.size()) {
      throw source_.error(row.offset,
                          "expected a row that continues a chain to have the "
                          "indices of the row before");
    }
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
        const auto shape = [](const Value& v) {
          return v.block()  ? (v.cols > 1 ? "a matrix" : "a column")
                 : v.vector ? "a vector"
                            : "a scalar";
        };
        if (e.lhs.value.vector != e.rhs.value.vector || e.lhs.value.rows != e.rhs.value.rows ||
            e.lhs.value.cols != e.rhs.value.cols) {
          throw source_.error(row.sides[k].offset, std::string("expected ") + shape(e.lhs.value) +
                                                       " on this side, as on the other, found " +
                                                       shape(e.rhs.value));
        }
        chain.last_latex = row.sides[k].latex;
        chain.last_node = right;
        e.facts = facts_;
        e.substitutions = symbols_.substitutions();
        // A given chain a = b = c in a check's statement that no model tests: only a = b is
        // given; b = c must follow from it (nothing else would test that the links agree).
        const bool untested_link = given && !first_link &&
                                   (role == Role::statement || role == Role::correction) &&
                                   groups_.back().models.empty();
        const bool premise =
            (given && !untested_link) || (equations_.empty() && role == Role::plain);
        e.premise = premise;
        if (!premise) {
          e.premises =
              first_link ? first_premises : std::vector<std::size_t>{equations_.size() - 1};
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
    if (row.tag) {
      if (tags_.contains(*row.tag)) {
        throw source_.error(row.offset, "expected a new tag, found \\tag{" + *row.tag +
                                            "} that an equation above already carries");
      }
      for (const std::size_t i : last_links) {
        equations_[i].tag = row.tag;
      }
      // A tagged chain stands for its last link, which carries the whole chain (a = c).
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
    // A test is what a check's models test, not a line of the derivation: what comes after
    // does not follow from it.
    if (role != Role::test) {
      previous_ = given ? block_premises_ : last_links;
    }
  }
  also_.reset();
  if (!group_open_) {
    return;
  }
  Group& g = groups_.back();
  std::vector<std::size_t> read;
  for (std::size_t i = first_equation; i < equations_.size(); ++i) {
    read.push_back(i);
  }
  if (role == Role::statement) {
    g.statement = std::string(block.content);
    g.statement_offset = block.offset;
    g.statement_equations = read;
    awaiting_ = Awaiting::nothing;
  } else if (role == Role::correction) {
    g.correction = std::string(block.content);
    g.correction_equations = read;
    awaiting_ = Awaiting::nothing;
    // What holds from here on is the correction: the statement's tags name it.
    for (auto& [tag, indices] : tags_) {
      const bool statement = std::any_of(indices.begin(), indices.end(), [&](std::size_t i) {
        return std::find(g.statement_equations.begin(), g.statement_equations.end(), i) !=
               g.statement_equations.end();
      });
      if (statement) {
        indices = read;
      }
    }
  } else if (role == Role::test) {
    g.test_equations.insert(g.test_equations.end(), read.begin(), read.end());
  } else {
    g.evidence_equations.insert(g.evidence_equations.end(), read.begin(), read.end());
  }
}

void Reader::assume(const Directive& d) {
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

void Reader::fact(std::size_t at, const SymbolName& name, Sign sign) {
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

void Reader::let(const Directive& d) {
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

void Reader::from(const Directive& d) {
  from_ = std::pair{d.offset, named(d)};
}

void Reader::units(const Directive& d) {
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
  }
}
}  // namespace impulse::derivations::file
