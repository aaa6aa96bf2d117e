// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Scene files and JSON reports (target ImpulseLab::scene, which adds nlohmann-json).
///
/// Not part of the installed package: the library proper stays Eigen-only.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "impulse/scene/scene.hpp"

namespace impulse::scene {

/// @brief Reads a scene from the text of a scene file (see the scene format).
///
/// All or nothing: either the whole scene is read and valid, or InvalidInput is thrown with a
/// message that starts with @p source and names the place, e.g.
/// `scene.json: bodies[1].mass: must be positive and finite, got -1`, or for a syntax error
/// `scene.json: line 3, column 7: syntax error …`. Refused besides the rules of
/// scene::validate: JSON syntax errors, a repeated key in an object, unknown keys (with the
/// nearest known key suggested), keys that do not apply to the body's kind, wrong types, missing
/// fields, vectors of the wrong shape for the dimension, numbers beyond the range of doubles,
/// unknown body names, unknown kinds and policies.
/// @param text the file's contents
/// @param source how messages name the file ("scene.json", "<stdin>")
/// @return the scene, valid
[[nodiscard]] Scene parse_scene(std::string_view text, std::string_view source);

/// @brief The whole contents of a file; InvalidInput (`"<path>: cannot read: <reason>"`) when it
/// cannot be read.
/// @param path the file
/// @return its bytes
[[nodiscard]] std::string read_file(const std::string& path);

/// @brief parse_scene on a file's contents, the message naming @p path.
/// @param path the scene file
/// @return the scene, valid
[[nodiscard]] Scene load_scene(const std::string& path);

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
