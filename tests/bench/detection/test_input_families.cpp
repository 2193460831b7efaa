// SPDX-License-Identifier: BSD-3-Clause
// Tests of the input families (input_families.hpp): reproducible from their seeds, with the groups
// they document, and the near-tangent margins and near-parallel tilts they claim.

#include "input_families.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "joint_reference.hpp"

namespace clearjoint::bench {
namespace {

using geometry::ContactScenario;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(InputFamilies, SameSeedGivesBitForBitTheSameInputs) {
  for (const FamilySpec& spec : family_specs()) {
    SCOPED_TRACE(spec.name);
    const std::vector<DetectionInput> first = generate_family(spec.name, SuiteSize::quick);
    const std::vector<DetectionInput> second = generate_family(spec.name, SuiteSize::quick);
    ASSERT_EQ(first.size(), second.size());
    ASSERT_FALSE(first.empty());
    for (std::size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].id, second[i].id);
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(same_bits(first[i].journal.p_WP[k], second[i].journal.p_WP[k]));
        EXPECT_TRUE(same_bits(first[i].journal.axis_W[k], second[i].journal.axis_W[k]));
        EXPECT_TRUE(same_bits(first[i].bearing.axis_W[k], second[i].bearing.axis_W[k]));
      }
    }
  }
}

TEST(InputFamilies, IdsAreUnique) {
  std::set<std::string> ids;
  for (const FamilySpec& spec : family_specs()) {
    for (const DetectionInput& input : generate_family(spec.name, SuiteSize::quick)) {
      EXPECT_TRUE(ids.insert(input.id).second) << input.id;
    }
  }
}

TEST(InputFamilies, MarginFamiliesHaveEveryDocumentedGroup) {
  std::set<std::string> tangent, parallel;
  for (const DetectionInput& input : generate_family("near_tangent", SuiteSize::quick)) tangent.insert(input.group);
  for (const DetectionInput& input : generate_family("near_parallel", SuiteSize::quick)) parallel.insert(input.group);
  for (int k = 3; k <= 15; ++k) EXPECT_EQ(tangent.count("k=" + std::to_string(k)), 1u) << k;
  EXPECT_EQ(tangent.size(), 13u);
  for (int k = 4; k <= 16; ++k) EXPECT_EQ(parallel.count("k=" + std::to_string(k)), 1u) << k;
  EXPECT_EQ(parallel.count("parallel"), 1u);
  EXPECT_EQ(parallel.size(), 14u);
}

TEST(InputFamilies, NearTangentMarginsAreTheNominalOnesUpToTheRoundingOfTheJournalCentre) {
  // The generator solves for the journal centre in MPFR, then rounds it to double: each
  // coordinate moves by at most half an ulp, so the centre by at most sqrt(3)/2 ulp(max |P_j|),
  // and a margin (a distance of a rim point from the wall or a base plane) by no more.
  for (const DetectionInput& input : generate_family("near_tangent", SuiteSize::quick)) {
    SCOPED_TRACE(input.id);
    const bool radial = input.id.find("radial") != std::string::npos || input.id.find("line") != std::string::npos;
    const double clearance = radial ? input.dimensions.radial_clearance() : input.dimensions.axial_clearance();
    const double sign = input.id.find("/+/") != std::string::npos ? 1.0 : -1.0;
    const double nominal = sign * std::pow(10.0, -input.group_value) * clearance;
    const double largest = input.journal.p_WP.cwiseAbs().maxCoeff();
    const double ulp = std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest;
    const double bound = 0.5 * std::sqrt(3.0) * ulp;
    EXPECT_LE(std::fabs(input.measured_margin * clearance - nominal), bound);
    EXPECT_EQ(input.measured_margin > 0, sign > 0);  // every margin keeps its sign
  }
}

TEST(InputFamilies, NearParallelTiltsAreTheNominalOnesOnTheCanonicalBearing) {
  // On the bearing along z the journal axis (t cos, t sin, 1) has the angle atan(t) to it, t
  // rounded once per component (relative 2^-53); elsewhere the rounded axis carries the tilt only
  // to ~1e-16 rad, and the group k = 0 is exactly parallel.
  for (const DetectionInput& input : generate_family("near_parallel", SuiteSize::quick)) {
    SCOPED_TRACE(input.id);
    if (input.group == "parallel") {
      EXPECT_EQ(input.measured_tilt, 0.0);
      continue;
    }
    EXPECT_GT(input.measured_tilt, 0.0);
    if (input.bearing.axis_W == geometry::Vector3::UnitZ()) {
      const double nominal = std::atan(std::pow(10.0, -input.group_value));
      EXPECT_NEAR(input.measured_tilt, nominal, 4e-16 * nominal);
    }
  }
}

TEST(InputFamilies, RealisticFamilyIsAboutHalfInContact) {
  // Issue 5 asks for "about half of them in contact"; the generator's offsets (up to 1.5 times the
  // room left at the tilt) give a third per direction. Accept 35 % to 65 %.
  constexpr double kLowestShare = 0.35, kHighestShare = 0.65;
  const std::vector<DetectionInput> inputs = generate_family("realistic", SuiteSize::quick);
  int in_contact = 0;
  for (const DetectionInput& input : inputs) {
    const ReferenceAnswer answer = reference_detect(joint_as_given(input.dimensions, input.bearing, input.journal));
    ASSERT_TRUE(answer.decided);
    in_contact += answer.scenario != ContactScenario::none ? 1 : 0;
  }
  const double share = static_cast<double>(in_contact) / static_cast<double>(inputs.size());
  EXPECT_GE(share, kLowestShare);
  EXPECT_LE(share, kHighestShare);
}

TEST(InputFamilies, UnitVariantsDescribeTheSameJointInMicrometresAndKilometres) {
  std::map<std::string, std::vector<DetectionInput>> by_unit;
  for (const DetectionInput& input : generate_family("extreme", SuiteSize::quick)) by_unit[input.group].push_back(input);
  ASSERT_EQ(by_unit["metres"].size(), by_unit["micrometres"].size());
  ASSERT_EQ(by_unit["metres"].size(), by_unit["kilometres"].size());
  ASSERT_FALSE(by_unit["metres"].empty());
  for (std::size_t i = 0; i < by_unit["metres"].size(); ++i) {
    const DetectionInput& m = by_unit["metres"][i];
    EXPECT_EQ(by_unit["micrometres"][i].dimensions.bearing_radius, m.dimensions.bearing_radius * 1e6);
    EXPECT_EQ(by_unit["kilometres"][i].journal.p_WP, m.journal.p_WP * 1e-3);
    EXPECT_EQ(by_unit["kilometres"][i].journal.axis_W, m.journal.axis_W);
  }
}

TEST(InputFamilies, UnknownFamilyIsAnErrorNamingIt) {
  try {
    generate_family("realistc", SuiteSize::quick);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("realistc"), std::string::npos);
  }
}

}  // namespace
}  // namespace clearjoint::bench
