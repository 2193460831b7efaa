// SPDX-License-Identifier: BSD-3-Clause
// The cost of one evaluation of the clearance joint's forces in each engine, beside the plain
// detection, on one set of journal poses (issue 35, "Cost"):
//   BM_Detection       geometry::detect_contacts alone
//   BM_Clearjoint      dynamics::ClearanceRevoluteJoint::add_forces (detection, contact
//                      kinematics, force law, friction, application): the baseline
//   BM_SimbodyForce    ClearanceRevoluteForce::add_body_forces (what realising Dynamics calls)
//   BM_SimbodyCalcForceContribution  the same through Simbody's public Force API, whose own
//                      temporaries (allocated per call) are Simbody's cost, not the element's
//   BM_MujocoPassive   ClearanceJoints::add_passive_forces into qfrc_passive
// The adapters' overhead is their time over BM_Clearjoint's. Each engine's state is prepared
// outside the timed loop (poses realised to Velocity in Simbody; mj_kinematics and mj_comVel in
// MuJoCo), so that the figures are the force element's own cost.
//
//   engines_clearance_force_bench --benchmark_out=engines.json --benchmark_out_format=json
//
// Poses: a free journal in a grounded bearing (paper Table 2 dimensions), its centre at a
// random radial offset between 0.9 and 1.02 radial clearances and a random tilt up to half
// the angle at which a rim reaches the wall, random velocities; about half touch. Seed kSeed,
// also written as the counter "seed".

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "../common/uniform_source.hpp"
#include "clearjoint/dynamics/generalised_forces.hpp"
#include "clearjoint/dynamics/system_kinematics.hpp"
#include "clearjoint/mujoco/clearance_joints.hpp"
#include "clearjoint/simbody/clearance_revolute_force.hpp"

namespace {

using namespace clearjoint;
using dynamics::Vector3;
using dynamics::Vector4;

constexpr std::uint64_t kSeed = 35;
// Few enough that every engine's prepared states (a Simbody State, an mjData each) stay in the
// cache, as the one state an integrator evaluates does.
constexpr int kPoseCount = 64;

struct JournalPose {
  Vector3 position_W;
  Vector4 euler_parameters;
  Vector3 velocity_W;
  Vector3 angular_velocity_W;
};

const dynamics::ClearanceJointParameters kParameters{};  // paper Table 2

std::vector<JournalPose> poses() {
  bench::UniformSource uniform(kSeed);
  const geometry::JointDimensions& d = kParameters.dimensions;
  const double radial_clearance = d.bearing_radius - d.journal_radius;
  const double rim_tilt = 2.0 * radial_clearance / d.journal_length;  // about where a rim touches
  std::vector<JournalPose> out;
  for (int k = 0; k < kPoseCount; ++k) {
    const double angle = uniform(0.0, 2.0 * M_PI);
    const double offset = radial_clearance * uniform(0.9, 1.02);
    const double tilt = 0.5 * rim_tilt * uniform(-1.0, 1.0);
    const Vector3 tilt_axis(-std::sin(angle), std::cos(angle), 0.0);
    out.push_back({Vector3(offset * std::cos(angle), offset * std::sin(angle), uniform(-1e-5, 1e-5)),
                   dynamics::euler_parameters_from_axis_angle(tilt_axis, tilt),
                   Vector3(uniform(-0.3, 0.3), uniform(-0.3, 0.3), uniform(-0.03, 0.03)),
                   Vector3(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-5.0, 5.0))});
  }
  return out;
}

void set_counters(benchmark::State& state) {
  state.counters["seed"] = static_cast<double>(kSeed);
  state.counters["poses"] = kPoseCount;
  state.SetItemsProcessed(state.iterations());
}

void BM_Detection(benchmark::State& state) {
  std::vector<geometry::PartPose> journals;
  for (const JournalPose& p : poses()) {
    journals.push_back({p.position_W, dynamics::rotation_from_euler_parameters(p.euler_parameters).col(2)});
  }
  const geometry::PartPose bearing{};
  geometry::JointContacts contacts;
  size_t k = 0;
  for (auto _ : state) {
    geometry::detect_contacts(kParameters.dimensions, bearing, journals[k], contacts, kParameters.detection);
    benchmark::DoNotOptimize(contacts.contact_count);
    k = (k + 1) % journals.size();
  }
  set_counters(state);
}
BENCHMARK(BM_Detection);

void BM_Clearjoint(benchmark::State& state) {
  const dynamics::ClearanceRevoluteJoint joint("pin", {dynamics::kGround}, {0}, kParameters);
  std::vector<dynamics::SystemKinematics> kinematics;
  for (const JournalPose& p : poses()) {
    dynamics::SystemKinematics k(1);
    const dynamics::Matrix3 R = dynamics::rotation_from_euler_parameters(p.euler_parameters);
    k.set(0, {p.position_W, p.euler_parameters, p.velocity_W, R.transpose() * p.angular_velocity_W});
    kinematics.push_back(k);
  }
  const double memory[dynamics::kContactSlotCount] = {};
  double rate[dynamics::kContactSlotCount] = {};
  dynamics::GeneralisedForces forces(kinematics.front());
  size_t k = 0;
  for (auto _ : state) {
    joint.add_forces({0.0, kinematics[k], memory, rate}, forces);
    benchmark::DoNotOptimize(&forces);
    k = (k + 1) % kinematics.size();
  }
  set_counters(state);
}
BENCHMARK(BM_Clearjoint);

void simbody_force(benchmark::State& state, bool through_simbody) {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter(system);
  SimTK::GeneralForceSubsystem forces(system);
  SimTK::MobilizedBody::Free journal(
      matter.Ground(), SimTK::Body::Rigid(SimTK::MassProperties(1.0, SimTK::Vec3(0.0), SimTK::Inertia(1e-5))));
  const simbody::ClearanceRevoluteForce force(system, forces, "pin", {matter.Ground()}, {journal}, kParameters);
  const SimTK::State initial = system.realizeTopology();
  std::vector<SimTK::State> states;
  for (const JournalPose& p : poses()) {
    SimTK::State s = initial;
    const Vector4& e = p.euler_parameters;
    journal.setQToFitTransform(s, SimTK::Transform(SimTK::Rotation(SimTK::Quaternion(e[0], e[1], e[2], e[3])),
                                                   SimTK::Vec3(p.position_W[0], p.position_W[1], p.position_W[2])));
    journal.setUToFitVelocity(s, SimTK::SpatialVec(
        SimTK::Vec3(p.angular_velocity_W[0], p.angular_velocity_W[1], p.angular_velocity_W[2]),
        SimTK::Vec3(p.velocity_W[0], p.velocity_W[1], p.velocity_W[2])));
    states.push_back(s);
  }
  // Realised in place: a copied State's cache entries are out of date.
  for (SimTK::State& s : states) system.realize(s, SimTK::Stage::Velocity);
  SimTK::Vector_<SimTK::SpatialVec> body_forces(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0.0), SimTK::Vec3(0.0)));
  SimTK::Vector_<SimTK::Vec3> particle_forces(0);
  SimTK::Vector mobility_forces(matter.getNumMobilities(), 0.0);
  size_t k = 0;
  for (auto _ : state) {
    if (through_simbody) {
      force.calcForceContribution(states[k], body_forces, particle_forces, mobility_forces);
    } else {
      force.add_body_forces(states[k], body_forces);
    }
    benchmark::DoNotOptimize(&body_forces[1]);
    k = (k + 1) % states.size();
  }
  set_counters(state);
  state.counters["detections_per_call"] =
      static_cast<double>(force.joint().statistics().detection_calls) / static_cast<double>(state.iterations());
}
void BM_SimbodyForce(benchmark::State& state) { simbody_force(state, false); }
BENCHMARK(BM_SimbodyForce);
void BM_SimbodyCalcForceContribution(benchmark::State& state) { simbody_force(state, true); }
BENCHMARK(BM_SimbodyCalcForceContribution);

/// A free journal in a bearing fixed in the world, as MJCF.
constexpr const char* kFreeJournal = R"(<mujoco>
  <worldbody>
    <site name="bearing" pos="0 0 0"/>
    <body name="journal">
      <freejoint/>
      <inertial pos="0 0 0" mass="1" diaginertia="1e-5 1e-5 1e-5"/>
      <site name="journal" pos="0 0 0"/>
    </body>
  </worldbody>
  <custom>
    <text name="clearance:pin" data="bearing journal"/>
    <numeric name="clearance:pin:dimensions" data="0.01 0.02 0.0099 0.0198"/>
  </custom>
</mujoco>)";

void BM_MujocoPassive(benchmark::State& state) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "clearjoint_bench_free_journal.xml";
  std::ofstream(path) << kFreeJournal;
  char error[1000] = "";
  mjModel* model = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(path);
  if (model == nullptr) {
    state.SkipWithError(error);
    return;
  }
  {
    const mujoco::ClearanceJoints clearance(model);
    std::vector<mjData*> data;
    for (const JournalPose& p : poses()) {
      mjData* d = mj_makeData(model);
      for (int i = 0; i < 3; ++i) d->qpos[i] = p.position_W[i];
      for (int i = 0; i < 4; ++i) d->qpos[3 + i] = p.euler_parameters[i];
      // A free joint's qvel: linear velocity in the world, angular velocity in the body frame.
      const Vector3 w_B = dynamics::rotation_from_euler_parameters(p.euler_parameters).transpose() *
                          p.angular_velocity_W;
      for (int i = 0; i < 3; ++i) d->qvel[i] = p.velocity_W[i];
      for (int i = 0; i < 3; ++i) d->qvel[3 + i] = w_B[i];
      mj_kinematics(model, d);
      mj_comPos(model, d);
      mj_comVel(model, d);
      data.push_back(d);
    }
    size_t k = 0;
    for (auto _ : state) {
      clearance.add_passive_forces(data[k]);
      benchmark::DoNotOptimize(data[k]->qfrc_passive);
      k = (k + 1) % data.size();
    }
    for (mjData* d : data) mj_deleteData(d);
  }
  mj_deleteModel(model);
  set_counters(state);
}
BENCHMARK(BM_MujocoPassive);

}  // namespace

BENCHMARK_MAIN();
