// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/integrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

using test::PendulumParameters;
using test::pendulum_model;

constexpr double kIntegrationTolerance = 1e-10;
// The period is measured from zero crossings interpolated linearly between samples 1e-3 s apart;
// near a crossing x'' = 0, so the interpolation error is O(omega^2 dt^3) ~ 1e-9 s and largely the
// same at every crossing. Over 5 periods (7 s) that leaves 1e-9 relative; 1e-8 is the bound.
constexpr double kPeriodTolerance = 1e-8;
constexpr double kEnergyTolerance = 1e-8;

std::vector<double> upward_crossings(BuiltModel& built, const IntegratorSettings& settings) {
  std::vector<double> crossings;
  double last_t = 0.0, last_x = 0.0;
  std::vector<double> y = built.initial_state;
  integrate(*built.system, y, settings, [&](double t, std::span<const double> state) {
    const double x = state[0];
    if (t > settings.start_time && last_x < 0.0 && x >= 0.0) {
      crossings.push_back(last_t + (t - last_t) * (-last_x) / (x - last_x));
    }
    last_t = t;
    last_x = x;
  });
  return crossings;
}

TEST(Pendulum, SwingsWithTheSmallAnglePeriod) {
  const PendulumParameters p;  // theta0 = 0.01 rad
  BuiltModel built = build_model(pendulum_model(p));
  const double pivot_inertia = p.central_inertia + p.mass * p.length * p.length;
  const double small_angle_period =
      2 * M_PI * std::sqrt(pivot_inertia / (p.mass * test::kStandardGravity * p.length));
  // Finite amplitude: T = T0 (1 + theta0^2/16 + 11 theta0^4/3072 + ...); the theta0^4 term is
  // 4e-11 here, below the tolerance.
  const double expected = small_angle_period * (1 + p.initial_angle * p.initial_angle / 16);
  IntegratorSettings settings;
  settings.end_time = 5.2 * small_angle_period;
  settings.report_step = 1e-3;
  settings.relative_tolerance = settings.absolute_tolerance = kIntegrationTolerance;
  const std::vector<double> crossings = upward_crossings(built, settings);
  ASSERT_EQ(crossings.size(), 5u);
  const double period = (crossings.back() - crossings.front()) / 4.0;
  EXPECT_NEAR(period / expected, 1.0, kPeriodTolerance);
  // and the small-angle formula itself is right to the amplitude correction, 6e-6:
  EXPECT_NEAR(period / small_angle_period, 1.0, 1e-5);
  EXPECT_GT(std::abs(period / small_angle_period - 1.0), 1e-6);
}

TEST(Pendulum, KeepsItsEnergyOverLargeSwings) {
  PendulumParameters p;
  p.initial_angle = 1.0;
  BuiltModel built = build_model(pendulum_model(p));
  MultibodySystem& system = *built.system;
  std::vector<double> y = built.initial_state;
  const double E0 = system.kinetic_energy(y) + system.potential_energy(0.0, y);
  const double energy_scale = p.mass * test::kStandardGravity * p.length;
  double worst = 0.0;
  IntegratorSettings settings;
  settings.end_time = 5.0;
  settings.report_step = 1e-2;
  settings.relative_tolerance = settings.absolute_tolerance = kIntegrationTolerance;
  integrate(system, y, settings, [&](double t, std::span<const double> state) {
    const double E = system.kinetic_energy(state) + system.potential_energy(t, state);
    worst = std::max(worst, std::abs(E - E0) / energy_scale);
  });
  EXPECT_LT(worst, kEnergyTolerance);
}

/// A force that turns into NaN after t = 0.05 s, to provoke a non-finite state.
class PoisonedForce final : public ForceElement {
 public:
  std::string_view name() const override { return "poison"; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override {
    if (context.time > 0.05) forces.add_force(0, Vector3::Constant(std::numeric_limits<double>::quiet_NaN()));
  }
};

TEST(Integrator, StopsWithAClearErrorWhenTheStateStopsBeingFinite) {
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<PoisonedForce>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  std::vector<double> y = system.pack(std::vector<BodyState>{BodyState{}});
  IntegratorSettings settings;
  settings.end_time = 1.0;
  settings.report_step = 0.01;
  try {
    integrate(system, y, settings, [](double, std::span<const double>) {});
    FAIL() << "integration went on with NaN";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_TRUE(message.find("no longer finite") != std::string::npos ||
                message.find("collapsed") != std::string::npos ||
                message.find("no acceptable step") != std::string::npos)
        << message;
  }
}

/// A stiff force k x with k so large the explicit stepper cannot keep a step above the minimum.
class RunawayForce final : public ForceElement {
 public:
  std::string_view name() const override { return "runaway"; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override {
    const double x = context.kinematics.body(0).position_W.x();
    forces.add_force(0, Vector3(x * x * x * 1e6, 0.0, 0.0));  // blows up in finite time
  }
};

TEST(Integrator, StopsWithAClearErrorWhenTheStepCollapses) {
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<RunawayForce>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.position_W.x() = 1.0;
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 1.0;
  settings.report_step = 0.01;
  settings.minimum_step = 1e-9;
  EXPECT_THROW(integrate(system, y, settings, [](double, std::span<const double>) {}), SolverError);
}

/// A linear spring so stiff that the explicit stepper's stability limit keeps every step near
/// 3e-10 s (omega = 1e10 rad/s): legal steps, far above minimum_step, and a run of hours.
class VeryStiffSpring final : public ForceElement {
 public:
  std::string_view name() const override { return "stiff"; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override {
    const double x = context.kinematics.body(0).position_W.x();
    forces.add_force(0, Vector3(-1e20 * x, 0.0, 0.0));
  }
};

TEST(Integrator, StopsEarlyNamingTheStepWhenTheStepsLeftWouldExceedTheBudget) {
  // The budget is projected every kStallWindowSteps steps: the run stops after the first window,
  // not after max_steps, and says why.
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<VeryStiffSpring>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.position_W.x() = 1e-3;
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 0.01;  // some 3e7 steps of 3e-10 s
  settings.report_step = 0.01;
  settings.max_steps = 10'000'000;
  long steps = 0;
  try {
    integrate(system, y, settings, [](double, std::span<const double>) {}, [&](double) { ++steps; });
    FAIL() << "the run went on";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the step size has collapsed to a mean of"), std::string::npos) << message;
    EXPECT_NE(message.find("more than solver.max_steps = 10000000"), std::string::npos) << message;
  }
  EXPECT_EQ(steps, kStallWindowSteps - 1);  // the monitor is not called for the step that stopped it
}

TEST(Integrator, StopsACollapsedRunWithinItsStallWallTimeAlsoWhenItsStepsFitTheBudget) {
  // 4 ms at 1.5e-11 s a step: some 2.7e8 steps, under a max_steps of 1e9, so the step budget
  // lets it run for many minutes; the stall rule, on a stall_wall_time shortened to 0.2 s, stops
  // it after about 0.1 s of wall time.
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<VeryStiffSpring>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.position_W.x() = 1e-3;
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 0.004;
  settings.report_step = 0.004;
  settings.max_steps = 1'000'000'000;
  settings.stall_wall_time = 0.2;
  constexpr long kWentOn = 1'000'000;  // steps: seconds of wall time
  long steps = 0;
  try {
    integrate(system, y, settings, [](double, std::span<const double>) {}, [&](double) {
      if (++steps == kWentOn) throw std::runtime_error("the run went on past 1,000,000 steps");
    });
    FAIL() << "the run finished";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the step size has collapsed to a mean of"), std::string::npos) << message;
    EXPECT_NE(message.find("(the stall rule"), std::string::npos) << message;
  }
  EXPECT_LT(steps, kWentOn);
}

TEST(Integrator, RunsOnWhenTheProjectedStepsStayWithinTheBudget) {
  // The same spring over a span that fits the budget: 1e-5 s is some 30,000 steps.
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<VeryStiffSpring>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.position_W.x() = 1e-3;
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 1e-5;
  settings.report_step = 1e-5;
  settings.initial_step = 1e-12;
  const IntegrationStatistics stats = integrate(system, y, settings, [](double, std::span<const double>) {});
  EXPECT_GT(stats.steps, 1000);
}

TEST(Integrator, CallsTheStepMonitorWithTimesInOrderWithTheReports) {
  // Reports inside a step come before the monitor's call for the step's end.
  std::vector<std::unique_ptr<ForceElement>> forces;
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  std::vector<double> y = system.pack(std::vector<BodyState>{BodyState{}});
  IntegratorSettings settings;
  settings.end_time = 1.0;
  settings.report_step = 1e-3;
  std::vector<double> times;
  integrate(system, y, settings, [&](double t, std::span<const double>) { times.push_back(t); },
            [&](double t) { times.push_back(t); });
  EXPECT_GT(times.size(), 1001u);
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
}

/// Keeps a count of the accepted states it is shown (update_extra_state) in its one extra state
/// variable, and notes every value its force evaluation (trial stages included) reads there. Its
/// force is a stiff one-sided spring at x = 0.5 m, whose onset makes the controller reject steps.
class AcceptedStateCounter final : public ForceElement, public ForceEvents {
 public:
  std::string_view name() const override { return "counter"; }
  int extra_state_count() const override { return 1; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override {
    const double seen = context.extra_state[0];
    if (seen != std::floor(seen) || seen < 1.0 || seen > static_cast<double>(updates)) ++foreign_values;
    const double x = context.kinematics.body(0).position_W.x();
    forces.add_force(0, Vector3(x > 0.5 ? -1e6 * (x - 0.5) : 0.0, 0.0, 0.0));
  }
  bool update_extra_state(double, const SystemKinematics&, std::span<double> state) const override {
    state[0] += 1.0;
    ++updates;
    return true;
  }
  mutable long updates = 0;
  mutable long foreign_values = 0;  ///< values read that no accepted update wrote
};

TEST(Integrator, ChangesExtraStateOnlyAtAcceptedStepsEvenWhenStepsAreRejected) {
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<AcceptedStateCounter>());
  const auto& counter = dynamic_cast<const AcceptedStateCounter&>(*forces.back());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.velocity_W.x() = 1.0;  // reaches the spring at t = 0.5 s and bounces
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 1.0;
  settings.report_step = 0.01;
  const IntegrationStatistics stats = integrate(system, y, settings, [](double, std::span<const double>) {});
  // Dormand-Prince takes 6 new evaluations per attempt (the 7th is reused, FSAL) and 1 more after
  // each restart: more than 7 per accepted step means some attempts were rejected.
  EXPECT_GT(stats.derivative_calls, 7 * stats.steps + 1);
  // One update at the start and one after every accepted step but the last (the run ends there).
  EXPECT_EQ(counter.updates, stats.steps);
  EXPECT_EQ(stats.restarts, stats.steps);
  EXPECT_EQ(counter.foreign_values, 0);
}

/// A stiff one-sided spring at x = 0.5 m that a ball at 1 m/s penetrates by 1 mm at most, and a
/// right-hand side undefined (SolverError) beyond x = 0.52 m, where only trial stages of steps that
/// are too long can go.
class WallWithUndefinedBeyond final : public ForceElement {
 public:
  std::string_view name() const override { return "wall"; }
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override {
    const double x = context.kinematics.body(0).position_W.x();
    if (x > 0.52) throw SolverError("undefined beyond x = 0.52 m");
    forces.add_force(0, Vector3(x > 0.5 ? -1e6 * (x - 0.5) : 0.0, 0.0, 0.0));
  }
};

TEST(Integrator, RetriesAShorterStepWhenATrialStageCannotBeEvaluated) {
  std::vector<std::unique_ptr<ForceElement>> forces;
  forces.push_back(std::make_unique<WallWithUndefinedBeyond>());
  MultibodySystem system({{"ball", 1.0, Vector3(1, 1, 1)}}, {}, std::move(forces), {});
  BodyState s;
  s.position_W.x() = 0.45;
  s.velocity_W.x() = 1.0;
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  IntegratorSettings settings;
  settings.end_time = 0.2;
  settings.report_step = 0.01;
  settings.initial_step = 0.1;  // its stages reach x = 0.55
  settings.relative_tolerance = settings.absolute_tolerance = 1e-10;
  double largest_x = 0.0;
  const IntegrationStatistics stats = integrate(system, y, settings, [&](double, std::span<const double> state) {
    largest_x = std::max(largest_x, state[0]);
  });
  EXPECT_GE(stats.failed_attempts, 1);
  // The linear wall (omega = 1000 rad/s) stops the ball at 0.5 + v / omega = 0.501 m: the solution
  // never goes near the undefined region.
  EXPECT_LT(largest_x, 0.502);
  // And comes back elastically at 1 m/s (x velocity). The wall force's derivative jumps at
  // x = 0.5, which the steps straddling it do not resolve to the integrator's order; the error
  // then follows the tolerance less than linearly: measured 6.4e-6 m/s at 1e-7 and 1.1e-9 at the
  // 1e-10 used here. The bound leaves a margin of 9.
  constexpr double kReboundTolerance = 1e-8;
  EXPECT_NEAR(y[7], -1.0, kReboundTolerance);
}

/// validate()'s message for `settings` changed by `edit` ("accepted" when it passes).
template <typename Edit>
std::string refusal(Edit edit) {
  IntegratorSettings settings;
  edit(settings);
  try {
    validate(settings);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(IntegratorSettings, RejectARelativeToleranceOutsideTheRangeDoublePrecisionCanMeetNamingIt) {
  // Simbody's setAccuracy aborts at 1; at 1e-300 odeint's steps shrink until the run stalls.
  EXPECT_EQ(refusal([](auto& s) { s.relative_tolerance = 1.0; }),
            "solver.relative_tolerance = 1: must be in [1e-14, 0.1]");
  EXPECT_EQ(refusal([](auto& s) { s.relative_tolerance = 1e-300; }),
            "solver.relative_tolerance = 1e-300: must be in [1e-14, 0.1]");
  EXPECT_EQ(refusal([](auto& s) { s.relative_tolerance = kMaxRelativeTolerance; }), "accepted");
  EXPECT_EQ(refusal([](auto& s) { s.relative_tolerance = kMinRelativeTolerance; }), "accepted");
}

TEST(IntegratorSettings, RejectAMinimumStepThatNoStepOfTheRunCouldRespectNamingIt) {
  // Simbody aborts on minimum_step 1.0 in a 1 s run reported every 1e-5 s.
  EXPECT_EQ(refusal([](auto& s) { s.minimum_step = 1.0; }),
            "solver.minimum_step = 1: must be shorter than the run, solver.end_time - solver.start_time = 1 s");
  EXPECT_EQ(refusal([](auto& s) { s.minimum_step = 1e-5; }),
            "solver.minimum_step = 1.0000000000000001e-05: must be shorter than solver.report_step = "
            "1.0000000000000001e-05 s");
  EXPECT_EQ(refusal([](auto& s) { s.minimum_step = 2e-6; }),
            "solver.minimum_step = 1.9999999999999999e-06: must not be longer than solver.initial_step = "
            "9.9999999999999995e-07 s");
  EXPECT_EQ(refusal([](auto& s) { s.stall_wall_time = 0.0; }), "solver.stall_wall_time = 0: must be positive");
}

TEST(IntegratorSettings, KeepTheFieldPathOfARefusedSetting) {
  IntegratorSettings settings;
  settings.minimum_step = 1.0;
  try {
    validate(settings);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_EQ(e.field_path(), "solver.minimum_step");
  }
}

TEST(IntegratorSettings, RejectAStepBudgetOutsideOneToOneE15NamingItsFieldPath) {
  // The one range of solver.max_steps, for a model file, Python's builder and every engine.
  EXPECT_EQ(refusal([](auto& s) { s.max_steps = 0; }), "solver.max_steps = 0: must be in [1, 1e15]");
  EXPECT_EQ(refusal([](auto& s) { s.max_steps = 2'000'000'000'000'000; }),
            "solver.max_steps = 2000000000000000: must be in [1, 1e15]");
  EXPECT_EQ(refusal([](auto& s) { s.max_steps = 1'000'000'000'000'000; }), "accepted");
  const auto path_of = [](auto edit) {
    IntegratorSettings settings;
    edit(settings);
    try {
      validate(settings);
    } catch (const ModelError& e) {
      return std::string(e.field_path());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(path_of([](auto& s) { s.max_steps = 0; }), "solver.max_steps");
  EXPECT_EQ(path_of([](auto& s) { s.end_time = s.start_time; }), "solver.end_time");
  EXPECT_EQ(path_of([](auto& s) { s.report_step = 1e-300; }), "solver.report_step");
}

TEST(IntegratorSettings, RejectNonPositiveToleranceNamingTheField) {
  IntegratorSettings settings;
  settings.relative_tolerance = 0.0;
  try {
    validate(settings);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "solver.relative_tolerance = 0: must be positive");
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
