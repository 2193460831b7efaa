// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/candidate_prefilter.{hpp,cpp}: a candidate contact claimed absent must be
// absent for every rim centre and base point within their error bounds (checked in 256-bit
// MPFR), on joints near and far from touching, at tiny and huge scales and with axis components
// far below the a priori guard's old lower limit; and the fused tests decide what rim_reach and
// rim_side_of_plane decide one by one.

#include "filters/candidate_prefilter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "enclosure_checks.hpp"
#include "mpfr_reference.hpp"
#include "predicates/rim_distance_polynomial.hpp"
#include "predicates/rim_plane_quantities.hpp"

namespace clearjoint::geometry::detail {
namespace {

namespace it = internal_testing;
using it::Real;
using it::RealVector3;

/// An upper bound on the farthest distance from the wall's axis (through 0 along a) of the
/// circle at radial_centres[k], plus its centre error: the "strictly inside" claim must keep
/// this below R.
Real farthest_reach(const CandidatePrefilterInput& in, int k) {
  const RealVector3 a = it::to_real(in.bearing_axis);
  const RealVector3 c = it::to_real(in.radial_centres[k]);
  const Real distance = it::norm(it::cross(c, a)) / it::norm(a);
  return distance + Real(in.journal_radius) + Real(in.radial_errors[k]);
}

/// The largest signed distance of rim k beyond base plane k (outward normal +-a) plus both
/// errors: the exact "strictly on the inner side" claim is that this stays below 0.
Real deepest_beyond_base(const CandidatePrefilterInput& in, int k) {
  const RealVector3 a = it::to_real(in.bearing_axis);
  const RealVector3 n = it::to_real(in.journal_axis);
  const RealVector3 d = it::to_real(in.rim_centres[k]) - it::to_real(in.base_points[k]);
  const Real sigma = k == 0 ? 1 : -1;
  const Real a_length = it::norm(a);
  const Real s = sigma * it::dot(a, d) / a_length;
  const Real in_plane = it::norm(it::cross(a, n)) / (a_length * it::norm(n));  // |sin(angle)|
  return s + Real(in.journal_radius) * in_plane + Real(in.rim_errors[k]) + Real(in.base_errors[k]);
}

/// A joint of Table 2's proportions times `scale`, journal tilted and offset at random around
/// touching; errors of a few ulps of the centres (as detection computes them), or larger.
CandidatePrefilterInput random_joint(std::mt19937_64& rng, double scale, double error_ulps) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double R = 0.01 * scale, r = 0.0099 * scale, Li = 0.02 * scale, Lj = 0.0198 * scale;
  const double cr = R - r, ca = 0.5 * (Li - Lj);
  const Vector3 a = it::random_direction(rng);
  const Vector3 side = a.cross(it::random_direction(rng)).normalized();
  const double tilt = unit(rng) * 2.5 * cr / Lj;
  const Vector3 n = (std::cos(tilt) * a + std::sin(tilt) * side) * std::pow(2.0, 4 * unit(rng));
  const Vector3 centre = 1.6 * cr * unit(rng) * side + 1.6 * ca * unit(rng) * a;
  const Vector3 h_j = (0.5 * Lj) * n.normalized(), h_i = (0.5 * Li) * a;
  const double e = error_ulps * 1.1e-16 * (centre.norm() + Lj);
  return {{centre + h_j, centre - h_j}, {e, e}, {centre + h_j, centre - h_j}, {e, e}, {h_i, -h_i}, {e, e}, a, n, R, r};
}

void check_claims(const CandidatePrefilterInput& in, const CandidatesClear& clear) {
  for (int k = 0; k < 2; ++k) {
    if (clear.radial[k]) {
      ASSERT_LT(farthest_reach(in, k), Real(in.bearing_radius)) << "radial " << k;
    }
    if (clear.axial[k]) {
      ASSERT_LT(deepest_beyond_base(in, k), 0) << "axial " << k;
    }
  }
}

TEST(CandidatePrefilter, NeverClaimsACandidateAbsentThatAnyCentreWithinItsErrorReaches) {
  std::mt19937_64 rng(20261123);
  int claims = 0, candidates = 0;
  for (int i = 0; i < 4000; ++i) {
    const double scale = i % 4 == 0 ? 1e-6 : (i % 4 == 1 ? 1.0 : (i % 4 == 2 ? 1e6 : 1e-90));
    const CandidatePrefilterInput in = random_joint(rng, scale, i % 3 == 0 ? 4.0 : 1e6);
    const CandidatesClear clear = prove_candidates_clear(in);
    check_claims(in, clear);
    for (int k = 0; k < 2; ++k) claims += clear.radial[k] + clear.axial[k];
    candidates += 4;
  }
  // Not vacuous: about half the candidates are clear in this family, and most are proved so.
  EXPECT_GT(claims, candidates / 5);
}

TEST(CandidatePrefilter, DecidesAsTheOneByOneTestsDo) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const CandidatePrefilterInput in = random_joint(rng, 1.0, 4.0);
    const CandidatesClear clear = prove_candidates_clear(in);
    const Cylinder3 wall{Vector3::Zero(), in.bearing_axis, in.bearing_radius};
    for (int k = 0; k < 2; ++k) {
      const Circle3 rim{in.rim_centres[k], in.journal_axis, in.journal_radius};
      const Plane3 base{in.base_points[k], k == 0 ? in.bearing_axis : Vector3(-in.bearing_axis)};
      EXPECT_EQ(clear.radial[k], rim_reach(rim, wall, true, in.rim_errors[k]) == RimReach::strictly_inside) << i;
      EXPECT_EQ(clear.axial[k], rim_side_of_plane(rim, base, true, in.rim_errors[k] + in.base_errors[k]) ==
                                    RimSide::strictly_negative)
          << i;
    }
  }
}

TEST(CandidatePrefilter, StaysRightWithAxisComponentsFarBelowTheOldGuard) {
  // Axes tilted by 1e-300 rad and a journal offset by 1e-310 m: products underflow; the
  // underflow allowance keeps every claim true.
  CandidatePrefilterInput in{{Vector3(1e-310, 0.0, 0.0099), Vector3(1e-310, 0.0, -0.0099)},
                             {2e-18, 2e-18},
                             {Vector3(1e-310, 0.0, 0.0099), Vector3(1e-310, 0.0, -0.0099)},
                             {2e-18, 2e-18},
                             {Vector3(0.0, 0.0, 0.01), Vector3(0.0, 0.0, -0.01)},
                             {2e-18, 2e-18},
                             Vector3(1e-300, 0.0, 1.0),
                             Vector3(0.0, 1e-300, 1.0),
                             0.01,
                             0.0099};
  const CandidatesClear clear = prove_candidates_clear(in);
  check_claims(in, clear);
  EXPECT_TRUE(clear.radial[0] && clear.radial[1] && clear.axial[0] && clear.axial[1]);
  // A rim exactly in its base plane (parallel axes) is not clear.
  in.rim_centres[0].z() = 0.01;
  EXPECT_FALSE(prove_candidates_clear(in).axial[0]);
}

TEST(CandidatePrefilter, TestsTheAlignedLineOnTheMidSectionAndTheFacesOnTheRims) {
  // Parallel axes (the aligned case): the line test takes the journal's mid-length section,
  // centred 0.95 cr off the axis (clear); the faces take rims 1e-9 m inside base A (clear) and
  // beyond base B (not clear).
  const Vector3 z = Vector3::UnitZ();
  const double R = 0.01, r = 0.0099, cr = R - r;
  const Vector3 centre(0.95 * cr, 0.0, 0.0);
  CandidatePrefilterInput in{{centre, centre},
                             {1e-18, 1e-18},
                             {Vector3(0.95 * cr, 0.0, 0.01 - 1e-9), Vector3(0.95 * cr, 0.0, -0.01 - 1e-9)},
                             {2e-18, 2e-18},
                             {Vector3(0.0, 0.0, 0.01), Vector3(0.0, 0.0, -0.01)},
                             {2e-18, 2e-18},
                             z,
                             2.0 * z,
                             R,
                             r};
  const CandidatesClear clear = prove_candidates_clear(in);
  check_claims(in, clear);
  EXPECT_TRUE(clear.radial[0]);
  EXPECT_TRUE(clear.axial[0]);
  EXPECT_FALSE(clear.axial[1]);
  in.radial_centres = {Vector3(1.01 * cr, 0.0, 0.0), Vector3(1.01 * cr, 0.0, 0.0)};  // beyond
  EXPECT_FALSE(prove_candidates_clear(in).radial[0]);
}

TEST(CandidatePrefilter, FallsBackToTheRunningErrorBeyondTheGuard) {
  // Coordinates of 1e40 exceed the a priori range (2^100 ~ 1.3e30): the one-by-one tests with
  // their running error bounds decide, and correctly.
  std::mt19937_64 rng(11);
  int claims = 0;
  for (int i = 0; i < 200; ++i) {
    const CandidatePrefilterInput in = random_joint(rng, 1e40, 4.0);
    const CandidatesClear clear = prove_candidates_clear(in);
    check_claims(in, clear);
    claims += clear.radial[0] + clear.radial[1] + clear.axial[0] + clear.axial[1];
  }
  EXPECT_GT(claims, 100);
}

}  // namespace
}  // namespace clearjoint::geometry::detail
