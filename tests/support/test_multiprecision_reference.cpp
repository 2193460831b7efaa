// SPDX-License-Identifier: BSD-3-Clause
// Checks of the multiprecision reference itself (support/testing), on configurations whose
// answers are known in closed form, and against brute-force sampling. The kernel is not called
// here: a reference that is only ever compared with the code it checks proves nothing.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "multiprecision_reference.hpp"

namespace clearjoint::test::reference {
namespace {

using geometry::Circle3;
using geometry::CircleCylinderTopology;
using geometry::CirclePlaneTopology;
using geometry::Cylinder3;
using geometry::Plane3;
using geometry::Vector3;

/// The reference refines roots to kRootWidth (1e-60) in t; after atan and the closed forms below
/// (evaluated in MPFR too) 1e-50 leaves a wide margin while still proving 50 correct digits.
const Real kReferenceAgreement("1e-50");

Real real_pi() { return two_pi() / 2; }

// The tilted rim of the header's example: centre on the z axis, normal (0,3,4), radius 5. In
// frame_of's parametrisation (k = 0, u = (0,4,-3)/5, v = (-1,0,0)) its points are
// (-5 sin, 4 cos, -3 cos), so dist^2 to the z axis is 16 + 9 sin^2: an ellipse with semi-axes 5, 4.
Circle3 tilted_rim() { return {Vector3(0, 0, 0), Vector3(0, 3, 4), 5.0}; }
Cylinder3 z_cylinder(double radius) { return {Vector3(0, 0, 0), Vector3(0, 0, 1), radius}; }

TEST(MultiprecisionReference, FindsTheFourClosedFormCrossingsOfTheTiltedRim) {
  const CylinderReference ref = reference_circle_cylinder(tilted_rim(), z_cylinder(4.5));
  ASSERT_FALSE(ref.ambiguous) << ref.why;
  EXPECT_EQ(ref.topology, CircleCylinderTopology::crossing);
  ASSERT_EQ(ref.roots.size(), 4u);
  // 16 + 9 sin^2 = 20.25.
  const Real s0 = asin(sqrt(Real(425) / 900));
  const Real expected[4] = {s0, real_pi() - s0, real_pi() + s0, two_pi() - s0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(abs(ref.roots[i].angle - expected[i]), kReferenceAgreement) << i;
    EXPECT_EQ(ref.roots[i].multiplicity_hint, 1);
    const RealVector p = rim_point(tilted_rim(), expected[i]);
    for (int k = 0; k < 3; ++k) EXPECT_LT(abs(ref.roots[i].point[k] - p[k]), kReferenceAgreement);
  }
  // Outside (|sin| large) around pi/2 and 3 pi/2.
  ASSERT_EQ(ref.outside_arcs.size(), 2u);
  EXPECT_LT(abs(ref.outside_arcs[0][0] - expected[0]), kReferenceAgreement);
  EXPECT_LT(abs(ref.outside_arcs[0][1] - expected[1]), kReferenceAgreement);
  EXPECT_LT(abs(ref.outside_arcs[1][0] - expected[2]), kReferenceAgreement);
  EXPECT_LT(abs(ref.outside_arcs[1][1] - expected[3]), kReferenceAgreement);
}

TEST(MultiprecisionReference, FlagsAnExactInternalTangencyAsAmbiguousWithADoubleRootHint) {
  // Rim centre (1,0,0), radius 1 in z = 0, wall radius 2: touches at (2,0,0), where
  // x(theta) = (1 - sin, cos, 0) gives theta = 3 pi / 2.
  const Circle3 rim{Vector3(1, 0, 0), Vector3(0, 0, 1), 1.0};
  const CylinderReference ref = reference_circle_cylinder(rim, z_cylinder(2.0));
  EXPECT_TRUE(ref.ambiguous);
  ASSERT_EQ(ref.roots.size(), 1u);
  EXPECT_EQ(ref.roots[0].multiplicity_hint, 2);
  EXPECT_LT(abs(ref.roots[0].angle - 3 * real_pi() / 2), Real("1e-25"));
}

TEST(MultiprecisionReference, SeparatesTheTwoCrossingsOneUlpBeyondATangency) {
  // Centre one ulp beyond 1: the rim reaches 2 + 2^-52 and crosses twice, about
  // 2 sqrt(2^-52) = 3e-8 rad apart: decidable, not ambiguous.
  const Circle3 rim{Vector3(std::nextafter(1.0, 2.0), 0, 0), Vector3(0, 0, 1), 1.0};
  const CylinderReference ref = reference_circle_cylinder(rim, z_cylinder(2.0));
  ASSERT_FALSE(ref.ambiguous) << ref.why;
  ASSERT_EQ(ref.roots.size(), 2u);
  EXPECT_EQ(ref.outside_arcs.size(), 1u);
  const Real gap = ref.roots[1].angle - ref.roots[0].angle;
  EXPECT_GT(gap, Real("1e-8"));
  EXPECT_LT(gap, Real("1e-7"));
}

TEST(MultiprecisionReference, SaysInsideOneUlpShortOfATangency) {
  const Circle3 rim{Vector3(std::nextafter(1.0, 0.0), 0, 0), Vector3(0, 0, 1), 1.0};
  const CylinderReference ref = reference_circle_cylinder(rim, z_cylinder(2.0));
  ASSERT_FALSE(ref.ambiguous) << ref.why;
  EXPECT_EQ(ref.topology, CircleCylinderTopology::inside);
  EXPECT_TRUE(ref.roots.empty());
}

TEST(MultiprecisionReference, ReportsARimOnTheWallAsVanishing) {
  const Circle3 rim{Vector3(0, 0, 3), Vector3(0, 0, 1), 2.0};
  const Cylinder3 wall{Vector3(0, 0, -1), Vector3(0, 0, 7), 2.0};
  const CylinderReference ref = reference_circle_cylinder(rim, wall);
  EXPECT_TRUE(ref.ambiguous);
  EXPECT_EQ(ref.topology, CircleCylinderTopology::on_surface);
}

TEST(MultiprecisionReference, TellsInsideFromOutsideForCoaxialRims) {
  const Circle3 small{Vector3(0, 0, 3), Vector3(0, 0, 1), 1.0};
  const Circle3 large{Vector3(0, 0, 3), Vector3(0, 0, 1), 3.0};
  const CylinderReference in = reference_circle_cylinder(small, z_cylinder(2.0));
  const CylinderReference out = reference_circle_cylinder(large, z_cylinder(2.0));
  ASSERT_FALSE(in.ambiguous) << in.why;
  ASSERT_FALSE(out.ambiguous) << out.why;
  EXPECT_EQ(in.topology, CircleCylinderTopology::inside);
  EXPECT_EQ(out.topology, CircleCylinderTopology::outside);
  EXPECT_EQ(out.outside_arcs.size(), 1u);
}

TEST(MultiprecisionReference, FindsTheFarthestReachOfAnOffsetRim) {
  const Circle3 rim{Vector3(1, 0, 0), Vector3(0, 0, 1), 1.0};
  const FarthestReach reach = farthest_reach(rim, z_cylinder(2.0));
  ASSERT_FALSE(reach.ambiguous);
  EXPECT_LT(abs(reach.distance - 2), kReferenceAgreement);
  EXPECT_LT(abs(reach.radial[0] - 1), kReferenceAgreement);
  EXPECT_LT(abs(reach.point[0] - 2), kReferenceAgreement);
  EXPECT_LT(abs(reach.angle - 3 * real_pi() / 2), kReferenceAgreement);
}

TEST(MultiprecisionReference, DecidesTheIntegerPlaneTangencyExactly) {
  // Rim centre (0,0,3), normal (0,3,4), radius 5 spans z in [0, 6]: it touches z = 0 at (0,4,0).
  const Circle3 rim{Vector3(0, 0, 3), Vector3(0, 3, 4), 5.0};
  const PlaneReference ref = reference_circle_plane(rim, {Vector3(7, -2, 0), Vector3(0, 0, 1)});
  EXPECT_EQ(ref.topology, CirclePlaneTopology::tangent);
  EXPECT_EQ(ref.side, 1);
  ASSERT_EQ(ref.roots.size(), 1u);
  EXPECT_EQ(ref.roots[0].multiplicity_hint, 2);
  EXPECT_LT(abs(ref.roots[0].point[1] - 4), kReferenceAgreement);
  EXPECT_LT(abs(ref.roots[0].point[2]), kReferenceAgreement);
  EXPECT_LT(abs(ref.max_signed_distance - 6), kReferenceAgreement);

  const Plane3 lowered{Vector3(0, 0, std::nextafter(0.0, -1.0)), Vector3(0, 0, 1)};
  EXPECT_EQ(reference_circle_plane(rim, lowered).topology, CirclePlaneTopology::disjoint);
  const Plane3 raised{Vector3(0, 0, std::nextafter(0.0, 1.0)), Vector3(0, 0, 1)};
  EXPECT_EQ(reference_circle_plane(rim, raised).topology, CirclePlaneTopology::two_crossings);
}

TEST(MultiprecisionReference, FindsTheClosedFormPlaneCrossings) {
  // Radius 5 in z = 0 against x = 3: crossings (3, +-4, 0), deepest point (5,0,0) at depth 2.
  const Circle3 rim{Vector3(0, 0, 0), Vector3(0, 0, 1), 5.0};
  const PlaneReference ref = reference_circle_plane(rim, {Vector3(3, 0, 0), Vector3(2, 0, 0)});
  ASSERT_EQ(ref.topology, CirclePlaneTopology::two_crossings);
  ASSERT_EQ(ref.roots.size(), 2u);
  // x(theta) = (-5 sin, 5 cos, 0).
  EXPECT_LT(abs(ref.roots[0].point[0] - 3) + abs(ref.roots[0].point[1] + 4), kReferenceAgreement);
  EXPECT_LT(abs(ref.roots[1].point[0] - 3) + abs(ref.roots[1].point[1] - 4), kReferenceAgreement);
  EXPECT_LT(abs(ref.max_signed_distance - 2), kReferenceAgreement);
  EXPECT_LT(abs(ref.deepest_angle - 3 * real_pi() / 2), kReferenceAgreement);
}

TEST(MultiprecisionReference, AgreesWithDenseSamplingOnRandomRims) {
  // Brute force: count sign changes of the excess on a 2000-point grid of angles, in long double.
  // Only configurations whose roots are all more than two grid steps apart (and away from the grid
  // points) are counted, so the sampled count is then exact.
  constexpr unsigned kSeed = 20170101;
  RecordProperty("seed", static_cast<int>(kSeed));
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), radius(0.2, 1.5);
  constexpr int kGrid = 2000;
  const long double step = 2 * 3.14159265358979323846264338327950288L / kGrid;
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Circle3 rim{Vector3(coord(rng), coord(rng), coord(rng)),
                      Vector3(coord(rng), coord(rng), coord(rng)), radius(rng)};
    const Cylinder3 wall{Vector3(coord(rng), coord(rng), coord(rng)),
                         Vector3(coord(rng), coord(rng), coord(rng)), radius(rng)};
    const CylinderReference ref = reference_circle_cylinder(rim, wall);
    ASSERT_FALSE(ref.ambiguous) << ref.why;
    bool well_separated = true;
    for (std::size_t i = 0; i < ref.roots.size(); ++i) {
      const Real next = i + 1 < ref.roots.size() ? ref.roots[i + 1].angle
                                                 : ref.roots[0].angle + two_pi();
      if (next - ref.roots[i].angle < 3 * step) well_separated = false;
      // The excess really vanishes at every reported root (relative to the squared sizes).
      EXPECT_LT(abs(cylinder_excess(rim, wall, ref.roots[i].angle)), Real("1e-50"));
    }
    if (!well_separated) continue;
    const double kx = rim.normal.x(), ky = rim.normal.y(), kz = rim.normal.z();
    // frame_of's frame, recomputed here in long double.
    int k = 0;
    if (std::abs(ky) < std::abs(kx)) k = 1;
    if (std::abs(kz) < std::abs(k == 0 ? kx : ky)) k = 2;
    long double n[3] = {kx, ky, kz}, e[3] = {0, 0, 0};
    e[k] = 1;
    long double u[3] = {n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]};
    const long double un = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const long double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (auto& x : u) x /= un;
    long double v[3] = {(n[1] * u[2] - n[2] * u[1]) / nn, (n[2] * u[0] - n[0] * u[2]) / nn,
                        (n[0] * u[1] - n[1] * u[0]) / nn};
    const long double a[3] = {wall.axis.x(), wall.axis.y(), wall.axis.z()};
    const long double a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    auto excess = [&](long double th) {
      long double d[3];
      const long double c[3] = {rim.center.x(), rim.center.y(), rim.center.z()};
      const long double p[3] = {wall.axis_point.x(), wall.axis_point.y(), wall.axis_point.z()};
      for (int i = 0; i < 3; ++i)
        d[i] = c[i] - p[i] + rim.radius * (std::cos(th) * u[i] + std::sin(th) * v[i]);
      const long double x[3] = {d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2],
                                d[0] * a[1] - d[1] * a[0]};
      return (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / a2 -
             static_cast<long double>(wall.radius) * wall.radius;
    };
    int changes = 0;
    long double previous = excess(0);
    for (int i = 1; i <= kGrid; ++i) {
      const long double value = excess(i * step);
      if ((value > 0) != (previous > 0)) ++changes;
      previous = value;
    }
    EXPECT_EQ(changes, static_cast<int>(ref.roots.size())) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 200);
}

}  // namespace
}  // namespace clearjoint::test::reference
