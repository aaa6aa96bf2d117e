// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Scene files and JSON reports (target ImpulseLab::scene, which adds nlohmann-json).
///
/// Not part of the installed package: the library proper stays Eigen-only.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/methods/methods.hpp"
#include "impulse/scene/scene.hpp"

namespace impulse::scene {

/// @brief How much a scene file may hold. Beyond each limit the reader refuses the file with a
/// message that names the limit, before the excess costs memory or time.
///
/// The defaults (see docs/pages/accuracy.md for the measurements behind them):
/// - `max_bytes`, 64 MiB: a scene of max_contacts contacts written compactly fits, and a
///   pretty-printed one of 100,000 contacts (the largest bench/ measures) takes about 30 MiB.
///   The parsed document costs about 20 to 40 bytes of memory per byte of text at worst (a long
///   array of small values), so this also bounds the reader's memory to about 2.5 GiB.
/// - `max_depth`, 64: a scene nests 4 levels deep (the scene, `bodies`, a body, its `velocity`);
///   deeper arrays and objects are refused before parsing, since each level costs memory.
/// - `max_bodies` and `max_contacts`, 1,000,000 each: ten times the largest scene bench/
///   measures (100,000 contacts: 0.1 to 0.6 s and under 200 MiB with the sparse method, which
///   grows about linearly). Counted while parsing, so an array is refused at its limit.
///
/// The rules of a scene's contents (among them impulse::dense_limit, the most contacts the
/// policies `basic` and `drop-equation` may have, and the bound on serial collisions) are the
/// library's, checked by scene::World for a scene built in C++ just as for a file.
struct ReadLimits {
  std::size_t max_bytes = std::size_t{64} << 20U;  ///< size of the text, in bytes
  std::size_t max_depth = 64;                      ///< arrays and objects inside each other
  std::size_t max_bodies = 1'000'000;              ///< elements of `bodies`
  std::size_t max_contacts = 1'000'000;            ///< elements of `contacts`
};

/// @brief Reads a scene from the text of a scene file (see the scene format) and checks it.
///
/// All or nothing: either the whole scene is read and valid, or InvalidInput is thrown with a
/// message that starts with @p source and names the place, e.g.
/// `scene.json: bodies[1].mass: must be positive and finite, got -1`, or for a syntax error
/// `scene.json: line 3, column 7: syntax error …`. The reader refuses what is wrong with the
/// text: JSON syntax errors, a repeated key in an object, unknown keys (with the nearest known
/// key suggested), keys that do not apply to the body's kind, wrong types, missing fields,
/// vectors of the wrong shape for the dimension, numbers beyond the range of doubles, unknown
/// body names, unknown kinds and policies, `normal` and `normal_angle` together, and anything
/// beyond @p limits; scene::World then refuses, with the place, what the scene format's rules
/// refuse.
/// @param text the file's contents
/// @param source how messages name the file ("scene.json", "<stdin>")
/// @param limits how much the file may hold (see ReadLimits)
/// @return the checked scene
[[nodiscard]] World parse_world(std::string_view text, std::string_view source,
                                const ReadLimits& limits = {});

/// @brief parse_world(), for the scene alone.
/// @param text the file's contents
/// @param source how messages name the file ("scene.json", "<stdin>")
/// @param limits how much the file may hold (see ReadLimits)
/// @return the scene, valid
[[nodiscard]] Scene parse_scene(std::string_view text, std::string_view source,
                                const ReadLimits& limits = {});

/// @brief The whole contents of a file; InvalidInput (`"<path>: cannot read: <reason>"`) when it
/// cannot be read, or (`"<path>: holds more than … bytes …"`) when it is larger than
/// @p max_bytes, which is found without reading more than @p max_bytes + 1 bytes.
/// @param path the file
/// @param max_bytes the largest file accepted
/// @return its bytes
[[nodiscard]] std::string read_file(const std::string& path,
                                    std::size_t max_bytes = ReadLimits{}.max_bytes);

/// @brief parse_scene on a file's contents, the message naming @p path.
/// @param path the scene file
/// @param limits how much the file may hold (see ReadLimits)
/// @return the scene, valid
[[nodiscard]] Scene load_scene(const std::string& path, const ReadLimits& limits = {});

/// @brief parse_world on a file's contents, the message naming @p path.
/// @param path the scene file
/// @param limits how much the file may hold (see ReadLimits)
/// @return the checked scene
[[nodiscard]] World load_world(const std::string& path, const ReadLimits& limits = {});

/// @brief The message for text longer than @p max_bytes: `"<source>: holds more than …"`.
/// @param source how the message names the file
/// @param max_bytes the limit
/// @return the message, for InvalidInput
[[nodiscard]] std::string too_large_message(std::string_view source, std::size_t max_bytes);

/// @brief The report as `impulselab solve --format json` prints it (the scene format's
/// "Result"): `impulses`, `bodies`, `energy`, `momentum`, `contacts`, `system`, then for a method
/// that reports diagnostics `method` and its block, and `notes` when checking the scene changed
/// something (a normal made unit).
///
/// In 1D every vector is a plain number (its x coordinate). Rigid bodies add
/// `angular_velocity` and `angular_momentum`; `system` adds `condition_estimate`. `system.A`
/// is `null` when the solution does not hold A (a solver that never forms it); `B` is always
/// given; `system.residual` is @f$ \|A\,F\,dt - B\| @f$ for the impulses reported. Negative
/// zeros are written as 0. A method's per-contact values (methods::ContactColumn) are added to
/// each entry of `impulses`.
///
/// `method` names the method, "complementarity" or "serial" (it is absent for the paper's
/// simultaneous method, whose report stays exactly the specified one), followed by the
/// method's diagnostics (methods::Outcome::diagnostics): `complementarity` with `algorithm`
/// ("active-set", "lemke" or "projected-gauss-seidel"), `iterations` (pivots or sweeps),
/// `complementarity_residual` (@f$ \max_v |\min(A_{vv} F_v, w_v)| @f$), `converged`,
/// `least_norm` and `slack` (@f$ w = A\,F\,dt - B @f$ per contact); `serial` with `collisions`,
/// `passes`, `order` (the contact of each collision), `max_collisions` and `finished`.
/// @param result a result whose status is SolveStatus::success
/// @return the JSON document, keys in the order of the scene format
[[nodiscard]] nlohmann::ordered_json to_json(const Result& result);

/// @brief to_json() as `impulselab solve --format json` prints it: indented by 2, with a final
/// newline.
/// @param result a result whose status is SolveStatus::success
/// @return the text
[[nodiscard]] std::string report_json(const Result& result);

/// @brief Several methods' results for programs (`solve --compare --format json`): an object
/// with one member per method, named as the scene format names it, each the method's full
/// result (to_json(), with `method` added for the paper's too), or for a method that did not
/// finish `{"method": NAME, "error": MESSAGE}`.
/// @param results one per method (scene::resolve with methods)
/// @param source how the messages name the scene
/// @return the JSON document
[[nodiscard]] nlohmann::ordered_json comparison_json(std::span<const Result> results,
                                                     std::string_view source);

/// @brief How `impulselab solve` writes its report.
enum class Format {
  text,  ///< for people (scene::text_report, scene::comparison_text)
  json,  ///< for programs (report_json, comparison_json)
};

/// @brief What `impulselab solve` prints for a scene: the report, why the method did not finish,
/// and the warnings.
struct SolveOutput {
  /// The report exactly as `solve` writes it; empty when the method did not finish (with
  /// `--compare`, the report of the methods that did is still there).
  std::string report;
  /// Why a method did not finish (`solve` then exits with status 1), naming the scene; empty
  /// when it did.
  std::string unfinished;
  /// The warnings `solve` prints on standard error (without its "impulselab: warning: "): the
  /// elasticities' (scene::elasticity_warnings), the impulses' (scene::impulse_warnings) and
  /// the system's (scene::system_warnings).
  std::vector<std::string> warnings;
};

/// @brief `impulselab solve` on a checked scene: scene::resolve() with @p method or the scene's
/// own, then the report in @p format and the warnings. A scene whose numbers overflow a double
/// throws InvalidInput (scene::overflow_message).
/// @param world the checked scene
/// @param source how messages name the scene ("scene.json", "<stdin>")
/// @param method the method, instead of the scene's `solver.method`; nothing: the scene's
/// @param format text or JSON
/// @param colour whether the text report may use ANSI bold
/// @return the report, or why the method did not finish, and the warnings
[[nodiscard]] SolveOutput solve_output(const World& world, std::string_view source,
                                       std::optional<methods::Method> method, Format format,
                                       bool colour = false);

/// @brief solve_output() on a scene already resolved (scene::resolve()): the same report,
/// refusal and warnings, for a caller that also needs the Result itself (the interactive page
/// draws the bodies' motion from it).
/// @param result the resolved scene
/// @param source how messages name the scene
/// @param format text or JSON
/// @param colour whether the text report may use ANSI bold
/// @return the report, or why the method did not finish, and the warnings
[[nodiscard]] SolveOutput solve_output(const Result& result, std::string_view source, Format format,
                                       bool colour = false);

/// @brief `impulselab solve --compare` on a checked scene: every method (methods::all_methods)
/// on one assembled and solved system, side by side in @p format; the system's warnings once,
/// then each method's impulse warnings with its name in front ("serial: …"); `unfinished` holds
/// one line per method that did not finish (the others' report is still written). A method
/// whose numbers overflow throws InvalidInput naming it. The elasticities' warnings come first,
/// once.
/// @param world the checked scene
/// @param source how messages name the scene
/// @param format text or JSON
/// @param colour whether the text report may use ANSI bold
/// @return the comparison, the unfinished methods and the warnings
[[nodiscard]] SolveOutput compare_output(const World& world, std::string_view source, Format format,
                                         bool colour = false);

/// @brief `impulselab solve --compare restitution` on a checked scene: the scene resolved by its
/// own method three times, once for each restitution law (friction::RestitutionLaw: Newton's,
/// Poisson's, the energetic law), side by side in @p format (text: scene::laws_comparison_text;
/// JSON: `{"newton": RESULT, "poisson": RESULT, "energetic": RESULT}`, each result to_json()
/// with `"restitution"` added, or `{"restitution": NAME, "error": MESSAGE}` for one that did not
/// finish); each law's impulse warnings with its name in front ("newton: energy gained: …").
/// A law the scene cannot take (the energetic law above elasticity 2, several contacts with a
/// method other than serial) throws InvalidInput naming the scene, the place and the law.
/// The elasticities' warnings come first, once.
/// @param world the checked scene
/// @param source how messages name the scene
/// @param format text or JSON
/// @param colour whether the text report may use ANSI bold
/// @return the comparison, the unfinished laws and the warnings
[[nodiscard]] SolveOutput compare_laws_output(const World& world, std::string_view source,
                                              Format format, bool colour = false);

/// @brief The one entry point from a scene file's text to `solve --format json`'s output:
/// parse_world() then solve_output() in JSON. `impulselab solve` goes the same way; so may a
/// page that runs the library in a browser.
///
/// Bad input throws InvalidInput with exactly the message `solve` prints (and exits 2 with), a
/// scene whose numbers overflow a double too.
/// @param text the scene file's contents
/// @param source how messages name the scene ("scene.json", "<stdin>")
/// @param method the method, instead of the scene's `solver.method`; nothing: the scene's
/// @param limits how much the text may hold
/// @return the JSON report (empty if the method did not finish), why not, and the warnings
[[nodiscard]] SolveOutput solve_to_json(std::string_view text, std::string_view source,
                                        std::optional<methods::Method> method = std::nullopt,
                                        const ReadLimits& limits = {});

}  // namespace impulse::scene
