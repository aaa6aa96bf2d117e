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

TEST_CASE("Tasks: a fact or definition of the submission's own is a premise the task does not give",
          "[derivations][tasks]") {
  // The bounce: v² = 2 g h, v' = e v, v'² = 2 g h' give h' = e² h. A submission that assumes
  // e = 1 (or defines e := 1) reaches "h' = h"… and the target, e² h = h then, by a fact the task
  // does not give; one that defines a name of its own (k := e²) does not assume anything.
  const d::Task task{pins::read(tasks / "bounce-height" / "task.md"), "task.md"};
  const std::string given =
      "given:\n\n$$v^2 = 2 g h \\\\\nv' = e v \\\\\nv'^2 = 2 g h'$$\n\n"
      "$$2 g h' = 2 e^2 g h$$\n\n$$h' = e^2 h$$\n";
  const auto judged = [&](const std::string& facts) {
    const d::DerivationReport report = d::check_derivation(facts + given, "own.md", task);
    REQUIRE(report.task);
    return *report.task;
  };
  const d::TaskResult same = judged("assume: g, h, v > 0, 0 < e \\le 1\n\n");
  CHECK(same.target_reached);
  const d::TaskResult fact = judged("assume: g, h, v > 0, 0 < e \\le 1, e = 1\n\n");
  CHECK_FALSE(fact.target_reached);
  CHECK(fact.reason == "extra-premise");
  CHECK(lines_text(fact.extra_premises) == "5");  // the first equation where it is in force
  const d::TaskResult sign = judged("assume: g, h, v > 0, 0 < e \\le 1, h' > 0\n\n");
  CHECK(sign.reason == "extra-premise");  // the task gives no sign of h'
  const d::TaskResult definition = judged("assume: g, h, v > 0, 0 < e \\le 1\n\nlet: e = 1\n\n");
  CHECK(definition.reason == "extra-premise");
  const d::TaskResult name = judged("assume: g, h, v > 0, 0 < e \\le 1\n\nlet: k = e^2\n\n");
  CHECK(name.target_reached);
}
