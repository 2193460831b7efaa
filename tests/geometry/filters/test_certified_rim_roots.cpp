// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/certified_rim_roots.{hpp,cpp} on hand-made coefficient sets: a proved
// answer must be right (count, enclosures holding the analytic or MPFR roots, sign_after), and
// multiple roots or ambiguous coefficients must never be "proved".

#include "filters/certified_rim_roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
namespace it = internal_testing;
using Coefficients = std::array<Real, 5>;

RimDistancePolynomial polynomial(double k0, double k1, double k2, double k3, double k4) {
  RimDistancePolynomial g;
  g.k = {Bounded(k0), Bounded(k1), Bounded(k2), Bounded(k3), Bounded(k4)};
  return g;
}

Coefficients exact(const RimDistancePolynomial& g) {
  return {Real(g.k[0].value), Real(g.k[1].value), Real(g.k[2].value), Real(g.k[3].value),
          Real(g.k[4].value)};
}

/// Bisection steps of the MPFR reference: a grid cell of 2 pi / 512 shrinks below 1e-20 rad.
constexpr int kReferenceBisections = 64;
/// What the reference roots may be off by (the final bisection width), added to each
/// enclosure radius in the checks; enclosures themselves are at least an ulp (~1e-16) wide.
const double kReferenceRootError = 1e-20;

/// All roots of the exact trig polynomial k, from a 256-bit grid scan with a rigorous cell
/// criterion (|g''| <= |k1| + |k2| + 4 (|k3| + |k4|)); nullopt when a cell cannot be decided
/// (roots too close together for the grid), so the caller skips that polynomial.
std::optional<std::vector<Real>> reference_roots(const Coefficients& k) {
  constexpr int kCells = 512;
  const Real h = it::two_pi() / kCells;
  const Real start("0.1");  // off every special angle
  const Real curvature = abs(k[1]) + abs(k[2]) + 4 * (abs(k[3]) + abs(k[4]));
  std::vector<Real> roots;
  Real a = start, ga = it::trig_polynomial(k, a);
  for (int i = 0; i < kCells; ++i) {
    const Real b = start + h * (i + 1);
    const Real gb = it::trig_polynomial(k, b);
    if (ga == 0 || gb == 0) return std::nullopt;
    if ((ga > 0) == (gb > 0)) {
      // A root pair inside needs both ends within curvature h^2 / 2 of zero.
      if (abs(ga) <= curvature * h * h / 2 && abs(gb) <= curvature * h * h / 2) return std::nullopt;
    } else {
      // Exactly one root when g' cannot vanish on the cell.
      if (abs(it::trig_polynomial_derivative(k, a)) <= curvature * h) return std::nullopt;
      Real low = a, high = b;
      const bool rising = gb > 0;
      for (int step = 0; step < kReferenceBisections; ++step) {
        const Real middle = (low + high) / 2;
        if ((it::trig_polynomial(k, middle) > 0) == rising) high = middle; else low = middle;
      }
      Real root = fmod((low + high) / 2, it::two_pi());
      roots.push_back(root);
    }
    a = b;
    ga = gb;
  }
  return roots;
}

/// A proved result must list exactly `truth` (each inside an enclosure, every enclosure holding
/// one), sorted in [0, 2 pi), with sign_after equal to the exact sign of g between roots.
void expect_proved_roots_match(const RimRoots& result, const std::vector<Real>& truth,
                               const Coefficients& k) {
  ASSERT_TRUE(result.proved) << to_string(result.failure);
  ASSERT_EQ(result.count, static_cast<int>(truth.size()));
  for (int i = 0; i < result.count; ++i) {
    const RootEnclosure& root = result.roots[i];
    EXPECT_GE(root.angle, 0.0);
    EXPECT_LT(root.angle, 2 * std::numbers::pi);
    EXPECT_EQ(root.multiplicity, 1);
    if (i > 0) {
      EXPECT_LT(result.roots[i - 1].angle, root.angle);
    }
    int holding = 0;
    for (const Real& t : truth)
      holding += it::circular_gap(Real(root.angle), t) <= Real(root.radius) + kReferenceRootError;
    EXPECT_EQ(holding, 1) << "enclosure " << root.angle << " +- " << root.radius;
    // The exact sign of g halfway to the next root.
    const double next = i + 1 < result.count ? result.roots[i + 1].angle
                                             : result.roots[0].angle + 2 * std::numbers::pi;
    const Real middle = (Real(root.angle) + Real(next)) / 2;
    EXPECT_EQ(root.sign_after, it::sign_of(it::trig_polynomial(k, middle)))
        << "after root " << root.angle;
  }
  for (const Real& t : truth) {
    bool held = false;
    for (int i = 0; i < result.count; ++i)
      held |= it::circular_gap(Real(result.roots[i].angle), t) <=
              Real(result.roots[i].radius) + kReferenceRootError;
    EXPECT_TRUE(held) << "root " << t.str(20) << " not enclosed";
  }
  if (result.count == 0) {
    for (int i = 0; i < 16; ++i)
      EXPECT_EQ(static_cast<int>(result.side_without_roots), it::sign_of(it::trig_polynomial(k, Real(0.4 * i))));
  }
}

/// How many polynomials of a random family the reference decided, and how many of those the
/// tiers proved.
struct ReferenceTally {
  int compared = 0, proved = 0;
};
/// certified_rim_roots(g), checked against the reference where it proves (and counted in
/// `tally`); nullopt where the reference cannot decide or the tiers do not prove.
std::optional<RimRoots> proved_and_checked(const RimDistancePolynomial& g, ReferenceTally& tally) {
  const std::optional<std::vector<Real>> truth = reference_roots(exact(g));
  if (!truth) return std::nullopt;
  ++tally.compared;
  const RimRoots result = certified_rim_roots(g);
  if (!result.proved) return std::nullopt;
  ++tally.proved;
  expect_proved_roots_match(result, *truth, exact(g));
  return result;
}

Real wrap(const Real& angle) {
  Real a = fmod(angle, it::two_pi());
  if (a < 0) a += it::two_pi();
  return a;
}

TEST(CertifiedRimRoots, FindsTheTwoRootsOfAPureFirstHarmonic) {
  // 1/2 + cos t: cos t = -1/2 at 2 pi / 3 and 4 pi / 3.
  const RimDistancePolynomial g = polynomial(0.5, 1, 0, 0, 0);
  expect_proved_roots_match(certified_rim_roots(g), {2 * it::pi() / 3, 4 * it::pi() / 3}, exact(g));
  // 1 + 3 cos t + 4 sin t = 1 + 5 cos(t - phi), phi = atan2(4, 3): t = phi +- acos(-1/5).
  const RimDistancePolynomial h = polynomial(1, 3, 4, 0, 0);
  const Real phi = atan2(Real(4), Real(3)), beta = acos(Real(-1) / 5);
  expect_proved_roots_match(certified_rim_roots(h), {wrap(phi - beta), wrap(phi + beta)}, exact(h));
}

TEST(CertifiedRimRoots, ReportsSignAfterOfAPureFirstHarmonic) {
  const RimRoots roots = certified_rim_roots(polynomial(0.5, 1, 0, 0, 0));
  ASSERT_TRUE(roots.proved);
  ASSERT_EQ(roots.count, 2);
  EXPECT_EQ(roots.roots[0].sign_after, -1);  // at 2 pi / 3, 1/2 + cos t becomes negative
  EXPECT_EQ(roots.roots[1].sign_after, +1);
}

TEST(CertifiedRimRoots, FindsTheFourRootsOfAPureSecondHarmonic) {
  const Real pi = it::pi();
  // cos 2t: pi/4 + j pi/2.
  const RimDistancePolynomial a = polynomial(0, 0, 0, 1, 0);
  expect_proved_roots_match(certified_rim_roots(a), {pi / 4, 3 * pi / 4, 5 * pi / 4, 7 * pi / 4},
                            exact(a));
  // 1/2 + cos 2t: cos 2t = -1/2 at pi/3, 2 pi/3, 4 pi/3, 5 pi/3.
  const RimDistancePolynomial b = polynomial(0.5, 0, 0, 1, 0);
  expect_proved_roots_match(certified_rim_roots(b), {pi / 3, 2 * pi / 3, 4 * pi / 3, 5 * pi / 3},
                            exact(b));
  // -sin 2t: roots on 0, pi/2, pi, 3 pi/2, including the seam of the circle.
  const RimDistancePolynomial c = polynomial(0, 0, 0, 0, -1);
  expect_proved_roots_match(certified_rim_roots(c), {Real(0), pi / 2, pi, 3 * pi / 2}, exact(c));
}

TEST(CertifiedRimRoots, ProvesTheSignOfRootFreePolynomials) {
  for (const RimDistancePolynomial& g :
       {polynomial(2, 0.1, 0, 0, 0), polynomial(-2, 0.3, -0.2, 0.1, 0), polynomial(3, 0, 0, 1, 0.5),
        polynomial(-3, 0.2, 0, 1, 0.5), polynomial(1e-300, 0, 0, 0, 0)}) {
    expect_proved_roots_match(certified_rim_roots(g), {}, exact(g));
  }
}

TEST(CertifiedRimRoots, MatchesTheMultiprecisionRootsOfRandomPolynomials) {
  std::mt19937_64 rng(211);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  ReferenceTally tally;
  for (int i = 0; i < 120; ++i) {
    // Vary the balance between the harmonics so that both tiers are exercised.
    const double second = (i % 3 == 0) ? 0.05 : (i % 3 == 1 ? 0.5 : 2.0);
    proved_and_checked(polynomial(coefficient(rng), coefficient(rng), coefficient(rng), second * coefficient(rng),
                                  second * coefficient(rng)),
                       tally);
  }
  EXPECT_GT(tally.compared, 100);
  EXPECT_GT(tally.proved, tally.compared * 9 / 10);  // unproved answers are allowed, but must be rare here
}

TEST(CertifiedRimRoots, NeverProvesADoubleRoot) {
  // 1 + cos t (double root at pi), 5 + 3 cos t + 4 sin t (double root at atan2(4,3) + pi),
  // 1 - cos 2t = 2 sin^2 t (double roots at 0 and pi), (cos t - 1/2)^2 (double roots at
  // +-pi/3), and g = 0 identically.
  for (const RimDistancePolynomial& g :
       {polynomial(1, 1, 0, 0, 0), polynomial(5, 3, 4, 0, 0), polynomial(1, 0, 0, -1, 0),
        polynomial(0.75, -1, 0, 0.5, 0), polynomial(-1, -1, 0, 0, 0), polynomial(0, 0, 0, 0, 0)}) {
    const RimRoots result = certified_rim_roots(g);
    EXPECT_FALSE(result.proved) << g.k[0].value << " " << g.k[1].value << " count " << result.count;
    EXPECT_NE(result.failure, CertificateReason::none);
  }
}

TEST(CertifiedRimRoots, IsNeverWrongOneUlpAwayFromADoubleRoot) {
  // k0 + cos t with k0 = 1 +- a few ulps: no root above 1, two roots pi +- acos(k0)... below.
  double up = 1.0, down = 1.0;
  int proved = 0;
  for (int step = 0; step < 64; ++step) {
    up = std::nextafter(up, 2.0);
    down = std::nextafter(down, 0.0);
    const RimDistancePolynomial above = polynomial(up, 1, 0, 0, 0);
    const RimRoots none = certified_rim_roots(above);
    if (none.proved) expect_proved_roots_match(none, {}, exact(above));
    const RimDistancePolynomial below = polynomial(down, 1, 0, 0, 0);
    const RimRoots two = certified_rim_roots(below);
    const Real beta = acos(-Real(down));  // cos t = -down
    if (two.proved) expect_proved_roots_match(two, {beta, it::two_pi() - beta}, exact(below));
    proved += none.proved + two.proved;
  }
  // Proved: 106 of the 128 measured (the few ulps nearest the double root are declined). The
  // floor leaves a margin of 16 for a tier that declines a little more.
  EXPECT_GE(proved, 90);
}

TEST(CertifiedRimRoots, NeverProvesWhenTheCoefficientErrorsAllowBothAnswers) {
  // The true k0 is anywhere in 1 +- 1e-10: some members have no root, some two, one a double.
  RimDistancePolynomial g = polynomial(1, 1, 0, 0, 0);
  g.k[0].error = 1e-10;
  EXPECT_FALSE(certified_rim_roots(g).proved);
  // Same with the uncertainty in the second harmonic.
  RimDistancePolynomial h = polynomial(1, 1, 0, 0, 0);
  h.k[3].error = 1e-10;
  EXPECT_FALSE(certified_rim_roots(h).proved);
}

TEST(CertifiedRimRoots, EnclosuresHoldTheRootsOfEveryPolynomialWithinTheCoefficientErrors) {
  // The stored coefficients carry errors: the exact polynomial may be any member of the box.
  const double kError = 1e-9;
  for (const std::array<double, 5>& centre :
       {std::array<double, 5>{0.5, 1, 0.2, 0.1, -0.05}, std::array<double, 5>{0.1, 0.3, -0.2, 1, 0.4}}) {
    RimDistancePolynomial g = polynomial(centre[0], centre[1], centre[2], centre[3], centre[4]);
    for (Bounded& k : g.k) k.error = kError;
    const RimRoots result = certified_rim_roots(g);
    ASSERT_TRUE(result.proved) << to_string(result.failure);
    for (int corner = 0; corner < 32; corner += 5) {  // a spread of the 32 corners
      Coefficients k;
      for (int i = 0; i < 5; ++i)
        k[i] = Real(centre[i]) + ((corner >> i) & 1 ? Real(kError) : -Real(kError));
      const std::optional<std::vector<Real>> truth = reference_roots(k);
      ASSERT_TRUE(truth.has_value());
      ASSERT_EQ(result.count, static_cast<int>(truth->size()));
      for (const Real& t : *truth) {
        bool held = false;
        for (int i = 0; i < result.count; ++i)
          held |= it::circular_gap(Real(result.roots[i].angle), t) <=
                  Real(result.roots[i].radius) + kReferenceRootError;
        EXPECT_TRUE(held) << "corner " << corner << " root " << t.str(20);
      }
    }
  }
}

// ---- The cap proof: a rim barely beyond or barely inside the wall -------------------------
// g = k0 + cos t + k3 cos 2t with k3 < 0 peaks at t = 0 at k0 + 1 + k3, while the first-harmonic
// bound there is k0 + 1 + |k3|: for a peak within 2 |k3| below that, the end arc around 0 has
// no proved sign, and the cap proof (certified_rim_roots.cpp) decides.
constexpr double kCapSecondHarmonic = -0x1p-9;

/// The roots of k0 + cos t + k3 cos 2t, from cos 2t = 2 c^2 - 1: 2 k3 c^2 + c + (k0 - k3) = 0,
/// each cosine in [-1, 1] giving t = +-acos(c).
std::vector<Real> cap_family_roots(double k0, double k3) {
  const Real a = 2 * Real(k3), b = 1, c = Real(k0) - Real(k3);
  const Real discriminant = b * b - 4 * a * c;
  std::vector<Real> roots;
  if (discriminant < 0) return roots;
  for (const int sign : {-1, 1}) {
    const Real cosine = (-b + sign * sqrt(discriminant)) / (2 * a);
    if (cosine <= -1 || cosine >= 1) continue;
    const Real t = acos(cosine);
    roots.push_back(t);
    roots.push_back(it::two_pi() - t);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

TEST(CertifiedRimRoots, ProvesTheTwoRootsOfAShallowCrossingInTierOne) {
  // Peak 2^-10 above zero: roots near +-0.045 rad.
  const double k0 = -1 - kCapSecondHarmonic + 0x1p-10;
  const RimDistancePolynomial g = polynomial(k0, 1, 0, kCapSecondHarmonic, 0);
  const RimRoots result = certified_rim_roots(g);
  expect_proved_roots_match(result, cap_family_roots(k0, kCapSecondHarmonic), exact(g));
  // Tier 1 hands on the cosine and sine of its roots; tier 2 does not.
  ASSERT_EQ(result.count, 2);
  EXPECT_TRUE(result.roots[0].has_trig());
  EXPECT_TRUE(result.roots[1].has_trig());
}

TEST(CertifiedRimRoots, ProvesNoRootWhenTheSecondHarmonicKeepsTheRimInside) {
  // Peak 2^-10 below zero, while the first-harmonic bound there, k0 + 1 + |k3|, is 3 2^-10 above
  // zero.
  const double k0 = -1 - kCapSecondHarmonic - 0x1p-10;
  const RimDistancePolynomial g = polynomial(k0, 1, 0, kCapSecondHarmonic, 0);
  ASSERT_TRUE(cap_family_roots(k0, kCapSecondHarmonic).empty());
  const RimRoots result = certified_rim_roots(g);
  expect_proved_roots_match(result, {}, exact(g));
  EXPECT_EQ(result.side_without_roots, RimSideWithoutRoots::inside);
}

TEST(CertifiedRimRoots, NeverProvesTheDoubleRootAtTheTopOfACap) {
  // k0 = -(1 + k3): g(0) = g'(0) = 0 (exact doubles), concave around it.
  for (const double k3 : {kCapSecondHarmonic, -0x1p-20, 0x1p-10}) {
    const RimDistancePolynomial g = polynomial(-(1 + k3), 1, 0, k3, 0);
    const RimRoots result = certified_rim_roots(g);
    EXPECT_FALSE(result.proved) << "k3 " << k3 << " count " << result.count;
  }
}

TEST(CertifiedRimRoots, IsNeverWrongOneUlpAwayFromTheDoubleRootAtTheTopOfACap) {
  const double top = -(1 + kCapSecondHarmonic);
  double up = top, down = top;
  int proved = 0;
  for (int step = 0; step < 64; ++step) {
    up = std::nextafter(up, 0.0);      // k0 larger: a peak just above zero, two close roots
    down = std::nextafter(down, -2.0);  // a peak just below zero: none
    for (const double k0 : {up, down}) {
      const RimDistancePolynomial g = polynomial(k0, 1, 0, kCapSecondHarmonic, 0);
      const RimRoots result = certified_rim_roots(g);
      if (!result.proved) continue;
      ++proved;
      expect_proved_roots_match(result, cap_family_roots(k0, kCapSecondHarmonic), exact(g));
    }
  }
  // Proved: 105 of the 128 measured; a few ulps from a double root any honest tier may decline
  // some. The floor leaves a margin of 15 and keeps the loop from passing on nothing.
  EXPECT_GE(proved, 90);
}

TEST(CertifiedRimRoots, MatchesTheExactRootsOfShallowCrossingsAndNearMisses) {
  // Peaks spread across the band where the first-harmonic proof cannot sign the end arc, with
  // the first harmonic's phase and the second harmonic's turned at random.
  std::mt19937_64 rng(2026'11'25);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ReferenceTally tally;
  int proved_in_tier_one = 0;
  const int kCases = 200;
  for (int i = 0; i < kCases; ++i) {
    const double second = 1e-3 * (1 + unit(rng));
    const double phase = 2 * std::numbers::pi * unit(rng), turn = 2 * std::numbers::pi * unit(rng);
    // Peak of cos(t - phase) + second cos(2 (t - turn)) above k0 + 1, as far as its worst 2 second.
    const double k0 = -1 + second * (4 * unit(rng) - 2);
    const RimDistancePolynomial g = polynomial(k0, std::cos(phase), std::sin(phase), second * std::cos(2 * turn),
                                               second * std::sin(2 * turn));
    // The reference's grid cannot separate roots much closer than its cell (peaks within
    // ~1e-5 of zero): those cases are left out.
    const std::optional<RimRoots> result = proved_and_checked(g, tally);
    proved_in_tier_one += result && result->count == 2 && result->roots[0].has_trig();
  }
  RecordProperty("compared", tally.compared);
  RecordProperty("proved", tally.proved);
  RecordProperty("proved_in_tier_one", proved_in_tier_one);
  EXPECT_GT(tally.compared, kCases * 3 / 4);
  EXPECT_GT(tally.proved, tally.compared * 9 / 10);
  // Before the cap proof, every crossing here went to tier 2; most are now tier 1's.
  EXPECT_GT(proved_in_tier_one, tally.compared / 4);
}

TEST(CertifiedRimRoots, RefusesToProveWithNonFiniteCoefficients) {
  RimDistancePolynomial g = polynomial(0.5, 1, 0, 0, 0);
  g.k[2].error = HUGE_VAL;
  EXPECT_FALSE(certified_rim_roots(g).proved);
  g = polynomial(0.5, HUGE_VAL, 0, 0, 0);
  EXPECT_FALSE(certified_rim_roots(g).proved);
}

TEST(CertifiedRimRoots, NamesCoefficientOverflowForAnyNonFiniteValueOrError) {
  const double non_finite[3] = {HUGE_VAL, -HUGE_VAL, std::numeric_limits<double>::quiet_NaN()};
  for (int i = 0; i < 5; ++i) {
    for (const double x : non_finite) {
      for (const bool in_error : {false, true}) {
        RimDistancePolynomial g = polynomial(0.5, 1, 0.25, 0.01, 0.02);
        (in_error ? g.k[i].error : g.k[i].value) = x;
        const RimRoots roots = certified_rim_roots(g);
        EXPECT_FALSE(roots.proved);
        EXPECT_EQ(roots.failure, CertificateReason::coefficient_overflow)
            << "coefficient " << i << (in_error ? " error " : " value ") << x;
      }
    }
  }
  // Finite extremes pass the check: the largest double, a subnormal, and a negative zero.
  RimDistancePolynomial g = polynomial(0.5, 1, 0.25, 0.01, 0.02);
  g.k[3].value = -0.0;
  g.k[4].error = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(certified_rim_roots(g).proved);
  g.k[0].value = std::numeric_limits<double>::max();
  EXPECT_NE(certified_rim_roots(g).failure, CertificateReason::coefficient_overflow);
}

TEST(ApproximateRimRoots, FindsTheRootsWithoutClaimingAProof) {
  const RimDistancePolynomial g = polynomial(0.5, 1, 0, 0, 0);
  const RimRoots result = approximate_rim_roots(g);
  EXPECT_FALSE(result.proved);
  EXPECT_NE(result.failure, CertificateReason::none);
  ASSERT_EQ(result.count, 2);
  // Tier 1's iteration in double converges to within a few ulps of the root.
  const double kIterationAccuracy = 1e-14;
  EXPECT_NEAR(result.roots[0].angle, 2 * std::numbers::pi / 3, kIterationAccuracy);
  EXPECT_NEAR(result.roots[1].angle, 4 * std::numbers::pi / 3, kIterationAccuracy);
}

// ---- sort_by_angle ----------------------------------------------------------------------

RimRoots with_angles(std::initializer_list<double> angles, int count) {
  RimRoots r;
  int i = 0;
  for (const double a : angles) {
    r.roots[i] = {a, 0.001 * (i + 1), i + 1, i % 2 ? -1 : 1};
    ++i;
  }
  r.count = count;
  return r;
}

TEST(SortByAngle, SortsTheFirstCountRootsCarryingTheirFields) {
  RimRoots r = with_angles({3.0, 1.0, 2.0, 0.5}, 3);
  sort_by_angle(r);
  EXPECT_EQ(r.roots[0].angle, 1.0);
  EXPECT_EQ(r.roots[1].angle, 2.0);
  EXPECT_EQ(r.roots[2].angle, 3.0);
  EXPECT_EQ(r.roots[3].angle, 0.5);  // beyond count: untouched
  // Each root keeps its own radius, multiplicity and sign.
  EXPECT_EQ(r.roots[0].multiplicity, 2);
  EXPECT_EQ(r.roots[0].radius, 0.002);
  EXPECT_EQ(r.roots[0].sign_after, -1);
  EXPECT_EQ(r.roots[2].multiplicity, 1);
}

TEST(SortByAngle, SortsFourRootsInReverseOrderAndLeavesShortListsAlone) {
  RimRoots four = with_angles({4.0, 3.0, 2.0, 1.0}, 4);
  sort_by_angle(four);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(four.roots[i].angle, 1.0 + i);
  RimRoots one = with_angles({5.0, 1.0}, 1);
  sort_by_angle(one);
  EXPECT_EQ(one.roots[0].angle, 5.0);
  EXPECT_EQ(one.roots[1].angle, 1.0);
  RimRoots none = with_angles({5.0, 1.0}, 0);
  sort_by_angle(none);
  EXPECT_EQ(none.roots[0].angle, 5.0);
}


/// One Halley run alone, as tier 1 would step each run without lanes: the reference that each
/// lane of HalleyRuns must reproduce bit for bit.
struct HalleyRunAlone {
  AngleBase base;
  double offset = 0.0;
  double slope = 0.0;
  bool running = true;

  explicit HalleyRunAlone(double guess) {
    const GridAngle start = grid_angle(guess);
    base = start.base;
    offset = start.offset;
  }
  void step(const RimDistancePolynomial& g) {
    if (!running) return;
    const ValueAndSlope at = g.approximate_near(base, offset);
    slope = std::fabs(at.slope);
    const double change = 2 * at.value * at.slope / (2 * at.slope * at.slope - at.value * at.curvature);
    if (!std::isfinite(change)) {
      running = false;
      return;
    }
    const double next = offset - change;
    if (std::fabs(next) > kMaxAngleOffset) {
      const GridAngle moved = grid_angle(base.angle + next);
      base = moved.base;
      offset = moved.offset;
      return;
    }
    offset = next;
    if (std::fabs(change) < kHalleyLastStep * (1.0 + std::fabs(base.angle))) running = false;
  }
};

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

/// Steps both for tier 1's six iterations, comparing lane i with run i after every step;
/// counts the steps on which a lane moved to another grid angle and on which one lane had
/// stopped while the other still ran.
void expect_lanes_step_as_the_runs_alone(const RimDistancePolynomial& g, std::array<double, 2> guesses,
                                         int& moves, int& one_stopped) {
  HalleyRuns lanes(g, guesses);
  HalleyRunAlone alone[2] = {HalleyRunAlone(guesses[0]), HalleyRunAlone(guesses[1])};
  for (int step = 0; step < 6; ++step) {
    const double bases_before[2] = {alone[0].base.angle, alone[1].base.angle};
    lanes.step();
    for (int i = 0; i < 2; ++i) {
      alone[i].step(g);
      if (bits(alone[i].base.angle) != bits(bases_before[i]) && bases_before[i] == bases_before[i]) ++moves;
      ASSERT_EQ(bits(lanes.base.angle[i]), bits(alone[i].base.angle)) << "lane " << i << " step " << step;
      ASSERT_EQ(bits(lanes.base.cos[i]), bits(alone[i].base.cos)) << "lane " << i << " step " << step;
      ASSERT_EQ(bits(lanes.base.sin[i]), bits(alone[i].base.sin)) << "lane " << i << " step " << step;
      ASSERT_EQ(bits(lanes.offset[i]), bits(alone[i].offset)) << "lane " << i << " step " << step;
      ASSERT_EQ(bits(lanes.slope[i]), bits(alone[i].slope)) << "lane " << i << " step " << step;
      ASSERT_EQ(lanes.running[i] != 0, alone[i].running) << "lane " << i << " step " << step;
    }
    if (alone[0].running != alone[1].running) ++one_stopped;
  }
}

TEST(HalleyRuns, EachLaneStepsBitForBitAsItsRunAlone) {
  // First-harmonic-dominated polynomials (tier 1's), started near their roots, from anywhere on
  // the circle (moves to other grid angles) and with one run on a root already (it stops at its
  // first step while the other runs on).
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), angle(-kTwoPi, 2 * kTwoPi);
  int moves = 0, one_stopped = 0;
  for (int i = 0; i < 3000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(unit(rng) * 40));
    const RimDistancePolynomial g =
        polynomial(0.8 * unit(rng) * scale, scale, unit(rng) * scale, 0.05 * unit(rng) * scale,
                   0.05 * unit(rng) * scale);
    const double phi = std::atan2(g.k[2].value, g.k[1].value);
    const double beta = std::acos(-g.k[0].value / std::hypot(g.k[1].value, g.k[2].value));
    switch (i % 3) {
      case 0:
        expect_lanes_step_as_the_runs_alone(g, {phi - beta + 0.01 * unit(rng), phi + beta + 0.01 * unit(rng)},
                                            moves, one_stopped);
        break;
      case 1:
        expect_lanes_step_as_the_runs_alone(g, {angle(rng), angle(rng)}, moves, one_stopped);
        break;
      default: {
        // Lane 0 starts where a first run settled: its next step is below kHalleyLastStep.
        HalleyRunAlone settled(phi - beta);
        for (int step = 0; step < 6; ++step) settled.step(g);
        expect_lanes_step_as_the_runs_alone(g, {settled.base.angle + settled.offset, angle(rng)},
                                            moves, one_stopped);
      }
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(moves, 300);
  EXPECT_GT(one_stopped, 300);
}

TEST(HalleyRuns, FreezesARunWithANonFiniteStepWhileTheOtherRuns) {
  // A NaN start (grid_angle gives NaN everywhere) and a zero slope each stop their lane at once.
  int moves = 0, one_stopped = 0;
  expect_lanes_step_as_the_runs_alone(polynomial(0.1, 1.0, 0.2, 0.01, 0.02),
                                      {std::numeric_limits<double>::quiet_NaN(), 1.0}, moves, one_stopped);
  expect_lanes_step_as_the_runs_alone(polynomial(0.0, 0.0, 0.0, 0.0, 0.0), {0.5, 2.0}, moves, one_stopped);
  expect_lanes_step_as_the_runs_alone(polynomial(1.0, 1.0, 0.0, 0.0, 0.0), {0.0, 3.0}, moves, one_stopped);
  EXPECT_GT(one_stopped, 0);
}

/// Tier 1's end-arc signs as first_harmonic_proof computed them before they shared lanes, with
/// scalar Bounded arithmetic: the reference end_arc_signs must reproduce in each lane.
int end_sign_alone(const Bounded& k0, const Bounded& amplitude, Bounded near_cos, Bounded far_cos,
                   double bound_h) {
  const Bounded hg(0.0, bound_h);
  const int near = (k0 + amplitude * near_cos - hg).sign();
  return near != 0 && near == (k0 + amplitude * far_cos - hg).sign() ? near : 0;
}

void expect_same_bits(const Bounded& scalar, const PairBounded& lanes, int lane) {
  EXPECT_EQ(bits(lanes.value[lane]), bits(scalar.value)) << "lane " << lane;
  EXPECT_EQ(bits(lanes.error[lane]), bits(scalar.error)) << "lane " << lane;
}

/// A value and error of random sign pattern and magnitude, zeros and subnormals included.
Bounded random_bounded(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1000), kind(0, 9);
  const double value = kind(rng) == 0 ? 0.0 : std::ldexp(unit(rng), exponent(rng));
  const double error = kind(rng) == 0 ? 0.0 : std::ldexp(std::fabs(unit(rng)), exponent(rng));
  return {value, error};
}

TEST(PairBoundedArithmetic, EachLaneIsTheScalarOperationBitForBit) {
  std::mt19937_64 rng(77);
  for (int i = 0; i < 20000; ++i) {
    const Bounded a[2] = {random_bounded(rng), random_bounded(rng)};
    const Bounded b[2] = {random_bounded(rng), random_bounded(rng)};
    const PairBounded pa = {Pair{a[0].value, a[1].value}, Pair{a[0].error, a[1].error}};
    const PairBounded pb = {Pair{b[0].value, b[1].value}, Pair{b[0].error, b[1].error}};
    const PairBounded sum = pa + pb, difference = pa - pb, product = pa * pb;
    const PairSigns lane_signs = signs(pa);
    for (int lane = 0; lane < 2; ++lane) {
      expect_same_bits(a[lane] + b[lane], sum, lane);
      expect_same_bits(a[lane] - b[lane], difference, lane);
      expect_same_bits(a[lane] * b[lane], product, lane);
      const int sign = lane_signs.positive[lane] ? 1 : lane_signs.negative[lane] ? -1 : 0;
      EXPECT_EQ(sign, a[lane].sign()) << "lane " << lane;
      EXPECT_FALSE(lane_signs.positive[lane] && lane_signs.negative[lane]);
    }
    if (HasFailure()) return;
  }
}

TEST(EndArcSigns, AreTheScalarEndSignsOfBothArcs) {
  // Tier 1's inputs (k0 against an amplitude, a cos(alpha) near 1, Hg a small fraction), with
  // k0 swept across -A - Hg .. A + Hg so that every end is decided either way or left open, at
  // many scales; and arbitrary Bounded operands for the arithmetic's corner cases.
  std::mt19937_64 rng(2025);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided[3] = {0, 0, 0};  // -1, 0, +1 at 0
  for (int i = 0; i < 40000; ++i) {
    Bounded k0, amplitude, cos_alpha;
    double bound_h;
    if (i % 4 != 3) {
      const double scale = std::ldexp(1.0, static_cast<int>(unit(rng) * 60));
      amplitude = {scale * (1 + 0.5 * unit(rng)), scale * std::ldexp(std::fabs(unit(rng)), -50)};
      bound_h = scale * std::ldexp(std::fabs(unit(rng)), -static_cast<int>(4 + 40 * std::fabs(unit(rng))));
      const double sin_alpha = std::fabs(unit(rng)) * 0.5;
      cos_alpha = sqrt(Bounded(1.0) - Bounded(sin_alpha) * sin_alpha);
      k0 = {amplitude.value * (1.2 * unit(rng)), scale * std::ldexp(std::fabs(unit(rng)), -50)};
      if (i % 4 == 2) k0.value = (unit(rng) > 0 ? 1 : -1) * (amplitude.value * cos_alpha.value + unit(rng) * bound_h);
    } else {
      k0 = random_bounded(rng);
      amplitude = random_bounded(rng);
      cos_alpha = random_bounded(rng);
      bound_h = std::fabs(random_bounded(rng).value);
    }
    const std::array<int, 2> lanes = end_arc_signs(k0, amplitude, cos_alpha, bound_h);
    const int at_zero = end_sign_alone(k0, amplitude, cos_alpha, Bounded(1.0), bound_h);
    const int at_pi = end_sign_alone(k0, amplitude, -cos_alpha, Bounded(-1.0), bound_h);
    ASSERT_EQ(lanes[0], at_zero) << "case " << i;
    ASSERT_EQ(lanes[1], at_pi) << "case " << i;
    ++decided[at_zero + 1];
  }
  EXPECT_GT(decided[0], 1000);
  EXPECT_GT(decided[1], 1000);
  EXPECT_GT(decided[2], 1000);
}
}  // namespace
}  // namespace clearjoint::geometry::detail
