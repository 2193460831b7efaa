// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The joint as the paper describes it: dimensions (eqs. 1-2), part poses and base centres
/// (eqs. 3-4). Subscript i is the bearing (body i), j the journal (body j).

#include <string_view>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry {

/// The lengths detect_contacts accepts: every dimension, and every coordinate of a part's centre
/// P, is 0 (coordinates only) or of magnitude in [kSmallestAcceptedLength, kLargestAcceptedLength].
/// The certificates hold inside this range and are not promised outside it, where the error
/// bounds, evaluated in double, under- or overflow (a scenario (a) pose scaled by a power of two
/// broke its certified bounds from 2^-511 and from 2^520 times its size). Any unit will do:
/// rescale a joint outside the range. The command line accepts the same range
/// (docs/command-line.md, "Limits"); axes, which mean only a direction, may be any finite,
/// non-zero vector.
inline constexpr double kSmallestAcceptedLength = 1e-150;
inline constexpr double kLargestAcceptedLength = 1e150;

/// Bearing radius Ri and length Li, journal radius Rj and length Lj (metres, or any one unit).
/// Preconditions (checked by validate()): Ri > Rj > 0, Li > Lj > 0, each in
/// [kSmallestAcceptedLength, kLargestAcceptedLength].
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
/// and non-zero. Each coordinate of P is 0 or of magnitude in [kSmallestAcceptedLength,
/// kLargestAcceptedLength].
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

/// The names validate() gives the four sizes in its messages, after the caller's path: the
/// members of JointDimensions by default; kPartDimensionNames for a description that groups them
/// by part, as the command line's JSON and the dynamics' model files do.
struct JointDimensionNames {
  std::string_view bearing_radius = "bearing_radius";
  std::string_view bearing_length = "bearing_length";
  std::string_view journal_radius = "journal_radius";
  std::string_view journal_length = "journal_length";
};
inline constexpr JointDimensionNames kPartDimensionNames{"bearing.radius", "bearing.length", "journal.radius",
                                                         "journal.length"};

/// The one check of a joint's dimensions, for every front-end: throw InvalidInput naming the
/// field and its value ("dimensions.journal_radius = 10: must be smaller than bearing_radius = 10
/// (the radial clearance Ri - Rj, eq. 1, must be positive)") for non-finite values, non-positive
/// sizes, sizes outside the accepted range, or a journal not smaller than its bearing. `name` is
/// the caller's path to the dimensions ("forces[0]"); empty, the field names stand alone.
void validate(const JointDimensions& dimensions, std::string_view name = "dimensions",
              const JointDimensionNames& names = {});
/// The names validate() gives a pose's two fields: the members of PartPose by default;
/// kPartPoseNames for the command line's JSON ("center", "axis").
struct PartPoseNames {
  std::string_view p_WP = "p_WP";
  std::string_view axis_W = "axis_W";
};
inline constexpr PartPoseNames kPartPoseNames{"center", "axis"};

/// The one check of a part's pose, for every front-end: throw InvalidInput naming the field and
/// its value for a non-finite centre or axis, a zero axis, or a centre coordinate outside the
/// accepted range. `name` is the caller's path to the pose ("journal").
void validate(const PartPose& pose, std::string_view name = "pose", const PartPoseNames& names = {});

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
