// SPDX-License-Identifier: BSD-3-Clause
// The clearance joint integrated through impacts (issue 7's physics checks): a free journal in a
// grounded bearing in zero gravity, and the shipped planar slider-crank with an aligned joint.

#include <gtest/gtest.h>

#include <cmath>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "dynamics_test_support.hpp"
#include "one_dimensional_impact.hpp"

namespace clearjoint::dynamics {
namespace {

constexpr double kStiffness = 1e11;  // Table 2, N/m^1.5
constexpr double kRadialClearance = 1e-4;

struct FreeJournal {
  double mass = 1.0;
  Vector3 offset_W = Vector3::Zero();  ///< P_j - P_i at t = 0
  Vector4 euler_parameters{1.0, 0.0, 0.0, 0.0};
  Vector3 velocity_W = Vector3::Zero();
  Vector3 angular_velocity_B = Vector3::Zero();
  ClearanceJointParameters joint;  ///< Table 2 dimensions; set the force law per test
};

/// A journal (its axis centre at its mass centre, axis z) inside a grounded bearing (origin, z).
ModelDescription free_journal_model(const FreeJournal& f) {
  ModelDescription model;
  model.name = "free journal";
  BodyDescription journal;
  journal.properties = {"journal", f.mass, Vector3(2.5e-5, 2.5e-5, 4.9e-5)};  // ~ a 1 kg rod, mm scale
  journal.initial.position_W = f.offset_W;
  journal.initial.euler_parameters = f.euler_parameters;
  journal.initial.velocity_W = f.velocity_W;
  journal.initial.angular_velocity_B = f.angular_velocity_B;
  model.bodies.push_back(journal);
  model.forces.push_back(ClearanceRevoluteDescription{
      "clearance", {"ground", Vector3::Zero(), Vector3::UnitZ()},
      {"journal", Vector3::Zero(), Vector3::UnitZ()}, f.joint});
  model.output_bodies = {"journal"};
  return model;
}

/// The clearance joint is the model's last force element (gravity, if any, comes first).
const ClearanceRevoluteJoint& joint_of(const MultibodySystem& system) {
  return dynamic_cast<const ClearanceRevoluteJoint&>(*system.force_elements().back());
}

/// The joint's state at a reported (t, y): its impact memory is y's last extra variables.
ClearanceJointState joint_state(const MultibodySystem& system, double t, std::span<const double> y) {
  SystemKinematics kinematics(system.layout().body_count);
  kinematics.update(t, y);
  return joint_of(system).evaluate(t, kinematics,
                                   system.extra_state(y, system.force_elements().size() - 1));
}

double total_energy(MultibodySystem& system, double t, std::span<const double> y) {
  return system.kinetic_energy(y) + system.potential_energy(t, y);  // includes K delta^2.5 / 2.5
}

IntegratorSettings settings(double end_time, double report_step, double tolerance) {
  IntegratorSettings s;
  s.end_time = end_time;
  s.report_step = report_step;
  s.relative_tolerance = s.absolute_tolerance = tolerance;
  return s;
}

/// Largest |E(t) - E(0)| / E(0) at the report times, and the impacts seen.
struct EnergyRun {
  double worst_relative_change = 0.0;
  double largest_increase = 0.0;  ///< max over report times of E(t_k) - E(t_k-1), relative to E(0)
  long impacts = 0;
};

EnergyRun run_energy(const FreeJournal& f, const IntegratorSettings& s) {
  BuiltModel built = build_model(free_journal_model(f));
  MultibodySystem& system = *built.system;
  std::vector<double> y = built.initial_state;
  const double E0 = total_energy(system, 0.0, y);
  double previous = E0;
  EnergyRun run;
  integrate(system, y, s, [&](double t, std::span<const double> state) {
    const double E = total_energy(system, t, state);
    run.worst_relative_change = std::max(run.worst_relative_change, std::abs(E - E0) / E0);
    run.largest_increase = std::max(run.largest_increase, (E - previous) / E0);
    previous = E;
  });
  run.impacts = joint_of(system).statistics().impacts;
  return run;
}

/// An aligned journal flying obliquely: line contacts on the wall and face contacts on both
/// bases, about 60 impacts in 50 ms.
FreeJournal oblique_aligned_journal() {
  FreeJournal f;
  f.velocity_W = Vector3(0.2, 0.13, 0.03);
  return f;
}

// Energy is conserved when the law is elastic: Hertz, or Lankarani-Nikravesh with ce = 1 (the
// damping factor 3 (1 - ce^2) / 4 is then 0). What remains is the integrator's error, which
// accumulates over the thousands of steps the impacts take and must shrink with the tolerance:
// 100 times tighter must give at least 10 times less (measured: 1.1e-5 at 1e-9, 2.1e-7 at 1e-11,
// a factor 54, over 57 impacts).
constexpr double kRequiredConvergenceFactor = 10.0;
// An upper bound for the drift at 1e-11 over those 57 impacts: a millionth of the energy.
constexpr double kEnergyDriftAtTightTolerance = 1e-6;
// Between two report times 1e-5 s apart the integrator error is far below that (measured 1e-14
// aligned, 1e-16 tilted with damping and friction).
constexpr double kEnergyGainBetweenReports = 1e-9;

TEST(ClearanceJointImpacts, ConserveEnergyThroughManyImpactsWithRestitutionOneAndNoFriction) {
  FreeJournal f = oblique_aligned_journal();
  f.joint.normal.model = NormalForceModel::lankarani_nikravesh;
  f.joint.normal.restitution = 1.0;
  f.joint.friction.coefficient = 0.0;
  const EnergyRun coarse = run_energy(f, settings(0.05, 1e-5, 1e-9));
  const EnergyRun fine = run_energy(f, settings(0.05, 1e-5, 1e-11));
  std::printf("impacts %ld; max |E - E0| / E0 = %.3g at tolerance 1e-9, %.3g at 1e-11\n",
              fine.impacts, coarse.worst_relative_change, fine.worst_relative_change);
  EXPECT_GE(fine.impacts, 40);
  EXPECT_LT(fine.worst_relative_change, kEnergyDriftAtTightTolerance);
  EXPECT_LT(fine.worst_relative_change * kRequiredConvergenceFactor, coarse.worst_relative_change);
}

// Characterisation, not conservation: with a tilted journal the wall contacts are rim points at
// the middle of the penetration arc (eqs. 18-21), which is not the rim's deepest point when the
// arc is asymmetric, so K delta^n along that normal is not the gradient of any potential. The
// energy then wanders by the contact model's error, which a tighter tolerance does not remove:
// measured 2.0e-4 of E0 at 1e-9 and 2.6e-4 at 1e-11 over ~200 impacts, single impacts gaining up
// to 4e-5. The bound below is 5 times the measurement; the aligned case above is exact.
constexpr double kTiltedRimEnergyDrift = 1e-3;

TEST(ClearanceJointImpacts, ConserveEnergyOnlyToTheContactModelsAccuracyWithTiltedRims) {
  FreeJournal f = oblique_aligned_journal();
  f.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitX(), 2e-3);
  f.angular_velocity_B = Vector3(0.5, 0.3, 0.0);
  f.joint.normal.model = NormalForceModel::hertz;
  f.joint.friction.coefficient = 0.0;
  const EnergyRun run = run_energy(f, settings(0.05, 1e-5, 1e-9));
  std::printf("impacts %ld; max |E - E0| / E0 = %.3g, largest gain between reports %.3g\n",
              run.impacts, run.worst_relative_change, run.largest_increase);
  EXPECT_GE(run.impacts, 100);
  EXPECT_LT(run.worst_relative_change, kTiltedRimEnergyDrift);
}

// With damping and friction the energy may only decrease, up to the integrator's error between
// two report times.
TEST(ClearanceJointImpacts, NeverGainEnergyWithDampingAndFriction) {
  constexpr double kTolerance = 1e-10;
  for (const double tilt : {0.0, 2e-3}) {  // aligned (line, face contacts); tilted (rim contacts)
    FreeJournal f = oblique_aligned_journal();
    f.euler_parameters = euler_parameters_from_axis_angle(Vector3::UnitX(), tilt);
    f.angular_velocity_B = Vector3(0.0, 0.0, 30.0);  // spin: friction at every contact
    f.joint.friction = {0.1, 1000.0};                 // Table 2; Lankarani-Nikravesh ce = 0.9
    const EnergyRun run = run_energy(f, settings(0.05, 1e-5, kTolerance));
    std::printf("tilt %g: impacts %ld; energy lost %.3g of E0; largest increase between reports %.3g of E0\n",
                tilt, run.impacts, run.worst_relative_change, run.largest_increase);
    EXPECT_GE(run.impacts, 20) << "tilt " << tilt;
    EXPECT_GT(run.worst_relative_change, 0.1) << "tilt " << tilt;  // it does dissipate
    EXPECT_LT(run.largest_increase, kEnergyGainBetweenReports) << "tilt " << tilt;
  }
}

/// The journal sent along +x from the centre at `speed`; returns the largest line-contact depth
/// and the x velocity once the contact is over.
struct SingleImpact {
  double peak_depth = 0.0;
  double rebound_velocity = 0.0;
  double recorded_impact_speed = 0.0;  ///< the delta_dot(-) the memory recorded
  long impacts = 0;
};

/// Hertz peak penetration of a mass m hitting at v: m v^2 / 2 = K delta^2.5 / 2.5.
double hertz_peak_depth(double mass, double speed) {
  return std::pow(5.0 * mass * speed * speed / (4.0 * kStiffness), 0.4);
}

SingleImpact single_impact(FreeJournal f, double speed, double tolerance, double report_step,
                           OnsetHandling onset = IntegratorSettings{}.onset) {
  f.velocity_W = Vector3(speed, 0.0, 0.0);
  f.joint.friction.coefficient = 0.0;
  BuiltModel built = build_model(free_journal_model(f));
  MultibodySystem& system = *built.system;
  std::vector<double> y = built.initial_state;
  const ClearanceRevoluteJoint& joint = joint_of(system);
  SingleImpact result;
  // Reaches the wall after cr / v; the contact lasts about 3 delta_max / v; stop before the way
  // back reaches the other side (2 cr further).
  const double end = (kRadialClearance + 5.0 * hertz_peak_depth(f.mass, speed)) / speed;
  IntegratorSettings s = settings(end, report_step, tolerance);
  s.onset = onset;
  integrate(system, y, s, [&](double t, std::span<const double> state) {
    const ClearanceJointState js = joint_state(system, t, state);
    const SlotState& line = js.slots[static_cast<int>(ContactSlot::line)];
    if (line.active) result.peak_depth = std::max(result.peak_depth, line.depth);
    result.rebound_velocity = state[system.layout().velocity_offset(0)];
  });
  result.impacts = joint.statistics().impacts;
  if (!joint.recorded_impacts().empty()) {
    result.recorded_impact_speed = joint.recorded_impacts().front().impact_speed;
  }
  return result;
}

TEST(ClearanceJointImpacts, ReachTheHertzPeakPenetrationInASingleElasticImpact) {
  FreeJournal f;
  f.joint.normal.model = NormalForceModel::hertz;
  const double v = 0.1;
  const double expected = hertz_peak_depth(f.mass, v);
  // Sampling every 1e-7 s misses the peak by at most a (dt/2)^2 / 2 = 2.3e-12 m (a = K delta^1.5 /
  // m = 1.8e3 m/s^2), 3e-7 relative; the integration at 1e-12 adds ~1e-12 m. Bound: 1e-6 relative.
  constexpr double kPeakTolerance = 1e-6;
  const SingleImpact impact = single_impact(f, v, 1e-12, 1e-7);
  std::printf("peak depth %.9g m, Hertz %.9g m, relative difference %.2g\n", impact.peak_depth,
              expected, impact.peak_depth / expected - 1.0);
  EXPECT_EQ(impact.impacts, 1);
  EXPECT_NEAR(impact.peak_depth / expected, 1.0, kPeakTolerance);
  // Elastic: comes back at the same speed. The integration at 1e-12 through the impact's few
  // hundred steps leaves 3.4e-12 m/s (measured); the bound leaves a margin of 30. A law that lost
  // 1e-6 of the energy would leave it by 5e-8 m/s.
  constexpr double kElasticReboundTolerance = 1e-10;
  EXPECT_NEAR(impact.rebound_velocity, -v, kElasticReboundTolerance);
}

// The impact velocity is recorded at the located instant of first touch, so a single impact at
// the paper's tolerance follows the exact 1-D law: restitution to 1e-4 relative (issue 23's
// requirement) from 1 m/s down to 1e-2 m/s.
constexpr double kLocatedRestitutionTolerance = 1e-4;

TEST(ClearanceJointImpacts, FollowTheExactLankaraniNikraveshRestitutionFromOneToOneHundredthMetrePerSecond) {
  FreeJournal f;  // Lankarani-Nikravesh, ce = 0.9
  for (const double v : {1.0, 0.3, 0.1, 0.03, 0.01}) {
    const double reference = test::integrated_restitution(f.joint.normal, f.mass, v);
    const double report_step = hertz_peak_depth(f.mass, v) / v / 100.0;  // 100 reports in contact
    const SingleImpact located = single_impact(f, v, 1e-7, report_step);  // the default
    const SingleImpact restarted =
        single_impact(f, v, 1e-7, report_step, OnsetHandling::restart_at_onset);
    const SingleImpact at_step_end = single_impact(f, v, 1e-7, report_step, OnsetHandling::step_end);
    const double restitution = -located.rebound_velocity / v;
    std::printf("v = %4.2f m/s: restitution / 1-D law - 1 = %+.2e (record at onset), %+.2e (restart "
                "at onset), %+.2e (step end); recorded delta_dot(-) / v - 1 = %+.2e located, %+.2e "
                "step end\n",
                v, restitution / reference - 1.0, -restarted.rebound_velocity / v / reference - 1.0,
                -at_step_end.rebound_velocity / v / reference - 1.0,
                located.recorded_impact_speed / v - 1.0, at_step_end.recorded_impact_speed / v - 1.0);
    EXPECT_EQ(located.impacts, 1) << "v = " << v;
    EXPECT_NEAR(restitution / reference, 1.0, kLocatedRestitutionTolerance) << "v = " << v;
  }
  // Lankarani-Nikravesh is derived for ce near 1: at ce = 0.9 its own effective restitution is
  // 0.913 (the 1-D reference), close to the chosen value.
  EXPECT_NEAR(test::integrated_restitution(f.joint.normal, f.mass, 0.1), f.joint.normal.restitution, 0.02);
}

/// The impact speeds the planar aligned slider-crank records in its first `duration` seconds.
std::vector<RecordedImpact> planar_aligned_impacts(double duration, double tolerance,
                                                   OnsetHandling onset) {
  ModelDescription model = test::shipped_model("slider_crank_planar_clearance_aligned.json");
  model.solver.end_time = duration;
  model.solver.relative_tolerance = model.solver.absolute_tolerance = tolerance;
  model.solver.onset = onset;
  BuiltModel built = build_model(model);
  std::vector<double> y = built.initial_state;
  integrate(*built.system, y, model.solver, [](double, std::span<const double>) {});
  return joint_of(*built.system).recorded_impacts();
}

// Issue 23: at the paper's tolerance the recorded impact speeds of the planar aligned model are
// within 1 % of those at 1e-12 for every impact of the first 5 ms (recorded at the end of the
// first accepted step in contact they were up to 88 % larger).
constexpr double kImpactSpeedAgreement = 0.01;

TEST(PlanarSliderCrankWithAlignedClearanceJoint, RecordsTheTightToleranceImpactSpeedsAtThePapersTolerance) {
  constexpr double kDuration = 5e-3;
  const OnsetHandling located = IntegratorSettings{}.onset;
  const std::vector<RecordedImpact> reference = planar_aligned_impacts(kDuration, 1e-12, located);
  const std::vector<RecordedImpact> paper = planar_aligned_impacts(kDuration, 1e-7, located);
  const std::vector<RecordedImpact> unlocated =
      planar_aligned_impacts(kDuration, 1e-7, OnsetHandling::step_end);
  const std::vector<RecordedImpact> restarted =
      planar_aligned_impacts(kDuration, 1e-7, OnsetHandling::restart_at_onset);
  ASSERT_GE(reference.size(), 3u);
  ASSERT_EQ(paper.size(), reference.size());
  for (size_t i = 0; i < reference.size(); ++i) {
    const double step_end_speed = i < unlocated.size() ? unlocated[i].impact_speed : NAN;
    const double restarted_speed = i < restarted.size() ? restarted[i].impact_speed : NAN;
    std::printf("impact %2zu at %.7f s (%s): delta_dot(-) at 1e-12 %.6f m/s; at 1e-7 %.6f (%+.2e), "
                "restarting at onset %.6f (%+.2e), recorded at the step end %.6f (%+.2e)\n",
                i + 1, reference[i].time, std::string(to_string(reference[i].slot)).c_str(),
                reference[i].impact_speed, paper[i].impact_speed,
                paper[i].impact_speed / reference[i].impact_speed - 1.0, restarted_speed,
                restarted_speed / reference[i].impact_speed - 1.0, step_end_speed,
                step_end_speed / reference[i].impact_speed - 1.0);
    EXPECT_EQ(paper[i].slot, reference[i].slot) << "impact " << i + 1;
    EXPECT_NEAR(paper[i].impact_speed / reference[i].impact_speed, 1.0, kImpactSpeedAgreement)
        << "impact " << i + 1 << " at " << reference[i].time << " s";
  }
}

TEST(PlanarSliderCrankWithAlignedClearanceJoint, KeepsTheRodsThirdEulerParameterZeroAndNoAxialMotion) {
  ModelDescription model = test::shipped_model("slider_crank_planar_clearance_aligned.json");
  model.solver.end_time = 0.03;
  BuiltModel built = build_model(model);
  MultibodySystem& system = *built.system;
  const BodyIndex rod = system.body_index("rod", "test");
  const ClearanceRevoluteJoint& joint = joint_of(system);
  std::vector<double> y = built.initial_state;
  double largest_e1_e2 = 0.0, largest_axis_angle = 0.0, largest_axial_offset = 0.0;
  long axial_contacts = 0, line_contacts = 0;
  integrate(system, y, model.solver, [&](double t, std::span<const double> state) {
    const BodyState s = system.body_state(state, rod);
    largest_e1_e2 = std::max({largest_e1_e2, std::abs(s.euler_parameters[1]), std::abs(s.euler_parameters[2])});
    const ClearanceJointState c = joint_state(system, t, state);
    largest_axis_angle = std::max(largest_axis_angle, c.axis_angle);
    largest_axial_offset = std::max(largest_axial_offset, std::abs(c.rim_a_in_bearing.z() - 0.0099));
    axial_contacts += c.slots[static_cast<int>(ContactSlot::axial_a)].active +
                      c.slots[static_cast<int>(ContactSlot::axial_b)].active;
    line_contacts += c.slots[static_cast<int>(ContactSlot::line)].active;
  });
  std::printf("impacts %ld, report times in line contact %ld\n", joint.statistics().impacts, line_contacts);
  EXPECT_GE(joint.statistics().impacts, 3);
  EXPECT_GT(line_contacts, 0);
  // Exactly: every out-of-plane quantity is computed from exact zeros (products with 0, sums of
  // 0), so a planar mechanism stays planar bit for bit; any non-zero would be a formulation error.
  EXPECT_EQ(largest_e1_e2, 0.0);
  EXPECT_EQ(largest_axis_angle, 0.0);
  EXPECT_EQ(largest_axial_offset, 0.0);
  EXPECT_EQ(axial_contacts, 0);
}

}  // namespace
}  // namespace clearjoint::dynamics
