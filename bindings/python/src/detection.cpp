// SPDX-License-Identifier: BSD-3-Clause
// The library's value types as Python classes: enums, JointDimensions, and the single-query
// results (Certificate, RimCrossing, RimArc, Contact, JointContacts), read-only with readable
// reprs, their attributes bound from the results' field lists. Array results of batches are in
// detection_batch.cpp and kernel.cpp.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <charconv>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "numpy_views.hpp"
#include "result_attributes.hpp"
#include "result_dicts.hpp"
#include "result_types.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace geo = clearjoint::geometry;

std::string repr_number(double x) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);  // shortest round trip
  std::string text(buffer, end);
  // As Python writes floats: 10.0, not 10.
  if (text.find_first_of(".eni") == std::string::npos) text += ".0";
  return text;
}

std::string repr_vector(const geo::Vector3& v) {
  return "[" + repr_number(v.x()) + ", " + repr_number(v.y()) + ", " + repr_number(v.z()) + "]";
}

std::string repr_certificate(const geo::Certificate& c) {
  std::string text = std::string(geo::to_string(c.level));
  if (c.reason != geo::CertificateReason::none) text += " (" + std::string(c.reason_text()) + ")";
  return text;
}

namespace {

/// The functions that give an enum's text; the enum classes themselves are clearjoint/_enums.py's.
void bind_enum_texts(py::module_& m) {
  m.def("certificate_reason_text",
        [](const py::handle& reason) {
          return std::string(geo::to_string(enum_argument<geo::CertificateReason>(reason, "reason")));
        },
        py::arg("reason"),
        "The reason (a CertificateReason or its code) as a sentence (\"certificate switched off\", "
        "...); empty for none.");
  m.def("scenario_label",
        [](const py::handle& scenario) {
          return std::string(geo::label(enum_argument<geo::ContactScenario>(scenario, "scenario")));
        },
        py::arg("scenario"),
        "The scenario's (a ContactScenario or its code) label for people: \"(a) single radial\", "
        "\"none\", ...; clearjoint detect writes its key (\"a\").");
}

std::string dimensions_call_error(const py::args& args, const py::kwargs& kwargs) {
  const char* usage =
      "JointDimensions(bearing_radius=Ri, bearing_length=Li, journal_radius=Rj, journal_length=Lj)";
  if (args.size() == 1 && py::isinstance<py::dict>(args[0])) {
    return std::string("JointDimensions takes keyword arguments, not a dict: write JointDimensions(**d) "
                       "for a dict d with the keys of ") + usage;
  }
  if (!args.empty()) {
    return std::string("JointDimensions takes keyword arguments only, to keep radii and lengths apart: ") + usage;
  }
  std::string message = "JointDimensions:";
  for (const char* field : {"bearing_radius", "bearing_length", "journal_radius", "journal_length"}) {
    if (!kwargs.contains(field)) message += std::string(" missing ") + field + ";";
  }
  for (const auto& item : kwargs) {
    const std::string key = py::str(item.first);
    if (key != "bearing_radius" && key != "bearing_length" && key != "journal_radius" && key != "journal_length") {
      message += " unknown keyword " + key + ";";
    }
  }
  return message + " write " + usage;
}

void bind_dimensions(py::module_& m) {
  py::class_<geo::JointDimensions>(
      m, "JointDimensions",
      "Bearing radius Ri and length Li, journal radius Rj and length Lj, in any one length unit "
      "(metres in the shipped models). Keyword arguments only. Raises ValueError naming the field "
      "unless all are finite, Ri > Rj > 0 and Li > Lj > 0.")
      .def(py::init([](const py::handle& bearing_radius, const py::handle& bearing_length,
                       const py::handle& journal_radius, const py::handle& journal_length) {
             const geo::JointDimensions d{number_argument(bearing_radius, "JointDimensions.bearing_radius"),
                                          number_argument(bearing_length, "JointDimensions.bearing_length"),
                                          number_argument(journal_radius, "JointDimensions.journal_radius"),
                                          number_argument(journal_length, "JointDimensions.journal_length")};
             geo::validate(d, "JointDimensions");
             return d;
           }),
           py::kw_only(), py::arg("bearing_radius"), py::arg("bearing_length"),
           py::arg("journal_radius"), py::arg("journal_length"))
      // Every other call (positional numbers, a dict, a missing or unknown keyword) lands here,
      // for a message that says what to write instead of pybind11's list of signatures.
      .def(py::init([](const py::args& args, const py::kwargs& kwargs) -> geo::JointDimensions {
        throw py::type_error(dimensions_call_error(args, kwargs));
      }))
      .def_readonly("bearing_radius", &geo::JointDimensions::bearing_radius, "Ri")
      .def_readonly("bearing_length", &geo::JointDimensions::bearing_length, "Li")
      .def_readonly("journal_radius", &geo::JointDimensions::journal_radius, "Rj")
      .def_readonly("journal_length", &geo::JointDimensions::journal_length, "Lj")
      .def_property_readonly("radial_clearance", &geo::JointDimensions::radial_clearance,
                             "cr = Ri - Rj, eq. (1)")
      .def_property_readonly("axial_clearance", &geo::JointDimensions::axial_clearance,
                             "ca = (Li - Lj) / 2, eq. (2)")
      .def("__repr__", [](const geo::JointDimensions& d) {
        return "JointDimensions(bearing_radius=" + repr_number(d.bearing_radius) +
               ", bearing_length=" + repr_number(d.bearing_length) +
               ", journal_radius=" + repr_number(d.journal_radius) +
               ", journal_length=" + repr_number(d.journal_length) + ")";
      })
      .def(py::pickle(
          [](const geo::JointDimensions& d) {
            return py::make_tuple(d.bearing_radius, d.bearing_length, d.journal_radius, d.journal_length);
          },
          [](const py::tuple& t) {
            const geo::JointDimensions d{number_argument(t[0], "bearing_radius"), number_argument(t[1], "bearing_length"),
                                         number_argument(t[2], "journal_radius"), number_argument(t[3], "journal_length")};
            geo::validate(d, "JointDimensions");
            return d;
          }));
}

// The attributes of each result are its field list's (result_attributes.hpp); bound here are the
// class docs, the attributes that are not fields, and the reprs.
void bind_results(py::module_& m) {
  py::class_<geo::Certificate> certificate(m, "Certificate", "A trust level and, unless certified, why.");
  add_as_dict_and_pickle(def_field_attributes(certificate)
      .def_property_readonly("reason_text", [](const geo::Certificate& c) { return std::string(c.reason_text()); },
                             "The reason as a sentence for humans; empty for certified answers.")
      .def("__repr__", [](const geo::Certificate& c) { return "Certificate(" + repr_certificate(c) + ")"; }),
      "{'level': Certainty, 'reason': CertificateReason}");

  py::class_<geo::RimCrossing> crossing(
      m, "RimCrossing",
      "A point where a rim meets a surface. When certified or exact, the true angle lies within "
      "angle_error of angle (radians) and the true point within point_error (length unit, "
      "Euclidean) of point; uncertain answers carry inf.");
  add_as_dict_and_pickle(def_field_attributes(crossing)
      .def("__repr__", [](const geo::RimCrossing& c) {
        return "RimCrossing(angle=" + repr_number(c.angle) + " +- " + repr_number(c.angle_error) +
               ", point=" + repr_vector(c.point) + " +- " + repr_number(c.point_error) +
               ", multiplicity=" + std::to_string(c.multiplicity) + ")";
      }),
      "The attributes as a dict, point a list of three floats.");

  py::class_<geo::RimArc> arc(m, "RimArc",
                              "Rim angles swept counter-clockwise from begin to end (radians in "
                              "[0, 2 pi); end < begin when the arc passes angle 0); full: the whole rim.");
  add_as_dict_and_pickle(def_field_attributes(arc)
      .def_property_readonly("middle", &geo::RimArc::middle, "the arc's middle angle (eqs. 13, 18)")
      .def_property_readonly("sweep", &geo::RimArc::sweep, "angular length in [0, 2 pi]")
      .def("__repr__", [](const geo::RimArc& a) {
        return "RimArc(begin=" + repr_number(a.begin) + ", end=" + repr_number(a.end) +
               (a.full ? ", full=True)" : ")");
      }),
      "{'begin', 'end', 'full'}");

  py::class_<geo::Contact> contact(
      m, "Contact",
      "One contact (eqs. 22-23): normal points out of the bearing, in the direction the journal "
      "penetrates; point_journal - point_bearing = depth * normal (up to rounding); the force on "
      "the journal acts along -normal. World frame, the input's length unit.");
  add_as_dict_and_pickle(def_field_attributes(contact)
      .def("__repr__", [](const geo::Contact& c) {
        return "Contact(" + std::string(geo::to_string(c.type)) + " at " + std::string(geo::to_string(c.base)) +
               ", depth=" + repr_number(c.depth) + ", point_journal=" + repr_vector(c.p_WCj) +
               ", normal=" + repr_vector(c.normal_W) + ", " + repr_certificate(c.certificate) + ")";
      }),
      "The attributes as a dict, named as DetectionBatch's contact columns less their prefix "
      "(type, base, depth, ..., certificate, certificate_reason); vectors as lists of three "
      "floats, crossings as a list of RimCrossing.as_dict().");

  py::class_<geo::JointContacts> joint_contacts(m, "JointContacts",
                                                "Every contact between a journal and its bearing in one pose.");
  def_field_attributes(joint_contacts)
      .def_readonly("contact_count", &geo::JointContacts::contact_count)
      .def("__repr__", [](const geo::JointContacts& r) {
        std::string text = "JointContacts(" + std::string(geo::label(r.scenario)) +
                           (r.aligned ? ", aligned" : "") + ", " + repr_certificate(r.certificate);
        for (int k = 0; k < r.contact_count; ++k) {
          const geo::Contact& c = r.contacts[k];
          text += std::string(k == 0 ? ";" : ",") + " " + std::string(geo::to_string(c.type)) + " at " +
                  std::string(geo::to_string(c.base)) + " depth " + repr_number(c.depth);
        }
        return text + ")";
      })
      // DetectionBatch rows are rebuilt through the dict of as_dict().
      .def_static("_from_dict", &from_dict<geo::JointContacts>, py::arg("d"));
  add_as_dict_and_pickle(joint_contacts,
                         "{'scenario', 'aligned', 'certificate', 'certificate_reason', "
                         "'contact_count', 'contacts': [Contact.as_dict(), ...]}: the columns of "
                         "DetectionBatch.poses() and, per contact, of DetectionBatch.contacts(). "
                         "Plain Python values (enums are IntEnums): json.dumps takes it.");
}

}  // namespace

void bind_types(py::module_& module) {
  bind_enum_texts(module);
  bind_dimensions(module);
  bind_results(module);
}

}  // namespace clearjoint::python
