// SPDX-License-Identifier: BSD-3-Clause
// Circle against plane, paper eqs. (11)-(15); derivation in docs/circle-plane.md.
//
// With s = n_p . (c - p) and P n_p the part of the plane normal in the circle's plane, the
// signed distance of rim point x(theta) from the plane is, times |n_p|,
//   f(theta) = s + r |P n_p| cos(theta - theta_m),   |P n_p|^2 = |n_p x n_c|^2 / |n_c|^2,
// theta_m the angle of P n_p in the rim frame. The topology is the sign of
// s^2 |n_c|^2 - r^2 |n_p x n_c|^2 (plane_terms.hpp), decided by a filter then exactly
// (filtered_predicate.hpp).

#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "arithmetic/angles.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/filtered_predicate.hpp"
#include "arithmetic/pair_lanes.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "exact/circle_plane_exact.hpp"
#include "model/primitives_detail.hpp"
#include "predicates/rim_plane_quantities.hpp"
#include "queries/rounded_point_queries.hpp"

namespace clearjoint::geometry {
namespace {

using detail::Bounded;
using detail::BoundedVector3;

/// Reason given when the topology is decided but a crossing or the depth is not finite.
constexpr CertificateReason kNotRepresentable = CertificateReason::plane_results_not_representable;

/// See intersect_circle_cylinder.cpp: rounding of point_at.
constexpr double kPointRoundingUlps = 32 * detail::kUnitRoundoff;
/// acos and asin in glibc: at most 1-2 ulps; we allow 4 ulps of pi.
constexpr double kLibmAngleError = 4 * 2 * detail::kUnitRoundoff * std::numbers::pi;

/// sqrt(x^2 + y^2) within 2 ulps; std::hypot (correctly rounded, but several times the cost)
/// only where the squares could under- or overflow.
double length_2d(double x, double y) {
  constexpr double kSafeLow = 0x1p-500, kSafeHigh = 0x1p500;
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double m = ax > ay ? ax : ay;  // not std::fmax: a libm call (error_bounded.hpp)
  if (m > kSafeLow && m < kSafeHigh) return std::sqrt(x * x + y * y);
  return std::hypot(x, y);
}

/// An angle enclosure with the cosine and sine of its centre value.
struct AngleWithTrig {
  Bounded angle;
  double cos, sin;
};

/// The angle of an enclosed vector (x, y) in (-pi, pi], with its cosine and sine.
///
/// Its error has three parts. Moving the vector by delta (at most the sum of the component
/// errors) turns it by at most asin(delta / L) <= (pi / 2) delta / L when delta < L, L its
/// length (computed within 2 ulps: (1 - 4u) makes it a lower bound). The angle itself is
/// acos(x / L) or asin(y / L), whichever argument is at most 1/sqrt(2) in magnitude, where either
/// has slope below 1.5: the quotient's relative error (2 ulps of L, one rounding) is under 8u of
/// an argument at most 1, so 12u of angle, and kLibmAngleError covers the call; pi - a adds the
/// rounding of pi and of the difference. Not std::atan2: glibc's costs three times acos or asin,
/// and the cosine and sine are wanted for the crossing points anyway.
AngleWithTrig angle_of(const Bounded& x, const Bounded& y) {
  constexpr double kQuotientAngleError = 12 * detail::kUnitRoundoff;
  constexpr double kReflectionError = 4 * detail::kUnitRoundoff * std::numbers::pi;
  const double computed_length = length_2d(x.value, y.value);
  if (!(computed_length > 0.0)) return {{0.0, std::numbers::pi}, 1.0, 0.0};  // no direction known
  const double c = x.value / computed_length, s = y.value / computed_length;
  double angle;
  if (std::fabs(c) <= std::fabs(s)) {
    angle = std::copysign(std::acos(c), s);
  } else {
    const double a = std::asin(s);  // in [-pi/4, pi/4]
    angle = c > 0 ? a : (s >= 0 ? std::numbers::pi - a : -std::numbers::pi - a);
  }
  const double length = computed_length * (1 - 4 * detail::kUnitRoundoff);
  const double delta = (x.error + y.error) * detail::kErrorInflation;  // >= hypot of the errors
  if (!(delta < 0.5 * length)) return {{angle, std::numbers::pi}, c, s};
  const double turn = 0.5 * std::numbers::pi * delta / (length - delta) * detail::kErrorInflation;
  return {{angle, (turn + kQuotientAngleError + kLibmAngleError + kReflectionError) * detail::kErrorInflation},
          c, s};
}

/// acos of an enclosed cosine. Away from +-1 one acos and the derivative bound
/// |acos'| = 1 / sqrt(1 - c^2) suffice, and the centre's cosine is c itself; near +-1 the
/// monotone acos at both enclosure ends, whose midpoint needs its own cosine and sine (the
/// crossing points must sit at the reported angles, not at acos(c)). "Near" is within 2^-20 of
/// +-1, where the slope bound exceeds ~700: below that the two give enclosures of the same width
/// (both are the enclosure's spread times acos's slope there), and the first costs one libm call
/// instead of four (the four calls are a fifth of a random circle-plane query, so the switch sits
/// as close to +-1 as the widths allow).
constexpr double kNearUnitCosine = 1 - 0x1p-20;

AngleWithTrig acos_of(const Bounded& c) {
  const double spread = c.error * detail::kErrorInflation;
  const double far = std::fabs(c.value) + spread;
  if (far < kNearUnitCosine) {
    // sqrt((1 - x)(1 + x)) of the far end (lane 0, for the slope bound) and of the centre (lane 1,
    // its sine) side by side (pair_lanes.hpp): one packed square root, each lane correctly
    // rounded as std::sqrt is (~4 instructions fewer per crossing rim than two, callgrind).
    const detail::Pair x = {far, c.value};
    const detail::Pair root = detail::square_root((1.0 - x) * (1.0 + x));
    const double slope_bound = 1.0 / root[0] * (1 + 0x1p-40);
    return {{std::acos(c.value), spread * slope_bound + kLibmAngleError}, c.value, root[1]};
  }
  const double low = std::acos(std::clamp(c.value + spread, -1.0, 1.0));
  const double high = std::acos(std::clamp(c.value - spread, -1.0, 1.0));
  const double middle = 0.5 * (low + high);
  return {{middle, 0.5 * (high - low) + kLibmAngleError}, std::cos(middle), std::sin(middle)};
}

/// |P n_p| = |w| / |n_c|. When |w|^2 would underflow (normals parallel to within ~1e-150, or a
/// subnormal tilt), w is first scaled by an exact power of two, so that a rim barely tipped
/// through the plane still gets representable crossing angles.
Bounded in_plane_normal_length(const detail::PlaneQuantities& q) {
  constexpr double kTinySquare = 0x1p-1000, kUp = 0x1p600, kDown = 0x1p-600;
  const Bounded plain = sqrt(q.w2 / q.nc2);
  if (!(q.w2.value < kTinySquare)) return plain;  // nearly always: w's zero test only after it
  const bool w_computed_zero = q.w.x.value == 0.0 && q.w.y.value == 0.0 && q.w.z.value == 0.0;
  if (w_computed_zero) return plain;
  const BoundedVector3 w{q.w.x * kUp, q.w.y * kUp, q.w.z * kUp};
  const Bounded scaled = sqrt(squared_norm(w) / q.nc2) * kDown;
  // The scaling also scales the error bounds, whose squares can overflow (w computed as exactly
  // 0, from normals equal up to rounding, still has a bound of 1e-16: the plain enclosure, which
  // is finite if wide, is taken above); should the scaled one still overflow, the plain one.
  return scaled.finite() ? scaled : plain;
}

/// The topology, with the certificate that covers the whole answer.
struct Decision {
  detail::CirclePlaneTopologyAndSide topology;
  Certificate certificate;
};
using Verdict = detail::TierVerdict<CertificateReason>;
/// The floating-point tier of the topology: proved by the filter on q (widened), or read off the
/// double values when the certificate is off, into `decision`; open (plane_filter_undecided) when
/// only the exact tier (exact_circle_plane_topology) can decide.
Verdict decide_by_filter(const Circle3& circle, const Plane3& plane, const IntersectionOptions& options,
                         const detail::PlaneQuantities& q, Decision& decision);
/// The last tier, when the filter left the topology open and the exact tier is off: the signs
/// read off the double values, marked uncertain.
Decision approximate_decision(const detail::PlaneQuantities& q);
/// Fills `out` (default-constructed) for a decided topology: the certificate, the depth (if
/// with_depth) and the crossings, on q (widened) and the stored rim; each crossing point's bound
/// also covers centre_error (the exact rim is that much farther).
void describe(const Circle3& circle, const IntersectionOptions& options, double centre_error,
              const detail::PlaneQuantities& q, const Decision& decision, bool with_depth,
              CirclePlaneIntersection& out);
/// Inputs that plane_quantities_if_ready turns away, validated (InvalidInput otherwise) and
/// rescaled by powers of two where that is exact: lengths by 2^-exponent, each normal on its own.
struct Rescaled {
  Circle3 circle;
  Plane3 plane;
  int exponent = 0;
};
Rescaled rescale(const Circle3& circle, const Plane3& plane);

/// How far the exact rim centre and plane point may lie from the stored ones (the bounds of
/// rounded_point.hpp, before any rescaling), and their recipes for the exact tier; zero and null
/// for exact inputs (kExactPoints).
struct PointErrors {
  double centre = 0.0, point = 0.0;
  const detail::RoundedPoint* centre_recipe = nullptr;
  const detail::RoundedPoint* point_recipe = nullptr;
};
constexpr PointErrors kExactPoints{};

/// What an entry asks of answer(): the whole query, or the part detect_contacts uses. That part
/// declines (answer returns false) inputs that need rescaling or the exact tier, whose recipes
/// the detection builds only then, and leaves the depth (max_signed_distance and its bound) as
/// default-constructed: the detection measures depth at its contact point (eq. 23), and this
/// one's Bounded square root and division were ~100 of the ~1,360 instructions of a detection's
/// query (callgrind). Leaving it out does not change require_finite_bounds' verdict: for inputs
/// that need no rescaling (|n_p|^2 >= 2^-200, lengths below 2^61, normals' 1-norms at most
/// 2^100) the depth is below 2^263 in magnitude, and its bound is finite whenever the filter
/// proves the answer (a proved sign of s or of the discriminant needs a finite bound on s, and
/// |P n_p| and |n_p| then have finite bounds, small relative to them).
enum class Scope { whole_query, detection };

/// Every entry below: the query on the stored inputs, into `out` (default-constructed); true
/// unless `scope` declines, before touching `out`. The public query calls it directly: one more call level, or the
/// errors and recipes as four arguments, cost it ~10-20 of its ~780 instructions.
bool answer(const Circle3& circle, const Plane3& plane, const IntersectionOptions& options,
            const PointErrors& errors, Scope scope, CirclePlaneIntersection& out);

/// Leaves `out` alone when every value and (for a proved answer) every bound is finite; otherwise
/// marks it uncertain with kNotRepresentable and removes its bounds. `with_depth`: the depth was
/// computed (Scope).
void require_finite_bounds(CirclePlaneIntersection& out, bool with_depth) {
  // Inputs whose magnitudes lie hundreds of orders apart can under- or overflow the double
  // steps after the topology (decided exactly regardless): then the points are not answers.
  // A certified answer must also carry finite bounds (their intermediate values can overflow
  // where the values themselves do not).
  const bool bounded = out.certificate.level != Certainty::uncertain;
  bool finite = !with_depth || (std::isfinite(out.max_signed_distance) &&
                                 (!bounded || std::isfinite(out.max_signed_distance_error)));
  for (int i = 0; i < out.crossing_count; ++i) {
    finite = finite && std::isfinite(out.crossings[i].angle) && out.crossings[i].point.allFinite() &&
             (!bounded || (std::isfinite(out.crossings[i].angle_error) && std::isfinite(out.crossings[i].point_error)));
  }
  if (!finite) {
    out.certificate = {Certainty::uncertain, kNotRepresentable};
    for (int i = 0; i < out.crossing_count; ++i) {
      out.crossings[i].angle_error = out.crossings[i].point_error = kNoErrorBound;
    }
    out.max_signed_distance_error = kNoErrorBound;
  }
}

}  // namespace

CirclePlaneIntersection intersect_circle_plane(const Circle3& circle, const Plane3& plane,
                                               const IntersectionOptions& options) {
  CirclePlaneIntersection out;
  answer(circle, plane, options, kExactPoints, Scope::whole_query, out);
  return out;
}

CirclePlaneIntersection detail::intersect_circle_plane(const Circle3& circle, const Plane3& plane,
                                                       const IntersectionOptions& options,
                                                       const RoundedPoint* centre,
                                                       const RoundedPoint* point) {
  CirclePlaneIntersection out;
  const PointErrors errors{centre == nullptr ? 0.0 : centre->error, point == nullptr ? 0.0 : point->error, centre,
                           point};
  answer(circle, plane, options, errors, Scope::whole_query, out);
  return out;
}

bool detail::intersect_circle_plane_if_filtered(const Circle3& circle, const Plane3& plane,
                                                const IntersectionOptions& options, double centre_error,
                                                double point_error, CirclePlaneIntersection& out) {
  return answer(circle, plane, options, {centre_error, point_error, nullptr, nullptr}, Scope::detection, out);
}

namespace {

Rescaled rescale(const Circle3& circle_in, const Plane3& plane_in) {
  // The inline test, then validate(), which formats its message and is out of line.
  if (!detail::passes_validation(circle_in)) validate(circle_in, "circle");
  if (!detail::passes_validation(plane_in)) validate(plane_in, "plane");
  // Exact power-of-two rescaling, as in intersect_circle_cylinder (scale_normalisation.hpp).
  Rescaled r{circle_in, plane_in, 0};
  r.circle.normal = detail::direction_scaled(circle_in.normal);
  r.plane.normal = detail::direction_scaled(plane_in.normal);
  int e = detail::length_exponent(std::max({r.circle.center.cwiseAbs().maxCoeff(),
                                            r.plane.point.cwiseAbs().maxCoeff(), r.circle.radius}));
  if (e != 0 && !(detail::scales_exactly(r.circle.center, e) && detail::scales_exactly(r.circle.radius, e) &&
                  detail::scales_exactly(r.plane.point, e))) {
    e = 0;
  }
  if (e != 0) {
    r.circle.center = detail::scaled(r.circle.center, e);
    r.circle.radius = std::ldexp(r.circle.radius, -e);
    r.plane.point = detail::scaled(r.plane.point, e);
  }
  r.exponent = e;
  return r;
}

bool answer(const Circle3& circle_in, const Plane3& plane_in, const IntersectionOptions& options,
            const PointErrors& errors, Scope scope, CirclePlaneIntersection& out) {
  // Realistic inputs are valid, inside the a priori guard and need no rescaling
  // (plane_quantities_if_ready): for them the checks, the rescaling and the copies, a fifth of a
  // disjoint query, are skipped.
  // Named, not a structured binding: the tiers' lambdas below capture q (Clang 14 cannot capture
  // a structured binding).
  detail::ReadyPlaneQuantities prepared = detail::plane_quantities_if_ready(circle_in, plane_in);
  detail::PlaneQuantities& q = prepared.q;
  Rescaled rescaled;
  const Circle3* circle = &circle_in;
  const Plane3* plane = &plane_in;
  if (!prepared.ready) {
    if (scope == Scope::detection) return false;
    rescaled = rescale(circle_in, plane_in);
    circle = &rescaled.circle;
    plane = &rescaled.plane;
    q = detail::floating_point_filter(
        detail::plane_a_priori_bounds_apply(*circle, *plane),
        [&] { return detail::plane_quantities_a_priori(*circle, *plane); },
        [&] { return detail::plane_quantities_running_error(*circle, *plane); });
  }
  const int e = rescaled.exponent;
  // Every bound below then holds for the exact centre and point too (rounded_point.hpp).
  const double scaled_centre_error = detail::scaled_error(errors.centre, e);
  const double scaled_point_error = detail::scaled_error(errors.point, e);
  if (scaled_centre_error + scaled_point_error != 0.0) {
    detail::widen_for_point_error(q, scaled_centre_error + scaled_point_error);
  }
  // The topology, in filtered_predicate.hpp's order, each tier filling `decision` in place: a
  // decision copied out of a std::optional is a 16-byte load of two 8-byte stores that the store
  // buffer cannot forward, and the random-pose queries were measurably slower for it.
  Decision decision;
  const bool answered = detail::filtered_exact_or_fallback<CertificateReason>(
      options.certify && options.exact_fallback,
      [&] { return decide_by_filter(*circle, *plane, options, q, decision); },
      [&](CertificateReason filter_failure) {
        // The detection's pass declines: it builds the exact tier's recipes only now and asks
        // again for the whole query.
        if (scope == Scope::detection) return Verdict::declined();
        decision = {detail::exact_circle_plane_topology(*circle, *plane, errors.centre_recipe, errors.point_recipe, e),
                    {Certainty::exact, filter_failure}};
        return Verdict::done();
      },
      [&](CertificateReason) { decision = approximate_decision(q); });
  if (!answered) return false;
  const bool with_depth = scope == Scope::whole_query;
  describe(*circle, options, scaled_centre_error, q, decision, with_depth, out);
  if (e != 0) {
    for (int i = 0; i < out.crossing_count; ++i) {
      out.crossings[i].point = detail::scaled(out.crossings[i].point, -e);
      out.crossings[i].point_error = std::ldexp(out.crossings[i].point_error, e);
    }
    out.max_signed_distance = std::ldexp(out.max_signed_distance, e);
    out.max_signed_distance_error = std::ldexp(out.max_signed_distance_error, e);
  }
  require_finite_bounds(out, with_depth);
  return true;
}

Verdict decide_by_filter(const Circle3& circle, const Plane3& plane, const IntersectionOptions& options,
                         const detail::PlaneQuantities& q, Decision& decision) {
  const Bounded& s = q.s;
  const BoundedVector3& w = q.w;
  const Bounded& w2 = q.w2;

  // Filter: every sign the topology needs, proved from the error bounds (a priori or running).
  const bool parallel_proved_false = w.x.sign() != 0 || w.y.sign() != 0 || w.z.sign() != 0;
  // Exactly parallel normals (the paper's aligned joints keep them so): every component of
  // n_p x n_c is a difference of two products, zero exactly when the products are equal.
  const Vector3& a = plane.normal;
  const Vector3& b = circle.normal;
  const bool parallel_exact = !parallel_proved_false &&
                              detail::exactly_equal_products(a.y(), b.z(), a.z(), b.y()) &&
                              detail::exactly_equal_products(a.z(), b.x(), a.x(), b.z()) &&
                              detail::exactly_equal_products(a.x(), b.y(), a.y(), b.x());
  const Bounded& discriminant = q.discriminant;
  detail::CirclePlaneTopologyAndSide decided{};
  bool filtered = false;
  if (parallel_exact && s.sign() != 0) {
    decided = {CirclePlaneTopology::disjoint, s.sign()};
    filtered = true;
  } else if (parallel_proved_false && discriminant.sign() != 0 && s.sign() != 0) {
    decided = discriminant.sign() > 0 ? detail::CirclePlaneTopologyAndSide{CirclePlaneTopology::disjoint, s.sign()}
                                      : detail::CirclePlaneTopologyAndSide{CirclePlaneTopology::two_crossings, 0};
    filtered = true;
  } else if (parallel_proved_false && discriminant.sign() < 0) {
    decided = {CirclePlaneTopology::two_crossings, 0};
    filtered = true;
  }
  if (filtered && options.certify) {
    decision = {decided, {Certainty::certified, CertificateReason::none}};
    return Verdict::done();
  }
  if (!options.certify) {
    // Plain double pipeline: read the signs off the computed values.
    const bool parallel = w2.value == 0.0;
    const int side = s.value > 0 ? 1 : (s.value < 0 ? -1 : 0);
    if (parallel) decided = {side == 0 ? CirclePlaneTopology::circle_in_plane : CirclePlaneTopology::disjoint, side};
    else if (discriminant.value > 0) decided = {CirclePlaneTopology::disjoint, side};
    else if (discriminant.value == 0) decided = {CirclePlaneTopology::tangent, side};
    else decided = {CirclePlaneTopology::two_crossings, 0};
    decision = {decided, {Certainty::uncertain, CertificateReason::certificate_switched_off}};
    return Verdict::done();
  }
  return Verdict::open(CertificateReason::plane_filter_undecided);
}

Decision approximate_decision(const detail::PlaneQuantities& q) {
  const Bounded& s = q.s;
  const Bounded& discriminant = q.discriminant;
  const int side = s.value > 0 ? 1 : (s.value < 0 ? -1 : 0);
  const detail::CirclePlaneTopologyAndSide decided{
      discriminant.value > 0 ? CirclePlaneTopology::disjoint : CirclePlaneTopology::two_crossings,
      discriminant.value > 0 ? side : 0};
  return {decided, {Certainty::uncertain, CertificateReason::plane_filter_undecided_exact_fallback_off}};
}

void describe(const Circle3& circle, const IntersectionOptions& options, double centre_error,
              const detail::PlaneQuantities& q, const Decision& decision, bool with_depth,
              CirclePlaneIntersection& out) {
  const Bounded& s = q.s;
  const Bounded& np2 = q.np2;
  const Bounded r = circle.radius;
  const detail::CirclePlaneTopologyAndSide& decided = decision.topology;
  // Field by field: the decision was just built in memory field by field, and GCC copied the
  // struct with one 16-byte load, which waits for both stores (no store forwarding).
  out.certificate.level = decision.certificate.level;
  out.certificate.reason = decision.certificate.reason;
  out.topology = decided.topology;
  out.side = static_cast<PlaneSide>(decided.side);
  const bool bounded = options.certify && out.certificate.level != Certainty::uncertain;

  // Deepest reach beyond the plane, in metres: (s + r |P n_p|) / |n_p|.
  const Bounded in_plane_normal = in_plane_normal_length(q);  // |P n_p|
  if (with_depth) {
    const Bounded deepest = (s + r * in_plane_normal) / sqrt(np2);
    out.max_signed_distance = deepest.value;
    out.max_signed_distance_error = bounded && deepest.finite() ? deepest.error : kNoErrorBound;
  }

  if (out.topology == CirclePlaneTopology::disjoint || out.topology == CirclePlaneTopology::circle_in_plane) {
    if (out.topology == CirclePlaneTopology::disjoint && out.side == PlaneSide::positive) {
      out.penetration = {0.0, detail::kTwoPi, true};
      out.has_penetration = true;
    }
    if (out.topology == CirclePlaneTopology::circle_in_plane && with_depth) {
      out.max_signed_distance = 0.0;  // exactly: every rim point lies in the plane
      out.max_signed_distance_error = bounded ? 0.0 : kNoErrorBound;
    }
    return;
  }

  // theta_m: angle of P n_p in the rim frame, from w and |n_c|^2 (rim_plane_quantities.hpp).
  const detail::DeepestDirection toward = detail::deepest_direction(circle, q);
  const AngleWithTrig theta_m_with_trig = angle_of(toward.along_u, toward.along_v);
  const Bounded& theta_m = theta_m_with_trig.angle;
  const double cos_m = theta_m_with_trig.cos, sin_m = theta_m_with_trig.sin;

  // The points on the stored (rounded) frame; `rounding` covers it and the sums.
  const CircleFrame frame = frame_of(circle);
  // |c|_1 >= |c|: no square root
  const double rounding = kPointRoundingUlps * (circle.center.cwiseAbs().sum() + 2 * circle.radius);
  // Crossing points by angle addition from cos/sin of theta_m and beta: no libm sine or cosine.
  // They differ from point_at(angle) by a few ulps of the terms, inside `rounding`.
  auto point_with = [&](double cos_angle, double sin_angle) -> Vector3 {
    return circle.center + circle.radius * (cos_angle * frame.u + sin_angle * frame.v);
  };
  // A rim's crossings share one angle error (theta_m's, plus beta's when there are two), hence
  // one pair of bounds, formed once; each crossing is written in place, already in angle order
  // (building them apart and swapping cost ~5.6 of a ~1180-instruction query, callgrind).
  auto set_bounds = [&](double error, double& angle_error, double& point_error) {
    // wrapping subtracts a rounded 2 pi: one more ulp of 2 pi.
    // Capped at pi: every rim angle is within pi of the reported one (ill-conditioned crossings,
    // such as those of a rim tipped by a subnormal angle, can have an unbounded derivative bound).
    const double wrapped_error = error + 4 * detail::kUnitRoundoff * detail::kTwoPi;
    // not std::fmin (an out-of-line libm call); a NaN error becomes pi, as with fmin
    angle_error = bounded ? (wrapped_error < std::numbers::pi ? wrapped_error : std::numbers::pi) : kNoErrorBound;
    // The exact rim's crossing is also centre_error farther away (its centre moved that much).
    point_error = bounded ? (circle.radius * angle_error + rounding + centre_error) * (1 + 4 * detail::kUnitRoundoff)
                          : kNoErrorBound;
  };
  double angle_error, point_error;

  if (out.topology == CirclePlaneTopology::tangent) {
    // The touching point is where f is smallest (side +1) or largest (side -1).
    const double angle = out.side == PlaneSide::positive ? theta_m.value + std::numbers::pi : theta_m.value;
    const double sign = out.side == PlaneSide::positive ? -1.0 : 1.0;
    set_bounds(theta_m.error, angle_error, point_error);
    out.crossings[0] = {detail::wrap_angle(angle), angle_error, point_with(sign * cos_m, sign * sin_m),
                        point_error, 2};
    out.crossing_count = 1;
    return;
  }

  // Two crossings at theta_m -+ beta, cos(beta) = -s / (r |P n_p|); beyond the plane between them.
  const AngleWithTrig beta = acos_of(-s / (r * in_plane_normal));
  const Bounded& half_width = beta.angle;
  set_bounds(theta_m.error + half_width.error, angle_error, point_error);
  const double cb = beta.cos, sb = beta.sin;
  const double before = detail::wrap_angle(theta_m.value - half_width.value);
  const double after = detail::wrap_angle(theta_m.value + half_width.value);
  out.penetration = {before, after, false};
  out.has_penetration = true;
  const int first = after < before ? 1 : 0;  // sorted by angle
  out.crossings[first] = {before, angle_error, point_with(cos_m * cb + sin_m * sb, sin_m * cb - cos_m * sb),
                          point_error, 1};
  out.crossings[1 - first] = {after, angle_error, point_with(cos_m * cb - sin_m * sb, sin_m * cb + cos_m * sb),
                              point_error, 1};
  out.crossing_count = 2;
}

}  // namespace

}  // namespace clearjoint::geometry
