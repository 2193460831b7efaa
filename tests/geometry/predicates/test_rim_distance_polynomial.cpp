// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/rim_distance_polynomial.{hpp,cpp}: the coefficients, value and
// derivative (also by angle addition, value_near) must enclose the exact quantities of the stored primitives (256-bit MPFR from the
// definitions in primitives.hpp), and rim_reach must never give a wrong decided answer.

#include "predicates/rim_distance_polynomial.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "arithmetic/a_priori_bounds.hpp"
#include "enclosure_checks.hpp"
#include "model/primitives_detail.hpp"
#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
using internal_testing::RealVector3;
namespace it = internal_testing;
using internal_testing::Encloses;
using internal_testing::random_direction;

struct Pose {
  Circle3 circle;
  Cylinder3 cylinder;
};

/// Length scale of a pose: every coefficient is a sum of terms of at most this magnitude.
Real magnitude(const Pose& pose) {
  const RealVector3 q = it::to_real(pose.circle.center) - it::to_real(pose.cylinder.axis_point);
  const Real s = it::norm(q) + Real(pose.circle.radius) + Real(pose.cylinder.radius);
  return s * s;
}


/// The five exact coefficients, derived independently of the implementation's cross-product
/// forms: project q, u, v off the axis and expand |q_perp + r (cos u_perp + sin v_perp)|^2 - R^2
/// (cos^2 = (1 + cos 2t)/2, sin^2 = (1 - cos 2t)/2, 2 sin cos = sin 2t).
/// `centre_shift`: the rim's centre moved by this much (exactly, in MPFR).
std::array<Real, 5> exact_coefficients(const Pose& pose,
                                       const RealVector3& centre_shift = {Real(0), Real(0), Real(0)}) {
  const it::RealFrame frame = it::documented_frame(pose.circle.normal);
  const RealVector3 d = it::to_real(pose.cylinder.axis);
  const RealVector3 d_hat = Real(1) / it::norm(d) * d;
  auto perp = [&](const RealVector3& w) { return w - it::dot(w, d_hat) * d_hat; };
  const RealVector3 q = perp(it::to_real(pose.circle.center) + centre_shift -
                             it::to_real(pose.cylinder.axis_point));
  const RealVector3 u = perp(frame.u), v = perp(frame.v);
  const Real r(pose.circle.radius), R(pose.cylinder.radius);
  return {it::dot(q, q) + r * r * (it::dot(u, u) + it::dot(v, v)) / 2 - R * R,
          2 * r * it::dot(q, u), 2 * r * it::dot(q, v),
          r * r * (it::dot(u, u) - it::dot(v, v)) / 2, r * r * it::dot(u, v)};
}


/// A random pose whose rim comes near the wall, with lengths times `scale`, non-unit normal
/// and axis (magnitudes 1e-3..1e3), and a tilt between the rim normal and the axis of `tilt`
/// radians (negative: random tilt).
Pose random_pose(std::mt19937_64& rng, double scale, double tilt) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> decade(-3.0, 3.0);
  const Vector3 axis_dir = random_direction(rng);
  Vector3 normal_dir = random_direction(rng);
  if (tilt >= 0) {
    const Vector3 side = axis_dir.cross(random_direction(rng)).normalized();
    normal_dir = std::cos(tilt) * axis_dir + std::sin(tilt) * side;
  }
  const double R = scale * (1.0 + 0.5 * unit(rng));
  const double r = R * (0.7 + 0.25 * unit(rng));
  const Vector3 axis_point = scale * Vector3(unit(rng), unit(rng), unit(rng));
  // Centre: off the axis by about R - r .. R + r so that the rim usually crosses the wall.
  const Vector3 off = axis_dir.cross(random_direction(rng)).normalized();
  const Vector3 centre = axis_point + scale * unit(rng) * 3.0 * axis_dir +
                         (R + r * unit(rng)) * off;
  Pose pose;
  pose.circle = {centre, normal_dir * std::pow(10.0, decade(rng)), r};
  pose.cylinder = {axis_point, axis_dir * std::pow(10.0, decade(rng)), R};
  return pose;
}

std::vector<double> sample_angles(std::mt19937_64& rng) {
  std::vector<double> angles = {0.0, 1.5707963267948966, 3.141592653589793, 4.71238898038469,
                                6.283185307179586, -1.0, 1e-300, 100.0};
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  for (int i = 0; i < 24; ++i) angles.push_back(angle(rng));
  return angles;
}

/// All checks of one pose: coefficients, value and derivative at many angles, the curvature
/// bound. `tight` also demands that the bounds are useful (a few hundred ulps of the scale).
void check_pose(const Pose& pose, std::mt19937_64& rng, bool tight) {
  const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder);
  const std::array<Real, 5> k = exact_coefficients(pose);
  const Real scale = magnitude(pose);
  // Tightness: the longest rounding chain is a few dozen operations on terms of size `scale`.
  const double kUsefulRelativeError = 1e-12;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(Encloses(g.k[i], k[i], scale)) << "k" << i;
    if (tight) {
      ASSERT_LE(Real(g.k[i].error), kUsefulRelativeError * scale) << "k" << i;
    }
  }
  Real max_curvature = 0;
  for (const double theta : sample_angles(rng)) {
    const Real t(theta);
    const Bounded value = g.value(theta);
    ASSERT_TRUE(Encloses(value, it::rim_distance_excess(pose.circle, pose.cylinder, t), scale))
        << "g(" << theta << ")";
    ASSERT_TRUE(Encloses(value, it::trig_polynomial(k, t), scale)) << "g(" << theta << ")";
    ASSERT_TRUE(Encloses(g.derivative(theta), it::trig_polynomial_derivative(k, t), scale))
        << "g'(" << theta << ")";
    if (tight) {
      ASSERT_LE(Real(value.error), kUsefulRelativeError * scale);
    }
    // The angle-addition evaluation of the tier-1 proof (value_near) at the real angle
    // base + offset, base the grid angle nearest to theta (angle_grid.hpp), for offsets across
    // its whole range |offset| <= kMaxAngleOffset, theta's own among them.
    const GridAngle split = grid_angle(theta);
    const AngleBase& base = split.base;
    for (const double offset : {split.offset, 0.0, 1e-12, -3e-9, 1e-4, -0.01, kMaxAngleOffset,
                                -kMaxAngleOffset,
                                std::uniform_real_distribution<double>(-kMaxAngleOffset,
                                                                       kMaxAngleOffset)(rng)}) {
      const Real shifted = Real(base.angle) + Real(offset);
      // The cosine and sine tier 1 hands to the crossing points (RootEnclosure::cos, sin).
      const CosSin trig = cos_sin_near(base, offset);
      ASSERT_LE(abs(Real(trig.cos) - cos(shifted)), Real(kAngleAdditionTrigError))
          << base.angle << " + " << offset;
      ASSERT_LE(abs(Real(trig.sin) - sin(shifted)), Real(kAngleAdditionTrigError))
          << base.angle << " + " << offset;
      const Bounded near = g.value_near(base, offset);
      ASSERT_TRUE(Encloses(near, it::rim_distance_excess(pose.circle, pose.cylinder, shifted), scale))
          << "g(" << base.angle << " + " << offset << ")";
      ASSERT_TRUE(Encloses(near, it::trig_polynomial(k, shifted), scale))
          << "g(" << base.angle << " + " << offset << ")";
      if (tight) {
        ASSERT_LE(Real(near.error), kUsefulRelativeError * scale);
      }
      // Tier 1's proof by the slope: approximate_near's value and slope within
      // near_error_bounds of the exact ones, at every offset in range.
      const ValueAndSlope approximate = g.approximate_near(base, offset);
      const RimDistancePolynomial::NearErrorBounds bounds = g.near_error_bounds();
      ASSERT_LE(abs(Real(approximate.value) - it::trig_polynomial(k, shifted)), Real(bounds.value))
          << "g(" << base.angle << " + " << offset << ")";
      ASSERT_LE(abs(Real(approximate.slope) - it::trig_polynomial_derivative(k, shifted)), Real(bounds.slope))
          << "g'(" << base.angle << " + " << offset << ")";
      if (tight) {
        ASSERT_LE(Real(bounds.value), kUsefulRelativeError * scale);
        ASSERT_LE(Real(bounds.slope), kUsefulRelativeError * scale);
      }
    }
    const Real second = -k[1] * cos(t) - k[2] * sin(t) - 4 * k[3] * cos(2 * t) - 4 * k[4] * sin(2 * t);
    max_curvature = std::max(max_curvature, abs(second));
  }
  EXPECT_GE(Real(g.second_derivative_bound()), max_curvature);
  EXPECT_GE(Real(g.curvature_bound()), max_curvature);
  EXPECT_GE(g.curvature_bound(), g.second_derivative_bound() * (1 - 1e-12));  // the looser of the two
}

TEST(RimDistancePolynomial, EnclosesTheExactDistanceExcessForRandomPoses) {
  std::mt19937_64 rng(101);
  for (int i = 0; i < 60; ++i) check_pose(random_pose(rng, 1.0, -1.0), rng, true);
}

TEST(RimDistancePolynomial, EvaluatesTwoOffsetsInLanesBitForBitAsOneAtATime) {
  // value_near and approximate_near over Pair (tier 1's proof points and Newton runs): lane i
  // must be the double call at offset i, field for field, at scales from 1e-50 to 1e50.
  std::mt19937_64 rng(107);
  std::uniform_real_distribution<double> offsets(-kMaxAngleOffset, kMaxAngleOffset), angles(0.0, kTwoPi);
  auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  for (int i = 0; i < 300; ++i) {
    const Pose pose = random_pose(rng, i % 3 == 0 ? 1e-50 : (i % 3 == 1 ? 1.0 : 1e50), -1.0);
    const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder);
    const AngleBase base = grid_angle(angles(rng)).base, other = grid_angle(angles(rng)).base;
    const double offset[2] = {offsets(rng), i % 4 == 0 ? 0.0 : offsets(rng)};
    const PairBounded near = g.value_near(base, Pair{offset[0], offset[1]});
    const AngleBaseOf<Pair> bases = {{base.angle, other.angle}, {base.cos, other.cos}, {base.sin, other.sin}};
    const ValueAndSlopeOf<Pair> at = g.approximate_near(bases, Pair{offset[0], offset[1]});
    for (int lane = 0; lane < 2; ++lane) {
      const Bounded one = g.value_near(base, offset[lane]);
      EXPECT_EQ(bits(near.lane(lane).value), bits(one.value)) << i << " lane " << lane;
      EXPECT_EQ(bits(near.lane(lane).error), bits(one.error)) << i << " lane " << lane;
      const ValueAndSlope alone = g.approximate_near(lane == 0 ? base : other, offset[lane]);
      EXPECT_EQ(bits(at.value[lane]), bits(alone.value)) << i << " lane " << lane;
      EXPECT_EQ(bits(at.slope[lane]), bits(alone.slope)) << i << " lane " << lane;
      EXPECT_EQ(bits(at.cos[lane]), bits(alone.cos)) << i << " lane " << lane;
      EXPECT_EQ(bits(at.sin[lane]), bits(alone.sin)) << i << " lane " << lane;
    }
  }
}

TEST(RimDistancePolynomial, EnclosesTheExactDistanceExcessAtTinyTilts) {
  std::mt19937_64 rng(103);
  for (const double tilt : {0.0, 1e-15, 1e-12, 1e-9, 1e-6}) {
    for (int i = 0; i < 8; ++i) check_pose(random_pose(rng, 1.0, tilt), rng, true);
  }
}

TEST(RimDistancePolynomial, EnclosesTheExactDistanceExcessAtHugeAndTinyScales) {
  std::mt19937_64 rng(107);
  for (const double scale : {1e-100, 1e-30, 1e-3, 1e3, 1e30, 1e100}) {
    for (int i = 0; i < 8; ++i) check_pose(random_pose(rng, scale, i % 2 ? -1.0 : 1e-12), rng, true);
  }
}

TEST(RimDistancePolynomial, EnclosesTheExactDistanceExcessWithVeryShortNormals) {
  // A normal of length ~1e-161: |n|^2 and |n x d|^2 are subnormal, the hardest case for the
  // error bound of the tilt term (the bound may be loose, or not finite, but must hold).
  // v' = n x u' scales as |n|^2, so |v'|^2 underflows below |n| ~ 1e-77: not certified then.
  std::mt19937_64 rng(109);
  for (const double length : {1e-30, 1e30, 1e-100, 1e-155, 1e-161}) {
    for (int i = 0; i < 8; ++i) {
      Pose pose = random_pose(rng, 1.0, -1.0);
      pose.circle.normal = pose.circle.normal.normalized() * length;
      const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder);
      const std::array<Real, 5> k = exact_coefficients(pose);
      for (int j = 0; j < 5; ++j) {
        // Lengths 1e+-30 stay far from under- and overflow: the bound must be finite there.
        if (std::fabs(std::log10(length)) < 50) {
          ASSERT_TRUE(g.k[j].finite()) << "k" << j;
        }
        if (!g.k[j].finite()) continue;  // "not certified" is allowed
        EXPECT_TRUE(Encloses(g.k[j], k[j], magnitude(pose))) << "length " << length << " k" << j;
      }
    }
  }
}

TEST(RimDistancePolynomial, MatchesTheAnalyticPolynomialOfATiltedCircleCentredOnTheAxis) {
  // Normal (0,3,4), radius 5, centred on the z axis: x(t) = (-5 sin t, 4 cos t, -3 cos t)
  // (frame of primitives.hpp: u = (0,4,-3)/5, v = (-1,0,0)), so
  // g = 25 sin^2 + 16 cos^2 - R^2 = 16 + 9/2 - R^2 - (9/2) cos 2t.
  const Circle3 circle{{0, 0, 7}, {0, 3, 4}, 5};
  const Cylinder3 cylinder{{0, 0, -2}, {0, 0, 2}, 4.5};
  const RimDistancePolynomial g = rim_distance_polynomial(circle, cylinder);
  const double expected[5] = {16 + 4.5 - 20.25, 0, 0, -4.5, 0};
  for (int i = 0; i < 5; ++i) {
    EXPECT_LE(std::fabs(g.k[i].value - expected[i]), g.k[i].error) << "k" << i;
  }
}

// ---- widen_for_centre_error -------------------------------------------------------------

TEST(RimDistancePolynomial, HandsBackTheRimFrameBitForBitOnTheAPrioriPath) {
  // The query's crossing points use this frame instead of frame_of: it must be the same doubles,
  // or the crossing points would change.
  std::mt19937_64 rng(113);
  for (int i = 0; i < 200; ++i) {
    const double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1e-20 : 1e20);
    const Pose pose = random_pose(rng, scale, i % 2 ? -1.0 : 1e-3);
    std::optional<CircleFrame> frame;
    const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder, true, frame);
    ASSERT_TRUE(frame.has_value());
    const CircleFrame expected = frame_of(pose.circle);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(frame->u[j], expected.u[j]) << "pose " << i;
      EXPECT_EQ(frame->v[j], expected.v[j]) << "pose " << i;
    }
    // And the coefficients are the ones of the overload without the frame.
    const RimDistancePolynomial plain = rim_distance_polynomial(pose.circle, pose.cylinder, true);
    for (int j = 0; j < 5; ++j) {
      EXPECT_EQ(g.k[j].value, plain.k[j].value);
      EXPECT_EQ(g.k[j].error, plain.k[j].error);
    }
  }
}

TEST(RimDistancePolynomial, LeavesTheFrameEmptyOnTheRunningErrorPath) {
  const Pose pose{{{1, 2, 3}, {0.1, 0.2, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 2}};
  std::optional<CircleFrame> frame = frame_of(pose.circle);
  rim_distance_polynomial(pose.circle, pose.cylinder, false, frame);
  EXPECT_FALSE(frame.has_value());
}

TEST(RimDistancePolynomial, WidenedForACentreErrorEnclosesEveryRimWithinIt) {
  // The widened coefficients must enclose the exact coefficients of the rim at any centre within
  // the error; shifts of exactly the error's length in random directions (and along the
  // worst-case directions: towards the axis, along u and v) are checked.
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> decade(-14.0, -1.0);
  for (int i = 0; i < 200; ++i) {
    const Pose pose = random_pose(rng, i % 2 == 0 ? 1.0 : 1e-3, -1.0);
    const double error = std::pow(10.0, decade(rng)) * pose.cylinder.radius;
    RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder);
    widen_for_centre_error(g, pose.circle, pose.cylinder, error);
    const Vector3 d = pose.cylinder.axis.normalized();
    const Vector3 q = pose.circle.center - pose.cylinder.axis_point;
    const Vector3 toward_axis = -(q - q.dot(d) * d).normalized();
    const CircleFrame frame = frame_of(pose.circle);
    for (const Vector3& direction : {toward_axis, Vector3(-toward_axis), frame.u, frame.v,
                                     random_direction(rng), random_direction(rng)}) {
      // A shift of exactly the error's length (in MPFR: a double sum would round).
      const RealVector3 unit = Real(1) / it::norm(it::to_real(direction)) * it::to_real(direction);
      const std::array<Real, 5> k = exact_coefficients(pose, Real(error) * unit);
      for (int c = 0; c < 5; ++c) {
        ASSERT_TRUE(Encloses(g.k[c], k[c], magnitude(pose))) << i << " k" << c;
      }
    }
  }
}

TEST(RimDistancePolynomial, WideningByZeroChangesNothing) {
  std::mt19937_64 rng(7);
  const Pose pose = random_pose(rng, 1.0, -1.0);
  const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder);
  RimDistancePolynomial widened = g;
  widen_for_centre_error(widened, pose.circle, pose.cylinder, 0.0);
  for (int c = 0; c < 5; ++c) EXPECT_EQ(widened.k[c].error, g.k[c].error);
}

// ---- axis_offset, shared by the reach test, the polynomial and the widening ---------------

/// Poses for the bit-for-bit comparisons: random ones at several scales, and ones whose inputs
/// sit at the edges of the a priori guard (2^-100 and 2^100), where the shared quantities are
/// formed from the extreme magnitudes the a priori path accepts.
std::vector<Pose> shared_offset_poses() {
  std::mt19937_64 rng(20261124);
  std::vector<Pose> poses;
  for (int i = 0; i < 300; ++i) {
    const double scale = i % 4 == 0 ? 1.0 : (i % 4 == 1 ? 0x1p-60 : (i % 4 == 2 ? 0x1p60 : 1e-3));
    poses.push_back(random_pose(rng, scale, i % 2 ? -1.0 : 1e-9));
  }
  for (int i = 0; i < 40; ++i) {
    Pose pose = random_pose(rng, 1.0, -1.0);
    const double edge = i % 2 ? kSmallestGuardedInput : kLargestGuardedInput;
    pose.circle.normal[i % 3] = std::copysign(edge, pose.circle.normal[i % 3]);
    pose.cylinder.axis[(i / 2) % 3] = std::copysign(edge, pose.cylinder.axis[(i / 2) % 3]);
    poses.push_back(pose);
  }
  return poses;
}

TEST(AxisOffset, HoldsTheQuantitiesTheKernelFormedSeparatelyBitForBit) {
  // rim_reach, the a priori polynomial and the widening each used to form these themselves, with
  // these Eigen expressions; their answers stay the same only if the shared ones are these doubles.
  for (const Pose& pose : shared_offset_poses()) {
    const AxisOffset offset = axis_offset(pose.circle, pose.cylinder);
    const Vector3 q = pose.circle.center - pose.cylinder.axis_point;
    const Vector3& d = pose.cylinder.axis;
    const Vector3 perp = q.cross(d), perp_abs = abs_cross(q.cwiseAbs(), d.cwiseAbs());
    for (int j = 0; j < 3; ++j) {
      ASSERT_EQ(offset.q[j], q[j]);
      ASSERT_EQ(offset.perp[j], perp[j]);
      ASSERT_EQ(offset.perp_abs[j], perp_abs[j]);
    }
    ASSERT_EQ(offset.perp2, q.cross(d).squaredNorm());
    ASSERT_EQ(offset.perp2_abs, perp_abs.squaredNorm());
    ASSERT_EQ(offset.axis_norm2, d.squaredNorm());
  }
}

TEST(AxisOffset, GivesTheReachTestPolynomialAndWideningTheirOwnAnswersBitForBit) {
  // The query's sequence (intersect_circle_cylinder.cpp) with one offset against each function
  // called on its own, on both paths, with and without a centre error.
  for (const Pose& pose : shared_offset_poses()) {
    const AxisOffset offset = axis_offset(pose.circle, pose.cylinder);
    ASSERT_EQ(reach_a_priori_bounds_apply(offset, pose.circle, pose.cylinder),
              reach_a_priori_bounds_apply(pose.circle, pose.cylinder));
    for (const bool a_priori : {true, false}) {
      for (const double centre_error : {0.0, 1e-9 * pose.cylinder.radius}) {
        ASSERT_EQ(rim_reach(pose.circle, pose.cylinder, offset, a_priori, centre_error),
                  rim_reach(pose.circle, pose.cylinder, a_priori, centre_error));
        std::optional<CircleFrame> frame, own_frame;
        RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder, offset, a_priori, frame);
        RimDistancePolynomial own = rim_distance_polynomial(pose.circle, pose.cylinder, a_priori, own_frame);
        widen_for_centre_error(g, pose.circle, offset, centre_error);
        widen_for_centre_error(own, pose.circle, pose.cylinder, centre_error);
        for (int j = 0; j < 5; ++j) {
          ASSERT_EQ(g.k[j].value, own.k[j].value) << "k" << j;
          ASSERT_EQ(g.k[j].error, own.k[j].error) << "k" << j;
        }
        ASSERT_EQ(frame.has_value(), own_frame.has_value());
      }
    }
  }
}

/// The a priori coefficients (value, bound) as scalar Eigen expressions, one double at a time:
/// the formulas rim_distance_polynomial_a_priori evaluates two lanes at a time.
std::array<Bounded, 5> scalar_a_priori_coefficients(const Circle3& circle, const Cylinder3& cylinder) {
  const Vector3 q = circle.center - cylinder.axis_point;
  const Vector3 &d = cylinder.axis, &n = circle.normal;
  const Vector3 u = n.cross(Vector3::Unit(frame_axis_index(n)));
  const Vector3 v = n.cross(u);
  const Vector3 qa = q.cwiseAbs(), da = d.cwiseAbs(), na = n.cwiseAbs(), ua = u.cwiseAbs();
  const Vector3 va = abs_cross(na, ua);
  const double inverse_d2 = 1.0 / d.squaredNorm();
  const double iu = 1.0 / std::sqrt(u.squaredNorm()), iv = 1.0 / std::sqrt(v.squaredNorm());
  const double r = circle.radius, R = cylinder.radius, r2 = r * r;
  const Vector3 a = q.cross(d), a_abs = abs_cross(qa, da);
  const double fc = a.dot(u.cross(d)) * iu, fc_abs = a_abs.dot(abs_cross(ua, da)) * iu;
  const double fs = a.dot(v.cross(d)) * iv, fs_abs = a_abs.dot(abs_cross(va, da)) * iv;
  const double au = u.dot(d) * iu, au_abs = ua.dot(da) * iu;
  const double av = v.dot(d) * iv, av_abs = va.dot(da) * iv;
  const double in2 = 1.0 / n.squaredNorm();
  const double tilt = n.cross(d).squaredNorm() * in2, tilt_abs = abs_cross(na, da).squaredNorm() * in2;
  const double values[5] = {(a.squaredNorm() - 0.5 * r2 * tilt) * inverse_d2 + (r - R) * (r + R),
                            2.0 * r * fc * inverse_d2, 2.0 * r * fs * inverse_d2,
                            0.5 * r2 * (av * av - au * au) * inverse_d2, -(r2 * au * av) * inverse_d2};
  const double twins[5] = {(a_abs.squaredNorm() + 0.5 * r2 * tilt_abs) * inverse_d2 + std::fabs(r - R) * (r + R),
                           2.0 * r * fc_abs * inverse_d2, 2.0 * r * fs_abs * inverse_d2,
                           0.5 * r2 * (av_abs * av_abs + au_abs * au_abs) * inverse_d2,
                           r2 * au_abs * av_abs * inverse_d2};
  std::array<Bounded, 5> k;
  for (int i = 0; i < 5; ++i) k[i] = {values[i], kGamma64 * twins[i] * kMagnitudeInflation};
  return k;
}

TEST(RimDistancePolynomial, APrioriCoefficientsInLanesAreTheScalarFormulasBitForBit) {
  // Each lane must round exactly as the scalar expression (no reordering, no contraction): the
  // query's answers, proved from these bounds, are otherwise not the documented ones.
  for (const Pose& pose : shared_offset_poses()) {
    const RimDistancePolynomial g = rim_distance_polynomial(pose.circle, pose.cylinder, true);
    const std::array<Bounded, 5> expected = scalar_a_priori_coefficients(pose.circle, pose.cylinder);
    for (int j = 0; j < 5; ++j) {
      ASSERT_EQ(g.k[j].value, expected[j].value) << "k" << j;
      ASSERT_EQ(g.k[j].error, expected[j].error) << "k" << j;
    }
  }
}

// ---- rim_reach --------------------------------------------------------------------------

/// Sampled max and min of dist(x(t), axis) - R over the rim, in MPFR.
std::pair<Real, Real> sampled_excess_range(const Pose& pose) {
  const it::RealFrame frame = it::documented_frame(pose.circle.normal);
  Real low = 0, high = 0;
  const Real step = it::two_pi() / 180;
  for (int i = 0; i < 180; ++i) {
    const Real excess =
        it::axis_distance_excess(it::rim_point(pose.circle, frame, step * i), pose.cylinder);
    if (i == 0 || excess < low) low = excess;
    if (i == 0 || excess > high) high = excess;
  }
  return {low, high};
}

void check_reach_is_never_wrong(const Pose& pose) {
  const RimReach reach = rim_reach(pose.circle, pose.cylinder);
  const Real centre = it::centre_axis_distance(pose.circle, pose.cylinder);
  const Real r(pose.circle.radius), R(pose.cylinder.radius);
  if (reach == RimReach::strictly_inside) {
    ASSERT_LT(centre + r, R) << "claimed strictly inside";
    ASSERT_LT(sampled_excess_range(pose).second, 0) << "claimed strictly inside";
  } else if (reach == RimReach::strictly_outside) {
    ASSERT_GT(centre - r, R) << "claimed strictly outside";
    ASSERT_GT(sampled_excess_range(pose).first, 0) << "claimed strictly outside";
  }
}

TEST(RimReach, IsNeverWrongOnRandomPoses) {
  std::mt19937_64 rng(113);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inside = 0, outside = 0;
  for (int i = 0; i < 300; ++i) {
    Pose pose = random_pose(rng, i % 3 == 0 ? 1e-50 : (i % 3 == 1 ? 1.0 : 1e50), -1.0);
    // Move the centre across the whole range from the axis to well beyond the wall.
    const Vector3 d = pose.cylinder.axis.normalized();
    const Vector3 q = pose.circle.center - pose.cylinder.axis_point;
    const Vector3 perp = q - q.dot(d) * d;
    pose.circle.center = pose.cylinder.axis_point + q.dot(d) * d +
                         perp * (3.0 * unit(rng) * pose.cylinder.radius / perp.norm());
    check_reach_is_never_wrong(pose);
    const RimReach reach = rim_reach(pose.circle, pose.cylinder);
    inside += reach == RimReach::strictly_inside;
    outside += reach == RimReach::strictly_outside;
  }
  // The test would be vacuous if nothing were ever decided.
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 10);
}

TEST(RimReach, DecidesClearCasesAndLeavesExactTouchingUndecided) {
  const Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 2};
  // dist(c) + r == R exactly: the rim touches the wall from inside.
  EXPECT_EQ(rim_reach({{1, 0, 0}, {0, 0, 1}, 1}, wall), RimReach::undecided);
  // dist(c) - r == R exactly: touches from outside.
  EXPECT_EQ(rim_reach({{3, 0, 0}, {0, 0, 1}, 1}, wall), RimReach::undecided);
  EXPECT_EQ(rim_reach({{0.5, 0, 5}, {0, 1, 1}, 1}, wall), RimReach::strictly_inside);
  EXPECT_EQ(rim_reach({{0, -4, 5}, {1, 1, 1}, 1}, wall), RimReach::strictly_outside);
  EXPECT_EQ(rim_reach({{2, 0, 0}, {0, 0, 1}, 1}, wall), RimReach::undecided);  // crossing
  // A rim larger than the wall can never be strictly inside.
  EXPECT_NE(rim_reach({{0, 0, 0}, {0, 0, 1}, 3}, wall), RimReach::strictly_inside);
}

TEST(RimReach, WithACentreErrorIsNeverWrongForAnyCentreWithinIt) {
  // A rim whose centre is only known to within e: strictly inside must hold for the farthest
  // centre, strictly outside for the nearest. Rims with dist + r = R - e/2 (inside for the stored
  // centre, not for every centre within e) must stay undecided; at R - 2e they are decided when
  // e is well above the rounding of the test (a priori: 64 u of the squares, ~1e-14 here).
  const Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 2};
  for (const bool a_priori : {true, false}) {
    for (const double e : {1e-3, 1e-9, 1e-15}) {
      SCOPED_TRACE(e);
      const Circle3 barely{{1 - 0.5 * e, 0, 0}, {0, 0, 1}, 1};
      const Circle3 barely_out{{3 + 0.5 * e, 0, 0}, {0, 0, 1}, 1};
      EXPECT_EQ(rim_reach(barely, wall, a_priori, e), RimReach::undecided);
      EXPECT_EQ(rim_reach(barely_out, wall, a_priori, e), RimReach::undecided);
      if (e < 1e-12) continue;
      EXPECT_EQ(rim_reach(barely, wall, a_priori, 0.0), RimReach::strictly_inside);
      EXPECT_EQ(rim_reach(Circle3{{1 - 2 * e, 0, 0}, {0, 0, 1}, 1}, wall, a_priori, e),
                RimReach::strictly_inside);
      EXPECT_EQ(rim_reach(Circle3{{3 + 2 * e, 0, 0}, {0, 0, 1}, 1}, wall, a_priori, e),
                RimReach::strictly_outside);
    }
  }
}

TEST(RimReach, IsNeverWrongFromOneUlpAwayFromTouchingToWhereItDecides) {
  // Integer poses touching exactly, then R, r and the centre moved by 1 to 4 ulps (where nothing
  // can be decided) and on by 2^8 .. 2^40 ulps, across the distance where the bounds start to
  // decide: every answer given there must be right.
  const std::vector<Pose> touching = {
      {{{1, 0, 0}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 2}},
      {{{3, 0, 0}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 2}},
      {{{3, 4, 9}, {1, 2, 3}, 2}, {{0, 0, -5}, {0, 0, 3}, 7}},   // dist 5: 5 + 2 = 7
      {{{3, 4, 9}, {1, 2, 3}, 2}, {{0, 0, -5}, {0, 0, 3}, 3}},   // 5 - 2 = 3
      {{{6, 8, 1}, {1, 0, 0}, 1e-3}, {{0, 0, 0}, {0, 0, 1e-9}, 10 - 1e-3}},
  };
  // x moved by n of its ulps towards `direction` (n a power of two or small: exact steps).
  auto moved = [](double x, double direction, double n) { return x + n * (std::nextafter(x, direction) - x); };
  int decided = 0;
  for (const Pose& base : touching) {
    for (int which = 0; which < 3; ++which) {
      for (const double direction : {-HUGE_VAL, HUGE_VAL}) {
        for (const double ulps : {1.0, 2.0, 3.0, 4.0, 0x1p8, 0x1p16, 0x1p24, 0x1p32, 0x1p40}) {
          Pose pose = base;
          if (which == 0) pose.cylinder.radius = moved(base.cylinder.radius, direction, ulps);
          if (which == 1) pose.circle.radius = moved(base.circle.radius, direction, ulps);
          if (which == 2) pose.circle.center.x() = moved(base.circle.center.x(), direction, ulps);
          SCOPED_TRACE(ulps);
          check_reach_is_never_wrong(pose);
          decided += rim_reach(pose.circle, pose.cylinder) != RimReach::undecided;
        }
      }
    }
  }
  // Decided: 73 of the 270 measured (none within 4 ulps, most from 2^32 ulps on). The floor
  // leaves a margin of 13.
  EXPECT_GE(decided, 60);
}

TEST(APrioriGuard, AcceptsExactlyMagnitudesInItsRangeOrZeroInEveryInputPosition) {
  // The guard of the a priori bounds (cylinder_a_priori_bounds_apply, reach_a_priori_bounds_apply):
  // every guarded value zero or of magnitude in [2^-100, 2^100]. Each of its nine positions is
  // set in turn to values just inside and just outside the range, both signs, and to NaN and
  // infinity, in an otherwise accepted pose (the axis point at the origin, so that q = c - p is
  // the centre itself and the reach guard's q sees the same value).
  const double low = kSmallestGuardedInput, high = kLargestGuardedInput;
  struct Case {
    double value;
    bool in_range;
  };
  const std::vector<Case> cases = {
      {0.0, true}, {-0.0, true}, {low, true}, {high, true}, {1.0, true},
      {std::nextafter(low, 0.0), false}, {std::nextafter(high, HUGE_VAL), false},
      {0x1p-1074, false}, {HUGE_VAL, false}, {std::nan(""), false}};
  const Pose accepted{{{0.5, -0.25, 1.0}, {0.0, 0.6, 0.8}, 1.0}, {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 2.0}};
  ASSERT_TRUE(cylinder_a_priori_bounds_apply(accepted.circle, accepted.cylinder));
  for (int position = 0; position < 12; ++position) {
    for (const Case& c : cases) {
      for (const double sign : {1.0, -1.0}) {
        Pose pose = accepted;
        const double x = sign * c.value;
        // Radii are positive in every valid input, but the guard does not rely on that.
        if (position < 3) pose.circle.center[position] = x;
        else if (position < 6) pose.circle.normal[position - 3] = x;
        else if (position < 9) pose.cylinder.axis[position - 6] = x;
        else if (position == 9) pose.circle.radius = x;
        else if (position == 10) pose.cylinder.radius = x;
        else pose.cylinder.axis_point.x() = x, pose.circle.center.x() = x;  // q.x = 0 stays in range
        const bool reach = reach_a_priori_bounds_apply(pose.circle, pose.cylinder);
        const bool full = cylinder_a_priori_bounds_apply(pose.circle, pose.cylinder);
        // The normal is the only position the reach guard leaves to the full guard; the axis
        // point (position 11) reaches the reach guard only through q = x - x, which is 0 for a
        // finite x and NaN otherwise.
        const bool reach_expected = position < 3 || (position >= 6 && position <= 10) ? c.in_range
                                    : position == 11                                   ? std::isfinite(x)
                                                                                       : true;
        EXPECT_EQ(reach, reach_expected) << position << " " << x;
        EXPECT_EQ(full, c.in_range) << position << " " << x;
      }
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
