// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

/// A free ball falling under gravity: x = x0 + v0 t + g t^2 / 2 exactly for any step.
ModelDescription falling_ball(double end_time) {
  ModelDescription model;
  BodyDescription ball;
  ball.properties.name = "ball";
  ball.properties.mass = 2.0;
  ball.properties.principal_inertia = Vector3(1.0, 1.0, 1.0);
  model.bodies.push_back(ball);
  model.gravity_W = Vector3(0.0, 0.0, -9.81);
  model.solver.end_time = end_time;
  model.solver.report_step = 0.01;
  model.output_bodies = {"ball"};
  return model;
}

ModelDescription short_clearance_run() {
  ModelDescription model = test::shipped_model("slider_crank_spatial_clearance.json");
  model.solver.end_time = 0.05;
  model.solver.report_step = 1e-3;
  return model;
}

TEST(Simulator, SteppedToTheEndGivesTheStateIntegrateGivesBitForBit) {
  const ModelDescription model = short_clearance_run();
  const BuiltModel built = build_model(model);
  std::vector<double> y = built.initial_state;
  const IntegrationStatistics reference = integrate(*built.system, y, model.solver, {});
  Simulator sim(model);
  std::vector<double> last_report;
  sim.start([&](double, std::span<const double> state) { last_report.assign(state.begin(), state.end()); });
  while (!sim.finished()) sim.step();
  EXPECT_EQ(last_report, y);
  EXPECT_EQ(sim.statistics().steps, reference.steps);
  EXPECT_EQ(sim.statistics().derivative_calls, reference.derivative_calls);
}

TEST(Simulator, AdvanceToLandsOnTheTimeAsked) {
  Simulator sim(short_clearance_run());
  for (const double t : {1e-4, 3.3e-3, 1e-2, 0.02, 0.05}) {
    sim.advance_to(t);
    EXPECT_NEAR(sim.time(), t, 4 * std::numeric_limits<double>::epsilon() * t) << t;
  }
  EXPECT_TRUE(sim.finished());
}

TEST(Simulator, RefusesToAdvanceBackwardsOrPastTheEnd) {
  Simulator sim(short_clearance_run());
  sim.advance_to(0.01);
  EXPECT_THROW(sim.advance_to(0.005), ModelError);
  EXPECT_THROW(sim.advance_to(0.06), ModelError);
}

TEST(Simulator, AnAppliedForceAddsItsUniformAcceleration) {
  // F = m a on a free ball: the displacement against the ball without the load is F t^2 / (2m).
  const double force = 4.0, t = 0.5;
  Simulator loaded(falling_ball(1.0)), free(falling_ball(1.0));
  loaded.apply_load("ball", Vector3(force, 0.0, 0.0), Vector3::Zero());
  loaded.advance_to(t);
  free.advance_to(t);
  const double expected = force * t * t / (2.0 * 2.0);
  EXPECT_NEAR(loaded.body_state("ball").position_W.x() - free.body_state("ball").position_W.x(), expected, 1e-9);
  EXPECT_NEAR(loaded.body_state("ball").position_W.z(), free.body_state("ball").position_W.z(), 1e-12);
}

TEST(Simulator, ClearingTheLoadsStopsTheirAcceleration) {
  Simulator sim(falling_ball(1.0));
  sim.apply_load("ball", Vector3(4.0, 0.0, 0.0), Vector3::Zero());
  sim.advance_to(0.25);
  const double speed = sim.body_state("ball").velocity_W.x();
  sim.clear_loads();
  sim.advance_to(0.75);
  EXPECT_NEAR(speed, 4.0 / 2.0 * 0.25, 1e-9);
  EXPECT_NEAR(sim.body_state("ball").velocity_W.x(), speed, 1e-12);
}

TEST(Simulator, NamesAnUnknownBodyOrAJointThatIsNoClearanceJoint) {
  Simulator sim(short_clearance_run());
  EXPECT_THROW(sim.apply_load("nobody", Vector3::Zero(), Vector3::Zero()), ModelError);
  EXPECT_THROW(sim.apply_load("ground", Vector3::Zero(), Vector3::Zero()), ModelError);
  EXPECT_THROW(sim.apply_load("crank", Vector3(NAN, 0, 0), Vector3::Zero()), ModelError);
  EXPECT_THROW(sim.joint_state("crank-rod"), ModelError);
}

TEST(Simulator, ReportsEveryImpactOnceInTimeOrder) {
  Simulator sim(short_clearance_run());
  std::vector<ImpactEvent> impacts;
  while (!sim.finished()) {
    sim.advance_to(std::min(sim.time() + 5e-3, sim.end_time()));
    for (ImpactEvent& e : sim.take_impacts()) impacts.push_back(std::move(e));
  }
  ASSERT_FALSE(impacts.empty());
  for (size_t k = 1; k < impacts.size(); ++k) EXPECT_LE(impacts[k - 1].time, impacts[k].time);
  for (const ImpactEvent& e : impacts) {
    EXPECT_EQ(e.joint, "ground-crank clearance");
    EXPECT_GT(e.impact_speed, 0.0);
  }
  EXPECT_TRUE(sim.take_impacts().empty());
}

TEST(Simulator, GivesTheClearanceJointsContactsAtTheCurrentState) {
  Simulator sim(short_clearance_run());
  sim.advance_to(0.02);
  const ClearanceJointState state = sim.joint_state("ground-crank clearance");
  EXPECT_GE(state.contacts.contact_count, 0);
  EXPECT_TRUE(state.force_on_journal_W.allFinite());
}

TEST(Simulator, ContinuesFromAStateSetBetweenSteps) {
  Simulator sim(falling_ball(1.0));
  sim.advance_to(0.5);
  std::vector<double> y(sim.state().begin(), sim.state().end());
  y[2] = 100.0;  // z of the ball
  sim.set_state(y);
  EXPECT_EQ(sim.body_state("ball").position_W.z(), 100.0);
  sim.advance_to(0.6);
  EXPECT_LT(sim.body_state("ball").position_W.z(), 100.0);
  EXPECT_THROW(sim.set_state(std::vector<double>(3, 0.0)), ModelError);
}

TEST(Simulator, RefusesAStateWithZeroOrNonUnitEulerParametersLeavingItUsable) {
  // A zero quaternion once left the simulator failing every step ("Jacobian lost rank").
  Simulator sim(short_clearance_run());
  sim.advance_to(1e-3);
  const std::vector<double> before(sim.state().begin(), sim.state().end());
  for (const double scale : {0.0, 0.5, 1.0 + 1e-5}) {
    SCOPED_TRACE(scale);
    std::vector<double> y = before;
    for (int k = 3; k < 7; ++k) y[k] *= scale;  // the first body's Euler parameters
    try {
      sim.set_state(y);
      ADD_FAILURE() << "accepted";
    } catch (const ModelError& e) {
      EXPECT_EQ(e.field_path(), "state[3:7]");
      EXPECT_NE(std::string(e.what()).find("must have norm 1 (within 1e-06)"), std::string::npos) << e.what();
    }
    EXPECT_EQ(std::vector<double>(sim.state().begin(), sim.state().end()), before);
  }
  sim.advance_to(2e-3);  // still usable
  EXPECT_NEAR(sim.time(), 2e-3, 1e-15);
}

TEST(Simulator, RefusesANonFiniteStateNamingTheEntry) {
  Simulator sim(short_clearance_run());
  std::vector<double> y(sim.state().begin(), sim.state().end());
  y[8] = NAN;
  try {
    sim.set_state(y);
    FAIL() << "accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.field_path(), "state[8]");
  }
}

TEST(SimulationRun, BuildsTheModelOnceAndPlansItsTablesBeforeTheRun) {
  const SimulationRun run(short_clearance_run());
  std::vector<std::string> names;
  for (const TablePlan& t : run.tables()) names.push_back(t.name);
  EXPECT_EQ(names, (std::vector<std::string>{"body_crank", "body_rod", "body_slider", "energy", "reactions",
                                              "force_ground-crank_clearance"}));
  double columns = 0;
  for (const TablePlan& t : run.tables()) columns += static_cast<double>(t.header.size());
  EXPECT_EQ(run.size().columns, columns);
  EXPECT_EQ(run.size().report_rows, 51.0);
}

TEST(SimulationRun, WritesEveryDecimationthRowAndTheLast) {
  ModelDescription model = short_clearance_run();
  model.output_decimation = 7;
  SimulationRun run(model);
  TablesInMemory tables;
  run.run(tables);
  const auto& energy = tables.tables()[3];
  ASSERT_EQ(energy.name, "energy");
  // 51 report times (0 .. 50 ms): indices 0, 7, .., 49 and the last, 50.
  EXPECT_EQ(energy.rows(), 9u);
  EXPECT_EQ(energy.values[energy.values.size() - energy.header.size()], 0.05);
}

TEST(SimulationRun, RefusesARunBeyondTheSizeGuardUnlessAllowed) {
  ModelDescription model = falling_ball(2000.0);
  model.solver.report_step = 100.0;
  EXPECT_THROW(SimulationRun{model}, ModelError);
  EXPECT_NO_THROW(SimulationRun(model, RunOptions{.allow_large = true}));
}

}  // namespace
}  // namespace clearjoint::dynamics
