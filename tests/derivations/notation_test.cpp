// SPDX-License-Identifier: GPL-3.0-or-later
// The notation of spec/derivation-format.md, read as the contract says. Two writings the contract
// calls the same must follow from each other ("follows"); writings of different things must not.
// A test of the form "$$X = c$$ $$Y = c$$ → follows" can fail: were X and Y read as different
// symbols or values, the step would not follow and a counterexample would show it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "derivations/derivation.hpp"
#include "notation_pairs.hpp"

namespace d = impulse::derivations;

namespace {

using impulse::test::different;
using impulse::test::same;
using impulse::test::verdicts;

}  // namespace

TEST_CASE("Numbers and operators as the contract writes them", "[derivations][notation]") {
  same("0.5 x", "\\frac{1}{2} x");
  same("\\dfrac{1}{2} x", "\\tfrac{1}{2} x");
  same("\\frac12 x", "0.5 x");
  same("a \\cdot b", "a b");
  same("a \\times b", "ab");
  same("a / b \\cdot 2", "\\frac{2a}{b}", "assume: b > 0");
  same("\\sqrt{4} x", "2x");
  same("(a + b)^2", "\\left(a + b\\right)^2");
  same("[a + b]^2", "\\left[a + b\\right] \\left(b + a\\right)");
  same("a^{2}", "a a");
  same("\\tan x", "\\frac{\\sin x}{\\cos x}");
  same("\\sin^2 x + \\cos^2 x", "1");
  same("\\sin 2x", "2 \\sin x \\cos x");
  same("\\exp(\\ln b)", "b", "assume: b > 0");
  different("a - b", "b - a");
  different("2a", "a");
}

TEST_CASE("Spacing and names as the contract writes them", "[derivations][notation]") {
  same("a\\,b\\;c\\!d\\quad e", "abcde");
  same("E_{\\mathrm{kin}}", "E_{kin}");
  same("\\mathrm{E}_k", "E_k");
  same("\\text{elasticity} p", "\\mathrm{elasticity}\\, p");
  // One name, against a product of letters (a word without the letter i: a lone i is refused as
  // the imaginary unit, students_notation_test.cpp).
  different("\\mathrm{speed}", "speed");
}

TEST_CASE("Symbols: subscripts, primes, accents, \\Delta and dt", "[derivations][notation]") {
  same("p'_1", "p_1'");
  same("{p_1'}", "p'_1");
  same("p_{1}'", "p'_{1}");
  same("v_{vx}", "v_{vx}");
  same("\\vec{p} \\cdot \\vec n", "\\vec p \\cdot \\vec{n}", "vector: p, n");
  same("F dt", "Fdt");
  same("F\\,\\mathrm{d}t", "F dt");
  same("\\omega_1", "\\omega_{1}");
  different("p_1", "p_1'");
  different("p'", "p''");
  different("v_{vn}", "v_{on}");
  different("\\omega", "w");
  // \Delta E_o and dt are one symbol each: the counterexample names them, not their letters.
  const d::DerivationReport report =
      d::check_derivation("$$a = 1$$\n\n$$\\Delta E_o + F dt = a$$\n", "symbols.md");
  REQUIRE(report.equations.at(1).verdict == d::Verdict::does_not_follow);
  std::vector<std::string> names;
  for (const auto& v : report.equations.at(1).counterexample) {
    names.push_back(v.symbol);
  }
  CHECK(names == std::vector<std::string>{"F", "\\Delta E_o", "a", "dt"});
}

TEST_CASE("A division followed by a product: read where it is not ambiguous",
          "[derivations][notation]") {
  // A number over a number, then factors: the half of m v^2.
  same("1/2 m v^2", "\\frac{1}{2} m v^2");
  different("1/2 m v^2", "\\frac{1}{2 m} v^2");
  // Then a differential: F over m, times dt.
  same("F/m\\,dt", "\\frac{F}{m} dt");
  // Otherwise refused (errors_test.cpp): v^2/2g.
  CHECK_THROWS_AS(d::check_derivation("$$h = v^2/2g$$\n", "h.md"), d::DerivationError);
  CHECK_THROWS_AS(d::check_derivation("$$a = b/c d$$\n", "a.md"), d::DerivationError);
  // Written with parentheses it is read: a c d = b follows wherever a = b/(c d) is defined, and
  // not back where c d = 0.
  CHECK(verdicts("$$a = b/(c d)$$\n\n$$a c d = b$$") ==
        std::vector<std::string>{"premise", "follows-one-way"});
}

TEST_CASE("A differential written \\mathrm{d}p is one symbol", "[derivations][notation]") {
  // The contract's example, F \mathrm{d}t = \mathrm{d}p: the differential is a symbol of its own,
  // not the product of a symbol d and p.
  same("\\mathrm{d}p", "\\text{d}p");
  different("\\mathrm{d}p", "p");
  different("\\mathrm{d}p", "\\mathrm{d}p_1");
  // Read as products, d p = d p_1 + d p_2 would give p = p_1 + p_2 wherever d is not 0 (a
  // condition on a "d" the file never wrote). Differentials that add up say nothing of the
  // quantities: p = 1, p_1 = 1, p_2 = -1 with dp = 0, dp_1 = -1, dp_2 = 1 breaks the step.
  const d::DerivationReport report = d::check_derivation(
      "$$\\mathrm{d}p = \\mathrm{d}p_1 + \\mathrm{d}p_2$$\n\n$$p = p_1 + p_2$$\n",
      "differentials.md");
  REQUIRE(report.equations.at(1).verdict == d::Verdict::does_not_follow);
  std::vector<std::string> names;
  for (const auto& v : report.equations.at(1).counterexample) {
    names.push_back(v.symbol);
  }
  CHECK(std::find(names.begin(), names.end(), "d") == names.end());
  CHECK(std::find(names.begin(), names.end(), "\\mathrm{d}p") != names.end());
  // Divided by dt, as the paper does: F dt = dp gives F = dp / dt.
  CHECK(verdicts("$$F\\,\\mathrm{d}t = \\mathrm{d}p$$\n\n$$F = \\mathrm{d}p / \\mathrm{d}t$$") ==
        std::vector<std::string>{"premise", "follows-if"});
}

TEST_CASE("Vectors of the plane", "[derivations][notation]") {
  const std::string vectors = "vector: a, b\n";
  same("\\vec a \\cdot \\vec b", "a_x b_x + a_y b_y", vectors);
  same("\\det(\\vec a, \\vec b)", "a_x b_y - a_y b_x", vectors);
  same("\\|\\vec a\\|^2", "a_x^2 + a_y^2", vectors);
  same("\\left\\|\\vec a\\right\\|", "\\sqrt{a_x^2 + a_y^2}", vectors);
  same("(\\vec a + 2\\vec b) \\cdot [1, 0]", "a_x + 2 b_x", vectors);
  same("(\\vec a - \\vec b) \\cdot \\vec a", "\\|\\vec a\\|^2 - \\vec a \\cdot \\vec b", vectors);
  different("\\det(\\vec a, \\vec b)", "\\det(\\vec b, \\vec a)", vectors);
  // An equation between vectors holds component by component.
  CHECK(verdicts(vectors + "$$\\vec a = [1, 2]$$\n\n$$a_x = 1$$\n") ==
        std::vector<std::string>{"premise", "follows-one-way"});
  CHECK(verdicts(vectors + "$$\\vec a = [1, 2]$$\n\n$$[a_x, a_y] = [1, 2]$$\n") ==
        std::vector<std::string>{"premise", "follows"});
  // A counterexample gives a vector as [x, y].
  const auto report = d::check_derivation(vectors +
                                              "$$c = \\vec a \\cdot \\vec b$$\n\n"
                                              "$$c = a_x b_y$$\n",
                                          "v.md");
  REQUIRE(report.equations.at(1).verdict == d::Verdict::does_not_follow);
  bool vector_value = false;
  for (const auto& v : report.equations.at(1).counterexample) {
    vector_value = vector_value || (v.vector && (v.symbol == "a" || v.symbol == "b"));
  }
  CHECK(vector_value);
}

TEST_CASE("Blocks: rows, chains, environments and continued rows", "[derivations][notation]") {
  // A chain a = b = c is two equations; "&" is ignored; a row beginning with "=" continues it.
  CHECK(verdicts("$$a = b + b = 2b$$") == std::vector<std::string>{"premise", "follows"});
  CHECK(verdicts("$$\\begin{aligned} a &= b + b \\\\ &= 2b \\\\ a - 2b &= 0 \\end{aligned}$$") ==
        std::vector<std::string>{"premise", "follows", "follows"});
  CHECK(verdicts("$$\\begin{split} a &= b + b \\\\ &= 2b \\end{split}$$") ==
        std::vector<std::string>{"premise", "follows"});
  CHECK(verdicts("$$\\begin{gathered} a = b \\\\ a - b = 0 \\end{gathered}$$") ==
        std::vector<std::string>{"premise", "follows"});
  CHECK(verdicts("$$\\begin{align*} a &= b \\\\ a - b &= 0 \\end{align*}$$") ==
        std::vector<std::string>{"premise", "follows"});
  // A block on one line with prose around it; several blocks on a line.
  CHECK(verdicts("We have $$a = b$$ and so $$a - b = 0$$.") ==
        std::vector<std::string>{"premise", "follows"});
  // A row beginning with "+" continues the side before (a long right side).
  CHECK(verdicts("$$\\begin{aligned} a &= b \\\\ &\\quad + c \\end{aligned}$$\n\n$$a - b = c$$") ==
        std::vector<std::string>{"premise", "follows"});
  // Inline math and $$ in code are prose.
  CHECK(verdicts("Inline $a = 2$ is prose; so is `$$a = 3$$` in code.\n\n$$a = b$$") ==
        std::vector<std::string>{"premise"});
}

TEST_CASE("Directives: given, from, let, assume", "[derivations][notation]") {
  // Every equation of the block after given: is a premise; the step after follows from all.
  CHECK(verdicts("given:\n\n$$a = b \\\\ c = d$$\n\n$$a + c = b + d$$") ==
        std::vector<std::string>{"premise", "premise", "follows-one-way"});
  // from: names the equations a step follows from instead of the one before.
  CHECK(verdicts("$$a = 1 \\tag{1}$$\n\n$$b = 2$$\n\nfrom: (1)\n\n$$2a = 2$$") ==
        std::vector<std::string>{"premise", "does-not-follow", "follows"});
  // let: the symbol stands for its expression in later equations.
  CHECK(verdicts("let: E = \\frac{1}{2} m v^2\n\n$$E = a$$\n\n$$m v^2 = 2a$$") ==
        std::vector<std::string>{"premise", "follows"});
  // assume: a division by a symbol assumed non-zero needs no condition.
  CHECK(verdicts("$$F x = F y$$\n\n$$x = y$$") ==
        std::vector<std::string>{"premise", "follows-if"});
  CHECK(verdicts("assume: F \\neq 0\n\n$$F x = F y$$\n\n$$x = y$$") ==
        std::vector<std::string>{"premise", "follows"});
  CHECK(verdicts("assume: m_1, m_2 > 0\n\n$$(m_1 + m_2) x = 1$$\n\n$$x = \\frac{1}{m_1 + m_2}$$") ==
        std::vector<std::string>{"premise", "follows"});
  // \geq alone does not keep a factor from zero.
  CHECK(verdicts("assume: F \\geq 0\n\n$$F x = F y$$\n\n$$x = y$$") ==
        std::vector<std::string>{"premise", "follows-if"});
}

TEST_CASE("The JSON report has the contract's keys", "[derivations][notation]") {
  const auto report = d::check_derivation(
      "assume: m_1, m_2 > 0\n\n$$F\\,dt\\left(\\frac{1}{m_1}+\\frac{1}{m_2}\\right) = "
      "\\frac{2p_1}{m_1}\\cdot F\\,dt \\tag{2}$$\n\n$$\\frac{1}{m_1}+\\frac{1}{m_2} = "
      "\\frac{2p_1}{m_1}$$\n\n$$p_1 = 2$$\n",
      "elastic.md");
  const auto json = nlohmann::json::parse(d::render(report, d::Format::json));
  CHECK(json["file"] == "elastic.md");
  const auto& e = json["equations"];
  REQUIRE(e.size() == 3);
  CHECK(e[0]["line"] == 3);
  CHECK(e[0]["tag"] == "2");
  CHECK(e[0]["verdict"] == "premise");
  CHECK(e[1]["tag"].is_null());
  CHECK(e[1]["verdict"] == "follows-if");
  CHECK(e[1]["condition"].get<std::string>().find("\\neq 0") != std::string::npos);
  CHECK(e[2]["verdict"] == "does-not-follow");
  CHECK(e[2]["residual"].is_string());
  CHECK(e[2]["counterexample"]["p_1"].is_number());
  CHECK(e[2]["counterexample"]["m_1"].is_number());
  for (const char* key : {"premise", "follows", "follows-one-way", "follows-if", "does-not-follow",
                          "dimensions", "undecided"}) {
    CHECK(json["summary"].contains(key));
  }
  CHECK(json["summary"]["does-not-follow"] == 1);
  CHECK(d::exit_status(report) == 1);
}

TEST_CASE("What is left of a step is shown factored, without terms that cancel",
          "[derivations][notation]") {
  // From ΔK = ½ m v² (1 - e)(1 + e) the step ΔK = J² (1 - e) / (2 m (1 + e)) leaves, over one
  // denominator (by hand):
  //   ½ m v² (1 - e)(1 + e) - J² (1 - e) / (2 m (1 + e))
  //     = (1 - e) (m² v² (1 + e)² - J²) / (2 m (1 + e))
  //     = (1 - e) (m v (1 + e) - J) (m v (1 + e) + J) / (2 m (1 + e)).
  // GiNaC 1.8's factorisation wrote each of the two last factors with terms that cancel,
  // (e v + v) m - 10 (1 + e) m + 10 e m + 10 m - J, and that was what the report showed.
  const auto report = d::check_derivation(
      "assume: m > 0, 0 \\le e \\le 1\n\n$$\\Delta K = \\frac12 m v^2 (1-e)(1+e)$$\n\n"
      "$$\\Delta K = \\frac{J^2 (1-e)}{2 m (1+e)}$$\n",
      "energy.md");
  REQUIRE(report.equations.size() == 2);
  const auto& step = report.equations[1];
  REQUIRE(step.verdict == d::Verdict::does_not_follow);
  CAPTURE(step.residual, step.residual_text);
  CHECK(step.residual.find("10") == std::string::npos);
  CHECK(step.residual.find("e m v + m v - J") != std::string::npos);
  CHECK(step.residual.find("e m v + m v + J") != std::string::npos);
  CHECK(step.residual.find("1 - e") != std::string::npos);
}
