// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Everything of the ImpulseLab library: include this one header.
#pragma once

#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/friction/bodies.hpp"
#include "impulse/friction/contact.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
#include "impulse/methods/methods.hpp"
#include "impulse/methods/serial.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "impulse/one_d/one_d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "impulse/scene/scene.hpp"

/// @brief The ImpulseLab library: the collision impulses of the paper *Collision handling*, in the
/// form A·Fdt = B.
///
/// This namespace holds what every section shares: the elasticity (impulse::Elasticity), the
/// system and its ⊕ (impulse::ContactSystem), and its solution (impulse::solve). The bodies of
/// each paper section live in a namespace of their own: impulse::one_d (section 1),
/// impulse::material_2d (section 2), impulse::rigid_2d (section 3), impulse::multipoint
/// (sections 4 and 5); impulse::scene turns a scene file's bodies and contacts into a solved
/// collision. impulse::methods goes beyond the paper: impulses that only push (with Coulomb
/// friction too, all contacts at once), and contacts resolved one at a time; so does
/// impulse::friction: one contact with Coulomb friction, followed through the normal impulse,
/// with three laws of restitution.
namespace impulse {}
