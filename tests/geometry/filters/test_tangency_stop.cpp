// SPDX-License-Identifier: BSD-3-Clause
// Tests of tier 2's stop at a proved multiple root (certified_rim_roots.cpp, section 3.1 of
// docs/circle-cylinder.md): where the exact tier proves a tangency inside the arc the search has
// narrowed to, the search stops with the reason the full search gives; everywhere else the
// search runs as it did without the exact tier, bit for bit.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "filters/certified_rim_roots.hpp"

namespace clearjoint::geometry::detail {
namespace {

RimDistancePolynomial polynomial(double k0, double k1, double k2, double k3, double k4) {
  RimDistancePolynomial g;
  g.k = {Bounded(k0), Bounded(k1), Bounded(k2), Bounded(k3), Bounded(k4)};
  return g;
}

/// Enclosure radius of the stand-in exact roots: a few ulps of the angles, which are the doubles
/// nearest the true roots (within half an ulp, 4.4e-16 at 2 pi).
constexpr double kStandInRadius = 4e-15;

/// Stands in for the exact tier: hands out fixed roots and counts the requests.
class FixedRoots final : public ExactRootsOnRequest {
 public:
  FixedRoots(std::vector<double> angles, int multiplicity, bool decided = true) : decided_(decided) {
    roots_.proved = true;
    for (const double angle : angles) {
      roots_.roots[static_cast<std::size_t>(roots_.count++)] = {angle, kStandInRadius, multiplicity, +1};
    }
  }
  const RimRoots* roots() override {
    ++requests;
    return decided_ ? &roots_ : nullptr;
  }
  int requests = 0;

 private:
  RimRoots roots_;
  bool decided_;
};

/// Every field of two answers equal, bit for bit.
void expect_same_answer(const RimRoots& a, const RimRoots& b) {
  EXPECT_EQ(a.proved, b.proved);
  EXPECT_EQ(a.failure, b.failure);
  EXPECT_EQ(a.side_without_roots, b.side_without_roots);
  ASSERT_EQ(a.count, b.count);
  for (int i = 0; i < a.count; ++i) {
    const RootEnclosure &x = a.roots[static_cast<std::size_t>(i)], &y = b.roots[static_cast<std::size_t>(i)];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.angle), std::bit_cast<std::uint64_t>(y.angle)) << "root " << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.radius), std::bit_cast<std::uint64_t>(y.radius)) << "root " << i;
    EXPECT_EQ(x.multiplicity, y.multiplicity);
    EXPECT_EQ(x.sign_after, y.sign_after);
  }
}

struct Tangency {
  RimDistancePolynomial g;
  std::vector<double> double_roots;  // the nearest doubles
};

/// Trig polynomials with double roots (tier 1 cannot prove them; tier 2 halves its way into them).
std::vector<Tangency> tangencies() {
  const double pi = std::numbers::pi;
  return {
      {polynomial(1, 1, 0, 0, 0), {pi}},                              // 1 + cos t
      {polynomial(5, 3, 4, 0, 0), {std::atan2(4.0, 3.0) + pi}},       // 5 + 3 cos t + 4 sin t
      {polynomial(1, 0, 0, -1, 0), {0.0, pi}},                        // 2 sin^2 t
      {polynomial(0.75, -1, 0, 0.5, 0), {pi / 3, 5 * pi / 3}},        // (cos t - 1/2)^2
      {polynomial(-1, -1, 0, 0, 0), {0.0}},                           // -(1 + cos t) touches from below
  };
}

TEST(TangencyStop, StopsWithTheFullSearchsReasonWhereTheExactTierProvesADoubleRoot) {
  for (const Tangency& tangency : tangencies()) {
    const RimRoots full = certified_rim_roots(tangency.g);
    ASSERT_FALSE(full.proved);
    FixedRoots exact(tangency.double_roots, 2);
    const RimRoots stopped = certified_rim_roots(tangency.g, &exact);
    EXPECT_FALSE(stopped.proved) << "k0 " << tangency.g.k[0].value;
    EXPECT_EQ(stopped.failure, full.failure) << "k0 " << tangency.g.k[0].value;
    EXPECT_EQ(stopped.failure, CertificateReason::interval_proof_failed_near_multiple_root);
    EXPECT_EQ(exact.requests, 1) << "k0 " << tangency.g.k[0].value;
  }
}

TEST(TangencyStop, LeavesTheSearchAsItWasWhenTheExactRootsAreSimple) {
  // Close simple roots where the search met a tangency's signs: no stop, the full search's answer.
  for (const Tangency& tangency : tangencies()) {
    FixedRoots exact(tangency.double_roots, 1);
    expect_same_answer(certified_rim_roots(tangency.g, &exact), certified_rim_roots(tangency.g));
  }
}

TEST(TangencyStop, LeavesTheSearchAsItWasWhenTheMultipleRootLiesElsewhere) {
  for (const Tangency& tangency : tangencies()) {
    std::vector<double> moved;
    for (const double angle : tangency.double_roots) moved.push_back(std::fmod(angle + 0.5, 2 * std::numbers::pi));
    FixedRoots exact(moved, 2);
    expect_same_answer(certified_rim_roots(tangency.g, &exact), certified_rim_roots(tangency.g));
  }
}

TEST(TangencyStop, LeavesTheSearchAsItWasWhenTheExactTierCannotDecide) {
  for (const Tangency& tangency : tangencies()) {
    FixedRoots exact(tangency.double_roots, 2, /*decided=*/false);
    expect_same_answer(certified_rim_roots(tangency.g, &exact), certified_rim_roots(tangency.g));
    EXPECT_LE(exact.requests, 1);
  }
}

TEST(TangencyStop, NeverAsksTheExactTierForWellSeparatedRoots) {
  // Tier 1 proves the first two, tier 2 the four roots of the second harmonic and the root-free
  // rims: nothing looks like a tangency, so the exact tier is never asked.
  for (const RimDistancePolynomial& g :
       {polynomial(0, 1, 0, 0, 0), polynomial(0.3, 0.6, -0.8, 0.05, 0.02), polynomial(0, 0, 0, 1, 0),
        polynomial(0.1, 0.2, 0.1, 1, 0.5), polynomial(2, 1, 0, 0.3, 0), polynomial(-2, 0.5, 0.5, 0.2, 0.1)}) {
    FixedRoots exact({}, 2);
    const RimRoots with_exact = certified_rim_roots(g, &exact);
    EXPECT_TRUE(with_exact.proved) << "k0 " << g.k[0].value;
    EXPECT_EQ(exact.requests, 0) << "k0 " << g.k[0].value;
    expect_same_answer(with_exact, certified_rim_roots(g));
  }
}

TEST(TangencyStop, NeverProvesADoubleRootWhateverTheExactTierSays) {
  // The stop only ever ends the search unproved: the exact tier's roots never become tier 2's.
  for (const Tangency& tangency : tangencies()) {
    for (const int multiplicity : {1, 2, 4}) {
      FixedRoots exact(tangency.double_roots, multiplicity);
      EXPECT_FALSE(certified_rim_roots(tangency.g, &exact).proved);
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
