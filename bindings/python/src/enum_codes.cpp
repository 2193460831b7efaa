// SPDX-License-Identifier: BSD-3-Clause
// The table of every enum the package shows, from the library's tables: the Python member names,
// their codes (the C++ values, which array results hold as int8) and their labels as docstrings.

#include "enum_codes.hpp"

#include "bindings.hpp"
#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

/// The (class name, docstring, [(member, code, label), ...]) rows of clearjoint/_enums.py.
class EnumTables {
 public:
  /// Add E's table, as the library has it.
  template <geometry::TabledEnum E>
  EnumTables& add(const char* doc) {
    py::list rows;
    for (const geo::EnumEntry<E>& entry : geo::EnumTable<E>::entries) {
      rows.append(py::make_tuple(std::string(entry.name), static_cast<int>(entry.value), std::string(entry.label)));
    }
    tables_.append(py::make_tuple(PythonEnum<E>::name, doc, rows));
    return *this;
  }
  py::list list() const { return tables_; }

 private:
  py::list tables_;
};

py::list enum_tables() {
  EnumTables tables;
  tables.add<geo::Certainty>("Trust in an answer, strongest first. Array results hold these codes as int8.");
  tables.add<geo::CertificateReason>(
      "Why an answer is uncertain, or, for an exact one, why the floating-point tiers did not "
      "decide it; none for certified answers. Array results hold these codes as int8. "
      "certificate_reason_text(code) gives the sentence.");
  tables.add<geo::ContactScenario>(
      "The contact scenarios of the paper's Fig. 2: (a)-(i) misaligned axes, (j)-(l) parallel "
      "axes, plus none (free flight) and beyond_model. Array results hold these codes as int8; "
      "scenario_label(code) gives the label.");
  tables.add<geo::PinInHoleScenario>(
      "The contact scenarios of the pin-in-hole joint (docs/contact-detection.md, \"The "
      "pin-in-hole joint\"): edges, line, stops, face, their combinations, plus none and "
      "beyond_model.");
  tables.add<geo::ContactType>("What a contact is against. Array results hold these codes as int8.");
  tables.add<geo::ContactBase>("Where a contact is. Array results hold these codes as int8.");
  tables.add<geo::CirclePlaneTopology>("How a circle meets a plane. Array results hold these codes as int8.");
  tables.add<geo::CircleCylinderTopology>(
      "How a circle meets a cylinder's lateral surface. Array results hold these codes as int8.");
  tables.add<dynamics::ContactSlot>(
      "The clearance joint's contact slots: their keys prefix its output columns (radial_a.depth), "
      "their labels name them in plots.");
  return tables.list();
}

}  // namespace

py::object python_enum_class(const char* name) {
  // Looked up with the GIL held, by which time the package has imported clearjoint._enums (or
  // the import happens here). A plain pointer, not a function-local static object: a static's
  // initialisation guard could deadlock against the GIL if the import released it.
  static PyObject* module = nullptr;
  if (module == nullptr) module = py::module_::import("clearjoint._enums").release().ptr();
  return py::handle(module).attr(name);
}

int enum_code(const py::handle& value, const char* argument, const char* enum_name, int count) {
  const std::string shown = std::string(argument) + " = " + std::string(py::repr(value));
  py::object code;
  if (!PyBool_Check(value.ptr())) code = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!code) {
    PyErr_Clear();
    throw py::type_error(shown + ": must be a " + enum_name + " or its integer code");
  }
  if (code < py::int_(0) || !(code < py::int_(count))) {
    throw py::value_error(shown + ": not a " + enum_name + " code (0 to " + std::to_string(count - 1) + ")");
  }
  return code.cast<int>();
}

void bind_enum_tables(py::module_& module) {
  module.def("_enum_tables", &enum_tables,
             "[(class name, docstring, [(member, code, docstring), ...]), ...] for clearjoint/_enums.py.");
}

}  // namespace clearjoint::python
