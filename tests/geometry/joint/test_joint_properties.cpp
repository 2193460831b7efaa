// SPDX-License-Identifier: BSD-3-Clause
// detect_contacts over 100,000 random joints: every answer has the properties of
// joint_properties.hpp (an A/B swap, a reversed journal axis, a power-of-two change of units and
// a random rigid motion give the same scenario and the transformed contacts). The long run of
// 1e7 joints is bench/geometry/joint_properties_run.cpp.

#include <gtest/gtest.h>

#include <array>
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

}  // namespace
}  // namespace clearjoint::geometry
