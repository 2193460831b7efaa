// SPDX-License-Identifier: BSD-3-Clause
// Tests of detect_contacts: each scenario of Fig. 2 plus none and beyond_model, built from a
// journal tilted in the y-z plane of a bearing on the z axis, where every depth and contact
// point has a closed form (derived below); invariance under rigid motions, flipping the journal
// axis and changes of units; the parallel-axes decision and its tolerance option.

#include "clearjoint/geometry/joint/detect_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "geometry_test_support.hpp"
#include "tilted_journal_scenarios.hpp"

namespace clearjoint::geometry {
namespace {

using testing::bearing_on_z;
using testing::kLongAxialClearance;
using testing::kMisalignedCases;
using testing::kTable2;
using testing::kWideRadialClearance;
using testing::RigidMotion;
using testing::ScenarioCase;
using testing::TiltedJournal;
using testing::random_motion;

// Tolerances, in units of the joint (mm here). Inputs are O(10); each double operation errs by
// ~1e-15 relative. The contact point sits at the middle of certified crossing angles (errors
// ~1e-14 rad, times Rj = 10); depths are differences of O(10) numbers. 1e-11 leaves three orders
// of margin above that and is still ten orders below the clearance 0.1.
constexpr double kLengthTolerance = 1e-11;

/// One expected contact, from the closed forms.
struct ExpectedContact {
  ContactType type;
  ContactBase base;
  double depth;
  Vector3 p_WCj;
  Vector3 p_WCi;
  Vector3 normal_W;
};

std::vector<ExpectedContact> analytic_contacts(const JointDimensions& d, const TiltedJournal& t) {
  const Vector3 axis(0.0, std::sin(t.tilt), std::cos(t.tilt));
  const Vector3 e_perp(0.0, std::cos(t.tilt), -std::sin(t.tilt));
  const Vector3 center(0.0, t.y0, t.z0);
  const Vector3 rim_a = center + 0.5 * d.journal_length * axis;
  const Vector3 rim_b = center - 0.5 * d.journal_length * axis;
  const double half_li = 0.5 * d.bearing_length;
  std::vector<ExpectedContact> out;
  for (const auto& [base, rim] : {std::pair{ContactBase::a, rim_a}, std::pair{ContactBase::b, rim_b}}) {
    const double side = rim.y() >= 0 ? 1.0 : -1.0;
    const double depth = std::abs(rim.y()) + d.journal_radius * std::cos(t.tilt) - d.bearing_radius;
    const Vector3 p_WCj = rim + side * d.journal_radius * e_perp;
    if (depth > 0) {
      out.push_back({ContactType::radial, base, depth, p_WCj,
                     Vector3(0.0, side * d.bearing_radius, p_WCj.z()), Vector3(0.0, side, 0.0)});
    }
  }
  {
    const double depth = rim_a.z() + d.journal_radius * std::sin(t.tilt) - half_li;
    const Vector3 p_WCj = rim_a - d.journal_radius * e_perp;
    if (depth > 0) {
      out.push_back({ContactType::axial, ContactBase::a, depth, p_WCj,
                     Vector3(0.0, p_WCj.y(), half_li), Vector3::UnitZ()});
    }
  }
  {
    const double depth = d.journal_radius * std::sin(t.tilt) - rim_b.z() - half_li;
    const Vector3 p_WCj = rim_b + d.journal_radius * e_perp;
    if (depth > 0) {
      out.push_back({ContactType::axial, ContactBase::b, depth, p_WCj,
                     Vector3(0.0, p_WCj.y(), -half_li), -Vector3::UnitZ()});
    }
  }
  return out;
}

const Contact* find_contact(const JointContacts& result, ContactType type, ContactBase base) {
  for (int k = 0; k < result.contact_count; ++k) {
    if (result.contacts[k].type == type && result.contacts[k].base == base) return &result.contacts[k];
  }
  return nullptr;
}

void expect_near(const Vector3& actual, const Vector3& expected, double tolerance) {
  EXPECT_LE((actual - expected).norm(), tolerance) << "actual " << actual.transpose()
                                                   << ", expected " << expected.transpose();
}

/// The result matches the closed forms contact by contact, and every contact satisfies the
/// stated invariants (p_WCj - p_WCi = depth n; crossings on the surface).
void expect_analytic(const JointContacts& result, const JointDimensions& d, const TiltedJournal& t) {
  const std::vector<ExpectedContact> expected = analytic_contacts(d, t);
  ASSERT_EQ(result.contact_count, int(expected.size()));
  for (const ExpectedContact& e : expected) {
    const Contact* c = find_contact(result, e.type, e.base);
    ASSERT_NE(c, nullptr);
    EXPECT_NEAR(c->depth, e.depth, kLengthTolerance);
    expect_near(c->p_WCj, e.p_WCj, kLengthTolerance);
    expect_near(c->p_WCi, e.p_WCi, kLengthTolerance);
    expect_near(c->normal_W, e.normal_W, kLengthTolerance);
    expect_near(c->p_WCj - c->p_WCi, c->depth * c->normal_W, kLengthTolerance);  // eqs. (22)-(23)
    EXPECT_EQ(c->crossing_count, 2);
    for (int k = 0; k < c->crossing_count; ++k) {
      const Vector3& x = c->crossings[k].point;
      if (e.type == ContactType::radial) {
        EXPECT_NEAR(std::hypot(x.x(), x.y()), d.bearing_radius, kLengthTolerance);
      } else {
        EXPECT_NEAR(std::abs(x.z()), 0.5 * d.bearing_length, kLengthTolerance);
      }
    }
    EXPECT_NE(c->certificate.level, Certainty::uncertain);
  }
  EXPECT_FALSE(result.aligned);
  EXPECT_NE(result.certificate.level, Certainty::uncertain);
}

TEST(DetectContacts, EachMisalignedScenarioMatchesTheClosedForms) {
  for (const ScenarioCase& c : kMisalignedCases) {
    SCOPED_TRACE(c.name);
    const JointContacts result = detect_contacts(c.dimensions, bearing_on_z(), c.journal.pose());
    EXPECT_EQ(result.scenario, c.scenario) << to_string(result.scenario);
    expect_analytic(result, c.dimensions, c.journal);
  }
}

TEST(DetectContacts, ContactsAreListedRadialFirstThenByBase) {
  const JointContacts result =
      detect_contacts(kTable2, bearing_on_z(), TiltedJournal{0.0, 0.0, 0.013}.pose());
  ASSERT_EQ(result.contact_count, 4);
  EXPECT_EQ(result.contacts[0].type, ContactType::radial);
  EXPECT_EQ(result.contacts[0].base, ContactBase::a);
  EXPECT_EQ(result.contacts[1].base, ContactBase::b);
  EXPECT_EQ(result.contacts[2].type, ContactType::axial);
  EXPECT_EQ(result.contacts[2].base, ContactBase::a);
  EXPECT_EQ(result.contacts[3].base, ContactBase::b);
}

// ---- aligned axes: eqs. (6)-(10) ------------------------------------------------------------

TEST(DetectContacts, CentredAlignedJournalHasNoContact) {
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), PartPose{});
  EXPECT_TRUE(result.aligned);
  EXPECT_EQ(result.scenario, ContactScenario::none);
  EXPECT_EQ(result.contact_count, 0);
  EXPECT_NE(result.certificate.level, Certainty::uncertain);
}

TEST(DetectContacts, OffsetAlignedJournalTouchesAlongALine) {
  // (j): eccentricity e = 0.15 > cr = 0.1 along +y; depth e - cr (eqs. 6-8, 23).
  const PartPose journal{Vector3(0.0, 0.15, 0.02), Vector3::UnitZ()};
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), journal);
  EXPECT_TRUE(result.aligned);
  EXPECT_EQ(result.scenario, ContactScenario::line);
  ASSERT_EQ(result.contact_count, 1);
  const Contact& c = result.contacts[0];
  EXPECT_EQ(c.type, ContactType::radial);
  EXPECT_EQ(c.base, ContactBase::mid);
  EXPECT_NEAR(c.depth, 0.05, kLengthTolerance);
  expect_near(c.normal_W, Vector3::UnitY(), kLengthTolerance);
  expect_near(c.p_WCj, Vector3(0.0, 0.15 + 9.9, 0.02), kLengthTolerance);  // eq. (8)
  expect_near(c.p_WCi, Vector3(0.0, 10.0, 0.02), kLengthTolerance);        // eq. (7)
  EXPECT_EQ(c.crossing_count, 0);
  EXPECT_NE(c.certificate.level, Certainty::uncertain);
}

TEST(DetectContacts, AlignedJournalPushedAlongItsAxisTouchesAFace) {
  // (k): the journal's base A at z = 0.13 + 9.9 is 0.03 beyond base A at z = 10 (eqs. 9-10).
  const PartPose journal{Vector3(0.03, 0.04, 0.13), Vector3::UnitZ()};
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), journal);
  EXPECT_EQ(result.scenario, ContactScenario::face);
  ASSERT_EQ(result.contact_count, 1);
  const Contact& c = result.contacts[0];
  EXPECT_EQ(c.type, ContactType::axial);
  EXPECT_EQ(c.base, ContactBase::a);
  EXPECT_NEAR(c.depth, 0.03, kLengthTolerance);
  expect_near(c.normal_W, Vector3::UnitZ(), kLengthTolerance);
  expect_near(c.p_WCj, Vector3(0.03, 0.04, 10.03), kLengthTolerance);  // eq. (10)
  expect_near(c.p_WCi, Vector3(0.03, 0.04, 10.0), kLengthTolerance);   // eq. (9)
}

TEST(DetectContacts, AlignedJournalCanTouchLineAndFaceTogether) {
  // (l): line along +y (depth 0.05) and the face at B (depth 0.03), axis pointing down (-z):
  // labels follow the bearing, so the face contact is still reported at B.
  const PartPose journal{Vector3(0.0, 0.15, -0.13), -Vector3::UnitZ()};
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), journal);
  EXPECT_EQ(result.scenario, ContactScenario::line_and_face);
  const Contact* line = find_contact(result, ContactType::radial, ContactBase::mid);
  const Contact* face = find_contact(result, ContactType::axial, ContactBase::b);
  ASSERT_NE(line, nullptr);
  ASSERT_NE(face, nullptr);
  EXPECT_NEAR(line->depth, 0.05, kLengthTolerance);
  EXPECT_NEAR(face->depth, 0.03, kLengthTolerance);
  expect_near(face->normal_W, -Vector3::UnitZ(), kLengthTolerance);
  expect_near(face->p_WCj, Vector3(0.0, 0.15, -10.03), kLengthTolerance);
}

TEST(DetectContacts, ExactlyParallelNonUnitAxesAreAligned) {
  // eq. (5) is decided on the stored doubles: (1, 3, 7) and (-0.5, -1.5, -3.5) are exactly
  // parallel although neither is unit; one ulp off in one component is not.
  const PartPose bearing{Vector3::Zero(), Vector3(1.0, 3.0, 7.0)};
  PartPose journal{Vector3::Zero(), Vector3(-0.5, -1.5, -3.5)};
  EXPECT_TRUE(detect_contacts(kTable2, bearing, journal).aligned);
  journal.axis_W.z() = std::nextafter(-3.5, 0.0);
  EXPECT_FALSE(detect_contacts(kTable2, bearing, journal).aligned);
}

TEST(DetectContacts, ParallelismOfTinyAxesIsStillDecidedExactly) {
  // Components near 2^-500 are outside the two-product range; the rational fallback decides.
  const PartPose bearing{Vector3::Zero(), 0x1p-500 * Vector3(1.0, 3.0, 7.0)};
  PartPose journal{Vector3::Zero(), Vector3(-0.5, -1.5, -3.5)};
  EXPECT_TRUE(detect_contacts(kTable2, bearing, journal).aligned);
  journal.axis_W.y() = std::nextafter(-1.5, 0.0);
  EXPECT_FALSE(detect_contacts(kTable2, bearing, journal).aligned);
}

TEST(DetectContacts, AngleToleranceTreatsNearlyParallelAxesAsAlignedButUncertain) {
  // Tilt 1e-6 rad with eccentricity 0.15: misaligned, two radial contacts of nearly equal depth
  // (scenario (c)); with a 1e-5 rad tolerance, a line contact of depth 0.05 (eq. 6-8).
  const TiltedJournal nearly{0.15, 0.0, 1e-6};
  const JointContacts exact = detect_contacts(kTable2, bearing_on_z(), nearly.pose());
  EXPECT_FALSE(exact.aligned);
  EXPECT_EQ(exact.scenario, ContactScenario::radial_at_both_bases);
  DetectionOptions options;
  options.parallel_angle_tolerance = 1e-5;
  const JointContacts relaxed = detect_contacts(kTable2, bearing_on_z(), nearly.pose(), options);
  EXPECT_TRUE(relaxed.aligned);
  EXPECT_EQ(relaxed.scenario, ContactScenario::line);
  ASSERT_EQ(relaxed.contact_count, 1);
  EXPECT_NEAR(relaxed.contacts[0].depth, 0.05, kLengthTolerance);
  EXPECT_EQ(relaxed.contacts[0].certificate.level, Certainty::uncertain);
  EXPECT_EQ(relaxed.certificate.level, Certainty::uncertain);
  // A tolerance below the tilt changes nothing.
  options.parallel_angle_tolerance = 1e-7;
  EXPECT_FALSE(detect_contacts(kTable2, bearing_on_z(), nearly.pose(), options).aligned);
}

// ---- beyond the model ---------------------------------------------------------------------------

TEST(DetectContacts, PenetrationDeeperThanTheClearanceIsBeyondTheModel) {
  // Aligned, e = 0.25: line depth 0.15 > cr = 0.1. The contact is still reported.
  const PartPose journal{Vector3(0.0, 0.25, 0.0), Vector3::UnitZ()};
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), journal);
  EXPECT_EQ(result.scenario, ContactScenario::beyond_model);
  EXPECT_EQ(result.certificate.level, Certainty::certified);  // 0.15 is far from 0.1: proved
  ASSERT_EQ(result.contact_count, 1);
  EXPECT_NEAR(result.contacts[0].depth, 0.15, kLengthTolerance);
  // Misaligned: radial depth at A is 0.2 + S(0.005) = 0.149 > cr.
  const TiltedJournal deep{0.2, 0.0, 0.005};
  const JointContacts misaligned = detect_contacts(kTable2, bearing_on_z(), deep.pose());
  EXPECT_EQ(misaligned.scenario, ContactScenario::beyond_model);
  EXPECT_EQ(misaligned.certificate.level, Certainty::certified);
  const Contact* radial = find_contact(misaligned, ContactType::radial, ContactBase::a);
  ASSERT_NE(radial, nullptr);
  EXPECT_NEAR(radial->depth, analytic_contacts(kTable2, deep)[0].depth, kLengthTolerance);
}

TEST(DetectContacts, PutsTheJournalPointAtTheArcMiddleWhenTheArcSweepsAboutHalfTheRim) {
  // Rims far beyond the wall (beyond the model), offset so that their radial arcs sweep from
  // about 0.7 to 1.3 half turns: the middle is found along the chord's midpoint where the chord
  // passes farther than r/4 from the rim centre (sweeps below ~0.84 or above ~1.16 half turns),
  // along the chord's perpendicular nearer to it (journal_contact_point). The closed forms
  // (analytic_contacts) put the middle on the tilt plane for every offset.
  int near_half_turn = 0;
  for (double y0 = 1.0; y0 <= 1.8; y0 += 0.01) {
    const TiltedJournal t{y0, 0.0, 0.001};
    const JointContacts result = detect_contacts(kTable2, bearing_on_z(), t.pose());
    SCOPED_TRACE(y0);
    EXPECT_EQ(result.scenario, ContactScenario::beyond_model);
    expect_analytic(result, kTable2, t);
    for (int k = 0; k < result.contact_count; ++k) {
      const Contact& c = result.contacts[k];
      const Vector3 chord_middle = 0.5 * (c.crossings[0].point + c.crossings[1].point);
      near_half_turn += (chord_middle - Vector3(0.0, y0, chord_middle.z())).head<2>().norm() < 0.25 * kTable2.journal_radius;
    }
  }
  EXPECT_GT(near_half_turn, 10);  // both branches ran
}

TEST(DetectContacts, RimCrossingTheWallFourTimesIsBeyondTheModel) {
  // A short journal (Lj = 2) tilted 0.5 rad, rim A centre at c_y = 1: by the closed form of
  // TiltedJournal, |c_y| cos(tilt) = 0.88 < Rj sin^2(tilt) = 2.27, so f peaks inside
  // s in (-1, 1) at Rj^2 + c_y^2 / sin^2(tilt) = 102.36 > Ri^2, while f(+-1) < Ri^2: the rim
  // leaves the wall on two arcs, mirror images under x -> -x. Rim B (c_y = 0.042) stays inside;
  // both rims stay far from the bases.
  const JointDimensions short_journal{10.0, 20.0, 9.9, 2.0};
  const double tilt = 0.5;
  const TiltedJournal journal{1.0 - std::sin(tilt), 0.0, tilt};
  const JointContacts result = detect_contacts(short_journal, bearing_on_z(), journal.pose());
  EXPECT_EQ(result.scenario, ContactScenario::beyond_model);
  ASSERT_EQ(result.contact_count, 2);
  const Contact& first = result.contacts[0];
  const Contact& second = result.contacts[1];
  for (const Contact* c : {&first, &second}) {
    EXPECT_EQ(c->type, ContactType::radial);
    EXPECT_EQ(c->base, ContactBase::a);
    EXPECT_GT(c->depth, 0.0);
    EXPECT_EQ(c->crossing_count, 2);
    expect_near(c->p_WCj - c->p_WCi, c->depth * c->normal_W, kLengthTolerance);
  }
  // Mirror images: same y, z and depth, opposite x.
  EXPECT_NEAR(first.p_WCj.x(), -second.p_WCj.x(), kLengthTolerance);
  EXPECT_NEAR(first.p_WCj.y(), second.p_WCj.y(), kLengthTolerance);
  EXPECT_NEAR(first.p_WCj.z(), second.p_WCj.z(), kLengthTolerance);
  EXPECT_NEAR(first.depth, second.depth, kLengthTolerance);
}

TEST(DetectContacts, RimEntirelyBeyondABaseIsBeyondTheModelWithItsDeepestPoint) {
  // Table 2, tilt 0.005, z0 = 0.5: rim A spans z in c_z -+ Rj sin(tilt) = [10.35, 10.45], all
  // above base A at z = 10. The contact is the deepest rim point (closed form of TiltedJournal),
  // depth 0.449 > ca; no crossings bound it.
  const TiltedJournal lifted{0.0, 0.5, 0.005};
  const JointContacts result = detect_contacts(kTable2, bearing_on_z(), lifted.pose());
  EXPECT_EQ(result.scenario, ContactScenario::beyond_model);
  const std::vector<ExpectedContact> expected = analytic_contacts(kTable2, lifted);
  ASSERT_EQ(expected.size(), 1u);
  ASSERT_EQ(result.contact_count, 1);
  const Contact& c = result.contacts[0];
  EXPECT_EQ(c.type, ContactType::axial);
  EXPECT_EQ(c.base, ContactBase::a);
  EXPECT_NEAR(c.depth, expected[0].depth, kLengthTolerance);
  expect_near(c.p_WCj, expected[0].p_WCj, kLengthTolerance);
  expect_near(c.p_WCi, expected[0].p_WCi, kLengthTolerance);
  EXPECT_EQ(c.crossing_count, 0);
}

// ---- invariances ---------------------------------------------------------------------------

/// A joint configuration for the invariance tests: every misaligned case above, and the aligned
/// ones ((j), (k), (l), none, beyond the model).
struct JointCase {
  const char* name;
  JointDimensions dimensions;
  PartPose journal;
  ContactScenario scenario;
};

std::vector<JointCase> all_cases() {
  std::vector<JointCase> cases;
  for (const ScenarioCase& c : kMisalignedCases) {
    cases.push_back({c.name, c.dimensions, c.journal.pose(), c.scenario});
  }
  cases.push_back({"aligned none", kTable2, PartPose{Vector3(0.01, 0.02, 0.03), Vector3::UnitZ()},
                   ContactScenario::none});
  cases.push_back({"j", kTable2, PartPose{Vector3(0.0, 0.15, 0.02), Vector3::UnitZ()},
                   ContactScenario::line});
  cases.push_back({"k", kTable2, PartPose{Vector3(0.03, 0.04, 0.13), Vector3::UnitZ()},
                   ContactScenario::face});
  cases.push_back({"l", kTable2, PartPose{Vector3(0.0, 0.15, -0.13), -Vector3::UnitZ()},
                   ContactScenario::line_and_face});
  cases.push_back({"aligned beyond", kTable2, PartPose{Vector3(0.0, 0.25, 0.0), Vector3::UnitZ()},
                   ContactScenario::beyond_model});
  return cases;
}

TEST(DetectContacts, InvarianceCasesHaveTheirScenarios) {
  for (const JointCase& c : all_cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(detect_contacts(c.dimensions, bearing_on_z(), c.journal).scenario, c.scenario);
  }
}

/// Every field of the answer, bit for bit (contacts up to contact_count).
void expect_identical(const JointContacts& a, const JointContacts& b) {
  ASSERT_EQ(a.scenario, b.scenario);
  ASSERT_EQ(a.contact_count, b.contact_count);
  EXPECT_EQ(a.aligned, b.aligned);
  EXPECT_EQ(a.certificate.level, b.certificate.level);
  EXPECT_EQ(a.certificate.reason, b.certificate.reason);
  for (int k = 0; k < a.contact_count; ++k) {
    const Contact& x = a.contacts[k];
    const Contact& y = b.contacts[k];
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.base, y.base);
    EXPECT_EQ(x.p_WCj, y.p_WCj);
    EXPECT_EQ(x.p_WCi, y.p_WCi);
    EXPECT_EQ(x.normal_W, y.normal_W);
    EXPECT_EQ(x.depth, y.depth);
    EXPECT_EQ(x.p_WCj_error, y.p_WCj_error);
    EXPECT_EQ(x.p_WCi_error, y.p_WCi_error);
    EXPECT_EQ(x.depth_error, y.depth_error);
    EXPECT_EQ(x.certificate.level, y.certificate.level);
    EXPECT_EQ(x.certificate.reason, y.certificate.reason);
    ASSERT_EQ(x.crossing_count, y.crossing_count);
    for (int j = 0; j < x.crossing_count; ++j) {
      EXPECT_EQ(x.crossings[j].angle, y.crossings[j].angle);
      EXPECT_EQ(x.crossings[j].angle_error, y.crossings[j].angle_error);
      EXPECT_EQ(x.crossings[j].point, y.crossings[j].point);
      EXPECT_EQ(x.crossings[j].point_error, y.crossings[j].point_error);
      EXPECT_EQ(x.crossings[j].multiplicity, y.crossings[j].multiplicity);
    }
  }
}

TEST(DetectContacts, LeavesAReusedResultUntouchedWhenTheInputIsBad) {
  const std::vector<JointCase> cases = all_cases();
  const JointCase& c = *std::find_if(cases.begin(), cases.end(), [](const JointCase& k) {
    return k.scenario != ContactScenario::none;
  });
  JointContacts reused;
  detect_contacts(c.dimensions, bearing_on_z(), c.journal, reused);
  const int count = reused.contact_count;
  ASSERT_GT(count, 0);
  PartPose bad = c.journal;
  bad.axis_W = Vector3::Zero();
  EXPECT_THROW(detect_contacts(c.dimensions, bearing_on_z(), bad, reused), InvalidInput);
  EXPECT_EQ(reused.contact_count, count);
  EXPECT_EQ(reused.scenario, c.scenario);
}

// ---- (rigid motions etc.) ------------------------------------------------------------------------------

PartPose moved(const RigidMotion& motion, const PartPose& pose) {
  return {motion.point(pose.p_WP), motion.direction(pose.axis_W)};
}

/// Same scenario and, contact by contact, the same contacts up to `map` (points) and `scale`
/// (lengths).
template <class PointMap>
void expect_equivalent(const JointContacts& reference, const JointContacts& other, PointMap map,
                       double length_scale, double tolerance) {
  ASSERT_EQ(other.scenario, reference.scenario);
  ASSERT_EQ(other.contact_count, reference.contact_count);
  EXPECT_EQ(other.aligned, reference.aligned);
  for (int k = 0; k < reference.contact_count; ++k) {
    const Contact& r = reference.contacts[k];
    const Contact& o = other.contacts[k];
    EXPECT_EQ(o.type, r.type);
    EXPECT_EQ(o.base, r.base);
    EXPECT_NEAR(o.depth, r.depth * length_scale, tolerance * length_scale);
    expect_near(o.p_WCj, map(r.p_WCj, 1.0), tolerance * length_scale);
    expect_near(o.p_WCi, map(r.p_WCi, 1.0), tolerance * length_scale);
    expect_near(o.normal_W, map(r.normal_W, 0.0), tolerance);
  }
}

TEST(DetectContacts, WritesIntoAReusedResultExactlyWhatAFreshCallReturns) {
  // The in-place overload leaves contacts past contact_count as they were: cycle through every
  // case (many contacts, none, aligned, beyond the model) twice, into one result, so that each
  // answer is written over a different earlier one. Every field, bit for bit.
  const std::vector<JointCase> cases = all_cases();
  JointContacts reused;
  for (int round = 0; round < 2; ++round) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const JointCase& c = cases[(i * 7 + round) % cases.size()];
      SCOPED_TRACE(c.name);
      const JointContacts fresh = detect_contacts(c.dimensions, bearing_on_z(), c.journal);
      detect_contacts(c.dimensions, bearing_on_z(), c.journal, reused);
      expect_identical(reused, fresh);
    }
  }
}

TEST(DetectContacts, WritesIntoAResultFullOfStaleValuesWhatAFreshCallReturns) {
  // The point contacts are written field by field into the result, not built fresh: every slot
  // filled with values no answer has (two crossings, NaN everywhere, the other type and base)
  // before each call must not show through, beyond-model rims with fewer crossings included.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Contact stale;
  stale.type = ContactType::axial;
  stale.base = ContactBase::mid;
  stale.p_WCj = stale.p_WCi = stale.normal_W = Vector3::Constant(nan);
  stale.depth = nan;
  stale.crossings = {RimCrossing{nan, nan, Vector3::Constant(nan), nan, 7}, RimCrossing{nan, nan, Vector3::Constant(nan), nan, 7}};
  stale.crossing_count = 2;
  stale.certificate = {Certainty::uncertain, CertificateReason::more_than_four_roots};
  stale.p_WCj_error = stale.p_WCi_error = stale.depth_error = nan;
  // Besides the scenario cases: a slightly tilted journal whose rims lie wholly beyond the wall
  // (its centre Ri + Rj + 1 mm off the axis): full penetration arcs, point contacts without
  // crossings.
  std::vector<JointCase> cases = all_cases();
  const double tilt = 1e-3;
  cases.push_back({"rims wholly beyond the wall", kTable2,
                   {Vector3(kTable2.bearing_radius + kTable2.journal_radius + 1e-3, 0.0, 0.0),
                    Vector3(std::sin(tilt), 0.0, std::cos(tilt))},
                   ContactScenario::beyond_model});
  int fewer_crossings = 0;
  for (const JointCase& c : cases) {
    SCOPED_TRACE(c.name);
    JointContacts reused;
    reused.contacts.fill(stale);
    reused.contact_count = kMaxContacts;
    const JointContacts fresh = detect_contacts(c.dimensions, bearing_on_z(), c.journal);
    detect_contacts(c.dimensions, bearing_on_z(), c.journal, reused);
    expect_identical(reused, fresh);
    for (int k = 0; k < fresh.contact_count; ++k) {
      const Contact& contact = fresh.contacts[k];
      if (!fresh.aligned && contact.crossing_count < 2) ++fewer_crossings;
    }
  }
  EXPECT_GT(fewer_crossings, 0);  // misaligned point contacts with fewer than two crossings were seen
}

TEST(DetectContacts, ProvesFreeFlightStraightFromThePosesWithTheGeneralPathsAnswer) {
  // With the angle tolerance 0 the prefilters run straight from the poses (prefilter_if_ready in
  // detect_contacts.cpp); any positive tolerance skips that, and 1e-300 rad aligns nothing that
  // is not exactly parallel. The two answers must agree bit for bit, in free flight and in
  // contact, misaligned and exactly aligned (a quarter of the poses: no tilt, and axis lengths
  // that are powers of two, so that the rotation keeps the axes exactly parallel), for bearings
  // in any pose, journals either way round and axes of any length.
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cr = kTable2.radial_clearance(), ca = kTable2.axial_clearance();
  const double max_tilt = 2.0 * cr / kTable2.journal_length;
  DetectionOptions general_path;
  general_path.parallel_angle_tolerance = 1e-300;
  std::array<int, 2> free_flight{}, in_contact{};  // [aligned]
  for (int i = 0; i < 3000; ++i) {
    const RigidMotion motion = random_motion(rng, i % 2 == 0 ? 0.0 : 1e3);
    const double offset = 1.5 * cr * unit(rng), offset_azimuth = 2 * std::numbers::pi * unit(rng);
    const double shift = 1.5 * ca * (2 * unit(rng) - 1);
    const bool aligned = i % 4 == 0;
    const double tilt = aligned ? 0.0 : max_tilt * (0.001 + unit(rng));
    const double tilt_azimuth = 2 * std::numbers::pi * unit(rng);
    const double exponent = 8 * unit(rng) - 4;
    const double flip = i % 3 == 0 ? -1.0 : 1.0;
    const double axis_length = std::pow(2.0, aligned ? std::floor(exponent) : exponent);
    const PartPose bearing = moved(motion, bearing_on_z());
    const PartPose journal =
        moved(motion, {{offset * std::cos(offset_azimuth), offset * std::sin(offset_azimuth), shift},
                       flip * axis_length *
                           Vector3(std::sin(tilt) * std::cos(tilt_azimuth),
                                   std::sin(tilt) * std::sin(tilt_azimuth), std::cos(tilt))});
    const JointContacts shortcut = detect_contacts(kTable2, bearing, journal);
    const JointContacts general = detect_contacts(kTable2, bearing, journal, general_path);
    SCOPED_TRACE(i);
    expect_identical(shortcut, general);
    EXPECT_EQ(shortcut.aligned, aligned);
    (shortcut.contact_count == 0 ? free_flight : in_contact)[aligned] += 1;
  }
  // Not vacuous: both outcomes are common in this family, aligned or not.
  for (const bool aligned : {false, true}) {
    EXPECT_GT(free_flight[aligned], 100) << aligned;
    EXPECT_GT(in_contact[aligned], 100) << aligned;
  }
}

TEST(DetectContacts, EveryScenarioIsInvariantUnderRigidMotionsOfTheWholeJoint) {
  std::mt19937_64 rng(20170401);
  // Rotating inputs of size ~10 and translations up to 100 perturbs them by ~1e-13; the closed
  // forms move the contact by the same order. 1e-9 leaves margin for the middle of a shallow arc,
  // whose angle is conditioned like 1/sqrt(depth).
  constexpr double kMotionTolerance = 1e-9;
  for (const JointCase& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const JointContacts reference = detect_contacts(c.dimensions, bearing_on_z(), c.journal);
    for (int trial = 0; trial < 8; ++trial) {
      const RigidMotion motion = random_motion(rng, 100.0);
      const JointContacts result = detect_contacts(c.dimensions, moved(motion, bearing_on_z()),
                                                   moved(motion, c.journal));
      expect_equivalent(reference, result,
                        [&](const Vector3& x, double w) {
                          return Vector3(motion.rotation * x + w * motion.translation);
                        },
                        1.0, kMotionTolerance);
    }
  }
}

TEST(DetectContacts, FlippingTheJournalAxisChangesNothing) {
  constexpr double kFlipTolerance = 1e-11;  // only the rim frames' rounding differs
  for (const JointCase& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const PartPose journal = c.journal;
    const PartPose flipped{journal.p_WP, -journal.axis_W};
    const JointContacts reference = detect_contacts(c.dimensions, bearing_on_z(), journal);
    const JointContacts result = detect_contacts(c.dimensions, bearing_on_z(), flipped);
    expect_equivalent(reference, result, [](const Vector3& x, double) { return x; }, 1.0,
                      kFlipTolerance);
  }
}

TEST(DetectContacts, ChangingUnitsScalesLengthsOnly) {
  // mm -> m and mm -> um. Scaling by a non-power of 2 rounds every input once (relative 1e-16).
  constexpr double kUnitTolerance = 1e-10;
  for (const double factor : {1e-3, 1e3}) {
    for (const JointCase& c : all_cases()) {
      SCOPED_TRACE(c.name);
      const JointDimensions d = c.dimensions;
      const JointDimensions scaled{d.bearing_radius * factor, d.bearing_length * factor,
                                   d.journal_radius * factor, d.journal_length * factor};
      const PartPose journal = c.journal;
      const JointContacts reference = detect_contacts(d, bearing_on_z(), journal);
      const JointContacts result =
          detect_contacts(scaled, bearing_on_z(), PartPose{journal.p_WP * factor, journal.axis_W});
      expect_equivalent(reference, result,
                        [&](const Vector3& x, double w) { return Vector3(w == 0.0 ? x : x * factor); },
                        factor, kUnitTolerance);
    }
  }
}

// ---- options and validation ---------------------------------------------------------------------

TEST(DetectContacts, SwitchingCertificatesOffGivesTheSameContactsMarkedUncertain) {
  // Every case of every scenario, with and without certificates: the same scenario, contacts,
  // points, normals and depths (both compute them in double from the same formulas; the
  // certified path only adds the bounds and decisions around them), every answer uncertain.
  constexpr double kSameComputation = 0.0;
  DetectionOptions options;
  options.intersection.certify = false;
  int compared = 0;
  for (const JointCase& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const JointContacts certified = detect_contacts(c.dimensions, bearing_on_z(), c.journal);
    if (certified.certificate.level == Certainty::uncertain) continue;  // nothing proved to compare
    const JointContacts unchecked = detect_contacts(c.dimensions, bearing_on_z(), c.journal, options);
    EXPECT_EQ(unchecked.certificate.level, Certainty::uncertain);
    for (int k = 0; k < unchecked.contact_count; ++k) {
      EXPECT_EQ(unchecked.contacts[k].certificate.level, Certainty::uncertain) << k;
    }
    expect_equivalent(certified, unchecked, [](const Vector3& x, double) { return x; }, 1.0, kSameComputation);
    ++compared;
  }
  EXPECT_EQ(compared, static_cast<int>(all_cases().size()));  // every case is certified (17 measured)
  const TiltedJournal journal{0.0, 0.0, 0.013};  // (i)
  EXPECT_EQ(detect_contacts(kTable2, bearing_on_z(), journal.pose(), options).scenario, ContactScenario::all_four);
}

TEST(DetectContacts, BadInputsAreRejectedWithTheirNames) {
  PartPose zero_axis;
  zero_axis.axis_W = Vector3::Zero();
  EXPECT_THROW(detect_contacts(kTable2, zero_axis, PartPose{}), InvalidInput);
  try {
    detect_contacts(kTable2, PartPose{}, zero_axis);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(std::string(error.what()), "journal.axis_W = [0, 0, 0]: must not be the zero vector");
  }
  const JointDimensions inverted{9.9, 20.0, 10.0, 19.8};
  EXPECT_THROW(detect_contacts(inverted, PartPose{}, PartPose{}), InvalidInput);
  DetectionOptions options;
  options.parallel_angle_tolerance = -1.0;
  EXPECT_THROW(detect_contacts(kTable2, PartPose{}, PartPose{}, options), InvalidInput);
}

/// P_j,z for a journal on the bearing's axis whose rim A centre P_j,z + Lj/2 rounds to exactly
/// `plane` while the exact sum lies beyond it (direction +1) or short of it (-1): found by walking
/// ulps from plane - Lj/2, with Knuth's two-sum telling the sign of the rounding.
std::optional<double> journal_centre_rounding_onto(double plane, double half_length, int direction) {
  double z = plane - half_length;
  for (int step = 0; step < 4096; ++step) {
    const double sum = z + half_length;
    const double z_part = sum - half_length;
    const double rounding = (z - z_part) + (half_length - (sum - z_part));  // exact sum - sum
    if (sum == plane && (rounding > 0 ? 1 : rounding < 0 ? -1 : 0) == direction) return z;
    z = std::nextafter(z, direction > 0 ? 1.0 : -1.0);
  }
  return std::nullopt;
}

TEST(DetectContacts, DecidesAFaceTouchForTheExactRimCentreNotForItsRounding) {
  // Base plane A at Li/2; the journal's rim A centre rounds onto it. Decided on the rounded
  // centre the rim would lie in the plane (no face contact); the exact centre is a fraction of
  // an ulp beyond it (face contact) or short of it (none), and the answer must follow it.
  const double plane = 0.5 * kTable2.bearing_length;
  const double half = 0.5 * kTable2.journal_length;
  for (const int direction : {+1, -1}) {
    SCOPED_TRACE(direction);
    const std::optional<double> z = journal_centre_rounding_onto(plane, half, direction);
    ASSERT_TRUE(z.has_value());
    const JointContacts answer =
        detect_contacts(kTable2, bearing_on_z(), PartPose{Vector3(0.0, 0.0, *z), Vector3::UnitZ()});
    EXPECT_TRUE(answer.aligned);
    EXPECT_NE(answer.certificate.level, Certainty::uncertain);
    if (direction > 0) {
      EXPECT_EQ(answer.scenario, ContactScenario::face);
      ASSERT_EQ(answer.contact_count, 1);
      EXPECT_EQ(answer.contacts[0].base, ContactBase::a);
      // Only the exact tier can tell: the rounded centre lies in the plane.
      EXPECT_EQ(answer.contacts[0].certificate.level, Certainty::exact);
    } else {
      EXPECT_EQ(answer.scenario, ContactScenario::none);
      EXPECT_EQ(answer.contact_count, 0);
    }
  }
}

// Found by fuzzing `clearjoint detect`: the base and rim centres (eqs. 3-4) were rounded in world
// coordinates, so 1e13 m from the origin (an ulp of 2 mm, twenty clearances) a centred, slightly
// tilted journal came back as scenario (d). Detection now works relative to the bearing centre.
TEST(DetectContacts, GivesTheSameAnswerForAJointFarFromTheOrigin) {
  const Vector3 tilted_axis(0.0, 0.005, 1.0);
  const JointContacts at_origin =
      detect_contacts(kTable2, PartPose{Vector3::Zero(), Vector3::UnitZ()},
                      PartPose{Vector3::Zero(), tilted_axis});
  ASSERT_EQ(at_origin.scenario, ContactScenario::none);
  for (const double far : {1e9, 1e13, -1e15}) {
    const Vector3 centre(far, far, far);  // both parts share it exactly
    const JointContacts moved = detect_contacts(kTable2, PartPose{centre, Vector3::UnitZ()},
                                                PartPose{centre, tilted_axis});
    EXPECT_EQ(moved.scenario, at_origin.scenario) << far;
    EXPECT_EQ(moved.contact_count, 0) << far;
  }
}

// The aligned journal's eccentricity (eq. 6) is the part of its offset square to the axis. Far
// along a diagonal axis, an offset whose two components are one ulp (2^-33) apart has
// e = 2^-33 / sqrt(2), eight clearances, yet the rounded cross products of off_axis can cancel to
// exactly 0 (on about a third of these poses). The kernel proves the line on the exact joint, and
// the contact must be listed (it was dropped, leaving a certified "none"), with a unit normal square
// to the axis and a depth whose bound covers the exact depth. The exact depth, 7.2 clearances, is
// beyond the model; the label follows the rounded depth, whose bound (~7e-9) spans the clearance
// here: either label is consistent with it, and the answer's certificate says that it is not
// proved (beyond_model_undecided) while the contact's own certificate stays certified.
TEST(DetectContacts, ListsTheLineContactWhereRoundingLosesTheWholeEccentricityAsUncertain) {
  // The kernel proves the line on the exact joint, but rounding the offset far along the axis
  // loses its direction: the points have no bound. The contact was `certified` with null point
  // bounds (the command line printed "certificate": "exact" beside "point_bearing_error": null);
  // a certificate covers every number of its contact, so this one is uncertain and says why.
  const JointDimensions joint{
      .bearing_radius = 1e-3, .bearing_length = 4e6, .journal_radius = 1e-3 - 1e-11, .journal_length = 1e5};
  const Vector3 diagonal(1.0, 1.0, 0.0);
  const PartPose bearing{Vector3::Zero(), diagonal};
  for (int k = 0; k < 200; ++k) {
    const double x = 1e6 + 0.37 * k;
    const double y = std::nextafter(x, 2e6);
    const JointContacts result = detect_contacts(joint, bearing, PartPose{Vector3(x, y, 0.0), diagonal});
    ASSERT_TRUE(result.aligned);
    EXPECT_TRUE(result.scenario == ContactScenario::line || result.scenario == ContactScenario::beyond_model)
        << "pose " << k << ": " << to_string(result.scenario);
    ASSERT_EQ(result.contact_count, 1) << "pose " << k;
    EXPECT_EQ(result.certificate.level, Certainty::uncertain);
    const Contact& c = result.contacts[0];
    EXPECT_EQ(c.base, ContactBase::mid);
    EXPECT_EQ(c.certificate.level, Certainty::uncertain);
    EXPECT_EQ(c.certificate.reason, CertificateReason::contact_not_representable_in_world);
    EXPECT_EQ(c.p_WCj_error, kNoErrorBound);
    EXPECT_EQ(c.p_WCi_error, kNoErrorBound);
    EXPECT_EQ(c.depth_error, kNoErrorBound);
    EXPECT_NEAR(c.normal_W.norm(), 1.0, 1e-15);
    EXPECT_NEAR(c.normal_W.dot(diagonal), 0.0, 1e-15);
  }
}

TEST(DetectContacts, BoundsTheDepthOfARimBeyondItsBaseAllRoundTightly) {
  // Beyond the model, an axial contact's point is the rim's deepest point; its depth had the
  // trivial bound of any rim point, the rim's diameter (19.8 mm for Table 2): certified, but
  // vacuous. The closed form of tilted_journal_scenarios.hpp: depth z0 + T at base A.
  for (const double z0 : {0.3, 0.5, 2.0}) {
    for (const double tilt : {0.001, 0.005, 0.05}) {
      const TiltedJournal journal{0.0, z0, tilt};
      const JointContacts result = detect_contacts(kTable2, bearing_on_z(), journal.pose());
      ASSERT_EQ(result.scenario, ContactScenario::beyond_model) << z0 << " " << tilt;
      const auto axial = std::find_if(result.contacts.begin(), result.contacts.begin() + result.contact_count,
                                      [](const Contact& c) { return c.type == ContactType::axial; });
      ASSERT_NE(axial, result.contacts.begin() + result.contact_count);
      ASSERT_NE(axial->certificate.level, Certainty::uncertain);
      const double T = 0.5 * kTable2.journal_length * std::cos(tilt) + kTable2.journal_radius * std::sin(tilt) -
                       0.5 * kTable2.bearing_length;
      EXPECT_LE(std::fabs(axial->depth - (z0 + T)), axial->depth_error) << z0 << " " << tilt;
      // Some 1e-13 mm measured at tilt 0.001; a millionth of the clearance is far from vacuous.
      EXPECT_LT(axial->depth_error, 1e-6 * kTable2.axial_clearance()) << z0 << " " << tilt;
      EXPECT_LT(axial->p_WCj_error, 1e-6 * kTable2.axial_clearance()) << z0 << " " << tilt;
    }
  }
}

TEST(DetectContacts, GivesEveryCertifiedContactFiniteBounds) {
  // The documented contract: a contact that is exact or certified has finite bounds on its points
  // and depth, over every case and under rigid motions far from the origin.
  int checked = 0;
  for (const JointCase& c : all_cases()) {
    for (const double far : {0.0, 1e3, 1e6, 1e9}) {
      const Vector3 shift(far, -0.5 * far, 0.25 * far);
      const JointContacts result =
          detect_contacts(c.dimensions, PartPose{shift, Vector3::UnitZ()}, PartPose{c.journal.p_WP + shift, c.journal.axis_W});
      for (int i = 0; i < result.contact_count; ++i) {
        const Contact& contact = result.contacts[i];
        if (contact.certificate.level == Certainty::uncertain) continue;
        ++checked;
        EXPECT_TRUE(std::isfinite(contact.p_WCj_error) && std::isfinite(contact.p_WCi_error) &&
                    std::isfinite(contact.depth_error))
            << c.name << " at " << far;
      }
    }
  }
  EXPECT_GT(checked, 40);
}

// From the detection suite's extreme family (cr/Ri = 1e-6): a rim just past a bearing base, its
// two crossings so close that their enclosures are wide. The depth bound through the contact
// point was 1.25e-4 m, ten thousand clearances, so the beyond-model label could not be proved and
// the answer was uncertain; the kernel's own enclosure of the deepest reach gives 2e-11 m.
TEST(DetectContacts, BoundsTheDepthOfAnAxialContactNearATangencyByTheDeepestReach) {
  const JointDimensions joint{.bearing_radius = 0x1.47ae147ae147bp-7,
                              .bearing_length = 0x1.47ae147ae147bp-6,
                              .journal_radius = 0x1.47adff0152658p-7,
                              .journal_length = 0x1.47adff0152658p-6};
  const PartPose bearing{Vector3(-0x1.35aefbaaa87efp-3, -0x1.67ba9ddff9698p-6, -0x1.63b79b14aab3p-6),
                         Vector3(0x1.37778ce8607d1p-2, 0x1.e0bbe38c5ce95p-1, -0x1.4981f5dfd3018p-3)};
  const PartPose journal{Vector3(-0x1.35aefb9a2d224p-3, -0x1.67ba9a1d6be45p-6, -0x1.63b79c694e74ep-6),
                         Vector3(0x1.377779e874fb6p-2, 0x1.e0bbea448281dp-1, -0x1.4981a0dc9d9abp-3)};
  const JointContacts result = detect_contacts(joint, bearing, journal);
  EXPECT_EQ(result.scenario, ContactScenario::single_axial);
  EXPECT_NE(result.certificate.level, Certainty::uncertain) << result.certificate.reason_text();
  ASSERT_EQ(result.contact_count, 1);
  const Contact& c = result.contacts[0];
  EXPECT_EQ(c.type, ContactType::axial);
  EXPECT_LT(c.depth_error, 0.01 * joint.axial_clearance());
  EXPECT_LT(c.depth + c.depth_error, joint.axial_clearance());  // within the model, proved
}

TEST(DetectContacts, RefusesJointsWhoseLengthsLieOutsideTheAcceptedRange) {
  // Found by fuzzing `clearjoint detect` (SIGFPE inside GMP, minutes in the exact tier) and the
  // library with magnitudes 1e-300..1e300: bounds that overflowed under a
  // certified contact, and exact tiers that ran for seconds on 27,000-bit coefficients. Such
  // joints lie outside [kSmallestAcceptedLength, kLargestAcceptedLength] and are refused
  // (test_detect_contacts_scaling.cpp sweeps the range itself).
  struct Joint {
    JointDimensions dimensions;
    PartPose bearing, journal;
  };
  const Joint joints[] = {
      {{1e-300, 1.575384515905611e-151, 9.900000000000001e-301, 7.876922579528056e-152},
       {{-2.0687103341290957e+82, 5.919393313130888e-129, -7.95690373977745e+45},
        {2.8671301291721063e+113, 1e-300, 6.330020853250564e+115}},
       {{-4.6608518798052456e+125, 8.630725688781501e-41, -9.714339045571734e+131},
        {-7.088122218224904e+147, -4.022925612848003e+93, 1e-300}}},
      {{1.7e+308, 5813.066039239765, 8.5e+307, 5754.935378847367},
       {{-4408673.018689724, -0.08610969950031569, 0.0026643831445110422},
        {401161.5775188713, 43735964.99146108, 382966.3675463995}},
       {{643800.211523991, 47957.74228088685, 5.246818470893499e-07},
        {-9.245901800796875e-06, 0.0009331053976989397, 0.00787128668568102}}},
      // Found by a fuzz of the library (magnitudes 1e-300..1e300): the crossings' error bounds
      // overflowed in the translation back to the world frame (|x|^2 beyond 1e308) under a
      // `certified` contact; the exact tier ran for 22 s and 6 s on 27,000-bit coefficients.
      {{0x1.5c52cd97971d7p+303, 0x1.5c52cd97971d7p+304, 0x1.58d71856130b4p+303, 0x1.58d71856130b4p+304},
       {{-0x1.224963074da6dp+904, 0x1.7f98576aa2a97p-912, 0x1.e4dad6fb932e1p+275},
        {0x1.2fcfddbb974ccp-2, -0x1.6fa5d6b930ce8p-3, 0x0p+0}},
       {{-0x1.224963074da6dp+904, -0x1.dda297d2b0f16p+295, -0x1.69cfad7c4f334p+296},
        {0x1.306f302d919e5p-2, -0x1.706f300130c74p-3, 0x1.5a58b85abf575p-12}}},
      {{0x1.787a8a5d99cbbp-259, 0x1.787a8a5d99cbbp-258, 0x1.74b6c14d4e049p-259, 0x1.74b6c14d4e049p-258},
       {{0x1.a13099b2fe71p-3, -0x1.8287f98be9da8p-1, 0x1.7b09c3841caecp+800},
        {-0x1.9e6c90d0343f6p+862, -0x1.9f807d1a32113p+553, 0x1.cf5606c827a1bp-252}},
       {{0x1.a13099b2fe71p-3, -0x1.8287f98be9da8p-1, 0x1.7b09c3841caecp+800},
        {-0x1.9e6c90d0343f6p+862, -0x1.72b051ba1ba0cp+947, 0x1.5763c246ef2fep-11}}},
      {{0x1.135974fd1b99fp+133, 0x1.135974fd1b99fp+134, 0x1.10988ffa93a53p+133, 0x1.10988ffa93a53p+134},
       {{0x1.1cedadc30fab2p-1, 0x1.f38526804cac4p-985, -0x1.f4e27afb65da6p-2},
        {0x1.247a388377ec2p-911, 0x0p+0, 0x1.dc377949cd1p-1}},
       {{0x1.d66fc0f858cd8p-1, -0x1.07aa7df2fdfcp-3, -0x1.6dc4a5f61acb8p-1},
        {0x1.247a388377ec2p-911, 0x1.2c3beed9ea90fp+879, 0x1.dc00a4e2b230ap-1}}},
  };
  for (const Joint& joint : joints) {
    EXPECT_THROW(detect_contacts(joint.dimensions, joint.bearing, joint.journal), InvalidInput);
  }
}

}  // namespace
}  // namespace clearjoint::geometry
