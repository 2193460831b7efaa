// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Reading the caller's cj_pose_array (clearjoint.h) for the batch calls cj_detect_many and
/// cj_detect_pin_in_hole_many: the checks of the arrays and the count, and pose k read in place.

#include <cstdint>
#include <cstring>
#include <string>

#include "conversions.hpp"

namespace clearjoint::c_api {

/// Pose k of `poses` (clearjoint.h: component c at component[c] + k * stride bytes). memcpy,
/// because an array of the caller's own structs need not keep its doubles aligned.
inline geo::PartPose pose_at(const cj_pose_array& poses, std::size_t k) {
  const std::ptrdiff_t offset = static_cast<std::ptrdiff_t>(k) * poses.stride;
  double v[6];
  for (int c = 0; c < 6; ++c) {
    std::memcpy(&v[c], reinterpret_cast<const char*>(poses.component[c]) + offset, sizeof(double));
  }
  // Through Eigen::Map, as pose_of (conversions.hpp), for the same reason.
  return {Eigen::Map<const geo::Vector3>(v), Eigen::Map<const geo::Vector3>(v + 3)};
}

inline void require_components(const cj_pose_array* poses, const char* name) {
  require_not_null(poses, name, "a cj_pose_array");
  for (int c = 0; c < 6; ++c) {
    if (poses->component[c] == nullptr) {
      throw ValidationError(std::string(name) + ".component[" + std::to_string(c) + "]",
                            " = NULL: must point to the first pose's value");
    }
  }
}

/// Throws ValidationError naming `count` when no array of `count` results of `result_size` bytes
/// can exist: an object is at most PTRDIFF_MAX bytes (the C standard's bound on pointer
/// differences), so such a count is a caller's mistake (a negative number cast to size_t, an
/// uninitialised variable) and the loop would read and write past every array it was given.
inline void require_count(std::size_t count, std::size_t result_size, const char* result_type) {
  const std::size_t largest = static_cast<std::size_t>(PTRDIFF_MAX) / result_size;
  if (count > largest) [[unlikely]] {
    throw ValidationError("count", " = " + std::to_string(count) + ": more poses than an array of " + result_type +
                                       " can hold (at most " + std::to_string(largest) + ")");
  }
}

}  // namespace clearjoint::c_api
