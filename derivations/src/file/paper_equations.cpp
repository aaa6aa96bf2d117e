// SPDX-License-Identifier: GPL-3.0-or-later
// The equation runner: an equation or a step of a paper file, as printed and, for an erratum, as
// corrected. Each variant is its own equations decided from the equations before, its evidence
// decided from it, and its statements evaluated by every model the check names.
#include <algorithm>
#include <set>

#include "file/decide.hpp"
#include "file/paper.hpp"
#include "file/step.hpp"
#include "file/text.hpp"
#include "file/time.hpp"
#include "numeric.hpp"

namespace impulse::derivations::paper {

namespace {

using file::Equation;

// What one variant of a check found.
struct Variant {
  bool fails = false;
  bool unknown = false;
  bool evidence = false;  // something tested it
  double worst = 0.0;
  std::size_t samples = 0;
  std::set<Method> methods;
  std::string note;

  [[nodiscard]] bool holds() const { return evidence && !fails && !unknown; }
};

// An equation of the variant and the equations it must follow from.
using Tested = std::vector<std::pair<std::size_t, std::vector<std::size_t>>>;

// The variant's equations: its own (the statement, or the correction), the evidence (whose
// premises in the corrected variant are the correction's equations instead of the statement's)
// and what its models test besides.
Tested tested_equations(const std::vector<Equation>& eqs, const file::Group& g, bool corrected) {
  const std::set<std::size_t> statement(g.statement_equations.begin(), g.statement_equations.end());
  Tested tested;
  for (const std::size_t i : corrected ? g.correction_equations : g.statement_equations) {
    tested.emplace_back(i, eqs[i].premises);
  }
  for (const std::size_t i : g.evidence_equations) {
    std::vector<std::size_t> premises;
    for (const std::size_t p : eqs[i].premises) {
      if (!corrected || !statement.contains(p)) {
        premises.push_back(p);
        continue;
      }
      for (const std::size_t c : g.correction_equations) {
        if (std::find(premises.begin(), premises.end(), c) == premises.end()) {
          premises.push_back(c);
        }
      }
    }
    tested.emplace_back(i, premises);
  }
  for (const std::size_t i : g.test_equations) {
    tested.emplace_back(i, std::vector<std::size_t>{});
  }
  return tested;
}

// Each equation decided from its premises, exactly and numerically (file::Checker).
void decide(FileRun& run, const file::Group& g, const Tested& tested, Variant& out) {
  DerivationOptions settings;
  settings.seed = check_seed(run.options.seed, g.id) & 0xFFFFFFFFULL;
  file::Checker checker(run.symbols, settings);
  for (const auto& [index, premises] : tested) {
    const EquationResult r = checker.check(run.read.equations, index, run.source, &premises);
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
    out.note += (out.note.empty() ? "" : "; ") + line;
  }
}

bool has_differential(file::Symbols& symbols, const ex& x) {
  for (const ex& s : file::symbols_of(x)) {
    const file::SymbolInfo* info = symbols.info(s);
    if (info != nullptr && info->name.differential) {
      return true;
    }
  }
  return false;
}

// What the models evaluate: every equation of the variant but the evidence's hypotheses (its
// own premises, elasticity = 2 say, which a model does not hold) and what follows from them; the
// equations that solve for what a model does not give (the check's own premises that are not
// tests, and the premises of each); the facts in force.
struct ModelInput {
  std::vector<Target> targets;
  std::vector<ex> pool;
  file::Facts facts;
};

ModelInput model_input(FileRun& run, const file::Group& g, const Tested& tested) {
  const std::vector<Equation>& eqs = run.read.equations;
  std::set<std::size_t> hypotheses;
  for (const std::size_t i : g.evidence_equations) {
    if (eqs[i].premise) {
      hypotheses.insert(i);
    }
  }
  std::set<std::size_t> in_targets;
  for (const auto& entry : tested) {
    in_targets.insert(entry.first);
  }
  const std::set<std::size_t> tests(g.test_equations.begin(), g.test_equations.end());
  ModelInput in;
  for (const auto& [index, premises] : tested) {
    const Equation& e = eqs[index];
    if (hypotheses.contains(index) || std::any_of(premises.begin(), premises.end(),
                                                  [&](auto q) { return hypotheses.contains(q); })) {
      continue;
    }
    in.facts = e.facts;
    if (e.premise && !tests.contains(index)) {
      for (const ex& d : file::scalars_of(e, e.substitutions).differences) {
        in.pool.push_back(d);
      }
    }
    for (const std::size_t p : premises) {
      if (!in_targets.contains(p)) {
        for (const ex& d : file::scalars_of(eqs[p], e.substitutions).differences) {
          in.pool.push_back(d);
        }
      }
    }
    // The target: read with time (integrals, pulses) when a model shapes the force.
    const bool instant = has_differential(run.symbols, e.lhs.value.x) ||
                         has_differential(run.symbols, e.rhs.value.x);
    file::for_each_scalar(e, [&](const ex& l, const ex& r) {
      std::vector<ex> ds;
      for (const auto* side : {&e.lhs, &e.rhs}) {
        for (const ex& d : side->denominators) {
          ds.push_back(file::exact_reading(d.subs(e.substitutions)));
        }
      }
      in.targets.push_back(
          {l.subs(e.substitutions), r.subs(e.substitutions), ds, instant, e.latex});
    });
  }
  return in;
}

// The models the check names, on every equation of the variant and the definitions in force.
void evaluate_models(FileRun& run, const file::Group& g, const Tested& tested,
                     const std::vector<std::size_t>& own, Variant& out) {
  const ModelInput in = model_input(run, g, tested);
  run.define_for_probe(
      g, own,
      tested.empty() ? GiNaC::exmap{} : run.read.equations[tested.front().first].substitutions);
  for (const file::ModelUse& use : g.models) {
    // A model that does not shape the force reads the equations exactly (forces constant over
    // the contact).
    std::vector<Target> targets = in.targets;
    if (!model_named(run, use).draws_the_rest) {
      for (Target& t : targets) {
        t.left = file::exact_reading(t.left);
        t.right = file::exact_reading(t.right);
        t.instant = false;
      }
    }
    const EquationFinding found = evaluate(run, use, targets, in.pool, in.facts, g);
    out.methods.insert(found.method);
    out.samples += found.points;
    out.worst = std::max(out.worst, found.worst);
    if (found.fails) {
      out.fails = true;
    } else if (!found.holds) {
      out.unknown = true;
    }
    out.evidence = out.evidence || found.points > 0;
    out.note += (out.note.empty() ? "" : "; ") + found.detail;
  }
}

Variant run_variant(FileRun& run, const file::Group& g, bool corrected) {
  Variant out;
  const Tested tested = tested_equations(run.read.equations, g, corrected);
  decide(run, g, tested, out);
  if (!g.models.empty()) {
    evaluate_models(run, g, tested, corrected ? g.correction_equations : g.statement_equations,
                    out);
  }
  return out;
}

}  // namespace

Result check_equation(FileRun& run, const file::Group& g, Result r) {
  const Variant printed = run_variant(run, g, false);
  Outcome& o = r.outcome;
  o.methods.assign(printed.methods.begin(), printed.methods.end());
  // Two significant digits, as the note and the text report show it: the digits after them are
  // rounding, and they change from run to run with the order GiNaC gives a sum's terms.
  o.max_relative_error = printed.samples > 0
                             ? std::optional<double>(std::stod(num::brief(printed.worst, 2)))
                             : std::nullopt;
  o.samples = printed.samples > 0 ? std::optional<std::size_t>(printed.samples) : std::nullopt;
  o.note = "As printed: " + printed.note + ".";
  if (g.correction_equations.empty()) {
    o.status = printed.holds() ? Status::verified : Status::failed;
    if (!printed.evidence) {
      o.explanation = "Nothing tested the statement: it is a premise and no model evaluates it.";
    } else if (!printed.holds()) {
      o.explanation = "The statement as printed does not pass: " + printed.note;
    }
    return r;
  }
  const Variant corrected = run_variant(run, g, true);
  o.correction = file::trimmed(g.correction);
  o.explanation = g.explanation;
  o.note += " Corrected: " + corrected.note + ".";
  for (const Method m : corrected.methods) {
    if (std::find(o.methods.begin(), o.methods.end(), m) == o.methods.end()) {
      o.methods.push_back(m);
    }
  }
  std::sort(o.methods.begin(), o.methods.end());
  o.status =
      printed.fails && !printed.unknown && corrected.holds() ? Status::erratum : Status::failed;
  if (o.status == Status::failed) {
    o.explanation = std::string(!printed.fails ? "The print was not shown to fail"
                                               : "The correction was not shown to hold") +
                    " (" + (printed.fails ? corrected.note : printed.note) + ").";
  }
  return r;
}

}  // namespace impulse::derivations::paper
