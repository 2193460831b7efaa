// SPDX-License-Identifier: BSD-3-Clause
// Issue 35's first agreement figure: the planar slider-crank with an aligned clearance joint
// (models/slider_crank_planar_clearance_aligned.json) at tolerance 1e-10 in clearjoint and in
// Simbody: every impact speed of the 1 s run within 0.5 %, the slider within 1e-6 m over the
// first 0.1 s.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "simbody_agreement_support.hpp"

namespace clearjoint::simbody::testing {
namespace {

constexpr double kTolerance = 1e-10;
constexpr double kSampleStep = 1e-4;          // [s]: slider compared every 0.1 ms
constexpr double kPositionWindow = 0.1;       // [s]
constexpr double kPositionTolerance = 1e-6;   // [m]
constexpr double kImpactSpeedTolerance = 5e-3;  // relative

TEST(SimbodyPlanarAgreement, ImpactSpeedsAndSliderAgreeWithClearjointAtTolerance1e10) {
  const dynamics::ModelDescription model =
      shipped_model("slider_crank_planar_clearance_aligned.json", kTolerance);
  const EngineRun reference = run_in_clearjoint(model, kSampleStep);
  const EngineRun simbody = run_in_simbody(model, kSampleStep);

  const int slider = 2;  // bodies: crank, rod, slider
  double worst_position = 0.0;
  for (size_t k = 0; k < reference.sample_times.size() && reference.sample_times[k] <= kPositionWindow; ++k) {
    worst_position = std::max(worst_position,
                              (simbody.positions[k][slider] - reference.positions[k][slider]).norm());
  }
  EXPECT_LT(worst_position, kPositionTolerance);

  ASSERT_GT(reference.impacts.size(), 0u);
  EXPECT_EQ(simbody.impacts.size(), reference.impacts.size());
  double worst_speed = 0.0;
  double worst_time = 0.0;
  const size_t common = std::min(simbody.impacts.size(), reference.impacts.size());
  for (size_t k = 0; k < common; ++k) {
    const dynamics::RecordedImpact& a = reference.impacts[k];
    const dynamics::RecordedImpact& b = simbody.impacts[k];
    EXPECT_EQ(b.slot, a.slot) << "impact " << k;
    EXPECT_NEAR(b.impact_speed, a.impact_speed, kImpactSpeedTolerance * a.impact_speed)
        << "impact " << k << " at t = " << a.time;
    worst_speed = std::max(worst_speed, std::abs(b.impact_speed / a.impact_speed - 1.0));
    worst_time = std::max(worst_time, std::abs(b.time - a.time));
  }
  // The figures of docs/engines.md.
  std::printf("planar aligned, tolerance 1e-10: slider within %.2g m over %.2g s; %zu impacts "
              "(clearjoint %zu): speeds within %.2g (relative), instants within %.2g s\n",
              worst_position, kPositionWindow, simbody.impacts.size(), reference.impacts.size(),
              worst_speed, worst_time);
}

}  // namespace
}  // namespace clearjoint::simbody::testing
