// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/multibody_system.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/gravity.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"

namespace clearjoint::dynamics {
namespace {

// Integrating at tolerance 1e-10 for 10 s: the global error of Dormand-Prince stays within
// ~100 x the local tolerance for these smooth, non-stiff motions, hence 1e-8.
constexpr double kIntegrationTolerance = 1e-10;
constexpr double kConservationTolerance = 1e-8;

TEST(TorqueFreeAsymmetricBody, ConservesEnergyAndAngularMomentum) {
  // Spinning mostly about the intermediate principal axis: the tumbling (Dzhanibekov) motion,
  // the hardest torque-free case for an integrator.
  const Vector3 inertia(0.01, 0.02, 0.035);
  std::vector<BodyProperties> bodies{{"tumbler", 2.0, inertia}};
  MultibodySystem system(bodies, {}, {}, {});
  BodyState s;
  s.euler_parameters = euler_parameters_from_axis_angle(Vector3(1, -2, 0.5), 0.8);
  s.velocity_W = Vector3(0.1, 0.2, -0.3);
  s.angular_velocity_B = Vector3(0.05, 6.0, 0.1);
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  auto momentum_W = [&](std::span<const double> state) {
    const BodyState b = system.body_state(state, 0);
    return Vector3(rotation_from_euler_parameters(b.euler_parameters.normalized()) *
                   inertia.cwiseProduct(b.angular_velocity_B));
  };
  const double E0 = system.kinetic_energy(y);
  const Vector3 H0 = momentum_W(y);
  double worst_energy = 0.0, worst_momentum = 0.0, worst_norm = 0.0;
  double smallest_omega_y = 6.0;
  IntegratorSettings settings;
  settings.end_time = 10.0;
  settings.report_step = 1e-2;
  settings.relative_tolerance = settings.absolute_tolerance = kIntegrationTolerance;
  integrate(system, y, settings, [&](double, std::span<const double> state) {
    worst_energy = std::max(worst_energy, std::abs(system.kinetic_energy(state) - E0) / E0);
    worst_momentum = std::max(worst_momentum, (momentum_W(state) - H0).norm() / H0.norm());
    const Vector4 p = system.body_state(state, 0).euler_parameters;
    worst_norm = std::max(worst_norm, std::abs(p.norm() - 1.0));
    smallest_omega_y = std::min(smallest_omega_y, system.body_state(state, 0).angular_velocity_B.y());
  });
  EXPECT_LT(smallest_omega_y, 0.0) << "the body never flipped: not the tumbling motion intended";
  EXPECT_LT(worst_energy, kConservationTolerance);
  EXPECT_LT(worst_momentum, kConservationTolerance);
  EXPECT_LT(worst_norm, kConservationTolerance);
}

TEST(MultibodySystem, AppliesTheGyroscopicTermOfNewtonEuler) {
  // Free body, no forces: J' domega'/dt = -omega' x J' omega' (eq. 35).
  const Vector3 inertia(1.0, 2.0, 3.0);
  MultibodySystem system({{"top", 1.0, inertia}}, {}, {}, {});
  BodyState s;
  s.angular_velocity_B = Vector3(1.0, 2.0, 3.0);
  std::vector<double> y = system.pack(std::vector<BodyState>{s});
  std::vector<double> rate(y.size());
  system.derivative(0.0, y, rate);
  const Vector3 w = s.angular_velocity_B;
  const Vector3 expected = -(w.cross(inertia.cwiseProduct(w))).cwiseQuotient(inertia);
  EXPECT_LT((system.accelerations().tail<3>() - expected).norm(), 1e-15);
}

TEST(MultibodySystem, RightHandSideReadsTheJointBlocksWithoutStackingThem) {
  // The spatial slider-crank with its clearance joint (Section 6.2): the constraint solve uses
  // each joint's blocks; the stacked m x 6n Phi_q is for reactions and residuals only.
  BuiltModel built = build_model(test::shipped_model("slider_crank_spatial_clearance.json"));
  MultibodySystem& system = *built.system;
  std::vector<double> rate(built.initial_state.size());
  const long before = system.constraints().dense_assemblies();
  for (int k = 0; k < 3; ++k) system.derivative(0.0, built.initial_state, rate);
  EXPECT_EQ(system.constraints().dense_assemblies(), before);
  const ConstraintViolation violation = system.constraint_violation(0.0, built.initial_state);
  EXPECT_EQ(system.constraints().dense_assemblies(), before + 1);
  EXPECT_LT(violation.position, 1e-12);
}

TEST(MultibodySystem, ReportsRedundantJointsWhenSolving) {
  SystemKinematics initial(1);
  initial.set(0, BodyState{});
  std::vector<JointEquations> joints;
  for (const char* name : {"first hinge", "same hinge again"}) {
    JointDescription j;
    j.name = name;
    j.type = JointType::revolute;
    j.body_i = "ground";
    j.body_j = "door";
    joints.push_back(JointEquations::build(j, kGround, 0, initial));
  }
  MultibodySystem system({{"door", 1.0, Vector3(1, 1, 1)}}, std::move(joints), {}, {});
  std::vector<double> y = system.pack(std::vector<BodyState>{BodyState{}});
  std::vector<double> rate(y.size());
  EXPECT_THROW(system.derivative(0.0, y, rate), SolverError);
}

TEST(MultibodySystem, RejectsNonPositiveMassNamingTheField) {
  try {
    MultibodySystem system({{"brick", -0.3, Vector3(1, 1, 1)}}, {}, {}, {});
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "bodies[0].mass = -0.29999999999999999: must be positive");
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
