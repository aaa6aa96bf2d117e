// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/facts.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::is_a;

std::string relation_latex(const std::string& what, Sign sign) {
  switch (sign) {
    case Sign::positive:
      return what + " > 0";
    case Sign::negative:
      return what + " < 0";
    case Sign::nonnegative:
      return what + " \\geq 0";
    case Sign::nonpositive:
      return what + " \\leq 0";
    case Sign::nonzero:
      return what + " \\neq 0";
    case Sign::zero:
      return what + " = 0";
    case Sign::unknown:
      break;
  }
  return what;
}

namespace {

bool strict(Sign s) {
  return s == Sign::positive || s == Sign::negative;
}
bool at_least_zero(Sign s) {
  return s == Sign::positive || s == Sign::nonnegative || s == Sign::zero;
}
bool at_most_zero(Sign s) {
  return s == Sign::negative || s == Sign::nonpositive || s == Sign::zero;
}
// The sign of a product of two quantities of known signs.
Sign times(Sign a, Sign b) {
  if (a == Sign::zero || b == Sign::zero) {
    return Sign::zero;
  }
  if (a == Sign::unknown || b == Sign::unknown) {
    return Sign::unknown;
  }
  if (a == Sign::nonzero || b == Sign::nonzero) {
    return (a == Sign::nonzero || strict(a)) && (b == Sign::nonzero || strict(b)) ? Sign::nonzero
                                                                                  : Sign::unknown;
  }
  const bool negative = at_most_zero(a) != at_most_zero(b);
  const bool sharp = strict(a) && strict(b);
  if (negative) {
    return sharp ? Sign::negative : Sign::nonpositive;
  }
  return sharp ? Sign::positive : Sign::nonnegative;
}

// The sign of a sum of two quantities of known signs.
Sign plus(Sign a, Sign b) {
  if (a == Sign::zero) {
    return b;
  }
  if (b == Sign::zero) {
    return a;
  }
  if (at_least_zero(a) && at_least_zero(b)) {
    return a == Sign::positive || b == Sign::positive ? Sign::positive : Sign::nonnegative;
  }
  if (at_most_zero(a) && at_most_zero(b)) {
    return a == Sign::negative || b == Sign::negative ? Sign::negative : Sign::nonpositive;
  }
  return Sign::unknown;
}

}  // namespace

bool Facts::add(const ex& symbol, Sign sign) {
  const Sign old = of_symbol(symbol);
  Sign combined = sign;
  if (old != Sign::unknown && old != sign) {
    const auto pair = [&](Sign a, Sign b) {
      return (old == a && sign == b) || (old == b && sign == a);
    };
    if (pair(Sign::nonnegative, Sign::nonzero) || pair(Sign::positive, Sign::nonnegative) ||
        pair(Sign::positive, Sign::nonzero)) {
      combined = Sign::positive;
    } else if (pair(Sign::nonpositive, Sign::nonzero) || pair(Sign::negative, Sign::nonpositive) ||
               pair(Sign::negative, Sign::nonzero)) {
      combined = Sign::negative;
    } else {
      return false;  // > 0 and < 0, ≥ 0 and ≤ 0 (that would be = 0: not a form of assume:)
    }
  }
  signs_[symbol] = combined;
  return true;
}

Sign Facts::of_symbol(const ex& symbol) const {
  const auto found = signs_.find(symbol);
  return found == signs_.end() ? Sign::unknown : found->second;
}

Sign Facts::sign(const ex& e) const {
  if (is_a<GiNaC::numeric>(e)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_real()) {
      return Sign::unknown;
    }
    return n.is_zero() ? Sign::zero : n.is_positive() ? Sign::positive : Sign::negative;
  }
  if (is_a<GiNaC::constant>(e)) {  // π
    return Sign::positive;
  }
  if (is_a<GiNaC::symbol>(e)) {
    return of_symbol(e);
  }
  if (is_a<GiNaC::mul>(e)) {
    Sign s = Sign::positive;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      s = times(s, sign(e.op(i)));
      if (s == Sign::unknown) {
        return s;
      }
    }
    return s;
  }
  if (is_a<GiNaC::add>(e)) {
    Sign s = Sign::zero;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      s = plus(s, sign(e.op(i)));
      if (s == Sign::unknown) {
        return s;
      }
    }
    return s;
  }
  if (is_a<GiNaC::power>(e)) {
    const Sign base = sign(e.op(0));
    const ex exponent = e.op(1);
    if (exponent.info(GiNaC::info_flags::even)) {  // our symbols are real
      if (base == Sign::zero) {
        return Sign::zero;
      }
      return strict(base) || base == Sign::nonzero ? Sign::positive : Sign::nonnegative;
    }
    if (exponent.info(GiNaC::info_flags::integer)) {  // odd, or negative odd
      return base;
    }
    if (is_a<GiNaC::numeric>(exponent)) {  // a root of a non-negative base
      return base == Sign::positive ? Sign::positive
             : at_least_zero(base)  ? Sign::nonnegative
                                    : Sign::unknown;
    }
    return base == Sign::positive ? Sign::positive : Sign::unknown;
  }
  if (is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name == "exp") {
      return Sign::positive;
    }
    if (name == "abs") {
      const Sign inner = sign(e.op(0));
      return inner == Sign::unknown                      ? Sign::nonnegative
             : inner == Sign::zero                       ? Sign::zero
             : (strict(inner) || inner == Sign::nonzero) ? Sign::positive
                                                         : Sign::nonnegative;
    }
  }
  return Sign::unknown;
}

bool Facts::nonzero(const ex& e) const {
  const Sign s = sign(e);
  return strict(s) || s == Sign::nonzero;
}

bool Facts::satisfied(const ex& symbol, const GiNaC::numeric& value) const {
  switch (of_symbol(symbol)) {
    case Sign::positive:
      return value.is_positive();
    case Sign::negative:
      return value.is_negative();
    case Sign::nonnegative:
      return !value.is_negative();
    case Sign::nonpositive:
      return !value.is_positive();
    case Sign::nonzero:
      return !value.is_zero();
    default:
      return true;
  }
}

}  // namespace impulse::derivations::file
