// SPDX-License-Identifier: BSD-3-Clause
// cj_intersect_circle_plane and cj_intersect_circle_cylinder: the kernel's two queries.
#include "conversions.hpp"

using namespace clearjoint::c_api;

namespace {

geo::Circle3 circle_of(const cj_circle& c) { return {vector_of(c.center), vector_of(c.normal), c.radius}; }

int32_t code_of(geo::CirclePlaneTopology t) {
  switch (t) {
    case geo::CirclePlaneTopology::disjoint: return CJ_CIRCLE_PLANE_DISJOINT;
    case geo::CirclePlaneTopology::tangent: return CJ_CIRCLE_PLANE_TANGENT;
    case geo::CirclePlaneTopology::two_crossings: return CJ_CIRCLE_PLANE_TWO_CROSSINGS;
    case geo::CirclePlaneTopology::circle_in_plane: return CJ_CIRCLE_PLANE_CIRCLE_IN_PLANE;
  }
  return CJ_CIRCLE_PLANE_DISJOINT;
}

int32_t code_of(geo::CircleCylinderTopology t) {
  switch (t) {
    case geo::CircleCylinderTopology::inside: return CJ_CIRCLE_CYLINDER_INSIDE;
    case geo::CircleCylinderTopology::outside: return CJ_CIRCLE_CYLINDER_OUTSIDE;
    case geo::CircleCylinderTopology::crossing: return CJ_CIRCLE_CYLINDER_CROSSING;
    case geo::CircleCylinderTopology::on_surface: return CJ_CIRCLE_CYLINDER_ON_SURFACE;
  }
  return CJ_CIRCLE_CYLINDER_INSIDE;
}

/// Only certify and exact_fallback apply to the kernel queries (clearjoint.h); the reserved
/// fields are checked as for a detection.
geo::IntersectionOptions intersection_options_of(const cj_options* options) {
  const geo::DetectionOptions detection = detection_options_of(options);
  return detection.intersection;
}

}  // namespace

extern "C" cj_status cj_intersect_circle_plane(const cj_circle* circle, const cj_plane* plane,
                                               const cj_options* options,
                                               cj_circle_plane_result* result, char* message,
                                               size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(circle, "circle = NULL: must point to the circle");
    require_not_null(plane, "plane = NULL: must point to the plane");
    require_not_null(result, "result = NULL: must point to a cj_circle_plane_result to fill");
    const geo::CirclePlaneIntersection found = geo::intersect_circle_plane(
        circle_of(*circle), {vector_of(plane->point), vector_of(plane->normal)}, intersection_options_of(options));
    cj_circle_plane_result out{};
    out.topology = code_of(found.topology);
    out.side = static_cast<int32_t>(found.side);  // PlaneSide's values are -1, 0, +1
    for (int k = 0; k < 2; ++k) copy_crossing(found.crossings[k], out.crossings[k]);
    out.crossing_count = found.crossing_count;
    out.has_penetration = found.has_penetration ? 1 : 0;
    out.penetration = arc_of(found.penetration);
    out.max_signed_distance = found.max_signed_distance;
    out.max_signed_distance_error_bound = found.max_signed_distance_error;
    out.certificate = certificate_of(found.certificate);
    *result = out;
  });
}

extern "C" cj_status cj_intersect_circle_cylinder(const cj_circle* circle, const cj_cylinder* cylinder,
                                                  const cj_options* options,
                                                  cj_circle_cylinder_result* result, char* message,
                                                  size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(circle, "circle = NULL: must point to the circle");
    require_not_null(cylinder, "cylinder = NULL: must point to the cylinder");
    require_not_null(result, "result = NULL: must point to a cj_circle_cylinder_result to fill");
    const geo::CircleCylinderIntersection found = geo::intersect_circle_cylinder(
        circle_of(*circle), {vector_of(cylinder->axis_point), vector_of(cylinder->axis), cylinder->radius},
        intersection_options_of(options));
    cj_circle_cylinder_result out{};
    out.topology = code_of(found.topology);
    for (int k = 0; k < 4; ++k) copy_crossing(found.crossings[k], out.crossings[k]);
    out.crossing_count = found.crossing_count;
    for (int k = 0; k < 2; ++k) out.penetration_arcs[k] = arc_of(found.penetration_arcs[k]);
    out.arc_count = found.arc_count;
    out.certificate = certificate_of(found.certificate);
    *result = out;
  });
}
