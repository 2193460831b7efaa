// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The library's enums in Python: real enum.IntEnum classes (comparing equal to their codes, as
// NumPy arrays of codes need), built by clearjoint/_enums.py from the (name, code) table this
// module exports, so that the member names are written down once. A type caster turns each C++
// value into its class's member and takes integer codes back.

#include <pybind11/pybind11.h>

#include <type_traits>

#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/contact_scenario.hpp"
#include "clearjoint/geometry/detect_contacts.hpp"
#include "clearjoint/geometry/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/intersect_circle_plane.hpp"

namespace clearjoint::python {

/// The Python class name and member count of each enum with a table in enum_codes.cpp.
template <typename E>
struct PythonEnum : std::false_type {};
#define CLEARJOINT_PYTHON_ENUM(Type, count_)                \
  template <>                                               \
  struct PythonEnum<geometry::Type> : std::true_type {      \
    static constexpr const char* name = #Type;              \
    static constexpr int count = count_;                    \
  };
CLEARJOINT_PYTHON_ENUM(Certainty, 3)
CLEARJOINT_PYTHON_ENUM(CertificateReason, 17)
CLEARJOINT_PYTHON_ENUM(ContactScenario, 14)
CLEARJOINT_PYTHON_ENUM(ContactType, 2)
CLEARJOINT_PYTHON_ENUM(ContactBase, 3)
CLEARJOINT_PYTHON_ENUM(CirclePlaneTopology, 4)
CLEARJOINT_PYTHON_ENUM(CircleCylinderTopology, 4)
#undef CLEARJOINT_PYTHON_ENUM

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
