// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab check run as a user runs it: the formats, the section filter, the exit statuses.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/program.hpp"

namespace t = impulselab::test;
using Catch::Matchers::Contains;
using nlohmann::json;

TEST_CASE("check --format json: one section, parsed by a program", "[cli]") {
  const t::Run r = t::run("check --section 1.1 --samples 200 --format json");
  REQUIRE(r.status == 0);
  REQUIRE(r.err.empty());
  const json report = json::parse(r.out);
  REQUIRE(report.at("samples") == 200);
  REQUIRE_FALSE(report.at("checks").empty());
  for (const json& c : report.at("checks")) {
    CHECK(c.at("section") == "1.1");
  }
  CHECK(report.at("summary").at("failed") == 0);
}

TEST_CASE("check as text ends with the summary and the errata", "[cli]") {
  const t::Run r = t::run("check --section 4 --samples 200");
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Contains("Summary: "));
  CHECK_THAT(r.out, Contains("Errata:"));
  CHECK_THAT(r.out, Contains("eq-4.4 (4.4)"));
  CHECK(r.out.find('\033') == std::string::npos);  // not a terminal: no colour
}

TEST_CASE("check --format markdown and --output", "[cli]") {
  const auto folder = t::fresh_folder("check-output");
  const auto file = folder / "report.md";
  const t::Run r = t::run("check --section 2 --samples 100 --format markdown --output " +
                          t::quote(file.string()));
  REQUIRE(r.status == 0);
  REQUIRE(r.out.empty());
  const std::string md = t::read_text(file);
  CHECK_THAT(md, Contains("# Derivation check report"));
  CHECK_THAT(md, Contains("{#check-claim-2-sign}"));
}

TEST_CASE("check refuses bad usage with exit status 2", "[cli]") {
  const t::Run unknown = t::run("check --section 9");
  CHECK(unknown.status == 2);
  CHECK_THAT(unknown.err, Contains("--section 9: no check is in that section"));
  CHECK_THAT(unknown.err, Contains("1.1"));
  CHECK(t::run("check --samples 0").status == 2);
  CHECK(t::run("check --samples many").status == 2);
  CHECK(t::run("check --format xml").status == 2);
  CHECK(t::run("check --bogus").status == 2);
  const t::Run help = t::run("check --help");
  CHECK(help.status == 0);
  CHECK_THAT(help.out, Contains("--samples"));
}

TEST_CASE("The same seed gives the same report", "[cli]") {
  const auto first = t::run("check --section 3.1 --samples 100 --seed 5 --format json");
  const auto second = t::run("check --section 3.1 --samples 100 --seed 5 --format json");
  REQUIRE(first.status == 0);
  auto a = json::parse(first.out), b = json::parse(second.out);
  // Timings differ from run to run; everything else is the same.
  for (auto* report : {&a, &b}) {
    report->erase("seconds");
    for (auto& c : report->at("checks"))
      c.erase("seconds");
  }
  CHECK(a == b);
}

TEST_CASE("check runs at fixed addresses, so that GiNaC's order of terms is one per program",
          "[cli]") {
  if (std::system("setarch --addr-no-randomize true > /dev/null 2>&1") != 0) {
    WARN("this system refuses fixed addresses (ADDR_NO_RANDOMIZE): check runs as it is");
    return;
  }
  // The program reads a file that is a pipe, and waits for it; meanwhile a watcher reads the
  // process's personality (the shell's process becomes impulselab by exec), then writes the file.
  // Without the second start at fixed addresses, the personality stays 00000000.
  const t::fs::path folder = t::fresh_folder("fixed-addresses");
  const std::string fifo = (folder / "student.md").string();
  const std::string seen = (folder / "personality").string();
  const std::string watcher = "mkfifo " + t::quote(fifo) +
                              " && ( for i in $(seq 1 200); do p=$(cat /proc/$$/personality); " +
                              "[ \"$p\" = 00040000 ] && break; sleep 0.05; done; echo \"$p\" > " +
                              t::quote(seen) + "; printf '$$x = 1$$\\n\\n$$2x = 2$$\\n' > " +
                              t::quote(fifo) + " ) & ";
  const t::Run r = t::run("check " + t::quote(fifo), "/dev/null", watcher);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("Every step follows."));
  CHECK(t::read_text(seen) == "00040000\n");
}

TEST_CASE("impulselab-check is impulselab check: the same checks and verdicts, no other verb",
          "[cli]") {
  // The two are different programs, each at its own fixed addresses: GiNaC's order of terms may
  // differ between them, and with it the last digits of a numeric residual. What a check is and
  // its verdict may not.
  const std::string arguments = "check --section 3 --samples 200 --format json";
  const t::Run whole = t::run(arguments);
  const t::Run alone = t::run_program(IMPULSELAB_CHECK_BINARY, arguments);
  REQUIRE(whole.status == 0);
  REQUIRE(alone.status == 0);
  const json a = json::parse(whole.out);
  const json b = json::parse(alone.out);
  REQUIRE(a.at("checks").size() == b.at("checks").size());
  REQUIRE_FALSE(a.at("checks").empty());
  for (std::size_t i = 0; i < a.at("checks").size(); ++i) {
    for (const char* key : {"id", "kind", "statement", "status", "methods", "samples"}) {
      CHECK(a.at("checks")[i].at(key) == b.at("checks")[i].at(key));
    }
  }
  CHECK(a.at("summary") == b.at("summary"));
  // solve is not one of its verbs: refused as impulselab refuses a verb it does not have.
  const t::Run solve = t::run_program(IMPULSELAB_CHECK_BINARY, "solve scene.json");
  CHECK(solve.status == 2);
  CHECK_THAT(solve.err, Contains("A subcommand is required"));
  CHECK(t::run("solve --help").status == 0);
}

TEST_CASE("check --section friction: the checks beyond the paper, apart", "[cli]") {
  const t::Run r = t::run("check --section friction --samples 500 --format json");
  REQUIRE(r.status == 0);
  const json report = json::parse(r.out);
  CHECK(report.at("checks").empty());  // none of the paper's
  const json& beyond = report.at("beyond_the_paper");
  CHECK(beyond.at("title") == "Beyond the paper: friction");
  REQUIRE_FALSE(beyond.at("checks").empty());
  for (const json& c : beyond.at("checks")) {
    CHECK(c.at("section").get<std::string>().rfind("friction.", 0) == 0);
  }
  CHECK(beyond.at("summary").at("failed") == 0);
  const t::Run text = t::run("check --section friction --samples 500");
  CHECK_THAT(text.out, Contains("Beyond the paper: friction"));
  CHECK_THAT(text.out, Contains("Summary beyond the paper: "));
  // A section of the paper has none of them; an unknown one names friction among the known.
  CHECK(json::parse(t::run("check --section 1.1 --samples 100 --format json").out)
            .count("beyond_the_paper") == 0);
  CHECK_THAT(t::run("check --section 9").err, Contains("friction.1"));
}
