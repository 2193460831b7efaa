// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.bearing_characteristics: the handbook query of clearjoint::lubrication
// (bearing_characteristics.hpp); clearjoint/lubrication/ is the Python face users call.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "result_dicts.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

py::dict characteristics(double eccentricity_ratio, double width_ratio, const std::string& motion,
                         const std::optional<std::string>& cavitation, const std::string& method,
                         const std::optional<std::pair<int, int>>& grid) {
  const lubrication::BearingCharacteristicsQuery query = lubrication::query_from_names(
      eccentricity_ratio, width_ratio,
      {.motion = motion, .method = method, .cavitation = cavitation, .grid = grid});
  lubrication::BearingCharacteristics result;
  {
    py::gil_scoped_release release;  // a fine grid takes milliseconds
    result = lubrication::bearing_characteristics(query);
  }
  py::dict d = as_dict(result);
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
