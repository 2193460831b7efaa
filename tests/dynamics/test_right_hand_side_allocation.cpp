// SPDX-License-Identifier: BSD-3-Clause
// The right-hand side allocates nothing: MultibodySystem::derivative (with the clearance joint's
// detection, contact forces and the constraint solve), begins_event and update_extra_states are
// called hundreds of thousands of times per simulated second. This executable replaces malloc,
// calloc and realloc by counting wrappers around glibc's own (__libc_malloc etc.); operator new
// and Eigen's dynamic storage both end in malloc, so every heap allocation is counted. Under
// AddressSanitizer (scripts/run-sanitizers.sh) malloc belongs to the sanitizer's runtime, which
// aborts at start-up when the program replaces it; there the sanitizer's allocation hook, which
// every malloc, calloc, realloc and operator new of its allocator calls, counts instead.

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <vector>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define CLEARJOINT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)  // Clang
#if __has_feature(address_sanitizer)
#define CLEARJOINT_TEST_UNDER_ASAN 1
#endif
#endif

#ifdef CLEARJOINT_TEST_UNDER_ASAN
#include <sanitizer/allocator_interface.h>
#endif

namespace {
std::atomic<long> heap_allocations{0};
}  // namespace

#ifdef CLEARJOINT_TEST_UNDER_ASAN
namespace {
void count_allocation(const volatile void*, std::size_t) {
  heap_allocations.fetch_add(1, std::memory_order_relaxed);
}
void ignore_release(const volatile void*) {}
// Installed before main, so before any test runs (the runtime takes both hooks or none).
const bool hooks_installed =
    __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_release) != 0;
}  // namespace
#else
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
}

extern "C" {
void* malloc(std::size_t size) {
  heap_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  heap_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  heap_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(pointer, size);
}
}
#endif

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
    const long before = heap_allocations.load();
    system.derivative(t, states[k], rate);
    system.begins_event(t, states[k]);
    counted.allocations += heap_allocations.load() - before;
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
#ifdef CLEARJOINT_TEST_UNDER_ASAN
  ASSERT_TRUE(hooks_installed) << "the sanitizer refused the allocation hooks";
#endif
  // The counter itself works: a vector of doubles is one allocation.
  const long before = heap_allocations.load();
  std::vector<double> v(100);
  v[0] = 1.0;
  // The vector's storage escapes into an empty asm statement: without it Clang elides the
  // allocation and its release ([expr.new]/13 lets a compiler omit them), and nothing is counted.
  asm volatile("" : : "r"(v.data()) : "memory");
  EXPECT_EQ(heap_allocations.load() - before, 1);
}

}  // namespace
}  // namespace clearjoint::dynamics
