// SPDX-License-Identifier: GPL-3.0-or-later
// The paper runner's entrance (file/paper.hpp): the paper's files read, each check run in its room
// (an equation or a step, or a claim) and counted; and what the engine knows of one file while
// it checks it.
#include "file/paper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <memory>
#include <optional>
#include <set>

#include "derivations/derivation.hpp"
#include "file/decide.hpp"
#include "file/text.hpp"
#include "file/time.hpp"
#include "impulse/core/error.hpp"
#include "numeric.hpp"

namespace impulse::derivations {

namespace paper {

std::string shown_number(double x) {
  return num::brief(x == 0.0 ? 0.0 : x, 6);
}

std::string symbol_text(file::Symbols& symbols, const ex& s) {
  const file::SymbolInfo* info = symbols.info(s);
  if (info == nullptr) {
    return GiNaC::is_a<GiNaC::symbol>(s) ? GiNaC::ex_to<GiNaC::symbol>(s).get_name() : "?";
  }
  return info->name.latex();
}

std::vector<ex> FileRun::symbols_of_name(std::string_view latex) {
  const std::string key(latex);
  if (const auto found = names_.find(key); found != names_.end()) {
    return found->second;
  }
  const file::Source names{key};
  const file::SymbolName name = file::read_symbol_or_differential(names, 0, latex, file::Limits{});
  const file::Value v = symbols.value_of(name);
  return names_[key] = v.vector ? std::vector<ex>{v.x, v.y} : std::vector<ex>{v.x};
}

std::vector<ex> FileRun::slots_of(const std::vector<std::string>& inputs) {
  std::vector<ex> slots;
  for (const std::string& input : inputs) {
    const std::vector<ex> named = symbols_of_name(input);
    slots.insert(slots.end(), named.begin(), named.end());
  }
  return slots;
}

std::optional<ex> FileRun::definition(std::string_view symbol,
                                      const std::vector<std::string>& inputs) {
  try {
    const std::vector<ex> slots = slots_of(inputs);
    const ex e = file::exact_reading(symbols_of_name(symbol)[0].subs(probe_substitutions_));
    for (const ex& s : file::symbols_of(std::vector<ex>{e})) {
      if (std::none_of(slots.begin(), slots.end(), [&](const ex& x) { return x.is_equal(s); })) {
        return std::nullopt;  // the file does not define it from these inputs
      }
    }
    return e;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::function<double(std::span<const double>)> FileRun::function(
    std::string_view symbol, const std::vector<std::string>& inputs) {
  const auto nothing = [](std::span<const double>) { return std::nan(""); };
  const std::optional<ex> e = definition(symbol, inputs);
  if (asked_ != nullptr) {
    asked_->push_back({std::string(symbol), inputs, e});
  }
  if (!e) {
    return nothing;
  }
  try {
    file::TimedExpression compiled(*e, slots_of(inputs));
    return [compiled = std::move(compiled)](std::span<const double> values) {
      return compiled(values, nullptr);
    };
  } catch (const std::exception&) {
    return nothing;
  }
}

void FileRun::define_for_probe(const file::Group& g, const std::vector<std::size_t>& own,
                               GiNaC::exmap in_force) {
  GiNaC::exmap defined;
  const auto define = [&](const std::vector<std::size_t>& equations) {
    for (const std::size_t i : equations) {
      const file::Equation& e = read.equations[i];
      const file::Value& l = e.lhs.value;
      const file::Value& r = e.rhs.value;
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
  for (const file::Group& above : read.groups) {
    if (above.id == g.id) {
      break;
    }
    define(above.statement_equations);
  }
  define(own);
  probe_substitutions_ = std::move(in_force);
  for (const auto& [name, definition] : defined) {
    probe_substitutions_.emplace(name, definition);
  }
}

const ModelPoints& FileRun::points(const models::Model& model, const models::Settings& settings) {
  std::list<Kept>& kept = points_[&model];
  for (const Kept& k : kept) {
    if (k.seed == settings.seed && k.samples == settings.samples &&
        std::all_of(k.asked.begin(), k.asked.end(), [&](const Asked& a) {
          const std::optional<ex> now = definition(a.symbol, a.inputs);
          return now.has_value() == a.definition.has_value() &&
                 (!now || now->is_equal(*a.definition));
        })) {
      return k.made;
    }
  }
  Kept& made = kept.emplace_back();
  made.seed = settings.seed;
  made.samples = settings.samples;
  asked_ = &made.asked;
  try {
    made.made.points = model.points(*this, settings);
  } catch (...) {
    asked_ = nullptr;
    kept.pop_back();
    throw;
  }
  asked_ = nullptr;
  // Most models give every point the same names: a point is compared with the one before, and
  // only a point that differs looks its names up.
  std::map<std::string, std::size_t> sets;
  const models::Point* before = nullptr;
  for (const models::Point& point : made.made.points) {
    const auto same_names = [](const models::Value& a, const models::Value& b) {
      return a.symbol == b.symbol;
    };
    if (before != nullptr && before->values.size() == point.values.size() &&
        std::equal(point.values.begin(), point.values.end(), before->values.begin(), same_names)) {
      made.made.names.push_back(made.made.names.back());
    } else {
      std::string key;
      for (const models::Value& v : point.values) {
        key += v.symbol;
        key += '\n';
      }
      made.made.names.push_back(sets.emplace(key, sets.size()).first->second);
    }
    before = &point;
  }
  return made.made;
}

void FileRun::done_with(const file::Group& g) {
  const auto same = [](const file::ModelUse& a, const file::ModelUse& b) {
    return a.method == b.method && a.name == b.name;
  };
  const auto here = std::find_if(read.groups.begin(), read.groups.end(),
                                 [&](const file::Group& x) { return &x == &g; });
  for (const file::ModelUse& use : g.models) {
    const bool named_later =
        here != read.groups.end() &&
        std::any_of(std::next(here), read.groups.end(), [&](const file::Group& later) {
          return std::any_of(later.models.begin(), later.models.end(),
                             [&](const file::ModelUse& x) { return same(x, use); });
        });
    const std::optional<Method> method = value_named<Method>(use.method);
    const models::Model* model = method ? models::find(*method, use.name) : nullptr;
    if (!named_later && model != nullptr) {
      points_.erase(model);
    }
  }
}

}  // namespace paper

namespace {

using namespace file;

// One check of a file: its place and statement, the outcome of its room, and how long it took.
Result check(paper::FileRun& run, const Group& g) {
  Result r;
  r.check.id = g.id;
  r.check.section = g.section;
  r.check.equation = g.label;
  r.check.kind = g.kind;
  r.check.statement = file::trimmed(g.statement);
  r.check.line = run.source.place(g.statement_offset).line;
  const auto begin = std::chrono::steady_clock::now();
  r = g.kind == Kind::claim ? paper::check_claim(run, g, std::move(r))
                            : paper::check_equation(run, g, std::move(r));
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - begin;
  r.seconds = took.count();
  return r;
}

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
      checks.push_back({g.id, g.section, g.label, g.kind, file::trimmed(g.statement), file.name,
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
    paper::FileRun run_file(*p.source, p.read, p.reader->symbols(), options);
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
        result = check(run_file, g);
      } catch (const ReadError& e) {
        throw placed(file, e.place(), e.what());
      }
      run_file.done_with(g);
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
