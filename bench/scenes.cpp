// SPDX-License-Identifier: GPL-3.0-or-later
#include "scenes.hpp"

#include <array>
#include <charconv>
#include <random>
#include <string>

#include "impulse/core/error.hpp"

namespace impulse::scenes {

namespace {

using Eigen::Vector2d;
using multipoint::Contact;
using multipoint::StaticBody;
using rigid_2d::RigidBody;

constexpr double box_width = 1.0;
constexpr double box_height = 0.5;
const Vector2d down(0.0, -1.0);  // a box's outward normal towards what it rests on

// A box of the given mass centred at `centre`, falling at about 1 with a small spread.
RigidBody falling_box(double mass, const Vector2d& centre, std::mt19937_64& engine) {
  std::uniform_real_distribution<double> spread(-0.1, 0.1);
  RigidBody box;
  box.mass = mass;
  box.inertia = mass * (box_width * box_width + box_height * box_height) / 12.0;  // a rectangle
  box.position = centre;
  box.p = mass * Vector2d(spread(engine), -1.0 + spread(engine));
  box.L = box.inertia * 2.0 * spread(engine);
  return box;
}

void require_contacts(std::size_t contacts) {
  if (contacts == 0) {
    throw InvalidInput("a generated scene needs at least 1 contact, got 0");
  }
}

Scene with_ground() {
  Scene scene;
  scene.bodies.emplace_back(StaticBody{});
  scene.names.emplace_back("ground");
  return scene;
}

std::string number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

std::string pair(const Vector2d& v) {
  std::string text("[");
  text.append(number(v.x())).append(", ").append(number(v.y())).append("]");
  return text;
}

}  // namespace

Scene stack(std::size_t contacts, std::uint64_t seed) {
  require_contacts(contacts);
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> mass(0.5, 2.0);
  Scene scene = with_ground();
  scene.elasticity = Elasticity(1.5);
  std::size_t below = 0;  // the ground, then each box in turn
  for (std::size_t level = 0; scene.contacts.size() < contacts; ++level) {
    const double bottom = box_height * static_cast<double>(level);
    scene.bodies.emplace_back(
        falling_box(mass(engine), Vector2d(0.0, bottom + box_height / 2), engine));
    scene.names.push_back("box" + std::to_string(level));
    const std::size_t box = scene.bodies.size() - 1;
    for (const double corner : {-box_width / 2, box_width / 2}) {
      if (scene.contacts.size() < contacts) {
        scene.contacts.push_back(Contact{box, below, down, Vector2d(corner, bottom)});
      }
    }
    below = box;
  }
  return scene;
}

Scene pyramid(std::size_t contacts, std::uint64_t seed) {
  require_contacts(contacts);
  constexpr double gap = 0.2;
  constexpr double pitch = box_width + gap;
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> mass(0.5, 2.0);
  // The smallest base whose full pyramid has enough contacts: 2b on the ground, 4 per box above.
  std::size_t base = 1;
  while (2 * base + 2 * base * (base - 1) < contacts) {
    ++base;
  }
  Scene scene = with_ground();
  scene.elasticity = Elasticity(1.2);
  std::vector<std::size_t> below;  // the row underneath, by body index
  for (std::size_t row = 0; row < base && scene.contacts.size() < contacts; ++row) {
    std::vector<std::size_t> current;
    const double bottom = box_height * static_cast<double>(row);
    for (std::size_t k = 0; k + row < base && scene.contacts.size() < contacts; ++k) {
      const double x = (static_cast<double>(k) + static_cast<double>(row) / 2.0) * pitch;
      scene.bodies.emplace_back(
          falling_box(mass(engine), Vector2d(x, bottom + box_height / 2), engine));
      scene.names.push_back("box" + std::to_string(row) + "_" + std::to_string(k));
      const std::size_t box = scene.bodies.size() - 1;
      current.push_back(box);
      if (row == 0) {
        // On the ground at both bottom corners.
        for (const double corner : {-box_width / 2, box_width / 2}) {
          if (scene.contacts.size() < contacts) {
            scene.contacts.push_back(Contact{box, 0, down, Vector2d(x + corner, bottom)});
          }
        }
        continue;
      }
      // Straddling boxes k and k + 1 of the row below: with each, the two ends of the overlap
      // of the bottom face with the box's top face.
      const std::array<std::pair<std::size_t, std::array<double, 2>>, 2> supports{{
          {below[k], {x - box_width / 2, x - gap / 2}},
          {below[k + 1], {x + gap / 2, x + box_width / 2}},
      }};
      for (const auto& [support, ends] : supports) {
        for (const double end : ends) {
          if (scene.contacts.size() < contacts) {
            scene.contacts.push_back(Contact{box, support, down, Vector2d(end, bottom)});
          }
        }
      }
    }
    below = std::move(current);
  }
  return scene;
}

Scene cradle(std::size_t contacts) {
  require_contacts(contacts);
  Scene scene;
  scene.elasticity = Elasticity::elastic();
  for (std::size_t i = 0; i <= contacts; ++i) {
    const Vector2d velocity = i == 0 ? Vector2d(1.0, 0.0) : Vector2d::Zero();
    scene.bodies.emplace_back(material_2d::PointMass{1.0, velocity});  // mass 1: p = v
    scene.names.push_back("ball" + std::to_string(i));
  }
  for (std::size_t i = 0; i < contacts; ++i) {
    // Ball i touches ball i + 1 halfway between their centres; its outward normal is +x.
    scene.contacts.push_back(
        Contact{i, i + 1, Vector2d::UnitX(), Vector2d(static_cast<double>(i) + 0.5, 0.0)});
  }
  return scene;
}

Scene generate(std::string_view kind, std::size_t contacts, std::uint64_t seed) {
  if (kind == "stack") {
    return stack(contacts, seed);
  }
  if (kind == "pyramid") {
    return pyramid(contacts, seed);
  }
  if (kind == "cradle") {
    return cradle(contacts);
  }
  std::string message("scene kind must be stack, pyramid or cradle, got ");
  message.append(kind);
  throw InvalidInput(message);
}

Scene sliding(Scene scene, double speed) {
  for (multipoint::Body& body : scene.bodies) {
    if (auto* box = std::get_if<RigidBody>(&body)) {
      box->p.x() += box->mass * speed;
    }
  }
  return scene;
}

multipoint::Configuration configuration(const Scene& scene) {
  return {scene.bodies, std::vector<Elasticity>(scene.bodies.size(), scene.elasticity),
          scene.contacts};
}

std::string to_json(const Scene& scene) {
  std::string out("{\n  \"dimension\": 2,\n  \"elasticity\": ");
  out.append(number(scene.elasticity.value())).append(",\n  \"bodies\": [\n");
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    out.append("    {\"name\": \"").append(scene.names[i]).append("\", ");
    if (const auto* r = std::get_if<RigidBody>(&scene.bodies[i])) {
      out.append("\"kind\": \"rigid\", \"mass\": ").append(number(r->mass));
      out.append(", \"inertia\": ").append(number(r->inertia));
      out.append(", \"position\": ").append(pair(r->position));
      out.append(", \"velocity\": ").append(pair(r->p / r->mass));
      out.append(", \"angular_velocity\": ").append(number(r->L / r->inertia)).append("}");
    } else if (const auto* m = std::get_if<material_2d::PointMass>(&scene.bodies[i])) {
      out.append("\"kind\": \"material\", \"mass\": ").append(number(m->mass));
      out.append(", \"velocity\": ").append(pair(m->p / m->mass)).append("}");
    } else {
      out.append("\"kind\": \"static\"}");
    }
    out.append(i + 1 < scene.bodies.size() ? ",\n" : "\n");
  }
  out.append("  ],\n  \"contacts\": [\n");
  for (std::size_t v = 0; v < scene.contacts.size(); ++v) {
    const Contact& c = scene.contacts[v];
    out.append("    {\"bumper\": \"").append(scene.names[c.bumper]);
    out.append("\", \"wedge\": \"").append(scene.names[c.wedge]);
    out.append("\", \"normal\": ").append(pair(c.normal));
    out.append(", \"point\": ").append(pair(c.point)).append("}");
    out.append(v + 1 < scene.contacts.size() ? ",\n" : "\n");
  }
  out.append("  ]\n}\n");
  return out;
}

}  // namespace impulse::scenes
