// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief A resolved scene for people: the text report, several methods side by side, and what
/// to warn about. Built from the Result alone, whatever the method.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/scene/run.hpp"
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

/// @brief What `impulselab solve` writes for a run, as text: text_report() of its one result
/// (nothing when its method did not finish), or the results side by side (`--compare`: one
/// column per method, `--compare restitution`: one per law, with the tangential impulses and how
/// each contact ended) in the tables of text_report() — impulses, velocities (and spins) after,
/// approach speeds after, energy and momentum, and each one's summary ("-" for one that did not
/// finish).
/// @param run a scene resolved (scene::run)
/// @param source how to name the scene
/// @param colour whether headings may use ANSI bold
/// @return the report, ending with a newline; empty when the one method did not finish
[[nodiscard]] std::string text(const Run& run, std::string_view source, bool colour);

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

/// @brief The warnings about the elasticities the bodies collided at, one sentence each, naming
/// @p source and the place of the number (`bodies[k].elasticity`, or `elasticity` for the scene's
/// default, once): above 2, beyond perfectly elastic, a collision creates kinetic energy; below
/// 1, short of perfectly inelastic, the bodies still approach each other after the impulse (an
/// elasticity is 1 + the coefficient of restitution: a coefficient typed in its place lands
/// here). The same for every method of a scene.
/// @param result a resolved scene
/// @param source how to name the scene
/// @return the lines; empty when every elasticity is from 1 to 2
[[nodiscard]] std::vector<std::string> elasticity_warnings(const Result& result,
                                                           std::string_view source);

/// @brief Why the method did not finish, naming @p source (`"scene.json: serial collisions did
/// not end: …"`), or "" when it did.
/// @param result a resolved scene
/// @param source how to name the scene
/// @return the message
[[nodiscard]] std::string unfinished_message(const Result& result, std::string_view source);

}  // namespace impulse::scene
