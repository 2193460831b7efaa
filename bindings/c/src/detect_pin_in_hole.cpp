// SPDX-License-Identifier: BSD-3-Clause
// cj_detect_pin_in_hole: one detection through the C++ detect_pin_in_hole_contacts.
#include "pin_in_hole_conversions.hpp"

using namespace clearjoint::c_api;

extern "C" cj_status cj_detect_pin_in_hole(const cj_pin_in_hole_dimensions* dimensions, const cj_pose* hole,
                                           const cj_pose* pin, const cj_options* options,
                                           cj_pin_in_hole_result* result, char* message,
                                           size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(dimensions, "dimensions", "the joint's dimensions");
    require_not_null(hole, "hole", "the hole's pose");
    require_not_null(pin, "pin", "the pin's pose");
    require_not_null(result, "result", "a cj_pin_in_hole_result to fill");
    const geo::PinInHoleContacts found = geo::detect_pin_in_hole_contacts(
        pin_in_hole_dimensions_of(*dimensions), pose_of(*hole), pose_of(*pin), detection_options_of(options));
    copy_pin_in_hole_result(found, *result);
  });
}
