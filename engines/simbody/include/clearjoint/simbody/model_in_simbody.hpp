// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A clearjoint model file's mechanism built in Simbody: bodies as MobilizedBodies, ideal joints
/// as mobilizers (a spanning tree from the ground) or, for the joints that close a loop,
/// constraints, and clearance joints as ClearanceRevoluteForce. The initial state is the one
/// clearjoint's own builder makes consistent (dynamics::consistent_start, from the mechanism
/// alone: no clearjoint force element is built for it), so that both engines start from the same
/// state.
///
/// Joints and their mobilizers (F on the parent, M on the child; M is F carried into the child
/// at the initial poses, so that every mobilizer starts at q = 0):
///   revolute       Pin        about F's z = the parent's axis
///   spherical      Ball       (or Constraint::Ball when it closes a loop)
///   universal      Universal  about F's x = the parent's cross axis, then M's y = the child's
///   cylindrical    Cylinder   along and about F's z = the parent's axis
///   translational  Slider     along F's x = the parent's axis
///   fixed          Weld
/// A body that no joint reaches from the ground gets a Free mobilizer. The tree takes joints
/// other than spherical first, so that loops close with spherical joints where the model allows.
///
/// Not supported (UnsupportedFeature names each one): angle_driver joints, point loads, and loops
/// closed by joints other than spherical.

#include <memory>
#include <string>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/simbody/clearance_revolute_force.hpp"

namespace clearjoint::simbody {

/// A model feature the Simbody route does not build; what() names it ("joints[3] \"drive\"
/// (angle_driver): ...").
class UnsupportedFeature : public dynamics::ModelError {
 public:
  using dynamics::ModelError::ModelError;
};

/// How one of the model's joints is realised in Simbody, for its reaction.
struct JointInSimbody {
  std::string name;
  /// The body whose reaction clearjoint reports: body j, or body i when body j is the ground.
  SimTK::MobilizedBody reported_body;
  /// Its joint point, in its frame.
  SimTK::Vec3 point_on_reported_body{0.0};
  /// The mobilizer whose child is one of the joint's bodies (invalid for a loop constraint).
  SimTK::MobilizedBody mobilizer;
  bool reported_body_is_child = true;
  /// A loop-closing spherical joint (only when mobilizer is not used).
  SimTK::Constraint::Ball loop;
  bool closes_loop = false;
};

class SimbodyModel {
 public:
  /// Throws UnsupportedFeature for what the route cannot build, dynamics::ModelError or
  /// dynamics::SolverError as dynamics::build_model does for a model that is not usable.
  explicit SimbodyModel(const dynamics::ModelDescription& model);
  SimbodyModel(const SimbodyModel&) = delete;
  SimbodyModel& operator=(const SimbodyModel&) = delete;

  SimTK::MultibodySystem& system() { return *system_; }
  const SimTK::SimbodyMatterSubsystem& matter() const { return *matter_; }
  /// The initial state at solver.start_time, realised to Velocity, with the clearance joints'
  /// memories set for contacts present at the start.
  const SimTK::State& initial_state() const { return initial_state_; }
  /// The mobilized body of model body `name` ("ground" too); throws ModelError naming `field`.
  const SimTK::MobilizedBody& body(const std::string& name, const std::string& field) const;
  /// The model's joints, in its order.
  const std::vector<JointInSimbody>& joints() const { return joints_; }
  /// The model's clearance joints, in its force order.
  const std::vector<std::unique_ptr<ClearanceRevoluteForce>>& clearance_joints() const {
    return clearance_joints_;
  }
  /// What dynamics::consistent_start reported on making the initial conditions consistent.
  const dynamics::InitialConditionReport& initial_conditions() const { return initial_conditions_; }

 private:
  std::unique_ptr<SimTK::MultibodySystem> system_;
  std::unique_ptr<SimTK::SimbodyMatterSubsystem> matter_;
  std::unique_ptr<SimTK::GeneralForceSubsystem> forces_;
  std::vector<std::string> body_names_;         ///< model order
  std::vector<SimTK::MobilizedBody> bodies_;    ///< model order
  std::vector<JointInSimbody> joints_;
  std::vector<std::unique_ptr<ClearanceRevoluteForce>> clearance_joints_;
  dynamics::InitialConditionReport initial_conditions_;
  SimTK::State initial_state_;
};

}  // namespace clearjoint::simbody
