// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <cmath>
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "model/input_checks.hpp"

namespace clearjoint::geometry {
/// Index k of the smallest |normal_k| (first on ties): the frame uses u' = normal x e_k.
/// Inline: as an out-of-line call it cost ~40 instructions, a third of frame_of.
inline int frame_axis_index(const Vector3& normal) {
  const double x = std::fabs(normal.x()), y = std::fabs(normal.y()), z = std::fabs(normal.z());
  int k = 0;
  double smallest = x;
  if (y < smallest) {
    k = 1;
    smallest = y;
  }
  if (z < smallest) k = 2;
  return k;
}

namespace detail {

/// What validate() accepts, as one inline test for the queries' entry: validate() itself (out of
/// line, and it formats the message) runs only when this fails.
inline bool nonzero(const Vector3& v) { return (v.x() != 0.0) | (v.y() != 0.0) | (v.z() != 0.0); }
inline bool finite_positive(double x) { return (x > 0.0) & (x - x == 0.0); }
inline bool passes_validation(const Circle3& c) {
  return all_finite(c.center) & all_finite(c.normal) & nonzero(c.normal) & finite_positive(c.radius);
}
inline bool passes_validation(const Plane3& p) {
  return all_finite(p.point) & all_finite(p.normal) & nonzero(p.normal);
}
inline bool passes_validation(const Cylinder3& c) {
  return all_finite(c.axis_point) & all_finite(c.axis) & nonzero(c.axis) & finite_positive(c.radius);
}

inline bool passes_validation(const JointDimensions& d) {
  // length_in_range implies finite and non-zero; with the ordering below, positive.
  return length_in_range(d.bearing_radius) & length_in_range(d.bearing_length) &
         length_in_range(d.journal_radius) & length_in_range(d.journal_length) &
         (d.journal_radius > 0.0) & (d.journal_length > 0.0) &
         (d.journal_radius < d.bearing_radius) & (d.journal_length < d.bearing_length);
}
inline bool passes_validation(const PartPose& pose) {
  return coordinates_in_range(pose.p_WP) & all_finite(pose.axis_W) & nonzero(pose.axis_W);
}

/// The range of kSmallestAcceptedLength/kLargestAcceptedLength over a joint's lengths: the part of
/// validation that the free-flight prefilter's guard does not imply.
inline bool lengths_in_range(const JointDimensions& d, const PartPose& bearing, const PartPose& journal) {
  return length_in_range(d.bearing_radius) & length_in_range(d.bearing_length) &
         length_in_range(d.journal_radius) & length_in_range(d.journal_length) &
         coordinates_in_range(bearing.p_WP) & coordinates_in_range(journal.p_WP);
}

}  // namespace detail
}  // namespace clearjoint::geometry
