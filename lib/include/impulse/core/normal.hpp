// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief A contact normal checked once: made from any finite non-zero vector, or from an angle.
#pragma once

#include <Eigen/Core>
#include <string_view>

namespace impulse {

/// @brief A unit normal, checked (and if need be scaled to unit length) when it is made, so that
/// a collision along it checks nothing.
///
/// A vector whose length is 1 within impulse::unit_normal_tolerance is kept exactly as given
/// (the scene format's unit normals keep their digits); any other finite non-zero vector is
/// divided by its length, and rescaled() says so, with given_length(). The division is carried
/// out after an exact scaling by a power of two, so that vectors of any size, subnormal ones
/// included, come out unit to rounding. A normal on a line is the vector (±1, 0).
class UnitNormal {
 public:
  /// @brief The unit normal along @p direction.
  /// @param direction a finite, non-zero vector; otherwise InvalidInput, e.g.
  ///        `"normal must be a finite non-zero vector, got [0, 0]"`
  explicit UnitNormal(const Eigen::Vector2d& direction) : UnitNormal("normal", direction) {}

  /// @brief The unit normal along @p direction, messages naming it @p what.
  /// @param what the quantity's name as a refusal shows it ("contacts[2].normal")
  /// @param direction a finite, non-zero vector
  UnitNormal(std::string_view what, const Eigen::Vector2d& direction);

  /// @brief The unit normal at @p degrees counter-clockwise from the x axis:
  /// @f$ (\cos\theta, \sin\theta) @f$. Multiples of 90° are exact ((0, 1) at 90°, not
  /// (6e-17, 1)): the angle is reduced to within 45° of one before its cosine and sine are taken.
  /// @param degrees the angle, finite (else InvalidInput naming "normal_angle")
  /// @return the normal
  [[nodiscard]] static UnitNormal from_degrees(double degrees);

  /// @brief The unit vector.
  /// @return n, of length 1 within unit_normal_tolerance
  [[nodiscard]] const Eigen::Vector2d& vector() const { return n_; }

  /// @brief @f$ \|\vec{n}\|^2 @f$, computed once: 1 within about 2e-9 (to rounding for a normal
  /// that was rescaled or made from an angle). The single-contact formulas divide it by each
  /// body's mass, as (4.5) writes @f$ \vec{n}\cdot\vec{n}/m @f$.
  /// @return the squared length of vector()
  [[nodiscard]] double squared_norm() const { return squared_; }

  /// @brief Whether the vector given was not of unit length within unit_normal_tolerance and was
  /// divided by its length.
  /// @return true when the normal is not the vector given
  [[nodiscard]] bool rescaled() const { return given_length_ != 1.0; }

  /// @brief The length of the vector given (1 for an angle, and for a vector kept as given).
  /// @return its Euclidean length, or 1
  [[nodiscard]] double given_length() const { return given_length_; }

  /// @brief The opposite normal: the other body's, @f$ -\vec{n} @f$.
  /// @return -n (squared_norm(), rescaled() and given_length() as this one's)
  [[nodiscard]] UnitNormal operator-() const {
    UnitNormal opposite = *this;
    opposite.n_ = -n_;
    return opposite;
  }

 private:
  UnitNormal() = default;
  Eigen::Vector2d n_ = Eigen::Vector2d::UnitX();
  double squared_ = 1.0;       // |n|², the same for -n
  double given_length_ = 1.0;  // 1 unless the vector given was rescaled
};

}  // namespace impulse
