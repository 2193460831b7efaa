// SPDX-License-Identifier: BSD-3-Clause
#include "two_body_clearance_joint.hpp"

namespace clearjoint::engines {

namespace {

constexpr dynamics::BodyIndex kBearing = 0;
constexpr dynamics::BodyIndex kJournal = 1;

dynamics::ClearanceJointPart on_body(dynamics::ClearanceJointPart part, dynamics::BodyIndex body) {
  part.body = body;
  return part;
}

/// The engine's rotation matrix as it is, without a round trip through Euler parameters.
dynamics::BodyKinematics body_kinematics(const RigidMotion& motion) {
  dynamics::BodyKinematics k;
  k.position_W = motion.origin_W;
  k.rotation = motion.rotation;
  k.velocity_W = motion.velocity_W;
  k.angular_velocity_W = motion.angular_velocity_W;
  k.angular_velocity_B = motion.rotation.transpose() * motion.angular_velocity_W;
  return k;
}

}  // namespace

TwoBodyClearanceJoint::TwoBodyClearanceJoint(const std::string& name,
                                             const dynamics::ClearanceJointPart& bearing,
                                             const dynamics::ClearanceJointPart& journal,
                                             const dynamics::ClearanceJointParameters& parameters)
    : joint_(name, on_body(bearing, kBearing), on_body(journal, kJournal), parameters) {}

void TwoBodyClearanceJoint::set_motions(double time, const RigidMotion& bearing,
                                        const RigidMotion& journal) {
  time_ = time;
  kinematics_.set_kinematics(kBearing, body_kinematics(bearing));
  kinematics_.set_kinematics(kJournal, body_kinematics(journal));
}

dynamics::ClearanceJointState TwoBodyClearanceJoint::evaluate(std::span<const double> impact_memory) const {
  return joint_.evaluate(time_, kinematics_, impact_memory);
}

BodyWrenches TwoBodyClearanceJoint::wrenches(std::span<const double> impact_memory) const {
  forces_.clear();
  // The extra state's rates: the memory's stay zero; a lubricated joint writes W_film's.
  double rate[dynamics::kFilmWorkIndex + 1] = {};
  joint_.add_forces({time_, kinematics_, impact_memory, rate}, forces_);
  return {forces_.force_W(kBearing), forces_.moment_W(kBearing), forces_.force_W(kJournal),
          forces_.moment_W(kJournal), rate[dynamics::kFilmWorkIndex]};
}

double TwoBodyClearanceJoint::potential_energy() const { return joint_.potential_energy(kinematics_); }

bool TwoBodyClearanceJoint::memory_is_stale(std::span<const double> impact_memory) const {
  const dynamics::ClearanceJointState state = evaluate(impact_memory);
  for (int slot = 0; slot < dynamics::kContactSlotCount; ++slot) {
    if (state.slots[slot].active != (impact_memory[slot] != 0.0)) return true;
  }
  return false;
}

bool TwoBodyClearanceJoint::update_impact_memory(std::span<double> impact_memory) {
  return joint_.update_extra_state(time_, kinematics_, impact_memory);
}

void TwoBodyClearanceJoint::record_outputs(std::span<const double> extra_state,
                                           std::span<double> values) const {
  joint_.record_outputs(time_, kinematics_, extra_state, values);
}

}  // namespace clearjoint::engines
