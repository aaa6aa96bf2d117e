// SPDX-License-Identifier: GPL-3.0-or-later
// Bodies in contact, for the models of sections 3 to 5: bodies, contacts, the global Jacobian
// built from the definitions (each contact's generalised normals: the velocity of the contact
// points along the normal, as a linear function of the bodies' velocities), the impulses of the
// law of restitution at every contact, and the bodies after a set of impulses. Nothing here is
// one of the paper's coefficients.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "numeric.hpp"

namespace impulse::derivations::many {

struct Body {
  double m = 1;  ///< mass; 0 for a static body
  double I = 0;  ///< moment of inertia about the centre; 0 for a point mass or a static body
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  double L = 0;
  [[nodiscard]] bool is_static() const { return m == 0; }
  [[nodiscard]] bool rigid() const { return I > 0; }
  [[nodiscard]] Eigen::Vector2d velocity_at(const Eigen::Vector2d& point) const;
  [[nodiscard]] double energy() const;
};

struct Contact {
  std::size_t a = 0, b = 0;  ///< a's outward normal is n, b's is -n
  Eigen::Vector2d n = Eigen::Vector2d::UnitX();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

struct Scene {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

/// det(a, b): the moment of b at arm a.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
/// Each rigid body's inertia and angular momentum fitted to its contacts: its radius of gyration
/// 0.4 to 1 times its farthest contact arm (at least 0.1), its turning speed at that arm up to 10.
void fit_inertias(num::Random& r, Scene& s);
/// The bodies after the impulses: -n F_v on body a, +n F_v on body b of each contact v.
Scene after(const Scene& scene, const Eigen::VectorXd& F);

/// The kinetic energy of the scene.
double energy(const Scene& scene);

/// J (contacts x degrees of freedom) with approach = J v, and the inverse masses: the system
/// A = J M^-1 J^T of the definitions, and B = J (e v) for elasticity e.
struct Model {
  Eigen::MatrixXd J;
  Eigen::VectorXd velocity;      ///< generalised velocities
  Eigen::VectorXd inverse_mass;  ///< per degree of freedom
  [[nodiscard]] Eigen::MatrixXd A() const;
};
Model model(const Scene& scene);

/// The minimum-norm least-squares solution (complete orthogonal decomposition).
Eigen::VectorXd solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& B);

/// Whether B lies in the range of A: the least-squares residual relative to |A||x| + |B|.
double inconsistency(const Eigen::MatrixXd& A, const Eigen::VectorXd& B);

/// A system A F = B as a model assembles it from a file's coefficients.
struct System {
  Eigen::MatrixXd A;
  Eigen::VectorXd B;
};

}  // namespace impulse::derivations::many
