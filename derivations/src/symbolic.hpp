// SPDX-License-Identifier: GPL-3.0-or-later
// Printers of GiNaC expressions that give the same text in every run, and a compiler from an
// expression to a fast double function so that the numeric methods evaluate the very expression
// the exact ones read.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace impulse::derivations::sym {

using GiNaC::ex;

/// LaTeX of an expression, the terms of sums and the factors of products in the
/// order of canonical() (the same in every run; GiNaC's own order is not).
[[nodiscard]] std::string latex(const ex& e);
/// The same as plain text: "2*p_1/m_1-F*dt".
[[nodiscard]] std::string plain(const ex& e);
/// @p e or -e, whichever these printers show without a minus sign in front (for a condition
/// e != 0, whose sign does not matter: "v_2' - v_2", never "-v_2' + v_2" in one run and the other
/// in the next).
[[nodiscard]] ex up_to_sign(const ex& e);

/// An expression compiled to a function of doubles: sums, products, powers and numbers only.
class Compiled {
 public:
  Compiled() = default;
  /// The value at the given arguments (one per symbol, in the order given to compile()).
  [[nodiscard]] double operator()(std::span<const double> arguments) const;
  [[nodiscard]] double operator()(std::initializer_list<double> arguments) const {
    return (*this)(std::span<const double>(arguments.begin(), arguments.size()));
  }

  /// A stack machine: operands are pushed, operations pop theirs and push the result.
  enum class Op { constant, variable, add, mul, power, raise, function };
  /// The functions a compiled expression may call.
  enum class Function { sin, cos, tan, exp, log, abs, asin, acos, atan, sinh, cosh, tanh };
  struct Instruction {
    Op op;
    double value;       // constant, or the exponent of power
    std::size_t index;  // variable index, the operand count of add / mul, or the Function
  };

 private:
  friend Compiled compile(const ex& e, const std::vector<ex>& symbols);
  std::vector<Instruction> program_;
  std::size_t arguments_ = 0;
  mutable std::vector<double> stack_;  // sized by compile() to the deepest the program goes
};

/// A key that orders an expression's operands the same way in every run (GiNaC's own order of a
/// sum's terms follows hash values that differ between processes): compile in this order.
[[nodiscard]] std::string canonical(const ex& e);

/// The canonical forms already made, by expression: for a caller that asks for those of the
/// parts of one expression after those of its whole.
using CanonicalForms = std::map<ex, std::string, GiNaC::ex_is_less>;

/// canonical(), its parts' forms taken from @p made and the new ones kept there.
[[nodiscard]] std::string canonical(const ex& e, CanonicalForms& made);

/// GiNaC's map with a function: @p e with each of its operands replaced by @p f of it.
[[nodiscard]] ex map_parts(const ex& e, const std::function<ex(const ex&)>& f);

/// @p e rewritten from the top down: where @p f gives an expression for a part (@p e itself
/// first), the part is replaced by it and not looked into; elsewhere its operands are rewritten.
[[nodiscard]] ex rewritten(const ex& e, const std::function<std::optional<ex>(const ex&)>& f);

/// Whether @p e is a call of the GiNaC function named @p name ("log", "exp", "abs", "sin", ...).
[[nodiscard]] bool is_function(const ex& e, const char* name);

/// Whether @p e is an even root, x^(p/q) with q even (√x, x^(3/2), x^(1/4)): real only where x is
/// not negative.
[[nodiscard]] bool is_even_root(const ex& e);

/// k and m where @p e = k p + m, linear in the part p (a symbol, or any expression taken as one:
/// e^x, √x, |x|) and neither k nor m holding p; else nothing. k is not 0.
[[nodiscard]] std::optional<std::pair<ex, ex>> linear_in(const ex& e, const ex& p);

/// The part of @p e that @p is says yes to, where every such part is the same one (√x twice is
/// one root); nothing where there is none or two differ.
template <typename Is>
std::optional<ex> only_part(const ex& e, Is&& is) {
  std::optional<ex> found;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is(*it)) {
      if (found && !found->is_equal(*it)) {
        return std::nullopt;
      }
      found = *it;
    }
  }
  return found;
}

/// Calls @p each with every factor of @p e when it is a product, else with @p e itself.
/// @param e an expression
/// @param each what to do with a factor
template <typename Each>
void for_each_factor(const ex& e, Each&& each) {
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      each(e.op(i));
    }
  } else {
    each(e);
  }
}

/// Calls @p each with every term of @p e when it is a sum, else with @p e itself.
/// @param e an expression
/// @param each what to do with a term
template <typename Each>
void for_each_term(const ex& e, Each&& each) {
  if (GiNaC::is_a<GiNaC::add>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      each(e.op(i));
    }
  } else {
    each(e);
  }
}

/// What a costly function of an expression gave, remembered by expression (structurally equal
/// expressions are one entry) for a caller that asks again: bounded, emptied when full.
template <typename Value>
class Remembered {
 public:
  /// The value kept for @p e, or null.
  [[nodiscard]] const Value* find(const ex& e) const {
    const auto found = table_.find(e);
    return found == table_.end() ? nullptr : &found->second;
  }
  /// Keeps @p value for @p e (in place of one kept before) and returns it.
  const Value& keep(const ex& e, Value value) {
    if (table_.size() >= bound) {
      table_.clear();
    }
    return table_.insert_or_assign(e, std::move(value)).first->second;
  }

 private:
  static constexpr std::size_t bound = 4096;
  std::map<ex, Value, GiNaC::ex_is_less> table_;
};

/// Compiles @p e; throws std::invalid_argument on anything but numbers, π, the given symbols,
/// sums, products, powers and the functions sin, cos, tan, exp, log, abs, their inverses and
/// the hyperbolic sin, cos and tan.
[[nodiscard]] Compiled compile(const ex& e, const std::vector<ex>& symbols);

}  // namespace impulse::derivations::sym
