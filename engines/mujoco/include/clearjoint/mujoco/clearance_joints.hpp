// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// clearjoint's spatial revolute joints with radial and axial clearance added to a MuJoCo 2.2
/// model. The mechanism is an ordinary MJCF model; each clearance joint is declared in its
/// <custom> section and placed by two sites (docs/engines.md, "MuJoCo"):
///
///   <site name="pin.bearing" .../>            centre P_i of the bearing, its z axis the bearing's
///   <site name="pin.journal" .../>            centre P_j of the journal, its z axis the journal's
///   <custom>
///     <text    name="clearance:pin" data="pin.bearing pin.journal"/>   bearing site, journal site
///     <numeric name="clearance:pin:dimensions" data="0.010 0.020 0.0099 0.0198"/>  Ri Li Rj Lj [m]
///     <text    name="clearance:pin:normal_force_model" data="lankarani_nikravesh"/>  (optional)
///     <numeric name="clearance:pin:normal_force" data="1e11 1.5 0.9 1e-3"/>  K n ce v_min (optional)
///     <numeric name="clearance:pin:friction" data="0.1 1000"/>      mu_k, k [s/m] (optional)
///     <numeric name="clearance:pin:parallel_angle_tolerance" data="0"/>  [rad] (optional)
///   </custom>
///
/// Optional values default to paper Table 2 (dynamics::ClearanceJointParameters).
///
/// The pin-in-hole joint (a pin longer than the hole it passes through, docs/dynamics.md, "The
/// pin-in-hole geometry") instead of the paper's journal-bearing: the bearing's site is the hole's
/// centre midway between the link's faces, the journal's the pin point P that sits there when the
/// pin is centred, and the dimensions element is replaced by
///
///     <text    name="clearance:pin:geometry" data="pin_in_hole"/>    (default journal_bearing)
///     <numeric name="clearance:pin:pin_in_hole" data="0.01 0.02 0.0099 0.0101 0.015 -0.0101 0.015"/>
///
/// holding geometry::PinInHoleDimensions in the model file's order: hole.radius hole.length
/// pin.radius, then pin.stops[k].position pin.stops[k].outer_radius for each of 0, 1 or 2 stops
/// (3, 5 or 7 values) [m]. They are checked by the kernel's validate(PinInHoleDimensions); the
/// other fields and the force laws are the paper joint's. The forces
/// (detection, force law, friction: dynamics::ClearanceRevoluteJoint's own code) enter through
/// MuJoCo's passive-force callback mjcb_passive, as generalised forces in qfrc_passive, so that
/// every integrator stage (RK4's four) sees them.
///
/// Impact-speed memory: held here, one value per contact slot, read by every stage and changed
/// only by after_step(), which the caller runs after each mj_step on the accepted state: a
/// contact present there without memory records max(delta_dot, minimum_impact_speed), a slot
/// whose contact ended is cleared. MuJoCo steps at a fixed size and offers no event location, so
/// the onset is the end of the first step in contact (clearjoint's OnsetHandling::step_end): the
/// recorded speed is the approach speed one step after first touch.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::mujoco {

/// A clearance joint's declaration that the model does not satisfy (a missing site, a malformed
/// <custom> value, dimensions that fail the joint's checks); what() names it. One of the
/// project's bad-input errors (dynamics::ModelError, a ValidationError): an error of the joint's
/// own checks keeps its field_path() ("rod_slider.journal.radius") with the declaration as its
/// source; the adapter's own errors about an element have an empty path.
class ModelError : public dynamics::ModelError {
 public:
  using dynamics::ModelError::ModelError;
};

class ClearanceJoints {
 public:
  /// Read every "clearance:<name>" declaration of `model`. Throws ModelError naming the custom
  /// element or site at fault. `model` must outlive this object.
  explicit ClearanceJoints(const mjModel* model);
  ~ClearanceJoints();
  ClearanceJoints(const ClearanceJoints&) = delete;
  ClearanceJoints& operator=(const ClearanceJoints&) = delete;

  /// Make this object the one mjcb_passive calls for its model (several objects, one per model,
  /// may be installed; the callback is set while any is). Undone by the destructor.
  void install();

  /// Add every joint's forces to d->qfrc_passive (what the callback does). Needs d's positions
  /// and velocities propagated (mj_kinematics, mj_comVel), as they are inside mj_passive.
  void add_passive_forces(mjData* data) const;
  /// Update the impact-speed memories at the accepted state (after mj_step, and once after
  /// mj_forward on the initial state). Returns true if a memory changed.
  bool after_step(mjData* data);

  int count() const;
  const dynamics::ClearanceRevoluteJoint& joint(int k) const;
  /// Joint k's memory: dynamics::kContactSlotCount values [m/s], 0 = none.
  std::span<const double> impact_memory(int k) const;
  /// dynamics::ClearanceRevoluteJoint::output_columns() values of joint k at `data`'s state: a
  /// row of clearjoint's force_<name>.csv without its time.
  void record_outputs(int k, const mjData* data, std::span<double> values) const;
  /// The elastic energy stored in every joint's contacts at `data`'s state [J]
  /// (dynamics::ClearanceRevoluteJoint::potential_energy): a potential MuJoCo's own energy
  /// (mjData::energy) does not hold, since the joints' forces enter as passive forces.
  double potential_energy(const mjData* data) const;

 private:
  struct Joint;
  const mjModel* model_;
  std::vector<std::unique_ptr<Joint>> joints_;
  bool installed_ = false;
};

}  // namespace clearjoint::mujoco
