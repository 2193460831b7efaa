// SPDX-License-Identifier: BSD-3-Clause
// The one serialisation of a run's summary: the command line writes it as summary.json, the
// Python package reads the same text into its dict, and the HDF5 file keeps it as an attribute.

#include <nlohmann/json.hpp>

#include "clearjoint/dynamics/simulation.hpp"

namespace clearjoint::dynamics {

std::string summary_json(const SimulationSummary& s) {
  // Insertion order: the keys as documented (docs/dynamics.md, "Summary"). Non-finite numbers
  // (none in a completed run) would be written as null: the text is strict JSON either way.
  nlohmann::ordered_json j;
  j["steps"] = s.integration.steps;
  j["derivative_calls"] = s.integration.derivative_calls;
  j["smallest_step"] = s.integration.smallest_step;
  j["largest_step"] = s.integration.largest_step;
  j["restarts"] = s.integration.restarts;
  j["failed_attempts"] = s.integration.failed_attempts;
  j["located_onsets"] = s.integration.located_onsets;
  j["onset_probes"] = s.integration.onset_probes;
  j["initial_condition_iterations"] = s.initial_conditions.iterations;
  j["initial_position_residual"] = s.initial_conditions.position_residual;
  j["initial_velocity_residual"] = s.initial_conditions.velocity_residual;
  j["initial_energy"] = s.initial_energy;
  j["max_energy_change"] = s.max_energy_change;
  j["max_position_violation"] = s.max_position_violation;
  j["max_velocity_violation"] = s.max_velocity_violation;
  j["max_euler_norm_drift"] = s.max_euler_norm_drift;
  j["element_statistics"] = s.element_statistics;
  j["overrides"] = nlohmann::ordered_json::parse(overrides_json(s.overrides));
  return j.dump(2) + "\n";
}

}  // namespace clearjoint::dynamics
