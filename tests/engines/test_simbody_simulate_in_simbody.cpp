// SPDX-License-Identifier: BSD-3-Clause
// A model file run in Simbody (clearjoint simulate --engine simbody): the same tables, columns and
// report times as clearjoint's own run, also decimated, values that agree, a lubricated joint's
// film work integrated so that its energy balances, every shipped model built, and the features
// the route does not support refused by name.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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
/// At tolerance 1e-10 over tens of milliseconds, every column of the two engines agrees to a part
/// in kAgreement of its largest magnitude (docs/engines.md, "The same physics in three engines").
constexpr double kAgreement = 1e-4;

dynamics::ModelDescription shipped_model(const std::string& file) {
  return dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
}

const TablesInMemory::Table& table(const TablesInMemory& tables, const std::string& name) {
  for (const auto& t : tables.tables()) {
    if (t.name == name) return t;
  }
  throw std::runtime_error("no table " + name);
}

/// Largest |a - b| over column `column` of two tables with the same rows; infinite where one is
/// NaN (no contact, no film solution) and the other is not.
double largest_difference(const TablesInMemory::Table& a, const TablesInMemory::Table& b, size_t column) {
  double largest = 0.0;
  const size_t width = a.header.size();
  for (size_t r = 0; r < std::min(a.rows(), b.rows()); ++r) {
    const double x = a.values[r * width + column];
    const double y = b.values[r * width + column];
    if (std::isnan(x) && std::isnan(y)) continue;
    if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::infinity();
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

/// Every table of `reference` in `simbody` with the same columns and report times, and values
/// that agree (the tolerance below).
void expect_same_tables(const TablesInMemory& simbody, const TablesInMemory& reference) {
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
      EXPECT_LE(largest_difference(got, expected, c), kAgreement * scale + kRoundingFloor) << column;
    }
  }
}

/// The planar aligned slider-crank over 20 ms (two impacts and the contact that follows), reported
/// every 0.1 ms at tolerance 1e-10.
dynamics::ModelDescription short_planar_run() {
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_clearance_aligned.json");
  model.solver.end_time = 0.02;  // [s]
  model.solver.report_step = 1e-4;
  model.solver.relative_tolerance = model.solver.absolute_tolerance = 1e-10;
  return model;
}

TEST(SimulateInSimbody, WritesClearjointsTablesColumnsAndReportTimesWithAgreeingValues) {
  const dynamics::ModelDescription model = short_planar_run();
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  expect_same_tables(simbody, reference);
  const auto& energy = table(simbody, "energy");
  EXPECT_LT(largest_magnitude(energy, 6), 1e-9);  // Simbody keeps its quaternions normalised
}

TEST(SimulateInSimbody, RunsAPinInHoleJointThroughTheSameForceElementAsClearjoint) {
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_clearance_pin_in_hole.json");
  model.solver.end_time = 0.02;  // [s]: the pin reaches its line contact and rides on it
  model.solver.report_step = 1e-4;
  model.solver.relative_tolerance = model.solver.absolute_tolerance = 1e-10;
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  expect_same_tables(simbody, reference);
  // The scenario column holds the pin-in-hole table's numbers: the line contact (4) is reached.
  const auto& forces = table(simbody, "force_rod-slider_pin");
  bool line = false;
  for (size_t r = 0; r < forces.rows(); ++r) {
    line = line || forces.values[r * forces.header.size() + 1] ==
                       static_cast<double>(geometry::PinInHoleScenario::line);
  }
  EXPECT_TRUE(line);
}

TEST(SimulateInSimbody, WritesTheRowsOfEveryKthReportTimeAndTheLastAsClearjointDoes) {
  dynamics::ModelDescription model = short_planar_run();
  model.output_decimation = 3;  // 201 report times: rows 0, 3, ..., 198 and the last, 200
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  expect_same_tables(simbody, reference);
  const auto& energy = table(simbody, "energy");
  ASSERT_EQ(energy.rows(), 68u);
  EXPECT_EQ(energy.values[energy.header.size()], 3 * model.solver.report_step);  // second row
  EXPECT_EQ(energy.values[(energy.rows() - 1) * energy.header.size()], model.solver.end_time);
}

TEST(SimulateInSimbody, WritesEveryReportTimeWhenTheDecimationExceedsTheirCount) {
  dynamics::ModelDescription model = short_planar_run();
  model.solver.end_time = 1e-3;
  model.output_decimation = 1'000'000;
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  expect_same_tables(simbody, reference);
  EXPECT_EQ(table(simbody, "energy").rows(), 2u);  // the first and the last
}

// A lubricated journal (1 kg) free in a grounded bearing, no gravity, thrown across the clearance
// while spinning: the film alone catches it (tests/dynamics/test_joint_film.cpp runs it in
// clearjoint).
const dynamics::Vector3 kThrowVelocity(0.05, 0.02, 0.0);  // m/s
/// What the film can take: the journal's translation, 1/2 m v^2 [J].
const double kThrowEnergy = 0.5 * kThrowVelocity.squaredNorm();
/// |E(t) - E(0) - W_film(t)| / kThrowEnergy at tolerance 1e-10: clearjoint's own run keeps it
/// under 1e-6 (test_joint_film); the same bound for Simbody's.
constexpr double kFilmEnergyBalance = 1e-6;

dynamics::ModelDescription thrown_lubricated_journal() {
  dynamics::ModelDescription model;
  model.name = "journal on its film";
  dynamics::BodyDescription journal;
  journal.properties = {"journal", 1.0, dynamics::Vector3(2.5e-5, 2.5e-5, 4.9e-5)};
  journal.initial.velocity_W = kThrowVelocity;
  journal.initial.angular_velocity_B = dynamics::Vector3(0.0, 0.0, 100.0);  // rad/s
  model.bodies.push_back(journal);
  dynamics::ClearanceJointParameters p;  // paper Table 2 dimensions
  p.normal.model = dynamics::NormalForceModel::hertz;
  p.friction.coefficient = 0.0;
  dynamics::JointLubrication film;
  film.viscosity = 0.002;  // Pa s, a light oil: the journal crosses most of the clearance
  film.method = dynamics::FilmMethod::short_bearing;
  film.film_thickness_limit = film.transition_width = 2e-6;  // m
  p.lubrication = film;
  model.forces.push_back(dynamics::ClearanceRevoluteDescription{
      "clearance", {"ground", dynamics::Vector3::Zero(), dynamics::Vector3::UnitZ()},
      {"journal", dynamics::Vector3::Zero(), dynamics::Vector3::UnitZ()}, p});
  model.output_bodies = {"journal"};
  model.solver.end_time = 0.02;  // s
  model.solver.report_step = 1e-4;
  model.solver.relative_tolerance = model.solver.absolute_tolerance = 1e-10;
  return model;
}

TEST(SimulateInSimbody, IntegratesALubricatedJointsFilmWorkSoThatTheEnergyBalances) {
  const dynamics::ModelDescription model = thrown_lubricated_journal();
  TablesInMemory reference, simbody;
  dynamics::simulate(model, reference);
  simulate_in_simbody(model, simbody);
  expect_same_tables(simbody, reference);  // film.work among the columns

  const auto& energy = table(simbody, "energy");
  const auto& force = table(simbody, "force_clearance");
  const auto column = [](const TablesInMemory::Table& t, const std::string& name) {
    return static_cast<size_t>(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
  };
  const size_t total = column(energy, "total");
  const size_t work = column(force, "film.work");
  ASSERT_LT(work, force.header.size());
  const double E0 = energy.values[total];
  double worst = 0.0;
  for (size_t r = 0; r < energy.rows(); ++r) {
    const double E = energy.values[r * energy.header.size() + total];
    const double W = force.values[r * force.header.size() + work];
    worst = std::max(worst, std::abs(E - E0 - W) / kThrowEnergy);
  }
  const double final_work = force.values[(force.rows() - 1) * force.header.size() + work];
  std::printf("Simbody: W_film = %.6g J of %.3g J thrown; max |E - E0 - W| / (thrown) = %.3g\n",
              final_work, kThrowEnergy, worst);
  EXPECT_LT(final_work, -0.5 * kThrowEnergy);  // the film has taken most of the energy
  EXPECT_LT(worst, kFilmEnergyBalance);
}

TEST(SimulateInSimbody, StopsARunThatTakesMoreStepsThanTheBudgetNamingIt) {
  dynamics::ModelDescription model = short_planar_run();
  model.solver.max_steps = 10;  // the 20 ms run takes thousands at 1e-10
  TablesInMemory simbody;
  try {
    simulate_in_simbody(model, simbody);
    ADD_FAILURE() << "no error";
  } catch (const dynamics::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.max_steps = 10"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(simbody.committed());
}

/// The planar ideal slider-crank with its slider tied to the ground by a spring so stiff (1e18
/// N/m) that Simbody's explicit steps stay near 1e-10 s: legal steps far above minimum_step,
/// hours for 20 ms.
dynamics::ModelDescription stiff_run() {
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  model.solver.end_time = 0.02;
  model.solver.report_step = 0.02;
  model.solver.max_steps = 1'000'000'000;
  dynamics::SpringDamperDescription spring;
  spring.name = "stiff";
  spring.body_i = "ground";
  spring.body_j = "slider";
  spring.point_i_B = dynamics::Vector3(0.5, 0.0, 0.0);
  spring.parameters.stiffness = 1e18;
  spring.parameters.free_length = 0.1;
  model.forces.push_back(spring);
  return model;
}

/// Thrown by a test's progress callback to end a run that went on.
struct WentOn {};

TEST(SimulateInSimbody, StopsARunWhoseStepHasCollapsedWithinItsStallWallTime) {
  // stall_wall_time shortened to 0.2 s: stopped after about 0.1 s. The progress callback ends
  // the run if it goes on for 20 s.
  dynamics::ModelDescription model = stiff_run();
  model.solver.stall_wall_time = 0.2;
  const auto start = std::chrono::steady_clock::now();
  TablesInMemory simbody;
  try {
    simulate_in_simbody(model, simbody, [&](double) {
      if (std::chrono::steady_clock::now() - start > std::chrono::seconds(20)) throw WentOn{};
    });
    ADD_FAILURE() << "the run finished";
  } catch (const dynamics::SolverError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("Simbody integration stopped at t = ", 0), 0u) << message;
    EXPECT_NE(message.find("the step size has collapsed to a mean of"), std::string::npos) << message;
  } catch (const WentOn&) {
    ADD_FAILURE() << "the run went on for 20 s";
  }
  EXPECT_FALSE(simbody.committed());
}

TEST(SimulateInSimbody, ReportsProgressBetweenReportTimes) {
  // One report step for the whole run: progress comes from between the report times, and a
  // callback that throws there (a user's interrupt) stops the run.
  dynamics::ModelDescription model = stiff_run();
  model.solver.max_steps = 3'000'000;  // ends a run that never reports
  TablesInMemory simbody;
  double reported = -1.0;
  try {
    simulate_in_simbody(model, simbody, [&](double fraction) {
      if (fraction > 0.0 && fraction < 1.0) {
        reported = fraction;
        throw WentOn{};
      }
    });
    ADD_FAILURE() << "the run finished";
  } catch (const WentOn&) {
  } catch (const dynamics::SolverError& e) {
    ADD_FAILURE() << e.what();
  }
  EXPECT_GT(reported, 0.0);
  EXPECT_FALSE(simbody.committed());
}

TEST(SimulateInSimbody, RefusesSolverSettingsSimbodyWouldAbortOnNamingTheField) {
  // Simbody's Integrator asserts (SIGABRT) on these.
  for (const auto& [edit, field] : std::vector<std::pair<std::function<void(dynamics::IntegratorSettings&)>, std::string>>{
           {[](auto& s) { s.minimum_step = 1.0; }, "solver.minimum_step"},
           {[](auto& s) { s.relative_tolerance = 1.0; }, "solver.relative_tolerance"},
           {[](auto& s) { s.relative_tolerance = 1e-300; }, "solver.relative_tolerance"}}) {
    SCOPED_TRACE(field);
    dynamics::ModelDescription model = short_planar_run();
    edit(model.solver);
    TablesInMemory simbody;
    try {
      simulate_in_simbody(model, simbody);
      ADD_FAILURE() << "accepted";
    } catch (const dynamics::ModelError& e) {
      EXPECT_EQ(e.field_path(), field) << e.what();
    }
    EXPECT_TRUE(simbody.tables().empty());
  }
}

TEST(SimulateInSimbody, RefusesAJournalThatStartsBeyondItsClearance) {
  // 5 cm beyond: Simbody ran it for minutes.
  dynamics::ModelDescription model = short_planar_run();
  std::get<dynamics::ClearanceRevoluteDescription>(model.forces.at(0)).journal.point_B.y() += 0.05;
  model.solver.max_steps = 1'000'000;  // ends the run if it is not refused
  TablesInMemory simbody;
  try {
    simulate_in_simbody(model, simbody);
    ADD_FAILURE() << "the run went on";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("clearance joint \"rod-slider clearance\" starts beyond its model"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(simbody.tables().empty());
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

TEST(SimulateInSimbody, RefusesASpringsNegativeStiffnessNamingTheField) {
  // The route builds Simbody's spring, not clearjoint's, and checks it as clearjoint's would.
  dynamics::ModelDescription model = shipped_model("slider_crank_planar_ideal.json");
  dynamics::SpringDamperDescription spring{"weak", "ground", "slider", dynamics::Vector3::Zero(),
                                           dynamics::Vector3::Zero(), {}};
  spring.parameters.stiffness = -1.0;
  model.forces.push_back(spring);
  try {
    SimbodyModel built(model);
    ADD_FAILURE() << "accepted";
  } catch (const dynamics::ModelError& e) {
    EXPECT_STREQ(e.what(), "weak.stiffness = -1: must be >= 0");
  }
}

}  // namespace
}  // namespace clearjoint::simbody
