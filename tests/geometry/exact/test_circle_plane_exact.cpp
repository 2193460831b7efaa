// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/circle_plane_exact.{hpp,cpp}: the exact topology of a circle against a
// plane on integer (exactly representable) poses, non-unit normals, both sides, and single-ulp
// perturbations of a tangency; random poses against 256-bit MPFR extremes.

#include "exact/circle_plane_exact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
namespace it = internal_testing;
using Topology = CirclePlaneTopology;

void expect_topology(const Circle3& circle, const Plane3& plane, Topology topology, int side) {
  const CirclePlaneTopologyAndSide result = exact_circle_plane_topology(circle, plane);
  EXPECT_EQ(result.topology, topology);
  EXPECT_EQ(result.side, side);
}

const Plane3 kGround{{0, 0, 0}, {0, 0, 1}};

TEST(CirclePlaneExact, ReportsAVerticalCircleTouchingThePlaneAsTangentOnEitherSide) {
  expect_topology({{0, 0, 1}, {1, 0, 0}, 1}, kGround, Topology::tangent, +1);
  expect_topology({{0, 0, -1}, {1, 0, 0}, 1}, kGround, Topology::tangent, -1);
  // Flipping the plane normal flips the side.
  expect_topology({{0, 0, 1}, {1, 0, 0}, 1}, {{0, 0, 0}, {0, 0, -3}}, Topology::tangent, -1);
}

TEST(CirclePlaneExact, ReportsCrossingAndDisjointVerticalCircles) {
  expect_topology({{0, 0, 1}, {1, 0, 0}, 2}, kGround, Topology::two_crossings, 0);
  expect_topology({{0, 0, 0}, {0, 1, 0}, 1}, kGround, Topology::two_crossings, 0);
  expect_topology({{0, 0, 1}, {1, 0, 0}, 0.5}, kGround, Topology::disjoint, +1);
  expect_topology({{7, -3, -1}, {1, 0, 0}, 0.5}, kGround, Topology::disjoint, -1);
}

TEST(CirclePlaneExact, ReportsParallelCirclesAsDisjointOrInThePlane) {
  expect_topology({{5, 5, 2}, {0, 0, 3}, 10}, kGround, Topology::disjoint, +1);
  expect_topology({{5, 5, -2}, {0, 0, -0.5}, 10}, kGround, Topology::disjoint, -1);
  expect_topology({{5, 5, 0}, {0, 0, 3}, 10}, kGround, Topology::circle_in_plane, 0);
  expect_topology({{1, 2, 2}, {2, 4, 4}, 1}, {{0, 0, 0}, {1, 2, 2}}, Topology::disjoint, +1);
  expect_topology({{2, 0, -1}, {1, 2, 2}, 1}, {{0, 1, -1}, {-1, -2, -2}}, Topology::circle_in_plane, 0);
}

TEST(CirclePlaneExact, ReportsTangencyOfATiltedCircleWithNonUnitNormals) {
  // Normal (0,3,4): the circle reaches r |n x e_z| / |n| = 3r/5 below its centre.
  expect_topology({{0, 0, 3}, {0, 3, 4}, 5}, kGround, Topology::tangent, +1);
  expect_topology({{0, 0, -3}, {0, 3, 4}, 5}, {{1, 1, 0}, {0, 0, 2}}, Topology::tangent, -1);
  expect_topology({{0, 0, 2}, {0, 3, 4}, 5}, kGround, Topology::two_crossings, 0);
  expect_topology({{0, 0, 4}, {0, -6, 8}, 5}, kGround, Topology::disjoint, +1);
  // Plane normal (1,2,2) (length 3), circle normal (2,1,-2) perpendicular to it: the circle
  // reaches r below its centre, which is at distance 9 / 3 = 3 from the plane.
  expect_topology({{1, 2, 2}, {2, 1, -2}, 3}, {{0, 0, 0}, {1, 2, 2}}, Topology::tangent, +1);
  expect_topology({{-1, -2, -2}, {2, 1, -2}, 3}, {{0, 0, 0}, {1, 2, 2}}, Topology::tangent, -1);
  expect_topology({{1, 2, 2}, {2, 1, -2}, 4}, {{0, 0, 0}, {1, 2, 2}}, Topology::two_crossings, 0);
}

TEST(CirclePlaneExact, SeparatesTangencyFromItsOneUlpNeighbours) {
  const Circle3 tangent{{0, 0, 3}, {0, 3, 4}, 5};
  Circle3 smaller = tangent, larger = tangent, higher = tangent, lower = tangent;
  smaller.radius = std::nextafter(5.0, 0.0);
  larger.radius = std::nextafter(5.0, 10.0);
  higher.center.z() = std::nextafter(3.0, 10.0);
  lower.center.z() = std::nextafter(3.0, 0.0);
  expect_topology(smaller, kGround, Topology::disjoint, +1);
  expect_topology(larger, kGround, Topology::two_crossings, 0);
  expect_topology(higher, kGround, Topology::disjoint, +1);
  expect_topology(lower, kGround, Topology::two_crossings, 0);
  // A plane normal one ulp off the parallel case: no longer parallel, far from the circle.
  expect_topology({{0, 0, 1}, {0, 0, 1}, 1}, {{0, 0, 0}, {0x1p-60, 0, 1}}, Topology::disjoint, +1);
  // One ulp of tilt on an in-plane circle: it now crosses the plane.
  expect_topology({{0, 0, 0}, {0x1p-60, 0, 1}, 1}, kGround, Topology::two_crossings, 0);
}

// The tier decides in integers on the stack where the inputs, at their common exponent, fit in
// some 170 bits, and in GMP's integers otherwise (circle_plane_exact.cpp): each case below is
// posed once within that range and once with a term hundreds of binades smaller, which forces GMP.

TEST(CirclePlaneExact, SeparatesTangencyFromItsNeighboursWhateverTheInputsSpan) {
  for (const double tiny : {0x1p-100, 0x1p-400}) {
    // A plane point off the origin by `tiny` along x, which the plane's normal (0, 0, 1) ignores:
    // the same tangency, but its integers span the binades down to `tiny`.
    const Plane3 ground{{tiny, 0, 0}, {0, 0, 1}};
    expect_topology({{0, 0, 3}, {0, 3, 4}, 5}, ground, Topology::tangent, +1);
    expect_topology({{0, 0, 3}, {0, 3, 4}, std::nextafter(5.0, 0.0)}, ground, Topology::disjoint, +1);
    expect_topology({{0, 0, 3}, {0, 3, 4}, std::nextafter(5.0, 10.0)}, ground, Topology::two_crossings, 0);
    expect_topology({{0, 0, -3}, {0, 3, 4}, 5}, ground, Topology::tangent, -1);
    // A normal `tiny` off the vertical: the rim in the plane now crosses it.
    expect_topology({{0, 0, 0}, {tiny, 0, 1}, 1}, kGround, Topology::two_crossings, 0);
    expect_topology({{5, 5, 0}, {0, 0, 3}, 10}, ground, Topology::circle_in_plane, 0);
  }
}

TEST(CirclePlaneExact, DecidesTheExactCentreOfARecipeRatherThanItsRoundedValue) {
  // Centre 1 + tiny above the ground (minuend 1, subtrahend -tiny), stored rounded to 1: the
  // rounded rim touches the ground, the exact one stays above it.
  for (const double tiny : {0x1p-100, 0x1p-400}) {
    RoundedPoint centre;
    centre.minuend = {0, 0, 1};
    centre.subtrahend = {0, 0, -tiny};
    centre.value = centre.minuend - centre.subtrahend;
    ASSERT_EQ(centre.value.z(), 1.0);
    const Circle3 rim{centre.value, {1, 0, 0}, 1};
    EXPECT_EQ(exact_circle_plane_topology(rim, kGround).topology, Topology::tangent);
    const CirclePlaneTopologyAndSide exact = exact_circle_plane_topology(rim, kGround, &centre);
    EXPECT_EQ(exact.topology, Topology::disjoint);
    EXPECT_EQ(exact.side, +1);
    // A half-length step of -(4 tiny / 2) (0, 0, 1) takes it to 1 - tiny: crossing; of half
    // that, back onto the ground: tangent.
    centre.direction = {0, 0, 1};
    centre.length = 4 * tiny;
    centre.sign = -1;
    EXPECT_EQ(exact_circle_plane_topology(rim, kGround, &centre).topology, Topology::two_crossings);
    centre.length = 2 * tiny;
    EXPECT_EQ(exact_circle_plane_topology(rim, kGround, &centre).topology, Topology::tangent);
  }
}

TEST(CirclePlaneExact, AgreesWithMultiprecisionExtremesOnRandomPoses) {
  // min/max over the circle of the signed distance to the plane, in MPFR:
  // s / |n_p| -+ r |n_p x n_c| / (|n_p| |n_c|).
  std::mt19937_64 rng(401);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  int crossing = 0, disjoint = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Circle3 circle{{coordinate(rng), coordinate(rng), coordinate(rng)},
                         {coordinate(rng), coordinate(rng), coordinate(rng)},
                         std::fabs(coordinate(rng)) + 0.1};
    const Plane3 plane{{coordinate(rng), coordinate(rng), coordinate(rng)},
                       {coordinate(rng), coordinate(rng), coordinate(rng)}};
    const it::RealVector3 np = it::to_real(plane.normal), nc = it::to_real(circle.normal);
    const Real centre = it::dot(np, it::to_real(circle.center) - it::to_real(plane.point)) / it::norm(np);
    const Real reach = Real(circle.radius) * it::norm(it::cross(np, nc)) / (it::norm(np) * it::norm(nc));
    const CirclePlaneTopologyAndSide result = exact_circle_plane_topology(circle, plane);
    if (centre - reach > 0) {
      EXPECT_EQ(result.topology, Topology::disjoint);
      EXPECT_EQ(result.side, +1);
      ++disjoint;
    } else if (centre + reach < 0) {
      EXPECT_EQ(result.topology, Topology::disjoint);
      EXPECT_EQ(result.side, -1);
      ++disjoint;
    } else {
      EXPECT_EQ(result.topology, Topology::two_crossings);
      ++crossing;
    }
  }
  EXPECT_GT(crossing, 50);
  EXPECT_GT(disjoint, 50);
}

}  // namespace
}  // namespace clearjoint::geometry::detail
