// SPDX-License-Identifier: GPL-3.0-or-later
// The numeric findings that sections 4 and 5 share on a system assembled from the paper's
// printed coefficients.
#include "many.hpp"
#include "sections.hpp"

namespace impulse::derivations {

std::vector<Finding> printed_system_findings(
    const Context& c, bool rigid, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::string& scenes) {
  const double e = elastic ? 2.0 : 1.0;
  num::Random r(c.seed);
  num::Errors physics, model_agreement, library;
  for (std::size_t i = 0; i < c.share(4); ++i) {
    const many::Scene s = many::random_scene(r, rigid, true, 5, 6);
    const many::System sys = assemble_printed(s);
    const many::Model md = many::model(s);
    model_agreement.add_relative(many::matrix_error(sys.A, md.A()));
    const Eigen::VectorXd B_model = md.J * (e * md.velocity);
    model_agreement.add((sys.B - B_model).norm(), 0.0, B_model.norm() + sys.B.norm() + 1e-300);
    const Eigen::VectorXd F = many::solve(sys.A, sys.B);
    const many::Scene after = many::after(s, F);
    if (elastic) {
      const double E = many::energy(s);
      if (E > 0) {
        physics.add(many::energy(after), E, many::energy_scale(E, sys.A, F));
      }
    } else {
      const double scale = many::approach_scale(s, sys.A, F);
      if (scale > 0) {
        physics.add(many::approach(after).cwiseAbs().maxCoeff(), 0.0, scale);
      }
    }
    const auto lib = many::library_system(s, e);
    library.add_relative(many::matrix_error(lib.A(), sys.A));
    library.add((lib.B() - sys.B).norm(), 0.0, sys.B.norm() + 1e-300);
  }
  return {numeric(Method::numeric, physics, 1e-8,
                  scenes + (elastic ? ": energy kept" : ": approach speeds zero")),
          numeric(Method::numeric, model_agreement, num::holds_below,
                  "the summed blocks equal A = J M^-1 J^T and B built from the contact Jacobian"),
          numeric(Method::numeric, library, num::holds_below,
                  "the library's multipoint::assemble gives the same A and B")};
}

}  // namespace impulse::derivations
