// SPDX-License-Identifier: GPL-3.0-or-later
// The points functions of the models, one file per family (models.cpp names them).
#pragma once

#include <vector>

#include "models/model.hpp"

namespace impulse::derivations::models {

// line.cpp: two bodies on a line.
std::vector<Point> spring_contact_on_a_line(Probe&, const Settings&);
std::vector<Point> damper_contact_on_a_line(Probe&, const Settings&);
std::vector<Point> spring_damper_contact_on_a_line(Probe&, const Settings&);
std::vector<Point> bodies_on_a_line_one_elasticity(Probe&, const Settings&);
std::vector<Point> bodies_on_a_line_two_elasticities(Probe&, const Settings&);
std::vector<Point> bodies_and_impulses_on_a_line(Probe&, const Settings&);
std::vector<Point> changes_of_units_on_a_line(Probe&, const Settings&);

// plane.cpp: point masses in the plane.
std::vector<Point> base_turned_to_a_vector(Probe&, const Settings&);
std::vector<Point> momenta_and_normals_in_the_plane(Probe&, const Settings&);
std::vector<Point> pucks(Probe&, const Settings&);

// rigid.cpp: rigid bodies of point masses, a rod on a penalty contact.
std::vector<Point> point_cloud_rigid_body(Probe&, const Settings&);
std::vector<Point> point_cloud_hit_at_several_points(Probe&, const Settings&);
std::vector<Point> point_cloud_pinned(Probe&, const Settings&);
std::vector<Point> turned_point(Probe&, const Settings&);
std::vector<Point> rod_on_a_penalty_spring(Probe&, const Settings&);
std::vector<Point> rod_on_a_penalty_damper(Probe&, const Settings&);

// contacts.cpp: bodies in contact by the law of restitution.
std::vector<Point> two_rigid_bodies_elastic(Probe&, const Settings&);
std::vector<Point> two_rigid_bodies_inelastic(Probe&, const Settings&);
std::vector<Point> two_rigid_bodies_one_elasticity(Probe&, const Settings&);

// friction.cpp (beyond the paper): a body struck obliquely, a rod striking a rough floor.
std::vector<Point> point_cloud_struck_obliquely(Probe&, const Settings&);
std::vector<Point> rod_slip_then_stick(Probe&, const Settings&);
std::vector<Point> rods_striking_rough_floors(Probe&, const Settings&);
// pulses.cpp: pulses of force on a body (section 4) and on a turning body (section 5).
std::vector<Point> pulses_on_a_body(Probe&, const Settings&);
std::vector<Point> pulses_on_a_turning_body(Probe&, const Settings&);
// library.cpp: the library's rigid body as a reference.
std::vector<Point> library_rigid_body_hit_at_several_points(Probe&, const Settings&);

// scenes.cpp: scenes of bodies at several contacts (sections 4 and 5).
std::vector<Point> two_point_masses_elastic(Probe&, const Settings&);
std::vector<Point> two_point_masses_inelastic(Probe&, const Settings&);
std::vector<Point> point_masses_in_scenes_elastic(Probe&, const Settings&);
std::vector<Point> point_masses_in_scenes_inelastic(Probe&, const Settings&);
std::vector<Point> point_masses_summed_elastic(Probe&, const Settings&);
std::vector<Point> point_masses_summed_inelastic(Probe&, const Settings&);
std::vector<Point> two_rigid_bodies_at_three_contacts_elastic(Probe&, const Settings&);
std::vector<Point> two_rigid_bodies_at_three_contacts_inelastic(Probe&, const Settings&);
std::vector<Point> rigid_bodies_summed_elastic(Probe&, const Settings&);
std::vector<Point> rigid_bodies_summed_inelastic(Probe&, const Settings&);
std::vector<Point> rigid_bodies_summed_any_elasticity(Probe&, const Settings&);
std::vector<Point> point_masses_an_elasticity_each(Probe&, const Settings&);
std::vector<Point> point_mass_against_three_walls(Probe&, const Settings&);

}  // namespace impulse::derivations::models
