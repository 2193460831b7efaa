// SPDX-License-Identifier: BSD-3-Clause
// cj_intersect_circle_plane and cj_intersect_circle_cylinder: the kernel's two queries.
#include "conversions.hpp"

using namespace clearjoint::c_api;

namespace {

geo::Circle3 circle_of(const cj_circle& c) { return {vector_of(c.center), vector_of(c.normal), c.radius}; }

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
    require_not_null(circle, "circle", "the circle");
    require_not_null(plane, "plane", "the plane");
    require_not_null(result, "result", "a cj_circle_plane_result to fill");
    const geo::CirclePlaneIntersection found = geo::intersect_circle_plane(
        circle_of(*circle), {vector_of(plane->point), vector_of(plane->normal)}, intersection_options_of(options));
    *result = circle_plane_result_of(found);
  });
}

extern "C" cj_status cj_intersect_circle_cylinder(const cj_circle* circle, const cj_cylinder* cylinder,
                                                  const cj_options* options,
                                                  cj_circle_cylinder_result* result, char* message,
                                                  size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(circle, "circle", "the circle");
    require_not_null(cylinder, "cylinder", "the cylinder");
    require_not_null(result, "result", "a cj_circle_cylinder_result to fill");
    const geo::CircleCylinderIntersection found = geo::intersect_circle_cylinder(
        circle_of(*circle), {vector_of(cylinder->axis_point), vector_of(cylinder->axis), cylinder->radius},
        intersection_options_of(options));
    *result = circle_cylinder_result_of(found);
  });
}
