// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// clearjoint's spatial revolute joint with radial and axial clearance as a Simbody force element
/// (a Force::Custom): a bearing cylinder fixed in one MobilizedBody, a journal cylinder in
/// another, and between them the certified contact detection, the normal force law and the
/// regularised friction of clearjoint::dynamics::ClearanceRevoluteJoint (paper Sections 3-4),
/// evaluated by that class itself.
///
/// Impact-speed memory (the delta_dot(-) of eq. 28). One value per contact slot
/// (dynamics::ContactSlot), held in a Simbody discrete variable of the State, so that it is
/// constant through every step and its trial stages. A triggered event handler, added to the
/// System with the force, watches for a contact present in a slot without memory (or a memory
/// whose contact ended): Simbody localises the first instant where that holds inside the step,
/// and the handler records max(delta_dot, minimum_impact_speed) there, as clearjoint's own
/// integrator does at a located onset. The witness is a step function (-1, +1): Simbody's
/// localisation brackets its sign change as it would a root. Until the memory is set, a stage
/// uses its own approach speed, as in clearjoint.
///
/// The memory is not set by Simbody at the start of a run: call initialize_impact_memory() on
/// the initial State (after realising it to Velocity) when the parts may start in contact.
///
/// Lubricated joints (parameters.lubrication). The oil film's force and moment are applied with
/// the contacts', and its work on the system, W_film(t) = integral of the film's power
/// (dynamics::JointFilmState::power), is a continuous state variable (a Simbody z, 0 at the
/// start) that Simbody integrates with the motion under the same accuracy: the force table's
/// film.work, and with System::calcEnergy the energy balance E(t) - E(0) = W_film(t) of a
/// damping-free joint, as in clearjoint's own run.

#include <span>
#include <string>
#include <vector>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/simbody/simbody_headers.hpp"

namespace clearjoint::simbody {

/// One cylinder of the joint: the centre P of its axis segment and its axis direction a (need
/// not be unit), in the frame of `body`.
struct ClearancePartInBody {
  SimTK::MobilizedBody body;
  SimTK::Vec3 point_B{0.0};
  SimTK::Vec3 axis_B{0.0, 0.0, 1.0};
};

class ClearanceRevoluteForce : public SimTK::Force::Custom {
 public:
  /// Adds the force to `forces` and its onset event handler to `system`, which must own
  /// `forces`. Throws dynamics::ModelError naming "<name>.<field>" for bad dimensions, axes or
  /// force law, and for a bearing and journal on the same body.
  ClearanceRevoluteForce(SimTK::MultibodySystem& system, SimTK::GeneralForceSubsystem& forces,
                         const std::string& name, const ClearancePartInBody& bearing,
                         const ClearancePartInBody& journal,
                         const dynamics::ClearanceJointParameters& parameters);

  /// Set the memory for contacts present in `state` (realised to Velocity): a run that starts
  /// in contact records the approach speeds at its first instant.
  void initialize_impact_memory(SimTK::State& state) const;
  /// The memory in `state`: dynamics::kContactSlotCount values [m/s], 0 = none.
  std::span<const double> impact_memory(const SimTK::State& state) const;
  /// The joint at `state` (realised to Velocity): contacts, forces, slots, the outputs' geometry.
  dynamics::ClearanceJointState evaluate(const SimTK::State& state) const;
  /// Add the joint's forces at `state` (realised to Velocity) to `body_forces` (one entry per
  /// mobilized body, ground frame, moment first): what Simbody's calcForce does when it
  /// realises Dynamics, without Force::calcForceContribution's temporaries. For callers that
  /// assemble forces themselves, and for benchmarks.
  void add_body_forces(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& body_forces) const;
  /// The values of dynamics::ClearanceRevoluteJoint::output_columns() at `state` (realised to
  /// Velocity): the columns of clearjoint's force_<name>.csv, film.work from film_work().
  void record_outputs(const SimTK::State& state, std::span<double> values) const;
  /// W_film [J] in `state`: the oil film's work on the system since the start; 0 for a dry joint.
  double film_work(const SimTK::State& state) const;
  /// clearjoint's joint that computes everything: its name, parameters, output_columns(),
  /// statistics_text() and recorded_impacts() (the impacts recorded by the event handler).
  const dynamics::ClearanceRevoluteJoint& joint() const;

  class Impl;

 private:
  const Impl& impl() const;
};

}  // namespace clearjoint::simbody
