// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.bearing_characteristics: the handbook query of clearjoint::lubrication
// (bearing_characteristics.hpp); clearjoint/lubrication/ is the Python face users call.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "clearjoint/geometry/primitives.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

/// "a, b": the names a front end accepts, from the library's own table.
template <typename Values>
std::string known_names(const Values& values) {
  std::string names;
  for (auto v : values) names += (names.empty() ? "" : ", ") + std::string(lubrication::to_string(v));
  return names;
}

/// The value named `name`, or ValueError "<field> = '<name>': unknown (known: ...)".
template <typename Value, typename Parse, typename Values>
Value parse(const std::string& name, const char* field, Parse from_string, const Values& values) {
  if (const std::optional<Value> value = from_string(name)) return *value;
  throw geometry::InvalidInput(std::string(field) + " = '" + name + "': unknown (known: " +
                               known_names(values) + ")");
}

py::dict characteristics(double eccentricity_ratio, double width_ratio, const std::string& motion,
                         const std::optional<std::string>& cavitation, const std::string& method,
                         const std::optional<std::pair<int, int>>& grid) {
  lubrication::BearingCharacteristicsQuery query;
  query.eccentricity_ratio = eccentricity_ratio;
  query.width_ratio = width_ratio;
  query.motion = parse<lubrication::BearingMotion>(motion, "motion", lubrication::bearing_motion_from_string,
                                                   lubrication::kBearingMotions);
  query.method = parse<lubrication::BearingMethod>(method, "method", lubrication::bearing_method_from_string,
                                                   lubrication::kBearingMethods);
  query.cavitation = cavitation ? parse<lubrication::CavitationModel>(
                                      *cavitation, "cavitation", lubrication::cavitation_model_from_string,
                                      lubrication::kCavitationModels)
                                : lubrication::default_cavitation(query.method);
  if (grid) {
    query.grid.circumferential_cells = grid->first;
    query.grid.axial_cells = grid->second;
    try {
      lubrication::validate(query.grid);
    } catch (const geometry::InvalidInput& e) {
      throw geometry::InvalidInput("grid = (" + std::to_string(grid->first) + ", " +
                                   std::to_string(grid->second) + "): " + e.what());
    }
  }
  lubrication::BearingCharacteristics result;
  {
    py::gil_scoped_release release;  // a fine grid takes milliseconds
    result = lubrication::bearing_characteristics(query);
  }
  py::dict d;
  d["sommerfeld_number"] = result.sommerfeld_number;
  d["attitude_angle"] = result.attitude_angle;
  d["side_flow_variable"] = result.side_flow_variable;
  d["max_pressure_ratio"] = result.max_pressure_ratio;
  d["iterations"] = result.iterations;
  d["converged"] = result.converged;
  d["cavitation"] = std::string(lubrication::to_string(query.cavitation));
  d["grid"] = query.method == lubrication::BearingMethod::grid
                  ? py::object(py::make_tuple(query.grid.circumferential_cells, query.grid.axial_cells))
                  : py::object(py::none());
  return d;
}

}  // namespace

void bind_lubrication(py::module_& module) {
  module.def("bearing_characteristics", &characteristics, py::arg("eccentricity_ratio"),
             py::arg("width_ratio"), py::arg("motion"), py::arg("cavitation"), py::arg("method"),
             py::arg("grid"),
             "The non-dimensional characteristics of a plain journal bearing as a dict; "
             "clearjoint.lubrication.bearing_characteristics is the documented entry.");
}

}  // namespace clearjoint::python
