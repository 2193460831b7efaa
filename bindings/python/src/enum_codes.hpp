// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The library's enums in Python: real enum.IntEnum classes (comparing equal to their codes, as
// NumPy arrays of codes need), built by clearjoint/_enums.py from the (name, code, label) rows
// this module exports, which are the library's enum tables. A type caster turns each C++ value
// into its class's member and takes integer codes back.

#include <pybind11/pybind11.h>

#include <type_traits>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

namespace clearjoint::python {

/// Every enum with a table in the library (clearjoint/geometry/model/enum_table.hpp) is an IntEnum
/// class of the table's type name, with the table's names as members and its codes as values.
template <typename E>
struct PythonEnum : std::false_type {};
template <geometry::TabledEnum E>
struct PythonEnum<E> : std::true_type {
  static constexpr const char* name = geometry::EnumTable<E>::type_name.data();
  static constexpr int count = geometry::enum_count<E>();
};

/// clearjoint.<name>, the enum.IntEnum class clearjoint/_enums.py built.
pybind11::object python_enum_class(const char* name);

/// `value` as a code of E: any integer (an IntEnum member, int, numpy.int8, ...) in range.
/// TypeError (not an integer, or a bool) or ValueError (out of range) naming `argument`.
template <typename E>
E enum_argument(const pybind11::handle& value, const char* argument);

/// The shared part of enum_argument: the code, checked against [0, count).
int enum_code(const pybind11::handle& value, const char* argument, const char* enum_name, int count);

template <typename E>
E enum_argument(const pybind11::handle& value, const char* argument) {
  return static_cast<E>(enum_code(value, argument, PythonEnum<E>::name, PythonEnum<E>::count));
}

}  // namespace clearjoint::python

namespace pybind11::detail {

template <typename E>
struct type_caster<E, enable_if_t<clearjoint::python::PythonEnum<E>::value>> {
  PYBIND11_TYPE_CASTER(E, const_name("int"));

  bool load(handle source, bool) {
    if (!PyLong_Check(source.ptr()) || PyBool_Check(source.ptr())) return false;
    const long code = PyLong_AsLong(source.ptr());
    if (code == -1 && PyErr_Occurred()) {
      PyErr_Clear();
      return false;
    }
    if (code < 0 || code >= clearjoint::python::PythonEnum<E>::count) return false;
    value = static_cast<E>(code);
    return true;
  }

  static handle cast(E source, return_value_policy, handle) {
    return clearjoint::python::python_enum_class(clearjoint::python::PythonEnum<E>::name)(
               static_cast<int>(source))
        .release();
  }
};

}  // namespace pybind11::detail
