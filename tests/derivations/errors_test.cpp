// SPDX-License-Identifier: GPL-3.0-or-later
// Derivation files that cannot be read: each is refused with the place (line and column) where
// the reader stopped and what it expected there; nothing is checked. The places were counted by
// hand in each file (tests/derivations/malformed/); the hostile inputs (deep nesting, binary
// bytes, huge files, thousands of equations) are made here.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "derivations/derivation.hpp"

namespace d = impulse::derivations;

namespace {

struct Expected {
  std::size_t line;
  std::size_t column;
  std::string fragment;  // part of the message
};

// file → where it is refused (counted by hand) and what the message says.
const std::map<std::string, Expected> expected{
    {"unbalanced-brace.md", {3, 17, "expected '}' to close this '{'"}},  // the { of {2m
    {"unknown-command.md", {3, 7, "unknown command \\foo"}},
    {"block-never-closed.md", {3, 1, "closed by $$"}},
    {"assume-not-a-form.md", {3, 9, "expected facts of the forms"}},  // the m of m \in \{1, 2\}
    {"assume-not-zero.md", {3, 11, "on both sides of '>'"}},          // the > of m >
    {"missing-tag.md", {5, 7, "no equation before this line carries \\tag{2}"}},
    {"no-equation.md", {4, 1, "expected a display equation"}},  // the end of the file
    {"expression-alone.md", {3, 3, "found an expression without '='"}},
    {"vector-equals-scalar.md", {5, 12, "expected a vector on this side"}},  // the m
    {"unknown-environment.md", {3, 3, "found {pmatrix}: a matrix is declared"}},
    {"environment-not-ended.md", {3, 3, "expected \\end{aligned}"}},
    {"duplicate-tag.md", {5, 3, "an equation above already carries"}},
    {"given-at-end.md", {5, 1, "expected a display block after given:"}},
    {"from-at-end.md", {5, 1, "expected a display equation after from:"}},
    // The first $ (line 3, column 8): |x| = 3 on the line of given: was never read, and x = 3,
    // the next block, was taken as the premise (every step followed).
    {"given-on-its-line.md", {3, 8, "expected nothing after given:"}},
    {"let-self.md", {3, 11, "does not use x itself"}},  // the x of 2x
    {"contradictory-facts.md", {4, 9, "m < 0 contradicts m > 0"}},
    {"units-not-mlt.md", {3, 11, "found 'm'"}},
    {"relation-in-block.md", {3, 5, "found the relation \\leq"}},
    {"empty-block.md", {3, 1, "found nothing"}},
    {"exponent-too-large.md", {3, 10, "an exponent of at most 1000"}},
    {"comment-not-closed.md", {3, 1, "closed by -->"}},
    {"fence-not-closed.md", {3, 1, "closed by ```"}},
    {"det-of-scalars.md", {3, 12, "expected two vectors in \\det"}},
    {"assume-vector.md", {4, 9, "a vector"}},
    {"extra-brace.md", {3, 8, "it closes no '{'"}},
    {"left-without-right.md", {3, 19, "expected \\right to close the \\left at line 3, column 7"}},
    {"dangling-operator.md", {3, 10, "expected a term, found the end of the expression"}},
    {"vectors-side-by-side.md", {5, 14, "between two vectors, found them side by side"}},
    {"divide-by-zero.md", {3, 7, "found a division by zero"}},
    {"continues-nothing.md", {3, 3, "begins with '='"}},
    {"vector-after-use.md", {5, 9, "declared a vector before it is used"}},
    {"text-prose.md", {4, 11, "words belong outside the display block"}},
    // The \frac of dy/dx (line 5, column 3): y is no declared function, so its derivative
    // would be 0 (read as d y over d x it would cancel to y / x).
    {"derivative.md", {5, 3, "nothing in y holds x"}},
    // The p of \mathrm{d}p (line 5, column 30): dp is one symbol, which would have nothing to do
    // with the function p.
    {"differential-of-function.md", {5, 30, "p is declared a function"}},
    // The \vec of \vec a (line 3, column 8): a and b are not declared vectors, so \cdot would
    // multiply numbers, and (a b)^2 = a^2 b^2 would follow where (a . b)^2 = |a|^2 |b|^2 does not.
    {"dot-of-undeclared.md", {3, 8, "written as a vector but not declared one"}},
    // The g of v^2/2g (line 5, column 12): (v^2/2) g as read from left to right, v^2/(2g) as a
    // student means it.
    {"division-then-product.md", {5, 12, "a/b c could be a over b, times c"}},
    // The \text of \text{or} (line 5, column 14): x = 3 or x = -3 are cases, one of which
    // holds; read as two steps, x = -3 would not follow from x^2 = 9 where x = 3.
    {"cases-joined-by-or.md", {5, 14, "does not join two equations by 'or'"}},
    // The x of x(t) (line 3, column 3): x not declared a function, x(t) was x times t, and
    // x(0) = 0 followed (x times 0), though the function's value at 0 is x_0.
    {"value-of-undeclared.md", {3, 3, "x times t?"}},
    // The second \mathrm, of \mathrm{d}(m v) (line 3, column 20).
    {"differential-of-expression.md", {3, 20, "of an expression it is not read"}},
};

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The error a text is refused with; fails the test if it is read.
d::DerivationError refusal(const std::string& text) {
  try {
    (void)d::check_derivation(text, "test.md");
  } catch (const d::DerivationError& e) {
    return e;
  }
  FAIL("the file was read");
  return {0, 0, ""};
}

}  // namespace

TEST_CASE("Malformed derivation files: refused with the place and what was expected",
          "[derivations][errors]") {
  std::size_t files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(IMPULSELAB_DERIVATION_MALFORMED_DIR)) {
    const std::string name = entry.path().filename().string();
    INFO(name);
    const auto e = expected.find(name);
    REQUIRE(e != expected.end());  // every file has its expectation
    const d::DerivationError error = refusal(read(entry.path()));
    INFO(error.line() << ":" << error.column() << ": " << error.what());
    CHECK(error.line() == e->second.line);
    CHECK(error.column() == e->second.column);
    CHECK(std::string(error.what()).find(e->second.fragment) != std::string::npos);
    ++files;
  }
  CHECK(files == expected.size());
}

TEST_CASE("Hostile derivation files: refused, never a crash, a hang or a stack overflow",
          "[derivations][errors]") {
  SECTION("nesting thousands deep") {
    const std::string deep =
        "$$a = " + std::string(5000, '(') + "b" + std::string(5000, ')') + "$$";
    const auto e = refusal(deep);
    CHECK(std::string(e.what()).find("levels of nesting") != std::string::npos);
    const std::string braces =
        "$$a = " + std::string(5000, '{') + "b" + std::string(5000, '}') + "$$";
    CHECK(std::string(refusal(braces).what()).find("levels of nesting") != std::string::npos);
    std::string fractions = "b";
    for (int i = 0; i < 1500; ++i) {  // 15,000 characters: within the size limit
      fractions = "\\frac{" + fractions + "}{2}";
    }
    CHECK(std::string(refusal("$$a = " + fractions + "$$").what()).find("nesting") !=
          std::string::npos);
  }
  SECTION("binary bytes") {
    // A NUL byte on line 2, column 3; an invalid UTF-8 byte on line 1, column 5.
    const auto nul = refusal(std::string("ab\ncd") + '\0' + "e");
    CHECK(nul.line() == 2);
    CHECK(nul.column() == 3);
    CHECK(std::string(nul.what()).find("binary") != std::string::npos);
    const auto bad = refusal("$$a \xFF= b$$");
    CHECK(bad.line() == 1);
    CHECK(bad.column() == 5);
    std::string garbage;
    for (int i = 0; i < 4096; ++i) {
      garbage += static_cast<char>((i * 131 + 7) % 256);
    }
    (void)refusal(garbage);
  }
  SECTION("a display ending just after a group, where the reader looks ahead for primes") {
    // Found by the fuzzer (it read past the line's tokens under ASan): `{p}` last on the line
    // makes the reader look two tokens ahead for `^{\prime}`. Read as written: a premise.
    const auto report = d::check_derivation("# x\n\n$$E = dfoo{p}$$\n", "test.md");
    REQUIRE(report.equations.size() == 1);
    CHECK(report.equations[0].verdict == d::Verdict::premise);
    CHECK(refusal("$$a = v^{").line() == 1);
  }
  SECTION("powers of a thousand: decided without expanding them") {
    // (c+b+a)^{999}(a+b+c) is (a+b+c)^{1000} as GiNaC writes products of powers; with d for the
    // last c the difference is (a+b+c)^{999}(c - d), not zero (a = b = 0, c = 1, d = 0 gives 1).
    // Expanded, either side would be half a million terms: the checker must not try.
    const std::string premise = "$$x = (a+b+c)^{1000}$$\n\n";
    const auto same = d::check_derivation(premise + "$$x = (c+b+a)^{999}(a+b+c)$$\n", "t.md");
    CHECK(same.equations.at(1).verdict == d::Verdict::follows);
    const auto slip = d::check_derivation(premise + "$$x = (c+b+a)^{999}(a+b+d)$$\n", "t.md");
    CHECK(slip.equations.at(1).verdict == d::Verdict::does_not_follow);
  }
  SECTION("more than the limits") {
    const std::string big(d::max_derivation_bytes + 1, 'a');
    const auto e = refusal(big);
    CHECK(e.line() == 1);
    CHECK(e.column() == 1);
    CHECK(std::string(e.what()).find("at most 4 MiB") != std::string::npos);
    std::string many;
    for (int i = 0; i < 2001; ++i) {
      many += "$$a = b$$\n";
    }
    CHECK(std::string(refusal(many).what()).find("at most 2000 display blocks") !=
          std::string::npos);
    CHECK(std::string(refusal("$$a = " + std::string(410, '9') + "$$").what())
              .find("a number of at most 400 characters") != std::string::npos);
    // (10^{900})^{900} would be a number of 810,000 digits.
    CHECK(std::string(refusal("$$a = {10^{900}}^{900}$$").what()).find("digits") !=
          std::string::npos);
  }
}
