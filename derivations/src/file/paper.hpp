// SPDX-License-Identifier: GPL-3.0-or-later
// The paper runner: each check of a paper file judged from what the engine finds on it. An
// equation or a step is verified when everything it is tested by passes (its own equations follow
// from the equations before, its evidence follows from it, every model it names agrees); an
// erratum when that fails for the statement as printed and passes for its correction; a claim is
// verified when every row holds (exactly, or on every case its search produces) and refuted when
// a case breaks it. Nothing here knows which statements are right.
//
// Its rooms: paper.cpp reads the files and counts the results; paper_equations.cpp runs an
// equation or a step, paper_claims.cpp a claim; paper_models.cpp evaluates the statements of
// either at a model's points.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/check.hpp"
#include "file/reader.hpp"
#include "models/model.hpp"

namespace impulse::derivations::paper {

using GiNaC::ex;

/// A number for a counterexample or a note: a few significant digits, and no "-0".
std::string shown_number(double x);

/// A symbol as the file writes it.
std::string symbol_text(file::Symbols& symbols, const ex& s);

/// A model's points, and for each the set of names it gives values (its number among them):
/// what the points are evaluated in is prepared once per set of names.
struct ModelPoints {
  std::vector<models::Point> points;
  std::vector<std::size_t> names;
};

/// What the engine knows of one file while it checks it: what it read, and what the models
/// ask of it (the probe and the points they share).
class FileRun : public models::Probe {
 public:
  FileRun(const file::Source& file_source, file::ReadFile& file_read, file::Symbols& file_symbols,
          const Options& run_options)
      : source(file_source), read(file_read), symbols(file_symbols), options(run_options) {}

  const file::Source& source;  ///< the file's text, for the places of errors
  file::ReadFile& read;        ///< its equations and checks
  file::Symbols& symbols;      ///< what its names mean
  const Options& options;      ///< the run's seed and samples

  /// The symbols a name of the file stands for: one, or a vector's two (read once).
  std::vector<ex> symbols_of_name(std::string_view latex);

  /// The file's definition of @p symbol as a function of @p inputs (Probe::function).
  std::function<double(std::span<const double>)> function(
      std::string_view symbol, const std::vector<std::string>& inputs) override;

  /// What the models read through the probe from now on: the definitions @p in_force, then each
  /// equation of a statement whose left side is one symbol, for the checks above @p g and then
  /// @p own (the check's statement, or its correction in that variant).
  void define_for_probe(const file::Group& g, const std::vector<std::size_t>& own,
                        GiNaC::exmap in_force);

  /// A model's points, made once per file and kept for the checks that name it again: a model
  /// knows nothing of the check, so its points depend only on the run's seed and samples and on
  /// the file's definitions it reads through the probe. They are made again when one of those
  /// reads differently now (another variant of a check, other definitions in force).
  const ModelPoints& points(const models::Model& model, const models::Settings& settings);

  /// Lets go of the points of the models @p g names that no check after it in the file names.
  void done_with(const file::Group& g);

 private:
  // A definition the model read through the probe while making its points.
  struct Asked {
    std::string symbol;
    std::vector<std::string> inputs;
    std::optional<ex> definition;
  };
  struct Kept {
    std::uint64_t seed = 0;
    std::size_t samples = 0;
    std::vector<Asked> asked;
    ModelPoints made;
  };

  /// The symbols @p inputs name, in their order (a vector's components one after the other).
  std::vector<ex> slots_of(const std::vector<std::string>& inputs);
  /// The file's definition of @p symbol in @p inputs as the probe reads it now, or nothing.
  std::optional<ex> definition(std::string_view symbol, const std::vector<std::string>& inputs);

  GiNaC::exmap probe_substitutions_;
  std::map<std::string, std::vector<ex>> names_;
  std::map<const models::Model*, std::list<Kept>> points_;
  std::vector<Asked>* asked_ = nullptr;  // where function() records, while points are made
};

// ---- the model evaluator (paper_models.cpp) ---------------------------------------------------

/// A statement of an equation or a step, read at a model's points: left - right, relative to the
/// size of its terms, must vanish where its denominators do not.
struct Target {
  ex left;
  ex right;
  std::vector<ex> denominators;
  bool instant = false;  ///< an equation between differentials, read at an instant of the contact
  std::string text;
};

/// One relation of a claim as numbers compare it: lhs - rhs and the size of its terms, or the
/// value and the bounds of a membership.
struct Compare {
  file::Relation::Kind kind = file::Relation::Kind::equal;
  ex left;
  ex right;
  std::vector<ex> members;  ///< in_set; in_range: low (or nothing), high (or nothing)
  ex scale;                 ///< the size of the terms the two sides are made of
  bool low_closed = false;
  bool high_closed = false;
  bool has_low = false;
  bool has_high = false;
  std::string text;  ///< the relation as written

  /// Whether it is a membership (its sides are the members, not a right side).
  [[nodiscard]] bool membership() const {
    return kind == file::Relation::Kind::in_set || kind == file::Relation::Kind::in_range;
  }
};

/// A claim's rows as numbers compare them: each row's hypotheses and conclusions.
struct Rows {
  std::vector<std::vector<Compare>> hypotheses;
  std::vector<std::vector<Compare>> conclusions;
};

/// What a model found on the statements of an equation or a step.
struct EquationFinding {
  Method method = Method::numeric;
  std::size_t points = 0;  ///< points where something was tested
  double worst = 0.0;      ///< the worst relative residual there
  bool holds = false;
  bool fails = false;
  std::string detail;  ///< for the check's note
};

/// What a model found on one row of a claim.
struct RowFinding {
  std::size_t tested = 0;     ///< cases where the row's hypotheses hold
  std::size_t satisfied = 0;  ///< and its conclusions too
  std::size_t failures = 0;   ///< and not its conclusions
  std::string first_failure;  ///< the first such case, and the relation it breaks
  std::string witness;        ///< the first case that satisfies it
};

/// What a model found on a claim.
struct ClaimFinding {
  Method method = Method::numeric;
  std::vector<RowFinding> rows;
};

/// The statements of an equation or a step at the points of the model @p use names, the
/// unknowns a point leaves solved from the equations before (@p pool) with the signs @p facts
/// give.
EquationFinding evaluate(FileRun& run, const file::ModelUse& use,
                         const std::vector<Target>& targets, const std::vector<ex>& pool,
                         const file::Facts& facts, const file::Group& g);

/// The rows of a claim at the points of the model @p use names, as for an equation.
ClaimFinding evaluate(FileRun& run, const file::ModelUse& use, const Rows& rows,
                      const std::vector<ex>& pool, const file::Facts& facts, const file::Group& g);

/// The model a file names; refused at its place when the checker has none of that name.
const models::Model& model_named(const FileRun& run, const file::ModelUse& use);

// ---- the rooms -------------------------------------------------------------------------------

/// An equation or a step (paper_equations.cpp): @p r with its outcome.
Result check_equation(FileRun& run, const file::Group& g, Result r);

/// A claim (paper_claims.cpp): @p r with its outcome.
Result check_claim(FileRun& run, const file::Group& g, Result r);

}  // namespace impulse::derivations::paper
