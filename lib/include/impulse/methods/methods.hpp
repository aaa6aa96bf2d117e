// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Beyond the paper: which method turns a many-contact scene into impulses.
#pragma once

/// @brief Beyond the paper: two other ways to resolve many contacts, beside the paper's linear
/// system.
///
/// The paper solves every contact at once from one system @f$ \mathbf{A}\,\vec{F}dt = \vec{B} @f$
/// (Method::simultaneous, impulse::multipoint::resolve). Its solution may pull: an impulse can
/// come out negative, which no contact between two bodies that merely touch can exert. Engines
/// do it differently, and this namespace holds the two usual alternatives, built from the same
/// A and B and the same per-body blocks:
///
/// - Method::complementarity keeps the paper's A and B but lets a contact only push: it finds
///   @f$ F \ge 0 @f$ with @f$ w = A F - B \ge 0 @f$ and @f$ F_v w_v = 0 @f$ at every contact (a
///   linear complementarity problem, solve_complementarity());
/// - Method::serial resolves one contact at a time, the fastest-approaching first, each with the
///   single-contact formula, until no contact approaches (resolve_serial()).
///
/// Each method's answer for a scene is one value, an Outcome (methods/outcome.hpp): its impulses,
/// the bodies after as it produced them, and how it reports itself. The methods are the rows of
/// one table (methods/resolve.hpp, EnumNames<Method>): each row's name, words, whether it can
/// take a contact law, and how it resolves; resolve() reads it.
///
/// The docs page "Three ways to resolve many contacts" and lab 7 compare the three.
namespace impulse::methods {

/// @brief How the impulses of a scene are found.
enum class Method {
  /// The paper: every contact at once, @f$ \mathbf{A}\,\vec{F}dt = \vec{B} @f$ (the default).
  simultaneous,
  /// The paper's A and B with impulses that only push: a linear complementarity problem.
  complementarity,
  /// One contact at a time, the fastest-approaching first, until none approaches.
  serial,
};

}  // namespace impulse::methods
