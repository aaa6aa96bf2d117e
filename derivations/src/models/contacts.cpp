// SPDX-License-Identifier: GPL-3.0-or-later
// Bodies in contact resolved by the law of restitution, from the definitions alone (scene.hpp):
// at every contact the velocity of approach along the normal after the impulses is (1 - e)
// times the one before (e the elasticity: 2 keeps it, reversed; 1 stops it), the impulses found
// from the contact Jacobian, A = J M^-1 J^T and B = J (e v), by the minimum-norm solution.
#include <cmath>

#include "models/catalogue.hpp"
#include "models/scene.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

using Eigen::Vector2d;
using Eigen::VectorXd;

// Two rigid bodies touching at one point, their radii of gyration on the scale of their arms.
many::Scene two_rigid_bodies(num::Random& r) {
  many::Scene s;
  const Vector2d point = r.vector(1);
  for (int k = 0; k < 2; ++k) {
    many::Body b;
    b.m = r.mass();
    b.position = r.vector(2);
    const double reach = std::max(0.1, (point - b.position).norm());
    const double gyration = reach * r.uniform(0.4, 1.0);
    b.I = b.m * gyration * gyration;
    b.p = b.m * r.vector(10);
    b.L = b.I * r.uniform(-10, 10) / reach;
    s.bodies.push_back(b);
  }
  s.contacts.push_back({0, 1, r.unit_vector(), point});
  return s;
}

// The impulses of the law of restitution with elasticity e on every body.
VectorXd impulses(const many::Scene& s, double e) {
  const many::Model md = many::model(s);
  return many::solve(md.A(), md.J * (e * md.velocity));
}

Point one_contact(const many::Scene& s, double e) {
  const VectorXd F = impulses(s, e);
  const many::Scene after = many::after(s, F);
  const many::Body& own = s.bodies[0];
  const many::Body& other = s.bodies[1];
  const many::Contact& c = s.contacts[0];
  Point p;
  p.set("m", own.m).set("I", own.I).set("\\vec{p}", own.p).set("L", own.L);
  p.set("\\vec{r}", c.point - own.position).set("\\vec{n}", c.n);
  p.set("m_o", other.m).set("I_o", other.I).set("\\vec{p_o}", other.p).set("L_o", other.L);
  p.set("\\vec{r_o}", c.point - other.position);
  p.set("F", F(0)).set("dt", 1.0);
  const Vector2d own_after = after.bodies[0].velocity_at(c.point);
  const Vector2d other_after = after.bodies[1].velocity_at(c.point);
  p.set("\\vec{v_v'}", own_after).set("\\vec{v_o'}", other_after);
  p.set("v'_{vn}", own_after.dot(c.n)).set("v'_{on}", other_after.dot(c.n));
  p.set("E_k", own.energy()).set("E_k'", after.bodies[0].energy());
  p.set("E_o", other.energy()).set("E_o'", after.bodies[1].energy());
  p.set("\\mathit{elasticity}", e)
      .set("\\mathit{elasticity}_1", e)
      .set("\\mathit{elasticity}_2", e);
  return p;
}

std::vector<Point> rigid_pairs(const Settings& s, double low, double high) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    const many::Scene pair = two_rigid_bodies(r);
    points.push_back(one_contact(pair, low == high ? low : r.uniform(low, high)));
  }
  return points;
}

}  // namespace

std::vector<Point> two_rigid_bodies_elastic(Probe&, const Settings& s) {
  return rigid_pairs(s, 2.0, 2.0);
}

std::vector<Point> two_rigid_bodies_inelastic(Probe&, const Settings& s) {
  return rigid_pairs(s, 1.0, 1.0);
}

std::vector<Point> two_rigid_bodies_one_elasticity(Probe&, const Settings& s) {
  return rigid_pairs(s, 0.0, 3.0);
}

std::vector<Model> contacts_models() {
  return {
      {Method::numeric, "two rigid bodies at one contact, elastic",
       "Two rigid bodies touching at one point (masses 1e-3 to 1e3, radii of gyration on the "
       "scale of their arms), resolved by the law of restitution with elasticity 2 from the "
       "contact Jacobian: the body's m, I, p, L, arm r and outward normal n, the other's m_o, "
       "I_o, p_o, L_o and arm r_o, the impulse F (dt = 1), the contact points' velocities "
       "after (v_v', v_o' and their parts along n, v'_vn and v'_on) and the kinetic energies.",
       two_rigid_bodies_elastic},
      {Method::numeric, "two rigid bodies at one contact, inelastic",
       "The same, with elasticity 1: the contact points leave with one velocity along the "
       "normal.",
       two_rigid_bodies_inelastic},
      {Method::numeric, "two rigid bodies at one contact, one elasticity",
       "The same, with one elasticity for both bodies drawn from 0 to 3.",
       two_rigid_bodies_one_elasticity},
  };
}

}  // namespace impulse::derivations::models
