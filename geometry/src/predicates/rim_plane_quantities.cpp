// SPDX-License-Identifier: BSD-3-Clause
#include "predicates/rim_plane_quantities.hpp"

#include <bit>
#include <cmath>
#include <optional>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/filtered_predicate.hpp"
#include "arithmetic/pair_lanes.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "arithmetic/twinned.hpp"
#include "model/primitives_detail.hpp"
#include "predicates/plane_terms.hpp"

namespace clearjoint::geometry::detail {
namespace {

BoundedVector3 exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }

/// The a priori terms: plane_terms on Twinned (twinned.hpp), each value beside its
/// absolute-value twin, formed in one chain of packed operations. Chains of roundings: c - p 1
/// (rounded in double, its twin |c - p|), s 4, w 2, w2 5, nc2 and np2 3, discriminant 10
/// (s^2 nc2 9, r^2 w2 7, then the difference).
struct APrioriTerms {
  PlaneTerms<Twinned> terms;  ///< nc2 and np2 in both lanes: x^2 and |x|^2 round alike
  double nc_1, np_1;          ///< 1-norms of the normals, for the guard (plane_quantities_if_ready)
};
APrioriTerms a_priori_terms(const Circle3& circle, const Plane3& plane) {
  // Component by component, not through Eigen's cwiseAbs/cross/dot, whose temporaries it did
  // not fold away here (this and the guard below were ~240 instructions of a ~1250-instruction
  // query).
  const Vector3& c = circle.center;
  const Vector3& p = plane.point;
  const Vector3& np = plane.normal;
  const Vector3& nc = circle.normal;
  const Vector3Of<Twinned> offset{Twinned::of(c.x() - p.x()), Twinned::of(c.y() - p.y()), Twinned::of(c.z() - p.z())};
  const Vector3Of<Twinned> n_p{Twinned::of(np.x()), Twinned::of(np.y()), Twinned::of(np.z())};
  const Vector3Of<Twinned> n_c{Twinned::of(nc.x()), Twinned::of(nc.y()), Twinned::of(nc.z())};
  // Filled member by member: built in one braced return, the terms stayed in memory (GCC did not
  // split the nested aggregate into registers) and plane_quantities_if_ready spilled ~15 values.
  APrioriTerms t;
  t.terms = plane_terms(offset, n_c, n_p, Twinned::of(circle.radius));
  t.nc_1 = (n_c.x + n_c.y + n_c.z).twin();
  t.np_1 = (n_p.x + n_p.y + n_p.z).twin();
  return t;
}

/// a_priori_with_underflow(value, twin) of {value, twin}, in the lanes: Bounded is {value, error},
/// the layout of a Pair. Lane 1 is a_priori_with_underflow's kGamma64 * twin *
/// kMagnitudeInflation + kUnderflowAllowance; lane 0 multiplies the value by 1 twice and adds -0,
/// which gives back its bits (-0 and subnormals included). Test: the bits equal those of
/// a_priori_with_underflow (test_rim_plane_quantities.cpp). As two scalar calls, with the lanes
/// taken apart first, it cost ~23 more instructions per plane query (callgrind).
Bounded a_priori_from_twin(Twinned value_and_twin) {
  return std::bit_cast<Bounded>(value_and_twin.lanes * Pair{1.0, kGamma64} * Pair{1.0, kMagnitudeInflation} +
                                Pair{-0.0, kUnderflowAllowance});
}

PlaneQuantities plane_quantities_from_terms(const PlaneTerms<Twinned>& t, double np2) {
  return {a_priori_from_twin(t.s),
          {a_priori_from_twin(t.w.x), a_priori_from_twin(t.w.y), a_priori_from_twin(t.w.z)},
          a_priori_from_twin(t.w2),
          a_priori_from_twin(t.nc2),
          a_priori_with_underflow(np2, np2),
          a_priori_from_twin(t.discriminant)};
}

}  // namespace

PlaneQuantities plane_quantities_a_priori(const Circle3& circle, const Plane3& plane) {
  return plane_quantities_from_terms(a_priori_terms(circle, plane).terms, plane.normal.squaredNorm());
}

/// The running error bound of error_bounded.hpp, for inputs outside the a priori guard (it also
/// covers underflow and overflow).
PlaneQuantities plane_quantities_running_error(const Circle3& circle, const Plane3& plane) {
  return plane_terms(exact(circle.center) - exact(plane.point), exact(circle.normal), exact(plane.normal),
                     Bounded(circle.radius));
}

namespace {

/// The magnitudes the guards below test, written out component by component (Eigen's
/// reductions cost ~65 instructions here).
struct GuardMagnitudes {
  double lengths;     ///< |c|_1 + |p|_1
  double nc_1, np_1;  ///< 1-norms of the normals
  double nc2, np2;    ///< their squares
};
/// |c|_1 + |p|_1.
double lengths_one_norm(const Circle3& circle, const Plane3& plane) {
  const Vector3& c = circle.center;
  const Vector3& p = plane.point;
  return (std::fabs(c.x()) + std::fabs(c.y()) + std::fabs(c.z())) +
         (std::fabs(p.x()) + std::fabs(p.y()) + std::fabs(p.z()));
}
GuardMagnitudes guard_magnitudes(const Circle3& circle, const Plane3& plane) {
  const Vector3& nc = circle.normal;
  const Vector3& np = plane.normal;
  return {lengths_one_norm(circle, plane),
          std::fabs(nc.x()) + std::fabs(nc.y()) + std::fabs(nc.z()),
          std::fabs(np.x()) + std::fabs(np.y()) + std::fabs(np.z()),
          nc.x() * nc.x() + nc.y() * nc.y() + nc.z() * nc.z(),
          np.x() * np.x() + np.y() * np.y() + np.z() * np.z()};
}

/// Normals whose squares lie below 2^-200 (the old lower limit's square) take the running error:
/// the depth divides by |n_p|.
constexpr double kSmallestNormalSquare = 0x1p-200;
bool normals_in_guard(const GuardMagnitudes& g) {
  return (g.nc_1 <= kLargestGuardedInput) & (g.np_1 <= kLargestGuardedInput) &
         (g.nc2 >= kSmallestNormalSquare) & (g.np2 >= kSmallestNormalSquare);
}

bool inputs_ready(const GuardMagnitudes& g, double radius) {
  // The lengths: the largest is at least the radius and at most the 1-norm sum, so both inside
  // scale_normalisation.hpp's unscaled range put it there.
  return (g.lengths < kLargestUnscaledLength) & (radius >= kSmallestUnscaledLength) &
         (radius < kLargestUnscaledLength) & normals_in_guard(g);
}

}  // namespace

bool plane_a_priori_bounds_apply(const Circle3& circle, const Plane3& plane) {
  // The upper limit of a_priori_bounds.hpp's guard on every input and on c - p (via 1-norms:
  // |x|_inf <= |x|_1 and |c - p|_1 <= |c|_1 + |p|_1); the lower limit is replaced by
  // kUnderflowAllowance in every bound.
  const GuardMagnitudes g = guard_magnitudes(circle, plane);
  return (g.lengths <= kLargestGuardedInput) & (circle.radius <= kLargestGuardedInput) & normals_in_guard(g);
}

ReadyPlaneQuantities plane_quantities_if_ready(const Circle3& circle, const Plane3& plane) {
  const APrioriTerms t = a_priori_terms(circle, plane);
  const double np2 = t.terms.np2.value();
  const GuardMagnitudes g{lengths_one_norm(circle, plane), t.nc_1, t.np_1, t.terms.nc2.value(), np2};
  if (!inputs_ready(g, circle.radius)) return {};
  return {true, plane_quantities_from_terms(t.terms, np2)};
}

DeepestDirection deepest_direction(const Circle3& circle, const PlaneQuantities& q) {
  const Vector3& nc = circle.normal;
  const Bounded nc_length = sqrt(q.nc2);
  // (w x n_c)_k = w_(k+1) n_(k+2) - w_(k+2) n_(k+1), indices mod 3; n_c's components are exact.
  // Spelled out per k (the indexing and % 3 cost ~20 of its ~170 instructions).
  switch (frame_axis_index(nc)) {
    case 0: return {nc_length * q.w.x, q.w.y * Bounded(nc.z()) - q.w.z * Bounded(nc.y())};
    case 1: return {nc_length * q.w.y, q.w.z * Bounded(nc.x()) - q.w.x * Bounded(nc.z())};
    default: return {nc_length * q.w.z, q.w.x * Bounded(nc.y()) - q.w.y * Bounded(nc.x())};
  }
}

RimSide rim_side_of_plane(const Circle3& circle, const Plane3& plane) {
  return rim_side_of_plane(circle, plane, plane_a_priori_bounds_apply(circle, plane));
}

RimSide rim_side_of_plane(const Circle3& circle, const Plane3& plane, bool a_priori_bounds_apply,
                          double distance_error) {
  struct SideQuantities {
    Bounded s, discriminant;
  };
  return filtered_predicate(
      a_priori_bounds_apply,
      [&] {  // only the two values the side needs, not all the quantities
        const PlaneTerms<Twinned> t = a_priori_terms(circle, plane).terms;
        SideQuantities q{a_priori_from_twin(t.s), a_priori_from_twin(t.discriminant)};
        if (distance_error != 0.0) {
          const double np2 = plane.normal.squaredNorm();
          widen_side_quantities(q.s, q.discriminant, a_priori_with_underflow(np2, np2), a_priori_from_twin(t.nc2),
                                distance_error);
        }
        return q;
      },
      [&] {
        PlaneQuantities q = plane_quantities_running_error(circle, plane);
        widen_for_point_error(q, distance_error);
        return SideQuantities{q.s, q.discriminant};
      },
      [](const SideQuantities& q) -> std::optional<RimSide> {
        if (q.discriminant.sign() <= 0) return std::nullopt;
        const int side = q.s.sign();
        if (side == 0) return std::nullopt;
        return side < 0 ? RimSide::strictly_negative : RimSide::strictly_positive;
      },
      // No exact tier: a filter for the callers (the prefilters), which run the whole query when
      // it cannot tell.
      [] { return RimSide::undecided; });
}

}  // namespace clearjoint::geometry::detail
