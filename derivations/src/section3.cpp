// SPDX-License-Identifier: GPL-3.0-or-later
// Section 3: a rigid body in the plane with one contact point.
//
// The physics: a rigid body of mass m and moment of inertia I about its centre of mass, momentum
// p and angular momentum L about that centre; an impulse J at the material point at arm r (from
// the centre) changes p by J and L by det(r, J) (Newton-Euler); the impulse on the body is -n Fdt,
// n its outward normal. The other body of the contact (rigid, arm r_o, or a point mass) receives
// +n Fdt. Elastic: the total kinetic energy is unchanged; inelastic: both material points at the
// contact have the same velocity along n afterwards.
#include <cmath>
#include <complex>
#include <numbers>

#include "cloud.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "numeric.hpp"
#include "sections.hpp"

namespace impulse::derivations {

namespace {

using Eigen::Vector2d;
using GiNaC::ex;
using sym::Equation;

struct RigidSymbols {
  GiNaC::possymbol m{"m"}, I{"I"};
  GiNaC::realsymbol px{"px", "p_x"}, py{"py", "p_y"}, L{"L"};
  GiNaC::realsymbol rx{"rx", "r_x"}, ry{"ry", "r_y"};
  GiNaC::realsymbol nx{"nx", "n_x"}, ny{"ny", "n_y"};
  GiNaC::realsymbol F{"Fdt", "F\\,dt"};
  GiNaC::realsymbol Eo{"Eo", "E_o"}, Eo2{"Eo2", "E_o'"}, dEo{"dEo", "\\Delta E_o"};
  GiNaC::realsymbol von{"von", "v'_{on}"};
  // The other body: rigid (mass, inertia, momentum, spin, arm) or, with the rotation dropped,
  // a point mass.
  GiNaC::possymbol mo{"mo", "m_o"}, Io{"Io", "I_o"};
  GiNaC::realsymbol pox{"pox", "p_{ox}"}, poy{"poy", "p_{oy}"}, Lo{"Lo", "L_o"};
  GiNaC::realsymbol rox{"rox", "r_{ox}"}, roy{"roy", "r_{oy}"};
  [[nodiscard]] ex arm() const { return rx * ny - ry * nx; }  // det(r, n)
  [[nodiscard]] ex n2() const { return nx * nx + ny * ny; }
  [[nodiscard]] std::vector<ex> body() const { return {m, I, px, py, L, rx, ry, nx, ny}; }
};

const RigidSymbols& rs() {
  static const RigidSymbols s;
  return s;
}

ex det(const ex& ax, const ex& ay, const ex& bx, const ex& by) {
  return ax * by - ay * bx;
}

// Kinetic energies after an impulse (jx, jy) at arm (ax, ay), from the definitions.
ex rigid_energy(const ex& m, const ex& I, const ex& px, const ex& py, const ex& L) {
  return (px * px + py * py) / (2 * m) + L * L / (2 * I);
}

// The printed (3.6) and (3.10) coefficients for a body with normal (nx, ny) at arm (rx, ry).
struct Coefficients {
  ex A, B;
};
Coefficients printed_3_6(const ex& m, const ex& I, const ex& px, const ex& py, const ex& L,
                         const ex& rx, const ex& ry, const ex& nx, const ex& ny) {
  const ex d = det(rx, ry, nx, ny);
  return {d * d / I + (nx * nx + ny * ny) / m, 2 * L * d / I + 2 * (px * nx + py * ny) / m};
}
Coefficients printed_3_10(const ex& m, const ex& I, const ex& px, const ex& py, const ex& L,
                          const ex& rx, const ex& ry, const ex& nx, const ex& ny) {
  const ex d = det(rx, ry, nx, ny);
  return {d * d / I + (nx * nx + ny * ny) / m, L * d / I + (px * nx + py * ny) / m};
}

// ---- numbers ------------------------------------------------------------------------------

struct Body {
  double m, I;
  Vector2d p;
  double L;
  [[nodiscard]] double energy() const { return p.squaredNorm() / (2 * m) + L * L / (2 * I); }
  [[nodiscard]] Vector2d velocity_at(const Vector2d& r) const {
    return p / m + L / I * Vector2d(-r.y(), r.x());
  }
  [[nodiscard]] Body after(const Vector2d& r, const Vector2d& J) const {
    return {m, I, p + J, L + (r.x() * J.y() - r.y() * J.x())};
  }
};

Body sample_body(num::Random& r) {
  Body b{r.mass(), 0, {}, 0};
  const double gyration = r.log_uniform(0.1, 10);  // radius of gyration
  b.I = b.m * gyration * gyration;
  b.p = b.m * r.vector(10);
  b.L = b.I * r.uniform(-10, 10) / gyration;
  return b;
}

using cloud::Cloud;

// ---- the checks -----------------------------------------------------------------------------

Outcome claim_point_components(const Context&) {
  // v_v = (L/I)[-r_y, r_x] + p/m: its x component involves L and p_x only, its y component L and
  // p_y only.
  const auto& s = rs();
  const ex vx = -s.ry * s.L / s.I + s.px / s.m;
  const ex vy = s.rx * s.L / s.I + s.py / s.m;
  const bool separate = GiNaC::diff(vx, s.py).is_zero() && GiNaC::diff(vy, s.px).is_zero() &&
                        !GiNaC::diff(vx, s.L).is_zero() && !GiNaC::diff(vy, s.L).is_zero();
  return judge(ClaimVerdict{{symbolic(separate)}, std::nullopt, {}, {}});
}

Outcome equation_3_1(const Context& c) {
  // E_k = L^2/2I + |p|^2/2m, against a body made of point masses with its energy summed point by
  // point (I, p and L of the points; the centre of mass is the origin).
  const GiNaC::possymbol m1("m1"), m2("m2");
  const GiNaC::realsymbol ax("ax"), ay("ay"), Vx("Vx"), Vy("Vy"), w("w");
  // Two masses with their centre at the origin: m1 a + m2 b = 0.
  const ex bx = -m1 * ax / m2, by = -m1 * ay / m2;
  const auto speed2 = [&](const ex& x, const ex& y) {
    return GiNaC::pow(Vx - w * y, 2) + GiNaC::pow(Vy + w * x, 2);
  };
  const ex summed = m1 * speed2(ax, ay) / 2 + m2 * speed2(bx, by) / 2;
  const ex M = m1 + m2;
  const ex I = m1 * (ax * ax + ay * ay) + m2 * (bx * bx + by * by);
  const ex L = I * w;
  const ex printed = L * L / (2 * I) + (GiNaC::pow(M * Vx, 2) + GiNaC::pow(M * Vy, 2)) / (2 * M);
  const bool exact = sym::simplify(printed - summed).is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Cloud cloud = cloud::sample(r);
    const double Lc = cloud.angular_momentum();
    const Vector2d p = cloud.momentum();
    errors.add(Lc * Lc / (2 * cloud.inertia()) + p.squaredNorm() / (2 * cloud.mass()),
               cloud.energy());
  }
  return judge(EquationVerdict{
      {symbolic(exact, "two point masses about their centre of mass"),
       numeric(Method::numeric, errors, num::holds_below, "bodies of 3 to 6 point masses")},
      {},
      {},
      {},
      "L and I are taken about the centre of mass; about any other "
      "origin of a free body the split has a cross term."});
}

Outcome equation_3_2(const Context& c) {
  const auto& s = rs();
  const GiNaC::realsymbol Fx("Fx"), Fy("Fy");
  // The printed expansions: det(r, F) = r_x F_y - r_y F_x and |p + F|^2 by components.
  const ex rotational = GiNaC::pow(s.L + det(s.rx, s.ry, Fx, Fy), 2) / (2 * s.I);
  const ex rotational_expanded = GiNaC::pow(s.L + (s.rx * Fy - s.ry * Fx), 2) / (2 * s.I);
  const ex translational_expanded =
      (GiNaC::pow(s.px + Fx, 2) + GiNaC::pow(s.py + Fy, 2)) / (2 * s.m);
  const ex translational = ((s.px + Fx) * (s.px + Fx) + (s.py + Fy) * (s.py + Fy)) / (2 * s.m);
  const bool exact = sym::simplify(rotational - rotational_expanded).is_zero() &&
                     sym::simplify(translational - translational_expanded).is_zero();
  // Against a body of point masses that receives an impulse at one of its points.
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Cloud cloud = cloud::sample(r);
    const std::size_t k =
        static_cast<std::size_t>(r.integer(0, static_cast<int>(cloud.m.size()) - 1));
    const Vector2d J = r.vector(10) * cloud.mass();
    const Vector2d arm = cloud.r[k];
    const double L = cloud.angular_momentum();
    const Vector2d p = cloud.momentum();
    const double I = cloud.inertia();
    const double M = cloud.mass();
    const double printed = std::pow(L + (arm.x() * J.y() - arm.y() * J.x()), 2) / (2 * I) +
                           (std::pow(p.x() + J.x(), 2) + std::pow(p.y() + J.y(), 2)) / (2 * M);
    // The body's own response (Gauss's principle on its points), energy summed point by point.
    errors.add(printed, cloud::after(cloud, {{k, J}}).energy());
  }
  return judge(EquationVerdict{{symbolic(exact, "the expanded forms equal the det and norm forms"),
                                numeric(Method::numeric, errors, num::holds_below,
                                        "bodies of point masses receiving an impulse at a point, "
                                        "their response by Gauss's principle")},
                               {},
                               {},
                               {},
                               {}});
}

Outcome equation_3_3(const Context& c) {
  // F_x dt = -n_x Fdt, F_y dt = -n_y Fdt: section 2's vectorised impulse; the library applies it.
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Body b = sample_body(r);
    const Vector2d n = r.unit_vector();
    const Vector2d point = r.vector(3);
    const double F = r.uniform(-10, 10) * b.m;
    const rigid_2d::RigidBody before{b.m, b.I, {0, 0}, b.p, b.L};
    const auto after = rigid_2d::apply_impulse(before, point, n, F);
    errors.add((after.p - before.p - Vector2d(-n.x() * F, -n.y() * F)).norm(), 0.0,
               std::abs(F) + b.p.norm());
  }
  return judge(EquationVerdict{{numeric(Method::numeric, errors, num::holds_below,
                                        "the library's rigid_2d::apply_impulse changes p by "
                                        "(F_x dt, F_y dt)")},
                               {},
                               {},
                               {},
                               "The display lost its label; the text's reference to (3.3) "
                               "between (3.2) and (3.4) identifies it."});
}

// ---- the energy derivation of section 3.1 ----------------------------------------------------

// (3.4): E_k + E_o = E_k' + E_o', with (3.1)-(3.3) substituted: the combined line.
Equation conservation_with_definitions(const ex& Eo_after) {
  const auto& s = rs();
  const ex Fx = -s.nx * s.F, Fy = -s.ny * s.F;
  return {s.Eo + rigid_energy(s.m, s.I, s.px, s.py, s.L),
          Eo_after + rigid_energy(s.m, s.I, s.px + Fx, s.py + Fy, s.L + det(s.rx, s.ry, Fx, Fy))};
}

Equation printed_combined() {
  const auto& s = rs();
  const ex d = s.rx * s.ny - s.ry * s.nx;
  return {s.Eo + s.L * s.L / (2 * s.I) + (s.px * s.px + s.py * s.py) / (2 * s.m),
          s.Eo2 + (s.L * s.L - 2 * s.L * s.F * d + s.F * s.F * d * d) / (2 * s.I) +
              (s.px * s.px - 2 * s.F * s.nx * s.px + s.F * s.F * s.nx * s.nx + s.py * s.py -
               2 * s.F * s.ny * s.py + s.F * s.F * s.ny * s.ny) /
                  (2 * s.m)};
}

Outcome combined_step(const Context&) {
  const bool follows =
      sym::nonzero_multiple(printed_combined(), conservation_with_definitions(rs().Eo2), {})
          .has_value();
  return judge(EquationVerdict{
      {symbolic(follows, "(3.4) with (3.1), (3.2) and (3.3) substituted")}, {}, {}, {}, {}});
}

Equation printed_divided() {
  const auto& s = rs();
  const ex d = s.rx * s.ny - s.ry * s.nx;
  return {s.F * (d * d / s.I + (s.nx * s.nx + s.ny * s.ny) / s.m) + 2 * s.dEo / s.F,
          2 * s.L * d / s.I + 2 * (s.nx * s.px + s.ny * s.py) / s.m};
}

Outcome divided_step(const Context&) {
  const auto& s = rs();
  // With E_o' = E_o + dE_o, the combined line minus the repeated terms, divided by Fdt/2.
  const Equation combined = conservation_with_definitions(s.Eo + s.dEo);
  const bool follows = sym::nonzero_multiple(printed_divided(), combined, {{s.F}}).has_value();
  return judge(EquationVerdict{
      {symbolic(follows, "a multiple of the combined line when Fdt != 0")}, {}, {}, {}, {}});
}

Outcome equation_3_5(const Context&) {
  const auto& s = rs();
  const Equation printed{s.F * (s.arm() * s.arm() / s.I + s.n2() / s.m) + 2 * s.dEo / s.F,
                         2 * s.L * s.arm() / s.I + 2 * (s.px * s.nx + s.py * s.ny) / s.m};
  const bool same = sym::nonzero_multiple(printed, printed_divided(), {}).has_value();
  const bool from_definition =
      sym::nonzero_multiple(printed, conservation_with_definitions(s.Eo + s.dEo), {{s.F}})
          .has_value();
  return judge(EquationVerdict{{symbolic(same, "the line before it with det and the norm"),
                                symbolic(from_definition, "from (3.4) directly, Fdt != 0")},
                               {},
                               {},
                               {},
                               {}});
}

// The other body's energy change when it receives +n F at its arm r_o (rigid) or anywhere
// (a point mass, `rigid` false).
ex other_energy_change(bool rigid, const ex& F) {
  const auto& s = rs();
  const ex Jx = s.nx * F, Jy = s.ny * F;
  if (rigid) {
    return rigid_energy(s.mo, s.Io, s.pox + Jx, s.poy + Jy, s.Lo + det(s.rox, s.roy, Jx, Jy)) -
           rigid_energy(s.mo, s.Io, s.pox, s.poy, s.Lo);
  }
  const auto e = [](const ex& m, const ex& x, const ex& y) { return (x * x + y * y) / (2 * m); };
  return e(s.mo, s.pox + Jx, s.poy + Jy) - e(s.mo, s.pox, s.poy);
}

// The other body's own coefficients with its own normal -n.
Coefficients other_coefficients(bool rigid, bool elastic) {
  const auto& s = rs();
  if (rigid) {
    return elastic ? printed_3_6(s.mo, s.Io, s.pox, s.poy, s.Lo, s.rox, s.roy, -s.nx, -s.ny)
                   : printed_3_10(s.mo, s.Io, s.pox, s.poy, s.Lo, s.rox, s.roy, -s.nx, -s.ny);
  }
  const ex pn = -(s.pox * s.nx + s.poy * s.ny);
  const ex n2 = s.nx * s.nx + s.ny * s.ny;
  return {n2 / s.mo, (elastic ? 2 : 1) * pn / s.mo};
}

Outcome claim_split(const Context&) {
  // 2 dE_o / Fdt = Fdt A_o - B_o with the other body's own (3.6): its part of (3.5) has the same
  // form as the body's own, for a rigid body and for a point mass.
  const auto& s = rs();
  bool ok = true;
  for (const bool rigid : {true, false}) {
    const Coefficients o = other_coefficients(rigid, true);
    ok = ok &&
         sym::simplify(2 * other_energy_change(rigid, s.F) / s.F - (s.F * o.A - o.B)).is_zero();
  }
  return judge(
      ClaimVerdict{{symbolic(ok, "for a rigid body and for a point mass")}, std::nullopt, {}, {}});
}

// The impulse of the summed system, symbolic.
ex summed_impulse(bool rigid_other, bool elastic) {
  const auto& s = rs();
  const Coefficients own = elastic
                               ? printed_3_6(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny)
                               : printed_3_10(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny);
  const Coefficients other = other_coefficients(rigid_other, elastic);
  return (own.B + other.B) / (own.A + other.A);
}

ex own_energy_change(const ex& F) {
  const auto& s = rs();
  const ex Fx = -s.nx * F, Fy = -s.ny * F;
  return rigid_energy(s.m, s.I, s.px + Fx, s.py + Fy, s.L + det(s.rx, s.ry, Fx, Fy)) -
         rigid_energy(s.m, s.I, s.px, s.py, s.L);
}

// Numbers: a rigid body against a rigid body or a point mass, printed coefficients compiled.
struct Pair {
  Body own, other;
  Vector2d r, ro, n;
};

Pair sample_pair(num::Random& r) {
  Pair h{sample_body(r), sample_body(r), {}, {}, r.unit_vector()};
  h.r = r.vector(1) * std::sqrt(h.own.I / h.own.m) * 2;
  h.ro = r.vector(1) * std::sqrt(h.other.I / h.other.m) * 2;
  return h;
}

struct CompiledCoefficients {
  sym::Compiled A, B;
  [[nodiscard]] double a(const Body& b, const Vector2d& r, const Vector2d& n) const {
    return A({b.m, b.I, b.p.x(), b.p.y(), b.L, r.x(), r.y(), n.x(), n.y()});
  }
  [[nodiscard]] double b(const Body& bd, const Vector2d& r, const Vector2d& n) const {
    return B({bd.m, bd.I, bd.p.x(), bd.p.y(), bd.L, r.x(), r.y(), n.x(), n.y()});
  }
};

CompiledCoefficients compile_coefficients(bool elastic) {
  const auto& s = rs();
  const Coefficients k = elastic ? printed_3_6(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny)
                                 : printed_3_10(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny);
  return {sym::compile(k.A, s.body()), sym::compile(k.B, s.body())};
}

// ---- an independent continuous-time contact: a tilted rod falling onto the ground, held by a
// penalty spring (and damper) at its lowest end while that end is below the ground -----------

struct RodRun {
  double impulse;
  double closed_form;
};

RodRun rod_on_ground(double k, double damping, double theta, double elasticity) {
  // Uniform rod: length 2, mass 1, I = m l^2 / 12 = 1/3, centre at the origin, falling at 1 and
  // spinning at 0.3 rad/s; its lower end touches the ground y = -sin(theta) at t = 0.
  const double m = 1.0, I = 1.0 / 3.0;
  const double ground = -std::sin(theta);
  // y = [x, y, angle, vx, vy, w, J]
  const auto end_of = [](double angle) { return Vector2d(-std::cos(angle), -std::sin(angle)); };
  const auto rhs = [&](double, const double* y, double* dy) {
    const Vector2d arm = end_of(y[2]);
    const double depth = ground - (y[1] + arm.y());
    const double sink = -(y[4] + y[5] * arm.x());                   // the end's downward speed
    const double f = depth > 0 ? k * depth + damping * sink : 0.0;  // upwards on the rod
    dy[0] = y[3];
    dy[1] = y[4];
    dy[2] = y[5];
    dy[3] = 0.0;
    dy[4] = f / m;
    dy[5] = arm.x() * f / I;  // det(arm, (0, f))
    dy[6] = f;
  };
  const std::vector<double> y0{0, 0, theta, 0, -1, 0.3, 0};
  const auto ended = [&](double t, const double* y) {
    if (t <= 0)
      return 1.0;
    const Vector2d arm = end_of(y[2]);
    if (damping > 0 && k == 0) {
      return -(y[4] + y[5] * arm.x()) - 1e-12;  // the end stops sinking
    }
    return ground - (y[1] + arm.y());  // the end is out of the ground again
  };
  // The spring's period, or the damper's time (1/sqrt(k) is not computed for a damper alone:
  // it would be 1/0, an infinity born for nothing).
  const double time_scale = k > 0 ? 1 / std::sqrt(k) : 1 / damping;
  const auto end =
      num::integrate_until(rhs, y0, ended, time_scale / 50, 1e4 * time_scale, 1e-12 * time_scale);
  // The closed form from (3.6)/(3.10): the rod's outward normal at its end is (0, -1), the
  // ground contributes nothing.
  const Vector2d arm = end_of(theta);
  const Vector2d n(0, -1);
  const double d = arm.x() * n.y() - arm.y() * n.x();
  const double A = d * d / I + 1 / m;
  const double B = elasticity * (0.3 * I * d / I + Vector2d(0, -m).dot(n) / m);
  return {end.y[6], B / A};
}

Finding rod_convergence(double elasticity) {
  // Stiffer springs (or dampers) shorten the contact, so the rod turns less while it lasts: the
  // impulse must approach the closed form.
  std::string table;
  const std::vector<double> strengths = elasticity == 2 ? std::vector<double>{1e2, 1e4, 1e6, 1e8}
                                                        : std::vector<double>{1e1, 1e2, 1e3, 1e4};
  bool shrinking = true;
  double first = 0, last = 0;
  for (const double s : strengths) {
    double worst = 0;
    for (const double theta : {0.3, 0.7, 1.1}) {
      const RodRun run =
          elasticity == 2 ? rod_on_ground(s, 0, theta, 2) : rod_on_ground(0, s, theta, 1);
      worst = std::max(worst, num::relative_error(run.impulse, run.closed_form));
    }
    if (s == strengths.front()) {
      first = worst;
    } else {
      shrinking = shrinking && worst < last;
    }
    last = worst;
    table += (table.empty() ? "" : ", ") + num::brief(worst, 2) + " at " +
             (elasticity == 2 ? "k = " : "c = ") + num::brief(s, 1);
  }
  const double decades = std::log10(strengths.back() / strengths.front());
  const double slope = std::log10(last / first) / decades;
  const bool converged = shrinking && last < 1e-3;
  Finding f{Method::ode,
            converged,
            last,
            strengths.size() * 3,
            "a tilted rod on a penalty " + std::string(elasticity == 2 ? "spring" : "damper") +
                ", worst relative error of the impulse " + table + " (slope " +
                num::brief(slope, 2) + " per decade)",
            true};
  return f;
}

Outcome equation_3_6(const Context& c) {
  const auto& s = rs();
  std::vector<Finding> findings;
  for (const bool rigid : {true, false}) {
    const ex F = summed_impulse(rigid, true);
    findings.push_back(
        symbolic(sym::simplify(own_energy_change(F) + other_energy_change(rigid, F)).is_zero(),
                 rigid ? "summed with another rigid body's (3.6), energy is kept"
                       : "summed with a point mass's, energy is kept"));
  }
  const auto printed = compile_coefficients(true);
  num::Random r(c.seed);
  num::Errors energy, library;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double A = printed.a(h.own, h.r, h.n) + printed.a(h.other, h.ro, -h.n);
    const double B = printed.b(h.own, h.r, h.n) + printed.b(h.other, h.ro, -h.n);
    const double F = B / A;
    energy.add(h.own.after(h.r, -h.n * F).energy() + h.other.after(h.ro, h.n * F).energy(),
               h.own.energy() + h.other.energy());
    const auto lib = rigid_2d::contribution({h.own.m, h.own.I, {0, 0}, h.own.p, h.own.L}, h.r, h.n,
                                            Elasticity::elastic());
    library.add(lib.a, printed.a(h.own, h.r, h.n));
    library.add(lib.b, printed.b(h.own, h.r, h.n),
                2 * (std::abs(h.own.L * (h.r.x() * h.n.y() - h.r.y() * h.n.x()) / h.own.I) +
                     std::abs(h.own.p.dot(h.n) / h.own.m)));
  }
  findings.push_back(numeric(Method::numeric, energy, num::holds_below,
                             "rigid bodies against rigid bodies, energy kept"));
  findings.push_back(numeric(Method::numeric, library, num::holds_below,
                             "the library's rigid_2d::contribution gives the same A and B"));
  findings.push_back(rod_convergence(2));
  (void)s;
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome equation_3_4(const Context& c) {
  // The balance (3.4) holds for the collision (3.6) produces; checked numerically here, exactly
  // in (3.6)'s check.
  const auto printed = compile_coefficients(true);
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double F = (printed.b(h.own, h.r, h.n) + printed.b(h.other, h.ro, -h.n)) /
                     (printed.a(h.own, h.r, h.n) + printed.a(h.other, h.ro, -h.n));
    errors.add(h.own.energy() + h.other.energy(),
               h.own.after(h.r, -h.n * F).energy() + h.other.after(h.ro, h.n * F).energy());
  }
  return judge(EquationVerdict{{numeric(Method::numeric, errors, num::holds_below,
                                        "the elastic impulse of (3.6) keeps E_k + E_o")},
                               {},
                               {},
                               {},
                               "A definition of the elastic collision; the check confirms that "
                               "the impulse derived from it satisfies it."});
}

Outcome point_velocity(const Context& c) {
  // v_v = w [-r_y, r_x] + v: the time derivative of a material point turning with the body.
  const GiNaC::realsymbol t("t"), w("w"), ax("ax"), ay("ay"), Vx("Vx"), Vy("Vy");
  const ex x = Vx * t + GiNaC::cos(w * t) * ax - GiNaC::sin(w * t) * ay;
  const ex y = Vy * t + GiNaC::sin(w * t) * ax + GiNaC::cos(w * t) * ay;
  const bool exact = (GiNaC::diff(x, t).subs(t == 0) - (w * (-ay) + Vx)).expand().is_zero() &&
                     (GiNaC::diff(y, t).subs(t == 0) - (w * ax + Vy)).expand().is_zero();
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Cloud cloud = cloud::sample(r);
    const std::size_t k =
        static_cast<std::size_t>(r.integer(0, static_cast<int>(cloud.m.size()) - 1));
    const Vector2d arm = cloud.r[k];
    // The complex-step derivative of the point's position, exact to rounding: x'(0) is
    // Im x(i h) / h for a tiny h (no difference of nearby values, so nothing cancels).
    using Complex = std::complex<double>;
    const double h = 1e-30;
    const Complex time(0.0, h);
    const Complex angle = cloud.w * time;
    const Complex cx = cloud.V.x() * time + std::cos(angle) * arm.x() - std::sin(angle) * arm.y();
    const Complex cy = cloud.V.y() * time + std::sin(angle) * arm.x() + std::cos(angle) * arm.y();
    const Vector2d difference(cx.imag() / h, cy.imag() / h);
    const double L = cloud.angular_momentum();
    const Vector2d p = cloud.momentum();
    const Vector2d printed = L / cloud.inertia() * Vector2d(-arm.y(), arm.x()) + p / cloud.mass();
    errors.add((printed - difference).norm(), 0.0, cloud.V.norm() + std::abs(cloud.w) * arm.norm());
  }
  return judge(EquationVerdict{{symbolic(exact, "the derivative of the turning point at t = 0"),
                                numeric(Method::numeric, errors, num::holds_below,
                                        "the complex-step derivative of a turning body's point")},
                               {},
                               {},
                               {},
                               {}});
}

Outcome equation_3_7(const Context& c) {
  const auto& s = rs();
  // The component lines from the vector line with F dt = -n Fdt (3.3).
  const ex Fx = -s.nx * s.F, Fy = -s.ny * s.F;
  const ex spin = (s.L + det(s.rx, s.ry, Fx, Fy)) / s.I;
  const ex vx_vector = spin * (-s.ry) + (s.px + Fx) / s.m;
  const ex vy_vector = spin * s.rx + (s.py + Fy) / s.m;
  const ex d = s.rx * s.ny - s.ry * s.nx;
  const ex vx_printed = -s.ry * (s.L - s.F * d) / s.I + (s.px - s.F * s.nx) / s.m;
  const ex vy_printed = s.rx * (s.L - s.F * d) / s.I + (s.py - s.F * s.ny) / s.m;
  const bool exact = sym::simplify(vx_vector - vx_printed).is_zero() &&
                     sym::simplify(vy_vector - vy_printed).is_zero();
  const auto vx =
      sym::compile(vx_printed, {s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny, s.F});
  const auto vy =
      sym::compile(vy_printed, {s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny, s.F});
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    // A body of point masses hit at one of its points: that point's velocity afterwards (Gauss's
    // principle) against the printed components with the body's p, L, m and I.
    const Cloud body = cloud::sample(r);
    const auto k = static_cast<std::size_t>(r.integer(0, static_cast<int>(body.m.size()) - 1));
    const Vector2d arm = body.r[k];
    const Vector2d n = r.unit_vector();
    const double F = r.uniform(-10, 10) * body.mass();
    const Vector2d after = cloud::after(body, {{k, -n * F}}).velocity(k);
    const Vector2d p = body.momentum();
    const double L = body.angular_momentum(), I = body.inertia(), m = body.mass();
    const std::initializer_list<double> args{m,       I,       p.x(), p.y(), L,
                                             arm.x(), arm.y(), n.x(), n.y(), F};
    const double scale =
        after.norm() + std::abs(F) / m + (std::abs(L) + std::abs(F) * arm.norm()) / I * arm.norm();
    errors.add(vx(args), after.x(), scale);
    errors.add(vy(args), after.y(), scale);
    const rigid_2d::RigidBody lb{m, I, {0, 0}, p, L};
    const Vector2d lib = rigid_2d::point_velocity(rigid_2d::apply_impulse(lb, arm, n, F), arm);
    errors.add(lib.x(), vx(args), scale);
    errors.add(lib.y(), vy(args), scale);
  }
  return judge(
      EquationVerdict{{symbolic(exact, "the components follow from the vector line and (3.3)"),
                       numeric(Method::numeric, errors, num::holds_below,
                               "bodies of point masses (Gauss's principle), and the "
                               "library's rigid_2d::apply_impulse and point_velocity")},
                      {},
                      {},
                      {},
                      {}});
}

Outcome equation_3_8_and_expansion(const Context&) {
  const auto& s = rs();
  const ex d = s.rx * s.ny - s.ry * s.nx;
  const ex vx = -s.ry * (s.L - s.F * d) / s.I + (s.px - s.F * s.nx) / s.m;
  const ex vy = s.rx * (s.L - s.F * d) / s.I + (s.py - s.F * s.ny) / s.m;
  const ex cast = vx * s.nx + vy * s.ny;  // (3.8)
  const ex printed_long = (s.L - s.F * d) / s.I * d +
                          (s.px * s.nx + s.py * s.ny - s.F * (s.nx * s.nx + s.ny * s.ny)) / s.m;
  const ex printed_short =
      (s.L - s.F * s.arm()) / s.I * s.arm() + ((s.px * s.nx + s.py * s.ny) - s.F * s.n2()) / s.m;
  const bool exact = sym::simplify(cast - printed_long).is_zero() &&
                     sym::simplify(printed_long - printed_short).is_zero();
  return judge(
      EquationVerdict{{symbolic(exact, "(3.7) cast on n, both printed forms")}, {}, {}, {}, {}});
}

Outcome equalisation_reading(const Context& c) {
  // Inelastic: both material points move alike along n. With v'_on the other point's velocity
  // cast on the same n, that is v'_vn = v'_on; checked at the impulse of the summed (3.10).
  const auto printed = compile_coefficients(false);
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double F = (printed.b(h.own, h.r, h.n) + printed.b(h.other, h.ro, -h.n)) /
                     (printed.a(h.own, h.r, h.n) + printed.a(h.other, h.ro, -h.n));
    const double vvn = h.own.after(h.r, -h.n * F).velocity_at(h.r).dot(h.n);
    const double von = h.other.after(h.ro, h.n * F).velocity_at(h.ro).dot(h.n);
    errors.add(vvn, von, h.own.velocity_at(h.r).norm() + h.other.velocity_at(h.ro).norm());
  }
  return judge(EquationVerdict{{numeric(Method::numeric, errors)},
                               {},
                               {},
                               {},
                               "v'_on is read as the other point's velocity cast on the same "
                               "normal n; cast on the other body's own normal -n it would be "
                               "v'_vn = -v'_on."});
}

Outcome equation_3_9(const Context& c) {
  const auto& s = rs();
  // From v'_vn (the expansion) and v'_vn = v'_on.
  const ex vvn =
      (s.L - s.F * s.arm()) / s.I * s.arm() + ((s.px * s.nx + s.py * s.ny) - s.F * s.n2()) / s.m;
  const Equation printed{s.F * (s.arm() * s.arm() / s.I + s.n2() / s.m) + s.von,
                         s.L * s.arm() / s.I + (s.px * s.nx + s.py * s.ny) / s.m};
  const bool follows = sym::nonzero_multiple(printed, {vvn, s.von}, {}).has_value();
  // Numbers: at the summed (3.10) impulse, with v'_on the other point's velocity along n.
  const auto k = compile_coefficients(false);
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double F = (k.b(h.own, h.r, h.n) + k.b(h.other, h.ro, -h.n)) /
                     (k.a(h.own, h.r, h.n) + k.a(h.other, h.ro, -h.n));
    const double von = h.other.after(h.ro, h.n * F).velocity_at(h.ro).dot(h.n);
    errors.add(F * k.a(h.own, h.r, h.n) + von, k.b(h.own, h.r, h.n),
               std::abs(F * k.a(h.own, h.r, h.n)) + std::abs(von));
  }
  return judge(EquationVerdict{
      {symbolic(follows, "from v'_vn = v'_on"), numeric(Method::numeric, errors)}, {}, {}, {}, {}});
}

Outcome claim_other_form(const Context&) {
  // v'_on = Fdt A_o - B_o with the other body's own (3.10) (normal -n): its velocity along n
  // after receiving +n Fdt.
  const auto& s = rs();
  bool ok = true;
  for (const bool rigid : {true, false}) {
    const ex Jx = s.nx * s.F, Jy = s.ny * s.F;
    ex von;
    if (rigid) {
      const ex spin = (s.Lo + det(s.rox, s.roy, Jx, Jy)) / s.Io;
      von = (spin * (-s.roy) + (s.pox + Jx) / s.mo) * s.nx +
            (spin * s.rox + (s.poy + Jy) / s.mo) * s.ny;
    } else {
      von = ((s.pox + Jx) * s.nx + (s.poy + Jy) * s.ny) / s.mo;
    }
    const Coefficients o = other_coefficients(rigid, false);
    ok = ok && sym::simplify(von - (s.F * o.A - o.B)).is_zero();
  }
  return judge(
      ClaimVerdict{{symbolic(ok, "for a rigid body and for a point mass")}, std::nullopt, {}, {}});
}

Outcome equation_3_10(const Context& c) {
  std::vector<Finding> findings;
  const auto& s = rs();
  for (const bool rigid : {true, false}) {
    const ex F = summed_impulse(rigid, false);
    const ex Fx = -s.nx * F, Fy = -s.ny * F;
    const ex spin = (s.L + det(s.rx, s.ry, Fx, Fy)) / s.I;
    const ex own =
        (spin * (-s.ry) + (s.px + Fx) / s.m) * s.nx + (spin * s.rx + (s.py + Fy) / s.m) * s.ny;
    ex other;
    if (rigid) {
      const ex ospin = (s.Lo + det(s.rox, s.roy, -Fx, -Fy)) / s.Io;
      other = (ospin * (-s.roy) + (s.pox - Fx) / s.mo) * s.nx +
              (ospin * s.rox + (s.poy - Fy) / s.mo) * s.ny;
    } else {
      other = ((s.pox - Fx) * s.nx + (s.poy - Fy) * s.ny) / s.mo;
    }
    findings.push_back(
        symbolic(sym::simplify(own - other).is_zero(),
                 rigid ? "summed with another rigid body's, the points move alike along n"
                       : "summed with a point mass's, likewise"));
  }
  const auto printed = compile_coefficients(false);
  num::Random r(c.seed);
  num::Errors equal, library;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double F = (printed.b(h.own, h.r, h.n) + printed.b(h.other, h.ro, -h.n)) /
                     (printed.a(h.own, h.r, h.n) + printed.a(h.other, h.ro, -h.n));
    equal.add(h.own.after(h.r, -h.n * F).velocity_at(h.r).dot(h.n),
              h.other.after(h.ro, h.n * F).velocity_at(h.ro).dot(h.n),
              h.own.velocity_at(h.r).norm() + h.other.velocity_at(h.ro).norm());
    const auto lib = rigid_2d::contribution({h.own.m, h.own.I, {0, 0}, h.own.p, h.own.L}, h.r, h.n,
                                            Elasticity::inelastic());
    library.add(lib.a, printed.a(h.own, h.r, h.n));
    library.add(lib.b, printed.b(h.own, h.r, h.n),
                std::abs(h.own.L * (h.r.x() * h.n.y() - h.r.y() * h.n.x()) / h.own.I) +
                    std::abs(h.own.p.dot(h.n) / h.own.m));
  }
  findings.push_back(numeric(Method::numeric, equal, num::holds_below, "normal velocities equal"));
  findings.push_back(numeric(Method::numeric, library, num::holds_below,
                             "the library's rigid_2d::contribution at elasticity 1"));
  findings.push_back(rod_convergence(1));
  return judge(EquationVerdict{std::move(findings), {}, {}, {}, {}});
}

Outcome claim_only_b(const Context&) {
  const auto& s = rs();
  const Coefficients e = printed_3_6(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny);
  const Coefficients i = printed_3_10(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny);
  const bool ok = sym::simplify(e.A - i.A).is_zero() && sym::simplify(e.B - 2 * i.B).is_zero();
  return judge(
      ClaimVerdict{{symbolic(ok, "A equal, B_elastic = 2 B_inelastic")}, std::nullopt, {}, {}});
}

Outcome claim_compatible_1d(const Context&) {
  // An arm along the normal (no lever, det(r, n) = 0) and a unit normal: (3.6) and (3.10) are
  // section 1's per-body terms a = 1/m and b = e p_n / m.
  const auto& s = rs();
  const GiNaC::realsymbol t("t"), k("k");
  const ex nx = (1 - t * t) / (1 + t * t), ny = 2 * t / (1 + t * t);
  const ex rx = k * nx, ry = k * ny;  // arm along n
  const Coefficients e = printed_3_6(s.m, s.I, s.px, s.py, s.L, rx, ry, nx, ny);
  const Coefficients i = printed_3_10(s.m, s.I, s.px, s.py, s.L, rx, ry, nx, ny);
  const ex pn = s.px * nx + s.py * ny;
  const bool ok = sym::simplify(e.A - 1 / s.m).is_zero() &&
                  sym::simplify(e.B - 2 * pn / s.m).is_zero() &&
                  sym::simplify(i.B - pn / s.m).is_zero();
  return judge(
      ClaimVerdict{{symbolic(ok, "central impact with a unit normal")}, std::nullopt, {}, {}});
}

Outcome solving_sum(const Context& c) {
  // F (A_1 + A_2) = B_1 + B_2 for any pairing and elasticities: the library's rigid_2d::collide
  // and section 1's restitution law on the contact points (e equal for both).
  num::Random r(c.seed);
  num::Errors law, library;
  const auto elastic = compile_coefficients(true);
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Pair h = sample_pair(r);
    const double e1 = r.uniform(0, 3), e2 = r.uniform(0, 3);
    // Printed (3.6) is the e = 2 case; elasticity e scales B by e / 2.
    const double A = elastic.a(h.own, h.r, h.n) + elastic.a(h.other, h.ro, -h.n);
    const double B = e1 / 2 * elastic.b(h.own, h.r, h.n) + e2 / 2 * elastic.b(h.other, h.ro, -h.n);
    const double F = B / A;
    const auto lib = rigid_2d::collide({h.own.m, h.own.I, {0, 0}, h.own.p, h.own.L}, Elasticity(e1),
                                       {h.other.m, h.other.I, h.r - h.ro, h.other.p, h.other.L},
                                       Elasticity(e2), h.r, h.n);
    library.add(lib.solution.Fdt, F,
                (std::abs(e1 / 2 * elastic.b(h.own, h.r, h.n)) +
                 std::abs(e2 / 2 * elastic.b(h.other, h.ro, -h.n))) /
                    A);
    // One elasticity for both: the points part at (e - 1) times their closing speed.
    const double e = e1;
    const double Fe = (e / 2) * (elastic.b(h.own, h.r, h.n) + elastic.b(h.other, h.ro, -h.n)) / A;
    const double before = h.own.velocity_at(h.r).dot(h.n) - h.other.velocity_at(h.ro).dot(h.n);
    const double after = h.own.after(h.r, -h.n * Fe).velocity_at(h.r).dot(h.n) -
                         h.other.after(h.ro, h.n * Fe).velocity_at(h.ro).dot(h.n);
    law.add(after, (1 - e) * before,
            h.own.velocity_at(h.r).norm() + h.other.velocity_at(h.ro).norm());
  }
  return judge(EquationVerdict{
      {numeric(Method::numeric, law, num::holds_below, "restitution law of the contact points"),
       numeric(Method::numeric, library, num::holds_below,
               "the library's rigid_2d::collide with per-body elasticities")},
      {},
      {},
      {},
      {}});
}

Outcome claim_dimensions(const Context& c) {
  const auto& s = rs();
  const GiNaC::possymbol M("M"), X("X"), T("T");
  const GiNaC::exmap scale{
      {s.m, M * s.m},           {s.I, M * X * X * s.I},     {s.px, M * X / T * s.px},
      {s.py, M * X / T * s.py}, {s.L, M * X * X / T * s.L}, {s.rx, X * s.rx},
      {s.ry, X * s.ry}};
  const Coefficients k = printed_3_6(s.m, s.I, s.px, s.py, s.L, s.rx, s.ry, s.nx, s.ny);
  const bool exact = sym::simplify(k.A.subs(scale) - k.A / M).is_zero() &&
                     sym::simplify(k.B.subs(scale) - k.B * X / T).is_zero();
  const auto printed = compile_coefficients(true);
  num::Random r(c.seed);
  num::Errors errors;
  for (std::size_t i = 0; i < c.samples; ++i) {
    const Body b = sample_body(r);
    const Vector2d arm = r.vector(2), n = r.unit_vector();
    const double Ms = r.log_uniform(1e-3, 1e3), Xs = r.log_uniform(1e-3, 1e3),
                 Ts = r.log_uniform(1e-3, 1e3);
    const Body scaled{Ms * b.m, Ms * Xs * Xs * b.I, Ms * Xs / Ts * b.p, Ms * Xs * Xs / Ts * b.L};
    errors.add(printed.a(scaled, Xs * arm, n), printed.a(b, arm, n) / Ms);
    errors.add(printed.b(scaled, Xs * arm, n), printed.b(b, arm, n) * Xs / Ts,
               2 *
                   (std::abs(b.L * (arm.x() * n.y() - arm.y() * n.x()) / b.I) +
                    std::abs(b.p.dot(n) / b.m)) *
                   Xs / Ts);
  }
  return judge(ClaimVerdict{{symbolic(exact), numeric(Method::numeric, errors)},
                            std::nullopt,
                            {},
                            "(3.6) under a change of the units of mass, length and time."});
}

}  // namespace

std::vector<Check> section3_checks() {
  std::vector<Check> c;
  c.push_back(make_check("claim-3-point-velocity", "3", std::nullopt, Kind::claim,
                         R"(v_{vx} = f(L, p_x), \quad v_{vy} = f(L, p_y))",
                         claim_point_components));
  c.push_back(make_check(
      "eq-3.1", "3.1", "(3.1)", Kind::equation,
      R"(E_{k} = E_{r} + E_{t}, \quad E_{r} = \frac{L^{2}}{2I}, \quad E_{t} = \frac{\|\vec{p}\|^{2}}{2m} = \frac{p_{x}^{2} + p_{y}^{2}}{2m})",
      equation_3_1));
  c.push_back(make_check(
      "eq-3.2", "3.1", "(3.2)", Kind::equation,
      R"(E'_{r} = \frac{(L + \det(\vec{r}, \vec{Fdt}))^{2}}{2I} = \frac{(L + (r_{x}F_{y}dt - r_{y}F_{x}dt))^{2}}{2I}, \quad E'_{t} = \frac{\|\vec{p} + \vec{Fdt}\|^{2}}{2m} = \frac{(p_{x} + F_{x}dt)^{2} + (p_{y} + F_{y}dt)^{2}}{2m})",
      equation_3_2));
  c.push_back(make_check("eq-3.3", "3.1", "(3.3)", Kind::equation,
                         R"(F_x dt = -n_x F dt, \quad F_y dt = -n_y F dt)", equation_3_3));
  c.push_back(make_check("eq-3.4", "3.1", "(3.4)", Kind::equation, R"(E_k + E_o = E_k' + E_o')",
                         equation_3_4));
  c.push_back(make_check(
      "s3.1-combined", "3.1", std::nullopt, Kind::step,
      R"(E_o + \frac{L^2}{2I} + \frac{p_x^2 + p_y^2}{2m} = E_o' + \frac{L^2 - 2LFdt(r_x n_y - r_y n_x) + (Fdt)^2(r_x n_y - r_y n_x)^2}{2I} + \frac{p_x^2 - 2Fdt n_x p_x + (Fdt)^2 n_x^2 + p_y^2 - 2Fdt n_y p_y + (Fdt)^2 n_y^2}{2m})",
      combined_step));
  c.push_back(make_check(
      "s3.1-divided", "3.1", std::nullopt, Kind::step,
      R"(Fdt\left(\frac{(r_{x}n_{y}-r_{y}n_{x})^{2}}{I}+\frac{n_{x}^{2}+n_{y}^{2}}{m}\right)+\frac{2\Delta E_{o}}{Fdt}=\frac{2L(r_{x}n_{y}-r_{y}n_{x})}{I}+\frac{2(n_{x}p_{x}+n_{y}p_{y})}{m})",
      divided_step));
  c.push_back(make_check(
      "eq-3.5", "3.1", "(3.5)", Kind::equation,
      R"(Fdt\left(\frac{\det(\vec{r},\vec{n})^2}{I} + \frac{\|\vec{n}\|^2}{m}\right) + \frac{2\Delta E_o}{Fdt} = \frac{2L\det(\vec{r},\vec{n})}{I} + \frac{2\vec{p}\cdot\vec{n}}{m})",
      equation_3_5));
  c.push_back(make_check(
      "claim-3.1-split", "3.1", std::nullopt, Kind::claim,
      R"(\frac{2\Delta E_o}{Fdt} = Fdt\,A_o - B_o \text{ with the other body's own } (A_o, B_o))",
      claim_split));
  c.push_back(make_check(
      "eq-3.6", "3.1", "(3.6)", Kind::equation,
      R"(A_{elastic} = \frac{\det(\vec{r}, \vec{n})^2}{I} + \frac{\|\vec{n}\|^2}{m}, \quad B_{elastic} = \frac{2L \det(\vec{r}, \vec{n})}{I} + \frac{2\vec{p} \cdot \vec{n}}{m})",
      equation_3_6));
  c.push_back(make_check(
      "s3.2-point-velocity", "3.2", std::nullopt, Kind::step,
      R"(\vec{v_v} = \vec{v_r} + \vec{v_t} = \omega[-r_y, r_x] + \vec{v} = \frac{L}{I}[-r_y, r_x] + \frac{\vec{p}}{m})",
      point_velocity));
  c.push_back(make_check(
      "eq-3.7", "3.2", "(3.7)", Kind::equation,
      R"(\vec{v_{v'}} = \frac{(L + \det(\vec{r}, \vec{F}dt))}{I} [-r_y, r_x] + \frac{\vec{p} + \vec{F}dt}{m}, \quad v'_{vx} = -r_y \frac{L - Fdt(r_x n_y - r_y n_x)}{I} + \frac{p_x - Fdt n_x}{m}, \quad v'_{vy} = r_x \frac{L - Fdt(r_x n_y - r_y n_x)}{I} + \frac{p_y - Fdt n_y}{m})",
      equation_3_7));
  c.push_back(make_check(
      "eq-3.8", "3.2", "(3.8)", Kind::equation,
      R"(v'_{vn} = \vec{v_v}' \cdot \vec{n} = v'_{vx} n_x + v'_{vy} n_y = \frac{L - Fdt \det(\vec{r}, \vec{n})}{I} \det(\vec{r}, \vec{n}) + \frac{\vec{p} \cdot \vec{n} - Fdt \|\vec{n}\|^2}{m})",
      equation_3_8_and_expansion));
  c.push_back(make_check("s3.2-equalisation", "3.2", std::nullopt, Kind::step,
                         R"(v'_{vn} = v'_{on})", equalisation_reading));
  c.push_back(make_check(
      "eq-3.9", "3.2", "(3.9)", Kind::equation,
      R"(Fdt\left(\frac{\det(\vec{r}, \vec{n})^2}{I} + \frac{\|\vec{n}\|^2}{m}\right) + v'_{on} = \frac{L\det(\vec{r}, \vec{n})}{I} + \frac{\vec{p} \cdot \vec{n}}{m})",
      equation_3_9));
  c.push_back(make_check("claim-3.2-other-form", "3.2", std::nullopt, Kind::claim,
                         R"(v'_{on} = Fdt\,A_o - B_o \text{ with the other body's own (3.10)})",
                         claim_other_form));
  c.push_back(make_check(
      "eq-3.10", "3.2", "(3.10)", Kind::equation,
      R"(A_{inelastic} = \frac{\det(\vec{r}, \vec{n})^2}{I} + \frac{\|\vec{n}\|^2}{m}, \quad B_{inelastic} = \frac{L \det(\vec{r}, \vec{n})}{I} + \frac{\vec{p} \cdot \vec{n}}{m})",
      equation_3_10));
  c.push_back(make_check("claim-3.3-only-b", "3.3", std::nullopt, Kind::claim,
                         R"(A_{elastic} = A_{inelastic}, \quad B_{elastic} = 2 B_{inelastic})",
                         claim_only_b));
  c.push_back(make_check(
      "claim-3.3-compatible", "3.3", std::nullopt, Kind::claim,
      R"(\det(\vec{r},\vec{n}) = 0,\ \|\vec{n}\| = 1 \Rightarrow A = \frac{1}{m},\ B = elasticity\,\frac{p_n}{m})",
      claim_compatible_1d));
  c.push_back(make_check("s3.4-sum", "3.4", std::nullopt, Kind::step,
                         R"(Fdt(A_1 + A_2) = B_1 + B_2)", solving_sum));
  c.push_back(make_check("claim-3-dimensions", "3.4", std::nullopt, Kind::claim,
                         R"([A_{elastic}] = [1/m_{ass}], \qquad [B_{elastic}] = [velocity])",
                         claim_dimensions));
  return c;
}

}  // namespace impulse::derivations
