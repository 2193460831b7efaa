// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A result class's attributes, one read-only property per field of the result's field list
// (clearjoint/geometry/joint/result_fields.hpp), named by its key, with its doc: a field added to
// a result is an attribute of its Python class without a line here (as Drake binds a struct's
// attributes from its Serialize()). Values as Python has them: numbers, bools, vectors as NumPy
// arrays of shape (3,), enums as their IntEnum members, error bounds as floats, lists of entries in
// use as lists, optional values as the value or None.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstddef>
#include <tuple>
#include <vector>

#include "clearjoint/geometry/joint/result_fields.hpp"
#include "clearjoint/geometry/model/circle_plane_topology.hpp"
#include "enum_codes.hpp"  // the enums' type caster

namespace clearjoint::python {

namespace field_values {

template <class T>
T python_value(const T& value) {
  return value;
}
/// PlaneSide's codes are -1, 0, 1: an int, not an IntEnum.
inline int python_value(const geometry::PlaneSide& side) { return static_cast<int>(side); }
inline double python_value(geometry::ErrorBound<const double> bound) { return bound.value; }
template <class Item, std::size_t N>
std::vector<Item> python_value(geometry::FieldList<const std::array<Item, N>, const int> list) {
  return {list.items.begin(), list.items.begin() + list.count};
}
template <class Value>
pybind11::object python_value(geometry::OptionalField<const Value, const bool> optional) {
  return optional.present ? pybind11::cast(optional.value) : pybind11::none();
}

}  // namespace field_values

/// One property per field of Result's field list, in the list's order.
template <geometry::DescribedResult Result>
pybind11::class_<Result>& def_field_attributes(pybind11::class_<Result>& cls) {
  std::apply(
      [&](const auto&... field) {
        // Keys and docs are string literals: null-terminated, static.
        (cls.def_property_readonly(
             field.key.data(), [field](const Result& r) { return field_values::python_value(field.view(r)); },
             field.doc.empty() ? nullptr : field.doc.data()),
         ...);
      },
      geometry::ResultFields<Result>::fields);
  return cls;
}

}  // namespace clearjoint::python
