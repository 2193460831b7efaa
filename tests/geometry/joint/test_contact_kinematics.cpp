// SPDX-License-Identifier: BSD-3-Clause
// Tests of contact_kinematics (eqs. 24-26): material-point velocities against finite differences
// of rigidly moved points, the approach speed against finite differences of the detected depth,
// and the face contact point (a material point of the journal) against its own finite difference.

#include "clearjoint/geometry/joint/contact_kinematics.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace clearjoint::geometry {
namespace {

// Table 2 of the paper, in millimetres.
const JointDimensions kTable2{10.0, 20.0, 9.9, 19.8};

// Central differences with step h err by (h^2/6) times the third time derivative, plus rounding
// ~1e-14 / h (positions O(10) mm, depths O(0.1) mm). For the depth the third derivative is large:
// the deepest rim point turns around the rim at about |w_j - w_i| / tilt ~ 1 / 0.005 = 200 rad/s,
// giving ~1e5 mm/s^3 (measured: the error scales as h^2, 2.6e-4 at h = 1e-4). At h = 1e-6 the
// truncation is ~3e-8 and the rounding ~1e-8, below the tolerance 1e-7 on speeds of O(10) mm/s.
constexpr double kStep = 1e-6;
constexpr double kFiniteDifferenceTolerance = 1e-7;

/// Where a body's point `p_W` (given at time 0) is at time t under the body's motion: the mass
/// centre moves with v, the body turns about it with constant omega.
Vector3 moved_point(const BodyMotion& body, const Vector3& p_W, double t) {
  const double speed = body.w_W.norm();
  const Eigen::Matrix3d rotation =
      speed > 0 ? Eigen::AngleAxisd(speed * t, body.w_W / speed).toRotationMatrix()
                : Eigen::Matrix3d::Identity();
  return body.p_WM + t * body.v_WM + rotation * (p_W - body.p_WM);
}

Vector3 moved_direction(const BodyMotion& body, const Vector3& d_W, double t) {
  return moved_point(body, body.p_WM + d_W, t) - moved_point(body, body.p_WM, t);
}

PartPose moved_pose(const BodyMotion& body, const PartPose& pose, double t) {
  return {moved_point(body, pose.p_WP, t), moved_direction(body, pose.axis_W, t)};
}

const BodyMotion kBearingMotion{Vector3(0.3, -0.2, 1.0), Vector3(0.4, -0.1, 0.25),
                                Vector3(0.2, 0.5, -0.3)};
const BodyMotion kJournalMotion{Vector3(-0.4, 0.6, 2.0), Vector3(-0.3, 0.7, 0.1),
                                Vector3(-0.6, 0.1, 0.9)};

// Scenario (e) of test_detect_contacts: radial and axial at base A, mirror-symmetric about the
// y-z plane, so each journal point is its rim's deepest point.
const PartPose kBearing{Vector3::Zero(), Vector3::UnitZ()};
const PartPose kJournal{Vector3(0.0, 0.08, 0.08), Vector3(0.0, std::sin(0.005), std::cos(0.005))};

TEST(ContactKinematics, MaterialPointVelocitiesMatchFiniteDifferencesOfMovedPoints) {
  const JointContacts contacts = detect_contacts(kTable2, kBearing, kJournal);
  ASSERT_EQ(contacts.scenario, ContactScenario::radial_and_axial_same_base);
  for (int k = 0; k < contacts.contact_count; ++k) {
    const Contact& c = contacts.contacts[k];
    const ContactKinematics kinematics = contact_kinematics(c, kBearingMotion, kJournalMotion);
    const Vector3 fd_i = (moved_point(kBearingMotion, c.p_WCi, kStep) -
                          moved_point(kBearingMotion, c.p_WCi, -kStep)) / (2 * kStep);
    const Vector3 fd_j = (moved_point(kJournalMotion, c.p_WCj, kStep) -
                          moved_point(kJournalMotion, c.p_WCj, -kStep)) / (2 * kStep);
    EXPECT_LE((kinematics.v_WCi - fd_i).norm(), kFiniteDifferenceTolerance);  // eq. (25)
    EXPECT_LE((kinematics.v_WCj - fd_j).norm(), kFiniteDifferenceTolerance);
  }
}

TEST(ContactKinematics, ApproachSpeedIsTheRateOfChangeOfTheDetectedDepth) {
  // The journal point is the deepest rim point, so (envelope theorem) the depth's rate is the
  // relative normal velocity of the two material points, eq. (24), both bodies moving.
  const JointContacts now = detect_contacts(kTable2, kBearing, kJournal);
  const JointContacts later = detect_contacts(kTable2, moved_pose(kBearingMotion, kBearing, kStep),
                                              moved_pose(kJournalMotion, kJournal, kStep));
  const JointContacts earlier =
      detect_contacts(kTable2, moved_pose(kBearingMotion, kBearing, -kStep),
                      moved_pose(kJournalMotion, kJournal, -kStep));
  ASSERT_EQ(later.contact_count, now.contact_count);
  ASSERT_EQ(earlier.contact_count, now.contact_count);
  ASSERT_EQ(now.contact_count, 2);
  for (int k = 0; k < now.contact_count; ++k) {
    ASSERT_EQ(later.contacts[k].type, now.contacts[k].type);
    const double fd = (later.contacts[k].depth - earlier.contacts[k].depth) / (2 * kStep);
    const ContactKinematics kinematics =
        contact_kinematics(now.contacts[k], kBearingMotion, kJournalMotion);
    EXPECT_NEAR(kinematics.approach_speed, fd, kFiniteDifferenceTolerance) << "contact " << k;
    EXPECT_GT(std::abs(fd), 1e-3) << "the motion should change the depth noticeably";
  }
}

TEST(ContactKinematics, TangentialVelocityIsTheRestOfTheRelativeVelocity) {
  const JointContacts contacts = detect_contacts(kTable2, kBearing, kJournal);
  for (int k = 0; k < contacts.contact_count; ++k) {
    const Contact& c = contacts.contacts[k];
    const ContactKinematics kinematics = contact_kinematics(c, kBearingMotion, kJournalMotion);
    // eq. (26): v_T is normal-free and completes the relative velocity. Rounding of O(1) speeds.
    constexpr double kRounding = 1e-14;
    EXPECT_NEAR(kinematics.tangential_velocity_W.dot(c.normal_W), 0.0, kRounding);
    const Vector3 relative = kinematics.v_WCj - kinematics.v_WCi;
    EXPECT_LE((kinematics.tangential_velocity_W + kinematics.approach_speed * c.normal_W - relative)
                  .norm(),
              kRounding);
  }
}

TEST(ContactKinematics, FaceContactPointMovesWithTheJournal) {
  // (k): the journal's contact point is its base centre (eq. 10), a material point. Translating
  // and spinning the journal about its own axis keeps the axes exactly parallel (z), so the
  // detected point's finite difference is its material velocity, eq. (25).
  const PartPose journal{Vector3(0.03, 0.04, 0.13), Vector3::UnitZ()};
  const BodyMotion spinning{Vector3(0.03, 0.04, 0.13), Vector3(0.2, -0.1, 0.3),
                            Vector3(0.0, 0.0, 2.0)};
  const BodyMotion fixed{};
  const JointContacts now = detect_contacts(kTable2, kBearing, journal);
  ASSERT_EQ(now.scenario, ContactScenario::face);
  const JointContacts later = detect_contacts(kTable2, kBearing, moved_pose(spinning, journal, kStep));
  const JointContacts earlier =
      detect_contacts(kTable2, kBearing, moved_pose(spinning, journal, -kStep));
  ASSERT_EQ(later.scenario, ContactScenario::face);
  ASSERT_EQ(earlier.scenario, ContactScenario::face);
  const Vector3 fd = (later.contacts[0].p_WCj - earlier.contacts[0].p_WCj) / (2 * kStep);
  const ContactKinematics kinematics = contact_kinematics(now.contacts[0], fixed, spinning);
  EXPECT_LE((kinematics.v_WCj - fd).norm(), kFiniteDifferenceTolerance);
  // Moving up at 0.3 pushes the face deeper: positive approach speed, depth rate 0.3.
  EXPECT_NEAR(kinematics.approach_speed, 0.3, 1e-15);
  const double depth_rate = (later.contacts[0].depth - earlier.contacts[0].depth) / (2 * kStep);
  EXPECT_NEAR(kinematics.approach_speed, depth_rate, kFiniteDifferenceTolerance);
}

TEST(ContactKinematics, BodiesAtRestHaveNoContactVelocity) {
  const JointContacts contacts = detect_contacts(kTable2, kBearing, kJournal);
  const ContactKinematics kinematics =
      contact_kinematics(contacts.contacts[0], BodyMotion{}, BodyMotion{});
  EXPECT_EQ(kinematics.approach_speed, 0.0);
  EXPECT_EQ(kinematics.tangential_velocity_W, Vector3::Zero());
}

}  // namespace
}  // namespace clearjoint::geometry
