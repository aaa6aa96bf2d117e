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

// A power with a whole exponent up to 64 is multiplied out: the same rounding on every platform.
bool whole_exponent(double exponent) {
  return exponent == std::round(exponent) && std::abs(exponent) <= 64;
}

double whole_power(double base, double exponent) {
  double r = 1.0;
  for (int k = 0; k < static_cast<int>(std::abs(exponent)); ++k) {
    r *= base;
  }
  return exponent < 0 ? 1.0 / r : r;
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
  integrand_of_.assign(ops_.size(), 0);
  for (std::size_t i = 0; i < ops_.size(); ++i) {
    if (ops_[i].kind == Op::integral) {
      integrand_of_[ops_[i].begin] = i;
    }
  }
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
    const Op& exponent = ops_[op.kids[1]];
    op.whole = exponent.kind == Op::constant && whole_exponent(exponent.value);
  } else if (GiNaC::is_a<GiNaC::integral>(e)) {
    op.kind = Op::integral;
    op.index = slots.size();
    op.kids.push_back(compile(e.op(1), slots));
    op.kids.push_back(compile(e.op(2), slots));
    slots.push_back(e.op(0));  // the variable is bound inside the integrand only
    ++depth_;
    op.begin = ops_.size();  // inside an integral nothing is shared: its integrand runs from here
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

GiNaC::ex shaped_outside_integrals(const GiNaC::ex& e, const GiNaC::exmap& shaped) {
  return sym::rewritten(e, [&shaped](const GiNaC::ex& part) -> std::optional<GiNaC::ex> {
    if (GiNaC::is_a<GiNaC::integral>(part)) {
      return part;
    }
    if (GiNaC::is_a<GiNaC::symbol>(part)) {
      const auto found = shaped.find(part);
      return found == shaped.end() ? part : found->second;
    }
    return std::nullopt;
  });
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
  // Every operation's value once (an integrand's at each node of its integral), on the stack
  // unless the program is large; the slots are the symbols' values, then the integrals'
  // variables. Each is written before it is read: nothing is initialised.
  constexpr std::size_t on_stack = 256;
  std::array<double, on_stack> small_results;  // NOLINT(cppcoreguidelines-pro-type-member-init)
  std::array<double, on_stack> small_slots;    // NOLINT(cppcoreguidelines-pro-type-member-init)
  const std::unique_ptr<double[]> large_results(ops_.size() > on_stack ? new double[ops_.size()]
                                                                       : nullptr);
  const std::unique_ptr<double[]> large_slots(slots_ > on_stack ? new double[slots_] : nullptr);
  double* results = large_results ? large_results.get() : small_results.data();
  double* slots = large_slots ? large_slots.get() : small_slots.data();
  const std::size_t given = std::min(values.size(), slots_);
  std::copy_n(values.begin(), given, slots);
  std::fill(slots + given, slots + slots_, 0.0);
  run(0, ops_.size(), slots, shape, results);
  for (std::size_t r = 0; r < roots_.size() && r < out.size(); ++r) {
    out[r] = results[roots_[r]];
  }
}

void TimedExpression::run(std::size_t begin, std::size_t end, double* slots,
                          const PulseShape* shape, double* results) const {
  std::array<double, 2> operands{};
  for (std::size_t i = begin; i < end; ++i) {
    if (i != begin && integrand_of_[i] != 0) {
      i = integrand_of_[i];  // the integrand is the integral's to run
    }
    const Op& op = ops_[i];
    switch (op.kind) {
      case Op::constant:
        results[i] = op.value;
        break;
      case Op::variable:
        results[i] = slots[op.index];
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
      case Op::integral:
        results[i] = integral(op, slots, shape, results);
        break;
      case Op::power:
        if (op.whole) {  // its exponent a constant: known whole when compiled
          results[i] = whole_power(results[op.kids[0]], ops_[op.kids[1]].value);
          break;
        }
        [[fallthrough]];
      default:
        for (std::size_t k = 0; k < op.kids.size() && k < operands.size(); ++k) {
          operands[k] = results[op.kids[k]];
        }
        results[i] = apply(op, operands.data(), shape);
        break;
    }
  }
}

double TimedExpression::integral(const Op& op, double* slots, const PulseShape* shape,
                                 double* results) const {
  const double a = results[op.kids[0]];
  const double b = results[op.kids[1]];
  // Pieces between the pulse's kinks (in t: the kinks times the duration), each by a 24-point
  // Gauss–Legendre rule: smooth pieces are integrated to rounding. (No allocation: an integral
  // inside an integral runs this at every node of the outer one.)
  std::array<double, 16> cuts{a, b};
  std::size_t count = 2;
  if (shape != nullptr && duration_slot_ < slots_) {
    const double duration = slots[duration_slot_];
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
  const std::size_t integrand = op.kids[2];
  const double saved = slots[op.index];
  double total = 0.0;
  for (std::size_t piece = 0; piece + 1 < count; ++piece) {
    const double middle = 0.5 * (cuts[piece] + cuts[piece + 1]);
    const double half = 0.5 * (cuts[piece + 1] - cuts[piece]);
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      slots[op.index] = middle + half * rule.x[k];
      run(op.begin, integrand + 1, slots, shape, results);
      total += half * rule.w[k] * results[integrand];
    }
  }
  slots[op.index] = saved;
  return b < a ? -total : total;  // the pieces run from the smaller limit up
}

double TimedExpression::apply(const Op& op, const double* operands, const PulseShape* shape) const {
  switch (op.kind) {
    case Op::power: {
      const double base = operands[0];
      const double exponent = operands[1];
      if (whole_exponent(exponent)) {
        return whole_power(base, exponent);
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

}  // namespace impulse::derivations::file
