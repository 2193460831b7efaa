// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/joint/joint_setup.hpp: detect_contacts' fast path (prefilter_if_ready,
// then set_up from its values) must hand on exactly what the general path (set_up from the inputs,
// eq. 5 by axes_exactly_parallel, the prefilters on set_up's values) computes. Nothing but this
// test keeps the two in step, so it compares them field by field, bit for bit, over generated
// poses: random joints near touching at scales from 2^-70 to 2^90 and far from the origin,
// coincident and reversed axes (exactly parallel, eq. 5), axes along the coordinate axes with
// exact radial and axial tangencies, centred journals, axes one ulp from parallel, axes of tiny
// and huge length and with components far below the others.

#include "joint/joint_setup.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "model/primitives_detail.hpp"

namespace clearjoint::geometry::detail {
namespace {

struct Pose {
  JointDimensions dimensions;
  PartPose bearing, journal;
};

std::string describe(const Pose& p) {
  std::ostringstream s;
  s << std::hexfloat << "Ri " << p.dimensions.bearing_radius << " Li " << p.dimensions.bearing_length << " Rj "
    << p.dimensions.journal_radius << " Lj " << p.dimensions.journal_length << " P_i "
    << p.bearing.p_WP.transpose() << " a_i " << p.bearing.axis_W.transpose() << " P_j "
    << p.journal.p_WP.transpose() << " a_j " << p.journal.axis_W.transpose();
  return s.str();
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vector3& a, const Vector3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}
template <class T, std::size_t N>
bool same_bits(const std::array<T, N>& a, const std::array<T, N>& b) {
  for (std::size_t k = 0; k < N; ++k) {
    if (!same_bits(a[k], b[k])) return false;
  }
  return true;
}
bool same_bits(int a, int b) { return a == b; }

/// The names of the JointSetup fields in which the fast path differs from the general one;
/// empty when every field has the same bits (inputs_in_guard aside: it says which path ran).
std::vector<std::string> differing_fields(const JointSetup& fast, const JointSetup& general) {
  std::vector<std::string> differ;
#define CLEARJOINT_COMPARE_FIELD(field) \
  if (!same_bits(fast.field, general.field)) differ.push_back(#field)
  CLEARJOINT_COMPARE_FIELD(bearing_radius);
  CLEARJOINT_COMPARE_FIELD(journal_radius);
  CLEARJOINT_COMPARE_FIELD(radial_clearance);
  CLEARJOINT_COMPARE_FIELD(axial_clearance);
  CLEARJOINT_COMPARE_FIELD(bearing_length);
  CLEARJOINT_COMPARE_FIELD(journal_length);
  CLEARJOINT_COMPARE_FIELD(p_WPi);
  CLEARJOINT_COMPARE_FIELD(p_WPj);
  CLEARJOINT_COMPARE_FIELD(bearing_axis_hat_W);
  CLEARJOINT_COMPARE_FIELD(journal_axis_hat_W);
  CLEARJOINT_COMPARE_FIELD(bearing_axis_W);
  CLEARJOINT_COMPARE_FIELD(journal_axis_W);
  CLEARJOINT_COMPARE_FIELD(bearing_axis_scaled_W);
  CLEARJOINT_COMPARE_FIELD(journal_axis_scaled_W);
  CLEARJOINT_COMPARE_FIELD(bearing_bases);
  CLEARJOINT_COMPARE_FIELD(bearing_base_errors);
  CLEARJOINT_COMPARE_FIELD(journal_rims);
  CLEARJOINT_COMPARE_FIELD(journal_rim_errors);
  CLEARJOINT_COMPARE_FIELD(journal_centre_error);
  CLEARJOINT_COMPARE_FIELD(toward_a);
  CLEARJOINT_COMPARE_FIELD(p_WPi_world);
  CLEARJOINT_COMPARE_FIELD(p_WPj_world);
#undef CLEARJOINT_COMPARE_FIELD
  return differ;
}

/// How many poses reached each comparison: the test must not pass by skipping them.
struct Reached {
  int ready = 0;      ///< the fast path ran: decisions compared
  int set_up = 0;     ///< ... and found a candidate not clear: set_up compared field by field
  int aligned = 0;    ///< ready with exactly parallel axes
  int not_ready = 0;  ///< outside the fast path's guard: nothing to compare
};

/// Both paths on one pose; a failure names the pose and what differs.
void compare_paths(const Pose& p, Reached& reached) {
  const DetectionOptions options;  // parallel_angle_tolerance 0: eq. (5) decided exactly
  Prefilter fast;
  prefilter_if_ready(p.dimensions, p.bearing, p.journal, options, fast);
  if (!fast.ready) {
    ++reached.not_ready;
    return;
  }
  ++reached.ready;
  // Ready promises inputs that pass every validate() (detect_contacts then skips them).
  ASSERT_TRUE(passes_validation(p.dimensions) && passes_validation(p.bearing) && passes_validation(p.journal))
      << describe(p);
  const JointSetup general = set_up(p.dimensions, p.bearing, p.journal);
  const bool exactly_parallel = axes_exactly_parallel(p.bearing.axis_W, p.journal.axis_W);
  ASSERT_EQ(fast.exactly_parallel, exactly_parallel) << describe(p);
  reached.aligned += exactly_parallel;
  const CandidatesClear clear =
      exactly_parallel ? prove_aligned_candidates_clear(general) : prove_misaligned_candidates_clear(general);
  ASSERT_EQ(fast.clear.radial, clear.radial) << describe(p);
  ASSERT_EQ(fast.clear.axial, clear.axial) << describe(p);
  if (fast.no_contact) return;  // the fast path hands nothing on: detection is over
  ++reached.set_up;
  const JointSetup handed_on = set_up(p.dimensions, p.bearing, p.journal, fast);
  ASSERT_TRUE(handed_on.inputs_in_guard);
  const std::vector<std::string> differ = differing_fields(handed_on, general);
  ASSERT_TRUE(differ.empty()) << "fields differ: " << ::testing::PrintToString(differ) << "; " << describe(p);
}

/// Poses around touching, in the proportions of the paper's Table 2 (bearing radius 10 mm,
/// clearance 0.1 mm), generated by `family` from a seeded engine.
class PoseSource {
 public:
  explicit PoseSource(std::uint64_t seed) : rng_(seed) {}

  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(rng_); }
  int whole(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng_); }
  Vector3 direction() {
    Vector3 v;
    do {
      v = Vector3(normal_(rng_), normal_(rng_), normal_(rng_));
    } while (!(v.norm() > 1e-3));
    return v.normalized();
  }
  /// A unit vector perpendicular to `a`.
  Vector3 across(const Vector3& a) { return a.cross(direction()).normalized(); }

  /// Table 2's joint times `scale`, with a random journal length and radius below the bearing's.
  JointDimensions dimensions(double scale) {
    const double Ri = 0.01 * scale, Li = 0.02 * scale;
    return {Ri, Li, Ri * (1 - uniform(1e-4, 2e-2)), Li * (1 - uniform(1e-4, 2e-2))};
  }
  /// The journal tilted by up to ~2.5 clearance angles and offset by up to ~1.6 clearances in
  /// each direction: every candidate contact sometimes present, sometimes clear.
  Pose near_touching(double scale, const Vector3& origin, double axis_length) {
    Pose p;
    p.dimensions = dimensions(scale);
    const double cr = p.dimensions.radial_clearance(), ca = p.dimensions.axial_clearance();
    const Vector3 a = direction();
    const Vector3 side = across(a);
    const double tilt = uniform(-2.5, 2.5) * cr / p.dimensions.journal_length;
    p.bearing = {origin, a * axis_length};
    p.journal = {origin + 1.6 * cr * uniform(-1, 1) * side + 1.6 * ca * uniform(-1, 1) * a,
                 (std::cos(tilt) * a + std::sin(tilt) * side) * (axis_length * std::exp2(whole(-3, 3)))};
    return p;
  }

 private:
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

constexpr int kPosesPerFamily = 20000;  // 7 families: 140,000 poses

/// Runs `kPosesPerFamily` poses of one family and checks that most reached the comparisons.
Reached run_family(std::uint64_t seed, const std::function<Pose(PoseSource&)>& family) {
  PoseSource source(seed);
  Reached reached;
  for (int n = 0; n < kPosesPerFamily; ++n) {
    compare_paths(family(source), reached);
    if (::testing::Test::HasFatalFailure()) break;
  }
  return reached;
}

TEST(JointSetup, FastPathEqualsGeneralPathOnRandomJointsNearTouching) {
  const Reached r = run_family(1, [](PoseSource& s) {
    const double scale = std::exp2(s.whole(-70, 90));
    const Vector3 origin = s.direction() * (scale * std::exp2(s.whole(-10, 30)) * s.uniform(0, 1));
    return s.near_touching(scale, origin, std::exp2(s.whole(-20, 20)) * s.uniform(0.5, 2));
  });
  EXPECT_GT(r.set_up, kPosesPerFamily / 4);
  EXPECT_GT(r.ready - r.set_up, kPosesPerFamily / 20);  // free flight proved by the prefilters
}

TEST(JointSetup, FastPathEqualsGeneralPathWithCoincidentAxes) {
  // a_j = 2^k a_i: exactly parallel (eq. 5), the aligned prefilters (line and faces).
  const Reached r = run_family(2, [](PoseSource& s) {
    Pose p = s.near_touching(std::exp2(s.whole(-30, 30)), Vector3::Zero(), s.uniform(0.1, 10));
    p.journal.axis_W = p.bearing.axis_W * std::exp2(s.whole(-5, 5));
    return p;
  });
  EXPECT_EQ(r.aligned, r.ready);
  EXPECT_GT(r.set_up, kPosesPerFamily / 4);
}

TEST(JointSetup, FastPathEqualsGeneralPathWithTheJournalReversed) {
  // a_j against a_i: the journal's base B faces bearing base A (toward_a = -1); exactly
  // reversed half of the time, tilted otherwise.
  const Reached r = run_family(3, [](PoseSource& s) {
    Pose p = s.near_touching(1.0, s.direction() * s.uniform(0, 1e3), 1.0);
    p.journal.axis_W = s.whole(0, 1) == 0 ? Vector3(-p.bearing.axis_W) : Vector3(-p.journal.axis_W);
    return p;
  });
  EXPECT_GT(r.aligned, kPosesPerFamily / 4);
  EXPECT_GT(r.set_up, kPosesPerFamily / 4);
}

TEST(JointSetup, FastPathEqualsGeneralPathAtExactTangenciesAlongTheCoordinateAxes) {
  // Axes along x, y or z (either sign); the journal offset by exactly the radial clearance
  // across the axis (the line touches the wall) or the axial clearance along it (a face touches
  // its base), or both, or centred; dimensions in binary fractions so the clearances are exact.
  const Reached r = run_family(4, [](PoseSource& s) {
    const int k = s.whole(0, 2);
    const double sign = s.whole(0, 1) == 0 ? 1.0 : -1.0;
    Vector3 a = Vector3::Zero(), side = Vector3::Zero();
    a[k] = sign;
    side[(k + 1) % 3] = 1.0;
    const double scale = std::exp2(s.whole(-40, 40));
    Pose p;
    p.dimensions = {scale * 0.5, scale * 2.0, scale * (0.5 - 0x1p-8 * s.whole(1, 8)), scale * (2.0 - 0x1p-6 * s.whole(1, 8))};
    const double cr = p.dimensions.radial_clearance(), ca = p.dimensions.axial_clearance();
    const Vector3 origin = scale * Vector3(s.whole(-4, 4), s.whole(-4, 4), s.whole(-4, 4));
    const int kind = s.whole(0, 3);
    const Vector3 offset = (kind == 0 || kind == 2 ? cr : 0.0) * side + (kind == 1 || kind == 2 ? ca : 0.0) * a;
    p.bearing = {origin, a};
    p.journal = {origin + (s.whole(0, 1) == 0 ? offset : Vector3(-offset)), s.whole(0, 1) == 0 ? a : Vector3(-a)};
    return p;
  });
  EXPECT_EQ(r.ready, kPosesPerFamily);
  EXPECT_EQ(r.aligned, kPosesPerFamily);
  EXPECT_GT(r.set_up, kPosesPerFamily / 2);
}

TEST(JointSetup, FastPathEqualsGeneralPathWithAxesOneUlpFromParallel) {
  // One component of a_j one ulp away from a_i's: not parallel (eq. 5 fails, exactly), yet
  // within every floating-point tolerance.
  const Reached r = run_family(5, [](PoseSource& s) {
    Pose p = s.near_touching(std::exp2(s.whole(-10, 10)), Vector3::Zero(), 1.0);
    p.journal.axis_W = p.bearing.axis_W;
    const int k = s.whole(0, 2);
    p.journal.axis_W[k] = std::nextafter(p.journal.axis_W[k], s.whole(0, 1) == 0 ? 2.0 : -2.0);
    return p;
  });
  EXPECT_GT(r.ready - r.aligned, kPosesPerFamily / 2);
  EXPECT_GT(r.set_up, kPosesPerFamily / 4);
}

TEST(JointSetup, FastPathEqualsGeneralPathWithTinyHugeAndLopsidedAxes) {
  // Axis lengths near the ends of unit_axis' direct range (the fast path's guard), and axes
  // with a component 2^-300 of the others (its square underflows).
  const Reached r = run_family(6, [](PoseSource& s) {
    Pose p = s.near_touching(std::exp2(s.whole(-20, 20)), Vector3::Zero(), std::exp2(s.whole(-520, 520)));
    if (s.whole(0, 1) == 0) {
      const int k = s.whole(0, 2);
      p.journal.axis_W[k] = std::ldexp(p.journal.axis_W[k], -300);
      p.bearing.axis_W[s.whole(0, 2)] *= 0x1p-300;
    }
    return p;
  });
  EXPECT_GT(r.ready, kPosesPerFamily / 4);
  EXPECT_GT(r.not_ready, 0);  // the guard's limits are inside the generated range
  EXPECT_GT(r.set_up, kPosesPerFamily / 10);
}

TEST(JointSetup, FastPathEqualsGeneralPathNearTheMagnitudeGuard) {
  // Table 2's joint times 2^98 to 2^110, far from the origin: some inside the prefilters'
  // magnitude guard (2^100 on the bearing radius and on twice the 1-norms), some beyond it.
  const Reached r = run_family(7, [](PoseSource& s) {
    const double scale = std::exp2(s.whole(98, 110));
    return s.near_touching(scale, s.direction() * scale * s.uniform(0, 8), 1.0);
  });
  EXPECT_GT(r.ready, kPosesPerFamily / 10);
  EXPECT_GT(r.not_ready, kPosesPerFamily / 10);
  EXPECT_GT(r.set_up, kPosesPerFamily / 20);
}

}  // namespace
}  // namespace clearjoint::geometry::detail
