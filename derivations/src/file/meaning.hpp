// SPDX-License-Identifier: GPL-3.0-or-later
// What the trees of a derivation file mean: each symbol a real number or a vector of the plane
// (`vector:`), each expression a GiNaC expression or a pair of them, each `let:` a substitution
// in force from its line on, each `units:` a dimension. Type errors (a vector added to a scalar,
// \det of scalars) are ReadErrors with their place; dimension mismatches are findings.
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "file/latex.hpp"
#include "file/text.hpp"

namespace impulse::derivations::file {

/// A scalar, or a vector of the plane [x, y].
struct Value {
  bool vector = false;
  GiNaC::ex x;  ///< the scalar, or the x component
  GiNaC::ex y;  ///< the y component of a vector
};

/// An expression's value and the denominators written in it (each one must not be zero where
/// the expression is read: the conditions a division brings).
struct Meaning {
  Value value;
  std::vector<GiNaC::ex> denominators;
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

/// The symbols, vectors, definitions and units of one file, as its lines declare them.
class Symbols {
 public:
  Symbols(const Source& source, const Limits& limits) : source_(source), limits_(limits) {}

  /// `vector: name` from here on.
  void declare_vector(const SymbolName& name);
  /// `units: name [D]`.
  void declare_units(const SymbolName& name, const Dimension& dimension, std::size_t offset);
  /// `let: name = expression`: throws ReadError when the definition uses the name itself or
  /// its kind (scalar, vector) contradicts a `vector:` declaration.
  void define(const SymbolName& name, const Side& definition, std::size_t offset);

  /// The meaning of a tree under the declarations so far (definitions are not substituted:
  /// `substitutions()` does that when a step is decided).
  [[nodiscard]] Meaning meaning(const Node& node);
  /// The dimension of a tree, when the units of its symbols are known; an issue when its terms
  /// disagree.
  struct DimensionResult {
    std::optional<Dimension> dimension;
    std::optional<DimensionIssue> issue;
  };
  [[nodiscard]] DimensionResult dimension(const Node& node);
  /// Whether any units were declared.
  [[nodiscard]] bool has_units() const { return !units_.empty(); }

  /// The definitions in force, as substitutions of GiNaC symbols (fully substituted: a
  /// definition that uses an earlier one carries its value).
  [[nodiscard]] const GiNaC::exmap& substitutions() const { return substitutions_; }
  /// What a GiNaC symbol of this file stands for.
  [[nodiscard]] const SymbolInfo* info(const GiNaC::ex& symbol) const;
  /// The GiNaC symbol a scalar name stands for (a component of a vector when it is one), or 0
  /// when the name is a vector.
  [[nodiscard]] GiNaC::ex scalar_of(const SymbolName& name) {
    const Value v = symbol_value(name);
    return v.vector ? GiNaC::ex(0) : v.x;
  }
  /// The GiNaC symbol of a scalar name (made on first use).
  [[nodiscard]] GiNaC::ex scalar(const SymbolName& name, std::optional<SymbolName> of = {},
                                 int component = 0);

 private:
  bool is_vector(const SymbolName& name) const;
  std::optional<std::pair<SymbolName, int>> component_of(const SymbolName& name) const;
  Value symbol_value(const SymbolName& name);
  std::optional<Dimension> symbol_dimension(const SymbolName& name) const;
  ReadError error(std::size_t offset, const std::string& message) const {
    return source_.error(offset, message);
  }

  const Source& source_;
  const Limits& limits_;
  std::map<std::string, GiNaC::ex> symbols_;  // latex key → GiNaC symbol
  std::map<GiNaC::ex, SymbolInfo, GiNaC::ex_is_less> infos_;
  std::map<std::string, bool> vectors_;     // unprimed latex keys declared vectors
  std::map<std::string, Dimension> units_;  // latex key → dimension
  std::map<std::string, std::optional<Dimension>> defined_dimensions_;
  GiNaC::exmap substitutions_;
};

/// Reads the dimension of `units:` ("M L T^-1", "M L^{2}", "1").
[[nodiscard]] Dimension read_dimension(const Source& source, std::size_t offset,
                                       std::string_view text);

}  // namespace impulse::derivations::file
