// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.simulate_text / simulate_file / simulate_into_folder: run a model with the GIL
// released, returning its tables or writing its folder; the Python layer
// (clearjoint/_simulate.py) turns them into columns. _core.Simulator: a model stepped from Python
// (clearjoint/_simulator.py).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <functional>
#include <memory>

#include "bindings.hpp"
#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/dynamics/model_overrides.hpp"
#include "clearjoint/dynamics/run_size.hpp"
#include "clearjoint/dynamics/simulation.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/dynamics/simulator.hpp"
#include "clearjoint/engines/engine_choice.hpp"
#include "run_folder.hpp"

#ifdef CLEARJOINT_WITH_NONSMOOTH
#include "clearjoint/nonsmooth/moreau_jean_run.hpp"
#endif

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

/// The summary as the dict of json.loads(summary_json): one serialisation for summary.json,
/// run.h5 and Python.
py::object summary_to_python(const dynamics::SimulationSummary& s) {
  return py::module_::import("json").attr("loads")(dynamics::summary_json(s));
}

/// What a run does with its model: where it comes from, and the overrides the call adds.
/// The keyword that names the engine: the field path of an engine's refusal.
constexpr std::string_view kEngineKeyword = "engine";

struct RunRequest {
  bool allow_large = false;
  std::optional<double> report_step;
  std::optional<long> decimation;
  /// simulate(overrides=...): written into the model's JSON text before it is read.
  dynamics::ModelOverrides overrides;
  std::string engine = "clearjoint";
  /// simulate(write_fclib=..., fclib_count=...): the program's --write-fclib and --fclib-count
  /// (docs/nonsmooth.md, "FCLIB problems").
  std::optional<std::string> fclib_folder;
  std::optional<long> fclib_count;
};

/// Python's overrides {path: JSON text of the value}, in the order given, named in messages as
/// the argument ("overrides['solver.end_time']").
dynamics::ModelOverrides overrides_of(const std::vector<std::pair<std::string, std::string>>& items) {
  dynamics::ModelOverrides overrides;
  for (const auto& [path, value] : items) overrides.push_back({path, value, "overrides['" + path + "']"});
  return overrides;
}

/// The model text with the request's overrides written in (the text as given without any).
std::string text_with_overrides(const std::string& json_text, const std::string& source, const RunRequest& request) {
  return request.overrides.empty() ? json_text : dynamics::apply_overrides(json_text, source, request.overrides);
}

dynamics::ModelDescription with_overrides(dynamics::ModelDescription model, const RunRequest& request) {
  if (request.report_step) {
    model.solver.report_step = *request.report_step;
    dynamics::validate(model.solver);
  }
  if (request.decimation) {
    if (!(*request.decimation >= 1 && *request.decimation <= static_cast<long>(dynamics::kMaxDecimation))) {
      throw py::value_error("decimation = " + std::to_string(*request.decimation) + ": must be in [1, 1e9]");
    }
    model.output_decimation = *request.decimation;
  }
  return model;
}

/// The run of `model`, planned before any output exists, as the program's simulate plans it
/// (engines/choice: the engine's checks under the keyword's name, Simbody's route, a
/// solver.method "moreau_jean" model as nonsmooth::MoreauJeanRun); a Moreau-Jean run that also
/// writes its contact problems (write_fclib) here, as the program's --write-fclib.
using engines::PlannedRun;
PlannedRun plan_run(const dynamics::ModelDescription& model, const RunRequest& request) {
  const dynamics::ModelDescription m = with_overrides(model, request);
  const dynamics::RunOptions options{.allow_large = request.allow_large};
  if (request.fclib_folder && m.solver_method != dynamics::SolverMethod::moreau_jean) {
    throw dynamics::ModelError("write_fclib = '" + *request.fclib_folder +
                               "': needs solver.method = \"moreau_jean\" (a compliant run has no contact "
                               "problems; docs/nonsmooth.md)");
  }
#ifdef CLEARJOINT_WITH_NONSMOOTH
  if (request.fclib_folder && request.engine == engines::kDefaultEngine) {
    auto run = std::make_shared<nonsmooth::MoreauJeanRun>(m, options);
    const nonsmooth::FclibExport fclib{*request.fclib_folder,
                                       request.fclib_count.value_or(nonsmooth::kDefaultFclibProblems)};
    // Checked under the keyword's name first (errors name write_fclib, not the program's
    // --write-fclib); the run's own check of the same folder then passes.
    nonsmooth::prepare_fclib_folder(fclib, "write_fclib");
    run->write_fclib(fclib);
    return [run](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
      return run->run(output, progress);
    };
  }
#endif
  return engines::plan_run(request.engine, kEngineKeyword, m, options);
}

/// The callback run under the GIL-free integration: takes the GIL back to let Python handle
/// signals (Ctrl-C raises KeyboardInterrupt here, which unwinds the run: nothing is committed)
/// and to call `progress(fraction)` unless it is None. Called at every report time and, between
/// them, every 0.1 s of wall time (simulation.hpp).
dynamics::ProgressCallback python_progress(const py::object& progress) {
  return [&progress](double fraction) {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(fraction);
  };
}

/// Run in memory without the GIL: (tables, summary). The model is built once (SimulationRun),
/// with the command line's size guard unless `allow_large`.
py::tuple run_in_memory(const dynamics::ModelDescription& model, const py::object& progress, const RunRequest& request) {
  const PlannedRun run = plan_run(model, request);
  dynamics::TablesInMemory tables;
  dynamics::SimulationSummary summary;
  {
    py::gil_scoped_release release;
    summary = run(tables, python_progress(progress));
  }
  summary.overrides = request.overrides;
  return py::make_tuple(tables_to_python(tables), summary_to_python(summary));
}

/// Run into a folder, as `clearjoint simulate --out` does (run_folder.hpp): the summary.
py::object run_into_folder(const dynamics::ModelDescription& model, const std::string& model_json,
                           const py::object& progress, const RunRequest& request, const std::string& out,
                           const std::string& format, bool force) {
  const PlannedRun run = plan_run(model, request);
  const dynamics::RunFolderOptions options{dynamics::run_format(format), force, request.overrides};
  dynamics::SimulationSummary summary;
  {
    py::gil_scoped_release release;
    const dynamics::ProgressCallback callback = python_progress(progress);
    summary = dynamics::write_run_folder(
        [&](dynamics::SimulationOutput& output) { return run(output, callback); },
        model_json, out, options);
  }
  return summary_to_python(summary);
}

using OverrideItems = std::vector<std::pair<std::string, std::string>>;

RunRequest request_of(bool allow_large, std::optional<double> report_step, std::optional<long> decimation,
                      const OverrideItems& overrides, const std::string& engine,
                      const std::optional<std::string>& fclib_folder, std::optional<long> fclib_count) {
  engines::require_engine(engine, kEngineKeyword);
  return {allow_large, report_step, decimation, overrides_of(overrides), engine, fclib_folder, fclib_count};
}

/// The state as a NumPy copy (the simulator's buffer changes at every step).
py::array_t<double> state_array(std::span<const double> state) {
  py::array_t<double> out(static_cast<py::ssize_t>(state.size()));
  std::copy(state.begin(), state.end(), out.mutable_data());
  return out;
}

dynamics::Vector3 vector3(const py::handle& value, const char* name) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 1 || array.shape(0) != 3) {
    throw py::type_error(std::string(name) + ": must be 3 numbers");
  }
  return {array.at(0), array.at(1), array.at(2)};
}

py::dict body_state_dict(const dynamics::BodyState& s) {
  py::dict d;
  d["position"] = state_array(std::span<const double>(s.position_W.data(), 3));
  d["euler_parameters"] = state_array(std::span<const double>(s.euler_parameters.data(), 4));
  d["velocity"] = state_array(std::span<const double>(s.velocity_W.data(), 3));
  d["angular_velocity_body"] = state_array(std::span<const double>(s.angular_velocity_B.data(), 3));
  return d;
}

py::array_t<double> vector_array(const dynamics::Vector3& v) {
  return state_array(std::span<const double>(v.data(), 3));
}

/// A clearance joint's state as a dict: the contacts (a JointContacts, as detect gives), the
/// force and moment on the journal in the world frame (contacts plus film), each contact's force,
/// each slot's law variables (eqs. 23-24), the film where the joint is lubricated, the axis angle
/// and the rim centres in the bearing frame: the quantities of the run's joint table.
py::dict joint_state_dict(const dynamics::ClearanceJointState& s) {
  py::dict d;
  if (s.pin_in_hole_scenario) {
    // A pin-in-hole joint: its contacts as detect_pin_in_hole gives them.
    geometry::PinInHoleContacts pin;
    pin.scenario = *s.pin_in_hole_scenario;
    pin.aligned = s.contacts.aligned;
    pin.certificate = s.contacts.certificate;
    pin.contact_count = s.contacts.contact_count;
    std::copy_n(s.contacts.contacts.begin(), pin.contact_count, pin.contacts.begin());
    d["contacts"] = py::cast(pin);
  } else {
    d["contacts"] = py::cast(s.contacts);
  }
  d["force_on_journal"] = vector_array(s.force_on_journal_W);
  d["moment_on_journal"] = vector_array(s.moment_on_journal_W);
  py::array_t<double> contact_forces({static_cast<py::ssize_t>(s.contacts.contact_count), py::ssize_t{3}});
  for (int k = 0; k < s.contacts.contact_count; ++k) {
    for (int i = 0; i < 3; ++i) contact_forces.mutable_at(k, i) = s.contact_force_on_journal_W[k][i];
  }
  d["contact_force_on_journal"] = contact_forces;
  py::dict slots;
  for (int k = 0; k < dynamics::kContactSlotCount; ++k) {
    const dynamics::SlotState& slot = s.slots[k];
    py::dict entry;
    entry["active"] = slot.active;
    entry["depth"] = slot.depth;
    entry["approach_speed"] = slot.approach_speed;
    entry["impact_speed"] = slot.impact_speed;
    entry["normal_force"] = slot.normal_force;
    entry["friction_force"] = slot.friction_force;
    slots[py::str(std::string(dynamics::to_string(static_cast<dynamics::ContactSlot>(k))))] = entry;
  }
  d["slots"] = slots;
  if (s.film) {
    const dynamics::JointFilmState& f = *s.film;
    py::dict film;
    film["regime"] = static_cast<int>(f.regime);  // the force table's film.regime code
    film["weight"] = f.weight;
    film["min_thickness"] = f.min_thickness;
    film["eccentricity_ratio"] = f.eccentricity_ratio;
    film["attitude_angle"] = f.attitude_angle;
    film["max_pressure"] = f.max_pressure;
    film["force_on_journal"] = vector_array(f.force_on_journal_W);
    film["moment_on_journal"] = vector_array(f.moment_on_journal_W);
    film["power"] = f.power;
    d["film"] = film;
  } else {
    d["film"] = py::none();
  }
  d["axis_angle"] = s.axis_angle;
  d["rim_a_in_bearing"] = vector_array(s.rim_a_in_bearing);
  d["rim_b_in_bearing"] = vector_array(s.rim_b_in_bearing);
  return d;
}

}  // namespace

void bind_simulation(py::module_& module) {
  module.def(
      "simulate_text",
      [](const std::string& json_text, const std::string& source, const py::object& progress, bool allow_large,
         std::optional<double> report_step, std::optional<long> decimation, const OverrideItems& overrides,
         const std::string& engine, const std::optional<std::string>& write_fclib, std::optional<long> fclib_count) {
        const RunRequest request =
            request_of(allow_large, report_step, decimation, overrides, engine, write_fclib, fclib_count);
        return run_in_memory(dynamics::parse_model(text_with_overrides(json_text, source, request), source), progress,
                             request);
      },
      py::arg("json_text"), py::arg("source"), py::arg("progress") = py::none(), py::arg("allow_large") = false,
      py::arg("report_step") = py::none(), py::arg("decimation") = py::none(),
      py::arg("overrides") = OverrideItems{}, py::arg("engine") = "clearjoint",
      py::arg("write_fclib") = py::none(), py::arg("fclib_count") = py::none(),
      "Parse a model from JSON text (`source` names it in messages), with `overrides` [(path, JSON "
      "value)] written in (model_overrides.hpp), and run it with `engine`: (tables, summary), "
      "tables = {name: (header, values[columns, rows])}.");
  module.def(
      "simulate_file",
      [](const std::string& path, const py::object& progress, bool allow_large, std::optional<double> report_step,
         std::optional<long> decimation, const OverrideItems& overrides, const std::string& engine,
         const std::optional<std::string>& write_fclib, std::optional<long> fclib_count) {
        const RunRequest request =
            request_of(allow_large, report_step, decimation, overrides, engine, write_fclib, fclib_count);
        const std::string text = text_with_overrides(dynamics::read_model_text(path), path, request);
        return run_in_memory(dynamics::parse_model(text, path), progress, request);
      },
      py::arg("path"), py::arg("progress") = py::none(), py::arg("allow_large") = false,
      py::arg("report_step") = py::none(), py::arg("decimation") = py::none(),
      py::arg("overrides") = OverrideItems{}, py::arg("engine") = "clearjoint",
      py::arg("write_fclib") = py::none(), py::arg("fclib_count") = py::none(),
      "Read a model file and run it: (tables, summary) as simulate_text.");
  module.def(
      "simulate_into_folder",
      [](const std::string& json_text, const std::string& source, const std::string& out, const std::string& format,
         bool force, const py::object& progress, bool allow_large, std::optional<double> report_step,
         std::optional<long> decimation, const OverrideItems& overrides, const std::string& engine,
         const std::optional<std::string>& write_fclib, std::optional<long> fclib_count) {
        const RunRequest request =
            request_of(allow_large, report_step, decimation, overrides, engine, write_fclib, fclib_count);
        const std::string text = text_with_overrides(json_text, source, request);
        return run_into_folder(dynamics::parse_model(text, source), text, progress, request, out, format, force);
      },
      py::arg("json_text"), py::arg("source"), py::arg("out"), py::arg("format"), py::arg("force"),
      py::arg("progress") = py::none(), py::arg("allow_large") = false, py::arg("report_step") = py::none(),
      py::arg("decimation") = py::none(), py::arg("overrides") = OverrideItems{}, py::arg("engine") = "clearjoint",
      py::arg("write_fclib") = py::none(), py::arg("fclib_count") = py::none(),
      "Run a model (JSON text) into the output folder `out` as `clearjoint simulate --out` does "
      "(model.json: the model as run, overrides written in); the summary.");
  module.def(
      "engines",
      [] {
        std::vector<std::string> names;
        for (const std::string_view name : engines::available_engines()) names.emplace_back(name);
        return names;
      },
      "The engines simulate() can run in this build.");
  module.def("hdf5_available", &dynamics::hdf5_available, "Whether this build writes HDF5 run files.");

  py::class_<dynamics::Simulator>(module, "Simulator")
      .def(py::init([](const std::string& json_text, const std::string& source) {
             return std::make_unique<dynamics::Simulator>(dynamics::parse_model(json_text, source));
           }),
           py::arg("json_text"), py::arg("source"))
      .def_property_readonly("time", &dynamics::Simulator::time)
      .def_property_readonly("end_time", &dynamics::Simulator::end_time)
      .def_property_readonly("finished", &dynamics::Simulator::finished)
      .def_property_readonly("state", [](const dynamics::Simulator& s) { return state_array(s.state()); })
      .def("set_state",
           [](dynamics::Simulator& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& y) {
             if (y.ndim() != 1) throw py::value_error("state: must be a 1-D array");
             s.set_state(std::span<const double>(y.data(), static_cast<std::size_t>(y.shape(0))));
           })
      .def("body_state", [](const dynamics::Simulator& s, const std::string& body) {
        return body_state_dict(s.body_state(body));
      })
      .def("apply_load",
           [](dynamics::Simulator& s, const std::string& body, const py::handle& force, const py::handle& moment) {
             s.apply_load(body, vector3(force, "force"), vector3(moment, "moment"));
           },
           py::arg("body"), py::arg("force"), py::arg("moment"))
      .def("clear_loads", &dynamics::Simulator::clear_loads)
      .def("step",
           [](dynamics::Simulator& s) {
             py::gil_scoped_release release;
             s.step();
           })
      .def("advance_to",
           [](dynamics::Simulator& s, double t) {
             // A long advance runs without the GIL and looks at signals every 0.1 s of wall time,
             // as simulate does: Ctrl-C stops it at a step.
             py::gil_scoped_release release;
             auto last = std::chrono::steady_clock::now();
             s.advance_to(t, [&last] {
               const auto now = std::chrono::steady_clock::now();
               if (now - last < std::chrono::milliseconds(100)) return;
               last = now;
               py::gil_scoped_acquire acquire;
               if (PyErr_CheckSignals() != 0) throw py::error_already_set();
             });
           },
           py::arg("t"))
      .def("take_impacts",
           [](dynamics::Simulator& s) {
             py::list out;
             for (const dynamics::ImpactEvent& e : s.take_impacts()) {
               py::dict d;
               d["time"] = e.time;
               d["joint"] = e.joint;
               d["slot"] = std::string(dynamics::to_string(e.slot));
               d["impact_speed"] = e.impact_speed;
               out.append(d);
             }
             return out;
           })
      .def("joint_state",
           [](dynamics::Simulator& s, const std::string& name) { return joint_state_dict(s.joint_state(name)); },
           py::arg("name"))
      .def("statistics", [](const dynamics::Simulator& s) {
        const dynamics::IntegrationStatistics& i = s.statistics();
        py::dict d;
        d["steps"] = i.steps;
        d["derivative_calls"] = i.derivative_calls;
        d["restarts"] = i.restarts;
        d["located_onsets"] = i.located_onsets;
        return d;
      });
}

}  // namespace clearjoint::python
