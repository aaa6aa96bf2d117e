// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/step.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>

#include "file/decide.hpp"
#include "file/sample.hpp"
#include "file/time.hpp"
#include "numeric.hpp"
#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;

namespace {

void merge(Implication& total, const Implication& one) {
  using O = Implication::Outcome;
  if (total.outcome == O::fails) {
    return;
  }
  if (one.outcome == O::fails) {
    total = one;
    return;
  }
  if (one.outcome == O::unknown) {
    total.outcome = O::unknown;
    total.residual = one.residual;
    total.how = one.how;
    return;
  }
  if (total.outcome == O::unknown) {
    return;
  }
  if (one.outcome == O::holds_if) {
    total.outcome = O::holds_if;
    total.conditions.insert(total.conditions.end(), one.conditions.begin(), one.conditions.end());
    total.conditions_needed = total.conditions_needed && one.conditions_needed;
  }
  if (total.how.empty()) {
    total.how = one.how;
  } else if (!one.how.empty() && one.how != total.how) {
    total.how += "; " + one.how;
  }
}

std::optional<bool> converse_holds(const Scalars& before, const Scalars& step, const Facts& facts) {
  using O = Implication::Outcome;
  // Only whether the converse fails matters here, not the nicest point that shows it.
  Budget budget;
  budget.attempts = 48;
  budget.candidates = 1;
  bool all = true;
  for (const ex& target : before.differences) {
    const Implication back =
        implies({step.differences, step.denominators, target, before.denominators}, facts, budget);
    if (back.outcome == O::fails || back.outcome == O::holds_if) {
      return false;
    }
    if (back.outcome == O::unknown) {
      all = false;
    }
  }
  return all ? std::optional<bool>(true) : std::nullopt;
}

std::string trimmed(std::string text) {
  const std::size_t first = text.find_first_not_of(' ');
  const std::size_t last = text.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

ex readable(const ex& e) {
  const ex n = GiNaC::normal(e);
  if (!factorable(n.numer()) || !factorable(n.denom())) {
    return n;  // shown over one denominator, unfactored
  }
  try {
    return GiNaC::factor(n.numer()) / GiNaC::factor(n.denom());
  } catch (const std::exception&) {
    return n;
  }
}

std::string number_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

}  // namespace

std::string latex_of(const ex& e) {
  return trimmed(sym::latex(e));
}

std::string plain_of(const ex& e) {
  // Over one denominator, printed as numerator/denominator: "4*p_2/m_2", not "4*m_2^(-1)*p_2".
  const auto print = [](const ex& x) { return sym::plain(x); };
  const auto grouped = [&](const ex& x, bool denominator) {
    const std::string t = print(x);
    const bool group = GiNaC::is_a<GiNaC::add>(x) || (denominator && GiNaC::is_a<GiNaC::mul>(x));
    return group ? "(" + t + ")" : t;
  };
  ex parts;
  try {
    parts = GiNaC::normal(e).numer_denom();
  } catch (const std::exception&) {
    return print(e);
  }
  const ex numerator = parts.op(0);
  const ex denominator = parts.op(1);
  if (denominator.is_equal(1)) {
    return print(numerator);
  }
  return grouped(numerator, false) + "/" + grouped(denominator, true);
}

// A residual as a person reads it: over one denominator, factored when that is cheap.

void for_each_scalar(const Equation& e, const std::function<void(const ex&, const ex&)>& each) {
  if (e.lhs.value.block()) {
    for (std::size_t k = 0; k < e.lhs.value.entries.size(); ++k) {
      each(e.lhs.value.entries[k], e.rhs.value.entries[k]);
    }
    return;
  }
  each(e.lhs.value.x, e.rhs.value.x);
  if (e.lhs.value.vector) {
    each(e.lhs.value.y, e.rhs.value.y);
  }
}

Scalars scalars_of(const Equation& e, const GiNaC::exmap& substitutions) {
  Scalars s;
  for_each_scalar(e, [&](const ex& l, const ex& r) {
    const ex left = exact_reading(l.subs(substitutions));
    const ex right = exact_reading(r.subs(substitutions));
    s.differences.push_back(left - right);
    s.scales.push_back(term_scale(left) + term_scale(right));
  });
  for (const ex& d : e.lhs.denominators) {
    s.denominators.push_back(d.subs(substitutions));
  }
  for (const ex& d : e.rhs.denominators) {
    s.denominators.push_back(d.subs(substitutions));
  }
  return s;
}

EquationResult Checker::check(const std::vector<Equation>& equations, std::size_t index,
                              const Source& source, const std::vector<std::size_t>* premises) {
  Equation variant;
  if (premises != nullptr) {
    variant = equations[index];
    variant.premises = *premises;
  }
  const Equation& e = premises != nullptr ? variant : equations[index];
  EquationResult r;
  const Place place = source.place(e.offset);
  r.line = place.line;
  r.column = place.column;
  r.tag = e.tag;
  r.latex = e.latex;
  for (const std::size_t p : e.premises) {
    r.from.push_back(source.place(equations[p].offset).line);
  }
  if (e.dimension_issue) {
    r.verdict = Verdict::dimensions;
    r.dimension_first = e.dimension_issue->first.text();
    r.dimension_second = e.dimension_issue->second.text();
    r.dimension_what = e.dimension_issue->what;
    r.how = "units: " + e.dimension_issue->what;
    return r;
  }
  if (e.premise) {
    r.verdict = Verdict::premise;
    return r;
  }
  decide(equations, e, index, r);
  return r;
}

void Checker::decide(const std::vector<Equation>& equations, const Equation& e, std::size_t index,
                     EquationResult& r) {
  const Scalars step = scalars_of(e, e.substitutions);
  Scalars before;
  for (const std::size_t p : e.premises) {
    const Scalars s = scalars_of(equations[p], e.substitutions);
    before.differences.insert(before.differences.end(), s.differences.begin(), s.differences.end());
    before.scales.insert(before.scales.end(), s.scales.begin(), s.scales.end());
    before.denominators.insert(before.denominators.end(), s.denominators.begin(),
                               s.denominators.end());
  }

  // The exact method, component by component.
  Implication forward;
  forward.outcome = Implication::Outcome::holds;
  for (const ex& target : step.differences) {
    Implication one =
        implies({before.differences, before.denominators, target, step.denominators}, e.facts);
    merge(forward, one);
  }

  // The numeric method, as a second opinion. Where the exact method found conditions, the
  // points where one of them is zero are left out like those where a denominator is.
  NumericOpinion numeric;
  for (std::size_t k = 0; k < step.differences.size(); ++k) {
    std::vector<ex> denominators = before.denominators;
    denominators.insert(denominators.end(), step.denominators.begin(), step.denominators.end());
    if (forward.outcome == Implication::Outcome::holds_if) {
      denominators.insert(denominators.end(), forward.conditions.begin(), forward.conditions.end());
    }
    NumericProblem problem{before.differences, before.scales, denominators, step.differences[k],
                           step.scales[k]};
    const NumericOpinion one =
        sample(problem, e.facts, options_.seed * 7919 + index * 31 + k, options_.samples);
    numeric.points += one.points;
    numeric.worst = std::max(numeric.worst, one.worst);
    if (!numeric.counterexample && one.counterexample) {
      numeric.counterexample = one.counterexample;
      numeric.counterexample_residual = one.counterexample_residual;
    }
    numeric.how = one.how;
  }
  r.numeric_points = numeric.points;
  r.numeric_worst = numeric.worst;

  using O = Implication::Outcome;
  const std::string numeric_note =
      numeric.points == 0
          ? "numeric: " + numeric.how
          : "numeric: " + numeric.how + ", worst relative residual " + num::brief(numeric.worst, 2);
  switch (forward.outcome) {
    case O::holds:
    case O::holds_if: {
      if (numeric.counterexample) {
        r.verdict = Verdict::undecided;
        r.how = "the exact method finds that it follows (" + forward.how +
                "), but the numeric method finds a point where it fails (relative residual " +
                num::brief(numeric.counterexample_residual, 2) +
                "): the two disagree, so no verdict is given";
        numeric_point(*numeric.counterexample, r);
        return;
      }
      r.decided_by = "exact";
      if (forward.outcome == O::holds_if) {
        r.verdict = Verdict::follows_if;
        ex product = 1;
        std::string text;
        for (const ex& c : forward.conditions) {
          product *= c;
        }
        product = sym::up_to_sign(product);  // its sign does not matter: one form in every run
        r.condition = latex_of(product) + " \\neq 0";
        r.condition_text = plain_of(product) + " != 0";
        r.condition_needed = forward.conditions_needed;
        r.how = "exact: " + forward.how + "; " + numeric_note;
        if (!forward.conditions_needed) {
          r.how += "; whether the condition is needed was not decided";
        }
        return;
      }
      const std::optional<bool> converse = converse_holds(before, step, e.facts);
      r.converse = converse;
      r.verdict = converse.value_or(false) ? Verdict::follows : Verdict::follows_one_way;
      r.how = "exact: " + (forward.how.empty() ? std::string("it holds once the equations "
                                                             "before are used")
                                               : forward.how);
      if (!converse) {
        r.how += "; whether the equations before follow from it was not decided";
      } else if (!*converse) {
        r.how += "; the equations before do not follow from it";
      }
      r.how += "; " + numeric_note;
      return;
    }
    case O::fails: {
      r.verdict = Verdict::does_not_follow;
      r.decided_by = "exact";
      residual(forward.residual, r);
      exact_point(*forward.point, r);
      r.how = "exact: " +
              (forward.how.empty() ? std::string("what is left of the step does "
                                                 "not vanish")
                                   : forward.how) +
              "; the counterexample satisfies the equations before and the facts exactly";
      return;
    }
    case O::unknown:
      break;
  }
  if (numeric.counterexample) {
    r.verdict = Verdict::does_not_follow;
    r.decided_by = "numeric";
    residual(forward.residual, r);
    numeric_point(*numeric.counterexample, r);
    r.how = "exact: undecided (" + forward.how +
            "); numeric: a point on the equations before "
            "where the step fails (relative residual " +
            num::brief(numeric.counterexample_residual, 2) + ")";
    return;
  }
  r.verdict = Verdict::undecided;
  r.how = "exact: " + forward.how + "; " + numeric_note +
          " (agreement at random points is not a proof)";
}

void Checker::residual(const ex& e, EquationResult& r) const {
  const ex shown = readable(e);
  r.residual = latex_of(shown);
  r.residual_text = plain_of(shown);
}

template <typename Value>
void Checker::point(const std::vector<std::pair<ex, Value>>& values, EquationResult& r,
                    const std::function<double(const Value&)>& to_double,
                    const std::function<std::string(const Value&)>& exact) const {
  std::map<std::string, CounterexampleValue> entries;
  for (const auto& [symbol, value] : values) {
    const SymbolInfo* info = symbols_.info(symbol);
    if (info == nullptr) {
      continue;
    }
    if (info->of) {
      CounterexampleValue& v = entries[info->of->latex()];
      v.symbol = info->of->latex();
      v.vector = true;
      (info->component == 0 ? v.x : v.y) = to_double(value);
      (info->component == 0 ? v.exact_x : v.exact_y) = exact(value);
    } else {
      CounterexampleValue& v = entries[info->name.latex()];
      v.symbol = info->name.latex();
      v.x = to_double(value);
      v.exact_x = exact(value);
    }
  }
  for (auto& [name, value] : entries) {
    r.counterexample.push_back(std::move(value));
  }
}

void Checker::exact_point(const GiNaC::exmap& values, EquationResult& r) const {
  std::vector<std::pair<ex, ex>> list(values.begin(), values.end());
  point<ex>(
      list, r,
      [](const ex& v) {
        const ex f = GiNaC::evalf(v);
        return GiNaC::is_a<GiNaC::numeric>(f) ? GiNaC::ex_to<GiNaC::numeric>(f).to_double() : 0.0;
      },
      [](const ex& v) {
        return GiNaC::is_a<GiNaC::numeric>(v) ? number_text(GiNaC::ex_to<GiNaC::numeric>(v))
                                              : plain_of(v);
      });
  r.counterexample_exact = true;
}

void Checker::numeric_point(const std::vector<std::pair<ex, double>>& values,
                            EquationResult& r) const {
  point<double>(
      values, r, [](const double& v) { return v; }, [](const double&) { return std::string(); });
  r.counterexample_exact = false;
}

}  // namespace impulse::derivations::file
