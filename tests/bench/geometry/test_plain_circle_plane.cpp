// SPDX-License-Identifier: BSD-3-Clause
// Tests of bench/geometry/plain_circle_plane.hpp: the measuring stick must do the work of the
// certified query (same topology, depth and crossings where rounding cannot change the answer),
// or the floor it measures would be a floor of something else.

#include "plain_circle_plane.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

// Table 2 lengths are ~1e-2 m; both computations round a few dozen times, so they agree to a few
// hundred ulps of 1e-2 m (2e-18 m each); 1e-15 m leaves room and is still a millionth of a micron.
constexpr double kLengthAgreement = 1e-15;
// Crossing angles: their ill-conditioning is below 1e3 on these inputs (rims away from tangency,
// see kTangencyMargin), so 1e-10 rad is loose for both.
constexpr double kAngleAgreement = 1e-10;
// Rims whose deepest point is within this of the plane (metres) are left out: near tangency the
// plain topology can differ, which is what the certified query is for.
constexpr double kTangencyMargin = 1e-9;

TEST(PlainCirclePlane, AgreesWithTheCertifiedQueryOnRandomRimsAwayFromTangency) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const geo::Plane3 base{Vector3(0.0, 0.0, 0.01), Vector3(0.0, 0.0, 2.0)};  // normal not unit
  int crossings = 0, disjoint = 0;
  for (int i = 0; i < 4000; ++i) {
    const double tilt = 0.02 * unit(rng), azimuth = 2 * std::numbers::pi * unit(rng);
    const Vector3 axis(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
    const geo::Circle3 rim{Vector3(1e-4 * unit(rng), -1e-4 * unit(rng), 0.0099 + 2e-4 * unit(rng)), 3.0 * axis, 0.0099};
    const geo::CirclePlaneIntersection certified = geo::intersect_circle_plane(rim, base);
    if (std::fabs(certified.max_signed_distance) < kTangencyMargin) continue;
    const PlainCirclePlane plain = plain_circle_plane(rim, base);
    ASSERT_EQ(plain.topology, certified.topology) << i;
    if (certified.topology == geo::CirclePlaneTopology::disjoint) {
      EXPECT_EQ(plain.side, static_cast<int>(certified.side)) << i;
    }
    EXPECT_NEAR(plain.max_signed_distance, certified.max_signed_distance, kLengthAgreement) << i;
    ASSERT_EQ(plain.crossing_count, certified.crossing_count) << i;
    if (plain.crossing_count == 2) {
      ++crossings;
      // The certified query sorts its crossings by angle in [0, 2 pi); match them by point.
      for (int k = 0; k < 2; ++k) {
        const Vector3& p = plain.points[k];
        const int m = (p - certified.crossings[0].point).norm() < (p - certified.crossings[1].point).norm() ? 0 : 1;
        EXPECT_LT((p - certified.crossings[m].point).norm(), kLengthAgreement) << i;
        const double turn = std::remainder(plain.angles[k] - certified.crossings[m].angle, 2 * std::numbers::pi);
        EXPECT_LT(std::fabs(turn), kAngleAgreement) << i;
      }
    } else {
      ++disjoint;
    }
  }
  EXPECT_GT(crossings, 500);
  EXPECT_GT(disjoint, 500);
}

TEST(PlainCirclePlane, ReadsTangencyAndARimInThePlaneOffExactZeros) {
  const geo::Plane3 base{Vector3::Zero(), Vector3::UnitZ()};
  EXPECT_EQ(plain_circle_plane({Vector3(0, 0, 1), Vector3::UnitX(), 1.0}, base).topology,
            geo::CirclePlaneTopology::tangent);
  EXPECT_EQ(plain_circle_plane({Vector3::Zero(), Vector3::UnitZ(), 1.0}, base).topology,
            geo::CirclePlaneTopology::circle_in_plane);
  const PlainCirclePlane parallel = plain_circle_plane({Vector3(0, 0, -0.5), Vector3::UnitZ(), 1.0}, base);
  EXPECT_EQ(parallel.topology, geo::CirclePlaneTopology::disjoint);
  EXPECT_EQ(parallel.side, -1);
  EXPECT_EQ(parallel.max_signed_distance, -0.5);
}

}  // namespace
}  // namespace clearjoint::bench
