// SPDX-License-Identifier: GPL-3.0-or-later
// A lecturer's tasks (tests/derivations/tasks/): each task's submissions judged against it. The
// expectations (expect.tsv) were written with the problems and confirmed with SymPy by
// tasks/make.py: a correct submission reaches the target at the line named; one that states the
// target as a premise, adds a premise the task does not give, or stops short does not, and says
// why.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "derivations/derivation.hpp"
#include "derivations/pins.hpp"

namespace fs = std::filesystem;
namespace d = impulse::derivations;
namespace pins = impulse::derivations::pins;

namespace {

const fs::path tasks = IMPULSELAB_TASKS_DIR;

std::string lines_text(const std::vector<std::size_t>& lines) {
  std::string text;
  for (const std::size_t l : lines) {
    text += (text.empty() ? "" : ",") + std::to_string(l);
  }
  return text.empty() ? "-" : text;
}

}  // namespace

TEST_CASE("Tasks: every submission reaches its target, or fails with the reason",
          "[derivations][tasks]") {
  const auto rows = pins::read_tsv(tasks / "expect.tsv", 6);
  REQUIRE(rows.size() >= 50);  // ten problems, five submissions each
  std::size_t reached = 0;
  for (const auto& row : rows) {
    const std::string& problem = row[0];
    const std::string& file = row[1];
    INFO(problem << "/" << file);
    const d::Task task{pins::read(tasks / problem / "task.md"), "task.md"};
    const d::DerivationReport report =
        d::check_derivation(pins::read(tasks / problem / file), file, task);
    REQUIRE(report.task);
    const d::TaskResult& t = *report.task;
    CHECK((t.target_reached ? "true" : "false") == row[2]);
    CHECK((t.line ? std::to_string(*t.line) : std::string("-")) == row[3]);
    CHECK(lines_text(t.extra_premises) == row[4]);
    CHECK(t.reason == row[5]);
    // The run fails exactly when the target is not reached (the steps themselves pass).
    CHECK(d::exit_status(report) == (t.target_reached ? 0 : 1));
    reached += t.target_reached ? 1 : 0;
  }
  CHECK(reached == 20);  // the two correct submissions of each problem
}

TEST_CASE("Tasks: a task file without a target is refused", "[derivations][tasks]") {
  const d::Task task{"given:\n\n$$a = b$$\n", "task.md"};
  CHECK_THROWS_AS(d::check_derivation("$$a = b$$\n", "a.md", task), d::TaskError);
}
