// SPDX-License-Identifier: BSD-3-Clause
// clearjoint's Moreau-Jean integrator against Siconos's own kernel (issue 47's check, reported in
// docs/nonsmooth.md, "Comparison with Siconos"): a journal bouncing in a bearing fixed to the
// ground, frictionless, e = 0.9, theta = 1/2, h = 1e-5, over 0.1 s.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/nonsmooth/moreau_jean.hpp"
#include "siconos_journal_in_bearing.hpp"

namespace clearjoint::nonsmooth {
namespace {

using siconos_reference::PlanarJournal;
using siconos_reference::PlanarSample;

// The system: the paper's Section 6.1 clearance (bearing radius 10 mm, journal 9.9 mm, as in
// models/slider_crank_planar_clearance_aligned.json), a 0.5 kg journal starting centred and
// moving sideways and down, so that it bounces across the bearing, not along one diameter.
constexpr double kMass = 0.5;
constexpr double kGravity = 9.81;
constexpr double kClearance = 1e-4;
constexpr double kRestitution = 0.9;
constexpr double kStep = 1e-5;
constexpr long kSteps = 10000;  // 0.1 s
constexpr double kVx0 = 0.3, kVy0 = -0.5;

// Issue 47's tolerances: the first 10 impacts within one step, the normal relative velocity
// after each within 1 %.
constexpr int kImpactsCompared = 10;
constexpr long kImpactStepTolerance = 1;
constexpr double kReboundRelativeTolerance = 0.01;
// Rounding of positions of order c = 1e-4 m (a few ulps).
constexpr double kRoundingTolerance = 1e-18;  // [m]

std::string journal_model() {
  return R"({"name": "journal in bearing", "gravity": [0, -9.81, 0],
    "bodies": [{"name": "journal", "mass": 0.5, "inertia": [1e-4, 1e-4, 2e-5],
                "position": [0, 0, 0], "velocity": [0.3, -0.5, 0]}],
    "forces": [{"type": "clearance_revolute", "name": "joint",
      "bearing": {"body": "ground", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.01, "length": 0.02},
      "journal": {"body": "journal", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.0099, "length": 0.0198},
      "normal_force": {"model": "hertz", "stiffness": 1e11, "exponent": 1.5, "restitution": 0.9},
      "friction": {"coefficient": 0}}],
    "solver": {"method": "moreau_jean", "step": 1e-5, "theta": 0.5}})";
}

/// clearjoint's run, sampled as Siconos's: the journal centre's x, y and velocity after each step.
std::vector<PlanarSample> run_clearjoint() {
  MoreauJean scheme(dynamics::parse_model(journal_model(), "journal.json"));
  EXPECT_DOUBLE_EQ(scheme.step_size(), kStep);
  std::vector<PlanarSample> samples;
  for (long k = 0; k < kSteps; ++k) {
    scheme.step();
    double percussion = 0.0;
    for (const ContactPercussion& c : scheme.contacts()) percussion += c.normal_percussion;
    // State: [x y z e0..e3 | vx vy vz ...] (dynamics::StateLayout).
    const auto y = scheme.state();
    samples.push_back({y[0], y[1], y[7], y[8], percussion});
  }
  return samples;
}

std::vector<PlanarSample> run_reference() {
  PlanarJournal system;
  system.mass = kMass;
  system.gravity = kGravity;
  system.clearance = kClearance;
  system.restitution = kRestitution;
  system.vx0 = kVx0;
  system.vy0 = kVy0;
  system.step = kStep;
  system.steps = kSteps;
  return siconos_reference::run_siconos(system);
}

struct Impact {
  long step = 0;          ///< index of the step with the percussion (its end is (step + 1) h)
  double rebound = 0.0;   ///< normal relative velocity after it, > 0 separating [m/s]
};

/// The first step of each run of steps with a percussion, and the normal velocity after it,
/// n(q_k) . v_(k+1) with n = -q_k / |q_k| the inward normal at the step's start (the velocity
/// Newton's law acts on in Moreau-Jean's scheme).
std::vector<Impact> impacts(const std::vector<PlanarSample>& run) {
  std::vector<Impact> found;
  for (std::size_t k = 1; k < run.size(); ++k) {
    if (run[k].normal_percussion > 0.0 && run[k - 1].normal_percussion <= 0.0) {
      const double r = std::hypot(run[k - 1].x, run[k - 1].y);
      found.push_back({static_cast<long>(k), -(run[k - 1].x * run[k].vx + run[k - 1].y * run[k].vy) / r});
    }
  }
  return found;
}

TEST(SiconosComparison, FindsTheFirstTenImpactsAtTheSameStepsAndReboundsAsSiconosKernel) {
  const std::vector<Impact> ours = impacts(run_clearjoint());
  const std::vector<Impact> theirs = impacts(run_reference());
  ASSERT_GE(theirs.size(), static_cast<std::size_t>(kImpactsCompared));
  ASSERT_GE(ours.size(), static_cast<std::size_t>(kImpactsCompared));
  for (int i = 0; i < kImpactsCompared; ++i) {
    EXPECT_LE(std::labs(ours[i].step - theirs[i].step), kImpactStepTolerance)
        << "impact " << i << ": clearjoint t = " << (ours[i].step + 1) * kStep
        << " s, Siconos t = " << (theirs[i].step + 1) * kStep << " s";
    EXPECT_GT(theirs[i].rebound, 0.0) << "impact " << i;
    EXPECT_NEAR(ours[i].rebound, theirs[i].rebound, kReboundRelativeTolerance * std::fabs(theirs[i].rebound))
        << "impact " << i;
  }
}

// The 1e-6 m bound over 0.1 s is not met (docs/nonsmooth.md, "Comparison with Siconos"): Siconos
// 4.4's percussion at the first impact points 4e-5 rad off the normal at the step's start, where
// clearjoint's (Moreau-Jean's H(q_k)) points, and the bouncing amplifies that to 4e-5 m by 0.07 s.
// What holds, and is asserted: the free flight before the first impact agrees to rounding.
TEST(SiconosComparison, AgreesWithSiconosKernelToRoundingUntilTheFirstImpact) {
  const std::vector<PlanarSample> ours = run_clearjoint();
  const std::vector<PlanarSample> theirs = run_reference();
  ASSERT_EQ(ours.size(), theirs.size());
  const std::vector<Impact> first = impacts(theirs);
  ASSERT_FALSE(first.empty());
  for (long k = 0; k < first.front().step; ++k) {
    EXPECT_NEAR(ours[k].x, theirs[k].x, kRoundingTolerance) << "step " << k;
    EXPECT_NEAR(ours[k].y, theirs[k].y, kRoundingTolerance) << "step " << k;
  }
}

}  // namespace
}  // namespace clearjoint::nonsmooth
