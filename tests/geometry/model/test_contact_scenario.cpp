// SPDX-License-Identifier: BSD-3-Clause
// Tests of contact_scenario: Fig. 2's names and the rule that picks one from the contacts.

#include "clearjoint/geometry/model/contact_scenario.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

namespace clearjoint::geometry {
namespace {

ContactPresence misaligned(bool radial_a, bool radial_b, bool axial_a, bool axial_b) {
  ContactPresence p;
  p.radial_at_a = radial_a;
  p.radial_at_b = radial_b;
  p.axial_at_a = axial_a;
  p.axial_at_b = axial_b;
  return p;
}

ContactPresence aligned(bool line, bool face_a, bool face_b) {
  ContactPresence p;
  p.aligned = true;
  p.line = line;
  p.axial_at_a = face_a;
  p.axial_at_b = face_b;
  return p;
}

TEST(ClassifyScenario, NamesEveryMisalignedPatternOfFigureTwo) {
  using S = ContactScenario;
  EXPECT_EQ(classify_scenario(misaligned(false, false, false, false)), S::none);
  EXPECT_EQ(classify_scenario(misaligned(true, false, false, false)), S::single_radial);
  EXPECT_EQ(classify_scenario(misaligned(false, true, false, false)), S::single_radial);
  EXPECT_EQ(classify_scenario(misaligned(false, false, true, false)), S::single_axial);
  EXPECT_EQ(classify_scenario(misaligned(false, false, false, true)), S::single_axial);
  EXPECT_EQ(classify_scenario(misaligned(true, true, false, false)), S::radial_at_both_bases);
  EXPECT_EQ(classify_scenario(misaligned(false, false, true, true)), S::axial_at_both_bases);
  EXPECT_EQ(classify_scenario(misaligned(true, false, true, false)), S::radial_and_axial_same_base);
  EXPECT_EQ(classify_scenario(misaligned(false, true, false, true)), S::radial_and_axial_same_base);
  EXPECT_EQ(classify_scenario(misaligned(true, false, false, true)),
            S::radial_and_axial_opposite_bases);
  EXPECT_EQ(classify_scenario(misaligned(false, true, true, false)),
            S::radial_and_axial_opposite_bases);
  EXPECT_EQ(classify_scenario(misaligned(true, true, true, false)), S::two_radial_one_axial);
  EXPECT_EQ(classify_scenario(misaligned(true, true, false, true)), S::two_radial_one_axial);
  EXPECT_EQ(classify_scenario(misaligned(true, false, true, true)), S::one_radial_two_axial);
  EXPECT_EQ(classify_scenario(misaligned(false, true, true, true)), S::one_radial_two_axial);
  EXPECT_EQ(classify_scenario(misaligned(true, true, true, true)), S::all_four);
}

TEST(ClassifyScenario, NamesEveryAlignedPattern) {
  using S = ContactScenario;
  EXPECT_EQ(classify_scenario(aligned(false, false, false)), S::none);
  EXPECT_EQ(classify_scenario(aligned(true, false, false)), S::line);
  EXPECT_EQ(classify_scenario(aligned(false, true, false)), S::face);
  EXPECT_EQ(classify_scenario(aligned(false, false, true)), S::face);
  EXPECT_EQ(classify_scenario(aligned(true, false, true)), S::line_and_face);
}

TEST(ClassifyScenario, BeyondModelWinsAndImpossiblePatternsAreBeyondModel) {
  using S = ContactScenario;
  ContactPresence p = misaligned(true, false, false, false);
  p.beyond_model = true;
  EXPECT_EQ(classify_scenario(p), S::beyond_model);
  EXPECT_EQ(classify_scenario(aligned(false, true, true)), S::beyond_model);  // Lj < Li
  ContactPresence line_misaligned = misaligned(false, false, false, false);
  line_misaligned.line = true;
  EXPECT_EQ(classify_scenario(line_misaligned), S::beyond_model);
}

TEST(ContactScenarioToString, GivesDistinctKeysThatAreTheFigureLetters) {
  std::set<std::string> names;
  for (int k = 0; k <= int(ContactScenario::beyond_model); ++k) {
    names.insert(std::string(to_string(ContactScenario(k))));
  }
  EXPECT_EQ(names.size(), 14u);
  EXPECT_EQ(to_string(ContactScenario::single_radial), "a");
  EXPECT_EQ(to_string(ContactScenario::line_and_face), "l");
  EXPECT_EQ(to_string(ContactScenario::none), "none");
  EXPECT_EQ(to_string(ContactScenario::beyond_model), "beyond_model");
}

TEST(ContactScenarioLabel, StartsWithTheKeyInParenthesesForEveryLetteredScenario) {
  std::set<std::string> labels;
  for (int k = 0; k <= int(ContactScenario::beyond_model); ++k) {
    const auto scenario = ContactScenario(k);
    labels.insert(std::string(label(scenario)));
    const std::string key(to_string(scenario));
    if (key.size() == 1) {
      EXPECT_EQ(std::string(label(scenario)).substr(0, 4), "(" + key + ") ");
    }
  }
  EXPECT_EQ(labels.size(), 14u);
  EXPECT_EQ(label(ContactScenario::single_radial), "(a) single radial");
  EXPECT_EQ(label(ContactScenario::beyond_model), "beyond model");
}

}  // namespace
}  // namespace clearjoint::geometry
