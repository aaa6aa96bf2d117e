// SPDX-License-Identifier: GPL-3.0-or-later
// The three report formats: JSON against the contract of spec/cli-and-report.md, text and
// markdown against what they promise.
#include <catch2/catch.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "derivations/check.hpp"

namespace check = impulse::derivations;
using nlohmann::json;

namespace {
const check::Report& report() {
  static const check::Report r = check::run({"", 500, 7});
  return r;
}
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}
}  // namespace

TEST_CASE("JSON report: the contract's fields and values", "[derivations]") {
  const json r = json::parse(check::render(report(), check::Format::json));
  REQUIRE(r.at("paper") == "Collision handling");
  REQUIRE(r.at("seed") == 7);
  REQUIRE(r.at("samples") == 500);
  const json& summary = r.at("summary");
  const std::set<std::string> statuses{"verified", "erratum", "refuted", "failed"};
  const std::set<std::string> kinds{"equation", "step", "claim"};
  const std::set<std::string> methods{"symbolic", "numeric", "quadrature", "ode", "search"};
  std::map<std::string, int> counted;
  std::set<std::string> ids;
  REQUIRE(r.at("checks").is_array());
  REQUIRE(r.at("checks").size() == report().results.size());
  for (const json& c : r.at("checks")) {
    CAPTURE(c.dump());
    REQUIRE(c.at("id").is_string());
    REQUIRE(ids.insert(c.at("id").get<std::string>()).second);
    REQUIRE(c.at("section").is_string());
    REQUIRE((c.at("equation").is_null() || c.at("equation").get<std::string>().front() == '('));
    REQUIRE(kinds.count(c.at("kind").get<std::string>()) == 1);
    REQUIRE(!c.at("statement").get<std::string>().empty());
    REQUIRE(!c.at("methods").empty());
    for (const json& m : c.at("methods")) {
      REQUIRE(methods.count(m.get<std::string>()) == 1);
    }
    const std::string status = c.at("status").get<std::string>();
    REQUIRE(statuses.count(status) == 1);
    ++counted[status];
    REQUIRE((c.at("max_relative_error").is_null() || c.at("max_relative_error").is_number()));
    REQUIRE((c.at("samples").is_null() || c.at("samples").is_number_unsigned()));
    if (status == "erratum") {
      REQUIRE(!c.at("correction").get<std::string>().empty());
      REQUIRE(!c.at("explanation").get<std::string>().empty());
    }
    if (status == "refuted") {
      REQUIRE(!c.at("counterexample").get<std::string>().empty());
      REQUIRE(!c.at("explanation").get<std::string>().empty());
    }
    // Numbered equations carry their label; steps and claims do not.
    REQUIRE((c.at("kind") == "equation") == c.at("equation").is_string());
    // The display (beyond the contract; the docs' pages show it): one \tag, the check's own
    // label, at the very end, where MathJax 2 accepts it; no \label.
    const std::string display = c.at("display").get<std::string>();
    CHECK(display.find("\\label{") == std::string::npos);
    if (c.at("equation").is_string()) {
      const std::string label = c.at("equation").get<std::string>();
      const std::string tag = "\\tag{" + label.substr(1, label.size() - 2) + "}";
      CHECK(display.size() >= tag.size());
      CHECK(display.rfind(tag) == display.size() - tag.size());
      CHECK(display.find("\\tag{") == display.size() - tag.size());
    } else {
      CHECK(display.find("\\tag{") == std::string::npos);
    }
  }
  for (const auto& s : statuses) {
    CAPTURE(s);
    REQUIRE(summary.at(s) == counted[s]);
  }
}

TEST_CASE("Text report: grouped by section, a summary line, the errata and refutations listed",
          "[derivations]") {
  const std::string text = check::render(report(), check::Format::text);
  const auto& s = report().summary;
  REQUIRE_THAT(text, Catch::Matchers::Contains(
                         "Summary: " + std::to_string(s.verified) + " verified, " +
                         std::to_string(s.erratum) + " errata, " + std::to_string(s.refuted) +
                         " refuted, " + std::to_string(s.failed) + " failed"));
  REQUIRE_THAT(text, Catch::Matchers::Contains("\nErrata:\n"));
  REQUIRE_THAT(text, Catch::Matchers::Contains("\nRefuted claims:\n"));
  for (const auto& r : report().results) {
    CAPTURE(r.check.id);
    // Each check's row, and each erratum and refutation again in the closing lists.
    const std::size_t expected = r.outcome.status == check::Status::verified ? 1 : 2;
    CHECK(count(text, "\n  " + r.check.id) >= expected);  // lines that start with the id
  }
  REQUIRE(text.find('\033') == std::string::npos);  // no colour unless asked for
  REQUIRE(check::render(report(), check::Format::text, true).find('\033') != std::string::npos);
}

TEST_CASE("Text report: a worst disagreement at the level of rounding is shown as such",
          "[derivations]") {
  // Below 1e-15 a relative disagreement's digits follow the order in which a sum's terms were
  // added (GiNaC's, which follows the program's layout in memory): 2.1e-16 in one build, 2.2e-16
  // in another. The table shows "<1e-15", the notes "below 1e-15"; above it, two digits.
  const std::string text = check::render(report(), check::Format::text);
  std::size_t rounding = 0;
  std::size_t above = 0;
  for (const auto& r : report().results) {
    if (!r.outcome.max_relative_error) {
      continue;
    }
    CAPTURE(r.check.id, *r.outcome.max_relative_error, r.outcome.note);
    const std::size_t row = text.find("\n  " + r.check.id + " ");
    REQUIRE(row != std::string::npos);
    const std::string line = text.substr(row + 1, text.find('\n', row + 1) - row - 1);
    if (*r.outcome.max_relative_error < 1e-15) {
      ++rounding;
      CHECK(line.ends_with("<1e-15"));
    } else {
      ++above;
      CHECK(line.find("<1e-15") == std::string::npos);
    }
    // No residual of the notes below the level (0, or below 1e-15) is printed as a number.
    static const std::regex below_level(R"(residual (0[ (,]|0$|[0-9.]+e-(1[6-9]|[2-9][0-9])))");
    CHECK(!std::regex_search(r.outcome.note, below_level));
  }
  // The paper has both kinds (equation (1.1)'s numeric samples agree to rounding; the ODE's
  // comparisons, to its tolerance).
  CHECK(rounding > 0);
  CHECK(above > 0);
}

TEST_CASE("Markdown report: a heading with an anchor and the math for every check",
          "[derivations]") {
  const std::string md = check::render(report(), check::Format::markdown);
  for (const auto& r : report().results) {
    CAPTURE(r.check.id);
    CHECK(count(md, "{#" + check::anchor(r.check.id) + "}") == 1);
    // The statement as the checker read it, but its \tag at the end of the display (MathJax 2
    // refuses one inside an environment; the docs' browser test sees that) and without \labels.
    static const std::regex tag(R"(\\tag\{[^}]*\})");
    static const std::regex tag_or_label(R"(\\(tag|label)\{[^}]*\})");
    CHECK(count(md, std::regex_replace(r.check.statement, tag_or_label, "")) >= 1);
    std::smatch found;
    if (std::regex_search(r.check.statement, found, tag)) {
      CHECK(count(md, found.str() + " \\f]") == 1);
    }
  }
  CHECK(check::anchor("eq-1.1") == "check-eq-1-1");
  // Doxygen math is \f$ ... \f$ or \f[ ... \f]: every dollar sign belongs to a \f$.
  CHECK(count(md, "$") == count(md, "\\f$"));
}
