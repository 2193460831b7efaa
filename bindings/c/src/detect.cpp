// SPDX-License-Identifier: BSD-3-Clause
// cj_detect: one detection through the C++ detect_contacts.
#include "conversions.hpp"

using namespace clearjoint::c_api;

extern "C" cj_status cj_detect(const cj_dimensions* dimensions, const cj_pose* bearing,
                               const cj_pose* journal, const cj_options* options,
                               cj_result* result, char* message, size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(dimensions, "dimensions = NULL: must point to the joint's dimensions");
    require_not_null(bearing, "bearing = NULL: must point to the bearing's pose");
    require_not_null(journal, "journal = NULL: must point to the journal's pose");
    require_not_null(result, "result = NULL: must point to a cj_result to fill");
    // One answer per thread, reused: the in-place overload writes only what the answer has,
    // where a fresh JointContacts would first write 1.4 KB of defaults (detect_contacts.hpp).
    thread_local geo::JointContacts found;
    geo::detect_contacts(dimensions_of(*dimensions), pose_of(*bearing), pose_of(*journal), found,
                         detection_options_of(options));
    copy_result(found, *result);
  });
}
