// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parts of the `clearjoint._core` extension module, one function per source file.

#include <pybind11/pybind11.h>

#include "clearjoint/geometry/model/detection_options.hpp"

namespace clearjoint::python {

void bind_enum_tables(pybind11::module_& module);     // enum_codes.cpp: _enum_tables()
void bind_simulation(pybind11::module_& module);      // simulation.cpp
void bind_types(pybind11::module_& module);           // detection.cpp: enums, dimensions, results
void bind_detection_batch(pybind11::module_& module); // detection_batch.cpp
void bind_kernel(pybind11::module_& module);          // kernel.cpp
void bind_lubrication(pybind11::module_& module);     // lubrication.cpp: bearing_characteristics
void bind_pin_in_hole(pybind11::module_& module);     // pin_in_hole.cpp: detect_pin_in_hole

/// The detection options by their keys (detection_batch.cpp), each checked as the keyword
/// argument of its name; shared by detect and detect_pin_in_hole.
geometry::DetectionOptions detection_options(const pybind11::dict& given);

}  // namespace clearjoint::python
