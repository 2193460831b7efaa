// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The kernel queries on a rim whose centre (and a plane whose point) detection computed by
// rounding (rounded_point.hpp): every certified or exact answer holds for the exact points, not
// only for the rounded ones. The public queries are these with exact points (nullptr).

#include "arithmetic/rounded_point.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

namespace clearjoint::geometry::detail {

/// circle.center must be centre->value. Crossing point errors include centre->error.
CircleCylinderIntersection intersect_circle_cylinder(const Circle3& circle, const Cylinder3& cylinder,
                                                     const IntersectionOptions& options,
                                                     const RoundedPoint* centre);
/// The same for inputs that pass validation (input_checks.hpp) and whose circle normal and
/// cylinder axis are already direction_scaled (scale_normalisation.hpp): the query above minus
/// those steps, with the same answer bit for bit (direction_scaled leaves a scaled direction as
/// it is). For detect_contacts, which checks its inputs and scales both axes once per joint
/// instead of once per candidate query.
CircleCylinderIntersection intersect_valid_circle_cylinder(const Circle3& circle, const Cylinder3& cylinder,
                                                           const IntersectionOptions& options,
                                                           const RoundedPoint* centre);
/// circle.center must be centre->value and plane.point point->value. Crossing point errors
/// include centre->error, the depth error both errors.
CirclePlaneIntersection intersect_circle_plane(const Circle3& circle, const Plane3& plane,
                                               const IntersectionOptions& options,
                                               const RoundedPoint* centre, const RoundedPoint* point);
/// For detect_contacts, which has the two errors at hand but builds the recipes only for the
/// exact tier, and measures depth at its contact point (eq. 23): true, with `out`
/// (default-constructed) filled with the answer the entry above gives for recipes with these
/// errors, bit for bit, except the depth (max_signed_distance and its error stay as
/// default-constructed), when the inputs need no rescaling (plane_quantities_if_ready) and no
/// exact tier; false otherwise, `out` then untouched: ask the entry above.
bool intersect_circle_plane_if_filtered(const Circle3& circle, const Plane3& plane,
                                        const IntersectionOptions& options, double centre_error,
                                        double point_error, CirclePlaneIntersection& out);

}  // namespace clearjoint::geometry::detail
