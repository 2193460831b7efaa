// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// What a force element contributes to the equations of motion: its share of g in eq. (35)
/// (gravity, loads, spring-dampers, the clearance joint), its potential energy, and the ODE state
/// it integrates along with the bodies. An element reads the bodies' kinematics (mass-centre
/// position, rotation, linear and angular velocity in the world frame) and adds forces at points
/// and moments. It may own extra ODE state (e.g. an impact-velocity memory): it declares how many
/// variables, gives their initial values, and writes their rates on every evaluation.
///
/// Two further roles are interfaces of their own, which an element derives from as well when it
/// has them (as Simbody keeps Force, EventHandler and Reporter apart):
///   ForceEvents   (force_events.hpp)    discrete changes of its extra state between accepted
///                                       steps, and the onsets the integrator locates;
///   ForceRecorder (force_recorder.hpp)  output columns recorded at report times, and a line of
///                                       statistics for the run summary.
/// A force law needs only this interface: name() and add_forces().

#include <span>
#include <string_view>

#include "clearjoint/dynamics/generalised_forces.hpp"

namespace clearjoint::dynamics {

/// What a force element sees on one evaluation of the right-hand side.
struct ForceContext {
  double time = 0.0;
  const SystemKinematics& kinematics;
  std::span<const double> extra_state;  ///< this element's own variables, extra_state_count()
  std::span<double> extra_state_rate;   ///< their time derivatives; zeroed before the call
};

class ForceElement {
 public:
  virtual ~ForceElement() = default;

  /// The element's name, unique in a model (its table is force_<name>).
  virtual std::string_view name() const = 0;

  /// Add this element's forces and moments. Called millions of times: do not allocate.
  /// May throw SolverError when the element cannot be evaluated (e.g. a spring of zero length).
  /// The right-hand side must be a function of (time, y) alone: anything an element remembers
  /// is extra state, changed only by its ForceEvents.
  virtual void add_forces(const ForceContext& context, GeneralisedForces& forces) const = 0;

  /// Potential energy of a conservative element (0 for those that are not), for energy checks.
  virtual double potential_energy(const SystemKinematics& /*kinematics*/) const { return 0.0; }

  /// Extra ODE state this element integrates along with the bodies.
  virtual int extra_state_count() const { return 0; }
  virtual void initial_extra_state(std::span<double> /*state*/) const {}
};

}  // namespace clearjoint::dynamics
