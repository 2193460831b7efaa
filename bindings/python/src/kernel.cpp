// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.intersect_circle_plane / intersect_circle_cylinder: the certified kernel
// queries (paper eqs. 11-15 and 16-21) on one primitive pair (a result object) or on a batch
// given as NumPy arrays (a dict of arrays padded to the query's largest crossing count: 2 or 4
// crossings a row are few enough to keep rows of equal shape).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "numpy_views.hpp"
#include "parallel_chunks.hpp"
#include "result_attributes.hpp"
#include "result_dicts.hpp"
#include "result_types.hpp"
#include "signal_check.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename T>
py::array_t<T> array_of(std::vector<py::ssize_t> shape) {
  return py::array_t<T>(std::move(shape));
}

/// Crossings of shape (N, K): angle, errors, points (N, K, 3), multiplicity (0 where unused).
struct CrossingColumns {
  py::array_t<std::int8_t> count, multiplicity;
  py::array_t<double> angle, angle_error, point, point_error;
  std::size_t slots;

  CrossingColumns(py::ssize_t rows, py::ssize_t k)
      : count(array_of<std::int8_t>({rows})),
        multiplicity(array_of<std::int8_t>({rows, k})),
        angle(array_of<double>({rows, k})),
        angle_error(array_of<double>({rows, k})),
        point(array_of<double>({rows, k, 3})),
        point_error(array_of<double>({rows, k})),
        slots(static_cast<std::size_t>(k)) {}

  // Raw pointers, taken with the GIL held, for the workers.
  struct Out {
    std::int8_t *count, *multiplicity;
    double *angle, *angle_error, *point, *point_error;
    std::size_t slots;
    void write(std::size_t n, const geo::RimCrossing* crossings, int used) const {
      count[n] = static_cast<std::int8_t>(used);
      for (std::size_t x = 0; x < slots; ++x) {
        const std::size_t i = n * slots + x;
        const bool in_use = static_cast<int>(x) < used;
        const geo::RimCrossing& c = crossings[x];
        multiplicity[i] = in_use ? static_cast<std::int8_t>(c.multiplicity) : 0;
        angle[i] = in_use ? c.angle : kNaN;
        angle_error[i] = in_use ? c.angle_error : kNaN;
        point_error[i] = in_use ? c.point_error : kNaN;
        for (int j = 0; j < 3; ++j) point[3 * i + j] = in_use ? c.point[j] : kNaN;
      }
    }
  };
  Out out() {
    return {count.mutable_data(), multiplicity.mutable_data(), angle.mutable_data(),
            angle_error.mutable_data(), point.mutable_data(), point_error.mutable_data(), slots};
  }
  void put(py::dict& d) const {
    d["crossing_count"] = count;
    d["crossing_angle"] = angle;
    d["crossing_angle_error"] = angle_error;
    d["crossing_point"] = point;
    d["crossing_point_error"] = point_error;
    d["crossing_multiplicity"] = multiplicity;
  }
};

/// Run `query(n)` over the rows in chunks without the GIL; returns the first bad row, if any.
/// Other failures (MemoryError, KeyboardInterrupt) propagate.
template <typename Query>
std::optional<RowError> run_rows(std::size_t rows, unsigned threads, const Query& query) {
  try {
    py::gil_scoped_release release;
    std::atomic<bool> interrupted{false};
    for_each_chunk(rows, chunk_rows(rows, threads), threads, interrupted, SignalCheck(),
                   [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t n = begin; n < end && !interrupted.load(std::memory_order_relaxed); ++n) {
        answer_row(n, [&] { query(n); });
      }
    });
  } catch (const RowError& error) {
    return error;  // the first bad row: chunks are handed out in order and finished once begun
  }
  return std::nullopt;
}

geo::IntersectionOptions intersection_options(const py::handle& certify, const py::handle& exact_fallback) {
  geo::IntersectionOptions options;
  options.certify = flag_argument(certify, "certify");
  options.exact_fallback = flag_argument(exact_fallback, "exact_fallback");
  return options;
}

py::object circle_plane(const py::handle& circle_center, const py::handle& circle_normal,
                        const py::handle& circle_radius, const py::handle& plane_point,
                        const py::handle& plane_normal, const py::handle& certify, const py::handle& exact_fallback,
                        const py::object& threads) {
  const VectorRows center(circle_center, "circle_center"), normal(circle_normal, "circle_normal");
  const ScalarRows radius(circle_radius, "circle_radius");
  const VectorRows point(plane_point, "plane_point"), plane_n(plane_normal, "plane_normal");
  const Broadcast shape = broadcast(center, normal, radius, point, plane_n);
  const geo::IntersectionOptions options = intersection_options(certify, exact_fallback);
  const unsigned thread_limit = thread_count(threads);
  auto circle = [&](std::size_t n) { return geo::Circle3{center[n], normal[n], radius[n]}; };
  auto plane = [&](std::size_t n) { return geo::Plane3{point[n], plane_n[n]}; };
  const std::initializer_list<FieldName> fields = {
      {"circle.center", "circle_center", center.batched()}, {"circle.normal", "circle_normal", normal.batched()},
      {"circle.radius", "circle_radius", radius.batched()}, {"plane.point", "plane_point", point.batched()},
      {"plane.normal", "plane_normal", plane_n.batched()}};

  if (!shape.batched) {
    std::optional<RowError> error;
    geo::CirclePlaneIntersection result;
    {
      py::gil_scoped_release release;
      try {
        result = geo::intersect_circle_plane(circle(0), plane(0), options);
      } catch (const ValidationError& e) {
        error = RowError::invalid(0, e);
      }
    }
    if (error) raise(*error, fields);
    return py::cast(result);
  }

  // Out of memory for the result columns: a MemoryError naming the batch, not "std::bad_alloc".
  return within_memory("intersect_circle_plane", shape.rows, "circles", [&]() -> py::object {
    const auto rows = static_cast<py::ssize_t>(shape.rows);
    auto topology = array_of<std::int8_t>({rows}), side = array_of<std::int8_t>({rows}),
         certificate = array_of<std::int8_t>({rows}), reason = array_of<std::int8_t>({rows});
    auto has_penetration = array_of<bool>({rows}), penetration_full = array_of<bool>({rows});
    auto penetration_begin = array_of<double>({rows}), penetration_end = array_of<double>({rows}),
         distance = array_of<double>({rows}), distance_error = array_of<double>({rows});
    CrossingColumns crossings(rows, 2);
    const CrossingColumns::Out crossing_out = crossings.out();
    std::int8_t *t = topology.mutable_data(), *s = side.mutable_data(), *c = certificate.mutable_data(),
                *cr = reason.mutable_data();
    bool *hp = has_penetration.mutable_data(), *pf = penetration_full.mutable_data();
    double *pb = penetration_begin.mutable_data(), *pe = penetration_end.mutable_data(),
           *d = distance.mutable_data(), *de = distance_error.mutable_data();
    const auto error = run_rows(shape.rows, thread_limit, [&](std::size_t n) {
      const geo::CirclePlaneIntersection r = geo::intersect_circle_plane(circle(n), plane(n), options);
      t[n] = static_cast<std::int8_t>(r.topology);
      s[n] = static_cast<std::int8_t>(r.side);
      c[n] = static_cast<std::int8_t>(r.certificate.level);
      cr[n] = static_cast<std::int8_t>(r.certificate.reason);
      hp[n] = r.has_penetration;
      pb[n] = r.has_penetration ? r.penetration.begin : kNaN;
      pe[n] = r.has_penetration ? r.penetration.end : kNaN;
      pf[n] = r.has_penetration && r.penetration.full;
      d[n] = r.max_signed_distance;
      de[n] = r.max_signed_distance_error;
      crossing_out.write(n, r.crossings.data(), r.crossing_count);
    });
    if (error) raise(*error, fields);
    py::dict out;
    out["topology"] = topology;
    out["side"] = side;
    crossings.put(out);
    out["has_penetration"] = has_penetration;
    out["penetration_begin"] = penetration_begin;
    out["penetration_end"] = penetration_end;
    out["penetration_full"] = penetration_full;
    out["max_signed_distance"] = distance;
    out["max_signed_distance_error"] = distance_error;
    out["certificate"] = certificate;
    out["certificate_reason"] = reason;
    return out;
  });
}

py::object circle_cylinder(const py::handle& circle_center, const py::handle& circle_normal,
                           const py::handle& circle_radius, const py::handle& cylinder_point,
                           const py::handle& cylinder_axis, const py::handle& cylinder_radius,
                           const py::handle& certify, const py::handle& exact_fallback, const py::object& threads) {
  const VectorRows center(circle_center, "circle_center"), normal(circle_normal, "circle_normal");
  const ScalarRows radius(circle_radius, "circle_radius");
  const VectorRows point(cylinder_point, "cylinder_point"), axis(cylinder_axis, "cylinder_axis");
  const ScalarRows wall_radius(cylinder_radius, "cylinder_radius");
  const Broadcast shape = broadcast(center, normal, radius, point, axis, wall_radius);
  const geo::IntersectionOptions options = intersection_options(certify, exact_fallback);
  const unsigned thread_limit = thread_count(threads);
  auto circle = [&](std::size_t n) { return geo::Circle3{center[n], normal[n], radius[n]}; };
  auto cylinder = [&](std::size_t n) { return geo::Cylinder3{point[n], axis[n], wall_radius[n]}; };
  const std::initializer_list<FieldName> fields = {
      {"circle.center", "circle_center", center.batched()}, {"circle.normal", "circle_normal", normal.batched()},
      {"circle.radius", "circle_radius", radius.batched()},
      {"cylinder.axis_point", "cylinder_point", point.batched()},
      {"cylinder.axis", "cylinder_axis", axis.batched()},
      {"cylinder.radius", "cylinder_radius", wall_radius.batched()}};

  if (!shape.batched) {
    std::optional<RowError> error;
    geo::CircleCylinderIntersection result;
    {
      py::gil_scoped_release release;
      try {
        result = geo::intersect_circle_cylinder(circle(0), cylinder(0), options);
      } catch (const ValidationError& e) {
        error = RowError::invalid(0, e);
      }
    }
    if (error) raise(*error, fields);
    return py::cast(result);
  }

  // Out of memory for the result columns: a MemoryError naming the batch, not "std::bad_alloc".
  return within_memory("intersect_circle_cylinder", shape.rows, "circles", [&]() -> py::object {
    const auto rows = static_cast<py::ssize_t>(shape.rows);
    auto topology = array_of<std::int8_t>({rows}), certificate = array_of<std::int8_t>({rows}),
         reason = array_of<std::int8_t>({rows}), arc_count = array_of<std::int8_t>({rows});
    auto arc_begin = array_of<double>({rows, 2}), arc_end = array_of<double>({rows, 2});
    auto arc_full = array_of<bool>({rows, 2});
    CrossingColumns crossings(rows, 4);
    const CrossingColumns::Out crossing_out = crossings.out();
    std::int8_t *t = topology.mutable_data(), *c = certificate.mutable_data(), *cr = reason.mutable_data(),
                *ac = arc_count.mutable_data();
    double *ab = arc_begin.mutable_data(), *ae = arc_end.mutable_data();
    bool* af = arc_full.mutable_data();
    const auto error = run_rows(shape.rows, thread_limit, [&](std::size_t n) {
      const geo::CircleCylinderIntersection r = geo::intersect_circle_cylinder(circle(n), cylinder(n), options);
      t[n] = static_cast<std::int8_t>(r.topology);
      c[n] = static_cast<std::int8_t>(r.certificate.level);
      cr[n] = static_cast<std::int8_t>(r.certificate.reason);
      ac[n] = static_cast<std::int8_t>(r.arc_count);
      for (int k = 0; k < 2; ++k) {
        const bool used = k < r.arc_count;
        ab[2 * n + k] = used ? r.penetration_arcs[k].begin : kNaN;
        ae[2 * n + k] = used ? r.penetration_arcs[k].end : kNaN;
        af[2 * n + k] = used && r.penetration_arcs[k].full;
      }
      crossing_out.write(n, r.crossings.data(), r.crossing_count);
    });
    if (error) raise(*error, fields);
    py::dict out;
    out["topology"] = topology;
    crossings.put(out);
    out["arc_count"] = arc_count;
    out["arc_begin"] = arc_begin;
    out["arc_end"] = arc_end;
    out["arc_full"] = arc_full;
    out["certificate"] = certificate;
    out["certificate_reason"] = reason;
    return out;
  });
}

// The attributes of each result are its field list's (result_attributes.hpp); bound here are the
// class docs, the attributes that are not fields, and the reprs.
void bind_kernel_types(py::module_& m) {
  py::class_<geo::CirclePlaneIntersection> plane(m, "CirclePlaneIntersection",
                                                 "A circle against a plane (a rim against a base, eqs. 11-15).");
  add_as_dict_and_pickle(def_field_attributes(plane)
      .def("__repr__", [](const geo::CirclePlaneIntersection& r) {
        return "CirclePlaneIntersection(" + std::string(geo::to_string(r.topology)) +
               ", side=" + std::to_string(static_cast<int>(r.side)) + ", crossings=" + std::to_string(r.crossing_count) +
               ", max_signed_distance=" + repr_number(r.max_signed_distance) + ", " +
               repr_certificate(r.certificate) + ")";
      }),
      "{'topology', 'side', 'crossings', 'penetration' (RimArc.as_dict() or None), "
      "'max_signed_distance', 'max_signed_distance_error', 'certificate', 'certificate_reason'}");

  py::class_<geo::CircleCylinderIntersection> cylinder(
      m, "CircleCylinderIntersection", "A circle against a cylinder's lateral surface (a rim against the wall, eqs. 16-21).");
  add_as_dict_and_pickle(def_field_attributes(cylinder)
      .def_property_readonly("root_count", &geo::CircleCylinderIntersection::root_count,
                             "crossings counted with multiplicity")
      .def("__repr__", [](const geo::CircleCylinderIntersection& r) {
        return "CircleCylinderIntersection(" + std::string(geo::to_string(r.topology)) +
               ", crossings=" + std::to_string(r.crossing_count) + ", arcs=" + std::to_string(r.arc_count) +
               ", " + repr_certificate(r.certificate) + ")";
      }),
      "{'topology', 'crossings', 'penetration_arcs', 'certificate', 'certificate_reason'}");
}

}  // namespace

void bind_kernel(py::module_& module) {
  bind_kernel_types(module);
  module.def("intersect_circle_plane", &circle_plane, py::arg("circle_center"), py::arg("circle_normal"),
             py::arg("circle_radius"), py::arg("plane_point"), py::arg("plane_normal"),
             py::arg("certify"), py::arg("exact_fallback"), py::arg("threads"),
             "clearjoint.intersect_circle_plane's compiled half.");
  module.def("intersect_circle_cylinder", &circle_cylinder, py::arg("circle_center"),
             py::arg("circle_normal"), py::arg("circle_radius"), py::arg("cylinder_point"),
             py::arg("cylinder_axis"), py::arg("cylinder_radius"), py::arg("certify"),
             py::arg("exact_fallback"), py::arg("threads"),
             "clearjoint.intersect_circle_cylinder's compiled half.");
}

}  // namespace clearjoint::python
