// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Beyond the paper: which method turns a many-contact scene into impulses.
#pragma once

#include <array>
#include <string_view>

#include "impulse/core/names.hpp"

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
/// the bodies after as it produced them, and how it reports itself; resolve()
/// (methods/resolve.hpp) is the one place that picks the method.
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

/// @brief Every method, in the order `--compare` shows them.
inline constexpr std::array<Method, 3> all_methods{Method::simultaneous, Method::complementarity,
                                                   Method::serial};

/// @brief What a method does, in words, for the reports.
struct MethodText {
  Method method;                 ///< the method
  std::string_view description;  ///< after its name in the text report ("Method: serial (…)")
  std::string_view brief;        ///< after its name in the legend of `--compare`
};

/// @brief The words of each method.
inline constexpr std::array<MethodText, 3> method_texts{{
    {Method::simultaneous, "the paper's: every contact at once, A·Fdt = B",
     "the paper's, every contact at once (A·Fdt = B)"},
    {Method::complementarity,
     "impulses only push: Fdt >= 0 and A·Fdt - B >= 0, one of them 0 at each contact",
     "impulses only push (Fdt >= 0, A·Fdt - B >= 0, one of them 0)"},
    {Method::serial, "one contact at a time, the fastest-approaching first, until none approaches",
     "one contact at a time, the fastest-approaching first"},
}};

/// @brief The words of @p method.
/// @param method the method
/// @return its entry of method_texts
[[nodiscard]] constexpr const MethodText& text_of(Method method) {
  for (const MethodText& text : method_texts) {
    if (text.method == method) {
      return text;
    }
  }
  return method_texts[0];
}

}  // namespace impulse::methods

namespace impulse {
/// @brief The scene format's names of the methods ("simultaneous", "complementarity", "serial").
template <>
struct EnumNames<methods::Method> {
  /// the names, in the order of methods::all_methods
  static constexpr std::array<Named<methods::Method>, 3> table{
      {{methods::Method::simultaneous, "simultaneous"},
       {methods::Method::complementarity, "complementarity"},
       {methods::Method::serial, "serial"}}};
};
}  // namespace impulse
