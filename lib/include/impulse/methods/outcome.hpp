// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief What any method found for a scene, as one value: its impulses, the bodies after as it
/// produced them, and how it reports itself.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/methods.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::methods {

/// @brief One value of a method's diagnostics in the JSON report.
using Value = std::variant<bool, std::int64_t, double, std::string, std::vector<double>,
                           std::vector<std::int64_t>>;

/// @brief A named value of a method's diagnostics: a key of its JSON block.
struct Field {
  std::string key;  ///< the JSON key ("iterations")
  Value value;      ///< its value
};

/// @brief A column of per-contact values that a method adds to the report: to each contact's
/// entry of `impulses` in JSON, and as a column of the text report's table of impulses. (Coulomb
/// friction adds the tangential impulse and how the contact ended, "slip", "stick" or
/// "reversed".)
struct ContactColumn {
  std::string key;      ///< the JSON key in each `impulses[v]`
  std::string heading;  ///< the heading of the text column
  /// one value per contact: numbers, or words
  std::variant<std::vector<double>, std::vector<std::string>> values;
};

/// @brief A method's answer for a configuration: what the reports show of it, without knowing
/// which method it was.
///
/// The impulses and the bodies after are the method's own: serial collisions report the state
/// their last collision left, not the summed impulses applied again. The text and JSON pieces
/// are the method's words; the scene's reports put them in place.
struct Outcome {
  Method method = Method::simultaneous;  ///< the method
  /// False when a number is beyond the range of doubles (the impulses or a body after): the
  /// rest is not meaningful, and a scene is refused as overflowing.
  bool finite = true;
  Eigen::VectorXd Fdt;                  ///< impulse magnitude at each contact
  std::vector<multipoint::Body> after;  ///< the bodies after, as the method produced them
  /// @f$ \|A\,F\,dt - B\| @f$ of the paper's system for these impulses (for the paper's own
  /// method, the solver's residual).
  double residual = 0.0;
  /// Whether the method came to its answer (false: serial collisions at their bound, a
  /// complementarity problem without solution); when false, `unfinished` says why.
  bool finished = true;
  std::string unfinished;  ///< why not, a sentence for after "<scene>: "
  /// Lines under the method's name in the text report (its algorithm, counts, residuals).
  std::vector<std::string> details;
  std::string summary;  ///< its diagnostics in one line, for `--compare`
  /// Warnings of its own (an approximate answer), each a sentence without a prefix. The
  /// warnings about impulses that pull and about the system are the scene's, for every method.
  std::vector<std::string> warnings;
  /// The JSON block the method adds after `system`, under its name (with `"method"`): empty for
  /// the paper's method, whose report is exactly the one the scene format specifies.
  std::vector<Field> diagnostics;
  std::vector<ContactColumn> per_contact;  ///< per-contact columns (none without friction)
  /// The whole impulse on each contact's bumper, when it is not @f$ -\vec{n}\,F\,dt @f$ (a
  /// tangential part); empty: @f$ -\vec{n}\,F\,dt @f$.
  std::vector<Eigen::Vector2d> on_bumper;
  /// The method's own result, for programs that want its typed diagnostics.
  std::variant<std::monostate, ComplementaritySolution, SerialDiagnostics> solution;
};

}  // namespace impulse::methods
