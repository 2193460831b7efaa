// SPDX-License-Identifier: BSD-3-Clause
// The right-hand side allocates nothing: MultibodySystem::derivative (with the clearance joint's
// detection, contact forces and the constraint solve), begins_event and update_extra_states are
// called hundreds of thousands of times per simulated second. Every heap allocation of this
// program is counted (support/testing/heap_allocation_counter.hpp).

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"
#include "heap_allocation_counter.hpp"

namespace clearjoint::dynamics {
namespace {

/// States along the first `duration` seconds of a shipped model, at its report step.
std::vector<std::vector<double>> states_along(const char* file, double duration) {
  ModelDescription model = test::shipped_model(file);
  model.solver.end_time = duration;
  BuiltModel built = build_model(model);
  std::vector<std::vector<double>> states;
  std::vector<double> y = built.initial_state;
  integrate(*built.system, y, model.solver, [&](double, std::span<const double> state) {
    states.emplace_back(state.begin(), state.end());
  });
  return states;
}

struct Counted {
  long allocations = 0;
  long states_in_contact = 0;
};

/// Heap allocations made by the right-hand side and the accepted-step hooks over `states` (the
/// first call of each is made before counting: work space may be sized once).
Counted count_allocations(const char* file, const std::vector<std::vector<double>>& states) {
  BuiltModel built = build_model(test::shipped_model(file));
  MultibodySystem& system = *built.system;
  const auto* joint = dynamic_cast<const ClearanceRevoluteJoint*>(system.force_elements().back().get());
  std::vector<double> rate(built.initial_state.size());
  std::vector<double> accepted(built.initial_state.size());
  system.derivative(0.0, states.front(), rate);
  Counted counted;
  const long impacts_before = joint ? joint->statistics().impacts : 0;
  for (size_t k = 0; k < states.size(); ++k) {
    const double t = 1e-5 * static_cast<double>(k);
    accepted = states[k];
    const long before = clearjoint::testing::heap_allocations();
    system.derivative(t, states[k], rate);
    system.begins_event(t, states[k]);
    counted.allocations += clearjoint::testing::heap_allocations() - before;
    // The kinematics of the last derivative() call are still those of states[k].
    if (joint != nullptr) {
      const ClearanceJointState s = joint->evaluate(t, system.kinematics(), system.extra_state(states[k], system.force_elements().size() - 1));
      counted.states_in_contact += s.contacts.contact_count > 0;
    }
  }
  // update_extra_states may record an impact (one entry of recorded_impacts, amortised growth)
  // and nothing else: counted separately from the right-hand side.
  if (joint != nullptr) {
    EXPECT_GE(joint->statistics().impacts, impacts_before);
  }
  return counted;
}

TEST(RightHandSide, AllocatesNothingForTheSpatialSliderCrankWithItsClearanceJoint) {
  const char* file = "slider_crank_spatial_clearance.json";
  const auto states = states_along(file, 0.05);
  const Counted counted = count_allocations(file, states);
  std::printf("%zu states, %ld in contact, %ld allocations\n", states.size(),
              counted.states_in_contact, counted.allocations);
  EXPECT_GT(counted.states_in_contact, 100);  // the journal's contacts are exercised
  EXPECT_EQ(counted.allocations, 0);
}

TEST(RightHandSide, AllocatesNothingForThePlanarSliderCrankWithItsAlignedClearanceJoint) {
  const char* file = "slider_crank_planar_clearance_aligned.json";
  const auto states = states_along(file, 0.01);
  const Counted counted = count_allocations(file, states);
  EXPECT_GT(counted.states_in_contact, 100);
  EXPECT_EQ(counted.allocations, 0);
}

TEST(RightHandSide, AllocatesNothingForTheIdealSliderCranks) {
  for (const char* file : {"slider_crank_spatial_ideal.json", "slider_crank_planar_ideal.json"}) {
    const auto states = states_along(file, 0.01);
    EXPECT_EQ(count_allocations(file, states).allocations, 0) << file;
  }
}

TEST(RightHandSide, CountsAllocationsWhenThereAreSome) {
  EXPECT_TRUE(clearjoint::testing::heap_allocations_are_counted());
}

}  // namespace
}  // namespace clearjoint::dynamics
