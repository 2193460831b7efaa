// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact tier for rim/cylinder: decides the crossings of the stored primitives exactly (the
// polynomial in integers, its roots isolated by real_root_isolation.hpp; CGAL::Gmpq where a
// quotient remains). Far costlier than the floating-point tiers
// (docs/reports/benchmarks-kernel.md), so only called when they cannot decide.
// docs/circle-cylinder.md, section 4.

#include "arithmetic/rounded_point.hpp"
#include "filters/certified_rim_roots.hpp"

namespace clearjoint::geometry::detail {

/// `proved` unless the tier gives up (`failure` says why): on inputs whose magnitudes lie so far
/// apart that an intermediate double leaves the double range, or that root isolation exceeds
/// its budget of sign evaluations (it never hangs). count == 0 with sign_without_roots == 0
/// means the rim lies on the cylinder. Roots carry exact multiplicities; enclosures are
/// certified (rational isolation, then rigorous double bounds for the angle).
/// `centre`, when given, is the recipe of the exact rim centre that circle.center rounds (before
/// the query's rescaling by 2^-scale_exponent): the tier then decides that rim, not the rounded one.
RimRoots exact_rim_roots(const Circle3& circle, const Cylinder3& cylinder,
                         const RoundedPoint* centre = nullptr, int scale_exponent = 0);

}  // namespace clearjoint::geometry::detail
