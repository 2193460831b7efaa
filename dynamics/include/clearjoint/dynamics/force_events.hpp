// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The events of a force element: discrete changes of its own extra state (force_element.hpp)
/// between accepted integration steps, and the onsets whose instant the integrator locates
/// (Simbody's EventHandler, apart from its Force). An element that has events derives from
/// ForceElement and from ForceEvents; MultibodySystem finds them once, when it is built
/// (events_of), and asks only those with extra state. The clearance joint's impact-velocity
/// memory is the shipped example.

#include <span>

#include "clearjoint/dynamics/force_element.hpp"

namespace clearjoint::dynamics {

class ForceEvents {
 public:
  virtual ~ForceEvents() = default;

  /// Discrete change of the extra state, called by the integrator with the state of every
  /// accepted step (and the initial state), never with trial stages or rejected steps. Returns
  /// true if it changed `state`; the integrator then restarts from the changed state. The
  /// right-hand side must stay a function of (time, y) alone: anything remembered goes here.
  virtual bool update_extra_state(double time, const SystemKinematics& kinematics,
                                  std::span<double> state) const = 0;

  /// True if update_extra_state() would, at this state, record something that begins here and
  /// depends on the instant it began (a contact onset whose impact velocity is remembered). The
  /// integrator then brackets the earliest such instant inside the step just accepted, by
  /// bisection on its dense output, and calls update_extra_state() there. `state` is this
  /// element's extra state, constant through a step (its rate is zero). Must not allocate.
  virtual bool begins_event(const SystemKinematics& /*kinematics*/,
                            std::span<const double> /*state*/) const {
    return false;
  }
};

/// The events of `element`, or null when it has none.
inline const ForceEvents* events_of(const ForceElement& element) {
  return dynamic_cast<const ForceEvents*>(&element);
}

}  // namespace clearjoint::dynamics
