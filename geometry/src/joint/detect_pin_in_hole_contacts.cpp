// SPDX-License-Identifier: BSD-3-Clause
// Contact detection in the pin-in-hole joint: the kernel's two queries with the roles of the
// paper's joint turned around (docs/contact-detection.md, "The pin-in-hole joint").
//
// Every centre a query needs (a hole edge centre P_i +- (L/2) a_i_hat, a stop centre
// P_j + s a_j_hat) is a RoundedPoint (rounded_point.hpp) in a frame whose origin is the other
// query primitive's point: the edges against the pin in a frame at the pin's point P_j (the pin's
// axis point is then exactly 0), the stops and the link faces in a frame at the hole's centre P_i.
// So every certified or exact answer is about the joint the input numbers define, as for
// detect_contacts. The contacts are moved back to the world frame at the end, with the rounding
// of that translation added to their bounds.

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "arithmetic/a_priori_bounds.hpp"
#include "arithmetic/error_bounded.hpp"
#include "arithmetic/rounded_point.hpp"
#include "arithmetic/scale_normalisation.hpp"
#include "exact/parallel_axes_exact.hpp"
#include "model/input_checks.hpp"
#include "model/primitives_detail.hpp"
#include "queries/rounded_point_queries.hpp"

namespace clearjoint::geometry {
namespace {

using detail::kUnitRoundoff;

/// The factor on u of the a priori bounds below. Each bounded quantity is at most a dozen
/// rounded operations deep (a dot product, a quotient, a cross product and a norm), so its
/// relative error is at most about 12u of the magnitudes involved (Higham, Lemma 3.3), the unit
/// axes being within 2u of a/|a|; 64 leaves a factor of five for what the count leaves out (the
/// magnitudes of intermediates, up to twice those named). Used only by the prefilters and the
/// pin-through-hole test, whose margins are of the order of the clearance, not of these bounds.
constexpr double kAPrioriFactor = 64.0;
/// A rim point evaluated by point_at: centre + r (cos u + sin v), with u, v and the sine and
/// cosine each within a few ulps (primitives.hpp): within 16u of |centre|_1 + 2 r (a factor of
/// two above the count of roundings).
constexpr double kPointEvaluationFactor = 16.0;
/// The deepest direction of a circle wholly beyond a plane, (n - (n . c) c) . (u, v) from the unit
/// normals n, c (within 2u and 3u of exact) and the rim frame u, v (a few ulps from the exact
/// frame), every magnitude at most 1: the inputs' 5u, 8u for the dot product and its product
/// with c, a few u for the subtraction and each projection, so within about 25u a component and
/// 35u as a vector (Higham, Lemma 3.3); kAPrioriFactor u = 64u leaves a factor of almost two.
constexpr double kDeepestDirectionError = kAPrioriFactor * kUnitRoundoff;
/// The rounding of n_A . n_B beyond the normals' own bounds: each unit normal w / |w| is within
/// about 3u of the direction of the computed w (a norm and a quotient), and the dot product of two
/// vectors of length ~1 adds 3u (Higham, eq. 3.5): 9u, rounded up to 16u.
constexpr double kNormalDotRounding = 16.0 * kUnitRoundoff;
/// A point's distance from a line, |a x ((x - c) x a)| with the unit axis a within 2u of the
/// exact direction: a difference, two cross products and a norm, about a dozen roundings of the
/// magnitudes |x|_1 + |c|_1 (Higham, Lemma 3.3), and the axis' 2u times |x - c|; kAPrioriFactor's
/// 64u leaves a factor of four. Used where a stop's contact is chosen (stop_against_face).
constexpr double kAxisDistanceFactor = kAPrioriFactor;

/// a*b == c*d in real arithmetic: Dekker's two-product in range, rationals otherwise.
bool products_equal(double a, double b, double c, double d) {
  if (detail::in_two_product_range(a) && detail::in_two_product_range(b) && detail::in_two_product_range(c) &&
      detail::in_two_product_range(d)) {
    return detail::exactly_equal_products(a, b, c, d);
  }
  return detail::exact_products_equal(a, b, c, d);
}

/// eq. (5) for the hole and the pin: a_i x a_j = 0 on the stored doubles, exactly. First the
/// floating-point filter (as detect_contacts'): a component of the cross product computed in
/// double is within gamma_64 of its absolute-value twin plus the products' underflow of the exact
/// one, so beyond that it is not zero and the axes are not parallel (every misaligned pose stops
/// there); otherwise each component exactly.
bool axes_exactly_parallel(const Vector3& a, const Vector3& b) {
  const Vector3 cross = a.cross(b);
  const Vector3 twin = detail::abs_cross(a.cwiseAbs(), b.cwiseAbs());
  constexpr double kProductUnderflow = 4 * detail::kUnderflowError;
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(cross[i]) > detail::kGamma64 * twin[i] * detail::kMagnitudeInflation + kProductUnderflow) {
      return false;
    }
  }
  return products_equal(a.y(), b.z(), a.z(), b.y()) && products_equal(a.z(), b.x(), a.x(), b.z()) &&
         products_equal(a.x(), b.y(), a.y(), b.x());
}

/// What the detection knows about the joint, in the world frame but for the offsets.
struct Setup {
  double hole_radius = 0.0;
  double half_length = 0.0;
  double pin_radius = 0.0;
  Vector3 p_WPi = Vector3::Zero();
  Vector3 p_WPj = Vector3::Zero();
  Vector3 hole_axis = Vector3::UnitZ();  // as given: the circles' and planes' normals
  Vector3 pin_axis = Vector3::UnitZ();
  Vector3 hole_hat = Vector3::UnitZ();   // unit_axis: the centres' definition
  Vector3 pin_hat = Vector3::UnitZ();
  /// +1 when the pin's axis points through face A (a_i . a_j > 0), -1 otherwise.
  int toward_a = 1;
  double cosine = 1.0;  // |a_i_hat . a_j_hat|
  double sine = 0.0;    // |a_i_hat x a_j_hat|
};

/// Index of a face: 0 for A (the one a_i points to), 1 for B.
constexpr int kFaceA = 0;
constexpr double face_sign(int face) { return face == kFaceA ? 1.0 : -1.0; }

/// The hole's edge centre at `face` in the frame at P_j (sign 0 with face -1: the mid-length centre).
detail::RoundedPoint edge_centre_from_pin(const Setup& s, int sign) {
  return detail::rounded_point(s.p_WPi, s.p_WPj, 2.0 * s.half_length, sign, s.hole_hat);
}
/// The same in the frame at P_i.
detail::RoundedPoint edge_centre_from_hole(const Setup& s, int sign) {
  return detail::rounded_point(Vector3::Zero(), Vector3::Zero(), 2.0 * s.half_length, sign, s.hole_hat);
}
/// A stop's centre P_j + s a_j_hat in the frame at P_i.
detail::RoundedPoint stop_centre_from_hole(const Setup& s, const AxialStop& stop) {
  return detail::rounded_point(s.p_WPj, s.p_WPi, 2.0 * std::fabs(stop.position), stop.position > 0.0 ? 1 : -1,
                               s.pin_hat);
}

/// Where the pin's axis meets the plane through c (frame at P_i) with normal a_i: its distance
/// rho from the hole's axis, with a bound on the error of its evaluation. Infinite when the axis
/// runs parallel to the plane.
struct AxisCrossing {
  double rho = 0.0;
  double error = 0.0;
};
/// The pin's axis x(t) = d_ji + t a_j_hat (d_ji = P_j - P_i) meets a_i_hat . x = c at
/// t = t_mid + c / (a_i_hat . a_j_hat), t_mid = -(a_i_hat . d_ji) / (a_i_hat . a_j_hat), and its
/// distance from the hole's axis is rho = |x(t) x a_i_hat| = |m + (c / dot) w| with
/// m = x(t_mid) x a_i_hat and w = a_j_hat x a_i_hat, formed once per joint.
struct AxisLine {
  double dot = 0.0;
  double t_mid = 0.0;
  Vector3 m = Vector3::Zero();
  Vector3 w = Vector3::Zero();
  double d_norm = 0.0;  // |d_ji|_1
};
AxisLine pin_axis_line(const Setup& s, const Vector3& d_ji) {
  AxisLine line;
  line.dot = s.hole_hat.dot(s.pin_hat);
  line.d_norm = d_ji.cwiseAbs().sum();
  if (line.dot == 0.0) return line;
  line.t_mid = -s.hole_hat.dot(d_ji) / line.dot;
  line.m = (d_ji + line.t_mid * s.pin_hat).cross(s.hole_hat);
  line.w = s.pin_hat.cross(s.hole_hat);
  return line;
}
AxisCrossing pin_axis_crossing(const AxisLine& line, double plane_offset) {
  if (line.dot == 0.0) return {std::numeric_limits<double>::infinity(), 0.0};
  const double shift = plane_offset / line.dot;
  const double rho = (line.m + shift * line.w).norm();
  const double scale = line.d_norm + std::fabs(plane_offset) + (std::fabs(line.t_mid) + std::fabs(shift)) * 2.0 + rho;
  return {rho, kAPrioriFactor * kUnitRoundoff * scale / std::fabs(line.dot)};
}

/// The contact's points and bounds moved from a frame at `origin` to the world frame: each
/// coordinate of the sum rounded once, |error| <= u |sum| componentwise, so the Euclidean error
/// grows by at most u |sum|_1 (times 1 + 4u for the rounding of the bound).
void to_world(const Vector3& origin, Contact& contact) {
  const auto move = [&origin](Vector3& point, double& error) {
    point += origin;
    error = (error + kUnitRoundoff * point.cwiseAbs().sum()) * (1 + 4 * kUnitRoundoff);
  };
  move(contact.p_WCj, contact.p_WCj_error);
  move(contact.p_WCi, contact.p_WCi_error);
  for (int k = 0; k < contact.crossing_count; ++k) move(contact.crossings[k].point, contact.crossings[k].point_error);
  const bool representable = std::isfinite(contact.p_WCj_error) && std::isfinite(contact.p_WCi_error) &&
                             std::isfinite(contact.depth_error) && detail::all_finite(contact.p_WCj) &&
                             detail::all_finite(contact.p_WCi);
  if (!representable && contact.certificate.level != Certainty::uncertain) {
    contact.certificate = {Certainty::uncertain, CertificateReason::contact_not_representable_in_world};
  }
  if (contact.certificate.level == Certainty::uncertain) {
    contact.p_WCj_error = contact.p_WCi_error = contact.depth_error = kNoErrorBound;
    for (int k = 0; k < contact.crossing_count; ++k) {
      contact.crossings[k].angle_error = contact.crossings[k].point_error = kNoErrorBound;
    }
  }
}

/// The largest angle error of a set of crossings (an arc's ends are among them).
template <class Crossings>
double largest_angle_error(const Crossings& crossings, int count) {
  double error = 0.0;
  for (int k = 0; k < count; ++k) error = std::max(error, crossings[k].angle_error);
  return error;
}

/// A hole circle point C_i (frame at P_j, its bound `point_error`) inside the pin: the contact's
/// pin point C_j = C_i pushed radially out from the pin's axis onto its surface, normal the
/// radial direction, depth Rp minus the distance of C_i from the axis (the edge's counterpart of
/// eqs. 19-23; the pin's axis passes through the origin of this frame). Returns a bound on how far
/// the computed unit normal lies from the exact one (the chord between them).
double radial_contact(const Setup& s, const Vector3& p_Ci, double point_error, Contact& contact) {
  // w = a x (C_i x a): C_i with its component along the axis removed, without the cancellation
  // of C_i - (C_i . a) a.
  const Vector3 w = s.pin_hat.cross(p_Ci.cross(s.pin_hat));
  const double distance = w.norm();
  const Vector3 normal = distance > 0.0 ? Vector3(w / distance) : Vector3(s.hole_hat.unitOrthogonal());
  const double evaluation = kAPrioriFactor * kUnitRoundoff * p_Ci.cwiseAbs().sum();
  contact.p_WCi = p_Ci;
  contact.p_WCi_error = point_error;
  contact.normal_W = normal;
  contact.depth = std::max(0.0, s.pin_radius - distance);
  contact.depth_error = point_error + evaluation + kUnitRoundoff * s.pin_radius;
  contact.p_WCj = p_Ci + contact.depth * normal;
  // The normal turns by at most (pi/2)(bound on w's error)/|w| (a displaced vector's direction),
  // which moves C_j, at distance Rp from the axis, by Rp times that.
  const double turn = distance > 0.0 ? 2.0 * (point_error + evaluation) / distance : kNoErrorBound;
  contact.p_WCj_error = point_error + contact.depth_error + s.pin_radius * turn +
                        kPointEvaluationFactor * kUnitRoundoff * (p_Ci.cwiseAbs().sum() + s.pin_radius);
  return turn;
}

/// The arcs of a hole circle strictly inside the pin: the complement of the query's arcs
/// strictly outside (its "penetration" arcs, which are the rim's when the circle is a journal
/// rim). Returns how many (0, 1 or 2).
int inside_arcs(const CircleCylinderIntersection& query, std::array<RimArc, 2>& arcs) {
  if (query.topology != CircleCylinderTopology::crossing) {
    if (query.topology == CircleCylinderTopology::inside) {
      arcs[0] = RimArc{0.0, 2 * std::numbers::pi, true};
      return 1;
    }
    return 0;
  }
  if (query.arc_count == 0) {
    arcs[0] = RimArc{0.0, 2 * std::numbers::pi, true};
    return 1;
  }
  if (query.arc_count == 1) {
    const RimArc& outside = query.penetration_arcs[0];
    if (outside.full) return 0;  // outside but for a touching point
    arcs[0] = RimArc{outside.end, outside.begin, false};
    return 1;
  }
  arcs[0] = RimArc{query.penetration_arcs[0].end, query.penetration_arcs[1].begin, false};
  arcs[1] = RimArc{query.penetration_arcs[1].end, query.penetration_arcs[0].begin, false};
  return 2;
}

/// What the answer accumulates besides its contacts.
struct Tally {
  Certificate certificate{Certainty::exact, CertificateReason::none};
  /// Beyond the model as computed: the answer's label, as detect_contacts' compare_with_clearance
  /// lets the computed depth label the paper's joint's answer.
  bool beyond = false;
  bool beyond_proved = false;     // beyond the model whatever the rounding
  bool beyond_undecided = false;  // a depth or crossing within its bound of its limit
  int radial = 0;
  int radial_at[2] = {0, 0};
  int axial = 0;
  bool line = false;
  int faces = 0;
  /// Per contact: a bound on the chord between its computed unit normal and the exact one
  /// (radial contacts; radial_contact's `turn`).
  std::array<double, kMaxPinInHoleContacts> normal_error{};
  void add(const Certificate& c) { certificate = weakest(certificate, c); }
  /// The computed depth above its limit labels the answer beyond the model; proved when the depth
  /// less its error is, undecided when the limit lies within the depth's error. An uncertain
  /// contact (the certificates switched off, or its query unproved) has no bound to prove
  /// anything with, and the answer is uncertain already (detect_contacts' compare_with_clearance).
  void check_depth(const Contact& contact, double limit) {
    beyond |= contact.depth > limit;
    if (contact.certificate.level == Certainty::uncertain) return;
    if (contact.depth - contact.depth_error > limit) {
      beyond_proved = true;
    } else if (contact.depth + contact.depth_error > limit) {
      beyond_undecided = true;
    }
  }
  /// Beyond the model by a decision the queries proved (or, uncertified, computed).
  void prove_beyond() { beyond = beyond_proved = true; }
};

Certificate proved(const DetectionOptions& options) {
  return options.intersection.certify ? Certificate{Certainty::certified, CertificateReason::none}
                                      : Certificate{Certainty::uncertain, CertificateReason::certificate_switched_off};
}

/// The hole's circle at `sign` (+1 face A, -1 face B, 0 mid-length) against the pin's lateral
/// surface: 0, 1 or 2 radial contacts, in the frame at P_j. `base` labels them.
void hole_circle_against_pin(const Setup& s, int sign, ContactBase base, const DetectionOptions& options,
                             PinInHoleContacts& out, Tally& tally) {
  const detail::RoundedPoint centre = edge_centre_from_pin(s, sign);
  // Valid inputs with scaled axes (detect_pin_in_hole_contacts checked and scaled them): the
  // query's answer without its checks, bit for bit.
  // The axes scaled by powers of two as the circle-cylinder query scales them
  // (scale_normalisation.hpp), here and not per joint: most poses run no such query.
  const Circle3 circle{centre.value, detail::direction_scaled(s.hole_axis), s.hole_radius};
  const Cylinder3 pin{Vector3::Zero(), detail::direction_scaled(s.pin_axis), s.pin_radius};
  const CircleCylinderIntersection query =
      detail::intersect_valid_circle_cylinder(circle, pin, options.intersection, &centre);
  tally.add(query.certificate);
  std::array<RimArc, 2> arcs;
  const int count = inside_arcs(query, arcs);
  if (query.topology == CircleCylinderTopology::inside || count == 2) tally.prove_beyond();
  const CircleFrame frame = frame_of(circle);
  const double angle_error = largest_angle_error(query.crossings, query.crossing_count);
  for (int k = 0; k < count && out.contact_count < kMaxPinInHoleContacts; ++k) {
    // A fresh slot: out's contacts are default-constructed and each slot is filled once.
    Contact& contact = out.contacts[out.contact_count++];
    contact.type = ContactType::radial;
    contact.base = base;
    contact.certificate = query.certificate;
    const Vector3 p_Ci = point_at(circle, frame, arcs[k].middle());
    const double point_error =
        arcs[k].full ? 2.0 * s.hole_radius + centre.error
                     : centre.error + s.hole_radius * angle_error +
                           kPointEvaluationFactor * kUnitRoundoff * (centre.value.cwiseAbs().sum() + 2.0 * s.hole_radius);
    tally.normal_error[out.contact_count - 1] = radial_contact(s, p_Ci, point_error, contact);
    // The crossings bounding this arc: its two ends.
    for (int c = 0; c < query.crossing_count && contact.crossing_count < 2; ++c) {
      const double angle = query.crossings[c].angle;
      if (angle == arcs[k].begin || angle == arcs[k].end) contact.crossings[contact.crossing_count++] = query.crossings[c];
    }
    tally.check_depth(contact, s.hole_radius - s.pin_radius);
    ++tally.radial;
    if (base != ContactBase::mid) ++tally.radial_at[base == ContactBase::a ? 0 : 1];
    if (base == ContactBase::mid) tally.line = true;
  }
}

/// The face of the link a stop looks at: the stop at a positive position is on the side the pin's
/// axis points to, which is face A when a_i . a_j > 0.
int face_of(const Setup& s, const AxialStop& stop) { return (stop.position > 0.0) == (s.toward_a > 0) ? 0 : 1; }

/// A point contact of a stop against its face, filled from a circle-plane answer that has a
/// penetration arc: `on_pin` when the circle is the stop's (C_j the arc middle, C_i its projection
/// on the face), otherwise the circle is the hole's edge (C_i the arc middle, C_j its projection
/// on the stop's plane). `normal` is the unit direction the pin penetrates. Frame at P_i.
/// `contact` is a fresh (default-constructed) slot.
void stop_contact(const Circle3& circle, const detail::RoundedPoint& centre, const CirclePlaneIntersection& query,
                  bool on_pin, const Vector3& normal, ContactBase base, Contact& contact) {
  contact.type = ContactType::axial;
  contact.base = base;
  contact.certificate = query.certificate;
  contact.normal_W = normal;
  contact.depth = std::max(0.0, query.max_signed_distance);
  contact.depth_error = query.max_signed_distance_error;
  const CircleFrame frame = frame_of(circle);
  double angle = query.penetration.middle();
  double point_error = 0.0;
  if (query.penetration.full) {
    // The whole circle beyond (a stop nearly flush on a tilted pin): its deepest point, where the
    // plane normal's part in the circle's plane points (eq. 14's theta_m, which is also the middle
    // of a penetration arc, so the contact moves continuously as the circle comes to lie beyond).
    const Vector3 n_hat = circle.normal.normalized();
    const Vector3 toward = on_pin ? normal : Vector3(-normal);
    const Vector3 in_plane = toward - toward.dot(n_hat) * n_hat;
    const double along_u = in_plane.dot(frame.u);
    const double along_v = in_plane.dot(frame.v);
    const double length = std::hypot(along_u, along_v);
    angle = length == 0.0 ? 0.0 : std::atan2(along_v, along_u);
    // (along_u, along_v) is within kDeepestDirectionError of its exact value; a vector of length
    // l displaced by e < l turns by at most asin(e / l) <= (pi/2) e / l. Where that reaches pi
    // (axes parallel to within rounding) any circle point is within the diameter of the deepest.
    const double turn = length > 2.0 * kDeepestDirectionError ? 2.0 * kDeepestDirectionError / length
                                                              : std::numbers::pi;
    point_error = turn >= std::numbers::pi
                      ? 2.0 * circle.radius + centre.error
                      : centre.error + circle.radius * turn +
                            kPointEvaluationFactor * kUnitRoundoff * (centre.value.cwiseAbs().sum() + 2.0 * circle.radius);
  } else {
    point_error = centre.error + circle.radius * largest_angle_error(query.crossings, query.crossing_count) +
                  kPointEvaluationFactor * kUnitRoundoff * (centre.value.cwiseAbs().sum() + 2.0 * circle.radius);
  }
  const Vector3 point = point_at(circle, frame, angle);
  const Vector3 other = on_pin ? Vector3(point - contact.depth * normal) : Vector3(point + contact.depth * normal);
  const double moved = point_error + contact.depth_error +
                       kPointEvaluationFactor * kUnitRoundoff * (point.cwiseAbs().sum() + contact.depth);
  contact.p_WCj = on_pin ? point : other;
  contact.p_WCi = on_pin ? other : point;
  contact.p_WCj_error = on_pin ? point_error : moved;
  contact.p_WCi_error = on_pin ? moved : point_error;
  for (int c = 0; c < query.crossing_count; ++c) contact.crossings[contact.crossing_count++] = query.crossings[c];
}

/// A point's distance from a line through `through` along the unit `axis`,
/// |axis x ((x - through) x axis)|, and a bound on its evaluation besides the errors of the point
/// and of the line's point: kAxisDistanceFactor u of the magnitudes involved.
struct BoundedDistance {
  double value = 0.0;
  double error = 0.0;
};
BoundedDistance distance_from_line(const Vector3& point, const Vector3& through, double through_scale,
                                   const Vector3& axis) {
  const Vector3 offset = point - through;
  return {axis.cross(offset.cross(axis)).norm(),
          kAxisDistanceFactor * kUnitRoundoff * (point.cwiseAbs().sum() + through.cwiseAbs().sum() + through_scale)};
}

/// Which side of `limit` a computed distance lies: `above` as computed, which labels the answer
/// (and decides alone when there is no bound to prove it with, as check_depth lets the computed
/// depth decide), and whether the bound `error` proves that side.
struct Side {
  bool above = false;
  bool proved = true;
};
Side side_of(double value, double error, double limit, bool certify) {
  Side side{value > limit, true};
  if (certify) side.proved = value - error > limit || value + error < limit;
  return side;
}

/// The misaligned stop at `stop` against its face (docs/contact-detection.md, "Stop against face
/// X"). The stop's depth into the link is linear over its plane and the contact region is its face
/// disk less the hole, so the contact is bounded by:
///  (1) the outer circle's deepest point m (eq. 14) when m lies outside the bore, even if other
///      parts of the circle lie over the hole: m is the disk's maximum and lies in the region;
///  (2) otherwise the hole's edge's deepest point q into the head (the edge against the stop's
///      plane, normal into the head) when q lies within Ro of the pin's axis: the disk's maximum
///      lying over the hole, the region's is where the edge bounds it;
///  (3) otherwise a corner where the outer circle meets the hole's edge, beyond the model: the
///      outer circle's contact as computed (or the edge's when it reaches into the head).
/// Each choice compares a computed distance and its bound with Rh or Ro; within the bound the
/// computed value chooses, and the answer is uncertain: beyond_model_undecided when the choice
/// decides between (3) and an ordinary contact. Frame at P_i.
void stop_against_face(const Setup& s, const AxialStop& stop, double axial_limit, const DetectionOptions& options,
                       PinInHoleContacts& out, Tally& tally) {
  const int face = face_of(s, stop);
  const ContactBase base = face == kFaceA ? ContactBase::a : ContactBase::b;
  const Vector3 into_link = -face_sign(face) * s.hole_axis;      // the face plane's normal
  const Vector3 into_link_hat = -face_sign(face) * s.hole_hat;
  const detail::RoundedPoint centre = stop_centre_from_hole(s, stop);
  const detail::RoundedPoint face_point = edge_centre_from_hole(s, face == kFaceA ? 1 : -1);
  const Circle3 outer{centre.value, s.pin_axis, stop.outer_radius};
  const CirclePlaneIntersection query =
      detail::intersect_circle_plane(outer, Plane3{face_point.value, into_link}, options.intersection, &centre, &face_point);
  tally.add(query.certificate);
  if (!query.has_penetration) return;
  if (out.contact_count >= kMaxPinInHoleContacts) return;
  Contact& contact = out.contacts[out.contact_count++];
  stop_contact(outer, centre, query, true, into_link_hat, base, contact);
  // (1) First without m: is the whole outer circle outside the bore? The hole's axis crosses the
  // stop's plane at X0 = t a_i_hat, t = (S . a_j_hat) / (a_i_hat . a_j_hat), and every point x of
  // the circle, x - X0 lying in the plane, is at least (Ro - |S - X0|) |cos(a_i, a_j)| from the
  // hole's axis (the edge prefilter's argument with the roles exchanged). This decides the
  // common case, and the one where m is not defined by the doubles (the axes parallel to within
  // rounding, the circle beyond the face all round).
  const double t = centre.value.dot(s.pin_hat) / s.hole_hat.dot(s.pin_hat);
  const double rho = (centre.value - t * s.hole_hat).norm();
  const double reach_error = centre.error + kAPrioriFactor * kUnitRoundoff *
                                                (centre.value.cwiseAbs().sum() + std::fabs(t) + rho + stop.outer_radius) /
                                                s.cosine;
  if ((stop.outer_radius - rho) * s.cosine - reach_error > s.hole_radius) {
    tally.check_depth(contact, axial_limit);
    ++tally.axial;
    return;
  }
  // Then m against the bore: the hole's axis passes through this frame's origin.
  const BoundedDistance m = distance_from_line(contact.p_WCj, Vector3::Zero(), 0.0, s.hole_hat);
  const Side m_outside = side_of(m.value, m.error + contact.p_WCj_error, s.hole_radius,
                                 contact.certificate.level != Certainty::uncertain);
  if (m_outside.above && m_outside.proved) {
    tally.check_depth(contact, axial_limit);
    ++tally.axial;
    return;
  }
  // (2) q against the head's rim: the pin's axis through the stop's centre S = P_j + s a_j_hat,
  // which lies within 2u |s| of the exact axis (a_j_hat's rounding), hence |s| in the scale.
  const double head_side = stop.position > 0.0 ? 1.0 : -1.0;
  const Circle3 edge{face_point.value, s.hole_axis, s.hole_radius};
  const CirclePlaneIntersection edge_query = detail::intersect_circle_plane(
      edge, Plane3{centre.value, head_side * s.pin_axis}, options.intersection, &face_point, &centre);
  tally.add(edge_query.certificate);
  Contact edge_contact;
  Side q_beyond_rim;  // no penetration: q is nowhere in the head
  q_beyond_rim.above = true;
  if (edge_query.has_penetration) {
    stop_contact(edge, face_point, edge_query, false, -head_side * s.pin_hat, base, edge_contact);
    edge_contact.certificate = weakest(query.certificate, edge_query.certificate);
    const BoundedDistance q = distance_from_line(edge_contact.p_WCi, centre.value, std::fabs(stop.position), s.pin_hat);
    q_beyond_rim = side_of(q.value, q.error + edge_contact.p_WCi_error + centre.error, stop.outer_radius,
                           edge_contact.certificate.level != Certainty::uncertain);
  }
  // (2), and (3) where the edge reaches into the head, report the edge's contact; (3) with the
  // edge nowhere in the head keeps the outer circle's.
  const bool at_corner = !m_outside.above && q_beyond_rim.above;
  if (!m_outside.above && edge_query.has_penetration) {
    contact = edge_contact;
  } else if (at_corner) {
    contact.certificate = weakest(query.certificate, edge_query.certificate);
  }
  // Which choices the bounds leave open: m either side of Rh unless proved, q likewise of Ro.
  const bool m_may_be_over_hole = !m_outside.above || !m_outside.proved;
  const bool q_may_be_within = edge_query.has_penetration && (!q_beyond_rim.above || !q_beyond_rim.proved);
  const bool q_may_be_beyond = q_beyond_rim.above || !q_beyond_rim.proved;
  const bool corner_possible = m_may_be_over_hole && q_may_be_beyond;
  const bool ordinary_possible = m_outside.above || !m_outside.proved || (m_may_be_over_hole && q_may_be_within);
  if (at_corner) tally.beyond = true;
  if (corner_possible && ordinary_possible) {
    tally.beyond_undecided = true;
  } else if (at_corner) {
    tally.prove_beyond();
  } else if (!m_outside.proved) {
    // (1) or (2), both ordinary: where the choice turns, m lies on the bore with q within the
    // rim, the outer circle seen along the hole's axis touching the hole's edge (a tangency).
    // The label stands; the contact (at m or at q, t delta apart) is not proved.
    contact.certificate = weakest(contact.certificate,
                                  {Certainty::uncertain, CertificateReason::interval_proof_failed_near_multiple_root});
  }
  tally.check_depth(contact, axial_limit);
  ++tally.axial;
}

/// The aligned stop: a face contact when its outer circle has points beyond the face plane (with
/// exactly parallel axes: the whole circle, flush beyond the face). C_j is the stop's centre
/// (as eq. 10 takes the journal base centre), C_i its projection on the face. Frame at P_i.
void stop_flush_on_face(const Setup& s, const AxialStop& stop, double axial_limit, const DetectionOptions& options,
                        PinInHoleContacts& out, Tally& tally) {
  const int face = face_of(s, stop);
  const Vector3 into_link = -face_sign(face) * s.hole_axis;
  const Vector3 into_link_hat = -face_sign(face) * s.hole_hat;
  const detail::RoundedPoint centre = stop_centre_from_hole(s, stop);
  const detail::RoundedPoint face_point = edge_centre_from_hole(s, face == kFaceA ? 1 : -1);
  const Circle3 outer{centre.value, s.pin_axis, stop.outer_radius};
  const CirclePlaneIntersection query =
      detail::intersect_circle_plane(outer, Plane3{face_point.value, into_link}, options.intersection, &centre, &face_point);
  tally.add(query.certificate);
  if (!query.has_penetration || out.contact_count >= kMaxPinInHoleContacts) return;
  Contact& contact = out.contacts[out.contact_count++];  // a fresh slot
  contact.type = ContactType::axial;
  contact.base = face == kFaceA ? ContactBase::a : ContactBase::b;
  contact.certificate = query.certificate;
  contact.normal_W = into_link_hat;
  contact.depth = std::max(0.0, query.max_signed_distance);
  contact.depth_error = query.max_signed_distance_error;
  contact.p_WCj = centre.value;
  contact.p_WCj_error = centre.error;
  contact.p_WCi = centre.value - contact.depth * into_link_hat;
  contact.p_WCi_error = centre.error + contact.depth_error +
                        kPointEvaluationFactor * kUnitRoundoff * (centre.value.cwiseAbs().sum() + contact.depth);
  tally.check_depth(contact, axial_limit);
  ++tally.axial;
  ++tally.faces;
}

/// The edge prefilter: every point x of the hole's circle at `sign` is at least
/// (Rh - rho) |cos(a_i, a_j)| from the pin's axis, rho the distance from the circle's centre at
/// which that axis crosses the circle's plane (x - X0 lies in the plane, whose normal makes the
/// angle with the axis). When that exceeds Rp with a margin for the evaluation, the edge is
/// proved clear of the pin.
bool edge_proved_clear(const Setup& s, const AxisCrossing& crossing) {
  const double reach = (s.hole_radius - crossing.rho) * s.cosine;
  const double error = crossing.error + kAPrioriFactor * kUnitRoundoff * (s.hole_radius + crossing.rho);
  return reach - error > s.pin_radius;
}

/// The stop prefilter: the stop's outer circle reaches at most |s_c| + Ro sin(a_i, a_j) from
/// its centre's signed distance s_c beyond the face plane (into the link). d_norm is |d_ji|_1.
bool stop_proved_clear(const Setup& s, const Vector3& d_ji, double d_norm, const AxialStop& stop) {
  const int face = face_of(s, stop);
  const Vector3 stop_centre = d_ji + stop.position * s.pin_hat;
  const double beyond = -face_sign(face) * s.hole_hat.dot(stop_centre) + s.half_length;
  const double reach = beyond + stop.outer_radius * s.sine;
  const double error = kAPrioriFactor * kUnitRoundoff *
                       (d_norm + std::fabs(stop.position) + s.half_length + stop.outer_radius);
  return reach + error < 0.0;
}

/// Whether validate() would pass, without formatting anything: a subset of its tests that
/// implies the rest, so that a false here sends the caller to validate() for the message.
bool passes_validation(const PinInHoleDimensions& d) {
  // length_in_range fails NaN and infinities; positivity and the order Rp < Rh are tested apart.
  bool ok = detail::length_in_range(d.hole_radius) & detail::length_in_range(d.hole_length) &
            detail::length_in_range(d.pin_radius) & (d.pin_radius > 0.0) & (d.hole_length > 0.0) &
            (d.pin_radius < d.hole_radius) & (d.stop_count >= 0) & (d.stop_count <= kMaxAxialStops);
  if (!ok) return false;
  const double half_length = 0.5 * d.hole_length;
  for (int k = 0; k < d.stop_count; ++k) {
    const AxialStop& stop = d.stops[static_cast<std::size_t>(k)];
    ok = ok & detail::length_in_range(stop.position) & (stop.position > half_length || stop.position < -half_length) &
         detail::length_in_range(stop.outer_radius) & (stop.outer_radius > d.hole_radius);
  }
  if (d.stop_count == 2) ok = ok & ((d.stops[0].position > 0.0) != (d.stops[1].position > 0.0));
  return ok;
}

/// Whether the sign of n_A . n_B that labels two edge contacts (classify) is that of the exact
/// normals: |n_A . n_B| above the normals' chord bounds plus the dot's rounding. At right angles
/// the label is not proved.
bool edge_sides_proved(const PinInHoleContacts& out, const Tally& tally) {
  const double facing = out.contacts[0].normal_W.dot(out.contacts[1].normal_W);
  const double bound = (tally.normal_error[0] + tally.normal_error[1]) * (1 + 4 * kUnitRoundoff) + kNormalDotRounding;
  return std::fabs(facing) > bound;
}

PinInHoleScenario classify(const PinInHoleContacts& out, const Tally& tally) {
  if (tally.beyond) return PinInHoleScenario::beyond_model;
  if (out.aligned) {
    if (tally.faces > 1) return PinInHoleScenario::beyond_model;
    if (tally.line) return tally.faces == 1 ? PinInHoleScenario::line_and_face : PinInHoleScenario::line;
    return tally.faces == 1 ? PinInHoleScenario::face : PinInHoleScenario::none;
  }
  if (tally.radial > 0 && tally.axial > 0) return PinInHoleScenario::edges_and_stops;
  if (tally.axial > 0) return tally.axial == 1 ? PinInHoleScenario::one_stop : PinInHoleScenario::both_stops;
  if (tally.radial == 1) return PinInHoleScenario::one_edge;
  if (tally.radial == 2) {
    // One contact at each edge (two at one edge is beyond the model): at opposite sides of the pin
    // when their radial normals point apart (edge_sides_proved decides whether that is proved).
    return out.contacts[0].normal_W.dot(out.contacts[1].normal_W) < 0.0 ? PinInHoleScenario::both_edges_opposite
                                                                       : PinInHoleScenario::both_edges_same_side;
  }
  return PinInHoleScenario::none;
}

}  // namespace

PinInHoleContacts detect_pin_in_hole_contacts(const PinInHoleDimensions& dimensions, const PartPose& hole,
                                              const PartPose& pin, const DetectionOptions& options) {
  // The inline tests first: validate() formats its message and is out of line, and the checks
  // run on every call.
  if (!passes_validation(dimensions)) validate(dimensions);
  // The poses' test is detect_contacts' (primitives_detail.hpp): bitwise, one branch each.
  if (!detail::passes_validation(hole)) validate(hole, "hole");
  if (!detail::passes_validation(pin)) validate(pin, "pin");
  if (!(options.parallel_angle_tolerance == 0.0)) validate(options);

  Setup s;
  s.hole_radius = dimensions.hole_radius;
  s.half_length = 0.5 * dimensions.hole_length;
  s.pin_radius = dimensions.pin_radius;
  s.p_WPi = hole.p_WP;
  s.p_WPj = pin.p_WP;
  s.hole_axis = hole.axis_W;
  s.pin_axis = pin.axis_W;
  s.hole_hat = unit_axis(hole);
  s.pin_hat = unit_axis(pin);
  const double dot = s.hole_hat.dot(s.pin_hat);
  s.toward_a = dot >= 0.0 ? 1 : -1;
  s.cosine = std::fabs(dot);
  s.sine = s.hole_hat.cross(s.pin_hat).norm();
  // The axial limit of the model: the axial clearance with two stops, half the hole's length
  // (the stop's face at the link's mid-plane) with one.
  const double axial_limit = dimensions.stop_count == 2 ? dimensions.axial_clearance() : s.half_length;

  PinInHoleContacts out;
  Tally tally;
  const Certificate clear = proved(options);
  tally.add(clear);
  const bool exactly_parallel = axes_exactly_parallel(hole.axis_W, pin.axis_W);
  bool aligned = exactly_parallel;
  if (!aligned && options.parallel_angle_tolerance > 0.0) {
    // |a_i_hat x a_j_hat| = sin(angle between the lines), compared in double, as detect_contacts.
    aligned = s.sine <= std::sin(options.parallel_angle_tolerance);
  }
  out.aligned = aligned;

  // Does the pin's axis pass through the hole? At the hole's mid-plane it must lie within Rh of
  // the hole's axis; the two answers are at least Rp apart from a wrong one whenever the pin's
  // section misses the hole's circle, and the undecided band is the evaluation's bound. The
  // computed crossing labels the answer, as a computed depth does (check_depth); the bound proves
  // the label or leaves it undecided.
  const Vector3 d_ji = s.p_WPj - s.p_WPi;
  const double d_ji_error = detail::difference_rounding_bound(d_ji);
  const AxisLine axis_line = pin_axis_line(s, d_ji);
  const AxisCrossing mid = pin_axis_crossing(axis_line, 0.0);
  const double crossing_shift = d_ji_error / std::max(s.cosine, 1e-300);  // d_ji's rounding at any plane
  const double mid_error = mid.error + crossing_shift;
  tally.beyond |= !(mid.rho < s.hole_radius);
  if (options.intersection.certify && !(mid.rho + mid_error < s.hole_radius)) {
    if (mid.rho - mid_error >= s.hole_radius) {
      tally.beyond_proved = true;
    } else {
      tally.beyond_undecided = true;
    }
  }

  if (aligned) {
    // The line contact: the hole's mid-length circle against the pin. Clear when the pin's axis
    // lies within Rh - Rp of the hole's (at the mid-plane, with the evaluation's bound).
    if (!(mid.rho + mid_error < s.hole_radius - s.pin_radius) || !exactly_parallel) {
      hole_circle_against_pin(s, 0, ContactBase::mid, options, out, tally);
    }
    for (int k = 0; k < dimensions.stop_count; ++k) {
      const AxialStop& stop = dimensions.stops[static_cast<std::size_t>(k)];
      if (exactly_parallel && stop_proved_clear(s, d_ji, axis_line.d_norm, stop)) continue;
      stop_flush_on_face(s, stop, axial_limit, options, out, tally);
    }
  } else {
    for (const int sign : {1, -1}) {
      const AxisCrossing at_face = pin_axis_crossing(axis_line, sign * s.half_length);
      const AxisCrossing bounded{at_face.rho, at_face.error + crossing_shift};
      if (edge_proved_clear(s, bounded)) continue;
      hole_circle_against_pin(s, sign, sign > 0 ? ContactBase::a : ContactBase::b, options, out, tally);
    }
    // Stops: face A's before face B's (two stops face opposite faces, validate()).
    const int count = dimensions.stop_count;
    const int first = count == 2 && face_of(s, dimensions.stops[0]) != kFaceA ? 1 : 0;
    for (int n = 0; n < count; ++n) {
      const AxialStop& stop = dimensions.stops[static_cast<std::size_t>(n == 0 ? first : 1 - first)];
      if (stop_proved_clear(s, d_ji, axis_line.d_norm, stop)) continue;
      stop_against_face(s, stop, axial_limit, options, out, tally);
    }
  }
  if (aligned && !exactly_parallel) {
    const Certificate relaxed{Certainty::uncertain, CertificateReason::axes_parallel_within_tolerance};
    tally.add(relaxed);
    for (int k = 0; k < out.contact_count; ++k) out.contacts[k].certificate = relaxed;
  }
  if (tally.beyond_undecided && !tally.beyond_proved) {
    tally.add({Certainty::uncertain, CertificateReason::beyond_model_undecided});
  }
  out.scenario = classify(out, tally);
  if ((out.scenario == PinInHoleScenario::both_edges_opposite ||
       out.scenario == PinInHoleScenario::both_edges_same_side) &&
      !edge_sides_proved(out, tally)) {
    tally.add({Certainty::uncertain, CertificateReason::edge_sides_undecided});
  }
  out.certificate = tally.certificate;
  // Back to the world frame: radial contacts were found in the frame at P_j, axial ones at P_i.
  for (int k = 0; k < out.contact_count; ++k) {
    Contact& contact = out.contacts[k];
    to_world(contact.type == ContactType::radial ? s.p_WPj : s.p_WPi, contact);
    out.certificate = weakest(out.certificate, contact.certificate);
  }
  return out;
}

}  // namespace clearjoint::geometry
