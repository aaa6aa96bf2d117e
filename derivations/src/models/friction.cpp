// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: friction at one contact, without the formulas of derivations/beyond/friction.md
// and without the library's exact rule (impulse::friction). A rod strikes a rough floor and is
// followed through its normal impulse by increments: at each increment Coulomb's law picks the
// tangential impulse (against the slip, μ times the increment, or the one that keeps the end from
// slipping when that lies inside the cone), the rod's momentum and angular momentum about its
// centre take the increment (Newton's second law for each), and the end's velocity is found again
// from the rod's motion. The work of the normal impulse is summed increment by increment. Where
// something happens inside an increment (the slip stops, compression ends, a law of restitution
// is met) the increment is cut there by bisection on its length. A body of point masses struck by
// an oblique impulse (Gauss's principle, cloud.hpp) tests the contact's velocity law itself.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "models/catalogue.hpp"
#include "models/cloud.hpp"
#include "numeric.hpp"

namespace impulse::derivations::models {

// Named, not anonymous: in a unity build this file is compiled with the other models, whose
// anonymous namespaces have helpers of the same names.
namespace rough_floor {

using Eigen::Vector2d;

double cross(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Vector2d perp(const Vector2d& r) {
  return {-r.y(), r.x()};
}

// A uniform rod striking a floor at its lower end.
struct Rod {
  double m = 1;
  double L = 1;
  double I = 1.0 / 12.0;
  Vector2d r;      // arm from the centre to the end on the floor
  Vector2d n;      // the floor's unit normal, into the rod
  Vector2d t;      // the floor's unit tangent
  Vector2d v;      // the centre's velocity before
  double w = 0;    // the spin before
  double mu = 0;   // Coulomb's coefficient
  double e = 1.5;  // the elasticity (the paper's parameter: 1 + the coefficient of restitution)
};

// The rod during the impact.
struct State {
  Vector2d v;
  double w = 0;
  double Pn = 0;    // the normal impulse so far
  double Pt = 0;    // the tangential impulse so far
  double work = 0;  // the work of the normal impulse so far, the sum of u_n dP_n
};

double normal_velocity(const Rod& rod, const State& s) {
  return (s.v + s.w * perp(rod.r)).dot(rod.n);
}

double tangential_velocity(const Rod& rod, const State& s) {
  return (s.v + s.w * perp(rod.r)).dot(rod.t);
}

// The state after an increment h of normal impulse that comes with k h of tangential impulse:
// the momentum takes the impulse, the angular momentum about the centre its moment. Inside one
// increment the end's normal velocity changes in proportion to the impulse, so the increment's
// work is the mean of its velocities times h.
State advance(const Rod& rod, const State& s, double h, double k) {
  const Vector2d J = h * rod.n + k * h * rod.t;
  State out = s;
  out.v += J / rod.m;
  out.w += cross(rod.r, J) / rod.I;
  out.Pn += h;
  out.Pt += k * h;
  out.work += 0.5 * h * (normal_velocity(rod, s) + normal_velocity(rod, out));
  return out;
}

// What the impulse went through, as the increments saw it.
struct Impact {
  int direction = 0;           // the slip's sign at the start (u_t's), +1 or -1
  std::optional<double> stop;  // the normal impulse where the slip first stopped
  bool slipped_again = false;  // the end slipped again after it had stopped (either way)
  double Pc = 0;               // the normal impulse where compression ended
  double work_c = 0;           // the work of the normal impulse during compression
  std::array<std::optional<State>, 3> end;  // the states at Newton's, Poisson's, the energetic end
};

enum Law { newton = 0, poisson = 1, energetic = 2 };

// Follows the impulse until every law's end is met; nothing when it takes too many increments.
std::optional<Impact> follow(const Rod& rod) {
  State s{rod.v, rod.w};
  const double un0 = normal_velocity(rod, s);
  const double c = rod.e - 1.0;  // the coefficient of restitution
  Impact out;
  const double ut0 = tangential_velocity(rod, s);
  out.direction = ut0 > 0 ? 1 : -1;
  int direction = out.direction;  // 0 while the end sticks
  bool compression = true;
  // A twentieth of the momentum the end's speed stands for, per increment.
  const double h0 = rod.m * std::hypot(un0, ut0) / 20.0;
  // Each event as a function of the state that rises through zero when it happens.
  const auto event = [&](int which, const State& x) -> double {
    switch (which) {
      case 0:  // the slip stops
        return direction == 0 ? -1.0 : -direction * tangential_velocity(rod, x);
      case 1:  // compression ends
        return compression ? normal_velocity(rod, x) : -1.0;
      case 2:  // Newton's: the end leaves at c times its approach speed
        return compression || out.end[newton] ? -1.0 : normal_velocity(rod, x) + c * un0;
      case 3:  // Poisson's: the impulse of restitution is c times that of compression
        return compression || out.end[poisson] ? -1.0 : x.Pn - out.Pc - c * out.Pc;
      default:  // the energetic law: restitution gives back c^2 of the work of compression
        return compression || out.end[energetic] ? -1.0
                                                 : (x.work - out.work_c) + c * c * out.work_c;
    }
  };
  const auto happen = [&](int which, const State& x) {
    switch (which) {
      case 0:
        direction = 0;
        if (!out.stop) {
          out.stop = x.Pn;
        }
        break;
      case 1:
        compression = false;
        out.Pc = x.Pn;
        out.work_c = x.work;
        break;
      default:
        out.end[static_cast<std::size_t>(which - 2)] = x;
        break;
    }
  };
  for (int step = 0; step < 4000; ++step) {
    if (out.end[newton] && out.end[poisson] && out.end[energetic]) {
      return out;
    }
    // What happens already (a law met at the end of compression, elasticity 1).
    bool fired = false;
    for (int which = 1; which < 5; ++which) {
      if (event(which, s) >= 0) {
        happen(which, s);
        fired = true;
      }
    }
    if (fired) {
      continue;
    }
    // Coulomb's law for this increment.
    double k = 0;
    if (direction != 0) {
      k = -rod.mu * direction;
    } else {
      // Sticking: the tangential impulse per unit of normal impulse that keeps u_t at zero (u_t
      // after the increment is affine in it: two trials give it), if the cone holds it.
      const double a = tangential_velocity(rod, advance(rod, s, h0, 0.0));
      const double b = tangential_velocity(rod, advance(rod, s, h0, 1.0));
      const double needed = -a / (b - a);
      if (std::abs(needed) <= rod.mu * (1 + 1e-12)) {
        k = needed;
      } else {  // the cone cannot hold it: the end slips, friction at its bound
        k = needed > 0 ? rod.mu : -rod.mu;
        direction = needed > 0 ? -1 : 1;
        out.slipped_again = true;
      }
    }
    // The first event inside the increment, by bisection on its length.
    double h = h0;
    int first = -1;
    for (int which = 0; which < 5; ++which) {
      if (event(which, advance(rod, s, h, k)) < 0) {
        continue;
      }
      double low = 0;
      double high = h;
      for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
        const double middle = 0.5 * (low + high);
        (event(which, advance(rod, s, middle, k)) >= 0 ? high : low) = middle;
      }
      h = high;
      first = which;
    }
    s = advance(rod, s, h, k);
    if (first >= 0) {
      happen(first, s);
    }
  }
  return std::nullopt;
}

// A rod of mass 0.01 to 100 and length 0.1 to 10 (I = m L^2 / 12), at 0.05 to π - 0.05 from a
// floor tilted by up to 0.5 rad, its lower end approaching the floor; μ from 0 to 1.5, the
// elasticity from 1 to 2.
Rod draw(num::Random& random) {
  Rod rod;
  rod.m = random.log_uniform(0.01, 100);
  rod.L = random.log_uniform(0.1, 10);
  rod.I = rod.m * rod.L * rod.L / 12.0;
  const double tilt = random.uniform(-0.5, 0.5);
  rod.n = {-std::sin(tilt), std::cos(tilt)};
  rod.t = {std::cos(tilt), std::sin(tilt)};
  const double angle = random.uniform(0.05, std::numbers::pi - 0.05);
  rod.r = -0.5 * rod.L * (std::cos(angle) * rod.t + std::sin(angle) * rod.n);
  const double speed = random.log_uniform(0.1, 10);
  for (;;) {
    rod.v = random.vector(speed);
    rod.w = random.uniform(-2, 2) * speed / rod.L;
    if ((rod.v + rod.w * perp(rod.r)).dot(rod.n) < -0.05 * speed) {
      break;
    }
  }
  rod.mu = random.uniform(0, 1.5);
  rod.e = random.uniform(1, 2);
  return rod;
}

// The case in the floor's own axes (t along it, n its normal): the arm, the centre's velocity.
Point rod_point(const Rod& rod, const Impact& impact) {
  const auto axes = [&](const Vector2d& x) { return Vector2d(x.dot(rod.t), x.dot(rod.n)); };
  Point p;
  p.set("m", rod.m).set("L", rod.L).set("I", rod.I);
  p.set("\\vec{r}", axes(rod.r)).set("\\vec{n}", axes(rod.n)).set("\\vec{t}", axes(rod.t));
  p.set("\\vec{v}", axes(rod.v)).set("\\omega", rod.w);
  p.set("\\mu", rod.mu).set("\\mathit{elasticity}", rod.e);
  const char* names[3][2] = {{"P_N", "P_{tN}"}, {"P_P", "P_{tP}"}, {"P_E", "P_{tE}"}};
  for (std::size_t law = 0; law < 3; ++law) {
    p.set(names[law][0], impact.end[law]->Pn).set(names[law][1], impact.end[law]->Pt);
  }
  return p;
}

}  // namespace rough_floor

std::vector<Point> point_cloud_struck_obliquely(Probe&, const Settings& s) {
  num::Random r(s.seed);
  std::vector<Point> points;
  for (std::size_t i = 0; i < s.share(10); ++i) {
    const cloud::Cloud body = cloud::sample(r);
    const auto k = static_cast<std::size_t>(r.integer(0, static_cast<int>(body.m.size()) - 1));
    // Any two directions, not necessarily at right angles, and any impulse along them.
    const Eigen::Vector2d n = r.unit_vector();
    const Eigen::Vector2d t = r.unit_vector();
    const double Pn = r.uniform(-10, 10) * body.mass();
    const double Pt = r.uniform(-10, 10) * body.mass();
    const cloud::Cloud after = cloud::after(body, {{k, Pn * n + Pt * t}});
    Point p;
    p.set("m", body.mass()).set("I", body.inertia()).set("\\vec{r}", body.r[k]);
    p.set("\\vec{n}", n).set("\\vec{t}", t).set("P_n", Pn).set("P_t", Pt);
    p.set("\\vec{v}", body.V).set("\\omega", body.w);
    p.set("\\vec{v}'", after.V).set("\\omega'", after.w);
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> rod_slip_then_stick(Probe&, const Settings& s) {
  num::Random random(s.seed);
  std::vector<Point> points;
  const std::size_t wanted = s.share(50);
  for (std::size_t tries = 0; points.size() < wanted && tries < 200 * wanted; ++tries) {
    const rough_floor::Rod rod = rough_floor::draw(random);
    const std::optional<rough_floor::Impact> impact = rough_floor::follow(rod);
    // Only what the increments saw: the slip stopped before compression ended, and the end stuck
    // from there to the last law's end.
    if (!impact || !impact->stop || *impact->stop >= impact->Pc || impact->slipped_again) {
      continue;
    }
    Point p = rough_floor::rod_point(rod, *impact);
    p.set("s", impact->direction).set("P_s", *impact->stop).set("P_c", impact->Pc);
    p.set("w_c", impact->work_c);
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> rods_striking_rough_floors(Probe&, const Settings& s) {
  num::Random random(s.seed);
  std::vector<Point> points;
  const std::size_t wanted = s.share(5);
  for (std::size_t tries = 0; points.size() < wanted && tries < 10 * wanted; ++tries) {
    const rough_floor::Rod rod = rough_floor::draw(random);
    if (const std::optional<rough_floor::Impact> impact = rough_floor::follow(rod)) {
      points.push_back(rod_point(rod, *impact));
    }
  }
  return points;
}

std::vector<Model> friction_models() {
  return {
      {Method::numeric, "point cloud struck obliquely",
       "The body of point masses (3 to 6) receiving an impulse P_n n + P_t t at one of its "
       "points (arm r) along any two unit directions n and t, not necessarily at right angles; "
       "its response by Gauss's principle: the centre's velocity v and spin omega before, v' "
       "and omega' after.",
       point_cloud_struck_obliquely},
      {Method::numeric, "rod on a rough floor, slip then stick",
       "A uniform rod (m 0.01 to 100, L 0.1 to 10, I = m L^2 / 12) strikes a floor tilted by "
       "up to 0.5 rad at its lower end (mu 0 to 1.5, elasticity 1 to 2), followed through its "
       "normal impulse by increments: Coulomb's law picks each increment's tangential impulse, "
       "the momentum and the angular momentum take it, and an event inside an increment (the "
       "slip stopping, compression ending, a law of restitution met) is located by bisection "
       "on its length. Kept: the cases where the slip stopped before compression ended and the "
       "end stuck from there on. It gives the slip's sign s at the start, the normal impulse "
       "P_s where the slip stopped, P_c where compression ended, the work w_c of the normal "
       "impulse until then (summed increment by increment), and the impulses at each law's "
       "end.",
       rod_slip_then_stick, 1e-9, 1e-6},
      {Method::search, "rods striking rough floors",
       "The rods and floors of the model above, every case (slip throughout, slip then stick, "
       "slip that stops and starts again): the normal and tangential impulses at Newton's end "
       "(P_N, P_tN), Poisson's (P_P, P_tP) and the energetic law's (P_E, P_tE).",
       rods_striking_rough_floors, 1e-9, 1e-6},
  };
}

}  // namespace impulse::derivations::models
