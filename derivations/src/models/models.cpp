// SPDX-License-Identifier: GPL-3.0-or-later
// The table of models: what a paper file may name after ode:, quadrature:, model: and search:.
#include "models/catalogue.hpp"
#include "models/model.hpp"

namespace impulse::derivations::models {

const std::vector<Model>& all() {
  static const std::vector<Model> table{
      {"ode",
       "linear spring contact on a line",
       "Two bodies on a line meet; while they overlap a linear spring pushes them apart (GSL "
       "rk8pd until the overlap is gone); the impulse is the time integral of the spring's force "
       "sampled along the motion (Simpson's rule), the momenta after come from the velocities at "
       "the end.",
       {"m_1", "m_2", "p_1", "p_2", "p_1'", "p_2'", "\\vec{p_1}", "\\vec{p_2}", "\\vec{p_1'}",
        "\\vec{p_2'}", "F", "\\vec{F}", "dt"},
       1e-9,
       1e-6,
       false,
       spring_contact_on_a_line},
      {"ode",
       "damper contact on a line",
       "As the linear spring, with a damper alone (force proportional to the closing speed): the "
       "contact ends when the bodies stop closing.",
       {"m_1", "m_2", "p_1", "p_2", "p_1'", "p_2'", "F", "dt"},
       1e-9,
       1e-6,
       false,
       damper_contact_on_a_line},
      {"ode",
       "spring-damper contact on a line",
       "A linear spring and damper of damping ratio 0.05, 0.2 or 0.5: the textbook coefficient "
       "of restitution exp(-z pi / sqrt(1 - z^2)) gives elasticity_1 = elasticity_2 = 1 + that "
       "coefficient.",
       {"m_1", "m_2", "p_1", "p_2", "p_1'", "p_2'", "F", "dt", "elasticity_1", "elasticity_2",
        "elasticity"},
       1e-9,
       1e-6,
       false,
       spring_damper_contact_on_a_line},
      {"search",
       "bodies on a line, one elasticity",
       "Approaching bodies on a line (small whole numbers first, then masses from 1e-3 to 1e3 "
       "and speeds up to 10) with one elasticity for both, from -3 to 10 (0, 1 and 2 included).",
       {"m_1", "m_2", "p_1", "p_2", "elasticity", "elasticity_1", "elasticity_2", "dt"},
       1e-9,
       1e-6,
       false,
       bodies_on_a_line_one_elasticity},
      {"search",
       "bodies on a line, two elasticities",
       "Approaching bodies on a line with an elasticity each, from 1 to 2 (the pairs 2, 1 and "
       "1, 2 on small whole numbers first).",
       {"m_1", "m_2", "p_1", "p_2", "elasticity_1", "elasticity_2", "dt"},
       1e-9,
       1e-6,
       false,
       bodies_on_a_line_two_elasticities},
      {"search",
       "bodies and impulses on a line",
       "Bodies on a line and any impulse between them, from -1e6 to 1e6.",
       {"m_1", "m_2", "p_1", "p_2", "F", "dt"},
       1e-9,
       1e-6,
       false,
       bodies_and_impulses_on_a_line},
      {"numeric",
       "changes of units on a line",
       "Bodies on a line seen in other units of mass, length and time (each changed by a factor "
       "from 1e-3 to 1e3): the same quantities, numbered with a tilde, in the new units.",
       {"m_1", "m_2", "p_1", "p_2", "\\tilde{m}_1", "\\tilde{m}_2", "\\tilde{p}_1", "\\tilde{p}_2",
        "\\mu", "\\lambda"},
       1e-9,
       1e-6,
       false,
       changes_of_units_on_a_line},
      {"numeric",
       "a base turned to a vector",
       "Vectors of the plane and their coordinates in a base turned to a direction: the rotation "
       "of Eigen::Rotation2D by minus the direction's angle, not a dot product. The coordinate of "
       "x along v is cast_v, that of p along the unit normal n (also given as tau = tan(angle/2)) "
       "is p_n.",
       {"\\vec{x}", "\\vec{v}", "\\mathrm{cast}_v", "\\vec{p}", "\\vec{n}", "\\tau", "p_n"},
       1e-9,
       1e-6,
       false,
       base_turned_to_a_vector},
      {"search",
       "momenta and normals in the plane",
       "A momentum and a unit normal (with tau = tan(angle/2)): first p = (0, 2) against n = (1, "
       "0), then random ones, every fourth along the contact's tangent.",
       {"\\vec{p}", "\\vec{n}", "\\tau"},
       1e-9,
       1e-6,
       false,
       momenta_and_normals_in_the_plane},
      {"search",
       "pucks",
       "Two point masses in the plane (masses 1e-3 to 1e3, any momenta), the bumper's outward "
       "normal n (and tau), one elasticity for both (2, 1 or from 0 to 3); first the bumper at "
       "(-1, 0) caught up by the wedge at (-3, 0) against n = (1, 0).",
       {"m_1", "m_2", "\\vec{p_1}", "\\vec{p_2}", "\\vec{n}", "\\tau", "\\mathit{elasticity}_1",
        "\\mathit{elasticity}_2", "dt"},
       1e-9,
       1e-6,
       false,
       pucks},
  };
  return table;
}

const Model* find(std::string_view method, std::string_view name) {
  for (const Model& m : all()) {
    if (m.method == method && m.name == name) {
      return &m;
    }
  }
  return nullptr;
}

}  // namespace impulse::derivations::models
