// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/multipoint/multipoint.hpp"

#include <cassert>
#include <cmath>
#include <string>
#include <utility>

#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"

namespace impulse::multipoint {

namespace {

using material_2d::PointMass;
using rigid_2d::RigidBody;

template <typename... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// C++20 deduces this for an aggregate by itself; clang 14 (the fuzzing build) does not yet.
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

std::string place(const char* array, std::size_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// Every body's touches in one pass over the contacts.
std::vector<std::vector<Touch>> touches_by_body(std::size_t bodies,
                                                std::span<const Contact> contacts) {
  std::vector<std::vector<Touch>> result(bodies);
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const Contact& c = contacts[v];
    const auto index = static_cast<Eigen::Index>(v);
    result[c.bumper].push_back({index, c.normal, c.point});
    result[c.wedge].push_back({index, -c.normal, c.point});
  }
  return result;
}

void require_elasticities(std::span<const Body> bodies, std::span<const Elasticity> elasticities) {
  if (elasticities.size() != bodies.size()) {
    throw InvalidInput("elasticities must give one value per body (" +
                       std::to_string(bodies.size()) + "), got " +
                       std::to_string(elasticities.size()));
  }
}

void require_one_per_contact(std::span<const Contact> contacts,
                             const Eigen::Ref<const Eigen::VectorXd>& Fdt) {
  if (Fdt.size() != static_cast<Eigen::Index>(contacts.size())) {
    throw InvalidInput("Fdt must give one impulse per contact (" + std::to_string(contacts.size()) +
                       "), got " + std::to_string(Fdt.size()));
  }
}

// The work of assemble(), approach() and apply_impulses() on arguments already checked: the free
// functions check theirs first, a Configuration did when it was made.

ContactSystem assemble_checked(std::span<const Body> bodies,
                               std::span<const Elasticity> elasticities,
                               const std::vector<std::vector<Touch>>& grouped, std::size_t contacts,
                               Storage storage);

Eigen::VectorXd approach_checked(std::span<const Body> state, std::span<const Contact> contacts) {
  Eigen::VectorXd speeds(static_cast<Eigen::Index>(contacts.size()));
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    speeds(static_cast<Eigen::Index>(v)) = detail::approach_at(state, contacts[v]);
  }
  return speeds;
}

std::vector<Body> after_checked(std::span<const Body> bodies, std::span<const Contact> contacts,
                                const Eigen::Ref<const Eigen::VectorXd>& Fdt) {
  std::vector<Body> after(bodies.begin(), bodies.end());
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const auto index = static_cast<Eigen::Index>(v);
    detail::apply_at(after, contacts[v], index, Fdt(index));
  }
  return after;
}

}  // namespace

namespace {
// Every check of validate() for one body or contact, in one branch: no name is built unless a
// check fails.
bool acceptable(const Body& body) {
  return std::visit(
      Overloaded{[](const PointMass& b) { return material_2d::detail::acceptable(b); },
                 [](const RigidBody& b) { return rigid_2d::detail::acceptable(b); },
                 [](const StaticBody&) { return true; }},
      body);
}

bool acceptable(const Contact& c, std::size_t bodies) {
  const bool indices_ok = (c.bumper < bodies) & (c.wedge < bodies) & (c.bumper != c.wedge);
  const bool normal_ok = is_unit_normal(c.normal);
  const bool point_ok = all_finite(c.point.x(), c.point.y());
  return indices_ok & normal_ok & point_ok;
}
}  // namespace

void validate(std::span<const Body> bodies, std::span<const Contact> contacts) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (acceptable(bodies[i])) [[likely]] {
      continue;
    }
    const std::string name = place("bodies", i);
    std::visit(Overloaded{[&](const PointMass& b) { material_2d::validate(b, name.c_str()); },
                          [&](const RigidBody& b) { rigid_2d::validate(b, name.c_str()); },
                          [](const StaticBody&) {}},
               bodies[i]);
  }
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const Contact& c = contacts[v];
    if (acceptable(c, bodies.size())) [[likely]] {
      continue;
    }
    const std::string name = place("contacts", v);
    for (const auto& [role, index] :
         {std::pair{".bumper", c.bumper}, std::pair{".wedge", c.wedge}}) {
      if (index >= bodies.size()) {
        throw InvalidInput(name + role + " must name one of the " + std::to_string(bodies.size()) +
                           " bodies, got index " + std::to_string(index));
      }
    }
    if (c.bumper == c.wedge) {
      throw InvalidInput(name + " must join two different bodies, got body " +
                         std::to_string(c.bumper) + " in contact with itself");
    }
    require_unit_normal(name + ".normal", c.normal);
    require_finite(name + ".point", c.point);
  }
}

std::vector<Touch> touches(std::size_t body, std::span<const Contact> contacts) {
  std::vector<Touch> result;
  for (std::size_t v = 0; v < contacts.size(); ++v) {
    const Contact& c = contacts[v];
    const auto index = static_cast<Eigen::Index>(v);
    if (c.bumper == body) {
      result.push_back({index, c.normal, c.point});
    } else if (c.wedge == body) {
      result.push_back({index, -c.normal, c.point});
    }
  }
  return result;
}

// A body's block is the Gram matrix of its scaled generalised normals: with column v of G equal
// to the body's normal at contact v scaled by M^(-1/2) and w = elasticity * M^(1/2) * velocity,
// a = G^T G and b = G^T w are the paper's a_vk and b_v. The solver can then factor G itself.

BlockContribution material_block(const PointMass& body, std::span<const Touch> touches,
                                 Elasticity elasticity) {
  const auto n = static_cast<Eigen::Index>(touches.size());
  BlockContribution block;
  block.G.resize(2, n);
  for (Eigen::Index v = 0; v < n; ++v) {
    const Touch& t = touches[static_cast<std::size_t>(v)];
    block.contacts.push_back(t.contact);
    block.G.col(v) = t.normal / std::sqrt(body.mass);
  }
  block.w = elasticity.value() * body.p / std::sqrt(body.mass);
  // (4.5)/(4.8): a_vk = n_k . n_v / m,  b_v = elasticity * p . n_v / m
  block.a.noalias() = block.G.transpose() * block.G;
  block.b.noalias() = block.G.transpose() * block.w;
  return block;
}

BlockContribution rigid_block(const RigidBody& body, std::span<const Touch> touches,
                              Elasticity elasticity) {
  const auto n = static_cast<Eigen::Index>(touches.size());
  BlockContribution block;
  block.G.resize(3, n);
  for (Eigen::Index v = 0; v < n; ++v) {
    const Touch& t = touches[static_cast<std::size_t>(v)];
    block.contacts.push_back(t.contact);
    block.G.col(v).head<2>() = t.normal / std::sqrt(body.mass);  // translation
    block.G(2, v) = det(t.point - body.position, t.normal) / std::sqrt(body.inertia);  // rotation
  }
  block.w.resize(3);
  block.w.head<2>() = elasticity.value() * body.p / std::sqrt(body.mass);
  block.w(2) = elasticity.value() * body.L / std::sqrt(body.inertia);
  // (5.3)/(5.5): a_vk = det(r_k, n_k) det(r_v, n_v) / I + n_k . n_v / m,
  //              b_v  = elasticity * (L det(r_v, n_v) / I + p . n_v / m)
  block.a.noalias() = block.G.transpose() * block.G;
  block.b.noalias() = block.G.transpose() * block.w;
  return block;
}

BlockContribution contribution(const Body& body, std::span<const Touch> touches,
                               Elasticity elasticity) {
  return std::visit(
      Overloaded{[&](const PointMass& b) { return material_block(b, touches, elasticity); },
                 [&](const RigidBody& b) { return rigid_block(b, touches, elasticity); },
                 [](const StaticBody&) { return BlockContribution{}; }},
      body);
}

ContactSystem assemble(std::span<const Body> bodies, std::span<const Elasticity> elasticities,
                       std::span<const Contact> contacts) {
  return assemble(bodies, elasticities, contacts, Storage::automatic);
}

ContactSystem assemble(std::span<const Body> bodies, std::span<const Elasticity> elasticities,
                       std::span<const Contact> contacts, Storage storage) {
  validate(bodies, contacts);
  require_elasticities(bodies, elasticities);
  return assemble_checked(bodies, elasticities, touches_by_body(bodies.size(), contacts),
                          contacts.size(), storage);
}

namespace {
ContactSystem assemble_checked(std::span<const Body> bodies,
                               std::span<const Elasticity> elasticities,
                               const std::vector<std::vector<Touch>>& grouped, std::size_t contacts,
                               Storage storage) {
  ContactSystem system(static_cast<Eigen::Index>(contacts), storage);
  std::size_t blocks = 0;
  std::size_t entries = 0;
  for (const std::vector<Touch>& touches : grouped) {
    blocks += touches.empty() ? 0U : 1U;
    entries += touches.size() * touches.size();
  }
  system.reserve(blocks, entries);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (!grouped[k].empty()) {
      system += contribution(bodies[k], grouped[k], elasticities[k]);  // the ⊕ of section 4.5
    }
  }
  return system;
}
}  // namespace

Eigen::VectorXd approach(std::span<const Body> bodies, std::span<const Contact> contacts) {
  validate(bodies, contacts);
  return approach_checked(bodies, contacts);
}

std::vector<Body> apply_impulses(std::span<const Body> bodies, std::span<const Contact> contacts,
                                 const Eigen::Ref<const Eigen::VectorXd>& Fdt) {
  validate(bodies, contacts);
  require_one_per_contact(contacts, Fdt);
  return after_checked(bodies, contacts, Fdt);
}

double kinetic_energy(const Body& body) {
  return std::visit(Overloaded{[](const PointMass& b) { return material_2d::kinetic_energy(b); },
                               [](const RigidBody& b) { return rigid_2d::kinetic_energy(b); },
                               [](const StaticBody&) { return 0.0; }},
                    body);
}

double kinetic_energy(std::span<const Body> bodies) {
  double total = 0.0;
  for (const Body& body : bodies) {
    total += kinetic_energy(body);
  }
  return total;
}

Eigen::Vector2d momentum(std::span<const Body> bodies) {
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (const Body& body : bodies) {
    std::visit(Overloaded{[&](const PointMass& b) { total += b.p; },
                          [&](const RigidBody& b) { total += b.p; }, [](const StaticBody&) {}},
               body);
  }
  return total;
}

Resolution resolve(std::span<const Body> bodies, std::span<const Elasticity> elasticities,
                   std::span<const Contact> contacts, const SolverOptions& options) {
  validate(bodies, contacts);
  require_elasticities(bodies, elasticities);
  Resolution resolution;
  resolution.solution =
      solve(assemble_checked(bodies, elasticities, touches_by_body(bodies.size(), contacts),
                             contacts.size(), Storage::automatic),
            options);
  resolution.after = resolution.solution.status == SolveStatus::success
                         ? after_checked(bodies, contacts, resolution.solution.Fdt)
                         : std::vector<Body>(bodies.begin(), bodies.end());
  return resolution;
}

Resolution resolve(std::span<const Body> bodies, Elasticity elasticity,
                   std::span<const Contact> contacts, const SolverOptions& options) {
  const std::vector<Elasticity> elasticities(bodies.size(), elasticity);
  return resolve(bodies, elasticities, contacts, options);
}

Configuration::Configuration(std::vector<Body> bodies, std::vector<Elasticity> elasticities,
                             std::vector<Contact> contacts)
    : Configuration(Trusted{}, std::move(bodies), std::move(elasticities), std::move(contacts)) {
  validate(bodies_, contacts_);
  require_elasticities(bodies_, elasticities_);
}

Configuration::Configuration(Trusted /*trusted*/, std::vector<Body> bodies,
                             std::vector<Elasticity> elasticities, std::vector<Contact> contacts)
    : bodies_(std::move(bodies)),
      elasticities_(std::move(elasticities)),
      contacts_(std::move(contacts)),
      touches_(touches_by_body(bodies_.size(), contacts_)) {}

ContactSystem Configuration::assemble(Storage storage) const {
  return assemble_checked(bodies_, elasticities_, touches_, contacts_.size(), storage);
}

Eigen::VectorXd Configuration::approach(std::span<const Body> state) const {
  assert(state.size() == bodies_.size());
  return approach_checked(state, contacts_);
}

std::vector<Body> Configuration::after(const Eigen::Ref<const Eigen::VectorXd>& Fdt) const {
  require_one_per_contact(contacts_, Fdt);
  return after_checked(bodies_, contacts_, Fdt);
}

}  // namespace impulse::multipoint
