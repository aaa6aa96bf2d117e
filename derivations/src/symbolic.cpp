// SPDX-License-Identifier: GPL-3.0-or-later
#include "symbolic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace impulse::derivations::sym {

using GiNaC::is_a;

ex simplify(const ex& e) {
  return GiNaC::normal(GiNaC::expand(e));
}

bool holds(const Equation& equation) {
  return simplify(equation.difference()).is_zero();
}

namespace {

bool declared_nonzero(const ex& e, const Assumptions& assumptions) {
  for (const ex& s : assumptions.nonzero) {
    if (s.is_equal(e)) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool definitely_positive(const ex& e, const Assumptions& assumptions) {
  if (is_a<GiNaC::numeric>(e)) {
    return GiNaC::ex_to<GiNaC::numeric>(e).is_positive();
  }
  if (is_a<GiNaC::symbol>(e)) {
    return e.info(GiNaC::info_flags::positive);
  }
  if (is_a<GiNaC::power>(e)) {
    const ex base = e.op(0);
    const ex exponent = e.op(1);
    if (exponent.info(GiNaC::info_flags::even) && base.info(GiNaC::info_flags::real)) {
      return definitely_nonzero(base, assumptions);
    }
    return definitely_positive(base, assumptions);
  }
  if (is_a<GiNaC::mul>(e) || is_a<GiNaC::add>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (!definitely_positive(e.op(i), assumptions)) {
        return false;
      }
    }
    return e.nops() > 0;
  }
  return false;
}

bool definitely_nonzero(const ex& e, const Assumptions& assumptions) {
  if (is_a<GiNaC::numeric>(e)) {
    return !e.is_zero();
  }
  if (is_a<GiNaC::symbol>(e)) {
    return e.info(GiNaC::info_flags::positive) || declared_nonzero(e, assumptions);
  }
  if (is_a<GiNaC::power>(e)) {
    return definitely_nonzero(e.op(0), assumptions);
  }
  if (is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (!definitely_nonzero(e.op(i), assumptions)) {
        return false;
      }
    }
    return true;
  }
  if (is_a<GiNaC::add>(e)) {
    // A sum is non-zero here when all its terms are positive, or all negative.
    return definitely_positive(e, assumptions) || definitely_positive(-e, assumptions) ||
           definitely_positive(GiNaC::expand(-e), assumptions);
  }
  return false;
}

std::optional<ex> nonzero_multiple(const Equation& step, const Equation& previous,
                                   const Assumptions& assumptions) {
  const ex previous_difference = simplify(previous.difference());
  const ex step_difference = simplify(step.difference());
  if (previous_difference.is_zero()) {
    return step_difference.is_zero() ? std::optional<ex>(1) : std::nullopt;
  }
  if (step_difference.is_zero()) {
    return std::nullopt;
  }
  const ex ratio = GiNaC::normal(step_difference / previous_difference);
  const ex parts = GiNaC::numer_denom(ratio);
  const ex numerator = GiNaC::factor(parts.op(0));
  const ex denominator = GiNaC::factor(parts.op(1));
  if (definitely_nonzero(numerator, assumptions) && definitely_nonzero(denominator, assumptions)) {
    return ratio;
  }
  return std::nullopt;
}

ex solve_for(const Equation& equation, const ex& unknown) {
  return GiNaC::lsolve(equation.lhs == equation.rhs, unknown);
}

std::string latex(const ex& e) {
  std::ostringstream out;
  out << GiNaC::latex << e;
  return out.str();
}

std::string latex(const Equation& equation) {
  return latex(equation.lhs) + " = " + latex(equation.rhs);
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

void emit(const ex& e, const std::vector<ex>& symbols,
          std::vector<Compiled::Instruction>& program) {
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
      operands.emplace_back(canonical(e.op(i)), e.op(i));
    }
    std::sort(operands.begin(), operands.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& operand : operands) {
      emit(operand.second, symbols, program);
    }
    program.push_back({is_a<GiNaC::add>(e) ? Op::add : Op::mul, 0.0, e.nops()});
    return;
  }
  if (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1))) {
    emit(e.op(0), symbols, program);
    program.push_back({Op::power, GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double(), 0});
    return;
  }
  if (is_a<GiNaC::power>(e)) {
    emit(e.op(0), symbols, program);
    emit(e.op(1), symbols, program);
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
    const std::pair<const char*, F> known[] = {{"sin", F::sin}, {"cos", F::cos}, {"tan", F::tan},
                                               {"exp", F::exp}, {"log", F::log}, {"abs", F::abs}};
    for (const auto& [n, f] : known) {
      if (name == n) {
        emit(e.op(0), symbols, program);
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
  if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      parts.push_back(canonical(e.op(i)));
    }
    std::sort(parts.begin(), parts.end());
    std::string key = is_a<GiNaC::add>(e) ? "+(" : "*(";
    for (const auto& part : parts) {
      key += part + ",";
    }
    return key + ")";
  }
  if (is_a<GiNaC::power>(e)) {
    return "^(" + canonical(e.op(0)) + "," + canonical(e.op(1)) + ")";
  }
  std::ostringstream out;
  out << e;
  return out.str();
}

Compiled compile(const ex& e, const std::vector<ex>& symbols) {
  if (depth(e) > 2000) {
    throw std::invalid_argument("compile: expression too deep");
  }
  Compiled compiled;
  compiled.arguments_ = symbols.size();
  emit(e, symbols, compiled.program_);
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

}  // namespace impulse::derivations::sym
