// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab solve SCENE --compare: the three methods' answers for one scene, side by side.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "impulse/scene/scene.hpp"

namespace impulselab {

/// One method's answer for a scene, or why there is none.
struct MethodOutcome {
  impulse::methods::Method method = impulse::methods::Method::simultaneous;  ///< the method
  impulse::scene::Result result;  ///< its result (meaningful when `failure` is empty)
  std::string failure;  ///< why the method gave no answer (did not finish); empty if it did
};

/// The scene solved by each method in turn: simultaneous, complementarity, serial. Throws
/// impulse::InvalidInput when the numbers overflow (as `solve` does).
/// @param scene the scene (its own method is ignored)
/// @param source how messages name the scene
/// @return three outcomes
std::vector<MethodOutcome> solve_each_method(const impulse::scene::Scene& scene,
                                             const std::string& source);

/// The outcomes side by side for people: impulses, velocities (and spins) after, approach
/// speeds after, energy and momentum, and each method's diagnostics, one column per method.
/// @param outcomes from solve_each_method()
/// @param source how to name the scene
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline
std::string comparison_text(const std::vector<MethodOutcome>& outcomes, const std::string& source,
                            bool colour);

/// The outcomes for programs: an object with one member per method, named as the scene format
/// names it, each the method's full result (impulse::scene::to_json, with `method` added for the
/// paper's too), or for a method that did not finish {"method": NAME, "error": MESSAGE}.
/// @param outcomes from solve_each_method()
/// @return the JSON document
nlohmann::ordered_json comparison_json(const std::vector<MethodOutcome>& outcomes);

/// `solve --compare`: solves the scene by each method, writes the comparison (text or JSON) to
/// @p output (standard output when empty or "-"), prints each method's warnings on standard
/// error with the method's name in front, and throws WorkFailed (exit 1) after writing when a
/// method did not finish.
/// @param scene the scene
/// @param source how messages name the scene
/// @param format "text" or "json"
/// @param output the --output value
void compare_methods(const impulse::scene::Scene& scene, const std::string& source,
                     const std::string& format, const std::string& output);

}  // namespace impulselab
