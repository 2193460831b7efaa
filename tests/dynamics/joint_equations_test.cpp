// SPDX-License-Identifier: BSD-3-Clause
// Every joint type's Jacobian and gamma against finite differences of Phi along a motion with
// constant rdot and constant body-frame omega' (so dv/dt = 0 and d2Phi/dt2 = -gamma exactly).

#include "clearjoint/dynamics/joint_equations.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace clearjoint::dynamics {
namespace {

// Central difference of Phi with h = 1e-6: truncation ~h^2 |Phi'''| ~ 1e-11, rounding
// ~1e-16 / h = 1e-10 for O(1) values; 1e-8 leaves a margin of 100.
constexpr double kFirstDerivativeStep = 1e-6;
constexpr double kJacobianTolerance = 1e-8;
// Second difference with h = 1e-4: truncation ~h^2 |Phi''''| / 12 ~ 1e-8, rounding
// ~4e-16 / h^2 = 4e-8 for O(1) values; 1e-6 leaves a margin of 25.
constexpr double kSecondDerivativeStep = 1e-4;
constexpr double kGammaTolerance = 1e-6;

struct Motion {
  std::array<BodyState, 2> states;
};

BodyState advanced(const BodyState& s, double h) {
  BodyState out = s;
  out.position_W += h * s.velocity_W;
  const Vector3& w = s.angular_velocity_B;
  const Vector4& p = s.euler_parameters;
  const Eigen::Quaterniond q = Eigen::Quaterniond(p[0], p[1], p[2], p[3]) *
                               Eigen::Quaterniond(Eigen::AngleAxisd(w.norm() * h, w.normalized()));
  out.euler_parameters = Vector4(q.w(), q.x(), q.y(), q.z());
  return out;
}

SystemKinematics kinematics_at(const Motion& m, double h) {
  SystemKinematics k(2);
  for (int b = 0; b < 2; ++b) k.set(b, advanced(m.states[b], h));
  return k;
}

Motion random_motion(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Motion m;
  for (BodyState& s : m.states) {
    s.position_W = Vector3(u(rng), u(rng), u(rng));
    s.euler_parameters = Vector4(u(rng), u(rng), u(rng), u(rng)).normalized();
    s.velocity_W = Vector3(u(rng), u(rng), u(rng));
    s.angular_velocity_B = 2.0 * Vector3(u(rng), u(rng), u(rng));
  }
  return m;
}

JointDescription description(JointType type) {
  JointDescription j;
  j.name = std::string(to_string(type));
  j.type = type;
  // One-character names assigned as characters: assigning the literals "a" and "b" trips GCC 12's
  // bogus -Wrestrict in std::string::assign (GCC bug 105329).
  j.body_i = 'a';
  j.body_j = 'b';
  j.point_i_B = Vector3(0.1, -0.2, 0.3);
  j.point_j_B = Vector3(-0.3, 0.05, 0.2);
  j.axis_i_B = Vector3(0.2, 1.0, -0.3);
  j.axis_j_B = Vector3(-0.5, 0.1, 0.9);
  j.angle = {1.7, -0.8};
  return j;
}

void check_against_finite_differences(JointType type, BodyIndex i, BodyIndex j, unsigned seed) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 10; ++trial) {
    const Motion m = random_motion(rng);
    const double t0 = 0.3;
    const JointEquations eq = JointEquations::build(description(type), i, j, kinematics_at(m, 0.0));
    auto phi = [&](double h) {
      ConstraintRows rows;
      eq.evaluate(t0 + h, kinematics_at(m, h), rows);
      return Eigen::VectorXd(rows.value.head(rows.count));
    };
    ConstraintRows rows;
    eq.evaluate(t0, kinematics_at(m, 0.0), rows);
    ASSERT_EQ(rows.count, equation_count(type));
    const int n = rows.count;
    Eigen::Matrix<double, 6, 1> v_i, v_j;
    v_i << m.states[0].velocity_W, m.states[0].angular_velocity_B;
    v_j << m.states[1].velocity_W, m.states[1].angular_velocity_B;
    if (i == kGround) v_i.setZero();
    if (j == kGround) v_j.setZero();
    const Eigen::VectorXd analytic_rate = rows.jacobian_i.topRows(n) * v_i +
                                          rows.jacobian_j.topRows(n) * v_j +
                                          rows.time_derivative.head(n);
    const double h1 = kFirstDerivativeStep;
    const Eigen::VectorXd numeric_rate = (phi(h1) - phi(-h1)) / (2 * h1);
    EXPECT_LT((analytic_rate - numeric_rate).cwiseAbs().maxCoeff(), kJacobianTolerance)
        << to_string(type) << " trial " << trial;
    const double h2 = kSecondDerivativeStep;
    const Eigen::VectorXd numeric_acceleration = (phi(h2) - 2 * phi(0.0) + phi(-h2)) / (h2 * h2);
    EXPECT_LT((rows.gamma.head(n) + numeric_acceleration).cwiseAbs().maxCoeff(), kGammaTolerance)
        << to_string(type) << " trial " << trial;
  }
}

class EveryJointType : public ::testing::TestWithParam<JointType> {};

TEST_P(EveryJointType, HasTheJacobianAndGammaOfItsConstraintFunction) {
  check_against_finite_differences(GetParam(), 0, 1, 11);
}

TEST_P(EveryJointType, HasTheJacobianAndGammaOfItsConstraintFunctionAgainstGround) {
  check_against_finite_differences(GetParam(), kGround, 1, 12);
  check_against_finite_differences(GetParam(), 0, kGround, 13);
}

INSTANTIATE_TEST_SUITE_P(Joints, EveryJointType,
                         ::testing::Values(JointType::spherical, JointType::revolute,
                                           JointType::universal, JointType::cylindrical,
                                           JointType::translational, JointType::fixed,
                                           JointType::angle_driver),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(RevoluteJoint, IsSatisfiedWhenPointsCoincideAndAxesAlign) {
  SystemKinematics k(2);
  BodyState a, b;
  a.position_W = Vector3(1, 2, 3);
  b.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitZ(), 0.4);
  b.position_W = a.position_W + Vector3(0, 0, 0.5) - rotation_from_euler_parameters(b.euler_parameters) * Vector3(0, 0, -0.2);
  k.set(0, a);
  k.set(1, b);
  JointDescription j = description(JointType::revolute);
  j.point_i_B = Vector3(0, 0, 0.5);
  j.point_j_B = Vector3(0, 0, -0.2);
  j.axis_i_B = j.axis_j_B = Vector3::UnitZ();
  ConstraintRows rows;
  JointEquations::build(j, 0, 1, k).evaluate(0.0, k, rows);
  EXPECT_LT(rows.value.head(rows.count).cwiseAbs().maxCoeff(), 1e-15);
}

}  // namespace
}  // namespace clearjoint::dynamics
