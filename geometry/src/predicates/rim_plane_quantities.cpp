// SPDX-License-Identifier: BSD-3-Clause
#include "rim_plane_quantities.hpp"

#include <array>
#include <bit>
#include <cmath>

#include "a_priori_bounds.hpp"
#include "pair_lanes.hpp"
#include "primitives_detail.hpp"
#include "scale_normalisation.hpp"

namespace clearjoint::geometry::detail {
namespace {

BoundedVector3 exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

namespace {

/// A value beside its absolute-value twin (a_priori_bounds.hpp), the value in lane 0 and the twin
/// in lane 1 (pair_lanes.hpp). The twin is the value's expression on |inputs| with subtractions
/// turned into additions, so one chain of packed operations forms both, each lane rounded exactly
/// as the scalar operation: the bits of the value and of the twin computed one after the other.
/// A subtracted product's factor enters as {x, -|x|}: a - (-|x|) y is a + |x| y exactly (negation
/// is exact, and so is that of a rounded product).
Pair with_twin(double x) {
  const PairMask kAllButLane1Sign = ~bits_of(Pair{0.0, -0.0});
  return pair_of_bits(bits_of(Pair{x, x}) & kAllButLane1Sign);
}
Pair with_negated_twin(double x) {
  const PairMask kLane1Sign = bits_of(Pair{0.0, -0.0});
  return pair_of_bits(bits_of(Pair{x, x}) | kLane1Sign);
}

/// The a priori computation in plain double, each value beside its absolute-value twin
/// (with_twin). Chains of roundings: c - p 1, s 4, w 2, w2 5, nc2 and np2 3, discriminant 10
/// (s^2 nc2 9, r^2 w2 7, then the difference).
struct APrioriTerms {
  Pair s;
  std::array<Pair, 3> w;
  Pair w2;
  Pair nc2, np2;  ///< in both lanes: x^2 and |x|^2 round alike, so each is its own twin
  Pair discriminant;
  double nc_1, np_1;  ///< 1-norms of the normals, for the guard (plane_quantities_if_ready)
};
APrioriTerms a_priori_terms(const Circle3& circle, const Plane3& plane) {
  // Component by component: the same operations as Eigen's cwiseAbs/cross/dot, without the
  // temporaries, which it did not fold away here (this and the guard below were ~240
  // instructions of a ~1250-instruction query); in lanes, the value's and the twin's at once.
  const Vector3& c = circle.center;
  const Vector3& p = plane.point;
  const Vector3& np = plane.normal;
  const Vector3& nc = circle.normal;
  const Pair dx = with_twin(c.x() - p.x()), dy = with_twin(c.y() - p.y()), dz = with_twin(c.z() - p.z());
  const Pair px = with_twin(np.x()), py = with_twin(np.y()), pz = with_twin(np.z());
  const Pair cx = with_twin(nc.x()), cy = with_twin(nc.y()), cz = with_twin(nc.z());
  APrioriTerms t;
  t.s = px * dx + py * dy + pz * dz;
  // w = n_p x n_c; its twin |n_p| x |n_c| with + (abs_cross).
  t.w = {py * cz - with_negated_twin(np.z()) * cy, pz * cx - with_negated_twin(np.x()) * cz,
         px * cy - with_negated_twin(np.y()) * cx};
  t.w2 = t.w[0] * t.w[0] + t.w[1] * t.w[1] + t.w[2] * t.w[2];
  t.nc2 = cx * cx + cy * cy + cz * cz;
  t.np2 = px * px + py * py + pz * pz;
  const double r2 = circle.radius * circle.radius;
  // r^2 w2 is subtracted from the value and added to the twin: -r^2 in lane 1 (with_negated_twin).
  t.discriminant = t.s * t.s * t.nc2 - Pair{r2, -r2} * t.w2;
  t.nc_1 = (cx + cy + cz)[1];
  t.np_1 = (px + py + pz)[1];
  return t;
}

/// a_priori_with_underflow(value, twin) of {value, twin}, in the lanes: Bounded is {value, error},
/// the layout of a Pair. Lane 1 is a_priori_with_underflow's kGamma64 * twin *
/// kMagnitudeInflation + kUnderflowAllowance; lane 0 multiplies the value by 1 twice and adds -0,
/// which gives back its bits (-0 and subnormals included). Test: the bits equal those of
/// a_priori_with_underflow (test_rim_plane_quantities.cpp). As two scalar calls, with the lanes
/// taken apart first, it cost ~23 more instructions per plane query (callgrind).
Bounded a_priori_from_twin(Pair value_and_twin) {
  return std::bit_cast<Bounded>(value_and_twin * Pair{1.0, kGamma64} * Pair{1.0, kMagnitudeInflation} +
                                Pair{-0.0, kUnderflowAllowance});
}

}  // namespace

namespace {
PlaneQuantities plane_quantities_from_terms(const APrioriTerms& t, double np2) {
  return {a_priori_from_twin(t.s),
          {a_priori_from_twin(t.w[0]), a_priori_from_twin(t.w[1]), a_priori_from_twin(t.w[2])},
          a_priori_from_twin(t.w2),
          a_priori_from_twin(t.nc2),
          a_priori_with_underflow(np2, np2),
          a_priori_from_twin(t.discriminant)};
}

}  // namespace

PlaneQuantities plane_quantities_a_priori(const Circle3& circle, const Plane3& plane) {
  return plane_quantities_from_terms(a_priori_terms(circle, plane), plane.normal.squaredNorm());
}

/// The running error bound of error_bounded.hpp, for inputs outside the a priori guard (it also
/// covers underflow and overflow).
PlaneQuantities plane_quantities_running_error(const Circle3& circle, const Plane3& plane) {
  const BoundedVector3 nc = exact(circle.normal), np = exact(plane.normal);
  const Bounded s = dot(np, exact(circle.center) - exact(plane.point));
  const BoundedVector3 w = cross(np, nc);
  const Bounded w2 = squared_norm(w), nc2 = squared_norm(nc);
  const Bounded r = circle.radius;
  return {s, w, w2, nc2, squared_norm(np), s * s * nc2 - r * r * w2};
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
  const double np2 = t.np2[0];
  const GuardMagnitudes g{lengths_one_norm(circle, plane), t.nc_1, t.np_1, t.nc2[0], np2};
  if (!inputs_ready(g, circle.radius)) return {};
  return {true, plane_quantities_from_terms(t, np2)};
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
  Bounded s, discriminant;
  if (a_priori_bounds_apply) {  // only the two values the side needs, not all the quantities
    const APrioriTerms t = a_priori_terms(circle, plane);
    s = a_priori_from_twin(t.s);
    discriminant = a_priori_from_twin(t.discriminant);
    if (distance_error != 0.0) {
      const double np2 = plane.normal.squaredNorm();
      widen_side_quantities(s, discriminant, a_priori_with_underflow(np2, np2),
                            a_priori_from_twin(t.nc2), distance_error);
    }
  } else {
    PlaneQuantities q = plane_quantities_running_error(circle, plane);
    widen_for_point_error(q, distance_error);
    s = q.s;
    discriminant = q.discriminant;
  }
  if (discriminant.sign() <= 0) return RimSide::undecided;
  const int side = s.sign();
  return side < 0 ? RimSide::strictly_negative
                  : side > 0 ? RimSide::strictly_positive : RimSide::undecided;
}

}  // namespace clearjoint::geometry::detail
