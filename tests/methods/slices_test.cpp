// SPDX-License-Identifier: GPL-3.0-or-later
// Serial collisions in slices (SerialCollisions, SerialMethod): advanced a few collisions at a
// time they end in exactly the state resolve_serial() and serial() reach in one call, because each
// collision depends only on the state the one before left.
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/methods/resolve.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "scenes.hpp"

namespace mp = impulse::multipoint;
namespace me = impulse::methods;

namespace {

// Bit for bit: the same collisions in the same order, the same sums and the same bodies after.
void require_same(const me::SerialResolution& a, const me::SerialResolution& b) {
  REQUIRE(a.diagnostics.order == b.diagnostics.order);
  CHECK(a.diagnostics.status == b.diagnostics.status);
  CHECK(a.diagnostics.passes == b.diagnostics.passes);
  CHECK(a.diagnostics.still_approaching == b.diagnostics.still_approaching);
  CHECK(a.diagnostics.approach_left == b.diagnostics.approach_left);
  CHECK(a.Fdt == b.Fdt);
  REQUIRE(a.after.size() == b.after.size());
  for (std::size_t k = 0; k < a.after.size(); ++k) {
    // A body's motion, whatever its kind: the velocity of three of its points (a spin shows).
    for (const Eigen::Vector2d& point :
         {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)}) {
      CHECK(mp::point_velocity(a.after[k], point) == mp::point_velocity(b.after[k], point));
    }
  }
}

}  // namespace

TEST_CASE("Serial collisions in slices end where one call ends, bit for bit",
          "[methods][section5]") {
  // The stack of 20 boxes (elasticity 1.5) runs to its bound (10000 collisions); the cradle of
  // 21 balls (elasticity 2) ends after one collision per contact; the pyramid (1.2) in between.
  for (const char* kind : {"stack", "cradle", "pyramid"}) {
    const auto scene = impulse::scenes::generate(kind, 40);
    const mp::Configuration configuration = impulse::scenes::configuration(scene);
    const me::SerialResolution whole = me::resolve_serial(configuration);
    for (const std::int64_t slice : {1, 7, 1000}) {
      CAPTURE(kind, slice);
      me::SerialCollisions collisions(configuration);
      std::int64_t calls = 0;
      while (!collisions.advance(slice)) {
        ++calls;
        // An unended slice runs exactly as many collisions as it was given.
        REQUIRE(collisions.collisions() == calls * slice);
        REQUIRE_FALSE(collisions.ended());
      }
      CHECK(collisions.ended());
      require_same(collisions.resolution(), whole);
    }
  }
}

TEST_CASE("Serial collisions in slices: the end is seen without another call", "[methods]") {
  // The cradle of 3 balls needs 2 collisions: a slice of 2 ends them, and says so.
  const auto scene = impulse::scenes::generate("cradle", 2);
  const mp::Configuration configuration = impulse::scenes::configuration(scene);
  me::SerialCollisions collisions(configuration);
  CHECK(collisions.advance(2));
  CHECK(collisions.collisions() == 2);
  CHECK(collisions.resolution().diagnostics.status == me::SerialStatus::finished);
  CHECK(collisions.resolution().diagnostics.passes == 1);
  // A bound of 3 on the stack: the third collision's slice ends at the bound, with what still
  // approaches.
  const auto stack = impulse::scenes::generate("stack", 10);
  const mp::Configuration stacked = impulse::scenes::configuration(stack);
  me::SerialCollisions bounded(stacked, {.max_collisions = 3});
  CHECK_FALSE(bounded.advance(2));
  CHECK(bounded.advance(1));
  CHECK(bounded.resolution().diagnostics.status == me::SerialStatus::collision_limit);
  CHECK(bounded.resolution().diagnostics.still_approaching >= 0);
  CHECK_THROWS_AS(bounded.advance(0), impulse::InvalidInput);
}

TEST_CASE("The serial method in slices gives serial()'s outcome", "[methods][section5]") {
  const auto scene = impulse::scenes::generate("stack", 40);
  const mp::Configuration configuration = impulse::scenes::configuration(scene);
  const me::Options options;
  const me::Paper paper = me::paper(configuration, options.solver);
  const me::Outcome whole = me::serial(configuration, paper, options);
  me::SerialMethod sliced(configuration, paper, options);
  CHECK(sliced.bound() == 10000);  // 100 per contact (4000), at least 10000
  while (!sliced.advance(333)) {
  }
  const me::Outcome outcome = sliced.finish();
  CHECK(outcome.Fdt == whole.Fdt);
  CHECK(outcome.finished == whole.finished);
  CHECK(outcome.unfinished == whole.unfinished);
  CHECK(outcome.details == whole.details);
  CHECK(outcome.summary == whole.summary);
  CHECK(outcome.residual == whole.residual);
}
