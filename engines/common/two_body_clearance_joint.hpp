// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// clearjoint's clearance revolute joint between two bodies whose poses and velocities come from
/// another engine (Simbody, MuJoCo). The adapters own their bodies; this class turns two rigid
/// motions into the joint's SystemKinematics (bearing = body 0, journal = body 1) and calls the
/// joint itself, so that detection, contact kinematics, force laws and the impact-speed memory
/// are clearjoint's own code, not a copy. Internal to the engine adapters (not installed).

#include <span>
#include <string>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/generalised_forces.hpp"
#include "clearjoint/dynamics/system_kinematics.hpp"

namespace clearjoint::engines {

/// A body's motion as an engine gives it: the body frame's origin and orientation in the world,
/// the origin's velocity and the angular velocity, both in the world frame.
struct RigidMotion {
  dynamics::Vector3 origin_W = dynamics::Vector3::Zero();
  /// Body-to-world rotation (orthonormal).
  dynamics::Matrix3 rotation = dynamics::Matrix3::Identity();
  dynamics::Vector3 velocity_W = dynamics::Vector3::Zero();
  dynamics::Vector3 angular_velocity_W = dynamics::Vector3::Zero();
};

/// The joint's resultant on each body: a force and its moment about the body frame's origin
/// (RigidMotion::origin_W), world frame; and, for a lubricated joint, the film's power.
struct BodyWrenches {
  dynamics::Vector3 force_on_bearing_W = dynamics::Vector3::Zero();
  dynamics::Vector3 moment_on_bearing_W = dynamics::Vector3::Zero();
  dynamics::Vector3 force_on_journal_W = dynamics::Vector3::Zero();
  dynamics::Vector3 moment_on_journal_W = dynamics::Vector3::Zero();
  /// dW_film/dt [W], the rate of the film's work on the system (dynamics::JointFilmState::power),
  /// for an engine to integrate as W_film; 0 for a dry joint.
  double film_power = 0.0;
};

class TwoBodyClearanceJoint {
 public:
  /// `bearing` and `journal` give P and a in each engine body's frame (their `body` fields are
  /// ignored). Throws dynamics::ModelError naming "<name>.<field>" for unusable values.
  TwoBodyClearanceJoint(const std::string& name, const dynamics::ClearanceJointPart& bearing,
                        const dynamics::ClearanceJointPart& journal,
                        const dynamics::ClearanceJointParameters& parameters);

  /// Load the two bodies' motions at `time`; every call below reads them.
  void set_motions(double time, const RigidMotion& bearing, const RigidMotion& journal);

  /// The joint's full evaluation (contacts, forces per contact, slots, outputs' geometry) with
  /// `impact_memory` (dynamics::kContactSlotCount values, 0 = none).
  dynamics::ClearanceJointState evaluate(std::span<const double> impact_memory) const;
  /// The joint's forces on both bodies at the loaded motions, through
  /// dynamics::ClearanceRevoluteJoint::add_forces itself (the path of clearjoint's own
  /// integrator: no outputs computed, the detection's work space reused).
  BodyWrenches wrenches(std::span<const double> impact_memory) const;
  /// The elastic energy stored in the contacts (dynamics::ClearanceRevoluteJoint::potential_energy).
  double potential_energy() const;
  /// True when a contact is present in a slot without memory, or a slot remembers a contact that
  /// is gone: the memory must be updated (update_impact_memory) at this instant.
  bool memory_is_stale(std::span<const double> impact_memory) const;
  /// Record delta_dot(-) for contacts that begin here, clear slots whose contact ended
  /// (dynamics::ClearanceRevoluteJoint::update_extra_state). Returns true if it changed.
  bool update_impact_memory(std::span<double> impact_memory);

  /// dynamics::ClearanceRevoluteJoint::record_outputs at the loaded motions. `extra_state` is the
  /// joint's: the impact memory, then W_film for a lubricated joint (its film.work column; NaN
  /// when the engine passes the memory alone).
  void record_outputs(std::span<const double> extra_state, std::span<double> values) const;
  /// True for a joint with an oil film, whose work an engine integrates (BodyWrenches::film_power).
  bool lubricated() const { return joint_.extra_state_count() > dynamics::kFilmWorkIndex; }

  const dynamics::ClearanceRevoluteJoint& joint() const { return joint_; }
  double time() const { return time_; }

 private:
  dynamics::ClearanceRevoluteJoint joint_;
  dynamics::SystemKinematics kinematics_{2};
  mutable dynamics::GeneralisedForces forces_{kinematics_};
  double time_ = 0.0;
};

}  // namespace clearjoint::engines
