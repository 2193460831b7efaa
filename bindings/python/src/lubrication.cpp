// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.bearing_characteristics: the handbook query of clearjoint::lubrication
// (bearing_characteristics.hpp); clearjoint/lubrication/ is the Python face users call. The
// arguments are checked here, each refusal naming the argument and its value: real numbers only
// (number_argument), names as str, the grid's counts as integers of any kind that fit an int.

#include <pybind11/pybind11.h>

#include <climits>
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "numpy_views.hpp"
#include "result_dicts.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

std::string quoted(const py::handle& value) { return std::string(py::repr(value)); }

/// A choice's name: a str (checked against the library's table by query_from_names); TypeError
/// naming the argument and the names for anything else.
template <geometry::TabledEnum E>
std::string name_argument(const py::handle& value, const char* name) {
  if (!py::isinstance<py::str>(value)) {
    throw py::type_error(std::string(name) + " = " + quoted(value) + ": must be one of " +
                         geometry::known_keys<E>() + " (a str)");
  }
  return value.cast<std::string>();
}

/// One count of the grid: any integer (int, numpy.int64: whatever implements __index__), not a
/// bool or a float, within an int (the solver counts cells in int; its own minima are checked by
/// query_from_names).
int cell_count(const py::handle& value, const char* name) {
  const auto refuse_type = [&] {
    return py::type_error(std::string(name) + " = " + quoted(value) + ": must be a whole number of cells (an int)");
  };
  if (PyBool_Check(value.ptr()) || py::isinstance(value, py::module_::import("numpy").attr("bool_"))) {
    throw refuse_type();
  }
  const auto count = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  if (!count) {
    PyErr_Clear();
    throw refuse_type();
  }
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(count.ptr(), &overflow);
  if (overflow != 0 || n < 0 || n > INT_MAX) {
    throw py::value_error(std::string(name) + " = " + quoted(count) + ": must be a whole number of cells in [0, " +
                          std::to_string(INT_MAX) + "]");
  }
  return static_cast<int>(n);
}

/// None or a pair (cells around, cells across).
std::optional<std::pair<int, int>> grid_argument(const py::handle& grid) {
  if (grid.is_none()) return std::nullopt;
  if (!py::isinstance<py::sequence>(grid) || py::isinstance<py::str>(grid) || py::len(grid) != 2) {
    throw py::type_error("grid = " + quoted(grid) + ": must be a pair (cells around, cells across) or None");
  }
  const py::sequence pair = py::reinterpret_borrow<py::sequence>(grid);
  return std::make_pair(cell_count(pair[0], "grid[0]"), cell_count(pair[1], "grid[1]"));
}

/// The library's message with its grid override spelt as the keyword that gives it.
std::string in_keyword_terms(std::string message) {
  constexpr std::string_view kOverride = "allow_large_grid";
  constexpr std::string_view kKeyword = "allow_large_grid=True";
  for (std::size_t at = message.find(kOverride); at != std::string::npos;
       at = message.find(kOverride, at + kKeyword.size())) {
    message.replace(at, kOverride.size(), kKeyword);
  }
  return message;
}

py::dict characteristics(const py::handle& eccentricity_ratio, const py::handle& width_ratio, const py::handle& motion,
                         const py::handle& cavitation, const py::handle& method, const py::handle& grid,
                         const py::handle& allow_large_grid) {
  lubrication::BearingCharacteristicsNames names;
  const double eps = number_argument(eccentricity_ratio, "eccentricity_ratio");
  const double ratio = number_argument(width_ratio, "width_ratio");
  names.motion = name_argument<lubrication::BearingMotion>(motion, "motion");
  names.method = name_argument<lubrication::BearingMethod>(method, "method");
  if (!cavitation.is_none()) {
    names.cavitation = name_argument<lubrication::CavitationModel>(cavitation, "cavitation");
  }
  names.grid = grid_argument(grid);
  names.allow_large_grid = flag_argument(allow_large_grid, "allow_large_grid");
  lubrication::BearingCharacteristicsQuery query;
  lubrication::BearingCharacteristics result;
  try {
    query = lubrication::query_from_names(eps, ratio, names);
    py::gil_scoped_release release;  // a fine grid takes milliseconds, an allowed large one seconds
    result = lubrication::bearing_characteristics(query);
  } catch (const geometry::InvalidInput& e) {
    throw py::value_error(in_keyword_terms(e.what()));
  }
  py::dict d = as_dict(result);
  d["cavitation"] = std::string(lubrication::to_string(query.cavitation));
  d["grid"] = query.method == lubrication::BearingMethod::grid || query.method == lubrication::BearingMethod::table
                  ? py::object(py::make_tuple(query.grid.circumferential_cells, query.grid.axial_cells))
                  : py::object(py::none());
  return d;
}

}  // namespace

void bind_lubrication(py::module_& module) {
  module.def("bearing_characteristics", &characteristics, py::arg("eccentricity_ratio"),
             py::arg("width_ratio"), py::arg("motion"), py::arg("cavitation"), py::arg("method"),
             py::arg("grid"), py::arg("allow_large_grid"),
             "The non-dimensional characteristics of a plain journal bearing as a dict; "
             "clearjoint.lubrication.bearing_characteristics is the documented entry.");
}

}  // namespace clearjoint::python
