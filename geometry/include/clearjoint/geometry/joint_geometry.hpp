// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The joint as the paper describes it: dimensions (eqs. 1-2), part poses and base centres
/// (eqs. 3-4). Subscript i is the bearing (body i), j the journal (body j).

#include <string_view>

#include "clearjoint/geometry/primitives.hpp"
#include "clearjoint/geometry/vector3.hpp"

namespace clearjoint::geometry {

/// Bearing radius Ri and length Li, journal radius Rj and length Lj (metres, or any one unit).
/// Preconditions (checked by validate()): finite, Ri > Rj > 0, Li > Lj > 0.
struct JointDimensions {
  double bearing_radius = 0.0;   ///< Ri
  double bearing_length = 0.0;   ///< Li
  double journal_radius = 0.0;   ///< Rj
  double journal_length = 0.0;   ///< Lj

  /// cr = Ri - Rj, eq. (1). Exact in double when Ri <= 2 Rj (Sterbenz).
  double radial_clearance() const noexcept { return bearing_radius - journal_radius; }
  /// ca = (Li - Lj) / 2, eq. (2).
  double axial_clearance() const noexcept { return 0.5 * (bearing_length - journal_length); }
};

/// Where one part (bearing or journal) is: P, the centre of its axis segment, and a, its axis
/// direction, both in the world frame W. The axis need not have unit length; it must be finite
/// and non-zero.
///
/// The joint these numbers define (what detect_contacts certifies its answers about): the rim,
/// wall and base-plane normals are the axes as given (any length: only their direction counts);
/// the base centres are exactly P +- (L/2) a_hat with a_hat = unit_axis(pose), the axis
/// normalised in double. That normalisation is the one rounding in the definition (a square root
/// has no exact double); a_hat is bitwise a when a . a evaluates to exactly 1, and otherwise
/// within a few ulps of a / |a|, which moves a centre by a few ulps of L. Everything after it is
/// exact: detection rounds the centres for speed but carries the rounding into its bounds and
/// evaluates the exact centres where a decision needs them.
struct PartPose {
  Vector3 p_WP = Vector3::Zero();
  Vector3 axis_W = Vector3::UnitZ();
};

/// Throw InvalidInput naming the field and its value ("dimensions.journal_radius = 10: must be
/// smaller than bearing_radius = 10") for non-finite values, non-positive sizes, or a journal
/// not smaller than its bearing.
void validate(const JointDimensions& dimensions, std::string_view name = "dimensions");
/// Throw InvalidInput for a non-finite centre or axis, or a zero axis.
void validate(const PartPose& pose, std::string_view name = "pose");

/// a / |a| rounded to double (rescaled first when |a|^2 would under- or overflow).
Vector3 unit_axis(const PartPose& pose);

/// The centres of a part's two bases: A = P + (L/2) a_hat (eq. 3), B = P - (L/2) a_hat (eq. 4),
/// a_hat = unit_axis(pose); each coordinate rounded to double (detection keeps the exact ones).
struct BaseCenters {
  Vector3 p_WA = Vector3::Zero();
  Vector3 p_WB = Vector3::Zero();
};
BaseCenters base_centers(const PartPose& pose, double length);
/// The same from a unit axis already computed (unit_axis(pose)).
BaseCenters base_centers(const Vector3& p_WP, const Vector3& unit_axis_W, double length);

}  // namespace clearjoint::geometry
