// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief A body checked once, when it is made: the collisions that take it check nothing.
#pragma once

namespace impulse {

/// @brief A body of one of the single-contact sections (one_d::Body, material_2d::PointMass,
/// rigid_2d::RigidBody) whose numbers were checked when it was made.
///
/// The constructor runs the section's `validate(body, name)` (found next to the body's type):
/// bad input is refused there, with its message (`"bumper.mass must be positive and finite,
/// got -1"`). A Checked body cannot be changed, so it stays valid, and the `collide` overloads
/// that take Checked bodies and an impulse::UnitNormal test nothing: an engine checks a body once
/// and collides it many times at the cost of the bare formula (bench/single_contact.cpp).
///
/// The bodies a collision returns are plain bodies: a body changed by an impulse is checked
/// again when it is made Checked again (its momentum could in principle have overflowed).
/// @tparam Body the section's body type
template <typename Body>
class Checked {
 public:
  /// @brief Checks @p body; InvalidInput with the section's message if it is refused.
  /// @param body the body
  /// @param name how messages name it ("bumper", "bodies[2]")
  explicit Checked(const Body& body, const char* name = "body") : body_(body) {
    validate(body_, name);  // the section's own check, found by argument-dependent lookup
  }

  /// @brief The body.
  /// @return the checked body
  [[nodiscard]] const Body& get() const { return body_; }

  /// @brief The body's members.
  /// @return the checked body
  const Body* operator->() const { return &body_; }

 private:
  Body body_;
};

}  // namespace impulse
