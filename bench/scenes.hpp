// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Generated many-body scenes for the scaling benchmarks and for labs: stacks and
/// pyramids of rigid boxes, cradles of equal balls, with an exact number of contacts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/elasticity.hpp"
#include "impulse/multipoint/multipoint.hpp"

namespace impulse::scenes {

/// @brief A scene in the library's types, with the names the scene format needs.
struct Scene {
  std::vector<multipoint::Body> bodies;       ///< body 0 is the static ground (not in cradles)
  std::vector<std::string> names;             ///< one per body, unique
  std::vector<multipoint::Contact> contacts;  ///< exactly the number asked for
  Elasticity elasticity;                      ///< everyone's
};

/// @brief Boxes (1 wide, 0.5 high) stacked in one column on a static ground, each resting on the
/// one below at its two bottom corners and all falling at about 1 (with a little seeded spread
/// of masses, velocities and spins), elasticity 1.5.
///
/// Each box adds two contacts, the lowest two with the ground; an odd count ends with a box
/// that lands on one corner. The system is regular (three degrees of freedom per box for two
/// contacts) but its condition number grows with the square of the height.
/// @param contacts the number of contacts, at least 1
/// @param seed the seed of the spread
/// @return the scene
[[nodiscard]] Scene stack(std::size_t contacts, std::uint64_t seed = 1);

/// @brief A brick-pattern pyramid of boxes (1 wide, 0.5 high, 0.2 apart in a row): the bottom row
/// stands on a static ground at two corners each, every other box straddles two boxes below and
/// touches each at the two ends of their overlap (four contacts). Rows are filled bottom up, left
/// to right, until the count is reached (the last box may get fewer contacts), and the whole
/// pyramid falls at about 1 with a seeded spread, elasticity 1.2.
///
/// All normals are vertical and a box on two boxes has four contacts for three degrees of
/// freedom: the system is dependent and the minimum-norm rule decides how the impulses share.
/// @param contacts the number of contacts, at least 1
/// @param seed the seed of the spread
/// @return the scene
[[nodiscard]] Scene pyramid(std::size_t contacts, std::uint64_t seed = 1);

/// @brief A Newton's cradle: contacts + 1 equal balls (point masses of mass 1, 1 apart) in a
/// row, touching, the first moving at 1 towards the others, elasticity 2 (elastic).
/// @param contacts the number of contacts, at least 1
/// @return the scene
[[nodiscard]] Scene cradle(std::size_t contacts);

/// @brief A scene by kind name: "stack", "pyramid" or "cradle" (else InvalidInput).
/// @param kind the kind
/// @param contacts the number of contacts, at least 1
/// @param seed the seed (unused by the cradle)
/// @return the scene
[[nodiscard]] Scene generate(std::string_view kind, std::size_t contacts, std::uint64_t seed = 1);

/// @brief The scene with every rigid body also moving sideways (along x) at `speed`: a stack
/// that slides as it lands, for friction.
/// @param scene the scene
/// @param speed the added velocity along x
/// @return the scene, sliding
[[nodiscard]] Scene sliding(Scene scene, double speed = 1);

/// @brief The scene's bodies, elasticities (everyone's) and contacts, checked.
/// @param scene the scene
/// @return its configuration
[[nodiscard]] multipoint::Configuration configuration(const Scene& scene);

/// @brief The scene as a scene file (shared/spec/scene-format.md): dimension 2, the elasticity,
/// the bodies (rigid: mass, inertia, position, velocity, angular_velocity; material: mass,
/// velocity; static: nothing else) and the contacts by body name.
/// @param scene the scene
/// @return the JSON text, one body or contact per line
[[nodiscard]] std::string to_json(const Scene& scene);

}  // namespace impulse::scenes
