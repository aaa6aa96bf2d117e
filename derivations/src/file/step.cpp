// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/step.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <sstream>

#include "file/calculus.hpp"
#include "file/decide.hpp"
#include "file/sample.hpp"
#include "file/text.hpp"
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
    if (!total.point) {
      total.point = one.point;
    }
  }
  if (total.how.empty()) {
    total.how = one.how;
  } else if (!one.how.empty() && one.how != total.how) {
    total.how += "; " + one.how;
  }
}

// A residual as a person reads it: over one denominator, factored when that is cheap.
ex readable(const ex& e) {
  if (expanded_terms(e) > most_expanded_terms) {
    return e;  // too large to bring over one denominator: shown as it stands
  }
  const ex n = GiNaC::normal(e);
  // GiNaC's factoring of a polynomial in several symbols took more than a minute on a residual
  // of 44 terms in six symbols (in one of several runs: its time follows the order GiNaC gives
  // the symbols): what is shown is factored only when small.
  constexpr double shown_factored = 30;
  if (!factorable(n.numer()) || !factorable(n.denom()) ||
      expanded_terms(n.numer()) > shown_factored) {
    return n;  // shown over one denominator, unfactored
  }
  try {
    return factored(n.numer()) / factored(n.denom());
  } catch (const std::exception&) {
    return n;
  }
}

std::string number_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

// Whether e is a polynomial in its symbols: numbers, symbols, sums, products and powers with
// whole non-negative exponents.
bool polynomial(const ex& e) {
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (GiNaC::is_a<GiNaC::numeric>(*i) || GiNaC::is_a<GiNaC::symbol>(*i) ||
        GiNaC::is_a<GiNaC::add>(*i) || GiNaC::is_a<GiNaC::mul>(*i)) {
      continue;
    }
    if (GiNaC::is_a<GiNaC::power>(*i) && i->op(1).info(GiNaC::info_flags::nonnegint)) {
      continue;
    }
    return false;
  }
  return true;
}

// The constant c ≠ 0 with target = c · premise, shown at random rational points, before
// anything is expanded: (a + b + c)^{1000} against (c + b + a)^{999} (a + b + c) at once. Both
// are polynomials of degree at most d; where they differ, a random point with coordinates from
// 2^20 values shows it with probability at least 1 - d / 2^20 (Schwartz and Zippel), and eight
// points together miss it with probability below (d / 2^20)^8 (below 10^-24 for d = 1000).
std::optional<ex> proportional(const ex& target, const ex& premise, std::uint64_t seed) {
  if (!polynomial(target) || !polynomial(premise)) {
    return std::nullopt;
  }
  const std::vector<ex> symbols = symbols_of(std::vector<ex>{target, premise});
  std::uint64_t state = seed * 0x9E3779B97F4A7C15ULL + 1;
  const auto draw = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<long>((state >> 40) % (1UL << 20)) + 1;
  };
  std::optional<GiNaC::numeric> ratio;
  for (int k = 0; k < 8; ++k) {
    GiNaC::exmap point;
    for (const ex& s : symbols) {
      point[s] = GiNaC::numeric(draw(), 1 + draw() % 1024);
    }
    const ex p = premise.subs(point);
    const ex t = target.subs(point);
    if (!GiNaC::is_a<GiNaC::numeric>(p) || !GiNaC::is_a<GiNaC::numeric>(t) || p.is_zero()) {
      return std::nullopt;
    }
    const GiNaC::numeric here = GiNaC::ex_to<GiNaC::numeric>(t) / GiNaC::ex_to<GiNaC::numeric>(p);
    if (here.is_zero() || (ratio && here != *ratio)) {
      return std::nullopt;
    }
    ratio = here;
  }
  return ratio ? std::optional<ex>(*ratio) : std::nullopt;
}

// The scalars with the functions the rules write out replaced (three rounds: a rule's value may
// hold a function another rule writes out).
Scalars by_rules(Scalars s, const std::vector<Rule>& rules) {
  for (std::vector<ex>* list : {&s.differences, &s.scales, &s.denominators}) {
    for (ex& d : *list) {
      for (int round = 0; round < 3 && has_atoms(d); ++round) {
        d = rewritten(d, rules);
      }
    }
  }
  return s;
}

// The scalars with each integral that was left undone at reading done where the facts rule out
// a pole between its limits (∫_{m_f}^{m_0} u/m dm with m_0, m_f > 0 is u (ln m_0 - ln m_f)).
Scalars integrals_by_facts(Scalars s, const Facts& facts) {
  const SignOf sign = [&facts](const ex& e) {
    const Sign of = facts.sign(e);
    return of == Sign::positive ? 1 : of == Sign::negative ? -1 : 0;
  };
  for (std::vector<ex>* list : {&s.differences, &s.scales, &s.denominators}) {
    for (ex& d : *list) {
      d = integrals_by_sign(d, sign);
    }
  }
  return s;
}

// e with tangents, cotangents and secants written through sines and cosines, over one
// denominator, its numerator (3 \cos^2 \tan^2 - 4 is 3 \sin^2 - 4: its range shows its sign).
ex in_sines(const ex& e) {
  if (expanded_terms(e) > 200) {
    return e;
  }
  const auto sines = [](const ex& x) -> std::optional<ex> {
    if (sym::is_function(x, "tan")) {
      return GiNaC::sin(x.op(0)) / GiNaC::cos(x.op(0));
    }
    return std::nullopt;
  };
  try {
    return GiNaC::normal(sym::rewritten(e, sines)).numer();
  } catch (const std::exception&) {
    return e;
  }
}

// e reduced by equalities, each a polynomial with a whole-number leading coefficient in one of
// its symbols: the remainder of e's numerator and denominator on division by it.
ex reduced(const ex& e, const std::vector<ex>& equalities) {
  if (equalities.empty() || expanded_terms(e) > 2000) {
    return e;
  }
  ex parts;
  try {
    parts = GiNaC::normal(e).numer_denom();
  } catch (const std::exception&) {
    return e;
  }
  // π as a symbol (GiNaC divides over the rationals only), never the one reduced.
  ex numerator = pi_as_symbol(GiNaC::expand(parts.op(0)));
  ex denominator = pi_as_symbol(GiNaC::expand(parts.op(1)));
  for (const ex& q : equalities) {
    const ex p = pi_as_symbol(GiNaC::expand(q));
    for (const ex& v : symbols_of(p)) {
      if (v.is_equal(pi_as_symbol(GiNaC::Pi)) || !p.is_polynomial(v) || p.degree(v) < 1 ||
          !GiNaC::is_a<GiNaC::numeric>(p.lcoeff(v)) || !numerator.is_polynomial(v) ||
          !denominator.is_polynomial(v)) {
        continue;
      }
      try {
        numerator = GiNaC::expand(GiNaC::rem(numerator, p, v));
        denominator = GiNaC::expand(GiNaC::rem(denominator, p, v));
      } catch (const std::exception&) {
        return e;  // not polynomials over the rationals (a root of n_x^2 + n_y^2): as it stands
      }
      break;
    }
  }
  if (denominator.is_zero()) {
    return e;
  }
  return symbol_as_pi(numerator / denominator);
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
  if (expanded_terms(e) > most_expanded_terms) {
    return print(e);  // too large to bring over one denominator: printed as it stands
  }
  ex parts;
  try {
    parts = GiNaC::normal(e).numer_denom();
  } catch (const std::exception&) {
    return print(e);
  }
  ex numerator = parts.op(0);
  ex denominator = parts.op(1);
  if (denominator.is_equal(1)) {
    return print(numerator);
  }
  // The sign in the numerator: GiNaC leaves it in either part, as its order of terms gives
  // (-(a)/(b - c) in one build, (a)/(c - b) in another).
  if (!sym::up_to_sign(denominator).is_equal(denominator)) {
    numerator = -numerator;
    denominator = -denominator;
  }
  return grouped(numerator, false) + "/" + grouped(denominator, true);
}

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

void Scalars::append(const Scalars& other) {
  differences.insert(differences.end(), other.differences.begin(), other.differences.end());
  scales.insert(scales.end(), other.scales.begin(), other.scales.end());
  denominators.insert(denominators.end(), other.denominators.begin(), other.denominators.end());
  written.insert(written.end(), other.written.begin(), other.written.end());
}

Scalars scalars_of(const Equation& e, const GiNaC::exmap& substitutions) {
  Scalars s;
  for_each_scalar(e, [&](const ex& l, const ex& r) {
    const ex left = exact_reading(l.subs(substitutions));
    const ex right = exact_reading(r.subs(substitutions));
    s.differences.push_back(left - right);
    s.scales.push_back(term_scale(left) + term_scale(right));
  });
  for (const Meaning* m : {&e.lhs, &e.rhs}) {
    for (std::size_t k = 0; k < m->denominators.size(); ++k) {
      s.denominators.push_back(exact_reading(m->denominators[k].subs(substitutions)));
      s.written.push_back(k < m->written.size() ? m->written[k] : std::string());
    }
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
    if (e.group == static_cast<std::size_t>(-1) && premises == nullptr) {
      premises_agree(equations, index, source);
    }
    r.verdict = Verdict::premise;
    return r;
  }
  try {
    decide(equations, e, index, r);
  } catch (const std::exception& failure) {
    // GiNaC or CLN gave up on an expression (an internal error of theirs): no verdict.
    EquationResult fresh;
    fresh.line = r.line;
    fresh.column = r.column;
    fresh.tag = r.tag;
    fresh.latex = r.latex;
    fresh.from = r.from;
    r = std::move(fresh);
    r.verdict = Verdict::undecided;
    r.how = std::string("the computer algebra stopped on this step: ") + failure.what();
  }
  return r;
}

void Checker::decide(const std::vector<Equation>& equations, const Equation& e, std::size_t index,
                     EquationResult& r) {
  Budget budget;
  budget.deadline = after(options_.step_seconds);
  const Scalars step = scalars_of(e, e.substitutions);
  Scalars before;
  for (const std::size_t p : e.premises) {
    before.append(scalars_of(equations[p], e.substitutions));
  }
  // Equal before anything is expanded: the step is the equation before times a number.
  std::optional<ex> multiple;
  if (before.differences.size() == 1 && step.differences.size() == 1 &&
      before.denominators.empty() && step.denominators.empty()) {
    multiple = proportional(step.differences[0], before.differences[0], options_.seed);
  }
  Forward forward;
  if (multiple) {
    forward.implication.outcome = Implication::Outcome::holds;
    forward.implication.how = "the step is the equation before times " + latex_of(*multiple) +
                              ", the two equal at 8 random rational points (polynomials: an "
                              "identity that fails would pass all 8 with a probability below "
                              "10^-24)";
  } else {
    forward = exact(before, step, e.facts, budget);
  }
  NumericOpinion opinion = numeric(before, step, forward, e.facts, index, budget);
  if (forward.implication.outcome == Implication::Outcome::unknown && !opinion.counterexample) {
    domain_reading(before, step, e.facts, index, budget, forward, opinion);
  }
  if (forward.implication.outcome == Implication::Outcome::unknown ||
      forward.implication.outcome == Implication::Outcome::fails) {
    root_reading(before, step, e.facts, index, budget, forward, opinion);
  }
  r.numeric_points = opinion.points;
  r.numeric_worst = opinion.worst;
  if (multiple && !opinion.counterexample) {
    // A number times the equation before: the converse holds too.
    r.verdict = Verdict::follows;
    r.decided_by = "exact";
    r.converse = true;
    r.how = "exact: " + forward.implication.how + "; numeric: " + opinion.how;
  } else {
    conclude(before, step, forward, opinion, e.facts, budget, r);
  }
  if (e.equivalence && r.verdict == Verdict::follows_if) {
    equivalence_if(before, step, forward.implication, e.facts, r);
  } else if (e.equivalence && r.verdict == Verdict::follows_one_way) {
    // Written as an equivalence (\iff): the converse must hold too.
    const std::optional<Implication> back = converse(before, step, e.facts, budget);
    r.verdict = Verdict::does_not_follow;
    r.equivalence_note =
        "written as an equivalence (\\iff), but the equation before does not follow from this one";
    r.how = r.equivalence_note + ": " + r.how;
    if (back && back->point) {
      residual(back->residual, r);
      exact_point(*back->point, r);
    } else {
      r.verdict = Verdict::undecided;
    }
  }
  if (past(budget.deadline) && r.verdict == Verdict::undecided) {
    r.how = "the step's time budget of " + num::brief(options_.step_seconds, 3) +
            " s ran out (--step-seconds): " + r.how;
  }
}

// Premises that no real values satisfy, under the facts in force (x^2 = -1; x = 1 and x = 2
// together), would make every step after them follow: refused, as facts that disagree are. The
// premises of a derivation file up to this one, without functions, integrals or sums (whose
// values the search treats as free), at most 12 of them, within 0.3 s.
void Checker::premises_agree(const std::vector<Equation>& equations, std::size_t index,
                             const Source& source) {
  Scalars all;
  std::size_t count = 0;
  for (std::size_t k = 0; k <= index; ++k) {
    if (equations[k].premise && equations[k].group == static_cast<std::size_t>(-1)) {
      all.append(scalars_of(equations[k], equations[k].substitutions));
      ++count;
    }
  }
  const auto atoms = [](const ex& x) { return has_atoms(x); };
  if (count > 12 || std::any_of(all.differences.begin(), all.differences.end(), atoms) ||
      std::any_of(all.denominators.begin(), all.denominators.end(), atoms)) {
    return;
  }
  Budget quick;
  quick.attempts = 0;
  quick.deadline = after(0.3);
  Implication none;
  try {
    none = implies({all.differences, all.denominators, 1, {}}, equations[index].facts, quick);
  } catch (const std::exception&) {
    return;  // the computer algebra gave up: nothing shown
  }
  if (none.outcome == Implication::Outcome::holds) {
    throw source.error(equations[index].offset,
                       "expected premises that some real values satisfy: no values satisfy this "
                       "equation together with the premises and facts before it, and every step "
                       "would follow from them");
  }
}

// A step written as an equivalence (\iff) that follows only under a condition is no
// equivalence: where the condition fails, a point of the equations before where the step does
// not hold shows it. Without such a point the verdict is left open.
void Checker::equivalence_if(const Scalars& before, const Scalars& step, const Implication& forward,
                             const Facts& facts, EquationResult& r) const {
  const std::string only_if =
      "written as an equivalence (\\iff), but the step follows from the "
      "equation before only where $" +
      r.condition + "$";
  const auto shown = [&](const GiNaC::exmap& point) {
    return std::any_of(step.differences.begin(), step.differences.end(), [&](const ex& d) {
      return fails_at({before.differences, before.denominators, d, step.denominators}, facts,
                      point);
    });
  };
  if (forward.point && shown(*forward.point)) {
    r.verdict = Verdict::does_not_follow;
    r.how = only_if +
            ": the point below satisfies the equation before and the facts exactly, "
            "and not the step (exact: " +
            forward.how + ")";
    r.equivalence_note = only_if + ", not where it is zero";
    for (const ex& d : step.differences) {
      if (!GiNaC::normal(d.subs(*forward.point)).is_zero()) {
        residual(d, r);  // the step as written: the equation before does not reduce it
        break;
      }
    }
    exact_point(*forward.point, r);
  } else {
    r.verdict = Verdict::undecided;
    r.how = only_if +
            ", and no point was found where the condition fails and the step with it: " + r.how;
  }
  r.condition.clear();
  r.condition_text.clear();
}

// Sums over an index in one form: from 1 to the letter of the upper limit (\sum_{i=1}^{N-1} is
// \sum_{i=1}^{N} less its last term), over the index of the first sum with those limits
// (\sum_j m_j is \sum_i m_i, the facts on m_j carried to m_i).
void Checker::sums_in_one_form(Scalars& before, Scalars& step, Facts& facts) {
  std::vector<std::vector<ex>*> lists{&before.differences, &before.denominators, &step.differences,
                                      &step.denominators};
  std::vector<std::pair<std::string, ex>> sums;
  for (const std::vector<ex>* list : lists) {
    for (const ex& e : *list) {
      for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (sym::is_function(*i, "indexed_sum")) {
          std::ostringstream text;
          text << *i;
          sums.emplace_back(text.str(), *i);
        }
      }
    }
  }
  if (sums.empty()) {
    return;
  }
  std::sort(sums.begin(), sums.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  GiNaC::exmap replaced;
  std::vector<std::pair<ex, ex>> renamed;
  std::map<std::string, ex> first_index;  // limits → the index of the first sum with them
  for (const auto& [text, sum] : sums) {
    if (replaced.count(sum) != 0) {
      continue;
    }
    const ex body = sum.op(0);
    const ex index = sum.op(1);
    ex lower = sum.op(2);
    ex upper = GiNaC::expand(sum.op(3));
    ex outside = 0;
    // The limits: lower 1, upper a letter.
    long k = 0;
    if (GiNaC::is_a<GiNaC::add>(upper) && GiNaC::is_a<GiNaC::numeric>(upper.op(upper.nops() - 1)) &&
        GiNaC::ex_to<GiNaC::numeric>(upper.op(upper.nops() - 1)).is_integer()) {
      k = GiNaC::ex_to<GiNaC::numeric>(upper.op(upper.nops() - 1)).to_long();
      upper = upper - k;
    }
    const bool whole_lower =
        GiNaC::is_a<GiNaC::numeric>(lower) && GiNaC::ex_to<GiNaC::numeric>(lower).is_integer();
    if (whole_lower && std::abs(k) <= 3 && !GiNaC::is_a<GiNaC::numeric>(upper)) {
      const long l = GiNaC::ex_to<GiNaC::numeric>(lower).to_long();
      if (l >= -3 && l <= 4) {
        for (long j = 1; j < l; ++j) {
          outside -= symbols_.at_index(body, index, ex(j), &renamed);
        }
        for (long j = l; j < 1; ++j) {
          outside += symbols_.at_index(body, index, ex(j), &renamed);
        }
        for (long j = 1; j <= k; ++j) {
          outside += symbols_.at_index(body, index, upper + j, &renamed);
        }
        for (long j = 0; j < -k; ++j) {
          outside -= symbols_.at_index(body, index, upper - j, &renamed);
        }
        lower = 1;
      } else {
        upper = upper + k;
      }
    } else {
      upper = upper + k;
    }
    // The index: the first one seen with these limits.
    std::ostringstream limits;
    limits << lower << ".." << upper;
    ex canonical_body = body;
    ex canonical_index = index;
    const auto [at, fresh] = first_index.emplace(limits.str(), index);
    if (!fresh && !at->second.is_equal(index) && !body.has(at->second)) {
      canonical_index = at->second;
      canonical_body = symbols_.at_index(body, index, canonical_index, &renamed);
    }
    replaced[sum] = indexed_sum(canonical_body, canonical_index, lower, upper) + outside;
  }
  for (std::vector<ex>* list : lists) {
    for (ex& e : *list) {
      e = e.subs(replaced, GiNaC::subs_options::no_pattern);
    }
  }
  facts = facts.carried(renamed);
}

// e under an instance, and the symbols that name a sum's limit renamed too (m_N at N = 2 is
// m_2).
ex Checker::instantiated(const ex& e, const Instance& instance,
                         std::vector<std::pair<ex, ex>>& renamed) {
  ex x = instantiate(e, instance, at_index(renamed));
  for (const auto& [limit, value] : instance.limits) {
    x = symbols_.at_index(x, limit, value, &renamed);
  }
  return x;
}

AtIndex Checker::at_index(std::vector<std::pair<ex, ex>>& renamed) {
  return [this, &renamed](const ex& body, const ex& index, long value) {
    return symbols_.at_index(body, index, value, &renamed);
  };
}

// The exact method on each component; functions, integrals and sums that cannot be done are
// unknowns of their own (atoms), which is sound for a step that holds whatever they are. A
// failure among them is only reported when a formula for them shows it (instance_failure).
Checker::Forward Checker::exact(const Scalars& given_before, const Scalars& given_step,
                                const Facts& given_facts, const Budget& budget) {
  Scalars before = integrals_by_facts(given_before, given_facts);
  Scalars step = integrals_by_facts(given_step, given_facts);
  Facts facts = given_facts;
  sums_in_one_form(before, step, facts);
  Atoms atoms;
  // A function an equation before writes out (F(t) = \frac{dp}{dt}) is replaced by what it is
  // equal to, inside integrals and derivatives too.
  const std::vector<Rule> rules = rules_of(before.differences, is_variable());
  Scalars hidden_before = by_rules(before, rules);
  Scalars hidden_step = by_rules(step, rules);
  for (Scalars* s : {&hidden_before, &hidden_step}) {
    for (std::vector<ex>* list : {&s->differences, &s->denominators}) {
      for (ex& d : *list) {
        d = atoms.hide(d);
      }
    }
  }
  const auto run = [&](const std::vector<ex>& extra) {
    Implication total;
    total.outcome = Implication::Outcome::holds;
    std::vector<ex> premises = hidden_before.differences;
    premises.insert(premises.end(), extra.begin(), extra.end());
    for (const ex& target : hidden_step.differences) {
      merge(total, implies({premises, hidden_before.denominators, target, hidden_step.denominators},
                           facts, budget));
    }
    return total;
  };
  Forward forward{run({}), ""};
  using O = Implication::Outcome;
  if (forward.implication.outcome != O::holds && !facts.equalities().empty()) {
    // The facts' equalities (a unit vector) as equations before, where the step needs them;
    // and everything reduced by them (n_x^2 is 1 - n_y^2 where n_x^2 + n_y^2 = 1).
    std::vector<ex> equalities;
    for (const ex& q : facts.equalities()) {
      equalities.push_back(atoms.hide(q));
    }
    const Scalars plain_before = hidden_before;
    const Scalars plain_step = hidden_step;
    for (Scalars* s : {&hidden_before, &hidden_step}) {
      for (std::vector<ex>* list : {&s->differences, &s->denominators}) {
        for (ex& d : *list) {
          d = reduced(d, equalities);
        }
      }
    }
    Forward with{run(equalities), ""};
    hidden_before = plain_before;
    hidden_step = plain_step;
    if (with.implication.outcome == O::holds || with.implication.outcome == O::holds_if ||
        forward.implication.outcome == O::unknown) {
      forward = with;
    }
  }
  if (forward.implication.outcome == O::holds_if) {
    drop_given_conditions(forward.implication, hidden_before, hidden_step, facts, budget);
  }
  if (atoms.any()) {
    Implication& i = forward.implication;
    for (ex& c : i.conditions) {
      c = atoms.show(c);
    }
    i.residual = atoms.show(i.residual);
    if (i.outcome == O::fails || i.outcome == O::unknown) {
      // Values of the atoms alone may be no values of any function: a formula must show it.
      Forward failure = instance_failure(before, step, facts, budget);
      if (failure.implication.outcome == O::fails) {
        return failure;
      }
      i.outcome = O::unknown;
      i.point.reset();
      i.how += std::string(i.how.empty() ? "" : "; ") +
               "no formula tried for the functions, integrals or sums shows the step failing";
    }
  }
  return forward;
}

namespace {

// Whether @p e is a product of symbols and their powers, times a positive number (2 g h, k/m,
// x^3): then the signs of its symbols give its own. Of a - b, the signs of a and b say nothing.
bool signed_by_symbols(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    return true;
  }
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    return GiNaC::ex_to<GiNaC::numeric>(e).is_positive();
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    return GiNaC::is_a<GiNaC::symbol>(e.op(0)) && GiNaC::is_a<GiNaC::numeric>(e.op(1));
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (!signed_by_symbols(e.op(i))) {
        return false;
      }
    }
    return true;
  }
  return false;
}

// The symbols in the arguments of the logarithms of @p e (each to be positive) and in the bases
// of its even roots (not negative), each once, in the order found; only of arguments that are
// products of symbols (signed_by_symbols).
void domain_signs(const ex& e, std::vector<std::pair<ex, Sign>>& out) {
  const bool logarithm = sym::is_function(e, "log");
  const bool even_root = sym::is_even_root(e);
  if ((logarithm || even_root) && signed_by_symbols(e.op(0))) {
    const Sign sign = logarithm ? Sign::positive : Sign::nonnegative;
    for (const ex& s : symbols_of(e.op(0))) {
      const auto known =
          std::find_if(out.begin(), out.end(), [&](const auto& o) { return o.first.is_equal(s); });
      if (known == out.end()) {
        out.emplace_back(s, sign);
      } else if (sign == Sign::positive) {
        known->second = sign;
      }
    }
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    domain_signs(e.op(i), out);
  }
}

// At most this many symbols get a sign for the rules of roots and logarithms: a condition on more
// says little a reader can use.
constexpr std::size_t most_signed_symbols = 4;

}  // namespace

// A step the exact method could not decide, whose logarithms and even roots hold symbols the
// facts do not give the sign they need (\ln(a b) then \ln a + \ln b; \sqrt{a b} then
// \sqrt{a} \sqrt{b}): decided again as if the file assumed them positive (a logarithm's) or not
// negative (a root's). Where it then holds, the verdict is follows-if with those signs as the
// condition, and the numeric opinion is taken at points that keep them. (Where one of them has
// the other sign, a root or logarithm of the step or of the equations before often has no real
// value; whether the condition is needed is not decided.) Returns whether it did.
bool Checker::domain_reading(const Scalars& before, const Scalars& step, const Facts& facts,
                             std::size_t index, const Budget& budget, Forward& forward,
                             NumericOpinion& opinion) {
  std::vector<std::pair<ex, Sign>> found;
  for (const Scalars* s : {&before, &step}) {
    for (const std::vector<ex>* list : {&s->differences, &s->denominators}) {
      for (const ex& d : *list) {
        domain_signs(d, found);
      }
    }
  }
  // By name: GiNaC's order of a sum's terms, and so the order found, may differ between builds.
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return plain_of(a.first) < plain_of(b.first); });
  Facts with = facts;
  std::vector<std::pair<ex, Sign>> assumed;
  for (const auto& [symbol, sign] : found) {
    const Sign known = facts.of_symbol(symbol);
    if (known == Sign::positive || (known == Sign::nonnegative && sign == Sign::nonnegative)) {
      continue;
    }
    if (!with.add(symbol, sign)) {
      return false;  // the facts give it the other sign: no such reading
    }
    assumed.emplace_back(symbol, sign);
  }
  if (assumed.empty() || assumed.size() > most_signed_symbols) {
    return false;
  }
  Forward read = exact(before, step, with, budget);
  using O = Implication::Outcome;
  if (read.implication.outcome != O::holds && read.implication.outcome != O::holds_if) {
    return false;
  }
  Implication& i = read.implication;
  i.outcome = O::holds_if;
  i.signs = assumed;
  i.conditions_needed = false;
  i.point.reset();
  std::string signs;
  for (const auto& [symbol, sign] : assumed) {
    signs += (signs.empty() ? "" : ", ") + relation_latex(latex_of(symbol), sign);
  }
  i.how = (i.how.empty() ? std::string("it holds once the equations before are used") : i.how) +
          " where " + signs +
          " (the rules of roots and logarithms hold where a root's argument is not negative and a "
          "logarithm's is positive; the facts do not give these signs: assume them where they "
          "hold)";
  forward = read;
  opinion = numeric(before, step, forward, with, index, budget);
  return true;
}

// A step k √R + q = 0 (one square root; k a number, or of a sign the facts give), where the exact
// method found it failing or could not decide: it holds wherever k² R = q² does and -q/k ≥ 0, the
// root being the one that is not negative. Where the equations before give k² R = q², the step
// follows where the facts give -q/k ≥ 0 (s² = a² + b² then s = √(a² + b²), for s > 0), else it
// follows-if -q/k ≥ 0 when that is a symbol (v² = 2 g h then v = √(2 g h) follows where v ≥ 0, as
// x² = 9 then x = 3 does where x + 3 ≠ 0: it dropped the negative root). A point where it failed is
// kept unless it breaks that sign. Returns whether it decided the step.
bool Checker::root_reading(const Scalars& before, const Scalars& step, const Facts& facts,
                           std::size_t index, const Budget& budget, Forward& forward,
                           NumericOpinion& opinion) {
  if (step.differences.size() != 1 || has_atoms(step.differences[0])) {
    return false;
  }
  const ex& target = step.differences[0];
  // The one square root of a symbol's expression (√2 of √(2 g h) = √2 √(g h) is a number).
  const std::optional<ex> root = sym::only_part(target, [](const ex& x) {
    return GiNaC::is_a<GiNaC::power>(x) && x.op(1).is_equal(GiNaC::numeric(1, 2)) &&
           !symbols_of(x.op(0)).empty();
  });
  const GiNaC::symbol stand_in("root");  // GiNaC expands √(g h) as it pleases: a symbol for it
  const auto kq = root ? sym::linear_in(target.subs(*root == stand_in), stand_in) : std::nullopt;
  // q real wherever the root is: no other root of a symbol's expression in it ((g h)^(3/2) is
  // imaginary where g h < 0).
  const auto other_root = [](const ex& e) {
    return std::any_of(e.preorder_begin(), e.preorder_end(), [](const ex& x) {
      return GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
             !x.op(1).info(GiNaC::info_flags::integer) && !symbols_of(x.op(0)).empty();
    });
  };
  if (!kq || kq->second.has(stand_in) || other_root(kq->second) || other_root(kq->first)) {
    return false;
  }
  const auto& [k, q] = *kq;
  // -q/k must not be negative: -q where k > 0, q where k < 0 (k a number, or of a sign the facts
  // give: (m + M)/m of m, M > 0).
  const ex k_value = GiNaC::evalf(k);
  Sign k_sign = facts.sign(k);
  if (GiNaC::is_a<GiNaC::numeric>(k_value) && GiNaC::ex_to<GiNaC::numeric>(k_value).is_real() &&
      !k_value.is_zero()) {
    k_sign = GiNaC::ex_to<GiNaC::numeric>(k_value).is_positive() ? Sign::positive : Sign::negative;
  }
  if (k_sign != Sign::positive && k_sign != Sign::negative) {
    return false;
  }
  const ex sign_of = k_sign == Sign::positive ? ex(-q) : q;
  const Sign known = facts.sign(sign_of);
  const bool given = known == Sign::positive || known == Sign::nonnegative || known == Sign::zero;
  if (!given && !GiNaC::is_a<GiNaC::symbol>(sign_of)) {
    return false;
  }
  const auto& point = forward.implication.point;
  if (point && forward.implication.outcome == Implication::Outcome::fails) {
    const ex there = GiNaC::evalf(sign_of.subs(*point));
    if (given || !GiNaC::is_a<GiNaC::numeric>(there) ||
        !GiNaC::ex_to<GiNaC::numeric>(there).is_negative()) {
      return false;  // the point keeps the sign: it stands
    }
  }
  Facts with = facts;
  if (!given && !with.add(sign_of, Sign::nonnegative)) {
    return false;
  }
  Scalars squared = step;
  squared.differences[0] = GiNaC::expand(GiNaC::numer(GiNaC::normal(k * k * root->op(0) - q * q)));
  squared.scales[0] = term_scale(squared.differences[0]);
  Forward read = exact(before, squared, with, budget);
  using O = Implication::Outcome;
  if (read.implication.outcome != O::holds && read.implication.outcome != O::holds_if) {
    return false;
  }
  Implication& i = read.implication;
  const std::string sign_text = relation_latex(latex_of(sign_of), Sign::nonnegative);
  i.how = "the step squared (" + latex_of(squared.differences[0]) + " = 0): " +
          (i.how.empty() ? std::string("it holds once the equations before are used") : i.how) +
          "; the root is not negative, so the step holds where " + sign_text +
          (given ? ", which the facts give" : "");
  if (!given) {
    // Needed where the step failed at a point that breaks the sign (v = -1 of v² = 2 g h).
    const bool failed = forward.implication.outcome == O::fails && point;
    i.outcome = O::holds_if;
    i.signs.emplace_back(sign_of, Sign::nonnegative);
    i.conditions_needed = failed && i.conditions.empty();
    i.point = failed ? point : std::nullopt;
  }
  forward = read;
  opinion = numeric(before, step, forward, with, index, budget);
  return true;
}

namespace {

// An equation that names a function at its variable (F(t) = …) holds for every value of that
// variable: its numerator split into the coefficients of each power of each variable, and of each
// power of its exponential (e^t, of a formula exp(u): e^t = F_0 for every t holds for no F_0). A
// part that would expand into too many terms, or is no polynomial in the variable, stays whole;
// nothing, where an exponential of the variable stays in such a part (at one t, e^t = F_0 holds
// with F_0 = e^t, and that would pass for a counterexample).
std::optional<std::vector<ex>> by_powers(const ex& written, const std::vector<ex>& variables) {
  std::vector<ex> parts{written};
  std::vector<std::pair<ex, ex>> exponentials;  // e^v and the symbol standing for it
  for (const ex& v : variables) {
    if (!written.has(GiNaC::exp(v))) {
      continue;
    }
    const GiNaC::symbol e_v("exp_" + plain_of(v));
    exponentials.emplace_back(GiNaC::exp(v), e_v);
    for (ex& part : parts) {
      part = part.subs(GiNaC::exp(v) == e_v);
    }
  }
  std::vector<ex> all = variables;
  for (const auto& [exponential, symbol] : exponentials) {
    all.push_back(symbol);
  }
  for (const ex& v : all) {
    std::vector<ex> split;
    for (const ex& part : parts) {
      if (expanded_terms(part) > most_expanded_terms) {
        split.push_back(part);
        continue;
      }
      const ex expanded = GiNaC::expand(GiNaC::normal(part).numer());
      if (!expanded.has(v) || !expanded.is_polynomial(v)) {
        split.push_back(part);
        continue;
      }
      for (int d = 0; d <= expanded.degree(v); ++d) {
        split.push_back(expanded.coeff(v, d));
      }
    }
    parts = split;
  }
  for (ex& part : parts) {
    for (const auto& [exponential, symbol] : exponentials) {
      if (part.has(symbol)) {
        return std::nullopt;
      }
    }
  }
  return parts;
}

}  // namespace

// Small formulas for the file's functions and values for the numbers of terms of its sums, in
// turn: a failure under one of them is a real counterexample.
Checker::Forward Checker::instance_failure(const Scalars& given_before, const Scalars& given_step,
                                           const Facts& facts, const Budget& budget) {
  const std::vector<Rule> rules = rules_of(given_before.differences, is_variable());
  const Scalars before = by_rules(given_before, rules);
  const Scalars step = by_rules(given_step, rules);
  std::vector<ex> all = before.differences;
  all.insert(all.end(), step.differences.begin(), step.differences.end());
  for (const Instance& instance : instances(all, 8)) {
    if (past(budget.deadline)) {
      break;
    }
    std::vector<std::pair<ex, ex>> renamed;
    const AtIndex at = at_index(renamed);
    const auto apply = [&](std::vector<ex> list) {
      for (ex& x : list) {
        x = instantiated(x, instance, renamed);
      }
      return list;
    };
    // Under the formulas, each power of a function's variable on its own (by_powers). The
    // equations before as written too, where the formulas leave no function unknown, not only
    // with their rules put in: a rule dp/dt = F_0 put in leaves 0 = 0, and p(u) = 1 (where
    // dp/dt = 0) then showed p(T) - p(0) = F_0 T failing at F_0 = 1, where the equation before
    // does not hold. (A rule F(t) = m dv/dt that defines F stays put in: F is any function.)
    // (An instance under which an equation before cannot be held to every value of the variable
    // is passed over: by_powers.)
    std::vector<ex> premises;
    bool usable = true;
    for (const Scalars* s : {&given_before, &before}) {
      for (const ex& p : s->differences) {
        const ex written = instantiated(p, instance, renamed);
        if (s == &given_before && has_atoms(written)) {
          continue;
        }
        const std::optional<std::vector<ex>> parts =
            by_powers(written, function_variables(p, is_variable()));
        usable = usable && parts.has_value();
        if (parts) {
          premises.insert(premises.end(), parts->begin(), parts->end());
        }
      }
    }
    if (!usable) {
      continue;
    }
    const std::vector<ex> premise_denominators = apply(before.denominators);
    const std::vector<ex> targets = apply(step.differences);
    const std::vector<ex> target_denominators = apply(step.denominators);
    std::vector<ex> everything = premises;
    everything.insert(everything.end(), targets.begin(), targets.end());
    if (std::any_of(everything.begin(), everything.end(),
                    [](const ex& x) { return has_atoms(x); })) {
      continue;
    }
    const Facts carried = facts.carried(renamed);
    for (const ex& target : targets) {
      Implication one =
          implies({premises, premise_denominators, target, target_denominators}, carried, budget);
      if (one.outcome == Implication::Outcome::fails) {
        one.how = "with " + instance.text + ": " + one.how;
        return {one, instance.text};
      }
    }
  }
  Implication none;
  none.outcome = Implication::Outcome::unknown;
  return {none, ""};
}

// A condition c ≠ 0 that the facts give (m_1 + m_2 > 0), or that the equations before give
// (no values satisfy them where c = 0), is no condition.
void Checker::drop_given_conditions(Implication& forward, const Scalars& before,
                                    const Scalars& step, const Facts& facts,
                                    const Budget& budget) const {
  std::vector<ex> kept;
  Budget quick = budget;
  quick.attempts = 24;
  quick.candidates = 1;
  // The denominators as written (and their factors): I + m (r_x n_y - r_y n_x)^2 shows its
  // sign as written, not once expanded.
  std::vector<ex> written;
  for (const Scalars* s : {&before, &step}) {
    for (const ex& d : s->denominators) {
      written.push_back(d);
      if (GiNaC::is_a<GiNaC::mul>(d)) {
        for (std::size_t i = 0; i < d.nops(); ++i) {
          written.push_back(d.op(i));
        }
      }
    }
  }
  const auto given_as_written = [&](const ex& c) {
    for (const ex& d : written) {
      if (expanded_terms(d) > 200 || expanded_terms(c) > 200 || !facts.nonzero(d)) {
        continue;
      }
      // c is d times something the facts keep from zero (1/m + …/I and I m (…)); with a unit
      // vector, c may be d reduced by its equality (n_x^2 written 1 - n_y^2), so the quotient
      // is reduced too.
      if (facts.nonzero(factored(GiNaC::normal(c / d))) ||
          (!facts.equalities().empty() &&
           facts.nonzero(factored(GiNaC::normal(reduced(c / d, facts.equalities())))))) {
        return true;
      }
    }
    return false;
  };
  // c reduced by the facts' equalities is a number: n_x^2 + n_y^2 where n_x^2 + n_y^2 = 1.
  const auto given_by_equality = [&](const ex& c) {
    const ex rest = reduced(c, facts.equalities());
    return GiNaC::is_a<GiNaC::numeric>(rest) && !rest.is_zero();
  };
  for (const ex& c : forward.conditions) {
    if (facts.nonzero(c) || given_as_written(c) || given_by_equality(c) ||
        facts.nonzero(in_sines(c)) ||
        (expanded_terms(c) <= 200 && facts.nonzero(factored(GiNaC::normal(c))))) {
      continue;
    }
    std::vector<ex> premises = before.differences;
    // |X| = 0 where X = 0: the exact method reads the latter.
    const bool absolute = sym::is_function(c, "abs");
    premises.push_back(absolute ? c.op(0) : c);
    premises.insert(premises.end(), facts.equalities().begin(), facts.equalities().end());
    const Implication there = implies({premises, before.denominators, 1, {}}, facts, quick);
    if (there.outcome == Implication::Outcome::holds) {
      continue;  // where c = 0, the equations before and the facts have no solution
    }
    kept.push_back(c);
  }
  forward.conditions = kept;
  if (kept.empty()) {
    forward.outcome = Implication::Outcome::holds;
    return;
  }
  // Conditions that the equations before and the facts never allow together: x^2 = y^2 then
  // x = y under x ≥ 0 ≥ y holds where x + y ≠ 0, but x + y = 0 wherever x^2 = y^2 there. The step
  // then holds nowhere but where it is trivially true (x = y = 0), and the point found where a
  // condition is 0 (x = 1, y = -1) is a counterexample. Where no such point was found (x = 0
  // then x/x = 1: the step is not defined where its condition is 0), any point of the equations
  // before and the facts is one: the step holds at none of them.
  if (step.differences.size() != 1) {
    return;
  }
  std::vector<ex> premises = before.differences;
  premises.insert(premises.end(), facts.equalities().begin(), facts.equalities().end());
  ex product = 1;
  for (const ex& c : kept) {
    product *= c;
  }
  const Implication never = implies({premises, before.denominators, product, {}}, facts, quick);
  if (never.outcome != Implication::Outcome::holds) {
    return;
  }
  if (!forward.point) {
    // A point of the equations before and the facts: where "1 = 0" fails.
    const Implication any = implies({premises, before.denominators, 1, {}}, facts, quick);
    if (any.outcome != Implication::Outcome::fails || !any.point) {
      return;
    }
    forward.point = any.point;
  }
  forward.outcome = Implication::Outcome::fails;
  forward.conditions.clear();
  forward.residual = step.differences[0];
  forward.how += std::string(forward.how.empty() ? "" : "; ") + "it holds only where " +
                 plain_of(sym::up_to_sign(product)) +
                 " != 0, which the equations before and the facts never allow";
}

// The numeric method, as a second opinion, at random points on the equations before. Where the
// exact method found conditions, the points where one of them is zero are left out like those
// where a denominator is. Functions and sums get the first instance's formulas.
NumericOpinion Checker::numeric(const Scalars& before, const Scalars& step, const Forward& forward,
                                const Facts& facts, std::size_t index, const Budget& budget) {
  const std::vector<Rule> rules = rules_of(before.differences, is_variable());
  Scalars b = by_rules(integrals_by_facts(before, facts), rules);
  Scalars s = by_rules(integrals_by_facts(step, facts), rules);
  Facts f = facts;
  std::vector<ex> all = before.differences;
  all.insert(all.end(), step.differences.begin(), step.differences.end());
  if (std::any_of(all.begin(), all.end(), [](const ex& x) { return has_atoms(x); })) {
    const std::vector<Instance> list = instances(all, 1);
    std::vector<std::pair<ex, ex>> renamed;
    const AtIndex at = at_index(renamed);
    std::vector<ex> premises;
    std::vector<ex> scales;
    for (std::size_t k = 0; k < b.differences.size(); ++k) {
      // Under the formula, each power of a function's variable on its own (by_powers).
      const ex written =
          list.empty() ? b.differences[k] : instantiated(b.differences[k], list[0], renamed);
      const std::vector<ex> parts =
          by_powers(written, function_variables(b.differences[k], is_variable()))
              .value_or(std::vector<ex>{written});
      for (const ex& p : parts) {
        premises.push_back(p);
        scales.push_back(term_scale(p));
      }
    }
    b.differences = premises;
    b.scales = scales;
    for (Scalars* x : {&b, &s}) {
      for (std::vector<ex>* v : {&x->denominators}) {
        for (ex& e : *v) {
          e = list.empty() ? e : instantiated(e, list[0], renamed);
        }
      }
    }
    for (std::vector<ex>* v : {&s.differences, &s.scales}) {
      for (ex& e : *v) {
        e = list.empty() ? e : instantiated(e, list[0], renamed);
      }
    }
    f = facts.carried(renamed);
  }
  NumericOpinion numeric;
  std::vector<ex> premises = b.differences;
  std::vector<ex> scales = b.scales;
  for (const ex& q : f.equalities()) {
    premises.push_back(q);
    scales.push_back(term_scale(q));
  }
  for (std::size_t k = 0; k < s.differences.size(); ++k) {
    std::vector<ex> denominators = b.denominators;
    denominators.insert(denominators.end(), s.denominators.begin(), s.denominators.end());
    if (forward.implication.outcome == Implication::Outcome::holds_if) {
      denominators.insert(denominators.end(), forward.implication.conditions.begin(),
                          forward.implication.conditions.end());
    }
    NumericProblem problem{premises,         scales,      denominators,
                           s.differences[k], s.scales[k], b.denominators.size()};
    const NumericOpinion one = sample(problem, f, options_.seed * 7919 + index * 31 + k,
                                      options_.samples, budget.deadline);
    numeric.points += one.points;
    numeric.worst = std::max(numeric.worst, one.worst);
    if (!numeric.counterexample && one.counterexample) {
      numeric.counterexample = one.counterexample;
      numeric.counterexample_residual = one.counterexample_residual;
    }
    numeric.not_real += one.not_real;
    if (!numeric.not_real_point && one.not_real_point) {
      numeric.not_real_point = one.not_real_point;
    }
    numeric.how = one.how;
  }
  return numeric;
}

std::optional<Implication> Checker::converse(const Scalars& given_before, const Scalars& given_step,
                                             const Facts& facts, const Budget& budget) {
  using O = Implication::Outcome;
  // Only whether the converse fails matters here, not the nicest point that shows it.
  Budget quick = budget;
  quick.attempts = 48;
  quick.candidates = 1;
  // The step is the equation before now: the functions it writes out are replaced.
  Scalars one_before = integrals_by_facts(given_before, facts);
  Scalars one_step = integrals_by_facts(given_step, facts);
  Facts one_facts = facts;
  sums_in_one_form(one_before, one_step, one_facts);
  const std::vector<Rule> rules = rules_of(one_step.differences, is_variable());
  const Scalars before = by_rules(one_before, rules);
  const Scalars step = by_rules(one_step, rules);
  Atoms atoms;
  std::vector<ex> equalities;
  for (const ex& q : facts.equalities()) {
    equalities.push_back(atoms.hide(q));
  }
  const auto hidden = [&](const std::vector<ex>& list) {
    std::vector<ex> out;
    for (const ex& d : list) {
      out.push_back(reduced(atoms.hide(d), equalities));
    }
    return out;
  };
  std::vector<ex> premises = hidden(step.differences);
  premises.insert(premises.end(), equalities.begin(), equalities.end());
  const std::vector<ex> premise_denominators = hidden(step.denominators);
  const std::vector<ex> target_denominators = hidden(before.denominators);
  bool all = true;
  for (const ex& target : hidden(before.differences)) {
    Implication back =
        implies({premises, premise_denominators, target, target_denominators}, facts, quick);
    if (back.outcome == O::holds_if) {
      drop_given_conditions(back, Scalars{premises, {}, premise_denominators, {}},
                            Scalars{{}, {}, target_denominators, {}}, facts, quick);
    }
    if ((back.outcome == O::fails || back.outcome == O::unknown) && atoms.any()) {
      // Values of atoms alone are no counterexample: a formula must show it.
      Forward failure = instance_failure(given_step, given_before, facts, quick);
      back = failure.implication.outcome == O::fails ? failure.implication : Implication{};
    }
    if (back.outcome == O::fails || back.outcome == O::holds_if) {
      return back;
    }
    if (back.outcome == O::unknown) {
      all = false;
    }
  }
  if (!all) {
    return std::nullopt;
  }
  Implication holds;
  holds.outcome = O::holds;
  return holds;
}

void Checker::conclude(const Scalars& before, const Scalars& step, const Forward& forward,
                       const NumericOpinion& numeric, const Facts& facts, const Budget& budget,
                       EquationResult& r) {
  using O = Implication::Outcome;
  const Implication& exact = forward.implication;
  const std::string numeric_note = numeric.points == 0
                                       ? "numeric: " + numeric.how
                                       : "numeric: " + numeric.how + ", worst relative residual " +
                                             num::residual_text(numeric.worst);
  switch (exact.outcome) {
    case O::holds:
    case O::holds_if: {
      if (numeric.counterexample) {
        r.verdict = Verdict::undecided;
        r.how = "the exact method finds that it follows (" + exact.how +
                "), but the numeric method finds a point where it fails (relative residual " +
                num::brief(numeric.counterexample_residual, 2) +
                "): the two disagree, so no verdict is given";
        numeric_point(*numeric.counterexample, r);
        return;
      }
      if (numeric.points == 0 && numeric.not_real >= 8 && numeric.not_real_point) {
        // x = 1/sin θ then √x = 1/√(sin θ) on -π/2 < θ < 0: both sides are imaginary wherever
        // the equation before holds, and their real reading (roots ≥ 0) holds vacuously.
        std::string at;
        for (const auto& [symbol, value] : *numeric.not_real_point) {
          at += (at.empty() ? "" : ", ") + latex_of(symbol) + " = " + num::brief(value, 3);
        }
        r.verdict = Verdict::undecided;
        r.how = "the exact method finds that it follows (" + exact.how +
                "), but the step has no real value at any of the " +
                std::to_string(numeric.not_real) +
                " points found on the equations before and the facts (e.g. " + at +
                "): a step that is nowhere real is not shown to follow";
        return;
      }
      r.decided_by = "exact";
      if (exact.outcome == O::holds_if) {
        r.verdict = Verdict::follows_if;
        condition(exact, before, step, r);
        r.condition_needed = exact.conditions_needed;
        r.how = "exact: " + exact.how + "; " + numeric_note;
        if (!exact.conditions_needed) {
          r.how += "; whether the condition is needed was not decided";
        }
        return;
      }
      const std::optional<Implication> back = converse(before, step, facts, budget);
      r.converse = back ? std::optional<bool>(back->outcome == O::holds) : std::nullopt;
      r.verdict = r.converse.value_or(false) ? Verdict::follows : Verdict::follows_one_way;
      r.how = "exact: " + (exact.how.empty() ? std::string("it holds once the equations "
                                                           "before are used")
                                             : exact.how);
      if (!r.converse) {
        r.how += "; whether the equations before follow from it was not decided";
      } else if (!*r.converse) {
        r.how += "; the equations before do not follow from it";
      }
      r.how += "; " + numeric_note;
      return;
    }
    case O::fails: {
      r.verdict = Verdict::does_not_follow;
      r.decided_by = "exact";
      residual(exact.residual, r);
      exact_point(*exact.point, r);
      r.counterexample_functions = forward.instance;
      r.how = "exact: " +
              (exact.how.empty() ? std::string("what is left of the step does not vanish")
                                 : exact.how) +
              "; the counterexample satisfies the equations before and the facts exactly";
      return;
    }
    case O::unknown:
      break;
  }
  if (numeric.counterexample) {
    r.verdict = Verdict::does_not_follow;
    r.decided_by = "numeric";
    residual(exact.residual, r);
    numeric_point(*numeric.counterexample, r);
    r.how = "exact: undecided (" + exact.how +
            "); numeric: a point on the equations before where the step fails (relative "
            "residual " +
            num::brief(numeric.counterexample_residual, 2) + ")";
    return;
  }
  r.verdict = Verdict::undecided;
  r.how =
      "exact: " + exact.how + "; " + numeric_note + " (agreement at random points is not a proof)";
}

// The condition as the file wrote it where it is one of the denominators written (or a
// constant times one), else as computed.
void Checker::condition(const Implication& forward, const Scalars& before, const Scalars& step,
                        EquationResult& r) const {
  std::vector<std::pair<ex, std::string>> written;
  for (const Scalars* s : {&step, &before}) {
    for (std::size_t k = 0; k < s->denominators.size(); ++k) {
      if (k < s->written.size() && !s->written[k].empty()) {
        written.emplace_back(s->denominators[k], s->written[k]);
      }
    }
  }
  std::vector<std::string> latex;
  ex product = 1;
  for (const ex& c : forward.conditions) {
    product *= c;
    std::string text = latex_of(sym::up_to_sign(c));
    for (const auto& [d, w] : written) {
      if (expanded_terms(d) > 200 || expanded_terms(c) > 200) {
        continue;
      }
      const ex ratio = GiNaC::normal(c / d);
      if (GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero()) {
        text = trimmed(w);
        break;
      }
    }
    latex.push_back(text + " \\neq 0");
  }
  // By their text: the conditions come in GiNaC's order of a product's factors, which follows hash
  // values seeded by addresses and differed between runs of one program (the plain text below is
  // printed in an order of its own).
  std::sort(latex.begin(), latex.end());
  std::string plain;
  if (!forward.conditions.empty()) {
    product = sym::up_to_sign(product);  // its sign does not matter: one form in every run
    plain = plain_of(product) + " != 0";
  }
  for (const auto& [symbol, sign] : forward.signs) {
    latex.push_back(relation_latex(latex_of(symbol), sign));
    plain += std::string(plain.empty() ? "" : ", ") + relation_text(plain_of(symbol), sign);
  }
  std::string joined;
  for (const std::string& l : latex) {
    joined += (joined.empty() ? "" : ", \\quad ") + l;
  }
  r.condition = joined;
  r.condition_text = plain;
}

bool Checker::follows(const std::vector<const Equation*>& premises, const Equation& target,
                      const Facts& facts, double seconds, bool both) {
  Budget budget;
  budget.deadline = after(seconds);
  Scalars before;
  for (const Equation* p : premises) {
    before.append(scalars_of(*p, p->substitutions));
  }
  const Scalars step = scalars_of(target, target.substitutions);
  try {
    const Forward forward = exact(before, step, facts, budget);
    if (forward.implication.outcome != Implication::Outcome::holds) {
      return false;
    }
    if (!both) {
      return true;
    }
    const std::optional<Implication> back = converse(before, step, facts, budget);
    return back && back->outcome == Implication::Outcome::holds;
  } catch (const std::exception&) {
    return false;
  }
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
