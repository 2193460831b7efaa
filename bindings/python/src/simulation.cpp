// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.simulate_text / simulate_file: run a model with the GIL released and return
// its tables; the Python layer (clearjoint/_simulate.py) turns them into columns.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

/// {name: (header, values)} with values shaped (columns, rows): row k of it is one column of the
/// table, contiguous, so the Python layer hands out columns without copying.
py::dict tables_to_python(const dynamics::TablesInMemory& tables) {
  py::dict result;
  for (const dynamics::TablesInMemory::Table& table : tables.tables()) {
    const size_t columns = table.header.size();
    const size_t rows = table.rows();
    py::array_t<double> values({columns, rows});
    auto out = values.mutable_unchecked<2>();
    for (size_t r = 0; r < rows; ++r) {
      for (size_t c = 0; c < columns; ++c) out(c, r) = table.values[r * columns + c];
    }
    py::list header;
    for (const std::string& column : table.header) header.append(column);
    result[py::str(table.name)] = py::make_tuple(header, values);
  }
  return result;
}

py::dict summary_to_python(const dynamics::SimulationSummary& s) {
  py::dict d;
  d["steps"] = s.integration.steps;
  d["derivative_calls"] = s.integration.derivative_calls;
  d["smallest_step"] = s.integration.smallest_step;
  d["largest_step"] = s.integration.largest_step;
  d["restarts"] = s.integration.restarts;
  d["failed_attempts"] = s.integration.failed_attempts;
  d["initial_condition_iterations"] = s.initial_conditions.iterations;
  d["initial_position_residual"] = s.initial_conditions.position_residual;
  d["initial_velocity_residual"] = s.initial_conditions.velocity_residual;
  d["initial_energy"] = s.initial_energy;
  d["max_energy_change"] = s.max_energy_change;
  d["max_position_violation"] = s.max_position_violation;
  d["max_velocity_violation"] = s.max_velocity_violation;
  d["max_euler_norm_drift"] = s.max_euler_norm_drift;
  py::list statistics;
  for (const std::string& line : s.element_statistics) statistics.append(line);
  d["element_statistics"] = statistics;
  return d;
}

/// Run without the GIL. At every report time, and between them every 0.1 s of wall time
/// (simulation.hpp), the callback takes the GIL back to let Python handle signals (Ctrl-C raises
/// KeyboardInterrupt here, which unwinds the run: nothing is committed) and to call
/// `progress(fraction)` unless it is None. The size guard of the command line (run_size.hpp)
/// refuses a run far beyond any real study unless `allow_large`.
py::tuple run(const dynamics::ModelDescription& model, const py::object& progress, bool allow_large) {
  if (!allow_large) dynamics::check_run_size(dynamics::estimate_run_size(model));
  dynamics::TablesInMemory tables;
  dynamics::SimulationSummary summary;
  {
    py::gil_scoped_release release;
    summary = dynamics::simulate(model, tables, [&progress](double fraction) {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(fraction);
    });
  }
  return py::make_tuple(tables_to_python(tables), summary_to_python(summary));
}

}  // namespace

void bind_simulation(py::module_& module) {
  module.def(
      "simulate_text",
      [](const std::string& json_text, const std::string& source, const py::object& progress, bool allow_large) {
        return run(dynamics::parse_model(json_text, source), progress, allow_large);
      },
      py::arg("json_text"), py::arg("source"), py::arg("progress") = py::none(), py::arg("allow_large") = false,
      "Parse a model from JSON text (`source` names it in messages) and run it: "
      "(tables, summary), tables = {name: (header, values[columns, rows])}.");
  module.def(
      "simulate_file",
      [](const std::string& path, const py::object& progress, bool allow_large) {
        return run(dynamics::read_model_file(path), progress, allow_large);
      },
      py::arg("path"), py::arg("progress") = py::none(), py::arg("allow_large") = false,
      "Read a model file and run it: (tables, summary) as simulate_text.");
}

}  // namespace clearjoint::python
