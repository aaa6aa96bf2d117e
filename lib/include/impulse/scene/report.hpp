// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief A resolved scene for people: the text report, several methods side by side, and what
/// to warn about. Built from the Result alone, whatever the method.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/scene/scene.hpp"

namespace impulse::scene {

/// @brief The text report of `impulselab solve`: the method and its own lines, the notes of the
/// scene's check, the impulses (with the method's per-contact columns), each body's motion
/// before and after (and its rotation for rigid bodies), energy and momentum before and after,
/// each contact's approach speed before and after, and the system A·Fdt = B with its rank,
/// residual and diagnostics (A itself up to 10 contacts).
///
/// Rounding noise is shown as 0: a value smaller than impulse::rounding_noise times the largest
/// value of its kind in the report could not be told from 0 at 6 significant digits. The
/// residual and the condition estimate are shown as computed; the JSON report keeps every digit
/// of everything.
/// @param result a result whose status is success
/// @param source how to name the scene ("scene.json", "<stdin>")
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline
[[nodiscard]] std::string text_report(const Result& result, std::string_view source, bool colour);

/// @brief Several methods' results for one scene side by side (`solve --compare`): impulses,
/// velocities (and spins) after, approach speeds after, energy and momentum, and each method's
/// summary, one column per method ("-" for a method that did not finish).
/// @param results the results, one per method, of one world (scene::resolve with methods)
/// @param source how to name the scene
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline
[[nodiscard]] std::string comparison_text(std::span<const Result> results, std::string_view source,
                                          bool colour);

/// @brief The three restitution laws' results for one scene side by side (`solve --compare
/// restitution`): the tables of comparison_text(), one column per law, with the tangential
/// impulses and how each contact ended.
/// @param results the results, one per law, of the same scene but for `solver.restitution`
/// @param laws the law of each result
/// @param source how to name the scene
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline
[[nodiscard]] std::string laws_comparison_text(std::span<const Result> results,
                                               std::span<const friction::RestitutionLaw> laws,
                                               std::string_view source, bool colour);

/// @brief The warnings about the impulses, one sentence each: every negative impulse
/// ("contact 1 (b–c): negative impulse -0.666667 (the contact pulls)"; an impulse within
/// impulse::rounding_noise of the largest one's size from 0 is rounding, not a pull), then the
/// method's own (an approximate answer).
/// @param result a resolved scene
/// @param prefix put in front of each line, e.g. "serial: " when several methods are shown
/// @return the lines
[[nodiscard]] std::vector<std::string> impulse_warnings(const Result& result,
                                                        std::string_view prefix = "");

/// @brief The warnings about the paper's system, one sentence each, naming @p source: a
/// condition estimate above impulse::ill_conditioned, and a solution the solver found
/// inconsistent (which never happens to a scene in exact arithmetic: rounding lost part of the
/// system). The system is the same for every method of a scene: one set of these serves them all.
/// @param result a resolved scene (status success)
/// @param source how to name the scene
/// @return the lines; empty when there is nothing to warn about
[[nodiscard]] std::vector<std::string> system_warnings(const Result& result,
                                                       std::string_view source);

/// @brief Why the method did not finish, naming @p source (`"scene.json: serial collisions did
/// not end: …"`), or "" when it did.
/// @param result a resolved scene
/// @param source how to name the scene
/// @return the message
[[nodiscard]] std::string unfinished_message(const Result& result, std::string_view source);

/// @brief The refusal of a result whose numbers are beyond doubles (status non_finite):
/// `"scene.json: the numbers overflow: …"`, with the method's name when @p name_method.
/// @param result the result
/// @param source how to name the scene
/// @param name_method whether to name the method (several are shown)
/// @return the message, for InvalidInput
[[nodiscard]] std::string overflow_message(const Result& result, std::string_view source,
                                           bool name_method);

}  // namespace impulse::scene
