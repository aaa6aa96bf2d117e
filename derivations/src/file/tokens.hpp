// SPDX-License-Identifier: GPL-3.0-or-later
// The LaTeX of a display block cut into tokens: commands (\frac, \alpha, \\), single letters,
// numbers, single characters, and spacing. The tables here name every command the grammar
// (grammar.hpp) gives a place; a command in none of them is unknown, and the grammar refuses it.
#pragma once

#include <cstddef>
#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "file/text.hpp"

namespace impulse::derivations::file {

/// The kinds of token.
enum class Tok { command, letter, number, character, spacing, end };

/// One token, with the span of the file it came from.
struct Token {
  Tok kind = Tok::end;
  std::string text;
  std::size_t offset = 0;
  std::size_t end = 0;
  bool space_before = false;  ///< the file had a space (or spacing) right before it
  std::string written;        ///< what the file has here, where it is read as `text` ({\rm)
};

/// The commands the grammar knows, by the place they take.
namespace commands {
using Set = std::set<std::string, std::less<>>;
extern const Set greek;          ///< \alpha … \Omega: letters of names
extern const Set spacing;        ///< \, \; \quad …: ignored
extern const Set functions;      ///< \sin \cos … \ln \log: functions of one argument
extern const Set fractions;      ///< \frac \dfrac \tfrac \cfrac
extern const Set accents;        ///< \vec \hat \mathbf …: the symbol under them, as a vector
extern const Set modifiers;      ///< \bar \dot \ddot \tilde …: another symbol
extern const Set names;          ///< \mathrm \text \operatorname …: a name of letters
extern const Set sizes;          ///< \big \Bigl \biggr …: delimiter sizes
extern const Set relations;      ///< < > \leq … \iff: relations and arrows
extern const Set arrows;         ///< \Rightarrow \implies \therefore: a step inside a block
extern const Set equivalences;   ///< \iff \Leftrightarrow: a step that must be an equivalence
extern const Set environments;   ///< aligned, align*, equation …: arrange equations
extern const Set text_commands;  ///< \text \mbox \textrm …: words, annotations between equations
}  // namespace commands

/// Cuts @p text (which begins at @p base in @p source) into tokens, ending with an `end` token.
/// Throws ReadError at a character that is not LaTeX (a Greek letter pasted as Unicode, …).
[[nodiscard]] std::vector<Token> tokenize(const Source& source, std::size_t base,
                                          std::string_view text);

/// Whether @p t is of @p kind with the text @p text.
[[nodiscard]] inline bool is(const Token& t, Tok kind, std::string_view text) {
  return t.kind == kind && t.text == text;
}
/// Whether @p t is the single character @p c.
[[nodiscard]] inline bool is_char(const Token& t, char c) {
  return t.kind == Tok::character && t.text.size() == 1 && t.text[0] == c;
}
/// Whether @p t is the command @p name ("\\frac").
[[nodiscard]] inline bool is_command(const Token& t, std::string_view name) {
  return is(t, Tok::command, name);
}
/// Whether @p t is a command of @p set.
[[nodiscard]] inline bool in(const Token& t, const commands::Set& set) {
  return (t.kind == Tok::command || t.kind == Tok::character) && set.contains(t.text);
}

/// A token as a message names it ("'\\frac'", "the number 2", "the end of the expression").
[[nodiscard]] std::string describe(const Token& t);

/// The LaTeX of a run of tokens as written: their texts, with a space where the file had one.
[[nodiscard]] std::string join(const std::vector<Token>& tokens);

/// Whether every token of @p tokens is spacing.
[[nodiscard]] bool blank_tokens(const std::vector<Token>& tokens);

/// @p tokens without the spacing at either end.
[[nodiscard]] std::vector<Token> trimmed_tokens(std::vector<Token> tokens);

/// The offset of the first token that is not spacing, or @p fallback.
[[nodiscard]] std::size_t first_offset(const std::vector<Token>& tokens, std::size_t fallback);

/// Checks that braces pair up, so that an unbalanced brace is reported where it stands.
void check_braces(const Source& source, const std::vector<Token>& tokens);

/// The depth of every token, counting braces, parentheses, brackets, \{ \}, \left … \right and
/// the sized delimiters (\bigl( … \bigr)).
[[nodiscard]] std::vector<int> depths(const std::vector<Token>& tokens);

/// The runs of @p tokens between the separators that stand at depth 0 (each separator is kept
/// in @p separators when given).
[[nodiscard]] std::vector<std::vector<Token>> split_top(
    const std::vector<Token>& tokens, const std::function<bool(const Token&)>& separator,
    std::vector<Token>* separators = nullptr);

}  // namespace impulse::derivations::file
