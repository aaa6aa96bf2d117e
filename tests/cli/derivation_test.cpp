// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab check NOTES.md run as a student runs it: the exit statuses of the contract (0 every
// step passes, 1 one does not, 2 the file cannot be read, with FILE:LINE:COLUMN), the three
// formats, --output, and hostile files: huge, binary, not Markdown.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/program.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using nlohmann::json;

namespace {

std::string derivation(const std::string& name) {
  return t::quote(std::string(IMPULSELAB_DERIVATION_FILES_DIR) + "/" + name);
}

}  // namespace

TEST_CASE("check NOTES.md: every step follows, exit 0", "[cli][derivations]") {
  const t::Run r = t::run("check " + derivation("s3-elastic.md"));
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Contains("follows-if"));
  // The summary names the step that holds only under its condition: no bare "Every step follows."
  CHECK_THAT(r.out, Contains("Every step follows, but one step holds only under a condition the "
                             "facts do not give: line"));
}

TEST_CASE("check NOTES.md: a slip, exit 1, its line stands out", "[cli][derivations]") {
  const t::Run r = t::run("check " + derivation("slip-sign-1-1.md"));
  REQUIRE(r.status == 1);
  CHECK_THAT(r.out, Contains(">>  13  does-not-follow"));  // the slip's line, marked
  CHECK_THAT(r.out, Contains("First failing line: 13"));
  CHECK_THAT(r.out, Contains("counterexample:"));
  CHECK_THAT(r.err, Contains("line 13 does-not-follow"));
}

TEST_CASE("check NOTES.md --format json and markdown", "[cli][derivations]") {
  const t::Run r = t::run("check " + derivation("slip-sign-1-1.md") + " --format json");
  REQUIRE(r.status == 1);
  const json report = json::parse(r.out);
  CHECK(report.at("summary").at("does-not-follow") == 1);
  const json& last = report.at("equations").back();
  CHECK(last.at("line") == 13);
  CHECK(last.at("verdict") == "does-not-follow");
  CHECK(last.at("counterexample").is_object());
  const t::Run m = t::run("check " + derivation("s3-elastic.md") + " --format markdown");
  REQUIRE(m.status == 0);
  CHECK_THAT(m.out, Contains("| line | verdict | equation | details |"));
}

TEST_CASE("check NOTES.md: the same report in every run", "[cli][derivations]") {
  // GiNaC orders a sum's terms by hashes that change from process to process; before the
  // report's printers ordered them themselves, these files' residuals and conditions came out
  // differently in most of ten runs ("-m_2 + m_1" or "m_1 - m_2", "F dt" or "dt F"). Each is run
  // in several processes here, and every report must be the same.
  const std::string tutorials = std::string(IMPULSELAB_SCENES_DIR) + "/../derivations/";
  for (const std::string& file :
       {derivation("slip-from-wrong-tag.md"), derivation("slip-swapped-index.md"),
        derivation("slip-divide-may-be-zero.md"), t::quote(tutorials + "verdicts-tour.md")}) {
    CAPTURE(file);
    const t::Run first = t::run("check " + file);
    REQUIRE(first.status <= 1);
    for (int k = 0; k < 5; ++k) {
      CHECK(t::run("check " + file).out == first.out);
    }
  }
}

TEST_CASE("check NOTES.md --output writes the report whole", "[cli][derivations]") {
  const auto folder = t::fresh_folder("derivation-output");
  const auto file = folder / "report.json";
  const t::Run r = t::run("check " + derivation("s1-inelastic.md") + " --format json --output " +
                          t::quote(file.string()));
  REQUIRE(r.status == 0);
  CHECK(r.out.empty());
  CHECK(json::parse(t::read_text(file)).at("summary").at("follows") == 3);
}

TEST_CASE("check NOTES.md: a file that cannot be read, exit 2 with FILE:LINE:COLUMN",
          "[cli][derivations]") {
  const std::string path =
      std::string(IMPULSELAB_DERIVATION_MALFORMED_DIR) + "/unbalanced-brace.md";
  const t::Run r = t::run("check " + t::quote(path));
  REQUIRE(r.status == 2);
  CHECK(r.out.empty());
  // The contract's form, as compilers print it, alone on standard error.
  CHECK(r.err == path + ":3:17: expected '}' to close this '{'\n");
}

TEST_CASE("check NOTES.md: hostile files end in exit 2, never a crash", "[cli][derivations]") {
  const auto folder = t::fresh_folder("derivation-hostile");
  SECTION("a 100 MB file") {
    const auto big = folder / "big.md";
    std::ofstream(big).put('#');
    std::filesystem::resize_file(big, std::uintmax_t{100} << 20);  // sparse: costs no disk
    const t::Run r = t::run("check " + t::quote(big.string()));
    CHECK(r.status == 2);
    CHECK_THAT(r.err,
               StartsWith(big.string() + ":1:1: expected a derivation file of at most 4 MiB"));
  }
  SECTION("binary garbage") {
    const auto bin = folder / "garbage.md";
    std::ofstream out(bin, std::ios::binary);
    for (int i = 0; i < 10000; ++i) {
      out.put(static_cast<char>((i * 7919 + 13) % 256));
    }
    out.close();
    const t::Run r = t::run("check " + t::quote(bin.string()));
    CHECK(r.status == 2);
    CHECK_FALSE(r.signalled);
    CHECK_THAT(r.err, StartsWith(bin.string() + ":1:"));
  }
  SECTION("not a Markdown file, or a section of the paper with it") {
    CHECK(t::run("check notes.txt").status == 2);
    const t::Run r = t::run("check " + derivation("s3-elastic.md") + " --section 4");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("--section"));
    CHECK(t::run("check " + derivation("s3-elastic.md") + " --samples 100000").status == 2);
  }
  SECTION("a file that does not exist") {
    const t::Run r = t::run("check " + t::quote((folder / "missing.md").string()));
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("cannot read"));
  }
}

TEST_CASE("check several files and a folder: a row each, the worst exit status",
          "[cli][derivations]") {
  const t::Run r = t::run("check " + derivation("s3-elastic.md") + " " +
                          derivation("slip-sign-1-1.md") + " --format csv");
  REQUIRE(r.status == 1);  // the slip's file fails
  CHECK_THAT(r.out, StartsWith("file,exit,equations,premise,follows,"));
  CHECK_THAT(r.out, Contains("s3-elastic.md,0,"));
  CHECK_THAT(r.out, Contains("slip-sign-1-1.md,1,"));
  CHECK_THAT(r.err, Contains("1 of 2 files fail"));
  const t::Run text =
      t::run("check " + derivation("s3-elastic.md") + " " + derivation("slip-sign-1-1.md"));
  CHECK_THAT(text.out, Contains("Summary of 2 files:"));
  const t::Run folder =
      t::run("check " + t::quote(IMPULSELAB_DERIVATION_FILES_DIR) + " --format json");
  REQUIRE(folder.status == 1);  // the folder holds the slips
  const json rows = json::parse(folder.out);
  CHECK(rows.at("files").size() > 30);
  CHECK(rows.at("exit") == 1);
}

TEST_CASE("check --task: the target reached, or not, and why", "[cli][derivations]") {
  const std::string task = std::string(IMPULSELAB_TASKS_DIR) + "/inelastic-energy-lost/";
  const t::Run good =
      t::run("check --task " + t::quote(task + "task.md") + " " + t::quote(task + "correct-a.md"));
  REQUIRE(good.status == 0);
  CHECK_THAT(good.out, Contains("the target is reached at line 19"));
  const t::Run assumed = t::run("check --task " + t::quote(task + "task.md") + " " +
                                t::quote(task + "assumes-target.md") + " --format json");
  REQUIRE(assumed.status == 1);
  const json report = json::parse(assumed.out);
  CHECK(report.at("task").at("target_reached") == false);
  CHECK(report.at("task").at("reason") == "target-assumed");
  CHECK(report.at("task").at("extra_premises") == json::array({10}));
  // The message on standard error says why, as the report does: the target is not "not
  // reached" when the submission assumed it, or used a premise the task does not give.
  CHECK_THAT(assumed.err, Contains("the target is assumed, not derived (the premise at line 10"));
  CHECK_THAT(assumed.err, !Contains("not reached"));
  const t::Run extra = t::run("check --task " + t::quote(task + "task.md") + " " +
                              t::quote(task + "extra-premise.md"));
  REQUIRE(extra.status == 1);
  CHECK_THAT(extra.err, Contains("a premise the task does not give (line"));
  CHECK_THAT(extra.err, !Contains("not reached"));
  const t::Run no_target =
      t::run("check --task " + derivation("s3-elastic.md") + " " + t::quote(task + "correct-a.md"));
  CHECK(no_target.status == 2);
  CHECK_THAT(no_target.err, Contains("expected target:"));
}

TEST_CASE("check --step-seconds: a time budget, checked", "[cli][derivations]") {
  CHECK(t::run("check " + derivation("s3-elastic.md") + " --step-seconds 0").status == 2);
  CHECK(t::run("check " + derivation("s3-elastic.md") + " --step-seconds 5").status == 0);
}
