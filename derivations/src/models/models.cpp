// SPDX-License-Identifier: GPL-3.0-or-later
// The table of models: what a paper file may name after ode:, quadrature:, model: and search:.
#include "models/catalogue.hpp"
#include "models/model.hpp"

namespace impulse::derivations::models {

namespace {

// The scene models of sections 4 and 5 (scenes.cpp): what they are and the values they give.
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
const std::vector<std::string_view> by_the_law{"m",
                                               "\\vec{p}",
                                               "m_o",
                                               "\\vec{p_o}",
                                               "dt",
                                               "F_k",
                                               "\\vec{n_k}",
                                               "\\vec{F_k}",
                                               "\\vec{n_v}",
                                               "F_v",
                                               "\\vec{F_v}",
                                               "\\vec{v_{vt}}",
                                               "\\vec{v_{vt}'}",
                                               "\\vec{v_{vo}}",
                                               "\\vec{v_{vo}'}",
                                               "\\Delta E_{vt}",
                                               "\\Delta E_{vo}",
                                               "E",
                                               "E'",
                                               "a_{Bqs}",
                                               "b_{Bq}"};
const std::vector<std::string_view> rigid_by_the_law{"m",
                                                     "I",
                                                     "\\vec{p}",
                                                     "L",
                                                     "m_o",
                                                     "I_o",
                                                     "\\vec{p_o}",
                                                     "L_o",
                                                     "dt",
                                                     "F_k",
                                                     "\\vec{n_k}",
                                                     "\\vec{r_k}",
                                                     "\\vec{F_k}",
                                                     "\\vec{n_v}",
                                                     "\\vec{r_v}",
                                                     "F_v",
                                                     "\\vec{F_v}",
                                                     "\\vec{v_{vt}}",
                                                     "\\vec{v_{vr}}",
                                                     "\\vec{v_{vt}'}",
                                                     "\\vec{v_{vr}'}",
                                                     "\\vec{v_{vo}}",
                                                     "\\vec{v_{vo}'}",
                                                     "\\Delta E_{vt}",
                                                     "\\Delta E_{vr}",
                                                     "\\Delta E_{vo}",
                                                     "E",
                                                     "E'"};
const std::vector<std::string_view> summed{
    "m", "\\vec{p}", "\\vec{n_v}", "\\vec{v_{vt}'}", "\\vec{v_{vo}'}", "E", "E'"};
const std::vector<std::string_view> rigid_summed{"m",
                                                 "I",
                                                 "\\vec{p}",
                                                 "L",
                                                 "\\vec{n_v}",
                                                 "\\vec{r_v}",
                                                 "\\vec{v_{vt}'}",
                                                 "\\vec{v_{vr}'}",
                                                 "\\vec{v_{vo}'}",
                                                 "E",
                                                 "E'"};
const std::vector<std::string_view> rigid_summed_elasticity{"m",
                                                            "I",
                                                            "\\vec{p}",
                                                            "L",
                                                            "\\vec{n_v}",
                                                            "\\vec{r_v}",
                                                            "\\vec{v_{vt}'}",
                                                            "\\vec{v_{vr}'}",
                                                            "\\vec{v_{vo}'}",
                                                            "E",
                                                            "E'",
                                                            "\\mathit{elasticity}"};

}  // namespace

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
      {"numeric",
       "point cloud rigid body",
       "A rigid body made of 3 to 6 point masses: its mass, inertia, momentum, angular momentum "
       "and kinetic energy summed point by point; an impulse -n F dt at one of its points (arm "
       "r), the body's response by Gauss's principle (the rigid motion nearest, in the mass "
       "metric, to the points' free response); the point's velocity before and after by a "
       "complex-step derivative of its motion, and its parts: v_t the centre's velocity, v_r "
       "the rest.",
       {"m", "I", "\\vec{p}", "L", "E_k", "E_k'", "\\vec{r}", "\\vec{n}", "F", "dt", "\\vec{F}",
        "\\vec{v_v}", "\\vec{v_v'}", "\\omega", "\\vec{v}", "\\vec{v_r}", "\\vec{v_t}"},
       1e-9,
       1e-6,
       false,
       point_cloud_rigid_body},
      {"numeric",
       "point cloud rigid body hit at several points",
       "The body of point masses receiving impulses -n_k F_k dt at three of its points (arms "
       "r_1, r_2, r_3): its angular momentum's change dL summed point by point after Gauss's "
       "principle, and the velocity of a fourth point (arm r_v) before and after, split into the "
       "centre's v_vt, v'_vt and the rest v_vr, v'_vr.",
       {"m", "I", "\\vec{p}", "L", "dt", "\\vec{r_k}", "\\vec{n_k}", "F_k", "\\vec{F_k}",
        "\\mathrm{d}L", "\\vec{r_v}", "\\vec{v_{vt}}", "\\vec{v_{vr}}", "\\vec{v_{vt}'}",
        "\\vec{v_{vr}'}"},
       1e-9,
       1e-6,
       false,
       point_cloud_hit_at_several_points},
      {"numeric",
       "point cloud pinned",
       "Point masses turning together about a pin O: the kinetic energy E, angular momentum L_O "
       "and inertia I_O about O summed point by point, the inertia I about the centre of mass, "
       "the mass m, the distance d from O to the centre and the rate of turning omega.",
       {"E", "L_O", "I_O", "I", "m", "d", "\\omega"},
       1e-9,
       1e-6,
       false,
       point_cloud_pinned},
      {"numeric",
       "turned point",
       "A material point at arm r_v turned by a small angle d alpha: its displacement along a "
       "unit normal n_v, d S_v, from the complex-step derivative of its rotation.",
       {"\\vec{r_v}", "\\vec{n_v}", "\\mathrm{d}\\alpha", "\\mathrm{d}S_v"},
       1e-9,
       1e-6,
       false,
       turned_point},
      {"ode",
       "rigid rod on a penalty spring",
       "A uniform rod falls, turning, onto a ground tilted by up to 0.3 rad; while its end is "
       "below the ground a stiff linear spring (1e14 times its mass) pushes it out along the "
       "ground's normal (GSL rk8pd). The impulse is the push's integral sampled along the motion; "
       "r is the end's arm when it touches, n the rod's outward normal there (minus the "
       "ground's); the ground does not move (E_o = E_o' = 0). The rod turns a little while it "
       "is pushed, so the instant impulse is matched to about 1e-7.",
       {"m", "I", "\\vec{p}", "L", "\\vec{r}", "\\vec{n}", "F", "dt", "\\vec{F}", "E_k", "E_k'",
        "E_o", "E_o'"},
       1e-6,
       1e-3,
       false,
       rod_on_a_penalty_spring},
      {"ode",
       "rigid rod on a penalty damper",
       "As the rod on a spring, held by a damper (1e8 times its mass) that stops its end: the "
       "contact ends when the end stops sinking.",
       {"m", "I", "\\vec{p}", "L", "\\vec{r}", "\\vec{n}", "F", "dt", "\\vec{F}", "E_k", "E_k'",
        "E_o", "E_o'"},
       1e-6,
       1e-3,
       false,
       rod_on_a_penalty_damper},
      {"numeric",
       "two rigid bodies at one contact, elastic",
       "Two rigid bodies touching at one point (masses 1e-3 to 1e3, radii of gyration on the "
       "scale of their arms), resolved by the law of restitution with elasticity 2 from the "
       "contact Jacobian: the body's m, I, p, L, arm r and outward normal n, the other's m_o, "
       "I_o, p_o, L_o and arm r_o, the impulse F (dt = 1), the contact points' velocities after "
       "(v_v', v_o' and their parts along n, v'_vn and v'_on) and the kinetic energies.",
       {"m",           "I",
        "\\vec{p}",    "L",
        "\\vec{r}",    "\\vec{n}",
        "m_o",         "I_o",
        "\\vec{p_o}",  "L_o",
        "\\vec{r_o}",  "F",
        "dt",          "\\vec{v_v'}",
        "\\vec{v_o'}", "v'_{vn}",
        "v'_{on}",     "E_k",
        "E_k'",        "E_o",
        "E_o'",        "\\mathit{elasticity}"},
       1e-9,
       1e-6,
       false,
       two_rigid_bodies_elastic},
      {"numeric",
       "two rigid bodies at one contact, inelastic",
       "The same, with elasticity 1: the contact points leave with one velocity along the normal.",
       {"(as the elastic one)"},
       1e-9,
       1e-6,
       false,
       two_rigid_bodies_inelastic},
      {"numeric",
       "two rigid bodies at one contact, one elasticity",
       "The same, with one elasticity for both bodies drawn from 0 to 3.",
       {"(as the elastic one)"},
       1e-9,
       1e-6,
       false,
       two_rigid_bodies_one_elasticity},
      // Beyond the paper: friction (friction.cpp; derivations/beyond/friction.md).
      {"numeric",
       "point cloud struck obliquely",
       "The body of point masses (3 to 6) receiving an impulse P_n n + P_t t at one of its points "
       "(arm r) along any two unit directions n and t, not necessarily at right angles; its "
       "response by Gauss's principle: the centre's velocity v and spin omega before, v' and "
       "omega' after.",
       {"m", "I", "\\vec{r}", "\\vec{n}", "\\vec{t}", "P_n", "P_t", "\\vec{v}", "\\omega",
        "\\vec{v}'", "\\omega'"},
       1e-9,
       1e-6,
       false,
       point_cloud_struck_obliquely},
      {"numeric",
       "rod on a rough floor, slip then stick",
       "A uniform rod (m 0.01 to 100, L 0.1 to 10, I = m L^2 / 12) strikes a floor tilted by up "
       "to 0.5 rad at its lower end (mu 0 to 1.5, elasticity 1 to 2), followed through its normal "
       "impulse by increments: Coulomb's law picks each increment's tangential impulse, the "
       "momentum and the angular momentum take it, and an event inside an increment (the slip "
       "stopping, compression ending, a law of restitution met) is located by bisection on its "
       "length. Kept: the cases where the slip stopped before compression ended and the end stuck "
       "from there on. It gives the slip's sign s at the start, the normal impulse P_s where the "
       "slip stopped, P_c where compression ended, the work w_c of the normal impulse until then "
       "(summed increment by increment), and the impulses at each law's end.",
       {"m",        "L",        "I",       "\\vec{r}", "\\vec{n}",
        "\\vec{t}", "\\vec{v}", "\\omega", "\\mu",     "\\mathit{elasticity}",
        "s",        "P_s",      "P_c",     "w_c",      "P_N",
        "P_{tN}",   "P_P",      "P_{tP}",  "P_E",      "P_{tE}"},
       1e-9,
       1e-6,
       false,
       rod_slip_then_stick,
       true},
      {"search",
       "rods striking rough floors",
       "The rods and floors of the model above, every case (slip throughout, slip then stick, "
       "slip that stops and starts again): the normal and tangential impulses at Newton's end "
       "(P_N, P_tN), Poisson's (P_P, P_tP) and the energetic law's (P_E, P_tE).",
       {"m", "L", "I", "\\vec{r}", "\\vec{n}", "\\vec{t}", "\\vec{v}", "\\omega", "\\mu",
        "\\mathit{elasticity}", "P_N", "P_{tN}", "P_P", "P_{tP}", "P_E", "P_{tE}"},
       1e-9,
       1e-6,
       false,
       rods_striking_rough_floors,
       true},
      // Sections 4 and 5 (pulses.cpp)
      {"quadrature",
       "pulses of force on a body",
       "A point mass m of momentum p receiving three mean forces F_1, F_2, F_3 over a contact "
       "of duration dt, all shaped by one pulse (constant, half-sine, triangular, or peaking "
       "early, in turn); its motion along the normal n_v integrated in time (GSL rk8pd). At an "
       "instant t of the contact: the path S_v along n_v so far, and the rates of the path, of "
       "the momentum and of the velocity along n_v (d S_v, d p_v, d v_v per dt); over the whole "
       "contact, Delta E_vt the change of the kinetic energy of the motion along n_v; v_v the "
       "velocity along n_v before.",
       {"m", "\\vec{p}", "dt", "\\vec{F_1}", "\\vec{F_2}", "\\vec{F_3}", "\\vec{n_v}", "t", "S_v",
        "\\mathrm{d}S_v", "\\mathrm{d}p_v", "\\mathrm{d}v_v", "\\Delta E_{vt}", "v_v"},
       1e-9,
       1e-6,
       true,
       pulses_on_a_body},
      {"quadrature",
       "pulses of force on a turning body",
       "Three mean forces F_1, F_2, F_3 at arms r_1, r_2, r_3 of a body of inertia I and "
       "angular momentum L, over a contact of duration dt, all shaped by one pulse (constant, "
       "half-sine, triangular, or peaking early, in turn); the body's turning integrated in time "
       "(GSL rk8pd) from the torque, and Delta E_vr the work of the first force along n_v on the "
       "rotational motion of the point at arm r_v, integrated with it; at an instant t of the "
       "contact, the angle alpha turned so far and the rates of the angle, of the rate of "
       "turning and of the angular momentum (d alpha, d omega, d L per dt); omega the rate of "
       "turning before.",
       {"I", "L", "dt", "\\vec{r_1}", "\\vec{r_2}", "\\vec{r_3}", "\\vec{F_1}", "\\vec{F_2}",
        "\\vec{F_3}", "\\vec{r_v}", "\\vec{n_v}", "\\Delta E_{vr}", "t", "\\alpha", "\\omega",
        "\\mathrm{d}\\alpha", "\\mathrm{d}\\omega", "\\mathrm{d}L"},
       1e-9,
       1e-6,
       true,
       pulses_on_a_turning_body},
      {"numeric",
       "the library's rigid body hit at several points",
       "A rigid body of impulse::rigid_2d (masses 1e-3 to 1e3, radii of gyration 0.1 to 10) "
       "receiving impulses -n_k F_k dt at three arms r_k, one at a time by "
       "rigid_2d::apply_impulse; the velocity of the point at arm r_v before and after by "
       "rigid_2d::point_velocity, split into the centre's (v_vt, v'_vt) and the rest (v_vr, "
       "v'_vr).",
       {"m", "I", "\\vec{p}", "L", "dt", "\\vec{r_k}", "\\vec{n_k}", "F_k", "\\vec{F_k}",
        "\\vec{r_v}", "\\vec{v_{vt}}", "\\vec{v_{vr}}", "\\vec{v_{vt}'}", "\\vec{v_{vr}'}"},
       1e-9,
       1e-6,
       false,
       library_rigid_body_hit_at_several_points},
      // Sections 4 and 5 (scenes.cpp)
      {"numeric", "two point masses at one to three contacts, elastic", two_bodies_law, by_the_law,
       1e-8, 1e-6, false, two_point_masses_elastic},
      {"numeric", "two point masses at one to three contacts, inelastic", two_bodies_law,
       by_the_law, 1e-8, 1e-6, false, two_point_masses_inelastic},
      {"numeric", "point masses in scenes, elastic", scenes_law, by_the_law, 1e-8, 1e-6, false,
       point_masses_in_scenes_elastic},
      {"numeric", "point masses in scenes, inelastic", scenes_law, by_the_law, 1e-8, 1e-6, false,
       point_masses_in_scenes_inelastic},
      {"numeric", "point masses in scenes, the elastic coefficients summed", scenes_summed, summed,
       1e-8, 1e-6, false, point_masses_summed_elastic},
      {"numeric", "point masses in scenes, the inelastic coefficients summed", scenes_summed,
       summed, 1e-8, 1e-6, false, point_masses_summed_inelastic},
      {"numeric", "two rigid bodies at one to three contacts, elastic", two_rigid_law,
       rigid_by_the_law, 1e-8, 1e-6, false, two_rigid_bodies_at_three_contacts_elastic},
      {"numeric", "two rigid bodies at one to three contacts, inelastic", two_rigid_law,
       rigid_by_the_law, 1e-8, 1e-6, false, two_rigid_bodies_at_three_contacts_inelastic},
      {"numeric", "rigid bodies in scenes, the elastic coefficients summed", rigid_scenes_summed,
       rigid_summed, 1e-8, 1e-6, false, rigid_bodies_summed_elastic},
      {"numeric", "rigid bodies in scenes, the inelastic coefficients summed", rigid_scenes_summed,
       rigid_summed, 1e-8, 1e-6, false, rigid_bodies_summed_inelastic},
      {"numeric", "rigid bodies in scenes, elasticity times the inelastic coefficients",
       rigid_scenes_elasticity, rigid_summed_elasticity, 1e-8, 1e-6, false,
       rigid_bodies_summed_any_elasticity},
      {"search",
       "point masses in scenes, an elasticity each",
       "The scenes of four point masses, each body's block of the file's a_{vi(inelastic)} and "
       "b_{v(inelastic)} with its b times an elasticity of its own from 0 to 3, summed; rho the "
       "least-squares residual of the system relative to its terms (scene.hpp's inconsistency).",
       {"\\rho", "\\mathit{elasticity}_1", "\\mathit{elasticity}_2", "\\mathit{elasticity}_3",
        "\\mathit{elasticity}_4"},
       1e-9,
       1e-6,
       false,
       point_masses_an_elasticity_each},
      {"search",
       "a point mass against three walls, the nearest equal impulses",
       "A point mass against three static walls (first mass 1 at (2, 1) into the corner of walls "
       "with outward normals (1, 0), (0, 1) and the diagonal, then random ones); f the equal "
       "impulse over dt = 1 nearest (least squares) to solving the system of the law of "
       "restitution with elasticity 2 (the contact Jacobian). A point per wall v.",
       {"m", "\\vec{p}", "\\vec{n_k}", "\\vec{n_v}", "f", "dt"},
       1e-9,
       1e-6,
       false,
       point_mass_against_three_walls},
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
