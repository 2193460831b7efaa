// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The input families of the detection benchmarks (issue 5), each generated from a fixed seed.
///
/// Units: metres unless a configuration says otherwise (the extreme family's unit variants).
/// Every family uses the paper's Table 2 joint unless it says otherwise. Each input has an id
/// that names the family, the group (margin or tilt class) and a serial number, so that a failure
/// can be traced back to its generator.
///
///   realistic      a bearing anywhere in a mechanism (centre within 0.2 m of the origin, any axis
///                  direction), journal tilted up to the largest tilt the clearances allow, its
///                  centre offset up to 1.5 cr radially and 1.5 ca axially.
///   near_tangent   one candidate contact (radial, axial, line or face) at a signed margin of
///                  10^-k clearances from touching, k = 3..15, bearing at the origin so that the
///                  doubles can hold the margin; the margin actually reached by the rounded pose is
///                  recorded (`measured_margin`, in clearances).
///   near_parallel  journal tilts of 10^-k rad, k = 4..16, and exactly parallel axes (group k = 0),
///                  offsets up to 1.5 clearances.
///   extreme        scenario (i) at and just beyond the largest tilt, the journal axis reversed,
///                  coincident axes, clearance ratios cr/Ri from 1e-6 to 0.2, and one set of
///                  configurations in metres, micrometres and kilometres.
///   trajectories   consecutive poses of a journal bouncing inside the bearing (scripted).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "clearjoint/geometry/model/joint_geometry.hpp"

namespace clearjoint::bench {

struct DetectionInput {
  std::string id;      ///< "near_tangent/radial_a/k=7/+/3"
  std::string family;  ///< "near_tangent"
  std::string group;   ///< "k=7" (near-tangent, near-parallel), a sub-family name, or ""
  /// Numeric group value (k of the 10^-k margin or tilt; 0 = exactly parallel); NaN if none.
  double group_value = 0.0;
  /// near_tangent: the signed margin the rounded pose actually has, in clearances (positive:
  /// penetrating); NaN elsewhere.
  double measured_margin = 0.0;
  /// near_parallel: the angle between the stored axes (rad), evaluated in MPFR; NaN elsewhere.
  double measured_tilt = 0.0;
  geometry::JointDimensions dimensions;
  geometry::PartPose bearing;
  geometry::PartPose journal;
};

struct FamilySpec {
  const char* name;
  std::uint64_t seed;
  const char* description;
};

/// The five families, their seeds and one-line descriptions, in report order.
const std::vector<FamilySpec>& family_specs();

/// Paper Table 2 in metres: Ri = 10 mm, Li = 20 mm, Rj = 9.9 mm, Lj = 19.8 mm (cr = ca = 0.1 mm).
geometry::JointDimensions table2_dimensions();

/// Size of the families: `full` for the documented run, `quick` for the ctest variant (every
/// group still present, fewer inputs per group).
enum class SuiteSize { quick, full };

/// Generates one family. `progress` (may be empty) is called now and then with a fraction done.
std::vector<DetectionInput> generate_family(const std::string& family, SuiteSize size,
                                            const std::function<void(double)>& progress = {});

}  // namespace clearjoint::bench
