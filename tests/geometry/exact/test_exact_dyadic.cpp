// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/exact/exact_dyadic.hpp: interval_of_quotient and interval_of against
// CGAL::to_interval of the same rational, formed and reduced, on random integers of up to
// thousands of bits and on the edge cases (exact values, subnormal and out-of-range results,
// negative values, ties of the 53-bit rounding).

#include "exact/exact_dyadic.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <random>
#include <utility>

namespace clearjoint::geometry::detail {
namespace {

/// x 2^shift / d as CGAL's canonical rational, and CGAL's enclosure of it.
std::pair<double, double> cgal_interval(const mpz_class& x, long shift, const mpz_class& d) {
  CGAL::Gmpq value(CGAL::Gmpz(x.get_mpz_t()), CGAL::Gmpz(d.get_mpz_t()));
  if (shift > 0) mpq_mul_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(shift));
  if (shift < 0) mpq_div_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(-shift));
  return CGAL::to_interval(value);
}

void expect_cgal_interval(const mpz_class& x, long shift, const mpz_class& d) {
  const std::pair<double, double> ours = interval_of_quotient(x, shift, d), cgal = cgal_interval(x, shift, d);
  EXPECT_EQ(ours.first, cgal.first) << x << " 2^" << shift << " / " << d;
  EXPECT_EQ(ours.second, cgal.second) << x << " 2^" << shift << " / " << d;
}

TEST(ExactDyadic, EnclosesAQuotientAsCgalDoesOnRandomIntegersOfManySizes) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20170508);
  std::mt19937_64 small(20170508);
  std::uniform_int_distribution<int> bits(1, 3000), shifts(-3000, 3000), sign(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    mpz_class x = random.get_z_bits(bits(small)), d = random.get_z_bits(bits(small)) + 1;
    if (sign(small) == 1) x = -x;
    SCOPED_TRACE(trial);
    expect_cgal_interval(x, shifts(small), d);
  }
}

TEST(ExactDyadic, EnclosesExactSubnormalAndOutOfRangeQuotientsAsCgalDoes) {
  const mpz_class three = 3, seven = 7, one = 1, zero = 0;
  expect_cgal_interval(zero, 5, seven);        // zero
  expect_cgal_interval(three * 8, -3, three);  // exactly 1
  expect_cgal_interval(-seven, 10, one);       // an exact integer
  expect_cgal_interval(one, -1074, one);       // the smallest subnormal, exact
  expect_cgal_interval(one, -1060, three);     // a subnormal, rounded
  expect_cgal_interval(one, -1021, three);     // just below the normal range
  expect_cgal_interval(one, -1020, three);     // the smallest normal binade, rounded
  expect_cgal_interval(one, -1100, three);     // below every double
  expect_cgal_interval(seven, 1021, one);      // the largest binade, exact
  expect_cgal_interval(seven, 1022, three);    // the largest binade, rounded
  expect_cgal_interval(seven, 1023, three);    // beyond the largest double
  expect_cgal_interval(-seven, 2000, three);   // far beyond, negative
  // Just below 2^1024: rounded away from zero to 2^1024, beyond the range.
  const mpz_class nearly_two = (mpz_class(1) << 200) - 1;
  expect_cgal_interval(nearly_two, 1024 - 200, one);
  expect_cgal_interval(-nearly_two, 1024 - 200, one);
}

/// x 2^shift as CGAL's canonical rational.
CGAL::Gmpq dyadic_rational(const mpz_class& x, long shift) {
  CGAL::Gmpq value(CGAL::Gmpz(x.get_mpz_t()));
  if (shift > 0) mpq_mul_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(shift));
  if (shift < 0) mpq_div_2exp(value.mpq(), value.mpq(), static_cast<mp_bitcnt_t>(-shift));
  return value;
}

void expect_cgal_interval_of(const CGAL::Gmpq& value) {
  const std::pair<double, double> ours = interval_of(value), cgal = CGAL::to_interval(value);
  EXPECT_EQ(ours.first, cgal.first) << value;
  EXPECT_EQ(ours.second, cgal.second) << value;
}

TEST(ExactDyadic, EnclosesADyadicRationalAsCgalDoesOnRandomIntegersOfManySizes) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20170509);
  std::mt19937_64 small(20170509);
  std::uniform_int_distribution<int> bits(1, 3000), shifts(-3000, 3000), sign(0, 1);
  for (int trial = 0; trial < 4000; ++trial) {
    mpz_class x = random.get_z_bits(bits(small));
    if (sign(small) == 1) x = -x;
    SCOPED_TRACE(trial);
    expect_cgal_interval_of(dyadic_rational(x, shifts(small)));
  }
}

TEST(ExactDyadic, EnclosesDyadicRationalsAtTheEdgesAsCgalDoes) {
  const mpz_class one = 1;
  const mpz_class top = (one << 53) - 1;  // 53 bits, every one set
  for (const long shift : {-1200L, -1126L, -1075L, -1074L, -1073L, -1023L, -1022L, -1021L, -1020L, -60L, 0L, 40L,
                           969L, 970L, 971L, 1000L}) {
    SCOPED_TRACE(shift);
    expect_cgal_interval_of(dyadic_rational(0, shift));
    expect_cgal_interval_of(dyadic_rational(one, shift));
    expect_cgal_interval_of(dyadic_rational(-top, shift));
    expect_cgal_interval_of(dyadic_rational(top, shift));
    // 54 bits: a tie of the 53-bit rounding, the lowest bit set, and one bit beyond with the
    // truncated part all ones.
    expect_cgal_interval_of(dyadic_rational((top << 1) + 1, shift));
    expect_cgal_interval_of(dyadic_rational(-((top << 1) + 1), shift));
    expect_cgal_interval_of(dyadic_rational((one << 53) + 1, shift));
    expect_cgal_interval_of(dyadic_rational((top << 20) + ((one << 20) - 1), shift - 20));
  }
  // Just below 2^1024 (rounded away to beyond the range) and a rational that is not dyadic.
  expect_cgal_interval_of(dyadic_rational((one << 200) - 1, 1024 - 200));
  expect_cgal_interval_of(dyadic_rational(-((one << 200) - 1), 1024 - 200));
  expect_cgal_interval_of(CGAL::Gmpq(1, 3));
  expect_cgal_interval_of(CGAL::Gmpq(-5, 12));
}

TEST(ExactDyadic, EnclosesWithoutCgalInsideTheNormalRangeAndLeavesTheEdgesToIt) {
  const mpz_class one = 1;
  const mpz_class wide = (one << 120) + 12345;  // inexact at 53 bits
  for (const long shift : {-1000L, -120L, 0L, 800L}) {
    SCOPED_TRACE(shift);
    const auto ours = interval_of_dyadic(wide.get_mpz_t(), shift);
    ASSERT_TRUE(ours.has_value());
    const std::pair<double, double> cgal = CGAL::to_interval(dyadic_rational(wide, shift));
    EXPECT_EQ(ours->first, cgal.first);
    EXPECT_EQ(ours->second, cgal.second);
    EXPECT_LT(ours->first, ours->second);  // inexact: two neighbouring doubles
  }
  // Within a binade of the subnormals or of the overflow: CGAL decides.
  EXPECT_FALSE(interval_of_dyadic(one.get_mpz_t(), -1022).has_value());
  EXPECT_FALSE(interval_of_dyadic(wide.get_mpz_t(), 1023 - 121 + 1).has_value());
}

}  // namespace
}  // namespace clearjoint::geometry::detail
