// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The one entry from a checked scene to what a user is shown: its results, the warnings,
/// and why a method did not finish, for `solve`, `solve --compare`, `solve --compare
/// restitution` and each row of `sweep`. The command line, the sweep and the interactive page
/// all come in here; the reports (scene/report.hpp as text, scene/json.hpp as JSON) are written
/// from what it returns.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/methods/methods.hpp"
#include "impulse/scene/scene.hpp"

namespace impulse::scene {

/// @brief What is asked of a scene.
struct Request {
  /// What is set side by side.
  enum class Compare {
    nothing,  ///< the scene resolved once
    methods,  ///< every method that can take the scene (`--compare`), on one solved system
    laws,     ///< every restitution law, each by the scene's method (`--compare restitution`)
  };
  Compare compare = Compare::nothing;  ///< what is set side by side; nothing by default
  /// The method instead of the scene's `solver.method` (not with a comparison).
  std::optional<methods::Method> method = std::nullopt;
  /// A row of `sweep`: every body at this elasticity (World::with_elasticity). Its warnings
  /// are the system's alone (the same at every elasticity); its messages name the elasticity.
  std::optional<double> elasticity = std::nullopt;
};

/// @brief A scene resolved as asked, and what to tell the user about it.
struct Run {
  Request request;              ///< what was asked
  std::vector<Result> results;  ///< one; or one per method compared, or per law in their order
  /// Each a sentence for after "impulselab: warning: ": the elasticities'
  /// (scene::elasticity_warnings, once; not for a row of a sweep) and the system's
  /// (scene::system_warnings, once), the methods left out of a comparison, then each result's
  /// impulse warnings (scene::impulse_warnings), with the method's or the law's name in front
  /// when several are shown. None when the one method asked for did not finish.
  std::vector<std::string> warnings;
  /// Why a method did not finish, one line each naming the scene (`solve` then exits with
  /// status 1); empty when every one did.
  std::string unfinished;
};

/// @brief Resolves @p world as @p request asks (scene::resolve), and says what to warn about.
///
/// A scene a method cannot take (friction at several contacts with the paper's method), one a
/// restitution law cannot take, and one whose numbers overflow a double are refused with
/// InvalidInput, the message starting with @p source: `"scene.json: contacts: the method …"`,
/// `"scene.json: the numbers overflow (method serial): …"`, and for a comparison of laws or a row
/// of a sweep naming the law or the elasticity.
/// @param world the checked scene
/// @param source how the messages name the scene ("scene.json", "<stdin>")
/// @param request what to resolve
/// @return the results, the warnings and why a method did not finish
[[nodiscard]] Run run(const World& world, std::string_view source, const Request& request = {});

/// @brief run() in slices, for a page that must draw every frame: a request for one method
/// runs its serial collisions a bounded number at a time (scene::Resolving); anything else
/// (another method, a comparison) runs whole when finished. Advanced in one slice or in many,
/// finish() gives exactly what run() gives, and the same refusals (InvalidInput, from the
/// constructor, advance() or finish()).
class RunInSlices {
 public:
  /// @brief Starts a run of a world that outlives it (scene::run's).
  /// @param world the checked scene
  /// @param source how the messages name the scene
  /// @param request what to resolve
  RunInSlices(const World& world, std::string_view source, const Request& request = {});
  /// @brief Starts a run that keeps the world (a page's scene, read for it).
  /// @param world the checked scene, moved in
  /// @param source how the messages name the scene
  /// @param request what to resolve
  RunInSlices(World&& world, std::string_view source, const Request& request = {});
  /// @brief Frees its state.
  ~RunInSlices();
  /// @brief Takes over another run in progress (which is left without state).
  /// @param other the one taken over
  RunInSlices(RunInSlices&& other) noexcept;
  /// @brief Takes over another run in progress (which is left without state).
  /// @param other the one taken over
  /// @return this one
  RunInSlices& operator=(RunInSlices&& other) noexcept;

  /// @brief Runs at most @p collisions more serial collisions.
  /// @param collisions how many at most (at least 1)
  /// @return whether the run has ended (then finish() gives it)
  bool advance(std::int64_t collisions);
  /// @brief The serial collisions so far (0 for anything else).
  /// @return their number
  [[nodiscard]] std::int64_t collisions() const;
  /// @brief The bound on serial collisions (0 for anything else).
  /// @return the bound
  [[nodiscard]] std::int64_t bound() const;
  /// @brief The run, once advance() has returned true.
  /// @return run()'s answer
  [[nodiscard]] Run finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace impulse::scene
