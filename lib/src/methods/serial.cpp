// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/methods/serial.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>
#include <variant>

#include "impulse/core/error.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"

namespace impulse::methods {

std::string_view to_string(SerialStatus status) {
  switch (status) {
    case SerialStatus::finished:
      return "finished";
    case SerialStatus::collision_limit:
      return "collision-limit";
    case SerialStatus::non_finite:
      return "non-finite";
  }
  return "?";
}

std::int64_t count_passes(std::span<const Eigen::Index> order) {
  std::int64_t passes = 0;
  std::unordered_set<Eigen::Index> in_this_pass;
  for (const Eigen::Index v : order) {
    if (passes == 0 || in_this_pass.contains(v)) {
      ++passes;
      in_this_pass.clear();
    }
    in_this_pass.insert(v);
  }
  return passes;
}

namespace {

using Eigen::Index;
using Eigen::Vector2d;
using multipoint::Body;
using multipoint::Contact;

// Contact c's approach speed: both bodies' point velocities cast on their own outward normals
// (as multipoint::approach computes it for every contact).
double approach_at(std::span<const Body> bodies, const Contact& c) {
  return multipoint::point_velocity(bodies[c.bumper], c.point).dot(c.normal) +
         multipoint::point_velocity(bodies[c.wedge], c.point).dot(-c.normal);
}

// One body's 1x1 block at one contact: (a, b) of the single-contact formula, from the same
// blocks the paper's many-contact system sums ((4.5)/(4.8), (5.3)/(5.5) with one contact).
ScalarContribution single(const Body& body, const Vector2d& normal, const Vector2d& point,
                          Elasticity elasticity) {
  const multipoint::Touch touch{0, normal, point};
  const BlockContribution block =
      multipoint::contribution(body, std::span<const multipoint::Touch>(&touch, 1), elasticity);
  if (block.contacts.empty()) {
    return {};  // a static body contributes nothing
  }
  return {block.a(0, 0), block.b(0)};
}

// The impulse -normal * Fdt on a body at a point (nothing for a static body).
void push(Body& body, const Vector2d& point, const Vector2d& normal, double Fdt) {
  if (auto* mass = std::get_if<material_2d::PointMass>(&body)) {
    *mass = material_2d::apply_impulse(*mass, normal, Fdt);
  } else if (auto* rigid = std::get_if<rigid_2d::RigidBody>(&body)) {
    *rigid = rigid_2d::apply_impulse(*rigid, point, normal, Fdt);
  }
}

}  // namespace

SerialResolution resolve_serial(std::span<const Body> bodies,
                                std::span<const Elasticity> elasticities,
                                std::span<const Contact> contacts, const SerialOptions& options) {
  multipoint::validate(bodies, contacts);
  if (elasticities.size() != bodies.size()) {
    throw InvalidInput("elasticities must give one value per body (" +
                       std::to_string(bodies.size()) + "), got " +
                       std::to_string(elasticities.size()));
  }
  if (options.max_collisions < 0) {
    throw InvalidInput("max_collisions must be at least 1 (or 0 for " +
                       std::to_string(collisions_per_contact) + " per contact), got " +
                       std::to_string(options.max_collisions));
  }
  if (!(options.approach_tolerance >= 0.0 && std::isfinite(options.approach_tolerance))) {
    throw InvalidInput("approach_tolerance must be finite and at least 0, got " +
                       format_number(options.approach_tolerance));
  }
  const auto n = static_cast<Index>(contacts.size());
  SerialResolution r;
  r.after.assign(bodies.begin(), bodies.end());
  r.Fdt = Eigen::VectorXd::Zero(n);
  SerialDiagnostics& d = r.diagnostics;
  d.max_collisions = options.max_collisions > 0
                         ? options.max_collisions
                         : collisions_per_contact * std::max<std::int64_t>(1, n);

  // Which contacts each body touches: after a collision only theirs change speed.
  std::vector<std::vector<Index>> touching(bodies.size());
  double speed = 0.0;  // the largest speed of a body's point at a contact, before
  Eigen::VectorXd u(n);
  for (Index v = 0; v < n; ++v) {
    const Contact& c = contacts[static_cast<std::size_t>(v)];
    touching[c.bumper].push_back(v);
    touching[c.wedge].push_back(v);
    speed = std::max(speed, multipoint::point_velocity(bodies[c.bumper], c.point).norm() +
                                multipoint::point_velocity(bodies[c.wedge], c.point).norm());
    u(v) = approach_at(r.after, c);
  }
  d.approach_threshold = options.approach_tolerance * speed;
  if (!all_finite_in(u) || !std::isfinite(speed)) {
    d.status = SerialStatus::non_finite;
    return r;
  }

  while (n > 0) {
    Index fastest = 0;
    u.maxCoeff(&fastest);  // the first of equal speeds: the lowest contact index
    if (!(u(fastest) > d.approach_threshold)) {
      break;  // no contact approaches
    }
    if (static_cast<std::int64_t>(d.order.size()) >= d.max_collisions) {
      d.status = SerialStatus::collision_limit;
      d.still_approaching = fastest;
      d.approach_left = u(fastest);
      break;
    }
    const Contact& c = contacts[static_cast<std::size_t>(fastest)];
    // The single-contact formula: F dt (a_1 + a_2) = b_1 + b_2, each body with its own normal
    // (bumper n, wedge -n) and its own elasticity.
    const ScalarSolution one =
        solve(single(r.after[c.bumper], c.normal, c.point, elasticities[c.bumper]) +
              single(r.after[c.wedge], -c.normal, c.point, elasticities[c.wedge]));
    if (one.status != SolveStatus::success || !std::isfinite(one.Fdt)) {
      d.status = SerialStatus::non_finite;
      break;
    }
    push(r.after[c.bumper], c.point, c.normal, one.Fdt);  // -n Fdt on the bumper
    push(r.after[c.wedge], c.point, -c.normal, one.Fdt);  // +n Fdt on the wedge
    r.Fdt(fastest) += one.Fdt;
    d.order.push_back(fastest);
    for (const std::size_t body : {c.bumper, c.wedge}) {
      for (const Index v : touching[body]) {
        u(v) = approach_at(r.after, contacts[static_cast<std::size_t>(v)]);
      }
    }
    if (!all_finite_in(u)) {
      d.status = SerialStatus::non_finite;
      break;
    }
  }
  d.passes = count_passes(d.order);
  return r;
}

SerialResolution resolve_serial(std::span<const Body> bodies, Elasticity elasticity,
                                std::span<const Contact> contacts, const SerialOptions& options) {
  const std::vector<Elasticity> elasticities(bodies.size(), elasticity);
  return resolve_serial(bodies, elasticities, contacts, options);
}

}  // namespace impulse::methods
