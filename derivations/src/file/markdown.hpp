// SPDX-License-Identifier: GPL-3.0-or-later
// The Markdown layer of a derivation file: display blocks and directive lines, in the order
// they stand, with their byte offsets. A display block is $$ … $$, \[ … \], one of the
// environments equation, align, gather, multline (and their starred forms) outside $$, or a
// fenced ```math block; a display written any other way (\begin{eqnarray}, …) is refused at its
// line. Prose, inline math, code and HTML comments are skipped (a $$ inside a code span, a
// fenced code block or a comment is not a display block); a line that is an equation in inline
// math alone is listed, to be reported as not checked.
#pragma once

#include <cstddef>
#include <string_view>
#include <variant>
#include <vector>

#include "file/text.hpp"

namespace impulse::derivations::file {

/// The directive words of the format (spec/derivation-format.md), then those accepted beyond it
/// for the paper's files (docs/pages/derivations.md).
enum class DirectiveKind {
  assume,
  let,
  given,
  from,
  vector,
  units,
  // part two of the contract: what students write
  function,
  unit,
  target,
  // beyond the contract
  also,
  section,
  check,
  claim,
  correction,
  evidence,
  test,
  explanation,
  index,
  arrow,
  differentials,
  forces,
  matrix,
  column,
  model,
  ode,
  quadrature,
  search,
};

/// A directive line: `word: content`.
struct Directive {
  DirectiveKind kind;
  std::size_t offset = 0;          ///< where the word begins
  std::size_t content_offset = 0;  ///< where the content begins (after the colon and spaces)
  std::string_view content;        ///< the LaTeX after the colon, trimmed
};

/// A display block: the text between `$$` and `$$` (or `\[` and `\]`, or an environment's
/// \begin and \end).
struct Block {
  std::size_t offset = 0;          ///< where the opening `$$` stands
  std::size_t content_offset = 0;  ///< the first byte after it
  std::string_view content;        ///< up to the closing `$$`
};

/// A line of prose that is nothing but an equation in inline math (`$x = 2 y$`, `\(x = 2 y\)`,
/// perhaps as a list item or before a full stop): not read, as inline math is not, but reported,
/// since it reads like a display the writer meant to be checked.
struct LoneInline {
  std::size_t offset = 0;    ///< where the opening `$` or `\(` stands
  std::string_view written;  ///< the inline math with its delimiters
};

using Item = std::variant<Directive, Block, LoneInline>;

/// The directives and display blocks of @p source, in order. Throws ReadError for a block that
/// is never closed, a fenced code block or comment never closed, or more display blocks than
/// the limits allow.
[[nodiscard]] std::vector<Item> read_markdown(const Source& source, const Limits& limits);

/// The name of a directive kind ("assume", …).
[[nodiscard]] std::string_view to_string(DirectiveKind kind);

}  // namespace impulse::derivations::file
