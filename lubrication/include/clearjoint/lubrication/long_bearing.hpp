// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The long-bearing (Sommerfeld) closed form with the half-Sommerfeld (Guembel) condition.

#include "clearjoint/lubrication/planar_film.hpp"

namespace clearjoint::lubrication {

/// The film load of an aligned journal when B / D -> infinity: the axial pressure flow is
/// dropped, the Reynolds equation integrates in psi,
///   p'(psi) = (6 eta R^2 / c^2) [Omega (3 eps^2 / (2 + eps^2) - eps cos psi) - 2 eps' sin psi]
///             / (1 - eps cos psi)^3,   Omega = omega - 2 phi',
/// with the constant fixed by a periodic pressure, and p = 0 (ambient) at the thickest film
/// psi = pi, where a long bearing is fed. The force is the integral of p > 0 (Guembel) times the
/// width B; pure rotation gives So = 3 eps sqrt(pi^2 (1 - eps^2) + 4 eps^2) /
/// ((2 + eps^2)(1 - eps^2)) and tan beta = pi sqrt(1 - eps^2) / (2 eps).
/// Accuracy: every output to a few ulps for any eps < 1 (the forms of long_bearing.cpp keep the
/// factor 1 - eps^2 out of every difference; kClosedFormRelativeError in
/// bearing_characteristics.hpp states the bound the tests hold against a multiprecision
/// evaluation); with squeeze and rotation together, also kLongBearingRootTolerance.
/// Cost: closed form for eps' = 0. With squeeze, the second end of the positive region lies
/// between the pressure's two extrema (closed form) and is found there by Newton's method in the
/// Sommerfeld angle, safeguarded by bisection (kLongBearingRootTolerance): a few sines and
/// cosines, no sampling. Side flow: 0 (no ends).
PlanarFilmLoad long_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                 double viscosity);

/// Tolerance (rad, in the Sommerfeld angle) of the pressure root found with squeeze and rotation
/// together: 8e-15, about 4 ulps of gamma in (pi, 3 pi] (its ulp is 1.8e-15 above 2 pi). The
/// force integrals are primitives of p', so an end off by delta moves them by p'(r) delta: a
/// relative 1e-14 of the force for a root that is not much steeper than the pressure's mean
/// slope. Pure rotation and pure squeeze have their ends at multiples of pi, taken exactly.
inline constexpr double kLongBearingRootTolerance = 8e-15;

}  // namespace clearjoint::lubrication
