// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The misaligned scenarios (a)-(i) of the paper's Fig. 2, plus none, built from a journal tilted
/// in the y-z plane of a bearing on the z axis, where every depth and contact point has a closed
/// form. Shared by the library's detection tests (test_detect_contacts.cpp) and the detection
/// suite's tests of its reference and of the paper baseline (tests/bench/detection), so that all
/// three check the same configurations.

#include <cmath>
#include <string_view>

#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"

namespace clearjoint::geometry::testing {

// Table 2 of the paper, in millimetres: cr = ca = 0.1.
inline const JointDimensions kTable2{10.0, 20.0, 9.9, 19.8};
// A larger radial clearance (cr = 1, ca = 0.1): both rims can reach their bases without
// touching the wall (scenario (d)), which Table 2 does not allow (there the radial and axial
// reaches grow alike with the tilt, see TiltedJournal).
inline const JointDimensions kWideRadialClearance{10.0, 20.0, 9.0, 19.8};
// A longer axial clearance (cr = 0.1, ca = 0.5): both rims reach the wall without reaching the
// bases (scenario (c)).
inline const JointDimensions kLongAxialClearance{10.0, 20.0, 9.9, 19.0};

/// The bearing on the z axis, centred at the origin: base A at z = Li/2, base B at z = -Li/2.
inline PartPose bearing_on_z() { return {Vector3::Zero(), Vector3::UnitZ()}; }

/// A journal centred at (0, y0, z0) with axis (0, sin tilt, cos tilt).
///
/// Closed forms. A rim with centre c = (0, c_y, c_z) has points
///   x(s) = c + Rj (cos(theta) e_x + s e_perp),  s = sin(theta),  e_perp = (0, cos tilt, -sin tilt).
/// Squared distance to the z axis: f(s) = Rj^2 + c_y^2 + 2 c_y Rj cos(tilt) s - Rj^2 sin^2(tilt) s^2,
/// concave in s, largest at s = sign(c_y) when |c_y| cos(tilt) >= Rj sin^2(tilt) (always so
/// below; else the rim crosses the wall four times), with value (|c_y| + Rj cos tilt)^2. So the
/// radial depth is |c_y| + Rj cos(tilt) - Ri at the point c + sign(c_y) Rj e_perp. The mirror
/// symmetry x -> -x makes that point the middle of the penetration arc (eq. 18).
/// Height of a rim point: c_z - Rj s sin(tilt): the axial depth at A is c_z + Rj sin(tilt) - Li/2
/// at c - Rj e_perp, at B it is Rj sin(tilt) - c_z - Li/2 at c + Rj e_perp.
/// With rim A centre c_A = P + (Lj/2) a and rim B c_B = P - (Lj/2) a, and |y0| below
/// (Lj/2) sin(tilt): radial depths +-y0 + S, axial depths +-z0 + T, with
/// S = (Lj/2) sin(tilt) + Rj cos(tilt) - Ri and T = (Lj/2) cos(tilt) + Rj sin(tilt) - Li/2.
struct TiltedJournal {
  double y0 = 0.0;
  double z0 = 0.0;
  double tilt = 0.0;

  PartPose pose() const {
    return {Vector3(0.0, y0, z0), Vector3(0.0, std::sin(tilt), std::cos(tilt))};
  }
};

struct ScenarioCase {
  const char* name;
  JointDimensions dimensions;
  TiltedJournal journal;
  ContactScenario scenario;
};

// Table 2: S = T = 9.9 (sin + cos)(tilt) - 10, i.e. -0.0506 at tilt 0.005 and +0.0279 at 0.013.
inline const ScenarioCase kMisalignedCases[] = {
    {"none", kTable2, {0.0, 0.0, 0.005}, ContactScenario::none},
    {"a", kTable2, {0.08, 0.0, 0.005}, ContactScenario::single_radial},
    {"a_at_b", kTable2, {-0.08, 0.0, 0.005}, ContactScenario::single_radial},
    {"b", kTable2, {0.0, 0.08, 0.005}, ContactScenario::single_axial},
    {"b_at_b", kTable2, {0.0, -0.08, 0.005}, ContactScenario::single_axial},
    // kLongAxialClearance at tilt 0.015: S = +0.047, T = -0.353.
    {"c", kLongAxialClearance, {0.0, 0.0, 0.015}, ContactScenario::radial_at_both_bases},
    // kWideRadialClearance at tilt 0.02: S = -0.80, T = +0.078.
    {"d", kWideRadialClearance, {0.0, 0.0, 0.02}, ContactScenario::axial_at_both_bases},
    {"e", kTable2, {0.08, 0.08, 0.005}, ContactScenario::radial_and_axial_same_base},
    {"f", kTable2, {0.08, -0.08, 0.005}, ContactScenario::radial_and_axial_opposite_bases},
    {"g", kTable2, {0.0, 0.04, 0.013}, ContactScenario::two_radial_one_axial},
    {"h", kTable2, {0.04, 0.0, 0.013}, ContactScenario::one_radial_two_axial},
    {"i", kTable2, {0.0, 0.0, 0.013}, ContactScenario::all_four},
};

/// The case of that name in kMisalignedCases (the first one when the name is unknown: callers
/// name cases that exist).
inline const ScenarioCase& misaligned_case(const char* name) {
  for (const ScenarioCase& c : kMisalignedCases) {
    if (std::string_view(c.name) == name) return c;
  }
  return kMisalignedCases[0];
}

}  // namespace clearjoint::geometry::testing
