// SPDX-License-Identifier: BSD-3-Clause
#include "result_dicts.hpp"

#include <pybind11/stl.h>

#include <array>
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

double number(const py::dict& d, const char* key) { return py::cast<double>(d[key]); }

geo::Vector3 vector(const py::dict& d, const char* key) {
  const auto values = py::cast<std::vector<double>>(d[key]);
  if (values.size() != 3) throw py::value_error(std::string(key) + ": must hold 3 numbers");
  return {values[0], values[1], values[2]};
}

/// d[key] as a list of at most `capacity` dicts.
py::list dict_list(const py::dict& d, const char* key, std::size_t capacity) {
  auto list = py::cast<py::list>(d[key]);
  if (list.size() > capacity) {
    throw py::value_error(std::string(key) + ": at most " + std::to_string(capacity) + " entries");
  }
  return list;
}

geo::Certificate certificate(const py::dict& d, const char* level, const char* reason) {
  return {enum_argument<geo::Certainty>(d[level], level), enum_argument<geo::CertificateReason>(d[reason], reason)};
}

void put_certificate(py::dict& d, const geo::Certificate& c) {
  d["certificate"] = py::cast(c.level);
  d["certificate_reason"] = py::cast(c.reason);
}

template <std::size_t N>
py::list crossing_list(const std::array<geo::RimCrossing, N>& crossings, int count) {
  py::list out;
  for (int k = 0; k < count; ++k) out.append(as_dict(crossings[k]));
  return out;
}

template <std::size_t N>
int read_crossings(const py::dict& d, std::array<geo::RimCrossing, N>& crossings) {
  const py::list list = dict_list(d, "crossings", N);
  for (std::size_t k = 0; k < list.size(); ++k) crossings[k] = from_dict<geo::RimCrossing>(py::cast<py::dict>(list[k]));
  return static_cast<int>(list.size());
}

}  // namespace

py::dict as_dict(const geo::Certificate& c) {
  py::dict d;
  d["level"] = py::cast(c.level);
  d["reason"] = py::cast(c.reason);
  return d;
}

py::dict as_dict(const geo::RimCrossing& c) {
  py::dict d;
  d["angle"] = c.angle;
  d["angle_error"] = c.angle_error;
  d["point"] = vector_list(c.point);
  d["point_error"] = c.point_error;
  d["multiplicity"] = c.multiplicity;
  return d;
}

py::dict as_dict(const geo::RimArc& a) {
  py::dict d;
  d["begin"] = a.begin;
  d["end"] = a.end;
  d["full"] = a.full;
  return d;
}

py::dict as_dict(const geo::Contact& c) {
  py::dict d;
  d["type"] = py::cast(c.type);
  d["base"] = py::cast(c.base);
  d["depth"] = c.depth;
  d["depth_error"] = c.depth_error;
  d["point_journal"] = vector_list(c.p_WCj);
  d["point_journal_error"] = c.p_WCj_error;
  d["point_bearing"] = vector_list(c.p_WCi);
  d["point_bearing_error"] = c.p_WCi_error;
  d["normal"] = vector_list(c.normal_W);
  d["crossings"] = crossing_list(c.crossings, c.crossing_count);
  put_certificate(d, c.certificate);
  return d;
}

py::dict as_dict(const geo::JointContacts& r) {
  py::dict d;
  d["scenario"] = py::cast(r.scenario);
  d["aligned"] = r.aligned;
  put_certificate(d, r.certificate);
  d["contact_count"] = r.contact_count;
  py::list contacts;
  for (int k = 0; k < r.contact_count; ++k) contacts.append(as_dict(r.contacts[k]));
  d["contacts"] = contacts;
  return d;
}

py::dict as_dict(const geo::CirclePlaneIntersection& r) {
  py::dict d;
  d["topology"] = py::cast(r.topology);
  d["side"] = static_cast<int>(r.side);
  d["crossings"] = crossing_list(r.crossings, r.crossing_count);
  d["penetration"] = r.has_penetration ? py::object(as_dict(r.penetration)) : py::none();
  d["max_signed_distance"] = r.max_signed_distance;
  d["max_signed_distance_error"] = r.max_signed_distance_error;
  put_certificate(d, r.certificate);
  return d;
}

py::dict as_dict(const geo::CircleCylinderIntersection& r) {
  py::dict d;
  d["topology"] = py::cast(r.topology);
  d["crossings"] = crossing_list(r.crossings, r.crossing_count);
  py::list arcs;
  for (int k = 0; k < r.arc_count; ++k) arcs.append(as_dict(r.penetration_arcs[k]));
  d["penetration_arcs"] = arcs;
  put_certificate(d, r.certificate);
  return d;
}

template <>
geo::Certificate from_dict(const py::dict& d) {
  return certificate(d, "level", "reason");
}

template <>
geo::RimCrossing from_dict(const py::dict& d) {
  geo::RimCrossing c;
  c.angle = number(d, "angle");
  c.angle_error = number(d, "angle_error");
  c.point = vector(d, "point");
  c.point_error = number(d, "point_error");
  c.multiplicity = py::cast<int>(d["multiplicity"]);
  return c;
}

template <>
geo::RimArc from_dict(const py::dict& d) {
  return {number(d, "begin"), number(d, "end"), py::cast<bool>(d["full"])};
}

template <>
geo::Contact from_dict(const py::dict& d) {
  geo::Contact c;
  c.type = enum_argument<geo::ContactType>(d["type"], "type");
  c.base = enum_argument<geo::ContactBase>(d["base"], "base");
  c.depth = number(d, "depth");
  c.depth_error = number(d, "depth_error");
  c.p_WCj = vector(d, "point_journal");
  c.p_WCj_error = number(d, "point_journal_error");
  c.p_WCi = vector(d, "point_bearing");
  c.p_WCi_error = number(d, "point_bearing_error");
  c.normal_W = vector(d, "normal");
  c.crossing_count = read_crossings(d, c.crossings);
  c.certificate = certificate(d, "certificate", "certificate_reason");
  return c;
}

template <>
geo::JointContacts from_dict(const py::dict& d) {
  geo::JointContacts r;
  r.scenario = enum_argument<geo::ContactScenario>(d["scenario"], "scenario");
  r.aligned = py::cast<bool>(d["aligned"]);
  r.certificate = certificate(d, "certificate", "certificate_reason");
  const py::list contacts = dict_list(d, "contacts", geo::kMaxContacts);
  for (std::size_t k = 0; k < contacts.size(); ++k) r.contacts[k] = from_dict<geo::Contact>(py::cast<py::dict>(contacts[k]));
  r.contact_count = static_cast<int>(contacts.size());
  if (py::cast<int>(d["contact_count"]) != r.contact_count) {
    throw py::value_error("contact_count: must be the number of contacts");
  }
  return r;
}

template <>
geo::CirclePlaneIntersection from_dict(const py::dict& d) {
  geo::CirclePlaneIntersection r;
  r.topology = enum_argument<geo::CirclePlaneTopology>(d["topology"], "topology");
  const int side = py::cast<int>(d["side"]);
  if (side < -1 || side > 1) throw py::value_error("side: must be -1, 0 or 1");
  r.side = static_cast<geo::PlaneSide>(side);
  r.crossing_count = read_crossings(d, r.crossings);
  const py::object penetration = d["penetration"];
  r.has_penetration = !penetration.is_none();
  if (r.has_penetration) r.penetration = from_dict<geo::RimArc>(py::cast<py::dict>(penetration));
  r.max_signed_distance = number(d, "max_signed_distance");
  r.max_signed_distance_error = number(d, "max_signed_distance_error");
  r.certificate = certificate(d, "certificate", "certificate_reason");
  return r;
}

template <>
geo::CircleCylinderIntersection from_dict(const py::dict& d) {
  geo::CircleCylinderIntersection r;
  r.topology = enum_argument<geo::CircleCylinderTopology>(d["topology"], "topology");
  r.crossing_count = read_crossings(d, r.crossings);
  const py::list arcs = dict_list(d, "penetration_arcs", r.penetration_arcs.size());
  for (std::size_t k = 0; k < arcs.size(); ++k) r.penetration_arcs[k] = from_dict<geo::RimArc>(py::cast<py::dict>(arcs[k]));
  r.arc_count = static_cast<int>(arcs.size());
  r.certificate = certificate(d, "certificate", "certificate_reason");
  return r;
}

}  // namespace clearjoint::python
