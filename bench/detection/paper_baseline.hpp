// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The paper's contact detection as written (Marques et al. 2017, Section 3), in plain double
/// precision: the baseline the detection benchmarks compare clearjoint with. Bench-only code.
///
/// * Parallel axes: eq. (5), a~_i a_j = 0, tested on the unit axes in double (the paper gives no
///   tolerance, so the test is "every component of the cross product is exactly 0"); then the
///   line contact (eqs. 6-8) when the eccentricity exceeds cr, and a face contact (eqs. 9-10) when
///   a journal base lies beyond a bearing base plane.
/// * Axial contact at base X: the rim (eq. 11) against the base plane (eq. 12) in closed form, the
///   line common to both planes cut by the rim: two points are a penetration, fewer no contact
///   (the paper: "zero, one or two points ... no contact, tangent contact or penetration"; a
///   tangent point, of zero depth, is not reported). Contact points by eqs. (13)-(15).
/// * Radial contact at rim X: eqs. (16)-(17) solved for x in R^3 by plain Newton-Raphson, assuming
///   at most two roots (the paper's small-tilt argument). The rim is penetrating when its point
///   in the radial direction of the rim centre (the farthest one for an untilted rim) lies beyond
///   the wall; then Newton starts from the two fixed guesses a quarter turn either side of that
///   point and each run is taken to reach one crossing. Contact points by eqs. (18)-(21).
/// * Depth by eq. (23), the scenario by geometry::classify_scenario from the contacts found. The
///   paper has no notion of "beyond the model": a rim with four crossings, or beyond a surface
///   all round, is answered as the method finds it.
///
/// Every answer is `uncertain` (nothing is proved). No heap allocation.

#include "clearjoint/geometry/joint/detect_contacts.hpp"

namespace clearjoint::bench {

/// Newton stops when a step moves x by at most this fraction of the journal radius: ~50 ulps,
/// beyond which quadratic convergence makes further steps vanish in rounding.
inline constexpr double kNewtonStepTolerance = 1e-12;
/// Newton gives up (the crossing is then missing) after this many steps.
inline constexpr int kNewtonMaxIterations = 50;

geometry::JointContacts detect_contacts_paper_baseline(const geometry::JointDimensions& dimensions,
                                                       const geometry::PartPose& bearing,
                                                       const geometry::PartPose& journal);

}  // namespace clearjoint::bench
