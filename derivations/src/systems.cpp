// SPDX-License-Identifier: GPL-3.0-or-later
// What sections 4 and 5 (still C++) share: building and running a check, the numeric findings on
// a system assembled from the paper's printed coefficients, the printed per-contact energies.
#include "sections.hpp"

namespace impulse::derivations {

CodedCheck make_check(std::string id, std::string section, std::optional<std::string> equation,
                      Kind kind, std::string statement,
                      std::function<Outcome(const Context&)> evaluate) {
  Check c;
  c.id = std::move(id);
  c.section = std::move(section);
  c.equation = std::move(equation);
  c.kind = kind;
  c.statement = std::move(statement);
  return {std::move(c), std::move(evaluate)};
}

Outcome evaluate(const CodedCheck& check, const Context& context) {
  try {
    return check.evaluate(context);
  } catch (const std::exception& e) {
    Outcome outcome;
    outcome.status = Status::failed;
    outcome.explanation = std::string("The check could not be evaluated: ") + e.what();
    return outcome;
  }
}

}  // namespace impulse::derivations
