// SPDX-License-Identifier: BSD-3-Clause
// Tests of the detection suite's MPFR reference (joint_reference.hpp): closed forms of a journal
// tilted in the y-z plane of a bearing on the z axis (the construction of
// tests/geometry/joint/test_detect_contacts.cpp, here evaluated in MPFR on the exact unit axis),
// the aligned formulas, a rim crossing the wall four times, and agreement with the independent
// test reference (support/testing) on joints whose centres are doubles.

#include "joint_reference.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "input_families.hpp"
#include "multiprecision_reference.hpp"
#include "tilted_journal_scenarios.hpp"

namespace clearjoint::bench {
namespace {

using geometry::ContactBase;
using geometry::ContactScenario;
using geometry::ContactType;
using geometry::JointDimensions;
using geometry::PartPose;
using geometry::Vector3;
using geometry::testing::bearing_on_z;
using geometry::testing::kMisalignedCases;
using geometry::testing::kTable2;
using geometry::testing::misaligned_case;
using geometry::testing::ScenarioCase;
using geometry::testing::TiltedJournal;

// The reference refines roots to 1e-90 (in tan of the half angle) at 1e-120 working precision;
// depths and points from the arc middle then agree with a closed form to far better than this
// (relative to the joint's size, 10 mm).
const Real kAgreement("1e-80");

/// Closed-form depths (tilted_journal_scenarios.hpp derives them): with the unit axis
/// (0, s, c) = a/|a| taken exactly and rim centres c_X = P +- (Lj/2)(0, s, c), a rim with
/// |c_y| c >= Rj s^2 reaches |c_y| + Rj c from the axis (radial depth |c_y| + Rj c - Ri), and
/// heights c_z -+ Rj s (axial depths c_zA + Rj s - Li/2 at A, Rj s - c_zB - Li/2 at B).
struct ClosedForm {
  Real radial[2], axial[2];
};
ClosedForm closed_form(const JointDimensions& d, const TiltedJournal& t) {
  const PartPose pose = t.pose();
  const RealVector axis = normalized(to_real(pose.axis_W));
  const Real& s = axis[1];
  const Real& c = axis[2];
  const Real half = Real(d.journal_length) / 2;
  const Real rim_y[2] = {Real(t.y0) + half * s, Real(t.y0) - half * s};
  const Real rim_z[2] = {Real(t.z0) + half * c, Real(t.z0) - half * c};
  ClosedForm f;
  for (int k = 0; k < 2; ++k) f.radial[k] = abs(rim_y[k]) + Real(d.journal_radius) * c - Real(d.bearing_radius);
  f.axial[0] = rim_z[0] + Real(d.journal_radius) * s - Real(d.bearing_length) / 2;
  f.axial[1] = Real(d.journal_radius) * s - rim_z[1] - Real(d.bearing_length) / 2;
  return f;
}

const ReferenceContact* find(const ReferenceAnswer& answer, ContactType type, ContactBase base) {
  for (const ReferenceContact& c : answer.contacts) {
    if (c.type == type && c.base == base) return &c;
  }
  return nullptr;
}


TEST(JointReference, EachMisalignedScenarioHasTheClosedFormDepths) {
  // The closed forms offset the centres along the exact unit axis.
  for (const ScenarioCase& c : kMisalignedCases) {
    SCOPED_TRACE(c.name);
    const ReferenceAnswer answer =
        reference_detect(joint_with_exact_unit_axes(c.dimensions, bearing_on_z(), c.journal.pose()));
    ASSERT_TRUE(answer.decided) << answer.why;
    EXPECT_EQ(answer.scenario, c.scenario);
    EXPECT_FALSE(answer.aligned);
    const ClosedForm f = closed_form(c.dimensions, c.journal);
    for (int k = 0; k < 2; ++k) {
      const ContactBase base = k == 0 ? ContactBase::a : ContactBase::b;
      const ReferenceContact* radial = find(answer, ContactType::radial, base);
      ASSERT_EQ(radial != nullptr, f.radial[k] > 0);
      if (radial) {
        EXPECT_LT(abs(radial->depth - f.radial[k]), kAgreement);
        EXPECT_EQ(radial->crossings.size(), 2u);
      }
      const ReferenceContact* axial = find(answer, ContactType::axial, base);
      ASSERT_EQ(axial != nullptr, f.axial[k] > 0);
      if (axial) {
        EXPECT_LT(abs(axial->depth - f.axial[k]), kAgreement);
        EXPECT_EQ(axial->crossings.size(), 2u);
      }
    }
  }
}

TEST(JointReference, ContactPointsSatisfyTheDepthAndNormalRelation) {
  // eqs. (22)-(23): p_WCj - p_WCi = depth * normal, and the bearing point lies on its surface.
  const ScenarioCase& c = misaligned_case("i");  // all four contacts
  const ReferenceAnswer answer = reference_detect(joint_as_given(c.dimensions, bearing_on_z(), c.journal.pose()));
  ASSERT_EQ(answer.contacts.size(), 4u);
  for (const ReferenceContact& contact : answer.contacts) {
    const RealVector gap = sub(sub(contact.p_WCj, contact.p_WCi), scale(contact.depth, contact.normal_W));
    EXPECT_LT(norm(gap), kAgreement);
    if (contact.type == ContactType::radial) {
      EXPECT_LT(abs(sqrt(contact.p_WCi[0] * contact.p_WCi[0] + contact.p_WCi[1] * contact.p_WCi[1]) - 10), kAgreement);
    } else {
      EXPECT_LT(abs(abs(contact.p_WCi[2]) - 10), kAgreement);
    }
  }
}

TEST(JointReference, AlignedJournalsFollowTheLineAndFaceFormulas) {
  // (j): eccentricity 0.15 > cr: line depth 0.05 (eqs. 6-8); (k): journal base 0.03 beyond base A;
  // (l): both, the axis pointing down (labels follow the bearing: the face is at B).
  const ReferenceAnswer line =
      reference_detect(joint_as_given(kTable2, bearing_on_z(), {Vector3(0.0, 0.15, 0.02), Vector3::UnitZ()}));
  EXPECT_TRUE(line.aligned);
  EXPECT_EQ(line.scenario, ContactScenario::line);
  ASSERT_EQ(line.contacts.size(), 1u);
  EXPECT_LT(abs(line.contacts[0].depth - (Real("0.15") - (Real(10) - Real(9.9)))), Real("1e-17"));
  const ReferenceAnswer face =
      reference_detect(joint_as_given(kTable2, bearing_on_z(), {Vector3(0.03, 0.04, 0.13), Vector3::UnitZ()}));
  EXPECT_EQ(face.scenario, ContactScenario::face);
  ASSERT_EQ(face.contacts.size(), 1u);
  EXPECT_EQ(face.contacts[0].base, ContactBase::a);
  // beyond = z0 + Lj/2 - Li/2 on the stored doubles.
  EXPECT_EQ(face.contacts[0].depth, Real(0.13) + Real(9.9) - Real(10));
  const ReferenceAnswer both =
      reference_detect(joint_as_given(kTable2, bearing_on_z(), {Vector3(0.0, 0.15, -0.13), -Vector3::UnitZ()}));
  EXPECT_EQ(both.scenario, ContactScenario::line_and_face);
  ASSERT_NE(find(both, ContactType::axial, ContactBase::b), nullptr);
}

TEST(JointReference, ExactlyTouchingFaceIsNoContact) {
  // Table 2 in micrometres (integers): the journal base exactly in the bearing base plane
  // (beyond = 100 + 9900 - 10000 = 0). A contact needs penetration; one ulp further is one.
  const JointDimensions micrometres{10000.0, 20000.0, 9900.0, 19800.0};
  const ReferenceAnswer touching =
      reference_detect(joint_as_given(micrometres, bearing_on_z(), {Vector3(0.0, 0.0, 100.0), Vector3::UnitZ()}));
  ASSERT_TRUE(touching.decided);
  EXPECT_EQ(touching.scenario, ContactScenario::none);
  const ReferenceAnswer pressed = reference_detect(joint_as_given(
      micrometres, bearing_on_z(), {Vector3(0.0, 0.0, std::nextafter(100.0, 200.0)), Vector3::UnitZ()}));
  EXPECT_EQ(pressed.scenario, ContactScenario::face);
}

TEST(JointReference, RimCrossingTheWallFourTimesIsBeyondTheModelWithTwoContacts) {
  // test_detect_contacts.cpp's construction: Lj = 2, tilt 0.5, rim A centre at c_y = 1.
  const JointDimensions short_journal{10.0, 20.0, 9.9, 2.0};
  const TiltedJournal journal{1.0 - std::sin(0.5), 0.0, 0.5};
  const ReferenceAnswer answer = reference_detect(joint_as_given(short_journal, bearing_on_z(), journal.pose()));
  ASSERT_TRUE(answer.decided) << answer.why;
  EXPECT_EQ(answer.scenario, ContactScenario::beyond_model);
  ASSERT_EQ(answer.contacts.size(), 2u);
  for (const ReferenceContact& c : answer.contacts) {
    EXPECT_EQ(c.type, ContactType::radial);
    EXPECT_EQ(c.base, ContactBase::a);
    EXPECT_EQ(c.crossings.size(), 2u);
  }
  // Mirror images under x -> -x.
  EXPECT_LT(abs(answer.contacts[0].p_WCj[0] + answer.contacts[1].p_WCj[0]), kAgreement);
  EXPECT_LT(abs(answer.contacts[0].depth - answer.contacts[1].depth), kAgreement);
}

TEST(JointReference, RadialMarginOfAParallelRimIsEccentricityMinusClearance) {
  const ReferenceJoint joint = joint_as_given(kTable2, bearing_on_z(), {Vector3(0.06, 0.08, 0.0), Vector3::UnitZ()});
  const RadialMargin margin = radial_margin(joint, ContactBase::a);
  ASSERT_TRUE(margin.decided);
  // e = |(0.06, 0.08)| in exact arithmetic on the doubles; cr = 10 - 9.9 on the doubles.
  const Real e = sqrt(Real(0.06) * Real(0.06) + Real(0.08) * Real(0.08));
  EXPECT_LT(abs(margin.margin - (e - (Real(10) - Real(9.9)))), kAgreement);
  EXPECT_LT(abs(axial_margin(joint, ContactBase::a) - (Real(9.9) - Real(10))), kAgreement);
}

TEST(JointReference, ExactlyNormalisedAxesMoveOnlyTheCentres) {
  const PartPose bearing{Vector3(0.1, -0.2, 0.3), Vector3(0.3, -0.2, 0.93)};
  const PartPose journal{Vector3(0.1, -0.2, 0.3), Vector3(0.31, -0.2, 0.93)};
  const ReferenceJoint given = joint_as_given(kTable2, bearing, journal);
  const ReferenceJoint rounded = joint_with_exact_unit_axes(kTable2, bearing, journal);
  for (int k = 0; k < 2; ++k) {
    // The library's unit axis is a/|a| rounded to double: the centres it offsets differ from
    // those along the exact a/|a| by a few ulps, and do differ.
    const Real shift = norm(sub(given.journal_rim[static_cast<std::size_t>(k)], rounded.journal_rim[static_cast<std::size_t>(k)]));
    EXPECT_GT(shift, 0);
    EXPECT_LT(shift, Real("1e-14"));
  }
  EXPECT_EQ(norm(sub(given.p_WPi, rounded.p_WPi)), 0);
  EXPECT_EQ(norm(sub(given.journal_axis_hat, rounded.journal_axis_hat)), 0);
}

/// The test reference refines its roots to test::reference::kRootWidth in tan(half angle), i.e.
/// within 2 kRootWidth radians: its crossing points are within 2 kRootWidth Rj of the true ones
/// (this reference's are far closer). Twice that is the agreement expected on a rim of radius Rj.
Real crossing_agreement(double journal_radius) {
  return 4 * Real(test::reference::kRootWidth) * Real(journal_radius);
}

/// The joint with its centres rounded to double as detect_contacts computes them (in its frame
/// centred on the bearing: P_j - P_i, then +- (L/2) a_hat), so that the test reference, which
/// takes rims with double centres, can decide the same rims.
ReferenceJoint joint_with_double_centres(const geometry::JointDimensions& dimensions, const PartPose& bearing,
                                         const PartPose& journal) {
  ReferenceJoint joint = joint_as_given(dimensions, bearing, journal);
  const PartPose local_bearing{Vector3::Zero(), bearing.axis_W};
  const PartPose local_journal{journal.p_WP - bearing.p_WP, journal.axis_W};
  const geometry::BaseCenters bearing_bases = geometry::base_centers(local_bearing, dimensions.bearing_length);
  const geometry::BaseCenters journal_bases = geometry::base_centers(local_journal, dimensions.journal_length);
  const RealVector origin = to_real(bearing.p_WP);
  auto world = [&origin](const Vector3& local) {
    const RealVector l = to_real(local);
    return RealVector{origin[0] + l[0], origin[1] + l[1], origin[2] + l[2]};
  };
  const bool same_direction = bearing.axis_W.dot(journal.axis_W) >= 0.0;
  joint.bearing_base = {world(bearing_bases.p_WA), world(bearing_bases.p_WB)};
  joint.journal_rim = same_direction
                          ? std::array<RealVector, 2>{world(journal_bases.p_WA), world(journal_bases.p_WB)}
                          : std::array<RealVector, 2>{world(journal_bases.p_WB), world(journal_bases.p_WA)};
  return joint;
}

/// A Real of the test reference (150 digits) in this reference's type.
Real from_test_reference(const test::reference::Real& x) { return Real(x.str(kReferenceDigits10 + 10)); }

TEST(JointReference, AgreesWithTheTestReferenceOnTheCrossingsOfRoundedRims) {
  // The independent reference of support/testing takes rims with double centres: the
  // joint with its centres rounded as detect_contacts rounds them, in its frame centred on the
  // bearing (the rounded centres are doubles there). Both must find the same crossings of each
  // rim with the wall.
  const std::vector<DetectionInput> inputs = generate_family("realistic", SuiteSize::quick);
  int compared = 0;
  for (const DetectionInput& input : inputs) {
    SCOPED_TRACE(input.id);
    const ReferenceJoint joint = joint_with_double_centres(input.dimensions, input.bearing, input.journal);
    const ReferenceAnswer answer = reference_detect(joint);
    ASSERT_TRUE(answer.decided);
    if (answer.aligned) continue;
    for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
      const std::size_t k = base == ContactBase::a ? 0 : 1;
      const RealVector origin = to_real(input.bearing.p_WP);
      const RealVector local_centre = sub(joint.journal_rim[k], origin);
      const geometry::Circle3 rim{to_double(local_centre), input.journal.axis_W, input.dimensions.journal_radius};
      ASSERT_EQ(to_real(rim.center), local_centre);  // the rounded centre is a double in that frame
      const geometry::Cylinder3 wall{geometry::Vector3::Zero(), input.bearing.axis_W, input.dimensions.bearing_radius};
      const test::reference::CylinderReference other = test::reference::reference_circle_cylinder(rim, wall);
      ASSERT_FALSE(other.ambiguous) << other.why;
      std::vector<RealVector> ours;
      for (const ReferenceContact& c : answer.contacts) {
        if (c.type == ContactType::radial && c.base == base) ours.insert(ours.end(), c.crossings.begin(), c.crossings.end());
      }
      ASSERT_EQ(ours.size(), other.roots.size());
      for (const test::reference::ReferenceRoot& root : other.roots) {
        const RealVector point{origin[0] + from_test_reference(root.point[0]),
                               origin[1] + from_test_reference(root.point[1]),
                               origin[2] + from_test_reference(root.point[2])};
        Real nearest = -1;
        for (const RealVector& x : ours) {
          const Real d = norm(sub(x, point));
          if (nearest < 0 || d < nearest) nearest = d;
        }
        EXPECT_LT(nearest, crossing_agreement(input.dimensions.journal_radius));
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 50);  // the quick realistic family has well over 50 crossings
}

}  // namespace
}  // namespace clearjoint::bench
