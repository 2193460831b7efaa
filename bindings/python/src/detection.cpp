// SPDX-License-Identifier: BSD-3-Clause
// The library's value types as Python classes: enums, JointDimensions, and the single-query
// results (Certificate, RimCrossing, RimArc, Contact, JointContacts), read-only with readable
// reprs. Array results of batches are in detection_batch.cpp and kernel.cpp.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <charconv>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/contact_scenario.hpp"
#include "clearjoint/geometry/detect_contacts.hpp"
#include "clearjoint/geometry/joint_geometry.hpp"
#include "clearjoint/geometry/rim_arc.hpp"
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

std::vector<geo::RimCrossing> first_crossings(const geo::RimCrossing* crossings, int count) {
  return {crossings, crossings + count};
}

namespace {

const char* type_name(geo::ContactType t) { return t == geo::ContactType::radial ? "radial" : "axial"; }
const char* base_name(geo::ContactBase b) {
  return b == geo::ContactBase::a ? "a" : b == geo::ContactBase::b ? "b" : "mid";
}

void bind_enums(py::module_& m) {
  py::enum_<geo::Certainty>(m, "Certainty",
                            "Trust in an answer, strongest first. Array results hold these codes "
                            "as int8: exact 0, certified 1, uncertain 2.")
      .value("exact", geo::Certainty::exact, "decided with exact rational arithmetic")
      .value("certified", geo::Certainty::certified,
             "proved in floating point with rigorous error bounds")
      .value("uncertain", geo::Certainty::uncertain, "not proved; the certificate's reason says why");

  // Every CertificateReason, in declaration order (array results hold the codes as int8).
  py::enum_<geo::CertificateReason> reason(
      m, "CertificateReason",
      "Why an answer is uncertain, or, for an exact one, why the floating-point tiers did not "
      "decide it; none for certified answers. Array results hold these codes as int8 (none 0). "
      "certificate_reason_text(code) gives the sentence.");
  reason.value("none", geo::CertificateReason::none)
      .value("not_decided", geo::CertificateReason::not_decided)
      .value("certificate_switched_off", geo::CertificateReason::certificate_switched_off)
      .value("plane_filter_undecided", geo::CertificateReason::plane_filter_undecided)
      .value("plane_filter_undecided_exact_fallback_off",
             geo::CertificateReason::plane_filter_undecided_exact_fallback_off)
      .value("plane_results_not_representable", geo::CertificateReason::plane_results_not_representable)
      .value("subdivision_budget_exhausted", geo::CertificateReason::subdivision_budget_exhausted)
      .value("more_than_four_roots", geo::CertificateReason::more_than_four_roots)
      .value("interval_proof_failed_near_multiple_root",
             geo::CertificateReason::interval_proof_failed_near_multiple_root)
      .value("coefficient_overflow", geo::CertificateReason::coefficient_overflow)
      .value("cylinder_points_not_representable", geo::CertificateReason::cylinder_points_not_representable)
      .value("exact_root_isolation_budget_exhausted",
             geo::CertificateReason::exact_root_isolation_budget_exhausted)
      .value("exact_coefficients_too_large", geo::CertificateReason::exact_coefficients_too_large)
      .value("exact_intermediate_beyond_double_range",
             geo::CertificateReason::exact_intermediate_beyond_double_range)
      .value("contact_not_representable_in_world", geo::CertificateReason::contact_not_representable_in_world)
      .value("axes_parallel_within_tolerance", geo::CertificateReason::axes_parallel_within_tolerance)
      .value("beyond_model_undecided", geo::CertificateReason::beyond_model_undecided);
  m.def("certificate_reason_text", [](geo::CertificateReason r) { return std::string(geo::to_string(r)); },
        py::arg("reason"), "The reason as a sentence (\"certificate switched off\", ...); empty for none.");

  py::enum_<geo::ContactScenario>(
      m, "ContactScenario",
      "The contact scenarios of the paper's Fig. 2: (a)-(i) misaligned axes, (j)-(l) parallel "
      "axes, plus none (free flight) and beyond_model. Array results hold the codes as int8, in "
      "this order: none 0, single_radial 1 (a), ..., all_four 9 (i), line 10 (j), face 11 (k), "
      "line_and_face 12 (l), beyond_model 13.")
      .value("none", geo::ContactScenario::none, "free flight: no contact")
      .value("single_radial", geo::ContactScenario::single_radial, "(a) one rim against the wall")
      .value("single_axial", geo::ContactScenario::single_axial, "(b) one rim against a base")
      .value("radial_at_both_bases", geo::ContactScenario::radial_at_both_bases,
             "(c) both rims against the wall")
      .value("axial_at_both_bases", geo::ContactScenario::axial_at_both_bases,
             "(d) each rim against its base")
      .value("radial_and_axial_same_base", geo::ContactScenario::radial_and_axial_same_base,
             "(e) one rim against the wall and the base on its side")
      .value("radial_and_axial_opposite_bases", geo::ContactScenario::radial_and_axial_opposite_bases,
             "(f) one rim against the wall, the other against its base")
      .value("two_radial_one_axial", geo::ContactScenario::two_radial_one_axial,
             "(g) both rims against the wall, one against a base")
      .value("one_radial_two_axial", geo::ContactScenario::one_radial_two_axial,
             "(h) one rim against the wall, both against their bases")
      .value("all_four", geo::ContactScenario::all_four, "(i) both rims against wall and bases")
      .value("line", geo::ContactScenario::line, "(j) parallel axes, journal along the wall")
      .value("face", geo::ContactScenario::face, "(k) parallel axes, journal base on a bearing base")
      .value("line_and_face", geo::ContactScenario::line_and_face, "(l) (j) and (k) together")
      .value("beyond_model", geo::ContactScenario::beyond_model,
             "a configuration the paper's model does not cover (four wall crossings on a rim, a "
             "rim wholly beyond a surface, a penetration deeper than the clearance)");
  m.def("scenario_label", [](geo::ContactScenario s) { return std::string(geo::label(s)); },
        py::arg("scenario"),
        "The scenario's label for people: \"(a) single radial\", \"none\", ...; clearjoint detect "
        "writes its key (\"a\").");

  py::enum_<geo::ContactType>(m, "ContactType", "radial 0: against the lateral wall; axial 1: against a base.")
      .value("radial", geo::ContactType::radial, "against the lateral wall (eqs. 16-21; line: eqs. 6-8)")
      .value("axial", geo::ContactType::axial, "against a base (eqs. 11-15; face: eqs. 9-10)");
  py::enum_<geo::ContactBase>(m, "ContactBase",
                              "a 0, b 1: at bearing base A (eq. 3) or B (eq. 4) and the journal "
                              "rim facing it; mid 2: the journal's mid-length (line contact).")
      .value("a", geo::ContactBase::a)
      .value("b", geo::ContactBase::b)
      .value("mid", geo::ContactBase::mid);
}

void bind_dimensions(py::module_& m) {
  py::class_<geo::JointDimensions>(
      m, "JointDimensions",
      "Bearing radius Ri and length Li, journal radius Rj and length Lj, in any one length unit "
      "(metres in the shipped models). Keyword arguments only. Raises ValueError naming the field "
      "unless all are finite, Ri > Rj > 0 and Li > Lj > 0.")
      .def(py::init([](double bearing_radius, double bearing_length, double journal_radius,
                       double journal_length) {
             const geo::JointDimensions d{bearing_radius, bearing_length, journal_radius, journal_length};
             geo::validate(d, "JointDimensions");
             return d;
           }),
           py::kw_only(), py::arg("bearing_radius"), py::arg("bearing_length"),
           py::arg("journal_radius"), py::arg("journal_length"))
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
            const geo::JointDimensions d{t[0].cast<double>(), t[1].cast<double>(),
                                         t[2].cast<double>(), t[3].cast<double>()};
            geo::validate(d, "JointDimensions");
            return d;
          }));
}

void bind_results(py::module_& m) {
  py::class_<geo::Certificate>(m, "Certificate", "A trust level and, unless certified, why.")
      .def_property_readonly("level", [](const geo::Certificate& c) { return c.level; })
      .def_property_readonly("reason", [](const geo::Certificate& c) { return c.reason; },
                             "A CertificateReason to branch on; none for certified answers.")
      .def_property_readonly("reason_text", [](const geo::Certificate& c) { return std::string(c.reason_text()); },
                             "The reason as a sentence for humans; empty for certified answers.")
      .def("__repr__", [](const geo::Certificate& c) { return "Certificate(" + repr_certificate(c) + ")"; });

  py::class_<geo::RimCrossing>(
      m, "RimCrossing",
      "A point where a rim meets a surface. When certified or exact, the true angle lies within "
      "angle_error of angle (radians) and the true point within point_error (length unit, "
      "Euclidean) of point; uncertain answers carry inf.")
      .def_readonly("angle", &geo::RimCrossing::angle, "rim angle in [0, 2 pi), radians")
      .def_readonly("angle_error", &geo::RimCrossing::angle_error)
      .def_readonly("point", &geo::RimCrossing::point, "world frame, shape (3,)")
      .def_readonly("point_error", &geo::RimCrossing::point_error)
      .def_readonly("multiplicity", &geo::RimCrossing::multiplicity,
                    "1 crossing, 2 tangency, 3-4 higher-order contact")
      .def("__repr__", [](const geo::RimCrossing& c) {
        return "RimCrossing(angle=" + repr_number(c.angle) + " +- " + repr_number(c.angle_error) +
               ", point=" + repr_vector(c.point) + " +- " + repr_number(c.point_error) +
               ", multiplicity=" + std::to_string(c.multiplicity) + ")";
      });

  py::class_<geo::RimArc>(m, "RimArc",
                          "Rim angles swept counter-clockwise from begin to end (radians in "
                          "[0, 2 pi); end < begin when the arc passes angle 0); full: the whole rim.")
      .def_readonly("begin", &geo::RimArc::begin)
      .def_readonly("end", &geo::RimArc::end)
      .def_readonly("full", &geo::RimArc::full)
      .def_property_readonly("middle", &geo::RimArc::middle, "the arc's middle angle (eqs. 13, 18)")
      .def_property_readonly("sweep", &geo::RimArc::sweep, "angular length in [0, 2 pi]")
      .def("__repr__", [](const geo::RimArc& a) {
        return "RimArc(begin=" + repr_number(a.begin) + ", end=" + repr_number(a.end) +
               (a.full ? ", full=True)" : ")");
      });

  py::class_<geo::Contact>(
      m, "Contact",
      "One contact (eqs. 22-23): normal points out of the bearing, in the direction the journal "
      "penetrates; point_journal - point_bearing = depth * normal (up to rounding); the force on "
      "the journal acts along -normal. World frame, the input's length unit.")
      .def_property_readonly("type", [](const geo::Contact& c) { return c.type; })
      .def_property_readonly("base", [](const geo::Contact& c) { return c.base; })
      .def_readonly("depth", &geo::Contact::depth, "penetration depth >= 0")
      .def_readonly("point_journal", &geo::Contact::p_WCj, "C_j on the journal (eqs. 8, 10, 14, 19)")
      .def_readonly("point_bearing", &geo::Contact::p_WCi, "C_i on the bearing (eqs. 7, 9, 15, 21)")
      .def_readonly("normal", &geo::Contact::normal_W, "unit normal, out of the bearing")
      .def_readonly("depth_error", &geo::Contact::depth_error,
                    "bound on the depth's error; certified unless uncertain (then inf)")
      .def_readonly("point_journal_error", &geo::Contact::p_WCj_error, "bound on point_journal's error (Euclidean)")
      .def_readonly("point_bearing_error", &geo::Contact::p_WCi_error, "bound on point_bearing's error (Euclidean)")
      .def_property_readonly(
          "crossings", [](const geo::Contact& c) { return first_crossings(c.crossings.data(), c.crossing_count); },
          "the rim crossings bounding the penetration arc (none for line and face contacts)")
      .def_readonly("certificate", &geo::Contact::certificate)
      .def("__repr__", [](const geo::Contact& c) {
        return std::string("Contact(") + type_name(c.type) + " at " + base_name(c.base) +
               ", depth=" + repr_number(c.depth) + ", point_journal=" + repr_vector(c.p_WCj) +
               ", normal=" + repr_vector(c.normal_W) + ", " + repr_certificate(c.certificate) + ")";
      });

  py::class_<geo::JointContacts>(m, "JointContacts",
                                 "Every contact between a journal and its bearing in one pose.")
      .def_readonly("scenario", &geo::JointContacts::scenario)
      .def_readonly("aligned", &geo::JointContacts::aligned,
                    "axes parallel (exactly, eq. 5, or within parallel_angle_tolerance)")
      .def_property_readonly(
          "contacts",
          [](const geo::JointContacts& r) {
            return std::vector<geo::Contact>(r.contacts.begin(), r.contacts.begin() + r.contact_count);
          },
          "radial before axial, base A before B")
      .def_readonly("contact_count", &geo::JointContacts::contact_count)
      .def_readonly("certificate", &geo::JointContacts::certificate,
                    "the weakest over every decision taken, including 'no contact'")
      .def("__repr__", [](const geo::JointContacts& r) {
        std::string text = "JointContacts(" + std::string(geo::label(r.scenario)) +
                           (r.aligned ? ", aligned" : "") + ", " + repr_certificate(r.certificate);
        for (int k = 0; k < r.contact_count; ++k) {
          const geo::Contact& c = r.contacts[k];
          text += std::string(k == 0 ? ";" : ",") + " " + type_name(c.type) + " at " +
                  base_name(c.base) + " depth " + repr_number(c.depth);
        }
        return text + ")";
      });
}

}  // namespace

void bind_types(py::module_& module) {
  bind_enums(module);
  bind_dimensions(module);
  bind_results(module);
}

}  // namespace clearjoint::python
