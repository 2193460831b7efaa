// SPDX-License-Identifier: BSD-3-Clause
// One small model per joint type, integrated: constraint drift and mechanical energy over the run,
// and, where the motion has a closed form (the cylindrical and translational slides, the driven
// crank), the motion itself.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {
namespace {

constexpr double kGravity = 9.81;
// At integration tolerance 1e-10 over 0.5 s, with Baumgarte alpha = beta = 5, these one- and
// two-body models keep |Phi| below 1.7e-11 and their energy to 1.1e-10 of m g L (measured, the
// worst of the seven). The bounds leave margins of ~60 and ~9; a joint that did work (a wrong
// Jacobian transposed into the reactions) or let its constraint drift would leave them by orders
// of magnitude.
constexpr double kIntegrationTolerance = 1e-10;
constexpr double kConstraintDrift = 1e-9;  // metres (and radians for the orientation rows)
constexpr double kEnergyDrift = 1e-9;      // of the model's energy scale m g L
// The slides' closed form s = g_axial t^2 / 2 is a quadratic, which Dormand-Prince integrates
// exactly: what remains is rounding, measured 1.1e-15 m over the 0.87 m travelled.
constexpr double kClosedFormTolerance = 1e-12;

BodyDescription body(const std::string& name, const Vector3& position_W, double mass = 1.0) {
  BodyDescription b;
  b.properties = {name, mass, Vector3(0.01, 0.02, 0.015)};
  b.initial.position_W = position_W;
  return b;
}

JointDescription joint(JointType type, const std::string& i, const std::string& j, const Vector3& point_i_B,
                       const Vector3& point_j_B, const Vector3& axis_i_B = Vector3::UnitZ(),
                       const Vector3& axis_j_B = Vector3::UnitZ()) {
  JointDescription d;
  d.name = std::string(to_string(type));
  d.type = type;
  d.body_i = i;
  d.body_j = j;
  d.point_i_B = point_i_B;
  d.point_j_B = point_j_B;
  d.axis_i_B = axis_i_B;
  d.axis_j_B = axis_j_B;
  return d;
}

struct ModelRun {
  double max_constraint_violation = 0.0;
  double max_energy_change = 0.0;  ///< max |E(t) - E(0)| [J]
  double max_closed_form_error = 0.0;
  int reports = 0;
};

/// Integrate `model` for 0.5 s; `closed_form(t, body 0's state)` returns the error of the motion
/// against its closed form (0 where there is none).
ModelRun integrate_model(ModelDescription model,
                    const std::function<double(double, const BodyState&)>& closed_form = {}) {
  model.name = "joint model";
  model.gravity_W = Vector3(0.0, -kGravity, 0.0);
  BuiltModel built = build_model(model);
  MultibodySystem& system = *built.system;
  IntegratorSettings s;
  s.end_time = 0.5;
  s.report_step = 5e-3;
  s.relative_tolerance = s.absolute_tolerance = kIntegrationTolerance;
  std::vector<double> y = built.initial_state;
  ModelRun run;
  const double E0 = system.kinetic_energy(y) + system.potential_energy(0.0, y);
  integrate(system, y, s, [&](double t, std::span<const double> state) {
    const ConstraintViolation v = system.constraint_violation(t, state);
    run.max_constraint_violation = std::max(run.max_constraint_violation, v.position);
    const double E = system.kinetic_energy(state) + system.potential_energy(t, state);
    run.max_energy_change = std::max(run.max_energy_change, std::abs(E - E0));
    if (closed_form) {
      run.max_closed_form_error = std::max(run.max_closed_form_error, closed_form(t, system.body_state(state, 0)));
    }
    ++run.reports;
  });
  return run;
}

void expect_drift_and_energy_within_bounds(const ModelRun& run, double energy_scale) {
  EXPECT_EQ(run.reports, 101);
  EXPECT_LT(run.max_constraint_violation, kConstraintDrift);
  EXPECT_LT(run.max_energy_change, kEnergyDrift * energy_scale);
}

TEST(JointModels, ASphericalPendulumKeepsItsPointAndItsEnergy) {
  // Mass centre 0.5 m from the pivot ((0.3, -0.4, 0)), moving out of the plane of swing.
  ModelDescription m;
  m.bodies.push_back(body("bob", Vector3(0.3, -0.4, 0.0)));
  m.bodies[0].initial.velocity_W = Vector3(0.0, 0.0, 1.2);
  m.joints.push_back(joint(JointType::spherical, "ground", "bob", Vector3::Zero(), Vector3(-0.3, 0.4, 0.0)));
  expect_drift_and_energy_within_bounds(integrate_model(m), kGravity * 0.5);
}

TEST(JointModels, ARevolutePendulumKeepsItsAxisAndItsEnergy) {
  ModelDescription m;
  m.bodies.push_back(body("bob", Vector3(0.3, -0.4, 0.0)));
  m.joints.push_back(joint(JointType::revolute, "ground", "bob", Vector3::Zero(), Vector3(-0.3, 0.4, 0.0)));
  expect_drift_and_energy_within_bounds(integrate_model(m), kGravity * 0.5);
}

TEST(JointModels, AUniversalPendulumKeepsItsCrossAxesPerpendicularAndItsEnergy) {
  // Ground axis x, body axis z: the bob swings about both.
  ModelDescription m;
  m.bodies.push_back(body("bob", Vector3(0.0, -0.5, 0.0)));
  m.bodies[0].initial.velocity_W = Vector3(0.4, 0.0, -1.0);          // (2, 0, -0.8) x (0, -0.5, 0)
  m.bodies[0].initial.angular_velocity_B = Vector3(2.0, 0.0, -0.8);  // body axes = world axes
  m.joints.push_back(joint(JointType::universal, "ground", "bob", Vector3::Zero(), Vector3(0.0, 0.5, 0.0),
                           Vector3::UnitX(), Vector3::UnitZ()));
  expect_drift_and_energy_within_bounds(integrate_model(m), kGravity * 0.5);
}

/// The slide axis (1, -1, 0)/sqrt 2 through the origin: gravity's component along it is g / sqrt 2
/// and neither joint transmits an axial force, so the mass centre's axial coordinate from rest is
/// s = g t^2 / (2 sqrt 2) whatever the body does about the axis.
const Vector3 kSlideAxis = Vector3(1.0, -1.0, 0.0).normalized();
double slide_error(double t, const BodyState& b) {
  return std::abs(b.position_W.dot(kSlideAxis) - kGravity * t * t / (2.0 * std::sqrt(2.0)));
}

TEST(JointModels, ACylindricalJointSlidesAsTheAxialClosedFormWhileTheBodySwingsAboutIt) {
  // Mass centre 0.2 m off the axis (along z): gravity turns the body about the axis as it slides.
  ModelDescription m;
  m.bodies.push_back(body("slider", Vector3(0.0, 0.0, 0.2)));
  m.joints.push_back(joint(JointType::cylindrical, "ground", "slider", Vector3::Zero(), Vector3(0.0, 0.0, -0.2),
                           Vector3(1.0, -1.0, 0.0), Vector3(1.0, -1.0, 0.0)));
  Vector4 last_orientation;
  const ModelRun run = integrate_model(m, [&](double t, const BodyState& b) {
    last_orientation = b.euler_parameters;
    return slide_error(t, b);
  });
  expect_drift_and_energy_within_bounds(run, kGravity * 0.2);
  EXPECT_LT(run.max_closed_form_error, kClosedFormTolerance);
  // It did turn about the axis (the cylindrical joint's second freedom): by more than 0.1 rad.
  EXPECT_LT(last_orientation[0], std::cos(0.05));
}

TEST(JointModels, ATranslationalJointSlidesAsTheAxialClosedFormWithoutTurning) {
  ModelDescription m;
  m.bodies.push_back(body("slider", Vector3(0.0, 0.0, 0.2)));
  m.joints.push_back(joint(JointType::translational, "ground", "slider", Vector3::Zero(), Vector3(0.0, 0.0, -0.2),
                           Vector3(1.0, -1.0, 0.0), Vector3(1.0, -1.0, 0.0)));
  double largest_turn = 0.0;
  const ModelRun run = integrate_model(m, [&](double t, const BodyState& b) {
    largest_turn = std::max(largest_turn, b.euler_parameters.tail<3>().norm());
    return slide_error(t, b);
  });
  expect_drift_and_energy_within_bounds(run, kGravity * 0.2);
  EXPECT_LT(run.max_closed_form_error, kClosedFormTolerance);
  EXPECT_LT(largest_turn, kConstraintDrift);
}

TEST(JointModels, AFixedJointMakesTwoBodiesSwingAsOnePendulumKeepingItsEnergy) {
  // A revolute pendulum with a second body welded on at an angle.
  ModelDescription m;
  m.bodies.push_back(body("arm", Vector3(0.0, -0.3, 0.0)));
  m.bodies.push_back(body("weight", Vector3(0.2, -0.6, 0.0), 0.5));
  m.bodies[0].initial.angular_velocity_B = Vector3(0.0, 0.0, 2.0);
  m.bodies[0].initial.velocity_W = Vector3(0.6, 0.0, 0.0);   // (0, 0, 2) x (0, -0.3, 0)
  m.bodies[1].initial.angular_velocity_B = Vector3(0.0, 0.0, 2.0);
  m.bodies[1].initial.velocity_W = Vector3(1.2, 0.4, 0.0);   // (0, 0, 2) x (0.2, -0.6, 0)
  m.joints.push_back(joint(JointType::revolute, "ground", "arm", Vector3::Zero(), Vector3(0.0, 0.3, 0.0)));
  m.joints.push_back(joint(JointType::fixed, "arm", "weight", Vector3(0.2, -0.3, 0.0), Vector3::Zero()));
  expect_drift_and_energy_within_bounds(integrate_model(m), kGravity * 0.6);
}

TEST(JointModels, AnAngleDriverTurnsACrankAtItsPrescribedAngleWithConstantEnergy) {
  // A crank on a revolute joint, mass centre on the axis, driven at 3 rad/s: without gravity
  // torque about the axis its kinetic energy Izz w^2 / 2 is constant, and its angle is 3 t.
  ModelDescription m;
  m.bodies.push_back(body("crank", Vector3::Zero()));
  m.bodies[0].initial.angular_velocity_B = Vector3(0.0, 0.0, 3.0);
  m.joints.push_back(joint(JointType::revolute, "ground", "crank", Vector3::Zero(), Vector3::Zero()));
  JointDescription driver = joint(JointType::angle_driver, "ground", "crank", Vector3::Zero(), Vector3::Zero());
  driver.angle = {3.0, 0.0};
  m.joints.push_back(driver);
  const ModelRun run = integrate_model(m, [](double t, const BodyState& b) {
    const double angle = 2.0 * std::atan2(b.euler_parameters[3], b.euler_parameters[0]);
    return std::abs(std::remainder(angle - 3.0 * t, 2.0 * M_PI));
  });
  expect_drift_and_energy_within_bounds(run, 0.015 * 9.0 / 2.0);
  EXPECT_LT(run.max_closed_form_error, kConstraintDrift);
}

}  // namespace
}  // namespace clearjoint::dynamics
