// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Serial collisions: one contact at a time, the fastest-approaching first.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/core/names.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::methods {

/// @brief How serial collisions ended.
enum class SerialStatus {
  finished,         ///< no contact approaches any more
  collision_limit,  ///< the bound on collisions was reached while a contact still approached
  non_finite,       ///< a collision gave a NaN or an infinity (numbers beyond doubles)
};

/// @brief Collisions allowed per contact when SerialOptions::max_collisions is 0 ...
inline constexpr std::int64_t collisions_per_contact = 100;

/// @brief ... and at least this many: about what the interactive page (collide.html) runs in
/// WebAssembly within one frame by the slowest rule (the exact rule with friction, about 1 µs a
/// collision; the paper's formula takes about a quarter), so that a scene whose collisions do not
/// end (a stack of boxes below elasticity 2, an inelastic collapse) is refused while a slider
/// still moves smoothly. A scene that needs more sets `solver.max_collisions`.
inline constexpr std::int64_t least_collisions = 10'000;

/// @brief The bound on serial collisions when SerialOptions::max_collisions is 0.
/// @param contacts the number of contacts
/// @return the larger of collisions_per_contact times @p contacts and least_collisions
[[nodiscard]] constexpr std::int64_t default_collision_bound(std::int64_t contacts) {
  return contacts * collisions_per_contact > least_collisions ? contacts * collisions_per_contact
                                                              : least_collisions;
}

/// @brief The default bound in words, as the refusals say it.
/// @return "100 per contact, at least 10000"
[[nodiscard]] std::string default_collision_bound_words();

/// @brief The largest bound on serial collisions a scene may ask for (each costs a few
/// microseconds: 10⁹ of them take tens of minutes).
inline constexpr std::int64_t most_collisions = 1'000'000'000;

/// @brief The bound and the tolerance of serial collisions.
struct SerialOptions {
  /// The most collisions before giving up; 0 means default_collision_bound() of the number of
  /// contacts. Negative values throw InvalidInput. (A scene's bound, `solver.max_collisions`,
  /// is a whole number from 1 to most_collisions.)
  std::int64_t max_collisions = 0;
  /// A contact approaches when its approach speed exceeds this fraction of the largest speed of
  /// a body's point at any contact before the collisions (rounding leaves a resolved contact at
  /// about 1e-16 of it).
  double approach_tolerance = 1e-12;
};

/// @brief What serial collisions did, besides the impulses.
struct SerialDiagnostics {
  SerialStatus status = SerialStatus::finished;  ///< finished, or why not
  std::vector<Eigen::Index> order;  ///< the contact resolved at each collision, in turn
  /// The order cut into passes: a pass ends where a contact comes up that the pass has already
  /// resolved. One pass means that no contact needed a second collision.
  std::int64_t passes = 0;
  std::int64_t max_collisions = 0;      ///< the bound that applied
  double approach_threshold = 0.0;      ///< the approach speed above which a contact approaches
  Eigen::Index still_approaching = -1;  ///< collision_limit: the fastest contact left, else -1
  double approach_left = 0.0;           ///< collision_limit: its approach speed
};

/// @brief Serial collisions of a scene: the impulses, the bodies after and the diagnostics.
struct SerialResolution {
  SerialDiagnostics diagnostics;        ///< status, order, passes, bound
  Eigen::VectorXd Fdt;                  ///< the sum of the impulses each contact received
  std::vector<multipoint::Body> after;  ///< the bodies after the last collision
};

/// @brief Resolves the contacts one at a time: the contact with the largest approach speed
/// (above SerialOptions::approach_tolerance of the speeds; the lowest index among equal speeds)
/// collides alone, then the next, until no contact approaches or the bound on collisions is
/// reached.
///
/// Each collision is the paper's single-contact formula for its two bodies: the 1×1 system
/// @f$ F\,dt\,(a_1 + a_2) = b_1 + b_2 @f$ of their shares of that one contact
/// (multipoint::share: (1.3), the cast of section 2, or (3.6)/(3.10)), each body with its own
/// elasticity. The bodies after are the state the last collision left (not the summed impulses
/// applied again). At elasticity 2 each collision keeps the kinetic
/// energy, so the whole sequence does; below 2 the same pair can collide again and again (a
/// partly elastic collision leaves the first body following the second), in principle without
/// end (inelastic collapse), which the bound cuts off with SerialStatus::collision_limit.
/// @param bodies the bodies (validated with the contacts, InvalidInput)
/// @param elasticities one per body (a size mismatch throws InvalidInput)
/// @param contacts the contacts
/// @param options the bound and the tolerance
/// @return the summed impulses, the bodies after and the order of the collisions
[[nodiscard]] SerialResolution resolve_serial(std::span<const multipoint::Body> bodies,
                                              std::span<const Elasticity> elasticities,
                                              std::span<const multipoint::Contact> contacts,
                                              const SerialOptions& options = {});

/// @brief As the other overload, every body with the same elasticity.
/// @param bodies the bodies
/// @param elasticity everyone's elasticity
/// @param contacts the contacts
/// @param options the bound and the tolerance
/// @return the summed impulses, the bodies after and the order of the collisions
[[nodiscard]] SerialResolution resolve_serial(std::span<const multipoint::Body> bodies,
                                              Elasticity elasticity,
                                              std::span<const multipoint::Contact> contacts,
                                              const SerialOptions& options = {});

/// @brief Serial collisions in slices: the collisions of resolve_serial(), a bounded number at a
/// time, for a caller that must return within a frame (a page that redraws as a slider moves, an
/// engine with a time budget per step). Advanced to their end in one slice or in many, they end
/// in the same state, bit for bit: each collision depends only on the state the last one left.
///
/// The configuration must outlive this object.
class SerialCollisions {
 public:
  /// @brief One collision at contact @p v: changes @p state (the bodies) and returns the normal
  /// impulse, or nothing when a number overflowed.
  using Collide =
      std::function<std::optional<double>(Eigen::Index v, std::vector<multipoint::Body>& state)>;

  /// @brief The configuration's serial collisions, each the paper's single-contact formula
  /// (resolve_serial()'s).
  /// @param configuration the bodies, elasticities and contacts
  /// @param options the bound and the tolerance (checked: InvalidInput)
  explicit SerialCollisions(const multipoint::Configuration& configuration,
                            const SerialOptions& options = {});
  /// @brief The configuration's serial collisions, each by @p collide (the exact rule with
  /// friction, say; an empty one is the paper's formula).
  /// @param configuration the bodies, elasticities and contacts
  /// @param options the bound and the tolerance (checked: InvalidInput)
  /// @param collide one collision
  SerialCollisions(const multipoint::Configuration& configuration, const SerialOptions& options,
                   Collide collide);
  /// @brief Frees its state.
  ~SerialCollisions();
  /// @brief Takes over another collisions (which is left without state).
  /// @param other the one taken over
  SerialCollisions(SerialCollisions&& other) noexcept;
  /// @brief Takes over another collisions (which is left without state).
  /// @param other the one taken over
  /// @return this one
  SerialCollisions& operator=(SerialCollisions&& other) noexcept;

  /// @brief Runs at most @p collisions more collisions (fewer when they end first).
  /// @param collisions how many at most (at least 1)
  /// @return whether the collisions have ended (no contact approaches, the bound, an overflow)
  bool advance(std::int64_t collisions);
  /// @brief Whether the collisions have ended.
  /// @return true once advance() has returned true
  [[nodiscard]] bool ended() const;
  /// @brief The collisions so far.
  /// @return their number
  [[nodiscard]] std::int64_t collisions() const;
  /// @brief The impulses, the bodies and the diagnostics so far (the passes counted once the
  /// collisions have ended).
  /// @return the resolution
  [[nodiscard]] const SerialResolution& resolution() const;
  /// @brief The resolution moved out, once the collisions have ended (this object is then
  /// spent).
  /// @return the impulses, the bodies after and the diagnostics
  [[nodiscard]] SerialResolution take() &&;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// @brief Serial collisions of a configuration checked when it was made.
/// @param configuration the bodies, elasticities and contacts
/// @param options the bound and the tolerance (checked: InvalidInput)
/// @return the summed impulses, the bodies after and the order of the collisions
[[nodiscard]] SerialResolution resolve_serial(const multipoint::Configuration& configuration,
                                              const SerialOptions& options = {});

/// @brief The passes of an order of collisions: the order cut wherever a contact comes up that
/// the current pass has already resolved.
/// @param order the contacts in the order they collided
/// @return the number of passes (0 for no collision)
[[nodiscard]] std::int64_t count_passes(std::span<const Eigen::Index> order);

}  // namespace impulse::methods

namespace impulse {
/// @brief The names of the statuses of serial collisions.
template <>
struct EnumNames<methods::SerialStatus> {
  /// "finished", "collision-limit", "non-finite"
  static constexpr std::array<Named<methods::SerialStatus>, 3> table{
      {{methods::SerialStatus::finished, "finished"},
       {methods::SerialStatus::collision_limit, "collision-limit"},
       {methods::SerialStatus::non_finite, "non-finite"}}};
};
}  // namespace impulse
