// SPDX-License-Identifier: GPL-3.0-or-later
// Random many-body scenes for the section 4 and 5 property tests, and the physics to judge them,
// computed from the raw fields.
#pragma once

#include <vector>

#include "impulse/multipoint/multipoint.hpp"
#include "support/sampling.hpp"

namespace impulse::test {

struct Scene {
  std::vector<multipoint::Body> bodies;
  std::vector<multipoint::Contact> contacts;
};

enum class Kinds { material, rigid, material_and_rigid };

/// 2 to 6 bodies of the given kinds (plus, if `with_static`, a static one now and then) and
/// 1 to 8 contacts between random pairs, with random normals and contact points.
///
/// Masses span 1e-3 .. 1e3. A rigid body's moment of inertia follows from its mass and its
/// radius of gyration k (I = m k^2), and k from how far its contact points lie from its centre:
/// a contact point is on the body, and ordinary convex bodies reach no further than 2.5 k from
/// their centre (a disc sqrt(2) k, a rod or a square sqrt(3) k). Drawing I independently of the
/// arms would make tiny discs touched ten radii away, a geometry no body has. Inertias still
/// span about 1e-4 .. 1e4. Condition numbers of A still reach 1e11 (mass ratios of 1e6 and
/// nearly dependent contacts); see approach_scale for what that means for the tolerances.
inline Scene random_scene(Sampler& sample, Kinds kinds, bool with_static) {
  Scene scene;
  const int count = sample.integer(2, 6);
  for (int i = 0; i < count; ++i) {
    if (with_static && sample.integer(0, 4) == 0) {
      scene.bodies.emplace_back(multipoint::StaticBody{});
      continue;
    }
    const bool rigid =
        kinds == Kinds::rigid || (kinds == Kinds::material_and_rigid && sample.coin());
    const double m = sample.mass();
    if (rigid) {
      // Inertia and spin are set below, once the contact arms are known.
      scene.bodies.emplace_back(
          rigid_2d::RigidBody{m, 1.0, sample.vector(1), m * sample.vector(10), 0.0});
    } else {
      scene.bodies.emplace_back(material_2d::PointMass{m, m * sample.vector(10)});
    }
  }
  const int contacts = sample.integer(1, 8);
  for (int v = 0; v < contacts; ++v) {
    const auto bumper = static_cast<std::size_t>(sample.integer(0, count - 1));
    auto wedge = static_cast<std::size_t>(sample.integer(0, count - 2));
    if (wedge >= bumper) {
      ++wedge;  // any body but the bumper
    }
    scene.contacts.push_back({bumper, wedge, sample.unit_vector(), sample.vector(2)});
  }
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    if (auto* r = std::get_if<rigid_2d::RigidBody>(&scene.bodies[k])) {
      double reach = 0.1;
      for (const auto& c : scene.contacts) {
        if (c.bumper == k || c.wedge == k) {
          reach = std::max(reach, (c.point - r->position).norm());
        }
      }
      const double gyration = reach * sample.uniform(0.4, 1.0);
      r->inertia = r->mass * gyration * gyration;
      r->L = r->inertia * sample.uniform(-10, 10) / reach;  // rim speeds like the translation
    }
  }
  return scene;
}

// Independent physics: energies, velocities of material points, momenta.
inline double energy(const multipoint::Body& body) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p.squaredNorm() / (2 * m->mass);
  }
  if (const auto* r = std::get_if<rigid_2d::RigidBody>(&body)) {
    return r->p.squaredNorm() / (2 * r->mass) + r->L * r->L / (2 * r->inertia);
  }
  return 0.0;
}

inline double energy(const std::vector<multipoint::Body>& bodies) {
  double total = 0;
  for (const auto& b : bodies) {
    total += energy(b);
  }
  return total;
}

inline Eigen::Vector2d velocity_at(const multipoint::Body& body, const Eigen::Vector2d& x) {
  if (const auto* m = std::get_if<material_2d::PointMass>(&body)) {
    return m->p / m->mass;
  }
  if (const auto* r = std::get_if<rigid_2d::RigidBody>(&body)) {
    const Eigen::Vector2d arm = x - r->position;
    return r->p / r->mass + r->L / r->inertia * Eigen::Vector2d(-arm.y(), arm.x());
  }
  return Eigen::Vector2d::Zero();
}

/// Largest normal-velocity mismatch over the contacts: |(v_bumper - v_wedge) . n|.
inline double worst_approach(const std::vector<multipoint::Body>& bodies,
                             const std::vector<multipoint::Contact>& contacts) {
  double worst = 0;
  for (const auto& c : contacts) {
    const double u =
        (velocity_at(bodies[c.bumper], c.point) - velocity_at(bodies[c.wedge], c.point))
            .dot(c.normal);
    worst = std::max(worst, std::abs(u));
  }
  return worst;
}

inline double speed_scale(const Scene& scene) {
  double scale = 0;
  for (const auto& c : scene.contacts) {
    scale = std::max({scale, velocity_at(scene.bodies[c.bumper], c.point).norm(),
                      velocity_at(scene.bodies[c.wedge], c.point).norm()});
  }
  return scale;
}

/// The size of the numbers whose sum is each contact's approach speed after the collision:
/// the speeds before, and for every contact v the terms sum_k |A_vk Fdt_k| of the velocity change
/// that the impulses bring. In a nearly dependent system the exact impulses are far larger than
/// the momenta (they push against each other), and the approach after is their small difference:
/// it can only be as exact as the rounding of these terms, whichever way the system is solved.
inline double approach_scale(const Scene& scene, const Solution& solution) {
  const double terms =
      solution.Fdt.size() == 0 ? 0.0 : (solution.A.cwiseAbs() * solution.Fdt.cwiseAbs()).maxCoeff();
  return std::max(speed_scale(scene), terms);
}

inline Eigen::Vector2d momentum(const std::vector<multipoint::Body>& bodies) {
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (const auto& b : bodies) {
    if (const auto* m = std::get_if<material_2d::PointMass>(&b)) {
      total += m->p;
    } else if (const auto* r = std::get_if<rigid_2d::RigidBody>(&b)) {
      total += r->p;
    }
  }
  return total;
}

inline double momentum_scale(const std::vector<multipoint::Body>& bodies,
                             const Eigen::VectorXd& Fdt) {
  double scale = Fdt.cwiseAbs().sum();
  for (const auto& b : bodies) {
    if (const auto* m = std::get_if<material_2d::PointMass>(&b)) {
      scale += m->p.norm();
    } else if (const auto* r = std::get_if<rigid_2d::RigidBody>(&b)) {
      scale += r->p.norm();
    }
  }
  return scale;
}

}  // namespace impulse::test
