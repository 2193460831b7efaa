// SPDX-License-Identifier: BSD-3-Clause
// Tests of bench/geometry/detection_poses.{hpp,cpp}: the poses both detection benchmarks time.

#include "detection_poses.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;

/// Draw tolerance: the generator scales uniform draws by the bounds and rounds a few times.
constexpr double kRoundingSlack = 1e-12;

TEST(DetectionPoses, KeepsOnlyPosesWithTheWantedOutcome) {
  for (const Outcome wanted : {Outcome::in_contact, Outcome::free_flight}) {
    const auto poses = journals(wanted == Outcome::in_contact ? 1 : 2, kMaxTilt, wanted);
    ASSERT_EQ(poses.size(), kInputCount);
    for (const geo::PartPose& journal : poses) {
      const bool contact = geo::detect_contacts(kTable2, kBearing, journal).contact_count > 0;
      ASSERT_EQ(contact, wanted == Outcome::in_contact);
    }
  }
}

TEST(DetectionPoses, DrawsCentresAndTiltsWithinTheDocumentedRanges) {
  const double cr = kTable2.radial_clearance(), ca = kTable2.axial_clearance();
  for (const geo::PartPose& journal : journals(1, kMaxTilt, Outcome::in_contact)) {
    EXPECT_LE(std::hypot(journal.p_WP.x(), journal.p_WP.y()), 1.5 * cr * (1 + kRoundingSlack));
    EXPECT_LE(std::fabs(journal.p_WP.z()), 1.5 * ca * (1 + kRoundingSlack));
    EXPECT_NEAR(journal.axis_W.norm(), 1.0, kRoundingSlack);
    EXPECT_LE(std::acos(std::fmin(journal.axis_W.z(), 1.0)), kMaxTilt * (1 + kRoundingSlack) + kRoundingSlack);
  }
}

TEST(DetectionPoses, GivesTheSamePosesForTheSameStreamAndOthersForAnother) {
  const auto first = journals(3, 0.0, Outcome::in_contact);
  const auto again = journals(3, 0.0, Outcome::in_contact);
  const auto other = journals(5, 0.0, Outcome::in_contact);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    ASSERT_EQ(first[i].p_WP, again[i].p_WP);
    ASSERT_EQ(first[i].axis_W, again[i].axis_W);
  }
  EXPECT_NE(first[0].p_WP, other[0].p_WP);
}

TEST(DetectionPoses, KeepsTheJournalAlignedWhenNoTiltIsAllowed) {
  for (const geo::PartPose& journal : journals(3, 0.0, Outcome::in_contact)) {
    ASSERT_EQ(journal.axis_W, geo::Vector3::UnitZ());
  }
}

}  // namespace
}  // namespace clearjoint::bench
