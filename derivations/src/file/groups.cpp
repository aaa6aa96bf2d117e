// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's checks in a derivation file (accepted beyond the contract): section:, check:,
// claim:, correction:, evidence:, test:, explanation: and the models a check names, and the
// bookkeeping of a check's blocks (its statement, its correction, its evidence and tests).
#include <algorithm>
#include <cctype>

#include "file/reader.hpp"

namespace impulse::derivations::file {

Group* Reader::group() {
  return group_open_ ? &groups_.back() : nullptr;
}

void Reader::in_group(const Directive& d, const std::string& word) const {
  if (!group_open_) {
    throw source_.error(d.offset, "expected " + word + " inside a check (after check: or claim:)");
  }
}

void Reader::on_section(const Directive& d) {
  close_group();
  const std::string_view text = d.content;
  // The paper's numbers (4, 4.1), or a name of a section beyond the paper in lower-case
  // letters, alone or numbered below (friction, friction.2).
  const std::size_t name = text.find_first_not_of("abcdefghijklmnopqrstuvwxyz");
  const std::string_view number = name == 0 ? text
                                  : name == std::string_view::npos || text[name] != '.'
                                      ? std::string_view(name == std::string_view::npos ? "0" : "")
                                      : text.substr(name + 1);
  const bool valid =
      !text.empty() && !number.empty() && std::isdigit(static_cast<unsigned char>(number[0])) &&
      std::isdigit(static_cast<unsigned char>(number.back())) &&
      std::all_of(number.begin(), number.end(),
                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }) &&
      number.find("..") == std::string_view::npos;
  if (!valid) {
    throw source_.error(
        d.content_offset,
        "expected a section number after section: (e.g. 4 or 4.1, or friction.1 beyond the "
        "paper)");
  }
  section_ = std::string(text);
}

void Reader::on_check(const Directive& d) {
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

void Reader::on_correction(const Directive& d) {
  in_group(d, "correction:");
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
}

void Reader::on_evidence(const Directive& d) {
  in_group(d, "evidence:");
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
}

void Reader::on_test(const Directive& d) {
  in_group(d, "test:");
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
}

void Reader::on_explanation(const Directive& d) {
  in_group(d, "explanation:");
  if (d.content.empty()) {
    throw source_.error(d.content_offset, "expected a sentence after explanation:");
  }
  groups_.back().explanation +=
      (groups_.back().explanation.empty() ? "" : " ") + std::string(d.content);
}

void Reader::on_model(const Directive& d) {
  const std::string word(to_string(d.kind));
  in_group(d, word + ":");
  if (d.content.empty()) {
    throw source_.error(d.content_offset, "expected the name of a model after " + word + ":");
  }
  groups_.back().models.push_back(
      {d.kind == DirectiveKind::model ? "numeric" : word, std::string(d.content), d.offset});
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

// A check's block read: it is the statement, the correction, evidence or a test.
void Reader::finish_group_block(const Block& block, Role role, std::size_t first_equation) {
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

}  // namespace impulse::derivations::file
