// SPDX-License-Identifier: BSD-3-Clause
// Tests of detect_pin_in_hole_contacts: the closed forms of issue 48 (an aligned pin offset
// radially leans along the bore, a pin tilted about the hole's centre bears on both edges at
// opposite sides, a pushed pin bears on one stop), the degenerate cases (tangent, parallel,
// coincident axes, huge and tiny scales) and bad input named by its field. Expected values are
// worked out below in long double from the geometry, not taken from the code.

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry {
namespace {

/// The closed forms below are evaluated in long double and the detection in double on inputs of
/// size ~10: a few ulps of 10 (2e-15) each; 1e-12, the figure, leaves a wide margin.
constexpr double kClosedFormTolerance = 1e-12;

// A hole of radius 10 and length 20 (mm) along z at the origin, a pin of radius 9.9 (cr = 0.1),
// heads at -10.5 and +10.5 with outer radius 16 (ca = 0.5).
PinInHoleDimensions joint() {
  PinInHoleDimensions d;
  d.hole_radius = 10.0;
  d.hole_length = 20.0;
  d.pin_radius = 9.9;
  d.stops[0] = {-10.5, 16.0};
  d.stops[1] = {10.5, 16.0};
  d.stop_count = 2;
  return d;
}
const PartPose kHole{Vector3::Zero(), Vector3::UnitZ()};

bool decided(const Certificate& certificate) { return certificate.level != Certainty::uncertain; }

TEST(DetectPinInHoleContacts, AnAlignedPinOffsetRadiallyLeansAlongTheBoreInALineContact) {
  // Pin axis parallel to the hole's, 0.15 off along x: the hole's mid circle point (10, 0, 0) is
  // 10 - 0.15 = 9.85 from the pin's axis, 0.05 inside the pin of radius 9.9.
  const PinInHoleContacts answer =
      detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(0.15, 0.0, 0.0), Vector3::UnitZ()});
  EXPECT_EQ(answer.scenario, PinInHoleScenario::line);
  EXPECT_TRUE(answer.aligned);
  ASSERT_EQ(answer.contact_count, 1);
  const Contact& line = answer.contacts[0];
  EXPECT_EQ(line.type, ContactType::radial);
  EXPECT_EQ(line.base, ContactBase::mid);
  EXPECT_NEAR(line.depth, 0.05, kClosedFormTolerance);
  EXPECT_TRUE((line.p_WCi - Vector3(10.0, 0.0, 0.0)).norm() < kClosedFormTolerance) << line.p_WCi.transpose();
  EXPECT_TRUE((line.p_WCj - Vector3(10.05, 0.0, 0.0)).norm() < kClosedFormTolerance) << line.p_WCj.transpose();
  EXPECT_TRUE((line.normal_W - Vector3::UnitX()).norm() < kClosedFormTolerance);
  EXPECT_TRUE(decided(answer.certificate));
  EXPECT_LE(std::fabs(line.depth - 0.05), line.depth_error);
}

TEST(DetectPinInHoleContacts, APinTiltedAboutTheHolesCentreBearsOnBothEdgesAtOppositeSides) {
  // Axis a = (0, sin t, cos t) through the hole's centre. A point of edge A, (10 cos p, 10 sin p,
  // 10), is sqrt(200 - 100 (sin p sin t + cos t)^2) from the axis, least at p = pi/2 (symmetric
  // about it, so the arc's middle is there): 10 sqrt(1 - sin 2t), the depth 9.9 minus that. Edge B
  // by the half-turn symmetry about x: the point (0, -10, -10), the same depth.
  const long double t = 0.0125L;
  const PinInHoleContacts answer = detect_pin_in_hole_contacts(
      joint(), kHole, PartPose{Vector3::Zero(), Vector3(0.0, double(std::sin(t)), double(std::cos(t)))});
  // The axis as stored (its components rounded): a_hat within an ulp of the above, which moves
  // the depth by ~1e-15.
  const long double depth = 9.9L - 10.0L * std::sqrt(1.0L - std::sin(2.0L * t));
  EXPECT_EQ(answer.scenario, PinInHoleScenario::both_edges_opposite);
  EXPECT_FALSE(answer.aligned);
  ASSERT_EQ(answer.contact_count, 2);
  EXPECT_EQ(answer.contacts[0].base, ContactBase::a);
  EXPECT_EQ(answer.contacts[1].base, ContactBase::b);
  for (int k = 0; k < 2; ++k) {
    const Contact& edge = answer.contacts[k];
    const double side = k == 0 ? 1.0 : -1.0;
    EXPECT_EQ(edge.type, ContactType::radial);
    EXPECT_NEAR(edge.depth, double(depth), kClosedFormTolerance);
    EXPECT_TRUE((edge.p_WCi - Vector3(0.0, 10.0 * side, 10.0 * side)).norm() < kClosedFormTolerance)
        << edge.p_WCi.transpose();
    // The normal: C_i's component across the axis, normalised: (0, cos t, -sin t) at A (C_i . a =
    // 10 (sin t + cos t)), its opposite at B.
    const Vector3 normal(0.0, double(std::cos(t)), double(-std::sin(t)));
    EXPECT_TRUE((edge.normal_W - side * normal).norm() < kClosedFormTolerance) << edge.normal_W.transpose();
    EXPECT_TRUE((edge.p_WCj - edge.p_WCi - edge.depth * edge.normal_W).norm() < kClosedFormTolerance);
    EXPECT_EQ(edge.crossing_count, 2);
    EXPECT_TRUE(decided(edge.certificate));
    EXPECT_LE(std::fabs(edge.depth - double(depth)), edge.depth_error + 1e-15);
  }
}

TEST(DetectPinInHoleContacts, APinPushedAxiallyBearsOnOneStopFlushOnItsFace) {
  // Pushed 0.75 along +z: the stop at -10.5 (a head below face B, z = -10) comes to z = -9.75,
  // 0.25 into the link; the pin penetrates along +z.
  const PinInHoleContacts answer =
      detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(0.0, 0.0, 0.75), Vector3::UnitZ()});
  EXPECT_EQ(answer.scenario, PinInHoleScenario::face);
  ASSERT_EQ(answer.contact_count, 1);
  const Contact& face = answer.contacts[0];
  EXPECT_EQ(face.type, ContactType::axial);
  EXPECT_EQ(face.base, ContactBase::b);
  EXPECT_NEAR(face.depth, 0.25, kClosedFormTolerance);
  EXPECT_TRUE((face.normal_W - Vector3::UnitZ()).norm() < kClosedFormTolerance);
  EXPECT_TRUE((face.p_WCj - Vector3(0.0, 0.0, -9.75)).norm() < kClosedFormTolerance);
  EXPECT_TRUE((face.p_WCi - Vector3(0.0, 0.0, -10.0)).norm() < kClosedFormTolerance);
  EXPECT_TRUE(decided(answer.certificate));
}

TEST(DetectPinInHoleContacts, ATiltedPinPushedAxiallyBearsOnOneStopAtItsOuterCircle) {
  // Axis a = (0, sin t, cos t) through (0, 0, 0.52). The stop at -10.5 has centre
  // (0.52 - 10.5 cos t) along z, and its outer circle (radius 16, plane normal to a) rises at
  // most 16 sin t above it, at the point c + 16 (0, -cos t, sin t): depth beyond face B (z = -10)
  // 0.52 - 10.5 cos t + 16 sin t + 10 (0.100, below ca = 0.5; the circle's lowest point, 0.16
  // below the highest, stays outside the link, so the contact is a point, not the whole circle).
  // The edges stay clear: a point of edge A is at least about 10 sqrt(1 - sin 2t) - 0.52 t > 9.9
  // from the axis.
  const long double t = 0.005L;
  const PinInHoleContacts answer = detect_pin_in_hole_contacts(
      joint(), kHole, PartPose{Vector3(0.0, 0.0, 0.52), Vector3(0.0, double(std::sin(t)), double(std::cos(t)))});
  const long double depth = 0.52L - 10.5L * std::cos(t) + 16.0L * std::sin(t) + 10.0L;
  const Vector3 point(0.0, double(-10.5L * std::sin(t) - 16.0L * std::cos(t)),
                      double(0.52L - 10.5L * std::cos(t) + 16.0L * std::sin(t)));
  EXPECT_EQ(answer.scenario, PinInHoleScenario::one_stop);
  ASSERT_EQ(answer.contact_count, 1);
  const Contact& stop = answer.contacts[0];
  EXPECT_EQ(stop.type, ContactType::axial);
  EXPECT_EQ(stop.base, ContactBase::b);
  EXPECT_NEAR(stop.depth, double(depth), kClosedFormTolerance);
  EXPECT_TRUE((stop.p_WCj - point).norm() < kClosedFormTolerance) << stop.p_WCj.transpose();
  EXPECT_NEAR(stop.p_WCi.z(), -10.0, kClosedFormTolerance);
  EXPECT_TRUE((stop.normal_W - Vector3::UnitZ()).norm() < kClosedFormTolerance);
  EXPECT_TRUE(decided(stop.certificate));
  EXPECT_LE(std::fabs(stop.depth - double(depth)), stop.depth_error + 1e-15);
}

TEST(DetectPinInHoleContacts, ATiltedPinHeldAgainstItsHeadBearsOnTheOuterCirclesDeepestPoint) {
  // A pin pressed against head B and barely tilted: axis a = (0, sin t, cos t) with t = 1e-4
  // through (0, 0, z0), the stop at -10.5 (outer radius 16) with its centre d = z0 - 10.5 cos t
  // + 10 = 0.01 beyond face B (z = -10). Its outer circle dips between d - 16 sin t = 0.0084 and
  // d + 16 sin t = 0.0116 into the link: beyond the face all round, a stop contact at the
  // deepest point c + 16 (0, -cos t, sin t) (eq. 14's theta_m, as for an arc), depth d + 16 sin t.
  const long double t = 1e-4L;
  const double z0 = double(0.01L - 10.0L + 10.5L * std::cos(t));
  const PinInHoleContacts answer = detect_pin_in_hole_contacts(
      joint(), kHole, PartPose{Vector3(0.0, 0.0, z0), Vector3(0.0, double(std::sin(t)), double(std::cos(t)))});
  const long double centre_depth = z0 - 10.5L * std::cos(t) + 10.0L;
  const long double depth = centre_depth + 16.0L * std::sin(t);
  const Vector3 point(0.0, double(-10.5L * std::sin(t) - 16.0L * std::cos(t)),
                      double(z0 - 10.5L * std::cos(t) + 16.0L * std::sin(t)));
  EXPECT_EQ(answer.scenario, PinInHoleScenario::one_stop);
  EXPECT_FALSE(answer.aligned);
  ASSERT_EQ(answer.contact_count, 1);
  const Contact& stop = answer.contacts[0];
  EXPECT_EQ(stop.type, ContactType::axial);
  EXPECT_EQ(stop.base, ContactBase::b);
  EXPECT_NEAR(stop.depth, double(depth), kClosedFormTolerance);
  EXPECT_TRUE((stop.p_WCj - point).norm() < kClosedFormTolerance) << stop.p_WCj.transpose();
  EXPECT_TRUE((stop.p_WCi - Vector3(point.x(), point.y(), -10.0)).norm() < kClosedFormTolerance)
      << stop.p_WCi.transpose();
  EXPECT_TRUE((stop.normal_W - Vector3::UnitZ()).norm() < kClosedFormTolerance);
  EXPECT_TRUE(decided(answer.certificate));
  // Bounds that enclose the closed form and are of the direction's rounding over the tilt
  // (16 * 128 u / t = 2.3e-9), not the circle's diameter.
  EXPECT_LE(std::fabs(stop.depth - double(depth)), stop.depth_error + 1e-15);
  EXPECT_LE((stop.p_WCj - point).norm(), stop.p_WCj_error + 1e-15);
  EXPECT_LT(stop.p_WCj_error, 1e-8);
}

TEST(DetectPinInHoleContacts, TwoEdgeNormalsAtRightAnglesLeaveTheSideLabelUncertain) {
  // Axis a = (0, sin t, cos t) through (x, 0, 0): it crosses face A at (x, 10 tan t) and face B at
  // (x, -10 tan t) from the hole's axis, and each edge bears on the pin towards that offset, so
  // n_A . n_B runs from -1 (x = 0, tilted about the centre) to about +1 (x >> 10 tan t) and is 0
  // near x = 10 tan t = 0.08. Bisected on the sign of the answer's own n_A . n_B to adjacent
  // doubles: there the normals are at right angles to within a rounding, and whether the edges
  // bear at opposite sides or on one side is not proved.
  const double t = std::atan(0.008);
  const Vector3 axis(0.0, std::sin(t), std::cos(t));
  const auto at = [&](double x) { return detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(x, 0.0, 0.0), axis}); };
  const auto facing = [](const PinInHoleContacts& answer) {
    return answer.contacts[0].normal_W.dot(answer.contacts[1].normal_W);
  };
  double lo = 0.07, hi = 0.09;
  ASSERT_EQ(at(lo).contact_count, 2);
  ASSERT_EQ(at(hi).contact_count, 2);
  ASSERT_LT(facing(at(lo)), 0.0);
  ASSERT_GT(facing(at(hi)), 0.0);
  // Far from right angles both labels are proved.
  EXPECT_EQ(at(lo).scenario, PinInHoleScenario::both_edges_opposite);
  EXPECT_TRUE(decided(at(lo).certificate));
  EXPECT_EQ(at(hi).scenario, PinInHoleScenario::both_edges_same_side);
  EXPECT_TRUE(decided(at(hi).certificate));
  while (std::nextafter(lo, hi) < hi) {
    const double mid = 0.5 * (lo + hi);
    (facing(at(mid)) < 0.0 ? lo : hi) = mid;
  }
  for (const double x : {lo, hi}) {
    const PinInHoleContacts answer = at(x);
    ASSERT_EQ(answer.contact_count, 2) << x;
    EXPECT_LT(std::fabs(facing(answer)), 1e-12) << x;
    EXPECT_EQ(answer.certificate.level, Certainty::uncertain) << x;
    EXPECT_EQ(answer.certificate.reason, CertificateReason::edge_sides_undecided) << x;
    // The contacts themselves are still proved.
    EXPECT_TRUE(decided(answer.contacts[0].certificate) && decided(answer.contacts[1].certificate)) << x;
  }
}

TEST(DetectPinInHoleContacts, ACentredPinTouchesNothingAndThatIsProved) {
  const PinInHoleContacts answer = detect_pin_in_hole_contacts(joint(), kHole, PartPose{});
  EXPECT_EQ(answer.scenario, PinInHoleScenario::none);
  EXPECT_EQ(answer.contact_count, 0);
  EXPECT_TRUE(answer.aligned);
  EXPECT_EQ(answer.certificate.level, Certainty::certified);
}

TEST(DetectPinInHoleContacts, AnAlignedPinTouchingTheBoreExactlyHasNoContactAndOneUlpMoreHasOne) {
  // Dyadic sizes: cr = 10 - 9.875 = 0.125 exactly; an offset of 0.125 touches along a generator.
  PinInHoleDimensions d = joint();
  d.pin_radius = 9.875;
  const PinInHoleContacts touching =
      detect_pin_in_hole_contacts(d, kHole, PartPose{Vector3(0.125, 0.0, 0.0), Vector3::UnitZ()});
  EXPECT_EQ(touching.scenario, PinInHoleScenario::none);
  EXPECT_TRUE(decided(touching.certificate));
  const PinInHoleContacts beyond = detect_pin_in_hole_contacts(
      d, kHole, PartPose{Vector3(std::nextafter(0.125, 1.0), 0.0, 0.0), Vector3::UnitZ()});
  EXPECT_EQ(beyond.scenario, PinInHoleScenario::line);
  EXPECT_TRUE(decided(beyond.certificate));
  ASSERT_EQ(beyond.contact_count, 1);
  EXPECT_LT(beyond.contacts[0].depth, 1e-15);
}

TEST(DetectPinInHoleContacts, ParallelAxesOfAnyLengthAndSignAreAlignedExactly) {
  // (1, 3, 7) and (-0.5, -1.5, -3.5) are parallel exactly; one ulp off in the last component
  // they are not (eq. 5 decided on the stored doubles).
  const PartPose hole{Vector3::Zero(), Vector3(1.0, 3.0, 7.0)};
  const PinInHoleContacts parallel =
      detect_pin_in_hole_contacts(joint(), hole, PartPose{Vector3::Zero(), Vector3(-0.5, -1.5, -3.5)});
  EXPECT_TRUE(parallel.aligned);
  EXPECT_EQ(parallel.scenario, PinInHoleScenario::none);
  const PinInHoleContacts skew = detect_pin_in_hole_contacts(
      joint(), hole, PartPose{Vector3::Zero(), Vector3(-0.5, -1.5, std::nextafter(-3.5, 0.0))});
  EXPECT_FALSE(skew.aligned);
  EXPECT_EQ(skew.scenario, PinInHoleScenario::none);
  EXPECT_TRUE(decided(skew.certificate));
}

TEST(DetectPinInHoleContacts, AToleranceTreatsANearlyParallelPinAsAlignedButUncertain) {
  DetectionOptions options;
  options.parallel_angle_tolerance = 1e-5;
  const PinInHoleContacts answer = detect_pin_in_hole_contacts(
      joint(), kHole, PartPose{Vector3(0.15, 0.0, 0.0), Vector3(1e-7, 0.0, 1.0)}, options);
  EXPECT_TRUE(answer.aligned);
  EXPECT_EQ(answer.scenario, PinInHoleScenario::line);
  EXPECT_EQ(answer.certificate.reason, CertificateReason::axes_parallel_within_tolerance);
  EXPECT_EQ(answer.certificate.level, Certainty::uncertain);
}

TEST(DetectPinInHoleContacts, ThePinsAxisOutsideTheHoleIsBeyondTheModel) {
  // The pin's axis 30 off the hole's: it does not pass through the hole at all.
  const PinInHoleContacts beside =
      detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(30.0, 0.0, 0.0), Vector3::UnitZ()});
  EXPECT_EQ(beside.scenario, PinInHoleScenario::beyond_model);
  // Across the hole, parallel to the link's faces.
  const PinInHoleContacts across = detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3::Zero(), Vector3::UnitX()});
  EXPECT_EQ(across.scenario, PinInHoleScenario::beyond_model);
  // Offset 0.35 radially with cr = 0.1: a line contact 0.25 deep, deeper than cr.
  const PinInHoleContacts deep =
      detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(0.35, 0.0, 0.0), Vector3::UnitZ()});
  EXPECT_EQ(deep.scenario, PinInHoleScenario::beyond_model);
  ASSERT_EQ(deep.contact_count, 1);
  EXPECT_NEAR(deep.contacts[0].depth, 0.25, kClosedFormTolerance);
  // Pushed 1.25 along z with ca = 0.5: the stop 0.75 into face B.
  const PinInHoleContacts pushed =
      detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(0.0, 0.0, 1.25), Vector3::UnitZ()});
  EXPECT_EQ(pushed.scenario, PinInHoleScenario::beyond_model);
}

// The stops below are heads barely larger than the hole, on a pin tilted by t about x: axis
// a = (0, sin t, cos t) through (0, y0, z0), the stop at -10.5 with centre S = (0, yS, zS),
// yS = y0 - 10.5 sin t, zS = z0 - 10.5 cos t, g = zS + 10 its height above face B (z = -10). In the
// plane x = 0 the outer circle's deepest point into the link is m = S + Ro (0, -cos t, sin t), depth
// g + Ro sin t; the hole's edge's deepest point into the head is q = (0, -10, -10), depth
// (S - q) . a = (yS + 10) sin t + g cos t, at (yS + 10) cos t - g sin t from the pin's axis.

/// The joint above with a stop of outer radius `outer` at -10.5.
PinInHoleDimensions small_head(double outer) {
  PinInHoleDimensions d = joint();
  d.stops[0].outer_radius = outer;
  return d;
}

/// A pose of the comment above and its closed forms.
struct SmallHeadPose {
  long double t, y0, z0, ro;
  long double ys() const { return y0 - 10.5L * std::sin(t); }
  long double g() const { return z0 - 10.5L * std::cos(t) + 10.0L; }
  /// The outer circle's deepest point m and its depth into the link.
  Vector3 m() const { return Vector3(0.0, double(ys() - ro * std::cos(t)), double(g() - 10.0L + ro * std::sin(t))); }
  long double circle_depth() const { return g() + ro * std::sin(t); }
  /// The hole's edge's depth into the head, (S - q) . a.
  long double edge_depth() const { return (ys() + 10.0L) * std::sin(t) + g() * std::cos(t); }
  Vector3 axis() const { return Vector3(0.0, double(std::sin(t)), double(std::cos(t))); }
  PinInHoleContacts detect() const {
    return detect_pin_in_hole_contacts(small_head(double(ro)), kHole,
                                       PartPose{Vector3(0.0, double(y0), double(z0)), axis()});
  }
};

/// The answer has `scenario`, proved, and one contact: a stop at face B with `depth` and `normal`.
void expect_one_stop_at_face_b(const PinInHoleContacts& answer, PinInHoleScenario scenario, long double depth,
                               const Vector3& normal) {
  EXPECT_EQ(to_string(answer.scenario), to_string(scenario));
  EXPECT_TRUE(decided(answer.certificate));
  ASSERT_EQ(answer.contact_count, 1);
  const Contact& stop = answer.contacts[0];
  EXPECT_EQ(stop.type, ContactType::axial);
  EXPECT_EQ(stop.base, ContactBase::b);
  EXPECT_NEAR(stop.depth, double(depth), kClosedFormTolerance);
  EXPECT_LE(std::fabs(stop.depth - double(depth)), stop.depth_error + 1e-15);
  EXPECT_TRUE((stop.normal_W - normal).norm() < kClosedFormTolerance) << stop.normal_W.transpose();
}

TEST(DetectPinInHoleContacts, AHeadPartlyOverTheHoleWhoseDeepestPointIsOverTheLinkBearsThereAsAnOrdinaryStop) {
  // Ro = 10.05, t = 0.004, the pin through (0, -0.03, 0.52): yS = -0.072, so the circle's point
  // on the +y side, yS + Ro cos t = 9.978, lies over the hole, but m at yS - Ro cos t = -10.12 lies
  // over the link's face: m is the disk's deepest point and it is in the contact region, an
  // ordinary stop contact at m of depth g + Ro sin t = 0.060 (below ca = 0.5), C_i its projection
  // on face B. The edges stay clear: their points are at least 9.928 from the pin's axis.
  const SmallHeadPose pose{0.004L, -0.03L, 0.52L, 10.05L};
  const PinInHoleContacts answer = pose.detect();
  ASSERT_NO_FATAL_FAILURE(
      expect_one_stop_at_face_b(answer, PinInHoleScenario::one_stop, pose.circle_depth(), Vector3::UnitZ()));
  const Contact& stop = answer.contacts[0];
  const Vector3 m = pose.m();
  EXPECT_TRUE((stop.p_WCj - m).norm() < kClosedFormTolerance) << stop.p_WCj.transpose();
  EXPECT_TRUE((stop.p_WCi - Vector3(0.0, m.y(), -10.0)).norm() < kClosedFormTolerance) << stop.p_WCi.transpose();
}

TEST(DetectPinInHoleContacts, AHeadWhoseDeepestDirectionLiesOverTheHoleBearsOnTheHolesEdge) {
  // Ro = 10.02, t = 0.003, the pin through (0, 0.0515, 0.55): yS = 0.0200000, g = 0.0500047. m at
  // yS - Ro cos t = -9.999955 lies over the hole, and q, (10 + yS) cos t - g sin t = 10.01980 from
  // the pin's axis, lies within the head's disk: q is the deepest point of the disk less the hole.
  // The contact is bounded by the hole's edge: C_i = q on the link, C_j = q + delta a on the stop's
  // face, n = a (the way the pin moves into the link), delta = (yS + 10) sin t + g cos t = 0.080.
  // The edges stay clear (at least 9.920 from the pin's axis), and so does the other stop.
  const SmallHeadPose pose{0.003L, 0.0515L, 0.55L, 10.02L};
  const PinInHoleContacts answer = pose.detect();
  ASSERT_NO_FATAL_FAILURE(
      expect_one_stop_at_face_b(answer, PinInHoleScenario::one_stop, pose.edge_depth(), pose.axis()));
  const Contact& stop = answer.contacts[0];
  const long double depth = pose.edge_depth();
  const Vector3 q(0.0, -10.0, -10.0);
  const Vector3 on_head(0.0, double(-10.0L + depth * std::sin(pose.t)), double(-10.0L + depth * std::cos(pose.t)));
  EXPECT_TRUE((stop.p_WCi - q).norm() < kClosedFormTolerance) << stop.p_WCi.transpose();
  EXPECT_TRUE((stop.p_WCj - on_head).norm() < kClosedFormTolerance) << stop.p_WCj.transpose();
  EXPECT_LE((stop.p_WCi - q).norm(), stop.p_WCi_error + 1e-15);
}

TEST(DetectPinInHoleContacts, AHeadMeetingTheHolesEdgeAtACornerIsBeyondTheModel) {
  // Ro = 10.02, t = 0.002, the pin through (0, 0.051, 0.55): yS = 0.030. m at yS - Ro cos t = -9.99
  // lies over the hole and q, (10 + yS) cos t - g sin t = 10.030 from the pin's axis, beyond the
  // head's rim: the deepest point of the disk less the hole is a corner where the outer circle
  // meets the hole's edge, beyond the model. The contact is the hole's edge inside the head (normal
  // a, C_i = q), depth (yS + 10) sin t + g cos t = 0.070.
  const SmallHeadPose pose{0.002L, 0.051L, 0.55L, 10.02L};
  const PinInHoleContacts answer = pose.detect();
  ASSERT_NO_FATAL_FAILURE(
      expect_one_stop_at_face_b(answer, PinInHoleScenario::beyond_model, pose.edge_depth(), pose.axis()));
  EXPECT_TRUE((answer.contacts[0].p_WCi - Vector3(0.0, -10.0, -10.0)).norm() < kClosedFormTolerance)
      << answer.contacts[0].p_WCi.transpose();
}

/// Walks the pin's offset y0 over 401 steps of `step` about `y_star` (Ro = 10.02, t = 0.002,
/// z0 = 0.55), and to 200,000 steps either side, and tallies the answers by the choice `is_second`
/// reads from them: proved (the second choice exactly when above y_star), or uncertain for
/// `reason`, with either choice.
struct ChoiceWalk {
  int proved = 0, far_proved = 0, undecided_first = 0, undecided_second = 0;
};
template <class Second>
ChoiceWalk walk_the_stop_choice(long double y_star, double step, CertificateReason reason, Second is_second) {
  constexpr int kFar = 200000;
  ChoiceWalk walk;
  for (int k = -200; k <= 200; ++k) {
    const int at = k == -200 ? -kFar : (k == 200 ? kFar : k);
    const SmallHeadPose pose{0.002L, y_star + at * step, 0.55L, 10.02L};
    const PinInHoleContacts answer = pose.detect();
    EXPECT_EQ(answer.contact_count, 1) << "at " << at;
    if (answer.contact_count != 1) continue;
    const bool second = is_second(answer);
    if (decided(answer.certificate)) {
      ++walk.proved;
      if (at == -kFar || at == kFar) ++walk.far_proved;
      EXPECT_EQ(second, at > 0) << "at " << at;
    } else {
      EXPECT_EQ(answer.certificate.reason, reason) << "at " << at;
      ++(second ? walk.undecided_second : walk.undecided_first);
    }
  }
  return walk;
}

TEST(DetectPinInHoleContacts, AStopsChoiceWithinItsBoundIsTheComputedOneAndUncertain) {
  // Ro = 10.02, t = 0.002, z0 = 0.55 (g = 0.05002), as at the corner above. Walking y0 across
  // yS = Ro cos t - 10, where m reaches the bore, the contact passes from m (case 1: one_stop,
  // normal z) to q (case 2: one_stop, normal a); the outer circle then touches the hole's edge
  // seen along the hole's axis, and within m's bound the answer is uncertain for that tangency.
  // Walking across yS = (Ro + g sin t) / cos t - 10, where q reaches the head's rim, the label passes
  // from one_stop to beyond_model (case 3), and within q's bound the answer is uncertain as to
  // whether it is beyond the model. Either way the computed distance chooses; beyond the bounds
  // the choice is proved. The walks' steps are 2e-15, their far ends 4e-10 away; m's bound is
  // 7e-11 (its deepest direction's over the tilt, Ro 128 u / sin t), q's about 1e-10. On the
  // outer circle's side of the first walk the band is narrower: the circle is proved wholly
  // outside the bore without m to within about 1e-13.
  const long double t = 0.002L, ro = 10.02L;
  const long double g = 0.55L - 10.5L * std::cos(t) + 10.0L;
  const auto by_edge = [](const PinInHoleContacts& answer) {
    EXPECT_EQ(to_string(answer.scenario), to_string(PinInHoleScenario::one_stop));
    return (answer.contacts[0].normal_W - Vector3::UnitZ()).norm() > 1e-6;
  };
  const ChoiceWalk m_walk = walk_the_stop_choice(ro * std::cos(t) - 10.0L + 10.5L * std::sin(t), 2e-15,
                                                 CertificateReason::interval_proof_failed_near_multiple_root, by_edge);
  const auto at_corner = [](const PinInHoleContacts& answer) {
    return answer.scenario == PinInHoleScenario::beyond_model;
  };
  const ChoiceWalk q_walk = walk_the_stop_choice((ro + g * std::sin(t)) / std::cos(t) - 10.0L + 10.5L * std::sin(t),
                                                 2e-15, CertificateReason::beyond_model_undecided, at_corner);
  for (const ChoiceWalk& walk : {m_walk, q_walk}) {
    EXPECT_GT(walk.undecided_first, 0);
    EXPECT_GT(walk.undecided_second, 0);
    EXPECT_EQ(walk.far_proved, 2);
  }
}

DetectionOptions uncertified() {
  DetectionOptions options;
  options.intersection.certify = false;
  return options;
}

/// A pin tilted by t about the x axis, its axis (0, sin t, cos t) through `point`.
PartPose tilted(double t, const Vector3& point = Vector3::Zero()) {
  return PartPose{point, Vector3(0.0, std::sin(t), std::cos(t))};
}

TEST(DetectPinInHoleContacts, AnUncertifiedAnswerIsBeyondTheModelWhenTheComputedDepthExceedsTheClearance) {
  // Tilted by t = 0.03 about the hole's centre: both edges 9.9 - 10 sqrt(1 - sin 2t) = 0.204 deep
  // (the closed form of the two-edge test above), twice cr = 0.1. Aligned and 0.35 off: a line
  // contact 0.25 deep. Neither depth is near its limit, so the computed depth decides as surely
  // as the certified one.
  for (const PartPose& pin : {tilted(0.03), PartPose{Vector3(0.35, 0.0, 0.0), Vector3::UnitZ()}}) {
    const PinInHoleContacts certified = detect_pin_in_hole_contacts(joint(), kHole, pin);
    const PinInHoleContacts plain = detect_pin_in_hole_contacts(joint(), kHole, pin, uncertified());
    EXPECT_EQ(to_string(certified.scenario), to_string(PinInHoleScenario::beyond_model)) << pin.axis_W.transpose();
    EXPECT_TRUE(decided(certified.certificate));
    EXPECT_EQ(to_string(plain.scenario), to_string(PinInHoleScenario::beyond_model)) << pin.axis_W.transpose();
    ASSERT_GE(plain.contact_count, 1);
    EXPECT_GT(plain.contacts[0].depth, 2.0 * joint().radial_clearance());
    EXPECT_EQ(plain.certificate.level, Certainty::uncertain);
    EXPECT_EQ(plain.certificate.reason, CertificateReason::certificate_switched_off);
  }
}

TEST(DetectPinInHoleContacts, AnUncertifiedAnswerIsBeyondTheModelWhenAStopsComputedDepthExceedsTheAxialClearance) {
  // Tilted by t = 0.005 through (0, 0, 1): the stop at -10.5 reaches 1 - 10.5 cos t + 16 sin t + 10
  // = 0.58 into face B (the one-stop test's closed form, pushed 0.48 further), above ca = 0.5;
  // aligned and pushed 1.25: face B 0.75 deep.
  for (const PartPose& pin : {tilted(0.005, Vector3(0.0, 0.0, 1.0)), PartPose{Vector3(0.0, 0.0, 1.25), Vector3::UnitZ()}}) {
    const PinInHoleContacts certified = detect_pin_in_hole_contacts(joint(), kHole, pin);
    const PinInHoleContacts plain = detect_pin_in_hole_contacts(joint(), kHole, pin, uncertified());
    EXPECT_EQ(to_string(certified.scenario), to_string(PinInHoleScenario::beyond_model)) << pin.axis_W.transpose();
    EXPECT_TRUE(decided(certified.certificate));
    EXPECT_EQ(to_string(plain.scenario), to_string(PinInHoleScenario::beyond_model)) << pin.axis_W.transpose();
    ASSERT_EQ(plain.contact_count, 1);
    EXPECT_EQ(plain.contacts[0].type, ContactType::axial);
    EXPECT_GT(plain.contacts[0].depth, joint().axial_clearance() + 0.05);
  }
}

TEST(DetectPinInHoleContacts, AnUncertifiedAnswerHasTheCertifiedScenarioAwayFromTheBoundaries) {
  // One pose per scenario, each a clearance's tenth or more from any change of scenario: the plain
  // double-precision answer is the certified one without its proofs.
  const struct {
    PinInHoleDimensions dimensions;
    PartPose pin;
    PinInHoleScenario scenario;
  } poses[] = {
      {joint(), PartPose{}, PinInHoleScenario::none},
      {joint(), tilted(0.0125), PinInHoleScenario::both_edges_opposite},
      {joint(), tilted(std::atan(0.008), Vector3(0.09, 0.0, 0.0)), PinInHoleScenario::both_edges_same_side},
      {joint(), tilted(0.0125, Vector3(0.0, 0.0, 0.4)), PinInHoleScenario::edges_and_stops},
      {joint(), tilted(0.005, Vector3(0.0, 0.0, 0.52)), PinInHoleScenario::one_stop},
      {joint(), PartPose{Vector3(0.15, 0.0, 0.0), Vector3::UnitZ()}, PinInHoleScenario::line},
      {joint(), PartPose{Vector3(0.0, 0.0, 0.75), Vector3::UnitZ()}, PinInHoleScenario::face},
      {joint(), PartPose{Vector3(0.15, 0.0, 0.75), Vector3::UnitZ()}, PinInHoleScenario::line_and_face},
      {joint(), tilted(0.03), PinInHoleScenario::beyond_model},
      {joint(), PartPose{Vector3(30.0, 0.0, 0.0), Vector3::UnitZ()}, PinInHoleScenario::beyond_model},
      {joint(), PartPose{Vector3::Zero(), Vector3::UnitX()}, PinInHoleScenario::beyond_model},
      {small_head(10.05), tilted(0.004, Vector3(0.0, -0.03, 0.52)), PinInHoleScenario::one_stop},
      {small_head(10.02), tilted(0.002, Vector3(0.0, 0.051, 0.55)), PinInHoleScenario::beyond_model},
  };
  for (const auto& pose : poses) {
    const PinInHoleContacts certified = detect_pin_in_hole_contacts(pose.dimensions, kHole, pose.pin);
    const PinInHoleContacts plain = detect_pin_in_hole_contacts(pose.dimensions, kHole, pose.pin, uncertified());
    const std::string where = "pin at (" + std::to_string(pose.pin.p_WP.x()) + ", " + std::to_string(pose.pin.p_WP.y()) +
                              ", " + std::to_string(pose.pin.p_WP.z()) + ") along y " +
                              std::to_string(pose.pin.axis_W.y());
    EXPECT_EQ(to_string(certified.scenario), to_string(pose.scenario)) << where;
    EXPECT_TRUE(decided(certified.certificate)) << where;
    EXPECT_EQ(to_string(plain.scenario), to_string(certified.scenario)) << where;
    EXPECT_EQ(plain.contact_count, certified.contact_count) << where;
    EXPECT_EQ(plain.certificate.reason, CertificateReason::certificate_switched_off) << where;
  }
}

TEST(DetectPinInHoleContacts, AnUncertifiedAnswerTakesThePinThroughTheHoleFromTheComputedCrossing) {
  // No stops; the pin's axis (0, 1, 0.001) through (10, 0, 0): nearly parallel to the link's
  // faces, it crosses the mid-plane on the bore, at exactly 10 = Rh as computed, and its edges
  // stay 9.99 from it, clear of the pin. Certified, that crossing lies within its bound of Rh and
  // the answer is uncertain; uncertified, the computed crossing decides (at Rh or beyond: not
  // through the hole), as a computed depth decides against its limit.
  PinInHoleDimensions d = joint();
  d.stop_count = 0;
  const PartPose pin{Vector3(10.0, 0.0, 0.0), Vector3(0.0, 1.0, 0.001)};
  const PinInHoleContacts certified = detect_pin_in_hole_contacts(d, kHole, pin);
  EXPECT_EQ(certified.contact_count, 0);
  EXPECT_EQ(certified.certificate.reason, CertificateReason::beyond_model_undecided);
  EXPECT_EQ(to_string(certified.scenario), to_string(PinInHoleScenario::beyond_model));  // as computed
  const PinInHoleContacts plain = detect_pin_in_hole_contacts(d, kHole, pin, uncertified());
  EXPECT_EQ(plain.contact_count, 0);
  EXPECT_EQ(to_string(plain.scenario), to_string(PinInHoleScenario::beyond_model));
  EXPECT_EQ(plain.certificate.reason, CertificateReason::certificate_switched_off);
  // A hundredth inside the bore: through the hole, both ways.
  const PartPose inside{Vector3(9.99, 0.0, 0.0), pin.axis_W};
  EXPECT_EQ(to_string(detect_pin_in_hole_contacts(d, kHole, inside, uncertified()).scenario),
            to_string(detect_pin_in_hole_contacts(d, kHole, inside).scenario));
}

TEST(DetectPinInHoleContacts, ACertifiedAnswerWithinItsBoundOfTheClearanceIsLabelledByTheComputedDepth) {
  // An aligned pin offset by e: a line contact e - cr deep. Walking e over the doubles around 2 cr
  // crosses the band where the depth lies within its bound of cr: there the answer is uncertain
  // (beyond_model_undecided) and, as the paper's joint labels it (compare_with_clearance), the
  // computed depth says whether it is beyond_model; outside the band the label is proved.
  const double limit = joint().hole_radius - joint().pin_radius;
  int undecided_beyond = 0, undecided_within = 0;
  double e = 2.0 * limit;
  for (int k = 0; k < 200; ++k) e = std::nextafter(e, 0.0);
  for (int k = 0; k < 400; ++k, e = std::nextafter(e, 1.0)) {
    const PinInHoleContacts answer = detect_pin_in_hole_contacts(joint(), kHole, PartPose{Vector3(e, 0.0, 0.0), Vector3::UnitZ()});
    ASSERT_EQ(answer.contact_count, 1) << "e = " << e;
    const bool deeper = answer.contacts[0].depth > limit;
    EXPECT_EQ(to_string(answer.scenario), to_string(deeper ? PinInHoleScenario::beyond_model : PinInHoleScenario::line))
        << "e = " << e << ", depth " << answer.contacts[0].depth;
    if (answer.certificate.reason == CertificateReason::beyond_model_undecided) ++(deeper ? undecided_beyond : undecided_within);
  }
  EXPECT_GT(undecided_beyond, 0);
  EXPECT_GT(undecided_within, 0);
}

TEST(DetectPinInHoleContacts, ScalingEverythingByAPowerOfTwoScalesTheAnswerExactly) {
  // Huge and tiny joints: the tilted-pin closed form at 2^-400 and 2^400 times its size gives the
  // same scenario and depths times the scale (powers of two scale every double exactly).
  const double t = 0.0125;
  const PartPose pin{Vector3::Zero(), Vector3(0.0, std::sin(t), std::cos(t))};
  const PinInHoleContacts reference = detect_pin_in_hole_contacts(joint(), kHole, pin);
  ASSERT_EQ(reference.contact_count, 2);
  for (const int e : {-400, 400}) {
    PinInHoleDimensions d = joint();
    d.hole_radius = std::ldexp(d.hole_radius, e);
    d.hole_length = std::ldexp(d.hole_length, e);
    d.pin_radius = std::ldexp(d.pin_radius, e);
    for (AxialStop& stop : d.stops) stop = {std::ldexp(stop.position, e), std::ldexp(stop.outer_radius, e)};
    const PartPose hole{Vector3(std::ldexp(3.0, e), 0.0, 0.0), Vector3::UnitZ()};
    const PartPose moved{Vector3(std::ldexp(3.0, e), 0.0, 0.0), pin.axis_W};
    const PinInHoleContacts scaled = detect_pin_in_hole_contacts(d, hole, moved);
    EXPECT_EQ(scaled.scenario, reference.scenario) << e;
    ASSERT_EQ(scaled.contact_count, 2) << e;
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(std::ldexp(scaled.contacts[k].depth, -e), reference.contacts[k].depth, 1e-15) << e;
    }
    EXPECT_TRUE(decided(scaled.certificate)) << e;
  }
}

TEST(DetectPinInHoleContacts, BadInputIsNamedByItsField) {
  const auto message = [](const PinInHoleDimensions& d, const PartPose& hole, const PartPose& pin) -> std::string {
    try {
      detect_pin_in_hole_contacts(d, hole, pin);
    } catch (const InvalidInput& error) {
      return error.what();
    }
    return "";
  };
  PinInHoleDimensions thick = joint();
  thick.pin_radius = 10.5;
  EXPECT_EQ(message(thick, kHole, PartPose{}).rfind("dimensions.pin_radius = 10.5: must be smaller than", 0), 0u);
  EXPECT_EQ(message(joint(), PartPose{Vector3::Zero(), Vector3::Zero()}, PartPose{}),
            "hole.axis_W = [0, 0, 0]: must not be the zero vector");
  EXPECT_EQ(message(joint(), kHole, PartPose{Vector3(std::nan(""), 0.0, 0.0), Vector3::UnitZ()}),
            "pin.p_WP = [nan, 0, 0]: every component must be finite");
  try {
    DetectionOptions options;
    options.parallel_angle_tolerance = -1.0;
    detect_pin_in_hole_contacts(joint(), kHole, PartPose{}, options);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(std::string(error.what()), "options.parallel_angle_tolerance = -1: must lie in [0, pi/2) radians");
  }
  PinInHoleDimensions inside = joint();
  inside.stops[0].position = -5.0;
  EXPECT_EQ(message(inside, kHole, PartPose{}).rfind("dimensions.stops[0].position = -5: the stop lies inside", 0), 0u);
}

}  // namespace
}  // namespace clearjoint::geometry
