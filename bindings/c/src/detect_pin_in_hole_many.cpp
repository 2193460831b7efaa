// SPDX-License-Identifier: BSD-3-Clause
// cj_detect_pin_in_hole_many: the pin-in-hole joint over the caller's arrays of poses, read in
// place through strides, with cj_detect_many's conventions.
#include <string>

#include "pin_in_hole_conversions.hpp"
#include "pose_arrays.hpp"

using namespace clearjoint::c_api;

extern "C" cj_status cj_detect_pin_in_hole_many(const cj_pin_in_hole_dimensions* dimensions,
                                                const cj_pose_array* holes, const cj_pose_array* pins,
                                                size_t count, const cj_options* options,
                                                cj_pin_in_hole_result* results, size_t* processed,
                                                char* message, size_t message_capacity) {
  size_t done = 0;
  const cj_status status = reporting_failures(message, message_capacity, [&] {
    require_not_null(dimensions, "dimensions", "the joint's dimensions");
    if (count == 0) return;
    require_count(count, sizeof(cj_pin_in_hole_result), "cj_pin_in_hole_result");
    require_components(holes, "holes");
    require_components(pins, "pins");
    require_not_null(results, "results", "count cj_pin_in_hole_result");
    const geo::PinInHoleDimensions joint = pin_in_hole_dimensions_of(*dimensions);
    geo::validate(joint);  // before the loop: not a pose's fault, so not named after one
    const geo::DetectionOptions detection = detection_options_of(options);
    geo::validate(detection);  // likewise
    // A pose repeated for every k (stride 0, often the hole) is read once.
    const bool fixed_hole = holes->stride == 0, fixed_pin = pins->stride == 0;
    const geo::PartPose first_hole = pose_at(*holes, 0), first_pin = pose_at(*pins, 0);
    for (; done < count; ++done) {
      geo::PinInHoleContacts found;
      try {
        found = geo::detect_pin_in_hole_contacts(joint, fixed_hole ? first_hole : pose_at(*holes, done),
                                                 fixed_pin ? first_pin : pose_at(*pins, done), detection);
      } catch (const geo::InvalidInput& e) {
        throw geo::InvalidInput("poses[" + std::to_string(done) + "]", std::string(": ") + e.what());
      }
      copy_pin_in_hole_result(found, results[done]);
    }
  });
  if (processed != nullptr) *processed = done;
  return status;
}
