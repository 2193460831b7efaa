// SPDX-License-Identifier: BSD-3-Clause
// The spring-damper's forces and energy at hand-built poses (a 3-4-5 line of action), and a body
// on a spring-damper integrated against the damped oscillator's closed form.

#include "clearjoint/dynamics/spring_damper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/generalised_forces.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {
namespace {

// The hand-derived values below are sums of a few products of small integers and tenths: each is
// exact or within an ulp or two of numbers of order 10-50.
constexpr double kHandValueTolerance = 1e-13;

/// Body 0 at (-1, 0, 0), unrotated, at rest, its point (1, 0, 0): P_i = origin. Body 1 at
/// (2, 4, 0) turned 90 degrees about z, its point (0, -1, 0) -> world offset (1, 0, 0): P_j =
/// (3, 4, 0), so d = P_j - P_i = (3, 4, 0), l = 5, direction (0.6, 0.8, 0). Body 1 moves at
/// (1, 2, 0) and spins at 0.5 rad/s about z: P_j's velocity is (1, 2, 0) + (0, 0, 0.5) x (1, 0, 0)
/// = (1, 2.5, 0), so dl/dt = 0.6 + 2.0 = 2.6.
SystemKinematics three_four_five_pose() {
  SystemKinematics k(2);
  BodyState i, j;
  i.position_W = Vector3(-1, 0, 0);
  j.position_W = Vector3(2, 4, 0);
  j.euler_parameters = Vector4(std::sqrt(0.5), 0, 0, std::sqrt(0.5));  // 90 degrees about z
  j.velocity_W = Vector3(1, 2, 0);
  j.angular_velocity_B = Vector3(0, 0, 0.5);
  k.set(0, i);
  k.set(1, j);
  return k;
}

const Vector3 kPointI_B(1, 0, 0), kPointJ_B(0, -1, 0);

void expect_near(const Vector3& actual, const Vector3& expected, double tolerance) {
  EXPECT_LT((actual - expected).cwiseAbs().maxCoeff(), tolerance) << actual.transpose() << " vs "
                                                                   << expected.transpose();
}

GeneralisedForces forces_of(const ForceElement& element, const SystemKinematics& k) {
  GeneralisedForces forces(k);
  element.add_forces({0.0, k, {}, {}}, forces);
  return forces;
}

TEST(SpringDamper, PullsBothPointsTogetherWithStiffnessTimesStretchPlusDampingTimesRate) {
  // k = 10 N/m, c = 5 N s/m, l0 = 2 m: tension 10 (5 - 2) + 5 (2.6) = 43 N along (0.6, 0.8, 0).
  const SpringDamper spring("s", 0, kPointI_B, 1, kPointJ_B, {10.0, 5.0, 2.0});
  const SystemKinematics k = three_four_five_pose();
  const GeneralisedForces f = forces_of(spring, k);
  expect_near(f.force_W(0), Vector3(25.8, 34.4, 0), kHandValueTolerance);
  expect_near(f.force_W(1), Vector3(-25.8, -34.4, 0), kHandValueTolerance);
  // Moments about the mass centres: (1, 0, 0) x (25.8, 34.4, 0) on body 0, (1, 0, 0) x (-25.8,
  // -34.4, 0) on body 1.
  expect_near(f.moment_W(0), Vector3(0, 0, 34.4), kHandValueTolerance);
  expect_near(f.moment_W(1), Vector3(0, 0, -34.4), kHandValueTolerance);
  // k (l - l0)^2 / 2 = 10 * 9 / 2.
  EXPECT_NEAR(spring.potential_energy(k), 45.0, kHandValueTolerance);
}

TEST(SpringDamper, PushesThePointsApartWhenCompressedAndStillWhenTheRateCancelsTheStretch) {
  const SystemKinematics k = three_four_five_pose();
  // l0 = 8: stretch -3, no damping: tension -30, pushing apart.
  const GeneralisedForces pushed = forces_of(SpringDamper("s", 0, kPointI_B, 1, kPointJ_B, {10.0, 0.0, 8.0}), k);
  expect_near(pushed.force_W(1), Vector3(18, 24, 0), kHandValueTolerance);
  // k (l - l0) = 10 (5 - 7.6) = -26 against c dl/dt = 10 (2.6) = 26: no force at all.
  const GeneralisedForces balanced =
      forces_of(SpringDamper("s", 0, kPointI_B, 1, kPointJ_B, {10.0, 10.0, 7.6}), k);
  expect_near(balanced.force_W(0), Vector3::Zero(), kHandValueTolerance);
  expect_near(balanced.force_W(1), Vector3::Zero(), kHandValueTolerance);
}

TEST(SpringDamper, AnchoredToTheGroundActsOnTheBodyOnly) {
  const SystemKinematics k = three_four_five_pose();
  // Ground point (0, 0, 0) = P_i above: the same force on body 1, nothing stored for the ground.
  const SpringDamper spring("s", kGround, Vector3::Zero(), 1, kPointJ_B, {10.0, 5.0, 2.0});
  const GeneralisedForces f = forces_of(spring, k);
  expect_near(f.force_W(1), Vector3(-25.8, -34.4, 0), kHandValueTolerance);
  EXPECT_EQ(f.force_W(0), Vector3::Zero());
}

TEST(SpringDamper, RejectsAZeroLengthAndNegativeParametersNamingThem) {
  SystemKinematics k(2);  // both bodies at the origin: P_i = P_j
  const SpringDamper spring("s", 0, Vector3::Zero(), 1, Vector3::Zero(), {10.0, 0.0, 1.0});
  try {
    forces_of(spring, k);
    ADD_FAILURE() << "no exception";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("spring-damper 's' at t = 0: length 0 m"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(SpringDamper("s", 0, Vector3::Zero(), 1, Vector3::Zero(), {-1.0, 0.0, 1.0}), ModelError);
  EXPECT_THROW(SpringDamper("s", 0, Vector3::Zero(), 1, Vector3::Zero(), {1.0, -1.0, 1.0}), ModelError);
  EXPECT_THROW(SpringDamper("s", 0, Vector3::Zero(), 1, Vector3::Zero(), {1.0, 0.0, -1.0}), ModelError);
}

// ---- a damped oscillator ------------------------------------------------------------------------

/// m x'' = -k (x - l0) - c x' along x: a body on a spring-damper to the ground point at the origin,
/// released at rest from x = l0 + A. Underdamped: x - l0 = A e^(-zeta w t) (cos wd t +
/// zeta w / wd sin wd t), w = sqrt(k / m), zeta = c / (2 sqrt(k m)), wd = w sqrt(1 - zeta^2).
struct Oscillator {
  double mass = 2.0, stiffness = 800.0, damping = 4.0, free_length = 0.1, amplitude = 0.01;
  double displacement(double t) const {
    const double w = std::sqrt(stiffness / mass);
    const double zeta = damping / (2.0 * std::sqrt(stiffness * mass));
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    return amplitude * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
  }
};

TEST(SpringDamper, MovesABodyAsTheDampedOscillatorsClosedForm) {
  const Oscillator o;
  ModelDescription model;
  model.name = "oscillator";
  BodyDescription body;
  body.properties = {"mass", o.mass, Vector3::Constant(0.01)};
  body.initial.position_W = Vector3(o.free_length + o.amplitude, 0, 0);
  model.bodies.push_back(body);
  model.forces.push_back(SpringDamperDescription{"spring", "ground", "mass", Vector3::Zero(), Vector3::Zero(),
                                                 {o.stiffness, o.damping, o.free_length}});
  model.output_bodies = {"mass"};
  BuiltModel built = build_model(model);
  IntegratorSettings s;
  s.end_time = 1.0;  // 3.2 periods (w = 20 rad/s), amplitude down to e^-1
  s.report_step = 1e-3;
  s.relative_tolerance = s.absolute_tolerance = 1e-11;
  // Dormand-Prince at tolerance 1e-11: the error over the second is measured 4.0e-12 m. The
  // bound leaves a margin of 25; a wrong k, c, l0 or sign moves x by a good fraction of the
  // 1e-2 m amplitude.
  constexpr double kTrajectoryTolerance = 1e-10;
  double worst = 0.0, off_line = 0.0;
  int reports = 0;
  std::vector<double> y = built.initial_state;
  integrate(*built.system, y, s, [&](double t, std::span<const double> state) {
    const BodyState b = built.system->body_state(state, 0);
    worst = std::max(worst, std::abs(b.position_W.x() - o.free_length - o.displacement(t)));
    off_line = std::max(off_line, b.position_W.tail<2>().cwiseAbs().maxCoeff());
    ++reports;
  });
  EXPECT_EQ(reports, 1001);
  EXPECT_LT(worst, kTrajectoryTolerance);
  EXPECT_EQ(off_line, 0.0);  // the force is along x exactly
}

}  // namespace
}  // namespace clearjoint::dynamics
