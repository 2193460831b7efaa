// SPDX-License-Identifier: BSD-3-Clause
// detect_contacts over 100,000 random joints: every answer has the properties of
// joint_properties.hpp (an A/B swap, a reversed journal axis, a power-of-two change of units and
// a random rigid motion give the same scenario and the transformed contacts). The long run of
// 1e7 joints is bench/geometry/joint_properties_run.cpp.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "joint_properties.hpp"

namespace clearjoint::geometry {
namespace {

namespace props = properties;

constexpr long kJoints = 100'000;

TEST(JointProperties, HoldForOneHundredThousandRandomJoints) {
  std::mt19937_64 rng(20170401);  // fixed: a failure names its joint index and replays
  std::uniform_int_distribution<int> unit_exponent(-40, 40);
  std::array<long, static_cast<int>(ContactScenario::beyond_model) + 1> scenarios{};
  long violations = 0;
  for (long i = 0; i < kJoints; ++i) {
    const props::Joint joint = props::random_joint(rng);
    const Eigen::Isometry3d motion = props::random_motion(rng, 100.0 * props::joint_size(joint));
    const std::string violation = props::check_properties(joint, motion, unit_exponent(rng));
    if (!violation.empty() && ++violations <= 10) ADD_FAILURE() << "joint " << i << ": " << violation;
    scenarios[static_cast<std::size_t>(
        detect_contacts(joint.dimensions, joint.bearing, joint.journal).scenario)] += 1;
  }
  EXPECT_EQ(violations, 0);
  // Not vacuous: free flight, every misaligned scenario (a)-(i), the aligned line contact (j)
  // and beyond-the-model answers all occur hundreds of times.
  for (const ContactScenario s :
       {ContactScenario::none, ContactScenario::single_radial, ContactScenario::single_axial,
        ContactScenario::radial_at_both_bases, ContactScenario::radial_and_axial_same_base,
        ContactScenario::line, ContactScenario::beyond_model}) {
    EXPECT_GT(scenarios[static_cast<std::size_t>(s)], 100) << to_string(s);
  }
}

// Joints on which fuzz_detect_raw (fuzz/) found an answer breaking the properties: each is
// checked with the unit change the fuzzer used, then for what was wrong.

/// A journal whose centre lies on the bearing axis 6.4e5 bearing lengths beyond it, tilted 45
/// degrees: each rim is mirror-symmetric about the plane of the axes (to 1e-63), so its two wall
/// crossings share their coordinate along the rim frame's first axis and the exact tier must tell
/// them apart by the sign of the second.
const props::Joint kSymmetricRimFarAlongTheAxis{
    {0.0099960493296384813, 0.02, 0.0098999999999356079, 0.019800000000000002},
    {{0, 0, 0}, {0, 0, 1.625000000003638}},
    {{0, 0, -638320.63889005606}, {-5.876301149817338e-28, 2.4173705217460969e+35, 2.4173705217460969e+35}}};

/// Five contacts with coordinates around 1e5: the exact tier decides the rims, two of whose
/// crossings lie 7e-15 apart along the rim frame's first axis.
const props::Joint kFiveContactsFarFromTheOrigin{
    {0.0099999999999998944, 0.02, 0.0099000000000000008, 0.0034515625000000002},
    {{-131100, -0.19999999999999862, 1}, {1, 0, 0}},
    {{0.5, -0.19999999999999832, 1.0000800004656614}, {3.2305717468261719e-05, 0, 0.0049999999912720573}}};

/// Lengths of 1e32 beside radii of 1e-2: in the bearing-centred frame the journal's rims round onto
/// the bearing axis.
constexpr double kFar = -9.2392341159222657e+32;
const props::Joint kRimsRoundedOntoTheAxis{
    {0.01, 1.0384593717069655e+32, 0.0099000000000000008, 0.019800000000000002},
    {{kFar, kFar, kFar}, {kFar, kFar, kFar}},
    {{0, 0, 0}, {0, 0, 0.012999999999999999}}};

/// Every length ~7e-38 (normal doubles): the bearing centre is within 1e-12 of the origin.
constexpr double kTiny = 7.1175030496847524e-38;
const props::Joint kTinyJoint{
    {7.1175030496847586e-38, 7.1175030496852869e-38, kTiny, kTiny},
    {{7.1175029270711367e-38, kTiny, kTiny}, {5.4072740308728683e-37, kTiny, kTiny}},
    {{kTiny, kTiny, kTiny}, {7.1175038691008998e-38, kTiny, kTiny}}};

TEST(JointProperties, HoldForTheJointsOnWhichTheFuzzerFoundThemBroken) {
  EXPECT_EQ(props::check_properties(kSymmetricRimFarAlongTheAxis, std::nullopt, 0), "");
  EXPECT_EQ(props::check_properties(kFiveContactsFarFromTheOrigin, std::nullopt, 0), "");
  EXPECT_EQ(props::check_properties(kRimsRoundedOntoTheAxis, std::nullopt, -54), "");
  EXPECT_EQ(props::check_properties(kTinyJoint, std::nullopt, -59), "");
}

/// The joint scaled by 2^exponent, exactly (every length stays a normal double).
props::Joint scaled(const props::Joint& j, int exponent) {
  const double f = std::ldexp(1.0, exponent);
  props::Joint out = j;
  out.dimensions = {j.dimensions.bearing_radius * f, j.dimensions.bearing_length * f, j.dimensions.journal_radius * f,
                    j.dimensions.journal_length * f};
  out.bearing.p_WP = j.bearing.p_WP * f;
  out.journal.p_WP = j.journal.p_WP * f;
  return out;
}

TEST(JointProperties, PlaceTheContactsOfATinyJointInTheWorldFrameAtEveryScale) {
  // The same joint at lengths ~6 and at lengths 2^-200 to 2^60 times that: the contact points
  // scale with it (within their bounds), so the translation back to the world frame happened.
  const props::Joint unit = scaled(kTinyJoint, 126);
  const JointContacts reference = detect_contacts(unit.dimensions, unit.bearing, unit.journal);
  ASSERT_EQ(reference.contact_count, 4);
  for (const int exponent : {-200, -126, -60, -1, 60}) {
    const props::Joint j = scaled(unit, exponent);
    const JointContacts answer = detect_contacts(j.dimensions, j.bearing, j.journal);
    ASSERT_EQ(answer.contact_count, reference.contact_count) << "2^" << exponent;
    const double f = std::ldexp(1.0, exponent);
    for (int i = 0; i < answer.contact_count; ++i) {
      const Contact &c = answer.contacts[i], &r = reference.contacts[i];
      EXPECT_LE((c.p_WCj / f - r.p_WCj).norm(), c.p_WCj_error / f + r.p_WCj_error) << "2^" << exponent << " contact " << i;
      EXPECT_LE((c.p_WCi / f - r.p_WCi).norm(), c.p_WCi_error / f + r.p_WCi_error) << "2^" << exponent << " contact " << i;
    }
  }
}

TEST(JointProperties, PutTheDeepestPointOfASymmetricRimAtTheMiddleOfItsArc) {
  const props::Joint& j = kSymmetricRimFarAlongTheAxis;
  const JointContacts answer = detect_contacts(j.dimensions, j.bearing, j.journal);
  // The journal centre is on the axis and the rim centres (L/2)/sqrt(2) off it; the rim point
  // farthest from the axis, the arc's middle by symmetry, lies Rj/sqrt(2) farther.
  const double expected_depth =
      (0.5 * j.dimensions.journal_length + j.dimensions.journal_radius) / std::sqrt(2.0) - j.dimensions.bearing_radius;
  int radial = 0;
  for (int i = 0; i < answer.contact_count; ++i) {
    const Contact& c = answer.contacts[i];
    if (c.type != ContactType::radial) continue;
    ++radial;
    EXPECT_NE(c.certificate.level, Certainty::uncertain);
    EXPECT_LT(c.depth_error, 1e-6);
    EXPECT_NEAR(c.depth, expected_depth, c.depth_error + 1e-15);
  }
  EXPECT_EQ(radial, 2);
}

TEST(JointProperties, GiveMirrorImageContactsTheSameDepthFarFromTheOrigin) {
  const props::Joint& j = kFiveContactsFarFromTheOrigin;
  const JointContacts answer = detect_contacts(j.dimensions, j.bearing, j.journal);
  ASSERT_EQ(answer.contact_count, 5);
  // Radial contacts 0, 1 (rim A) and 2, 3 (rim B) are mirror images across the plane y = -0.2,
  // up to the inputs' last bits.
  for (const int first : {0, 2}) {
    const Contact &c = answer.contacts[first], &mirror = answer.contacts[first + 1];
    ASSERT_EQ(c.type, ContactType::radial);
    ASSERT_EQ(mirror.type, ContactType::radial);
    EXPECT_GT(c.depth, 0.0);
    EXPECT_LT(mirror.depth_error, 1e-6);
    EXPECT_NEAR(mirror.depth, c.depth, c.depth_error + mirror.depth_error);
  }
}

TEST(JointProperties, GiveUnitNormalsWhereTheRimsRoundOntoTheAxis) {
  const props::Joint& j = kRimsRoundedOntoTheAxis;
  const JointContacts answer = detect_contacts(j.dimensions, j.bearing, j.journal);
  ASSERT_GT(answer.contact_count, 0);
  for (int i = 0; i < answer.contact_count; ++i) {
    const Contact& c = answer.contacts[i];
    EXPECT_TRUE(c.normal_W.allFinite() && c.p_WCi.allFinite() && c.p_WCj.allFinite()) << "contact " << i;
    EXPECT_NEAR(c.normal_W.norm(), 1.0, 1e-15) << "contact " << i;
    // Square to the bearing axis for radial contacts.
    if (c.type == ContactType::radial) {
      EXPECT_NEAR(c.normal_W.dot(Vector3(1, 1, 1).normalized()), 0.0, 1e-15);
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry
