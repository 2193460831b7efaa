// SPDX-License-Identifier: BSD-3-Clause
#include "result_dicts.hpp"

#include "clearjoint/geometry/joint/result_fields.hpp"
#include "clearjoint/lubrication/result_fields.hpp"

#include <pybind11/stl.h>

#include <string_view>
#include <cstddef>
#include <string>
#include <vector>

namespace py = pybind11;

namespace clearjoint::python {

namespace geo = clearjoint::geometry;

namespace {

py::list vector_list(const geo::Vector3& v) {
  py::list out;
  for (int i = 0; i < 3; ++i) out.append(v[i]);
  return out;
}

/// Writes the fields it visits into a dict: vectors as lists, enums as their IntEnum members, a
/// certificate inside a result as two keys ("certificate": level, "certificate_reason"), lists
/// and optional values as (lists of) dicts.
class DictWriter {
 public:
  explicit DictWriter(py::dict& out) : out_(out) {}

  void operator()(std::string_view key, const double& x) { out_[name(key)] = x; }
  void operator()(std::string_view key, const int& n) { out_[name(key)] = n; }
  void operator()(std::string_view key, const bool& b) { out_[name(key)] = b; }
  void operator()(std::string_view key, const geo::Vector3& v) { out_[name(key)] = vector_list(v); }
  void operator()(std::string_view key, const geo::PlaneSide& side) { out_[name(key)] = static_cast<int>(side); }
  template <geo::TabledEnum E>
  void operator()(std::string_view key, const E& value) {
    out_[name(key)] = py::cast(value);
  }
  void operator()(std::string_view key, geo::ErrorBound<const double> bound) { out_[name(key)] = bound.value; }
  void operator()(std::string_view key, const geo::Certificate& c) {
    out_[name(key)] = py::cast(c.level);
    out_[py::str(std::string(key) + "_reason")] = py::cast(c.reason);
  }
  template <class Array>
  void operator()(std::string_view key, geo::FieldList<const Array, const int> list) {
    py::list items;
    for (int k = 0; k < list.count; ++k) items.append(as_dict(list.items[static_cast<std::size_t>(k)]));
    out_[name(key)] = items;
  }
  template <class Value>
  void operator()(std::string_view key, geo::OptionalField<const Value, const bool> optional) {
    out_[name(key)] = optional.present ? py::object(as_dict(optional.value)) : py::none();
  }

 private:
  static py::str name(std::string_view key) { return py::str(key.data(), key.size()); }
  py::dict& out_;
};

/// The inverse of DictWriter: sets the fields it visits from a dict (TypeError, KeyError or
/// ValueError naming the key for another dict).
class DictReader {
 public:
  explicit DictReader(const py::dict& in) : in_(in) {}

  void operator()(std::string_view key, double& x) { x = py::cast<double>(item(key)); }
  void operator()(std::string_view key, int& n) { n = py::cast<int>(item(key)); }
  void operator()(std::string_view key, bool& b) { b = py::cast<bool>(item(key)); }
  void operator()(std::string_view key, geo::Vector3& v) {
    const auto values = py::cast<std::vector<double>>(item(key));
    if (values.size() != 3) throw py::value_error(std::string(key) + ": must hold 3 numbers");
    v = {values[0], values[1], values[2]};
  }
  void operator()(std::string_view key, geo::PlaneSide& side) {
    const int code = py::cast<int>(item(key));
    if (code < -1 || code > 1) throw py::value_error(std::string(key) + ": must be -1, 0 or 1");
    side = static_cast<geo::PlaneSide>(code);
  }
  template <geo::TabledEnum E>
  void operator()(std::string_view key, E& value) {
    value = enum_argument<E>(item(key), std::string(key).c_str());
  }
  void operator()(std::string_view key, geo::ErrorBound<double> bound) { (*this)(key, bound.value); }
  void operator()(std::string_view key, geo::Certificate& c) {
    (*this)(key, c.level);
    (*this)(std::string(key) + "_reason", c.reason);
  }
  template <class Array>
  void operator()(std::string_view key, geo::FieldList<Array, int> list) {
    const auto items = py::cast<py::list>(item(key));
    if (items.size() > list.items.size()) {
      throw py::value_error(std::string(key) + ": at most " + std::to_string(list.items.size()) + " entries");
    }
    for (std::size_t k = 0; k < items.size(); ++k) {
      list.items[k] = from_dict<typename Array::value_type>(py::cast<py::dict>(items[k]));
    }
    list.count = static_cast<int>(items.size());
  }
  template <class Value>
  void operator()(std::string_view key, geo::OptionalField<Value, bool> optional) {
    const py::object value = item(key);
    optional.present = !value.is_none();
    if (optional.present) optional.value = from_dict<Value>(py::cast<py::dict>(value));
  }

 private:
  py::object item(std::string_view key) const { return in_[py::str(key.data(), key.size())]; }
  const py::dict& in_;
};

template <class Result>
py::dict dict_of(const Result& r) {
  py::dict d;
  geo::visit_fields(r, DictWriter(d));
  return d;
}

template <class Result>
Result result_of(const py::dict& d) {
  Result r;
  geo::visit_fields(r, DictReader(d));
  return r;
}

}  // namespace

/// A Certificate on its own is {"level", "reason"}, its two fields.
py::dict as_dict(const geo::Certificate& c) {
  py::dict d;
  d["level"] = py::cast(c.level);
  d["reason"] = py::cast(c.reason);
  return d;
}

py::dict as_dict(const geo::RimCrossing& c) { return dict_of(c); }
py::dict as_dict(const geo::RimArc& a) { return dict_of(a); }
py::dict as_dict(const lubrication::BearingCharacteristics& r) { return dict_of(r); }
py::dict as_dict(const geo::Contact& c) { return dict_of(c); }
py::dict as_dict(const geo::CirclePlaneIntersection& r) { return dict_of(r); }
py::dict as_dict(const geo::CircleCylinderIntersection& r) { return dict_of(r); }

py::dict as_dict(const geo::JointContacts& r) {
  py::dict d = dict_of(r);
  d["contact_count"] = r.contact_count;
  return d;
}

template <>
geo::Certificate from_dict(const py::dict& d) {
  return {enum_argument<geo::Certainty>(d["level"], "level"),
          enum_argument<geo::CertificateReason>(d["reason"], "reason")};
}

template <>
geo::RimCrossing from_dict(const py::dict& d) { return result_of<geo::RimCrossing>(d); }
template <>
geo::RimArc from_dict(const py::dict& d) { return result_of<geo::RimArc>(d); }
template <>
geo::Contact from_dict(const py::dict& d) { return result_of<geo::Contact>(d); }
template <>
geo::CirclePlaneIntersection from_dict(const py::dict& d) { return result_of<geo::CirclePlaneIntersection>(d); }
template <>
geo::CircleCylinderIntersection from_dict(const py::dict& d) {
  return result_of<geo::CircleCylinderIntersection>(d);
}

template <>
geo::JointContacts from_dict(const py::dict& d) {
  geo::JointContacts r = result_of<geo::JointContacts>(d);
  if (py::cast<int>(d["contact_count"]) != r.contact_count) {
    throw py::value_error("contact_count: must be the number of contacts");
  }
  return r;
}

template <>
geo::PinInHoleContacts from_dict(const py::dict& d) {
  geo::PinInHoleContacts r = result_of<geo::PinInHoleContacts>(d);
  if (py::cast<int>(d["contact_count"]) != r.contact_count) {
    throw py::value_error("contact_count: must be the number of contacts");
  }
  return r;
}

}  // namespace clearjoint::python
