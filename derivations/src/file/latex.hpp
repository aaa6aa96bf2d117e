// SPDX-License-Identifier: GPL-3.0-or-later
// The LaTeX of a display block, read into a syntax tree: rows of equations (split at \\ and at
// every `=`), each side an expression of numbers, symbols, sums, products, fractions, powers,
// functions, norms, determinants and vector literals. What the tree means (scalars or vectors,
// definitions) is the next layer's business (meaning.hpp); this one only knows the notation.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "file/text.hpp"

namespace impulse::derivations::file {

/// A symbol as written: `\Delta E_{o}'` is base "E", subscript "o", one prime, delta.
struct SymbolName {
  std::string base;       ///< a letter, a Greek command ("\omega"), "dt", or a \mathrm{} name
  std::string subscript;  ///< "", "1", "vn", "\alpha"
  int primes = 0;         ///< p' has one
  bool delta = false;     ///< \Delta X: the change of X, one symbol
  /// Written under an accent (\vec p, \vec{F_i}): the same symbol as without it, unless the
  /// file declares the letter with `arrow:` (meaning.hpp decides; the tree only records it).
  bool accent = false;
  /// Stands for the vector of an `arrow:` letter (\vec F, distinct from the number F).
  bool arrow = false;
  /// The differential of a symbol declared with `differentials:` (\mathrm{d}S_v, dL).
  bool differential = false;

  /// The canonical LaTeX of the symbol ("p_{1}'", "\Delta E_{o}", "\omega"), the key under which
  /// the file's symbols are known.
  [[nodiscard]] std::string latex() const;
  /// A plain-text name ("p_1'", "Delta E_o", "omega").
  [[nodiscard]] std::string plain() const;
  /// The same name without its primes.
  [[nodiscard]] SymbolName unprimed() const;
  /// The same symbol: the names agree in all but the accent as written.
  bool operator==(const SymbolName& other) const {
    return base == other.base && subscript == other.subscript && primes == other.primes &&
           delta == other.delta && arrow == other.arrow && differential == other.differential;
  }
};

/// The kinds of node of an expression tree.
enum class NodeKind {
  number,        ///< a decimal literal, exact: `text`
  symbol,        ///< `symbol`
  pi,            ///< \pi, the constant
  sum,           ///< children with `ops` '+' or '-' (the first may be '-': unary minus)
  product,       ///< children with `ops`: ' ' (first, or juxtaposition), '.' (\cdot), 'x' (\times),
                 ///< '*' and '/' (division by the child)
  fraction,      ///< \frac{children[0]}{children[1]}
  power,         ///< children[0]^children[1]
  function,      ///< `text` ("sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos",
                 ///< "arctan", "exp", "ln", "log") of children[0]; log: children[1] its base
  root,          ///< \sqrt{children[0]}, or the children[1]-th root when there are two
  norm,          ///< \|children[0]\|
  abs,           ///< |children[0]|
  det,           ///< \det(children[0], children[1])
  vector,        ///< [children[0], children[1]]
  call,          ///< a name right before a parenthesised list, F(t) or f(a, b): children[0] the
                 ///< name (a symbol), then one child per argument. A declared function's value,
                 ///< or a product (m(v_1 - v_2)): the meaning layer decides, or refuses
  derivative,    ///< \frac{d children[0]}{d x}, \frac{d}{dx}(children[0]): `symbol` the variable
                 ///< x, `text` the order ("1", "2")
  factorial,     ///< children[0]!
  sum_over,      ///< \sum_{text} children[0] over the index `text`: its declared range, or the
                 ///< limits children[1] (ops "l") and children[2] (ops "u") of \sum_{i=1}^{N}
  product_over,  ///< \prod, as sum_over
  integral,      ///< \int: children[0] the integrand, then the lower and upper limits when
                 ///< written (`ops`: "l", "u"); ops "d": the differential d`symbol` was written
                 ///< after the integrand and taken from it; without "d" the integrand is a
                 ///< 1-form that holds dt (the paper's files)
  bar,           ///< children[0]\Big|_{children[1]}^{children[2]}; `text`: the variable ("t",
                 ///< or the symbol of a lower limit written x = a, whose value is then
                 ///< children[1])
  dots,          ///< \cdots between the terms of a sum: the terms whose subscripts lie between
};

/// Node::text of the symbol d written upright: the operator of a differential, not a letter.
inline constexpr std::string_view upright_d = "\\mathrm{d}";
/// Node::text of the symbol e written upright (\mathrm{e}): Euler's number, not a letter.
inline constexpr std::string_view upright_e = "\\mathrm{e}";
/// The text of a call node that stands in a function's argument written without parentheses.
inline constexpr std::string_view bare_call = "bare";
/// Why a function's argument written without parentheses may not run on into a group:
/// \cos\theta(v_1 + v_2) could be cos(θ (v_1 + v_2)) or cos θ times (v_1 + v_2).
inline constexpr std::string_view runs_into_group =
    "expected parentheses around the argument of a function: written without them, it would "
    "run on into the group that follows, which may be meant outside; write \\cos(\\theta (a + "
    "b)) for the one, \\cos\\theta \\cdot (a + b) or (a + b) \\cos\\theta for the other";

/// A node of an expression tree, with the span of the file it was read from.
struct Node {
  NodeKind kind = NodeKind::number;
  std::size_t offset = 0;  ///< where its first token stands in the file
  std::size_t end = 0;     ///< the byte after its last token
  /// number: its digits; function: its name; the symbol d written upright (\mathrm{d}, \text{d}):
  /// upright_d, the d of a differential; the symbol e written so: upright_e, Euler's number;
  /// call: bare_call inside a function's argument written without parentheses
  std::string text;
  SymbolName symbol;  ///< symbol
  std::vector<Node> children;
  std::string ops;  ///< sum and product: one operator character per child
  /// Written in delimiters of its own: a group ( … ) or [ … ], or an evaluation bar on brackets
  /// (\\left[ … \\right]_a^b, \\left. … \\right|_a^b)
  bool enclosed = false;
  /// A call written with a space before its parenthesis (m_1 (v_1')^2): a product when the name is
  /// no function.
  bool spaced = false;
};

/// One side of an equation: its tree and its LaTeX as written (spacing kept, `&` dropped).
struct Side {
  Node expression;
  std::string latex;
  std::size_t offset = 0;  ///< where it begins in the file
};

/// How a row of a display block is joined to the row before it.
enum class Join {
  row,          ///< `\\`, or the first row: the row is a step from the one before
  arrow,        ///< \Rightarrow, \implies, \therefore: the same
  equivalence,  ///< \iff, \Leftrightarrow: a step that must be an equivalence
};

/// One row of a display block (between `\\`): `a = b = c` has three sides.
struct Row {
  std::vector<Side> sides;  ///< two or more; when `continues`, the first is the empty side
  bool continues = false;   ///< the row began with `=`: its left side is the row before's right
  Join join = Join::row;    ///< how it follows the row before
  std::optional<std::string> tag;  ///< `\tag{k}`: "k"
  /// `\label{k}`: "k" (accepted beyond the contract: it names the row for `from:` as a tag does,
  /// without a number in print)
  std::optional<std::string> label;
  std::size_t offset = 0;  ///< where the row begins in the file
};

/// Reads the rows of a display block. Throws ReadError with the place of whatever is not
/// understood (an unknown command, an unbalanced brace, an expression without `=`, …).
/// @param source the file
/// @param content_offset where the block's content begins in the file
/// @param content the block's content (between the two `$$`)
/// @param limits nesting depth, number length, exponent size
[[nodiscard]] std::vector<Row> read_block(const Source& source, std::size_t content_offset,
                                          std::string_view content, const Limits& limits);

/// A relation of a claim (accepted beyond the contract, for the paper's files): x = y, x \neq y,
/// x < y, x > y, x \leq y, x \geq y, x \in (a, b) (brackets closed, \infty open) or
/// x \in \{a, b, …\}.
struct Relation {
  enum class Kind { equal, not_equal, less, greater, less_equal, greater_equal, in_range, in_set };
  Kind kind = Kind::equal;
  Side left;
  Side right;                 ///< the other side (not for in_range, in_set)
  std::vector<Side> members;  ///< in_set: the members; in_range: the finite ends (see below)
  std::optional<Side> low;    ///< in_range: the lower end, or none for -\infty
  std::optional<Side> high;   ///< in_range: the upper end, or none for \infty
  bool low_closed = false;    ///< in_range: [a, …
  bool high_closed = false;   ///< in_range: …, b]
  std::size_t offset = 0;
};

/// One row of a claim: hypotheses ⇒ conclusions (each a list separated by commas; no
/// hypotheses without \Rightarrow), or \exists conclusions (some case satisfies them).
struct ClaimRow {
  bool exists = false;
  std::vector<Relation> hypotheses;
  std::vector<Relation> conclusions;
  std::size_t offset = 0;
  std::string latex;  ///< the row as written
};

/// Reads the rows of a claim's display block. Throws ReadError with the place of whatever is not
/// understood.
[[nodiscard]] std::vector<ClaimRow> read_claim_block(const Source& source,
                                                     std::size_t content_offset,
                                                     std::string_view content,
                                                     const Limits& limits);

/// Reads the relations of a directive's LaTeX, separated by commas (`assume:`): each chain
/// `a \leq b \leq c` gives a relation per link. Throws ReadError with the place of what is not
/// understood, or of a piece without a relation.
[[nodiscard]] std::vector<Relation> read_relation_list(const Source& source, std::size_t offset,
                                                       std::string_view text, const Limits& limits);

/// Reads one expression (the LaTeX of a directive: a `let:` right side), spanning the whole
/// of @p text.
[[nodiscard]] Side read_expression(const Source& source, std::size_t offset, std::string_view text,
                                   const Limits& limits);

/// Reads one symbol name spanning the whole of @p text (the names of `vector:`, `units:`,
/// `assume:`, `let:`). Throws ReadError when it is not one symbol.
[[nodiscard]] SymbolName read_symbol(const Source& source, std::size_t offset,
                                     std::string_view text, const Limits& limits);

/// As read_symbol, and a differential too: "\\mathrm{d}L" is L's differential (a `let:` of
/// one, a model's value for one). Accepted beyond the contract, for the paper's section 5.
[[nodiscard]] SymbolName read_symbol_or_differential(const Source& source, std::size_t offset,
                                                     std::string_view text, const Limits& limits);

}  // namespace impulse::derivations::file
