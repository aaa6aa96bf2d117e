// SPDX-License-Identifier: GPL-3.0-or-later
#include "sections.hpp"

namespace impulse::derivations {

std::vector<Check> section2_checks() {
  return {};
}

}  // namespace impulse::derivations
