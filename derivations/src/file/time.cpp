// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/time.hpp"

#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "file/calculus.hpp"
#include "symbolic.hpp"

namespace impulse::derivations::file {

namespace {
void pulse_latex(const GiNaC::ex& u, const GiNaC::print_context& c) {
  c.s << "\\phi(" << u << ")";
}
}  // namespace

REGISTER_FUNCTION(contact_pulse, print_func<GiNaC::print_latex>(pulse_latex))

const GiNaC::symbol& pulse_duration() {
  static const GiNaC::symbol tau("contact duration", "\\tau_c");
  return tau;
}

bool timed(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::integral>(e)) {
    return true;
  }
  if (GiNaC::is_a<GiNaC::function>(e) &&
      GiNaC::ex_to<GiNaC::function>(e).get_serial() == contact_pulse_SERIAL::serial) {
    return true;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (timed(e.op(i))) {
      return true;
    }
  }
  return false;
}

GiNaC::ex exact_reading(const GiNaC::ex& e) {
  if (!timed(e)) {
    return e;
  }
  if (GiNaC::is_a<GiNaC::function>(e) &&
      GiNaC::ex_to<GiNaC::function>(e).get_serial() == contact_pulse_SERIAL::serial) {
    return 1;
  }
  if (GiNaC::is_a<GiNaC::integral>(e)) {
    // Done where a formula is known (calculus.hpp); otherwise left as an integral.
    return integrate(exact_reading(e.op(3)), e.op(0), exact_reading(e.op(1)),
                     exact_reading(e.op(2)));
  }
  return e.map([](const GiNaC::ex& part) { return exact_reading(part); });
}

// ---- the quadrature reading ------------------------------------------------------------------

namespace {

const gsl_integration_glfixed_table& legendre() {
  static const std::unique_ptr<gsl_integration_glfixed_table,
                               void (*)(gsl_integration_glfixed_table*)>
      table(gsl_integration_glfixed_table_alloc(24), gsl_integration_glfixed_table_free);
  return *table;
}

// The 24-point Gauss–Legendre rule on [-1, 1], its nodes and weights taken from GSL once.
struct Legendre {
  std::array<double, 24> x{};
  std::array<double, 24> w{};
};

const Legendre& legendre_on_unit() {
  static const Legendre rule = [] {
    Legendre r;
    for (std::size_t k = 0; k < r.x.size(); ++k) {
      gsl_integration_glfixed_point(-1.0, 1.0, k, &r.x[k], &r.w[k], &legendre());
    }
    return r;
  }();
  return rule;
}

}  // namespace

TimedExpression::TimedExpression(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols)
    : TimedExpression(std::vector<GiNaC::ex>{e}, symbols) {}

TimedExpression::TimedExpression(const std::vector<GiNaC::ex>& expressions,
                                 const std::vector<GiNaC::ex>& symbols) {
  std::vector<GiNaC::ex> slots = symbols;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (symbols[i].is_equal(pulse_duration())) {
      duration_slot_ = i;
    }
  }
  for (const GiNaC::ex& e : expressions) {
    roots_.push_back(compile(e, slots));
  }
  slots_ = slots.size();
  outside_.clear();
  canonical_.clear();
}

std::size_t TimedExpression::compile(const GiNaC::ex& e, std::vector<GiNaC::ex>& slots) {
  // Outside integrals an expression means the same wherever it stands (inside one, a symbol may
  // be the integral's variable): compiled once.
  if (depth_ == 0) {
    if (const auto found = outside_.find(e); found != outside_.end()) {
      return found->second;
    }
  }
  Op op;
  op.outside = depth_ == 0;
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_real()) {
      throw std::invalid_argument("a complex number");
    }
    op.kind = Op::constant;
    op.value = n.to_double();
  } else if (GiNaC::is_a<GiNaC::constant>(e)) {
    op.kind = Op::constant;
    op.value = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double();
  } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
    // The last slot of the symbol: an integral's variable, bound inside its integrand, hides a
    // symbol of the same name outside it.
    const auto last = std::find_if(slots.rbegin(), slots.rend(),
                                   [&](const GiNaC::ex& s) { return s.is_equal(e); });
    const auto found = last == slots.rend() ? slots.end() : std::prev(last.base());
    if (found == slots.end()) {
      throw std::invalid_argument("a symbol without a value: " +
                                  GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    }
    op.kind = Op::variable;
    op.index = static_cast<std::size_t>(found - slots.begin());
  } else if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    op.kind = GiNaC::is_a<GiNaC::add>(e) ? Op::add : Op::mul;
    std::vector<std::pair<std::string, std::size_t>> order;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      order.emplace_back(sym::canonical(e.op(i), canonical_), i);  // the same order in every run
    }
    std::sort(order.begin(), order.end());
    for (const auto& [key, i] : order) {
      op.kids.push_back(compile(e.op(i), slots));
    }
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    op.kind = Op::power;
    op.kids.push_back(compile(e.op(0), slots));
    op.kids.push_back(compile(e.op(1), slots));
  } else if (GiNaC::is_a<GiNaC::integral>(e)) {
    op.kind = Op::integral;
    integrals_ = true;
    op.index = slots.size();
    op.kids.push_back(compile(e.op(1), slots));
    op.kids.push_back(compile(e.op(2), slots));
    slots.push_back(e.op(0));  // the variable is bound inside the integrand only
    ++depth_;
    op.kids.push_back(compile(e.op(3), slots));
    --depth_;
    slots[op.index] = GiNaC::symbol();  // and its binding ends there
  } else if (GiNaC::is_a<GiNaC::function>(e)) {
    const auto& f = GiNaC::ex_to<GiNaC::function>(e);
    const unsigned serial = f.get_serial();
    if (serial == contact_pulse_SERIAL::serial) {
      op.kind = Op::pulse;
    } else {
      const std::string name = f.get_name();
      if (name == "sin") {
        op.kind = Op::sin;
      } else if (name == "cos") {
        op.kind = Op::cos;
      } else if (name == "tan") {
        op.kind = Op::tan;
      } else if (name == "exp") {
        op.kind = Op::exp;
      } else if (name == "log") {
        op.kind = Op::log;
      } else if (name == "abs") {
        op.kind = Op::abs;
      } else {
        throw std::invalid_argument("the function " + name);
      }
    }
    op.kids.push_back(compile(e.op(0), slots));
  } else {
    throw std::invalid_argument("an expression that is not a number");
  }
  ops_.push_back(std::move(op));
  if (depth_ == 0) {
    outside_.emplace(e, ops_.size() - 1);
  }
  return ops_.size() - 1;
}

namespace {

struct ShapeOutsideIntegrals : GiNaC::map_function {
  explicit ShapeOutsideIntegrals(const GiNaC::exmap& shaped) : shaped_(shaped) {}
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (GiNaC::is_a<GiNaC::integral>(e)) {
      return e;
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto found = shaped_.find(e);
      return found == shaped_.end() ? e : found->second;
    }
    return e.map(*this);
  }
  const GiNaC::exmap& shaped_;
};

}  // namespace

GiNaC::ex shaped_outside_integrals(const GiNaC::ex& e, const GiNaC::exmap& shaped) {
  ShapeOutsideIntegrals shape(shaped);
  return shape(e);
}

double TimedExpression::operator()(std::span<const double> values, const PulseShape* shape) const {
  if (roots_.size() == 1) {
    double value = 0.0;
    (*this)(values, shape, std::span<double>(&value, 1));
    return value;
  }
  std::vector<double> all(roots_.size());
  (*this)(values, shape, all);
  return all[0];
}

void TimedExpression::operator()(std::span<const double> values, const PulseShape* shape,
                                 std::span<double> out) const {
  if (!integrals_ && values.size() >= slots_) {
    sweep(values, shape, out);
    return;
  }
  std::vector<double> slots(values.begin(), values.end());
  slots.resize(slots_, 0.0);
  std::vector<double> kept(ops_.size(), 0.0);
  std::vector<bool> known(ops_.size(), false);
  for (std::size_t r = 0; r < roots_.size() && r < out.size(); ++r) {
    out[r] = eval(roots_[r], slots, shape, kept, known);
  }
}

void TimedExpression::sweep(std::span<const double> values, const PulseShape* shape,
                            std::span<double> out) const {
  constexpr std::size_t on_stack = 256;
  std::array<double, on_stack> small{};
  const std::unique_ptr<double[]> large(ops_.size() > on_stack ? new double[ops_.size()] : nullptr);
  double* results = large ? large.get() : small.data();
  std::array<double, 2> operands{};
  for (std::size_t i = 0; i < ops_.size(); ++i) {
    const Op& op = ops_[i];
    switch (op.kind) {
      case Op::constant:
        results[i] = op.value;
        break;
      case Op::variable:
        results[i] = values[op.index];
        break;
      case Op::add: {
        double sum = 0.0;
        for (const std::size_t k : op.kids) {
          sum += results[k];
        }
        results[i] = sum;
        break;
      }
      case Op::mul: {
        double product = 1.0;
        for (const std::size_t k : op.kids) {
          product *= results[k];
        }
        results[i] = product;
        break;
      }
      default:
        for (std::size_t k = 0; k < op.kids.size() && k < operands.size(); ++k) {
          operands[k] = results[op.kids[k]];
        }
        results[i] = apply(op, operands.data(), shape);
        break;
    }
  }
  for (std::size_t r = 0; r < roots_.size() && r < out.size(); ++r) {
    out[r] = results[roots_[r]];
  }
}

double TimedExpression::apply(const Op& op, const double* operands, const PulseShape* shape) const {
  switch (op.kind) {
    case Op::power: {
      const double base = operands[0];
      const double exponent = operands[1];
      if (exponent == std::round(exponent) && std::abs(exponent) <= 64) {
        double r = 1.0;
        for (int k = 0; k < static_cast<int>(std::abs(exponent)); ++k) {
          r *= base;
        }
        return exponent < 0 ? 1.0 / r : r;
      }
      return std::pow(base, exponent);
    }
    case Op::sin:
      return std::sin(operands[0]);
    case Op::cos:
      return std::cos(operands[0]);
    case Op::tan:
      return std::tan(operands[0]);
    case Op::exp:
      return std::exp(operands[0]);
    case Op::log:
      return std::log(operands[0]);
    case Op::abs:
      return std::abs(operands[0]);
    case Op::pulse: {
      const double u = operands[0];
      if (shape == nullptr) {
        return 1.0;
      }
      return u < 0.0 || u > 1.0 ? 0.0 : shape->f(u);
    }
    default:
      return std::nan("");
  }
}

double TimedExpression::eval(std::size_t index, std::span<double> values, const PulseShape* shape,
                             std::span<double> kept, std::vector<bool>& known) const {
  const Op& op = ops_[index];
  if (op.outside && op.kind != Op::constant && op.kind != Op::variable) {
    if (!known[index]) {
      kept[index] = evaluated(op, values, shape, kept, known);
      known[index] = true;
    }
    return kept[index];
  }
  return evaluated(op, values, shape, kept, known);
}

double TimedExpression::evaluated(const Op& op, std::span<double> values, const PulseShape* shape,
                                  std::span<double> kept, std::vector<bool>& known) const {
  switch (op.kind) {
    case Op::constant:
      return op.value;
    case Op::variable:
      return values[op.index];
    case Op::add: {
      double sum = 0.0;
      for (const std::size_t k : op.kids) {
        sum += eval(k, values, shape, kept, known);
      }
      return sum;
    }
    case Op::mul: {
      double product = 1.0;
      for (const std::size_t k : op.kids) {
        product *= eval(k, values, shape, kept, known);
      }
      return product;
    }
    case Op::integral: {
      const double a = eval(op.kids[0], values, shape, kept, known);
      const double b = eval(op.kids[1], values, shape, kept, known);
      // Pieces between the pulse's kinks (in t: the kinks times the duration), each by a
      // 24-point Gauss–Legendre rule: smooth pieces are integrated to rounding. (No allocation:
      // an integral inside an integral runs this at every node of the outer one.)
      std::array<double, 16> cuts{a, b};
      std::size_t count = 2;
      if (shape != nullptr && duration_slot_ < values.size()) {
        const double duration = values[duration_slot_];
        const auto cut = [&](double t) {
          if ((t - a) * (t - b) < 0 && count < cuts.size()) {
            cuts[count++] = t;
          }
        };
        for (const double kink : shape->kinks) {
          cut(kink * duration);
        }
        cut(0.0);  // the pulse starts and stops there
        cut(duration);
      }
      std::sort(cuts.begin(), cuts.begin() + static_cast<std::ptrdiff_t>(count));
      const Legendre& rule = legendre_on_unit();
      const double saved = values[op.index];
      double total = 0.0;
      for (std::size_t piece = 0; piece + 1 < count; ++piece) {
        const double middle = 0.5 * (cuts[piece] + cuts[piece + 1]);
        const double half = 0.5 * (cuts[piece + 1] - cuts[piece]);
        for (std::size_t k = 0; k < rule.x.size(); ++k) {
          values[op.index] = middle + half * rule.x[k];
          total += half * rule.w[k] * eval(op.kids[2], values, shape, kept, known);
        }
      }
      values[op.index] = saved;
      return b < a ? -total : total;  // the pieces run from the smaller limit up
    }
    default: {
      std::array<double, 2> operands{};
      for (std::size_t k = 0; k < op.kids.size() && k < operands.size(); ++k) {
        operands[k] = eval(op.kids[k], values, shape, kept, known);
      }
      return apply(op, operands.data(), shape);
    }
  }
}

}  // namespace impulse::derivations::file
