// SPDX-License-Identifier: GPL-3.0-or-later
// Goal 1 of issues 7 and 16: the A·Fdt = B form costs nothing for a single contact.
//
// Each case is measured twice in one run: `<case>/library` goes through the library's public
// path for bodies checked when they were made (impulse::Checked bodies and an
// impulse::UnitNormal, made once per configuration before the timing: bad input is refused
// there, with its message): `collide`, i.e. each body's contribution, their sum, the solve
// Fdt = B / A, each body's update. `<case>/inlined` writes the same impulse and the same bodies
// after as one formula, the way an engine would hand-code it. Both read their inputs from the
// same pre-generated configurations, cycling through them, and both hand the same outcome, the
// impulse and the two bodies after (the library's own types), to benchmark::DoNotOptimize, so
// that neither can be folded away or hoisted out of the loop. The library's diagnostics (A, B,
// residual, flags) are not part of the outcome: a caller who does not read them does not pay for
// them, since the path is inline. Run the pairs interleaved
// (--benchmark_enable_random_interleaving=true, several repetitions): bench/run does.
//
// Not pairs, for the breakdown: `<case>/checked_each_time`, the overload that checks its plain
// bodies (and the normal's length) at every collision (as the public path once did at every one).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>

#include <vector>

#include "impulse/core/checked.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/one_d/one_d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"

namespace {

using Eigen::Vector2d;
using impulse::Checked;
using impulse::Elasticity;
using impulse::UnitNormal;

// A power of two, so that the index wraps with a mask; large enough that the branch predictor
// cannot learn the inputs, small enough (a few tens of KiB) to stay in the L1/L2 caches.
constexpr std::size_t configurations = 1024;
constexpr std::size_t mask = configurations - 1;

// One collision, its bodies stored in each section's own type, so that neither side of a pair
// converts anything in the timed loop.
struct Configuration {
  impulse::rigid_2d::RigidBody bumper;
  impulse::rigid_2d::RigidBody wedge;
  impulse::material_2d::PointMass bumper_point;  // the rigid bodies' masses and momenta
  impulse::material_2d::PointMass wedge_point;
  impulse::one_d::Body first;  // masses and the x components of the momenta
  impulse::one_d::Body second;
  Elasticity bumper_elasticity;
  Elasticity wedge_elasticity;
  Vector2d point;
  Vector2d n;
};

// Masses and inertias over three orders of magnitude, random normals, points and velocities.
const std::array<Configuration, configurations>& table() {
  static const auto configs = [] {
    std::array<Configuration, configurations> result{};
    std::mt19937_64 engine(20240607);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto log_uniform = [&](double low, double high) {
      return std::exp(std::log(low) + (unit(engine) + 1.0) / 2.0 * (std::log(high / low)));
    };
    for (Configuration& c : result) {
      const double angle = std::numbers::pi * unit(engine);
      c.n = {std::cos(angle), std::sin(angle)};
      c.point = {unit(engine), unit(engine)};
      for (auto* body : {&c.bumper, &c.wedge}) {
        body->mass = log_uniform(0.1, 100.0);
        body->inertia = log_uniform(0.1, 100.0);
        body->position = {unit(engine), unit(engine)};
        body->p = body->mass * Vector2d(10 * unit(engine), 10 * unit(engine));
        body->L = body->inertia * 10 * unit(engine);
      }
      c.bumper_point = {c.bumper.mass, c.bumper.p};
      c.wedge_point = {c.wedge.mass, c.wedge.p};
      c.first = {c.bumper.mass, c.bumper.p.x()};
      c.second = {c.wedge.mass, c.wedge.p.x()};
      c.bumper_elasticity = Elasticity(1.0 + (unit(engine) + 1.0) / 2.0);
      c.wedge_elasticity = Elasticity(1.0 + (unit(engine) + 1.0) / 2.0);
    }
    return result;
  }();
  return configs;
}

// The same configurations as the library takes them: bodies checked and normals made once.
struct CheckedConfiguration {
  Checked<impulse::rigid_2d::RigidBody> bumper;
  Checked<impulse::rigid_2d::RigidBody> wedge;
  Checked<impulse::material_2d::PointMass> bumper_point;
  Checked<impulse::material_2d::PointMass> wedge_point;
  Checked<impulse::one_d::Body> first;
  Checked<impulse::one_d::Body> second;
  Elasticity bumper_elasticity;
  Elasticity wedge_elasticity;
  Vector2d point;
  UnitNormal n;
};

const std::vector<CheckedConfiguration>& checked_table() {
  static const auto configs = [] {
    std::vector<CheckedConfiguration> result;
    result.reserve(configurations);
    for (const Configuration& c : table()) {
      result.push_back({Checked(c.bumper, "bumper"), Checked(c.wedge, "wedge"),
                        Checked(c.bumper_point, "bumper"), Checked(c.wedge_point, "wedge"),
                        Checked(c.first, "first"), Checked(c.second, "second"), c.bumper_elasticity,
                        c.wedge_elasticity, c.point, UnitNormal(c.n)});
    }
    return result;
  }();
  return configs;
}

struct OneDOutcome {
  double Fdt;
  impulse::one_d::Body first, second;
};

// §1: two bodies on a line, the first on the left (its outward direction +1).
void one_d_library(benchmark::State& state) {
  const auto& configs = checked_table();
  std::size_t i = 0;
  for (auto _ : state) {
    const CheckedConfiguration& c = configs[i++ & mask];
    const auto result =
        impulse::one_d::collide(c.first, c.bumper_elasticity, c.second, c.wedge_elasticity);
    OneDOutcome outcome{result.solution.Fdt, result.first, result.second};
    benchmark::DoNotOptimize(outcome);
  }
}

void one_d_inlined(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const double m1 = c.first.mass;
    const double m2 = c.second.mass;
    const double p1 = c.first.momentum;
    const double p2 = c.second.momentum;
    // (1.3) by hand: Fdt (1/m1 + 1/m2) = e1 p1/m1 - e2 p2/m2 (the second body's outward is -1).
    const double Fdt =
        (c.bumper_elasticity.value() * p1 / m1 - c.wedge_elasticity.value() * p2 / m2) /
        (1.0 / m1 + 1.0 / m2);
    OneDOutcome outcome{Fdt, {m1, p1 - Fdt}, {m2, p2 + Fdt}};
    benchmark::DoNotOptimize(outcome);
  }
}

struct MaterialOutcome {
  double Fdt;
  impulse::material_2d::PointMass bumper, wedge;
};

// §2: two point masses in the plane.
void material_library(benchmark::State& state) {
  const auto& configs = checked_table();
  std::size_t i = 0;
  for (auto _ : state) {
    const CheckedConfiguration& c = configs[i++ & mask];
    const auto result = impulse::material_2d::collide(c.bumper_point, c.bumper_elasticity,
                                                      c.wedge_point, c.wedge_elasticity, c.n);
    MaterialOutcome outcome{result.solution.Fdt, result.bumper, result.wedge};
    benchmark::DoNotOptimize(outcome);
  }
}

void material_inlined(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const double m1 = c.bumper_point.mass;
    const double m2 = c.wedge_point.mass;
    const Vector2d& n = c.n;
    // The cast onto the normal, then (1.3): each body's normal velocity towards the other.
    const double u1 = c.bumper_point.p.dot(n) / m1;
    const double u2 = -c.wedge_point.p.dot(n) / m2;
    const double Fdt = (c.bumper_elasticity.value() * u1 + c.wedge_elasticity.value() * u2) /
                       (1.0 / m1 + 1.0 / m2);
    MaterialOutcome outcome{Fdt, {m1, c.bumper_point.p - n * Fdt}, {m2, c.wedge_point.p + n * Fdt}};
    benchmark::DoNotOptimize(outcome);
  }
}

struct RigidOutcome {
  double Fdt;
  impulse::rigid_2d::RigidBody bumper, wedge;
};

// §3: two rigid bodies, one contact point.
void rigid_library(benchmark::State& state) {
  const auto& configs = checked_table();
  std::size_t i = 0;
  for (auto _ : state) {
    const CheckedConfiguration& c = configs[i++ & mask];
    const auto result = impulse::rigid_2d::collide(c.bumper, c.bumper_elasticity, c.wedge,
                                                   c.wedge_elasticity, c.point, c.n);
    RigidOutcome outcome{result.solution.Fdt, result.bumper, result.wedge};
    benchmark::DoNotOptimize(outcome);
  }
}

void rigid_inlined(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const auto& b1 = c.bumper;
    const auto& b2 = c.wedge;
    const Vector2d& n = c.n;
    const Vector2d r1 = c.point - b1.position;
    const Vector2d r2 = c.point - b2.position;
    const double arm1 = r1.x() * n.y() - r1.y() * n.x();     // det(r1, n)
    const double arm2 = -(r2.x() * n.y() - r2.y() * n.x());  // det(r2, -n)
    // Each point's normal velocity towards the other body, then
    // j = (e1 u1 + e2 u2) / (1/m1 + 1/m2 + (r1 x n)^2/I1 + (r2 x n)^2/I2).
    const double u1 = b1.L * arm1 / b1.inertia + b1.p.dot(n) / b1.mass;
    const double u2 = b2.L * arm2 / b2.inertia - b2.p.dot(n) / b2.mass;
    const double Fdt =
        (c.bumper_elasticity.value() * u1 + c.wedge_elasticity.value() * u2) /
        (1.0 / b1.mass + 1.0 / b2.mass + arm1 * arm1 / b1.inertia + arm2 * arm2 / b2.inertia);
    // The bodies after: p' = p -+ n j, L' = L - det(r, n_own) j.
    RigidOutcome outcome{Fdt,
                         {b1.mass, b1.inertia, b1.position, b1.p - n * Fdt, b1.L - arm1 * Fdt},
                         {b2.mass, b2.inertia, b2.position, b2.p + n * Fdt, b2.L - arm2 * Fdt}};
    benchmark::DoNotOptimize(outcome);
  }
}

// Not pairs: the overloads that check their plain bodies and the normal at every collision.
void one_d_checked_each_time(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const auto result =
        impulse::one_d::collide(c.first, c.bumper_elasticity, c.second, c.wedge_elasticity);
    OneDOutcome outcome{result.solution.Fdt, result.first, result.second};
    benchmark::DoNotOptimize(outcome);
  }
}

void material_checked_each_time(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const auto result = impulse::material_2d::collide(c.bumper_point, c.bumper_elasticity,
                                                      c.wedge_point, c.wedge_elasticity, c.n);
    MaterialOutcome outcome{result.solution.Fdt, result.bumper, result.wedge};
    benchmark::DoNotOptimize(outcome);
  }
}

void rigid_checked_each_time(benchmark::State& state) {
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const auto result = impulse::rigid_2d::collide(c.bumper, c.bumper_elasticity, c.wedge,
                                                   c.wedge_elasticity, c.point, c.n);
    RigidOutcome outcome{result.solution.Fdt, result.bumper, result.wedge};
    benchmark::DoNotOptimize(outcome);
  }
}

struct FrictionOutcome {
  double normal, tangential;
  impulse::multipoint::Body bumper, wedge;
};

// Beyond the paper: the same collisions with Coulomb friction (mu = 0.5, Newton's law
// at the bumper's elasticity), followed through the normal impulse by the exact single-contact
// rule through its public path: W and u0 from the bodies (multipoint::contribution), the phases,
// and the bodies after (multipoint::apply_impulses). Not a pair: it computes more than the
// paper's impulse (a tangential impulse and the phases), so rigid_single_contact/library is its
// reference.
void rigid_friction(benchmark::State& state) {
  namespace friction = impulse::friction;
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const Configuration& c = configs[i++ & mask];
    const auto result =
        friction::collide(c.bumper, c.wedge, c.point, c.n,
                          {0.5, c.bumper_elasticity, friction::RestitutionLaw::newton});
    FrictionOutcome outcome{result.impulse.normal, result.impulse.tangential, result.after.bumper,
                            result.after.wedge};
    benchmark::DoNotOptimize(outcome);
  }
}

// Not a pair either: the core alone (resolve_contact on W and u0 computed beforehand), to show in
// the table how much of the above is the rule and how much the bodies' side (building W from the
// blocks, which allocate, and applying the impulse through the many-body update).
void rigid_friction_core(benchmark::State& state) {
  namespace friction = impulse::friction;
  static const auto contacts = [] {
    std::array<friction::ContactDynamics, configurations> result{};
    for (std::size_t k = 0; k < configurations; ++k) {
      const Configuration& c = table()[k];
      result[k] = friction::dynamics(c.bumper, c.wedge, c.point, c.n);
    }
    return result;
  }();
  const auto& configs = table();
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & mask;
    const auto impulse = friction::resolve_contact(
        contacts[k], {0.5, configs[k].bumper_elasticity, friction::RestitutionLaw::newton});
    benchmark::DoNotOptimize(impulse);
  }
}

}  // namespace

// Registered in pairs, library first, so that the table reads one case at a time.
BENCHMARK(one_d_library)->Name("one_d_single_contact/library");
BENCHMARK(one_d_inlined)->Name("one_d_single_contact/inlined");
BENCHMARK(material_library)->Name("material_single_contact/library");
BENCHMARK(material_inlined)->Name("material_single_contact/inlined");
BENCHMARK(rigid_library)->Name("rigid_single_contact/library");
BENCHMARK(rigid_inlined)->Name("rigid_single_contact/inlined");
BENCHMARK(rigid_friction)->Name("rigid_single_contact_friction/library");
BENCHMARK(rigid_friction_core)->Name("rigid_single_contact_friction_breakdown/core");
BENCHMARK(one_d_checked_each_time)->Name("one_d_single_contact/checked_each_time");
BENCHMARK(material_checked_each_time)->Name("material_single_contact/checked_each_time");
BENCHMARK(rigid_checked_each_time)->Name("rigid_single_contact/checked_each_time");

BENCHMARK_MAIN();
