// SPDX-License-Identifier: GPL-3.0-or-later
// Paper files whose models read the coefficients the file defines (sections 4 and 5): a system
// assembled from a file's a and b passes only when they are right, says nothing when the file does
// not define them, and a claim about what such a model gives is decided by the model, not by
// algebra. Small files of their own, run by the same engine as the paper's.
#include <catch2/catch.hpp>
#include <string>

#include "derivations/check.hpp"

namespace check = impulse::derivations;
using check::Status;

namespace {

const std::string preamble = R"(# Coefficients

arrow: p, F
index: i \in \{1, 2, 3\}
vector: n_v, n_i, n_1, n_2, n_3, v_{vt}, v_{vo}
assume: m > 0

section: 4

)";

// One check: the elastic coefficients @p a and @p b (right sides), tested by scenes of point
// masses whose blocks of them are summed and solved: the energy must be kept.
check::Report elastic(const std::string& a, const std::string& b,
                      const std::string& name = "elastic") {
  const std::string text = preamble +
                           "check: s-x step\n"
                           "model: point masses in scenes, the elastic coefficients summed\n"
                           "given:\n\n$$a_{vi(" +
                           name + ")} = " + a + " \\\\ b_{v(" + name + ")} = " + b +
                           "$$\n\ntest:\n\n$$E' = E$$\n";
  return check::run({{"coefficients.md", text}}, {"", 400, 3});
}

}  // namespace

TEST_CASE("A model that sums a file's coefficients passes them only when they are right",
          "[derivations][coefficients]") {
  // (4.5): a_vi = n_i . n_v / m, b_v = 2 p . n_v / m keep the kinetic energy of any scene.
  const auto right =
      elastic(R"(\frac{\vec{n_i} \cdot \vec{n_v}}{m})", R"(\frac{2\vec{p} \cdot \vec{n_v}}{m})");
  REQUIRE(right.results.size() == 1);
  CHECK(right.results[0].outcome.status == Status::verified);
  // (4.8)'s b under the elastic name: the bodies stick together and lose energy.
  const auto inelastic_b =
      elastic(R"(\frac{\vec{n_i} \cdot \vec{n_v}}{m})", R"(\frac{\vec{p} \cdot \vec{n_v}}{m})");
  CHECK(inelastic_b.results[0].outcome.status == Status::failed);
  // The sign of a dropped: the impulses push the wrong way.
  const auto sign =
      elastic(R"(-\frac{\vec{n_i} \cdot \vec{n_v}}{m})", R"(\frac{2\vec{p} \cdot \vec{n_v}}{m})");
  CHECK(sign.results[0].outcome.status == Status::failed);
}

TEST_CASE("A model finds nothing to test when the file does not define the coefficients it sums",
          "[derivations][coefficients]") {
  // Named otherwise, the model cannot read them: no point is tested, and the check is not
  // verified for it.
  const auto other = elastic(R"(\frac{\vec{n_i} \cdot \vec{n_v}}{m})",
                             R"(\frac{2\vec{p} \cdot \vec{n_v}}{m})", "bouncy");
  REQUIRE(other.results.size() == 1);
  CHECK(other.results[0].outcome.status == Status::failed);
  CHECK_THAT(other.results[0].outcome.note, Catch::Matchers::Contains("0 points"));
}

TEST_CASE(
    "A claim with an index is read per value; one that names a model is the model's to decide",
    "[derivations][coefficients]") {
  const std::string definitions = preamble + R"(check: s-e step
model: point masses in scenes, the elastic coefficients summed
given:

$$a_{vi(elastic)} = \frac{\vec{n_i} \cdot \vec{n_v}}{m} \\ b_{v(elastic)} = \frac{2\vec{p} \cdot \vec{n_v}}{m}$$

test:

$$E' = E$$

check: s-i step
model: point masses in scenes, the inelastic coefficients summed
given:

$$a_{vi(inelastic)} = \frac{\vec{n_i} \cdot \vec{n_v}}{m} \\ b_{v(inelastic)} = \frac{\vec{p} \cdot \vec{n_v}}{m}$$

test:

$$\vec{v_{vt}'} \cdot \vec{n_v} = \vec{v_{vo}'} \cdot \vec{n_v}$$

)";
  const auto claim = [&](const std::string& rows, const std::string& more) {
    return check::run({{"claims.md", definitions + "claim: c\n" + more + "\n$$" + rows + "$$\n"}},
                      {"", 400, 3}, "c");
  };
  // a_{vi(elastic)} stands for a_{v1(elastic)}, a_{v2(elastic)}, a_{v3(elastic)}: each equals
  // its inelastic twin, exactly.
  const auto same =
      claim(R"(a_{vi(elastic)} = a_{vi(inelastic)}, \quad b_{v(elastic)} = 2 b_{v(inelastic)})",
            "from: s-e, s-i");
  REQUIRE(same.results.size() == 1);
  CHECK(same.results[0].outcome.status == Status::verified);
  const auto twice = claim(R"(a_{vi(elastic)} = 2 a_{vi(inelastic)})", "from: s-e, s-i");
  CHECK(twice.results[0].outcome.status != Status::verified);
  // E' = E does not follow from algebra (E and E' are the model's), yet the scenes keep it: the
  // model decides, and it holds.
  const auto kept =
      claim("E' = E", "model: point masses in scenes, the elastic coefficients summed");
  CHECK(kept.results[0].outcome.status == Status::verified);
  CHECK_THAT(kept.results[0].outcome.note, Catch::Matchers::Contains("cases searched"));
  // The inelastic blocks lose energy: refuted by a scene, with the file's explanation.
  const auto lost = claim("E' = E",
                          "model: point masses in scenes, the inelastic coefficients summed\n"
                          "explanation: they stick.");
  CHECK(lost.results[0].outcome.status == Status::refuted);
}

TEST_CASE("A test: display is what the models test, not a premise of what follows",
          "[derivations][coefficients]") {
  // E' = E is a test of the check above; the claim after it, with nothing of its own to go on,
  // must not be proven from it.
  const std::string text = preamble + R"(check: s-e step
model: point masses in scenes, the elastic coefficients summed
given:

$$a_{vi(elastic)} = \frac{\vec{n_i} \cdot \vec{n_v}}{m} \\ b_{v(elastic)} = \frac{2\vec{p} \cdot \vec{n_v}}{m}$$

test:

$$E' = E$$

claim: c

$$E' = E$$
)";
  const auto report = check::run({{"test-premise.md", text}}, {"", 200, 3}, "c");
  REQUIRE(report.results.size() == 1);
  CHECK(report.results[0].outcome.status != Status::verified);
}
