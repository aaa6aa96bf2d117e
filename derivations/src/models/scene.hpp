// SPDX-License-Identifier: GPL-3.0-or-later
// Bodies in contact, for the models of sections 3 to 5: bodies, contacts, the global Jacobian
// built from the definitions (each contact's generalised normals: the velocity of the contact
// points along the normal, as a linear function of the bodies' velocities), the impulses of the
// law of restitution at every contact, and the bodies after a set of impulses. Nothing here is
// one of the paper's coefficients.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "impulse/core/system.hpp"
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

/// Random bodies (point masses, or rigid bodies too) and contacts between random pairs. Rigid
/// bodies' radii of gyration follow their contact arms (contact points are on the body).
Scene random_scene(num::Random& r, bool rigid, bool with_static, int max_bodies, int max_contacts);

/// det(a, b): the moment of b at arm a.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
/// Each rigid body's inertia and angular momentum fitted to its contacts: its radius of gyration
/// 0.4 to 1 times its farthest contact arm (at least 0.1), its turning speed at that arm up to 10.
void fit_inertias(num::Random& r, Scene& s);
/// Two point masses touching at 1 to `max_contacts` points with random normals.
Scene random_pair(num::Random& r, int max_contacts);

/// The bodies after the impulses: -n F_v on body a, +n F_v on body b of each contact v.
Scene after(const Scene& scene, const Eigen::VectorXd& F);

double energy(const Scene& scene);
Eigen::Vector2d momentum(const Scene& scene);

/// Each contact's approach speed: a's point velocity along n plus b's along -n.
Eigen::VectorXd approach(const Scene& scene);

/// The largest speed of a contact point (the scale of the approach speeds).
double speed_scale(const Scene& scene);

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

/// A system A F = B as the checks assemble it from printed coefficients.
struct System {
  Eigen::MatrixXd A;
  Eigen::VectorXd B;
};

/// |a - b| / max(|a|, |b|) in the Frobenius norm (0 for two zero matrices).
double matrix_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

/// The size of the terms whose sum is the kinetic energy after, E - F . u + F^T A F / 2: the
/// impulses of a nearly dependent system are far larger than the momenta and push against each
/// other, and the energy after is then a small difference of large terms.
double energy_scale(double E, const Eigen::MatrixXd& A, const Eigen::VectorXd& F);

/// The size of the terms whose sum is a contact's approach speed after: the speeds before, and
/// the largest sum_k |A_vk F_k| of the change the impulses bring.
double approach_scale(const Scene& scene, const Eigen::MatrixXd& A, const Eigen::VectorXd& F);

/// The same scene assembled by the library (multipoint::assemble), every body at `elasticity`:
/// what the checks compare the printed coefficients' system with.
ContactSystem library_system(const Scene& scene, double elasticity);

}  // namespace impulse::derivations::many
