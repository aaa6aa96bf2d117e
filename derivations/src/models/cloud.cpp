// SPDX-License-Identifier: GPL-3.0-or-later
#include "models/cloud.hpp"

#include <Eigen/QR>

namespace impulse::derivations::cloud {

using Eigen::Vector2d;

double Cloud::mass() const {
  double M = 0;
  for (const double mi : m)
    M += mi;
  return M;
}

double Cloud::inertia() const {
  double I = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    I += m[i] * r[i].squaredNorm();
  return I;
}

Vector2d Cloud::velocity(std::size_t i) const {
  return velocity_at(r[i]);
}

Vector2d Cloud::velocity_at(const Vector2d& arm) const {
  return V + w * Vector2d(-arm.y(), arm.x());
}

double Cloud::energy() const {
  double E = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    E += 0.5 * m[i] * velocity(i).squaredNorm();
  return E;
}

Vector2d Cloud::momentum() const {
  Vector2d P = Vector2d::Zero();
  for (std::size_t i = 0; i < m.size(); ++i)
    P += m[i] * velocity(i);
  return P;
}

double Cloud::angular_momentum() const {
  double L = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Vector2d p = m[i] * velocity(i);
    L += r[i].x() * p.y() - r[i].y() * p.x();
  }
  return L;
}

Cloud sample(num::Random& rng) {
  Cloud c;
  const int n = rng.integer(3, 6);
  Vector2d centre = Vector2d::Zero();
  double M = 0;
  for (int i = 0; i < n; ++i) {
    c.m.push_back(rng.mass());
    c.r.push_back(rng.vector(3));
    centre += c.m.back() * c.r.back();
    M += c.m.back();
  }
  for (auto& ri : c.r)
    ri -= centre / M;
  c.V = rng.vector(10);
  c.w = rng.uniform(-10, 10);
  return c;
}

Cloud after(const Cloud& body, const std::vector<Kick>& kicks) {
  // Weighted least squares: rows sqrt(m_i) [I2 | perp(r_i)] (dV, dw) ~ sqrt(m_i) J_i / m_i.
  const auto n = static_cast<Eigen::Index>(body.m.size());
  Eigen::MatrixXd rows(2 * n, 3);
  Eigen::VectorXd target = Eigen::VectorXd::Zero(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double s = std::sqrt(body.m[k]);
    rows.block(2 * i, 0, 2, 3) << s, 0, -s * body.r[k].y(), 0, s, s * body.r[k].x();
  }
  for (const Kick& kick : kicks) {
    const auto i = static_cast<Eigen::Index>(kick.point);
    target.segment(2 * i, 2) += kick.J / std::sqrt(body.m[kick.point]);
  }
  const Eigen::Vector3d change = rows.colPivHouseholderQr().solve(target);
  Cloud result = body;
  result.V += change.head<2>();
  result.w += change(2);
  return result;
}

}  // namespace impulse::derivations::cloud
