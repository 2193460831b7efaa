// SPDX-License-Identifier: BSD-3-Clause
// Forces and moments of the clearance joint at one instant, its impact memory, its outputs and its
// input checks. The integrated behaviour (impacts, energy) is in test_clearance_joint_impacts.cpp.

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

using geometry::ContactScenario;

// Table 2: Ri = 10 mm, Rj = 9.9 mm, Li = 20 mm, Lj = 19.8 mm; clearances 0.1 mm.
constexpr double kRadialClearance = 1e-4;
constexpr double kAxialClearance = 1e-4;
constexpr double kDepth = 2e-6;
// The poses are built through mass centres 0.02-0.05 m away, where an ulp is 3.5e-18 to 7e-18 m:
// a few of those in a depth of 2e-6 m is ~1e-11 relative, 1.5 times that in delta^1.5 and in the
// sums of forces and moments. 1e-10 bounds it.
constexpr double kRelativeTolerance = 1e-10;

constexpr BodyIndex kBearing = 0;
constexpr BodyIndex kJournal = 1;
// Bearing body: mass centre at (0, 0, 0.05), bearing centre P_i at the world origin, axis z.
const Vector3 kBearingCentre_B(0.0, 0.0, -0.05);
// Journal body: P_j 20 mm from its mass centre along x, axis z, so that forces make moments.
const Vector3 kJournalCentre_B(0.02, 0.0, 0.0);

ClearanceJointParameters hertz_without_friction() {
  ClearanceJointParameters p;
  p.normal.model = NormalForceModel::hertz;
  p.friction.coefficient = 0.0;
  return p;
}

ClearanceRevoluteJoint make_joint(const ClearanceJointParameters& p) {
  return ClearanceRevoluteJoint("joint", {kBearing, kBearingCentre_B, Vector3::UnitZ()},
                                {kJournal, kJournalCentre_B, Vector3::UnitZ()}, p);
}

/// Bearing at rest with P_i at the origin; journal with P_j at `p_WPj`, rotated by `journal_p`.
SystemKinematics poses(const Vector3& p_WPj, const Vector4& journal_p = Vector4(1, 0, 0, 0),
                       const Vector3& journal_velocity_W = Vector3::Zero()) {
  SystemKinematics k(2);
  BodyState bearing;
  bearing.position_W = Vector3(0.0, 0.0, 0.05);
  k.set(kBearing, bearing);
  BodyState journal;
  journal.euler_parameters = journal_p;
  journal.position_W = p_WPj - rotation_from_euler_parameters(journal_p) * kJournalCentre_B;
  journal.velocity_W = journal_velocity_W;
  k.set(kJournal, journal);
  return k;
}

struct Applied {
  Vector3 force_bearing, moment_bearing, force_journal, moment_journal;
};

Applied apply(const ClearanceRevoluteJoint& joint, const SystemKinematics& k,
              std::span<const double> memory) {
  GeneralisedForces forces(k);
  std::array<double, kContactSlotCount> rate{};
  joint.add_forces({0.0, k, memory, rate}, forces);
  for (double r : rate) EXPECT_EQ(r, 0.0);  // the memory has no rate: it changes only between steps
  return {forces.force_W(kBearing), forces.moment_W(kBearing), forces.force_W(kJournal),
          forces.moment_W(kJournal)};
}

constexpr std::array<double, kContactSlotCount> kNoMemory{};

double hertz(double depth) { return 1e11 * depth * std::sqrt(depth); }

void expect_vector_near(const Vector3& actual, const Vector3& expected, double scale) {
  EXPECT_LE((actual - expected).norm(), kRelativeTolerance * scale)
      << "actual " << actual.transpose() << "\nexpected " << expected.transpose();
}

TEST(ClearanceRevoluteJoint, AppliesNothingToACentredJournal) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const Applied a = apply(joint, poses(Vector3::Zero()), kNoMemory);
  EXPECT_EQ(a.force_journal, Vector3::Zero());
  EXPECT_EQ(a.force_bearing, Vector3::Zero());
  EXPECT_EQ(joint.evaluate(0.0, poses(Vector3::Zero()), kNoMemory).contacts.scenario,
            ContactScenario::none);
  EXPECT_FALSE(joint.evaluate(0.0, poses(Vector3::Zero()), kNoMemory).pin_in_hole_scenario.has_value());
}

TEST(ClearanceRevoluteJoint, PushesAnAlignedJournalBackAtTheLineContactAndTheBearingForward) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const Vector3 p_WPj(kRadialClearance + kDepth, 0.0, 0.0);
  const SystemKinematics k = poses(p_WPj);
  const Applied a = apply(joint, k, kNoMemory);
  const double F = hertz(kDepth);
  const Vector3 force_on_journal(-F, 0.0, 0.0);
  // eq. (8): C_j = P_j + Rj n; eq. (7): C_i = P_i + ((P_j - P_i) . a) a + Ri n.
  const Vector3 p_WCj = p_WPj + Vector3(0.0099, 0.0, 0.0);
  const Vector3 p_WCi(0.010, 0.0, 0.0);
  expect_vector_near(a.force_journal, force_on_journal, F);
  expect_vector_near(a.moment_journal, (p_WCj - k.body(kJournal).position_W).cross(force_on_journal), F * 0.03);
  expect_vector_near(a.force_bearing, -force_on_journal, F);
  expect_vector_near(a.moment_bearing, (p_WCi - k.body(kBearing).position_W).cross(-force_on_journal), F * 0.06);
  EXPECT_EQ(joint.evaluate(0.0, k, kNoMemory).contacts.scenario, ContactScenario::line);
}

TEST(ClearanceRevoluteJoint, PushesAJournalBaseBackFromTheBearingBaseAtItsCentre) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const Vector3 p_WPj(0.0, 0.0, kAxialClearance + kDepth);  // rim A beyond base A (z = +10 mm)
  const SystemKinematics k = poses(p_WPj);
  const Applied a = apply(joint, k, kNoMemory);
  const double F = hertz(kDepth);
  const Vector3 force_on_journal(0.0, 0.0, -F);
  const Vector3 p_WCj = p_WPj + Vector3(0.0, 0.0, 0.0099);  // eq. (10): the journal base centre
  expect_vector_near(a.force_journal, force_on_journal, F);
  expect_vector_near(a.moment_journal, (p_WCj - k.body(kJournal).position_W).cross(force_on_journal), F * 0.03);
  expect_vector_near(a.force_bearing, -force_on_journal, F);
  EXPECT_EQ(joint.evaluate(0.0, k, kNoMemory).contacts.scenario, ContactScenario::face);
}

TEST(ClearanceRevoluteJoint, DragsASlidingJournalAgainstItsTangentialVelocity) {
  ClearanceJointParameters p = hertz_without_friction();
  p.friction = {0.1, 1000.0};
  const ClearanceRevoluteJoint joint = make_joint(p);
  const Vector3 p_WPj(kRadialClearance + kDepth, 0.0, 0.0);
  const SystemKinematics k = poses(p_WPj, Vector4(1, 0, 0, 0), Vector3(0.0, 0.004, 0.0));
  const Applied a = apply(joint, k, kNoMemory);
  const double F = hertz(kDepth);
  const double friction = 0.1 * F * std::tanh(1000.0 * 0.004);  // eq. (32)
  const Vector3 force_on_journal(-F, -friction, 0.0);
  expect_vector_near(a.force_journal, force_on_journal, F);
  expect_vector_near(a.force_bearing, -force_on_journal, F);
  // The friction acts at C_j, Rj + 20 mm from the journal's mass centre along x: a moment about z.
  const Vector3 p_WCj = p_WPj + Vector3(0.0099, 0.0, 0.0);
  expect_vector_near(a.moment_journal, (p_WCj - k.body(kJournal).position_W).cross(force_on_journal), F * 0.03);
  const ClearanceJointState s = joint.evaluate(0.0, k, kNoMemory);
  EXPECT_NEAR(s.slots[static_cast<int>(ContactSlot::line)].friction_force, friction,
              kRelativeTolerance * F);
}

TEST(ClearanceRevoluteJoint, DampsWithTheRememberedImpactVelocityElseWithTheCurrentOne) {
  ClearanceJointParameters p;  // Lankarani-Nikravesh, ce = 0.9
  p.friction.coefficient = 0.0;
  const ClearanceRevoluteJoint joint = make_joint(p);
  const SystemKinematics k =
      poses(Vector3(kRadialClearance + kDepth, 0.0, 0.0), Vector4(1, 0, 0, 0), Vector3(0.05, 0.0, 0.0));
  const int line = static_cast<int>(ContactSlot::line);
  const double factor = 0.75 * (1 - 0.81);  // eq. (28)
  // No memory yet: delta_dot(-) = delta_dot = 0.05 m/s, eq. (29) gives 1 + factor.
  const SlotState fresh = joint.evaluate(0.0, k, kNoMemory).slots[line];
  EXPECT_NEAR(fresh.normal_force, hertz(kDepth) * (1 + factor), kRelativeTolerance * hertz(kDepth));
  EXPECT_DOUBLE_EQ(fresh.approach_speed, 0.05);
  EXPECT_DOUBLE_EQ(fresh.impact_speed, 0.05);
  // Remembered 0.1 m/s: 1 + factor 0.05 / 0.1.
  std::array<double, kContactSlotCount> memory{};
  memory[line] = 0.1;
  const SlotState remembered = joint.evaluate(0.0, k, memory).slots[line];
  EXPECT_NEAR(remembered.normal_force, hertz(kDepth) * (1 + factor / 2), kRelativeTolerance * hertz(kDepth));
  EXPECT_EQ(remembered.impact_speed, 0.1);
}

TEST(ClearanceRevoluteJoint, RemembersTheImpactVelocityUntilTheContactEnds) {
  ClearanceJointParameters p;
  const ClearanceRevoluteJoint joint = make_joint(p);
  const int line = static_cast<int>(ContactSlot::line);
  std::array<double, kContactSlotCount> memory{};
  const Vector3 in_contact(kRadialClearance + kDepth, 0.0, 0.0);
  // First accepted state in contact: records the approach speed.
  EXPECT_TRUE(joint.update_extra_state(0.0, poses(in_contact, Vector4(1, 0, 0, 0), Vector3(0.05, 0, 0)), memory));
  EXPECT_EQ(memory[line], 0.05);
  // Later in the same contact (restitution): kept.
  EXPECT_FALSE(joint.update_extra_state(0.0, poses(in_contact, Vector4(1, 0, 0, 0), Vector3(-0.04, 0, 0)), memory));
  EXPECT_EQ(memory[line], 0.05);
  // Contact over: cleared.
  EXPECT_TRUE(joint.update_extra_state(0.0, poses(Vector3::Zero()), memory));
  EXPECT_EQ(memory[line], 0.0);
  EXPECT_FALSE(joint.update_extra_state(0.0, poses(Vector3::Zero()), memory));
  // A contact first seen while already separating records the floor, never a non-positive speed.
  EXPECT_TRUE(joint.update_extra_state(0.0, poses(in_contact, Vector4(1, 0, 0, 0), Vector3(-0.04, 0, 0)), memory));
  EXPECT_EQ(memory[line], p.normal.minimum_impact_speed);
  EXPECT_EQ(joint.statistics().impacts, 2);
  for (int slot = 0; slot < kContactSlotCount; ++slot) {
    if (slot != line) {
      EXPECT_EQ(memory[slot], 0.0) << to_string(static_cast<ContactSlot>(slot));
    }
  }
}

TEST(ClearanceRevoluteJoint, ActsAlongTheNormalAtATiltedRimWithoutNetMomentOnThePair) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  // Journal tilted 3 mrad about y: rim A (z = +9.9 mm) moves by +29.7 um in x. Shift the journal
  // so that rim A reaches 3 um beyond the wall and rim B stays inside.
  const double tilt = 3e-3;
  const Vector4 p = euler_parameters_from_axis_angle(Vector3::UnitY(), tilt);
  const Vector3 p_WPj(kRadialClearance + 3e-6 - 0.0099 * std::sin(tilt) + 0.0099 * (1 - std::cos(tilt)), 0.0, 0.0);
  const SystemKinematics k = poses(p_WPj, p);
  const ClearanceJointState s = joint.evaluate(0.0, k, kNoMemory);
  ASSERT_EQ(s.contacts.scenario, ContactScenario::single_radial);
  const geometry::Contact& c = s.contacts.contacts[0];
  // By symmetry about the x-z plane the arc middle is the rim's farthest point from the axis, 3 um
  // beyond the wall; the pose is built from rounded sines and cosines of 1e-2 m lengths (1e-18 m).
  constexpr double kPoseRounding = 1e-16;
  EXPECT_NEAR(c.depth, 3e-6, kPoseRounding);
  EXPECT_NEAR(s.axis_angle, tilt, 1e-15);
  const Applied a = apply(joint, k, kNoMemory);
  // Expected from the geometry, not from the contact the joint computed: the farthest point of rim
  // A is on the +x side, where the wall's outward normal is (1, 0, 0) (C_j - C_i along it, eqs.
  // 22-23); Hertz at the 3 um depth above (its rounding changes F by 1.5 (1e-16 / 3e-6) relative).
  const Vector3 outward_W = Vector3::UnitX();
  const double F = hertz(3e-6);
  expect_vector_near(c.normal_W, outward_W, 1.0);
  expect_vector_near(a.force_journal, -F * outward_W, F);
  expect_vector_near(a.force_bearing, F * outward_W, F);
  // Equal and opposite forces along C_j - C_i (parallel to n, eqs. 22-23) have no net moment.
  const Vector3 net_moment_about_origin =
      k.body(kJournal).position_W.cross(a.force_journal) + a.moment_journal +
      k.body(kBearing).position_W.cross(a.force_bearing) + a.moment_bearing;
  EXPECT_LE(net_moment_about_origin.norm(), kRelativeTolerance * F * 0.05);
}

/// Everything one evaluation of the joint gives at one pose, for bitwise comparison.
struct Evaluation {
  Applied applied;
  double energy = 0.0;
  bool event = false;
  ClearanceJointState state;
};

Evaluation evaluate_all(const ClearanceRevoluteJoint& joint, const SystemKinematics& k) {
  GeneralisedForces forces(k);
  std::array<double, kContactSlotCount> rate{};
  joint.add_forces({0.0, k, kNoMemory, rate}, forces);
  return {{forces.force_W(kBearing), forces.moment_W(kBearing), forces.force_W(kJournal),
           forces.moment_W(kJournal)},
          joint.potential_energy(k),
          joint.begins_event(k, kNoMemory),
          joint.evaluate(0.0, k, kNoMemory)};
}

bool same_bits(const Vector3& a, const Vector3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

bool same_bits(const Evaluation& a, const Evaluation& b) {
  const double energies[2] = {a.energy, b.energy};
  return same_bits(a.applied.force_bearing, b.applied.force_bearing) &&
         same_bits(a.applied.moment_bearing, b.applied.moment_bearing) &&
         same_bits(a.applied.force_journal, b.applied.force_journal) &&
         same_bits(a.applied.moment_journal, b.applied.moment_journal) &&
         std::memcmp(&energies[0], &energies[1], sizeof(double)) == 0 && a.event == b.event &&
         a.state.contacts.scenario == b.state.contacts.scenario &&
         a.state.contacts.contact_count == b.state.contacts.contact_count &&
         same_bits(a.state.force_on_journal_W, b.state.force_on_journal_W) &&
         same_bits(a.state.moment_on_journal_W, b.state.moment_on_journal_W) &&
         same_bits(a.state.rim_a_in_bearing, b.state.rim_a_in_bearing);
}

TEST(ClearanceRevoluteJoint, GivesEveryThreadEvaluatingItTheAnswerItGivesAlone) {
  ClearanceJointParameters p;  // Table 2 with friction: every part of the evaluation runs
  p.normal.model = NormalForceModel::lankarani_nikravesh;
  const ClearanceRevoluteJoint joint = make_joint(p);
  // Journals at rest in the centre, sliding against the wall, tilted into a rim contact, pushed
  // into a base: free flight and each contact type, so that threads disagree on the cached poses.
  std::vector<SystemKinematics> poses_to_evaluate;
  for (int k = 0; k < 12; ++k) {
    const double depth = 1e-6 * (k % 4);
    const double tilt = 1e-3 * (k % 3);
    const Vector4 q = euler_parameters_from_axis_angle(Vector3::UnitY(), tilt);
    const Vector3 p_WPj = k < 8 ? Vector3(kRadialClearance + depth - 0.0099 * std::sin(tilt), 0.0, 0.0)
                                : Vector3(0.0, 0.0, kAxialClearance + depth);
    poses_to_evaluate.push_back(poses(p_WPj, q, Vector3(0.0, 0.01 * k, -0.002 * k)));
  }
  std::vector<Evaluation> alone;
  for (const SystemKinematics& k : poses_to_evaluate) alone.push_back(evaluate_all(joint, k));
  ASSERT_GT(joint.statistics().detection_calls, 0);

  // Two cores or more make the evaluations overlap; each thread walks the poses from its own
  // start, so that the joint's workspace is held by one thread while others want it.
  constexpr int kThreads = 4;
  constexpr int kRounds = 200;
  std::atomic<int> mismatches{0};
  std::atomic<int> failures{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      try {
        for (int round = 0; round < kRounds; ++round) {
          for (size_t i = 0; i < poses_to_evaluate.size(); ++i) {
            const size_t pose = (i + static_cast<size_t>(t) * 5) % poses_to_evaluate.size();
            if (!same_bits(evaluate_all(joint, poses_to_evaluate[pose]), alone[pose])) ++mismatches;
          }
        }
      } catch (...) {
        ++failures;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(mismatches.load(), 0) << "of " << kThreads * kRounds * poses_to_evaluate.size() << " evaluations";
}

TEST(ClearanceRevoluteJoint, DropsTheForceOnAGroundBearing) {
  const ClearanceRevoluteJoint joint("grounded", {kGround, Vector3::Zero(), Vector3::UnitZ()},
                                     {0, Vector3::Zero(), Vector3::UnitZ()}, hertz_without_friction());
  SystemKinematics k(1);
  BodyState journal;
  journal.position_W = Vector3(kRadialClearance + kDepth, 0.0, 0.0);
  k.set(0, journal);
  GeneralisedForces forces(k);
  std::array<double, kContactSlotCount> rate{};
  joint.add_forces({0.0, k, kNoMemory, rate}, forces);
  expect_vector_near(forces.force_W(0), Vector3(-hertz(kDepth), 0.0, 0.0), hertz(kDepth));
  EXPECT_NEAR(joint.potential_energy(k), 1e11 * std::pow(kDepth, 2.5) / 2.5,
              kRelativeTolerance * 1e11 * std::pow(kDepth, 2.5));
}

TEST(ClearanceRevoluteJoint, RecordsOneValuePerColumnWithNaNDepthsForAbsentContacts) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const std::vector<std::string> columns = joint.output_columns();
  ASSERT_EQ(columns.size(), 17u + 5 * kContactSlotCount);
  std::vector<double> values(columns.size(), -1.0);
  const SystemKinematics k = poses(Vector3(kRadialClearance + kDepth, 0.0, 0.0));
  joint.record_outputs(0.0, k, kNoMemory, values);
  auto value = [&](const std::string& name) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    EXPECT_NE(it, columns.end()) << name;
    return values[static_cast<size_t>(it - columns.begin())];
  };
  EXPECT_EQ(value("scenario"), static_cast<double>(ContactScenario::line));
  EXPECT_EQ(value("aligned"), 1.0);
  EXPECT_EQ(value("contact_count"), 1.0);
  EXPECT_NEAR(value("line.depth"), kDepth, kRelativeTolerance * kDepth);
  EXPECT_NEAR(value("fx"), -hertz(kDepth), kRelativeTolerance * hertz(kDepth));
  EXPECT_TRUE(std::isnan(value("axial_a.depth")));
  EXPECT_EQ(value("axial_a.normal_force"), 0.0);
  // Journal rims relative to the bearing centre, in its frame: +-Lj/2 along the axis.
  EXPECT_DOUBLE_EQ(value("rim_a_axial"), 0.0099);
  EXPECT_DOUBLE_EQ(value("rim_b_axial"), -0.0099);
  constexpr double kUlpsOfTheMassCentres = 1e-17;  // see kRelativeTolerance
  EXPECT_NEAR(std::hypot(value("rim_a_u"), value("rim_a_v")), kRadialClearance + kDepth, kUlpsOfTheMassCentres);
}

TEST(ClearanceRevoluteJoint, ReportsRimsInABearingFrameBuiltFromTheBodyAxes) {
  const ClearanceRevoluteJoint along_z = make_joint(hertz_without_friction());
  EXPECT_EQ(along_z.bearing_frame_u_B(), Vector3::UnitX());
  EXPECT_EQ(along_z.bearing_frame_v_B(), Vector3::UnitY());
  const ClearanceRevoluteJoint along_y("j", {kBearing, Vector3::Zero(), Vector3(0, 2, 0)},
                                       {kJournal, Vector3::Zero(), Vector3::UnitY()}, {});
  EXPECT_EQ(along_y.bearing_frame_u_B(), Vector3::UnitX());
  EXPECT_EQ(along_y.bearing_frame_v_B(), -Vector3::UnitZ());  // (u, v, a) right-handed
}

TEST(ClearanceRevoluteJoint, StopsWithTheTimeWhenTheStateIsNotFinite) {
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const SystemKinematics k = poses(Vector3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0));
  GeneralisedForces forces(k);
  std::array<double, kContactSlotCount> rate{};
  try {
    joint.add_forces({0.25, k, kNoMemory, rate}, forces);
    FAIL() << "no error";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("clearance joint 'joint' at t = 0.25"), std::string::npos) << e.what();
  }
}

void expect_same_contacts(const geometry::JointContacts& actual, const geometry::JointContacts& expected) {
  EXPECT_EQ(actual.scenario, expected.scenario);
  ASSERT_EQ(actual.contact_count, expected.contact_count);
  for (int c = 0; c < actual.contact_count; ++c) {
    const geometry::Contact& a = actual.contacts[c];
    const geometry::Contact& e = expected.contacts[c];
    EXPECT_EQ(a.type, e.type);
    EXPECT_EQ(a.base, e.base);
    EXPECT_EQ(a.depth, e.depth);
    EXPECT_EQ(a.normal_W, e.normal_W);
    EXPECT_EQ(a.p_WCj, e.p_WCj);
    EXPECT_EQ(a.p_WCi, e.p_WCi);
  }
}

TEST(ClearanceRevoluteJoint, DetectsAtAStateWithANegligibleCoordinateWhatItDetectsAtThatCoordinateZero) {
  // A planar motion's out-of-plane coordinate, rounded to -8.7e-165 m instead of 0: below the
  // kernel's smallest accepted length (1e-150 m), so the joint hands the kernel 0 (kernel_pose.hpp)
  // and finds the contacts of that pose, bit for bit.
  constexpr double kNegligible = -8.7e-165;
  for (const auto& [p_WPj, flushed] :
       {std::pair{Vector3(kRadialClearance + kDepth, 0.0, kNegligible), Vector3(kRadialClearance + kDepth, 0.0, 0.0)},
        std::pair{Vector3(0.0, kNegligible, kAxialClearance + kDepth), Vector3(0.0, 0.0, kAxialClearance + kDepth)}}) {
    const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
    const ClearanceRevoluteJoint reference = make_joint(hertz_without_friction());
    const SystemKinematics k = poses(p_WPj);
    // The state's centre has the negligible coordinate (and the others of p_WPj, to rounding).
    const Vector3 p_WPj_state = k.body(kJournal).point_W(kJournalCentre_B);
    ASSERT_TRUE((p_WPj_state.array() == kNegligible).any()) << p_WPj_state.transpose();
    const ClearanceJointState state = joint.evaluate(0.25, k, kNoMemory);
    const ClearanceJointState expected = reference.evaluate(0.25, poses(flushed), kNoMemory);
    EXPECT_NE(state.contacts.contact_count, 0);
    expect_same_contacts(state.contacts, expected.contacts);
    EXPECT_EQ(state.force_on_journal_W, expected.force_on_journal_W);
  }
}

TEST(ClearanceRevoluteJoint, TakesAnAxisWithANegligibleComponentAsItIs) {
  // A journal turned by 2e-165 rad about x: its axis has a y component of that size. A direction
  // has no smallest length in the kernel (joint_geometry.hpp): detected as given, axes that are
  // not exactly parallel (eq. 5), so both rims touch the wall at the line contact's depth.
  const ClearanceRevoluteJoint joint = make_joint(hertz_without_friction());
  const SystemKinematics k =
      poses(Vector3(kRadialClearance + kDepth, 0.0, 0.0), euler_parameters_from_axis_angle(Vector3::UnitX(), 2e-165));
  const Vector3 axis_W = k.body(kJournal).rotation * Vector3::UnitZ();
  ASSERT_NE(axis_W.y(), 0.0);
  ASSERT_LT(std::abs(axis_W.y()), geometry::kSmallestAcceptedLength);
  const geometry::JointContacts contacts = joint.evaluate(0.25, k, kNoMemory).contacts;
  EXPECT_EQ(contacts.scenario, ContactScenario::radial_at_both_bases);
  ASSERT_EQ(contacts.contact_count, 2);
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(contacts.contacts[c].depth, kDepth, kRelativeTolerance * kDepth);
}

std::string construction_error(ClearanceJointParameters p, BodyIndex journal_body = kJournal,
                               Vector3 journal_axis = Vector3::UnitZ()) {
  try {
    ClearanceRevoluteJoint("j", {kBearing, Vector3::Zero(), Vector3::UnitZ()},
                           {journal_body, Vector3::Zero(), journal_axis}, p);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ClearanceRevoluteJoint, RejectsBadInputNamingTheField) {
  ClearanceJointParameters p;
  EXPECT_EQ(construction_error(p), "no error");
  p.dimensions.journal_radius = 0.010;
  EXPECT_EQ(construction_error(p), "j.journal.radius = 0.01: must be smaller than bearing.radius = "
                                   "0.01 (the radial clearance Ri - Rj, eq. 1, must be positive)");
  p = {};
  p.dimensions.journal_length = 0.03125;  // exact in binary: the message prints 17 digits
  EXPECT_EQ(construction_error(p), "j.journal.length = 0.03125: must be smaller than bearing.length = "
                                   "0.02 (the axial clearance (Li - Lj)/2, eq. 2, must be positive)");
  p = {};
  p.dimensions.bearing_radius = -0.01;
  EXPECT_EQ(construction_error(p), "j.bearing.radius = -0.01: must be positive");
  p = {};
  p.dimensions.journal_length = std::numeric_limits<double>::infinity();
  EXPECT_EQ(construction_error(p), "j.journal.length = inf: must be finite");
  p = {};
  // The kernel's accepted range (joint_geometry.hpp), checked when the joint is made, not at the
  // first contact detection of a run.
  p.dimensions.journal_length = 1e-200;
  EXPECT_EQ(construction_error(p).rfind("j.journal.length = 1e-200: a magnitude outside "
                                        "[1e-150, 1e150]", 0), 0u) << construction_error(p);
  p = {};
  // The kernel's words for a zero axis (geometry's validate(PartPose), clearjoint detect's).
  EXPECT_EQ(construction_error(p, kJournal, Vector3::Zero()), "j.journal.axis = [0, 0, 0]: must not be the zero vector");
  EXPECT_EQ(construction_error(p, kBearing),
            "j.journal.body: the journal and the bearing must be on different bodies");
  p.normal.restitution = -0.5;
  EXPECT_EQ(construction_error(p), "j.normal_force.restitution = -0.5: must lie in [0, 1]");
  p = {};
  p.detection.parallel_angle_tolerance = 2.0;
  EXPECT_EQ(construction_error(p), "j.detection.parallel_angle_tolerance = 2: must lie in [0, pi/2) radians");
}

// --- The pin-in-hole geometry (parameters.pin_in_hole): the same forces after its own detection.

// The paper's Table 2 clearances as a pin-in-hole joint: hole Rh = 10 mm through a link L = 20 mm
// long, pin Rp = 9.9 mm, heads whose faces are 0.1 mm beyond the link's faces (ca = 0.1 mm).
ClearanceJointParameters pin_in_hole_without_friction() {
  ClearanceJointParameters p = hertz_without_friction();
  geometry::PinInHoleDimensions d;
  d.hole_radius = 0.010;
  d.hole_length = 0.020;
  d.pin_radius = 0.0099;
  d.stops = {geometry::AxialStop{0.0101, 0.015}, geometry::AxialStop{-0.0101, 0.015}};
  d.stop_count = 2;
  p.pin_in_hole = d;
  return p;
}

TEST(ClearanceRevoluteJoint, PushesAnAlignedPinBackAtItsLineContactAsThePapersJointPushesItsJournal) {
  const ClearanceRevoluteJoint pin = make_joint(pin_in_hole_without_friction());
  const ClearanceRevoluteJoint paper = make_joint(hertz_without_friction());
  EXPECT_EQ(pin.radial_clearance(), paper.radial_clearance());
  const SystemKinematics k = poses(Vector3(kRadialClearance + kDepth, 0.0, 0.0));
  const Applied a = apply(pin, k, kNoMemory);
  const Applied b = apply(paper, k, kNoMemory);
  const double F = hertz(kDepth);
  expect_vector_near(a.force_journal, Vector3(-F, 0.0, 0.0), F);
  expect_vector_near(a.force_journal, b.force_journal, F);
  expect_vector_near(a.moment_journal, b.moment_journal, F * 0.03);
  expect_vector_near(a.force_bearing, b.force_bearing, F);
  expect_vector_near(a.moment_bearing, b.moment_bearing, F * 0.06);
  const ClearanceJointState s = pin.evaluate(0.0, k, kNoMemory);
  EXPECT_EQ(s.pin_in_hole_scenario, std::optional(geometry::PinInHoleScenario::line));
  EXPECT_TRUE(s.slots[static_cast<int>(ContactSlot::line)].active);
  EXPECT_NEAR(s.slots[static_cast<int>(ContactSlot::line)].depth, kDepth, kDepth * kRelativeTolerance);
}

TEST(ClearanceRevoluteJoint, PushesAPinBackWhenItsStopCrossesTheLinkFace) {
  const ClearanceRevoluteJoint pin = make_joint(pin_in_hole_without_friction());
  // The pin slides along +z: the head at -10.1 mm passes link face B (z = -10 mm) by kDepth.
  const SystemKinematics k = poses(Vector3(0.0, 0.0, kAxialClearance + kDepth));
  const Applied a = apply(pin, k, kNoMemory);
  const double F = hertz(kDepth);
  expect_vector_near(a.force_journal, Vector3(0.0, 0.0, -F), F);
  expect_vector_near(a.force_bearing, Vector3(0.0, 0.0, F), F);
  const ClearanceJointState s = pin.evaluate(0.0, k, kNoMemory);
  EXPECT_EQ(s.pin_in_hole_scenario, std::optional(geometry::PinInHoleScenario::face));
  EXPECT_TRUE(s.slots[static_cast<int>(ContactSlot::axial_b)].active);
  EXPECT_FALSE(s.slots[static_cast<int>(ContactSlot::axial_a)].active);
}

TEST(ClearanceRevoluteJoint, RecordsThePinInHoleScenarioNumberInTheScenarioColumn) {
  const ClearanceRevoluteJoint pin = make_joint(pin_in_hole_without_friction());
  const SystemKinematics k = poses(Vector3(kRadialClearance + kDepth, 0.0, 0.0));
  std::vector<double> values(pin.output_columns().size());
  pin.record_outputs(0.0, k, kNoMemory, values);
  EXPECT_EQ(values[0], static_cast<double>(geometry::PinInHoleScenario::line));
}

TEST(ClearanceRevoluteJoint, RejectsBadPinInHoleInputNamingTheField) {
  ClearanceJointParameters p = pin_in_hole_without_friction();
  EXPECT_EQ(construction_error(p), "no error");
  p.pin_in_hole->pin_radius = 0.010;
  EXPECT_EQ(construction_error(p).rfind("j.pin.radius = 0.01: must be smaller than", 0), 0u)
      << construction_error(p);
  p = pin_in_hole_without_friction();
  p.pin_in_hole->stops[0].position = 0.005;  // inside the hole
  EXPECT_EQ(construction_error(p).rfind("j.pin.stops[0].position = 0.005", 0), 0u) << construction_error(p);
  p = pin_in_hole_without_friction();
  p.lubrication = JointLubrication{};
  EXPECT_EQ(construction_error(p).rfind("j.lubrication: not supported with \"geometry\": \"pin_in_hole\"", 0), 0u)
      << construction_error(p);
}

TEST(ClearanceRevoluteJoint, RefusesAnAxisThatCannotBeNormalisedInDouble) {
  // |a|^2 overflows to infinity (a / |a| would be the zero vector) or underflows to 0 (a would
  // stay unnormalised): both are refused by name, as every other direction of a model is.
  const ClearanceJointParameters p;
  for (const Vector3& axis : {Vector3(1e200, 0.0, 0.0), Vector3(0.0, 1e-200, 0.0)}) {
    const std::string error = construction_error(p, kJournal, axis);
    EXPECT_EQ(error.rfind("j.journal.axis = [", 0), 0u) << error;
    EXPECT_NE(error.find("its length must lie in [1.4916681462400413e-154, 1.3407807929942596e+154]"),
              std::string::npos) << error;
  }
  // Within the range, however short or long: accepted (only the direction counts).
  EXPECT_EQ(construction_error(p, kJournal, Vector3(0.0, 0.0, 1e-150)), "no error");
  EXPECT_EQ(construction_error(p, kJournal, Vector3(0.0, 0.0, 1e150)), "no error");
}

}  // namespace
}  // namespace clearjoint::dynamics
