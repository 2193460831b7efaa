// SPDX-License-Identifier: BSD-3-Clause
// The point load's force, moment and potential at a hand-built pose, and a pendulum hung under a
// point load (in place of gravity) integrated against the small-amplitude closed form.

#include "clearjoint/dynamics/point_load.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/generalised_forces.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {
namespace {

constexpr double kHandValueTolerance = 1e-13;  // sums of products of small integers

void expect_near(const Vector3& actual, const Vector3& expected, double tolerance) {
  EXPECT_LT((actual - expected).cwiseAbs().maxCoeff(), tolerance) << actual.transpose() << " vs "
                                                                   << expected.transpose();
}

TEST(PointLoad, AppliesItsForceAtTheRotatedPointAndAddsItsMoment) {
  // Body at (1, 2, 3) turned 90 degrees about z: the point (0, -1, 0) is at world offset (1, 0, 0).
  SystemKinematics k(1);
  BodyState b;
  b.position_W = Vector3(1, 2, 3);
  b.euler_parameters = Vector4(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
  k.set(0, b);
  const PointLoad load("load", 0, Vector3(0, -1, 0), Vector3(0, 5, 7), Vector3(0.5, 0, 0));
  GeneralisedForces f(k);
  load.add_forces({0.0, k, {}, {}}, f);
  expect_near(f.force_W(0), Vector3(0, 5, 7), kHandValueTolerance);
  // (1, 0, 0) x (0, 5, 7) = (0, -7, 5), plus the couple (0.5, 0, 0).
  expect_near(f.moment_W(0), Vector3(0.5, -7, 5), kHandValueTolerance);
  // -f . x_P, x_P = (2, 2, 3): -(10 + 21).
  EXPECT_NEAR(load.potential_energy(k), -31.0, kHandValueTolerance);
}

TEST(PointLoad, RejectsNonFiniteValuesNamingTheField) {
  try {
    PointLoad("load", 0, Vector3::Zero(), Vector3(0, std::nan(""), 0), Vector3::Zero());
    ADD_FAILURE() << "no exception";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("load.force"), std::string::npos) << e.what();
  }
}

TEST(PointLoad, SwingsAPendulumAtTheSmallAmplitudeFrequency) {
  // A bob of mass m, central inertia Ic, its mass centre L below a revolute joint at the origin
  // (axis z); a point load (0, -F, 0) at the mass centre stands in for gravity. Linearised:
  // theta'' = -(F L / (Ic + m L^2)) theta, theta = theta0 cos(W t). The neglected cubic term
  // shifts the frequency by theta0^2 / 16 (relative): at theta0 = 1e-3 the angle error stays below
  // theta0 (theta0^2 / 16) W t = 1e-3 * 6.3e-8 * 2 pi * 3 periods = 1.2e-9 rad (measured 1.08e-9;
  // the integrator at 1e-11 adds far less). A load off by a fraction f shifts W by f / 2 and the
  // angle by ~1e-2 f.
  constexpr double m = 1.0, Ic = 0.01, L = 0.5, F = 9.81, theta0 = 1e-3;
  constexpr double kSmallAmplitudeBound = 2e-9;
  ModelDescription model;
  model.name = "pendulum under a point load";
  BodyDescription bob;
  bob.properties = {"bob", m, Vector3::Constant(Ic)};
  bob.initial.position_W = Vector3(L * std::sin(theta0), -L * std::cos(theta0), 0.0);
  bob.initial.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitZ(), theta0);
  model.bodies.push_back(bob);
  JointDescription pivot;
  pivot.name = "pivot";
  pivot.type = JointType::revolute;
  pivot.body_i = "ground";
  pivot.body_j = "bob";
  pivot.point_j_B = Vector3(0.0, L, 0.0);
  model.joints.push_back(pivot);
  model.forces.push_back(PointLoadDescription{"weight", "bob", Vector3::Zero(), Vector3(0, -F, 0), Vector3::Zero()});
  model.output_bodies = {"bob"};
  BuiltModel built = build_model(model);
  const double W = std::sqrt(F * L / (Ic + m * L * L));
  IntegratorSettings s;
  s.end_time = 3 * 2 * std::numbers::pi / W;
  s.report_step = s.end_time / 600;
  s.relative_tolerance = s.absolute_tolerance = 1e-11;
  double worst = 0.0;
  std::vector<double> y = built.initial_state;
  integrate(*built.system, y, s, [&](double t, std::span<const double> state) {
    const Vector3 r = built.system->body_state(state, 0).position_W;
    const double theta = std::atan2(r.x(), -r.y());
    worst = std::max(worst, std::abs(theta - theta0 * std::cos(W * t)));
  });
  EXPECT_LT(worst, kSmallAmplitudeBound);
}

}  // namespace
}  // namespace clearjoint::dynamics
