// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The interface of everything that adds to g in eq. (35): gravity, loads, spring-dampers, and
/// the clearance joint. An element reads the bodies' kinematics (mass-centre position, rotation,
/// linear and angular velocity in the world frame) and adds forces at points and moments. It may
/// own extra ODE state (e.g. an impact-velocity memory): it declares how many variables, gives
/// their initial values, writes their rates on every evaluation, and may change them discretely
/// between accepted integration steps (update_extra_state). It may also name output columns that
/// the simulation records at every report time.

#include <span>
#include <string>
#include <string_view>
#include <vector>

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

  virtual std::string_view name() const = 0;

  /// Add this element's forces and moments. Called millions of times: do not allocate.
  /// May throw SolverError when the element cannot be evaluated (e.g. a spring of zero length).
  virtual void add_forces(const ForceContext& context, GeneralisedForces& forces) const = 0;

  /// Potential energy of a conservative element (0 for those that are not), for energy checks.
  virtual double potential_energy(const SystemKinematics& /*kinematics*/) const { return 0.0; }

  /// Extra ODE state this element integrates along with the bodies.
  virtual int extra_state_count() const { return 0; }
  virtual void initial_extra_state(std::span<double> /*state*/) const {}

  /// Discrete change of the extra state, called by the integrator with the state of every
  /// accepted step (and the initial state), never with trial stages or rejected steps. Returns
  /// true if it changed `state`; the integrator then restarts from the changed state. The
  /// right-hand side must stay a function of (time, y) alone: anything remembered goes here.
  virtual bool update_extra_state(double /*time*/, const SystemKinematics& /*kinematics*/,
                                  std::span<double> /*state*/) const {
    return false;
  }

  /// True if update_extra_state() would, at this state, record something that begins here and
  /// depends on the instant it began (a contact onset whose impact velocity is remembered). The
  /// integrator then brackets the earliest such instant inside the step just accepted, by
  /// bisection on its dense output, and calls update_extra_state() there. `state` is this
  /// element's extra state, constant through a step (its rate is zero). Must not allocate.
  virtual bool begins_event(const SystemKinematics& /*kinematics*/,
                            std::span<const double> /*state*/) const {
    return false;
  }

  /// Names of the values record_outputs() writes (none by default).
  virtual std::vector<std::string> output_columns() const { return {}; }
  /// Write output_columns().size() values describing the element at this instant.
  virtual void record_outputs(double /*time*/, const SystemKinematics& /*kinematics*/,
                              std::span<const double> /*state*/, std::span<double> /*values*/) const {}
  /// One line of counters for run summaries (empty: nothing to say).
  virtual std::string statistics_text() const { return {}; }
};

}  // namespace clearjoint::dynamics
