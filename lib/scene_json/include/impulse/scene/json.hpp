// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The scene file format (target ImpulseLab::scene, which adds nlohmann-json): a scene's
/// text in, checked (parse_world); a resolved scene's report out (to_json, report_json). Its
/// syntax, types and places only: the rules of a scene, how it is resolved and what is warned
/// about are the library's (scene/scene.hpp, scene/run.hpp).
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

#include "impulse/scene/run.hpp"
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
/// - `max_keys`, 64: the keys of one object (a body has at most 10). The parser keeps an object's
///   members in the order of the file and looks a key up among those before it, so an object
///   of a million keys would take hours; counted while parsing, refused at the first key too
///   many.
///
/// The rules of a scene's contents (among them impulse::dense_limit, the most contacts the
/// policies `basic` and `drop-equation` may have, and the bound on serial collisions) are the
/// library's, checked by scene::World for a scene built in C++ just as for a file.
struct ReadLimits {
  std::size_t max_bytes = std::size_t{64} << 20U;  ///< size of the text, in bytes
  std::size_t max_depth = 64;                      ///< arrays and objects inside each other
  std::size_t max_bodies = 1'000'000;              ///< elements of `bodies`
  std::size_t max_contacts = 1'000'000;            ///< elements of `contacts`
  std::size_t max_keys = 64;                       ///< keys of one object
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

/// @brief What `impulselab solve --format json` writes for a run: report_json() of its one
/// result (nothing when its method did not finish), or for a comparison an object with one
/// member per result, named as the scene format names its method (`--compare`) or its law
/// (`--compare restitution`), each to_json() with `"method"` (or `"restitution"`) added, or for
/// one that did not finish `{"method": NAME, "error": MESSAGE}` (`"restitution"` for a law).
/// @param run a scene resolved (scene::run)
/// @param source how the messages name the scene
/// @return the text, indented by 2, with a final newline; empty when the one method did not
///         finish
[[nodiscard]] std::string report_json(const Run& run, std::string_view source);

/// @brief A scene file's text resolved, and what `impulselab solve --format json` prints for it.
struct JsonRun {
  Run run;             ///< the results, warnings and why a method did not finish
  std::string report;  ///< report_json() of the run
};

/// @brief The one entry from a scene file's text to `solve --format json`'s output:
/// parse_world(), scene::run(), report_json(). `impulselab solve` goes the same way; so does
/// the page that runs the library in a browser.
///
/// Bad input throws InvalidInput with exactly the message `solve` prints (and exits 2 with), a
/// scene whose numbers overflow a double too.
/// @param text the scene file's contents
/// @param source how messages name the scene ("scene.json", "<stdin>")
/// @param request what to resolve
/// @param limits how much the text may hold
/// @return the run and its JSON report
[[nodiscard]] JsonRun solve_to_json(std::string_view text, std::string_view source,
                                    const Request& request = {}, const ReadLimits& limits = {});

}  // namespace impulse::scene
