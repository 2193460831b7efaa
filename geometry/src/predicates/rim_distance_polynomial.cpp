// SPDX-License-Identifier: BSD-3-Clause
#include "predicates/rim_distance_polynomial.hpp"

#include <cmath>
#include <limits>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/filtered_predicate.hpp"
#include "arithmetic/lane_vector3.hpp"
#include "arithmetic/twinned.hpp"
#include "model/primitives_detail.hpp"

namespace clearjoint::geometry::detail {
namespace {

BoundedVector3 exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }

// Chains counted on the code below (a_priori_bounds.hpp): k0 21, k1 20, k2 26, k3 39 (squares
// of the normalised axis components), k4 32, the reach test 8; all under kGamma64's 64. The
// lanes' products by +-1 are exact and add no rounding.

}  // namespace

namespace {

/// |a| and |b| each zero or in [kSmallestGuardedInput, kLargestGuardedInput] (a_priori_bounds.hpp),
/// two values at once (pair_lanes.hpp) and without a branch:
/// |x| <= 2^100 and (|x| >= 2^-100 or x == 0) as double comparisons, which NaN and infinities
/// fail. Lanes are -1 where in range, 0 where not. The guards test 8 and 9 values; the scalar
/// form (an unsigned range test on the bits per value) took ~90 instructions per guard, twice
/// this. A short-circuit chain was worse: a conditional jump every few bytes, whose cost swung
/// by a factor 2 with code placement (measured on the well-inside rims).
PairMask in_range_pair(double a, double b) {
  const Pair kLow = {kSmallestGuardedInput, kSmallestGuardedInput};
  const Pair kHigh = {kLargestGuardedInput, kLargestGuardedInput};
  const Pair zero = {0.0, 0.0};
  const Pair x = magnitude(Pair{a, b});
  return (x <= kHigh) & ((x >= kLow) | (x == zero));
}

}  // namespace

AxisOffset axis_offset(const Circle3& circle, const Cylinder3& cylinder) {
  // A and |A|^2 of rim_reach_terms.hpp on Twinned: each value and its twin in one register, one
  // packed operation for both, a fifth fewer instructions than the two scalar chains of
  // ValueAndTwin<double> (and of Eigen's expressions), on the path every rim takes.
  const Vector3 q = circle.center - cylinder.axis_point;
  const Vector3& d = cylinder.axis;
  const OffsetFromAxis<Twinned> t =
      offset_from_axis(Vector3Of<Twinned>{Twinned::of(q.x()), Twinned::of(q.y()), Twinned::of(q.z())},
                       Vector3Of<Twinned>{Twinned::of(d.x()), Twinned::of(d.y()), Twinned::of(d.z())});
  return {q,
          {t.perp.x.value(), t.perp.y.value(), t.perp.z.value()},
          {t.perp.x.twin(), t.perp.y.twin(), t.perp.z.twin()},
          t.perp2.value(),
          t.perp2.twin(),
          d.squaredNorm()};
}

bool reach_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder) {
  return reach_a_priori_bounds_apply(axis_offset(circle, cylinder), circle, cylinder);
}

bool reach_a_priori_bounds_apply(const AxisOffset& offset, const Circle3& circle,
                                 const Cylinder3& cylinder) {
  const Vector3& q = offset.q;  // rounded, but that is fine for a range test
  const Vector3& d = cylinder.axis;
  return all_lanes(in_range_pair(q.x(), q.y()) & in_range_pair(q.z(), d.x()) &
                   in_range_pair(d.y(), d.z()) & in_range_pair(circle.radius, cylinder.radius));
}

bool cylinder_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder,
                                    bool reach_guard) {
  const Vector3 &c = circle.center, &p = cylinder.axis_point, &n = circle.normal;
  return reach_guard & all_lanes(in_range_pair(c.x(), c.y()) & in_range_pair(c.z(), p.x()) &
                                 in_range_pair(p.y(), p.z()) & in_range_pair(n.x(), n.y()) &
                                 in_range_pair(n.z(), n.z()));
}

bool cylinder_a_priori_bounds_apply(const Circle3& circle, const Cylinder3& cylinder) {
  return cylinder_a_priori_bounds_apply(circle, cylinder, reach_a_priori_bounds_apply(circle, cylinder));
}

namespace {

RimDistancePolynomial rim_distance_polynomial_a_priori(const Circle3& circle,
                                                       const Cylinder3& cylinder,
                                                       const AxisOffset& offset,
                                                       std::optional<CircleFrame>& frame) {
  // The same formulas as the running-error version, in plain double, each beside its
  // absolute-value twin (suffix _abs) which bounds its error. q = c - p is rounded,
  // q(1 + delta): |q| is its own bound (offset.perp_abs is abs_cross(|q|, |d|)).
  const Vector3& d = cylinder.axis;
  const Vector3& n = circle.normal;
  const Vector3 u = n.cross(Vector3::Unit(frame_axis_index(n)));  // exact
  const Vector3 v = n.cross(u);
  const Vector3 da = d.cwiseAbs(), na = n.cwiseAbs(), ua = u.cwiseAbs();
  const Vector3 v_abs = abs_cross(na, ua);

  const double inverse_axis_norm2 = 1.0 / offset.axis_norm2;
  const double r = circle.radius, R = cylinder.radius;
  const double r2 = r * r;

  // The u'- and v'-terms side by side, lane 0 of u', lane 1 of v'. Each lane rounds exactly as
  // the scalar Eigen expression of its formula would (candidate_prefilter_lanes.hpp; test:
  // APrioriCoefficientsInLanesAreTheScalarFormulasBitForBit): about 100 instructions fewer than
  // one double at a time (callgrind, 498 -> 394 per detection).
  const LaneVector3 uv = lanes(std::array<Vector3, 2>{u, v});
  const LaneVector3 uv_abs = lanes(std::array<Vector3, 2>{ua, v_abs});
  const Lanes inverse_norms = 1.0 / square_root(squared_norm(uv));  // 1 / |u'|, 1 / |v'|
  // frame_of(circle) with the same operations as primitives.cpp's unit(), whose plain branch
  // always applies here: the guard keeps |u'|^2 and |n|^2 within [2^-200, 2^202]. Formed as soon
  // as 1 / |u'| is known: at the end, with more values live, it cost 14 instructions more.
  const Vector3 u_hat = u * inverse_norms[0];
  frame = CircleFrame{u_hat, (n * (1.0 / std::sqrt(n.squaredNorm()))).cross(u_hat)};
  // First harmonic (q x d).(u x d) / |u'| and (q x d).(v x d) / |v'|, and u_hat . d, v_hat . d.
  const Lanes first = dot(offset.perp, cross(uv, d)) * inverse_norms;
  const Lanes first_abs = dot(offset.perp_abs, abs_cross(uv_abs, da)) * inverse_norms;
  const Lanes along = dot(d, uv) * inverse_norms, along_abs = dot(da, uv_abs) * inverse_norms;
  const double inverse_n_norm2 = 1.0 / n.squaredNorm();
  // From here on each pair is a value (lane 0) beside its absolute-value twin (lane 1): a
  // subtraction in the value is an addition in the twin, x - (-y) = x + y in IEEE arithmetic, so
  // lane 1's subtrahend is negated (times -1, exact) and the pair subtracted.
  const Lanes kTwinSubtrahend = {1.0, -1.0};
  const Lanes tilt_term =
      squared_norm(lanes(std::array<Vector3, 2>{n.cross(d), abs_cross(na, da)})) * inverse_n_norm2;
  const Lanes radii_term = Lanes{r - R, std::fabs(r - R)} * (r + R);
  // Lane i of a u'/v' pair beside lane i of its twin pair.
  auto with_twin = [](const Lanes& values, const Lanes& twins, int i) { return Lanes{values[i], twins[i]}; };
  const Lanes first_cos = with_twin(first, first_abs, 0), first_sin = with_twin(first, first_abs, 1);
  const Lanes along_u = with_twin(along, along_abs, 0), along_v = with_twin(along, along_abs, 1);

  const Lanes coefficients[5] = {
      (Lanes{offset.perp2, offset.perp2_abs} - 0.5 * r2 * tilt_term * kTwinSubtrahend) * inverse_axis_norm2 +
          radii_term,
      2.0 * r * first_cos * inverse_axis_norm2,
      2.0 * r * first_sin * inverse_axis_norm2,
      0.5 * r2 * (along_v * along_v - along_u * along_u * kTwinSubtrahend) * inverse_axis_norm2,
      // -(r2 along_u along_v) in lane 0, negated before the last product; its twin not negated.
      r2 * along_u * along_v * Lanes{-1.0, 1.0} * inverse_axis_norm2};
  // The bound kGamma64 * twin * kMagnitudeInflation in lane 1; lane 0's value times 1 (exact).
  const Lanes kBound = {1.0, kGamma64}, kInflation = {1.0, kMagnitudeInflation};
  RimDistancePolynomial g;
  for (int i = 0; i < 5; ++i) {
    const Lanes k = coefficients[i] * kBound * kInflation;
    g.k[i] = Bounded(k[0], k[1]);
  }
  return g;
}

}  // namespace

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder) {
  return rim_distance_polynomial(circle, cylinder, cylinder_a_priori_bounds_apply(circle, cylinder));
}

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              bool a_priori_bounds_apply) {
  std::optional<CircleFrame> frame;
  return rim_distance_polynomial(circle, cylinder, a_priori_bounds_apply, frame);
}

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              bool a_priori_bounds_apply,
                                              std::optional<CircleFrame>& frame) {
  return rim_distance_polynomial(circle, cylinder, axis_offset(circle, cylinder), a_priori_bounds_apply, frame);
}

RimDistancePolynomial rim_distance_polynomial(const Circle3& circle, const Cylinder3& cylinder,
                                              const AxisOffset& offset, bool a_priori_bounds_apply,
                                              std::optional<CircleFrame>& frame) {
  return floating_point_filter(
      a_priori_bounds_apply, [&] { return rim_distance_polynomial_a_priori(circle, cylinder, offset, frame); },
      [&] {
        frame.reset();
        return rim_distance_polynomial_running_error(circle, cylinder);
      });
}

RimDistancePolynomial rim_distance_polynomial_running_error(const Circle3& circle,
                                                            const Cylinder3& cylinder) {
  // Notation of docs/circle-cylinder.md: q = c - p (rim centre from axis point), d the axis,
  // n the rim normal, u' = n x e_k (exact), v' = n x u'; hats are unit vectors; D = |d|^2.
  const BoundedVector3 q = exact(circle.center) - exact(cylinder.axis_point);
  const BoundedVector3 d = exact(cylinder.axis);
  const BoundedVector3 n = exact(circle.normal);
  const Vector3 u_double = circle.normal.cross(Vector3::Unit(frame_axis_index(circle.normal)));
  const BoundedVector3 u = exact(u_double);  // exact: components are +-n_j or 0
  const BoundedVector3 v = cross(n, u);

  const Bounded axis_norm2 = squared_norm(d);
  // Reciprocals once: a bounded division costs several multiplications.
  const Bounded inverse_axis_norm2 = Bounded(1.0) / axis_norm2;
  const Bounded inverse_u_norm = Bounded(1.0) / sqrt(squared_norm(u));
  const Bounded inverse_v_norm = Bounded(1.0) / sqrt(squared_norm(v));
  const Bounded r = circle.radius;
  const Bounded r2 = r * r;

  // The offset projected off the axis before squaring: A = q x d, |A|^2 / D = dist(c, axis)^2.
  const BoundedVector3 offset_perp = cross(q, d);
  // (q x d).(u x d) = (q.u) D - (q.d)(u.d) without its cancellation.
  const Bounded first_cos = dot(offset_perp, cross(u, d)) * inverse_u_norm;
  const Bounded first_sin = dot(offset_perp, cross(v, d)) * inverse_v_norm;
  const Bounded axis_along_u = dot(u, d) * inverse_u_norm;  // u_hat . d
  const Bounded axis_along_v = dot(v, d) * inverse_v_norm;  // v_hat . d
  // |n_hat x d|^2 = D sin^2(tilt), computed as a cross product: no cancellation at small tilt.
  const Bounded tilt_term = squared_norm(cross(n, d)) / squared_norm(n);
  // Radii difference as (r - R)(r + R): r - R is exact when the radii are within a factor 2.
  const Bounded radii_term = (r - Bounded(cylinder.radius)) * (r + Bounded(cylinder.radius));

  RimDistancePolynomial g;
  g.k[0] = (squared_norm(offset_perp) - Bounded(0.5) * r2 * tilt_term) * inverse_axis_norm2 +
           radii_term;
  g.k[1] = Bounded(2.0) * r * first_cos * inverse_axis_norm2;
  g.k[2] = Bounded(2.0) * r * first_sin * inverse_axis_norm2;
  g.k[3] = Bounded(0.5) * r2 * (axis_along_v * axis_along_v - axis_along_u * axis_along_u) *
           inverse_axis_norm2;
  g.k[4] = -(r2 * axis_along_u * axis_along_v) * inverse_axis_norm2;
  return g;
}

namespace {

/// cos, sin, cos 2 theta and sin 2 theta, enclosed: what g and g' at theta are formed from.
struct BoundedHarmonics {
  BoundedSinCos first;
  Bounded cos2, sin2;
};

BoundedHarmonics harmonics_of(double theta) {
  const BoundedSinCos t = sincos_of(theta);
  return {t, (t.cos - t.sin) * (t.cos + t.sin), Bounded(2.0) * t.sin * t.cos};
}

Bounded value_of(const std::array<Bounded, 5>& k, const BoundedHarmonics& h) {
  return k[0] + k[1] * h.first.cos + k[2] * h.first.sin + k[3] * h.cos2 + k[4] * h.sin2;
}

Bounded derivative_of(const std::array<Bounded, 5>& k, const BoundedHarmonics& h) {
  return k[2] * h.first.cos - k[1] * h.first.sin + Bounded(2.0) * (k[4] * h.cos2 - k[3] * h.sin2);
}

}  // namespace

Bounded RimDistancePolynomial::value(double theta) const { return value_of(k, harmonics_of(theta)); }

Bounded RimDistancePolynomial::derivative(double theta) const { return derivative_of(k, harmonics_of(theta)); }

BoundedValueAndSlope RimDistancePolynomial::value_and_derivative(double theta) const {
  const BoundedHarmonics h = harmonics_of(theta);
  return {value_of(k, h), derivative_of(k, h)};
}

double RimDistancePolynomial::approximate_newton_step(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta);
  const double cos2 = (c - s) * (c + s), sin2 = 2 * s * c;
  const double value = k[0].value + k[1].value * c + k[2].value * s + k[3].value * cos2 + k[4].value * sin2;
  const double slope = k[2].value * c - k[1].value * s + 2 * (k[4].value * cos2 - k[3].value * sin2);
  return value / slope;
}

double RimDistancePolynomial::second_derivative_bound() const {
  // |g''| <= |first harmonic| + 4 |second harmonic|, each harmonic's amplitude bounded by the
  // hypot of its (enclosed) coefficients.
  auto high = [](const Bounded& x) { return std::fabs(x.value) + x.error; };
  const double bound = std::hypot(high(k[1]), high(k[2])) + 4 * std::hypot(high(k[3]), high(k[4]));
  return bound * (1 + 8 * kUnitRoundoff) + kUnderflowError;
}

RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder) {
  return rim_reach(circle, cylinder, cylinder_a_priori_bounds_apply(circle, cylinder));
}

namespace {

// The reach test of rim_reach_terms.hpp in its two floating-point forms.

RimReach rim_reach_running_error(const Circle3& circle, const Cylinder3& cylinder, double centre_error) {
  const Bounded R = cylinder.radius, r = circle.radius;
  const BoundedVector3 d = exact(cylinder.axis);
  return rim_reach_of(
      offset_from_axis(exact(circle.center) - exact(cylinder.axis_point), d).perp2, squared_norm(d), R - r, R + r,
      Bounded(centre_error), [](const Bounded& radii_gap, const Bounded& e) { return (radii_gap - e).sign() > 0; },
      [](const Bounded& x) { return x.sign() > 0; });
}

RimReach rim_reach_a_priori(const Circle3& circle, const Cylinder3& cylinder, const AxisOffset& offset,
                            double centre_error) {
  // Guard (reach_a_priori_bounds_apply): q, d, r and R in range, so no product of up to four
  // of them under- or overflows.
  // |q x d|^2 (rounding chain 6) against gap^2 D (chain 7: R - r, then - e, then squares);
  // the difference has chain 8: error <= gamma_64 (|q x d|_abs^2 + gap_abs^2 D), see
  // kGamma64, with gap_abs = (R - r) + e the twin of (R - r) - e (each subtraction of the
  // gap is rounded relative to its result, which is at most gap_abs). R - r is its own twin
  // where the gap is used: there R - r > e >= 0.
  using Twin = ValueAndTwin<double>;
  const double R = cylinder.radius, r = circle.radius;
  return rim_reach_of(
      Twin{offset.perp2, offset.perp2_abs}, Twin::nonnegative(offset.axis_norm2), Twin::nonnegative(R - r),
      Twin::nonnegative(R + r), Twin::nonnegative(centre_error),
      // The rounded R - r exceeds e, and then the exact R - r does too: rounding is monotone
      // and e is a double.
      [](const Twin& radii_gap, const Twin& e) { return radii_gap.value > e.value; },
      [](const Twin& x) { return a_priori_proves_positive(x); });
}

}  // namespace

RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder, bool a_priori_bounds_apply,
                   double centre_error) {
  return floating_point_filter(
      a_priori_bounds_apply, [&] { return rim_reach_a_priori(circle, cylinder, axis_offset(circle, cylinder), centre_error); },
      [&] { return rim_reach_running_error(circle, cylinder, centre_error); });
}

RimReach rim_reach(const Circle3& circle, const Cylinder3& cylinder, const AxisOffset& offset,
                   bool a_priori_bounds_apply, double centre_error) {
  return floating_point_filter(
      a_priori_bounds_apply, [&] { return rim_reach_a_priori(circle, cylinder, offset, centre_error); },
      [&] { return rim_reach_running_error(circle, cylinder, centre_error); });
}

void widen_for_centre_error(RimDistancePolynomial& g, const Circle3& circle,
                            const Cylinder3& cylinder, double centre_error) {
  if (centre_error == 0.0) return;
  widen_for_centre_error(g, circle, axis_offset(circle, cylinder), centre_error);
}

void widen_for_centre_error(RimDistancePolynomial& g, const Circle3& circle, const AxisOffset& offset,
                            double centre_error) {
  if (centre_error == 0.0) return;
  // With P the projection off the axis, k0 = |P q|^2 + (terms free of the centre) and
  // (k1, k2) = 2 r (P q . P u_hat, P q . P v_hat) (rim_distance_polynomial_running_error: (q x d)
  // . (u x d) / |d|^2 = P q . P u). A centre moved by delta, |delta| <= e, changes k0 by
  // |P(q + delta)|^2 - |P q|^2 <= (2 |P q| + e) e and k1, k2 by at most 2 r e (|P u_hat| <= 1).
  // |P q| = |q x d| / |d| is bounded above by the absolute-value twin of q x d (componentwise
  // a bound of the exact cross product of the exact q = c - p, rounded once), its roundings
  // covered by 2^-40 (they are a few tens of u), and an underflow allowance.
  double distance = std::sqrt(offset.perp2_abs / offset.axis_norm2) * (1 + 0x1p-40) +
                    0x1p-1000;
  if (!std::isfinite(distance)) distance = std::numeric_limits<double>::infinity();
  constexpr double kRounding = 1 + 16 * kUnitRoundoff;  // the few products below, rounded up
  g.k[0].error = (g.k[0].error + (2 * distance + centre_error) * centre_error * kRounding +
                  kUnderflowError) * kRounding;
  const double first = 2 * circle.radius * centre_error * kRounding + kUnderflowError;
  g.k[1].error = (g.k[1].error + first) * kRounding;
  g.k[2].error = (g.k[2].error + first) * kRounding;
}

}  // namespace clearjoint::geometry::detail
