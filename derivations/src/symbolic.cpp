// SPDX-License-Identifier: GPL-3.0-or-later
#include "symbolic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace impulse::derivations::sym {

using GiNaC::ex_to;
using GiNaC::is_a;

namespace {

// ---- printing in an order that is the same in every run ------------------------------------
// GiNaC prints a sum's terms and a product's factors in its own order, which follows hash values
// seeded by addresses: "F dt" in one run, "dt F" in the next. These printers order them by
// canonical() instead. Numbers, symbols and functions are printed by GiNaC.

enum class Style { latex, plain };

std::string ginac_text(const ex& e, Style style) {
  std::ostringstream out;
  if (style == Style::latex) {
    out << GiNaC::latex << e;
  } else {
    out << GiNaC::dflt << e;
  }
  return out.str();
}

// A term's sign and its magnitude: -3 a b is (true, 3 a b).
std::pair<bool, ex> sign_and_magnitude(const ex& term) {
  const auto negative_number = [](const ex& x) {
    return is_a<GiNaC::numeric>(x) && ex_to<GiNaC::numeric>(x).is_real() &&
           ex_to<GiNaC::numeric>(x).is_negative();
  };
  if (negative_number(term) ||
      (is_a<GiNaC::mul>(term) && negative_number(term.op(term.nops() - 1)))) {
    return {true, -term};  // a mul keeps its number last
  }
  return {false, term};
}

// Parts in the order of their canonical keys; a sum's terms by their magnitudes (so that a - b
// and -b + a are the same order).
std::vector<ex> ordered(const std::vector<ex>& parts, bool by_magnitude) {
  std::vector<std::pair<std::string, std::size_t>> keys;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto [negative, magnitude] = sign_and_magnitude(parts[i]);
    keys.emplace_back(
        by_magnitude ? canonical(magnitude) + (negative ? "-" : "+") : canonical(parts[i]), i);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<ex> out;
  for (const auto& [key, i] : keys) {
    out.push_back(parts[i]);
  }
  return out;
}

std::vector<ex> terms_of(const ex& sum) {
  std::vector<ex> terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    terms.push_back(sum.op(i));
  }
  return ordered(terms, true);
}

// Precedence of what a printed part is: a sum, a product, a power, an atom.
enum Level { sum_level = 1, product_level = 2, power_level = 3, atom_level = 4 };

// Text and whether it carries a minus sign in front (then it binds as a sum).
struct Signed {
  bool negative = false;
  std::string text;
};

Signed print_signed(const ex& e, Style style);

std::string grouped(const std::string& text, Style style) {
  return style == Style::latex ? "\\left(" + text + "\\right)" : "(" + text + ")";
}

std::string print(const ex& e, Style style, int context) {
  const Signed s = print_signed(e, style);
  int level = atom_level;
  if (s.negative || is_a<GiNaC::add>(e)) {
    level = sum_level;
  } else if (is_a<GiNaC::mul>(e) || (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1)) &&
                                     ex_to<GiNaC::numeric>(e.op(1)).is_real() &&
                                     ex_to<GiNaC::numeric>(e.op(1)).is_negative())) {
    level = product_level;
  } else if (is_a<GiNaC::power>(e)) {
    level = power_level;
  } else if (is_a<GiNaC::numeric>(e) && !ex_to<GiNaC::numeric>(e).is_integer()) {
    level = sum_level;
  }
  const std::string text = s.negative ? "-" + s.text : s.text;
  return level < context ? grouped(text, style) : text;
}

// A power as printed, from its parts: base^exponent (exponent 1: the base alone).
struct Power {
  ex base;
  ex exponent;

  // The order among a product's factors: canonical() of the power as printed.
  [[nodiscard]] std::string key() const {
    return exponent.is_equal(1) ? canonical(base)
                                : "^(" + canonical(base) + "," + canonical(exponent) + ")";
  }
  [[nodiscard]] std::string print(Style style) const {
    if (exponent.is_equal(1)) {
      return sym::print(base, style, power_level - 1);
    }
    if (style == Style::latex && exponent.is_equal(GiNaC::numeric(1, 2))) {
      return "\\sqrt{" + sym::print(base, style, 0) + "}";
    }
    const std::string b = sym::print(base, style, power_level + 1);
    const std::string p = sym::print(exponent, style, style == Style::latex ? 0 : atom_level);
    return style == Style::latex ? b + "^{" + p + "}" : b + "^" + p;
  }
};

// A factor as printed, and whether it takes a sign: a sum (or a whole power of one) whose first
// term is negative is shown negated, (a - b)^2 and not (-a + b)^2, the sign in front for an odd
// power. The power is kept in its parts, not made again: GiNaC would turn (a - b)^2 back into
// (-a + b)^2 where its own order of the terms puts b first (power::eval makes a power's sum lead
// with a positive coefficient in that order), so the same residual was printed with one sign in
// one build and the other in the next, and an odd power, turned into -1 times a power, was
// printed again without end.
std::pair<bool, Power> shown_power(const ex& factor) {
  const bool power = is_a<GiNaC::power>(factor);
  Power shown{power ? factor.op(0) : factor, power ? factor.op(1) : ex(1)};
  if (is_a<GiNaC::add>(shown.base) && is_a<GiNaC::numeric>(shown.exponent) &&
      ex_to<GiNaC::numeric>(shown.exponent).is_integer() &&
      sign_and_magnitude(terms_of(shown.base).front()).first) {
    shown.base = -shown.base;
    return {ex_to<GiNaC::numeric>(shown.exponent).is_odd(), shown};
  }
  return {false, shown};
}

std::string print_sum(const ex& e, Style style) {
  std::string out;
  for (const ex& term : terms_of(e)) {
    const Signed s = print_signed(term, style);
    const std::string text = s.text;
    if (out.empty()) {
      out = s.negative ? "-" + text : text;
    } else {
      out += s.negative ? style == Style::latex ? " - " : "-" : style == Style::latex ? " + " : "+";
      out += text;
    }
  }
  return out;
}

// A product's factors, each sum among them with its first term positive (a - b, not -a + b: the
// sign goes in front of the product), numbers and the denominator apart.
Signed print_product(const ex& e, Style style) {
  GiNaC::numeric coefficient = 1;
  std::vector<Power> above;
  std::vector<Power> below;
  const auto take = [&](ex factor) {
    if (is_a<GiNaC::numeric>(factor)) {
      coefficient *= ex_to<GiNaC::numeric>(factor);
      return;
    }
    bool down = false;
    if (is_a<GiNaC::power>(factor) && is_a<GiNaC::numeric>(factor.op(1)) &&
        ex_to<GiNaC::numeric>(factor.op(1)).is_real() &&
        ex_to<GiNaC::numeric>(factor.op(1)).is_negative()) {
      factor = GiNaC::pow(factor.op(0), -factor.op(1));
      down = true;
    }
    const auto [negative, shown] = shown_power(factor);
    if (negative) {
      coefficient = -coefficient;
    }
    (down ? below : above).push_back(shown);
  };
  for_each_factor(e, take);
  Signed out;
  if (coefficient.is_real() && coefficient.is_negative()) {
    out.negative = true;
    coefficient = -coefficient;
  }
  const std::string separator = style == Style::latex ? " " : "*";
  const auto join = [&](const std::vector<Power>& factors, const GiNaC::numeric& number) {
    std::string text;
    if (!number.is_equal(1) || factors.empty()) {
      text = ginac_text(number, style);
    }
    std::vector<std::pair<std::string, std::size_t>> keys;
    for (std::size_t i = 0; i < factors.size(); ++i) {
      keys.emplace_back(factors[i].key(), i);
    }
    std::sort(keys.begin(), keys.end());
    for (const auto& [key, i] : keys) {
      text += (text.empty() ? "" : separator) + factors[i].print(style);
    }
    return text;
  };
  if (!coefficient.is_rational()) {  // a floating-point or complex coefficient: GiNaC's digits
    out.text =
        join(above, coefficient) + (below.empty() ? "" : "/" + grouped(join(below, 1), style));
    return out;
  }
  const std::string top = join(above, coefficient.numer());
  if (below.empty() && coefficient.denom().is_equal(1)) {
    out.text = top;
    return out;
  }
  const std::string bottom = join(below, coefficient.denom());
  if (style == Style::latex) {
    // A part that is one sum alone needs no parentheses inside \frac{…}{…}.
    const auto part = [&](const std::vector<Power>& factors, const GiNaC::numeric& number,
                          const std::string& joined) {
      return factors.size() == 1 && number.is_equal(1) && factors[0].exponent.is_equal(1)
                 ? print(factors[0].base, style, 0)
                 : joined;
    };
    out.text = "\\frac{" + part(above, coefficient.numer(), top) + "}{" +
               part(below, coefficient.denom(), bottom) + "}";
    return out;
  }
  const bool several_above = above.size() + (coefficient.numer().is_equal(1) ? 0U : 1U) > 1;
  const bool several_below = below.size() + (coefficient.denom().is_equal(1) ? 0U : 1U) > 1;
  out.text =
      (several_above ? "(" + top + ")" : top) + "/" + (several_below ? "(" + bottom + ")" : bottom);
  return out;
}

Signed print_signed(const ex& e, Style style) {
  if (is_a<GiNaC::add>(e)) {
    return {false, print_sum(e, style)};
  }
  if (is_a<GiNaC::mul>(e) ||
      (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1)) &&
       ex_to<GiNaC::numeric>(e.op(1)).is_real() && ex_to<GiNaC::numeric>(e.op(1)).is_negative())) {
    return print_product(e, style);
  }
  if (is_a<GiNaC::power>(e)) {
    const auto [negative, shown] = shown_power(e);
    return {negative, shown.print(style)};
  }
  if (is_a<GiNaC::function>(e)) {
    // GiNaC prints the function's name; its arguments, printed here, stand in as symbols (an
    // absolute value's with one sign: |a + b|, not |-a - b| as GiNaC's order of terms may give).
    const bool absolute = ex_to<GiNaC::function>(e).get_name() == "abs";
    GiNaC::exvector arguments;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex argument = absolute ? up_to_sign(e.op(i)) : e.op(i);
      arguments.push_back(
          GiNaC::symbol(print(argument, Style::plain, 0), print(argument, Style::latex, 0)));
    }
    return {false,
            ginac_text(GiNaC::function(ex_to<GiNaC::function>(e).get_serial(), arguments), style)};
  }
  if (is_a<GiNaC::numeric>(e) && ex_to<GiNaC::numeric>(e).is_real() &&
      ex_to<GiNaC::numeric>(e).is_negative()) {
    return {true, ginac_text(-e, style)};
  }
  return {false, ginac_text(e, style)};
}

}  // namespace

std::string latex(const ex& e) {
  return print(e, Style::latex, 0);
}

std::string plain(const ex& e) {
  return print(e, Style::plain, 0);
}

ex up_to_sign(const ex& e) {
  if (is_a<GiNaC::add>(e)) {
    return sign_and_magnitude(terms_of(e).front()).first ? ex(-e) : e;
  }
  return print_signed(e, Style::latex).negative ? ex(-e) : e;
}

double Compiled::operator()(std::span<const double> arguments) const {
  if (arguments.size() != arguments_) {
    throw std::invalid_argument("compiled expression takes " + std::to_string(arguments_) +
                                " arguments, got " + std::to_string(arguments.size()));
  }
  double* stack = stack_.data();
  std::size_t top = 0;
  for (const Instruction& in : program_) {
    switch (in.op) {
      case Op::constant:
        stack[top++] = in.value;
        break;
      case Op::variable:
        stack[top++] = arguments[in.index];
        break;
      case Op::add: {
        double sum = 0.0;
        for (std::size_t k = 0; k < in.index; ++k) {
          sum += stack[--top];
        }
        stack[top++] = sum;
        break;
      }
      case Op::mul: {
        double product = 1.0;
        for (std::size_t k = 0; k < in.index; ++k) {
          product *= stack[--top];
        }
        stack[top++] = product;
        break;
      }
      case Op::power: {
        const double base = stack[--top];
        const double exponent = in.value;
        stack[top++] = exponent == 2.0    ? base * base
                       : exponent == -1.0 ? 1.0 / base
                                          : std::pow(base, exponent);
        break;
      }
      case Op::raise: {
        const double exponent = stack[--top];
        const double base = stack[--top];
        stack[top++] = std::pow(base, exponent);
        break;
      }
      case Op::function: {
        const double x = stack[top - 1];
        switch (static_cast<Function>(in.index)) {
          case Function::sin:
            stack[top - 1] = std::sin(x);
            break;
          case Function::cos:
            stack[top - 1] = std::cos(x);
            break;
          case Function::tan:
            stack[top - 1] = std::tan(x);
            break;
          case Function::exp:
            stack[top - 1] = std::exp(x);
            break;
          case Function::log:
            stack[top - 1] = std::log(x);
            break;
          case Function::abs:
            stack[top - 1] = std::abs(x);
            break;
          case Function::asin:
            stack[top - 1] = std::asin(x);
            break;
          case Function::acos:
            stack[top - 1] = std::acos(x);
            break;
          case Function::atan:
            stack[top - 1] = std::atan(x);
            break;
          case Function::sinh:
            stack[top - 1] = std::sinh(x);
            break;
          case Function::cosh:
            stack[top - 1] = std::cosh(x);
            break;
          case Function::tanh:
            stack[top - 1] = std::tanh(x);
            break;
        }
        break;
      }
    }
  }
  return stack[top - 1];
}

namespace {

// How deeply an expression nests (the recursion of emit() goes as deep).
std::size_t depth(const ex& e) {
  std::size_t deepest = 0;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    deepest = std::max(deepest, depth(e.op(i)));
  }
  return deepest + 1;
}

// The canonical forms of the operands are made once per compiled expression (@p made), not again
// at each level the recursion descends.
void emit(const ex& e, const std::vector<ex>& symbols, std::vector<Compiled::Instruction>& program,
          CanonicalForms& made) {
  using Op = Compiled::Op;
  if (is_a<GiNaC::numeric>(e)) {
    program.push_back({Op::constant, GiNaC::ex_to<GiNaC::numeric>(e).to_double(), 0});
    return;
  }
  if (is_a<GiNaC::symbol>(e)) {
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      if (symbols[i].is_equal(e)) {
        program.push_back({Op::variable, 0.0, i});
        return;
      }
    }
    throw std::invalid_argument("compile: unbound symbol " + latex(e));
  }
  if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
    std::vector<std::pair<std::string, ex>> operands;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      operands.emplace_back(canonical(e.op(i), made), e.op(i));
    }
    std::sort(operands.begin(), operands.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& operand : operands) {
      emit(operand.second, symbols, program, made);
    }
    program.push_back({is_a<GiNaC::add>(e) ? Op::add : Op::mul, 0.0, e.nops()});
    return;
  }
  if (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1))) {
    emit(e.op(0), symbols, program, made);
    program.push_back({Op::power, GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double(), 0});
    return;
  }
  if (is_a<GiNaC::power>(e)) {
    emit(e.op(0), symbols, program, made);
    emit(e.op(1), symbols, program, made);
    program.push_back({Op::raise, 0.0, 0});
    return;
  }
  if (is_a<GiNaC::constant>(e)) {
    program.push_back({Op::constant, GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(), 0});
    return;
  }
  if (is_a<GiNaC::function>(e) && e.nops() == 1) {
    using F = Compiled::Function;
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const std::pair<const char*, F> known[] = {
        {"sin", F::sin},   {"cos", F::cos},   {"tan", F::tan},   {"exp", F::exp},
        {"log", F::log},   {"abs", F::abs},   {"asin", F::asin}, {"acos", F::acos},
        {"atan", F::atan}, {"sinh", F::sinh}, {"cosh", F::cosh}, {"tanh", F::tanh}};
    for (const auto& [n, f] : known) {
      if (name == n) {
        emit(e.op(0), symbols, program, made);
        program.push_back({Op::function, 0.0, static_cast<std::size_t>(f)});
        return;
      }
    }
  }
  throw std::invalid_argument("compile: unsupported expression " + latex(e));
}

}  // namespace

// A key that orders an expression's operands the same way in every run. GiNaC orders the
// terms of a sum by hash values that may differ between processes; floating-point sums in
// different orders differ in their last bits, and a report must not change with the run.
std::string canonical(const ex& e) {
  CanonicalForms made;
  return canonical(e, made);
}

std::string canonical(const ex& e, CanonicalForms& made) {
  if (const auto found = made.find(e); found != made.end()) {
    return found->second;
  }
  std::string key;
  if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      parts.push_back(canonical(e.op(i), made));
    }
    std::sort(parts.begin(), parts.end());
    key = is_a<GiNaC::add>(e) ? "+(" : "*(";
    for (const auto& part : parts) {
      key += part + ",";
    }
    key += ")";
  } else if (is_a<GiNaC::power>(e)) {
    key = "^(" + canonical(e.op(0), made) + "," + canonical(e.op(1), made) + ")";
  } else if (is_a<GiNaC::function>(e)) {  // its arguments in their own canonical form
    key = ex_to<GiNaC::function>(e).get_name() + "(";
    for (std::size_t i = 0; i < e.nops(); ++i) {
      key += canonical(e.op(i), made) + ",";
    }
    key += ")";
  } else if (is_a<GiNaC::symbol>(e)) {  // its name, as GiNaC prints it
    key = ex_to<GiNaC::symbol>(e).get_name();
  } else {
    std::ostringstream out;
    out << e;
    key = out.str();
  }
  made.emplace(e, key);
  return key;
}

Compiled compile(const ex& e, const std::vector<ex>& symbols) {
  if (depth(e) > 2000) {
    throw std::invalid_argument("compile: expression too deep");
  }
  Compiled compiled;
  compiled.arguments_ = symbols.size();
  CanonicalForms made;
  emit(e, symbols, compiled.program_, made);
  // The deepest the stack goes, found by running the program's stack effects.
  std::size_t top = 0;
  std::size_t deepest = 0;
  for (const Compiled::Instruction& in : compiled.program_) {
    switch (in.op) {
      case Compiled::Op::constant:
      case Compiled::Op::variable:
        ++top;
        break;
      case Compiled::Op::add:
      case Compiled::Op::mul:
        top = top - in.index + 1;
        break;
      case Compiled::Op::raise:
        --top;
        break;
      case Compiled::Op::power:
      case Compiled::Op::function:
        break;
    }
    deepest = std::max(deepest, top);
  }
  compiled.stack_.assign(deepest + 1, 0.0);
  return compiled;
}

bool is_function(const ex& e, const char* name) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name;
}

bool is_even_root(const ex& e) {
  return GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
         !e.op(1).info(GiNaC::info_flags::integer) &&
         GiNaC::ex_to<GiNaC::numeric>(e.op(1)).denom().is_even();
}

std::optional<std::pair<ex, ex>> linear_in(const ex& e, const ex& p) {
  const ex expanded = GiNaC::expand(e);
  if (!expanded.is_polynomial(p) || expanded.degree(p) != 1) {
    return std::nullopt;
  }
  const ex k = expanded.coeff(p, 1);
  const ex m = GiNaC::expand(expanded - k * p);
  if (k.has(p) || m.has(p)) {
    return std::nullopt;
  }
  return std::pair{k, m};
}

ex map_parts(const ex& e, const std::function<ex(const ex&)>& f) {
  struct Mapper : GiNaC::map_function {
    const std::function<ex(const ex&)>& f;
    explicit Mapper(const std::function<ex(const ex&)>& g) : f(g) {}
    ex operator()(const ex& x) override { return f(x); }
  };
  Mapper m(f);
  return e.map(m);
}

ex rewritten(const ex& e, const std::function<std::optional<ex>(const ex&)>& f) {
  if (const auto replaced = f(e)) {
    return *replaced;
  }
  return map_parts(e, [&f](const ex& part) { return rewritten(part, f); });
}

}  // namespace impulse::derivations::sym
