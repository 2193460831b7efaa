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

dynamics::BodyState body_state(const RigidMotion& motion) {
  dynamics::BodyState state;
  state.position_W = motion.origin_W;
  state.euler_parameters = motion.orientation;
  state.velocity_W = motion.velocity_W;
  // SystemKinematics keeps omega in the body frame (eq. 33's omega'); the rotation is A(p).
  state.angular_velocity_B =
      dynamics::rotation_from_euler_parameters(motion.orientation).transpose() * motion.angular_velocity_W;
  return state;
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
  kinematics_.set(kBearing, body_state(bearing));
  kinematics_.set(kJournal, body_state(journal));
}

dynamics::ClearanceJointState TwoBodyClearanceJoint::evaluate(std::span<const double> impact_memory) const {
  return joint_.evaluate(time_, kinematics_, impact_memory);
}

int TwoBodyClearanceJoint::contact_forces(std::span<const double> impact_memory,
                                          std::span<ContactForce> out) const {
  const dynamics::ClearanceJointState state = evaluate(impact_memory);
  const int count = state.contacts.contact_count;
  for (int c = 0; c < count; ++c) {
    out[c] = {state.contact_force_on_journal_W[c], state.contacts.contacts[c].p_WCj,
              state.contacts.contacts[c].p_WCi};
  }
  return count;
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

void TwoBodyClearanceJoint::record_outputs(std::span<const double> impact_memory,
                                           std::span<double> values) const {
  joint_.record_outputs(time_, kinematics_, impact_memory, values);
}

}  // namespace clearjoint::engines
