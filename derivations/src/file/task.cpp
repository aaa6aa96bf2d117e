// SPDX-License-Identifier: GPL-3.0-or-later
// A submission checked against a lecturer's task: the task file's premises (after given:) and
// target (after target:) read in the task's own symbols, carried over by name into the
// submission's, and then: each premise the submission states must follow from the task's, and
// one of its steps must be equivalent to the target under the task's facts.
#include "file/task.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "file/decide.hpp"
#include "file/step.hpp"
#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;

namespace {

// Expressions of one file's symbols written in another's: each symbol by its name (a component
// of a vector by the vector's name and the component).
class Translator {
 public:
  Translator(const Symbols& from, Symbols& to) : from_(from), to_(to) {}

  ex operator()(const ex& e) {
    GiNaC::exmap map;
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      if (!GiNaC::is_a<GiNaC::symbol>(*i) || map.count(*i) != 0) {
        continue;
      }
      const SymbolInfo* info = from_.info(*i);
      if (info == nullptr) {
        continue;  // a symbol of the engine's own (a pulse's duration)
      }
      if (info->of) {
        const Value v = to_.value_of(*info->of);
        map[*i] = info->component == 0 ? v.x : v.y;
      } else {
        const Value v = to_.value_of(info->name);
        map[*i] = v.vector ? ex(*i) : v.x;
      }
    }
    return map.empty() ? e : e.subs(map, GiNaC::subs_options::no_pattern);
  }

  Value operator()(const Value& v) {
    Value out = v;
    out.x = (*this)(v.x);
    out.y = (*this)(v.y);
    for (ex& entry : out.entries) {
      entry = (*this)(entry);
    }
    return out;
  }

  // An equation with its definitions put in, in the other file's symbols.
  Equation operator()(const Equation& e) {
    Equation out = e;
    const auto defined = [&](const Meaning& m) {
      Meaning copy = m;
      copy.value.x = m.value.x.subs(e.substitutions);
      copy.value.y = m.value.y.subs(e.substitutions);
      for (ex& entry : copy.value.entries) {
        entry = entry.subs(e.substitutions);
      }
      for (ex& d : copy.denominators) {
        d = (*this)(d.subs(e.substitutions));
      }
      copy.value = (*this)(copy.value);
      return copy;
    };
    out.lhs = defined(e.lhs);
    out.rhs = defined(e.rhs);
    out.substitutions.clear();
    out.premises.clear();
    return out;
  }

  Facts operator()(const Facts& facts) {
    Facts out;
    for (const auto& [symbol, sign] : facts.all()) {
      (void)out.add((*this)(symbol), sign);
    }
    for (const auto& [relation, sign] : facts.relations()) {
      out.add_relation((*this)(relation), sign);
    }
    for (const ex& q : facts.equalities()) {
      out.add_equality((*this)(q));
    }
    return out;
  }

 private:
  const Symbols& from_;
  Symbols& to_;
};

// An equation of the submission with its definitions put in.
Equation defined(const Equation& e) {
  Equation out = e;
  const auto put = [&](Value& v) {
    v.x = v.x.subs(e.substitutions);
    v.y = v.y.subs(e.substitutions);
    for (ex& entry : v.entries) {
      entry = entry.subs(e.substitutions);
    }
  };
  put(out.lhs.value);
  put(out.rhs.value);
  for (ex& d : out.lhs.denominators) {
    d = d.subs(e.substitutions);
  }
  for (ex& d : out.rhs.denominators) {
    d = d.subs(e.substitutions);
  }
  out.substitutions.clear();
  return out;
}

// What a submission assumes of its own at an equation, beyond the task: a fact the task's facts
// do not give (assume: v > 0 where the task has none on v; assume: L = 2), or a definition of a
// symbol the task uses (let: L = 2, let: A = 4/m), which puts a value in for one of the task's
// quantities. A definition of a name of its own is an abbreviation, not a premise. Each is
// written once into @p seen; true when the equation brings a new one.
bool assumes_more(const Equation& e, const Facts& task, const std::set<ex, GiNaC::ex_is_less>& used,
                  std::set<std::string>& seen) {
  bool more = false;
  const auto note = [&](const std::string& what) { more = seen.insert(what).second || more; };
  for (const auto& [symbol, sign] : e.facts.all()) {
    if (!gives(task.sign(symbol), sign)) {
      note(relation_latex(sym::latex(symbol), sign));
    }
  }
  for (const auto& [relation, sign] : e.facts.relations()) {
    if (!gives(task.sign(relation), sign)) {
      note(relation_latex(sym::latex(relation), sign));
    }
  }
  for (const ex& q : e.facts.equalities()) {
    const bool given = std::any_of(task.equalities().begin(), task.equalities().end(),
                                   [&](const ex& t) { return GiNaC::normal(t - q).is_zero(); });
    if (!given) {
      note(sym::latex(q) + " = 0");
    }
  }
  for (const auto& [symbol, value] : e.substitutions) {
    if (used.contains(symbol)) {
      note(sym::latex(symbol) + " := " + sym::latex(value));
    }
  }
  return more;
}

bool passing(Verdict v) {
  return v == Verdict::follows || v == Verdict::follows_one_way || v == Verdict::follows_if ||
         v == Verdict::premise;
}

}  // namespace

TaskResult judge_task(const Task& task, const std::vector<Equation>& equations, Symbols& symbols,
                      Checker& checker, const DerivationReport& report,
                      const DerivationOptions& options) {
  Limits limits;
  limits.bytes = max_derivation_bytes;
  TaskResult result;
  result.task = task.file;
  try {
    const Source source(task.text, limits);
    Reader reader(source, limits);
    const ReadFile read = reader.read();
    if (read.targets.empty()) {
      throw source.error(source.text().size(),
                         "expected target: and the target's display equation in a task file");
    }
    Translator into(reader.symbols(), symbols);
    std::vector<Equation> premises;
    for (const Equation& e : read.equations) {
      if (e.premise && e.group == static_cast<std::size_t>(-1)) {
        premises.push_back(into(e));
      }
    }
    const Equation target = into(read.targets.front());
    const Facts facts = into(read.targets.front().facts);
    result.target = read.targets.front().latex;
    std::vector<const Equation*> given;
    for (const Equation& p : premises) {
      given.push_back(&p);
    }
    // The symbols of the task's premises, target and facts, in the submission's.
    std::set<ex, GiNaC::ex_is_less> used;
    std::vector<ex> written;
    for (const Equation* p : given) {
      written.insert(written.end(),
                     {p->lhs.value.x, p->lhs.value.y, p->rhs.value.x, p->rhs.value.y});
    }
    written.insert(written.end(), {target.lhs.value.x, target.lhs.value.y, target.rhs.value.x,
                                   target.rhs.value.y});
    for (const auto& [symbol, sign] : facts.all()) {
      written.push_back(symbol);
    }
    for (const ex& x : symbols_of(written)) {
      used.insert(x);
    }
    std::set<std::string> seen;
    const double seconds = options.step_seconds;
    bool assumed = false;
    bool broken = false;  // a step before the target that does not pass
    for (std::size_t i = 0; i < equations.size(); ++i) {
      const EquationResult& r = report.equations[i];
      if (assumes_more(equations[i], facts, used, seen)) {
        result.extra_premises.push_back(r.line);  // a fact or definition of its own, in force here
      }
      const Equation e = defined(equations[i]);
      if (e.premise) {
        // One of the task's premises; else the target stated as a premise (assumed, not
        // derived, though it follows); else it must follow from the task's premises.
        // (one of the task's: written as the task writes it, spacing aside)
        const auto bare = [](std::string latex) {
          latex.erase(std::remove_if(latex.begin(), latex.end(),
                                     [](char c) { return c == ' ' || c == '\n' || c == '\t'; }),
                      latex.end());
          return latex;
        };
        const bool the_tasks = std::any_of(given.begin(), given.end(), [&](const Equation* g) {
          return bare(g->latex) == bare(e.latex);
        });
        if (the_tasks) {
          continue;
        }
        if (checker.follows({&e}, target, facts, seconds, true)) {
          result.extra_premises.push_back(r.line);
          assumed = true;
        } else if (!checker.follows(given, e, facts, seconds, false)) {
          result.extra_premises.push_back(r.line);
        }
        continue;
      }
      if (!result.line && checker.follows({&e}, target, facts, seconds, true)) {
        result.line = r.line;
        broken = broken || !passing(r.verdict);
      } else if (!result.line) {
        broken = broken || !passing(r.verdict);
      }
    }
    result.target_reached = result.line && result.extra_premises.empty() && !broken;
    result.reason = result.target_reached            ? "reached"
                    : assumed                        ? "target-assumed"
                    : !result.extra_premises.empty() ? "extra-premise"
                    : result.line                    ? "step-fails"
                                                     : "not-reached";
    if (!result.target_reached) {
      result.line.reset();
    }
  } catch (const ReadError& e) {
    throw TaskError(e.place().line, e.place().column, e.what());
  }
  return result;
}

}  // namespace impulse::derivations::file
