// SPDX-License-Identifier: BSD-3-Clause
// The paper's two slider-cranks with ideal joints: mechanical energy and constraints over 1 s.

#include "clearjoint/dynamics/simulation.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

// Issue 6's acceptance figures: at integration tolerance 1e-10, energy conserved to 1e-8 relative
// to the initial mechanical energy (potential datum: the world origin) and |Phi| below 1e-8.
constexpr double kIntegrationTolerance = 1e-10;
constexpr double kRelativeEnergyTolerance = 1e-8;
constexpr double kConstraintTolerance = 1e-8;

SimulationSummary run(const std::string& file, const std::string& out) {
  ModelDescription model = test::shipped_model(file);
  model.solver.relative_tolerance = model.solver.absolute_tolerance = kIntegrationTolerance;
  model.solver.report_step = 1e-3;
  const auto dir = std::filesystem::temp_directory_path() / out;
  std::filesystem::remove_all(dir);
  const SimulationSummary summary = simulate(model, dir);
  for (const char* f : {"energy.csv", "reactions.csv", "body_slider.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  std::ifstream energy(dir / "energy.csv");
  const auto lines = std::count(std::istreambuf_iterator<char>(energy), {}, '\n');
  EXPECT_EQ(lines, 1 + 1001);  // header, t = 0 and 1000 report steps
  std::printf("%s: E0 = %.6g J, max |dE|/E0 = %.3g, max |Phi| = %.3g, max |dPhi/dt| = %.3g, "
              "max ||p|-1| = %.3g, %ld steps\n",
              file.c_str(), summary.initial_energy, summary.max_energy_change / summary.initial_energy,
              summary.max_position_violation, summary.max_velocity_violation,
              summary.max_euler_norm_drift, summary.integration.steps);
  return summary;
}

TEST(PlanarSliderCrank, ConservesMechanicalEnergyWithIdealJoints) {
  const SimulationSummary s = run("slider_crank_planar_ideal.json", "clearjoint_planar_test");
  EXPECT_LT(s.max_energy_change / std::abs(s.initial_energy), kRelativeEnergyTolerance);
  EXPECT_LT(s.max_position_violation, kConstraintTolerance);
}

TEST(SpatialSliderCrank, ConservesMechanicalEnergyWithIdealJoints) {
  const SimulationSummary s = run("slider_crank_spatial_ideal.json", "clearjoint_spatial_test");
  EXPECT_LT(s.max_energy_change / std::abs(s.initial_energy), kRelativeEnergyTolerance);
  EXPECT_LT(s.max_position_violation, kConstraintTolerance);
}

TEST(SpatialSliderCrankWithClearance, WritesTheJointsContactTimeSeriesUnlessAskedNotTo) {
  ModelDescription model = test::shipped_model("slider_crank_spatial_clearance.json");
  model.solver.end_time = 0.02;
  model.solver.report_step = 1e-3;
  const auto dir = std::filesystem::temp_directory_path() / "clearjoint_spatial_clearance_test";
  std::filesystem::remove_all(dir);
  const SimulationSummary summary = simulate(model, dir);
  const auto file = dir / "force_ground-crank_clearance.csv";
  ASSERT_TRUE(std::filesystem::exists(file));
  std::ifstream csv(file);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("time,scenario,aligned,certainty,contact_count,axis_angle,", 0), 0u) << header;
  EXPECT_NE(header.find("line.impact_speed"), std::string::npos);
  const auto rows = std::count(std::istreambuf_iterator<char>(csv), {}, '\n');
  EXPECT_EQ(rows, 21);
  ASSERT_EQ(summary.element_statistics.size(), 1u);
  EXPECT_NE(summary.element_statistics[0].find("contact detections"), std::string::npos);

  model.output_all_force_elements = false;  // "output": {"force_elements": []}
  std::filesystem::remove_all(dir);
  simulate(model, dir);
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_TRUE(std::filesystem::exists(dir / "body_slider.csv"));
}

}  // namespace
}  // namespace clearjoint::dynamics
