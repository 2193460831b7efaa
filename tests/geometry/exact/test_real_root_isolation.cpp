// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/exact/real_root_isolation.{hpp,cpp}: the square-free factors against
// CGAL's square-free factorisation of the same rational polynomial, the number of isolated roots
// against CGAL's Sturm-Habicht count, every isolating interval against the known roots of
// polynomials built from them, and the limits (oversized coefficients, a bound that is not
// dyadic).

#include "exact/real_root_isolation.hpp"

#include <gtest/gtest.h>

#include <CGAL/Polynomial_traits_d.h>
#include <CGAL/Polynomial/sturm_habicht_sequence.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace clearjoint::geometry::detail {
namespace {

using Polynomial = RationalPolynomial;

Polynomial linear(const Rational& root) { return Polynomial(-root, Rational(1)); }

/// CGAL's square-free factors of f (monic, multiplicity 1 first), degree-0 factors left out.
std::vector<std::pair<Polynomial, int>> cgal_factors(const Polynomial& f) {
  std::vector<std::pair<Polynomial, int>> factors, out;
  CGAL::Polynomial_traits_d<Polynomial>::Square_free_factorize_up_to_constant_factor()(f, std::back_inserter(factors));
  for (auto& [factor, multiplicity] : factors) {
    if (factor.degree() >= 1) out.emplace_back(factor, multiplicity);
  }
  return out;
}

/// A power of two above every root's magnitude (Cauchy: 1 + max |f_i / f_d|).
Rational root_bound(const Polynomial& f) {
  double largest = 0.0;
  for (int i = 0; i < f.degree(); ++i) largest = std::max(largest, std::fabs(CGAL::to_double(f[i] / f[f.degree()])));
  return Rational(std::ldexp(1.0, std::ilogb(largest + 1.0) + 2));
}

/// Every isolated root is a root of its factor (a rational one exactly, an irrational one by a
/// sign change over its interval), the intervals are disjoint, their number is CGAL's count of
/// distinct real roots, and each factor's multiplicity is CGAL's for that factor.
void expect_consistent_isolation(const Polynomial& f) {
  IsolatedRoots roots;
  EvaluationBudget budget;
  isolate_real_roots(f, root_bound(f), roots, budget);
  const auto reference = cgal_factors(f);
  int expected_count = 0;
  for (const auto& [factor, multiplicity] : reference) expected_count += CGAL::number_of_real_roots(factor);
  ASSERT_EQ(static_cast<int>(roots.size()), expected_count) << f;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const IsolatedRoot& root = roots[i];
    const Polynomial factor = root.factor->monic();
    bool listed = false;
    for (const auto& [reference_factor, multiplicity] : reference) {
      if (reference_factor == factor) {
        listed = true;
        EXPECT_EQ(root.multiplicity, multiplicity) << factor;
      }
    }
    EXPECT_TRUE(listed) << "factor " << factor << " is not one of CGAL's for " << f;
    ASSERT_LE(root.low, root.high);
    if (root.low == root.high) {
      EXPECT_EQ(factor.sign_at(root.low), CGAL::ZERO);
    } else {
      EXPECT_NE(factor.sign_at(root.low), factor.sign_at(root.high)) << "no sign change on the interval of root " << i;
    }
    // Roots of one factor come from disjoint half-open intervals (low, high]: closed ones may
    // share an end. Different factors are isolated independently.
    for (std::size_t j = 0; j < i; ++j) {
      if (roots[j].factor != root.factor) continue;
      EXPECT_TRUE(roots[j].high <= root.low || root.high <= roots[j].low) << "intervals " << j << " and " << i << " overlap";
    }
  }
}

TEST(RealRootIsolation, FactorsLikeCgalWithMultiplicitiesInYunsOrder) {
  const Polynomial f = linear(Rational(1, 3)) * linear(Rational(1, 3)) * linear(Rational(-5, 7)) *
                       Polynomial(Rational(-2), Rational(0), Rational(1));  // (x - 1/3)^2 (x + 5/7) (x^2 - 2)
  IsolatedRoots roots;
  EvaluationBudget budget;
  isolate_real_roots(Rational(-6) * f, Rational(4), roots, budget);
  ASSERT_EQ(roots.size(), 4u);
  // Multiplicity 1 first (x + 5/7 and x^2 - 2 together, one square-free factor), then 2.
  const auto reference = cgal_factors(f);
  ASSERT_EQ(reference.size(), 2u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(roots[static_cast<std::size_t>(i)].multiplicity, 1);
    EXPECT_EQ(roots[static_cast<std::size_t>(i)].factor->monic(), reference[0].first);
  }
  EXPECT_EQ(roots[3].multiplicity, 2);
  EXPECT_EQ(roots[3].factor->monic(), reference[1].first);
  EXPECT_LE(roots[3].low, Rational(1, 3));
  EXPECT_GE(roots[3].high, Rational(1, 3));
  EXPECT_LT(roots[3].high - roots[3].low, Rational(std::ldexp(1.0, -40)));
}

TEST(RealRootIsolation, EnclosesEachKnownRootInItsOwnNarrowInterval) {
  // Roots sqrt(2), -sqrt(2), 1/2 + 2^-40 and 1/2 - 2^-40: the last two 2^-39 apart.
  const Rational gap(std::ldexp(1.0, -40));
  const Polynomial f = Polynomial(Rational(-2), Rational(0), Rational(1)) * linear(Rational(1, 2) + gap) *
                       linear(Rational(1, 2) - gap);
  IsolatedRoots roots;
  EvaluationBudget budget;
  isolate_real_roots(f, Rational(4), roots, budget);
  ASSERT_EQ(roots.size(), 4u);
  const std::vector<double> expected = {-std::sqrt(2.0), std::sqrt(2.0), 0.5 - std::ldexp(1.0, -40), 0.5 + std::ldexp(1.0, -40)};
  for (const double x : expected) {
    int holding = 0;
    for (const IsolatedRoot& root : roots) {
      // The Newton shrink's widest enclosure: 2^21 ulps-worth (spreads below 2^20 either side).
      const double width = CGAL::to_double(root.high - root.low);
      EXPECT_LE(width, std::ldexp(1.0, 21) * std::numeric_limits<double>::epsilon() * 2);
      // The enclosures are a few ulps wide; the double root estimate is within an ulp of them.
      if (CGAL::to_double(root.low) <= std::nextafter(x, 1e300) && std::nextafter(x, -1e300) <= CGAL::to_double(root.high)) ++holding;
    }
    EXPECT_EQ(holding, 1) << "root " << x;
  }
  expect_consistent_isolation(f);
}

TEST(RealRootIsolation, AgreesWithCgalOnRandomProductsOfSmallFactors) {
  std::mt19937_64 random(20170504);
  std::uniform_int_distribution<int> small(-9, 9), denominator(1, 7), kind(0, 3);
  for (int trial = 0; trial < 300; ++trial) {
    Polynomial f(Rational(1));
    while (f.degree() < 4) {
      switch (kind(random)) {
        case 0:  // a rational root, sometimes repeated
        case 1: {
          const Polynomial factor = linear(Rational(small(random), denominator(random)));
          f *= factor;
          if (kind(random) == 0 && f.degree() < 4) f *= factor;
          break;
        }
        case 2:  // a quadratic, with or without real roots
          f *= Polynomial(Rational(small(random), denominator(random)), Rational(small(random)), Rational(denominator(random)));
          break;
        default:  // a scalar factor: the roots stay, the coefficients grow
          f *= Polynomial(Rational(small(random) == 0 ? 3 : small(random), denominator(random)));
          break;
      }
      if (f.is_zero()) f = Polynomial(Rational(1));
    }
    SCOPED_TRACE(trial);
    expect_consistent_isolation(f);
  }
}

TEST(RealRootIsolation, AgreesWithCgalOnRandomDoubleCoefficients) {
  // Coefficients like the rim polynomial's: doubles of mixed binary exponents.
  std::mt19937_64 random(20170505);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Rational> coefficients;
    for (int i = 0; i <= 4; ++i) coefficients.emplace_back(std::ldexp(unit(random), exponent(random)));
    if (coefficients.back() == Rational(0)) coefficients.back() = Rational(1);
    SCOPED_TRACE(trial);
    expect_consistent_isolation(Polynomial(coefficients.begin(), coefficients.end()));
  }
}

TEST(RealRootIsolation, CountsRootsInHalfOpenIntervalsWithSturmSequences) {
  const Polynomial f = linear(Rational(1)) * linear(Rational(2)) * linear(Rational(2)) * linear(Rational(-3, 2));
  const SturmSequence sturm(f);
  EXPECT_EQ(sturm.roots_in(Rational(-4), Rational(4)), 3);  // distinct roots
  EXPECT_EQ(sturm.roots_in(Rational(1), Rational(2)), 1);   // (1, 2]: 2 only
  EXPECT_EQ(sturm.roots_in(Rational(0), Rational(1)), 1);   // (0, 1]: 1
  EXPECT_EQ(sturm.roots_in(Rational(-3, 2), Rational(1, 3)), 0);
  EXPECT_EQ(sturm.roots_in(Rational(-5, 3), Rational(-4, 3)), 1);
}

TEST(RealRootIsolation, GivesUpOnCoefficientsBeyondItsLimit) {
  const Rational huge(std::ldexp(1.0, 1000));
  Rational big(1);
  for (int i = 0; i < 9; ++i) big *= huge;  // 9,001 bits
  IsolatedRoots roots;
  EvaluationBudget budget;
  try {
    isolate_real_roots(Polynomial(big + Rational(1), Rational(1)), Rational(4), roots, budget);
    FAIL() << "expected ExactTierGiveUp";
  } catch (const ExactTierGiveUp& gave_up) {
    EXPECT_EQ(gave_up.why, CertificateReason::exact_coefficients_too_large);
  }
}

TEST(RealRootIsolation, RejectsABoundThatIsNotDyadic) {
  IsolatedRoots roots;
  EvaluationBudget budget;
  EXPECT_THROW(isolate_real_roots(linear(Rational(1)), Rational(1, 3), roots, budget), std::invalid_argument);
}

TEST(RealRootIsolation, FindsNoRootOfAConstantOrOfAPolynomialWithoutRealRoots) {
  IsolatedRoots roots;
  EvaluationBudget budget;
  isolate_real_roots(Polynomial(Rational(5)), Rational(4), roots, budget);
  isolate_real_roots(Polynomial(Rational(1), Rational(0), Rational(1)), Rational(4), roots, budget);
  EXPECT_TRUE(roots.empty());
}


// The Sturm chain's last member, a constant whose sign alone is read, comes from a multiprecision
// filter where that decides and from the exact remainder otherwise: near two close roots it is
// small next to its terms by about their squared distance. Roots 2^-39 apart leave the filter its
// decision, 2^-200 apart (a cancellation beyond its precision) and a double root (a zero
// remainder) the exact path; each count must be the true one. A factor of 2^1000 gives the
// coefficients the size at which the filter is tried (the rim's reach thousands of bits).
TEST(RealRootIsolation, CountsCloseRootsCorrectlyWhateverDecidesTheChainsLastMember) {
  std::mt19937_64 random(20170506);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 2);
  const Rational huge(std::ldexp(1.0, 1000));
  for (int trial = 0; trial < 120; ++trial) {
    const Rational first(unit(random));
    const int gap_exponent = trial % 3 == 0 ? -39 : trial % 3 == 1 ? -200 : 0;
    const Rational second = gap_exponent == 0 ? first : first + Rational(std::ldexp(1.0, gap_exponent));
    // The large scalar, and a third factor: two real roots far off, or none.
    Polynomial f = linear(first) * linear(second) * Polynomial(huge * 3 + Rational(1));
    const bool real_pair = kind(random) == 0;
    f *= real_pair ? linear(Rational(3)) * linear(Rational(-3)) : Polynomial(Rational(1), Rational(0), Rational(1));
    const int distinct = (gap_exponent == 0 ? 1 : 2) + (real_pair ? 2 : 0);
    SCOPED_TRACE(trial);
    const SturmSequence sturm(f);
    EXPECT_EQ(sturm.roots_in(Rational(-4), Rational(4)), distinct);
    // Ends off the roots (Sturm's theorem on a polynomial with a multiple root needs that): the
    // pair, then each of its roots alone when there are two.
    const Rational below = first - Rational(1, 1024), above = second + Rational(1, 1024);
    EXPECT_EQ(sturm.roots_in(below, above), gap_exponent == 0 ? 1 : 2);
    if (gap_exponent != 0) {
      const Rational between = first + Rational(std::ldexp(1.0, gap_exponent - 1));
      EXPECT_EQ(sturm.roots_in(below, between), 1);
      EXPECT_EQ(sturm.roots_in(between, above), 1);
    }
    expect_consistent_isolation(f);
  }
}


// The member before the last (linear for a quartic) is kept as a multiprecision enclosure when the
// filter decides the chain's end, its exact coefficients computed at the first sign its filter
// cannot give: at its own root, a rational point found here from CGAL's Euclidean remainders
// (the chain's members up to positive factors). A count with that point as an end must need, and
// get, the exact member.
TEST(RealRootIsolation, CountsExactlyAtTheRootOfAChainMemberKnownOnlyByItsEnclosure) {
  std::mt19937_64 random(20170507);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Rational huge(std::ldexp(1.0, 1000));
  for (int trial = 0; trial < 40; ++trial) {
    const Rational first(unit(random)), second = first + Rational(std::ldexp(1.0, -39));
    const Rational third(2 + unit(random)), fourth(-2 + unit(random));
    const Polynomial f = linear(first) * linear(second) * linear(third) * linear(fourth) * Polynomial(huge * 3 + Rational(1));
    Polynomial quotient, r2, r1;
    Polynomial::euclidean_division(f, CGAL::differentiate(f), quotient, r2);
    Polynomial::euclidean_division(CGAL::differentiate(f), r2, quotient, r1);
    ASSERT_EQ(r1.degree(), 1);
    const Rational member_root = -r1[0] / r1[1];
    int below = 0;
    for (const Rational& root : {first, second, third, fourth}) below += root <= member_root ? 1 : 0;
    SCOPED_TRACE(trial);
    const SturmSequence sturm(f);
    EXPECT_EQ(sturm.roots_in(Rational(-8), member_root), below);
    EXPECT_EQ(sturm.roots_in(member_root, Rational(8)), 4 - below);
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
