// SPDX-License-Identifier: BSD-3-Clause
// Tests of the scoring (accuracy_scoring.hpp): each kind of failure is counted where it happens
// and nowhere else, enclosures are checked on proved crossings only, and the percentiles are
// nearest-rank.

#include "accuracy_scoring.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {
namespace {

using geometry::Certainty;
using geometry::ContactBase;
using geometry::ContactScenario;
using geometry::ContactType;
using geometry::JointContacts;
using geometry::JointDimensions;
using geometry::PartPose;
using geometry::Vector3;

// Table 2 in millimetres; a journal tilted 0.005 and offset 0.08 along y: scenario (a), one radial
// contact at A with two crossings.
const JointDimensions kTable2{10.0, 20.0, 9.9, 19.8};
const PartPose kBearing{Vector3::Zero(), Vector3::UnitZ()};
const PartPose kJournal{Vector3(0.0, 0.08, 0.0), Vector3(0.0, std::sin(0.005), std::cos(0.005))};

ReferenceAnswer reference() { return reference_detect(joint_as_given(kTable2, kBearing, kJournal)); }
JointContacts certified_answer() { return geometry::detect_contacts(kTable2, kBearing, kJournal); }

TEST(AccuracyScoring, CertifiedAnswerOfAnEasyInputHasNoFailure) {
  const InputScore score = score_answer(certified_answer(), reference());
  EXPECT_FALSE(score.failed());
  EXPECT_EQ(score.level, Certainty::certified);
  EXPECT_EQ(score.point_m.size(), 1u);
  EXPECT_EQ(score.crossing_m.size(), 2u);
  EXPECT_EQ(score.enclosures_checked, 2);
  EXPECT_LT(score.point_m[0], 1e-13);  // mm; double precision on coordinates ~10
}

TEST(AccuracyScoring, AnEmptyAnswerMissesTheContactAndNamesTheWrongScenario) {
  JointContacts empty;
  const InputScore score = score_answer(empty, reference());
  EXPECT_TRUE(score.wrong_scenario);
  EXPECT_EQ(score.missed, 1);
  EXPECT_EQ(score.spurious, 0);
  EXPECT_TRUE(score.failed());
}

TEST(AccuracyScoring, AnExtraContactIsSpurious) {
  JointContacts answer = certified_answer();
  geometry::Contact extra;
  extra.type = ContactType::axial;
  extra.base = ContactBase::b;
  answer.contacts[static_cast<std::size_t>(answer.contact_count++)] = extra;
  const InputScore score = score_answer(answer, reference());
  EXPECT_FALSE(score.wrong_scenario);  // the scenario field was left at (a)
  EXPECT_EQ(score.spurious, 1);
  EXPECT_EQ(score.missed, 0);
}

TEST(AccuracyScoring, ACrossingOutsideItsProvedEnclosureIsCounted) {
  JointContacts answer = certified_answer();
  geometry::RimCrossing& crossing = answer.contacts[0].crossings[0];
  crossing.point += Vector3(0.0, 0.0, 10.0 * crossing.point_error + 1e-12);
  const InputScore score = score_answer(answer, reference());
  EXPECT_EQ(score.enclosures_checked, 2);
  EXPECT_EQ(score.enclosures_missed, 1);
  EXPECT_TRUE(score.failed());
}

TEST(AccuracyScoring, TheSameErrorInAnUncertainContactBreaksNoPromise) {
  JointContacts answer = certified_answer();
  geometry::RimCrossing& crossing = answer.contacts[0].crossings[0];
  crossing.point += Vector3(0.0, 0.0, 10.0 * crossing.point_error + 1e-12);
  answer.contacts[0].certificate = {Certainty::uncertain, geometry::CertificateReason::certificate_switched_off};
  const InputScore score = score_answer(answer, reference());
  EXPECT_EQ(score.enclosures_checked, 0);
  EXPECT_EQ(score.enclosures_missed, 0);
  EXPECT_FALSE(score.failed());
  EXPECT_GT(score.crossing_m.size(), 0u);  // the error is still measured
}

TEST(AccuracyScoring, SummariesUseNearestRankPercentiles) {
  std::vector<double> values;
  for (int i = 1; i <= 200; ++i) values.push_back(i);
  const Summary s = summarize(values);
  EXPECT_EQ(s.count, 200u);
  EXPECT_EQ(s.median, 100.0);
  EXPECT_EQ(s.p99, 198.0);
  EXPECT_EQ(s.max, 200.0);
  EXPECT_TRUE(std::isnan(summarize({}).median));
}

TEST(AccuracyScoring, TallyCountsWrongScenariosWithinTheModelApart) {
  InputScore wrong;
  wrong.wrong_scenario = true;
  Tally tally;
  tally.add(wrong, ContactScenario::beyond_model);
  tally.add(wrong, ContactScenario::single_radial);
  tally.add(InputScore{}, ContactScenario::none);
  tally.add_undecided();
  EXPECT_EQ(tally.inputs, 4u);
  EXPECT_EQ(tally.wrong_scenarios, 2u);
  EXPECT_EQ(tally.wrong_scenarios_within_model, 1u);
  EXPECT_EQ(tally.reference_beyond_model, 1u);
  EXPECT_EQ(tally.failed_inputs, 2u);
  EXPECT_EQ(tally.reference_undecided, 1u);
}

}  // namespace
}  // namespace clearjoint::bench
