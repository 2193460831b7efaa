// SPDX-License-Identifier: BSD-3-Clause
// A model file run in Simbody (clearjoint simulate --engine simbody): the same tables, columns and
// report times as clearjoint's own run, values that agree, every shipped model built, and the
// features the route does not support refused by name.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/simbody/model_in_simbody.hpp"
#include "clearjoint/simbody/simulate_in_simbody.hpp"

namespace clearjoint::simbody {
namespace {

using dynamics::TablesInMemory;

/// Rounding left by Simbody in quantities that are exactly zero in clearjoint (a slider's
/// vertical velocity, its angular acceleration) [SI units]: measured up to 1.5e-12.
constexpr double kRoundingFloor = 1e-9;
/// After 1 ms at each model's own tolerance (1e-7), the two engines' positions differ by the
/// integrators' errors [m]: measured up to 1.2e-7 m (the misaligned planar model).
constexpr double kShortRunPositionTolerance = 1e-6;

dynamics::ModelDescription shipped_model(const std::string& file) {
  return dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
}

const TablesInMemory::Table& table(const TablesInMemory& tables, const std::string& name) {
  for (const auto& t : tables.tables()) {
    if (t.name == name) return t;
  }
  throw std::runtime_error("no table " + name);
}

/// Largest |a - b| over column `column` of two tables with the same rows.
double largest_difference(const TablesInMemory::Table& a, const TablesInMemory::Table& b, size_t column) {
  double largest = 0.0;
  const size_t width = a.header.size();
  for (size_t r = 0; r < std::min(a.rows(), b.rows()); ++r) {
    const double x = a.values[r * width + column];
    const double y = b.values[r * width + column];
    if (std::isnan(x) && std::isnan(y)) continue;
    largest = std::max(largest, std::abs(x - y));
  }
  return largest;
}

/// Largest |value| over column `column`.
double largest_magnitude(const TablesInMemory::Table& a, size_t column) {
  double largest = 0.0;
  for (size_t r = 0; r < a.rows(); ++r) {
    const double x = a.values[r * a.header.size() + column];
    if (!std::isnan(x)) largest = std::max(largest, std::abs(x));
  }
  return largest;
}

TEST(SimulateInSimbody, WritesClearjointsTablesColumnsAndReportTimesWithAgreeingValues) {
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_clearance_aligned.json");
  model.solver.end_time = 0.02;  // [s]: two impacts and the contact that follows
  model.solver.report_step = 1e-4;
  model.solver.relative_tolerance = model.solver.absolute_tolerance = 1e-10;
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  ASSERT_TRUE(simbody.committed());
  ASSERT_EQ(simbody.tables().size(), reference.tables().size());
  for (const auto& expected : reference.tables()) {
    SCOPED_TRACE(expected.name);
    const TablesInMemory::Table& got = table(simbody, expected.name);
    ASSERT_EQ(got.header, expected.header);
    ASSERT_EQ(got.rows(), expected.rows());
    EXPECT_EQ(largest_difference(got, expected, 0), 0.0);  // the same report times
    // Every column within a part in 1e-4 of its largest magnitude (or within kRoundingFloor of
    // a column that is zero in clearjoint, where Simbody leaves rounding), except the constraint
    // bookkeeping (violations, Euler-norm drift), which differs by design between the engines
    // and is checked for size below.
    for (size_t c = 1; c < expected.header.size(); ++c) {
      const std::string& column = expected.header[c];
      if (column.find("violation") != std::string::npos || column == "euler_norm_drift") continue;
      const double scale = largest_magnitude(expected, c);
      EXPECT_LE(largest_difference(got, expected, c), 1e-4 * scale + kRoundingFloor) << column;
    }
  }
  const auto& energy = table(simbody, "energy");
  EXPECT_LT(largest_magnitude(energy, 6), 1e-9);  // Simbody keeps its quaternions normalised
}

TEST(SimulateInSimbody, BuildsEveryShippedModel) {
  for (const auto& entry : std::filesystem::directory_iterator(CLEARJOINT_MODELS_DIR)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    dynamics::ModelDescription model = dynamics::read_model_file(entry.path());
    model.solver.end_time = model.solver.start_time + 1e-3;
    model.solver.report_step = 1e-4;
    TablesInMemory reference, simbody;
    dynamics::simulate(model, reference);
    EXPECT_NO_THROW(simulate_in_simbody(model, simbody));
    // Positions over 1 ms (body_*.x, y, z).
    for (const auto& expected : reference.tables()) {
      if (expected.name.rfind("body_", 0) != 0) continue;
      for (size_t c = 1; c <= 3; ++c) {
        EXPECT_LT(largest_difference(table(simbody, expected.name), expected, c), kShortRunPositionTolerance)
            << expected.name << "." << expected.header[c];
      }
    }
  }
}

/// The UnsupportedFeature message for the planar ideal slider-crank changed by `edit`.
template <typename Edit>
std::string refusal(Edit edit) {
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  edit(model);
  try {
    SimbodyModel built(model);
  } catch (const UnsupportedFeature& e) {
    return e.what();
  }
  return "no refusal";
}

TEST(SimulateInSimbody, RefusesAnAngleDriverByName) {
  const std::string error = refusal([](dynamics::ModelDescription& m) {
    dynamics::JointDescription drive;
    drive.name = "drive";
    drive.type = dynamics::JointType::angle_driver;
    drive.body_i = "ground";
    drive.body_j = "crank";
    drive.angle.rate = 150.0;
    m.joints.push_back(drive);
  });
  EXPECT_NE(error.find("\"drive\" (angle_driver)"), std::string::npos) << error;
}

TEST(SimulateInSimbody, RefusesAPointLoadByName) {
  const std::string error = refusal([](dynamics::ModelDescription& m) {
    m.forces.push_back(dynamics::PointLoadDescription{"push", "slider", dynamics::Vector3::Zero(),
                                                     dynamics::Vector3::UnitX(), dynamics::Vector3::Zero()});
  });
  EXPECT_NE(error.find("\"push\" (point_load)"), std::string::npos) << error;
}

}  // namespace
}  // namespace clearjoint::simbody
