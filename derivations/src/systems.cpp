// SPDX-License-Identifier: GPL-3.0-or-later
// What sections 4 and 5 (still C++) share: building and running a check, the numeric findings on
// a system assembled from the paper's printed coefficients, the printed per-contact energies.
#include "sections.hpp"

namespace impulse::derivations {

CodedCheck make_check(std::string id, std::string section, std::optional<std::string> equation,
                      Kind kind, std::string statement,
                      std::function<Outcome(const Context&)> evaluate) {
  Check c;
  c.id = std::move(id);
  c.section = std::move(section);
  c.equation = std::move(equation);
  c.kind = kind;
  c.statement = std::move(statement);
  return {std::move(c), std::move(evaluate)};
}

Outcome evaluate(const CodedCheck& check, const Context& context) {
  try {
    return check.evaluate(context);
  } catch (const std::exception& e) {
    Outcome outcome;
    outcome.status = Status::failed;
    outcome.explanation = std::string("The check could not be evaluated: ") + e.what();
    return outcome;
  }
}

namespace {
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
}  // namespace

ContactEnergy contact_energy(const many::Scene& scene, const Eigen::VectorXd& F, std::size_t body,
                             std::size_t contact) {
  using Eigen::Vector2d;
  const many::Contact& cv = scene.contacts[contact];
  const many::Body& b = scene.bodies[body];
  const std::size_t other = cv.a == body ? cv.b : cv.a;
  const Vector2d nv = cv.a == body ? cv.n : Vector2d(-cv.n);
  double pair = 0, all = 0, spin = 0;
  for (std::size_t k = 0; k < scene.contacts.size(); ++k) {
    const many::Contact& c = scene.contacts[k];
    if (c.a != body && c.b != body)
      continue;
    const Vector2d own = c.a == body ? c.n : Vector2d(-c.n);
    const Vector2d impulse = -own * F(static_cast<Eigen::Index>(k));
    all += impulse.dot(nv);
    if (c.a == other || c.b == other)
      pair += impulse.dot(nv);
    if (b.rigid())
      spin += cross(c.point - b.position, impulse);
  }
  ContactEnergy e;
  e.pair_impulse = pair;
  e.translational = pair * (all / 2 + b.p.dot(nv)) / b.m;
  if (b.rigid()) {
    e.rotational = cross(cv.point - b.position, nv) * pair * (spin / 2 + b.L) / b.I;
  }
  return e;
}

std::vector<Finding> printed_system_findings(
    const Context& c, bool rigid, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::string& scenes) {
  return printed_system_findings(
      c, elastic, assemble_printed,
      [rigid](num::Random& r) { return many::random_scene(r, rigid, true, 5, 6); }, scenes,
      c.share(4));
}

std::vector<Finding> printed_system_findings(
    const Context& c, bool elastic,
    const std::function<many::System(const many::Scene&)>& assemble_printed,
    const std::function<many::Scene(num::Random&)>& draw, const std::string& scenes,
    std::size_t count) {
  const double e = elastic ? 2.0 : 1.0;
  num::Random r(c.seed);
  num::Errors physics, model_agreement, library;
  for (std::size_t i = 0; i < count; ++i) {
    const many::Scene s = draw(r);
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
