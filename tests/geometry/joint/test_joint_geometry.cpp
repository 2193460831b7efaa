// SPDX-License-Identifier: BSD-3-Clause
// Tests of joint_geometry: dimensions and clearances (eqs. 1-2), validation, base centres
// (eqs. 3-4).

#include "clearjoint/geometry/joint_geometry.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace clearjoint::geometry {
namespace {

// Table 2 of the paper, in millimetres.
const JointDimensions kTable2{10.0, 20.0, 9.9, 19.8};

std::string message_of(const JointDimensions& dimensions) {
  try {
    validate(dimensions);
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

std::string message_of(const PartPose& pose) {
  try {
    validate(pose, "journal");
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(JointDimensions, ClearancesAreEquationsOneAndTwo) {
  // cr = Ri - Rj = 0.1 and ca = (Li - Lj)/2 = 0.1, up to the rounding of the decimal inputs.
  constexpr double kDecimalRounding = 4 * std::numeric_limits<double>::epsilon() * 20.0;
  EXPECT_NEAR(kTable2.radial_clearance(), 0.1, kDecimalRounding);
  EXPECT_NEAR(kTable2.axial_clearance(), 0.1, kDecimalRounding);
  const JointDimensions exact{8.0, 16.0, 6.0, 10.0};  // exactly representable
  EXPECT_EQ(exact.radial_clearance(), 2.0);
  EXPECT_EQ(exact.axial_clearance(), 3.0);
}

TEST(JointDimensions, ValidTable2DimensionsPass) { EXPECT_EQ(message_of(kTable2), ""); }

TEST(JointDimensions, EachBadFieldIsNamedWithItsValue) {
  JointDimensions d = kTable2;
  d.bearing_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(d), "dimensions.bearing_radius = nan: must be finite");
  d = kTable2;
  d.bearing_length = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(d), "dimensions.bearing_length = inf: must be finite");
  d = kTable2;
  d.journal_radius = -1.0;
  EXPECT_EQ(message_of(d), "dimensions.journal_radius = -1: must be positive");
  d = kTable2;
  d.journal_length = 0.0;
  EXPECT_EQ(message_of(d), "dimensions.journal_length = 0: must be positive");
}

TEST(JointDimensions, JournalNotSmallerThanBearingIsRejected) {
  JointDimensions d = kTable2;
  d.journal_radius = 10.0;
  EXPECT_EQ(message_of(d), "dimensions.journal_radius = 10: must be smaller than bearing_radius = 10");
  d = kTable2;
  d.journal_length = 25.0;
  EXPECT_EQ(message_of(d), "dimensions.journal_length = 25: must be smaller than bearing_length = 20");
}

TEST(PartPose, NonFiniteOrZeroFieldsAreNamed) {
  EXPECT_EQ(message_of(PartPose{}), "");
  PartPose pose;
  pose.axis_W = Vector3::Zero();
  EXPECT_EQ(message_of(pose), "journal.axis_W = [0, 0, 0]: must not be the zero vector");
  pose = PartPose{};
  pose.p_WP.y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(pose), "journal.p_WP = [0, inf, 0]: every component must be finite");
  pose = PartPose{};
  pose.axis_W.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(pose), "journal.axis_W = [nan, 0, 1]: every component must be finite");
}

TEST(BaseCenters, AreHalfALengthAlongTheUnitAxis) {
  // eqs. (3)-(4) with a non-unit axis: only its direction counts. (3, 4, 0)/5 is the unit axis.
  const PartPose pose{Vector3(1.0, 2.0, 3.0), Vector3(3.0, 4.0, 0.0)};
  const BaseCenters bases = base_centers(pose, 10.0);
  constexpr double kTolerance = 8 * std::numeric_limits<double>::epsilon() * 10.0;
  EXPECT_NEAR((bases.p_WA - Vector3(4.0, 6.0, 3.0)).norm(), 0.0, kTolerance);
  EXPECT_NEAR((bases.p_WB - Vector3(-2.0, -2.0, 3.0)).norm(), 0.0, kTolerance);
}

TEST(BaseCenters, TinyAndHugeAxesGiveTheSameCentres) {
  // The unit axis is computed without under- or overflow of |a|^2.
  const PartPose unit{Vector3(0.0, 0.0, 0.0), Vector3(0.0, 0.6, 0.8)};
  const BaseCenters reference = base_centers(unit, 2.0);
  for (double scale : {0x1p-600, 0x1p600}) {
    const BaseCenters scaled = base_centers(PartPose{unit.p_WP, unit.axis_W * scale}, 2.0);
    EXPECT_NEAR((scaled.p_WA - reference.p_WA).norm(), 0.0, 1e-15);
    EXPECT_NEAR((scaled.p_WB - reference.p_WB).norm(), 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace clearjoint::geometry
