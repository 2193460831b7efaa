// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Results as plain Python dicts and back: `as_dict()`, the pickled state of every result class,
// and the JointContacts (PinInHoleContacts) a DetectionBatch (PinInHoleBatch) row gives. Vectors are lists of three floats, enums
// their IntEnum members (ints to json), bounds and coordinates the very doubles of the result.

#include <pybind11/pybind11.h>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "enum_codes.hpp"

namespace clearjoint::python {

// {"level": Certainty, "reason": CertificateReason}
pybind11::dict as_dict(const geometry::Certificate& c);
// {"angle", "angle_error", "point", "point_error", "multiplicity"}
pybind11::dict as_dict(const geometry::RimCrossing& c);
// {"begin", "end", "full"}
pybind11::dict as_dict(const geometry::RimArc& a);
// {"type", "base", "depth", "depth_error", "point_journal", "point_journal_error",
//  "point_bearing", "point_bearing_error", "normal", "crossings": [...], "certificate",
//  "certificate_reason"}: the names of DetectionBatch's contact columns, less their prefix
pybind11::dict as_dict(const geometry::Contact& c);
// {"scenario", "aligned", "certificate", "certificate_reason", "contact_count", "contacts": [...]}
pybind11::dict as_dict(const geometry::JointContacts& r);
// {"topology", "side", "crossings", "penetration" (a dict or None), "max_signed_distance",
//  "max_signed_distance_error", "certificate", "certificate_reason"}
pybind11::dict as_dict(const geometry::CirclePlaneIntersection& r);
// {"topology", "crossings", "penetration_arcs", "certificate", "certificate_reason"}
pybind11::dict as_dict(const geometry::CircleCylinderIntersection& r);
// {"sommerfeld_number", "attitude_angle", "side_flow_variable", "max_pressure_ratio",
//  "iterations", "converged"}
pybind11::dict as_dict(const lubrication::BearingCharacteristics& r);

/// The inverses: a result from its as_dict() (TypeError, KeyError or ValueError for another dict).
template <typename Result>
Result from_dict(const pybind11::dict& d);
template <> geometry::Certificate from_dict(const pybind11::dict& d);
template <> geometry::RimCrossing from_dict(const pybind11::dict& d);
template <> geometry::RimArc from_dict(const pybind11::dict& d);
template <> geometry::Contact from_dict(const pybind11::dict& d);
template <> geometry::JointContacts from_dict(const pybind11::dict& d);
template <> geometry::PinInHoleContacts from_dict(const pybind11::dict& d);
template <> geometry::CirclePlaneIntersection from_dict(const pybind11::dict& d);
template <> geometry::CircleCylinderIntersection from_dict(const pybind11::dict& d);

/// Give a bound result class `as_dict()` and pickling through it.
template <typename Result>
void add_as_dict_and_pickle(pybind11::class_<Result> cls, const char* as_dict_doc) {
  cls.def("as_dict", [](const Result& r) { return as_dict(r); }, as_dict_doc)
      .def(pybind11::pickle([](const Result& r) { return as_dict(r); },
                            [](const pybind11::dict& d) { return from_dict<Result>(d); }));
}

}  // namespace clearjoint::python
