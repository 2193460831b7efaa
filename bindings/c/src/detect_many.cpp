// SPDX-License-Identifier: BSD-3-Clause
// cj_detect_many: detection over the caller's arrays of poses, read in place through strides,
// and the helpers that describe the common layouts.
#include <cstring>
#include <string>

#include "pose_arrays.hpp"

using namespace clearjoint::c_api;

extern "C" cj_status cj_detect_many(const cj_dimensions* dimensions, const cj_pose_array* bearings,
                                    const cj_pose_array* journals, size_t count,
                                    const cj_options* options, cj_result* results,
                                    size_t* processed, char* message, size_t message_capacity) {
  size_t done = 0;
  const cj_status status = reporting_failures(message, message_capacity, [&] {
    require_not_null(dimensions, "dimensions", "the joint's dimensions");
    if (count == 0) return;
    require_count(count, sizeof(cj_result), "cj_result");
    require_components(bearings, "bearings");
    require_components(journals, "journals");
    require_not_null(results, "results", "count cj_result");
    const geo::JointDimensions joint = dimensions_of(*dimensions);
    geo::validate(joint);  // before the loop: not a pose's fault, so not named after one
    const geo::DetectionOptions detection = detection_options_of(options);
    geo::validate(detection);  // likewise
    geo::JointContacts found;  // reused, as in cj_detect
    // A pose repeated for every k (stride 0, often the bearing) is read once.
    const bool fixed_bearing = bearings->stride == 0, fixed_journal = journals->stride == 0;
    const geo::PartPose first_bearing = pose_at(*bearings, 0), first_journal = pose_at(*journals, 0);
    for (; done < count; ++done) {
      try {
        geo::detect_contacts(joint, fixed_bearing ? first_bearing : pose_at(*bearings, done),
                             fixed_journal ? first_journal : pose_at(*journals, done), found, detection);
      } catch (const geo::InvalidInput& e) {
        throw geo::InvalidInput("poses[" + std::to_string(done) + "]", std::string(": ") + e.what());
      }
      copy_result(found, results[done]);
    }
  });
  if (processed != nullptr) *processed = done;
  return status;
}

extern "C" cj_pose_array cj_pose_array_rows(const double* data) {
  cj_pose_array poses{};
  for (int c = 0; c < 6; ++c) poses.component[c] = data == nullptr ? nullptr : data + c;
  poses.stride = 6 * static_cast<std::ptrdiff_t>(sizeof(double));
  return poses;
}

extern "C" cj_pose_array cj_pose_array_columns(const double* data, size_t count) {
  cj_pose_array poses{};
  for (int c = 0; c < 6; ++c) poses.component[c] = data == nullptr ? nullptr : data + c * count;
  poses.stride = static_cast<std::ptrdiff_t>(sizeof(double));
  return poses;
}

extern "C" cj_pose_array cj_pose_array_repeat(const cj_pose* pose) {
  cj_pose_array poses{};
  if (pose != nullptr) {
    for (int c = 0; c < 3; ++c) {
      poses.component[c] = &pose->p_WP[c];
      poses.component[c + 3] = &pose->axis_W[c];
    }
  }
  poses.stride = 0;
  return poses;
}
