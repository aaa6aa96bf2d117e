// SPDX-License-Identifier: GPL-3.0-or-later
#include "models/scene.hpp"

#include <Eigen/QR>
#include <algorithm>

namespace impulse::derivations::many {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;

double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

namespace {
Vector2d perp(const Vector2d& r) {
  return {-r.y(), r.x()};
}
}  // namespace

Vector2d Body::velocity_at(const Vector2d& point) const {
  if (is_static()) {
    return Vector2d::Zero();
  }
  Vector2d v = p / m;
  if (rigid()) {
    v += L / I * perp(point - position);
  }
  return v;
}

double Body::energy() const {
  if (is_static()) {
    return 0;
  }
  return p.squaredNorm() / (2 * m) + (rigid() ? L * L / (2 * I) : 0.0);
}

void fit_inertias(num::Random& r, Scene& s) {
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    Body& b = s.bodies[k];
    if (!b.rigid())
      continue;
    double reach = 0.1;
    for (const auto& c : s.contacts) {
      if (c.a == k || c.b == k)
        reach = std::max(reach, (c.point - b.position).norm());
    }
    const double gyration = reach * r.uniform(0.4, 1.0);
    b.I = b.m * gyration * gyration;
    b.L = b.I * r.uniform(-10, 10) / reach;
  }
}

Scene after(const Scene& scene, const VectorXd& F) {
  Scene s = scene;
  for (std::size_t v = 0; v < s.contacts.size(); ++v) {
    const Contact& c = s.contacts[v];
    const double f = F(static_cast<Eigen::Index>(v));
    for (const auto& [k, n] : {std::pair{c.a, Vector2d(c.n)}, std::pair{c.b, Vector2d(-c.n)}}) {
      Body& b = s.bodies[k];
      if (b.is_static())
        continue;
      const Vector2d J = -n * f;  // the impulse on a body is minus its own normal times F
      b.p += J;
      if (b.rigid())
        b.L += cross(c.point - b.position, J);
    }
  }
  return s;
}

double energy(const Scene& scene) {
  double E = 0;
  for (const Body& b : scene.bodies)
    E += b.energy();
  return E;
}

Model model(const Scene& scene) {
  std::vector<Eigen::Index> offset;
  Eigen::Index dof = 0;
  for (const Body& b : scene.bodies) {
    offset.push_back(dof);
    dof += b.is_static() ? 0 : (b.rigid() ? 3 : 2);
  }
  Model md;
  md.J = MatrixXd::Zero(static_cast<Eigen::Index>(scene.contacts.size()), dof);
  md.velocity = VectorXd::Zero(dof);
  md.inverse_mass = VectorXd::Zero(dof);
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const Body& b = scene.bodies[k];
    if (b.is_static())
      continue;
    md.velocity.segment(offset[k], 2) = b.p / b.m;
    md.inverse_mass.segment(offset[k], 2).setConstant(1 / b.m);
    if (b.rigid()) {
      md.velocity(offset[k] + 2) = b.L / b.I;
      md.inverse_mass(offset[k] + 2) = 1 / b.I;
    }
  }
  for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
    const Contact& c = scene.contacts[v];
    const auto row = static_cast<Eigen::Index>(v);
    for (const auto& [k, n] : {std::pair{c.a, Vector2d(c.n)}, std::pair{c.b, Vector2d(-c.n)}}) {
      const Body& b = scene.bodies[k];
      if (b.is_static())
        continue;
      // The body's normal velocity at the point: n . v + det(r, n) w.
      md.J.block(row, offset[k], 1, 2) += n.transpose();
      if (b.rigid())
        md.J(row, offset[k] + 2) += cross(c.point - b.position, n);
    }
  }
  return md;
}

MatrixXd Model::A() const {
  return J * inverse_mass.asDiagonal() * J.transpose();
}

VectorXd solve(const MatrixXd& A, const VectorXd& B) {
  if (A.rows() == 0)
    return VectorXd(0);
  // With two rounds of iterative refinement: a nearly singular system (masses 1e-3 to 1e3 make
  // some) is solved to a residual near rounding, so the motion it gives is.
  const Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod(A);
  VectorXd x = cod.solve(B);
  for (int round = 0; round < 2; ++round) {
    x += cod.solve(VectorXd(B - A * x));
  }
  return x;
}

double inconsistency(const MatrixXd& A, const VectorXd& B) {
  const VectorXd x = solve(A, B);
  const double scale = A.norm() * x.norm() + B.norm();
  return scale == 0 ? 0.0 : (A * x - B).norm() / scale;
}

}  // namespace impulse::derivations::many
