// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of a claim (accepted beyond the contract, for the paper's files): relations between
// expressions, hypotheses before \Rightarrow, \exists, and memberships of intervals and sets.
#include "file/grammar.hpp"
#include "file/latex.hpp"
#include "file/tokens.hpp"

namespace impulse::derivations::file {

namespace {

bool is_relation_token(const Token& t) {
  return is_char(t, '=') || is_char(t, '<') || is_char(t, '>') ||
         (t.kind == Tok::command &&
          (t.text == "\\le" || t.text == "\\leq" || t.text == "\\leqslant" || t.text == "\\ge" ||
           t.text == "\\geq" || t.text == "\\geqslant" || t.text == "\\neq" || t.text == "\\ne" ||
           t.text == "\\lt" || t.text == "\\gt" || t.text == "\\in"));
}

Relation::Kind relation_kind(const Token& t) {
  using K = Relation::Kind;
  if (is_char(t, '=')) {
    return K::equal;
  }
  if (is_char(t, '<') || is_command(t, "\\lt")) {
    return K::less;
  }
  if (is_char(t, '>') || is_command(t, "\\gt")) {
    return K::greater;
  }
  if (is_command(t, "\\neq") || is_command(t, "\\ne")) {
    return K::not_equal;
  }
  if (is_command(t, "\\in")) {
    return K::in_range;
  }
  if (t.text.starts_with("\\le")) {
    return K::less_equal;
  }
  return K::greater_equal;
}

// The right side of \in: (a, b), [a, b], (a, \infty) or \{a, b, …\}.
void read_membership(const Source& source, std::vector<Token> tokens, std::size_t at, Relation& r,
                     const Limits& limits) {
  tokens = trimmed_tokens(std::move(tokens));
  if (tokens.size() >= 2 && is_command(tokens.front(), "\\left")) {
    tokens.erase(tokens.begin());
  }
  if (tokens.size() >= 2 && is_command(tokens[tokens.size() - 2], "\\right")) {
    tokens.erase(tokens.end() - 2);
  }
  if (tokens.size() < 3) {
    throw source.error(at, "expected an interval (a, b) or a set \\{a, b\\} after \\in");
  }
  const Token open = tokens.front();
  const Token close = tokens.back();
  std::vector<Token> inside(tokens.begin() + 1, tokens.end() - 1);
  std::vector<std::vector<Token>> parts =
      split_top(inside, [](const Token& t) { return is_char(t, ','); });
  const auto side = [&](std::vector<Token> part) {
    if (blank_tokens(part)) {
      throw source.error(open.offset, "expected a value between the commas after \\in");
    }
    return parse_side(source, std::move(part), open.offset, limits);
  };
  if (is_command(open, "\\{")) {
    if (!is_command(close, "\\}")) {
      throw source.error(close.offset, "expected \\} to close the set after \\in");
    }
    r.kind = Relation::Kind::in_set;
    for (auto& part : parts) {
      r.members.push_back(side(std::move(part)));
    }
    return;
  }
  if (!(is_char(open, '(') || is_char(open, '[')) ||
      !(is_char(close, ')') || is_char(close, ']')) || parts.size() != 2) {
    throw source.error(open.offset,
                       "expected an interval (a, b), [a, b] or (a, \\infty) after \\in");
  }
  r.kind = Relation::Kind::in_range;
  r.low_closed = is_char(open, '[');
  r.high_closed = is_char(close, ']');
  const auto infinite = [](const std::vector<Token>& part, bool negative) {
    std::vector<Token> t = trimmed_tokens(part);
    if (negative) {
      return t.size() == 2 && is_char(t[0], '-') && is_command(t[1], "\\infty");
    }
    return (t.size() == 1 && is_command(t[0], "\\infty")) ||
           (t.size() == 2 && is_char(t[0], '+') && is_command(t[1], "\\infty"));
  };
  if (!infinite(parts[0], true)) {
    r.low = side(std::move(parts[0]));
  }
  if (!infinite(parts[1], false)) {
    r.high = side(std::move(parts[1]));
  }
}

std::vector<Relation> read_relations(const Source& source, const std::vector<Token>& tokens,
                                     std::size_t fallback, const Limits& limits) {
  std::vector<Relation> found;
  for (std::vector<Token>& chain :
       split_top(tokens, [](const Token& t) { return is_char(t, ','); })) {
    std::vector<Token> marks;
    std::vector<std::vector<Token>> sides = split_top(chain, is_relation_token, &marks);
    const std::size_t at = first_offset(chain, fallback);
    if (marks.empty()) {
      throw source.error(at, "expected a relation (=, \\neq, <, >, \\leq, \\geq, \\in)");
    }
    for (std::size_t k = 0; k < marks.size(); ++k) {
      if (blank_tokens(sides[k]) || blank_tokens(sides[k + 1])) {
        throw source.error(marks[k].offset,
                           "expected an expression on both sides of " + describe(marks[k]));
      }
      Relation r;
      r.offset = marks[k].offset;
      r.kind = relation_kind(marks[k]);
      r.left = parse_side(source, sides[k], at, limits);
      if (r.kind == Relation::Kind::in_range) {
        if (k + 1 != marks.size()) {
          throw source.error(marks[k + 1].offset,
                             "expected nothing after the set or interval of "
                             "\\in");
        }
        read_membership(source, sides[k + 1], marks[k].offset, r, limits);
      } else {
        r.right = parse_side(source, sides[k + 1], marks[k].offset, limits);
      }
      found.push_back(std::move(r));
    }
  }
  return found;
}

}  // namespace

std::vector<ClaimRow> read_claim_block(const Source& source, std::size_t content_offset,
                                       std::string_view content, const Limits& limits) {
  std::vector<Token> tokens = tokenize(source, content_offset, content);
  check_braces(source, tokens);
  tokens = strip_environments(source, std::move(tokens));
  std::vector<ClaimRow> rows;
  for (RowTokens& row_tokens : split_rows(source, tokens)) {
    if (row_tokens.tag) {
      throw source.error(row_tokens.offset,
                         "expected a claim without \\tag (claims are "
                         "unnumbered)");
    }
    ClaimRow row;
    row.offset = row_tokens.offset;
    std::vector<Token> body = trimmed_tokens(row_tokens.tokens);
    row.latex = join(body);
    if (!body.empty() && is_command(body.front(), "\\exists")) {
      row.exists = true;
      body.erase(body.begin());
    }
    std::vector<Token> arrows;
    std::vector<std::vector<Token>> parts = split_top(
        body,
        [](const Token& t) {
          return is_command(t, "\\Rightarrow") || is_command(t, "\\implies") ||
                 is_command(t, "\\Longrightarrow");
        },
        &arrows);
    if (parts.size() > 2) {
      throw source.error(arrows[1].offset, "expected one \\Rightarrow in a claim's row");
    }
    if (parts.size() == 2) {
      if (row.exists) {
        throw source.error(row.offset, "expected \\exists or \\Rightarrow, not both");
      }
      row.hypotheses = read_relations(source, parts[0], row.offset, limits);
    }
    row.conclusions = read_relations(source, parts.back(), row.offset, limits);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) {
    throw source.error(content_offset, "expected a claim in the display block, found nothing");
  }
  return rows;
}

std::vector<Relation> read_relation_list(const Source& source, std::size_t offset,
                                         std::string_view text, const Limits& limits) {
  std::vector<Token> tokens = tokenize(source, offset, text);
  check_braces(source, tokens);
  tokens.pop_back();
  return read_relations(source, tokens, offset, limits);
}

}  // namespace impulse::derivations::file
