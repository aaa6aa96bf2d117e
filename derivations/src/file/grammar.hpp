// SPDX-License-Identifier: GPL-3.0-or-later
// The grammar of one expression of a display block: one function per production, the rule it
// reads written above it (EBNF; 'x' a token, [a] optional, {a} repeated). A token the grammar has
// no place for is a ReadError with its place and what was expected there: nothing is skipped,
// and nothing outside the grammar is read by accident. What the tree means (is F(t) a function's
// value, is d a differential) is the meaning layer's business (meaning.hpp).
//
// The productions live in four files: grammar.cpp (sums, products, factors, powers, bars),
// grammar_atoms.cpp (groups, delimiters, fractions and derivatives, roots, functions),
// grammar_symbols.cpp (names, subscripts, primes) and grammar_big.cpp (sums, products and
// integrals with their limits and differentials).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "file/latex.hpp"
#include "file/text.hpp"
#include "file/tokens.hpp"

namespace impulse::derivations::file {

/// The tokens of one row of a display block, before its sides are read.
struct RowTokens {
  std::vector<Token> tokens;
  std::optional<std::string> tag;
  std::optional<std::string> label;
  std::size_t offset = 0;
  Join join = Join::row;
};

/// The tokens without the \begin{…} and \end{…} of the environments that arrange equations
/// (checked to pair up).
[[nodiscard]] std::vector<Token> strip_environments(const Source& source,
                                                    std::vector<Token> tokens);
/// The rows of a block (cut at \\), each with its \tag and \label; rows of spacing dropped.
[[nodiscard]] std::vector<RowTokens> split_rows(const Source& source,
                                                const std::vector<Token>& tokens);
/// The letter d alone (no subscript, prime, accent or Δ): the d of a derivative or differential.
[[nodiscard]] bool is_plain_d(const Node& n);
/// One side of an equation or relation, read by the grammar.
[[nodiscard]] Side parse_side(const Source& source, std::vector<Token> tokens,
                              std::size_t fallback_offset, const Limits& limits);

class Grammar {
 public:
  /// @param tokens a run of tokens ending with an `end` token
  Grammar(const Source& source, std::vector<Token> tokens, const Limits& limits)
      : source_(source), tokens_(std::move(tokens)), limits_(limits) {}

  /// whole := expression end
  Node whole_expression();
  /// whole-symbol := symbol end
  SymbolName whole_symbol();

 private:
  // ---- token access (grammar.cpp) ----
  const Token& peek();
  const Token& peek_raw() const { return tokens_[position_]; }
  const Token& ahead(std::size_t k) const;  ///< the k-th token after the next (spacing counted)
  /// the token at index i, or the closing `end` token for any index past it
  const Token& token(std::size_t i) const { return tokens_[std::min(i, tokens_.size() - 1)]; }
  Token take();
  void skip_spacing();
  [[nodiscard]] ReadError error(const Token& at, const std::string& message) const {
    return source_.error(at.offset, message);
  }
  [[nodiscard]] ReadError error_at(std::size_t offset, const std::string& message) const {
    return source_.error(offset, message);
  }
  void expect_char(char c, const Token& opener, const std::string& what);
  [[nodiscard]] std::string where(const Token& t) const;
  void enter(std::size_t depth, const Token& at) const;
  [[nodiscard]] Node make(NodeKind kind, std::size_t offset) const;

  // ---- sums, products, factors (grammar.cpp) ----
  Node expression(std::size_t depth);
  Node sum_term(std::size_t depth);
  void refuse_ambiguous_division(const Node& product, const Token& written) const;
  void refuse_mixed_number(const Node& product, const Token& written) const;
  void refuse_number_after_symbol(const Node& product, const Token& next) const;
  void refuse_bar_after_sum(const Node& sum) const;
  void refuse_unit(const Node& product, const Token& written) const;
  void refuse_written_unit(const Node& product, const Token& next) const;
  void refuse_digits_left(const Token& command) const;
  [[nodiscard]] bool runs_into_factor(const Token& next) const;
  [[nodiscard]] ReadError runs_on(const Token& at, const std::string& past);
  Node term(std::size_t depth);
  Node factor(std::size_t depth);
  Node postfix(std::size_t depth, Node base);
  Node power_of(std::size_t depth, Node base, const Token& caret);
  [[nodiscard]] bool degrees_follow() const;
  Node degrees(Node number, const Token& caret);
  bool bar_ahead();
  Node bar(std::size_t depth, Node base);
  Node script(std::size_t depth, const Token& caret);
  Node single_digit(const Token& t, bool script);
  [[nodiscard]] bool explicit_product(const Token& t) const;
  [[nodiscard]] bool starts_atom(const Token& t) const;
  [[nodiscard]] static bool big_operator(const Token& t);
  [[nodiscard]] bool differential_ahead() const;

  // ---- atoms (grammar_atoms.cpp) ----
  Node atom(std::size_t depth);
  Node bracket(std::size_t depth);
  Node group_inside(std::size_t depth, const Token& open, char close);
  Node brace_group(std::size_t depth, const Token& open);
  Node delimited(std::size_t depth);
  Node argument(std::size_t depth, const Token& before, const std::string& what = "");
  Node command(std::size_t depth);
  Node refused_command(const Token& t);
  Node fraction(std::size_t depth);
  std::optional<Node> as_derivative(const Node& top, const Node& bottom, std::size_t offset,
                                    std::size_t depth);
  Node root(std::size_t depth);
  Node function(std::size_t depth);
  Node bare_argument(std::size_t depth, const Token& function);
  Node determinant(std::size_t depth);
  Node norm(std::size_t depth);
  Node call(std::size_t depth, Node name);
  [[nodiscard]] bool call_ahead() const;

  // ---- symbols (grammar_symbols.cpp) ----
  Node symbol_atom(std::size_t depth);
  Node delta_symbol(std::size_t depth);
  [[nodiscard]] bool starts_symbol(const Token& t) const;
  std::string name_group(const Token& command_token);
  Node decorate(std::size_t depth, Node n);
  [[nodiscard]] bool primes_follow() const;
  int read_prime_script();
  std::string subscript(std::size_t depth);

  // ---- sums, products and integrals (grammar_big.cpp) ----
  Node big(std::size_t depth);
  Node sum_over(std::size_t depth, const Token& op);
  Node integral(std::size_t depth, const Token& op);
  bool path_domain();
  void take_differential(Node& integral);

  const Source& source_;
  std::vector<Token> tokens_;
  const Limits& limits_;
  std::size_t position_ = 0;
  std::size_t last_end_ = 0;
  int abs_depth_ = 0;                  // inside |…|: a '|' closes
  int norm_depth_ = 0;                 // inside \|…\|: a '\|' closes
  int sized_depth_ = 0;                // inside \bigl( … \bigr): a sized closing delimiter closes
  int bare_argument_ = 0;              // inside a function's argument written without parentheses
  std::vector<Token> bare_functions_;  // the functions whose bare arguments are being read
  // Where the rest of a number starts whose first digit single_digit took as an argument.
  std::size_t split_digits_at_ = std::numeric_limits<std::size_t>::max();
  int integrand_ = 0;  // inside an integrand: a differential ends a bare argument
};

}  // namespace impulse::derivations::file
