// SPDX-License-Identifier: GPL-3.0-or-later
// A display block read into rows: the environments that arrange equations stripped, the rows cut
// at \\ and at the arrows and annotations that separate equations inside a row, each row's tag
// and label taken, and its sides (between the '=') read by the grammar.
#include <algorithm>
#include <cctype>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include "file/grammar.hpp"
#include "file/latex.hpp"
#include "file/tokens.hpp"

namespace impulse::derivations::file {

namespace {

std::string environment_name(const Source& source, std::vector<Token>& tokens, std::size_t& i) {
  const Token& command = tokens[i];
  ++i;
  while (tokens[i].kind == Tok::spacing) {
    ++i;
  }
  if (!is_char(tokens[i], '{')) {
    throw source.error(tokens[i].offset, "expected {name} after " + command.text);
  }
  const std::size_t open = tokens[i].offset;
  ++i;
  std::string name;
  while (tokens[i].kind == Tok::letter || is_char(tokens[i], '*')) {
    name += tokens[i].text;
    ++i;
  }
  if (!is_char(tokens[i], '}')) {
    throw source.error(open, "expected '}' to close the environment's name");
  }
  ++i;
  return name;
}

// The text of a braced label after \tag or \label, trimmed; i is left on its closing brace.
std::optional<std::string> braced_label(const Source& source, const std::vector<Token>& tokens,
                                        std::size_t& i, const Token& command) {
  std::size_t k = i + 1;
  if (is_char(tokens[k], '*')) {
    ++k;
  }
  if (!is_char(tokens[k], '{')) {
    throw source.error(command.offset, "expected " + command.text + "{label}");
  }
  const std::size_t open = tokens[k].offset;
  std::size_t close = k + 1;
  while (tokens[close].kind != Tok::end && !is_char(tokens[close], '}')) {
    ++close;
  }
  if (tokens[close].kind == Tok::end) {
    throw source.error(open, "expected '}' to close the " + command.text.substr(1));
  }
  std::string label(source.text().substr(open + 1, tokens[close].offset - open - 1));
  while (!label.empty() && label.back() == ' ') {
    label.pop_back();
  }
  while (!label.empty() && label.front() == ' ') {
    label.erase(label.begin());
  }
  i = close;
  if (label.empty()) {
    return std::nullopt;
  }
  return label;
}

bool relation_token(const Token& t) {
  return is_char(t, '=') || is_char(t, '<') || is_char(t, '>') ||
         (t.kind == Tok::command && commands::relations.contains(t.text) &&
          !commands::arrows.contains(t.text) && !commands::equivalences.contains(t.text));
}

// Whether a run of tokens holds a relation outside every group: an equation's worth.
bool holds_relation(const std::vector<Token>& tokens) {
  const std::vector<int> d = depths(tokens);
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    if (d[k] == 0 && relation_token(tokens[k])) {
      return true;
    }
  }
  return false;
}

// The end of the \text{…} (or \mbox{…}) annotation that begins at i: the index after its '}'.
std::size_t annotation_end(const Source& source, const std::vector<Token>& tokens, std::size_t i) {
  std::size_t k = i + 1;
  while (k < tokens.size() && tokens[k].kind == Tok::spacing) {
    ++k;
  }
  if (k >= tokens.size() || !is_char(tokens[k], '{')) {
    throw source.error(tokens[i].offset, "expected {…} after " + tokens[i].text);
  }
  int depth = 0;
  for (; k < tokens.size(); ++k) {
    depth += is_char(tokens[k], '{') ? 1 : is_char(tokens[k], '}') ? -1 : 0;
    if (depth == 0) {
      return k + 1;
    }
  }
  throw source.error(tokens[i].offset, "expected '}' to close " + tokens[i].text);
}

// The end of a unit's power written after its \text{…} (which ends at @p end): ^2, ^{2},
// ^{-1}; @p end where no such power follows.
std::size_t unit_power_end(const std::vector<Token>& tokens, std::size_t end) {
  const std::size_t n = tokens.size();
  const auto digit = [&](std::size_t k) {
    return k < n && tokens[k].kind == Tok::number && tokens[k].text.size() == 1;
  };
  if (end >= n || !is_char(tokens[end], '^')) {
    return end;
  }
  if (digit(end + 1)) {
    return end + 2;
  }
  if (end + 1 < n && is_char(tokens[end + 1], '{')) {
    std::size_t k = end + 2;
    if (k < n && is_char(tokens[k], '-')) {
      ++k;
    }
    if (digit(k) && k + 1 < n && is_char(tokens[k + 1], '}')) {
      return k + 2;
    }
  }
  return end;
}

// A \text{…} alone in round brackets from @p k, ( \text{…} ) or \left( \text{…} \right): the
// index of the \text command and the index after the closing bracket; else nothing.
std::optional<std::pair<std::size_t, std::size_t>> bracketed_text(const Source& source,
                                                                  const std::vector<Token>& tokens,
                                                                  std::size_t k) {
  const std::size_t n = tokens.size();
  const bool left = is_command(tokens[k], "\\left");
  if (!(left ? k + 1 < n && is_char(tokens[k + 1], '(') : is_char(tokens[k], '('))) {
    return std::nullopt;
  }
  const auto skip = [&](std::size_t i) {
    while (i < n && tokens[i].kind == Tok::spacing) {
      ++i;
    }
    return i;
  };
  const std::size_t at = skip(k + (left ? 2 : 1));
  if (at >= n || !in(tokens[at], commands::text_commands)) {
    return std::nullopt;
  }
  std::size_t close = skip(annotation_end(source, tokens, at));
  if (left) {
    if (close >= n || !is_command(tokens[close], "\\right")) {
      return std::nullopt;
    }
    close = skip(close + 1);
  }
  if (close >= n || !is_char(tokens[close], ')')) {
    return std::nullopt;
  }
  return std::pair{at, close + 1};
}

// Whether a \text{…} (its '{' at open, end after its '}') holds words (spaces, punctuation, or
// nothing) rather than one name.
bool words(const std::vector<Token>& tokens, std::size_t open, std::size_t end) {
  if (end < open + 3) {
    return true;  // \text{}
  }
  for (std::size_t k = open + 1; k + 1 < end; ++k) {
    const Token& t = tokens[k];
    if ((t.kind != Tok::letter && t.kind != Tok::number) || t.space_before) {
      return true;
    }
  }
  return tokens[end - 1].space_before;
}

// The words of a \text{…} between open (its '{') and end (after its '}'): runs of letters.
std::vector<std::string> text_words(const std::vector<Token>& tokens, std::size_t open,
                                    std::size_t end) {
  std::vector<std::string> found;
  bool in_word = false;
  for (std::size_t k = open + 1; k + 1 < end; ++k) {
    const Token& t = tokens[k];
    if (t.kind == Tok::letter) {
      if (!in_word || t.space_before) {
        found.emplace_back();
      }
      found.back() += t.text;
    }
    in_word = t.kind == Tok::letter;
  }
  return found;
}

// The first word of a \text{…} (its '{' at open, end after its '}') that @p set holds, in lower
// case when @p lower, or empty.
std::string word_of(const std::vector<Token>& tokens, std::size_t open, std::size_t end,
                    const std::set<std::string, std::less<>>& set, bool lower) {
  for (std::string w : text_words(tokens, open, end)) {
    if (lower) {
      std::transform(w.begin(), w.end(), w.begin(), [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      });
    }
    if (set.contains(w)) {
      return w;
    }
  }
  return std::string();
}

// Whether the \text{…} from `open`, its '{', to `end` holds words in parentheses, (given) or
// (in joules): a note, as nobody writes a unit or a quantity so.
bool parenthesized(const std::vector<Token>& tokens, std::size_t open, std::size_t end) {
  std::size_t first = open + 1;
  std::size_t last = end - 1;  // the '}'
  while (first < last && tokens[first].kind == Tok::spacing) {
    ++first;
  }
  while (last > first && tokens[last - 1].kind == Tok::spacing) {
    --last;
  }
  return last > first + 2 && is_char(tokens[first], '(') && is_char(tokens[last - 1], ')');
}

// Whether @p t is a wide space, \quad or \qquad: what sets a note or a label apart.
bool wide_space(const Token& t) {
  return t.kind == Tok::spacing && (t.text == "\\quad" || t.text == "\\qquad");
}

// The word of a \text{…} that makes the equations it stands between cases, one of which holds
// ("or", "otherwise"), or the next one a condition of the one before ("if", "for", "when",
// "unless"), or denies it ("not"): read as two equations that both hold, v = 0 \text{ otherwise }
// v = 2u gave u = 0. Empty when there is none.
std::string disjunction(const std::vector<Token>& tokens, std::size_t open, std::size_t end) {
  static const std::set<std::string, std::less<>> conditional{
      "or",      "either",   "otherwise",    "else",     "unless",   "if",      "iff",    "only",
      "when",    "whenever", "while",        "whereas",  "for",      "at",      "except", "not",
      "nor",     "neither",  "respectively", "provided", "assuming", "suppose", "case",   "cases",
      "instead", "until",    "before",       "after",    "oder",     "sonst",   "wenn",   "falls",
      "ou",      "sinon",    "si",           "sino",     "cuando"};
  return word_of(tokens, open, end, conditional, true);
}

// The word of a \text{…} that is a unit outside SI's coherent ones (km, h, g, cm), or empty. A
// unit after a number is an annotation, ignored: the number must then be in SI units, or
// L = 2\,\text{km} and L = 2\,\text{m} were one equation. In a @p note, words in parentheses,
// "in" is the preposition.
std::string non_si_unit(const std::vector<Token>& tokens, std::size_t open, std::size_t end,
                        bool note) {
  static const std::set<std::string, std::less<>> units{
      "km", "cm", "mm", "um", "nm", "g",  "mg",  "t",   "h",   "hr",   "min", "ms",  "us",
      "ns", "kN", "MN", "kJ", "MJ", "kW", "MW",  "mph", "kph", "kmh",  "deg", "L",   "mL",
      "ft", "lb", "mi", "in", "yd", "eV", "keV", "MeV", "cal", "kcal", "bar", "atm", "rpm"};
  for (const std::string& w : text_words(tokens, open, end)) {
    if (units.contains(w) && !(note && w == "in")) {  // (in joules): the preposition
      return w;
    }
  }
  return std::string();
}

// The last token of @p tokens that is not spacing; nullptr where there is none.
const Token* last_written(const std::vector<Token>& tokens) {
  for (std::size_t k = tokens.size(); k-- > 0;) {
    if (tokens[k].kind != Tok::spacing) {
      return &tokens[k];
    }
  }
  return nullptr;
}

// Whether the last token of @p tokens that is not spacing is a number.
bool after_number(const std::vector<Token>& tokens) {
  const Token* last = last_written(tokens);
  return last != nullptr && last->kind == Tok::number;
}

// Whether the last token of @p tokens that is not spacing is a number with nothing wider than a
// thin space after it (\, \; \ ~): what follows it so is its unit.
bool close_after_number(const std::vector<Token>& tokens) {
  for (std::size_t k = tokens.size(); k-- > 0;) {
    if (tokens[k].kind != Tok::spacing) {
      return tokens[k].kind == Tok::number;
    }
    if (wide_space(tokens[k])) {
      return false;
    }
  }
  return false;
}

// A \text{…} that a row drops as an annotation, though it may be a quantity: one word right after a
// number that is no SI unit (a = 2\,\text{mass}, 2\,\text{kPa}: read as a = 2), or one letter
// anywhere else (p = m\,\text{v}, 3\,\mu\text{s}: read as p = m, 3μ). Empty when it is an
// annotation.
std::string dropped_quantity(const std::vector<Token>& before, const std::vector<Token>& tokens,
                             std::size_t open, std::size_t end) {
  // The coherent SI units and their products as one word (N s, the impulse's).
  static const std::set<std::string, std::less<>> si{
      "m",  "kg", "s", "N", "J",  "W",  "Pa", "Hz", "rad", "sr", "A",  "K",  "mol",
      "cd", "C",  "V", "T", "Wb", "Ns", "Nm", "Js", "kgm", "Ws", "As", "Ohm"};
  const std::vector<std::string> words = text_words(tokens, open, end);
  std::size_t marks = 0;  // what the braces hold besides spacing
  for (std::size_t k = open + 1; k + 1 < end; ++k) {
    marks += tokens[k].kind == Tok::spacing ? 0U : 1U;
  }
  if (close_after_number(before)) {
    const bool units = std::all_of(words.begin(), words.end(),
                                   [](const std::string& w) { return si.contains(w); });
    return words.size() == 1 && !units ? words[0] : std::string();
  }
  return words.size() == 1 && words[0].size() == 1 && marks == 1 ? words[0] : std::string();
}

// Whether the \text{…} that ends before `end` is set apart from what follows by \quad or \qquad,
// and a term follows (not '=' or an operator): \text{hence}\quad 2y = 6x, not \text{KE} = ….
bool leads_a_row(const std::vector<Token>& tokens, std::size_t end) {
  bool wide = false;
  std::size_t k = end;
  for (; k < tokens.size() && tokens[k].kind == Tok::spacing; ++k) {
    wide = wide || wide_space(tokens[k]);
  }
  if (!wide || k >= tokens.size() || tokens[k].kind == Tok::end || relation_token(tokens[k])) {
    return false;
  }
  static const std::string_view operators = "=+-*/^_&,";
  return !(tokens[k].kind == Tok::character && tokens[k].text.size() == 1 &&
           operators.find(tokens[k].text[0]) != std::string_view::npos) &&
         !is_command(tokens[k], "\\cdot") && !is_command(tokens[k], "\\times");
}

// An annotation (\text{…} between two equations or at the end of a row, from `open`, its '{', to
// `end`; t the \\text command) that would change what a row says if dropped: a word joining two
// equations as cases or conditions, a unit outside SI after a number, or what may be a quantity.
void refuse_annotation(const Source& source, const Token& t, const std::vector<Token>& before,
                       const std::vector<Token>& tokens, std::size_t open, std::size_t end,
                       bool last) {
  if (const std::string word = last ? "" : disjunction(tokens, open, end); !word.empty()) {
    throw source.error(t.offset,
                       "expected an annotation that does not join two equations by '" + word +
                           "': each equation of a row is a step that must hold, not one of "
                           "cases or a condition of another; write the cases as one "
                           "equation (a product equal to zero) or each in a derivation of "
                           "its own, and a condition with assume:");
  }
  // \text{(given)}, \text{(in joules)}: a note, never a quantity; a unit in it, (km) or (in
  // km), is a unit still.
  const bool note = parenthesized(tokens, open, end);
  if (const std::string unit = after_number(before) ? non_si_unit(tokens, open, end, note) : "";
      !unit.empty()) {
    throw source.error(t.offset, "expected a number in SI units (m, kg, s) before " + t.text + "{" +
                                     unit +
                                     "}: a unit after a number is an annotation, which "
                                     "this checker ignores; write the number in SI units");
  }
  if (const std::string word = note ? "" : dropped_quantity(before, tokens, open, end);
      !word.empty()) {
    throw source.error(t.offset,
                       "expected a unit in SI (m, kg, s, N, J, W, Pa, Hz, rad) or words "
                       "of an annotation, found " +
                           t.text + "{" + word +
                           "}: dropped as a note, it would be no part of the equation; "
                           "write " +
                           word + " without " + t.text +
                           " for a quantity, the number in SI units for a unit, and "
                           "set a note apart with \\quad");
  }
}

// Whether the tokens before @p end close a function's name: \sin, \ln, with a sub- or
// superscript (\log_2, \log_{10}, \sin^2, \cos^{2}): what follows is its argument.
bool argument_of_function(const std::vector<Token>& tokens, std::size_t end) {
  std::size_t k = end;
  while (k > 0 && tokens[k - 1].kind == Tok::spacing) {
    --k;
  }
  // One sub- or superscript at most: a number or letter, or a group in braces.
  if (k >= 2 && (tokens[k - 1].kind == Tok::number || tokens[k - 1].kind == Tok::letter) &&
      (is_char(tokens[k - 2], '_') || is_char(tokens[k - 2], '^'))) {
    k -= 2;
  } else if (k > 0 && is_char(tokens[k - 1], '}')) {
    std::size_t open = k - 1;
    int depth = 0;
    while (true) {
      depth += is_char(tokens[open], '}') ? 1 : is_char(tokens[open], '{') ? -1 : 0;
      if (depth == 0 || open == 0) {
        break;
      }
      --open;
    }
    if (depth != 0 || open == 0 ||
        !(is_char(tokens[open - 1], '_') || is_char(tokens[open - 1], '^'))) {
      return false;
    }
    k = open - 1;
  }
  return k > 0 && in(tokens[k - 1], commands::functions);
}

// An equation's label in brackets, read as a factor, let a slip by that factor pass (J = m (w -
// v) \; (2) gave J = 2 m (w - v)). Refused, as \tag{…} numbers an equation:
// - at the start of a row: (3.4) E_k + E_o = …, as the paper prints its equations; (2)\quad & V;
// - at the end after a space: (2), (3.4), (1b);
// - at the end after \quad or \qquad, where any bracket holding numbers and letters is a label:
//   [2], \{2\}, \left[3\right], (1b), and (2) after a letter (b(2) would be a call).
// Elsewhere \quad is spacing, as part one of the contract has it.
void refuse_written_number(const Source& source, const std::vector<Token>& tokens) {
  const std::size_t n = tokens.size();
  const auto skip = [&](std::size_t k) {
    while (k < n && (tokens[k].kind == Tok::spacing || is_char(tokens[k], '&'))) {
      ++k;
    }
    return k;
  };
  // The token after a label's closing bracket when one opens at `open`: (2), (3.4), (1b); after a
  // wide space, any bracket (\left[ … \right] too) around numbers, letters and points.
  const auto label_at = [&](std::size_t open, bool wide) -> std::optional<std::size_t> {
    std::size_t k = open;
    if (wide && k < n && is_command(tokens[k], "\\left")) {
      ++k;
    }
    if (k >= n || !(is_char(tokens[k], '(') ||
                    (wide && (is_char(tokens[k], '[') || is_command(tokens[k], "\\{") ||
                              is_command(tokens[k], "\\lbrack"))))) {
      return std::nullopt;
    }
    if (wide) {
      bool label = false;
      for (++k; k < n && (tokens[k].kind == Tok::number || tokens[k].kind == Tok::letter ||
                          tokens[k].kind == Tok::spacing || is_char(tokens[k], '.'));
           ++k) {
        label = label || tokens[k].kind != Tok::spacing;
      }
      if (k < n && is_command(tokens[k], "\\right")) {
        ++k;
      }
      const bool closed =
          k < n && (is_char(tokens[k], ')') || is_char(tokens[k], ']') ||
                    is_command(tokens[k], "\\}") || is_command(tokens[k], "\\rbrack"));
      return label && closed ? std::optional<std::size_t>(k + 1) : std::nullopt;
    }
    k = skip(k + 1);
    if (k >= n || tokens[k].kind != Tok::number) {
      return std::nullopt;
    }
    ++k;
    if (k < n && tokens[k].kind == Tok::letter && !tokens[k].space_before) {
      ++k;
    }
    k = skip(k);
    if (k >= n || !is_char(tokens[k], ')')) {
      return std::nullopt;
    }
    return k + 1;
  };
  const auto operator_like = [](const Token& t) {
    static const std::string_view before_term = "=+-/^_{([,&<>";
    return (t.kind == Tok::character && t.text.size() == 1 &&
            before_term.find(t.text[0]) != std::string_view::npos) ||
           in(t, commands::relations) || is_command(t, "\\cdot") || is_command(t, "\\times") ||
           is_command(t, "\\div");
  };
  const std::string message =
      "expected \\tag{…} for the equation's number: a label in brackets before an equation, or "
      "after it with a space, is its number more often than a factor; write \\tag{2} for the "
      "number, \\cdot (2) for the product";
  const std::size_t first = skip(0);
  if (const auto after = label_at(first, false)) {
    const std::size_t next = skip(*after);
    if (next < n && tokens[next].kind != Tok::end && !operator_like(tokens[next])) {
      throw source.error(tokens[first].offset, message);
    }
  }
  std::size_t last = n;
  while (last > 0 && (tokens[last - 1].kind == Tok::spacing || tokens[last - 1].kind == Tok::end)) {
    --last;
  }
  if (last == 0 || tokens[last - 1].kind == Tok::spacing) {
    return;
  }
  for (std::size_t open = last - 1; open-- > 0 && last - open <= 8;) {
    std::size_t before = open;
    bool wide = false;
    while (before > 0 && tokens[before - 1].kind == Tok::spacing) {
      wide = wide || wide_space(tokens[before - 1]);
      --before;
    }
    const bool spaced = before < open || tokens[open].space_before;
    if (!spaced || label_at(open, wide) != last) {
      continue;
    }
    if (!wide && argument_of_function(tokens, before)) {
      return;  // \sin (2x), \log_2 (8x): the function's argument, as part two reads it
    }
    if (before > 0 && !operator_like(tokens[before - 1])) {
      throw source.error(tokens[open].offset, message);
    }
    return;
  }
}

// row-steps := [arrow] equations {(arrow | annotation | ',') equations} [annotation]
// arrow := '\Rightarrow' | '\implies' | '\therefore' | '\Longrightarrow'   (a step)
//        | '\iff' | '\Leftrightarrow' | '\Longleftrightarrow'                (an equivalence)
// annotation := text-command '{' words '}'   (between equations, or at the end of a row)
// (a row cut here becomes several rows, each a step from the one before)
std::vector<RowTokens> split_steps(const Source& source, RowTokens row) {
  std::vector<RowTokens> pieces;
  RowTokens current;
  current.join = row.join;
  current.offset = row.offset;
  const std::vector<Token>& tokens = row.tokens;
  const std::vector<int> d = depths(tokens);
  const auto next_piece = [&](Join join, std::size_t offset) {
    if (!blank_tokens(current.tokens)) {
      current.tokens = trimmed_tokens(std::move(current.tokens));  // \quad around an arrow
      pieces.push_back(std::move(current));
    } else if (!pieces.empty() && join == Join::row) {
      join = current.join;  // two separators side by side: the first says how
    }
    current = RowTokens{};
    current.join = join;
    current.offset = offset;
  };
  // Whether the tokens from k to the next separator hold an equation (or nothing).
  const auto equation_follows = [&](std::size_t k, bool blank_counts) {
    std::vector<Token> rest;
    for (; k < tokens.size(); ++k) {
      if (d[k] == 0 && (in(tokens[k], commands::arrows) || in(tokens[k], commands::equivalences))) {
        break;
      }
      rest.push_back(tokens[k]);
    }
    return blank_tokens(rest) ? blank_counts : holds_relation(rest);
  };
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const Token& t = tokens[k];
    const bool top = d[k] == 0;
    if (top && (in(t, commands::arrows) || in(t, commands::equivalences))) {
      const std::vector<Token> rest(tokens.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                                    tokens.end());
      if (blank_tokens(rest)) {
        throw source.error(t.offset, "expected an equation after " + t.text);
      }
      next_piece(in(t, commands::arrows) ? Join::arrow : Join::equivalence,
                 first_offset(rest, t.offset));
      continue;
    }
    const Token* last = last_written(current.tokens);
    const bool in_script = last != nullptr && (is_char(*last, '_') || is_char(*last, '^'));
    // (\text{SUVAT}) is a note as \text{(SUVAT)} is, where a note may stand (it was a factor
    // SUVAT of the equation): the annotation then ends after its bracket.
    const auto bracketed = top && !in_script ? bracketed_text(source, tokens, k) : std::nullopt;
    if (bracketed || (top && in(t, commands::text_commands) && !in_script)) {
      const std::size_t at = bracketed ? bracketed->first : k;  // the \text command
      const Token& text = tokens[at];
      const std::size_t text_end = annotation_end(source, tokens, at);
      // A unit's power after a number, 9.81\,\text{m/s}^2, is part of the unit.
      const std::size_t end = bracketed                      ? bracketed->second
                              : after_number(current.tokens) ? unit_power_end(tokens, text_end)
                                                             : text_end;
      std::size_t open = at + 1;
      while (tokens[open].kind == Tok::spacing) {
        ++open;
      }
      const std::vector<Token> rest(tokens.begin() + static_cast<std::ptrdiff_t>(end),
                                    tokens.end());
      if (holds_relation(current.tokens) && equation_follows(end, true)) {
        // an annotation between two equations, or at the end of the row
        refuse_annotation(source, text, current.tokens, tokens, open, text_end, blank_tokens(rest));
        next_piece(Join::row, first_offset(rest, t.offset));
        k = end - 1;
        continue;
      }
      if (blank_tokens(current.tokens) && leads_a_row(tokens, end) &&
          equation_follows(end, false)) {
        // \text{hence}\quad 2y = 6x: a note before the row's equation (it was a factor hence)
        refuse_annotation(source, text, current.tokens, tokens, open, text_end, false);
        k = end - 1;
        continue;
      }
      if (words(tokens, open, text_end)) {
        throw source.error(text.offset,
                           "expected " + text.text +
                               "{…} between two equations or at the end of a row (an "
                               "annotation), found it inside an equation: words belong outside "
                               "the display block");
      }
      // one word inside an equation: a name (\text{KE} = …, \text{elasticity}\, p)
    }
    if (top && is_char(t, ',') && holds_relation(current.tokens)) {
      std::size_t next = k + 1;
      std::vector<Token> rest;
      for (; next < tokens.size() && !(d[next] == 0 && is_char(tokens[next], ',')); ++next) {
        rest.push_back(tokens[next]);
      }
      if (holds_relation(rest)) {
        next_piece(Join::row, first_offset(rest, t.offset));
        continue;
      }
    }
    if (current.tokens.empty() && t.kind != Tok::spacing) {
      current.offset = t.offset;
    }
    current.tokens.push_back(t);
  }
  if (!blank_tokens(current.tokens)) {
    current.tokens = trimmed_tokens(std::move(current.tokens));
    pieces.push_back(std::move(current));
  } else if (pieces.empty()) {
    throw source.error(row.offset, "expected an equation in the row, found only annotations");
  }
  for (const RowTokens& piece : pieces) {
    refuse_written_number(source, piece.tokens);
  }
  // The tag and label name the row's last equation.
  pieces.back().tag = row.tag;
  pieces.back().label = row.label;
  return pieces;
}

// A row without a relation that begins with + or - continues the last side of the row before.
std::vector<RowTokens> merge_continuations(const Source& source, std::vector<RowTokens> rows) {
  std::vector<RowTokens> merged;
  for (RowTokens& row : rows) {
    const bool has_relation = holds_relation(row.tokens);
    const Token& first = *std::find_if(row.tokens.begin(), row.tokens.end(),
                                       [](const Token& t) { return t.kind != Tok::spacing; });
    if (!has_relation && !merged.empty() && (is_char(first, '+') || is_char(first, '-')) &&
        row.join == Join::row) {
      merged.back().tokens.insert(merged.back().tokens.end(), row.tokens.begin(), row.tokens.end());
      if (row.tag) {
        if (merged.back().tag) {
          throw source.error(row.offset, "expected one \\tag per equation, found a second");
        }
        merged.back().tag = row.tag;
      }
      if (row.label) {
        merged.back().label = row.label;
      }
      continue;
    }
    if (!has_relation) {
      throw source.error(row.offset,
                         "expected an equation (… = …), found an expression without '='");
    }
    merged.push_back(std::move(row));
  }
  return merged;
}

// A side between two '=' that holds a space wider than \, between two terms: a = 2 \quad b = 3 is
// two equations to the writer, a chain a = 2b = 3 as read (a = 3 followed), and so are \;, ~~
// and \ \ . Refused: a comma or \quad\text{and}\quad separates equations, \cdot a product.
void refuse_spaced_equations(const Source& source, const std::vector<Token>& side) {
  const std::vector<int> d = depths(side);
  std::size_t first = 0;
  while (first < side.size() && side[first].kind == Tok::spacing) {
    ++first;
  }
  for (std::size_t k = first; k < side.size(); ++k) {
    if (side[k].kind != Tok::spacing || d[k] != 0) {
      continue;
    }
    // Spaces (\limits and \displaystyle are spacing tokens too, and no space): wide, or several.
    static const std::set<std::string, std::less<>> wide_spaces{
        "\\quad", "\\qquad", "\\;", "\\:", "\\>", "\\ ", "~", "\\hspace", "\\hspace*", "\\mspace"};
    std::size_t next = k;
    std::size_t spaces = 0;
    bool wide = false;
    for (; next < side.size() && side[next].kind == Tok::spacing; ++next) {
      wide = wide || wide_spaces.contains(side[next].text);
      spaces += wide_spaces.contains(side[next].text) || side[next].text == "\\," ? 1U : 0U;
    }
    wide = wide || spaces > 1;
    if (wide && next < side.size() && side[next].kind != Tok::end) {
      throw source.error(side[k].offset,
                         "expected one expression between two '=', found a wide space in it: "
                         "a = 2 \\quad b = 3 may be two equations (a = 2 and b = 3) or a chain "
                         "with a product (a = 2b = 3); write a comma or \\quad\\text{and}\\quad "
                         "between two equations, \\cdot for a product");
    }
    k = next;
  }
}

// equation := [side] '=' side {'=' side}     (a row that begins with '=' continues a chain)
Row read_row(const Source& source, RowTokens& row_tokens, const Limits& limits) {
  Row row;
  row.tag = row_tokens.tag;
  row.label = row_tokens.label;
  row.offset = row_tokens.offset;
  row.join = row_tokens.join;
  std::vector<std::vector<Token>> sides(1);
  const std::vector<int> d = depths(row_tokens.tokens);
  for (std::size_t k = 0; k < row_tokens.tokens.size(); ++k) {
    const Token& t = row_tokens.tokens[k];
    if (d[k] == 0 && (is_command(t, "\\approx") || is_command(t, "\\simeq"))) {
      throw source.error(t.offset, "expected '=', found " + t.text +
                                       ": an approximation is not a step that follows or not "
                                       "(write the exact equation, or name the approximation "
                                       "with let:)");
    }
    if (d[k] == 0 && t.kind != Tok::spacing && relation_token(t) && !is_char(t, '=')) {
      throw source.error(t.offset, "expected '=', found the relation " + t.text +
                                       ": this checker reads equations (facts such as x > 0 "
                                       "go in an assume: line)");
    }
    if (d[k] == 0 && is_char(t, '=')) {
      sides.emplace_back();
      continue;
    }
    sides.back().push_back(t);
  }
  row.continues = blank_tokens(sides[0]);
  for (std::size_t k = 0; k < sides.size(); ++k) {
    if (k == 0 && row.continues) {
      Side empty;
      empty.offset = row.offset;
      row.sides.push_back(std::move(empty));
      continue;
    }
    if (blank_tokens(sides[k])) {
      const std::size_t at = sides[k].empty() ? row.offset : sides[k].front().offset;
      throw source.error(
          at, k == 0 ? "expected an expression before '='" : "expected an expression after '='");
    }
    if (k > 0 && k + 1 < sides.size()) {
      refuse_spaced_equations(source, sides[k]);
    }
    row.sides.push_back(parse_side(source, std::move(sides[k]), row.offset, limits));
  }
  return row;
}

}  // namespace

// Removes \begin{…} and \end{…} of the environments that only arrange equations, checking that
// they pair up.
std::vector<Token> strip_environments(const Source& source, std::vector<Token> tokens) {
  std::vector<Token> kept;
  std::vector<std::pair<std::string, std::size_t>> open;
  std::set<std::size_t> box_ends;  // the '}' of each \boxed{…}
  for (std::size_t i = 0; i < tokens.size();) {
    const Token& t = tokens[i];
    if (box_ends.contains(i)) {
      ++i;
      continue;
    }
    if (is_command(t, "\\boxed") && is_char(tokens[i + 1], '{')) {
      // \boxed{v' = -e v}: the answer framed, read as if unframed (its braces would hide the
      // relation from the row).
      int depth = 0;
      for (std::size_t k = i + 1; tokens[k].kind != Tok::end; ++k) {
        depth += is_char(tokens[k], '{') ? 1 : is_char(tokens[k], '}') ? -1 : 0;
        if (depth == 0) {
          box_ends.insert(k);
          break;
        }
      }
      i += 2;
      continue;
    }
    if (is_command(t, "\\begin")) {
      const std::size_t at = t.offset;
      const std::string name = environment_name(source, tokens, i);
      if (!commands::environments.contains(name)) {
        const bool matrix = name.size() > 6 && name.ends_with("matrix");
        throw source.error(at,
                           "expected an environment that arranges equations (aligned, "
                           "align*, split, gathered, cases, equation), found {" +
                               name + "}" +
                               (matrix ? std::string(": a matrix is declared by its entries, "
                                                     "matrix: \\mathbf{A} = a_{qs} and column: "
                                                     "\\vec{B} = b_q over declared indices")
                                       : std::string()));
      }
      // Optional arguments: aligned[t], alignat{2}.
      if (is_char(tokens[i], '[')) {
        while (tokens[i].kind != Tok::end && !is_char(tokens[i], ']')) {
          ++i;
        }
        if (tokens[i].kind == Tok::end) {
          throw source.error(at, "expected ']' to close the environment's option");
        }
        ++i;
      }
      if (name.starts_with("alignat") && is_char(tokens[i], '{')) {
        while (tokens[i].kind != Tok::end && !is_char(tokens[i], '}')) {
          ++i;
        }
        ++i;
      }
      open.emplace_back(name, at);
      continue;
    }
    if (is_command(t, "\\end")) {
      const std::size_t at = t.offset;
      const std::string name = environment_name(source, tokens, i);
      if (open.empty()) {
        throw source.error(at, "expected no \\end{" + name + "}: no environment is open");
      }
      if (open.back().first != name) {
        throw source.error(at, "expected \\end{" + open.back().first + "} to close the \\begin{" +
                                   open.back().first + "} at " +
                                   std::to_string(source.place(open.back().second).line) + ":" +
                                   std::to_string(source.place(open.back().second).column) +
                                   ", found \\end{" + name + "}");
      }
      open.pop_back();
      continue;
    }
    kept.push_back(t);
    ++i;
  }
  if (!open.empty()) {
    throw source.error(open.back().second,
                       "expected \\end{" + open.back().first + "} to close this environment");
  }
  return kept;
}

// Whether the '&' at i separates two equations side by side (x &= 2 & y &= 3, align's columns
// in pairs) rather than marking where a row aligns (x &= 2): the row holds a relation before it,
// since its start or the last such '&', and what follows is neither a relation nor the end of
// the row nor an annotation (p &= m v && \text{…}).
bool separates_equations(const std::vector<Token>& tokens, std::size_t i, bool relation_before) {
  if (!relation_before) {
    return false;
  }
  std::size_t k = i + 1;
  while (k < tokens.size() && (tokens[k].kind == Tok::spacing || is_char(tokens[k], '&'))) {
    ++k;
  }
  if (k >= tokens.size()) {
    return false;
  }
  const Token& next = tokens[k];
  static const std::set<std::string> row_ends{"\\\\",    "\\tag",  "\\label", "\\nonumber",
                                              "\\notag", "\\text", "\\mbox",  "\\textrm"};
  return next.kind != Tok::end && !relation_token(next) &&
         !(next.kind == Tok::command && row_ends.contains(next.text));
}

// rows := row {'\\' ['[' length ']'] row}; '&', \nonumber and \notag are dropped, \tag{k} and
// \label{k} name their row.
std::vector<RowTokens> split_rows(const Source& source, const std::vector<Token>& tokens) {
  std::vector<RowTokens> rows(1);
  int braces = 0;
  bool relation_before = false;  // since the row's start or its last '&' between equations
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Tok::end) {
      break;
    }
    braces += is_char(t, '{') ? 1 : is_char(t, '}') ? -1 : 0;
    if (is_command(t, "\\\\") && braces == 0) {
      // \\[2pt]: the optional spacing belongs to the line break.
      if (i + 1 < tokens.size() && is_char(tokens[i + 1], '[')) {
        std::size_t k = i + 1;
        while (tokens[k].kind != Tok::end && !is_char(tokens[k], ']')) {
          ++k;
        }
        if (tokens[k].kind != Tok::end) {
          i = k;
        }
      }
      rows.emplace_back();
      relation_before = false;
      continue;
    }
    if (is_char(t, '&')) {
      if (braces == 0 && separates_equations(tokens, i, relation_before)) {
        Token comma = t;  // read as the comma between two equations is
        comma.kind = Tok::character;
        comma.text = ",";
        rows.back().tokens.push_back(comma);
        relation_before = false;
      }
      continue;
    }
    relation_before = relation_before || (braces == 0 && relation_token(t));
    if (is_command(t, "\\tag")) {
      const std::optional<std::string> label = braced_label(source, tokens, i, t);
      if (!label) {
        throw source.error(t.offset, "expected a label inside \\tag{}");
      }
      if (rows.back().tag) {
        throw source.error(t.offset, "expected one \\tag per row, found a second");
      }
      rows.back().tag = label;
      continue;
    }
    if (is_command(t, "\\label")) {
      if (const std::optional<std::string> label = braced_label(source, tokens, i, t)) {
        rows.back().label = label;
      }
      continue;
    }
    if (is_command(t, "\\nonumber") || is_command(t, "\\notag")) {
      continue;
    }
    if (rows.back().tokens.empty() && t.kind != Tok::spacing) {
      rows.back().offset = t.offset;
    }
    rows.back().tokens.push_back(t);
  }
  // Rows of spacing alone are nothing; trailing punctuation ends a sentence, not an equation.
  std::vector<RowTokens> kept;
  for (RowTokens& row : rows) {
    while (!row.tokens.empty() &&
           (row.tokens.back().kind == Tok::spacing || is_char(row.tokens.back(), ',') ||
            is_char(row.tokens.back(), '.') || is_char(row.tokens.back(), ';'))) {
      row.tokens.pop_back();
    }
    if (row.tokens.empty()) {
      if (row.tag) {
        throw source.error(source.text().size(), "expected an equation with the \\tag");
      }
      continue;
    }
    kept.push_back(std::move(row));
  }
  return kept;
}

Side parse_side(const Source& source, std::vector<Token> tokens, std::size_t fallback_offset,
                const Limits& limits) {
  Side side;
  std::size_t first = 0;
  while (first < tokens.size() && tokens[first].kind == Tok::spacing) {
    ++first;
  }
  side.offset = first < tokens.size() ? tokens[first].offset : fallback_offset;
  side.latex = join(tokens);
  Token end;
  end.offset = end.end = tokens.empty() ? fallback_offset : tokens.back().end;
  tokens.push_back(end);
  side.expression = Grammar(source, std::move(tokens), limits).whole_expression();
  return side;
}

std::vector<Row> read_block(const Source& source, std::size_t content_offset,
                            std::string_view content, const Limits& limits) {
  std::vector<Token> tokens = tokenize(source, content_offset, content);
  check_braces(source, tokens);
  tokens = strip_environments(source, std::move(tokens));
  std::vector<RowTokens> token_rows;
  bool beside = false;  // the row before ends with an equation after an annotation or a comma
  for (RowTokens& row : split_rows(source, tokens)) {
    const auto first = std::find_if(row.tokens.begin(), row.tokens.end(), [](const Token& t) {
      return t.kind != Tok::spacing && !is_char(t, '&');
    });
    if (beside && first != row.tokens.end() && is_char(*first, '=')) {
      // p &= m v && \text{with } v = J/m \\ &= J/m: the chain p = … was meant, and the line
      // went on from J/m (and its slip passed).
      throw source.error(first->offset,
                         "expected a line that continues one chain: this line begins with '=', "
                         "but the line before ends with an equation of its own (after an "
                         "annotation or a comma), so it could go on from that equation's right "
                         "side or from the chain's; write that equation on a line of its own "
                         "after the chain, or begin this line with its left side");
    }
    std::vector<RowTokens> pieces = split_steps(source, std::move(row));
    beside = pieces.size() > 1 && pieces.back().join == Join::row;
    for (RowTokens& piece : pieces) {
      token_rows.push_back(std::move(piece));
    }
  }
  if (token_rows.empty()) {
    throw source.error(content_offset > 2 ? content_offset - 2 : 0,
                       "expected an equation in the display block, found nothing");
  }
  std::vector<Row> rows;
  for (RowTokens& row_tokens : merge_continuations(source, std::move(token_rows))) {
    rows.push_back(read_row(source, row_tokens, limits));
  }
  return rows;
}

Side read_expression(const Source& source, std::size_t offset, std::string_view text,
                     const Limits& limits) {
  std::vector<Token> tokens = tokenize(source, offset, text);
  check_braces(source, tokens);
  tokens.pop_back();  // the end token; parse_side adds its own
  for (const Token& t : tokens) {
    if (is_char(t, '=') || is_char(t, '&') || is_command(t, "\\\\")) {
      throw source.error(t.offset, "expected one expression, found " + describe(t));
    }
  }
  if (tokens.empty()) {
    throw source.error(offset, "expected an expression");
  }
  return parse_side(source, std::move(tokens), offset, limits);
}

SymbolName read_symbol(const Source& source, std::size_t offset, std::string_view text,
                       const Limits& limits) {
  std::vector<Token> tokens = tokenize(source, offset, text);
  check_braces(source, tokens);
  return Grammar(source, std::move(tokens), limits).whole_symbol();
}

SymbolName read_symbol_or_differential(const Source& source, std::size_t offset,
                                       std::string_view text, const Limits& limits) {
  constexpr std::string_view d = "\\mathrm{d}";
  if (!text.starts_with(d) || text.size() == d.size()) {
    return read_symbol(source, offset, text, limits);
  }
  SymbolName name = read_symbol(source, offset + d.size(), text.substr(d.size()), limits);
  if (name.differential || name.delta) {
    throw source.error(offset, "expected one symbol after \\mathrm{d}");
  }
  name.differential = true;
  return name;
}

}  // namespace impulse::derivations::file
