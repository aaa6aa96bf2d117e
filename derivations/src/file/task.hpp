// SPDX-License-Identifier: GPL-3.0-or-later
// A submission judged against a lecturer's task (`impulselab check --task`): premises the task
// does not give, and whether a step reaches the target.
#pragma once

#include <vector>

#include "derivations/derivation.hpp"
#include "file/reader.hpp"

namespace impulse::derivations::file {

class Checker;

/// What the submission whose equations (and report) are given made of @p task. Throws TaskError
/// when the task file cannot be read or has no target.
[[nodiscard]] TaskResult judge_task(const Task& task, const std::vector<Equation>& equations,
                                    Symbols& symbols, Checker& checker,
                                    const DerivationReport& report,
                                    const DerivationOptions& options);

}  // namespace impulse::derivations::file
