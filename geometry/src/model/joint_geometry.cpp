// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/joint_geometry.hpp"

#include <cmath>
#include <string>
#include <string_view>
#include <utility>

#include "arithmetic/unit_axis_range.hpp"
#include "model/input_checks.hpp"

namespace clearjoint::geometry {
namespace {

using detail::format;
using detail::reject;
using detail::require_positive;

}  // namespace

void validate(const JointDimensions& dimensions, std::string_view name, const JointDimensionNames& names) {
  // In this order, so that the first bad field is the one named.
  const std::pair<double, std::string_view> sizes[] = {{dimensions.bearing_radius, names.bearing_radius},
                                                       {dimensions.bearing_length, names.bearing_length},
                                                       {dimensions.journal_radius, names.journal_radius},
                                                       {dimensions.journal_length, names.journal_length}};
  for (const auto& [value, field] : sizes) {
    require_positive(value, name, field);
    if (!detail::length_in_range(value)) detail::reject_out_of_range(format(value), name, field);
  }
  // eqs. (1)-(2): the clearances must be positive.
  if (!(dimensions.journal_radius < dimensions.bearing_radius)) {
    reject(name, names.journal_radius, format(dimensions.journal_radius),
           "must be smaller than " + std::string(names.bearing_radius) + " = " +
               format(dimensions.bearing_radius) + " (the radial clearance Ri - Rj, eq. 1, must be positive)");
  }
  if (!(dimensions.journal_length < dimensions.bearing_length)) {
    reject(name, names.journal_length, format(dimensions.journal_length),
           "must be smaller than " + std::string(names.bearing_length) + " = " +
               format(dimensions.bearing_length) + " (the axial clearance (Li - Lj)/2, eq. 2, must be positive)");
  }
}

void validate(const PartPose& pose, std::string_view name, const PartPoseNames& names) {
  detail::require_finite(pose.p_WP, name, names.p_WP);
  if (!detail::coordinates_in_range(pose.p_WP)) detail::reject_out_of_range(format(pose.p_WP), name, names.p_WP);
  detail::require_finite(pose.axis_W, name, names.axis_W);
  detail::require_nonzero(pose.axis_W, name, names.axis_W);
}

Vector3 unit_axis(const PartPose& pose) {
  const double squared = pose.axis_W.squaredNorm();
  if (detail::in_safe_square_range(squared)) {
    return pose.axis_W / std::sqrt(squared);
  }
  // Rescaled by a power of two (exact) so that the largest component is in [1, 2), then
  // normalised. Not Eigen's stableNormalized: it divides by sqrt(z) max|a_i|, a product that is
  // subnormal for a subnormal axis and keeps only its few significant bits (2e-5 off for
  // 0.36 2^-1060).
  const int exponent = std::ilogb(pose.axis_W.cwiseAbs().maxCoeff());
  const Vector3 scaled(std::ldexp(pose.axis_W.x(), -exponent), std::ldexp(pose.axis_W.y(), -exponent),
                       std::ldexp(pose.axis_W.z(), -exponent));
  return scaled / scaled.norm();
}

BaseCenters base_centers(const PartPose& pose, double length) {
  return base_centers(pose.p_WP, unit_axis(pose), length);
}

BaseCenters base_centers(const Vector3& p_WP, const Vector3& unit_axis_W, double length) {
  const Vector3 half_axis = (0.5 * length) * unit_axis_W;
  return {p_WP + half_axis,   // eq. (3)
          p_WP - half_axis};  // eq. (4)
}

}  // namespace clearjoint::geometry
