// SPDX-License-Identifier: GPL-3.0-or-later
// A derivation file read into what is checked: its equations (rows, chain links, rows of an index,
// each with the equations it must follow from, the facts and definitions in force) and, for the
// paper's files, its checks (the statement, the correction, the evidence and the models of each).
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "derivations/check.hpp"
#include "file/facts.hpp"
#include "file/latex.hpp"
#include "file/markdown.hpp"
#include "file/meaning.hpp"
#include "file/text.hpp"

namespace impulse::derivations::file {

/// What an equation is to the check it belongs to.
enum class Role {
  plain,       ///< outside every check (a setting, a definition, a step of the notes)
  statement,   ///< the check's statement (as printed)
  correction,  ///< what holds instead (an erratum)
  evidence,    ///< the check's evidence, in our words: it must follow from the statement
  test,        ///< what the check's models test besides the statement (not derived)
};

/// One equation as it is checked: for a link of a chain a = b = c, "a = c".
struct Equation {
  std::size_t offset = 0;
  std::optional<std::string> tag;
  std::string latex;
  bool premise = false;
  Meaning lhs;
  Meaning rhs;
  std::vector<std::size_t> premises;  ///< indices of the equations it must follow from
  Facts facts;                        ///< the facts in force at its line
  GiNaC::exmap substitutions;         ///< the definitions in force at its line
  std::optional<DimensionIssue> dimension_issue;
  std::size_t group = static_cast<std::size_t>(-1);  ///< its check, if any
  Role role = Role::plain;
  bool equivalence = false;  ///< written after \iff: it must be an equivalence
};

/// A model a check names: `ode: NAME`, `quadrature: NAME`, `model: NAME`, `search: NAME`.
struct ModelUse {
  std::string method;  ///< "ode", "quadrature", "numeric" (for model:), "search"
  std::string name;
  std::size_t offset = 0;
};

/// A check of the paper's files: `check: ID KIND` or `claim: ID` and what follows it.
struct Group {
  std::string id;
  Kind kind = Kind::equation;
  std::string section;
  std::optional<std::string> label;  ///< "(1.1)", from the statement's \tag
  std::size_t offset = 0;            ///< where check: stands
  std::string statement;             ///< the statement's block as written
  std::size_t statement_offset = 0;
  std::vector<std::size_t> statement_equations;
  std::vector<std::size_t> correction_equations;
  std::vector<std::size_t> evidence_equations;
  std::vector<std::size_t> test_equations;
  std::string correction;   ///< the correction's block as written
  std::string explanation;  ///< what goes wrong (erratum, refuted), in our words
  std::vector<ModelUse> models;
  // Claims: the rows, and what they are read with.
  std::vector<ClaimRow> rows;
  std::vector<std::size_t> claim_premises;
  Facts claim_facts;
  GiNaC::exmap claim_substitutions;
};

/// A file read: its equations and checks, and a task's target (`target:`).
struct ReadFile {
  std::vector<Equation> equations;
  std::vector<Group> groups;
  std::vector<Equation> targets;        ///< the equations of the block after target: (a task file)
  std::vector<LoneInline> lone_inline;  ///< equations in inline math on lines of their own
};

/// Reads a derivation file (throws ReadError at the first place not understood). Its parts:
/// reader.cpp (display blocks into equations), directives.cpp (the directives of a derivation:
/// assume:, let:, vector:, function: …) and groups.cpp (the paper's checks: check:, claim:,
/// correction: …).
class Reader {
 public:
  Reader(const Source& source, const Limits& limits);
  ReadFile read();
  Symbols& symbols() { return symbols_; }

 private:
  // ---- directives (directives.cpp) ----
  void read_directive(const Directive& d);
  void on_assume(const Directive& d);
  void on_unit(const Directive& d);
  void on_let(const Directive& d);
  void on_given(const Directive& d);
  void on_target(const Directive& d);
  void on_from(const Directive& d);
  void on_also(const Directive& d);
  void on_vector(const Directive& d);
  void on_function(const Directive& d);
  void on_units(const Directive& d);
  void on_index(const Directive& d);
  void on_arrow(const Directive& d);
  void on_differentials(const Directive& d);
  void on_forces(const Directive& d);
  void on_block(const Directive& d);
  void fact(std::size_t at, const Relation& relation);
  void symbol_fact(std::size_t at, const SymbolName& name, Sign sign);
  void relation_agrees(std::size_t at, const GiNaC::ex& difference, Sign sign) const;
  void equalities_agree(std::size_t at) const;
  std::vector<std::size_t> named(const Directive& d);

  // ---- the paper's checks (groups.cpp) ----
  void on_section(const Directive& d);
  void on_check(const Directive& d);
  void on_correction(const Directive& d);
  void on_evidence(const Directive& d);
  void on_test(const Directive& d);
  void on_explanation(const Directive& d);
  void on_model(const Directive& d);
  void in_group(const Directive& d, const std::string& word) const;
  void close_group();
  void read_claim(const Block& block);
  void finish_group_block(const Block& block, Role role, std::size_t first_equation);
  Group* group();

  // ---- display blocks (reader.cpp) ----
  /// How a block's equations are read: their role in a check, whether they are premises.
  struct BlockRole {
    Role role = Role::plain;
    bool given = false;
  };
  BlockRole block_role(const Block& block);
  void read_block(const Block& block);
  void read_target(const Block& block);
  void read_row(const Row& row, const BlockRole& how);
  using IndexValues = std::vector<std::pair<std::string, long>>;
  std::vector<IndexValues> index_copies(const Row& row) const;
  void name_row(const Row& row, Role role, const std::vector<std::size_t>& last_links);
  void note_used(const Node& node);
  void dimension(Equation& e, const Node& left, const Node& right);
  bool used_scalar(const SymbolName& name) const;

  const Source& source_;
  const Limits& limits_;
  Symbols symbols_;
  Facts facts_;
  std::vector<Equation> equations_;
  std::vector<Group> groups_;
  std::vector<Equation> targets_;
  std::vector<LoneInline> lone_inline_;
  std::map<std::string, std::vector<std::size_t>> tags_;
  std::set<std::string> used_;
  std::optional<std::size_t> given_;
  std::optional<std::size_t> target_;
  std::optional<std::pair<std::size_t, std::vector<std::size_t>>> from_;
  std::optional<std::pair<std::size_t, std::vector<std::size_t>>> also_;
  std::vector<std::size_t> previous_;
  std::vector<std::size_t> block_premises_;
  // The chain of the row before, one per row of an index (a = b, then = c continues it).
  struct Chain {
    Meaning start;
    std::string last_latex;
    Node last_node;
  };
  std::vector<Chain> chains_;
  // Paper files: the check being read, and what its next block is.
  std::string section_;
  bool group_open_ = false;
  enum class Awaiting { nothing, statement, correction } awaiting_ = Awaiting::nothing;
  // The definitions before a check's own let: (one between its check: line and its statement),
  // put back when the check ends.
  std::optional<GiNaC::exmap> outer_definitions_;
  bool statement_given_ = false;
  std::optional<std::size_t> evidence_;  // evidence: stands here, for the next block
  std::optional<std::size_t> test_;      // test: stands here, for the next block
  std::vector<std::size_t> statement_premises_;
};

/// The pieces of a directive's LaTeX separated by commas outside braces and brackets.
std::vector<std::pair<std::size_t, std::string_view>> split_commas(std::string_view text,
                                                                   std::size_t offset);

}  // namespace impulse::derivations::file
