// SPDX-License-Identifier: GPL-3.0-or-later
/// @file
/// @brief Everything of the ImpulseLab library: include this one header.
#pragma once

#include "impulse/core/elasticity.hpp"
#include "impulse/core/error.hpp"
#include "impulse/core/plane.hpp"
#include "impulse/core/solve.hpp"
#include "impulse/core/system.hpp"
#include "impulse/material_2d/material_2d.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "impulse/one_d/one_d.hpp"
#include "impulse/rigid_2d/rigid_2d.hpp"
#include "impulse/scene/scene.hpp"
