// SPDX-License-Identifier: GPL-3.0-or-later
// Section 2: point masses in the plane; each momentum is cast onto the contact normal.
//
// The physics: the bumper's outward normal is n, the wedge's -n; the bumper receives the impulse
// -n Fdt and the wedge +n Fdt; kinetic energy is |p|^2 / 2m. Unit normals are written with the
// rational parametrisation n = ((1 - t^2), 2t) / (1 + t^2) so that the algebra stays rational.
#include <Eigen/Geometry>
#include <cmath>

#include "impulse/material_2d/material_2d.hpp"
#include "numeric.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::Vector2d;
using GiNaC::ex;

struct PlaneSymbols {
  GiNaC::possymbol m1{"m1", "m_1"};
  GiNaC::possymbol m2{"m2", "m_2"};
  GiNaC::realsymbol p1x{"p1x", "p_{1x}"}, p1y{"p1y", "p_{1y}"};
  GiNaC::realsymbol p2x{"p2x", "p_{2x}"}, p2y{"p2y", "p_{2y}"};
  GiNaC::realsymbol t{"t"};
  GiNaC::realsymbol e{"e", "elasticity"};
  [[nodiscard]] ex nx() const { return (1 - t * t) / (1 + t * t); }
  [[nodiscard]] ex ny() const { return 2 * t / (1 + t * t); }
};

const PlaneSymbols& plane() {
  static const PlaneSymbols s;
  return s;
}

struct Puck {
  double m;
  Vector2d p;
  [[nodiscard]] double energy() const { return p.squaredNorm() / (2 * m); }
  [[nodiscard]] Vector2d v() const { return p / m; }
};

struct Hit {
  Puck bumper, wedge;
  Vector2d n;  // outward from the bumper
};

Hit sample_hit(num::Random& r) {
  Hit h{{r.mass(), {}}, {r.mass(), {}}, r.unit_vector()};
  h.bumper.p = h.bumper.m * r.vector(10);
  h.wedge.p = h.wedge.m * r.vector(10);
  return h;
}

// The impulse magnitude of (1.3) applied to the momenta cast on each body's own normal.
double cast_impulse(const Hit& h, double e1, double e2) {
  const double bumper_pn = h.bumper.p.dot(h.n);
  const double wedge_pn = h.wedge.p.dot(-h.n);
  return (e1 * bumper_pn / h.bumper.m + e2 * wedge_pn / h.wedge.m) /
         (1 / h.bumper.m + 1 / h.wedge.m);
}

Outcome cast_operator(const Context& c) {
  // Read as cast_v(x) = x . v / |v|: the coordinate of x along v. Exactly: with the unit
  // u = v / |v| and its perpendicular w, x = cast_v(x) u + (x . w) w must rebuild x.
  const auto& s = plane();
  const GiNaC::realsymbol x("x"), y("y");
  const GiNaC::possymbol k("k");  // v = k (n_x, n_y), |v| = k
  const ex vx = k * s.nx(), vy = k * s.ny();
  const ex cast = (x * vx + y * vy) / k;
  const ex across = -x * s.ny() + y * s.nx();
  const bool exact = sym::simplify(cast * s.nx() - across * s.ny() - x).is_zero() &&
                     sym::simplify(cast * s.ny() + across * s.nx() - y).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Vector2d v = r.vector(10);
    const Vector2d w = r.vector(10);
    const double angle = std::atan2(v.y(), v.x());
    const Eigen::Matrix2d to_base = Eigen::Rotation2Dd(-angle).toRotationMatrix();
    const Vector2d in_base = to_base * w;
    errors.add(material_2d::cast(w, v), in_base.x(), w.norm());
  }
  return judge(EquationVerdict{
      {symbolic(exact, "the cast and the perpendicular coordinate rebuild x"),
       numeric(Method::numeric, errors, num::holds_below,
               "the library's material_2d::cast against a rotation of the base")},
      {},
      {},
      {},
      "The printed operator has lost its left operand; it is read as the map x -> x . v / |v|."});
}

Outcome normal_momentum(const Context& c) {
  const auto& s = plane();
  // p_n is p's coordinate along n in the orthonormal base (n, t), t = (-n_y, n_x): the printed
  // p_x n_x + p_y n_y with the tangent coordinate must rebuild p.
  const ex pn = s.p1x * s.nx() + s.p1y * s.ny();
  const ex pt = -s.p1x * s.ny() + s.p1y * s.nx();
  const bool exact = sym::simplify(pn * s.nx() - pt * s.ny() - s.p1x).is_zero() &&
                     sym::simplify(pn * s.ny() + pt * s.nx() - s.p1y).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Vector2d n = r.unit_vector();
    const Vector2d p = r.vector(10);
    // The change of base: rotate by minus the normal's angle.
    const Eigen::Matrix2d to_base =
        Eigen::Rotation2Dd(-std::atan2(n.y(), n.x())).toRotationMatrix();
    errors.add(p.x() * n.x() + p.y() * n.y(), (to_base * p).x(), p.norm());
  }
  return judge(EquationVerdict{
      {symbolic(exact, "p_n n + p_t t rebuilds p"),
       numeric(Method::numeric, errors, num::holds_below, "against a rotation of the base")},
      {},
      {},
      {},
      {}});
}

Outcome claim_sign(const Context& c) {
  // Formal reading: p_n > 0 when the body moves along n; otherwise p_n < 0, or p_n = 0 for a body
  // at rest. Motion along the contact's tangent is neither.
  const auto fails = [](const Vector2d& p, const Vector2d& n) {
    // p . n within rounding of zero counts as zero (a tangent built from a rounded normal is
    // off by an ulp).
    const double pn = std::abs(p.dot(n)) <= 1e-12 * p.norm() ? 0.0 : p.dot(n);
    const bool at_rest = p.isZero(0.0);
    return !(pn > 0) && !(pn < 0) && !at_rest;
  };
  num::Random r(c.seed);
  std::size_t failures = 0;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Vector2d n = r.unit_vector();
    // Every fourth body slides exactly along the tangent (t = (-n_y, n_x) times a length).
    const Vector2d p = i % 4 == 0 ? r.uniform(0.5, 2) * Vector2d(-n.y(), n.x()) : r.vector(10);
    failures += fails(p, n) ? 1U : 0U;
  }
  std::optional<std::string> counterexample;
  const Vector2d p(0, 2), n(1, 0);
  if (fails(p, n)) {
    counterexample = "p = (0, 2), n = (1, 0): the body moves (along the tangent), yet p_n = " +
                     num::number(p.dot(n)) + ", neither positive nor negative.";
  }
  return judge(ClaimVerdict{
      {search(1, counterexample ? 1 : 0, "the worked counterexample"),
       search(c.samples, failures, "random momenta, every fourth along the tangent")},
      counterexample,
      "p_n is zero for every motion along the contact's tangent, not only for a body at rest; "
      "its sign does tell whether the body moves towards (+) or away from (-) the other side.",
      {}});
}

Outcome impulse_vector(const Context& c) {
  // With the bumper receiving -n Fdt and the wedge +n Fdt, and Fdt from (1.3) on the cast
  // momenta (elasticity 2), the total kinetic energy must not change; with the opposite sign it
  // would. Exactly, with symbolic momenta and normal, and on random pucks.
  const auto& s = plane();
  const ex nx = s.nx(), ny = s.ny();
  const ex bumper_pn = s.p1x * nx + s.p1y * ny;
  const ex wedge_pn = -(s.p2x * nx + s.p2y * ny);
  const ex F = (2 * bumper_pn / s.m1 + 2 * wedge_pn / s.m2) / (1 / s.m1 + 1 / s.m2);
  const auto energy = [](const ex& px, const ex& py, const ex& m) {
    return (px * px + py * py) / (2 * m);
  };
  const ex before = energy(s.p1x, s.p1y, s.m1) + energy(s.p2x, s.p2y, s.m2);
  // The printed vectorised impulse on the bumper: [-n_x Fdt, -n_y Fdt].
  const ex after =
      energy(s.p1x - nx * F, s.p1y - ny * F, s.m1) + energy(s.p2x + nx * F, s.p2y + ny * F, s.m2);
  const bool exact = sym::simplify(after - before).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  num::Errors library;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Hit h = sample_hit(r);
    const double F0 = cast_impulse(h, 2, 2);
    const Puck b{h.bumper.m, h.bumper.p + Vector2d(-h.n.x() * F0, -h.n.y() * F0)};
    const Puck w{h.wedge.m, h.wedge.p - Vector2d(-h.n.x() * F0, -h.n.y() * F0)};
    errors.add(b.energy() + w.energy(), h.bumper.energy() + h.wedge.energy());
    library.add(
        (material_2d::impulse_vector(h.n, F0) - Vector2d(-h.n.x() * F0, -h.n.y() * F0)).norm(), 0.0,
        std::abs(F0));
  }
  return judge(
      EquationVerdict{{symbolic(exact, "elastic impulse applied as printed keeps the energy"),
                       numeric(Method::numeric, errors),
                       numeric(Method::numeric, library, num::holds_below,
                               "the library's material_2d::impulse_vector agrees")},
                      {},
                      {},
                      {},
                      "The printed vector is the impulse on the bumper; the wedge "
                      "receives its opposite."});
}

Outcome claim_opposes_motion(const Context& c) {
  // Formal reading: the impulse on a body points against the body's velocity.
  num::Random r(c.seed);
  std::size_t failures = 0;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Hit h = sample_hit(r);
    const double F = cast_impulse(h, 2, 2);
    if (F <= 0) {
      continue;  // the bodies separate; there is no collision to speak of
    }
    const Vector2d on_bumper = -h.n * F;
    failures += on_bumper.dot(h.bumper.v()) > 0 ? 1U : 0U;
  }
  // A clean instance: the bumper drifts away from the wedge, which catches up.
  const Hit h{{1, {-1, 0}}, {1, {-3, 0}}, {1, 0}};
  const double F = cast_impulse(h, 2, 2);
  const Vector2d on_bumper = -h.n * F;
  std::optional<std::string> counterexample;
  if (F > 0 && on_bumper.dot(h.bumper.v()) > 0) {
    counterexample =
        "bumper m = 1 at velocity (-1, 0), wedge m = 1 at (-3, 0) catching up, "
        "n = (1, 0), elasticity 2: Fdt = " +
        num::number(F) + ", so the bumper receives (" + num::number(on_bumper.x()) +
        ", 0), along its own motion; it speeds up to (" +
        num::number((h.bumper.p + on_bumper).x() / h.bumper.m) + ", 0).";
  }
  return judge(ClaimVerdict{{search(1, counterexample ? 1 : 0, "the worked counterexample"),
                             search(c.samples, failures, "colliding pucks at random")},
                            counterexample,
                            "The impulse on a body is minus its own outward normal times Fdt: it "
                            "pushes the body away from the contact, which is along the body's "
                            "motion whenever the other body catches up from behind.",
                            {}});
}

Outcome claim_cast_reduction(const Context& c) {
  // Section 1 applied to the cast momenta: elasticity 2 keeps the energy, elasticity 1 equalises
  // the normal velocities, and the tangential velocities stay; the library agrees.
  num::Random r(c.seed);
  num::Errors energy, equal, tangent, library;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Hit h = sample_hit(r);
    const Vector2d t(-h.n.y(), h.n.x());
    const double e1 = r.uniform(0, 3), e2 = r.uniform(0, 3);
    for (const double e : {2.0, 1.0}) {
      const double F = cast_impulse(h, e, e);
      const Puck b{h.bumper.m, h.bumper.p - h.n * F};
      const Puck w{h.wedge.m, h.wedge.p + h.n * F};
      if (e == 2.0) {
        energy.add(b.energy() + w.energy(), h.bumper.energy() + h.wedge.energy());
      } else {
        equal.add(b.v().dot(h.n), w.v().dot(h.n), h.bumper.v().norm() + h.wedge.v().norm());
      }
      tangent.add(b.v().dot(t), h.bumper.v().dot(t), h.bumper.v().norm());
      tangent.add(w.v().dot(t), h.wedge.v().dot(t), h.wedge.v().norm());
    }
    const auto lib = material_2d::collide({h.bumper.m, h.bumper.p}, Elasticity(e1),
                                          {h.wedge.m, h.wedge.p}, Elasticity(e2), h.n);
    const double scale = (std::abs(e1 * h.bumper.p.dot(h.n) / h.bumper.m) +
                          std::abs(e2 * h.wedge.p.dot(h.n) / h.wedge.m)) /
                         (1 / h.bumper.m + 1 / h.wedge.m);
    library.add(lib.solution.Fdt, cast_impulse(h, e1, e2), scale);
  }
  return judge(ClaimVerdict{
      {numeric(Method::numeric, energy, num::holds_below, "energy at elasticity 2"),
       numeric(Method::numeric, equal, num::holds_below, "normal velocities at elasticity 1"),
       numeric(Method::numeric, tangent, num::holds_below, "tangential velocities unchanged"),
       numeric(Method::numeric, library, num::holds_below, "the library's material_2d::collide")},
      std::nullopt,
      {},
      {}});
}

}  // namespace

std::vector<Check> section2_checks() {
  std::vector<Check> c;
  c.push_back(make_check("s2-cast", "2", std::nullopt, Kind::step,
                         R"(cast \ \vec{v} \equiv \cdot \frac{\vec{v}}{\|\vec{v}\|})",
                         cast_operator));
  c.push_back(make_check("s2-normal-momentum", "2", std::nullopt, Kind::step,
                         R"(p_n = \vec{p} \cdot \vec{n} = p_x n_x + p_y n_y)", normal_momentum));
  c.push_back(make_check(
      "claim-2-sign", "2", std::nullopt, Kind::claim,
      R"(p_n > 0 \text{ if moving along } \vec{n}, \text{ else } p_n < 0 \text{ (or } p_n = 0 \text{ at rest)})",
      claim_sign));
  c.push_back(make_check(
      "claim-2-cast-reduction", "2", std::nullopt, Kind::claim,
      R"(\text{(1.3) on } p_n = \vec{p}\cdot\vec{n} \text{ of each body (own normal) resolves the planar collision})",
      claim_cast_reduction));
  c.push_back(make_check("s2-impulse-vector", "2", std::nullopt, Kind::step,
                         R"(\vec{Fdt} = -\vec{n} \cdot Fdt = [-n_x Fdt, -n_y Fdt])",
                         impulse_vector));
  c.push_back(
      make_check("claim-2-inverted-normal", "2", std::nullopt, Kind::claim,
                 R"(\vec{F}dt \cdot \vec{v} < 0 \text{ for the body that receives } \vec{F}dt)",
                 claim_opposes_motion));
  return c;
}

}  // namespace impulse::derivations
