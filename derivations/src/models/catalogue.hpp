// SPDX-License-Identifier: GPL-3.0-or-later
// The models of each family, in the order of the docs; models.cpp puts them in one table.
#pragma once

#include <vector>

#include "models/model.hpp"

namespace impulse::derivations::models {

std::vector<Model> line_models();   // line.cpp: two bodies on a line
std::vector<Model> plane_models();  // plane.cpp: point masses in the plane
std::vector<Model>
rigid_models();  // rigid.cpp: rigid bodies of point masses, a rod on a penalty contact
std::vector<Model> contacts_models();  // contacts.cpp: bodies in contact by the law of restitution
std::vector<Model> friction_models();  // friction.cpp: beyond the paper, friction: a body struck
                                       // obliquely, a rod striking a rough floor
std::vector<Model> pulses_models();    // pulses.cpp: pulses of force on a body (section 4) and on a
                                       // turning body (section 5)
std::vector<Model> library_models();   // library.cpp: the library's rigid body as a reference
std::vector<Model>
scenes_models();  // scenes.cpp: scenes of bodies at several contacts (sections 4 and 5)

}  // namespace impulse::derivations::models
