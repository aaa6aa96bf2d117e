// SPDX-License-Identifier: GPL-3.0-or-later
// What the trees of a derivation file mean: each symbol a real number or a vector of the plane
// (`vector:`), each expression a GiNaC expression or a pair of them, each `let:` a substitution
// in force from its line on, each `units:` a dimension. Type errors (a vector added to a scalar,
// \det of scalars) are ReadErrors with their place; dimension mismatches are findings.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "file/latex.hpp"
#include "file/text.hpp"

namespace impulse::derivations::file {

/// A scalar, a vector of the plane [x, y], or (accepted beyond the contract) a block: a matrix
/// or a column over the contacts, declared with `matrix:` or `column:`.
struct Value {
  Value() = default;
  /// A scalar (vector false, y 0) or a vector of the plane.
  Value(bool is_vector, GiNaC::ex x_value, GiNaC::ex y_value)
      : vector(is_vector), x(std::move(x_value)), y(std::move(y_value)) {}
  bool vector = false;
  GiNaC::ex x;                     ///< the scalar, or the x component
  GiNaC::ex y;                     ///< the y component of a vector
  std::size_t rows = 0;            ///< a block's rows (0: not a block)
  std::size_t cols = 0;            ///< a block's columns (1: a column)
  std::vector<GiNaC::ex> entries;  ///< a block's entries, row by row
  [[nodiscard]] bool block() const { return rows > 0; }
};

/// An expression's value and the denominators written in it (each one must not be zero where
/// the expression is read: the conditions a division brings).
struct Meaning {
  Value value;
  std::vector<GiNaC::ex> denominators;
  std::vector<std::string> written;  ///< each denominator's LaTeX as the file wrote it
};

/// A function the file declares with `function:` (accepted beyond part one of the contract):
/// F(t) is its value at t; its derivatives and integrals are read.
struct FunctionDeclaration {
  SymbolName name;
  std::vector<SymbolName> variables;  ///< t unless the file writes others: function: u(x, t)
  unsigned serial = 0;                ///< the GiNaC function that stands for it
  bool variable_written = false;      ///< false: `function: F`, whose variable is t by default
};

/// A dimension M^a L^b T^c with rational exponents.
struct Dimension {
  GiNaC::numeric mass = 0;
  GiNaC::numeric length = 0;
  GiNaC::numeric time = 0;
  bool operator==(const Dimension& other) const {
    return mass == other.mass && length == other.length && time == other.time;
  }
  /// "M L T^-1", or "1" when dimensionless.
  [[nodiscard]] std::string text() const;
};
/// The dimension of a product (a quotient) of quantities of dimensions @p a and @p b.
[[nodiscard]] Dimension operator+(const Dimension& a, const Dimension& b);
[[nodiscard]] Dimension operator-(const Dimension& a, const Dimension& b);

/// Where an equation's terms disagree in dimension.
struct DimensionIssue {
  std::size_t offset = 0;  ///< the term where the disagreement shows
  Dimension first;         ///< the dimension of the terms before it (or of the left side)
  Dimension second;        ///< its dimension (or the right side's)
  std::string what;        ///< a sentence: which terms, and what was expected
};

/// What a scalar symbol of GiNaC stands for in the file: its own name, or a component of a
/// vector.
struct SymbolInfo {
  SymbolName name;               ///< as written ("p_x'", "m_1")
  std::optional<SymbolName> of;  ///< the vector it is a component of
  int component = 0;             ///< 0: x, 1: y
};

/// A copy of @p node with the index @p index replaced by @p value in the subscripts of its
/// symbols (subscripts of up to three letters and digits: a_{vi} with i = 2 is a_{v2}), except
/// inside a sum over the same index.
[[nodiscard]] Node with_index(const Node& node, const std::string& index, long value);
/// The same with the index written as @p value ("N", "N-1").
[[nodiscard]] Node with_index_text(const Node& node, const std::string& index,
                                   const std::string& value);
/// How much of a subscript can hold indices: all of a plain one (one to three letters and
/// digits), or the plain part before a word in parentheses (a_{vi(elastic)}, the paper's names of
/// its coefficients); 0 for none.
[[nodiscard]] std::size_t index_part(const std::string& subscript);

/// The symbols, vectors, definitions and units of one file, as its lines declare them.
class Symbols {
 public:
  Symbols(const Source& source, const Limits& limits) : source_(source), limits_(limits) {}

  // ---- accepted beyond the contract (the paper's files) ----
  /// `arrow: F`: \vec F (any subscript, primes) is a vector distinct from the number F.
  void declare_arrow(const std::string& letter) { arrows_.insert(letter); }
  /// `differentials: S_v`: dS_v and \mathrm{d}S_v are one symbol, the differential of S_v.
  void declare_differential(const SymbolName& name) {
    differentials_.insert(resolve(name).latex());
  }
  /// `forces: F_v`: a force that varies over the contact (its value is its mean): inside an
  /// integral it is shaped by the contact's pulse.
  void declare_force(const SymbolName& name);
  /// `index: i \in \{1, 2\}`: the values of an index of sums and of rows.
  void declare_index(const std::string& letter, std::vector<long> values) {
    indices_[letter] = std::move(values);
  }
  /// `matrix: \mathbf{A} = a_{vi}` or `column: \vec{B} = b_v`: a block over the contacts, its
  /// entry given by the template (the indices of the template in the order they appear: row,
  /// then column).
  void declare_block(const SymbolName& name, const Side& entry, bool matrix, std::size_t offset);
  /// The declared indices.
  [[nodiscard]] const std::map<std::string, std::vector<long>>& indices() const { return indices_; }
  /// The force symbols (scalars and the components of vectors) declared with `forces:`.
  [[nodiscard]] const std::vector<GiNaC::ex>& forces() const { return forces_; }
  /// The declared indices that stand free in @p node (not bound by a sum).
  [[nodiscard]] std::vector<std::string> free_indices(const Node& node) const;
  /// The name as the file's declarations read it (an accent over an `arrow:` letter).
  [[nodiscard]] SymbolName resolve(SymbolName name) const;

  /// `function: F` or `function: F(x)`: F(a) is a function's value from here on.
  void declare_function(const SymbolName& name, std::vector<SymbolName> variables,
                        std::size_t offset);
  /// The function @p name is declared as, if it is one.
  [[nodiscard]] const FunctionDeclaration* function(const SymbolName& name) const;
  /// Whether @p symbol is a declared variable of the function whose GiNaC serial is @p serial.
  [[nodiscard]] bool is_variable_of(unsigned serial, const GiNaC::ex& symbol) const;
  /// The declaration of the function GiNaC knows by @p serial, if the file declared it.
  [[nodiscard]] const FunctionDeclaration* function_of(unsigned serial) const;
  /// The symbols that stand as the upper limit of a sum over an index (whole numbers at least
  /// the lower limit: the number of terms), with that lower limit.
  [[nodiscard]] const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& counts() const {
    return counts_;
  }
  /// @p body (a sum's term over @p index) at a value of the index: the symbols whose subscript
  /// holds the index letter renamed (m_i at 2 is m_2), the index itself the value. The symbols
  /// renamed, with the symbol they came from, are added to @p renamed when given.
  [[nodiscard]] GiNaC::ex at_index(const GiNaC::ex& body, const GiNaC::ex& index, long value,
                                   std::vector<std::pair<GiNaC::ex, GiNaC::ex>>* renamed = nullptr);
  /// The same at a value that is a letter (another index, N) or a letter plus a whole number
  /// (N - 1): m_i at N - 1 is the symbol m_{N-1}.
  [[nodiscard]] GiNaC::ex at_index(const GiNaC::ex& body, const GiNaC::ex& index,
                                   const GiNaC::ex& value,
                                   std::vector<std::pair<GiNaC::ex, GiNaC::ex>>* renamed = nullptr);
  /// How a value of an index is written in a subscript ("2", "N", "N-1"), if it can be.
  [[nodiscard]] std::optional<std::string> index_text(const GiNaC::ex& value) const;
  /// Whether the symbol @p s is indexed by the index @p index (m_i by i).
  [[nodiscard]] bool indexed_by(const GiNaC::ex& s, const GiNaC::ex& index) const;

  /// The symbols of @p node named by a fact of `assume:`: each is a real quantity of the file
  /// (so e to a power is that quantity's power, not Euler's number's; i is no imaginary unit).
  void note_quantities(const Node& node);
  /// Whether the file says @p name is a real quantity: a fact names it, `units:` gives its
  /// dimension, `let:` defines it, or it is declared a vector or a function.
  [[nodiscard]] bool is_quantity(const SymbolName& name) const;

  /// `vector: name` from here on.
  void declare_vector(const SymbolName& name);
  /// `units: name [D]`.
  void declare_units(const SymbolName& name, const Dimension& dimension, std::size_t offset);
  /// `let: name = expression`: throws ReadError when the definition uses the name itself or
  /// its kind (scalar, vector) contradicts a `vector:` declaration.
  void define(const SymbolName& name, const Side& definition, std::size_t offset);

  /// @p node with each name before parentheses read: a declared function's value stays a call,
  /// anything else becomes a product. Throws ReadError where the reading is ambiguous.
  [[nodiscard]] Node resolved(const Node& node) const;
  /// The meaning of a tree under the declarations so far (definitions are not substituted:
  /// `substitutions()` does that when a step is decided).
  [[nodiscard]] Meaning meaning(const Node& node);
  /// The dimension of a tree, when the units of its symbols are known; an issue when its terms
  /// disagree.
  struct DimensionResult {
    std::optional<Dimension> dimension;
    std::optional<DimensionIssue> issue;
    /// The dimensions of the arguments of the side's logarithms of quantities (ln X where X has
    /// one), with their signs and coefficients: the equation's two sides must leave the same.
    Dimension logarithms;
    std::optional<std::size_t> logarithm_at;  ///< the argument of the first such logarithm
  };
  [[nodiscard]] DimensionResult dimension(const Node& node);
  /// Whether any units were declared.
  [[nodiscard]] bool has_units() const { return !units_.empty(); }

  /// The definitions in force, as substitutions of GiNaC symbols (fully substituted: a
  /// definition that uses an earlier one carries its value).
  [[nodiscard]] const GiNaC::exmap& substitutions() const { return substitutions_; }
  /// Puts back definitions saved with substitutions() (a check's own let: ends with it).
  void restore_substitutions(GiNaC::exmap saved) { substitutions_ = std::move(saved); }
  /// What a GiNaC symbol of this file stands for.
  [[nodiscard]] const SymbolInfo* info(const GiNaC::ex& symbol) const;
  /// The GiNaC symbol a scalar name stands for (a component of a vector when it is one), or 0
  /// when the name is a vector.
  [[nodiscard]] GiNaC::ex scalar_of(const SymbolName& name) {
    const Value v = symbol_value(name);
    return v.vector ? GiNaC::ex(0) : v.x;
  }
  /// What a name stands for: a scalar symbol, or the two of a vector (made on first use).
  [[nodiscard]] Value value_of(const SymbolName& name) { return symbol_value(name); }
  /// Whether a name is declared a differential's (`differentials:`).
  [[nodiscard]] bool is_differential(const SymbolName& name) const { return name.differential; }
  /// The GiNaC symbol of a scalar name (made on first use).
  [[nodiscard]] GiNaC::ex scalar(const SymbolName& name, std::optional<SymbolName> of = {},
                                 int component = 0);

 private:
  friend class Evaluator;
  friend class DimensionWalk;
  friend class CallResolver;
  bool is_vector(const SymbolName& name) const;
  std::optional<std::pair<SymbolName, int>> component_of(const SymbolName& name) const;
  Value symbol_value(const SymbolName& name);
  std::optional<Dimension> symbol_dimension(const SymbolName& name) const;
  ReadError error(std::size_t offset, const std::string& message) const {
    return source_.error(offset, message);
  }
  /// The node as the file writes it.
  std::string written(const Node& n) const {
    return source_.text().substr(n.offset, n.end > n.offset ? n.end - n.offset : 0);
  }

  struct Block {
    Side entry;
    std::vector<std::string> indices;  // row index, then column index (matrices)
  };
  Value block_value(const Block& block, std::size_t offset,
                    const std::function<Value(const Node&)>& eval) const;
  std::vector<std::pair<Node, char>> expanded_terms(const Node& sum);
  // The factors of a product (the operator before each: ' ', '.', 'x', '*', '/'), with a
  // differential merged into one symbol: \mathrm{d} before a scalar symbol, and d before a
  // symbol declared with `differentials:`. \mathrm{d} before a declared function, or before
  // no symbol, is refused; before a vector it stays a factor.
  std::vector<std::pair<Node, char>> factors(const Node& product) const;
  Value block_product(const Value& a, const Value& b, char op, std::size_t offset,
                      std::vector<GiNaC::ex>& denominators) const;
  std::vector<std::string> indices_in(const Node& node) const;

  const Source& source_;
  const Limits& limits_;
  std::set<std::string> arrows_;
  std::set<std::string> differentials_;
  std::vector<GiNaC::ex> forces_;
  std::map<std::string, std::vector<long>> indices_;
  std::map<std::string, Block> blocks_;       // latex key → template
  std::map<std::string, GiNaC::ex> symbols_;  // latex key → GiNaC symbol
  std::map<GiNaC::ex, SymbolInfo, GiNaC::ex_is_less> infos_;
  std::map<std::string, bool> vectors_;     // unprimed latex keys declared vectors
  std::map<std::string, Dimension> units_;  // latex key → dimension
  std::set<std::string> quantities_;        // latex keys a fact of assume: names
  std::map<std::string, std::optional<Dimension>> defined_dimensions_;
  GiNaC::exmap substitutions_;
  std::map<std::string, FunctionDeclaration> functions_;  // latex key → declaration
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> counts_;   // a sum's upper limit, its lower
  std::optional<SymbolName> integration_variable_;        // of the last integral read (for a bar)
  std::map<std::string, bool> accented_;  // scalar latex keys → first written with an accent
  std::map<std::string, std::string> letter_forms_;  // \epsilon_1 → the form first written
};

/// Reads the dimension of `units:` ("M L T^-1", "M L^{2}", "1").
[[nodiscard]] Dimension read_dimension(const Source& source, std::size_t offset,
                                       std::string_view text);

}  // namespace impulse::derivations::file
