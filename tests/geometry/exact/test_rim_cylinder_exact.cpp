// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/rim_cylinder_exact.{hpp,cpp}: exactly representable rim/wall poses with
// analytic roots and multiplicities (tangencies, double roots, the M = 0 and shared-root branches
// of the file's elimination), and random integer poses against 256-bit MPFR signs.

#include "exact/rim_cylinder_exact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
namespace it = internal_testing;

struct ExpectedRoot {
  Real angle;
  int multiplicity;
  int sign_after;
};

Real g_at(const Circle3& circle, const Cylinder3& cylinder, const Real& theta) {
  return it::rim_distance_excess(circle, cylinder, theta);
}

/// Checks every enclosure, multiplicity and sign against the analytic roots, and sign_after
/// against the exact sign of g at the midpoint to the next root.
void expect_roots(const Circle3& circle, const Cylinder3& cylinder,
                  const std::vector<ExpectedRoot>& expected) {
  const RimRoots result = exact_rim_roots(circle, cylinder);
  ASSERT_TRUE(result.proved);
  ASSERT_EQ(result.count, static_cast<int>(expected.size()));
  for (int i = 0; i < result.count; ++i) {
    const RootEnclosure& root = result.roots[i];
    EXPECT_GE(root.angle, 0.0);
    EXPECT_LT(root.angle, 2 * std::numbers::pi);
    if (i > 0) {
      EXPECT_LT(result.roots[i - 1].angle, root.angle);
    }
    int matches = 0;
    for (const ExpectedRoot& e : expected) {
      if (it::circular_gap(Real(root.angle), e.angle) <= Real(root.radius)) {
        ++matches;
        EXPECT_EQ(root.multiplicity, e.multiplicity) << "root at " << root.angle;
        EXPECT_EQ(root.sign_after, e.sign_after) << "root at " << root.angle;
      }
    }
    EXPECT_EQ(matches, 1) << "enclosure " << root.angle << " +- " << root.radius;
    const double next = i + 1 < result.count ? result.roots[i + 1].angle
                                             : result.roots[0].angle + 2 * std::numbers::pi;
    EXPECT_EQ(root.sign_after,
              it::sign_of(g_at(circle, cylinder, (Real(root.angle) + Real(next)) / 2)))
        << "direct sign after root " << root.angle;
  }
}

const Real kPi = it::pi();

TEST(RimCylinderExact, ReportsInternalTangencyAsOneDoubleRoot) {
  // Frame: u = (0,1,0), v = (-1,0,0); x(t) = (1 - sin t, cos t, 0), g = -2 - 2 sin t.
  expect_roots({{1, 0, 0}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 2}, {{3 * kPi / 2, 2, -1}});
}

TEST(RimCylinderExact, ReportsTangencyOfAnUntiltedRimWhoseLineEquationVanishes) {
  // Centre along u: M is identically zero and the crossings lie on vertical lines of L.
  // x(t) = (-sin t, 1 + cos t, 0): g = 2 cos t - 2, double root at 0 (on the seam).
  expect_roots({{0, 1, 0}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 2}, {{Real(0), 2, -1}});
  // Outside the wall: x(t) = (-2 sin t, 3 + 2 cos t, 0), g = 12 + 12 cos t, double root at pi.
  expect_roots({{0, 3, 0}, {0, 0, 1}, 2}, {{0, 0, 0}, {0, 0, 1}, 1}, {{kPi, 2, +1}});
  // Non-unit, reversed normal (u = (0,-1,0), v = (-1,0,0)), non-unit axis, axis point shifted
  // along the axis: x(t) = (-2 sin t, 3 - 2 cos t, 5), g = 12 - 12 cos t, double root at 0.
  expect_roots({{0, 3, 5}, {0, 0, -7}, 2}, {{0, 0, -3}, {0, 0, 0.5}, 1}, {{Real(0), 2, +1}});
}

// Normal (0,3,4), radius 5, centred on the z axis: u = (0,4,-3)/5, v = (-1,0,0),
// x(t) = (-5 sin t, 4 cos t, -3 cos t), dist^2 = 16 + 9 sin^2 t.
const Circle3 kTiltedRim{{0, 0, 0}, {0, 3, 4}, 5};

TEST(RimCylinderExact, ReportsTwoDoubleRootsWhereTheWallTouchesTheProjectedMinorAxis) {
  expect_roots(kTiltedRim, {{0, 0, 0}, {0, 0, 1}, 4}, {{Real(0), 2, +1}, {kPi, 2, +1}});
}

TEST(RimCylinderExact, ReportsTwoDoubleRootsWhereTheWallTouchesTheMajorAxis) {
  expect_roots(kTiltedRim, {{0, 0, 0}, {0, 0, 1}, 5}, {{kPi / 2, 2, -1}, {3 * kPi / 2, 2, -1}});
}

TEST(RimCylinderExact, ReportsFourSimpleRootsBetweenTheAxes) {
  // 9 sin^2 t = 4.5^2 - 16 = 17/4: sin t = +-sqrt(17)/6.
  const Real a = asin(sqrt(Real(17)) / 6);
  expect_roots(kTiltedRim, {{0, 0, 0}, {0, 0, 1}, 4.5},
               {{a, 1, +1}, {kPi - a, 1, -1}, {kPi + a, 1, +1}, {2 * kPi - a, 1, -1}});
}

TEST(RimCylinderExact, ReportsACoaxialRimOfEqualRadiusAsLyingOnTheWall) {
  const RimRoots on = exact_rim_roots({{0, 0, 7}, {0, 0, 5}, 3}, {{0, 0, -1}, {0, 0, 2}, 3});
  EXPECT_TRUE(on.proved);
  EXPECT_EQ(on.count, 0);
  EXPECT_EQ(on.side_without_roots, RimSideWithoutRoots::on_surface);
  const RimRoots inside = exact_rim_roots({{0, 0, 7}, {0, 0, 5}, 2}, {{0, 0, -1}, {0, 0, 2}, 3});
  EXPECT_TRUE(inside.proved);
  EXPECT_EQ(inside.count, 0);
  EXPECT_EQ(inside.side_without_roots, RimSideWithoutRoots::inside);
  const RimRoots outside = exact_rim_roots({{0, 0, 7}, {0, 0, 5}, 4}, {{0, 0, -1}, {0, 0, 2}, 3});
  EXPECT_EQ(outside.count, 0);
  EXPECT_EQ(outside.side_without_roots, RimSideWithoutRoots::beyond);
}

TEST(RimCylinderExact, HandlesLAndMSharingARootWhenTheRimPlaneContainsTheAxis) {
  // Rim in z = 0 centred on the axis of direction (3,4,0): dist = |m . x| with m = (-4,3,0)/5,
  // x(t) = 5 (-sin t, cos t, 0), m . x = 5 sin(t + phi), phi = asin(3/5). g = 25 sin^2(t + phi) - 16.
  // Both rim points of X = 0 (t = pi/2, 3 pi/2) are on the wall: L and M share the root X = 0.
  const Real phi = asin(Real(3) / 5);
  expect_roots({{0, 0, 0}, {0, 0, 1}, 5}, {{0, 0, 0}, {3, 4, 0}, 4},
               {{kPi / 2 - 2 * phi, 1, +1}, {kPi / 2, 1, -1}, {3 * kPi / 2 - 2 * phi, 1, +1},
                {3 * kPi / 2, 1, -1}});
}

TEST(RimCylinderExact, MergesTheSharedRootLinesMeetingOnTheRimIntoADoubleRoot) {
  // Rim centre (0,-15,0), radius 25 in z = 0; wall axis (3,4,0) through 0, R = 16.
  // m . x(t) = 25 sin(t + phi) - 9, g = (25 sin(t + phi) - 9)^2 - 256: tangent where
  // sin(t + phi) = 1 (t = pi/2 - phi, X = 15), crossing where sin(t + phi) = -7/25, one of them
  // (t = 3 pi/2 + phi) the mirror of the tangent point on the same line X = 15.
  const Real phi = asin(Real(3) / 5);
  expect_roots({{0, -15, 0}, {0, 0, 1}, 25}, {{0, 0, 0}, {3, 4, 0}, 16},
               {{kPi / 2 - phi, 2, -1}, {kPi + asin(Real(7) / 25) - phi, 1, +1},
                {3 * kPi / 2 + phi, 1, -1}});
}

/// Each enclosure holds a sign change of g (a simple root) and is narrower than `width`.
void expect_simple_roots(const RimRoots& result, const Circle3& circle, const Cylinder3& cylinder, int count,
                         double width) {
  ASSERT_TRUE(result.proved);
  ASSERT_EQ(result.count, count);
  for (int i = 0; i < result.count; ++i) {
    const RootEnclosure& root = result.roots[i];
    EXPECT_EQ(root.multiplicity, 1);
    EXPECT_LT(root.radius, width) << "root at " << root.angle;
    EXPECT_EQ(it::sign_of(g_at(circle, cylinder, Real(root.angle) - Real(root.radius))),
              -it::sign_of(g_at(circle, cylinder, Real(root.angle) + Real(root.radius))))
        << "root at " << root.angle << " +- " << root.radius;
  }
}

TEST(RimCylinderExact, SeparatesTwoCrossingsThatShareTheirFirstRimCoordinate) {
  // A rim tilted 45 degrees about x, its centre 0.7 off the wall's axis (z) along y: mirror-
  // symmetric about the plane x = 0, which holds the axis, so its two crossings share X (the
  // frame's u' = n x e_x lies in that plane) and have opposite Y. Exactly symmetric, and broken
  // by 2^-200: there L and M nearly share a root and -L/M at the crossings is beyond double
  // arithmetic; their exact signs at the root pick each crossing's half of the rim.
  const Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 1};
  for (const double asymmetry : {0.0, 0x1p-200, -0x1p-200}) {
    const Circle3 rim{{asymmetry, 0.7, 0.0}, {asymmetry, 1, 1}, 1};
    const RimRoots roots = exact_rim_roots(rim, wall);
    expect_simple_roots(roots, rim, wall, 2, 1e-12);
    if (roots.count == 2) {
      EXPECT_GT(roots.roots[1].angle - roots.roots[0].angle, 0.1) << "asymmetry " << asymmetry;
    }
  }
}

TEST(RimCylinderExact, AgreesWithDirectSignsOnRandomIntegerPoses) {
  std::mt19937_64 rng(307);
  std::uniform_int_distribution<int> small_int(-4, 4);
  auto small = [&](std::mt19937_64& g) { return static_cast<double>(small_int(g)); };
  std::uniform_int_distribution<int> radius(1, 8);
  int with_roots = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Vector3 normal(small(rng), small(rng), small(rng));
    const Vector3 axis(small(rng), small(rng), small(rng));
    if (normal.isZero() || axis.isZero()) continue;
    const Circle3 circle{{small(rng), small(rng), small(rng)}, normal, radius(rng) * 0.5};
    const Cylinder3 cylinder{{small(rng), small(rng), small(rng)}, axis, radius(rng) * 0.5};
    const RimRoots result = exact_rim_roots(circle, cylinder);
    ASSERT_TRUE(result.proved);
    int total = 0;
    for (int i = 0; i < result.count; ++i) {
      const RootEnclosure& root = result.roots[i];
      total += root.multiplicity;
      // g has the sign sign_after just past the enclosure, and the sign before it is flipped
      // exactly when the multiplicity is odd (enclosures are far narrower than root gaps here).
      const Real before = g_at(circle, cylinder, Real(root.angle) - Real(root.radius));
      const Real after = g_at(circle, cylinder, Real(root.angle) + Real(root.radius));
      EXPECT_EQ(it::sign_of(after), root.sign_after) << "trial " << trial;
      EXPECT_EQ(it::sign_of(before), root.multiplicity % 2 ? -root.sign_after : root.sign_after)
          << "trial " << trial;
      const double next = i + 1 < result.count ? result.roots[i + 1].angle
                                               : result.roots[0].angle + 2 * std::numbers::pi;
      EXPECT_EQ(root.sign_after,
                it::sign_of(g_at(circle, cylinder, (Real(root.angle) + Real(next)) / 2)));
    }
    // Crossings of a circle with a quadric, with multiplicity: an even number, at most 4.
    EXPECT_EQ(total % 2, 0) << "trial " << trial;
    EXPECT_LE(total, 4);
    if (result.count == 0 && result.side_without_roots != RimSideWithoutRoots::on_surface) {
      for (int i = 0; i < 8; ++i)
        EXPECT_EQ(it::sign_of(g_at(circle, cylinder, Real(0.8 * i))), static_cast<int>(result.side_without_roots));
    }
    with_roots += result.count > 0;
  }
  EXPECT_GT(with_roots, 20);
}

TEST(RimCylinderExact, GivesUpOnCoefficientsTooLargeToIsolateQuickly) {
  // A rim normal whose components lie ~1e500 apart (found by a fuzz of detect_contacts, where
  // this query ran for 6 s on 27,000-bit coefficients): the tier gives up, saying why.
  const Circle3 rim{{0x1.d66fc0f858cd8p-1, -0x1.07aa7df2fdfcp-3, -0x1.6dc4a5f61acb8p-1},
                    {0x1.247a388377ec2p-911, 0x1.2c3beed9ea90fp+879, 0x1.dc00a4e2b230ap-1},
                    0x1.10988ffa93a53p+133};
  const Cylinder3 wall{{0x1.1cedadc30fab2p-1, 0x1.f38526804cac4p-985, -0x1.f4e27afb65da6p-2},
                       {0x1.247a388377ec2p-911, 0x0p+0, 0x1.dc377949cd1p-1},
                       0x1.135974fd1b99fp+133};
  const RimRoots roots = exact_rim_roots(rim, wall);
  EXPECT_FALSE(roots.proved);
  EXPECT_EQ(roots.failure, CertificateReason::exact_coefficients_too_large) << to_string(roots.failure);
}

TEST(RimCylinderExact, DecidesTheExactCentreOfARecipeNotItsRounding) {
  // A rim of radius 1 in a wall of radius 2, its centre 1 - 2^-70 off the axis (not a double;
  // the recipe minuend - subtrahend keeps it exact). Stored, the centre rounds to 1 and the rim
  // touches the wall (one double root); exactly, it stays strictly inside.
  const Vector3 minuend(1.0, 0.0, 0.0), subtrahend(0x1p-70, 0.0, 0.0);
  const RoundedPoint centre = rounded_point(minuend, subtrahend, 0.0, 0, Vector3::Zero());
  ASSERT_EQ(centre.value.x(), 1.0);
  const Circle3 rim{centre.value, {0, 0, 1}, 1};
  const Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 2};
  const RimRoots rounded = exact_rim_roots(rim, wall);
  ASSERT_TRUE(rounded.proved);
  EXPECT_EQ(rounded.count, 1);  // tangent at the rounded centre
  const RimRoots exact = exact_rim_roots(rim, wall, &centre, 0);
  ASSERT_TRUE(exact.proved);
  EXPECT_EQ(exact.count, 0);
  EXPECT_EQ(exact.side_without_roots, RimSideWithoutRoots::inside);  // strictly inside
}

}  // namespace
}  // namespace clearjoint::geometry::detail
