// SPDX-License-Identifier: GPL-3.0-or-later
// The table of models: what a paper file may name after ode:, quadrature:, model: and search:,
// each family's rows kept with its points functions.
#include "models/catalogue.hpp"
#include "models/model.hpp"

namespace impulse::derivations::models {

const std::vector<Model>& all() {
  static const std::vector<Model> table = [] {
    std::vector<Model> rows;
    for (std::vector<Model> (*family)() :
         {line_models, plane_models, rigid_models, contacts_models, friction_models, pulses_models,
          library_models, scenes_models}) {
      for (Model& model : family()) {
        rows.push_back(std::move(model));
      }
    }
    return rows;
  }();
  return table;
}

const Model* find(Method method, std::string_view name) {
  for (const Model& m : all()) {
    if (m.method == method && m.name == name) {
      return &m;
    }
  }
  return nullptr;
}

}  // namespace impulse::derivations::models
