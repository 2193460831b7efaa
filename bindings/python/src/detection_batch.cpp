// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.detect: detect_contacts on one pose (a JointContacts) or on a batch of poses
// given as NumPy arrays (a dict of packed arrays, packed_contacts.hpp, which clearjoint/_detect.py
// wraps), without the GIL and spread over threads.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "bindings.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/option_fields.hpp"
#include "numpy_views.hpp"
#include "packed_contacts.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

/// The pose arguments, read once.
struct PoseRows {
  VectorRows bearing_center;
  VectorRows bearing_axis;
  VectorRows journal_center;
  VectorRows journal_axis;

  geo::PartPose bearing(std::size_t n) const { return {bearing_center[n], bearing_axis[n]}; }
  geo::PartPose journal(std::size_t n) const { return {journal_center[n], journal_axis[n]}; }
};

/// The library's field paths, as the Python arguments.
[[noreturn]] void raise(const RowError& error, const PoseRows& poses) {
  raise(error, {{"bearing.p_WP", "bearing_center", poses.bearing_center.batched()},
                {"bearing.axis_W", "bearing_axis", poses.bearing_axis.batched()},
                {"journal.p_WP", "journal_center", poses.journal_center.batched()},
                {"journal.axis_W", "journal_axis", poses.journal_axis.batched()},
                {"options.parallel_angle_tolerance", "parallel_angle_tolerance", false}});
}

py::dict detect_batch(const geo::JointDimensions& dimensions, const PoseRows& poses,
                      std::size_t rows, const geo::DetectionOptions& options, unsigned threads) {
  try {
    return packed_contacts<geo::JointContacts>(rows, threads, [&](std::size_t n, geo::JointContacts& result) {
      geo::detect_contacts(dimensions, poses.bearing(n), poses.journal(n), result, options);
    });
  } catch (const RowError& error) {
    raise(error, poses);
  }
}

}  // namespace

/// The options clearjoint.detect passes by their keys in the option list (option_fields.hpp),
/// each checked as its keyword argument. A key it does not pass is an error of the package, not
/// of the caller: tests/test_detect.py checks that detect has a keyword for each.
geo::DetectionOptions detection_options(const py::dict& given) {
  geo::DetectionOptions options;
  geo::visit_options(options, [&given](std::string_view key, auto& value) {
    const std::string name(key);
    if (!given.contains(name)) throw std::logic_error("clearjoint.detect passes no option " + name);
    const py::handle argument = given[py::str(name)];
    if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, bool>) {
      value = flag_argument(argument, name.c_str());
    } else {
      value = number_argument(argument, name);
    }
  });
  return options;
}

namespace {

/// Every option's default by its key, for the check of detect's keywords.
py::dict detection_option_defaults() {
  py::dict defaults;
  const geo::DetectionOptions options;
  geo::visit_options(options, [&defaults](std::string_view key, const auto& value) {
    defaults[py::str(std::string(key))] = value;
  });
  return defaults;
}

py::object detect(const geo::JointDimensions& dimensions, const py::handle& bearing_center,
                  const py::handle& bearing_axis, const py::handle& journal_center,
                  const py::handle& journal_axis, const py::dict& option_arguments, const py::object& threads) {
  const PoseRows poses{VectorRows(bearing_center, "bearing_center"), VectorRows(bearing_axis, "bearing_axis"),
                       VectorRows(journal_center, "journal_center"), VectorRows(journal_axis, "journal_axis")};
  const Broadcast shape =
      broadcast(poses.bearing_center, poses.bearing_axis, poses.journal_center, poses.journal_axis);
  const geo::DetectionOptions options = detection_options(option_arguments);
  const unsigned thread_limit = thread_count(threads);
  if (shape.batched) {
    return within_memory("detect", shape.rows, "poses",
                         [&]() -> py::object { return detect_batch(dimensions, poses, shape.rows, options, thread_limit); });
  }
  geo::JointContacts result;
  try {
    py::gil_scoped_release release;
    geo::detect_contacts(dimensions, poses.bearing(0), poses.journal(0), result, options);
  } catch (const ValidationError& e) {
    raise(RowError::invalid(0, e), poses);
  }
  return py::cast(result);
}

}  // namespace

void bind_detection_batch(py::module_& module) {
  module.def("detect", &detect, py::arg("dims"), py::arg("bearing_center"), py::arg("bearing_axis"),
             py::arg("journal_center"), py::arg("journal_axis"), py::arg("options"), py::arg("threads"),
             "clearjoint.detect's compiled half: a JointContacts, or a dict of arrays for a batch.");
  module.def("_detection_option_defaults", &detection_option_defaults,
             "Each detection option's default by its key (the library's option list).");
}

}  // namespace clearjoint::python
