// SPDX-License-Identifier: BSD-3-Clause
// The pin-in-hole joint in Python: PinInHoleDimensions, the PinInHoleContacts result (its
// attributes bound from its field list) and clearjoint._core.detect_pin_in_hole, which calls
// detect_pin_in_hole_contacts on one pose (a PinInHoleContacts), or on a batch of poses given as
// NumPy arrays (a dict of packed arrays, packed_contacts.hpp, which clearjoint/_detect.py wraps),
// without the GIL and spread over threads.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"
#include "numpy_views.hpp"
#include "packed_contacts.hpp"
#include "result_attributes.hpp"
#include "result_dicts.hpp"
#include "result_types.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

/// The stops as Python gives them: a sequence of (position, outer_radius) pairs, at most
/// kMaxAxialStops. The values' ranges are validate()'s to check.
void read_stops(const py::handle& stops, geo::PinInHoleDimensions& d) {
  const std::string name = "PinInHoleDimensions.stops";
  if (!py::isinstance<py::sequence>(stops) || py::isinstance<py::str>(stops)) {
    throw py::type_error(name + " = " + std::string(py::repr(stops)) +
                         ": must be a sequence of (position, outer_radius) pairs");
  }
  const py::sequence list = py::reinterpret_borrow<py::sequence>(stops);
  if (list.size() > static_cast<std::size_t>(geo::kMaxAxialStops)) {
    throw py::value_error(name + " = " + std::string(py::repr(stops)) + ": at most " +
                          std::to_string(geo::kMaxAxialStops) +
                          " stops (one on each side of the hole; () for a free sliding pin)");
  }
  d.stop_count = static_cast<int>(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string entry = name + "[" + std::to_string(k) + "]";
    const py::handle stop = list[k];
    if (!py::isinstance<py::sequence>(stop) || py::isinstance<py::str>(stop) || py::len(stop) != 2) {
      throw py::type_error(entry + " = " + std::string(py::repr(stop)) + ": must be a (position, outer_radius) pair");
    }
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(stop);
    d.stops[k] = {number_argument(pair[0], entry + ".position"), number_argument(pair[1], entry + ".outer_radius")};
  }
}

py::tuple stops_tuple(const geo::PinInHoleDimensions& d) {
  py::tuple stops(d.stop_count);
  for (int k = 0; k < d.stop_count; ++k) stops[k] = py::make_tuple(d.stops[k].position, d.stops[k].outer_radius);
  return stops;
}

geo::PinInHoleDimensions make_dimensions(const py::handle& hole_radius, const py::handle& hole_length,
                                         const py::handle& pin_radius, const py::handle& stops) {
  geo::PinInHoleDimensions d;
  d.hole_radius = number_argument(hole_radius, "PinInHoleDimensions.hole_radius");
  d.hole_length = number_argument(hole_length, "PinInHoleDimensions.hole_length");
  d.pin_radius = number_argument(pin_radius, "PinInHoleDimensions.pin_radius");
  read_stops(stops, d);
  geo::validate(d, "PinInHoleDimensions");
  return d;
}

void bind_dimensions(py::module_& m) {
  py::class_<geo::PinInHoleDimensions>(
      m, "PinInHoleDimensions",
      "A pin through a hole: hole radius Rh and length L between the link's faces, pin radius Rp, "
      "and 0, 1 or 2 axial stops as (position, outer_radius) pairs (position along the pin's axis "
      "from its point P, the stop's head beyond it), any one length unit. Keyword arguments only. "
      "Raises ValueError naming the field unless all are finite, Rh > Rp > 0, L > 0, each stop "
      "outside the hole (|position| > L/2) and larger than it (outer_radius > Rh), two stops on "
      "opposite sides.")
      .def(py::init(&make_dimensions), py::kw_only(), py::arg("hole_radius"), py::arg("hole_length"),
           py::arg("pin_radius"), py::arg("stops") = py::tuple())
      .def_readonly("hole_radius", &geo::PinInHoleDimensions::hole_radius, "Rh")
      .def_readonly("hole_length", &geo::PinInHoleDimensions::hole_length, "L, between the link's faces")
      .def_readonly("pin_radius", &geo::PinInHoleDimensions::pin_radius, "Rp")
      .def_property_readonly("stops", &stops_tuple, "((position, outer_radius), ...): 0 to 2 stops")
      .def_property_readonly("radial_clearance", &geo::PinInHoleDimensions::radial_clearance, "cr = Rh - Rp")
      .def_property_readonly("axial_clearance", &geo::PinInHoleDimensions::axial_clearance,
                             "((s_max - s_min) - L) / 2 with two stops; inf with fewer")
      .def("__repr__", [](const geo::PinInHoleDimensions& d) {
        std::string stops;
        for (int k = 0; k < d.stop_count; ++k) {
          stops += std::string(k == 0 ? "" : ", ") + "(" + repr_number(d.stops[k].position) + ", " +
                   repr_number(d.stops[k].outer_radius) + ")";
        }
        if (d.stop_count == 1) stops += ",";
        return "PinInHoleDimensions(hole_radius=" + repr_number(d.hole_radius) + ", hole_length=" +
               repr_number(d.hole_length) + ", pin_radius=" + repr_number(d.pin_radius) + ", stops=(" + stops + "))";
      })
      .def(py::pickle([](const geo::PinInHoleDimensions& d) {
             return py::make_tuple(d.hole_radius, d.hole_length, d.pin_radius, stops_tuple(d));
           },
           [](const py::tuple& t) {
             if (t.size() != 4) throw py::value_error("PinInHoleDimensions: a pickled state of 4 values expected");
             return make_dimensions(t[0], t[1], t[2], t[3]);
           }));
}

py::dict as_dict(const geo::PinInHoleContacts& r) {
  py::list contacts;
  for (int k = 0; k < r.contact_count; ++k) contacts.append(python::as_dict(r.contacts[static_cast<std::size_t>(k)]));
  py::dict d;
  d["scenario"] = py::cast(r.scenario);
  d["aligned"] = r.aligned;
  d["certificate"] = py::cast(r.certificate.level);
  d["certificate_reason"] = py::cast(r.certificate.reason);
  d["contact_count"] = r.contact_count;
  d["contacts"] = contacts;
  return d;
}

void bind_result(py::module_& m) {
  py::class_<geo::PinInHoleContacts> contacts(
      m, "PinInHoleContacts",
      "Every contact between a pin and its hole in one pose. Each Contact as for the paper's "
      "joint, the link in the bearing's place and the pin in the journal's: point_journal on the "
      "pin, point_bearing on the link, normal the direction the pin penetrates; type radial for "
      "an edge or line contact, axial for a stop; base a or b for the link face, mid for the line.");
  def_field_attributes(contacts)
      .def_readonly("contact_count", &geo::PinInHoleContacts::contact_count)
      .def("as_dict", [](const geo::PinInHoleContacts& r) { return as_dict(r); },
           "{'scenario', 'aligned', 'certificate', 'certificate_reason', 'contact_count', "
           "'contacts': [Contact.as_dict(), ...]}: plain Python values (enums are IntEnums).")
      // PinInHoleBatch rows are rebuilt through the dict of as_dict().
      .def_static("_from_dict", &from_dict<geo::PinInHoleContacts>, py::arg("d"))
      .def("__repr__", [](const geo::PinInHoleContacts& r) {
        std::string text = "PinInHoleContacts(" + std::string(geo::to_string(r.scenario)) +
                           (r.aligned ? ", aligned" : "") + ", " + repr_certificate(r.certificate);
        for (int k = 0; k < r.contact_count; ++k) {
          const geo::Contact& c = r.contacts[static_cast<std::size_t>(k)];
          text += std::string(k == 0 ? ";" : ",") + " " + std::string(geo::to_string(c.type)) + " at " +
                  std::string(geo::to_string(c.base)) + " depth " + repr_number(c.depth);
        }
        return text + ")";
      });
}

/// The pose arguments, read once.
struct PinPoseRows {
  VectorRows hole_center, hole_axis, pin_center, pin_axis;

  geo::PartPose hole(std::size_t n) const { return {hole_center[n], hole_axis[n]}; }
  geo::PartPose pin(std::size_t n) const { return {pin_center[n], pin_axis[n]}; }
};

/// The library's field paths (detect_pin_in_hole_contacts.hpp), as the Python arguments.
[[noreturn]] void raise(const RowError& error, const PinPoseRows& poses) {
  python::raise(error, {{"hole.p_WP", "hole_center", poses.hole_center.batched()},
                        {"hole.axis_W", "hole_axis", poses.hole_axis.batched()},
                        {"pin.p_WP", "pin_center", poses.pin_center.batched()},
                        {"pin.axis_W", "pin_axis", poses.pin_axis.batched()},
                        {"options.parallel_angle_tolerance", "parallel_angle_tolerance", false}});
}

/// One PinInHoleContacts, or the packed arrays of a batch (row n: bit for bit the answer on that
/// pose alone), detected without the GIL.
py::object detect_pin_in_hole(const geo::PinInHoleDimensions& dimensions, const py::handle& hole_center,
                              const py::handle& hole_axis, const py::handle& pin_center,
                              const py::handle& pin_axis, const py::dict& option_arguments,
                              const py::object& threads) {
  const PinPoseRows poses{VectorRows(hole_center, "hole_center"), VectorRows(hole_axis, "hole_axis"),
                          VectorRows(pin_center, "pin_center"), VectorRows(pin_axis, "pin_axis")};
  const Broadcast shape = broadcast(poses.hole_center, poses.hole_axis, poses.pin_center, poses.pin_axis);
  const geo::DetectionOptions options = detection_options(option_arguments);
  const unsigned thread_limit = thread_count(threads);
  if (shape.batched) {
    return within_memory("detect_pin_in_hole", shape.rows, "poses", [&]() -> py::object {
      try {
        return packed_contacts<geo::PinInHoleContacts>(
            shape.rows, thread_limit, [&](std::size_t n, geo::PinInHoleContacts& result) {
              result = geo::detect_pin_in_hole_contacts(dimensions, poses.hole(n), poses.pin(n), options);
            });
      } catch (const RowError& error) {
        raise(error, poses);
      }
    });
  }
  geo::PinInHoleContacts result;
  try {
    py::gil_scoped_release release;
    result = geo::detect_pin_in_hole_contacts(dimensions, poses.hole(0), poses.pin(0), options);
  } catch (const ValidationError& e) {
    raise(RowError::invalid(0, e), poses);
  }
  return py::cast(result);
}

}  // namespace

void bind_pin_in_hole(py::module_& module) {
  bind_dimensions(module);
  bind_result(module);
  module.def("detect_pin_in_hole", &detect_pin_in_hole, py::arg("dims"), py::arg("hole_center"),
             py::arg("hole_axis"), py::arg("pin_center"), py::arg("pin_axis"), py::arg("options"),
             py::arg("threads"),
             "clearjoint.detect_pin_in_hole's compiled half: a PinInHoleContacts, or a dict of arrays "
             "for a batch.");
}

}  // namespace clearjoint::python
