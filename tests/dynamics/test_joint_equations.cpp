// SPDX-License-Identifier: BSD-3-Clause
// Every joint type's Phi against values derived by hand at assembled and displaced poses, and its
// Jacobian and gamma against finite differences of Phi along a motion with constant rdot and
// constant body-frame omega' (so dv/dt = 0 and d2Phi/dt2 = -gamma exactly).

#include "clearjoint/dynamics/joint_equations.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
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

// ---- Phi's value at assembled and displaced poses, derived by hand -----------------------------
//
// Body i at r_i = (1, 2, 3) turned 90 degrees about z (A_i (a, b, c) = (-b, a, c)); its joint point
// (0.5, 0, 0) is at P_i = (1, 2.5, 3). Its axis z' stays z; the perpendiculars the equations use
// are u' = unit_perpendicular(z) = z x x = y and v' = z x u' = -x, in the world u_i = (-1, 0, 0),
// v_i = (0, -1, 0). Body j's joint point is (0, 0, -0.4) on its z axis; assembled, body j is
// unrotated at r_j = P_i - (0, 0, -0.4) = (1, 2.5, 3.4). Displacements of body j below give each
// row's value from those vectors.

// Rotations of unit-size vectors and sums of metre-scale positions: a few ulps of 1.
constexpr double kPhiValueTolerance = 1e-14;

const Vector3 kPointI_B(0.5, 0.0, 0.0), kPointJ_B(0.0, 0.0, -0.4);
const Vector3 kJointPointI_W(1.0, 2.5, 3.0);

BodyState body_i_pose() {
  BodyState i;
  i.position_W = Vector3(1, 2, 3);
  i.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitZ(), std::numbers::pi / 2);
  return i;
}

/// Body j turned by `turn` (a rotation as Euler parameters), its joint point at P_i + offset_W.
BodyState body_j_pose(const Vector4& turn, const Vector3& offset_W = Vector3::Zero()) {
  BodyState j;
  j.euler_parameters = turn;
  j.position_W = kJointPointI_W + offset_W - rotation_from_euler_parameters(turn) * kPointJ_B;
  return j;
}

const Vector4 kUnturned(1.0, 0.0, 0.0, 0.0);

Vector4 turn_about(const Vector3& axis, double angle) { return euler_parameters_from_axis_angle(axis, angle); }

/// Phi of `type` (its axes z on both bodies unless given) built at the assembled pose, evaluated
/// with body j at `j` and time t.
Eigen::VectorXd phi_at(JointType type, const BodyState& j, double t = 0.0, const Vector3& axis_i_B = Vector3::UnitZ(),
                       const Vector3& axis_j_B = Vector3::UnitZ()) {
  JointDescription d = description(type);
  d.point_i_B = kPointI_B;
  d.point_j_B = kPointJ_B;
  d.axis_i_B = axis_i_B;
  d.axis_j_B = axis_j_B;
  SystemKinematics assembled(2), displaced(2);
  assembled.set(0, body_i_pose());
  assembled.set(1, body_j_pose(kUnturned));
  displaced.set(0, body_i_pose());
  displaced.set(1, j);
  ConstraintRows rows;
  JointEquations::build(d, 0, 1, assembled).evaluate(t, displaced, rows);
  return rows.value.head(rows.count);
}

void expect_rows(const Eigen::VectorXd& actual, std::initializer_list<double> expected) {
  ASSERT_EQ(actual.size(), static_cast<Eigen::Index>(expected.size()));
  int k = 0;
  for (const double e : expected) {
    EXPECT_NEAR(actual[k], e, kPhiValueTolerance) << "row " << k;
    ++k;
  }
}

TEST(JointPhi, SphericalIsTheGapBetweenTheTwoPoints) {
  expect_rows(phi_at(JointType::spherical, body_j_pose(turn_about(Vector3(1, 2, 2), 0.7))), {0, 0, 0});
  expect_rows(phi_at(JointType::spherical, body_j_pose(kUnturned, Vector3(0.01, -0.02, 0.03))), {0.01, -0.02, 0.03});
}

TEST(JointPhi, RevoluteIsZeroWhenTurnedAboutItsAxisAndSinAlphaWhenTilted) {
  expect_rows(phi_at(JointType::revolute, body_j_pose(turn_about(Vector3::UnitZ(), 1.1))), {0, 0, 0, 0, 0});
  // Tilted by alpha about x: h_j = (0, -sin alpha, cos alpha); u_i . h_j = 0, v_i . h_j = sin alpha.
  const double alpha = 0.3;
  expect_rows(phi_at(JointType::revolute, body_j_pose(turn_about(Vector3::UnitX(), alpha))),
              {0, 0, 0, 0, std::sin(alpha)});
  expect_rows(phi_at(JointType::revolute, body_j_pose(kUnturned, Vector3(0, 0, 0.05))), {0, 0, 0.05, 0, 0});
}

TEST(JointPhi, UniversalIsTheCosineBetweenItsCrossAxes) {
  // Axis x' on body i (world (0, 1, 0)), x' on body j (world x): perpendicular when assembled.
  // Body j turned by beta about z: h_j = (cos beta, sin beta, 0), h_i . h_j = sin beta. Turned
  // about its own x axis (the cross's freedom) or about y (the other), nothing.
  const double beta = 0.2;
  expect_rows(phi_at(JointType::universal, body_j_pose(turn_about(Vector3::UnitZ(), beta)), 0.0, Vector3::UnitX(),
                     Vector3::UnitX()),
              {0, 0, 0, std::sin(beta)});
  expect_rows(phi_at(JointType::universal, body_j_pose(turn_about(Vector3::UnitX(), 0.9)), 0.0, Vector3::UnitX(),
                     Vector3::UnitX()),
              {0, 0, 0, 0});
  expect_rows(phi_at(JointType::universal, body_j_pose(turn_about(Vector3::UnitY(), 0.9)), 0.0, Vector3::UnitX(),
                     Vector3::UnitX()),
              {0, 0, 0, 0});
}

TEST(JointPhi, CylindricalIsZeroAlongAndAboutItsAxisAndTheOffsetAcrossIt) {
  expect_rows(phi_at(JointType::cylindrical, body_j_pose(turn_about(Vector3::UnitZ(), -2.0), Vector3(0, 0, 0.7))),
              {0, 0, 0, 0});
  // Moved across the axis by d = (0.02, 0.03, 0): u_i . d = -0.02, v_i . d = -0.03.
  expect_rows(phi_at(JointType::cylindrical, body_j_pose(kUnturned, Vector3(0.02, 0.03, 0))), {0, 0, -0.02, -0.03});
  const double alpha = 0.3;
  expect_rows(phi_at(JointType::cylindrical, body_j_pose(turn_about(Vector3::UnitX(), alpha))),
              {0, std::sin(alpha), 0, 0});
}

TEST(JointPhi, TranslationalIsZeroAlongItsAxisAndMinusSinGammaWhenTurnedAboutIt) {
  expect_rows(phi_at(JointType::translational, body_j_pose(kUnturned, Vector3(0, 0, -0.3))), {0, 0, 0, 0, 0});
  // Turned by gamma about z: u_i . A_j (0, -1, 0) = (-1, 0, 0) . (sin gamma, -cos gamma, 0).
  const double gamma = 0.4;
  // Rows: the two axis pairs, the turn pair, then the two offsets (evaluate() orders pairs first).
  expect_rows(phi_at(JointType::translational, body_j_pose(turn_about(Vector3::UnitZ(), gamma))),
              {0, 0, -std::sin(gamma), 0, 0});
  expect_rows(phi_at(JointType::translational, body_j_pose(kUnturned, Vector3(0.02, 0.03, 0))),
              {0, 0, 0, -0.02, -0.03});
}

TEST(JointPhi, FixedIsThePointGapAndTheSinesOfTheRelativeTurn) {
  // Rows x_i . A_j A_i y', x_i . A_j A_i z', y_i . A_j A_i z' (x_i = (0, 1, 0), y_i = (-1, 0, 0)).
  const double gamma = 0.4, alpha = 0.3;
  expect_rows(phi_at(JointType::fixed, body_j_pose(turn_about(Vector3::UnitZ(), gamma))),
              {0, 0, 0, -std::sin(gamma), 0, 0});
  expect_rows(phi_at(JointType::fixed, body_j_pose(turn_about(Vector3::UnitX(), alpha))),
              {0, 0, 0, 0, -std::sin(alpha), 0});
  expect_rows(phi_at(JointType::fixed, body_j_pose(kUnturned, Vector3(0.01, 0, -0.02))), {0.01, 0, -0.02, 0, 0, 0});
}

TEST(JointPhi, AngleDriverIsTheSineOfThePrescribedAngleLessTheActualOne) {
  // description(): angle law 1.7 t - 0.8 t^2 / 2, at t = 0.5: 0.75 rad. Turned by 0.5 rad: sin 0.25.
  expect_rows(phi_at(JointType::angle_driver, body_j_pose(turn_about(Vector3::UnitZ(), 0.5)), 0.5), {std::sin(0.25)});
  expect_rows(phi_at(JointType::angle_driver, body_j_pose(turn_about(Vector3::UnitZ(), 0.75), Vector3(0.1, 0, 0)), 0.5),
              {0});
}

}  // namespace
}  // namespace clearjoint::dynamics
