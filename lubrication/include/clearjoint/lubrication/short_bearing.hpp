// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The short-bearing (Ocvirk) closed form with the half-Sommerfeld (Guembel) condition.

#include "clearjoint/lubrication/planar_film.hpp"

namespace clearjoint::lubrication {

/// The film load of an aligned journal when B / D -> 0: the circumferential pressure flow is
/// dropped from the Reynolds equation (Ocvirk 1952), which then integrates in z:
///   p(psi, z) = G(psi) (z^2 - B^2 / 4) / 2,
///   G = (6 eta / c^2) [eps (omega - 2 phi') sin psi - 2 eps' cos psi] / (1 - eps cos psi)^3,
/// kept where p > 0 (Guembel): a half period of psi, exactly. The force integrals are taken in
/// closed form by the Sommerfeld substitution (docs/lubrication.md). Any rotation, whirl and
/// squeeze; pure rotation gives So = (B/D)^2 eps sqrt(pi^2 (1 - eps^2) + 16 eps^2) /
/// (2 (1 - eps^2)^2) and tan beta = pi sqrt(1 - eps^2) / (4 eps).
/// Accuracy: the formulas are exact for their model (rounding only, relative 1e-14 away from
/// eps -> 1); against a finite bearing they overestimate the load by O((B/D)^2).
PlanarFilmLoad short_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                  double viscosity);

/// short_bearing_load without the peak pressure, whose search (32 samples and Brent's method) is
/// most of the closed form's cost: radial, tangential, magnitude, attitude_angle and side_flow
/// bit for bit short_bearing_load's, max_pressure NaN (0 without
/// wedge or squeeze, as there). For callers that need the force alone,
/// such as a right-hand side.
PlanarFilmLoad short_bearing_force(const PlanarBearing& bearing, const PlanarFilmState& state,
                                   double viscosity);

}  // namespace clearjoint::lubrication
