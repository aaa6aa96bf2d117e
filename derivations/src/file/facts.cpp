// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/facts.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <utility>

#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::is_a;

namespace {

// A sign's relation in LaTeX and in plain text; nothing for unknown.
std::pair<const char*, const char*> relation_of(Sign sign) {
  switch (sign) {
    case Sign::positive:
      return {" > 0", " > 0"};
    case Sign::negative:
      return {" < 0", " < 0"};
    case Sign::nonnegative:
      return {" \\geq 0", " >= 0"};
    case Sign::nonpositive:
      return {" \\leq 0", " <= 0"};
    case Sign::nonzero:
      return {" \\neq 0", " != 0"};
    case Sign::zero:
      return {" = 0", " = 0"};
    case Sign::unknown:
      break;
  }
  return {"", ""};
}

}  // namespace

std::string relation_latex(const std::string& what, Sign sign) {
  return what + relation_of(sign).first;
}

std::string relation_text(const std::string& what, Sign sign) {
  return what + relation_of(sign).second;
}

bool gives(Sign known, Sign needed) {
  switch (needed) {
    case Sign::positive:
    case Sign::negative:
    case Sign::zero:
      return known == needed;
    case Sign::nonnegative:
      return known == Sign::positive || known == Sign::nonnegative || known == Sign::zero;
    case Sign::nonpositive:
      return known == Sign::negative || known == Sign::nonpositive || known == Sign::zero;
    case Sign::nonzero:
      return known == Sign::positive || known == Sign::negative || known == Sign::nonzero;
    default:
      return true;
  }
}

Sign opposite(Sign sign) {
  switch (sign) {
    case Sign::positive:
      return Sign::nonpositive;
    case Sign::nonpositive:
      return Sign::positive;
    case Sign::negative:
      return Sign::nonnegative;
    case Sign::nonnegative:
      return Sign::negative;
    default:
      return Sign::unknown;
  }
}

std::vector<ex> symbols_of(const ex& e) {
  return symbols_of(std::vector<ex>{e});
}

std::vector<ex> symbols_of(const std::vector<ex>& expressions) {
  std::set<ex, GiNaC::ex_is_less> found;
  for (const ex& e : expressions) {
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      if (is_a<GiNaC::symbol>(*i)) {
        found.insert(*i);
      }
    }
  }
  std::vector<ex> list(found.begin(), found.end());
  // A stable order: by name, so that a report does not depend on GiNaC's hashing.
  std::sort(list.begin(), list.end(), [](const ex& a, const ex& b) {
    return GiNaC::ex_to<GiNaC::symbol>(a).get_name() < GiNaC::ex_to<GiNaC::symbol>(b).get_name();
  });
  return list;
}

bool has_sign(const GiNaC::numeric& v, Sign sign) {
  return sign == Sign::positive      ? v.is_positive()
         : sign == Sign::negative    ? v.is_negative()
         : sign == Sign::nonnegative ? !v.is_negative()
         : sign == Sign::nonpositive ? !v.is_positive()
         : sign == Sign::nonzero     ? !v.is_zero()
                                     : true;
}

std::optional<DefiniteForm> definite_form(const ex& e) {
  const ex p = GiNaC::expand(e);
  const std::vector<ex> symbols = symbols_of(p);
  if (!is_a<GiNaC::add>(p) || symbols.size() != 2) {
    return std::nullopt;
  }
  const ex& x = symbols[0];
  const ex& y = symbols[1];
  if (!p.is_polynomial(x) || !p.is_polynomial(y)) {
    return std::nullopt;
  }
  const ex a = p.coeff(x, 2).coeff(y, 0);
  const ex b = p.coeff(x, 1).coeff(y, 1);
  const ex c = p.coeff(x, 0).coeff(y, 2);
  if (!is_a<GiNaC::numeric>(a) || !is_a<GiNaC::numeric>(b) || !is_a<GiNaC::numeric>(c) ||
      !GiNaC::expand(p - a * x * x - b * x * y - c * y * y).is_zero() ||
      !GiNaC::ex_to<GiNaC::numeric>(b * b - 4 * a * c).is_negative()) {
    return std::nullopt;
  }
  return DefiniteForm{x, y, GiNaC::ex_to<GiNaC::numeric>(a).is_positive()};
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
Sign flipped(Sign s) {
  switch (s) {
    case Sign::positive:
      return Sign::negative;
    case Sign::negative:
      return Sign::positive;
    case Sign::nonnegative:
      return Sign::nonpositive;
    case Sign::nonpositive:
      return Sign::nonnegative;
    default:
      return s;
  }
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

// ---- ranges ------------------------------------------------------------------------------------

constexpr double infinity = std::numeric_limits<double>::infinity();

// [low, high], each end open or closed. An end computed exactly (a sum or product of doubles
// that needed no rounding, 0, a number a double holds) keeps whether it is reached; any other is
// moved outward by a relative 1e-12 (the functions' own rounding too), beyond every value, and so
// is open.
struct Range {
  double low = -infinity;
  double high = infinity;
  bool low_open = true;
  bool high_open = true;
};

double down(double x) {
  return std::isfinite(x) ? x - 1e-12 * (1 + std::abs(x)) : x;
}
double up(double x) {
  return std::isfinite(x) ? x + 1e-12 * (1 + std::abs(x)) : x;
}

// One end of a range: its value, whether it is exact, whether a value reaches it.
struct End {
  double value;
  bool exact;
  bool reached;
};

// An end as a range keeps it: itself when exact, else moved outward (and then open).
double low_of(const End& e) {
  return e.exact ? e.value : down(e.value);
}
double high_of(const End& e) {
  return e.exact ? e.value : up(e.value);
}
Range from_ends(const End& low, const End& high) {
  return {low_of(low), high_of(high), !(low.exact && low.reached), !(high.exact && high.reached)};
}

// a + b and whether the double sum is exact (its rounding error, by Knuth's two-sum, is 0).
End add_ends(double a, double b, bool reached) {
  const double s = a + b;
  if (!std::isfinite(s)) {
    return {s, !std::isnan(s), false};
  }
  const double b_part = s - a;
  const double error = (a - (s - b_part)) + (b - b_part);
  return {s, error == 0, reached};
}

Range point(double x) {
  return {x, x, false, false};
}

// A number as a range: itself when a double holds it exactly (an integer or a fraction over a
// power of two, as 2 or 1/2), else its double moved outward.
Range number_range(const GiNaC::numeric& n) {
  const double v = n.to_double();
  bool exact = false;
  if (n.is_rational()) {
    const GiNaC::numeric numerator = n.numer();
    const GiNaC::numeric denominator = n.denom();
    const GiNaC::numeric most(9007199254740992L);  // 2^53
    if (abs(numerator) < most && denominator < most) {
      const long d = denominator.to_long();
      exact = (d & (d - 1)) == 0;
    }
  }
  return exact ? point(v) : Range{down(v), up(v), false, false};
}

Range range_sum(const Range& a, const Range& b) {
  return from_ends(add_ends(a.low, b.low, !a.low_open && !b.low_open),
                   add_ends(a.high, b.high, !a.high_open && !b.high_open));
}

Range multiply(const Range& a, const Range& b) {
  // The four products of the ends, with 0 · ∞ as 0. A product is reached when both ends are, or
  // when it is 0 from a reached end 0 (times any value of the other range).
  const auto corner = [](double x, bool x_reached, double y, bool y_reached) -> End {
    if (x == 0 || y == 0) {
      return {0.0, true, (x == 0 && x_reached) || (y == 0 && y_reached)};
    }
    const double p = x * y;
    if (!std::isfinite(p)) {
      return {p, true, false};
    }
    const bool exact = std::fma(x, y, -p) == 0 && std::abs(p) > 1e-290;
    return {p, exact, x_reached && y_reached};
  };
  const End c[4] = {corner(a.low, !a.low_open, b.low, !b.low_open),
                    corner(a.low, !a.low_open, b.high, !b.high_open),
                    corner(a.high, !a.high_open, b.low, !b.low_open),
                    corner(a.high, !a.high_open, b.high, !b.high_open)};
  // The extreme values: exact when every corner of that value is, reached when one exact is.
  const auto extreme = [&](bool lowest) {
    double v = c[0].value;
    for (const End& e : c) {
      v = lowest ? std::min(v, e.value) : std::max(v, e.value);
    }
    End result{v, true, false};
    for (const End& e : c) {
      if (e.value == v) {
        result.exact = result.exact && e.exact;
        result.reached = result.reached || e.reached;
      }
    }
    return result;
  };
  return from_ends(extreme(true), extreme(false));
}

Range integer_power(const Range& a, long k) {
  if (k == 0) {
    return point(1);
  }
  Range r = point(1);
  for (long i = 0; i < k; ++i) {
    r = multiply(r, a);
  }
  if (k % 2 == 0) {
    // An even power is at least 0; of a range that holds 0, from 0.
    const bool holds_zero = a.low < 0 && a.high > 0;
    const bool touches_zero = (a.low == 0 && !a.low_open) || (a.high == 0 && !a.high_open);
    if (holds_zero || touches_zero) {
      r.low = 0;
      r.low_open = false;
    } else if (r.low <= 0) {
      r.low = 0;
      r.low_open = true;
    }
  }
  return r;
}

Range inverse(const Range& a) {
  const bool positive = a.low > 0 || (a.low == 0 && a.low_open);
  const bool negative = a.high < 0 || (a.high == 0 && a.high_open);
  if (positive) {
    return {a.high == infinity ? 0 : down(1 / a.high), a.low == 0 ? infinity : up(1 / a.low),
            a.high == infinity ? true : a.high_open, true};
  }
  if (negative) {
    return {a.high == 0 ? -infinity : down(1 / a.high), a.low == -infinity ? 0 : up(1 / a.low),
            true, a.low == -infinity ? true : a.low_open};
  }
  return {};
}

Sign sign_of(const Range& r) {
  if (r.low > 0 || (r.low == 0 && r.low_open)) {
    return Sign::positive;
  }
  if (r.high < 0 || (r.high == 0 && r.high_open)) {
    return Sign::negative;
  }
  if (r.low == 0) {
    return Sign::nonnegative;
  }
  if (r.high == 0) {
    return Sign::nonpositive;
  }
  return Sign::unknown;
}

// |a| over a's range: from 0 where a's range holds it (or reaches it), else between its ends'
// magnitudes.
Range magnitude_range(const Range& a) {
  if (a.low > 0 || (a.low == 0 && a.low_open)) {
    return a;
  }
  if (a.high < 0 || (a.high == 0 && a.high_open)) {
    return {-a.high, -a.low, a.high_open, a.low_open};
  }
  // The larger magnitude, reached if an end of it is (both ends when they are equal).
  const double top = std::max(a.high, -a.low);
  const bool open = (a.high != top || a.high_open) && (-a.low != top || a.low_open);
  return {0, top, false, open};
}

// exp over a's range: increasing, 1 at 0, above 0.
Range exponential_range(const Range& a) {
  const auto at = [](double v, bool low) {
    if (v == 0 || !std::isfinite(v)) {
      return v == 0 ? 1.0 : (v > 0 ? infinity : 0.0);
    }
    return low ? std::max(0.0, down(std::exp(v))) : up(std::exp(v));
  };
  return {at(a.low, true), at(a.high, false), a.low_open, a.high_open};
}

// sin or cos over a range of their argument no wider than a turn: the values at its ends, and ±1
// where a crest or trough lies inside (within 1e-9 of an end, a crest is taken to be at that end,
// as a bound of π/2 is). A value at an end within 1e-15 of 0 is 0 (cos of the double nearest π/2
// is 6e-17), with that end's openness: on 0 < θ < π/2, cos θ > 0; a value both ends give is open
// only when both are. The ends are moved outward for rounding but never beyond ±1, so that on
// 0 < θ < 2π, 1 - cos θ > 0.
Range wave(const Range& a, bool cosine, std::optional<double> exact_low,
           std::optional<double> exact_high) {
  constexpr double pi = 3.14159265358979323846;
  if (!std::isfinite(a.low) || !std::isfinite(a.high) || a.high - a.low > 2 * pi + 1e-9) {
    return {-1, 1, false, false};
  }
  const auto f = [&](double x) {
    const double v = cosine ? std::cos(x) : std::sin(x);
    return std::abs(v) < 1e-15 ? 0.0 : v;
  };
  const double at_low = exact_low ? *exact_low : f(a.low);
  const double at_high = exact_high ? *exact_high : f(a.high);
  Range r;
  bool low_exact = false;  // whether r's ends are exact values (the crests' ±1 are)
  bool high_exact = false;
  if (at_low < at_high) {
    r = {at_low, at_high, a.low_open, a.high_open};
    low_exact = exact_low.has_value();
    high_exact = exact_high.has_value();
  } else if (at_high < at_low) {
    r = {at_high, at_low, a.high_open, a.low_open};
    low_exact = exact_high.has_value();
    high_exact = exact_low.has_value();
  } else {
    // The same value at both ends is reached unless both are open: on 0 <= θ < π, sin θ = 0 at
    // θ = 0 (taking the open end's openness made sin θ > 0, and a division by it passed).
    const bool open = a.low_open && a.high_open;
    r = {at_low, at_high, open, open};
    low_exact = high_exact = exact_low && exact_high;
  }
  // Crests (cos at 2kπ, sin at π/2 + 2kπ) and troughs strictly inside.
  const double shift = cosine ? 0.0 : pi / 2;
  for (double k = std::ceil((a.low - shift) / pi - 1e-9); k * pi + shift < a.high + 1e-9; ++k) {
    const double x = k * pi + shift;
    if (x <= a.low + 1e-9 || x >= a.high - 1e-9) {
      continue;
    }
    if (static_cast<long>(k) % 2 == 0) {
      r.high = 1;
      r.high_open = false;
    } else {
      r.low = -1;
      r.low_open = false;
    }
  }
  const auto outward = [](double v, bool exact, bool low) {
    if (exact || v == 0 || v == 1 || v == -1) {
      return v;
    }
    return low ? std::max(-1.0, down(v)) : std::min(1.0, up(v));
  };
  return {outward(r.low, low_exact, true), outward(r.high, high_exact, false), r.low_open,
          r.high_open};
}

// tan over a range of its argument within one branch (between two odd multiples of π/2): the
// values at its ends; an end at an asymptote is infinite and left out, open or closed, for tan
// has no value there (nor has whatever is written in it: on 0 ≤ θ ≤ π, tan(θ/2) ≥ 0 where it
// is defined, and θ = π is decided apart); any other range, unknown. @p exact_low and
// @p exact_high are its exact values at the ends where known.
Range tangent(const Range& a, std::optional<double> exact_low, std::optional<double> exact_high) {
  constexpr double pi = 3.14159265358979323846;
  if (!std::isfinite(a.low) || !std::isfinite(a.high)) {
    return {};
  }
  const double k = std::round((a.low + a.high) / 2 / pi);  // the branch around kπ
  const double left = k * pi - pi / 2;
  const double right = k * pi + pi / 2;
  const bool at_left = std::abs(a.low - left) <= 1e-9;
  const bool at_right = std::abs(a.high - right) <= 1e-9;
  if ((a.low < left && !at_left) || (a.high > right && !at_right)) {
    return {};
  }
  const auto value = [](double x) {
    const double v = std::tan(x);
    return std::abs(v) < 1e-15 ? 0.0 : v;
  };
  // An exact value at an end (tan π/4 = 1) is kept; a rounded one is moved outward.
  const double low = at_left ? -infinity : exact_low ? *exact_low : value(a.low);
  const double high = at_right ? infinity : exact_high ? *exact_high : value(a.high);
  return {low == 0 || exact_low ? low : down(low), high == 0 || exact_high ? high : up(high),
          a.low_open || at_left, a.high_open || at_right};
}

}  // namespace

// ---- adding facts ------------------------------------------------------------------------------

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
  derived_signs_.clear();
  return true;
}

void Facts::add_relation(const ex& e, Sign sign) {
  wave_ends_.clear();
  derived_signs_.clear();
  const ex expanded = GiNaC::expand(e);
  if (is_a<GiNaC::symbol>(expanded)) {
    add(expanded, sign);
    return;
  }
  // c x with c a number: a fact on x (0 \le e is -e \le 0, that is e \geq 0).
  if (is_a<GiNaC::mul>(expanded) && expanded.nops() == 2 && is_a<GiNaC::symbol>(expanded.op(0)) &&
      is_a<GiNaC::numeric>(expanded.op(1)) && !expanded.op(1).is_zero()) {
    add(expanded.op(0),
        GiNaC::ex_to<GiNaC::numeric>(expanded.op(1)).is_positive() ? sign : flipped(sign));
    return;
  }
  // A product with one factor of unknown sign, a symbol, the others of strict signs: a fact on
  // that symbol (\omega L / 2 > 0 with L > 0: \omega > 0).
  const ex product = is_a<GiNaC::mul>(e) ? e : expanded;
  if (is_a<GiNaC::mul>(product) && (sign == Sign::positive || sign == Sign::negative)) {
    std::optional<ex> unknown;
    bool negative = sign == Sign::negative;
    bool usable = true;
    for (std::size_t i = 0; i < product.nops() && usable; ++i) {
      const ex f = product.op(i);
      const Sign s = this->sign(f);
      if (s == Sign::positive) {
        continue;
      }
      if (s == Sign::negative) {
        negative = !negative;
        continue;
      }
      if (is_a<GiNaC::symbol>(f) && !unknown) {
        unknown = f;
        continue;
      }
      usable = false;
    }
    if (usable && unknown) {
      add(*unknown, negative ? Sign::negative : Sign::positive);
    }
  }
  if (is_a<GiNaC::numeric>(expanded)) {
    return;  // a number: its sign is what it is
  }
  relations_.emplace_back(expanded, sign);
  // x - c (or c - x) with c a number bounds x.
  if (is_a<GiNaC::add>(expanded) && expanded.nops() == 2) {
    for (std::size_t k = 0; k < 2; ++k) {
      const ex variable_part = expanded.op(k);
      // A number, or a constant such as π/2 (its double one step outward, below).
      const ex number = GiNaC::evalf(expanded.op(1 - k));
      if (!is_a<GiNaC::numeric>(number) || !GiNaC::ex_to<GiNaC::numeric>(number).is_real()) {
        continue;
      }
      const bool exact = is_a<GiNaC::numeric>(expanded.op(1 - k));
      const double c = -GiNaC::ex_to<GiNaC::numeric>(number).to_double();
      ex symbol = variable_part;
      Sign s = sign;
      if (is_a<GiNaC::mul>(variable_part) && variable_part.nops() == 2 &&
          is_a<GiNaC::numeric>(variable_part.op(1)) && variable_part.op(1).is_equal(-1)) {
        symbol = variable_part.op(0);
        s = flipped(sign);
      }
      if (!is_a<GiNaC::symbol>(symbol)) {
        continue;
      }
      double bound = s == sign ? c : -c;
      const ex exact_bound = s == sign ? -expanded.op(1 - k) : expanded.op(1 - k);
      const bool sharp = s == Sign::positive || s == Sign::negative;
      auto& [low, high] = bounds_[symbol];
      auto& [low_strict, high_strict] = strict_[symbol];
      const bool lower = s == Sign::positive || s == Sign::nonnegative;
      if (!exact) {
        bound = std::nextafter(bound, lower ? -infinity : infinity);  // θ < π/2: not tighter
      }
      auto& [exact_low, exact_high] = exact_bounds_[symbol];
      if (lower) {
        if (!low || bound > *low || (bound == *low && sharp)) {
          low = bound;
          low_strict = sharp;
          exact_low = exact_bound;
        }
      } else if (s == Sign::negative || s == Sign::nonpositive) {
        if (!high || bound < *high || (bound == *high && sharp)) {
          high = bound;
          high_strict = sharp;
          exact_high = exact_bound;
        }
      }
    }
  }
}

void Facts::add_equality(const ex& e) {
  wave_ends_.clear();
  derived_signs_.clear();
  equalities_.push_back(GiNaC::expand(e));
}

Facts Facts::carried(const std::vector<std::pair<ex, ex>>& renamed) const {
  Facts copy = *this;
  for (const auto& [from, to] : renamed) {
    if (const auto found = signs_.find(from); found != signs_.end()) {
      copy.add(to, found->second);
    }
    if (const auto found = bounds_.find(from); found != bounds_.end()) {
      copy.bounds_[to] = found->second;
      copy.strict_[to] = strict_.at(from);
      copy.exact_bounds_[to] = exact_bounds_.at(from);
    }
  }
  copy.derived_signs_.clear();
  return copy;
}

// ---- what the facts prove ----------------------------------------------------------------------

Sign Facts::of_symbol(const ex& symbol) const {
  const auto found = signs_.find(symbol);
  if (found != signs_.end()) {
    return found->second;
  }
  const auto bound = bounds_.find(symbol);
  if (bound != bounds_.end()) {
    const auto& [low, high] = bound->second;
    if (low && *low > 0) {
      return Sign::positive;
    }
    if (high && *high < 0) {
      return Sign::negative;
    }
    if (low && *low == 0) {
      return Sign::nonnegative;
    }
    if (high && *high == 0) {
      return Sign::nonpositive;
    }
  }
  return Sign::unknown;
}

Sign Facts::of_relation(const ex& e) const {
  for (const auto& [r, sign] : relations_) {
    if (r.is_zero() || e.is_zero()) {
      continue;
    }
    ex ratio;
    try {
      ratio = GiNaC::normal(e / r);
    } catch (const std::exception&) {
      continue;
    }
    if (is_a<GiNaC::numeric>(ratio) && !ratio.is_zero()) {
      return GiNaC::ex_to<GiNaC::numeric>(ratio).is_positive() ? sign : flipped(sign);
    }
  }
  return Sign::unknown;
}

Sign Facts::structural(const ex& e) const {
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
    const Sign own = of_symbol(e);
    return own != Sign::unknown ? own : through_relation(e);
  }
  if (!relations_.empty() && !is_a<GiNaC::function>(e) && e.nops() <= 16) {
    if (const Sign s = of_relation(e); s != Sign::unknown) {
      return s;
    }
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
  if (sym::is_function(e, "exp")) {
    return Sign::positive;
  }
  if (sym::is_function(e, "abs")) {
    const Sign inner = sign(e.op(0));
    return inner == Sign::unknown                      ? Sign::nonnegative
           : inner == Sign::zero                       ? Sign::zero
           : (strict(inner) || inner == Sign::nonzero) ? Sign::positive
                                                       : Sign::nonnegative;
  }
  if (sym::is_function(e, "indexed_sum")) {
    // A sum of at least one term (its upper limit is at least its lower): as its terms.
    const Sign body = sign(e.op(0));
    return body == Sign::positive || body == Sign::negative || at_least_zero(body) ||
                   at_most_zero(body)
               ? body
               : Sign::unknown;
  }
  if (sym::is_function(e, "indexed_product")) {
    const Sign body = sign(e.op(0));
    return body == Sign::positive ? Sign::positive : Sign::unknown;
  }
  return Sign::unknown;
}

// A symbol's sign through a relation it stands in with coefficient ±1: m_0 > m_f and m_f > 0
// give m_0 = (m_0 - m_f) + m_f > 0. One relation deep at a time, at most three deep in all (a
// cycle of relations ends there).
Sign Facts::through_relation(const ex& x) const {
  thread_local int depth = 0;
  if (depth >= 3) {
    return Sign::unknown;
  }
  ++depth;
  struct Leave {
    ~Leave() { --depth; }
  } leave;
  for (const auto& [r, s] : relations_) {
    if (!r.is_polynomial(x) || r.degree(x) != 1) {
      continue;
    }
    const ex c = r.coeff(x, 1);
    if (!c.is_equal(1) && !c.is_equal(-1)) {
      continue;
    }
    // x = c r - c (r - c x), the second part free of x.
    const Sign of_r = c.is_equal(1) ? s : flipped(s);
    const ex rest = GiNaC::expand(x - c * r);
    const Sign total = plus(of_r, sign(rest));
    if (total != Sign::unknown) {
      return total;
    }
  }
  return Sign::unknown;
}

Sign Facts::sign(const ex& e) const {
  const Sign s = structural(e);
  if (s != Sign::unknown && s != Sign::nonnegative && s != Sign::nonpositive) {
    return s;
  }
  const Sign r = of_range(e);
  if (r == Sign::positive || r == Sign::negative) {
    return r;
  }
  if (const Sign d = of_increasing_difference(e); d != Sign::unknown) {
    return d;
  }
  if (of_wave_zeros(e) == Sign::nonzero) {
    // Never 0, and ≥ 0 or ≤ 0 by the other rules: of that strict sign.
    const Sign weak = s != Sign::unknown ? s : r;
    return weak == Sign::nonnegative   ? Sign::positive
           : weak == Sign::nonpositive ? Sign::negative
                                       : Sign::nonzero;
  }
  const Sign known = s != Sign::unknown ? s : r;
  if (known == Sign::unknown) {
    const Sign combined = of_linear_facts(e);
    if (combined != Sign::unknown) {
      return combined;
    }
    const Sign quadratic = of_quadratic(e);
    return quadratic != Sign::unknown ? quadratic : of_zeros(e);
  }
  if (known == Sign::nonnegative || known == Sign::nonpositive) {
    // ≤ 0 from the ranges (2 e^2 - e - 2 for 0 ≤ e ≤ 1), < 0 where it has no root there, or
    // where its only root is outside the facts (v_1^2 + v_2^2 with v_1 ≠ v_2)
    const Sign strict = of_zeros(e);
    return strict != Sign::unknown ? strict : known;
  }
  return known;
}

// A strict sign from where e is 0: nowhere the facts allow (of_roots_outside,
// of_zero_only_at_origin).
Sign Facts::of_zeros(const ex& e) const {
  const Sign roots = of_roots_outside(e);
  return roots != Sign::unknown ? roots : of_zero_only_at_origin(e);
}

namespace {

// @p term as k f(…), a real number k ≠ 0 times one function named in @p names: k and f(…).
std::optional<std::pair<GiNaC::numeric, ex>> scaled_function(
    const ex& term, const std::vector<const char*>& names) {
  GiNaC::numeric k = 1;
  std::optional<ex> f;
  const auto factor = [&](const ex& x) {
    const bool named = std::any_of(names.begin(), names.end(),
                                   [&](const char* name) { return sym::is_function(x, name); });
    if (is_a<GiNaC::numeric>(x)) {
      k *= GiNaC::ex_to<GiNaC::numeric>(x);
    } else if (!f && named) {
      f = x;
    } else {
      k = 0;  // another factor: no such term
    }
  };
  sym::for_each_factor(term, factor);
  if (!f || k.is_zero() || !k.is_real()) {
    return std::nullopt;
  }
  return std::pair{k, *f};
}

}  // namespace

// k a^r - k b^r for a positive r and a, b ≥ 0, where x^r increases strictly: the sign of
// k (a - b) where the facts give a - b a strict sign (√m_1 - √m_2 > 0 for m_1 > m_2 > 0).
Sign Facts::of_power_difference(const ex& e) const {
  struct Scaled {
    GiNaC::numeric k;
    ex base;
    ex exponent;
  };
  const auto scaled = [](const ex& term) -> std::optional<Scaled> {
    const bool product = is_a<GiNaC::mul>(term) && term.nops() == 2 &&
                         is_a<GiNaC::numeric>(term.op(1)) &&
                         GiNaC::ex_to<GiNaC::numeric>(term.op(1)).is_real();
    const ex power = product ? term.op(0) : term;
    if (!is_a<GiNaC::power>(power) || !is_a<GiNaC::numeric>(power.op(1)) ||
        !GiNaC::ex_to<GiNaC::numeric>(power.op(1)).is_rational() ||
        !GiNaC::ex_to<GiNaC::numeric>(power.op(1)).is_positive()) {
      return std::nullopt;
    }
    return Scaled{product ? GiNaC::ex_to<GiNaC::numeric>(term.op(1)) : GiNaC::numeric(1),
                  power.op(0), power.op(1)};
  };
  const auto first = scaled(e.op(0));
  const auto second = scaled(e.op(1));
  if (!first || !second || first->k != -second->k || !first->exponent.is_equal(second->exponent)) {
    return Sign::unknown;
  }
  if (!at_least_zero(sign(first->base)) || !at_least_zero(sign(second->base))) {
    return Sign::unknown;
  }
  const Sign between = sign(GiNaC::expand(first->base - second->base));
  if (between != Sign::positive && between != Sign::negative) {
    return Sign::unknown;
  }
  return first->k.is_positive() == (between == Sign::positive) ? Sign::positive : Sign::negative;
}

// k f(a) - k f(b) for a function f that increases strictly on the whole real line (exp, arctan;
// the reader writes sinh in exponentials): the sign of k (a - b), where the facts give a - b a
// strict sign (e^x - e^y > 0 for x > 1 > y, which the ranges of e^x and e^y, both open at e, cannot
// show once rounded).
Sign Facts::of_increasing_difference(const ex& e) const {
  if (!is_a<GiNaC::add>(e) || e.nops() != 2) {
    return Sign::unknown;
  }
  if (const Sign powers = of_power_difference(e); powers != Sign::unknown) {
    return powers;
  }
  const std::vector<const char*> increasing{"exp", "atan"};
  const auto first = scaled_function(e.op(0), increasing);
  const auto second = scaled_function(e.op(1), increasing);
  if (!first || !second || first->first != -second->first ||
      GiNaC::ex_to<GiNaC::function>(first->second).get_name() !=
          GiNaC::ex_to<GiNaC::function>(second->second).get_name()) {
    return Sign::unknown;
  }
  const Sign between = sign(GiNaC::expand(first->second.op(0) - second->second.op(0)));
  if (between != Sign::positive && between != Sign::negative) {
    return Sign::unknown;
  }
  return first->first.is_positive() == (between == Sign::positive) ? Sign::positive
                                                                   : Sign::negative;
}

namespace {

// Whether f (sin, cos or tan) takes the value v at an angle of the range from `from` to `to`
// (Facts::End: an open end is left out; from_value and to_value their values), an angle within
// 1e-20 of an end taken as at it only where f there is v exactly; nothing when that cannot be
// told, or when the range spans more than eight turns.
std::optional<bool> reaches(const ex& f, const ex& v, const Facts::End& from, const Facts::End& to,
                            const GiNaC::numeric& from_value, const GiNaC::numeric& to_value) {
  const bool tangent = sym::is_function(f, "tan");
  const bool sine = sym::is_function(f, "sin");
  const double step = tangent ? 3.141592653589793 : 6.283185307179586;
  if (!((to_value - from_value).to_double() / step < 8)) {
    return std::nullopt;
  }
  std::vector<ex> angles;
  if (tangent) {
    angles = {GiNaC::atan(v)};
  } else if (sine) {
    angles = {GiNaC::asin(v), GiNaC::Pi - GiNaC::asin(v)};
  } else {
    angles = {GiNaC::acos(v), -GiNaC::acos(v)};
  }
  const auto value_at = [&](const ex& u) {
    return tangent ? GiNaC::tan(u) : sine ? GiNaC::sin(u) : GiNaC::cos(u);
  };
  // Where an angle is against an end: +1 beyond it (inside the range), 0 at it, -1 short of it;
  // nothing when that cannot be told.
  const GiNaC::numeric tiny("1e-20");
  const auto against = [&](const ex& angle, const Facts::End& end,
                           int inward) -> std::optional<int> {
    const std::optional<GiNaC::numeric> gap = value_in_40_digits(angle - end.at);
    if (!gap) {
      return std::nullopt;
    }
    if (abs(*gap) > tiny) {
      return (gap->is_positive() ? 1 : -1) * inward;
    }
    try {
      if (GiNaC::normal(GiNaC::expand(value_at(end.at) - v)).is_zero()) {
        return 0;
      }
    } catch (const std::exception&) {
      // a pole at the end
    }
    return std::nullopt;
  };
  const ex period = tangent ? GiNaC::Pi : 2 * GiNaC::Pi;
  for (const ex& angle : angles) {
    const std::optional<GiNaC::numeric> base = value_in_40_digits(angle);
    if (!base || !base->is_real()) {
      return std::nullopt;  // |v| > 1: sin and cos never reach it, which their ranges show
    }
    const auto first = static_cast<long>(std::floor((from_value - *base).to_double() / step)) - 1;
    const auto last = static_cast<long>(std::ceil((to_value - *base).to_double() / step)) + 1;
    for (long n = first; n <= last; ++n) {
      const ex u = angle + n * period;
      const std::optional<int> past_from = against(u, from, 1);
      const std::optional<int> before_to = against(u, to, -1);
      if (!past_from || !before_to) {
        return std::nullopt;
      }
      if ((*past_from > 0 || (*past_from == 0 && !from.strict)) &&
          (*before_to > 0 || (*before_to == 0 && !to.strict))) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

// k f(c x + d) + b for f = sin, cos or tan, numbers k ≠ 0 and b (π and roots allowed), x a symbol
// with two exact ends: f takes the value v = -b/k at the angles asin v + 2nπ and π - asin v + 2nπ
// (sin), ±acos v + 2nπ (cos), atan v + nπ (tan). Where none of them lies in the range of c x + d
// (at an open end is not in it), the sum is never 0 (where it is defined: tan's poles are no
// zeros): 2 sin θ - √3 on 0 < θ < π/3, tan θ - 1 on π/4 < θ < 5π/4.
Sign Facts::of_wave_zeros(const ex& e) const {
  if (!is_a<GiNaC::add>(e) || e.nops() > 4) {
    return Sign::unknown;
  }
  std::optional<std::pair<GiNaC::numeric, ex>> wave;
  std::size_t at = 0;  // the term that is k f(…)
  while (at < e.nops() && !(wave = scaled_function(e.op(at), {"sin", "cos", "tan"}))) {
    ++at;
  }
  if (!wave) {
    return Sign::unknown;
  }
  ex b = 0;  // the other terms, each a real number
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (i == at) {
      continue;
    }
    const std::optional<GiNaC::numeric> value = value_in_40_digits(e.op(i));
    if (!value || !value->is_real()) {
      return Sign::unknown;
    }
    b += e.op(i);
  }
  const ex& f = wave->second;
  const std::optional<Affine> affine = affine_in_symbol(f.op(0));
  if (!affine) {
    return Sign::unknown;
  }
  const auto [low, high] = exact_ends(affine->symbol);
  if (!low || !high) {
    return Sign::unknown;
  }
  const bool rising = affine->c.is_positive();
  const End from{affine->c * (rising ? low : high)->at + affine->d, (rising ? low : high)->strict};
  const End to{affine->c * (rising ? high : low)->at + affine->d, (rising ? high : low)->strict};
  const ex v = -b / wave->first;
  const std::optional<GiNaC::numeric> v_value = value_in_40_digits(v);
  const std::optional<GiNaC::numeric> from_value = value_in_40_digits(from.at);
  const std::optional<GiNaC::numeric> to_value = value_in_40_digits(to.at);
  if (!v_value || !from_value || !to_value || !v_value->is_real()) {
    return Sign::unknown;
  }
  const std::optional<bool> zero = reaches(f, v, from, to, *from_value, *to_value);
  return zero && !*zero ? Sign::nonzero : Sign::unknown;
}

// a x² + b x + c in one of its symbols x, with a of a strict sign and b² - 4 a c < 0: never 0,
// of a's sign (x² + x + 1 > 0).
Sign Facts::of_quadratic(const ex& e) const {
  if (!is_a<GiNaC::add>(e) || e.nops() > 12 || !e.info(GiNaC::info_flags::polynomial)) {
    return Sign::unknown;
  }
  GiNaC::exset symbols;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is_a<GiNaC::symbol>(*it)) {
      symbols.insert(*it);
    }
  }
  if (symbols.size() > 3) {
    return Sign::unknown;
  }
  for (const ex& x : symbols) {
    if (e.degree(x) != 2) {
      continue;
    }
    const ex a = e.coeff(x, 2);
    const ex b = e.coeff(x, 1);
    const ex c = e.coeff(x, 0);
    const Sign leading = sign(a);
    if ((leading == Sign::positive || leading == Sign::negative) &&
        sign(GiNaC::expand(b * b - 4 * a * c)) == Sign::negative) {
      return leading;
    }
  }
  return Sign::unknown;
}

namespace {

// The number of sign changes of Sturm's sequence @p chain at x = @p at (at an end left open,
// none: at -∞ with @p high false, +∞ with it true), zeros skipped.
int sign_changes(const std::vector<ex>& chain, const ex& x, const std::optional<ex>& at,
                 bool high) {
  int changes = 0;
  int last = 0;
  for (const ex& p : chain) {
    int s = 0;
    if (at) {
      const ex v = p.subs(x == *at);
      s = v.is_zero() ? 0 : GiNaC::ex_to<GiNaC::numeric>(v).is_positive() ? 1 : -1;
    } else {  // the leading term decides, with the degree's parity toward -∞
      const int degree = p.degree(x);
      const bool positive = GiNaC::ex_to<GiNaC::numeric>(p.lcoeff(x)).is_positive();
      s = (positive == (high || degree % 2 == 0)) ? 1 : -1;
    }
    if (s != 0) {
      changes += last != 0 && s != last ? 1 : 0;
      last = s;
    }
  }
  return changes;
}

}  // namespace

// A polynomial in one symbol with rational coefficients (2 + e - 2 e^2 with 0 ≤ e ≤ 1) that has
// no real root where the facts keep the symbol has one sign there: the sign at a point inside.
// Sturm's theorem counts the roots between the ends exactly (the difference of the sign changes
// of p, p', and the negated remainders, at the two ends); an end that is a root is left undecided.
Sign Facts::of_roots_outside(const ex& e) const {
  if (!is_a<GiNaC::add>(e) || e.nops() > 13 || !e.info(GiNaC::info_flags::polynomial)) {
    return Sign::unknown;
  }
  const std::vector<ex> symbols = symbols_of(e);
  if (symbols.size() != 1) {
    return Sign::unknown;
  }
  const std::optional<ex> x = symbols[0];
  const ex p = GiNaC::expand(e);
  if (p.degree(*x) < 2 || p.degree(*x) > 12) {
    return Sign::unknown;
  }
  for (int k = 0; k <= p.degree(*x); ++k) {
    const ex c = p.coeff(*x, k);
    if (!is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) {
      return Sign::unknown;
    }
  }
  // The ends where they are rational numbers; an end that is not (π/6) is taken as open to
  // infinity, which can only find more roots.
  const auto [low_end, high_end] = exact_ends(*x);
  const auto rational = [](const std::optional<End>& end) -> std::optional<ex> {
    if (end && is_a<GiNaC::numeric>(end->at) &&
        GiNaC::ex_to<GiNaC::numeric>(end->at).is_rational()) {
      return end->at;
    }
    return std::nullopt;
  };
  const std::optional<ex> low = rational(low_end);
  const std::optional<ex> high = rational(high_end);
  if ((low && p.subs(*x == *low).is_zero()) || (high && p.subs(*x == *high).is_zero())) {
    return Sign::unknown;
  }
  std::vector<ex> chain{p, GiNaC::diff(p, GiNaC::ex_to<GiNaC::symbol>(*x))};
  while (!chain.back().is_zero() && chain.back().degree(*x) > 0) {
    const ex next = GiNaC::expand(-GiNaC::rem(chain[chain.size() - 2], chain.back(), *x));
    if (next.is_zero()) {
      break;
    }
    chain.push_back(next);
  }
  if (sign_changes(chain, *x, low, false) != sign_changes(chain, *x, high, true)) {
    return Sign::unknown;  // a root between the ends
  }
  const ex inside = low && high ? (*low + *high) / 2 : low ? *low + 1 : high ? *high - 1 : ex(0);
  return GiNaC::ex_to<GiNaC::numeric>(p.subs(*x == inside)).is_positive() ? Sign::positive
                                                                          : Sign::negative;
}

// A sum that is 0 only where each of its symbols is: even powers of symbols with coefficients of
// one sign (x^2 + 3 y^4), or a definite quadratic form in two symbols, a x^2 + b x y + c y^2 with
// numbers b^2 - 4 a c < 0 (x^2 + x y + y^2, a factor of x^3 - y^3). Where the facts do not hold
// with every symbol 0 (v_1 ≠ v_2), it is never 0: of its sign elsewhere, that of its coefficients.
Sign Facts::of_zero_only_at_origin(const ex& e) const {
  if (!is_a<GiNaC::add>(e) || e.nops() > 8 || !e.info(GiNaC::info_flags::polynomial)) {
    return Sign::unknown;
  }
  const ex p = GiNaC::expand(e);
  if (!is_a<GiNaC::add>(p)) {
    return Sign::unknown;
  }
  const std::vector<ex> symbols = symbols_of(p);
  if (symbols.empty() || symbols.size() > 4) {
    return Sign::unknown;
  }
  // each term c x^(2k): the signs of the c, all one
  int sign = 0;
  for (std::size_t i = 0; i < p.nops() && sign != 2; ++i) {
    const ex term = p.op(i);
    const ex power = is_a<GiNaC::mul>(term) && term.nops() == 2 ? term.op(0) : term;
    const ex c = is_a<GiNaC::mul>(term) && term.nops() == 2 ? term.op(1) : ex(1);
    const bool even = is_a<GiNaC::power>(power) && is_a<GiNaC::symbol>(power.op(0)) &&
                      is_a<GiNaC::numeric>(power.op(1)) &&
                      GiNaC::ex_to<GiNaC::numeric>(power.op(1)).is_even() &&
                      GiNaC::ex_to<GiNaC::numeric>(power.op(1)).is_positive();
    if (!even || !is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_real()) {
      sign = 2;
      break;
    }
    const int s = GiNaC::ex_to<GiNaC::numeric>(c).is_positive() ? 1 : -1;
    sign = sign == 0 || sign == s ? s : 2;
  }
  if (sign == 2) {
    if (const std::optional<DefiniteForm> form = definite_form(p)) {
      sign = form->positive ? 1 : -1;
    }
  }
  if (sign != 1 && sign != -1) {
    return Sign::unknown;
  }
  GiNaC::exmap origin;
  bool outside = false;
  for (const ex& x : symbols) {
    origin[x] = 0;
    outside = outside || !satisfied(x, 0);
  }
  outside = outside || !relations_hold(origin, false) ||
            std::any_of(equalities_.begin(), equalities_.end(), [&](const ex& q) {
              return certainly_nonzero(GiNaC::normal(q.subs(origin)));
            });
  if (!outside) {
    return Sign::unknown;
  }
  return sign == 1 ? Sign::positive : Sign::negative;
}

namespace {

// The sign of e = Σ λ_i r_i + c for the facts r_i of @p chosen (each with its sign) when that
// combination exists with numbers λ_i and c; unknown when it does not, or when its terms' signs
// disagree.
Sign combined_sign(const ex& e, const std::vector<const std::pair<ex, Sign>*>& chosen) {
  std::vector<GiNaC::symbol> lambdas;
  ex rest = e;
  GiNaC::lst unknowns;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    lambdas.emplace_back("lambda" + std::to_string(i));
    unknowns.append(lambdas.back());
    rest -= lambdas.back() * chosen[i]->first;
  }
  rest = GiNaC::expand(rest);
  GiNaC::exset in_rest;
  for (GiNaC::const_preorder_iterator it = rest.preorder_begin(); it != rest.preorder_end(); ++it) {
    if (is_a<GiNaC::symbol>(*it) && std::none_of(lambdas.begin(), lambdas.end(),
                                                 [&](const ex& l) { return it->is_equal(l); })) {
      in_rest.insert(*it);
    }
  }
  if (in_rest.size() > 6) {
    return Sign::unknown;
  }
  GiNaC::lst equations;
  for (const ex& v : in_rest) {
    equations.append(rest.coeff(v, 1) == 0);
  }
  ex solution;
  try {
    solution = GiNaC::lsolve(equations, unknowns);
  } catch (const std::exception&) {
    return Sign::unknown;
  }
  if (solution.nops() != chosen.size()) {
    return Sign::unknown;
  }
  GiNaC::lst values;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const ex k = solution.op(i).rhs();
    if (!is_a<GiNaC::numeric>(k)) {
      return Sign::unknown;  // not one combination (a λ left free)
    }
    values.append(lambdas[i] == k);
  }
  const ex c = GiNaC::expand(rest.subs(values));
  if (!is_a<GiNaC::numeric>(c)) {
    return Sign::unknown;
  }
  Sign total = GiNaC::ex_to<GiNaC::numeric>(c).is_zero()       ? Sign::zero
               : GiNaC::ex_to<GiNaC::numeric>(c).is_positive() ? Sign::positive
                                                               : Sign::negative;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const auto& k = GiNaC::ex_to<GiNaC::numeric>(values.op(i).rhs());
    const Sign s = chosen[i]->second;
    total = plus(total, k.is_zero() ? Sign::zero : k.is_positive() ? s : flipped(s));
  }
  return total;
}

}  // namespace

// e = Σ λ_i r_i + c with two or three linear facts r_i (relations, signs of symbols, the ends of
// ranges, equalities), numbers λ_i and c: the sign of that sum when its terms agree (x + y > 0
// and x - y > 0 give x = (r + q)/2 > 0; 2x + 3y > 0 and x + 2y < 0 give x = 2r - 3q > 0;
// x + y + z > 0, x ≥ y and x ≥ z give 3x > 0). Only for e linear in a few symbols, which is what
// a fact on a sum or difference bounds.
Sign Facts::of_linear_facts(const ex& e) const {
  if (relations_.empty() || relations_.size() > 12 ||
      (!is_a<GiNaC::add>(e) && !is_a<GiNaC::symbol>(e))) {
    return Sign::unknown;
  }
  GiNaC::lst symbols;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is_a<GiNaC::symbol>(*it) &&
        std::find(symbols.begin(), symbols.end(), *it) == symbols.end()) {
      symbols.append(*it);
    }
  }
  const auto linear = [](const ex& x) {
    for (GiNaC::const_preorder_iterator it = x.preorder_begin(); it != x.preorder_end(); ++it) {
      if (is_a<GiNaC::symbol>(*it) && (!x.is_polynomial(*it) || x.degree(*it) > 1)) {
        return false;
      }
    }
    return true;
  };
  if (symbols.nops() == 0 || symbols.nops() > 4 || !linear(e)) {
    return Sign::unknown;
  }
  // The linear facts: the relations, then what the facts say of each symbol of them or of e
  // alone (its sign, the ends of its range) and the linear equalities.
  std::vector<std::pair<ex, Sign>> facts;
  GiNaC::exset named(symbols.begin(), symbols.end());
  for (const auto& relation : relations_) {
    if (linear(relation.first)) {
      facts.push_back(relation);
      for (GiNaC::const_preorder_iterator it = relation.first.preorder_begin();
           it != relation.first.preorder_end(); ++it) {
        if (is_a<GiNaC::symbol>(*it)) {
          named.insert(*it);
        }
      }
    }
  }
  if (facts.empty() || named.size() > 6) {
    return Sign::unknown;
  }
  for (const ex& v : named) {
    if (const Sign s = of_symbol(v); s != Sign::unknown) {
      facts.emplace_back(v, s);
    }
    if (const auto found = exact_bounds_.find(v); found != exact_bounds_.end()) {
      const auto is_strict = strict_.find(v);
      const bool low_strict = is_strict != strict_.end() && is_strict->second.first;
      const bool high_strict = is_strict != strict_.end() && is_strict->second.second;
      if (found->second.first) {
        facts.emplace_back(v - *found->second.first,
                           low_strict ? Sign::positive : Sign::nonnegative);
      }
      if (found->second.second) {
        facts.emplace_back(*found->second.second - v,
                           high_strict ? Sign::positive : Sign::nonnegative);
      }
    }
  }
  for (const ex& q : equalities_) {
    if (linear(q)) {
      facts.emplace_back(q, Sign::zero);
    }
  }
  if (facts.size() > 16) {
    return Sign::unknown;
  }
  const auto covers = [&](const std::vector<const std::pair<ex, Sign>*>& chosen) {
    return std::all_of(symbols.begin(), symbols.end(), [&](const ex& v) {
      return std::any_of(chosen.begin(), chosen.end(),
                         [&](const auto* f) { return f->first.has(v); });
    });
  };
  // A strict sign ends the search; a weak one (≥ 0) is kept in case a strict one follows.
  Sign weak = Sign::unknown;
  const auto strict = [&](const std::vector<const std::pair<ex, Sign>*>& chosen) {
    if (!covers(chosen)) {
      return false;
    }
    const Sign s = combined_sign(e, chosen);
    if (s == Sign::nonnegative || s == Sign::nonpositive) {
      weak = s;
    }
    return s != Sign::unknown && s != Sign::nonnegative && s != Sign::nonpositive;
  };
  for (std::size_t i = 0; i < facts.size(); ++i) {
    for (std::size_t j = i + 1; j < facts.size(); ++j) {
      std::vector<const std::pair<ex, Sign>*> chosen{&facts[i], &facts[j]};
      if (strict(chosen)) {
        return combined_sign(e, chosen);
      }
      for (std::size_t k = j + 1; k < facts.size() && facts.size() <= 8; ++k) {
        chosen = {&facts[i], &facts[j], &facts[k]};
        if (strict(chosen)) {
          return combined_sign(e, chosen);
        }
      }
    }
  }
  return weak;
}

// A symbol's sign as the facts give it, or as linear facts added give it (x + y > 0 and x - y > 0
// give x > 0, and so e^x - 1 > 0), remembered until a fact is added.
Sign Facts::derived_sign(const ex& symbol) const {
  if (const Sign s = of_symbol(symbol); s != Sign::unknown || relations_.empty()) {
    return s;
  }
  if (const auto found = derived_signs_.find(symbol); found != derived_signs_.end()) {
    return found->second;
  }
  const Sign s = of_linear_facts(symbol);
  derived_signs_[symbol] = s;
  return s;
}

Sign Facts::of_range(const ex& e) const {
  const std::function<Range(const ex&)> range = [&](const ex& x) -> Range {
    if (is_a<GiNaC::numeric>(x)) {
      const auto& n = GiNaC::ex_to<GiNaC::numeric>(x);
      if (!n.is_real()) {
        return {};
      }
      return number_range(n);
    }
    if (is_a<GiNaC::constant>(x)) {
      return {3.14159265358979, 3.14159265358980, false, false};
    }
    if (is_a<GiNaC::symbol>(x)) {
      Range r;
      switch (derived_sign(x)) {
        case Sign::positive:
          r.low = 0;
          break;
        case Sign::nonnegative:
          r.low = 0;
          r.low_open = false;
          break;
        case Sign::negative:
          r.high = 0;
          break;
        case Sign::nonpositive:
          r.high = 0;
          r.high_open = false;
          break;
        default:
          break;
      }
      if (const auto found = bounds_.find(x); found != bounds_.end()) {
        const auto [low_strict, high_strict] = strict_.at(x);
        if (found->second.first && *found->second.first >= r.low) {
          r.low_open = *found->second.first == r.low ? (r.low_open || low_strict) : low_strict;
          r.low = *found->second.first;
        }
        if (found->second.second && *found->second.second <= r.high) {
          r.high_open =
              *found->second.second == r.high ? (r.high_open || high_strict) : high_strict;
          r.high = *found->second.second;
        }
      }
      return r;
    }
    if (is_a<GiNaC::add>(x)) {
      Range r = point(0);
      for (std::size_t i = 0; i < x.nops(); ++i) {
        r = range_sum(r, range(x.op(i)));
      }
      return r;
    }
    if (is_a<GiNaC::mul>(x)) {
      Range r = point(1);
      for (std::size_t i = 0; i < x.nops(); ++i) {
        r = multiply(r, range(x.op(i)));
      }
      return r;
    }
    if (is_a<GiNaC::power>(x) && x.op(1).info(GiNaC::info_flags::integer)) {
      const long k = GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_long();
      if (k > 12 || k < -12) {
        return {};
      }
      const Range base = range(x.op(0));
      return k >= 0 ? integer_power(base, k) : inverse(integer_power(base, -k));
    }
    if (sym::is_function(x, "sin") || sym::is_function(x, "cos") || sym::is_function(x, "tan")) {
      const char function = sym::is_function(x, "sin")   ? 's'
                            : sym::is_function(x, "cos") ? 'c'
                                                         : 't';
      Range a = range(x.op(0));
      const auto [exact_low, exact_high] = exact_wave_ends(x.op(0), function, a.low, a.high);
      if (exact_low || exact_high) {
        // An exact end is reached as the symbol's own end is: the argument's, moved outward
        // for rounding, is open (0 < θ ≤ π/6 reaches cos 3θ = 0).
        const std::optional<Affine> affine = affine_in_symbol(x.op(0));  // (exact ends: it is)
        const Range own = range(affine->symbol);
        const bool rising = affine->c.is_positive();
        a.low_open = rising ? own.low_open : own.high_open;
        a.high_open = rising ? own.high_open : own.low_open;
      }
      return function == 't' ? tangent(a, exact_low, exact_high)
                             : wave(a, function == 'c', exact_low, exact_high);
    }
    if (sym::is_function(x, "log")) {
      const Range a = range(x.op(0));
      if (a.low < 0 || (a.low == 0 && !a.low_open)) {
        return {};
      }
      const auto log_down = [](double v) { return v == 1 ? 0.0 : down(std::log(v)); };
      const auto log_up = [](double v) { return v == 1 ? 0.0 : up(std::log(v)); };
      return {a.low == 0 ? -infinity : log_down(a.low),
              a.high == infinity ? infinity : log_up(a.high), a.low_open, a.high_open};
    }
    if (sym::is_function(x, "abs")) {
      return magnitude_range(range(x.op(0)));
    }
    if (sym::is_function(x, "exp")) {
      return exponential_range(range(x.op(0)));
    }
    return {};
  };
  return sign_of(range(e));
}

std::pair<std::optional<double>, std::optional<double>> Facts::exact_wave_ends(
    const ex& argument, char function, double low_end, double high_end) const {
  const auto near = [](const std::optional<std::pair<double, double>>& end,
                       double at) -> std::optional<double> {
    if (!end || std::abs(end->first - at) > 1e-10 * (1 + std::abs(at))) {
      return std::nullopt;
    }
    return end->second;
  };
  for (const WaveEnds& known : wave_ends_) {
    if (known.function == function && known.argument.is_equal(argument)) {
      return {near(known.low, low_end), near(known.high, high_end)};
    }
  }
  WaveEnds ends{argument, function, std::nullopt, std::nullopt};
  const std::optional<Affine> affine = affine_in_symbol(argument);
  const auto found = affine ? exact_bounds_.find(affine->symbol) : exact_bounds_.end();
  if (found != exact_bounds_.end()) {
    const GiNaC::numeric& c = affine->c;
    // The value at c times an exact bound plus d, where it is a number a double holds, and where
    // that is: the argument's end must be there (not at a bound another fact made tighter).
    const auto value =
        [&](const std::optional<ex>& end) -> std::optional<std::pair<double, double>> {
      if (!end) {
        return std::nullopt;
      }
      const ex at = c * *end + affine->d;
      const ex where = GiNaC::evalf(at);
      ex v;
      try {
        v = function == 'c' ? GiNaC::cos(at) : function == 's' ? GiNaC::sin(at) : GiNaC::tan(at);
      } catch (const std::exception&) {
        return std::nullopt;  // tan at a pole (π/2)
      }
      if (!is_a<GiNaC::numeric>(where) || !is_a<GiNaC::numeric>(v) ||
          !GiNaC::ex_to<GiNaC::numeric>(v).is_rational()) {
        return std::nullopt;
      }
      const Range r = number_range(GiNaC::ex_to<GiNaC::numeric>(v));
      if (r.low != r.high) {
        return std::nullopt;
      }
      return std::pair{GiNaC::ex_to<GiNaC::numeric>(where).to_double(), r.low};
    };
    const auto& [low, high] = found->second;
    ends.low = value(c.is_positive() ? low : high);
    ends.high = value(c.is_positive() ? high : low);
  }
  if (wave_ends_.size() < 64) {
    wave_ends_.push_back(ends);
  }
  return {near(ends.low, low_end), near(ends.high, high_end)};
}

bool Facts::nonzero(const ex& e) const {
  const Sign s = sign(e);
  return strict(s) || s == Sign::nonzero;
}

std::pair<std::optional<double>, std::optional<double>> Facts::bounds(const ex& symbol) const {
  const auto found = bounds_.find(symbol);
  return found == bounds_.end() ? std::pair<std::optional<double>, std::optional<double>>{}
                                : found->second;
}

std::pair<std::optional<ex>, std::optional<ex>> Facts::exact_bounds(const ex& symbol) const {
  const auto found = exact_bounds_.find(symbol);
  return found == exact_bounds_.end() ? std::pair<std::optional<ex>, std::optional<ex>>{}
                                      : found->second;
}

std::pair<std::optional<Facts::End>, std::optional<Facts::End>> Facts::exact_ends(
    const ex& symbol) const {
  const auto [low_bound, high_bound] = exact_bounds(symbol);
  const Sign sign = of_symbol(symbol);
  const auto end = [&](const std::optional<ex>& bound, bool high) -> std::optional<End> {
    const bool from_sign = high ? (sign == Sign::negative || sign == Sign::nonpositive)
                                : (sign == Sign::positive || sign == Sign::nonnegative);
    const bool sign_strict = sign == Sign::positive || sign == Sign::negative;
    const ex value = bound ? GiNaC::evalf(*bound) : ex(0);
    if (bound && is_a<GiNaC::numeric>(value)) {
      const double b = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
      if (!from_sign || (high ? b < 0 : b > 0)) {
        return End{*bound, strict_bound(symbol, high)};
      }
      if (b == 0) {
        return End{ex(0), sign_strict || strict_bound(symbol, high)};
      }
    }
    if (from_sign) {
      return End{ex(0), sign_strict};
    }
    return std::nullopt;
  };
  return {end(low_bound, false), end(high_bound, true)};
}

std::optional<std::pair<ex, GiNaC::numeric>> multiple_of_symbol(const ex& argument) {
  const std::optional<Affine> affine = affine_in_symbol(argument);
  if (!affine || !affine->d.is_zero()) {
    return std::nullopt;
  }
  return std::pair{affine->symbol, affine->c};
}

std::optional<Affine> affine_in_symbol(const ex& argument) {
  // The constant terms of a sum (numbers, and terms with π that are real numbers in 40 digits) are
  // d; what is left must be one term c x.
  ex rest = argument;
  ex d = 0;
  if (is_a<GiNaC::add>(argument)) {
    rest = 0;
    for (std::size_t i = 0; i < argument.nops(); ++i) {
      const ex& term = argument.op(i);
      const std::optional<GiNaC::numeric> value = is_a<GiNaC::numeric>(term) || term.has(GiNaC::Pi)
                                                      ? value_in_40_digits(term)
                                                      : std::nullopt;
      if (value && value->is_real()) {
        d += term;
      } else {
        rest += term;
      }
    }
  }
  ex symbol = rest;
  GiNaC::numeric c = 1;
  if (is_a<GiNaC::mul>(rest) && rest.nops() == 2 && is_a<GiNaC::numeric>(rest.op(1))) {
    symbol = rest.op(0);
    c = GiNaC::ex_to<GiNaC::numeric>(rest.op(1));
  }
  if (!is_a<GiNaC::symbol>(symbol) || !c.is_rational() || c.is_zero()) {
    return std::nullopt;
  }
  return Affine{symbol, c, d};
}

bool Facts::strict_bound(const ex& symbol, bool high) const {
  const auto found = strict_.find(symbol);
  return found != strict_.end() && (high ? found->second.second : found->second.first);
}

bool Facts::satisfied(const ex& symbol, const GiNaC::numeric& value) const {
  bool ok = has_sign(value, of_symbol(symbol));
  if (const auto found = bounds_.find(symbol); ok && found != bounds_.end()) {
    const double v = value.to_double();
    const auto [low_strict, high_strict] = strict_.at(symbol);
    const auto& [low, high] = found->second;
    ok = (!low || v > *low || (!low_strict && v == *low)) &&
         (!high || v < *high || (!high_strict && v == *high));
  }
  return ok;
}

namespace {

// The value of @p e at @p at, when it is a real number there.
std::optional<GiNaC::numeric> judged(const ex& e, const GiNaC::exmap& at) {
  const ex value = GiNaC::evalf(e.subs(at));
  if (!is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real()) {
    return std::nullopt;
  }
  return GiNaC::ex_to<GiNaC::numeric>(value);
}

}  // namespace

bool Facts::relations_hold(const GiNaC::exmap& at, bool all_judged) const {
  for (const auto& [r, sign] : relations_) {
    const auto v = judged(r, at);
    if (!v) {
      if (all_judged) {
        return false;
      }
      continue;
    }
    if (!has_sign(*v, sign)) {
      return false;
    }
  }
  return true;
}

bool Facts::extends(const GiNaC::exmap& point) const {
  GiNaC::lst missing;
  for (const auto& [r, sign] : relations_) {
    if (judged(r, point)) {
      continue;
    }
    for (GiNaC::const_preorder_iterator it = r.preorder_begin(); it != r.preorder_end(); ++it) {
      if (is_a<GiNaC::symbol>(*it) && point.find(*it) == point.end() &&
          std::find(missing.begin(), missing.end(), *it) == missing.end()) {
        missing.append(*it);
      }
    }
  }
  if (missing.nops() == 0) {
    return true;
  }
  if (missing.nops() > 2) {
    return false;  // not searched: the point cannot be vouched for
  }
  // A few values each, between and beyond the usual magnitudes.
  static const std::vector<GiNaC::numeric> tried{0,
                                                 1,
                                                 -1,
                                                 2,
                                                 -2,
                                                 GiNaC::numeric(1, 2),
                                                 GiNaC::numeric(-1, 2),
                                                 5,
                                                 -5,
                                                 20,
                                                 -20,
                                                 GiNaC::numeric(1, 10),
                                                 GiNaC::numeric(-1, 10),
                                                 100,
                                                 -100};
  const std::size_t second = missing.nops() == 2 ? tried.size() : 1;
  for (std::size_t i = 0; i < tried.size(); ++i) {
    for (std::size_t j = 0; j < second; ++j) {
      GiNaC::exmap at = point;
      at[missing.op(0)] = tried[i];
      bool own = satisfied(missing.op(0), tried[i]);
      if (missing.nops() == 2) {
        at[missing.op(1)] = tried[j];
        own = own && satisfied(missing.op(1), tried[j]);
      }
      if (own && relations_hold(at, true)) {
        return true;
      }
    }
  }
  return false;
}

std::optional<GiNaC::numeric> value_in_40_digits(const ex& value) {
  if (is_a<GiNaC::numeric>(value)) {
    return GiNaC::ex_to<GiNaC::numeric>(value);
  }
  const long saved = GiNaC::Digits;
  GiNaC::Digits = 40;
  const ex f = GiNaC::evalf(value);
  GiNaC::Digits = saved;
  if (!is_a<GiNaC::numeric>(f)) {
    return std::nullopt;
  }
  return GiNaC::ex_to<GiNaC::numeric>(f);
}

bool certainly_nonzero(const ex& value) {
  const std::optional<GiNaC::numeric> v = value_in_40_digits(value);
  return v && v->is_real() && !v->is_zero() &&
         (v->is_rational() || GiNaC::abs(*v) > GiNaC::numeric(10).power(-20));
}

bool Facts::satisfied(const GiNaC::exmap& point) const {
  // Every relation holds at the point; a relation in symbols the point does not give (b of
  // a < b < c, where a counterexample names a and c) must hold for some values of them, with
  // their own facts: else a = 1, c = -1 passed for a counterexample.
  if (!relations_hold(point, false) || !extends(point)) {
    return false;
  }
  for (const ex& q : equalities_) {
    if (certainly_nonzero(GiNaC::normal(q.subs(point)))) {
      return false;
    }
  }
  return true;
}

namespace {

// Whether a double has a sign, a strict sign only beyond @p clear (has_sign of a number, above,
// with rounding allowed for).
bool has_sign(double v, Sign sign, double clear) {
  return sign == Sign::positive      ? v > clear
         : sign == Sign::negative    ? v < -clear
         : sign == Sign::nonnegative ? v >= 0
         : sign == Sign::nonpositive ? v <= 0
         : sign == Sign::nonzero     ? std::abs(v) > clear
                                     : true;
}

}  // namespace

bool Facts::satisfied_numerically(const std::vector<ex>& symbols,
                                  const std::vector<double>& values) const {
  // Each symbol's own sign, as Facts::satisfied asks of a number (its bounds are relations): the
  // sampler draws a symbol by its sign and the solver keeps the roots that have it; this holds it
  // whatever drew the point.
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (!has_sign(values[i], of_symbol(symbols[i]), 0.0)) {
      return false;
    }
  }
  if (relations_.empty() && equalities_.empty()) {
    return true;
  }
  GiNaC::exmap point;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    point[symbols[i]] = values[i];
  }
  const auto value_of = [&](const ex& e) -> std::optional<double> {
    const ex v = GiNaC::evalf(e.subs(point));
    if (!is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
      return std::nullopt;
    }
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  };
  // A strict fact's expression at rounding level from 0 is on its boundary, which the fact leaves
  // out (as a denominator there is): m_1 > m_2 with m_1 solved from (m_1 - m_2)(u - w) = 0 gave
  // m_1 - m_2 = 1e-17 > 0, and a point where u = w fails.
  constexpr double clear = 1e-9;
  for (const auto& [r, sign] : relations_) {
    const auto v = value_of(r);
    if (v && !has_sign(*v, sign, clear)) {
      return false;
    }
  }
  for (const ex& q : equalities_) {
    const auto v = value_of(q);
    if (v && std::abs(*v) > 1e-9) {
      return false;
    }
  }
  return true;
}

}  // namespace impulse::derivations::file
