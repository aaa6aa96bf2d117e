// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's checks: each check of a paper file judged from what the engine finds on it. An
// equation or a step is verified when everything it is tested by passes (its own equations follow
// from the equations before, its evidence follows from it, every model it names agrees); an
// erratum when that fails for the statement as printed and passes for its correction; a claim is
// verified when every row holds (exactly, or on every case its search produces) and refuted when
// a case breaks it. Nothing here knows which statements are right.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "derivations/derivation.hpp"
#include "file/decide.hpp"
#include "file/reader.hpp"
#include "file/sample.hpp"
#include "file/step.hpp"
#include "file/time.hpp"
#include "impulse/core/error.hpp"
#include "models/model.hpp"
#include "numeric.hpp"
#include "symbolic.hpp"

namespace impulse::derivations {

namespace {

using GiNaC::ex;
using namespace file;

// A number for a counterexample: a few significant digits, and no "-0".
std::string shown_number(double x) {
  return num::brief(x == 0.0 ? 0.0 : x, 6);
}

std::string symbol_text(Symbols& symbols, const ex& s) {
  const SymbolInfo* info = symbols.info(s);
  if (info == nullptr) {
    return GiNaC::is_a<GiNaC::symbol>(s) ? GiNaC::ex_to<GiNaC::symbol>(s).get_name() : "?";
  }
  return info->name.latex();
}

// A counterexample or a note in plain words: the report shows them as text, not as math, so the
// LaTeX of the file's symbols and relations is spelled out (\vec{p}_1 as p_1, \leq as ≤).
std::string plain(std::string text) {
  static const std::pair<std::string_view, std::string_view> words[] = {
      {"\\cdot", "·"},       {"\\leq", "≤"},   {"\\geq", "≥"},    {"\\neq", "≠"},
      {"\\Rightarrow", "⇒"}, {"\\times", "×"}, {"\\tau", "τ"},    {"\\alpha", "α"},
      {"\\omega", "ω"},      {"\\mu", "μ"},    {"\\lambda", "λ"}, {"\\Delta ", "Δ"},
      {"\\Delta", "Δ"},      {"\\ell", "ℓ"},   {"\\quad", " "},   {"\\,", " "},
      {"\\;", " "},          {"\\!", ""},      {"\\left", ""},    {"\\right", ""}};
  // Accents: \bar{X} as X̄, \tilde{X} as X̃; wrappers: \vec, \mathit, \mathrm, \text dropped.
  static const std::pair<std::string_view, std::string_view> accents[] = {
      {"\\bar{", "\u0304"}, {"\\tilde{", "\u0303"}, {"\\hat{", "\u0302"}, {"\\vec{", ""},
      {"\\mathit{", ""},    {"\\mathrm{", ""},      {"\\text{", ""},      {"\\operatorname{", ""}};
  for (const auto& [command, mark] : accents) {
    for (std::size_t at = text.find(command); at != std::string::npos; at = text.find(command)) {
      const std::size_t open = at + command.size();
      std::size_t close = open;
      for (int depth = 1; close < text.size(); ++close) {
        depth += text[close] == '{' ? 1 : text[close] == '}' ? -1 : 0;
        if (depth == 0) {
          break;
        }
      }
      if (close >= text.size()) {
        break;
      }
      const std::string inner = text.substr(open, close - open);
      text.replace(at, close + 1 - at, inner + std::string(mark));
    }
  }
  for (const auto& [command, word] : words) {
    for (std::size_t at = text.find(command); at != std::string::npos;
         at = text.find(command, at + word.size())) {
      text.replace(at, command.size(), word);
    }
  }
  std::string out;
  for (const char c : text) {
    if (c != '{' && c != '}' && c != '\\') {
      out += c;
    }
  }
  return out;
}

// What one model found on one variant of a check.
struct ModelFinding {
  Method method = Method::numeric;
  std::string name;
  std::size_t points = 0;  // points where something was tested
  double worst = 0.0;
  bool holds = false;
  bool fails = false;
  std::string detail;
  // Claims, per row: failures and the first one; the witness of an existence.
  std::vector<std::size_t> row_failures;
  std::vector<std::size_t> row_tested;
  std::vector<std::size_t> row_satisfied;
  std::vector<std::string> row_first_failure;
  std::vector<std::string> row_witness;
};

Method method_named(const std::string& name) {
  if (name == "ode") {
    return Method::ode;
  }
  if (name == "quadrature") {
    return Method::quadrature;
  }
  if (name == "search") {
    return Method::search;
  }
  return Method::numeric;
}

// One relation of a claim as the engine evaluates it: lhs - rhs and the size of its terms, or the
// value and the bounds of a membership.
struct Compare {
  Relation::Kind kind = Relation::Kind::equal;
  ex left;
  ex right;
  std::vector<ex> members;  // in_set; in_range: low (or nothing), high (or nothing)
  ex scale;                 // the size of the terms the two sides are made of
  bool low_closed = false;
  bool high_closed = false;
  bool has_low = false;
  bool has_high = false;
  std::string text;  // the relation as written
};

// Everything the engine knows of one file while it checks it.
class FileRun : public models::Probe {
 public:
  FileRun(const Source& source, ReadFile& read, Symbols& symbols, const Options& options)
      : source_(source), read_(read), symbols_(symbols), options_(options) {}

  Result check(const Group& g);
  std::function<double(std::span<const double>)> function(
      std::string_view symbol, const std::vector<std::string>& inputs) override;

 private:
  // ---- equations ----
  struct Variant {
    std::vector<EquationResult> results;
    std::vector<ModelFinding> models;
    bool fails = false;
    bool unknown = false;
    bool evidence = false;
    double worst = 0.0;
    std::size_t samples = 0;
    std::set<Method> methods;
    std::string note;
  };
  Variant run_variant(const Group& g, bool corrected);
  void define_for_probe(const Group& g, const std::vector<std::size_t>& own);
  std::vector<ex> symbols_of_name(std::string_view latex);

  // The model's points, evaluated on a list of equations (each = 0 with the size of its terms).
  struct Target {
    ex left;
    ex right;
    std::vector<ex> denominators;
    bool instant = false;  // an equation between differentials, read at an instant of the contact
    std::string text;
  };
  ModelFinding run_model(const ModelUse& use, const std::vector<Target>& targets,
                         const std::vector<ex>& pool, const Facts& facts, const Group& g,
                         const std::vector<std::vector<Compare>>* hypotheses = nullptr,
                         const std::vector<std::vector<Compare>>* conclusions = nullptr,
                         const std::vector<bool>* exists = nullptr);

  // ---- claims ----
  Result check_claim(const Group& g, Result r);

  const Source& source_;
  ReadFile& read_;
  Symbols& symbols_;
  const Options& options_;
  // Probe::function: the definitions in force at the check, and the statements' (define_for_probe).
  GiNaC::exmap probe_substitutions_;
  std::map<std::string, std::vector<ex>> names_;  // a model's names, read once
  // An ODE model's points, made once per file and shared by the checks that name it: a model
  // knows nothing of the check (it does not read the probe), so its points depend only on the
  // run's seed and samples (the rods on a penalty contact cost 30 ms each).
  std::map<const models::Model*, std::vector<models::Point>> points_;
};

std::vector<ex> FileRun::symbols_of_name(std::string_view latex) {
  const std::string key(latex);
  if (const auto found = names_.find(key); found != names_.end()) {
    return found->second;
  }
  const Source names{key};
  const SymbolName name = read_symbol_or_differential(names, 0, latex, Limits{});
  const Value v = symbols_.value_of(name);
  return names_[key] = v.vector ? std::vector<ex>{v.x, v.y} : std::vector<ex>{v.x};
}

std::function<double(std::span<const double>)> FileRun::function(
    std::string_view symbol, const std::vector<std::string>& inputs) {
  const auto nothing = [](std::span<const double>) { return std::nan(""); };
  try {
    std::vector<ex> slots;
    for (const std::string& input : inputs) {
      const std::vector<ex> named = symbols_of_name(input);
      slots.insert(slots.end(), named.begin(), named.end());
    }
    const ex e = exact_reading(symbols_of_name(symbol)[0].subs(probe_substitutions_));
    for (const ex& s : symbols_of(std::vector<ex>{e})) {
      if (std::none_of(slots.begin(), slots.end(), [&](const ex& x) { return x.is_equal(s); })) {
        return nothing;  // the file does not define it from these inputs
      }
    }
    TimedExpression compiled(e, slots);
    return [compiled = std::move(compiled)](std::span<const double> values) {
      return compiled(values, nullptr);
    };
  } catch (const std::exception&) {
    return nothing;
  }
}

// ---- a model's points against the file's statements -----------------------------------------

// One relation at a point: its sides are sides[slot] (left), then the right side or the members,
// then the size of the terms. Whether it holds, and whether that is sure (not within the rounding
// band between 1e-9 and 1e-6 of the terms' size). When it does not hold and @p shown is given, the
// sides as text for a counterexample (formatting them costs more than the rest, so only the first
// failure of a claim asks).
bool compare_holds(const Compare& c, const std::vector<double>& values,
                   const std::vector<TimedExpression>& sides, std::size_t& slot,
                   std::optional<bool>& conclusive_result, std::string* shown) {
  using K = Relation::Kind;
  const bool membership = c.kind == K::in_set || c.kind == K::in_range;
  const double left = sides[slot](values, nullptr);
  std::vector<double> others;
  const std::size_t count = membership ? c.members.size() : 1;
  for (std::size_t k = 0; k < count; ++k) {
    others.push_back(sides[slot + 1 + k](values, nullptr));
  }
  const double terms = std::max(std::abs(sides[slot + 1 + count](values, nullptr)), 1e-300);
  slot += 2 + count;
  if (!std::isfinite(left) || !std::isfinite(terms) ||
      !std::all_of(others.begin(), others.end(), [](double x) { return std::isfinite(x); })) {
    conclusive_result = std::nullopt;
    if (shown != nullptr) {
      *shown = "not finite";
    }
    return false;
  }
  bool holds = false;
  bool sure = true;
  if (!membership) {
    const double d = (left - others[0]) / terms;  // the relation's difference, relative
    const auto band = [&](double x) { return x > 1e-9 && x < 1e-6; };
    switch (c.kind) {
      case K::equal:
        holds = std::abs(d) <= 1e-9;
        sure = !band(std::abs(d));
        break;
      case K::not_equal:
        holds = std::abs(d) >= 1e-6;
        sure = !band(std::abs(d));
        break;
      case K::less_equal:
        holds = d <= 1e-9;
        sure = !band(d);
        break;
      case K::greater_equal:
        holds = -d <= 1e-9;
        sure = !band(-d);
        break;
      case K::less:
        holds = d <= -1e-9;
        sure = !(d > -1e-9 && d < 1e-6);
        break;
      case K::greater:
        holds = -d <= -1e-9;
        sure = !(-d > -1e-9 && -d < 1e-6);
        break;
      default:
        break;
    }
    if (!holds && shown != nullptr) {
      *shown = shown_number(left) + " and " + shown_number(others[0]);
    }
  } else if (c.kind == K::in_set) {
    holds = std::any_of(others.begin(), others.end(),
                        [&](double m) { return std::abs(left - m) <= 1e-12 * terms; });
  } else {
    std::size_t k = 0;
    holds = true;
    if (c.has_low) {
      holds = holds && (c.low_closed ? left >= others[k] : left > others[k]);
      ++k;
    }
    if (c.has_high) {
      holds = holds && (c.high_closed ? left <= others[k] : left < others[k]);
    }
  }
  conclusive_result = sure ? std::optional<bool>(holds) : std::nullopt;
  return holds;
}

ModelFinding FileRun::run_model(const ModelUse& use, const std::vector<Target>& targets,
                                const std::vector<ex>& pool, const Facts& facts, const Group& g,
                                const std::vector<std::vector<Compare>>* hypotheses,
                                const std::vector<std::vector<Compare>>* conclusions,
                                const std::vector<bool>* exists) {
  const models::Model* model = models::find(use.method, use.name);
  if (model == nullptr) {
    throw source_.error(
        use.offset, "expected a model this checker knows after " +
                        std::string(use.method == "numeric" ? "model" : use.method) + ": found \"" +
                        use.name + "\" (the models: docs/pages/derivations.md)");
  }
  ModelFinding f;
  f.method = method_named(use.method);
  f.name = use.name;
  const bool claim = conclusions != nullptr;
  const std::size_t rows = claim ? conclusions->size() : 0;
  f.row_failures.assign(rows, 0);
  f.row_tested.assign(rows, 0);
  f.row_satisfied.assign(rows, 0);
  f.row_first_failure.assign(rows, {});
  f.row_witness.assign(rows, {});

  // The seed of the model, not of the check: a check's samples still do not depend on which
  // other checks run.
  models::Settings settings{check_seed(options_.seed, use.method + ": " + use.name),
                            options_.samples};
  std::vector<models::Point> made;
  const std::vector<models::Point>* points_in = nullptr;
  // The costly ones (ODE models, and those marked shared); the others are cheaper made again
  // than kept.
  if (model->method == "ode" || model->shared) {
    auto cached = points_.find(model);
    if (cached == points_.end()) {
      cached = points_.emplace(model, model->points(*this, settings)).first;
    }
    points_in = &cached->second;
  } else {
    made = model->points(*this, settings);
    points_in = &made;
  }
  const std::vector<models::Point>& points = *points_in;

  // Every expression to evaluate, in one list of symbols.
  std::vector<ex> all;
  for (const Target& t : targets) {
    all.push_back(t.left);
    all.push_back(t.right);
    all.insert(all.end(), t.denominators.begin(), t.denominators.end());
  }
  all.insert(all.end(), pool.begin(), pool.end());
  const auto add_compare = [&](const std::vector<std::vector<Compare>>* list) {
    if (list == nullptr) {
      return;
    }
    for (const auto& row : *list) {
      for (const Compare& c : row) {
        all.push_back(c.left);
        all.push_back(c.right);
        all.push_back(c.scale);
        all.insert(all.end(), c.members.begin(), c.members.end());
      }
    }
  };
  add_compare(hypotheses);
  add_compare(conclusions);
  std::vector<ex> symbols = symbols_of(all);
  const ex t = symbols_.value_of(SymbolName{"t", "", 0, false}).x;
  const ex dt = symbols_.value_of(SymbolName{"dt", "", 0, false}).x;
  if (std::find_if(symbols.begin(), symbols.end(),
                   [&](const ex& s) { return s.is_equal(pulse_duration()); }) == symbols.end()) {
    symbols.push_back(pulse_duration());
  }
  // A model that shapes the force gives the contact's duration dt, the pulse's time scale, also
  // to a check whose equations do not write it (a path at the contact's end, S_v = ∫_0^t …).
  if (model->draws_the_rest && std::find_if(symbols.begin(), symbols.end(), [&](const ex& s) {
                                 return s.is_equal(dt);
                               }) == symbols.end()) {
    symbols.push_back(dt);
  }
  // An instant's forces are shaped at t, written or not (F_v = dp_v / dt).
  if (std::any_of(targets.begin(), targets.end(), [](const Target& x) { return x.instant; }) &&
      std::find_if(symbols.begin(), symbols.end(), [&](const ex& s) { return s.is_equal(t); }) ==
          symbols.end()) {
    symbols.push_back(t);
  }
  const auto index_of = [&](const ex& s) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      if (symbols[i].is_equal(s)) {
        return i;
      }
    }
    return std::nullopt;
  };

  // Cached per set of names a point gives.
  struct Prepared {
    std::vector<std::pair<std::size_t, int>> fixed;  // slot, component (0, 1) per point value
    std::vector<std::size_t> drawn;                  // slots drawn at random
    std::optional<Solver> solver;
    GiNaC::exmap exact_solution;                        // linear equations before, solved once
    std::vector<std::pair<ex, TimedExpression>> shown;  // those solutions, for the report
    std::vector<std::size_t> solved;
    std::vector<bool> tested;  // per target
    bool fixes_t = false;      // the point gives t: an instant's reading is at the model's t
    std::vector<TimedExpression> differences, scales;
    std::vector<std::vector<TimedExpression>> denominators;
    std::vector<TimedExpression> sides;  // claims: per relation, left then the others
    bool any = false;
  };
  std::map<std::string, Prepared> cache;
  num::Random random(check_seed(options_.seed, g.id + "/" + use.name) ^ 0x5DEECE66DULL);
  const std::map<std::string, std::vector<ex>> no_lookup;

  const models::Point* last_point = nullptr;  // the last point prepared, and what it gave
  Prepared* last_prepared = nullptr;
  const auto prepare = [&](const models::Point& point) -> Prepared& {
    // Most models give every point the same names: then the last point's preparation serves.
    if (last_point != nullptr && last_point->values.size() == point.values.size() &&
        std::equal(
            point.values.begin(), point.values.end(), last_point->values.begin(),
            [](const models::Value& a, const models::Value& b) { return a.symbol == b.symbol; })) {
      last_point = &point;
      return *last_prepared;
    }
    std::string key;
    for (const models::Value& v : point.values) {
      key += v.symbol;
      key += '\n';
    }
    last_point = &point;
    if (const auto found = cache.find(key); found != cache.end()) {
      last_prepared = &found->second;
      return found->second;
    }
    Prepared p;
    std::set<std::size_t> known;
    for (const models::Value& v : point.values) {
      const std::vector<ex> named = symbols_of_name(v.symbol);
      if ((named.size() == 2) != v.vector) {
        throw source_.error(use.offset, "expected the file to read " + v.symbol + " as the model " +
                                            use.name + " gives it, " +
                                            (v.vector ? "a vector" : "a number"));
      }
      for (std::size_t c = 0; c < named.size(); ++c) {
        const auto slot = index_of(named[c]);
        if (!slot) {
          p.fixed.emplace_back(static_cast<std::size_t>(-1), 0);
          continue;
        }
        p.fixed.emplace_back(*slot, static_cast<int>(c));
        known.insert(*slot);
      }
    }
    std::vector<std::size_t> unknown;
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      if (!known.contains(i) && !symbols[i].is_equal(pulse_duration())) {
        unknown.push_back(i);
      }
    }
    std::set<std::size_t> undetermined(unknown.begin(), unknown.end());
    std::vector<ex> used_equations;
    if (model->draws_the_rest) {
      p.drawn = unknown;
      undetermined.clear();
    } else {
      // Match each unknown with an equation before that holds it (the fewest unknowns first).
      std::vector<bool> used(pool.size(), false);
      std::vector<ex> equations;
      std::vector<ex> unknowns;
      for (const std::size_t u : unknown) {
        std::optional<std::size_t> best;
        std::size_t fewest = static_cast<std::size_t>(-1);
        for (std::size_t k = 0; k < pool.size(); ++k) {
          if (used[k] || !pool[k].has(symbols[u])) {
            continue;
          }
          std::size_t count = 0;
          for (const std::size_t w : unknown) {
            count += pool[k].has(symbols[w]) ? 1U : 0U;
          }
          if (count < fewest) {
            fewest = count;
            best = k;
          }
        }
        if (best) {
          used[*best] = true;
          equations.push_back(pool[*best]);
          unknowns.push_back(symbols[u]);
          p.solved.push_back(u);
          undetermined.erase(u);
        }
      }
      // What is solved from an equation that holds an undetermined symbol is undetermined too.
      for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < equations.size(); ++k) {
          const std::size_t u = p.solved[k];
          if (undetermined.contains(u)) {
            continue;
          }
          const bool depends =
              std::any_of(undetermined.begin(), undetermined.end(),
                          [&](std::size_t w) { return equations[k].has(symbols[w]); });
          if (depends) {
            undetermined.insert(u);
            changed = true;
          }
        }
      }
      // Equations linear in what they solve for are solved once, exactly: what they give is put
      // into the statements, so that their terms count in the size residuals are measured by.
      if (!equations.empty()) {
        bool linear = true;
        for (const ex& e : equations) {
          const ex numerator = GiNaC::normal(e).numer();
          for (const ex& u : unknowns) {
            linear = linear && numerator.is_polynomial(u) && numerator.degree(u) <= 1;
          }
        }
        if (linear) {
          GiNaC::lst system, names;
          for (std::size_t k = 0; k < equations.size(); ++k) {
            system.append(GiNaC::normal(equations[k]).numer() == 0);
            names.append(unknowns[k]);
          }
          try {
            const ex solution = GiNaC::lsolve(system, names);
            if (solution.nops() == unknowns.size()) {
              for (std::size_t k = 0; k < solution.nops(); ++k) {
                p.exact_solution[solution.op(k).lhs()] = solution.op(k).rhs();
              }
            }
          } catch (const std::exception&) {
            p.exact_solution.clear();
          }
        }
        if (p.exact_solution.empty()) {
          p.solver.emplace(equations, unknowns, symbols, facts, random);
        } else {
          p.solved.clear();
          for (const auto& [u, value] : p.exact_solution) {
            p.shown.emplace_back(u, TimedExpression(value, symbols));
          }
        }
      }
      used_equations = equations;
    }
    const auto determined = [&](const ex& e) {
      return std::none_of(undetermined.begin(), undetermined.end(),
                          [&](std::size_t u) { return e.has(symbols[u]); });
    };
    // The differentials the point gives, as rates: at an instant, dX is the value times dt.
    GiNaC::exmap rates;
    for (const models::Value& v : point.values) {
      const std::vector<ex> named = symbols_of_name(v.symbol);
      const SymbolInfo* info = symbols_.info(named[0]);
      if (!v.vector && info != nullptr && info->name.differential) {
        rates[named[0]] = named[0] * dt;
      }
    }
    if (const auto ts = index_of(t)) {
      p.fixes_t = known.contains(*ts);
    }
    for (const Target& target : targets) {
      ex left = target.left;
      ex right = target.right;
      if (target.instant) {
        // An equation between differentials at the instant t = u τ of the contact: forces
        // shaped there, a differential the model gives is its rate at that instant times dt, and
        // both sides are divided by dt (an equation between rates: dS_v = v_v dt and
        // F_v = dp_v / dt alike).
        GiNaC::exmap shaped = rates;
        for (const ex& force : symbols_.forces()) {
          shaped[force] = force * contact_pulse(t / pulse_duration());
        }
        left = GiNaC::expand(shaped_outside_integrals(left, shaped) / dt);
        right = GiNaC::expand(shaped_outside_integrals(right, shaped) / dt);
      }
      if (!p.exact_solution.empty()) {
        left = left.subs(p.exact_solution);
        right = right.subs(p.exact_solution);
      }
      const ex difference = left - right;
      const ex scale = term_scale(left) + term_scale(right);
      // An equation that solved for a symbol holds there by construction: it tests nothing.
      const bool solver =
          std::any_of(used_equations.begin(), used_equations.end(), [&](const ex& e) {
            return e.is_equal(target.left - target.right) ||
                   GiNaC::expand(e - (target.left - target.right)).is_zero();
          });
      const bool ok = !solver && determined(target.left) && determined(target.right);
      p.tested.push_back(ok);
      p.any = p.any || ok;
      p.differences.emplace_back(difference, symbols);
      p.scales.emplace_back(scale, symbols);
      std::vector<TimedExpression> ds;
      for (const ex& d : target.denominators) {
        ds.emplace_back(d, symbols);
      }
      p.denominators.push_back(std::move(ds));
    }
    const auto compile_compares = [&](const std::vector<std::vector<Compare>>* list) {
      if (list == nullptr) {
        return;
      }
      for (const auto& row : *list) {
        for (const Compare& c : row) {
          if (!determined(c.left) || !determined(c.right) ||
              !std::all_of(c.members.begin(), c.members.end(), determined)) {
            std::string names;
            for (const std::size_t u : undetermined) {
              if (c.left.has(symbols[u]) || c.right.has(symbols[u])) {
                names += (names.empty() ? "" : ", ") + symbol_text(symbols_, symbols[u]);
              }
            }
            throw source_.error(use.offset, "expected the model " + use.name +
                                                " or the "
                                                "equations before the claim to give " +
                                                names + " a value (in: " + c.text + ")");
          }
          const auto solved = [&](const ex& e) {
            return p.exact_solution.empty() ? e : e.subs(p.exact_solution);
          };
          const ex left = solved(c.left);
          p.sides.emplace_back(left, symbols);
          ex scale = term_scale(left);
          if (c.kind == Relation::Kind::in_set || c.kind == Relation::Kind::in_range) {
            for (const ex& m : c.members) {
              p.sides.emplace_back(solved(m), symbols);
              scale += term_scale(solved(m));
            }
          } else {
            const ex right = solved(c.right);
            p.sides.emplace_back(right, symbols);
            scale += term_scale(right);
          }
          p.sides.emplace_back(scale, symbols);
        }
      }
    };
    compile_compares(hypotheses);
    compile_compares(conclusions);
    if (claim) {
      p.any = true;
    }
    if (!p.any) {
      std::string names;
      for (const std::size_t u : undetermined) {
        names += (names.empty() ? "" : ", ") + symbol_text(symbols_, symbols[u]);
      }
      throw source_.error(
          use.offset,
          "expected the model " + use.name + " to test something in " + g.id +
              (names.empty()
                   ? ": each statement there is an equation the model's values were "
                     "solved with, which holds by construction"
                   : ": it does not give " + names + " a value, nor do the equations before"));
    }
    last_prepared = &cache.emplace(key, std::move(p)).first->second;
    return *last_prepared;
  };

  // The symbols a claim's relations use.
  std::vector<ex> relation_sides;
  for (const auto* list : {hypotheses, conclusions}) {
    for (const auto& row : list != nullptr ? *list : std::vector<std::vector<Compare>>{}) {
      for (const Compare& c : row) {
        relation_sides.push_back(c.left);
        relation_sides.push_back(c.right);
        relation_sides.insert(relation_sides.end(), c.members.begin(), c.members.end());
      }
    }
  }
  const std::vector<ex> in_relations = symbols_of(relation_sides);
  const auto claimed = [&](const ex& s) {
    return std::any_of(in_relations.begin(), in_relations.end(),
                       [&](const ex& x) { return x.is_equal(s); });
  };

  std::vector<double> values(symbols.size(), 0.0);
  for (const models::Point& point : points) {
    Prepared& p = prepare(point);
    std::fill(values.begin(), values.end(), 0.0);
    std::size_t k = 0;
    for (const models::Value& v : point.values) {
      const std::size_t components = v.vector ? 2 : 1;
      for (std::size_t c = 0; c < components; ++c, ++k) {
        const auto [slot, component] = p.fixed[k];
        if (slot != static_cast<std::size_t>(-1)) {
          values[slot] = component == 0 ? v.x : v.y;
        }
      }
    }
    for (const std::size_t slot : p.drawn) {
      values[slot] = draw_with_sign(random, facts.of_symbol(symbols[slot]));
    }
    for (const std::size_t slot : p.solved) {
      values[slot] = draw_with_sign(random, facts.of_symbol(symbols[slot]));
    }
    // The pulse's time scale: the duration dt, or for an instant a duration of its own.
    const auto tau = index_of(pulse_duration());
    if (const auto d = index_of(dt); d && tau) {
      values[*tau] = values[*d];
    } else if (tau) {
      values[*tau] = random.uniform(0.5, 2.0);
    }
    const bool instant =
        std::any_of(targets.begin(), targets.end(), [](const Target& x) { return x.instant; });
    if (instant && tau && p.fixes_t && index_of(dt)) {
      values[*tau] = values[*index_of(dt)];  // the model's instant t of its contact dt
    } else if (instant && tau) {
      values[*tau] = random.uniform(0.5, 2.0);
      if (const auto ts = index_of(t)) {
        values[*ts] = random.uniform(0.02, 0.98) * values[*tau];
      }
    }
    if (p.solver && !p.solver->solve(values)) {
      continue;
    }
    if (!std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); })) {
      continue;
    }
    if (!claim) {
      bool counted = false;
      for (std::size_t i = 0; i < targets.size(); ++i) {
        if (!p.tested[i]) {
          continue;
        }
        bool clear = true;
        for (const TimedExpression& d : p.denominators[i]) {
          const double x = d(values, point.pulse);
          clear = clear && std::isfinite(x) && std::abs(x) > 1e-12;
        }
        if (!clear) {
          continue;
        }
        const double difference = p.differences[i](values, point.pulse);
        const double scale = p.scales[i](values, point.pulse);
        if (!std::isfinite(difference) || !std::isfinite(scale)) {
          continue;
        }
        const double residual =
            difference == 0.0 ? 0.0 : std::abs(difference) / std::max(scale, 1e-300);
        f.worst = std::max(f.worst, residual);
        counted = true;
      }
      f.points += counted ? 1U : 0U;
      continue;
    }
    // A claim: each row whose hypotheses hold at the point.
    std::size_t slot = 0;
    std::vector<bool> applies(rows, true);
    for (std::size_t r = 0; r < rows && hypotheses != nullptr; ++r) {
      for (const Compare& c : (*hypotheses)[r]) {
        std::optional<bool> sure;
        if (!compare_holds(c, values, p.sides, slot, sure, nullptr)) {
          applies[r] = false;
        }
      }
    }
    bool counted = false;
    for (std::size_t r = 0; r < rows; ++r) {
      if (!applies[r]) {  // the row says nothing here: its sides are not evaluated
        for (const Compare& c : (*conclusions)[r]) {
          slot += 2 + (c.kind == Relation::Kind::in_set || c.kind == Relation::Kind::in_range
                           ? c.members.size()
                           : 1);
        }
        continue;
      }
      bool every = true;
      bool sure_all = true;
      std::string failure;
      const bool explain = f.row_first_failure[r].empty();
      for (const Compare& c : (*conclusions)[r]) {
        std::optional<bool> sure;
        std::string shown;
        const bool holds =
            compare_holds(c, values, p.sides, slot, sure, explain ? &shown : nullptr);
        if (!sure) {
          sure_all = false;
        }
        if (!holds && failure.empty() && explain) {
          failure = c.text + " fails (its sides: " + shown + ")";
        }
        every = every && holds;
      }
      if (!sure_all) {
        continue;
      }
      counted = true;
      ++f.row_tested[r];
      // The point, as text: the model's values, then what the equations before gave.
      const auto point_text = [&] {
        std::string text;
        for (const models::Value& v : point.values) {
          const std::vector<ex> named = symbols_of_name(v.symbol);
          if (std::none_of(named.begin(), named.end(),
                           [&](const ex& x) { return index_of(x).has_value(); })) {
            continue;  // a value the claim does not use
          }
          const SymbolInfo* info = symbols_.info(named[0]);
          const std::string name = info == nullptr ? v.symbol
                                   : info->of      ? info->of->latex()
                                                   : info->name.latex();
          text += (text.empty() ? "" : ", ") + name + " = ";
          text += v.vector ? "[" + shown_number(v.x) + ", " + shown_number(v.y) + "]"
                           : shown_number(v.x);
        }
        // What the equations before gave, by name (their own order follows GiNaC's hashes,
        // which change from run to run).
        // Only those the claim's relations use: the others say nothing of the case.
        std::vector<std::string> solved;
        for (const std::size_t s : p.solved) {
          if (claimed(symbols[s])) {
            solved.push_back(symbol_text(symbols_, symbols[s]) + " = " + shown_number(values[s]));
          }
        }
        for (const auto& [u, solution] : p.shown) {
          if (claimed(u)) {
            solved.push_back(symbol_text(symbols_, u) + " = " +
                             shown_number(solution(values, nullptr)));
          }
        }
        std::sort(solved.begin(), solved.end());
        for (const std::string& s : solved) {
          text += "; " + s;
        }
        return text;
      };
      if (every) {
        ++f.row_satisfied[r];
        if (f.row_witness[r].empty()) {
          f.row_witness[r] = point_text();
        }
      } else {
        ++f.row_failures[r];
        if (f.row_first_failure[r].empty()) {
          f.row_first_failure[r] = point_text() + " gives " + failure;
        }
      }
    }
    (void)exists;
    f.points += counted ? 1U : 0U;
  }
  if (!claim) {
    f.holds = f.points > 0 && f.worst <= model->holds_below;
    f.fails = f.points > 0 && f.worst >= model->fails_above;
    f.detail = std::string(use.method == "numeric" ? "model" : use.method) + ": " + use.name +
               ", " + std::to_string(f.points) + " points, worst relative residual " +
               num::brief(f.worst, 2) +
               (f.holds   ? " (holds)"
                : f.fails ? " (fails)"
                          : " (undecided)");
  }
  return f;
}

// A model that assembles from the coefficients of a check (a_vi = ..., b_v = ...) reads them
// through the probe: each equation of a statement whose left side is a symbol defines it there;
// the statements of the checks above first, then @p own (the check's statement, or its
// correction in that variant). The lets in force stand.
void FileRun::define_for_probe(const Group& g, const std::vector<std::size_t>& own) {
  const std::vector<Equation>& eqs = read_.equations;
  GiNaC::exmap defined;
  const auto define = [&](const std::vector<std::size_t>& equations) {
    for (const std::size_t i : equations) {
      const Equation& e = eqs[i];
      const Value& l = e.lhs.value;
      const Value& r = e.rhs.value;
      if (!e.premise || l.block() || r.block() || l.vector != r.vector) {
        continue;
      }
      const std::vector<std::pair<ex, ex>> sides =
          l.vector ? std::vector<std::pair<ex, ex>>{{l.x, r.x}, {l.y, r.y}}
                   : std::vector<std::pair<ex, ex>>{{l.x, r.x}};
      for (const auto& [name, definition] : sides) {
        if (GiNaC::is_a<GiNaC::symbol>(name)) {
          defined[name] = definition.subs(e.substitutions);
        }
      }
    }
  };
  for (const Group& above : read_.groups) {
    if (above.id == g.id) {
      break;
    }
    define(above.statement_equations);
  }
  define(own);
  for (const auto& [name, definition] : defined) {
    probe_substitutions_.emplace(name, definition);
  }
}

// ---- an equation or a step --------------------------------------------------------------------

FileRun::Variant FileRun::run_variant(const Group& g, bool corrected) {
  Variant out;
  DerivationOptions settings;
  settings.seed = check_seed(options_.seed, g.id) & 0xFFFFFFFFULL;
  Checker checker(symbols_, settings);
  const std::vector<Equation>& eqs = read_.equations;
  const std::vector<std::size_t>& own = corrected ? g.correction_equations : g.statement_equations;
  const std::set<std::size_t> statement(g.statement_equations.begin(), g.statement_equations.end());
  // The evidence's premises in the corrected variant: the statement's equations replaced by the
  // correction's.
  const auto remapped = [&](const std::vector<std::size_t>& premises) {
    std::vector<std::size_t> out_premises;
    for (const std::size_t p : premises) {
      if (corrected && statement.contains(p)) {
        for (const std::size_t c : g.correction_equations) {
          if (std::find(out_premises.begin(), out_premises.end(), c) == out_premises.end()) {
            out_premises.push_back(c);
          }
        }
      } else {
        out_premises.push_back(p);
      }
    }
    return out_premises;
  };
  std::vector<std::pair<std::size_t, std::vector<std::size_t>>> tested;
  for (const std::size_t i : own) {
    tested.emplace_back(i, eqs[i].premises);
  }
  for (const std::size_t i : g.evidence_equations) {
    tested.emplace_back(i, remapped(eqs[i].premises));
  }
  const std::set<std::size_t> tests(g.test_equations.begin(), g.test_equations.end());
  for (const std::size_t i : g.test_equations) {
    tested.emplace_back(i, std::vector<std::size_t>{});
  }
  std::string note;
  for (const auto& [index, premises] : tested) {
    const EquationResult r = checker.check(eqs, index, source_, &premises);
    if (r.verdict == Verdict::premise) {
      continue;
    }
    out.evidence = true;
    if (fails(r.verdict)) {
      (r.verdict == Verdict::undecided ? out.unknown : out.fails) = true;
    }
    if (r.decided_by == "exact" || r.verdict == Verdict::dimensions) {
      out.methods.insert(Method::symbolic);
    }
    if (r.numeric_points > 0) {
      out.methods.insert(Method::numeric);
      out.samples += r.numeric_points;
      out.worst = std::max(out.worst, r.numeric_worst);
    }
    std::string line = "line " + std::to_string(r.line) + " " + std::string(to_string(r.verdict));
    if (r.verdict == Verdict::follows_if) {
      line += " (if " + r.condition_text + ")";
    }
    if (r.verdict == Verdict::does_not_follow && !r.residual_text.empty()) {
      line += " (left over: " + r.residual_text + ")";
    }
    if (r.verdict == Verdict::dimensions) {
      line += " (" + r.dimension_what + ")";
    }
    note += (note.empty() ? "" : "; ") + line;
    out.results.push_back(r);
  }
  // The models: every equation of the check (the statement or its correction, and the
  // evidence), the definitions in force, the equations before them to solve for what a model
  // does not give.
  if (!g.models.empty()) {
    std::vector<Target> targets;
    std::vector<ex> pool;
    // The evidence's own premises are hypotheses (elasticity = 2, say): a model does not hold
    // them, so it tests neither them nor what follows from them.
    std::set<std::size_t> hypotheses;
    for (const std::size_t i : g.evidence_equations) {
      if (eqs[i].premise) {
        hypotheses.insert(i);
      }
    }
    std::set<std::size_t> in_targets;
    for (const auto& [index, premises] : tested) {
      (void)premises;
      in_targets.insert(index);
    }
    Facts facts;
    for (const auto& [index, premises] : tested) {
      const Equation& e = eqs[index];
      if (hypotheses.contains(index) ||
          std::any_of(premises.begin(), premises.end(),
                      [&](std::size_t q) { return hypotheses.contains(q); })) {
        continue;
      }
      facts = e.facts;
      // A premise of the check (a definition it states) solves for what it defines; a test
      // does not (it is what is tested).
      if (e.premise && !tests.contains(index)) {
        for (const ex& d : scalars_of(e, e.substitutions).differences) {
          pool.push_back(d);
        }
      }
      for (const std::size_t p : premises) {
        if (in_targets.contains(p)) {
          continue;
        }
        for (const ex& d : scalars_of(eqs[p], e.substitutions).differences) {
          pool.push_back(d);
        }
      }
      // The target: read with time (integrals, pulses) when a model shapes the force.
      bool instant = false;
      const auto has_differential = [&](const ex& x) {
        for (const ex& s : symbols_of(x)) {
          const SymbolInfo* info = symbols_.info(s);
          if (info != nullptr && info->name.differential) {
            return true;
          }
        }
        return false;
      };
      instant = has_differential(e.lhs.value.x) || has_differential(e.rhs.value.x);
      for_each_scalar(e, [&](const ex& l, const ex& r) {
        const ex left = l.subs(e.substitutions);
        const ex right = r.subs(e.substitutions);
        std::vector<ex> ds;
        for (const ex& d : e.lhs.denominators) {
          ds.push_back(exact_reading(d.subs(e.substitutions)));
        }
        for (const ex& d : e.rhs.denominators) {
          ds.push_back(exact_reading(d.subs(e.substitutions)));
        }
        targets.push_back({left, right, ds, instant, e.latex});
      });
    }
    // Targets that are premises of the check are tested unless they solve for a symbol: the
    // matching in run_model decides; here, the statement's premises also stand in the pool.
    probe_substitutions_ =
        tested.empty() ? GiNaC::exmap{} : eqs[tested.front().first].substitutions;
    define_for_probe(g, own);
    for (const ModelUse& use : g.models) {
      // A non-quadrature model reads the equations exactly (forces constant over the contact).
      const models::Model* model = models::find(use.method, use.name);
      std::vector<Target> read_targets = targets;
      if (model != nullptr && !model->draws_the_rest) {
        for (Target& t : read_targets) {
          t.left = exact_reading(t.left);
          t.right = exact_reading(t.right);
          t.instant = false;
        }
      }
      // Premise equations that solve for a symbol are not tested: keep only targets that are not
      // in the pool (a given block whose symbols the model sets entirely is tested).
      ModelFinding found = run_model(use, read_targets, pool, facts, g);
      out.methods.insert(found.method);
      out.samples += found.points;
      out.worst = std::max(out.worst, found.worst);
      if (found.fails) {
        out.fails = true;
      } else if (!found.holds) {
        out.unknown = true;
      }
      out.evidence = out.evidence || found.points > 0;
      note += (note.empty() ? "" : "; ") + found.detail;
      out.models.push_back(std::move(found));
    }
  }
  out.note = note;
  return out;
}

Result FileRun::check(const Group& g) {
  Result r;
  r.check.id = g.id;
  r.check.section = g.section;
  r.check.equation = g.label;
  r.check.kind = g.kind;
  r.check.statement = g.statement;
  const auto trim = [](std::string& s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\n')) {
      s.pop_back();
    }
    while (!s.empty() && (s.front() == ' ' || s.front() == '\n')) {
      s.erase(s.begin());
    }
  };
  trim(r.check.statement);
  r.check.line = source_.place(g.statement_offset).line;
  const auto begin = std::chrono::steady_clock::now();
  if (g.kind == Kind::claim) {
    r = check_claim(g, std::move(r));
  } else {
    const Variant printed = run_variant(g, false);
    Outcome& o = r.outcome;
    o.methods.assign(printed.methods.begin(), printed.methods.end());
    // Two significant digits, as the note and the text report show it: the digits after them
    // are rounding, and they change from run to run with the order GiNaC gives a sum's terms.
    o.max_relative_error = printed.samples > 0
                               ? std::optional<double>(std::stod(num::brief(printed.worst, 2)))
                               : std::nullopt;
    o.samples = printed.samples > 0 ? std::optional<std::size_t>(printed.samples) : std::nullopt;
    o.note = "As printed: " + printed.note + ".";
    const bool printed_holds = printed.evidence && !printed.fails && !printed.unknown;
    if (g.correction_equations.empty()) {
      o.status = printed_holds ? Status::verified : Status::failed;
      if (!printed.evidence) {
        o.explanation = "Nothing tested the statement: it is a premise and no model evaluates it.";
      } else if (!printed_holds) {
        o.explanation = "The statement as printed does not pass: " + printed.note;
      }
    } else {
      const Variant corrected = run_variant(g, true);
      std::string correction = g.correction;
      trim(correction);
      o.correction = correction;
      o.explanation = g.explanation;
      o.note += " Corrected: " + corrected.note + ".";
      for (const Method m : corrected.methods) {
        if (std::find(o.methods.begin(), o.methods.end(), m) == o.methods.end()) {
          o.methods.push_back(m);
        }
      }
      std::sort(o.methods.begin(), o.methods.end());
      const bool corrected_holds = corrected.evidence && !corrected.fails && !corrected.unknown;
      o.status =
          printed.fails && !printed.unknown && corrected_holds ? Status::erratum : Status::failed;
      if (o.status == Status::failed) {
        o.explanation = std::string(!printed.fails ? "The print was not shown to fail"
                                                   : "The correction was not shown to hold") +
                        " (" + (printed.fails ? corrected.note : printed.note) + ").";
      }
    }
  }
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - begin;
  r.seconds = took.count();
  return r;
}

// ---- a claim ------------------------------------------------------------------------------------

Result FileRun::check_claim(const Group& g, Result r) {
  Outcome& o = r.outcome;
  const std::vector<Equation>& eqs = read_.equations;
  const GiNaC::exmap& lets = g.claim_substitutions;
  std::vector<ex> premises;
  std::vector<ex> premise_denominators;
  for (const std::size_t p : g.claim_premises) {
    const Scalars s = scalars_of(eqs[p], lets);
    premises.insert(premises.end(), s.differences.begin(), s.differences.end());
    premise_denominators.insert(premise_denominators.end(), s.denominators.begin(),
                                s.denominators.end());
  }
  const auto value_of = [&](const Side& side, std::size_t at) {
    const Meaning m = symbols_.meaning(side.expression);
    if (m.value.vector || m.value.block()) {
      throw source_.error(at, "expected numbers on both sides of this relation of the claim");
    }
    return exact_reading(m.value.x.subs(lets));
  };
  const auto side_value = [&](const Side& side) { return symbols_.meaning(side.expression).value; };
  const auto relation_text = [](const Relation& rel) {
    std::string text = rel.left.latex;
    switch (rel.kind) {
      case Relation::Kind::equal:
        return text + " = " + rel.right.latex;
      case Relation::Kind::not_equal:
        return text + " \\neq " + rel.right.latex;
      case Relation::Kind::less:
        return text + " < " + rel.right.latex;
      case Relation::Kind::greater:
        return text + " > " + rel.right.latex;
      case Relation::Kind::less_equal:
        return text + " \\leq " + rel.right.latex;
      case Relation::Kind::greater_equal:
        return text + " \\geq " + rel.right.latex;
      default:
        return text + " \\in …";
    }
  };
  // A relation as compares of numbers: a vector equation is one per component.
  std::function<std::vector<Compare>(const Relation&)> compare;
  compare = [&](const Relation& rel) {
    std::vector<Compare> out;
    // A relation whose symbols carry a free index (a_{vi(elastic)} = a_{vi(inelastic)}) stands
    // for one relation per value, as a row of equations does.
    std::vector<std::string> free = symbols_.free_indices(rel.left.expression);
    if (rel.kind != Relation::Kind::in_set && rel.kind != Relation::Kind::in_range) {
      for (const std::string& letter : symbols_.free_indices(rel.right.expression)) {
        if (std::find(free.begin(), free.end(), letter) == free.end()) {
          free.push_back(letter);
        }
      }
    }
    if (!free.empty()) {
      for (const long value : symbols_.indices().at(free.front())) {
        Relation one = rel;
        one.left.expression = with_index(rel.left.expression, free.front(), value);
        one.right.expression = with_index(rel.right.expression, free.front(), value);
        for (Compare& c : compare(one)) {
          out.push_back(std::move(c));
        }
      }
      return out;
    }
    const Value left = side_value(rel.left);
    if (left.block()) {
      throw source_.error(rel.offset, "expected numbers or vectors in a claim's relation");
    }
    if (left.vector) {
      const Value right = side_value(rel.right);
      if (!right.vector ||
          (rel.kind != Relation::Kind::equal && rel.kind != Relation::Kind::not_equal)) {
        throw source_.error(rel.offset, "expected a vector compared with a vector by = only");
      }
      for (int k = 0; k < 2; ++k) {
        Compare c;
        c.kind = rel.kind;
        c.left = exact_reading((k == 0 ? left.x : left.y).subs(lets));
        c.right = exact_reading((k == 0 ? right.x : right.y).subs(lets));
        c.scale = term_scale(c.left) + term_scale(c.right);
        c.text = relation_text(rel) + (k == 0 ? " (x)" : " (y)");
        out.push_back(std::move(c));
      }
      return out;
    }
    Compare c;
    c.kind = rel.kind;
    c.left = value_of(rel.left, rel.offset);
    c.scale = term_scale(c.left);
    if (rel.kind == Relation::Kind::in_set) {
      for (const Side& m : rel.members) {
        c.members.push_back(value_of(m, rel.offset));
      }
    } else if (rel.kind == Relation::Kind::in_range) {
      if (rel.low) {
        c.members.push_back(value_of(*rel.low, rel.offset));
        c.has_low = true;
      }
      if (rel.high) {
        c.members.push_back(value_of(*rel.high, rel.offset));
        c.has_high = true;
      }
      c.low_closed = rel.low_closed;
      c.high_closed = rel.high_closed;
    } else {
      c.right = value_of(rel.right, rel.offset);
      c.scale += term_scale(c.right);
    }
    c.text = relation_text(rel);
    out.push_back(std::move(c));
    return out;
  };
  std::vector<std::vector<Compare>> hypotheses, conclusions;
  std::vector<bool> exists;
  for (const ClaimRow& row : g.rows) {
    std::vector<Compare> h, c;
    for (const Relation& rel : row.hypotheses) {
      for (Compare& x : compare(rel)) {
        h.push_back(std::move(x));
      }
    }
    for (const Relation& rel : row.conclusions) {
      for (Compare& x : compare(rel)) {
        c.push_back(std::move(x));
      }
    }
    hypotheses.push_back(std::move(h));
    conclusions.push_back(std::move(c));
    exists.push_back(row.exists);
  }
  // The exact method on each row: equalities from the premises and the hypotheses (when these
  // are equalities); a sign from the facts.
  enum class Exact { none, holds, fails, unknown };
  std::vector<Exact> exact(g.rows.size(), Exact::none);
  std::vector<std::string> exact_point(g.rows.size());
  std::string note;
  for (std::size_t k = 0; k < g.rows.size(); ++k) {
    if (exists[k]) {
      continue;
    }
    const bool equal_hypotheses =
        std::all_of(hypotheses[k].begin(), hypotheses[k].end(),
                    [](const Compare& c) { return c.kind == Relation::Kind::equal; });
    Exact row = Exact::holds;
    for (const Compare& c : conclusions[k]) {
      Exact one = Exact::none;
      if (c.kind == Relation::Kind::equal && equal_hypotheses) {
        std::vector<ex> given = premises;
        for (const Compare& h : hypotheses[k]) {
          given.push_back(h.left - h.right);
        }
        const Implication imp =
            implies({given, premise_denominators, c.left - c.right, {}}, g.claim_facts);
        using O = Implication::Outcome;
        one = imp.outcome == O::holds || imp.outcome == O::holds_if ? Exact::holds
              : imp.outcome == O::fails                             ? Exact::fails
                                                                    : Exact::unknown;
        if (imp.outcome == O::fails && imp.point) {
          std::string text;
          for (const auto& [s, v] : *imp.point) {
            std::ostringstream value;
            value << v;
            text += (text.empty() ? "" : ", ") + symbol_text(symbols_, s) + " = " + value.str();
          }
          exact_point[k] = text + " (exact)";
        }
      } else if (hypotheses[k].empty() &&
                 (c.kind == Relation::Kind::greater_equal || c.kind == Relation::Kind::greater ||
                  c.kind == Relation::Kind::less_equal || c.kind == Relation::Kind::less ||
                  c.kind == Relation::Kind::not_equal)) {
        const bool upward =
            c.kind == Relation::Kind::greater_equal || c.kind == Relation::Kind::greater;
        const Sign s = g.claim_facts.sign(
            upward || c.kind == Relation::Kind::not_equal ? c.left - c.right : c.right - c.left);
        const bool shown = c.kind == Relation::Kind::not_equal
                               ? (s == Sign::positive || s == Sign::negative || s == Sign::nonzero)
                           : (c.kind == Relation::Kind::greater || c.kind == Relation::Kind::less)
                               ? s == Sign::positive
                               : (s == Sign::positive || s == Sign::nonnegative || s == Sign::zero);
        one = shown ? Exact::holds : Exact::none;
      }
      // A claim that names models is about the values they give (energies after, an equal
      // impulse found by a search): algebra alone that does not prove it decides nothing.
      if (one == Exact::fails && !g.models.empty()) {
        one = Exact::none;
      }
      if (one == Exact::none) {
        row = row == Exact::holds ? Exact::none : row;
        continue;
      }
      if (one == Exact::fails) {
        row = Exact::fails;
      } else if (one == Exact::unknown && row != Exact::fails) {
        row = Exact::unknown;
      }
    }
    exact[k] = row;
    if (row != Exact::none) {
      o.methods.push_back(Method::symbolic);
    }
  }
  // The searches.
  std::vector<ModelFinding> found;
  for (const ModelUse& use : g.models) {
    probe_substitutions_ = lets;
    define_for_probe(g, {});
    found.push_back(
        run_model(use, {}, premises, g.claim_facts, g, &hypotheses, &conclusions, &exists));
    o.methods.push_back(found.back().method);
  }
  std::sort(o.methods.begin(), o.methods.end());
  o.methods.erase(std::unique(o.methods.begin(), o.methods.end()), o.methods.end());
  bool refuted = false;
  bool failed = false;
  std::size_t samples = 0;
  for (std::size_t k = 0; k < g.rows.size(); ++k) {
    std::size_t tested = 0, failures = 0, satisfied = 0;
    std::string first_failure, witness;
    for (const ModelFinding& f : found) {
      tested += f.row_tested[k];
      failures += f.row_failures[k];
      satisfied += f.row_satisfied[k];
      if (first_failure.empty()) {
        first_failure = f.row_first_failure[k];
      }
      if (witness.empty()) {
        witness = f.row_witness[k];
      }
    }
    samples += tested;
    std::string line = "row " + std::to_string(k + 1) + ": ";
    if (exists[k]) {
      if (satisfied > 0) {
        line += "a case satisfies it (" + witness + ")";
      } else if (tested > 0) {
        refuted = true;
        line += "no case of " + std::to_string(tested) + " satisfies it";
        if (o.counterexample.empty()) {
          o.counterexample = "none of " + std::to_string(tested) + " cases searched satisfies " +
                             g.rows[k].latex +
                             (first_failure.empty() ? "" : "; e.g. " + first_failure);
        }
      } else {
        failed = true;
        line += "nothing was searched";
      }
    } else if (exact[k] == Exact::fails) {
      refuted = true;
      line += "fails exactly";
      if (o.counterexample.empty()) {
        o.counterexample = exact_point[k].empty() ? first_failure : exact_point[k];
      }
    } else if (failures > 0) {
      if (exact[k] == Exact::holds) {
        failed = true;
        line += "proven exactly, yet a case fails (" + first_failure + ")";
      } else {
        refuted = true;
        line += std::to_string(failures) + " of " + std::to_string(tested) + " cases fail";
        if (o.counterexample.empty()) {
          o.counterexample = first_failure;
        }
      }
    } else if (exact[k] == Exact::holds) {
      line += "holds exactly" +
              (tested > 0 ? ", and on " + std::to_string(tested) + " cases searched" : "");
    } else if (tested > 0 && exact[k] != Exact::unknown) {
      line += "holds on " + std::to_string(tested) + " cases searched";
    } else {
      failed = true;
      line += "undecided";
    }
    note += (note.empty() ? "" : "; ") + line;
  }
  o.samples = samples > 0 ? std::optional<std::size_t>(samples) : std::nullopt;
  o.note = note + ".";
  o.counterexample = plain(o.counterexample);
  if (failed) {
    o.status = Status::failed;
    o.explanation = "The claim could not be decided: " + note + ".";
  } else if (refuted && g.explanation.empty()) {
    o.status = Status::failed;
    o.explanation =
        "The claim does not hold and the file does not say why (explanation:): " + note + ".";
  } else if (refuted) {
    o.status = Status::refuted;
    o.explanation = g.explanation;
  } else {
    o.status = Status::verified;
  }
  return r;
}

// ---- the files ----------------------------------------------------------------------------------

// An error in a paper file, as a compiler prints it: derivations/paper/FILE:LINE:COLUMN: what
// (a file beyond the paper is named beyond/FILE, in derivations/beyond/).
DerivationError placed(const PaperFile& file, Place place, const std::string& what) {
  const std::string folder =
      file.name.find('/') == std::string::npos ? "derivations/paper/" : "derivations/";
  return DerivationError(place.line, place.column,
                         folder + file.name + ":" + std::to_string(place.line) + ":" +
                             std::to_string(place.column) + ": " + what);
}

struct ReadPaper {
  std::unique_ptr<Limits> limits;  // the reader and its symbols keep references to these
  std::unique_ptr<Source> source;
  std::unique_ptr<Reader> reader;
  ReadFile read;
};

ReadPaper read_paper(const PaperFile& file) {
  ReadPaper p;
  p.limits = std::make_unique<Limits>();
  p.limits->bytes = max_derivation_bytes;
  try {
    p.source = std::make_unique<Source>(file.text, *p.limits);
    p.reader = std::make_unique<Reader>(*p.source, *p.limits);
    p.read = p.reader->read();
  } catch (const ReadError& e) {
    throw placed(file, e.place(), e.what());
  }
  return p;
}

// Counts a result in the summary and appends it.
void add(Report& report, Result result) {
  switch (result.outcome.status) {
    case Status::verified:
      ++report.summary.verified;
      break;
    case Status::erratum:
      ++report.summary.erratum;
      break;
    case Status::refuted:
      ++report.summary.refuted;
      break;
    case Status::failed:
      ++report.summary.failed;
      break;
  }
  report.results.push_back(std::move(result));
}

// The checks of some files, as their files state them.
std::vector<Check> checks_of(const std::vector<PaperFile>& files) {
  std::vector<Check> checks;
  for (const PaperFile& file : files) {
    const ReadPaper p = read_paper(file);
    for (const Group& g : p.read.groups) {
      std::string statement = g.statement;
      while (!statement.empty() && (statement.back() == ' ' || statement.back() == '\n')) {
        statement.pop_back();
      }
      while (!statement.empty() && (statement.front() == ' ' || statement.front() == '\n')) {
        statement.erase(statement.begin());
      }
      checks.push_back({g.id, g.section, g.label, g.kind, statement, file.name,
                        p.source->place(g.statement_offset).line});
    }
  }
  return checks;
}

}  // namespace

std::vector<Check> beyond_checks() {
  return checks_of(beyond_files());
}

std::vector<Check> all_checks() {
  return checks_of(paper_files());
}

Report run(const std::vector<PaperFile>& files, const Options& options, std::string_view only) {
  num::quiet_gsl();
  const impulse::detail::HeldFloatingPointExceptions held;
  Report report;
  report.options = options;
  const auto start = std::chrono::steady_clock::now();
  std::set<std::string> ids;
  for (const PaperFile& file : files) {
    ReadPaper p = read_paper(file);
    FileRun run_file(*p.source, p.read, p.reader->symbols(), options);
    for (const Group& g : p.read.groups) {
      if (!ids.insert(g.id).second) {
        throw placed(file, p.source->place(g.offset),
                     "expected a new id, found " + g.id + " that another file already has");
      }
      if (!in_section(g.section, options.section) || (!only.empty() && g.id != only)) {
        continue;
      }
      Result result;
      try {
        result = run_file.check(g);
      } catch (const ReadError& e) {
        throw placed(file, e.place(), e.what());
      }
      result.check.file = file.name;
      add(report, std::move(result));
    }
  }
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  report.seconds = took.count();
  return report;
}

Report run(const Options& options) {
  Report report = run(paper_files(), options);
  // Beyond the paper: the same engine on our own files, counted apart.
  Report beyond = run(beyond_files(), options);
  report.beyond = {std::move(beyond.results), beyond.summary, beyond.seconds};
  return report;
}

}  // namespace impulse::derivations
