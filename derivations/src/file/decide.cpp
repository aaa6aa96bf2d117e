// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/decide.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::numeric;
// Not "Outcome": in a unity build this file shares a translation unit with the paper runner,
// whose Outcome is the check report's.
using Implied = Implication::Outcome;

namespace {

double counted_terms(const ex& e) {
  constexpr double cap = 1e12;
  if (is_a<GiNaC::add>(e)) {
    double sum = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      sum += counted_terms(e.op(i));
    }
    return std::min(sum, cap);
  }
  if (is_a<GiNaC::mul>(e)) {
    double product = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      product = std::min(product * counted_terms(e.op(i)), cap);
    }
    return product;
  }
  if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) &&
      GiNaC::ex_to<numeric>(e.op(1)).is_integer()) {
    const double base = counted_terms(e.op(0));
    const double n = std::abs(GiNaC::ex_to<numeric>(e.op(1)).to_double());
    if (base <= 1) {
      return 1;
    }
    // Terms of (t_1 + … + t_b)^n: at most C(n + b - 1, b - 1), and never more than b^n.
    double count = 1;
    const double k = std::min(n, base - 1);
    for (double j = 1; j <= k; ++j) {
      count = std::min(count * (n + base - 1 - (k - j)) / j, cap);
    }
    return std::min(count, std::pow(base, n) < cap ? std::pow(base, n) : cap);
  }
  return 1;
}

}  // namespace

double expanded_terms(const ex& e) {
  if (e.nops() == 0) {
    return 1;  // a symbol or a number
  }
  // Remembered: the exact method bounds its work by the terms of the same premises and targets
  // again and again, and a walk over a large expression costs more than looking it up.
  thread_local sym::Remembered<double> counted;
  if (const double* found = counted.find(e)) {
    return *found;
  }
  return counted.keep(e, counted_terms(e));
}

namespace {

// Whether GiNaC's factoring is bounded on @p e (see factorable: the time grows fast with the
// variables, their order and the degree): at most 200 terms in at most 6 symbols, of a total
// degree at most 24 in those it is a polynomial in.
bool in_factoring_bounds(const ex& e) {
  if (expanded_terms(e) > 200) {
    return false;
  }
  const std::vector<ex> symbols = symbols_of(e);
  if (symbols.size() > 6) {
    return false;
  }
  int total = 0;
  for (const ex& s : symbols) {
    if (e.is_polynomial(s)) {
      total += e.degree(s);
    }
  }
  return total <= 24;
}

}  // namespace

namespace {

const GiNaC::symbol& pi_symbol() {
  thread_local const GiNaC::symbol pi("\\pi");
  return pi;
}

}  // namespace

ex pi_as_symbol(const ex& e) {
  return e.has(GiNaC::Pi) ? e.subs(GiNaC::Pi == pi_symbol()) : e;
}

ex symbol_as_pi(const ex& e) {
  return e.has(pi_symbol()) ? e.subs(pi_symbol() == GiNaC::Pi) : e;
}

namespace {

// The highest power of each symbol in the terms of an expanded sum (a symbol inside a function or
// under a root is not counted: such a sum is no polynomial, and divides nothing). One walk over
// the terms: GiNaC's degree() once per symbol of the divisor, after collecting its symbols, cost
// more than the long division it was there to spare (210 against 60 million instructions on the
// paper check).
std::map<ex, int, GiNaC::ex_is_less> highest_powers(const ex& expanded) {
  std::map<ex, int, GiNaC::ex_is_less> powers;
  const auto factor = [&](const ex& f) {
    if (is_a<GiNaC::symbol>(f)) {
      powers[f] = std::max(powers[f], 1);
    } else if (is_a<GiNaC::power>(f) && is_a<GiNaC::symbol>(f.op(0)) &&
               f.op(1).info(GiNaC::info_flags::posint)) {
      powers[f.op(0)] = std::max(powers[f.op(0)], GiNaC::ex_to<numeric>(f.op(1)).to_int());
    }
  };
  const auto term = [&](const ex& t) { sym::for_each_factor(t, factor); };
  sym::for_each_term(expanded, term);
  return powers;
}

}  // namespace

std::optional<ex> exact_quotient(const ex& dividend, const ex& divisor) {
  try {
    const ex a = GiNaC::expand(dividend);
    const ex b = GiNaC::expand(divisor);
    // A quick no before the long division: a polynomial b divides a polynomial a ≠ 0 only if a
    // has each of b's symbols to at least b's power (exact powers: both are expanded). Where
    // either is no polynomial, the division below says no as well.
    if (!is_a<numeric>(b) && !a.is_zero() && !a.is_equal(b)) {
      for (const auto& [s, power] : highest_powers(b)) {
        if (a.degree(s) < power) {
          return std::nullopt;
        }
      }
    }
    ex quotient;
    if (GiNaC::divide(pi_as_symbol(a), pi_as_symbol(b), quotient)) {
      return symbol_as_pi(quotient);
    }
  } catch (const std::exception&) {
    // not polynomials (a root, a function): no exact division
  }
  return std::nullopt;
}

ex factored(const ex& e) {
  if (expanded_terms(e) > 200) {
    return e;
  }
  if (e.has(GiNaC::Pi)) {
    // θ - π/2 made GiNaC's factoring throw; x^2 - π^2 = (x - π)(x + π).
    return symbol_as_pi(factored(pi_as_symbol(e)));
  }
  const ex parts = GiNaC::numer_denom(e);
  if (!in_factoring_bounds(parts.op(0)) || !in_factoring_bounds(parts.op(1))) {
    return e;  // beyond them, taken as it stands
  }
  const auto tidy = [](const ex& f) {
    if (is_a<GiNaC::power>(f)) {
      return GiNaC::pow(GiNaC::expand(f.op(0)), f.op(1));
    }
    return GiNaC::expand(f);
  };
  const ex product = GiNaC::factor(e);
  if (!is_a<GiNaC::mul>(product)) {
    return tidy(product);
  }
  ex tidied = 1;
  for (std::size_t i = 0; i < product.nops(); ++i) {
    tidied *= tidy(product.op(i));
  }
  return tidied;
}

bool factorable(const ex& e) {
  // GiNaC's factoring (square-free decomposition, then gcds over many variables) takes a time
  // that depends on the order it gives the variables and grows fast with their number: a
  // binomial in 13 symbols took from 0.03 s to 5 s by that order alone. Polynomials of
  // derivations factor in a few symbols once their monomial content is taken out (see
  // doubtful_factors); beyond these bounds a polynomial is taken as it stands.
  const std::vector<ex> symbols = symbols_of(e);
  return in_factoring_bounds(e) && std::all_of(symbols.begin(), symbols.end(),
                                               [&](const ex& s) { return e.is_polynomial(s); });
}

std::vector<ex> doubtful_factors(const ex& e, const Facts& facts) {
  std::vector<ex> factors;
  const auto add = [&](const ex& f) {
    if (is_a<numeric>(f) || facts.nonzero(f)) {
      return;
    }
    for (const ex& known : factors) {
      if (known.is_equal(f) || (-known).expand().is_equal(f.expand())) {
        return;
      }
    }
    factors.push_back(f);
  };
  // The monomial content first (F dt in F dt (…)): each of its symbols is a factor, found
  // without factoring; then the rest, factored when that is cheap.
  ex rest = GiNaC::expand(e);
  if (!rest.is_zero() && rest.info(GiNaC::info_flags::polynomial)) {
    for (const ex& s : symbols_of(rest)) {
      if (rest.is_polynomial(s) && rest.ldegree(s) > 0) {
        add(s);
        rest = GiNaC::expand(GiNaC::normal(rest / GiNaC::pow(s, rest.ldegree(s))));
      }
    }
  }
  const ex product = factorable(rest) ? factored(rest) : rest;
  const auto one = [&](const ex& f) {
    if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1))) {
      // b^k is 0 where b is, and b where its numerator is (√(x²/(x² + y²)), which
      // cos(arctan(y/x)) becomes, where x is); b^-k never is.
      if (!GiNaC::ex_to<numeric>(f.op(1)).is_negative()) {
        for (const ex& g : doubtful_factors(safe_numerator(f.op(0)), facts)) {
          add(g);
        }
      }
    } else {
      add(f);
    }
  };
  sym::for_each_factor(product, one);
  return factors;
}

namespace {

// Whether e holds what the facts may simplify: a power with an exponent that is not a whole
// number (a root, b^n), a logarithm, an exponential, an absolute value or a hyperbolic function.
bool needs_facts(const ex& e) {
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (is_a<GiNaC::power>(*i) && !i->op(1).info(GiNaC::info_flags::integer)) {
      return true;
    }
    if (is_a<GiNaC::function>(*i)) {
      const std::string& name = GiNaC::ex_to<GiNaC::function>(*i).get_name();
      if (name == "log" || name == "exp" || name == "abs" || name == "sinh" || name == "cosh" ||
          name == "tanh" || name == "asin" || name == "acos" || name == "atan") {
        return true;
      }
    }
  }
  return false;
}

bool positive(const ex& e, const Facts& facts) {
  return facts.sign(e) == Sign::positive;
}

// A positive rational as its prime factors below 10^4 with their powers (negative for the
// denominator's); what is left of the numerator or the denominator stays one factor.
std::vector<std::pair<numeric, long>> prime_powers(const numeric& q) {
  std::vector<std::pair<numeric, long>> powers;
  const auto add = [&](numeric n, long sign) {
    for (long p = 2; p < 10000 && n > 1; ++p) {
      long k = 0;
      while (GiNaC::mod(n, p).is_zero()) {
        n = n / p;
        ++k;
      }
      if (k > 0) {
        powers.emplace_back(numeric(p), sign * k);
      }
    }
    if (n > 1) {
      powers.emplace_back(n, sign);
    }
  };
  add(q.numer(), 1);
  add(q.denom(), -1);
  return powers;
}

// ln q of a positive rational q as a sum of its prime factors' logarithms, so that ln 8 meets
// 3 ln 2 and ln 6 meets ln 2 + ln 3.
ex rational_logarithm(const numeric& q) {
  ex sum = 0;
  for (const auto& [p, k] : prime_powers(q)) {
    sum += k * GiNaC::log(ex(p));  // as ex: the logarithm of a numeric alone is a float
  }
  return sum;
}

// q^r of a positive rational q and a rational r as its prime factors' powers, so that
// √(10/7) √(7/10) meets 1 and √6 meets √2 √3.
ex rational_root(const numeric& q, const numeric& r) {
  ex product = 1;
  for (const auto& [p, k] : prime_powers(q)) {
    product *= GiNaC::pow(ex(p), ex(k * r));  // as ex: a power of numerics alone is a float
  }
  return product;
}

// ln a, with the logarithm of a product of positive factors written as a sum, of a positive
// base's power as the power times its logarithm, of an exponential as its argument, and of a
// positive rational as its prime factors'.
ex logarithm(const ex& a, const Facts& facts) {
  if (is_a<numeric>(a) && GiNaC::ex_to<numeric>(a).is_rational() &&
      GiNaC::ex_to<numeric>(a).is_positive()) {
    return rational_logarithm(GiNaC::ex_to<numeric>(a));
  }
  if (is_a<GiNaC::mul>(a)) {
    bool all = true;
    for (std::size_t i = 0; i < a.nops() && all; ++i) {
      all = positive(a.op(i), facts);
    }
    if (all) {
      ex sum = 0;
      for (std::size_t i = 0; i < a.nops(); ++i) {
        sum += logarithm(a.op(i), facts);
      }
      return sum;
    }
  }
  if (is_a<GiNaC::power>(a) && positive(a.op(0), facts)) {
    return a.op(1) * logarithm(a.op(0), facts);
  }
  // ln(b^(2k)) = 2k ln|b| for any real b ≠ 0 (where b = 0, neither is defined).
  if (is_a<GiNaC::power>(a) && a.op(1).info(GiNaC::info_flags::even)) {
    return a.op(1) * logarithm(GiNaC::abs(a.op(0)), facts);
  }
  if (sym::is_function(a, "exp")) {
    return a.op(0);
  }
  return GiNaC::log(a);
}

// |a|: a or -a where the facts give a's sign, a product's as the product of its factors', an
// even power's as the power.
ex magnitude(const ex& a, const Facts& facts) {
  const Sign s = facts.sign(a);
  if (s == Sign::positive || s == Sign::nonnegative || s == Sign::zero) {
    return a;
  }
  if (s == Sign::negative || s == Sign::nonpositive) {
    return -a;
  }
  if (is_a<GiNaC::mul>(a)) {
    ex product = 1;
    for (std::size_t i = 0; i < a.nops(); ++i) {
      product *= magnitude(a.op(i), facts);
    }
    return product;
  }
  if (is_a<GiNaC::power>(a) && a.op(1).info(GiNaC::info_flags::even)) {
    return a;
  }
  if (is_a<GiNaC::add>(a) && expanded_terms(a) <= 50) {
    // A sum's factors each come out (|-e m v - m v| is m (1 + e) |v| for m > 0, e ≥ 0), and of
    // x and -x one stands for both (|v_f - v_i| meets |v_i - v_f|).
    try {
      if (const ex f = factored(a); is_a<GiNaC::mul>(f)) {
        return magnitude(f, facts);
      }
    } catch (const std::exception&) {
    }
    const ex minus = GiNaC::expand(-a);
    return GiNaC::abs(GiNaC::ex_is_less()(minus, a) ? minus : a);
  }
  return GiNaC::abs(a);
}

// e^y, with a sum in y as a product of exponentials and e^{k \ln x} as x^k (x > 0).
ex exponential(const ex& y, const Facts& facts) {
  const ex expanded = GiNaC::expand(y);
  const auto one = [&](const ex& term) -> ex {
    // k ln x: x^k
    ex k = 1;
    std::optional<ex> argument;
    const auto factor = [&](const ex& f) {
      if (sym::is_function(f, "log") && !argument && positive(f.op(0), facts)) {
        argument = f.op(0);
      } else {
        k *= f;
      }
    };
    sym::for_each_factor(term, factor);
    return argument ? GiNaC::pow(*argument, k) : GiNaC::exp(term);
  };
  if (is_a<GiNaC::add>(expanded)) {
    ex product = 1;
    for (std::size_t i = 0; i < expanded.nops(); ++i) {
      product *= one(expanded.op(i));
    }
    return product;
  }
  return one(expanded);
}

// (Π f^k)^(p/q): each factor the facts keep positive comes out as f^(k p/q), and each whose power
// k is a multiple of q as |f|^(k p/q), the absolute value dropped where the facts give f's sign.
ex root_taken(const ex& given_base, const numeric& exponent, const Facts& facts) {
  // A polynomial under the root factored where that is cheap: M^2 + 2 M m + m^2 is (M + m)^2. A
  // sum of fractions over one denominator first, its numerator and denominator factored:
  // 1 - 4τ/(1 + τ²) is (1 + τ² - 4τ)/(1 + τ²), whose factors' signs the facts may know (GiNaC's
  // normal() takes (x)^(-1/2) as (1/x)^(1/2), which is false for x < 0: the root must be taken
  // here, by the facts, before it).
  const auto in_factors = [](const ex& f) {
    if (!is_a<GiNaC::add>(f)) {
      return f;
    }
    try {
      if (factorable(f)) {
        return factored(f);
      }
      if (f.info(GiNaC::info_flags::rational_function) && expanded_terms(f) <= 60) {
        const ex parts = GiNaC::numer_denom(GiNaC::normal(f));
        if (factorable(parts.op(0)) && factorable(parts.op(1))) {
          return factored(parts.op(0)) / factored(parts.op(1));
        }
      }
    } catch (const std::exception&) {
    }
    return f;
  };
  ex base = 1;
  const auto each = [&](const ex& f) {
    if (is_a<GiNaC::power>(f)) {
      base *= GiNaC::pow(in_factors(f.op(0)), f.op(1));
    } else {
      base *= in_factors(f);
    }
  };
  sym::for_each_factor(given_base, each);
  const numeric q = exponent.denom();
  ex outside = 1;
  ex inside = 1;
  const auto one = [&](const ex& factor) {
    // A factor the facts keep positive comes out whatever its power: (k/m)^(1/2) is
    // k^(1/2) m^(-1/2) for k, m > 0 (the principal root of f g is f's times g's when f > 0).
    const bool power = is_a<GiNaC::power>(factor) && is_a<numeric>(factor.op(1)) &&
                       GiNaC::ex_to<numeric>(factor.op(1)).is_rational();
    const ex base_of = power ? factor.op(0) : factor;
    // A symbol the facts keep at least 0 comes out of a root too: √(x y) = √x √y for x, y ≥ 0.
    const Sign sign = facts.sign(base_of);
    const bool out =
        sign == Sign::positive || (sign == Sign::nonnegative && is_a<GiNaC::symbol>(factor) &&
                                   GiNaC::ex_to<numeric>(exponent).is_positive());
    if ((power || !is_a<numeric>(factor)) && out) {
      outside *= GiNaC::pow(base_of, (power ? factor.op(1) : ex(1)) * exponent);
      return;
    }
    // Under an even root, f^k with -f > 0 and k odd is -(-f)^k: (-f)^k comes out and its sign
    // stays inside (an odd root is the real one, below). GiNaC writes an integer power of a
    // difference with the sign its term order gives, an order that follows addresses:
    // 1/(m_1 - m_2) is -(m_2 - m_1)^(-1) in some runs, and its root under m_1 > m_2 was left
    // whole in those.
    if (const ex k = power ? factor.op(1) : ex(1);
        q.is_even() && !is_a<numeric>(base_of) && is_a<numeric>(k) &&
        GiNaC::ex_to<numeric>(k).is_odd() && facts.sign(-base_of) == Sign::positive) {
      outside *= GiNaC::pow(-base_of, k * exponent);
      inside *= -1;
      return;
    }
    if (is_a<GiNaC::power>(factor) && is_a<numeric>(factor.op(1)) &&
        GiNaC::ex_to<numeric>(factor.op(1)).is_integer() &&
        GiNaC::mod(GiNaC::ex_to<numeric>(factor.op(1)), q).is_zero()) {
      const ex f = factor.op(0);
      const Sign s = facts.sign(f);
      // An odd root keeps the sign (the real root: (x^3)^(1/3) = x, which |x| was), an even one
      // takes the magnitude.
      const ex magnitude = q.is_odd()                                        ? f
                           : (s == Sign::positive || s == Sign::nonnegative) ? f
                           : (s == Sign::negative || s == Sign::nonpositive) ? ex(-f)
                                                                             : GiNaC::abs(f);
      outside *= GiNaC::pow(magnitude, factor.op(1) * exponent);
    } else {
      inside *= factor;
    }
  };
  sym::for_each_factor(base, one);
  if (outside.is_equal(1)) {
    return GiNaC::pow(given_base, exponent);
  }
  return outside * GiNaC::pow(inside, exponent);
}

// Whether the facts keep the symbol @p u within [low, high] (within (low, high) with @p open):
// its bounds as written (or 0 from its sign) compared exactly.
bool within(const ex& u, const ex& low, const ex& high, bool open, const Facts& facts) {
  if (!is_a<GiNaC::symbol>(u)) {
    return false;
  }
  // Whether an end keeps u on the right side of `limit`.
  const auto keeps = [open](const std::optional<Facts::End>& end, const ex& limit, bool above) {
    if (!end) {
      return false;
    }
    const ex gap = GiNaC::evalf(above ? end->at - limit : limit - end->at);
    if (!is_a<numeric>(gap)) {
      return false;
    }
    const numeric& g = GiNaC::ex_to<numeric>(gap);
    return g.is_positive() || (g.is_zero() && (end->strict || !open));
  };
  const auto ends = facts.exact_ends(u);
  return keeps(ends.first, low, true) && keeps(ends.second, high, false);
}

// Whether the facts keep the symbol @p u on the range where @p function (sin, cos or tan) is
// one-to-one, its inverse's own range: arcsin's [-π/2, π/2], arccos' [0, π], arctan's
// (-π/2, π/2).
bool on_inverse_range(const std::string& function, const ex& u, const Facts& facts) {
  const ex half = GiNaC::Pi / 2;
  return (function == "sin" && within(u, -half, half, false, facts)) ||
         (function == "cos" && within(u, 0, GiNaC::Pi, false, facts)) ||
         (function == "tan" && within(u, -half, half, true, facts));
}

// arcsin(sin u) = u, arccos(cos u) = u, arctan(tan u) = u for a symbol u the facts keep on the
// inverse's own range.
std::optional<ex> inverse_of_own(const ex& x, const Facts& facts) {
  if (!is_a<GiNaC::function>(x) || x.nops() != 1 || !is_a<GiNaC::function>(x.op(0)) ||
      x.op(0).nops() != 1) {
    return std::nullopt;
  }
  const std::string& outer = GiNaC::ex_to<GiNaC::function>(x).get_name();
  const std::string& inner = GiNaC::ex_to<GiNaC::function>(x.op(0)).get_name();
  const ex u = x.op(0).op(0);
  const bool own = outer == "a" + inner && on_inverse_range(inner, u, facts);
  return own ? std::optional<ex>(u) : std::nullopt;
}

}  // namespace

ex by_facts(const ex& e, const Facts& facts) {
  if (e.nops() == 0 || !needs_facts(e)) {
    return e;
  }
  const ex x = sym::map_parts(e, [&facts](const ex& part) { return by_facts(part, facts); });
  if (is_a<GiNaC::power>(x)) {
    const ex base = x.op(0);
    const ex exponent = x.op(1);
    // (b^k)^n = b^(k n) for b > 0.
    if (is_a<GiNaC::power>(base) && positive(base.op(0), facts)) {
      return by_facts(GiNaC::pow(base.op(0), base.op(1) * exponent), facts);
    }
    // b^y with y no number, b > 0: e^{y \ln b}, so that logarithms and exponentials meet.
    if (!is_a<numeric>(exponent) && positive(base, facts)) {
      return exponential(exponent * logarithm(base, facts), facts);
    }
    if (is_a<numeric>(exponent) && !GiNaC::ex_to<numeric>(exponent).is_integer() &&
        GiNaC::ex_to<numeric>(exponent).is_rational()) {
      for (const ex& q : facts.equalities()) {
        // √(n_x² + n_y²) of a unit vector n: the radicand is a number by the equality.
        if (const ex rest = GiNaC::expand(base - q); is_a<numeric>(rest) && !base.is_equal(rest)) {
          return by_facts(GiNaC::pow(rest, exponent), facts);
        }
      }
      if (is_a<numeric>(base) && GiNaC::ex_to<numeric>(base).is_rational() &&
          GiNaC::ex_to<numeric>(base).is_positive()) {
        return rational_root(GiNaC::ex_to<numeric>(base), GiNaC::ex_to<numeric>(exponent));
      }
      // An odd root of a negative rational is the real one, as a student means it:
      // (-8)^(1/3) = -2, (-8)^(2/3) = 4.
      const numeric r = GiNaC::ex_to<numeric>(exponent);
      if (is_a<numeric>(base) && GiNaC::ex_to<numeric>(base).is_rational() &&
          GiNaC::ex_to<numeric>(base).is_negative() && r.denom().is_odd()) {
        const ex root = rational_root(-GiNaC::ex_to<numeric>(base), r);
        return r.numer().is_odd() ? ex(-root) : root;
      }
      return root_taken(base, GiNaC::ex_to<numeric>(exponent), facts);
    }
    return x;
  }
  if (sym::is_function(x, "log")) {
    return logarithm(x.op(0), facts);
  }
  if (sym::is_function(x, "exp")) {
    return exponential(x.op(0), facts);
  }
  if (sym::is_function(x, "abs")) {
    return magnitude(x.op(0), facts);
  }
  if (const auto inverse = inverse_of_own(x, facts)) {
    return *inverse;
  }
  // The hyperbolic functions as the exponentials they are, so that cosh² - sinh² meets 1.
  if (is_a<GiNaC::function>(x) && x.nops() == 1) {
    const std::string& name = GiNaC::ex_to<GiNaC::function>(x).get_name();
    if (name == "sinh" || name == "cosh" || name == "tanh") {
      const ex up = exponential(x.op(0), facts);
      const ex down = exponential(-x.op(0), facts);
      return name == "sinh"   ? (up - down) / 2
             : name == "cosh" ? (up + down) / 2
                              : (up - down) / (up + down);
    }
  }
  return x;
}

ex safe_numerator(const ex& e, double terms) {
  // Remembered: the exact method asks again for the numerators of the same premises at each
  // step of a file and in each variant of a check, and normal() (a gcd at every fraction) is the
  // costliest call it makes. normal() depends on its argument alone, so a remembered numerator is
  // the one it would compute again (kept with the bound it was asked for).
  thread_local sym::Remembered<std::pair<double, ex>> numerators;
  if (const auto* found = numerators.find(e); found != nullptr && found->first == terms) {
    return found->second;
  }
  ex numerator = expanded_terms(e) > terms ? e : GiNaC::normal(e).numer();
  return numerators.keep(e, {terms, std::move(numerator)}).second;
}

namespace {

// @p base as k/X, with k > 0 a number or what the facts keep positive (1/y, 4/y,
// (1 + τ²)/(τ² - 4τ + 1)): k and X; else nothing. A k the facts keep negative goes into X with its
// sign: GiNaC writes 1/(m_1 - m_2) as -1/(m_2 - m_1) when its order of terms (which follows
// addresses) puts m_2 first.
std::optional<std::pair<ex, ex>> over_something(const ex& base, const Facts& facts) {
  std::optional<ex> under;
  ex k = 1;
  const auto one = [&](const ex& f) {
    if (is_a<GiNaC::power>(f) && f.op(1).is_equal(-1) && !is_a<numeric>(f.op(0)) && !under) {
      under = f.op(0);
    } else {
      k *= f;
    }
  };
  sym::for_each_factor(base, one);
  if (!under) {
    return std::nullopt;
  }
  const Sign sign = facts.sign(k);
  if (sign == Sign::positive) {
    return std::pair{k, *under};
  }
  if (sign == Sign::negative) {
    return std::pair{ex(-k), ex(-*under)};
  }
  return std::nullopt;
}

// @p base with @p value put for @p symbol, over one denominator where that is small: b + 1/x
// put in a - b is 1/x, not x^(-1) (1 + x b) - b.
ex base_put_in(const ex& base, const ex& symbol, const ex& value) {
  const ex put = base.subs(GiNaC::exmap{{symbol, value}});
  if (expanded_terms(put) > 60) {
    return put;
  }
  try {
    return GiNaC::normal(put);
  } catch (const std::exception&) {
    return put;  // a division by zero: as it stands
  }
}

// The first X of @p e such that putting @p value for @p symbol makes a non-integer power of
// k/X (k > 0 a number): GiNaC writes (k/X)^c as k^c X^{-c} at once, which is false for a real
// X < 0 (√(1/X) = i/√|X|, but X^{-1/2} = -i/√|X|), so that x = 1/y would give √x = 1/√y for
// every y. Nothing when there is none.
std::optional<ex> reciprocal_under_power(const ex& e, const ex& symbol, const ex& value,
                                         const Facts& facts) {
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (!is_a<GiNaC::power>(*i) || i->op(1).info(GiNaC::info_flags::integer) ||
        !i->op(0).has(symbol)) {
      continue;
    }
    // The base as it will be, built without evaluating its power.
    if (const auto reciprocal = over_something(base_put_in(i->op(0), symbol, value), facts)) {
      return reciprocal->second;
    }
  }
  return std::nullopt;
}

// @p e with @p value put for @p symbol where @p under < 0: a non-integer power of k/under is
// written k^c (-1)^c (-under)^{-c}, its value there ((k/X)^c = (k/|X|)^c e^{iπc} for X < 0),
// which GiNaC leaves as it is.
ex put_in_below_zero(const ex& e, const ex& symbol, const ex& value, const ex& under,
                     const Facts& facts) {
  return sym::rewritten(e, [&](const ex& part) -> std::optional<ex> {
    if (!part.has(symbol)) {
      return part;
    }
    if (part.nops() == 0) {
      return part.subs(GiNaC::exmap{{symbol, value}});
    }
    if (is_a<GiNaC::power>(part) && !part.op(1).info(GiNaC::info_flags::integer)) {
      const auto reciprocal = over_something(base_put_in(part.op(0), symbol, value), facts);
      if (reciprocal && reciprocal->second.is_equal(under)) {
        const ex c = part.op(1).subs(GiNaC::exmap{{symbol, value}});
        return GiNaC::pow(reciprocal->first, c) * GiNaC::pow(-1, c) * GiNaC::pow(-under, -c);
      }
    }
    return std::nullopt;
  });
}

// @p e with the base of every root (a power to a fraction) expanded, inside and out.
ex bases_expanded(const ex& e) {
  const ex inside = sym::map_parts(e, bases_expanded);
  if (is_a<GiNaC::power>(inside) && is_a<numeric>(inside.op(1)) &&
      !inside.op(1).info(GiNaC::info_flags::integer)) {
    return GiNaC::pow(GiNaC::expand(inside.op(0)), inside.op(1));
  }
  return inside;
}

struct Solved {
  ex symbol;
  ex value;
  ex divisor;  // what the value divides by: a point where it vanishes is skipped before the
               // value is evaluated there (GiNaC leaks memory when an evaluation divides by 0)
};

// One state of the search: polynomial premises (each = 0), the target (a rational expression,
// = 0), the substitutions made so far.
struct Frame {
  std::vector<ex> premises;
  ex target;
  std::vector<Solved> solved;
  std::size_t depth = 0;
};

struct Found {
  Implied outcome = Implied::unknown;
  std::vector<ex> conditions;
  bool conditions_needed = true;
  ex residual;
  std::optional<GiNaC::exmap> point;  // fails; holds_if: where a condition is 0, if found
  std::vector<std::string> how;
};

ex numerator(const ex& e) {
  return safe_numerator(e);
}

// Whether a root (a power to a fraction) stands in @p e.
bool has_root(const ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is_a<GiNaC::power>(*it) && is_a<numeric>(it->op(1)) &&
        !GiNaC::ex_to<numeric>(it->op(1)).is_integer()) {
      return true;
    }
  }
  return false;
}

bool same_up_to_constant(const ex& a, const ex& b) {
  const ex ratio = GiNaC::normal(a / b);
  return is_a<numeric>(ratio);
}

// An expression in a sentence of the report: LaTeX between dollars, as in Markdown.
std::string text(const ex& e) {
  std::string latex = sym::latex(e);
  const std::size_t first = latex.find_first_not_of(' ');
  const std::size_t last = latex.find_last_not_of(' ');
  latex = first == std::string::npos ? "" : latex.substr(first, last - first + 1);
  return "$" + latex + "$";
}

// "$f \neq 0$" in a sentence of the report.
std::string unequal_to_zero(const ex& f) {
  const std::string shown = text(f);
  return shown.substr(0, shown.size() - 1) + " \\neq 0$";
}

class Decider {
 public:
  Decider(const Problem& problem, const Facts& facts, const Budget& budget)
      : problem_(problem), facts_(facts), budget_(budget) {
    std::vector<ex> all{problem.target};
    all.insert(all.end(), problem.premises.begin(), problem.premises.end());
    all.insert(all.end(), problem.premise_denominators.begin(), problem.premise_denominators.end());
    all.insert(all.end(), problem.target_denominators.begin(), problem.target_denominators.end());
    symbols_ = symbols_of(all);
  }

  Found run(Frame frame) {
    if (++frames_ > budget_.frames) {
      return unknown(frame, "the exact search reached its limit of cases");
    }
    if (past(budget_.deadline)) {
      return unknown(frame, "the step's time ran out");
    }
    frame.target = by_facts(frame.target, facts_);
    if (expanded_terms(frame.target) > budget_.terms) {
      return unknown(frame, "the step is too large to expand exactly");
    }
    ex target = numerator(frame.target);
    if (!target.is_zero() && has_root(target) && needs_facts(target)) {
      // Over one denominator the roots may hold new products (√(2 g (1 - (1 - τ²)/(1 + τ²)))
      // became √(τ²/(1 + τ²))): the facts once more.
      target = numerator(by_facts(target, facts_));
    }
    if (target.is_zero()) {
      Found found;
      found.outcome = Implied::holds;
      return found;
    }
    // The premises over one denominator; those that hold everywhere say nothing.
    std::vector<ex> numerators;
    for (const ex& premise : frame.premises) {
      if (expanded_terms(premise) > budget_.terms) {
        return unknown(frame, "an equation before is too large to expand exactly");
      }
      const ex p = numerator(premise);
      if (!p.is_zero()) {
        numerators.push_back(p);
      }
    }
    if (const auto undefined = undefined_premise(frame, numerators)) {
      // x = -b / (2a) with a = 0: no point of this case is one where the equations before are
      // defined, so it holds nothing against the step.
      Found outside;
      outside.outcome = Implied::holds;
      outside.how.push_back("where " + text(*undefined) +
                            " = 0 the equations before are not defined");
      return outside;
    }
    // The step a multiple of an equation before (the most common step: that equation rewritten,
    // multiplied or divided by a factor): it follows wherever that equation holds. Tried first:
    // it needs no factoring.
    if (auto found = multiple(numerators, target, true)) {
      return *found;
    }
    // A premise linear in a symbol whose coefficient the facts keep from zero: substitute it
    // (before any factoring, which costs more).
    if (const auto choice = best_linear(numerators, frame.target, true)) {
      return eliminate(frame, numerators, *choice);
    }
    // The premises as products of doubtful factors.
    std::vector<ex> singles;
    std::optional<std::pair<std::size_t, std::vector<ex>>> split;
    std::vector<ex> in_terms;  // premises split into their terms
    for (const ex& p : numerators) {
      std::vector<ex> factors = doubtful_factors(p, facts_);
      if (factors.empty()) {
        // A non-zero constant, or a product the facts keep from zero: no point satisfies it.
        Found found;
        found.outcome = Implied::holds;
        found.how.push_back("no values satisfy the equations before under the facts");
        return found;
      }
      // A sum of terms of one sign (x² + y², or x + y with x, y ≥ 0) is 0 where each term is:
      // each term's doubtful factors, their product 0 (x² = 0 is x = 0).
      if (factors.size() == 1) {
        if (const std::vector<ex> terms = zero_only_where_each(factors[0]); !terms.empty()) {
          for (const ex& t : terms) {
            const std::vector<ex> of_t = doubtful_factors(t, facts_);
            if (of_t.empty()) {  // a term the facts keep from 0: the sum is never 0
              Found found;
              found.outcome = Implied::holds;
              found.how.push_back("no values satisfy the equations before under the facts");
              return found;
            }
            ex product = 1;
            for (const ex& f : of_t) {
              product *= f;
            }
            singles.push_back(GiNaC::expand(product));
          }
          in_terms.push_back(factors[0]);
          continue;
        }
      }
      if (factors.size() > 1 && !split) {
        split = std::pair{singles.size(), factors};
      }
      ex product = 1;
      for (const ex& f : factors) {
        product *= f;
      }
      singles.push_back(factors.size() == 1 ? factors[0] : GiNaC::expand(product));
    }
    Found found = from_singles(frame, target, singles, split);
    for (const ex& sum : in_terms) {
      found.how.insert(found.how.begin(),
                       text(sum) + " is a sum of terms of one sign, each of them 0");
    }
    return found;
  }

 private:
  Found from_singles(const Frame& frame, const ex& target, const std::vector<ex>& singles,
                     const std::optional<std::pair<std::size_t, std::vector<ex>>>& split) {
    if (singles.empty()) {
      return leaf(frame, target);
    }
    // A multiple of a premise's doubtful factors (the factors the facts keep from zero dropped).
    if (auto found = multiple(singles, target, false)) {
      return *found;
    }
    if (const auto choice = best_linear(singles, frame.target, true)) {
      return eliminate(frame, singles, *choice);
    }
    if (split) {
      return branch(frame, singles, split->first, split->second);
    }
    if (const auto choice = best_linear(singles, frame.target, false)) {
      return eliminate(frame, singles, *choice);
    }
    return nonlinear(frame, singles, target);
  }

  struct Choice {
    std::size_t premise;
    ex symbol;
    ex coefficient;
    ex rest;
  };

  // A premise linear in a symbol: the one whose coefficient the facts show non-zero when
  // `provable`, else any; among those, a symbol of the target and without a fact of its own.
  std::optional<Choice> best_linear(const std::vector<ex>& premises, const ex& target,
                                    bool provable) const {
    std::optional<Choice> best;
    double best_score = -1;
    for (std::size_t i = 0; i < premises.size(); ++i) {
      const ex& p = premises[i];
      for (const ex& u : symbols_of(p)) {
        if (!p.is_polynomial(u) || p.degree(u) != 1) {
          continue;
        }
        const ex alpha = p.coeff(u, 1);
        const bool nonzero = facts_.nonzero(alpha);
        if (provable != nonzero) {
          continue;
        }
        double score = 0;
        score += is_a<numeric>(alpha) ? 40 : 0;
        score += target.has(u) ? 10 : 0;
        score += facts_.of_symbol(u) == Sign::unknown ? 5 : 0;
        score -= std::min(expanded_terms(alpha), 20.0);
        if (score > best_score) {
          best_score = score;
          best = Choice{i, u, alpha, p.coeff(u, 0)};
        }
      }
    }
    return best;
  }

  // The case of a sign of X, where the value put in makes a non-integer power of k/X (x = 1/y
  // put into √x): X > 0, where GiNaC's rewriting (k/X)^c = k^c X^{-c} holds, or X < 0, where
  // the power is written as its value there.
  struct SignCase {
    ex under;       // X
    bool negative;  // X < 0
  };

  // x = 1/y put into √x: two cases, y > 0 and y < 0 (y ≠ 0 where 1/y is defined); a failure in
  // either is one of the step, and it holds where it holds in both.
  Found by_sign(const Frame& frame, const std::vector<ex>& premises, const Choice& choice,
                const ex& under) {
    const Facts outer = facts_;
    std::vector<Found> cases;
    const Sign known = facts_.sign(under);
    for (const bool negative : {false, true}) {
      if (negative ? (known == Sign::positive || known == Sign::nonnegative)
                   : (known == Sign::negative || known == Sign::nonpositive)) {
        continue;  // the facts leave this case out
      }
      facts_.add_relation(under, negative ? Sign::negative : Sign::positive);
      cases.push_back(eliminate(frame, premises, choice, SignCase{under, negative}));
      facts_ = outer;
      cases.back().how.insert(cases.back().how.begin(),
                              "where " + text(under) + (negative ? " < 0" : " > 0"));
      if (cases.back().outcome == Implied::fails) {
        return cases.back();
      }
    }
    Found all = cases.front();
    for (const Found& f : cases) {
      if (f.outcome == Implied::unknown) {
        return unknown(frame, "a root of 1/(" + text(under) + ") once " + text(choice.symbol) +
                                  " is put in, undecided where " + text(under) +
                                  " < 0 (there it is not 1/√X)");
      }
      if (f.outcome == Implied::holds_if) {
        all.outcome = Implied::holds_if;
        all.conditions_needed = all.conditions_needed && f.conditions_needed;
        for (const ex& c : f.conditions) {
          if (std::none_of(all.conditions.begin(), all.conditions.end(),
                           [&](const ex& k) { return k.is_equal(c); })) {
            all.conditions.push_back(c);
          }
        }
      }
    }
    return all;
  }

  Found eliminate(const Frame& frame, const std::vector<ex>& premises, const Choice& choice,
                  const std::optional<SignCase>& sign_case = std::nullopt) {
    const ex value = -choice.rest / choice.coefficient;
    if (!sign_case) {
      std::vector<ex> all = premises;
      all.push_back(frame.target);
      for (const ex& e : all) {
        const std::optional<ex> under = reciprocal_under_power(e, choice.symbol, value, facts_);
        if (under && facts_.sign(*under) != Sign::positive) {
          return by_sign(frame, premises, choice, *under);
        }
      }
    }
    const auto put_in = [&](const ex& e) {
      return sign_case && sign_case->negative
                 ? put_in_below_zero(e, choice.symbol, value, sign_case->under, facts_)
                 : e.subs(GiNaC::exmap{{choice.symbol, value}});
    };
    Frame child;
    child.depth = frame.depth + 1;
    child.solved = frame.solved;
    child.solved.push_back({choice.symbol, value, choice.coefficient});
    try {
      for (std::size_t i = 0; i < premises.size(); ++i) {
        if (i != choice.premise) {
          child.premises.push_back(put_in(premises[i]));
        }
      }
      child.target = put_in(frame.target);
    } catch (const std::exception&) {
      // A denominator vanishes on the whole case: no point of it is one where the equations
      // are defined, so it holds nothing against the step.
      Found outside;
      outside.outcome = Implied::holds;
      outside.how.push_back("where " + text(choice.symbol) + " = " + text(value) +
                            " the equations are not defined");
      return outside;
    }
    // What the facts say of the symbol they say of its value now (u > 0 with u = \omega L / 2:
    // \omega L / 2 > 0, and with L > 0, \omega > 0).
    const Facts outer = facts_;
    if (const Sign sign = facts_.of_symbol(choice.symbol); sign != Sign::unknown) {
      facts_.add_relation(value, sign);
    }
    // So do the facts on expressions in it (v_1 - v_2 ≠ 0 with v_1 = 0: -v_2 ≠ 0); one that the
    // value makes a number it does not hold for leaves the case no point (where the coefficient
    // is not 0: the case where it is, below, is still searched).
    const std::optional<std::string> broken =
        sign_case ? std::nullopt : relations_put_in(outer, choice.symbol, value);
    Found found;
    if (broken) {
      found.outcome = Implied::holds;
      found.how.push_back("where " + text(choice.symbol) + " = " + text(value) + ", " + *broken +
                          " does not hold");
    } else {
      found = run(child);
    }
    facts_ = outer;
    const std::string solved_for = "solved for " + text(choice.symbol);
    found.how.insert(found.how.begin(), solved_for);
    if (found.outcome != Implied::holds && found.outcome != Implied::holds_if) {
      return found;
    }
    // The division by the coefficient: needed only if the step fails where it vanishes.
    for (const ex& g : doubtful_factors(choice.coefficient, facts_)) {
      Frame zero = frame;
      zero.premises = premises;
      zero.premises.push_back(g);
      zero.depth = frame.depth + 1;
      const Found there = run(zero);
      if (there.outcome == Implied::holds) {
        continue;
      }
      found.outcome = Implied::holds_if;
      found.conditions.push_back(g);
      if (there.outcome != Implied::fails) {
        found.conditions_needed = false;
      }
    }
    return found;
  }

  // The facts on expressions in @p symbol said of @p value, added to facts_; the first that
  // becomes a number it does not hold for, as text (nothing when every one holds or stays open).
  std::optional<std::string> relations_put_in(const Facts& facts, const ex& symbol,
                                              const ex& value) {
    const auto holds = [](const numeric& n, Sign sign) {
      return !n.is_real() || has_sign(n, sign);
    };
    // the symbol's own fact (v_2 ≠ 0, left by v_1 - v_2 ≠ 0 at v_1 = 0), where the value is a
    // number
    if (const Sign sign = facts.of_symbol(symbol); sign != Sign::unknown && is_a<numeric>(value) &&
                                                   !holds(GiNaC::ex_to<numeric>(value), sign)) {
      return relation_latex(text(symbol), sign);
    }
    for (const auto& [relation, sign] : facts.relations()) {
      if (!relation.has(symbol)) {
        continue;
      }
      ex now;
      try {
        now = GiNaC::normal(relation.subs(GiNaC::exmap{{symbol, value}}));
      } catch (const std::exception&) {
        continue;  // a division by zero: left to the search
      }
      if (!is_a<numeric>(now)) {
        facts_.add_relation(now, sign);
        continue;
      }
      if (!holds(GiNaC::ex_to<numeric>(now), sign)) {
        return relation_latex(text(relation), sign);
      }
    }
    return std::nullopt;
  }

  // A denominator of the equations before that vanishes on the whole case: it is 0 once the
  // case's values are put in, or a premise of the case divides it. Large expressions are left
  // alone (the search decides them as before).
  std::optional<ex> undefined_premise(const Frame& frame, const std::vector<ex>& numerators) const {
    constexpr double small = 60;  // terms: larger ones are left to the search (a division of
                                  // large polynomials, or the numerator of a large fraction, costs
                                  // more than the case)
    for (const ex& written : problem_.premise_denominators) {
      if (is_a<numeric>(written) || expanded_terms(written) > small) {
        continue;
      }
      ex d = written;
      bool changed = false;
      try {
        for (const Solved& s : frame.solved) {
          if (d.has(s.symbol)) {
            d = d.subs(GiNaC::exmap{{s.symbol, s.value}});
            changed = true;
          }
        }
      } catch (const std::exception&) {
        return written;  // the case's values divide by zero in it
      }
      try {
        if (changed) {
          if (expanded_terms(d) > small) {
            continue;
          }
          d = numerator(d);
          if (d.is_zero()) {
            return written;
          }
        }
      } catch (const std::exception&) {
        continue;
      }
      for (const ex& p : numerators) {
        // p divides d only if d has every symbol of p (checked first: it costs no division).
        const std::vector<ex> in_p = symbols_of(p);
        if (in_p.empty() || expanded_terms(p) > small ||
            !std::all_of(in_p.begin(), in_p.end(), [&](const ex& u) { return d.has(u); })) {
          continue;
        }
        if (exact_quotient(d, p)) {
          return written;
        }
      }
    }
    return std::nullopt;
  }

  // Whether f = 0 has no real solution: the facts keep f from zero, or f is a quadratic in a
  // symbol whose discriminant the facts keep negative.
  bool no_real_zero(const ex& f) const {
    if (facts_.nonzero(f)) {
      return true;
    }
    for (const ex& x : symbols_of(f)) {
      if (!f.is_polynomial(x) || f.degree(x) != 2) {
        continue;
      }
      const ex a = f.coeff(x, 2);
      const ex b = f.coeff(x, 1);
      const ex c = f.coeff(x, 0);
      if (facts_.sign(GiNaC::expand(b * b - 4 * a * c)) == Sign::negative) {
        return true;
      }
    }
    return false;
  }

  // The terms of @p f when it is a sum of a few terms that the facts give one sign, all ≥ 0 or
  // all ≤ 0; else none.
  std::vector<ex> terms_of_one_sign(const ex& f) const {
    const ex sum = GiNaC::expand(f);
    if (!is_a<GiNaC::add>(sum) || sum.nops() > 6) {
      return {};
    }
    bool up = true;    // every term ≥ 0
    bool down = true;  // every term ≤ 0
    std::vector<ex> terms;
    for (std::size_t i = 0; i < sum.nops(); ++i) {
      const Sign s = facts_.sign(sum.op(i));
      up = up && (s == Sign::positive || s == Sign::nonnegative || s == Sign::zero);
      down = down && (s == Sign::negative || s == Sign::nonpositive || s == Sign::zero);
      terms.push_back(sum.op(i));
    }
    return up || down ? terms : std::vector<ex>{};
  }

  // What must each be 0 for @p f to be 0: the terms of a sum of one sign (terms_of_one_sign), or
  // the two symbols of a definite quadratic form (definite_form: x^2 + x y + y^2, 0 only where
  // x = y = 0); else none.
  std::vector<ex> zero_only_where_each(const ex& f) const {
    if (std::vector<ex> terms = terms_of_one_sign(f); !terms.empty()) {
      return terms;
    }
    if (const std::optional<DefiniteForm> form = definite_form(f)) {
      return {form->x, form->y};
    }
    return {};
  }

  Found branch(const Frame& frame, const std::vector<ex>& premises, std::size_t index,
               std::vector<ex> factors) {
    // Each with one sign, in the order of their text: GiNaC gives a product's factors in an order,
    // and a sum's sign, that follow hash values seeded by addresses, so that the report's "factors
    // into", and which failing case gives the counterexample, changed between builds and runs.
    std::vector<std::pair<std::string, ex>> by_text;
    for (const ex& f : factors) {
      const ex signed_once = sym::up_to_sign(f);
      by_text.emplace_back(text(signed_once), signed_once);
    }
    std::stable_sort(by_text.begin(), by_text.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < factors.size(); ++i) {
      factors[i] = by_text[i].second;
      texts.push_back(std::move(by_text[i].first));
    }
    std::vector<Found> cases;
    for (const ex& f : factors) {
      if (no_real_zero(f)) {
        // x^2 + 2x + 4 = 0 (of x^3 = 8) has no real solution: the step holds there vacuously.
        Found empty;
        empty.outcome = Implied::holds;
        cases.push_back(empty);
        continue;
      }
      Frame child = frame;
      child.depth = frame.depth + 1;
      child.premises = premises;
      child.premises[index] = f;
      // A sum whose terms the facts give one sign (x + y with x, y ≤ 0), or a definite quadratic
      // form (x^2 + x y + y^2), is 0 only where each term or symbol is: the case is those, each 0
      // (x = y = 0).
      if (const std::vector<ex> terms = zero_only_where_each(f); !terms.empty()) {
        child.premises[index] = terms[0];
        child.premises.insert(child.premises.end(), terms.begin() + 1, terms.end());
      }
      cases.push_back(run(child));
    }
    Found combined;
    std::vector<ex> failing;
    bool any_unknown = false;
    const Found* first_failure = nullptr;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const Found& c = cases[i];
      if (c.outcome == Implied::fails) {
        failing.push_back(factors[i]);
        if (!first_failure) {
          first_failure = &c;
        }
      } else if (c.outcome == Implied::unknown) {
        any_unknown = true;
      } else {
        for (const ex& condition : c.conditions) {
          combined.conditions.push_back(condition);
        }
        combined.conditions_needed = combined.conditions_needed && c.conditions_needed;
      }
    }
    std::string cases_text = "the equation before factors into ";
    for (std::size_t i = 0; i < factors.size(); ++i) {
      cases_text += (i == 0 ? "" : i + 1 == factors.size() ? " and " : ", ") + texts[i];
    }
    if (failing.empty() && !any_unknown) {
      combined.outcome = combined.conditions.empty() ? Implied::holds : Implied::holds_if;
      combined.how.push_back(cases_text + ": the step holds in each case");
      return combined;
    }
    // Where the step fails on some of the cases and holds on the others, it follows only if it
    // is the equation before divided by the failing factors (the condition is that division's):
    // holding on a case the equation before allows as much as the failing one is no following.
    const auto divided = [&] {
      ex rest = 1;
      for (std::size_t i = 0; i < factors.size(); ++i) {
        if (std::none_of(failing.begin(), failing.end(),
                         [&](const ex& f) { return f.is_equal(factors[i]); })) {
          rest *= factors[i];
        }
      }
      const ex target = numerator(frame.target);
      if (const auto quotient = divides(GiNaC::expand(rest), target)) {
        return is_a<numeric>(*quotient) || doubtful_factors(*quotient, facts_).empty();
      }
      return false;
    };
    if (first_failure && !any_unknown && failing.size() < factors.size() && divided()) {
      combined.outcome = Implied::holds_if;
      for (const ex& f : failing) {
        combined.conditions.push_back(f);
      }
      combined.how.push_back(
          cases_text + ": the step holds where " +
          (failing.size() == 1 ? unequal_to_zero(failing[0]) : "these factors are not zero") +
          ", not where it is zero");
      combined.point = first_failure->point;  // where it is zero and the step fails
      return combined;
    }
    if (first_failure) {
      Found failure = *first_failure;
      failure.how.insert(failure.how.begin(), cases_text);
      return failure;
    }
    Found unknown_case;
    unknown_case.outcome = Implied::unknown;
    unknown_case.residual = frame.target;
    unknown_case.how.push_back(cases_text + ": some case could not be decided");
    return unknown_case;
  }

  // The target a multiple of a premise (it follows wherever that premise holds), or, with
  // `divided`, a premise the target times a factor the facts keep from zero.
  std::optional<Found> multiple(const std::vector<ex>& premises, const ex& target,
                                bool divided) const {
    for (const ex& p : premises) {
      if (const auto quotient = divides(p, target)) {
        Found found;
        found.outcome = Implied::holds;
        found.how.push_back(
            is_a<numeric>(*quotient)
                ? "the step is the equation before, rewritten"
                : "the step is the equation before times " +
                      text(factorable(*quotient) ? factored(*quotient) : *quotient));
        return found;
      }
      if (!divided) {
        continue;
      }
      if (const auto quotient = divides(target, p);
          quotient && doubtful_factors(*quotient, facts_).empty()) {
        Found found;
        found.outcome = Implied::holds;
        found.how.push_back("the step is the equation before divided by " + text(*quotient) +
                            ", which is not zero");
        return found;
      }
    }
    return std::nullopt;
  }

  // The quotient target / p when it is a polynomial (p divides the target exactly).
  std::optional<ex> divides(const ex& p, const ex& target) const {
    if (expanded_terms(target) > budget_.terms || expanded_terms(p) > budget_.terms) {
      return std::nullopt;
    }
    return exact_quotient(target, p);
  }

  // Premises that are linear in none of their symbols (and divide no step: see run()).
  Found nonlinear(const Frame& frame, const std::vector<ex>& premises, const ex& target) {
    if (premises.size() == 1) {
      // An irreducible premise that does not divide the step: the step fails at its generic
      // points. Find one, solving the premise as a quadratic in one symbol.
      for (const ex& u : symbols_of(premises[0])) {
        const ex& p = premises[0];
        if (!p.is_polynomial(u) || p.degree(u) != 2) {
          continue;
        }
        const ex a = p.coeff(u, 2);
        const ex b = p.coeff(u, 1);
        const ex c = p.coeff(u, 0);
        for (const int root : {1, -1}) {
          Frame leaf_frame = frame;
          leaf_frame.premises.clear();
          const ex value = (-b + root * GiNaC::sqrt(b * b - 4 * a * c)) / (2 * a);
          leaf_frame.solved.push_back({u, value, a});
          leaf_frame.target = frame.target.subs(GiNaC::exmap{{u, value}});
          Found found = leaf(leaf_frame, target, /*exact_only=*/false);
          if (found.outcome == Implied::fails) {
            found.residual = frame.target;
            found.how.insert(found.how.begin(),
                             "solved the equation before for " + text(u) + " (a quadratic)");
            return found;
          }
        }
      }
    }
    return unknown(frame,
                   "the equations before are not linear in any symbol and do not "
                   "divide the step");
  }

  Found unknown(const Frame& frame, const std::string& why) const {
    Found found;
    found.outcome = Implied::unknown;
    found.residual = frame.target;
    found.how.push_back(why);
    return found;
  }

  // No premise left and the target does not vanish: look for a point that shows it. (First, with
  // every root's base expanded: √((A - x)(A + x)) and √(A² - x²) are one root, which GiNaC does
  // not see.)
  Found leaf(const Frame& frame, const ex& target, bool exact_only = true) {
    Found found;
    if (has_root(target)) {
      // Like terms cancel as GiNaC writes them; normal() only on small expressions (on a large
      // one it cost seconds, at every leaf of a search).
      const ex expanded = bases_expanded(target);
      if (expanded.is_zero() ||
          (expanded_terms(expanded) <= 200 && GiNaC::normal(expanded).is_zero())) {
        found.outcome = Implied::holds;
        found.how.push_back("it holds once the bases of its roots are expanded");
        return found;
      }
    }
    found.residual = frame.target;
    found.point = counterexample(frame, exact_only);
    if (found.point) {
      found.outcome = Implied::fails;
      return found;
    }
    found.outcome = Implied::unknown;
    found.how.push_back("the step does not vanish once the equations before are used (" +
                        text(target) +
                        "), but no values satisfying the facts were found to show it");
    return found;
  }

  // ---- counterexamples ----
  // Small values first: a counterexample is to be checked by hand.
  static std::vector<numeric> candidates(Sign sign) {
    const std::vector<numeric> positive{
        1, 2, 3, numeric(1, 2), 4, 5, numeric(3, 2), numeric(1, 3), 7, numeric(2, 3), 6, 10};
    std::vector<numeric> list;
    for (std::size_t i = 0; i < positive.size(); ++i) {
      const numeric& v = positive[i];
      switch (sign) {
        case Sign::positive:
          list.push_back(v);
          break;
        case Sign::negative:
          list.push_back(-v);
          break;
        case Sign::nonnegative:
        case Sign::nonpositive:
          if (i == 3) {
            list.emplace_back(0);
          }
          list.push_back(sign == Sign::nonnegative ? v : -v);
          break;
        case Sign::nonzero:
          list.push_back(v);
          list.push_back(-v);
          break;
        default:
          list.push_back(v);
          if (i == 5) {
            list.emplace_back(0);
          }
          list.push_back(-v);
          break;
      }
    }
    return list;
  }

  // A value at a point of rationals, with roots of rationals written through their primes'
  // powers (so that √3 √2 √6 meets 6), then in 40 digits: GiNaC's floats hold about 17, and a
  // sum of roots that is 0 came out 1e-17 in them, which made a point where the step holds a
  // counterexample. Nothing in the value: empty.
  static std::optional<numeric> value_at(const ex& v) {
    return value_in_40_digits(GiNaC::normal(by_facts(v, Facts{})));
  }

  // Zero at the point: exactly, or within 1e-30 in 40 digits.
  static bool is_zero_value(const ex& v) {
    if (is_a<numeric>(v)) {
      return GiNaC::ex_to<numeric>(v).is_zero();
    }
    const std::optional<numeric> value = value_at(v);
    return value && (value->is_zero() || (value->is_real() && GiNaC::abs(*value) < below(30)));
  }

  // Certainly not zero, and real (certainly_nonzero of the facts' module).
  static bool nonzero_real(const ex& v) {
    return certainly_nonzero(GiNaC::normal(by_facts(v, Facts{})));
  }

  // 10^-k.
  static numeric below(int k) { return numeric(10).power(-k); }

  // A value exact without rounding although not a rational: a rational plus a rational multiple
  // of π (θ = 90° solved is π/2), at which GiNaC gives sines and cosines exactly.
  static bool rational_in_pi(const ex& v) {
    const ex e = GiNaC::expand(v);
    if (!e.is_polynomial(GiNaC::Pi) || e.degree(GiNaC::Pi) != 1) {
      return false;
    }
    const ex k = e.coeff(GiNaC::Pi, 1);
    const ex c = e.coeff(GiNaC::Pi, 0);
    return is_a<numeric>(k) && GiNaC::ex_to<numeric>(k).is_rational() && is_a<numeric>(c) &&
           GiNaC::ex_to<numeric>(c).is_rational();
  }

  static bool real_number(const ex& v) {
    const ex f = GiNaC::evalf(v);
    return is_a<numeric>(f) && GiNaC::ex_to<numeric>(f).is_real();
  }

  // Points made of small numbers: the free symbols get values in turn, the solved ones follow.
  std::optional<GiNaC::exmap> counterexample(const Frame& frame, bool exact_only) {
    std::vector<ex> free;
    for (const ex& s : symbols_) {
      const bool solved = std::any_of(frame.solved.begin(), frame.solved.end(),
                                      [&](const Solved& x) { return x.symbol.is_equal(s); });
      if (!solved) {
        free.push_back(s);
      }
    }
    std::optional<GiNaC::exmap> best;
    double best_cost = std::numeric_limits<double>::infinity();
    std::size_t valid = 0;
    std::uint64_t state = 0x9E3779B97F4A7C15ULL;
    for (std::size_t attempt = 0; attempt < budget_.attempts && valid < budget_.candidates;
         ++attempt) {
      GiNaC::exmap point;
      for (std::size_t k = 0; k < free.size(); ++k) {
        const std::vector<numeric> list = candidates(facts_.of_symbol(free[k]));
        std::size_t index = 0;
        if (attempt > 0) {
          state = state * 6364136223846793005ULL + 1442695040888963407ULL;
          // Small indices first: the first attempts stay with 1, 2, 3.
          const std::size_t reach = std::min(list.size(), 2 + attempt / 8);
          index = static_cast<std::size_t>((state >> 33) % reach);
        }
        point[free[k]] = list[index];
      }
      try {
        bool ok = true;
        for (auto s = frame.solved.rbegin(); s != frame.solved.rend() && ok; ++s) {
          if (is_zero_value(s->divisor.subs(point))) {
            ok = false;
            break;
          }
          const ex v = GiNaC::normal(s->value.subs(point));
          if (!real_number(v)) {
            ok = false;
            break;
          }
          if (exact_only && !is_a<numeric>(v) && !rational_in_pi(v)) {
            ok = false;
            break;
          }
          point[s->symbol] = v;
        }
        if (!ok || !satisfies(point)) {
          continue;
        }
        if (!nonzero_real(problem_.target.subs(point))) {
          continue;
        }
        ++valid;
        double cost = 0;
        for (const auto& [symbol, v] : point) {
          if (is_a<numeric>(v)) {
            const numeric n = GiNaC::ex_to<numeric>(v);
            cost += std::abs(n.numer().to_double()) + 3 * (n.denom().to_double() - 1);
          } else {
            cost += 50;
          }
        }
        if (cost < best_cost) {
          best_cost = cost;
          best = point;
        }
      } catch (const std::exception&) {
        continue;  // a division by zero at this point
      }
    }
    return best;
  }

 public:
  // Whether the point is a counterexample: see fails_at().
  bool fails_at(const GiNaC::exmap& point) const {
    try {
      return satisfies(point) && nonzero_real(problem_.target.subs(point));
    } catch (const std::exception&) {
      return false;  // a division by zero at this point
    }
  }

 private:
  // The point satisfies the facts, every premise exactly, and every equation is defined there.
  bool satisfies(const GiNaC::exmap& point) const {
    for (const auto& [symbol, value] : point) {
      if (is_a<numeric>(value)) {
        if (!facts_.satisfied(symbol, GiNaC::ex_to<numeric>(value))) {
          return false;
        }
      } else if (facts_.of_symbol(symbol) != Sign::unknown) {
        const ex f = GiNaC::evalf(value);
        if (!is_a<numeric>(f) || !facts_.satisfied(symbol, GiNaC::ex_to<numeric>(f))) {
          return false;
        }
      }
    }
    if (!facts_.satisfied(point)) {
      return false;  // a fact on an expression, or an equality (a unit vector)
    }
    for (const ex& d : problem_.premise_denominators) {
      if (is_zero_value(d.subs(point))) {
        return false;
      }
    }
    for (const ex& d : problem_.target_denominators) {
      if (is_zero_value(d.subs(point))) {
        return false;
      }
    }
    for (const ex& p : problem_.premises) {
      if (!is_zero_value(p.subs(point))) {
        return false;
      }
    }
    // Every root and logarithm real there: at a = b = -1, GiNaC's √a √b is i i = -1, and
    // √(a b) = √a √b "failed" at a point where its right side has no real value.
    for (const std::vector<ex>* list :
         {&problem_.premises, &problem_.premise_denominators, &problem_.target_denominators}) {
      for (const ex& e : *list) {
        if (!real_at(e, point)) {
          return false;
        }
      }
    }
    return real_at(problem_.target, point);
  }

  // Whether each even root and each logarithm in @p e has a real value at the point: the root's
  // base is not negative, the logarithm's argument is positive. (An odd root of a negative number
  // is real: by_facts writes it as the real root.)
  static bool real_at(const ex& e, const GiNaC::exmap& point) {
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      const bool even_root = sym::is_even_root(*it);
      const bool logarithm = sym::is_function(*it, "log");
      if (!even_root && !logarithm) {
        continue;
      }
      const ex exact = GiNaC::normal(it->op(0).subs(point));
      const ex v = is_a<numeric>(exact) ? exact : GiNaC::evalf(exact);
      if (!is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) {
        return false;
      }
      const numeric n = GiNaC::ex_to<numeric>(v);
      if (n.is_negative() || (logarithm && n.is_zero())) {
        return false;
      }
    }
    return true;
  }

  const Problem& problem_;
  Facts facts_;  // the facts, and what they say of the symbols solved for in the current case
  const Budget& budget_;
  std::vector<ex> symbols_;
  std::size_t frames_ = 0;
};

// ---- sines and cosines -------------------------------------------------------------------------
// sin, cos and tan of sums of whole multiples of products of symbols (θ, 2θ, θ + φ, ω t) are
// rewritten with τ = tan(angle/2): sin = 2τ/(1 + τ²), cos = (1 − τ²)/(1 + τ²). Identities of
// sines and cosines become identities of rational functions, which the search decides. Where a
// rewritten step holds for every τ, it holds for τ = tan(angle/2); where it fails, the failure
// may need a τ that is no tangent of the angle, so a failure is left to the numeric method.
struct TrigRewrite {
  GiNaC::exmap forward;                     // sin(…), cos(…), tan(…) → rational in τ
  std::vector<std::pair<ex, ex>> tangents;  // τ, and the angle it stands for
};

// a = Σ k_i M_i with rational k_i and monomials M_i of symbols, or M_i = π with 2 k_i whole
// (π/2 - θ); empty when a is not of that form.
std::optional<std::vector<std::pair<numeric, ex>>> angle_terms(const ex& a) {
  const ex expanded = GiNaC::expand(a);
  std::vector<std::pair<numeric, ex>> terms;
  const auto term = [&](const ex& t) {
    numeric k = 1;
    ex monomial = 1;
    const auto factor = [&](const ex& f) {
      if (is_a<numeric>(f)) {
        k *= GiNaC::ex_to<numeric>(f);
        return true;
      }
      if (is_a<GiNaC::symbol>(f) || f.is_equal(GiNaC::Pi) ||
          (is_a<GiNaC::power>(f) && is_a<GiNaC::symbol>(f.op(0)) &&
           f.op(1).info(GiNaC::info_flags::posint))) {
        monomial *= f;
        return true;
      }
      return false;
    };
    bool ok = true;
    if (is_a<GiNaC::mul>(t)) {
      for (std::size_t i = 0; i < t.nops() && ok; ++i) {
        ok = factor(t.op(i));
      }
    } else {
      ok = factor(t);
    }
    const bool pi = monomial.is_equal(GiNaC::Pi);
    if (!ok || !k.is_rational() || monomial.is_equal(1) || (monomial.has(GiNaC::Pi) && !pi) ||
        (pi && !(2 * k).is_integer())) {
      return false;
    }
    terms.emplace_back(k, monomial);
    return true;
  };
  if (is_a<GiNaC::add>(expanded)) {
    for (std::size_t i = 0; i < expanded.nops(); ++i) {
      if (!term(expanded.op(i))) {
        return std::nullopt;
      }
    }
  } else if (!term(expanded)) {
    return std::nullopt;
  }
  return terms;
}

// Whether sines and cosines of this angle are written through tangents of half angles: at most
// 4 angles, whose multiples add up to at most 12. The rational function grows with both, and
// beyond them it took longer than any step's time (sin(a + 2b + 3c + 4g + 5h + 6k), and
// sin((a + b)^5), whose expansion has multiples 1, 5, 10, 10, 5, 1, ran for minutes).
bool rewritable(const std::vector<std::pair<numeric, ex>>& terms) {
  numeric multiples = 0;
  for (const auto& [k, monomial] : terms) {
    multiples += GiNaC::abs(k.numer());
  }
  return terms.size() <= 4 && multiples <= 12;
}

class Trig {
 public:
  TrigRewrite rewrite(const std::vector<ex>& expressions) {
    TrigRewrite result;
    // Each monomial's base angle: the monomial over the least common denominator of its
    // multiples (θ_0 and θ_0/2 are 2 and 1 times θ_0/2), so that every angle is a whole multiple.
    for (const ex& e : expressions) {
      for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (!is_trig(*i)) {
          continue;
        }
        if (const auto terms = angle_terms(i->op(0)); terms && rewritable(*terms)) {
          for (const auto& [k, monomial] : *terms) {
            numeric& denominator = denominators_.emplace(monomial, 1).first->second;
            denominator = GiNaC::lcm(denominator, k.denom());
          }
        }
      }
    }
    for (const ex& e : expressions) {
      for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (!is_trig(*i)) {
          continue;
        }
        const std::string name = GiNaC::ex_to<GiNaC::function>(*i).get_name();
        const auto terms = angle_terms(i->op(0));
        if (!terms || !rewritable(*terms) || result.forward.count(*i) != 0) {
          continue;
        }
        auto [sine, cosine] = of_sum(*terms);
        result.forward[*i] = name == "sin" ? sine : name == "cos" ? cosine : sine / cosine;
      }
    }
    for (const auto& [monomial, tau] : tangents_) {
      result.tangents.emplace_back(tau, monomial);
    }
    return result;
  }

 private:
  std::pair<ex, ex> of_monomial(const ex& monomial) {
    for (const auto& [m, tau] : tangents_) {
      if (m.is_equal(monomial)) {
        return {2 * tau / (1 + tau * tau), (1 - tau * tau) / (1 + tau * tau)};
      }
    }
    std::ostringstream name;
    name << "tau_" << tangents_.size();
    const ex tau =
        GiNaC::realsymbol(name.str(), "\\tau_{" + std::to_string(tangents_.size()) + "}");
    tangents_.emplace_back(monomial, tau);
    return of_monomial(monomial);
  }

  static bool is_trig(const ex& e) {
    if (!is_a<GiNaC::function>(e) || e.nops() != 1) {
      return false;
    }
    const std::string& name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    return name == "sin" || name == "cos" || name == "tan";
  }

  // sin and cos of k·M, by the recurrences of whole multiples of M's base angle; of k·π (2k
  // whole) exactly.
  std::pair<ex, ex> of_multiple(const numeric& given_k, const ex& monomial) {
    if (monomial.is_equal(GiNaC::Pi)) {
      const long quarter = GiNaC::mod(numeric(2) * given_k, numeric(4)).to_long();  // k π mod 2π
      static const std::pair<int, int> values[4] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
      return {values[quarter].first, values[quarter].second};
    }
    const auto found = denominators_.find(monomial);
    const numeric denominator = found == denominators_.end() ? numeric(1) : found->second;
    const numeric k = given_k * denominator;
    const auto [s1, c1] = of_monomial(monomial / denominator);
    const long n = GiNaC::abs(k).to_long();
    ex s_previous = 0, c_previous = 1, s = s1, c = c1;
    if (n == 0) {
      return {0, 1};
    }
    for (long j = 1; j < n; ++j) {
      const ex s_next = GiNaC::normal(2 * c1 * s - s_previous);
      const ex c_next = GiNaC::normal(2 * c1 * c - c_previous);
      s_previous = s;
      c_previous = c;
      s = s_next;
      c = c_next;
    }
    return {k.is_negative() ? ex(-s) : s, c};
  }

  std::pair<ex, ex> of_sum(const std::vector<std::pair<numeric, ex>>& terms) {
    ex s = 0, c = 1;
    for (const auto& [k, monomial] : terms) {
      const auto [sk, ck] = of_multiple(k, monomial);
      const ex s_next = s * ck + c * sk;
      const ex c_next = c * ck - s * sk;
      s = GiNaC::normal(s_next);
      c = GiNaC::normal(c_next);
    }
    return {s, c};
  }

  std::vector<std::pair<ex, ex>> tangents_;                // base angle, τ
  std::map<ex, numeric, GiNaC::ex_is_less> denominators_;  // monomial, its base's divisor
};

}  // namespace

namespace {

// The conditions in τ alone (τ = tan(angle/2)) whose product is a number times 1 - τ², τ or both,
// replaced by cos(angle), sin(angle) or both: 1 - τ² = cos(angle) (1 + τ²) and 2τ = sin(angle)
// (1 + τ²).
// A product 1 - τ (or 1 + τ) whose other factor the facts on τ keep from 0 is cos(angle) too:
// 0 ≤ θ ≤ π/2 gives 1 + τ > 0, and dividing by cos θ needs only 1 - τ ≠ 0, that is cos θ ≠ 0.
std::vector<ex> in_the_angle(const std::vector<ex>& conditions, const ex& tau, const ex& angle,
                             const Facts& facts) {
  std::vector<ex> kept;
  ex product = 1;
  bool any = false;
  for (const ex& c : conditions) {
    const std::vector<ex> in_c = symbols_of(c);
    if (in_c.size() == 1 && in_c[0].is_equal(tau) && c.is_polynomial(tau)) {
      product *= c;
      any = true;
    } else {
      kept.push_back(c);
    }
  }
  if (!any) {
    return conditions;
  }
  try {
    for (const ex& other : {ex(1), 1 + tau, 1 - tau}) {
      if ((other.is_equal(1) || facts.nonzero(other)) &&
          is_a<numeric>(GiNaC::normal(product * other / (1 - tau * tau)))) {
        kept.push_back(GiNaC::cos(angle));
        return kept;
      }
    }
    if (is_a<numeric>(GiNaC::normal(product / tau))) {
      kept.push_back(GiNaC::sin(angle));
      return kept;
    }
    // τ (1 - τ²), of sin 2θ = 2 sin θ cos θ: sin(angle) ≠ 0 and cos(angle) ≠ 0.
    if (is_a<numeric>(GiNaC::normal(product / (tau * (1 - tau * tau))))) {
      kept.push_back(GiNaC::sin(angle));
      kept.push_back(GiNaC::cos(angle));
      return kept;
    }
  } catch (const std::exception&) {
  }
  // Else each condition of degree two in τ alone: p0 + p1 τ + p2 τ² = (1 + τ²)(a + b cos(angle)
  // + c sin(angle)) with a = (p0 + p2)/2, b = (p0 - p2)/2, c = p1/2, and both sides over 1 + τ²
  // tend to p2 = a - b where τ is infinite (the angle an odd multiple of π). (One of degree one
  // would become a condition there that it is not, and stays in τ.)
  std::vector<ex> converted;
  for (const ex& c : conditions) {
    const ex p = GiNaC::expand(c);
    const std::vector<ex> in_c = symbols_of(c);
    if (in_c.size() == 1 && in_c[0].is_equal(tau) && p.is_polynomial(tau) && p.degree(tau) == 2) {
      const ex p0 = p.coeff(tau, 0);
      const ex p1 = p.coeff(tau, 1);
      const ex p2 = p.coeff(tau, 2);
      converted.push_back((p0 + p2) / 2 + (p0 - p2) / 2 * GiNaC::cos(angle) +
                          p1 / 2 * GiNaC::sin(angle));
    } else {
      converted.push_back(c);
    }
  }
  return converted;
}

}  // namespace

bool fails_at(const Problem& problem, const Facts& facts, const GiNaC::exmap& point) {
  const Budget unused;
  return Decider(problem, facts, unused).fails_at(point);
}

namespace {

// ---- magnitudes --------------------------------------------------------------------------------
// A symbol x that the problem writes only as |x| and in even powers (|v'| = e |v| then v'^2 =
// e^2 v^2) is a problem in |x| alone: x^2 = |x|^2 for a real x, and any a ≥ 0 is |x| for x = a.
// |x| becomes a symbol of its own, at least 0, which the search can solve for; a case |v| = 0 then
// needs no condition |v| ≠ 0 that the step does not need.
struct MagnitudeRewrite {
  std::vector<std::pair<ex, ex>> pairs;  // (the symbol of |x|, x)
};

// @p e with |x| and the even powers of x written through @p magnitude.
ex through_magnitude(const ex& e, const ex& x, const ex& magnitude) {
  return sym::rewritten(e, [&](const ex& part) -> std::optional<ex> {
    if (sym::is_function(part, "abs") && part.op(0).is_equal(x)) {
      return magnitude;
    }
    if (is_a<GiNaC::power>(part) && part.op(0).is_equal(x) &&
        part.op(1).info(GiNaC::info_flags::even)) {
      return GiNaC::pow(magnitude, part.op(1));
    }
    return std::nullopt;
  });
}

MagnitudeRewrite magnitudes(Problem& problem, Facts& facts) {
  std::vector<ex*> all{&problem.target};
  for (std::vector<ex>* list :
       {&problem.premises, &problem.premise_denominators, &problem.target_denominators}) {
    for (ex& e : *list) {
      all.push_back(&e);
    }
  }
  std::vector<ex> inside;  // the symbols written as |x|
  for (const ex* e : all) {
    for (auto i = e->preorder_begin(); i != e->preorder_end(); ++i) {
      if (sym::is_function(*i, "abs") && is_a<GiNaC::symbol>(i->op(0)) &&
          std::none_of(inside.begin(), inside.end(),
                       [&](const ex& x) { return x.is_equal(i->op(0)); })) {
        inside.push_back(i->op(0));
      }
    }
  }
  MagnitudeRewrite rewrite;
  for (const ex& x : inside) {
    const Sign sign = facts.sign(x);
    if (sign != Sign::unknown && sign != Sign::nonzero) {
      continue;  // by_facts wrote |x| out already where the facts give its sign
    }
    const GiNaC::symbol magnitude("|" + GiNaC::ex_to<GiNaC::symbol>(x).get_name() + "|");
    std::vector<ex> written;
    bool alone = true;
    for (const ex* e : all) {
      written.push_back(through_magnitude(*e, x, magnitude));
      alone = alone && !written.back().has(x);
    }
    if (!alone) {
      continue;  // x stands in an odd power too: |x| is no symbol of its own there
    }
    for (std::size_t k = 0; k < all.size(); ++k) {
      *all[k] = written[k];
    }
    facts.add(magnitude, sign == Sign::nonzero ? Sign::positive : Sign::nonnegative);
    rewrite.pairs.emplace_back(magnitude, x);
  }
  return rewrite;
}

// What the search found, back in the symbols: |x| for its symbol in the conditions and what is
// left, x = |x|'s value at a counterexample (x ≥ 0 then, so its |x| and its even powers agree).
void from_magnitudes(Found& found, const MagnitudeRewrite& rewrite) {
  GiNaC::exmap back;
  for (const auto& [magnitude, x] : rewrite.pairs) {
    back[magnitude] = GiNaC::abs(x);
  }
  for (ex& c : found.conditions) {
    c = c.subs(back);
  }
  found.residual = found.residual.subs(back);
  if (found.point) {
    for (const auto& [magnitude, x] : rewrite.pairs) {
      if (const auto value = found.point->find(magnitude); value != found.point->end()) {
        const ex v = value->second;
        found.point->erase(value);
        (*found.point)[x] = v;
      }
    }
  }
}

// What the search found with sines and cosines written through tangents of half angles, back in
// the angles: a failure only as a value of the tangents (no point in the angles: the numeric
// method looks for one), the conditions in the angles (@p facts: those on the tangents too).
void from_tangents(Found& found, const TrigRewrite& rewrite, const ex& target, const Facts& facts) {
  if (found.outcome == Implied::fails) {
    found.outcome = Implied::unknown;
    found.point.reset();
    found.how.push_back(
        "with sines and cosines written through tangents of half angles, the "
        "step does not hold everywhere; the numeric method looks for the "
        "angles that show it");
    found.residual = target;
  } else {
    found.point.reset();  // in the tangents, not the angles
    // Conditions back in the angles: τ = tan(angle/2); those in one τ alone whose product is
    // 1 - τ² (or τ) are cos(angle) ≠ 0 (or sin(angle) ≠ 0), as the file would write them.
    for (const auto& [tau, angle] : rewrite.tangents) {
      found.conditions = in_the_angle(found.conditions, tau, angle, facts);
    }
    GiNaC::exmap back;
    for (const auto& [tau, angle] : rewrite.tangents) {
      back[tau] = GiNaC::tan(angle / 2);
    }
    for (ex& c : found.conditions) {
      c = c.subs(back);
    }
    found.how.insert(found.how.begin(),
                     "sines and cosines written through tangents of half "
                     "angles");
  }
}

// Whether the facts let `angle` (a rational multiple of one symbol, or any other product) be an
// odd multiple of π, where the tangent of its half is infinite: 0 < θ < π does not, 0 < θ ≤ π
// and θ ≥ 0 do. A closed end within 1e-9 of such a multiple counts as reaching it.
bool reaches_odd_pi(const ex& angle, const Facts& facts) {
  const auto multiple = multiple_of_symbol(GiNaC::expand(angle));
  if (!multiple) {
    return true;  // ω t, θ + φ: some value reaches it
  }
  const ex symbol = multiple->first;
  const numeric k = multiple->second;
  const auto [low, high] = facts.bounds(symbol);
  const Sign sign = facts.of_symbol(symbol);
  const double pi = 3.14159265358979323846;
  const double step = 2 * pi / std::abs(k.to_double());  // the symbol's odd multiples of π/k
  const double first = pi / k.to_double();
  // The odd multiples of π/k from the lower end (or from below the upper end, or around 0 with
  // no end), the first three: a sign fact may rule out one of them.
  const bool above_zero = sign == Sign::positive || sign == Sign::nonnegative;
  const bool below_zero = sign == Sign::negative || sign == Sign::nonpositive;
  const double from = low ? std::max(*low, above_zero ? 0.0 : *low)
                          : (above_zero ? 0.0 : (high ? *high - 4 * step : -2 * step));
  const double lowest = std::ceil((from - first) / step - 1e-9);
  for (double j = lowest; j < lowest + 3; ++j) {
    const double v = first + j * step;
    const double margin = 1e-9 * std::max(1.0, std::abs(v));
    const bool in = (!low || v >= *low - margin) && (!high || v <= *high + margin);
    const bool signed_ok = (!above_zero || v > 0) && (!below_zero || v < 0);
    if (!in) {
      continue;
    }
    // An open end exactly at v keeps it out.
    const bool at_open_low =
        low && std::abs(v - *low) <= margin && facts.strict_bound(symbol, false);
    const bool at_open_high =
        high && std::abs(v - *high) <= margin && facts.strict_bound(symbol, true);
    if (signed_ok && !at_open_low && !at_open_high) {
      return true;
    }
  }
  return false;
}

// The value of a sine or cosine rewritten through τ (a rational function of it) where τ is
// infinite: the angle an odd multiple of π. Empty when it has none there.
std::optional<ex> at_infinity(const ex& rewritten, const ex& tau) {
  const GiNaC::symbol epsilon("epsilon");
  const ex r = GiNaC::normal(rewritten.subs(tau == 1 / epsilon));
  const ex top = GiNaC::numer(r).subs(epsilon == 0);
  const ex bottom = GiNaC::denom(r).subs(epsilon == 0);
  if (GiNaC::normal(bottom).is_zero()) {
    return std::nullopt;
  }
  return GiNaC::normal(top / bottom);
}

// The tangent of half an angle misses the angle π (it is infinite there): a step that holds for
// every τ may fail at θ = π. (From J (1 + cos θ) = m u the step J = m u / (1 + cos θ) followed with
// no condition, and cos²θ = 1 gave cos θ = 1.) Where a step held through the tangents and the
// facts let an angle reach an odd multiple of π, the step is searched again with that angle's
// sines and cosines at their values there; unless it holds there too, it holds only where
// 1 + cos(angle) ≠ 0.
template <class Search>
void at_odd_pi(Found& found, const Problem& original, const TrigRewrite& rewrite,
               const Facts& facts, const Search& search) {
  if (found.outcome != Implied::holds && found.outcome != Implied::holds_if) {
    return;
  }
  for (const auto& [tau, angle] : rewrite.tangents) {
    if (!reaches_odd_pi(angle, facts)) {
      continue;
    }
    GiNaC::exmap there;
    bool defined = true;
    for (const auto& [trig, value] : rewrite.forward) {
      if (!value.has(tau)) {
        there[trig] = value;
      } else if (const auto limit = at_infinity(value, tau)) {
        there[trig] = *limit;
      } else {
        defined = false;  // tan(θ/2) itself: undefined at θ = π
      }
    }
    // A condition found already vanishes there (sin θ ≠ 0 leaves θ = π out): nothing to add.
    const ex the_angle = angle;  // a structured binding, which clang 14 lets no lambda name
    const bool left_out =
        defined && std::any_of(found.conditions.begin(), found.conditions.end(), [&](const ex& c) {
          try {
            return GiNaC::normal(c.subs(there)).is_zero() ||
                   (is_a<GiNaC::symbol>(the_angle) &&
                    GiNaC::normal(c.subs(the_angle == GiNaC::Pi)).is_zero());
          } catch (const std::exception&) {
            return false;
          }
        });
    if (left_out) {
      continue;
    }
    Implied outcome = Implied::unknown;
    std::vector<ex> conditions_there;
    if (defined) {
      Problem at = original;
      at.premise_denominators.clear();  // where they vanish, the divisor check speaks
      at.target_denominators.clear();
      try {
        for (ex& e : at.premises) {
          e = GiNaC::normal(e.subs(there));
        }
      } catch (const std::exception&) {
        continue;  // an equation before divides by zero there: no point of it lies there
      }
      try {
        at.target = GiNaC::normal(at.target.subs(there));
        const Found at_pi = search(at);
        outcome = at_pi.outcome;
        conditions_there = at_pi.conditions;
      } catch (const std::exception&) {
        outcome = Implied::fails;  // the step divides by zero there
      }
    }
    // There, it may hold where conditions already found hold (k y = k sin θ then y = sin θ: at
    // θ = π, k y = 0 gives y = 0 where k ≠ 0, the condition everywhere else too).
    const auto already_found = [&](const ex& c) {
      return std::any_of(found.conditions.begin(), found.conditions.end(), [&](const ex& d) {
        const ex ratio = GiNaC::normal(c / d);
        return is_a<numeric>(ratio) && !ratio.is_zero();
      });
    };
    if (outcome == Implied::holds ||
        (outcome == Implied::holds_if && found.outcome == Implied::holds_if &&
         std::all_of(conditions_there.begin(), conditions_there.end(), already_found))) {
      continue;
    }
    const ex condition = 1 + GiNaC::cos(angle);
    if (found.outcome == Implied::holds) {
      found.outcome = Implied::holds_if;
      found.conditions_needed = outcome == Implied::fails;
    }
    found.conditions.push_back(condition);
    found.how.push_back("at " + text(angle) +
                        " = π the tangent of its half is infinite, and there "
                        "the step " +
                        std::string(outcome == Implied::fails ? "fails" : "was not decided"));
  }
}

// k² S - R² for a premise k P + R, linear in the part P (with S = P², written without P), whose
// other terms R do not hold P (and nothing large); else nothing.
std::optional<ex> squared_without(const ex& premise, const ex& part, const ex& square) {
  const auto kr = expanded_terms(premise) > 20 ? std::nullopt : sym::linear_in(premise, part);
  if (!kr) {
    return std::nullopt;
  }
  const auto& [k, rest] = *kr;
  return GiNaC::expand(k * k * square - rest * rest);
}

// k² A - R² for a premise k √A + R whose one square root √A of a symbol's expression is in no
// other term (and nothing large): the premise squared, without its root; else nothing.
std::optional<ex> root_squared(const ex& premise) {
  const auto root = sym::only_part(premise, [](const ex& e) {
    return is_a<GiNaC::power>(e) && e.op(1).is_equal(GiNaC::numeric(1, 2)) &&
           !symbols_of(e.op(0)).empty();
  });
  return root ? squared_without(premise, *root, root->op(0)) : std::nullopt;
}

// k² A² - R² for a premise k |A| + R, the absolute value of a symbol's expression in no other
// term (the first, where there are several: R² squares the others, |B|² = B²); else nothing.
std::optional<ex> absolute_squared(const ex& premise) {
  for (GiNaC::const_preorder_iterator it = premise.preorder_begin(); it != premise.preorder_end();
       ++it) {
    if (sym::is_function(*it, "abs") && !symbols_of(it->op(0)).empty()) {
      return squared_without(premise, *it, GiNaC::pow(it->op(0), 2));
    }
  }
  return std::nullopt;
}

// The facts with those that keep @p premises real: x > 0 for each symbol x of a logarithm ln x
// in them, x ≥ 0 of a square root √x (an even root). A premise is read where it is real, so a
// step needs to hold only there: a = ln x + ln y gives a = ln(x y). Nothing is added against a
// fact (x < 0 with ln x: no real value satisfies the premise, which is said elsewhere).
Facts with_domain(const Facts& facts, const std::vector<ex>& premises) {
  Facts result = facts;
  for (const ex& p : premises) {
    for (GiNaC::const_preorder_iterator it = p.preorder_begin(); it != p.preorder_end(); ++it) {
      if (sym::is_function(*it, "log") && is_a<GiNaC::symbol>(it->op(0))) {
        (void)result.add(it->op(0), Sign::positive);
      } else if (sym::is_even_root(*it) && is_a<GiNaC::symbol>(it->op(0))) {
        (void)result.add(it->op(0), Sign::nonnegative);
      }
    }
  }
  return result;
}

// Each premise a f(u) + b = 0, with f a sine, cosine or tangent, u a symbol that the premise holds
// nowhere else, a and b numbers, and u kept by the facts where f is one-to-one (the inverse's own
// range: arcsin's [-π/2, π/2], arccos' [0, π], arctan's (-π/2, π/2)), is u = f⁻¹(-b/a) there:
// tan θ = 1 on 0 < θ < π/2 is θ = π/4. What was rewritten, as text ("" for nothing).
std::string inverted_on_range(Problem& problem, const Facts& facts) {
  std::string rewritten;
  for (ex& p : problem.premises) {
    std::optional<ex> inside;
    bool one = true;
    for (auto i = p.preorder_begin(); i != p.preorder_end() && one; ++i) {
      if (is_a<GiNaC::function>(*i)) {
        one = !inside || inside->is_equal(*i);
        inside = *i;
      }
    }
    if (!one || !inside || inside->nops() != 1 || !is_a<GiNaC::symbol>(inside->op(0))) {
      continue;
    }
    const std::string& name = GiNaC::ex_to<GiNaC::function>(*inside).get_name();
    const ex u = inside->op(0);
    const GiNaC::symbol f("f");
    const ex q = GiNaC::expand(p.subs(*inside == f));
    // A real constant: a number, or one written with roots and π (√3/2).
    const auto constant = [](const ex& e) {
      const ex v = GiNaC::evalf(e);
      return symbols_of(e).empty() && is_a<numeric>(v) && GiNaC::ex_to<numeric>(v).is_real();
    };
    if (q.has(u) || !q.is_polynomial(f) || q.degree(f) != 1 || !constant(q.coeff(f, 1)) ||
        q.coeff(f, 1).is_zero() || !constant(q.coeff(f, 0))) {
      continue;
    }
    const ex c = GiNaC::normal(-q.coeff(f, 0) / q.coeff(f, 1));
    const bool in_one = GiNaC::abs(GiNaC::ex_to<numeric>(GiNaC::evalf(c))) <= 1;
    if ((name != "tan" && !in_one) || !on_inverse_range(name, u, facts)) {
      continue;
    }
    const ex value = name == "sin"   ? GiNaC::asin(c)
                     : name == "cos" ? GiNaC::acos(c)
                                     : GiNaC::atan(c);
    p = u - value;
    rewritten += (rewritten.empty() ? "" : "; ") + text(p) + " = 0";
  }
  return rewritten;
}

// f - ln(-R/k) for a premise k e^f + R, its one exponential in no other term, where the facts
// keep k from 0 and -R/k is a positive number or the facts keep it positive (1/2 = e^{-T/τ} gives
// -T/τ = ln(1/2), in which T can be solved for); else nothing.
std::optional<ex> exponential_logarithm(const ex& premise, const Facts& facts) {
  const auto exponential = sym::only_part(premise, [](const ex& e) {
    return sym::is_function(e, "exp") && !symbols_of(e.op(0)).empty();
  });
  const auto kr = !exponential || expanded_terms(premise) > 20
                      ? std::nullopt
                      : sym::linear_in(premise, *exponential);
  if (!kr) {
    return std::nullopt;
  }
  const auto& [k, rest] = *kr;
  // Only where k cannot be 0: y (e^x - 1) = z (e^x - 1) holds at y = z whatever x is, and
  // does not give x = 0.
  if (!(is_a<numeric>(k) && !k.is_zero()) && !facts.nonzero(k)) {
    return std::nullopt;
  }
  const ex value = GiNaC::normal(-rest / k);
  const bool positive = (is_a<numeric>(value) && GiNaC::ex_to<numeric>(value).is_positive()) ||
                        facts.sign(value) == Sign::positive;
  if (!positive) {
    return std::nullopt;
  }
  return exponential->op(0) - GiNaC::log(value);
}

// Each premise k √A + R = 0, with the root in no other term, gives k² A = R², added beside it:
// √x = 3 is x = 9 (and √x = -3 holds nowhere, which the premise kept says). Likewise k |A| + R = 0
// gives k² A² = R²: |a - c| = e |b - d| is (a - c)² = e² (b - d)² wherever it holds; and
// k e^f + R = 0 gives f = ln(-R/k) where that is positive (exponential_logarithm). What was
// added, as text for the report ("" for nothing).
std::string add_squared_roots(Problem& problem, const Facts& facts) {
  const std::size_t written = problem.premises.size();
  std::string roots;
  std::string absolutes;
  std::string logarithms;
  const auto add = [&](const ex& e, std::string& list) {
    problem.premises.push_back(e);
    // one sign, whatever GiNaC's order of the terms (= 0 either way)
    list += (list.empty() ? "" : ", ") + text(sym::up_to_sign(e)) + " = 0";
  };
  for (std::size_t i = 0; i < written; ++i) {
    if (const auto squared = root_squared(problem.premises[i])) {
      add(*squared, roots);
    } else if (const auto squared_absolute = absolute_squared(problem.premises[i])) {
      add(*squared_absolute, absolutes);
    } else if (const auto logarithm = exponential_logarithm(problem.premises[i], facts)) {
      add(*logarithm, logarithms);
    }
  }
  std::string added;
  for (const auto& [what, list] :
       {std::pair<std::string, const std::string&>{"a root squared: ", roots},
        {"an absolute value squared: ", absolutes},
        {"the logarithm of an exponential: ", logarithms}}) {
    if (!list.empty()) {
      added += (added.empty() ? "" : "; ") + what + list;
    }
  }
  return added;
}

// The facts with, for each τ = tan(angle/2) of the rewriting, the bounds on τ that the angle's
// give where its half stays within one branch of the tangent (-π/2 to π/2), in which τ grows
// with it: 0 ≤ θ ≤ π gives τ ≥ 0, so that sin²θ = 1 gives sin θ = 1 (τ = -1, the other root,
// is θ = -π/2). The angle is a rational multiple of one symbol whose both ends the facts give (a
// bound, or 0 from its sign); anything else adds nothing.
Facts with_tangents(const Facts& facts, const TrigRewrite& rewrite) {
  Facts result = facts;
  const double half_pi = 3.14159265358979323846 / 2;
  for (const auto& [tau, angle] : rewrite.tangents) {
    const auto multiple = multiple_of_symbol(GiNaC::expand(angle));
    if (!multiple) {
      continue;
    }
    const numeric k = multiple->second;
    // Each end of the symbol: the tighter of its bound and its sign's 0, and whether it is strict.
    auto [low, high] = facts.exact_ends(multiple->first);
    if (!low || !high) {
      continue;
    }
    if (k.is_negative()) {
      std::swap(low, high);
    }
    // The half angle's ends, within one branch.
    const ex half_low = k * low->at / 2;
    const ex half_high = k * high->at / 2;
    const ex low_value = GiNaC::evalf(half_low);
    const ex high_value = GiNaC::evalf(half_high);
    if (!is_a<numeric>(low_value) || !is_a<numeric>(high_value)) {
      continue;
    }
    const double a = GiNaC::ex_to<numeric>(low_value).to_double();
    const double b = GiNaC::ex_to<numeric>(high_value).to_double();
    if (a < -half_pi - 1e-9 || b > half_pi + 1e-9) {
      continue;
    }
    if (a > -half_pi + 1e-9) {
      result.add_relation(tau - GiNaC::tan(half_low),
                          low->strict ? Sign::positive : Sign::nonnegative);
    }
    if (b < half_pi - 1e-9) {
      result.add_relation(tau - GiNaC::tan(half_high),
                          high->strict ? Sign::negative : Sign::nonpositive);
    }
  }
  return result;
}

}  // namespace

Implication implies(const Problem& given, const Facts& written_facts, const Budget& budget) {
  Implication result;
  // Where the equations before are real: ln x in them needs x > 0, √x needs x ≥ 0.
  const Facts facts = with_domain(written_facts, given.premises);
  // Roots, powers and logarithms simplified where the facts allow it.
  Problem original = given;
  for (std::vector<ex>* list :
       {&original.premises, &original.premise_denominators, &original.target_denominators}) {
    for (ex& e : *list) {
      e = by_facts(e, facts);
    }
  }
  original.target = by_facts(original.target, facts);
  const std::string inverted_text = inverted_on_range(original, facts);
  const std::string squared_text = add_squared_roots(original, facts);
  // Sines and cosines become rational functions of tangents of half angles.
  std::vector<ex> all{original.target};
  all.insert(all.end(), original.premises.begin(), original.premises.end());
  all.insert(all.end(), original.premise_denominators.begin(), original.premise_denominators.end());
  all.insert(all.end(), original.target_denominators.begin(), original.target_denominators.end());
  Trig trig;
  const TrigRewrite rewrite = trig.rewrite(all);
  Problem problem = original;
  if (!rewrite.forward.empty()) {
    const auto apply = [&](std::vector<ex>& list) {
      for (ex& e : list) {
        e = e.subs(rewrite.forward);
      }
    };
    apply(problem.premises);
    apply(problem.premise_denominators);
    apply(problem.target_denominators);
    problem.target = problem.target.subs(rewrite.forward);
  }
  const Facts tangent_facts = with_tangents(facts, rewrite);
  const auto search = [&](Problem searched, const Budget& limits, const Facts& known) {
    Facts with_magnitudes = known;
    const MagnitudeRewrite magnitude = magnitudes(searched, with_magnitudes);
    Decider decider(searched, with_magnitudes, limits);
    Frame start;
    start.premises = searched.premises;
    start.target = searched.target;
    Found found;
    try {
      found = decider.run(start);
    } catch (const std::exception& e) {
      found = Found{};
      found.outcome = Implied::unknown;
      found.residual = searched.target;
      found.how.push_back(std::string("the exact method stopped: ") + e.what());
    }
    from_magnitudes(found, magnitude);
    return found;
  };
  // The sines and cosines as they stand first: a step that holds with them as they are (the
  // same sine written again) needs no rewriting, whose rational functions can be large. Only
  // "holds" counts from it: with the sines as symbols, a point would be none.
  Found found;
  bool as_written = false;
  if (!rewrite.forward.empty()) {
    Budget quick = budget;
    quick.attempts = 0;
    found = search(original, quick, facts);
    as_written = found.outcome == Implied::holds;
  }
  if (!as_written) {
    found = search(problem, budget, tangent_facts);
  }
  if (!rewrite.forward.empty() && !as_written) {
    from_tangents(found, rewrite, original.target, tangent_facts);
    at_odd_pi(found, original, rewrite, facts,
              [&](const Problem& p) { return search(p, budget, facts); });
  }
  result.outcome = found.outcome;
  result.conditions = found.conditions;
  result.conditions_needed = found.conditions_needed;
  result.residual = found.residual;
  result.point = found.point;
  if (!squared_text.empty()) {
    found.how.insert(found.how.begin(), squared_text);
  }
  if (!inverted_text.empty()) {
    found.how.insert(found.how.begin(),
                     "the equation before solved on the facts' range: " + inverted_text);
  }
  for (std::size_t i = 0; i < found.how.size(); ++i) {
    result.how += (i == 0 ? "" : "; ") + found.how[i];
  }
  // What the step divides by that the equations before did not: where it vanishes, the step
  // is not even defined. (As written, before sines and cosines are rewritten: 1 + 3 cos^2 is
  // positive as it stands.)
  if (result.outcome == Implied::holds || result.outcome == Implied::holds_if) {
    std::vector<ex> before;
    for (const ex& d : original.premise_denominators) {
      for (const ex& f : doubtful_factors(numerator(d), facts)) {
        before.push_back(f);
      }
    }
    for (const ex& d : original.target_denominators) {
      for (const ex& f : doubtful_factors(numerator(d), facts)) {
        const auto known = [&](const ex& g) { return same_up_to_constant(f, g); };
        if (std::any_of(before.begin(), before.end(), known) ||
            std::any_of(result.conditions.begin(), result.conditions.end(), known)) {
          continue;
        }
        result.conditions.push_back(f);
        result.outcome = Implied::holds_if;
        if (result.how.find("divides by") == std::string::npos) {
          result.how +=
              std::string(result.how.empty() ? "" : "; ") + "the step divides by " + text(f);
        }
      }
    }
  }
  return result;
}

}  // namespace impulse::derivations::file
