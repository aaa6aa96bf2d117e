// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes of bodies at several contacts (sections 4 and 5): point masses or rigid bodies, their
// impulses found either by the law of restitution from the contact Jacobian (scene.hpp: nothing of
// the paper in it) or from the coefficients the file defines, each body's block summed into the
// system as the paper's ⊕ does (the file's a and b read through the probe, the system solved by
// its minimum-norm solution). A point is one contact v of the first body, seen from that body: its
// impulses numbered 1 to 3 (those exchanged with the other body of contact v, the paper's i) and 4,
// 5 (with further bodies, the j), the bodies' state, the velocities after, the work the impulses do
// at contact v, the kinetic energy of the scene before and after; and, for the checks of the
// summed blocks, each body's block as numbers.
#include <algorithm>
#include <cmath>
#include <optional>

#include "models/catalogue.hpp"
#include "models/scene.hpp"

namespace impulse::derivations::models {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;

std::string numbered(const std::string& head, std::size_t k, const std::string& tail = "}") {
  return head + std::to_string(k) + tail;
}

// Which scenes, and where their impulses come from.
struct Family {
  bool rigid = false;      // rigid bodies (section 5), else point masses (section 4)
  bool others = false;     // four bodies: the pair, and two more the first body touches
  double elasticity = 2;   // 2 or 1; 0: drawn (1, 2, or between), scaling the inelastic b
  bool from_file = false;  // the file's coefficients summed, else the law of restitution
  bool blocks = false;     // give each body's block of the file's coefficients as numbers
};

// The first body (0) touches the second (1) at one to three points (the slots 1 to 3); with
// others, the third (2) at slot 4, the fourth (3, static one time in four) at 5, and the second
// touches the third at 6. A slot without a contact gives a zero impulse.
struct Drawn {
  many::Scene scene;
  std::vector<std::optional<std::size_t>> slots;  // the contact in each slot
};

Drawn draw_scene(num::Random& r, const Family& f) {
  Drawn d;
  many::Scene& s = d.scene;
  const std::size_t count = f.others ? 4 : 2;
  for (std::size_t k = 0; k < count; ++k) {
    many::Body b;
    if (k == 3 && r.integer(0, 3) == 0) {
      b.m = 0;
    } else {
      b.m = r.mass();
      b.p = b.m * r.vector(10);
      b.position = r.vector(1);
      b.I = f.rigid ? 1.0 : 0.0;  // set from the arms below
    }
    s.bodies.push_back(b);
  }
  // Two contacts of one pair have normals at least 6 degrees apart: nearly parallel ones make the
  // system nearly singular, and its solution then rounding (every point of such a scene would
  // measure the solver, not the statement).
  const auto touch = [&](std::size_t a, std::size_t b) {
    Vector2d n = r.unit_vector();
    const auto too_close = [&](const Vector2d& m) {
      return std::any_of(s.contacts.begin(), s.contacts.end(), [&](const many::Contact& c) {
        return ((c.a == a && c.b == b) || (c.a == b && c.b == a)) &&
               std::abs(many::cross(c.n, m)) < 0.1;
      });
    };
    while (too_close(n)) {
      n = r.unit_vector();
    }
    d.slots.emplace_back(s.contacts.size());
    s.contacts.push_back({a, b, n, r.vector(2)});
  };
  const int pair = r.integer(1, 3);
  for (int v = 0; v < 3; ++v) {
    if (v < pair) {
      touch(0, 1);
    } else {
      d.slots.emplace_back(std::nullopt);
    }
  }
  if (f.others) {
    touch(0, 2);
    touch(0, 3);
    touch(1, 2);
  }
  many::fit_inertias(r, s);
  return d;
}

// The file's coefficients as compiled functions of the body's quantities at two contacts.
struct Coefficients {
  std::function<double(std::span<const double>)> a;
  std::function<double(std::span<const double>)> b;
};

Coefficients coefficients(Probe& probe, bool rigid, bool elastic) {
  // The file writes them with an index (a_{vi(elastic)}); the engine reads one per value of it,
  // all of one form: the first serves.
  const std::string kind = elastic ? "(elastic)}" : "(inelastic)}";
  if (rigid) {
    return {probe.function("a_{v1" + kind,
                           {"m", "I", "\\vec{r_1}", "\\vec{n_1}", "\\vec{r_v}", "\\vec{n_v}"}),
            probe.function("b_{v" + kind, {"m", "I", "L", "\\vec{p}", "\\vec{r_v}", "\\vec{n_v}"})};
  }
  return {probe.function("a_{v1" + kind, {"m", "\\vec{n_1}", "\\vec{n_v}"}),
          probe.function("b_{v" + kind, {"m", "\\vec{p}", "\\vec{n_v}"})};
}

// A body's contacts with its own outward normals and arms.
struct Touch {
  Eigen::Index v;
  Vector2d n;
  Vector2d r;
};

std::vector<Touch> touches(const many::Scene& s, std::size_t body) {
  std::vector<Touch> out;
  const many::Body& b = s.bodies[body];
  for (std::size_t v = 0; v < s.contacts.size(); ++v) {
    const many::Contact& c = s.contacts[v];
    if (c.a == body || c.b == body) {
      out.push_back(
          {static_cast<Eigen::Index>(v), c.a == body ? c.n : Vector2d(-c.n), c.point - b.position});
    }
  }
  return out;
}

// One body's block of the file's coefficients, zero outside its own contacts (the ⊕ padding).
many::System block(const many::Scene& s, std::size_t body, const Coefficients& k) {
  const auto N = static_cast<Eigen::Index>(s.contacts.size());
  many::System sys{MatrixXd::Zero(N, N), VectorXd::Zero(N)};
  const many::Body& b = s.bodies[body];
  if (b.is_static()) {
    return sys;
  }
  const std::vector<Touch> own = touches(s, body);
  for (const Touch& v : own) {
    sys.B(v.v) =
        b.rigid()
            ? k.b(std::array{b.m, b.I, b.L, b.p.x(), b.p.y(), v.r.x(), v.r.y(), v.n.x(), v.n.y()})
            : k.b(std::array{b.m, b.p.x(), b.p.y(), v.n.x(), v.n.y()});
    for (const Touch& i : own) {
      sys.A(v.v, i.v) = b.rigid() ? k.a(std::array{b.m, b.I, i.r.x(), i.r.y(), i.n.x(), i.n.y(),
                                                   v.r.x(), v.r.y(), v.n.x(), v.n.y()})
                                  : k.a(std::array{b.m, i.n.x(), i.n.y(), v.n.x(), v.n.y()});
    }
  }
  return sys;
}

// Every body's block, and their sum (the paper's ⊕) with each body's b times its weight (an
// elasticity; 1 when none is given). NaN entries when the file does not define the coefficients.
std::vector<many::System> blocks(const many::Scene& s, const Coefficients& k) {
  std::vector<many::System> all;
  for (std::size_t body = 0; body < s.bodies.size(); ++body) {
    all.push_back(block(s, body, k));
  }
  return all;
}

many::System added(const std::vector<many::System>& each, const std::vector<double>& weights = {}) {
  many::System sum{MatrixXd::Zero(each[0].A.rows(), each[0].A.cols()),
                   VectorXd::Zero(each[0].B.size())};
  for (std::size_t body = 0; body < each.size(); ++body) {
    sum.A += each[body].A;
    sum.B += (weights.empty() ? 1.0 : weights[body]) * each[body].B;
  }
  return sum;
}

// The work of the impulses of the pair at contact v on a body's motion, the forces constant over
// the contact (the mean velocity along the path is the mean of before and after): along n_v on
// the translation, and on the turning of the point at arm r_v.
struct Work {
  double translational = 0;
  double rotational = 0;
};

Work work_at(const many::Scene& s, const VectorXd& F, std::size_t body, std::size_t contact) {
  const many::Contact& cv = s.contacts[contact];
  const many::Body& b = s.bodies[body];
  const std::size_t other = cv.a == body ? cv.b : cv.a;
  const Vector2d nv = cv.a == body ? cv.n : Vector2d(-cv.n);
  double pair = 0, all = 0, spin = 0;
  for (const Touch& t : touches(s, body)) {
    const many::Contact& c = s.contacts[static_cast<std::size_t>(t.v)];
    const Vector2d impulse = -t.n * F(t.v);
    all += impulse.dot(nv);
    if (c.a == other || c.b == other) {
      pair += impulse.dot(nv);
    }
    spin += many::cross(t.r, impulse);
  }
  Work w;
  if (b.is_static()) {
    return w;
  }
  w.translational = pair * (b.p.dot(nv) + all / 2) / b.m;
  if (b.rigid()) {
    w.rotational = many::cross(cv.point - b.position, nv) * pair * (b.L + spin / 2) / b.I;
  }
  return w;
}

// One scene drawn and solved: its impulses F (the law's, or the file's blocks summed), the bodies
// after them, the elasticity and the coefficients it was solved with.
struct Case {
  Drawn drawn;
  VectorXd F;
  many::Scene after;
  double e = 2;
  const Coefficients* k = nullptr;
  double dt = 1;
};

// The motion the file's coefficients give: a point at every contact, seen from its first body.
void add_summed_points(const Family& f, const Case& c, std::vector<Point>& points) {
  const many::Scene& s = c.drawn.scene;
  for (const many::Contact& contact : s.contacts) {
    const many::Body& a = s.bodies[contact.a];
    const Vector2d centre_after = c.after.bodies[contact.a].p / a.m;
    Point p;
    p.set("E", many::energy(s)).set("E'", many::energy(c.after));
    p.set("m", a.m).set("\\vec{p}", a.p).set("\\vec{n_v}", contact.n);
    p.set("\\vec{v_{vt}'}", centre_after);
    if (f.rigid) {
      p.set("I", a.I).set("L", a.L).set("\\vec{r_v}", contact.point - a.position);
      p.set("\\vec{v_{vr}'}",
            Vector2d(c.after.bodies[contact.a].velocity_at(contact.point) - centre_after));
    }
    p.set("\\vec{v_{vo}'}", c.after.bodies[contact.b].velocity_at(contact.point));
    if (f.elasticity == 0) {
      p.set("\\mathit{elasticity}", c.e);
    }
    points.push_back(std::move(p));
  }
}

// What every point of a scene solved by the law shares: dt, the energies, the two bodies, and the
// first body's impulses numbered as the file's indices: 1 to 3 the pair's, 4 and 5 the others' (a
// slot without a contact: no impulse, any normal and arm).
Point common_values(num::Random& r, const Family& f, const Case& c) {
  const many::Scene& s = c.drawn.scene;
  const many::Body& own = s.bodies[0];
  const many::Body& other = s.bodies[1];
  Point common;
  common.set("dt", c.dt).set("E", many::energy(s)).set("E'", many::energy(c.after));
  common.set("m", own.m).set("\\vec{p}", own.p).set("m_o", other.m).set("\\vec{p_o}", other.p);
  if (f.rigid) {
    common.set("I", own.I).set("L", own.L).set("I_o", other.I).set("L_o", other.L);
  }
  for (std::size_t q = 0; q < (f.others ? 5U : 3U); ++q) {
    Vector2d n = r.unit_vector();
    Vector2d arm = r.vector(2);
    double mean = 0;
    if (const auto at = c.drawn.slots[q]) {
      const many::Contact& contact = s.contacts[*at];
      n = contact.a == 0 ? contact.n : Vector2d(-contact.n);
      arm = contact.point - own.position;
      mean = c.F(static_cast<Eigen::Index>(*at)) / c.dt;
    }
    common.set(numbered("F_", q + 1, ""), mean)
        .set(numbered("\\vec{n_", q + 1), n)
        .set(numbered("\\vec{F_", q + 1), Vector2d(-n * mean));
    if (f.rigid) {
      common.set(numbered("\\vec{r_", q + 1), arm);
    }
  }
  return common;
}

// Every body's block over the slots (zero where a slot has no contact); the impulse of the slot
// the first body is not in; and the blocks added and solved: their impulses G_q over dt, slot by
// slot (NaN when the file does not define the coefficients), beside the law's motion p', p_o'.
void add_blocks(const Family& f, const Case& c, Point& common) {
  const std::vector<std::optional<std::size_t>>& slots = c.drawn.slots;
  const std::vector<many::System> each = blocks(c.drawn.scene, *c.k);
  const auto entry = [&](std::size_t slot) { return static_cast<Eigen::Index>(*slots[slot]); };
  for (std::size_t body = 0; body < each.size(); ++body) {
    const many::System& b = each[body];
    const std::string name = std::to_string(body + 1);
    for (std::size_t v = 0; v < slots.size(); ++v) {
      common.set("b_{" + name + std::to_string(v + 1) + "}", slots[v] ? b.B(entry(v)) : 0.0);
      for (std::size_t i = 0; i < slots.size(); ++i) {
        common.set("a_{" + name + std::to_string(v + 1) + std::to_string(i + 1) + "}",
                   slots[v] && slots[i] ? b.A(entry(v), entry(i)) : 0.0);
      }
    }
  }
  if (f.others) {
    common.set("F_6", c.F(entry(5)) / c.dt);
  }
  const many::System sum = added(each);
  const bool defined = sum.A.allFinite() && sum.B.allFinite();
  const VectorXd G =
      defined ? many::solve(sum.A, sum.B) : VectorXd::Constant(sum.B.size(), std::nan(""));
  for (std::size_t q = 0; q < slots.size(); ++q) {
    common.set(numbered("G_", q + 1, ""), slots[q] ? G(entry(q)) / c.dt : 0.0);
  }
  common.set("\\vec{p'}", c.after.bodies[0].p).set("\\vec{p_o'}", c.after.bodies[1].p);
}

// A point per contact of the pair: the first body's velocities there before and after, the
// other's, the impulse it receives there and the work the impulses do.
void add_contact_points(const Family& f, const Case& c, const Point& common,
                        std::vector<Point>& points) {
  const many::Scene& s = c.drawn.scene;
  const many::Body& own = s.bodies[0];
  const Vector2d centre_after = c.after.bodies[0].p / own.m;
  for (std::size_t v = 0; v < 3; ++v) {
    if (!c.drawn.slots[v]) {
      continue;
    }
    const std::size_t slot = *c.drawn.slots[v];
    const many::Contact& contact = s.contacts[slot];
    Point p = common;
    p.set("\\vec{n_v}", contact.n);
    const Vector2d point_after = c.after.bodies[0].velocity_at(contact.point);
    p.set("\\vec{v_{vt}'}", centre_after).set("\\vec{v_{vt}}", Vector2d(own.p / own.m));
    if (f.rigid) {
      p.set("\\vec{r_v}", contact.point - own.position);
      p.set("\\vec{v_{vr}}", Vector2d(own.velocity_at(contact.point) - own.p / own.m));
      p.set("\\vec{v_{vr}'}", Vector2d(point_after - centre_after));
    }
    p.set("\\vec{v_{vo}}", s.bodies[1].velocity_at(contact.point));
    p.set("\\vec{v_{vo}'}", c.after.bodies[1].velocity_at(contact.point));
    // The impulse the body receives there: the momentum that contact's impulse alone gives the
    // body at rest (scene.hpp's after), over dt.
    const auto at = static_cast<Eigen::Index>(slot);
    VectorXd alone = VectorXd::Zero(c.F.size());
    alone(at) = c.F(at);
    many::Scene resting = s;
    resting.bodies[0].p.setZero();
    p.set("F_v", c.F(at) / c.dt)
        .set("\\vec{F_v}", Vector2d(many::after(resting, alone).bodies[0].p / c.dt));
    const Work mine_v = work_at(s, c.F, 0, slot);
    const Work theirs = work_at(s, c.F, 1, slot);
    p.set("\\Delta E_{vt}", mine_v.translational);
    p.set("\\Delta E_{vo}", theirs.translational + theirs.rotational);
    if (f.rigid) {
      p.set("\\Delta E_{vr}", mine_v.rotational);
    }
    points.push_back(std::move(p));
  }
}

std::vector<Point> scene_points(Probe& probe, const Settings& settings, const Family& f) {
  num::Random r(settings.seed);
  std::vector<Point> points;
  const Coefficients inelastic = coefficients(probe, f.rigid, false);
  const Coefficients elastic = coefficients(probe, f.rigid, true);
  const std::size_t scenes = settings.share(f.others ? 20 : 10);
  for (std::size_t count = 0; count < scenes; ++count) {
    Case c;
    c.drawn = draw_scene(r, f);
    const many::Scene& s = c.drawn.scene;
    c.e = f.elasticity;
    if (c.e == 0) {
      const int which = r.integer(0, 2);
      c.e = which == 0 ? 1.0 : which == 1 ? 2.0 : r.uniform(1.0, 2.0);
    }
    // The law of restitution's system. A scene where it is ill-conditioned (impulses that
    // push against each other, 1e4 times larger than the speeds call for: nearly parallel
    // normals between bodies of very different masses) is left out, as rounding would decide
    // there, not the file's statements.
    const many::Model md = many::model(s);
    const MatrixXd A = md.A();
    const VectorXd B = md.J * (c.e * md.velocity);
    c.F = many::solve(A, B);
    if (A.norm() * c.F.norm() > 1e4 * B.norm()) {
      continue;
    }
    // The impulses: the file's blocks summed, or the law's.
    c.k = f.elasticity == 0 || c.e == 1 ? &inelastic : &elastic;
    if (f.from_file) {
      many::System sum = added(blocks(s, *c.k));
      if (f.elasticity == 0) {
        sum.B *= c.e;  // elasticity times the inelastic b
      }
      if (!sum.A.allFinite() || !sum.B.allFinite()) {
        continue;  // the file does not define the coefficients: nothing to test with
      }
      c.F = many::solve(sum.A, sum.B);
    }
    c.after = many::after(s, c.F);
    if (f.from_file) {
      add_summed_points(f, c, points);
      continue;
    }
    c.dt = r.log_uniform(1e-3, 1.0);
    Point common = common_values(r, f, c);
    if (f.blocks) {
      add_blocks(f, c, common);
    }
    add_contact_points(f, c, common, points);
  }
  return points;
}

}  // namespace

std::vector<Point> two_point_masses_elastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, false, 2, false, true});
}
std::vector<Point> two_point_masses_inelastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, false, 1, false, true});
}
std::vector<Point> point_masses_in_scenes_elastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, true, 2, false, true});
}
std::vector<Point> point_masses_in_scenes_inelastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, true, 1, false, true});
}
std::vector<Point> point_masses_summed_elastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, true, 2, true, false});
}
std::vector<Point> point_masses_summed_inelastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {false, true, 1, true, false});
}
std::vector<Point> two_rigid_bodies_at_three_contacts_elastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {true, false, 2, false, false});
}
std::vector<Point> two_rigid_bodies_at_three_contacts_inelastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {true, false, 1, false, false});
}
std::vector<Point> rigid_bodies_summed_elastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {true, true, 2, true, false});
}
std::vector<Point> rigid_bodies_summed_inelastic(Probe& p, const Settings& s) {
  return scene_points(p, s, {true, true, 1, true, false});
}
std::vector<Point> rigid_bodies_summed_any_elasticity(Probe& p, const Settings& s) {
  return scene_points(p, s, {true, true, 0, true, false});
}

std::vector<Point> point_masses_an_elasticity_each(Probe& probe, const Settings& settings) {
  num::Random r(settings.seed);
  const Coefficients inelastic = coefficients(probe, false, false);
  std::vector<Point> points;
  for (std::size_t count = 0; count < settings.share(20); ++count) {
    const many::Scene s = draw_scene(r, {false, true, 1, true, false}).scene;  // any conditioning
    Point p;
    std::vector<double> elasticities;
    for (std::size_t body = 0; body < s.bodies.size(); ++body) {
      elasticities.push_back(r.uniform(0.0, 3.0));
      p.set(numbered("\\mathit{elasticity}_", body + 1, ""), elasticities.back());
    }
    const many::System sum = added(blocks(s, inelastic), elasticities);
    if (!sum.A.allFinite() || !sum.B.allFinite()) {
      continue;
    }
    p.set("\\rho", many::inconsistency(sum.A, sum.B));
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<Point> point_mass_against_three_walls(Probe&, const Settings& settings) {
  num::Random r(settings.seed);
  std::vector<Point> points;
  for (std::size_t count = 0; count < settings.share(20); ++count) {
    // First the corner: mass 1 at (2, 1) against walls with outward normals (1, 0), (0, 1) and
    // the diagonal; then random ones.
    many::Scene s;
    const bool corner = count == 0;
    s.bodies = {many::Body{corner ? 1.0 : r.mass(), 0, {0, 0}, {0, 0}, 0},
                many::Body{0, 0, {0, 0}, {0, 0}, 0}};
    s.bodies[0].p = corner ? Vector2d(2, 1) : Vector2d(s.bodies[0].m * r.vector(10));
    const double h = std::sqrt(0.5);
    for (int v = 0; v < 3; ++v) {
      const Vector2d n = !corner  ? r.unit_vector()
                         : v == 0 ? Vector2d(1, 0)
                         : v == 1 ? Vector2d(0, 1)
                                  : Vector2d(h, h);
      s.contacts.push_back({0, 1, n, Vector2d::Zero()});
    }
    // The system of the law of restitution, elasticity 2, and the equal impulse nearest to
    // solving it (least squares in f).
    const many::Model md = many::model(s);
    const MatrixXd A = md.A();
    const VectorXd B = md.J * (2 * md.velocity);
    const VectorXd column = A * VectorXd::Ones(3);
    const double f = column.dot(B) / column.squaredNorm();
    Point common;
    common.set("m", s.bodies[0].m).set("\\vec{p}", s.bodies[0].p).set("f", f).set("dt", 1.0);
    for (std::size_t q = 0; q < 3; ++q) {
      common.set(numbered("\\vec{n_", q + 1), s.contacts[q].n);
    }
    for (const many::Contact& c : s.contacts) {
      Point p = common;
      p.set("\\vec{n_v}", c.n);
      points.push_back(std::move(p));
    }
  }
  return points;
}

namespace {

// What the scene models are and the values they give.
constexpr std::string_view two_bodies_law =
    "Two point masses (masses 1e-3 to 1e3, any momenta) touching at one to three points, the "
    "normals of the pair at least 6 degrees apart; their impulses by the law of restitution (the "
    "contact Jacobian J, A = J M^-1 "
    "J^T, B = J (e v), the minimum-norm solution), elasticity 2 or 1 as named. A point per contact "
    "v, seen from the first body: its impulses F_k (mean forces over dt; a slot without a contact "
    "has none) and outward normals n_k, the impulse it receives at v, the velocities before and "
    "after, the work of the pair's impulses at v on either body (forces constant over the "
    "contact), the kinetic energy before and after; and every body's block a_{Bqs}, b_{Bq} (B its "
    "number) of the coefficients the file defines (its (4.5) or (4.8)), with the impulses G_q "
    "dt of their sum solved, and the law's momenta after, p' and p_o'. A scene whose system is "
    "ill-conditioned (impulses 1e4 times what the speeds call for) is left out.";
constexpr std::string_view scenes_law =
    "Four point masses (the fourth static one time in four): the first touches the second at one "
    "to three points (impulses 1 to 3, the pair's), the third and the fourth at one each (4 and "
    "5), the second the third at one (6); impulses and points as for two point masses.";
constexpr std::string_view scenes_summed =
    "The scenes of four point masses, their impulses from the file's own coefficients: each "
    "body's block of its a_{vi(elastic)} and b_{v(elastic)} (or inelastic, as named) at its own "
    "contacts and normals, the blocks added, the system solved (minimum-norm). A point per "
    "contact of the scene, seen from its first body: the velocities after, the kinetic energy of "
    "the scene before and after.";
constexpr std::string_view two_rigid_law =
    "Two rigid bodies (radii of gyration fitted to their arms) touching at one to three points, as "
    "the two point masses are, with their arms r_k and r_v, the turning part of a point's "
    "velocity v_vr and the work on the turning Delta E_vr.";
constexpr std::string_view rigid_scenes_summed =
    "Four rigid bodies (the fourth static one time in four) touching as the point masses do, their "
    "impulses from the file's a_{vk(elastic)} and b_{v(elastic)} (or inelastic, as named), summed "
    "and solved; a point per contact of the scene, seen from its first body.";
constexpr std::string_view rigid_scenes_elasticity =
    "As the rigid bodies with the inelastic coefficients summed, b_{v(inelastic)} times an "
    "elasticity: 1, 2 or between, drawn in turn.";
}  // namespace

std::vector<Model> scenes_models() {
  return {
      {Method::numeric, "two point masses at one to three contacts, elastic", two_bodies_law,
       two_point_masses_elastic, 1e-8},
      {Method::numeric, "two point masses at one to three contacts, inelastic", two_bodies_law,
       two_point_masses_inelastic, 1e-8},
      {Method::numeric, "point masses in scenes, elastic", scenes_law,
       point_masses_in_scenes_elastic, 1e-8},
      {Method::numeric, "point masses in scenes, inelastic", scenes_law,
       point_masses_in_scenes_inelastic, 1e-8},
      {Method::numeric, "point masses in scenes, the elastic coefficients summed", scenes_summed,
       point_masses_summed_elastic, 1e-8},
      {Method::numeric, "point masses in scenes, the inelastic coefficients summed", scenes_summed,
       point_masses_summed_inelastic, 1e-8},
      {Method::numeric, "two rigid bodies at one to three contacts, elastic", two_rigid_law,
       two_rigid_bodies_at_three_contacts_elastic, 1e-8},
      {Method::numeric, "two rigid bodies at one to three contacts, inelastic", two_rigid_law,
       two_rigid_bodies_at_three_contacts_inelastic, 1e-8},
      {Method::numeric, "rigid bodies in scenes, the elastic coefficients summed",
       rigid_scenes_summed, rigid_bodies_summed_elastic, 1e-8},
      {Method::numeric, "rigid bodies in scenes, the inelastic coefficients summed",
       rigid_scenes_summed, rigid_bodies_summed_inelastic, 1e-8},
      {Method::numeric, "rigid bodies in scenes, elasticity times the inelastic coefficients",
       rigid_scenes_elasticity, rigid_bodies_summed_any_elasticity, 1e-8},
      {Method::search, "point masses in scenes, an elasticity each",
       "The scenes of four point masses, each body's block of the file's a_{vi(inelastic)} and "
       "b_{v(inelastic)} with its b times an elasticity of its own from 0 to 3, summed; rho "
       "the least-squares residual of the system relative to its terms (scene.hpp's "
       "inconsistency).",
       point_masses_an_elasticity_each},
      {Method::search, "a point mass against three walls, the nearest equal impulses",
       "A point mass against three static walls (first mass 1 at (2, 1) into the corner of "
       "walls with outward normals (1, 0), (0, 1) and the diagonal, then random ones); f the "
       "equal impulse over dt = 1 nearest (least squares) to solving the system of the law of "
       "restitution with elasticity 2 (the contact Jacobian). A point per wall v.",
       point_mass_against_three_walls},
  };
}

}  // namespace impulse::derivations::models
