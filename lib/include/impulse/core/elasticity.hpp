// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief The paper's elasticity parameter (section 1.3).
#pragma once

namespace impulse {

/// @brief The paper's elasticity: the factor in front of each body's momentum term in (1.3).
///
/// @f$ e = 1 @f$ is perfectly inelastic (the normal velocities are equalised),
/// @f$ e = 2 @f$ perfectly elastic (kinetic energy is conserved). In terms of the usual
/// coefficient of restitution @f$ c @f$, @f$ e = 1 + c @f$: the bodies separate after the
/// collision at @f$ c @f$ times the speed at which they approached.
///
/// Values above 2 add energy and values in (0, 1) leave the bodies still approaching; the type
/// accepts them because the labs study them. Negative and non-finite values are refused.
class Elasticity {
 public:
  /// @brief Perfectly inelastic by default (e = 1).
  constexpr Elasticity() = default;

  /// @brief An elasticity of the given value.
  /// @param value e, finite and @f$ \ge 0 @f$; otherwise InvalidInput is thrown
  explicit Elasticity(double value);

  /// @brief e = 1: the normal velocities at the contact are equal after the collision.
  /// @return the perfectly inelastic elasticity
  [[nodiscard]] static constexpr Elasticity inelastic() { return Elasticity(Tag{}, 1.0); }

  /// @brief e = 2: kinetic energy is conserved.
  /// @return the perfectly elastic elasticity
  [[nodiscard]] static constexpr Elasticity elastic() { return Elasticity(Tag{}, 2.0); }

  /// @brief e = 1 + c from a coefficient of restitution c.
  /// @param restitution c, finite and @f$ \ge -1 @f$ (so that e is not negative)
  /// @return the elasticity 1 + c
  [[nodiscard]] static Elasticity from_restitution(double restitution);

  /// @brief The paper's elasticity e.
  /// @return e
  [[nodiscard]] constexpr double value() const { return value_; }

  /// @brief The coefficient of restitution e - 1.
  /// @return c = e - 1
  [[nodiscard]] constexpr double restitution() const { return value_ - 1.0; }

  /// @brief Elasticities compare by value.
  /// @param other the elasticity to compare with
  /// @return whether both hold the same e
  [[nodiscard]] constexpr bool operator==(const Elasticity& other) const = default;

 private:
  struct Tag {};
  constexpr Elasticity(Tag /*unchecked*/, double value) : value_(value) {}
  double value_ = 1.0;
};

}  // namespace impulse
