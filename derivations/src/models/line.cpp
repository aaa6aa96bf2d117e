// SPDX-License-Identifier: GPL-3.0-or-later
// Two bodies on a line: contacts simulated in continuous time, and searches over bodies,
// impulses and elasticities.
//
// The paper's convention: along the axis from body 1 to body 2, body 1's momentum is p_1 and
// body 2's is -p_2 (each counted positive towards the other body); the impulse F dt pushes body 2
// forwards and body 1 back. The momenta after, p_1' and p_2', are counted along the axis (the
// paper's p_2' = -p_2 + F dt).
#include <cmath>
#include <numbers>

#include "models/catalogue.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

namespace {

// Bodies just touching, body 1 behind body 2 and catching up: masses and velocities along the
// axis (v_1 > v_2).
struct Pair {
  double m1, m2, v1, v2;
};

// Masses from 1e-3 to 1e3, a closing speed from 0.1 to 10, velocities in the centre-of-mass frame
// moved by a random drift.
Pair random_pair(num::Random& r) {
  const double m1 = r.mass(), m2 = r.mass();
  const double closing = r.log_uniform(0.1, 10.0);
  const double drift = r.uniform(-5.0, 5.0);
  return {m1, m2, drift + closing * m2 / (m1 + m2), drift - closing * m1 / (m1 + m2)};
}

// The same in the centre-of-mass frame: energies are those of the relative motion alone, not
// small differences of the centre's energy, which no impulse changes.
Pair centred_pair(num::Random& r) {
  Pair p = random_pair(r);
  const double centre = (p.m1 * p.v1 + p.m2 * p.v2) / (p.m1 + p.m2);
  p.v1 -= centre;
  p.v2 -= centre;
  return p;
}

void set_before(Point& point, const Pair& b) {
  point.set("m_1", b.m1).set("m_2", b.m2).set("p_1", b.m1 * b.v1).set("p_2", -b.m2 * b.v2);
  point.set("\\vec{p_1}", Eigen::Vector2d(b.m1 * b.v1, 0.0))
      .set("\\vec{p_2}", Eigen::Vector2d(b.m2 * b.v2, 0.0));
}

enum class Law { spring, damper, spring_damper };

// One contact simulated: the bodies' positions and velocities under the contact force (of the
// overlap and the closing speed), integrated until the contact ends. The impulse is the force's
// time integral, sampled along the motion and summed by Gauss–Legendre: it is not integrated
// with the momenta, so that p' = p - J is a finding, not a construction.
Point contact(const Pair& b, Law law, double damping_ratio) {
  const double reduced = b.m1 * b.m2 / (b.m1 + b.m2);
  const double k = law == Law::damper ? 0.0 : 1e4 / reduced;  // period about 0.06
  const double c = law == Law::spring   ? 0.0
                   : law == Law::damper ? 1e2 * reduced
                                        : 2 * damping_ratio * std::sqrt(k * reduced);
  // y = [overlap, v1, v2]: the overlap grows at the closing speed.
  const auto force = [&](const double* y) { return k * y[0] + c * (y[1] - y[2]); };
  const num::OdeRhs rhs = [&](double, const double* y, double* dy) {
    const double f = force(y);  // on body 2, forwards
    dy[0] = y[1] - y[2];
    dy[1] = -f / b.m1;
    dy[2] = f / b.m2;
  };
  const double scale = law == Law::damper ? reduced / c : std::sqrt(reduced / k);
  const num::OdeEvent ended = [&](double t, const double* y) {
    if (t <= 0) {
      return 1.0;
    }
    // A spring contact ends when the overlap is gone; a damper's when the bodies stop closing
    // (within rounding of the velocities).
    return law == Law::damper ? (y[1] - y[2]) - 1e-12 * (std::abs(b.v1) + std::abs(b.v2)) : y[0];
  };
  const std::vector<double> start{0.0, b.v1, b.v2};
  const num::OdeResult end =
      num::integrate_until(rhs, start, ended, scale / 50, 1e4 * scale, 1e-13 * scale);
  const double duration = end.t;
  // The force along the motion, at the nodes of a Gauss–Legendre rule on each of 16 pieces.
  const double impulse = num::gauss_legendre(
      [&](const std::vector<double>& times) {
        std::vector<double> forces;
        for (const auto& y : num::integrate_to(rhs, start, times, scale / 50)) {
          forces.push_back(force(y.data()));
        }
        return forces;
      },
      0.0, duration, 16);
  Point p;
  set_before(p, b);
  const double v1 = end.y[1], v2 = end.y[2];
  p.set("p_1'", b.m1 * v1).set("p_2'", b.m2 * v2);
  p.set("\\vec{p_1'}", Eigen::Vector2d(b.m1 * v1, 0.0))
      .set("\\vec{p_2'}", Eigen::Vector2d(b.m2 * v2, 0.0));
  p.set("F", impulse / duration).set("dt", duration);
  p.set("\\vec{F}", Eigen::Vector2d(impulse / duration, 0.0));
  if (law == Law::spring_damper) {
    const double z = damping_ratio;
    const double elasticity = 1.0 + std::exp(-z * std::numbers::pi / std::sqrt(1 - z * z));
    p.set("\\mathit{elasticity}_1", elasticity)
        .set("\\mathit{elasticity}_2", elasticity)
        .set("\\mathit{elasticity}", elasticity);
  }
  return p;
}

std::vector<Point> contacts(const Settings& s, Law law) {
  num::Random r(s.seed);
  std::vector<Point> points;
  const std::size_t runs = std::max<std::size_t>(3, s.share(800));
  for (std::size_t i = 0; i < runs; ++i) {
    const double z = law == Law::spring_damper ? std::vector<double>{0.05, 0.2, 0.5}[i % 3] : 0.0;
    points.push_back(contact(random_pair(r), law, z));
  }
  return points;
}

// Small whole numbers first (a counterexample should be one a reader can check by hand), then
// random bodies in the centre-of-mass frame.
std::vector<Pair> whole_pairs() {
  std::vector<Pair> pairs;
  for (int m1 = 1; m1 <= 2; ++m1) {
    for (int v1 = 1; v1 <= 3; ++v1) {
      for (int v2 = 3; v2 >= -3; --v2) {  // body 2's velocity along the axis
        if (v1 > v2) {                    // approaching
          pairs.push_back(
              {static_cast<double>(m1), 1.0, static_cast<double>(v1), static_cast<double>(v2)});
        }
      }
    }
  }
  return pairs;
}

Point with_elasticities(const Pair& b, double e1, double e2) {
  Point p;
  set_before(p, b);
  p.set("\\mathit{elasticity}_1", e1).set("\\mathit{elasticity}_2", e2).set("dt", 1.0);
  if (e1 == e2) {
    p.set("\\mathit{elasticity}", e1);
  }
  return p;
}

}  // namespace

std::vector<Point> spring_contact_on_a_line(Probe&, const Settings& s) {
  return contacts(s, Law::spring);
}

std::vector<Point> damper_contact_on_a_line(Probe&, const Settings& s) {
  return contacts(s, Law::damper);
}

std::vector<Point> spring_damper_contact_on_a_line(Probe&, const Settings& s) {
  return contacts(s, Law::spring_damper);
}

std::vector<Point> bodies_on_a_line_one_elasticity(Probe&, const Settings& s) {
  std::vector<Point> points;
  for (const Pair& b : whole_pairs()) {
    for (const double e : {2.0, 1.0, 0.0, 0.5, 1.5, 3.0, -1.0}) {
      points.push_back(with_elasticities(b, e, e));
    }
  }
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.samples; ++i) {
    // One case in ten at an edge (0, 1 or 2), the rest spread over -3 .. 10.
    const double e = i % 10 == 0 ? static_cast<double>(i / 10 % 3) : r.uniform(-3.0, 10.0);
    points.push_back(with_elasticities(centred_pair(r), e, e));
  }
  return points;
}

std::vector<Point> bodies_on_a_line_two_elasticities(Probe&, const Settings& s) {
  std::vector<Point> points;
  for (const Pair& b : whole_pairs()) {
    points.push_back(with_elasticities(b, 2.0, 1.0));
    points.push_back(with_elasticities(b, 1.0, 2.0));
  }
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.samples; ++i) {
    const Pair b = random_pair(r);
    points.push_back(with_elasticities(b, r.uniform(1.0, 2.0), r.uniform(1.0, 2.0)));
  }
  return points;
}

std::vector<Point> bodies_and_impulses_on_a_line(Probe&, const Settings& s) {
  std::vector<Point> points;
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.samples; ++i) {
    const Pair b = i % 2 == 0 ? random_pair(r) : centred_pair(r);
    const double scale = std::abs(b.m1 * b.v1) + std::abs(b.m2 * b.v2);
    // Impulses of every size, and (every other case) near the one that equalises the velocities.
    const double equalising = (b.v1 - b.v2) * b.m1 * b.m2 / (b.m1 + b.m2);
    const double impulse = i % 2 == 0 ? r.uniform(-1.0, 1.0) * std::pow(10.0, r.uniform(-6, 6))
                                      : equalising * (1 + r.uniform(-2.0, 2.0));
    const double duration = r.log_uniform(1e-3, 1.0);
    Point p;
    set_before(p, b);
    p.set("F", (impulse == 0 ? scale * 1e-3 : impulse) / duration).set("dt", duration);
    p.set("\\vec{F}", Eigen::Vector2d(impulse / duration, 0.0));
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> changes_of_units_on_a_line(Probe&, const Settings& s) {
  std::vector<Point> points;
  num::Random r(s.seed);
  for (std::size_t i = 0; i < s.samples; ++i) {
    const Pair b = random_pair(r);
    const double mass = r.log_uniform(1e-3, 1e3);      // μ: the unit of mass changed
    const double velocity = r.log_uniform(1e-3, 1e3);  // λ: the unit of velocity changed
    Point p;
    set_before(p, b);
    p.set("\\mu", mass).set("\\lambda", velocity);
    p.set("\\tilde{m}_1", mass * b.m1).set("\\tilde{m}_2", mass * b.m2);
    p.set("\\tilde{p}_1", mass * velocity * b.m1 * b.v1)
        .set("\\tilde{p}_2", -mass * velocity * b.m2 * b.v2);
    p.set("\\mathit{elasticity}_1", r.uniform(0.0, 3.0))
        .set("\\mathit{elasticity}_2", r.uniform(0.0, 3.0));
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Model> line_models() {
  return {
      {Method::ode, "linear spring contact on a line",
       "Two bodies on a line meet; while they overlap a linear spring pushes them apart (GSL "
       "rk8pd until the overlap is gone); the impulse is the time integral of the spring's "
       "force sampled along the motion (Simpson's rule), the momenta after come from the "
       "velocities at the end.",
       spring_contact_on_a_line},
      {Method::ode, "damper contact on a line",
       "As the linear spring, with a damper alone (force proportional to the closing speed): "
       "the contact ends when the bodies stop closing.",
       damper_contact_on_a_line},
      {Method::ode, "spring-damper contact on a line",
       "A linear spring and damper of damping ratio 0.05, 0.2 or 0.5: the textbook coefficient "
       "of restitution exp(-z pi / sqrt(1 - z^2)) gives elasticity_1 = elasticity_2 = 1 + that "
       "coefficient.",
       spring_damper_contact_on_a_line},
      {Method::search, "bodies on a line, one elasticity",
       "Approaching bodies on a line (small whole numbers first, then masses from 1e-3 to 1e3 "
       "and speeds up to 10) with one elasticity for both, from -3 to 10 (0, 1 and 2 "
       "included).",
       bodies_on_a_line_one_elasticity},
      {Method::search, "bodies on a line, two elasticities",
       "Approaching bodies on a line with an elasticity each, from 1 to 2 (the pairs 2, 1 and "
       "1, 2 on small whole numbers first).",
       bodies_on_a_line_two_elasticities},
      {Method::search, "bodies and impulses on a line",
       "Bodies on a line and any impulse between them, from -1e6 to 1e6.",
       bodies_and_impulses_on_a_line},
      {Method::numeric, "changes of units on a line",
       "Bodies on a line seen in other units of mass, length and time (each changed by a "
       "factor from 1e-3 to 1e3): the same quantities, numbered with a tilde, in the new "
       "units.",
       changes_of_units_on_a_line},
  };
}

}  // namespace impulse::derivations::models
