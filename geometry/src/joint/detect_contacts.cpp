// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/joint/detect_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/angles.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "filters/candidate_prefilter.hpp"
#include "joint/joint_setup.hpp"
#include "model/primitives_detail.hpp"
#include "predicates/contact_error_bounds.hpp"
#include "predicates/rim_distance_polynomial.hpp"
#include "predicates/rim_plane_quantities.hpp"
#include "queries/rounded_point_queries.hpp"

namespace clearjoint::geometry {
namespace {

using detail::JointSetup;
using detail::Prefilter;
using detail::axes_exactly_parallel;
using detail::prefilter_if_ready;
using detail::set_up;

constexpr CertificateReason kNotRepresentableInWorld = CertificateReason::contact_not_representable_in_world;
constexpr CertificateReason kToleranceReason = CertificateReason::axes_parallel_within_tolerance;
constexpr CertificateReason kBeyondModelUndecided = CertificateReason::beyond_model_undecided;

/// The component of `offset` perpendicular to the unit axis `axis_hat`, written as
/// axis x (offset x axis): no cancellation of nearly equal terms, unlike offset - (offset.a) a.
Vector3 off_axis(const Vector3& offset, const Vector3& axis_hat) {
  return axis_hat.cross(offset.cross(axis_hat));
}

/// The recipes of rounded_point.hpp, for the kernel queries (their exact tiers).
detail::RoundedPoint rounded_centre(const JointSetup& s, ContactBase base) {
  const int sign = base == ContactBase::a ? s.toward_a : -s.toward_a;
  detail::RoundedPoint point{s.journal_rims[base == ContactBase::a ? 0 : 1],
                             s.journal_rim_errors[base == ContactBase::a ? 0 : 1],
                             s.p_WPj_world,
                             s.p_WPi_world,
                             s.journal_axis_hat_W,
                             s.journal_length,
                             sign};
  return point;
}
detail::RoundedPoint rounded_base(const JointSetup& s, ContactBase base) {
  const int k = base == ContactBase::a ? 0 : 1;
  return {s.bearing_bases[k], s.bearing_base_errors[k], Vector3::Zero(), Vector3::Zero(),
          s.bearing_axis_hat_W, s.bearing_length, k == 0 ? +1 : -1};
}
detail::RoundedPoint rounded_journal_centre(const JointSetup& s) {
  return {s.p_WPj, s.journal_centre_error, s.p_WPj_world, s.p_WPi_world, Vector3::Zero(), 0.0, 0};
}

const Vector3& bearing_base(const JointSetup& s, ContactBase base) {
  return s.bearing_bases[base == ContactBase::a ? 0 : 1];
}
const Vector3& journal_rim_center(const JointSetup& s, ContactBase base) {
  return s.journal_rims[base == ContactBase::a ? 0 : 1];
}
/// Outward normal of the bearing base: +a_i at A, -a_i at B.
double outward_sign(ContactBase base) { return base == ContactBase::a ? 1.0 : -1.0; }

Circle3 journal_rim(const JointSetup& s, ContactBase base) {
  return {journal_rim_center(s, base), s.journal_axis_W, s.journal_radius};
}

/// The circle-cylinder query of a journal circle (a rim, or the mid-length section) centred at
/// `centre` against the bearing wall, with the axes scaled once in set_up; inputs that
/// prefilter_if_ready found inside its guard skip the query's input checks.
CircleCylinderIntersection against_wall(const JointSetup& s, const detail::RoundedPoint& centre,
                                        const DetectionOptions& options) {
  const Circle3 circle{centre.value, s.journal_axis_scaled_W, s.journal_radius};
  const Cylinder3 wall{s.p_WPi, s.bearing_axis_scaled_W, s.bearing_radius};
  return s.inputs_in_guard ? detail::intersect_valid_circle_cylinder(circle, wall, options.intersection, &centre)
                           : detail::intersect_circle_cylinder(circle, wall, options.intersection, &centre);
}

/// Accumulates the weakest certificate over every decision.
class CertificateAccumulator {
 public:
  /// overall_ = any_ ? weakest(overall_, c) : c, field by field: `c` was often just built in
  /// memory field by field, and GCC copied the struct with one 16-byte load that waits for both
  /// stores (no store forwarding).
  void add(const Certificate& c) {
    if (!any_ || static_cast<int>(c.level) > static_cast<int>(overall_.level)) {
      overall_.level = c.level;
      overall_.reason = c.reason;
    }
    any_ = true;
  }
  Certificate result() const { return overall_; }

 private:
  Certificate overall_{};
  bool any_ = false;
};

/// What stands behind the beyond_model label (contact_scenario.hpp): a proved test (a rim with two
/// penetration arcs or beyond a surface all round, or a depth whose bound keeps it clear of the
/// clearance), or only depths that lie within their bound of the clearance.
struct BeyondModelEvidence {
  bool proved = false;
  bool undecided = false;
};

/// A depth deeper than the clearance is beyond the model (eqs. 1-2). The computed depth decides
/// it for the exact joint where its error bound keeps it clear of the clearance, itself Ri - Rj or
/// (Li - Lj)/2 rounded once (within kClearanceRounding of the exact one); the difference is
/// rounded once more, which kMarginShrink covers. Elsewhere the label follows the computed depth
/// and is recorded as undecided.
constexpr double kClearanceRounding = 2 * detail::kUnitRoundoff;  // > u, rounded up
constexpr double kMarginShrink = 1 - 4 * detail::kUnitRoundoff;
void compare_with_clearance(const Contact& contact, double clearance, ContactPresence& presence,
                            BeyondModelEvidence& beyond) {
  const bool deeper = contact.depth > clearance;
  if (deeper) presence.beyond_model = true;
  if (contact.certificate.level == Certainty::uncertain) return;  // the answer says so already
  if (std::fabs(contact.depth - clearance) * kMarginShrink > contact.depth_error + kClearanceRounding * clearance) {
    beyond.proved |= deeper;
  } else {
    beyond.undecided = true;
  }
}

/// Crossings bounding `arc` (its ends are crossing angles, as the kernel builds them). Two
/// crossings bound every arc but the full rim (both kernels build an arc between consecutive
/// crossings): that common case without the search, in the search's order.
/// Sets every crossing slot: those past crossing_count to RimCrossing{} (the callers do not
/// clear the contact first: see contact_header).
void copy_arc_crossings(const RimCrossing* crossings, int count, const RimArc& arc,
                        Contact& contact) {
  if (count == 2 && !arc.full) {
    contact.crossings = {crossings[0], crossings[1]};
    contact.crossing_count = 2;
    return;
  }
  contact.crossing_count = 0;
  for (int k = 0; k < count && contact.crossing_count < 2; ++k) {
    if (crossings[k].angle == arc.begin || crossings[k].angle == arc.end) {
      contact.crossings[contact.crossing_count++] = crossings[k];
    }
  }
  for (int k = contact.crossing_count; k < 2; ++k) contact.crossings[k] = RimCrossing{};
}

/// The fields of a point contact that the builders below do not compute: with copy_arc_crossings
/// and their own points, normal and depth, every field of the Contact is set, as in a fresh one,
/// without first writing the 224-byte default that they would overwrite (~30 instructions a
/// contact, callgrind).
void contact_header(ContactType type, ContactBase base, const Certificate& certificate, Contact& contact) {
  contact.type = type;
  contact.base = base;
  contact.certificate.level = certificate.level;  // field by field: see CertificateAccumulator
  contact.certificate.reason = certificate.reason;
}

/// The journal point of a point contact: the rim point at the middle of the penetration arc
/// (eqs. 13-14, 18-19). For a full arc (beyond the model) the middle is not meaningful; the rim
/// point farthest along `deepest_direction` (projected into the rim plane) is taken instead: for
/// an axial contact the exact deepest point, `deepest_direction` being the base normal within
/// `deepest_direction_error`, so the point and the depth get tight bounds.
/// The arc's end points are its crossings (the contact's, already copied), so the middle
/// costs no sine, cosine or rim frame: it lies along the chord's midpoint seen from the centre
/// (away from it when the arc sweeps more than half the rim). Where the chord passes within r/4
/// of the centre (a sweep near half a turn) that direction is ill-conditioned, but the chord is
/// then nearly a diameter (longer than 1.9 r) and the middle lies along its perpendicular in the
/// rim plane, (end - begin) x n_hat, for every sweep: with begin angle a and sweep s in the rim
/// frame (whose normal is n_hat), end - begin = 2 r sin(s/2) (-sin m, cos m), m = a + s/2 the
/// middle angle, and sin(s/2) > 0. The middle angle is evaluated only where neither applies.
/// `error`: a bound on the distance to the exact rim's exact arc middle (contact_error_bounds.hpp;
/// the rim centre within `centre_error` of rim.center). The two chord constructions propagate the
/// crossings' bounds; the full arc's point is bounded through its direction when that direction
/// is known within a bound (axial), and the radial full arc (a convention, not an arc middle) and
/// the angle evaluation get the trivial bound of any exact rim point.
/// Always inlined into its two callers: Clang made a call of it, which cost some 35 instructions
/// a contact in passing and returning (callgrind).
struct JournalPoint {
  Vector3 point;
  double error;
};
[[gnu::always_inline]] inline JournalPoint journal_contact_point(const Circle3& rim, double centre_error,
                                                                 const RimArc& arc, const Contact& contact,
                                                                 const Vector3& deepest_direction,
                                                                 const Vector3& rim_normal_hat,
                                                                 double deepest_direction_error = kNoErrorBound) {
  using detail::kEvaluationRounding;
  if (arc.full) {
    const Vector3 in_plane = off_axis(deepest_direction, rim_normal_hat);
    const double length = in_plane.norm();
    if (length > 0.0) {
      const Vector3 point = rim.center + (rim.radius / length) * in_plane;
      // x = a x (n x a) = n - (n . a) a moves by at most |dn| + 2 |da| (unit a and n) plus the
      // rounding of its two cross products; one more kUnitAxisError covers the second-order
      // terms. With an exact direction n (the axial case) the point is the exact rim's deepest
      // point within rim_point_along_error; otherwise (radial: a convention) the trivial bound.
      const double perturbation = deepest_direction_error + 3 * detail::kUnitAxisError + 4 * kEvaluationRounding;
      return {point, detail::rim_point_along_error(point, rim.center, centre_error, rim.radius, perturbation, length)};
    }
  } else if (contact.crossing_count == 2) {
    const RimCrossing &c0 = contact.crossings[0], &c1 = contact.crossings[1];
    const Vector3 &p0 = c0.point, &p1 = c1.point;
    const Vector3 towards_middle = 0.5 * (p0 + p1) - rim.center;
    const double length = towards_middle.norm();
    const double magnitudes = p0.cwiseAbs().sum() + p1.cwiseAbs().sum() + rim.center.cwiseAbs().sum();
    if (length > 0.25 * rim.radius) {
      // arc.sweep() of an arc that is not full, without the library call.
      const double side = detail::wrap_angle(arc.end - arc.begin) < std::numbers::pi ? 1.0 : -1.0;
      const Vector3 point = rim.center + (side * rim.radius / length) * towards_middle;
      // The crossings' errors move the chord's ends: x = (p0 + p1)/2 - c by half their sum, plus
      // the centre's error and the rounding of x. The side (towards or away from the middle) is
      // the exact arc's when the angle errors cannot carry the sweep across pi: |x| > r/4 keeps
      // the sweep more than 0.5 rad from pi.
      const double perturbation =
          0.5 * (c0.point_error + c1.point_error) + centre_error + kEvaluationRounding * magnitudes;
      const double error =
          c0.angle_error + c1.angle_error < 0.25
              ? detail::rim_point_along_error(point, rim.center, centre_error, rim.radius, perturbation, length)
              : detail::any_rim_point_error(point, rim.center, centre_error, rim.radius);
      return {point, error};
    }
    const Vector3 begin_to_end = contact.crossings[0].angle == arc.begin ? Vector3(p1 - p0) : Vector3(p0 - p1);
    const Vector3 across = begin_to_end.cross(rim_normal_hat);
    const double across_length = across.norm();
    if (across_length > 0.0) {  // NaN fails
      const Vector3 point = rim.center + (rim.radius / across_length) * across;
      // (P1 - P0) x n* for the exact ends and unit normal: the ends' errors, the normal's
      // direction error times |P1 - P0| <= 2 r, and the rounding of the difference and product.
      const double perturbation = c0.point_error + c1.point_error + 2 * rim.radius * detail::kUnitAxisError +
                                  kEvaluationRounding * (magnitudes + 2 * rim.radius);
      return {point, detail::rim_point_along_error(point, rim.center, centre_error, rim.radius, perturbation,
                                                   across_length)};
    }
  }
  const Vector3 point = point_at(rim, frame_of(rim), arc.middle());
  return {point, detail::any_rim_point_error(point, rim.center, centre_error, rim.radius)};
}

/// A unit direction square to the unit axis `axis_hat`: the stand-in where rounding has lost the
/// exact direction.
Vector3 any_direction_off_axis(const Vector3& axis_hat) {
  return off_axis(Vector3::Unit(frame_axis_index(axis_hat)), axis_hat).normalized();
}

/// The contact normal when the journal point, as rounded in the bearing frame, lies on the bearing
/// axis: eq. (20) has no direction, though the exact point (within its error bound, which is then
/// at least its distance to the axis) has one. Only at scales where the frame's rounding exceeds
/// the rim radius (lengths ~1e30 beside radii ~1e-2): the direction of the point from its rim
/// centre, off the axis, stands in, or any direction square to the axis. The contact's bearing
/// point then carries no error bound (radial_contact), so this is a convention, not a claim.
Vector3 radial_direction_off_axis(const JointSetup& s, const Circle3& rim, const Vector3& p_WCj) {
  const Vector3 direction = off_axis(p_WCj - rim.center, s.bearing_axis_hat_W);
  if (!(direction.norm() > 0.0)) return any_direction_off_axis(s.bearing_axis_hat_W);
  return direction.normalized();
}

/// Radial point contact from one penetration arc of rim `base` against the wall, eqs. (18)-(23),
/// written in place (every field set as in a fresh Contact: building one and copying it into the
/// result cost ~30 instructions per contact).
void radial_contact(const JointSetup& s, ContactBase base, const Circle3& rim, const CircleCylinderIntersection& hit,
                    const RimArc& arc, Contact& contact) {
  using detail::kEvaluationRounding;
  contact_header(ContactType::radial, base, hit.certificate, contact);
  // journal_contact_point reads the direction of the deepest point only for a full arc.
  const Vector3 radial_offset_of_center =
      arc.full ? off_axis(rim.center - s.p_WPi, s.bearing_axis_hat_W) : Vector3::Zero();
  copy_arc_crossings(hit.crossings.data(), hit.crossing_count, arc, contact);
  // The point's later uses read the local value: reading contact.p_WCj back made GCC load 16
  // bytes of what it had just stored as doubles, a store-forwarding stall per contact.
  const JournalPoint journal_point = journal_contact_point(rim, s.journal_rim_errors[base == ContactBase::a ? 0 : 1],
                                                          arc, contact, radial_offset_of_center, s.journal_axis_hat_W);
  const Vector3 p_WCj = journal_point.point;
  contact.p_WCj = p_WCj;
  const Vector3 offset = p_WCj - s.p_WPi;
  const Vector3 radial = off_axis(offset, s.bearing_axis_hat_W);
  const double distance_to_axis = radial.norm();
  contact.normal_W = distance_to_axis > 0.0 ? Vector3(radial / distance_to_axis)  // eq. (20)
                                            : radial_direction_off_axis(s, rim, p_WCj);
  contact.p_WCi = s.p_WPi + offset.dot(s.bearing_axis_hat_W) * s.bearing_axis_hat_W +
                  s.bearing_radius * contact.normal_W;  // eq. (21)
  // eq. (23): |C_j - C_i| = distance_to_axis - Ri for a point beyond the wall. Both terms are
  // close to Ri, so the difference is exact (Sterbenz); rounding of C_j may leave it a few
  // ulps below 0 for an arc of vanishing length, hence the clamp.
  contact.depth = std::max(0.0, distance_to_axis - s.bearing_radius);
  // Bounds: the exact point's distance to the exact axis (through P_i, the frame's exact origin,
  // direction a_i/|a_i|) differs from distance_to_axis by the point's error, the axis direction's
  // error times 2 |offset|, and the rounding; its direction from the axis by direction_error.
  const double magnitude = offset.cwiseAbs().sum();
  const double off_axis_error =
      journal_point.error + 2 * magnitude * detail::kUnitAxisError + kEvaluationRounding * magnitude;
  contact.p_WCj_error = journal_point.error;
  contact.depth_error = off_axis_error + kEvaluationRounding * (distance_to_axis + s.bearing_radius);
  contact.p_WCi_error =
      off_axis_error < 0.5 * distance_to_axis
          ? off_axis_error + s.bearing_radius * detail::direction_error(off_axis_error, distance_to_axis) +
                kEvaluationRounding * (magnitude + s.bearing_radius)
          : kNoErrorBound;
  if (hit.certificate.level == Certainty::uncertain) {
    contact.p_WCj_error = contact.p_WCi_error = contact.depth_error = kNoErrorBound;
  }
}

/// The error bounds of a contact against a base plane (axial, eqs. 13-15; face, eqs. 9-10): the
/// journal point p within `point_error` of the exact one, the base centre within `base_error`,
/// the normal a unit axis within kUnitAxisError of the exact direction. beyond = (p - B) . n
/// moves by both errors plus |p - B| times the direction's; the bearing point p - beyond n by the
/// point's error, beyond's, and |beyond| times the direction's.
void set_plane_contact_errors(const Vector3& p, double point_error, const Vector3& base_centre, double base_error,
                              double beyond, const Certificate& certificate, Contact& contact) {
  using detail::kEvaluationRounding;
  if (certificate.level == Certainty::uncertain) {
    contact.p_WCj_error = contact.p_WCi_error = contact.depth_error = kNoErrorBound;
    return;
  }
  const double magnitudes = p.cwiseAbs().sum() + base_centre.cwiseAbs().sum();
  const double depth_error = point_error + base_error + magnitudes * detail::kUnitAxisError + kEvaluationRounding * magnitudes;
  contact.p_WCj_error = point_error;
  contact.depth_error = depth_error;
  contact.p_WCi_error = point_error + depth_error + std::fabs(beyond) * detail::kUnitAxisError +
                        kEvaluationRounding * (magnitudes + std::fabs(beyond));
}

/// Axial point contact of rim `base` against base plane `base`, eqs. (13)-(15), (22)-(23), written
/// in place as radial_contact.
void axial_contact(const JointSetup& s, ContactBase base, const Circle3& rim, const CirclePlaneIntersection& hit,
                   Contact& contact) {
  contact_header(ContactType::axial, base, hit.certificate, contact);
  contact.normal_W = outward_sign(base) * s.bearing_axis_hat_W;
  copy_arc_crossings(hit.crossings.data(), hit.crossing_count, hit.penetration, contact);
  // From the local value, as in radial_contact.
  const int k = base == ContactBase::a ? 0 : 1;
  const JournalPoint journal_point =
      journal_contact_point(rim, s.journal_rim_errors[k], hit.penetration, contact, contact.normal_W, s.journal_axis_hat_W,
                            detail::kUnitAxisError);
  const Vector3 p_WCj = journal_point.point;
  contact.p_WCj = p_WCj;
  const double beyond_base = (p_WCj - bearing_base(s, base)).dot(contact.normal_W);
  contact.p_WCi = p_WCj - beyond_base * contact.normal_W;  // eq. (15)
  contact.depth = std::max(0.0, beyond_base);                      // eq. (23)
  set_plane_contact_errors(p_WCj, journal_point.error, bearing_base(s, base), s.bearing_base_errors[k], beyond_base,
                           hit.certificate, contact);
}

/// Bearing base plane `base`, with its outward normal.
Plane3 base_plane_of(const JointSetup& s, ContactBase base) {
  return {bearing_base(s, base), outward_sign(base) * s.bearing_axis_W};
}

/// The whole kernel query, with the recipes and the depth.
CirclePlaneIntersection whole_rim_against_base(const JointSetup& s, ContactBase base, const DetectionOptions& options) {
  const detail::RoundedPoint centre = rounded_centre(s, base);
  const detail::RoundedPoint point = rounded_base(s, base);
  return detail::intersect_circle_plane(journal_rim(s, base), base_plane_of(s, base), options.intersection, &centre,
                                        &point);
}

/// The kernel query of journal rim `base` against bearing base plane `base` (outward normal),
/// with both centres' rounding bounds and exact recipes (rounded_point.hpp). First the kernel's
/// detection entry, which needs no recipes and skips the depth (axial_contact takes it from the
/// contact point, eq. 23): ~160 of the ~1,420 instructions of a query (callgrind). The recipes
/// only where it declines (exact tier or rescaling).
CirclePlaneIntersection rim_against_base(const JointSetup& s, ContactBase base, const DetectionOptions& options) {
  const int k = base == ContactBase::a ? 0 : 1;
  CirclePlaneIntersection hit;
  if (!detail::intersect_circle_plane_if_filtered(journal_rim(s, base), base_plane_of(s, base), options.intersection,
                                                  s.journal_rim_errors[k], s.bearing_base_errors[k], hit)) {
    hit = whole_rim_against_base(s, base, options);
  }
  return hit;
}

/// Near a tangency an axial contact's depth bound through its point (set_plane_contact_errors) is
/// loose: the crossings' enclosures are wide, and the arc middle's error with them (up to the rim
/// radius), while the depth, the largest signed distance of the rim from the plane, is known far
/// better. The contact's depth approximates that maximum (eq. 23 at the arc middle, the deepest
/// rim point), and the kernel's whole query encloses it (max_signed_distance within its bound, for
/// the exact joint). Where the bound through the point is loose (above kLooseDepthBound of the
/// depth plus the clearance) the contact takes the smaller of the two; the query runs again for
/// its depth unless it ran whole already. Realistic contacts never get here: their bounds are some
/// 1e-13 of the clearance. Nor does a rim beyond the base all round: its point is a convention
/// with the trivial bound, and its label is proved by the full arc (refining it cost 2 % of the
/// in-contact benchmark's detections, a quarter of which are beyond the model).
constexpr double kLooseDepthBound = 0x1p-20;
void tighten_axial_depth_error(const JointSetup& s, ContactBase base, const CirclePlaneIntersection& hit,
                               const DetectionOptions& options, Contact& contact) {
  if (hit.penetration.full || contact.certificate.level == Certainty::uncertain ||
      !(contact.depth_error > kLooseDepthBound * (contact.depth + s.axial_clearance))) {
    return;
  }
  const CirclePlaneIntersection whole =
      std::isfinite(hit.max_signed_distance_error) ? hit : whole_rim_against_base(s, base, options);
  if (whole.certificate.level == Certainty::uncertain || !std::isfinite(whole.max_signed_distance_error)) return;
  // |max(0, a) - max(0, b)| <= |a - b|; the difference and the sum round once each.
  const double through_depth =
      (std::fabs(contact.depth - std::max(0.0, whole.max_signed_distance)) + whole.max_signed_distance_error) *
      (1 + detail::kEvaluationRounding);
  contact.depth_error = std::min(contact.depth_error, through_depth);
}

/// The certificate of a "no contact" proved by a reach prefilter: as the kernel gives for the
/// same decision (its own first test), so that switching the certificate off reads the same.
Certificate clear_certificate(const DetectionOptions& options) {
  return options.intersection.certify ? Certificate{Certainty::certified, CertificateReason::none}
                                      : Certificate{Certainty::uncertain, CertificateReason::certificate_switched_off};
}

/// The misaligned case: four candidate point contacts. `prefiltered`: the prefilters' answer when
/// prefilter_if_ready computed it (the same as prove_candidates_clear's on these centres), or null.
void detect_misaligned(const JointSetup& s, const DetectionOptions& options,
                       const detail::CandidatesClear* prefiltered, JointContacts& out,
                       ContactPresence& presence, BeyondModelEvidence& beyond, CertificateAccumulator& certificate) {
  // A rim proved to stay inside the wall or the base plane (the kernel's own first tests, here
  // for all four candidates at once and without the kernel's input checks, rescaling and result
  // assembly) has no contact there: in free flight this is the whole detection.
  const Certificate proved_clear = clear_certificate(options);
  const detail::CandidatesClear clear =
      prefiltered != nullptr ? *prefiltered : detail::prove_misaligned_candidates_clear(s);
  for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
    if (clear.radial[base == ContactBase::a ? 0 : 1]) {
      certificate.add(proved_clear);
      continue;
    }
    const Circle3 rim = journal_rim(s, base);
    const CircleCylinderIntersection hit = against_wall(s, rounded_centre(s, base), options);
    certificate.add(hit.certificate);
    if (hit.arc_count == 0) continue;
    (base == ContactBase::a ? presence.radial_at_a : presence.radial_at_b) = true;
    // Two arcs: four crossings; a full arc: the rim is beyond the wall all round.
    if (hit.arc_count > 1 || hit.penetration_arcs[0].full) presence.beyond_model = beyond.proved = true;
    for (int k = 0; k < hit.arc_count; ++k) {
      Contact& contact = out.contacts[out.contact_count++];
      radial_contact(s, base, rim, hit, hit.penetration_arcs[k], contact);
      compare_with_clearance(contact, s.radial_clearance, presence, beyond);
    }
  }
  for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
    if (clear.axial[base == ContactBase::a ? 0 : 1]) {
      certificate.add(proved_clear);
      continue;
    }
    const Circle3 rim = journal_rim(s, base);
    const CirclePlaneIntersection hit = rim_against_base(s, base, options);
    certificate.add(hit.certificate);
    if (!hit.has_penetration) continue;
    (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
    if (hit.penetration.full) presence.beyond_model = beyond.proved = true;  // the rim is beyond the base
    Contact& contact = out.contacts[out.contact_count++];
    axial_contact(s, base, rim, hit, contact);
    tighten_axial_depth_error(s, base, hit, options, contact);
    compare_with_clearance(contact, s.axial_clearance, presence, beyond);
  }
}

/// The error bounds of the aligned line contact, eqs. (6)-(8): the journal centre within its
/// rounding bound of P_j - P_i, the bearing axis a unit axis within kUnitAxisError of the exact
/// direction. The eccentricity moves by the centre's error plus 2 |offset| times the direction's;
/// the normal by direction_error of that; the depth e - cr also by cr's rounding.
void set_line_contact_errors(const JointSetup& s, const Vector3& offset, double eccentricity, Contact& contact) {
  using detail::kEvaluationRounding;
  if (contact.certificate.level == Certainty::uncertain) {
    contact.p_WCj_error = contact.p_WCi_error = contact.depth_error = kNoErrorBound;
    return;
  }
  const double magnitude = offset.cwiseAbs().sum();
  const double radial_error =
      s.journal_centre_error + 2 * magnitude * detail::kUnitAxisError + kEvaluationRounding * magnitude;
  contact.depth_error = radial_error + kEvaluationRounding * (eccentricity + s.bearing_radius);
  if (!(radial_error < 0.5 * eccentricity)) {
    contact.p_WCj_error = contact.p_WCi_error = kNoErrorBound;
    return;
  }
  const double normal_error = detail::direction_error(radial_error, eccentricity);
  contact.p_WCj_error =
      s.journal_centre_error + s.journal_radius * normal_error + kEvaluationRounding * (magnitude + s.journal_radius);
  contact.p_WCi_error = radial_error + s.bearing_radius * normal_error + kEvaluationRounding * (magnitude + s.bearing_radius);
}

/// The aligned case, eqs. (6)-(10). `exactly_parallel`: eq. (5) holds exactly, and the
/// existence of each contact is decided by the certified kernel; otherwise (angle tolerance)
/// in double precision, and the contacts are uncertain. `prefiltered`: as for detect_misaligned,
/// with the line's test on the mid-length section in its first lane.
void detect_aligned(const JointSetup& s, const DetectionOptions& options, bool exactly_parallel,
                    const detail::CandidatesClear* prefiltered, JointContacts& out,
                    ContactPresence& presence, BeyondModelEvidence& beyond, CertificateAccumulator& certificate) {
  const Certificate tolerance_certificate{Certainty::uncertain, kToleranceReason};
  const Vector3 offset = s.p_WPj - s.p_WPi;
  const Vector3 radial = off_axis(offset, s.bearing_axis_hat_W);
  const double eccentricity = radial.norm();
  // Line contact: the journal's mid-length cross-section reaches beyond the wall. With parallel
  // axes every cross-section has the same eccentricity e, and max distance e + Rj > Ri.
  bool line = false;
  Certificate line_certificate = tolerance_certificate;
  const Certificate proved_clear = clear_certificate(options);
  // The kernel's first tests for the line and both faces at once (candidate_prefilter.hpp): the
  // mid-length section against the wall, the rims against the base planes (with parallel
  // normals the side test is the sign of s).
  detail::CandidatesClear clear;
  if (exactly_parallel) {
    clear = prefiltered != nullptr ? *prefiltered : detail::prove_aligned_candidates_clear(s);
    if (clear.radial[0]) {
      line = false;  // the kernel's first test, without its input checks and result assembly
      line_certificate = proved_clear;
    } else {
      const CircleCylinderIntersection hit = against_wall(s, rounded_journal_centre(s), options);
      line = hit.arc_count > 0;
      line_certificate = hit.certificate;
    }
  } else {
    line = eccentricity > s.radial_clearance;
  }
  certificate.add(line_certificate);
  if (line) {
    presence.line = true;
    Contact contact;
    contact.type = ContactType::radial;
    contact.base = ContactBase::mid;
    contact.certificate = line_certificate;
    // eq. (6). The computed eccentricity is 0 where rounding the offset, far along the axis,
    // loses all of it though the kernel proved the line on the exact joint: then any direction
    // square to the axis stands in, and the points carry no error bound (set_line_contact_errors),
    // so this is a convention; the depth's bound still covers the exact depth.
    contact.normal_W =
        eccentricity > 0.0 ? Vector3(radial / eccentricity) : any_direction_off_axis(s.bearing_axis_hat_W);
    contact.p_WCi = s.p_WPi + offset.dot(s.bearing_axis_hat_W) * s.bearing_axis_hat_W +
                    s.bearing_radius * contact.normal_W;                       // eq. (7)
    contact.p_WCj = s.p_WPj + s.journal_radius * contact.normal_W;            // eq. (8)
    contact.depth = std::max(0.0, eccentricity - s.radial_clearance);        // eq. (23)
    set_line_contact_errors(s, offset, eccentricity, contact);
    compare_with_clearance(contact, s.radial_clearance, presence, beyond);
    out.contacts[out.contact_count++] = contact;
  }
  // Face contacts: the journal base facing bearing base X lies beyond X's plane.
  for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
    const Vector3 normal_W = outward_sign(base) * s.bearing_axis_hat_W;
    const Vector3& p_WBj = journal_rim_center(s, base);
    const double beyond_base = (p_WBj - bearing_base(s, base)).dot(normal_W);
    bool face = false;
    Certificate face_certificate = tolerance_certificate;
    if (exactly_parallel) {
      if (clear.axial[base == ContactBase::a ? 0 : 1]) {
        face = false;
        face_certificate = proved_clear;
      } else {
        const CirclePlaneIntersection hit = rim_against_base(s, base, options);
        face = hit.topology == CirclePlaneTopology::disjoint && hit.side == PlaneSide::positive;
        face_certificate = hit.certificate;
      }
    } else {
      face = beyond_base > 0.0;
    }
    certificate.add(face_certificate);
    if (!face) continue;
    (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
    Contact contact;
    contact.type = ContactType::axial;
    contact.base = base;
    contact.certificate = face_certificate;
    contact.normal_W = normal_W;
    contact.p_WCj = p_WBj;                               // eq. (10)
    contact.p_WCi = p_WBj - beyond_base * normal_W;      // eq. (9)
    contact.depth = std::max(0.0, beyond_base);          // eq. (23)
    const int k = base == ContactBase::a ? 0 : 1;
    set_plane_contact_errors(p_WBj, s.journal_rim_errors[k], bearing_base(s, base), s.bearing_base_errors[k],
                             beyond_base, face_certificate, contact);
    compare_with_clearance(contact, s.axial_clearance, presence, beyond);
    out.contacts[out.contact_count++] = contact;
  }
}

/// Back from the bearing-centred frame of set_up: each translated point is rounded once more,
/// by at most half an ulp per component, u |x|_1 in length (|x|_1 rather than |x|, whose square
/// overflows beyond 1e154).
void translate_to_world(const Vector3& p_WPi, JointContacts& out) {
  // Exactly zero: Eigen's isZero() is fuzzy (|x| <= 1e-12), which skipped the translation of a
  // whole joint smaller than that.
  if ((p_WPi.array() == 0.0).all()) return;
  constexpr double kTranslationRounding = 2 * detail::kUnitRoundoff;  // > u, rounded up
  for (int i = 0; i < out.contact_count; ++i) {
    Contact& contact = out.contacts[i];
    contact.p_WCj += p_WPi;
    contact.p_WCi += p_WPi;
    contact.p_WCj_error += kTranslationRounding * contact.p_WCj.cwiseAbs().sum();
    contact.p_WCi_error += kTranslationRounding * contact.p_WCi.cwiseAbs().sum();
    for (int k = 0; k < contact.crossing_count; ++k) {
      RimCrossing& crossing = contact.crossings[k];
      crossing.point += p_WPi;
      crossing.point_error += kTranslationRounding * crossing.point.cwiseAbs().sum();
    }
  }
}

/// Whether every number of `contact` that a certificate vouches for is a finite double.
bool representable(const Contact& contact) {
  bool finite = std::isfinite(contact.depth) & std::isfinite(contact.depth_error) &
                std::isfinite(contact.p_WCj_error) & std::isfinite(contact.p_WCi_error) &
                contact.p_WCj.allFinite() & contact.p_WCi.allFinite();
  for (int k = 0; k < contact.crossing_count; ++k) {
    const RimCrossing& crossing = contact.crossings[k];
    finite &= crossing.point.allFinite() & std::isfinite(crossing.point_error);
  }
  return finite;
}

/// A contact whose points, depth or bounds overflowed (on the way, or in the translation back)
/// is no longer an answer that a certificate can cover: it becomes uncertain, with infinite
/// bounds, and so does the whole answer. Its existence was decided all the same.
void withdraw_unrepresentable(JointContacts& out) {
  for (int i = 0; i < out.contact_count; ++i) {
    Contact& contact = out.contacts[i];
    if (contact.certificate.level == Certainty::uncertain || representable(contact)) continue;
    contact.certificate = {Certainty::uncertain, kNotRepresentableInWorld};
    contact.p_WCj_error = contact.p_WCi_error = contact.depth_error = kNoErrorBound;
    for (int k = 0; k < contact.crossing_count; ++k) contact.crossings[k].point_error = kNoErrorBound;
    out.certificate = {Certainty::uncertain, kNotRepresentableInWorld};
  }
}

#if defined(__clang__)
/// A default JointContacts, copied into each fresh answer under Clang (below).
const JointContacts& default_joint_contacts() {
  static const JointContacts defaults{};
  return defaults;
}
#endif

}  // namespace

JointContacts detect_contacts(const JointDimensions& dimensions, const PartPose& bearing,
                              const PartPose& journal, const DetectionOptions& options) {
  // A fresh answer's defaults are not all zero bits (the error bounds' infinities, the
  // certificates' `uncertain`). GCC 12 writes them as some hundred plain stores. Clang 14 writes
  // a memset of the whole 1.4 KB and then those stores over it, a sizeable part of a free-flight
  // detection; a copy of a default instance avoids the memset. Under GCC the copy is the slower
  // of the two (bench_detect_contacts, free flight, side by side).
#if defined(__clang__)
  JointContacts out = default_joint_contacts();
#else
  JointContacts out;
#endif
  detect_contacts(dimensions, bearing, journal, out, options);
  return out;
}

void detect_contacts(const JointDimensions& dimensions, const PartPose& bearing,
                     const PartPose& journal, JointContacts& out, const DetectionOptions& options) {
  // Every field the answer consists of is (re)set; contacts past contact_count are left alone.
  // The accepted range first: the prefilter's guard below implies the rest of validation, not it.
  if (!detail::lengths_in_range(dimensions, bearing, journal)) [[unlikely]] {
    validate(dimensions);
    validate(bearing, "bearing");
    validate(journal, "journal");
  }
  Prefilter prefilter;
  prefilter_if_ready(dimensions, bearing, journal, options, prefilter);
  if (prefilter.ready) {
    if (prefilter.no_contact) {
      // Proved by the prefilters alone: what the general path below answers then (its
      // certificates all clear_certificate, no contact, nothing to translate).
      out.contact_count = 0;
      out.aligned = prefilter.exactly_parallel;
      out.scenario = ContactScenario::none;
      out.certificate = clear_certificate(options);
      return;
    }
  } else {
    // The inline tests first: validate() formats its message and is out of line.
    if (!detail::passes_validation(dimensions)) validate(dimensions);
    if (!detail::passes_validation(bearing)) validate(bearing, "bearing");
    if (!detail::passes_validation(journal)) validate(journal, "journal");
    validate(options);
  }
  const JointSetup setup =
      prefilter.ready ? set_up(dimensions, bearing, journal, prefilter) : set_up(dimensions, bearing, journal);

  out.contact_count = 0;
  ContactPresence presence;
  BeyondModelEvidence beyond;
  CertificateAccumulator certificate;
  const bool exactly_parallel =
      prefilter.ready ? prefilter.exactly_parallel : axes_exactly_parallel(bearing.axis_W, journal.axis_W);
  bool aligned = exactly_parallel;
  if (!aligned && options.parallel_angle_tolerance > 0.0) {
    // |a_i_hat x a_j_hat| = sin(angle between the lines), compared in double.
    const double sine = setup.bearing_axis_hat_W.cross(setup.journal_axis_hat_W).norm();
    aligned = sine <= std::sin(options.parallel_angle_tolerance);
  }
  out.aligned = presence.aligned = aligned;
  const detail::CandidatesClear* prefiltered = prefilter.ready ? &prefilter.clear : nullptr;
  if (aligned) {
    detect_aligned(setup, options, exactly_parallel, prefiltered, out, presence, beyond, certificate);
  } else {
    detect_misaligned(setup, options, prefiltered, out, presence, beyond, certificate);
  }
  if (beyond.undecided && !beyond.proved) certificate.add({Certainty::uncertain, kBeyondModelUndecided});
  out.scenario = classify_scenario(presence);
  out.certificate = certificate.result();
  translate_to_world(bearing.p_WP, out);
  withdraw_unrepresentable(out);
}

}  // namespace clearjoint::geometry
