// SPDX-License-Identifier: GPL-3.0-or-later
// Named reference models: the physics a paper file calls on when algebra is not enough (a
// contact simulated in continuous time, a body made of point masses, pulses of force, scenes of
// many bodies, searches for counterexamples). A model knows nothing of the paper's formulas: it
// produces points (values of the file's symbols, in the paper's notation, as its physics gives
// them), and the engine evaluates the file's own statements there. A file chooses its models by
// name:
//
//     ode: spring-damper contact on a line
//
// Adding a model: write its points function in a file of this folder and add its row to that
// family's table at the end of the file (method, name, what it sets, its tolerance).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/check.hpp"
#include "file/time.hpp"

namespace impulse::derivations::models {

/// One value a model gives a symbol of the file: the symbol in the paper's notation ("m_1",
/// "\\vec{p_1}", "F", "dt"), a number or a vector of the plane.
struct Value {
  std::string symbol;
  bool vector = false;
  double x = 0.0;
  double y = 0.0;
};

/// A point: values of symbols, and (quadrature models) the shape of the contact force.
struct Point {
  std::vector<Value> values;
  const file::PulseShape* pulse = nullptr;
  /// Adds a number.
  Point& set(std::string symbol, double x) {
    values.push_back({std::move(symbol), false, x, 0.0});
    return *this;
  }
  /// Adds a vector.
  Point& set(std::string symbol, const Eigen::Vector2d& v) {
    values.push_back({std::move(symbol), true, v.x(), v.y()});
    return *this;
  }
};

/// The engine's side: the file's definitions as functions, for models that compute from what the
/// file says (a system assembled from its coefficients, say).
class Probe {
 public:
  virtual ~Probe() = default;
  /// The file's symbol @p symbol as a function of @p inputs (names in the paper's notation; a
  /// vector takes two arguments, x then y), compiled once for a model that evaluates it often.
  /// The function gives NaN when the file does not define the symbol from those inputs alone.
  [[nodiscard]] virtual std::function<double(std::span<const double>)> function(
      std::string_view symbol, const std::vector<std::string>& inputs) = 0;
};

/// How many points a model makes, and from which seed.
struct Settings {
  std::uint64_t seed = 1;
  std::size_t samples = 10000;
  /// A share of the samples for a costlier model: samples / divisor, at least 1.
  [[nodiscard]] std::size_t share(std::size_t divisor) const {
    return samples / divisor > 0 ? samples / divisor : 1;
  }
};

/// A named model.
struct Model {
  Method method = Method::numeric;  ///< ode, quadrature, numeric (`model:`) or search
  std::string_view name;            ///< what a file writes after the method
  std::string_view summary;         ///< the physics, and the symbols its points give values
  std::vector<Point> (*points)(Probe& probe, const Settings& settings) = nullptr;
  double holds_below = 1e-9;  ///< worst relative residual of a statement that holds on it
  double fails_above = 1e-6;  ///< smallest worst residual of one that does not
  /// Symbols of the file a point leaves unset are drawn at random (quadrature models: they only
  /// shape the force); otherwise they must follow from the equations before.
  bool draws_the_rest = false;
};

/// Every model, in the order of the docs.
[[nodiscard]] const std::vector<Model>& all();

/// The model a file names, or null.
[[nodiscard]] const Model* find(Method method, std::string_view name);

}  // namespace impulse::derivations::models
