// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core: the compiled half of the `clearjoint` package (bindings/python/clearjoint/
// holds the Python half and the documentation users see).

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/version.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, module) {
  module.doc() = "Compiled core of the clearjoint package; use the `clearjoint` package itself.";
  // The linked library's version, not the headers': the two agree in any consistent install.
  module.attr("__version__") = clearjoint::version_string();
  // clearjoint::ValidationError (geometry::InvalidInput, dynamics::ModelError) derives from
  // std::invalid_argument, which pybind11 already turns into ValueError; a solver failure gets its
  // own RuntimeError subclass.
  py::register_exception<clearjoint::dynamics::SolverError>(module, "SolverError", PyExc_RuntimeError)
      .attr("__doc__") =
      "The equations of motion cannot be solved from some time on: singular or inconsistent "
      "constraints, a collapsed step size, a state that stopped being finite. The message says "
      "when and why.";
  clearjoint::python::bind_enum_tables(module);
  clearjoint::python::bind_types(module);
  clearjoint::python::bind_detection_batch(module);
  clearjoint::python::bind_pin_in_hole(module);
  clearjoint::python::bind_kernel(module);
  clearjoint::python::bind_simulation(module);
  clearjoint::python::bind_lubrication(module);
}
