// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// What a force element records (Simbody's Reporter, apart from its Force): the columns of its
/// table force_<name> written at every report time (simulation.hpp), and a line of counters for
/// the run summary. An element that records derives from ForceElement and from ForceRecorder;
/// the compliant and the non-smooth runs find it with recorder_of (recorded_by_run). The
/// clearance joint's contact depths, forces and scenario are the shipped example.

#include <span>
#include <string>
#include <vector>

#include "clearjoint/dynamics/force_element.hpp"

namespace clearjoint::dynamics {

class ForceRecorder {
 public:
  virtual ~ForceRecorder() = default;

  /// Names of the values record_outputs() writes (none: the element has no table).
  virtual std::vector<std::string> output_columns() const = 0;
  /// Write output_columns().size() values describing the element at this instant; `state` is
  /// its extra state (force_element.hpp).
  virtual void record_outputs(double time, const SystemKinematics& kinematics,
                              std::span<const double> state, std::span<double> values) const = 0;
  /// One line of counters for run summaries (empty: nothing to say).
  virtual std::string statistics_text() const { return {}; }
};

/// What `element` records, or null when it records nothing.
inline const ForceRecorder* recorder_of(const ForceElement& element) {
  return dynamic_cast<const ForceRecorder*>(&element);
}

}  // namespace clearjoint::dynamics
