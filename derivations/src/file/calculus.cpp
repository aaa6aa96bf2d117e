// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/calculus.hpp"

#include "file/decide.hpp"

#include <algorithm>
#include <mutex>
#include <set>
#include <sstream>

#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::numeric;

namespace {

void indexed_sum_latex(const ex& body, const ex& index, const ex& lower, const ex& upper,
                       const GiNaC::print_context& c) {
  c.s << "\\sum_{" << index << " = " << lower << "}^{" << upper << "} \\left(" << body
      << "\\right)";
}
void indexed_product_latex(const ex& body, const ex& index, const ex& lower, const ex& upper,
                           const GiNaC::print_context& c) {
  c.s << "\\prod_{" << index << " = " << lower << "}^{" << upper << "} \\left(" << body
      << "\\right)";
}
void indexed_sum_plain(const ex& body, const ex& index, const ex& lower, const ex& upper,
                       const GiNaC::print_context& c) {
  c.s << "sum(" << body << ", " << index << "=" << lower << ".." << upper << ")";
}
void indexed_product_plain(const ex& body, const ex& index, const ex& lower, const ex& upper,
                           const GiNaC::print_context& c) {
  c.s << "product(" << body << ", " << index << "=" << lower << ".." << upper << ")";
}

// The functions registered for the files, by (name, arguments): serials are for the process.
struct Registry {
  std::mutex lock;
  std::map<std::pair<std::string, unsigned>, unsigned> serials;
  std::set<unsigned> abstract;
};

Registry& registry() {
  static Registry r;
  return r;
}

bool registered_abstract(unsigned serial) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> hold(r.lock);
  return r.abstract.contains(serial);
}

}  // namespace

REGISTER_FUNCTION(indexed_sum, print_func<GiNaC::print_latex>(indexed_sum_latex)
                                   .print_func<GiNaC::print_dflt>(indexed_sum_plain))
REGISTER_FUNCTION(indexed_product, print_func<GiNaC::print_latex>(indexed_product_latex)
                                       .print_func<GiNaC::print_dflt>(indexed_product_plain))

unsigned abstract_function(const std::string& name, const std::string& latex, unsigned arguments) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> hold(r.lock);
  const auto key = std::pair{name, arguments};
  if (const auto found = r.serials.find(key); found != r.serials.end()) {
    return found->second;
  }
  // GiNaC's own functions (S, G, H, psi, zeta, …) keep their names: a file's takes a prefix
  // where the name is taken.
  std::string registered = name;
  try {
    (void)GiNaC::function::find_function(registered, arguments);
    registered = "fn_" + name;
  } catch (const std::exception&) {
  }
  const unsigned serial = GiNaC::function::register_new(
      GiNaC::function_options(registered, arguments).latex_name(latex));
  r.serials.emplace(key, serial);
  r.abstract.insert(serial);
  return serial;
}

bool is_abstract(const ex& e) {
  if (is_a<GiNaC::fderivative>(e) || is_a<GiNaC::function>(e)) {
    return registered_abstract(GiNaC::ex_to<GiNaC::function>(e).get_serial());
  }
  return false;
}

namespace {

bool is_indexed(const ex& e) {
  if (!is_a<GiNaC::function>(e)) {
    return false;
  }
  const unsigned serial = GiNaC::ex_to<GiNaC::function>(e).get_serial();
  return serial == indexed_sum_SERIAL::serial || serial == indexed_product_SERIAL::serial;
}

bool is_atom(const ex& e) {
  return is_a<GiNaC::integral>(e) || is_abstract(e) || is_indexed(e);
}

// The terms of an expanded expression.
std::vector<ex> terms(const ex& e) {
  std::vector<ex> list;
  if (is_a<GiNaC::add>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      list.push_back(e.op(i));
    }
  } else {
    list.push_back(e);
  }
  return list;
}

// A term as (the factors that do not depend, the factors that do).
std::pair<ex, ex> split_term(const ex& term, const std::function<bool(const ex&)>& depends) {
  ex constant = 1;
  ex varying = 1;
  sym::for_each_factor(term, [&](const ex& f) { (depends(f) ? varying : constant) *= f; });
  return {constant, varying};
}

}  // namespace

bool has_atoms(const ex& e) {
  if (is_atom(e)) {
    return true;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_atoms(e.op(i))) {
      return true;
    }
  }
  return false;
}

ex sum_over(const ex& body, const ex& index, const ex& lower, const ex& upper,
            const std::function<bool(const ex&)>& depends) {
  const ex count = upper - lower + 1;
  ex total = 0;
  std::map<ex, ex, GiNaC::ex_is_less> grouped;  // varying part → its constant factor
  for (const ex& term : terms(GiNaC::expand(body))) {
    const auto [constant, varying] = split_term(term, depends);
    if (varying.is_equal(1)) {
      total += constant * count;
    } else {
      grouped[varying] += constant;
    }
  }
  for (const auto& [varying, constant] : grouped) {
    total += constant * indexed_sum(varying, index, lower, upper);
  }
  return total;
}

ex product_over(const ex& body, const ex& index, const ex& lower, const ex& upper,
                const std::function<bool(const ex&)>& depends) {
  const auto [constant, varying] = split_term(body, depends);
  const ex outside = GiNaC::pow(constant, upper - lower + 1);
  return varying.is_equal(1) ? outside : outside * indexed_product(varying, index, lower, upper);
}

// ---- integrals ---------------------------------------------------------------------------------

namespace {

// An antiderivative of g in x (g depends on x), where a formula is known.
std::optional<ex> antiderivative(const ex& g, const ex& x, int depth = 0) {
  if (depth > 8) {
    return std::nullopt;
  }
  const auto& s = GiNaC::ex_to<GiNaC::symbol>(x);
  if (g.is_polynomial(x)) {
    ex sum = 0;
    const ex expanded = GiNaC::expand(g);
    for (int k = expanded.ldegree(x); k <= expanded.degree(x); ++k) {
      sum += expanded.coeff(x, k) * GiNaC::pow(x, k + 1) / (k + 1);
    }
    return sum;
  }
  if (is_a<GiNaC::add>(g)) {
    ex sum = 0;
    for (std::size_t i = 0; i < g.nops(); ++i) {
      const ex part = g.op(i);
      if (!part.has(x)) {
        sum += part * x;
        continue;
      }
      const auto a = antiderivative(part, x, depth + 1);
      if (!a) {
        return std::nullopt;
      }
      sum += *a;
    }
    return sum;
  }
  if (is_a<GiNaC::mul>(g)) {
    // A constant factor comes out; a polynomial times sin, cos or exp of a linear argument is
    // done by parts.
    ex constant = 1;
    ex polynomial = 1;
    std::vector<ex> rest;
    for (std::size_t i = 0; i < g.nops(); ++i) {
      const ex f = g.op(i);
      if (!f.has(x)) {
        constant *= f;
      } else if (f.is_polynomial(x)) {
        polynomial *= f;
      } else {
        rest.push_back(f);
      }
    }
    if (!constant.is_equal(1)) {
      const auto a = antiderivative(g / constant, x, depth + 1);
      return a ? std::optional<ex>(constant * *a) : std::nullopt;
    }
    if (rest.size() == 1 && !polynomial.is_equal(1)) {
      const ex f = rest[0];
      const bool trig =
          sym::is_function(f, "sin") || sym::is_function(f, "cos") || sym::is_function(f, "exp");
      const auto km = trig ? sym::linear_in(f.op(0), x) : std::nullopt;
      if (km && GiNaC::expand(polynomial).degree(x) <= 6) {
        // ∫ P f = P F − ∫ P' F, with F an antiderivative of f.
        const auto outer = antiderivative(f, x, depth + 1);
        if (!outer) {
          return std::nullopt;
        }
        const auto inner = antiderivative(GiNaC::expand(polynomial.diff(s) * *outer), x, depth + 1);
        if (!inner) {
          return std::nullopt;
        }
        return polynomial * *outer - *inner;
      }
    }
    return std::nullopt;
  }
  if (is_a<GiNaC::power>(g)) {
    const ex base = g.op(0);
    const ex exponent = g.op(1);
    const auto km = sym::linear_in(base, x);
    if (km && !exponent.has(x)) {
      if (exponent.is_equal(-1)) {
        return GiNaC::log(base) / km->first;
      }
      return GiNaC::pow(base, exponent + 1) / (km->first * (exponent + 1));
    }
    return std::nullopt;
  }
  if (is_a<GiNaC::function>(g) && g.nops() == 1) {
    const auto km = sym::linear_in(g.op(0), x);
    if (sym::is_function(g, "sin") && km) {
      return -GiNaC::cos(g.op(0)) / km->first;
    }
    if (sym::is_function(g, "cos") && km) {
      return GiNaC::sin(g.op(0)) / km->first;
    }
    if (sym::is_function(g, "exp") && km) {
      return GiNaC::exp(g.op(0)) / km->first;
    }
  }
  // The derivative of a declared function of x: the fundamental theorem.
  if (is_a<GiNaC::fderivative>(g) && g.nops() == 1 && g.op(0).is_equal(x) && is_abstract(g)) {
    const auto& d = GiNaC::ex_to<GiNaC::fderivative>(g);
    // Differentiated once or more: the antiderivative differentiates once less.
    const std::size_t order = d.derivatives().size();
    const ex f = GiNaC::function(d.get_serial(), x);
    return order <= 1 ? f : f.diff(s, static_cast<unsigned>(order - 1));
  }
  return std::nullopt;
}

// A real number when e is one (π and square roots evaluated), else nothing.
std::optional<double> real_value(const ex& e) {
  const ex v = GiNaC::evalf(e);
  if (!is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) {
    return std::nullopt;
  }
  return GiNaC::ex_to<numeric>(v).to_double();
}

// Whether the formulas of antiderivative() hold for g between a and b: every power of an
// expression in x with a negative or fractional exponent (1 / (1 + x), \sqrt{x}) has its base
// linear in x; a negative exponent's base is positive at both limits given as numbers (so on
// the whole interval; for a whole exponent other than -1, of one sign there), and a fractional
// one's is not negative at a limit given as a number. A pole between the limits, or between
// limits that are not numbers, leaves the integral undone rather than evaluated across it.
bool formulas_hold(const ex& g, const ex& x, const ex& a, const ex& b, const SignOf& sign) {
  for (auto i = g.preorder_begin(); i != g.preorder_end(); ++i) {
    if (!is_a<GiNaC::power>(*i) || !i->op(0).has(x)) {
      continue;
    }
    const ex exponent = i->op(1);
    if (is_a<numeric>(exponent) && GiNaC::ex_to<numeric>(exponent).is_nonneg_integer()) {
      continue;
    }
    const ex base = i->op(0);
    if (!sym::linear_in(base, x)) {
      return false;
    }
    // The base's value at a limit, or where only its sign is known, ±1 for that sign.
    const auto at = [&](const ex& limit) -> std::optional<double> {
      const ex value = base.subs(x == limit);
      if (const auto v = real_value(value)) {
        return v;
      }
      const int s = sign ? sign(value) : 0;
      return s == 0 ? std::nullopt : std::optional<double>(s);
    };
    const auto at_a = at(a);
    const auto at_b = at(b);
    if (!is_a<numeric>(exponent)) {
      return false;  // x^n: the formula x^{n+1} / (n + 1) fails at n = -1
    }
    const bool pole = GiNaC::ex_to<numeric>(exponent).is_negative();
    if (!pole) {
      // \sqrt{s} and the like: finite, and real where the base is not negative (limits that
      // are symbols are taken as the file writes them, as for the power itself).
      if ((at_a && *at_a < 0) || (at_b && *at_b < 0)) {
        return false;
      }
      continue;
    }
    if (!at_a || !at_b) {
      return false;
    }
    const bool whole = GiNaC::ex_to<numeric>(exponent).is_integer() && !exponent.is_equal(-1);
    const bool clear =
        whole ? (*at_a > 0 && *at_b > 0) || (*at_a < 0 && *at_b < 0) : *at_a > 0 && *at_b > 0;
    if (!clear) {
      return false;
    }
  }
  return true;
}

}  // namespace

ex integrate(const ex& f, const ex& x, const ex& a, const ex& b, const SignOf& sign) {
  if (!f.has(x)) {
    return f * (b - a);
  }
  ex total = 0;
  ex undone = 0;
  for (const ex& term : terms(GiNaC::expand(f))) {
    const auto [constant, varying] = split_term(term, [&](const ex& e) { return e.has(x); });
    const auto a_of =
        formulas_hold(varying, x, a, b, sign) ? antiderivative(varying, x) : std::optional<ex>();
    if (a_of) {
      total += constant * (a_of->subs(x == b) - a_of->subs(x == a));
    } else {
      undone += term;
    }
  }
  // What is left undone, term by term with the factors free of x outside (the integral is
  // linear: ∫(F + H) is ∫F + ∫H), unless it has many terms (one integral then).
  const ex left = GiNaC::expand(undone);
  const std::vector<ex> parts = terms(left);
  if (parts.size() > 8) {
    return total + GiNaC::integral(x, a, b, left);
  }
  for (const ex& term : parts) {
    const auto [constant, varying] = split_term(term, [&](const ex& e) { return e.has(x); });
    total += constant * GiNaC::integral(x, a, b, varying);
  }
  return total;
}

ex integrals_by_sign(const ex& e, const SignOf& sign) {
  if (std::none_of(e.preorder_begin(), e.preorder_end(),
                   [](const ex& x) { return is_a<GiNaC::integral>(x); })) {
    return e;
  }
  // From the bottom up: an integral's integrand and limits first.
  const ex inner =
      sym::map_parts(e, [&sign](const ex& part) { return integrals_by_sign(part, sign); });
  if (is_a<GiNaC::integral>(inner)) {
    // op(0) the variable, op(1) and op(2) the limits, op(3) the integrand.
    return integrate(inner.op(3), inner.op(0), inner.op(1), inner.op(2), sign);
  }
  return inner;
}

// ---- atoms -------------------------------------------------------------------------------------

namespace {

// The variable of an integral at each depth of nesting, for integrals compared in one form.
const GiNaC::symbol& bound_variable(std::size_t depth) {
  static const std::vector<GiNaC::symbol> variables = [] {
    std::vector<GiNaC::symbol> v;
    for (int k = 0; k < 8; ++k) {
      v.emplace_back("x_" + std::to_string(k));
    }
    return v;
  }();
  return variables[depth];
}

// @p e with each integral in one form: its variable the one of its depth, its limits in GiNaC's
// order (and a minus sign where they were swapped), integrals inside likewise; nothing changed
// past a depth of 8. ∫_0^T F(s) ds and -∫_T^0 F(t) dt are then one expression.
ex one_form(const ex& e, std::size_t depth) {
  if (is_a<GiNaC::integral>(e) && depth < 8) {
    const ex& variable = bound_variable(depth);
    const ex low = one_form(e.op(1), depth);
    const ex high = one_form(e.op(2), depth);
    const ex body = one_form(e.op(3).subs(e.op(0) == variable), depth + 1);
    return low.compare(high) > 0 ? -GiNaC::integral(variable, high, low, body)
                                 : GiNaC::integral(variable, low, high, body);
  }
  if (e.nops() == 0) {
    return e;
  }
  return sym::map_parts(e, [depth](const ex& part) { return one_form(part, depth); });
}

}  // namespace

ex Atoms::hide(const ex& e) {
  if (is_atom(e)) {
    // An integral is kept in one form (its variable renamed, its limits ordered), so that the
    // same integral written two ways is one quantity.
    if (is_a<GiNaC::integral>(e)) {
      const ex form = one_form(e, 0);
      if (!form.is_equal(e)) {
        if (is_a<GiNaC::integral>(form)) {
          return hide_as(form, e);
        }
        return -hide_as(-form, -e);
      }
    }
    return hide_as(e, e);
  }
  if (e.nops() == 0) {
    return e;
  }
  return sym::map_parts(e, [this](const ex& part) { return hide(part); });
}

ex Atoms::hide_as(const ex& key, const ex& e) {
  if (const auto found = forward_.find(key); found != forward_.end()) {
    return found->second;
  }
  std::ostringstream plain;
  std::ostringstream latex;
  plain << GiNaC::dflt << e;
  latex << GiNaC::latex << e;
  const ex symbol = GiNaC::realsymbol(plain.str(), latex.str());
  forward_[key] = symbol;
  backward_[symbol] = e;
  return symbol;
}

ex Atoms::show(const ex& e) const {
  return backward_.empty() ? e : e.subs(backward_);
}

// ---- instances ---------------------------------------------------------------------------------

const GiNaC::symbol& instance_variable() {
  static const GiNaC::symbol u("u");
  return u;
}

namespace {

void collect(const ex& e, std::set<unsigned>& functions, std::set<ex, GiNaC::ex_is_less>& limits,
             std::map<unsigned, std::string>& names) {
  if (is_abstract(e)) {
    const auto& f = GiNaC::ex_to<GiNaC::function>(e);
    functions.insert(f.get_serial());
    names[f.get_serial()] = f.get_name();
  }
  if (is_indexed(e)) {
    for (const ex& limit : {e.op(2), e.op(3)}) {
      for (auto i = limit.preorder_begin(); i != limit.preorder_end(); ++i) {
        if (is_a<GiNaC::symbol>(*i)) {
          limits.insert(*i);
        }
      }
    }
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    collect(e.op(i), functions, limits, names);
  }
}

std::string text_of(const ex& e) {
  std::ostringstream out;
  out << GiNaC::dflt << e;
  return out.str();
}

}  // namespace

std::vector<Instance> instances(const std::vector<ex>& expressions, std::size_t most) {
  std::set<unsigned> functions;
  std::set<ex, GiNaC::ex_is_less> limits;
  std::map<unsigned, std::string> names;
  for (const ex& e : expressions) {
    collect(e, functions, limits, names);
  }
  // The functions and the limits by their names: their serials and GiNaC's order of symbols
  // follow what the process made before (another file checked first registered p before F),
  // and the formulas each gets must not.
  std::vector<std::pair<std::string, unsigned>> by_name;
  for (const unsigned serial : functions) {
    by_name.emplace_back(names[serial], serial);
  }
  std::sort(by_name.begin(), by_name.end());
  std::vector<std::pair<std::string, ex>> limits_by_name;
  for (const ex& limit : limits) {
    limits_by_name.emplace_back(text_of(limit), limit);
  }
  std::sort(limits_by_name.begin(), limits_by_name.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  const ex u = instance_variable();
  // Polynomials first; then an exponential, which a differential equation of decay or growth
  // asks for (x' = -k x holds for no polynomial but 0).
  const std::vector<ex> formulas{
      1, u, u * u, 1 + u, 2 - u, u * u * u - u, 1 + 2 * u + u * u, GiNaC::exp(u)};
  const std::vector<long> counts{2, 3, 1};
  std::vector<Instance> list;
  for (std::size_t k = 0; k < most; ++k) {
    Instance instance;
    std::size_t f = 0;
    for (const auto& [written, serial] : by_name) {
      const ex formula = formulas[(k + f) % formulas.size()];
      instance.formulas[serial] = formula;
      std::string name = names[serial];
      if (name.starts_with("fn_")) {
        name = name.substr(3);
      }
      instance.text += (instance.text.empty() ? "" : ", ") + name + "(u) = " + text_of(formula);
      ++f;
    }
    std::size_t l = 0;
    for (const auto& [written, limit] : limits_by_name) {
      const long value = counts[(k + l) % counts.size()];
      instance.limits[limit] = value;
      instance.text +=
          (instance.text.empty() ? "" : ", ") + text_of(limit) + " = " + std::to_string(value);
      ++l;
    }
    list.push_back(std::move(instance));
    if (functions.empty() && k + 1 >= counts.size()) {
      break;
    }
  }
  return list;
}

ex instantiate(const ex& e, const Instance& instance, const AtIndex& at_index) {
  const ex u = instance_variable();
  const std::function<ex(const ex&)> walk = [&](const ex& x) -> ex {
    if (is_abstract(x)) {
      const auto& f = GiNaC::ex_to<GiNaC::function>(x);
      const auto formula = instance.formulas.find(f.get_serial());
      if (formula == instance.formulas.end() || x.nops() != 1) {
        return x;
      }
      const ex argument = walk(x.op(0));
      ex value = formula->second;
      if (is_a<GiNaC::fderivative>(x)) {
        const auto order =
            static_cast<unsigned>(GiNaC::ex_to<GiNaC::fderivative>(x).derivatives().size());
        value = value.diff(GiNaC::ex_to<GiNaC::symbol>(u), order);
      }
      return value.subs(u == argument);
    }
    if (is_indexed(x)) {
      const ex lower = walk(x.op(2)).subs(instance.limits);
      const ex upper = walk(x.op(3)).subs(instance.limits);
      if (!is_a<GiNaC::numeric>(lower) || !is_a<GiNaC::numeric>(upper) ||
          !GiNaC::ex_to<GiNaC::numeric>(lower).is_integer() ||
          !GiNaC::ex_to<GiNaC::numeric>(upper).is_integer()) {
        return x;
      }
      const long from = GiNaC::ex_to<GiNaC::numeric>(lower).to_long();
      const long to = GiNaC::ex_to<GiNaC::numeric>(upper).to_long();
      const bool sum = GiNaC::ex_to<GiNaC::function>(x).get_serial() == indexed_sum_SERIAL::serial;
      ex total = sum ? ex(0) : ex(1);
      for (long k = from; k <= to && k - from < 100; ++k) {
        const ex term = walk(at_index(x.op(0), x.op(1), k));
        total = sum ? total + term : total * term;
      }
      return total;
    }
    if (is_a<GiNaC::integral>(x)) {
      const ex variable = x.op(0);
      return integrate(walk(x.op(3)), variable, walk(x.op(1)), walk(x.op(2)));
    }
    if (x.nops() == 0) {
      return x.subs(instance.limits);
    }
    return sym::map_parts(x, walk);
  };
  return walk(e);
}

// ---- rules ------------------------------------------------------------------------------------

std::vector<ex> function_variables(const ex& e, const IsVariable& is_variable) {
  std::vector<ex> found;
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (is_abstract(*i) && i->nops() == 1 && is_a<GiNaC::symbol>(i->op(0)) &&
        is_variable(GiNaC::ex_to<GiNaC::function>(*i).get_serial(), i->op(0)) &&
        std::none_of(found.begin(), found.end(),
                     [&](const ex& v) { return v.is_equal(i->op(0)); })) {
      found.push_back(i->op(0));
    }
  }
  return found;
}

namespace {

// Whether an equation can give a rule: it holds a value of a function, and it expands into few
// terms ((a+b+c)^{1000} would be half a million, and nobody writes F(t) = … inside one).
bool may_give_rule(const ex& equation) {
  if (expanded_terms(equation) > most_expanded_terms) {
    return false;
  }
  for (auto i = equation.preorder_begin(); i != equation.preorder_end(); ++i) {
    if (is_abstract(*i) && i->nops() == 1 && is_a<GiNaC::symbol>(i->op(0))) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<Rule> rules_of(const std::vector<ex>& equations, const IsVariable& is_variable) {
  std::vector<Rule> rules;
  for (const ex& equation : equations) {
    if (!may_give_rule(equation)) {
      continue;
    }
    const ex e = GiNaC::expand(equation);
    // The candidates in one order in every run: values before derivatives, then by their text.
    std::vector<std::pair<std::pair<std::size_t, std::string>, ex>> candidates;
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      if (!is_abstract(*i) || i->nops() != 1 || !is_a<GiNaC::symbol>(i->op(0))) {
        continue;
      }
      const std::size_t order = is_a<GiNaC::fderivative>(*i)
                                    ? GiNaC::ex_to<GiNaC::fderivative>(*i).derivatives().size()
                                    : 0;
      std::ostringstream text;
      text << GiNaC::dflt << *i;
      candidates.push_back({{order, text.str()}, *i});
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [key, atom] : candidates) {
      const unsigned serial = GiNaC::ex_to<GiNaC::function>(atom).get_serial();
      if (!is_variable(serial, atom.op(0))) {
        continue;  // p(T) = p_0 + J holds at T, not at every t
      }
      // Linear in the atom with a number as the coefficient, and no other value of F.
      const GiNaC::symbol slot("slot");
      const ex replaced = e.subs(atom == slot);
      bool other = false;
      for (auto j = replaced.preorder_begin(); j != replaced.preorder_end(); ++j) {
        other =
            other || (is_abstract(*j) && GiNaC::ex_to<GiNaC::function>(*j).get_serial() == serial);
      }
      if (other || !replaced.is_polynomial(slot) || replaced.degree(slot) != 1) {
        continue;
      }
      const ex coefficient = replaced.coeff(slot, 1);
      if (!is_a<GiNaC::numeric>(coefficient) || coefficient.is_zero()) {
        continue;
      }
      rules.push_back({serial, key.first, atom.op(0), -replaced.coeff(slot, 0) / coefficient});
      break;
    }
  }
  return rules;
}

ex rewritten(const ex& e, const std::vector<Rule>& rules) {
  if (rules.empty() || !has_atoms(e)) {
    return e;
  }
  const std::function<ex(const ex&)> walk = [&](const ex& x) -> ex {
    if (is_abstract(x) && x.nops() == 1) {
      const unsigned serial = GiNaC::ex_to<GiNaC::function>(x).get_serial();
      const std::size_t order = is_a<GiNaC::fderivative>(x)
                                    ? GiNaC::ex_to<GiNaC::fderivative>(x).derivatives().size()
                                    : 0;
      // The rule of the highest order not above the atom's: F'' from a rule for F'.
      const Rule* best = nullptr;
      for (const Rule& r : rules) {
        if (r.serial == serial && r.order <= order && (best == nullptr || r.order > best->order)) {
          best = &r;
        }
      }
      if (best == nullptr) {
        return x;
      }
      const ex argument = walk(x.op(0));
      ex value = best->value;
      if (order > best->order) {
        value = value.diff(GiNaC::ex_to<GiNaC::symbol>(best->variable),
                           static_cast<unsigned>(order - best->order));
      }
      return value.subs(best->variable == argument);
    }
    if (is_a<GiNaC::integral>(x)) {
      return integrate(walk(x.op(3)), x.op(0), walk(x.op(1)), walk(x.op(2)));
    }
    if (x.nops() == 0) {
      return x;
    }
    return sym::map_parts(x, walk);
  };
  return walk(e);
}

}  // namespace impulse::derivations::file
