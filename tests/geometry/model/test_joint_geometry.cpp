// SPDX-License-Identifier: BSD-3-Clause
// Tests of joint_geometry: dimensions and clearances (eqs. 1-2), validation, base centres
// (eqs. 3-4).

#include "clearjoint/geometry/model/joint_geometry.hpp"

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
  EXPECT_EQ(message_of(d), "dimensions.journal_radius = 10: must be smaller than bearing_radius = 10 "
                           "(the radial clearance Ri - Rj, eq. 1, must be positive)");
  d = kTable2;
  d.journal_length = 25.0;
  EXPECT_EQ(message_of(d), "dimensions.journal_length = 25: must be smaller than bearing_length = 20 "
                           "(the axial clearance (Li - Lj)/2, eq. 2, must be positive)");
}

TEST(JointDimensions, FieldsAreNamedInTheCallersTerms) {
  JointDimensions d = kTable2;
  d.journal_radius = 10.0;
  try {
    validate(d, "forces[2]", kPartDimensionNames);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field_path(), "forces[2].journal.radius");
    EXPECT_STREQ(e.what(), "forces[2].journal.radius = 10: must be smaller than bearing.radius = 10 "
                           "(the radial clearance Ri - Rj, eq. 1, must be positive)");
  }
  d = kTable2;
  d.bearing_length = -0.0099;
  try {
    validate(d, "", kPartDimensionNames);  // a description with the parts at its top level
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field_path(), "bearing.length");
    // The value as written, not its 17 significant digits (-0.0099000000000000008).
    EXPECT_STREQ(e.what(), "bearing.length = -0.0099: must be positive");
  }
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

TEST(PartPose, FieldsAreNamedInTheCallersTerms) {
  PartPose pose;
  pose.axis_W = Vector3::Zero();
  try {
    validate(pose, "bearing", kPartPoseNames);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field_path(), "bearing.axis");
    EXPECT_STREQ(e.what(), "bearing.axis = [0, 0, 0]: must not be the zero vector");
  }
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

TEST(UnitAxis, IsTheAxisOverItsLengthWithinAnUlpOfEachComponent) {
  // a / |a| in long double (64-bit significand) rounded once to double against unit_axis: the
  // library's a / sqrt(a . a) rounds three times (a . a, sqrt, the division), each half an ulp of
  // its result, so the two differ by at most 2 ulps of a component of magnitude <= 1.
  constexpr double kTwoUlpsOfOne = 2 * std::numeric_limits<double>::epsilon();
  const Vector3 axes[] = {Vector3(3, 4, 0),          Vector3(1, 2, 2),        Vector3(-0.3, 1e-3, 7.1),
                          Vector3(1e-5, -2e-5, 4e-6), Vector3(123.0, 456.0, -789.0)};
  for (const Vector3& a : axes) {
    const Vector3 u = unit_axis(PartPose{Vector3::Zero(), a});
    const long double length = std::sqrt(static_cast<long double>(a.x()) * a.x() +
                                         static_cast<long double>(a.y()) * a.y() +
                                         static_cast<long double>(a.z()) * a.z());
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(u[i], static_cast<double>(a[i] / length), kTwoUlpsOfOne) << a.transpose();
    }
  }
  // Exact cases: a coordinate axis of any length gives the unit coordinate axis exactly.
  EXPECT_EQ(unit_axis(PartPose{Vector3::Zero(), Vector3(0, 0, 7)}), Vector3(0, 0, 1));
  EXPECT_EQ(unit_axis(PartPose{Vector3::Zero(), Vector3(-0.25, 0, 0)}), Vector3(-1, 0, 0));
}

TEST(UnitAxis, NormalisesAxesWhoseSquaredLengthWouldUnderOrOverflowInDouble) {
  // Beyond |a|^2 in [2^-1000, 2^1000] unit_axis rescales before normalising (unit_axis_range.hpp).
  // The reference b / |b| of the axis b as stored (a subnormal b has lost bits of a: the
  // reference is taken of b, not of a) in long double, whose exponent range holds |b|^2 for every
  // double b. Rescaling by a power of two is exact; the normalisation then rounds as above.
  constexpr double kTwoUlpsOfOne = 2 * std::numeric_limits<double>::epsilon();
  const Vector3 a(0.36, -0.48, 0.8);
  for (const double scale : {0x1p-1060, 0x1p-520, 0x1p-490, 0x1p490, 0x1p520, 0x1p1000}) {
    const Vector3 b = a * scale;
    const Vector3 u = unit_axis(PartPose{Vector3::Zero(), b});
    const long double length = std::sqrt(static_cast<long double>(b.x()) * b.x() +
                                         static_cast<long double>(b.y()) * b.y() +
                                         static_cast<long double>(b.z()) * b.z());
    ASSERT_GT(length, 0.0L) << scale;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(u[i], static_cast<double>(b[i] / length), kTwoUlpsOfOne) << scale;
    }
  }
}

TEST(BaseCenters, FromAGivenUnitAxisArePlusAndMinusHalfTheLengthAlongIt) {
  // The three-argument form uses the axis as given (the caller has normalised it): with (0, 0, 2)
  // the centres are a length, not half a length, from P. Products and sums of small integers:
  // exact.
  const BaseCenters doubled = base_centers(Vector3(1, 2, 3), Vector3(0, 0, 2), 1.0);
  EXPECT_EQ(doubled.p_WA, Vector3(1, 2, 4));
  EXPECT_EQ(doubled.p_WB, Vector3(1, 2, 2));
  const BaseCenters table2 = base_centers(Vector3(0.5, -1, 0), Vector3(0, 1, 0), 19.8);
  EXPECT_EQ(table2.p_WA, Vector3(0.5, 8.9, 0));   // -1 + 9.9, rounded once
  EXPECT_EQ(table2.p_WB, Vector3(0.5, -10.9, 0));
  // And the two-argument form is the three-argument one at unit_axis(pose), bit for bit.
  for (const PartPose& pose : {PartPose{Vector3(1, 2, 3), Vector3(3, 4, 0)},
                               PartPose{Vector3(-7, 0.1, 2), Vector3(1, 2, 2)}}) {
    const BaseCenters two = base_centers(pose, 19.8);
    const BaseCenters three = base_centers(pose.p_WP, unit_axis(pose), 19.8);
    EXPECT_EQ(two.p_WA, three.p_WA);
    EXPECT_EQ(two.p_WB, three.p_WB);
  }
}

}  // namespace
}  // namespace clearjoint::geometry
