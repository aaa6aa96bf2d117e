// SPDX-License-Identifier: GPL-3.0-or-later
// The model evaluator: the statements of a check at the points of a model it names. A point gives
// some of the file's symbols; the others are drawn at random (a model that only shapes a force)
// or solved from the equations before; then each statement of an equation or a step is measured
// by its residual, and each row of a claim is held against its hypotheses and conclusions.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <span>

#include "file/decide.hpp"
#include "file/paper.hpp"
#include "file/sample.hpp"
#include "file/time.hpp"
#include "numeric.hpp"

namespace impulse::derivations::paper {

const models::Model& model_named(const FileRun& run, const file::ModelUse& use) {
  const std::optional<Method> method = value_named<Method>(use.method);
  const models::Model* model = method ? models::find(*method, use.name) : nullptr;
  if (model == nullptr) {
    throw run.source.error(
        use.offset,
        "expected a model this checker knows after " +
            std::string(method ? row_of(*method).directive : std::string_view(use.method)) +
            ": found \"" + use.name + "\" (the models: docs/pages/derivations.md)");
  }
  return *model;
}

namespace {

using file::Relation;
using file::TimedExpression;

// What a point leaves to find, for one set of names the points give: the slots it fixes (slot
// and component per value), those drawn at random, those the equations before solve (exactly
// once, or numerically at each point), and those nothing determines.
struct Unknowns {
  std::vector<std::pair<std::size_t, int>> fixed;
  std::vector<std::size_t> drawn;
  std::vector<std::size_t> solved;  // numerically, at each point
  std::set<std::size_t> undetermined;
  std::optional<file::Solver> solver;
  GiNaC::exmap exact_solution;                        // linear equations before, solved once
  std::vector<std::pair<ex, TimedExpression>> shown;  // those solutions, for the report
  std::vector<ex> used_equations;                     // the equations that solve for a symbol
  bool fixes_t = false;  // the point gives t: an instant's reading is at the model's t

  [[nodiscard]] ex solved_form(const ex& e) const {
    return exact_solution.empty() ? e : e.subs(exact_solution);
  }
};

// A model's points and the symbols they are evaluated in: every symbol of the statements and the
// equations before, the pulse's time scale, dt for a model that shapes the force, t at an instant.
class Evaluation {
 public:
  Evaluation(FileRun& file_run, const file::ModelUse& use, const std::vector<ex>& expressions,
             const std::vector<ex>& pool, const file::Facts& facts, const file::Group& g,
             bool instant)
      : model(model_named(file_run, use)),
        run(file_run),
        use_(use),
        pool_(pool),
        facts_(facts),
        random_(check_seed(file_run.options.seed, g.id + "/" + use.name) ^ 0x5DEECE66DULL),
        instant_(instant) {
    // The seed of the model, not of the check: a check's samples still do not depend on which
    // other checks run.
    const models::Settings settings{
        check_seed(run.options.seed, std::string(name_of(model.method)) + ": " + use.name),
        run.options.samples};
    points_ = &run.points(model, settings);
    symbols = file::symbols_of(expressions);
    t = run.symbols.value_of(file::SymbolName{"t", "", 0, false}).x;
    dt = run.symbols.value_of(file::SymbolName{"dt", "", 0, false}).x;
    add(file::pulse_duration());
    // A model that shapes the force gives the contact's duration dt, the pulse's time scale,
    // also to a check whose equations do not write it (a path at the contact's end, S_v = ∫…).
    if (model.draws_the_rest) {
      add(dt);
    }
    // An instant's forces are shaped at t, written or not (F_v = dp_v / dt).
    if (instant) {
      add(t);
    }
    tau_ = *index_of(file::pulse_duration());
    for (const ex& s : symbols) {
      signs_.push_back(facts.of_symbol(s));
    }
    dt_ = index_of(dt);
    t_ = index_of(t);
  }

  const models::Model& model;
  FileRun& run;
  std::vector<ex> symbols;
  ex t;
  ex dt;

  [[nodiscard]] const std::vector<models::Point>& points() const { return points_->points; }
  /// The set of names point @p k gives (its number among the model's sets).
  [[nodiscard]] std::size_t names(std::size_t k) const { return points_->names[k]; }

  [[nodiscard]] std::optional<std::size_t> index_of(const ex& s) const {
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      if (symbols[i].is_equal(s)) {
        return i;
      }
    }
    return std::nullopt;
  }

  [[nodiscard]] bool determined(const Unknowns& u, const ex& e) const {
    return std::none_of(u.undetermined.begin(), u.undetermined.end(),
                        [&](std::size_t k) { return e.has(symbols[k]); });
  }

  // The names of the undetermined symbols @p e holds (all of them: nothing).
  [[nodiscard]] std::string undetermined_names(const Unknowns& u,
                                               const std::function<bool(const ex&)>& in) const {
    std::string names;
    for (const std::size_t k : u.undetermined) {
      if (in(symbols[k])) {
        names += (names.empty() ? "" : ", ") + symbol_text(run.symbols, symbols[k]);
      }
    }
    return names;
  }

  [[nodiscard]] file::ReadError error(const std::string& what) const {
    return run.source.error(use_.offset, what);
  }

  Unknowns unknowns(const models::Point& point);
  bool values_at(const models::Point& point, Unknowns& u, std::vector<double>& values);
  [[nodiscard]] GiNaC::exmap rates(const models::Point& point) const;
  [[nodiscard]] std::string point_text(const models::Point& point, const Unknowns& u,
                                       const std::vector<double>& values,
                                       const std::vector<ex>& used) const;

 private:
  void add(const ex& s) {
    if (!index_of(s)) {
      symbols.push_back(s);
    }
  }
  void match(Unknowns& u, const std::vector<std::size_t>& unknown);
  void solve_linear(Unknowns& u, const std::vector<ex>& equations, const std::vector<ex>& solved);

  const file::ModelUse& use_;
  const std::vector<ex>& pool_;
  const file::Facts& facts_;
  num::Random random_;
  bool instant_;
  // The slots of the pulse's time scale, of dt and of t (the symbols are all added above).
  std::size_t tau_ = 0;
  std::optional<std::size_t> dt_;
  std::optional<std::size_t> t_;
  std::vector<file::Sign> signs_;  // each symbol's, as the facts give it
  const ModelPoints* points_ = nullptr;
};

Unknowns Evaluation::unknowns(const models::Point& point) {
  Unknowns u;
  std::set<std::size_t> known;
  for (const models::Value& v : point.values) {
    const std::vector<ex> named = run.symbols_of_name(v.symbol);
    if ((named.size() == 2) != v.vector) {
      throw error("expected the file to read " + v.symbol + " as the model " + use_.name +
                  " gives it, " + (v.vector ? "a vector" : "a number"));
    }
    for (std::size_t c = 0; c < named.size(); ++c) {
      const auto slot = index_of(named[c]);
      u.fixed.emplace_back(slot.value_or(static_cast<std::size_t>(-1)), static_cast<int>(c));
      if (slot) {
        known.insert(*slot);
      }
    }
  }
  std::vector<std::size_t> unknown;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (!known.contains(i) && !symbols[i].is_equal(file::pulse_duration())) {
      unknown.push_back(i);
    }
  }
  if (model.draws_the_rest) {
    u.drawn = unknown;
  } else {
    u.undetermined.insert(unknown.begin(), unknown.end());
    match(u, unknown);
  }
  if (const auto ts = index_of(t)) {
    u.fixes_t = known.contains(*ts);
  }
  return u;
}

// Matches each unknown with an equation before that holds it (the fewest unknowns first); what
// is solved from an equation that holds an undetermined symbol is undetermined too.
void Evaluation::match(Unknowns& u, const std::vector<std::size_t>& unknown) {
  std::vector<bool> used(pool_.size(), false);
  std::vector<ex> equations;
  std::vector<ex> solved;
  for (const std::size_t k : unknown) {
    std::optional<std::size_t> best;
    std::size_t fewest = static_cast<std::size_t>(-1);
    for (std::size_t q = 0; q < pool_.size(); ++q) {
      if (used[q] || !pool_[q].has(symbols[k])) {
        continue;
      }
      const auto count = static_cast<std::size_t>(std::count_if(
          unknown.begin(), unknown.end(), [&](std::size_t w) { return pool_[q].has(symbols[w]); }));
      if (count < fewest) {
        fewest = count;
        best = q;
      }
    }
    if (best) {
      used[*best] = true;
      equations.push_back(pool_[*best]);
      solved.push_back(symbols[k]);
      u.solved.push_back(k);
      u.undetermined.erase(k);
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t q = 0; q < equations.size(); ++q) {
      if (!u.undetermined.contains(u.solved[q]) &&
          std::any_of(u.undetermined.begin(), u.undetermined.end(),
                      [&](std::size_t w) { return equations[q].has(symbols[w]); })) {
        u.undetermined.insert(u.solved[q]);
        changed = true;
      }
    }
  }
  if (!equations.empty()) {
    solve_linear(u, equations, solved);
  }
  u.used_equations = equations;
}

// Equations linear in what they solve for are solved once, exactly: what they give is put into
// the statements, so that their terms count in the size residuals are measured by. The others
// are solved numerically at each point.
void Evaluation::solve_linear(Unknowns& u, const std::vector<ex>& equations,
                              const std::vector<ex>& solved) {
  bool linear = true;
  std::vector<ex> numerators;
  for (const ex& e : equations) {
    numerators.push_back(GiNaC::normal(e).numer());
    for (const ex& s : solved) {
      linear = linear && numerators.back().is_polynomial(s) && numerators.back().degree(s) <= 1;
    }
  }
  if (linear) {
    GiNaC::lst system, names;
    for (std::size_t q = 0; q < equations.size(); ++q) {
      system.append(numerators[q] == 0);
      names.append(solved[q]);
    }
    try {
      const ex solution = GiNaC::lsolve(system, names);
      if (solution.nops() == solved.size()) {
        for (std::size_t q = 0; q < solution.nops(); ++q) {
          u.exact_solution[solution.op(q).lhs()] = solution.op(q).rhs();
        }
      }
    } catch (const std::exception&) {
      u.exact_solution.clear();
    }
  }
  if (u.exact_solution.empty()) {
    u.solver.emplace(equations, solved, symbols, facts_, random_);
    return;
  }
  u.solved.clear();
  for (const auto& [s, value] : u.exact_solution) {
    u.shown.emplace_back(s, TimedExpression(value, symbols));
  }
}

// The differentials the point gives, as rates: at an instant, dX is the value times dt.
GiNaC::exmap Evaluation::rates(const models::Point& point) const {
  GiNaC::exmap rates;
  for (const models::Value& v : point.values) {
    const std::vector<ex> named = run.symbols_of_name(v.symbol);
    const file::SymbolInfo* info = run.symbols.info(named[0]);
    if (!v.vector && info != nullptr && info->name.differential) {
      rates[named[0]] = named[0] * dt;
    }
  }
  return rates;
}

// The values of every symbol at the point: the point's, the drawn ones, the pulse's time scale
// (the duration dt, or for an instant a duration of its own and an instant t in it), and those the
// equations before solve. False when the point gives nothing to test (no solution, not finite).
bool Evaluation::values_at(const models::Point& point, Unknowns& u, std::vector<double>& values) {
  std::fill(values.begin(), values.end(), 0.0);
  std::size_t k = 0;
  for (const models::Value& v : point.values) {
    for (std::size_t c = 0; c < (v.vector ? 2U : 1U); ++c, ++k) {
      const auto [slot, component] = u.fixed[k];
      if (slot != static_cast<std::size_t>(-1)) {
        values[slot] = component == 0 ? v.x : v.y;
      }
    }
  }
  for (const std::size_t slot : u.drawn) {
    values[slot] = file::draw_with_sign(random_, signs_[slot]);
  }
  for (const std::size_t slot : u.solved) {
    values[slot] = file::draw_with_sign(random_, signs_[slot]);
  }
  const std::size_t tau = tau_;
  const std::optional<std::size_t> d = dt_;
  values[tau] = d ? values[*d] : random_.uniform(0.5, 2.0);
  if (instant_ && u.fixes_t && d) {
    values[tau] = values[*d];  // the model's instant t of its contact dt
  } else if (instant_) {
    values[tau] = random_.uniform(0.5, 2.0);
    if (t_) {
      values[*t_] = random_.uniform(0.02, 0.98) * values[tau];
    }
  }
  if (u.solver && !u.solver->solve(values)) {
    return false;
  }
  return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
}

// The point, as text: the model's values that @p used holds, then what the equations before
// gave, by name (their own order follows GiNaC's hashes, which change from run to run).
std::string Evaluation::point_text(const models::Point& point, const Unknowns& u,
                                   const std::vector<double>& values,
                                   const std::vector<ex>& used) const {
  const auto in_used = [&](const ex& s) {
    return std::any_of(used.begin(), used.end(), [&](const ex& x) { return x.is_equal(s); });
  };
  std::string text;
  for (const models::Value& v : point.values) {
    const std::vector<ex> named = run.symbols_of_name(v.symbol);
    if (std::none_of(named.begin(), named.end(),
                     [&](const ex& x) { return index_of(x).has_value(); })) {
      continue;  // a value the claim does not use
    }
    const file::SymbolInfo* info = run.symbols.info(named[0]);
    const std::string name = info == nullptr ? v.symbol
                             : info->of      ? info->of->latex()
                                             : info->name.latex();
    text += (text.empty() ? "" : ", ") + name + " = ";
    text += v.vector ? "[" + shown_number(v.x) + ", " + shown_number(v.y) + "]" : shown_number(v.x);
  }
  std::vector<std::string> solved;
  for (const std::size_t s : u.solved) {
    if (in_used(symbols[s])) {
      solved.push_back(symbol_text(run.symbols, symbols[s]) + " = " + shown_number(values[s]));
    }
  }
  for (const auto& [s, solution] : u.shown) {
    if (in_used(s)) {
      solved.push_back(symbol_text(run.symbols, s) + " = " +
                       shown_number(solution(values, nullptr)));
    }
  }
  std::sort(solved.begin(), solved.end());
  for (const std::string& s : solved) {
    text += "; " + s;
  }
  return text;
}

// The preparations of a model's points, one per set of names the points give.
template <typename Prepared>
class ByNames {
 public:
  template <typename Make>
  Prepared& of(std::size_t names, const Make& make) {
    auto found = cache_.find(names);
    if (found == cache_.end()) {
      found = cache_.emplace(names, make()).first;
    }
    return found->second;
  }

 private:
  std::map<std::size_t, Prepared> cache_;
};

// ---- an equation or a step --------------------------------------------------------------------

// The statements compiled for one set of names: which are tested (an equation that solved for a
// symbol holds there by construction, and one with an undetermined symbol cannot be evaluated),
// and their differences, scales and denominators.
struct Statements {
  Unknowns unknowns;
  std::vector<bool> tested;
  std::vector<TimedExpression> differences;  // each with the size of its terms, compiled together
  std::vector<std::vector<TimedExpression>> denominators;
};

Statements compile(Evaluation& e, const models::Point& point, const std::vector<Target>& targets,
                   const file::Group& g, const std::string& model_name) {
  Statements s{e.unknowns(point), {}, {}, {}};
  const Unknowns& u = s.unknowns;
  const GiNaC::exmap rates = e.rates(point);
  bool any = false;
  for (const Target& target : targets) {
    ex left = target.left;
    ex right = target.right;
    if (target.instant) {
      // An equation between differentials at the instant t = u τ of the contact: forces shaped
      // there, a differential the model gives is its rate at that instant times dt, and both
      // sides are divided by dt (an equation between rates: dS_v = v_v dt and F_v = dp_v / dt).
      GiNaC::exmap shaped = rates;
      for (const ex& force : e.run.symbols.forces()) {
        shaped[force] = force * file::contact_pulse(e.t / file::pulse_duration());
      }
      left = GiNaC::expand(file::shaped_outside_integrals(left, shaped) / e.dt);
      right = GiNaC::expand(file::shaped_outside_integrals(right, shaped) / e.dt);
    }
    left = u.solved_form(left);
    right = u.solved_form(right);
    const bool solver =
        std::any_of(u.used_equations.begin(), u.used_equations.end(), [&](const ex& q) {
          return q.is_equal(target.left - target.right) ||
                 GiNaC::expand(q - (target.left - target.right)).is_zero();
        });
    const bool ok = !solver && e.determined(u, target.left) && e.determined(u, target.right);
    s.tested.push_back(ok);
    any = any || ok;
    s.differences.emplace_back(
        std::vector<ex>{left - right, file::term_scale(left) + file::term_scale(right)}, e.symbols);
    std::vector<TimedExpression> ds;
    for (const ex& d : target.denominators) {
      ds.emplace_back(d, e.symbols);
    }
    s.denominators.push_back(std::move(ds));
  }
  if (!any) {
    const std::string names = e.undetermined_names(u, [](const ex&) { return true; });
    throw e.error("expected the model " + model_name + " to test something in " + g.id +
                  (names.empty()
                       ? ": each statement there is an equation the model's values were "
                         "solved with, which holds by construction"
                       : ": it does not give " + names + " a value, nor do the equations before"));
  }
  return s;
}

// The worst relative residual of the tested statements at one point, if any was tested there.
std::optional<double> residual_at(const Statements& s, const models::Point& point,
                                  const std::vector<double>& values) {
  std::optional<double> worst;
  for (std::size_t i = 0; i < s.tested.size(); ++i) {
    if (!s.tested[i]) {
      continue;
    }
    bool clear = true;
    for (const TimedExpression& d : s.denominators[i]) {
      const double x = d(values, point.pulse);
      clear = clear && std::isfinite(x) && std::abs(x) > 1e-12;
    }
    if (!clear) {
      continue;
    }
    std::array<double, 2> both{};
    s.differences[i](values, point.pulse, both);
    const double difference = both[0];
    const double scale = both[1];
    if (!std::isfinite(difference) || !std::isfinite(scale)) {
      continue;
    }
    const double residual =
        difference == 0.0 ? 0.0 : std::abs(difference) / std::max(scale, 1e-300);
    worst = std::max(worst.value_or(0.0), residual);
  }
  return worst;
}

}  // namespace

EquationFinding evaluate(FileRun& run, const file::ModelUse& use,
                         const std::vector<Target>& targets, const std::vector<ex>& pool,
                         const file::Facts& facts, const file::Group& g) {
  std::vector<ex> expressions;
  for (const Target& t : targets) {
    expressions.push_back(t.left);
    expressions.push_back(t.right);
    expressions.insert(expressions.end(), t.denominators.begin(), t.denominators.end());
  }
  expressions.insert(expressions.end(), pool.begin(), pool.end());
  const bool instant =
      std::any_of(targets.begin(), targets.end(), [](const Target& x) { return x.instant; });
  Evaluation e(run, use, expressions, pool, facts, g, instant);
  EquationFinding f{e.model.method, 0, 0.0, false, false, {}};
  ByNames<Statements> prepared;
  std::vector<double> values(e.symbols.size(), 0.0);
  for (std::size_t at = 0; at < e.points().size(); ++at) {
    const models::Point& point = e.points()[at];
    Statements& s =
        prepared.of(e.names(at), [&] { return compile(e, point, targets, g, use.name); });
    if (!e.values_at(point, s.unknowns, values)) {
      continue;
    }
    if (const std::optional<double> worst = residual_at(s, point, values)) {
      f.worst = std::max(f.worst, *worst);
      ++f.points;
    }
  }
  f.holds = f.points > 0 && f.worst <= e.model.holds_below;
  f.fails = f.points > 0 && f.worst >= e.model.fails_above;
  f.detail = std::string(row_of(e.model.method).directive) + ": " + use.name + ", " +
             std::to_string(f.points) + " points, worst relative residual " +
             num::residual_text(f.worst) +
             (f.holds   ? " (holds)"
              : f.fails ? " (fails)"
                        : " (undecided)");
  return f;
}

namespace {

// ---- a claim ----------------------------------------------------------------------------------

// The claim's relations compiled for one set of names: per relation, its left side, then its
// right side or its members, then the size of its terms, compiled together.
struct Relations {
  Unknowns unknowns;
  std::vector<TimedExpression> sides;
};

Relations compile(Evaluation& e, const models::Point& point, const Rows& rows,
                  const std::string& model_name) {
  Relations r{e.unknowns(point), {}};
  const Unknowns& u = r.unknowns;
  for (const auto* list : {&rows.hypotheses, &rows.conclusions}) {
    for (const std::vector<Compare>& row : *list) {
      for (const Compare& c : row) {
        if (!e.determined(u, c.left) || !e.determined(u, c.right) ||
            !std::all_of(c.members.begin(), c.members.end(),
                         [&](const ex& m) { return e.determined(u, m); })) {
          const std::string names =
              e.undetermined_names(u, [&](const ex& s) { return c.left.has(s) || c.right.has(s); });
          throw e.error("expected the model " + model_name +
                        " or the equations before the claim to give " + names +
                        " a value (in: " + c.text + ")");
        }
        const ex left = u.solved_form(c.left);
        std::vector<ex> sides{left};
        ex scale = file::term_scale(left);
        for (const ex& side : c.membership() ? c.members : std::vector<ex>{c.right}) {
          sides.push_back(u.solved_form(side));
          scale += file::term_scale(u.solved_form(side));
        }
        sides.push_back(scale);
        r.sides.emplace_back(sides, e.symbols);
      }
    }
  }
  return r;
}

// Whether a relation holds at a point, and whether that is sure (not within the rounding band
// between 1e-9 and 1e-6 of the terms' size): its sides are those sides[slot] evaluates (left,
// then the right side or the members, then the size of the terms); @p slot moves past it. When it
// does not hold and @p shown is given, the sides as text for a counterexample (formatting them
// costs more than the rest, so only the first failure of a row asks).
bool holds(const Compare& c, const std::vector<double>& values,
           const std::vector<TimedExpression>& sides, std::size_t& slot, std::optional<bool>& sure,
           std::string* shown) {
  using K = Relation::Kind;
  const std::size_t count = c.membership() ? c.members.size() : 1;
  std::vector<double> all(count + 2);
  sides[slot](values, nullptr, all);
  ++slot;
  const double left = all[0];
  const std::span<const double> others(all.data() + 1, count);
  const double terms = std::max(std::abs(all[count + 1]), 1e-300);
  if (!std::isfinite(left) || !std::isfinite(terms) ||
      !std::all_of(others.begin(), others.end(), [](double x) { return std::isfinite(x); })) {
    sure = std::nullopt;
    if (shown != nullptr) {
      *shown = "not finite";
    }
    return false;
  }
  bool holds = false;
  bool certain = true;
  if (c.kind == K::in_set) {
    holds = std::any_of(others.begin(), others.end(),
                        [&](double m) { return std::abs(left - m) <= 1e-12 * terms; });
  } else if (c.kind == K::in_range) {
    const double* bound = others.data();
    holds = (!c.has_low || (c.low_closed ? left >= *bound : left > *bound)) &&
            (!c.has_high ||
             (c.high_closed ? left <= bound[c.has_low ? 1 : 0] : left < bound[c.has_low ? 1 : 0]));
  } else {
    const double d = (left - others[0]) / terms;  // the relation's difference, relative
    const auto band = [](double x) { return x > 1e-9 && x < 1e-6; };
    switch (c.kind) {
      case K::equal:
        holds = std::abs(d) <= 1e-9;
        certain = !band(std::abs(d));
        break;
      case K::not_equal:
        holds = std::abs(d) >= 1e-6;
        certain = !band(std::abs(d));
        break;
      case K::less_equal:
        holds = d <= 1e-9;
        certain = !band(d);
        break;
      case K::greater_equal:
        holds = -d <= 1e-9;
        certain = !band(-d);
        break;
      case K::less:
        holds = d <= -1e-9;
        certain = !(d > -1e-9 && d < 1e-6);
        break;
      case K::greater:
        holds = -d <= -1e-9;
        certain = !(-d > -1e-9 && -d < 1e-6);
        break;
      default:
        break;
    }
    if (!holds && shown != nullptr) {
      *shown = shown_number(left) + " and " + shown_number(others[0]);
    }
  }
  sure = certain ? std::optional<bool>(holds) : std::nullopt;
  return holds;
}

// One row at a point whose hypotheses hold: whether every conclusion holds surely, and the first
// that does not (explained when the row has no failure yet). Nothing when one is not sure.
std::optional<bool> row_holds(const std::vector<Compare>& conclusions,
                              const std::vector<double>& values,
                              const std::vector<TimedExpression>& sides, std::size_t& slot,
                              bool explain, std::string& failure) {
  bool every = true;
  bool sure_all = true;
  for (const Compare& c : conclusions) {
    std::optional<bool> sure;
    std::string shown;
    const bool one = holds(c, values, sides, slot, sure, explain ? &shown : nullptr);
    sure_all = sure_all && sure.has_value();
    if (!one && failure.empty() && explain) {
      failure = c.text + " fails (its sides: " + shown + ")";
    }
    every = every && one;
  }
  return sure_all ? std::optional<bool>(every) : std::nullopt;
}

}  // namespace

ClaimFinding evaluate(FileRun& run, const file::ModelUse& use, const Rows& rows,
                      const std::vector<ex>& pool, const file::Facts& facts, const file::Group& g) {
  std::vector<ex> expressions = pool;
  std::vector<ex> related;  // the symbols the relations use, for a case's text
  for (const auto* list : {&rows.hypotheses, &rows.conclusions}) {
    for (const std::vector<Compare>& row : *list) {
      for (const Compare& c : row) {
        for (const ex& x : {c.left, c.right, c.scale}) {
          expressions.push_back(x);
        }
        expressions.insert(expressions.end(), c.members.begin(), c.members.end());
        related.push_back(c.left);
        related.push_back(c.right);
        related.insert(related.end(), c.members.begin(), c.members.end());
      }
    }
  }
  Evaluation e(run, use, expressions, pool, facts, g, false);
  const std::vector<ex> in_relations = file::symbols_of(related);
  const std::size_t n = rows.conclusions.size();
  ClaimFinding f{e.model.method, std::vector<RowFinding>(n)};
  ByNames<Relations> prepared;
  std::vector<double> values(e.symbols.size(), 0.0);
  for (std::size_t at = 0; at < e.points().size(); ++at) {
    const models::Point& point = e.points()[at];
    Relations& r = prepared.of(e.names(at), [&] { return compile(e, point, rows, use.name); });
    if (!e.values_at(point, r.unknowns, values)) {
      continue;
    }
    // Each row whose hypotheses hold at the point; the others say nothing here.
    std::size_t slot = 0;
    std::vector<bool> applies(n, true);
    for (std::size_t k = 0; k < n; ++k) {
      for (const Compare& c : rows.hypotheses[k]) {
        std::optional<bool> sure;
        applies[k] = holds(c, values, r.sides, slot, sure, nullptr) && applies[k];
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      RowFinding& row = f.rows[k];
      if (!applies[k]) {
        slot += rows.conclusions[k].size();
        continue;
      }
      std::string failure;
      const std::optional<bool> every =
          row_holds(rows.conclusions[k], values, r.sides, slot, row.first_failure.empty(), failure);
      if (!every) {
        continue;
      }
      ++row.tested;
      std::string& first = *every ? row.witness : row.first_failure;
      ++(*every ? row.satisfied : row.failures);
      if (first.empty()) {
        first = e.point_text(point, r.unknowns, values, in_relations) +
                (*every ? "" : " gives " + failure);
      }
    }
  }
  return f;
}

}  // namespace impulse::derivations::paper
