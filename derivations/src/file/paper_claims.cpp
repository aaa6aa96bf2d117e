// SPDX-License-Identifier: GPL-3.0-or-later
// The claim runner: a claim of a paper file, row by row. A row is decided exactly where algebra
// can (its equalities from the premises and its hypotheses, a sign from the facts) and on the
// cases the claim's models produce; it holds, fails with a counterexample, or stays undecided.
#include <algorithm>
#include <sstream>

#include "file/decide.hpp"
#include "file/paper.hpp"
#include "file/sample.hpp"
#include "file/step.hpp"
#include "file/time.hpp"

namespace impulse::derivations::paper {

namespace {

using file::Relation;

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

std::string relation_text(const Relation& rel) {
  static const std::pair<Relation::Kind, std::string_view> signs[] = {
      {Relation::Kind::equal, " = "},          {Relation::Kind::not_equal, " \\neq "},
      {Relation::Kind::less, " < "},           {Relation::Kind::greater, " > "},
      {Relation::Kind::less_equal, " \\leq "}, {Relation::Kind::greater_equal, " \\geq "}};
  for (const auto& [kind, sign] : signs) {
    if (rel.kind == kind) {
      return rel.left.latex + std::string(sign) + rel.right.latex;
    }
  }
  return rel.left.latex + " \\in …";
}

// A claim's relations as compares of numbers, read with the claim's definitions.
class Reading {
 public:
  Reading(FileRun& run, const GiNaC::exmap& lets) : run_(run), lets_(lets) {}

  // A vector equation is one compare per component; a relation whose symbols carry a free
  // index (a_{vi(elastic)} = a_{vi(inelastic)}) one relation per value, as a row of equations.
  std::vector<Compare> compares(const Relation& rel) const {
    std::vector<std::string> free = run_.symbols.free_indices(rel.left.expression);
    if (rel.kind != Relation::Kind::in_set && rel.kind != Relation::Kind::in_range) {
      for (const std::string& letter : run_.symbols.free_indices(rel.right.expression)) {
        if (std::find(free.begin(), free.end(), letter) == free.end()) {
          free.push_back(letter);
        }
      }
    }
    std::vector<Compare> out;
    if (!free.empty()) {
      for (const long value : run_.symbols.indices().at(free.front())) {
        Relation one = rel;
        one.left.expression = file::with_index(rel.left.expression, free.front(), value);
        one.right.expression = file::with_index(rel.right.expression, free.front(), value);
        for (Compare& c : compares(one)) {
          out.push_back(std::move(c));
        }
      }
      return out;
    }
    const file::Value left = run_.symbols.meaning(rel.left.expression).value;
    if (left.block()) {
      throw run_.source.error(rel.offset, "expected numbers or vectors in a claim's relation");
    }
    return left.vector ? vector_compares(rel, left) : std::vector<Compare>{number_compare(rel)};
  }

 private:
  std::vector<Compare> vector_compares(const Relation& rel, const file::Value& left) const {
    const file::Value right = run_.symbols.meaning(rel.right.expression).value;
    if (!right.vector ||
        (rel.kind != Relation::Kind::equal && rel.kind != Relation::Kind::not_equal)) {
      throw run_.source.error(rel.offset, "expected a vector compared with a vector by = only");
    }
    std::vector<Compare> out;
    for (int k = 0; k < 2; ++k) {
      Compare c;
      c.kind = rel.kind;
      c.left = file::exact_reading((k == 0 ? left.x : left.y).subs(lets_));
      c.right = file::exact_reading((k == 0 ? right.x : right.y).subs(lets_));
      c.scale = file::term_scale(c.left) + file::term_scale(c.right);
      c.text = relation_text(rel) + (k == 0 ? " (x)" : " (y)");
      out.push_back(std::move(c));
    }
    return out;
  }

  Compare number_compare(const Relation& rel) const {
    Compare c;
    c.kind = rel.kind;
    c.left = number(rel.left, rel.offset);
    c.scale = file::term_scale(c.left);
    if (rel.kind == Relation::Kind::in_set) {
      for (const file::Side& m : rel.members) {
        c.members.push_back(number(m, rel.offset));
      }
    } else if (rel.kind == Relation::Kind::in_range) {
      c.has_low = rel.low.has_value();
      c.has_high = rel.high.has_value();
      for (const auto* bound : {&rel.low, &rel.high}) {
        if (*bound) {
          c.members.push_back(number(**bound, rel.offset));
        }
      }
      c.low_closed = rel.low_closed;
      c.high_closed = rel.high_closed;
    } else {
      c.right = number(rel.right, rel.offset);
      c.scale += file::term_scale(c.right);
    }
    c.text = relation_text(rel);
    return c;
  }

  ex number(const file::Side& side, std::size_t at) const {
    const file::Meaning m = run_.symbols.meaning(side.expression);
    if (m.value.vector || m.value.block()) {
      throw run_.source.error(at, "expected numbers on both sides of this relation of the claim");
    }
    return file::exact_reading(m.value.x.subs(lets_));
  }

  FileRun& run_;
  const GiNaC::exmap& lets_;
};

// What the exact method says of a row: nothing, holds, fails (at a point, when it has one), or
// could not decide.
enum class Exact { none, holds, fails, unknown };

struct Premises {
  std::vector<ex> differences;
  std::vector<ex> denominators;
};

// One conclusion decided exactly: an equality from the premises and the hypotheses (when these
// are equalities), a sign from the facts when there are no hypotheses.
Exact exact_one(FileRun& run, const file::Group& g, const Premises& premises,
                const std::vector<Compare>& hypotheses, const Compare& c, std::string& point) {
  using K = Relation::Kind;
  const bool equal_hypotheses = std::all_of(hypotheses.begin(), hypotheses.end(),
                                            [](const Compare& h) { return h.kind == K::equal; });
  if (c.kind == K::equal && equal_hypotheses) {
    std::vector<ex> given = premises.differences;
    for (const Compare& h : hypotheses) {
      given.push_back(h.left - h.right);
    }
    const file::Implication imp =
        file::implies({given, premises.denominators, c.left - c.right, {}}, g.claim_facts);
    using O = file::Implication::Outcome;
    if (imp.outcome == O::fails && imp.point) {
      std::string text;
      for (const auto& [s, v] : *imp.point) {
        std::ostringstream value;
        value << v;
        text += (text.empty() ? "" : ", ") + symbol_text(run.symbols, s) + " = " + value.str();
      }
      point = text + " (exact)";
    }
    return imp.outcome == O::holds || imp.outcome == O::holds_if ? Exact::holds
           : imp.outcome == O::fails                             ? Exact::fails
                                                                 : Exact::unknown;
  }
  if (!hypotheses.empty() || c.kind == K::equal || c.membership()) {
    return Exact::none;
  }
  const bool upward = c.kind == K::greater_equal || c.kind == K::greater;
  const file::Sign s =
      g.claim_facts.sign(upward || c.kind == K::not_equal ? c.left - c.right : c.right - c.left);
  using S = file::Sign;
  const bool shown = c.kind == K::not_equal
                         ? (s == S::positive || s == S::negative || s == S::nonzero)
                     : (c.kind == K::greater || c.kind == K::less)
                         ? s == S::positive
                         : (s == S::positive || s == S::nonnegative || s == S::zero);
  return shown ? Exact::holds : Exact::none;
}

// A row decided exactly: none when a conclusion says nothing, else the worst of them. A claim
// that names models is about the values they give (energies after, an equal impulse found by a
// search): algebra alone that does not prove it decides nothing.
Exact exact_row(FileRun& run, const file::Group& g, const Premises& premises,
                const std::vector<Compare>& hypotheses, const std::vector<Compare>& conclusions,
                std::string& point) {
  Exact row = Exact::holds;
  for (const Compare& c : conclusions) {
    Exact one = exact_one(run, g, premises, hypotheses, c, point);
    if (one == Exact::fails && !g.models.empty()) {
      one = Exact::none;
    }
    if (one == Exact::none) {
      row = row == Exact::holds ? Exact::none : row;
    } else if (one == Exact::fails) {
      row = Exact::fails;
    } else if (one == Exact::unknown && row != Exact::fails) {
      row = Exact::unknown;
    }
  }
  return row;
}

// What decides a claim: each row's verdict in the note, the first counterexample, and whether a
// row was refuted or left undecided.
struct Verdicts {
  std::string note;
  std::string counterexample;
  bool refuted = false;
  bool failed = false;
  std::size_t samples = 0;
};

// One row, from the exact method and the cases the models searched.
std::string row_verdict(const file::Group& g, std::size_t k, Exact exact,
                        const std::string& exact_point, const RowFinding& cases, Verdicts& v) {
  const auto counterexample = [&](const std::string& text) {
    if (v.counterexample.empty()) {
      v.counterexample = text;
    }
  };
  if (g.rows[k].exists) {
    if (cases.satisfied > 0) {
      return "a case satisfies it (" + cases.witness + ")";
    }
    if (cases.tested == 0) {
      v.failed = true;
      return "nothing was searched";
    }
    v.refuted = true;
    counterexample("none of " + std::to_string(cases.tested) + " cases searched satisfies " +
                   g.rows[k].latex +
                   (cases.first_failure.empty() ? "" : "; e.g. " + cases.first_failure));
    return "no case of " + std::to_string(cases.tested) + " satisfies it";
  }
  if (exact == Exact::fails) {
    v.refuted = true;
    counterexample(exact_point.empty() ? cases.first_failure : exact_point);
    return "fails exactly";
  }
  if (cases.failures > 0 && exact == Exact::holds) {
    v.failed = true;
    return "proven exactly, yet a case fails (" + cases.first_failure + ")";
  }
  if (cases.failures > 0) {
    v.refuted = true;
    counterexample(cases.first_failure);
    return std::to_string(cases.failures) + " of " + std::to_string(cases.tested) + " cases fail";
  }
  if (exact == Exact::holds) {
    return "holds exactly" +
           (cases.tested > 0 ? ", and on " + std::to_string(cases.tested) + " cases searched" : "");
  }
  if (cases.tested > 0 && exact != Exact::unknown) {
    return "holds on " + std::to_string(cases.tested) + " cases searched";
  }
  v.failed = true;
  return "undecided";
}

// The cases of every model on row k, the first failure and the first witness of the first model
// that has one.
RowFinding cases_of(const std::vector<ClaimFinding>& found, std::size_t k) {
  RowFinding all;
  for (const ClaimFinding& f : found) {
    const RowFinding& row = f.rows[k];
    all.tested += row.tested;
    all.failures += row.failures;
    all.satisfied += row.satisfied;
    all.first_failure = all.first_failure.empty() ? row.first_failure : all.first_failure;
    all.witness = all.witness.empty() ? row.witness : all.witness;
  }
  return all;
}

}  // namespace

Result check_claim(FileRun& run, const file::Group& g, Result r) {
  Outcome& o = r.outcome;
  const GiNaC::exmap& lets = g.claim_substitutions;
  Premises premises;
  for (const std::size_t p : g.claim_premises) {
    const file::Scalars s = file::scalars_of(run.read.equations[p], lets);
    premises.differences.insert(premises.differences.end(), s.differences.begin(),
                                s.differences.end());
    premises.denominators.insert(premises.denominators.end(), s.denominators.begin(),
                                 s.denominators.end());
  }
  const Reading reading(run, lets);
  Rows rows;
  for (const file::ClaimRow& row : g.rows) {
    std::vector<Compare> h, c;
    for (const Relation& rel : row.hypotheses) {
      for (Compare& x : reading.compares(rel)) {
        h.push_back(std::move(x));
      }
    }
    for (const Relation& rel : row.conclusions) {
      for (Compare& x : reading.compares(rel)) {
        c.push_back(std::move(x));
      }
    }
    rows.hypotheses.push_back(std::move(h));
    rows.conclusions.push_back(std::move(c));
  }
  std::vector<Exact> exact(g.rows.size(), Exact::none);
  std::vector<std::string> exact_point(g.rows.size());
  for (std::size_t k = 0; k < g.rows.size(); ++k) {
    if (!g.rows[k].exists) {
      exact[k] =
          exact_row(run, g, premises, rows.hypotheses[k], rows.conclusions[k], exact_point[k]);
      if (exact[k] != Exact::none) {
        o.methods.push_back(Method::symbolic);
      }
    }
  }
  // The searches.
  std::vector<ClaimFinding> found;
  for (const file::ModelUse& use : g.models) {
    run.define_for_probe(g, {}, lets);
    found.push_back(evaluate(run, use, rows, premises.differences, g.claim_facts, g));
    o.methods.push_back(found.back().method);
  }
  std::sort(o.methods.begin(), o.methods.end());
  o.methods.erase(std::unique(o.methods.begin(), o.methods.end()), o.methods.end());
  Verdicts v;
  for (std::size_t k = 0; k < g.rows.size(); ++k) {
    const RowFinding cases = cases_of(found, k);
    v.samples += cases.tested;
    v.note += (v.note.empty() ? "" : "; ") + ("row " + std::to_string(k + 1) + ": ") +
              row_verdict(g, k, exact[k], exact_point[k], cases, v);
  }
  o.samples = v.samples > 0 ? std::optional<std::size_t>(v.samples) : std::nullopt;
  o.note = v.note + ".";
  o.counterexample = plain(v.counterexample);
  if (v.failed) {
    o.status = Status::failed;
    o.explanation = "The claim could not be decided: " + v.note + ".";
  } else if (v.refuted && g.explanation.empty()) {
    o.status = Status::failed;
    o.explanation =
        "The claim does not hold and the file does not say why (explanation:): " + v.note + ".";
  } else if (v.refuted) {
    o.status = Status::refuted;
    o.explanation = g.explanation;
  } else {
    o.status = Status::verified;
  }
  return r;
}

}  // namespace impulse::derivations::paper
