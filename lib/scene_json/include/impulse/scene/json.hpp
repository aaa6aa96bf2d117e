// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Scene files and JSON reports (target ImpulseLab::scene, which adds nlohmann-json).
///
/// Not part of the installed package: the library proper stays Eigen-only.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

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
/// - `max_dense_contacts`, 2,048: the policies `basic` and `drop-equation` are served only by
///   the dense method, whose N×N matrices take 8·N² bytes each (32 MiB at 2,048; 80 GB at
///   100,000) and whose cost grows as N³ (seconds at 2,048).
struct ReadLimits {
  std::size_t max_bytes = std::size_t{64} << 20U;  ///< size of the text, in bytes
  std::size_t max_depth = 64;                      ///< arrays and objects inside each other
  std::size_t max_bodies = 1'000'000;              ///< elements of `bodies`
  std::size_t max_contacts = 1'000'000;            ///< elements of `contacts`
  std::size_t max_dense_contacts = 2'048;  ///< contacts when the policies need the dense method
};

/// @brief Reads a scene from the text of a scene file (see the scene format).
///
/// All or nothing: either the whole scene is read and valid, or InvalidInput is thrown with a
/// message that starts with @p source and names the place, e.g.
/// `scene.json: bodies[1].mass: must be positive and finite, got -1`, or for a syntax error
/// `scene.json: line 3, column 7: syntax error …`. Refused besides the rules of
/// scene::validate: JSON syntax errors, a repeated key in an object, unknown keys (with the
/// nearest known key suggested), keys that do not apply to the body's kind, wrong types, missing
/// fields, vectors of the wrong shape for the dimension, numbers beyond the range of doubles,
/// unknown body names, unknown kinds and policies, and anything beyond @p limits.
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

/// @brief The message for text longer than @p max_bytes: `"<source>: holds more than …"`.
/// @param source how the message names the file
/// @param max_bytes the limit
/// @return the message, for InvalidInput
[[nodiscard]] std::string too_large_message(std::string_view source, std::size_t max_bytes);

/// @brief The report as `impulselab solve --format json` prints it (the scene format's
/// "Result"): `impulses`, `bodies`, `energy`, `momentum`, `contacts`, `system`, and for the
/// methods that are not the paper's `method` and their diagnostics.
///
/// In 1D every vector is a plain number (its x coordinate). Rigid bodies add
/// `angular_velocity` and `angular_momentum`; `system` adds `condition_estimate`. `system.A`
/// is `null` when the solution does not hold A (a solver that never forms it); `B` is always
/// given. Negative zeros are written as 0.
///
/// `method` names the method, "complementarity" or "serial" (it is absent for the paper's
/// simultaneous method, whose report stays exactly the specified one), followed by the
/// method's diagnostics: `complementarity` with `algorithm` ("active-set", "lemke" or
/// "projected-gauss-seidel"), `iterations` (pivots or sweeps), `complementarity_residual`
/// (@f$ \max_v |\min(A_{vv} F_v, w_v)| @f$), `converged`, `least_norm` and `slack`
/// (@f$ w = A\,F\,dt - B @f$ per contact); `serial` with `collisions`, `passes`, `order` (the
/// contact of each collision), `max_collisions` and `finished`.
/// @param result a result whose status is SolveStatus::success
/// @return the JSON document, keys in the order of the scene format
[[nodiscard]] nlohmann::ordered_json to_json(const Result& result);

}  // namespace impulse::scene
