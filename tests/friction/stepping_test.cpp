// SPDX-License-Identifier: GPL-3.0-or-later
// An independent cross-check of Routh's method: the same collision integrated by impulse
// stepping on the bodies themselves.
//
// The stepper knows nothing of W, phases or their ends. It applies the normal impulse in small
// equal steps dP; with each, a tangential impulse mu dP against the slip measured at the start
// of the step (explicit Coulomb friction: while the contact sticks, the slip chatters about
// zero and the friction averages out to what sticking takes). After each step it measures the
// contact's velocity from the bodies' states (p += J, L += det(r, J); the point velocity from
// the definitions). Compression ends where the measured separation reaches 0, the slip stops
// where it first changes sign, and restitution ends where the law says, each located within its
// step by linear interpolation. Its errors are of the order of the step.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "impulse/friction/bodies.hpp"
#include "physics.hpp"
#include "support/sampling.hpp"

using Eigen::Vector2d;
using impulse::Elasticity;
using impulse::friction::ContactLaw;
using impulse::friction::ContactStatus;
using impulse::friction::RestitutionLaw;
using impulse::friction::Slip;
using impulse::multipoint::Body;
using impulse::multipoint::StaticBody;
using namespace impulse::test::friction;
namespace friction = impulse::friction;

namespace {

struct Stepped {
  double normal = 0.0;
  double tangential = 0.0;
  double compression = -1.0;  // the normal impulse where compression ended
  double slip_stop = -1.0;    // where the slip first changed sign (-1: never)
  int late_flips = 0;         // sign changes of the slip in the last tenth of the impulse
  Body bumper;
  Body wedge;
};

Vector2d measured_u(const Body& bumper, const Body& wedge, const Vector2d& point,
                    const Vector2d& n) {
  const Vector2d relative = velocity_at(bumper, point) - velocity_at(wedge, point);
  return {-n.dot(relative), friction::tangent(n).dot(relative)};
}

// Integrates the collision with `steps` equal normal steps over [0, scale]-sized impulses;
// `scale` only sets the step (it is the exact answer's size), not where anything ends.
Stepped step_through(const Hit& h, const ContactLaw& law, double scale, int steps) {
  const double dP = scale / steps;
  const double mu = law.friction;
  const double e = law.elasticity.value();
  const Vector2d n = h.normal;
  const Vector2d t = friction::tangent(n);
  Stepped s{0, 0, -1, -1, 0, h.bumper, h.wedge};
  Vector2d u = measured_u(s.bumper, s.wedge, h.point, n);
  const double newton_target = (e - 1.0) * -u.x();
  bool compressing = true;
  double work_compression = 0.0;
  double work_restitution = 0.0;
  for (long k = 0; k < 100L * steps; ++k) {
    const double direction = u.y() > 0 ? 1.0 : (u.y() < 0 ? -1.0 : 0.0);
    const double dPt = -direction * mu * dP;
    const Vector2d J = -n * dP + t * dPt;
    Body bumper = s.bumper;
    Body wedge = s.wedge;
    push(bumper, h.point, J);
    push(wedge, h.point, -J);
    const Vector2d next = measured_u(bumper, wedge, h.point, n);
    // Within the step u is linear in the fraction f of it: u_n(f) = a + f d.
    const double a = u.x();
    const double d = next.x() - u.x();
    const auto work = [&](double f1, double f2) {
      return dP * (a * (f2 - f1) + d * (f2 * f2 - f1 * f1) / 2);
    };
    double f_start = 0.0;  // where restitution starts within this step
    if (compressing) {
      if (next.x() < 0.0) {
        work_compression += work(0, 1);
        f_start = 1.0;
      } else {
        f_start = -a / d;
        work_compression += work(0, f_start);
        s.compression = s.normal + f_start * dP;
        compressing = false;
      }
    }
    double f_end = 2.0;  // where restitution ends within this step (beyond 1: not in it)
    if (!compressing) {
      switch (law.restitution) {
        case RestitutionLaw::newton:
          if (next.x() >= newton_target) {
            f_end = std::max(f_start, (newton_target - a) / d);
          }
          break;
        case RestitutionLaw::poisson:
          if (s.normal + dP >= e * s.compression) {
            f_end = std::max(f_start, (e * s.compression - s.normal) / dP);
          }
          break;
        case RestitutionLaw::energetic: {
          const double target = (e - 1) * (e - 1) * -work_compression;
          if (work_restitution + work(f_start, 1) >= target) {
            double low = f_start;  // bisection for the fraction where the work is reached
            double high = 1.0;
            for (int i = 0; i < 60; ++i) {
              const double mid = (low + high) / 2;
              (work_restitution + work(f_start, mid) >= target ? high : low) = mid;
            }
            f_end = high;
          } else {
            work_restitution += work(f_start, 1);
          }
          break;
        }
      }
    }
    if (direction != 0.0 && next.y() * direction <= 0.0) {
      if (s.slip_stop < 0.0) {
        s.slip_stop = s.normal + dP * u.y() / (u.y() - next.y());
      }
    }
    if (f_end <= 1.0) {  // the last, partial step
      push(s.bumper, h.point, f_end * J);
      push(s.wedge, h.point, -f_end * J);
      s.normal += f_end * dP;
      s.tangential += f_end * dPt;
      return s;
    }
    if (direction != 0.0 && next.y() * direction < 0.0 && s.normal > 0.9 * scale) {
      s.late_flips += 1;
    }
    s.bumper = bumper;
    s.wedge = wedge;
    s.normal += dP;
    s.tangential += dPt;
    u = next;
  }
  FAIL("the stepping did not end");
  return s;
}

// Compares the exact answer with the stepped one. The stepper's errors are a few steps' worth:
// an end located within its step, and, while sticking, a chatter of the slip of at most
// mu |W| dP. The tolerances allow `margin` steps of each.
void compare(const Hit& h, const ContactLaw& law, int steps, double margin,
             impulse::test::Worst& worst) {
  const auto exact = friction::collide(h.bumper, h.wedge, h.point, h.normal, law);
  REQUIRE(exact.impulse.status == ContactStatus::resolved);
  const double P = exact.impulse.normal;
  const Stepped stepped = step_through(h, law, P, steps);
  const double dP = P / steps;
  const double W = mobility(h);
  const double impulse_tolerance = margin * (1 + law.friction) * dP;
  const double speed_tolerance = margin * (1 + law.friction) * W * dP;
  CAPTURE(P, dP, W);

  const Vector2d u = measured_u(stepped.bumper, stepped.wedge, h.point, h.normal);
  // The worst error in the units of the tolerances (steps' worth).
  worst.see(std::max({std::abs(stepped.normal - P),
                      std::abs(stepped.tangential - exact.impulse.tangential),
                      std::abs(stepped.compression - exact.impulse.compression)}) /
            (impulse_tolerance / margin));
  worst.see((u - exact.impulse.u_after).cwiseAbs().maxCoeff() / (speed_tolerance / margin));
  CHECK(std::abs(stepped.normal - P) <= impulse_tolerance);
  CHECK(std::abs(stepped.tangential - exact.impulse.tangential) <= impulse_tolerance);
  CHECK(std::abs(stepped.compression - exact.impulse.compression) <= impulse_tolerance);
  const auto phases = exact.impulse.phases();
  if (phases.size() == 2) {  // a slip that stopped: where it first changed sign
    CHECK(std::abs(stepped.slip_stop - phases[0].end) <= impulse_tolerance);
  } else if (phases[0].regime == Slip::slip) {
    CHECK(stepped.slip_stop < 0.0);  // it never stopped
  }
  CAPTURE(u, exact.impulse.u_after);
  CHECK((u - exact.impulse.u_after).cwiseAbs().maxCoeff() <= speed_tolerance);
}

// Which regime the stepper ended in: chattering (stick), or one sign since its first change.
Slip stepped_outcome(const Stepped& s) {
  if (s.late_flips > 10) {
    return Slip::stick;
  }
  return s.slip_stop < 0.0 ? Slip::slip : Slip::reversed;
}

// The rod of contact_test.cpp: m = 1, I = 1/12, at 45 degrees, centre (h, h) above the end at
// the origin, moving at (0.7, -1).
Hit rod_hit() {
  const double h = std::numbers::sqrt2 / 4;
  return {impulse::rigid_2d::RigidBody{1.0, 1.0 / 12.0, {h, h}, {0.7, -1.0}, 0.0}, StaticBody{},
          Vector2d(0, 0), down};
}

}  // namespace

TEST_CASE("Impulse stepping on the bodies agrees with Routh's method on the worked cases",
          "[friction]") {
  // 100,000 steps: each end within 1e-5 of the impulse, located to a few steps.
  constexpr int steps = 100000;
  struct Case {
    const char* name;
    Hit hit;
    ContactLaw law;
    Slip outcome;
  };
  const Hit sliding{impulse::material_2d::PointMass{2.0, {6.0, -2.0}}, StaticBody{}, Vector2d(0, 0),
                    down};
  const Hit stopping{impulse::material_2d::PointMass{2.0, {1.0, -2.0}}, StaticBody{},
                     Vector2d(0, 0), down};
  const Case cases[] = {
      {"point mass sliding", sliding, {0.2, Elasticity(1.5), RestitutionLaw::newton}, Slip::slip},
      {"point mass sticking",
       stopping,
       {1.0, Elasticity(1.5), RestitutionLaw::poisson},
       Slip::stick},
      {"rod, Newton", rod_hit(), {0.8, Elasticity(1.9), RestitutionLaw::newton}, Slip::stick},
      {"rod, Poisson", rod_hit(), {0.8, Elasticity(1.9), RestitutionLaw::poisson}, Slip::stick},
      {"rod, energetic", rod_hit(), {0.8, Elasticity(1.9), RestitutionLaw::energetic}, Slip::stick},
      {"rod reversing", rod_hit(), {0.3, Elasticity(1.9), RestitutionLaw::newton}, Slip::reversed},
      {"rod reversing, energetic",
       rod_hit(),
       {0.3, Elasticity(1.5), RestitutionLaw::energetic},
       Slip::reversed},
  };
  impulse::test::Worst worst("friction: stepping, worked cases (in steps)");
  for (const Case& c : cases) {
    CAPTURE(c.name);
    compare(c.hit, c.law, steps, 5.0, worst);
    const auto exact =
        friction::collide(c.hit.bumper, c.hit.wedge, c.hit.point, c.hit.normal, c.law);
    CHECK(exact.impulse.outcome == c.outcome);
    const Stepped stepped = step_through(c.hit, c.law, exact.impulse.normal, steps);
    CHECK(stepped_outcome(stepped) == c.outcome);
  }
}

TEST_CASE("Impulse stepping on the bodies agrees with Routh's method on random contacts",
          "[friction]") {
  // Bodies of moderate proportions (masses 0.5 to 2, inertias 0.1 to 1, arms up to 1), so that
  // the stepper's chatter while sticking, mu |W| dP, stays small at 20,000 steps.
  constexpr int steps = 20000;
  impulse::test::Sampler sample("friction stepping");
  const auto rigid = [&] {
    impulse::rigid_2d::RigidBody b;
    b.mass = sample.uniform(0.5, 2.0);
    b.inertia = sample.uniform(0.1, 1.0);
    b.p = b.mass * sample.vector(2.0);
    b.L = b.inertia * sample.uniform(-2.0, 2.0);
    return b;
  };
  impulse::test::Worst worst("friction: stepping, random contacts (in steps)");
  int checked = 0;
  while (checked < impulse::test::configurations / 10) {
    Hit h{rigid(), StaticBody{}, sample.vector(1.0), sample.unit_vector()};
    auto& bumper = std::get<impulse::rigid_2d::RigidBody>(h.bumper);
    bumper.position = h.point + sample.vector(0.7);
    switch (sample.integer(0, 2)) {
      case 0:  // against a static body
        break;
      case 1: {  // against another rigid body
        auto other = rigid();
        other.position = h.point + sample.vector(0.7);
        h.wedge = other;
        break;
      }
      default:  // against a point mass
        h.wedge = impulse::material_2d::PointMass{sample.uniform(0.5, 2.0), sample.vector(2.0)};
        break;
    }
    const ContactLaw law{sample.uniform(0.05, 2.0), Elasticity(sample.uniform(1.0, 2.0)),
                         static_cast<RestitutionLaw>(sample.integer(0, 2))};
    if (friction::dynamics(h.bumper, h.wedge, h.point, h.normal).approach() <= 0.05) {
      continue;  // not approaching (or barely): nothing to integrate
    }
    CAPTURE(checked, bumper.p, bumper.L, bumper.position, h.point, h.normal, law.friction,
            law.elasticity.value(), impulse::name_of(law.restitution));
    compare(h, law, steps, 5.0, worst);
    ++checked;
  }
}
