// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "arithmetic/angles.hpp"
#include "arithmetic/filtered_predicate.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "exact/rim_cylinder_exact.hpp"
#include "filters/certified_rim_roots.hpp"
#include "model/primitives_detail.hpp"
#include "predicates/rim_distance_polynomial.hpp"
#include "queries/rounded_point_queries.hpp"

namespace clearjoint::geometry {
namespace {

using detail::RimRoots;

/// Rounding in point_at: the rounded frame (a few ulps per unit vector), cos and sin (1 ulp
/// each, glibc) and two multiply-adds; 32 unit roundoffs of |center| + 2 radius cover them.
constexpr double kPointRoundingUlps = 32 * detail::kUnitRoundoff;
/// The same with tier 1's cos and sin (RootEnclosure::cos, sin), each off by at most
/// kAngleAdditionTrigError (~25 u) instead of 1 ulp: 2 * 25u r more on the radius term, which
/// 64 unit roundoffs of |center| + 2 radius cover with room to spare.
constexpr double kPointFromRootTrigUlps = 64 * detail::kUnitRoundoff;
static_assert(2 * detail::kAngleAdditionTrigError < 64 * detail::kUnitRoundoff);

/// The answer without crossings. Its own function so that the reach test's answers need no
/// RimRoots (four default-constructed enclosures, ~30 instructions, on the path most free-flight
/// rims take).
void fill_without_roots(detail::RimSideWithoutRoots side, CircleCylinderIntersection& out) {
  using detail::RimSideWithoutRoots;
  out.topology = side == RimSideWithoutRoots::beyond   ? CircleCylinderTopology::outside
                 : side == RimSideWithoutRoots::inside ? CircleCylinderTopology::inside
                                                       : CircleCylinderTopology::on_surface;
  if (out.topology == CircleCylinderTopology::outside) {
    out.penetration_arcs[0] = {0.0, detail::kTwoPi, true};
    out.arc_count = 1;
  }
}

/// `centre_error`: how far the exact rim centre may lie from circle.center (rounded_point.hpp);
/// a crossing of the exact rim is that much farther from the computed point.
/// `frame`: frame_of(circle) if the caller has it already.
void fill(const Circle3& circle, const RimRoots& roots, bool bounded, double centre_error,
          CircleCylinderIntersection& out, const std::optional<CircleFrame>& frame = std::nullopt) {
  if (roots.count == 0) {
    fill_without_roots(roots.side_without_roots, out);
    return;
  }
  out.topology = CircleCylinderTopology::crossing;
  const CircleFrame rim_frame = frame ? *frame : frame_of(circle);
  const double size = circle.center.norm() + 2 * circle.radius;
  out.crossing_count = roots.count;
  for (int i = 0; i < roots.count; ++i) {
    const detail::RootEnclosure& root = roots.roots[i];
    RimCrossing& crossing = out.crossings[i];
    crossing.angle = root.angle;
    double rounding = kPointRoundingUlps * size;
    if (root.has_trig()) {
      crossing.point = circle.center + circle.radius * (root.cos * rim_frame.u + root.sin * rim_frame.v);
      rounding = kPointFromRootTrigUlps * size;
    } else {
      crossing.point = point_at(circle, rim_frame, root.angle);
    }
    crossing.multiplicity = root.multiplicity;
    // A chord is never longer than its arc: |x(t*) - x(t)| <= r |t* - t|.
    // Capped at pi: every rim angle is within pi of the reported one.
    // (A comparison, not std::fmin: that is an out-of-line libm call. A NaN radius gives pi
    // either way.)
    crossing.angle_error =
        bounded ? (root.radius < std::numbers::pi ? root.radius : std::numbers::pi) : kNoErrorBound;
    crossing.point_error =
        bounded ? (circle.radius * crossing.angle_error + rounding + centre_error) * (1 + 4 * detail::kUnitRoundoff)
                : kNoErrorBound;
  }
  // The rim is beyond the wall after every root whose sign_after is +1, up to the next root.
  for (int i = 0; i < roots.count && out.arc_count < 2; ++i) {
    if (roots.roots[i].sign_after <= 0) continue;
    const double begin = roots.roots[i].angle;
    const double end = roots.roots[(i + 1) % roots.count].angle;
    // A single root with the rim beyond the wall on both sides: the rim touches the wall from
    // outside; the whole rim but that point penetrates.
    out.penetration_arcs[out.arc_count++] = {begin, end, roots.count == 1};
  }
}

/// The exact tier's roots of one query, computed at the first request: tier 2's tangency check
/// (certified_rim_roots.hpp) or the fallback after the filter, whichever asks first; the other
/// gets the same roots.
class ExactRimRoots final : public detail::ExactRootsOnRequest {
 public:
  ExactRimRoots(const Circle3& circle, const Cylinder3& cylinder, const detail::RoundedPoint* centre,
                int scale_exponent)
      : circle_(circle), cylinder_(cylinder), centre_(centre), scale_exponent_(scale_exponent) {}
  const RimRoots& result() {
    if (!roots_) roots_ = detail::exact_rim_roots(circle_, cylinder_, centre_, scale_exponent_);
    return *roots_;
  }
  const RimRoots* roots() override { return result().proved ? &*roots_ : nullptr; }

 private:
  const Circle3& circle_;
  const Cylinder3& cylinder_;
  const detail::RoundedPoint* centre_;
  int scale_exponent_;
  std::optional<RimRoots> roots_;
};

/// The query on rescaled inputs; `centre` (unscaled recipe) and `scale_exponent` only for the
/// exact tier, `centre_error` already scaled.
CircleCylinderIntersection intersect_scaled(const Circle3& circle, const Cylinder3& cylinder,
                                            const IntersectionOptions& options, double centre_error,
                                            const detail::RoundedPoint* centre, int scale_exponent);

}  // namespace

int CircleCylinderIntersection::root_count() const noexcept {
  int total = 0;
  for (int i = 0; i < crossing_count; ++i) total += crossings[i].multiplicity;
  return total;
}

CircleCylinderIntersection intersect_circle_cylinder(const Circle3& circle,
                                                     const Cylinder3& cylinder,
                                                     const IntersectionOptions& options) {
  return detail::intersect_circle_cylinder(circle, cylinder, options, nullptr);
}

CircleCylinderIntersection detail::intersect_circle_cylinder(const Circle3& circle_in,
                                                             const Cylinder3& cylinder_in,
                                                             const IntersectionOptions& options,
                                                             const RoundedPoint* centre) {
  // The inline test first: validate() formats its message and is out of line.
  if (!detail::passes_validation(circle_in)) validate(circle_in, "circle");
  if (!detail::passes_validation(cylinder_in)) validate(cylinder_in, "cylinder");
  // Exact power-of-two rescaling (scale_normalisation.hpp), first of the directions to [1, 2).
  return intersect_valid_circle_cylinder(
      {circle_in.center, detail::direction_scaled(circle_in.normal), circle_in.radius},
      {cylinder_in.axis_point, detail::direction_scaled(cylinder_in.axis), cylinder_in.radius}, options, centre);
}

CircleCylinderIntersection detail::intersect_valid_circle_cylinder(const Circle3& circle_in,
                                                                   const Cylinder3& cylinder_in,
                                                                   const IntersectionOptions& options,
                                                                   const RoundedPoint* centre) {
  // Extreme lengths to near 1 (scale_normalisation.hpp); crossing points and their errors are
  // scaled back at the end.
  Circle3 circle = circle_in;
  Cylinder3 cylinder = cylinder_in;
  int e = detail::length_exponent(std::max({circle.center.cwiseAbs().maxCoeff(),
                                            cylinder.axis_point.cwiseAbs().maxCoeff(),
                                            circle.radius, cylinder.radius}));
  if (e != 0 && !(detail::scales_exactly(circle.center, e) && detail::scales_exactly(circle.radius, e) &&
                  detail::scales_exactly(cylinder.axis_point, e) && detail::scales_exactly(cylinder.radius, e))) {
    e = 0;
  }
  if (e != 0) {
    circle.center = detail::scaled(circle.center, e);
    circle.radius = std::ldexp(circle.radius, -e);
    cylinder.axis_point = detail::scaled(cylinder.axis_point, e);
    cylinder.radius = std::ldexp(cylinder.radius, -e);
  }
  const double centre_error = centre == nullptr ? 0.0 : detail::scaled_error(centre->error, e);
  CircleCylinderIntersection out = intersect_scaled(circle, cylinder, options, centre_error, centre, e);
  for (int i = 0; e != 0 && i < out.crossing_count; ++i) {
    out.crossings[i].point = detail::scaled(out.crossings[i].point, -e);
    out.crossings[i].point_error = std::ldexp(out.crossings[i].point_error, e);
  }
  // Inputs whose magnitudes lie hundreds of orders apart can under- or overflow the double
  // steps after the root count: then the points are not answers.
  // A certified answer must also carry finite bounds (fill's can overflow where points do not).
  const bool bounded = out.certificate.level != Certainty::uncertain;
  for (int i = 0; i < out.crossing_count; ++i) {
    const RimCrossing& crossing = out.crossings[i];
    const Vector3& point = crossing.point;
    if (!(bounded ? detail::every_value_finite(crossing.angle, point.x(), point.y(), point.z(), crossing.angle_error,
                               crossing.point_error)
                  : detail::every_value_finite(crossing.angle, point.x(), point.y(), point.z()))) {
      out.certificate = {Certainty::uncertain, CertificateReason::cylinder_points_not_representable};
      for (int k = 0; k < out.crossing_count; ++k) {
        out.crossings[k].angle_error = out.crossings[k].point_error = kNoErrorBound;
      }
      break;
    }
  }
  return out;
}

namespace {

CircleCylinderIntersection intersect_scaled(const Circle3& circle, const Cylinder3& cylinder,
                                            const IntersectionOptions& options, double centre_error,
                                            const detail::RoundedPoint* centre, int scale_exponent) {
  CircleCylinderIntersection out;

  // The reach test (rim_reach_terms.hpp) before any tier of the crossings: most free-flight rims
  // stop here. It needs only part of the magnitude guard; the rest only if it is undecided. The
  // centre's offset from the axis serves the guard, the reach test, the polynomial and the
  // widening.
  const detail::AxisOffset offset = detail::axis_offset(circle, cylinder);
  const bool reach_a_priori = detail::reach_a_priori_bounds_apply(offset, circle, cylinder);
  const detail::RimReach reach = detail::rim_reach(circle, cylinder, offset, reach_a_priori, centre_error);
  if (reach != detail::RimReach::undecided) {
    fill_without_roots(reach == detail::RimReach::strictly_outside ? detail::RimSideWithoutRoots::beyond
                                                                     : detail::RimSideWithoutRoots::inside,
                       out);
    out.certificate = options.certify ? Certificate{Certainty::certified, CertificateReason::none}
                                      : Certificate{Certainty::uncertain, CertificateReason::certificate_switched_off};
    return out;
  }

  // The crossings, in filtered_predicate.hpp's order: the certified roots of the rim polynomial
  // (tiers 1 and 2, docs/circle-cylinder.md), else the exact tier, else the approximate roots.
  const bool a_priori = detail::cylinder_a_priori_bounds_apply(circle, cylinder, reach_a_priori);
  std::optional<CircleFrame> frame;
  detail::RimDistancePolynomial g = detail::rim_distance_polynomial(circle, cylinder, offset, a_priori, frame);
  using Verdict = detail::TierVerdict<CertificateReason>;
  const bool exact_tier_on = options.certify && options.exact_fallback;
  ExactRimRoots exact_roots(circle, cylinder, centre, scale_exponent);
  detail::filtered_exact_or_fallback<CertificateReason>(
      exact_tier_on,
      [&] {
        if (!options.certify) return Verdict::open(CertificateReason::certificate_switched_off);
        detail::widen_for_centre_error(g, circle, offset, centre_error);
        const RimRoots roots = detail::certified_rim_roots(g, exact_tier_on ? &exact_roots : nullptr);
        if (!roots.proved) return Verdict::open(roots.failure);
        fill(circle, roots, true, centre_error, out, frame);
        out.certificate = {Certainty::certified, CertificateReason::none};
        return Verdict::done();
      },
      [&](CertificateReason filter_failure) {
        const RimRoots& exact = exact_roots.result();
        if (!exact.proved) return Verdict::open(exact.failure);
        fill(circle, exact, true, centre_error, out);
        out.certificate = {Certainty::exact, filter_failure};
        return Verdict::done();
      },
      [&](CertificateReason why) {  // the best guess, marked so
        fill(circle, detail::approximate_rim_roots(g), false, centre_error, out, frame);
        out.certificate = {Certainty::uncertain, why};
      });
  return out;
}

}  // namespace

}  // namespace clearjoint::geometry
