// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/arithmetic/error_bounded.hpp: every operation on Bounded must enclose the exact
// result of the exact operands (any real within value +- error), checked against 256-bit MPFR
// on random and adversarial inputs; sign() is 0 when undecided and never wrong.

#include "arithmetic/error_bounded.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mpfr_reference.hpp"

namespace clearjoint::geometry::detail {
namespace {

using internal_testing::Real;
using internal_testing::sign_of;

/// A Bounded together with a real number it claims to enclose.
struct Operand {
  Bounded bounded;
  Real truth;
};

/// |truth - value| <= error, evaluated in MPFR. The reference's own rounding (results of one
/// 256-bit operation on values already within the enclosure) is allowed for by
/// kReferenceRelativeError times the magnitudes involved.
::testing::AssertionResult Encloses(const Bounded& b, const Real& truth) {
  if (!b.finite()) return ::testing::AssertionSuccess();  // "not certified" is always allowed
  const Real distance = abs(truth - Real(b.value));
  const Real allowed =
      Real(b.error) + internal_testing::kReferenceRelativeError * (abs(truth) + std::fabs(b.value));
  if (distance <= allowed) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "value " << std::hexfloat << b.value << " error " << b.error << std::defaultfloat
         << " does not enclose " << truth.str(40) << " (distance " << distance.str(10) << ")";
}

::testing::AssertionResult SignIsNeverWrong(const Bounded& b, const Real& truth) {
  const int s = b.sign();
  if (s == 0 || s == sign_of(truth)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "sign() = " << s << " but the true value is "
                                       << truth.str(40);
}

/// Operands whose true value is one of the enclosure's ends, its centre, or a point inside.
std::vector<Operand> operands_around(double value, double error, std::mt19937_64& rng) {
  std::vector<Operand> out;
  std::uniform_real_distribution<double> inside(-1.0, 1.0);
  for (const double t : {-1.0, 1.0, 0.0, inside(rng)}) {
    const Real truth = Real(value) + Real(t) * Real(error);
    // Keep only truths the enclosure really contains (256 bits may round an end outwards).
    if (abs(truth - Real(value)) <= Real(error)) out.push_back({{value, error}, truth});
  }
  return out;
}

/// A random double with a random exponent among the given decades and a random sign.
double random_magnitude(std::mt19937_64& rng, const std::vector<int>& decades) {
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<std::size_t> pick(0, decades.size() - 1);
  std::bernoulli_distribution negative(0.5);
  const double x = mantissa(rng) * std::pow(10.0, decades[pick(rng)]);
  return negative(rng) ? -x : x;
}

/// Relative error sizes: exact, a few ulps, large, larger than the value itself.
double random_error(std::mt19937_64& rng, double value) {
  static const double kRelative[] = {0.0, 0x1p-52, 1e-10, 0.3, 2.0};
  std::uniform_int_distribution<int> pick(0, 4);
  return std::fabs(value) * kRelative[pick(rng)];
}

std::vector<Operand> random_operands(std::mt19937_64& rng, const std::vector<int>& decades,
                                     int count) {
  std::vector<Operand> out;
  for (int i = 0; i < count; ++i) {
    const double v = random_magnitude(rng, decades);
    for (const Operand& o : operands_around(v, random_error(rng, v), rng)) out.push_back(o);
  }
  return out;
}

// The magnitude classes of the brief: ordinary, near underflow (products of 1e-160 land in the
// subnormals), huge (1e150 squared is 1e300), and subnormal.
const std::vector<std::vector<int>> kDecadeClasses = {
    {-3, -1, 0, 1, 3}, {-170, -160, -155}, {140, 150, 153}, {-310, -315, -320}, {-160, 0, 150}};

using BinaryOp = std::function<Bounded(Bounded, Bounded)>;
using RealOp = std::function<Real(const Real&, const Real&)>;

void check_binary(const char* name, const BinaryOp& op, const RealOp& exact) {
  std::mt19937_64 rng(20240611);
  for (const std::vector<int>& decades : kDecadeClasses) {
    const std::vector<Operand> a = random_operands(rng, decades, 12);
    const std::vector<Operand> b = random_operands(rng, decades, 12);
    for (const Operand& x : a) {
      for (const Operand& y : b) {
        if (std::string(name) == "/" && y.truth == 0) continue;
        const Bounded r = op(x.bounded, y.bounded);
        const Real truth = exact(x.truth, y.truth);
        ASSERT_TRUE(Encloses(r, truth)) << name << " of " << x.bounded.value << " +- "
                                        << x.bounded.error << " and " << y.bounded.value << " +- "
                                        << y.bounded.error;
        ASSERT_TRUE(SignIsNeverWrong(r, truth)) << name;
      }
    }
  }
}

TEST(ErrorBounded, AdditionEnclosesTheExactSumOnRandomOperands) {
  check_binary("+", [](Bounded a, Bounded b) { return a + b; },
               [](const Real& a, const Real& b) { return a + b; });
}

TEST(ErrorBounded, SubtractionEnclosesTheExactDifferenceOnRandomOperands) {
  check_binary("-", [](Bounded a, Bounded b) { return a - b; },
               [](const Real& a, const Real& b) { return a - b; });
}

TEST(ErrorBounded, MultiplicationEnclosesTheExactProductOnRandomOperands) {
  check_binary("*", [](Bounded a, Bounded b) { return a * b; },
               [](const Real& a, const Real& b) { return a * b; });
}

TEST(ErrorBounded, DivisionEnclosesTheExactQuotientOnRandomOperands) {
  check_binary("/", [](Bounded a, Bounded b) { return a / b; },
               [](const Real& a, const Real& b) { return a / b; });
}

TEST(ErrorBounded, SubtractionOfNearlyEqualValuesEnclosesTheCancelledDifference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.5, 2.0);
  std::uniform_int_distribution<int> ulps(-8, 8);
  for (int i = 0; i < 2000; ++i) {
    const double a = unit(rng) * std::pow(10.0, (i % 7) * 50 - 150);
    double b = a;
    for (int k = ulps(rng); k != 0; k += (k > 0 ? -1 : 1))
      b = std::nextafter(b, k > 0 ? HUGE_VAL : -HUGE_VAL);
    // Exact operands, and operands carrying a few ulps of error of their own.
    for (const double relative_error : {0.0, 0x1p-52}) {
      for (const Operand& x : operands_around(a, std::fabs(a) * relative_error, rng)) {
        for (const Operand& y : operands_around(b, std::fabs(b) * relative_error, rng)) {
          const Bounded r = x.bounded - y.bounded;
          ASSERT_TRUE(Encloses(r, x.truth - y.truth));
          ASSERT_TRUE(SignIsNeverWrong(r, x.truth - y.truth));
        }
      }
    }
  }
}

TEST(ErrorBounded, ExactOperandsWithExactDifferenceGiveTheRightSign) {
  // Sterbenz: the difference of doubles within a factor 2 is exact, so the sign must be decided.
  const Bounded r = Bounded(1.0 + 0x1p-52) - Bounded(1.0);
  EXPECT_EQ(r.sign(), 1);
  EXPECT_TRUE(Encloses(r, Real(0x1p-52)));
  EXPECT_EQ((Bounded(1.0) - Bounded(1.0 + 0x1p-52)).sign(), -1);
}

TEST(ErrorBounded, ProductsNearUnderflowEncloseTheExactProduct) {
  // 1e-160 * 1e-160 = 1e-320 is subnormal; 1e-170 * 1e-170 underflows to 0.
  for (const double a : {1e-160, 3e-161, 1e-170, 0x1p-537, -2.5e-162}) {
    for (const double b : {1e-160, -7e-160, 1e-170, 0x1p-538, 4.9e-324}) {
      for (const double relative_error : {0.0, 1e-15}) {
        const Bounded x(a, std::fabs(a) * relative_error), y(b, std::fabs(b) * relative_error);
        const Bounded r = x * y;
        ASSERT_TRUE(r.finite());
        for (const Real& ta : {Real(a) - Real(x.error), Real(a) + Real(x.error)}) {
          for (const Real& tb : {Real(b) - Real(y.error), Real(b) + Real(y.error)}) {
            EXPECT_TRUE(Encloses(r, ta * tb)) << a << " * " << b;
            EXPECT_TRUE(SignIsNeverWrong(r, ta * tb)) << a << " * " << b;
          }
        }
      }
    }
  }
}

TEST(ErrorBounded, LargeMagnitudesStayEnclosedUntilOverflowIsReportedAsNotFinite) {
  const Bounded big(1e150, 1e135);
  const Bounded product = big * big;  // 1e300: finite
  ASSERT_TRUE(product.finite());
  EXPECT_TRUE(Encloses(product, (Real(1e150) + Real(1e135)) * (Real(1e150) + Real(1e135))));
  EXPECT_TRUE(Encloses(product, (Real(1e150) - Real(1e135)) * (Real(1e150) - Real(1e135))));
  EXPECT_FALSE((Bounded(1e200) * Bounded(1e200)).finite());
  EXPECT_FALSE((Bounded(1.7e308) + Bounded(1.7e308)).finite());
  EXPECT_FALSE((Bounded(1e300) / Bounded(1e-300)).finite());
}

TEST(ErrorBounded, SquareRootEnclosesTheExactRootIncludingNearZero) {
  // Operands whose true value is >= 0 (the documented precondition), many of them at or
  // straddling 0 where the first-order bound does not apply.
  const std::vector<std::pair<double, double>> cases = {
      {0.0, 0.0},      {0.0, 1e-300},    {1e-300, 1e-300}, {1e-300, 2e-300},  {-1e-310, 1e-300},
      {4.9e-324, 0.0}, {1e-320, 1e-321}, {4.0, 1.0},       {2.0, 0.0},        {1e300, 1e290},
      {1e-20, 1e-36},  {1.0, 0x1p-53},   {3.0, 2.999},     {0.25, 0.25},      {1e-200, 5e-201},
      {1.7e308, 1e292}, {0x1p1000, 0x1p960}, {0x1p-899, 0x1p-960}, {1e-250, 1e-320}};
  std::mt19937_64 rng(11);
  for (const auto& [value, error] : cases) {
    const Bounded r = sqrt(Bounded(value, error));
    ASSERT_TRUE(r.finite());
    for (const Operand& x : operands_around(value, error, rng)) {
      if (x.truth < 0) continue;  // outside the precondition
      EXPECT_TRUE(Encloses(r, boost::multiprecision::sqrt(x.truth))) << value << " +- " << error;
    }
    EXPECT_TRUE(Encloses(r, boost::multiprecision::sqrt(std::max(Real(0), Real(value) - Real(error)))));
  }
  // Random non-negative operands over the whole range.
  for (const std::vector<int>& decades : kDecadeClasses) {
    for (const Operand& x : random_operands(rng, decades, 40)) {
      // abs keeps the error, so |x| encloses the non-negative |truth|.
      const Bounded a = abs(x.bounded);
      const Real truth = abs(x.truth);
      const Bounded r = sqrt(a);
      EXPECT_TRUE(Encloses(r, boost::multiprecision::sqrt(truth)));
    }
  }
}

TEST(ErrorBounded, DivisionByAnEnclosureContainingZeroHasNoFiniteBound) {
  for (const Bounded divisor : {Bounded(0.0), Bounded(1e-3, 2e-3), Bounded(1.0, 1.0),
                                Bounded(-1.0, 1.5), Bounded(4.9e-324, 4.9e-324)}) {
    const Bounded q = Bounded(1.0) / divisor;
    EXPECT_FALSE(q.finite()) << divisor.value << " +- " << divisor.error;
    EXPECT_EQ(q.sign(), 0) << divisor.value << " +- " << divisor.error;
  }
  // Just not containing zero: finite, and the worst case (divisor 1 - 0.999) is enclosed.
  const Bounded q = Bounded(1.0) / Bounded(1.0, 0.999);
  ASSERT_TRUE(q.finite());
  EXPECT_TRUE(Encloses(q, Real(1) / (Real(1) - Real(0.999))));
  EXPECT_TRUE(Encloses(q, Real(1) / (Real(1) + Real(0.999))));
}

TEST(ErrorBounded, DivisionBySubnormalDivisorEnclosesTheExactQuotient) {
  // Exact dividend, subnormal divisor with a subnormal error: the true quotient can be as large
  // as a / (b - eb). Found by a random search against MPFR; the error computation |v| eb is
  // itself subnormal, where rounding is absolute, not relative.
  const double a = 0x0.00022ebap-1022, b = 0x0.000000007382ep-1022, eb = 0x0.000000000561ep-1022;
  const Bounded q = Bounded(a) / Bounded(b, eb);
  ASSERT_TRUE(q.finite());
  EXPECT_TRUE(Encloses(q, Real(a) / (Real(b) - Real(eb))));
  EXPECT_TRUE(Encloses(q, Real(a) / (Real(b) + Real(eb))));
}

TEST(ErrorBounded, NonFiniteErrorsPropagateAndNeverGiveASign) {
  const Bounded unbounded = Bounded(1.0) / Bounded(0.0, 1.0);
  for (const Bounded r : {unbounded + Bounded(1.0), unbounded * Bounded(2.0),
                          Bounded(3.0) - unbounded, sqrt(abs(unbounded)), unbounded * Bounded(0.0)}) {
    EXPECT_FALSE(r.finite());
    EXPECT_EQ(r.sign(), 0);
  }
}

TEST(ErrorBounded, SignIsDecidedOnlyOutsideTheEnclosure) {
  EXPECT_EQ(Bounded(1.0, 0.5).sign(), 1);
  EXPECT_EQ(Bounded(-1.0, 0.5).sign(), -1);
  EXPECT_EQ(Bounded(1.0, 1.0).sign(), 0);     // true value may be 0
  EXPECT_EQ(Bounded(-1.0, 1.0).sign(), 0);
  EXPECT_EQ(Bounded(1.0, 2.0).sign(), 0);     // may be negative
  EXPECT_EQ(Bounded(0.0).sign(), 0);          // exactly zero has no sign
  EXPECT_EQ(Bounded(0.0, 1e-300).sign(), 0);
  EXPECT_EQ(Bounded(1e-300).sign(), 1);       // exact tiny values are decided
  EXPECT_EQ(Bounded(-1e-300).sign(), -1);
  // Errors of one ulp less than the value: the true value is at least one ulp above 0.
  const double v = 1.0, e = std::nextafter(1.0, 0.0);
  EXPECT_NE(Bounded(-v, e).sign(), 1);
  EXPECT_NE(Bounded(v, e).sign(), -1);
}

TEST(ErrorBounded, UnaryOperationsAndAbsEncloseTheirExactResults) {
  std::mt19937_64 rng(3);
  for (const std::vector<int>& decades : kDecadeClasses) {
    for (const Operand& x : random_operands(rng, decades, 40)) {
      EXPECT_TRUE(Encloses(-x.bounded, -x.truth));
      EXPECT_TRUE(Encloses(abs(x.bounded), abs(x.truth)));
      EXPECT_TRUE(Encloses(square(x.bounded), x.truth * x.truth));
      Bounded sum = x.bounded;
      sum += Bounded(0.5);
      EXPECT_TRUE(Encloses(sum, x.truth + Real(0.5)));
    }
  }
}

TEST(ErrorBounded, ChainedExpressionsStayEnclosed) {
  // ((a b - c)(a + c) / (b^2 + 1)) and sqrt(a^2 + b^2 + c^2): rounding errors accumulate through
  // every bound, with operands whose true values sit anywhere in their enclosures.
  std::mt19937_64 rng(5);
  for (const std::vector<int>& decades : {std::vector<int>{-2, 0, 2}, std::vector<int>{-100, -90},
                                          std::vector<int>{60, 70}}) {
    const std::vector<Operand> ops = random_operands(rng, decades, 30);
    for (std::size_t i = 0; i + 2 < ops.size(); ++i) {
      const Operand &a = ops[i], &b = ops[i + 1], &c = ops[i + 2];
      const Bounded r = (a.bounded * b.bounded - c.bounded) * (a.bounded + c.bounded) /
                        (b.bounded * b.bounded + Bounded(1.0));
      const Real truth = (a.truth * b.truth - c.truth) * (a.truth + c.truth) /
                         (b.truth * b.truth + 1);
      ASSERT_TRUE(Encloses(r, truth));
      ASSERT_TRUE(SignIsNeverWrong(r, truth));
      const Bounded n = sqrt(a.bounded * a.bounded + b.bounded * b.bounded + c.bounded * c.bounded);
      ASSERT_TRUE(Encloses(n, boost::multiprecision::sqrt(a.truth * a.truth + b.truth * b.truth +
                                                          c.truth * c.truth)));
    }
  }
}

TEST(ErrorBounded, VectorAlgebraEnclosesExactDotAndCrossProducts) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  std::uniform_real_distribution<double> relative(0.0, 1e-12);
  for (int trial = 0; trial < 300; ++trial) {
    double va[3], vb[3], ea[3], eb[3];
    Real ta[3], tb[3];
    std::uniform_real_distribution<double> t(-1.0, 1.0);
    for (int i = 0; i < 3; ++i) {
      va[i] = coordinate(rng) * (trial % 3 == 0 ? 1e-150 : 1.0);
      vb[i] = coordinate(rng) * (trial % 3 == 1 ? 1e100 : 1.0);
      ea[i] = std::fabs(va[i]) * relative(rng);
      eb[i] = std::fabs(vb[i]) * relative(rng);
      ta[i] = Real(va[i]) + Real(t(rng)) * Real(ea[i]);
      tb[i] = Real(vb[i]) + Real(t(rng)) * Real(eb[i]);
    }
    // Nearly parallel vectors make the cross product cancel.
    if (trial % 5 == 0) {
      for (int i = 0; i < 3; ++i) {
        vb[i] = va[i] * 3.0;
        eb[i] = 0.0;
        tb[i] = Real(vb[i]);
      }
    }
    const BoundedVector3 a{{va[0], ea[0]}, {va[1], ea[1]}, {va[2], ea[2]}};
    const BoundedVector3 b{{vb[0], eb[0]}, {vb[1], eb[1]}, {vb[2], eb[2]}};
    ASSERT_TRUE(Encloses(dot(a, b), ta[0] * tb[0] + ta[1] * tb[1] + ta[2] * tb[2]));
    ASSERT_TRUE(Encloses(squared_norm(a), ta[0] * ta[0] + ta[1] * ta[1] + ta[2] * ta[2]));
    const BoundedVector3 c = cross(a, b);
    ASSERT_TRUE(Encloses(c.x, ta[1] * tb[2] - ta[2] * tb[1]));
    ASSERT_TRUE(Encloses(c.y, ta[2] * tb[0] - ta[0] * tb[2]));
    ASSERT_TRUE(Encloses(c.z, ta[0] * tb[1] - ta[1] * tb[0]));
    const BoundedVector3 diff = a - b;
    ASSERT_TRUE(Encloses(diff.y, ta[1] - tb[1]));
  }
}

TEST(ErrorBounded, SinCosOfADoubleAngleEnclosesTheExactValues) {
  std::vector<double> angles = {0.0, 1e-300, -1e-20, 1.0, 3.141592653589793, 1.5707963267948966,
                                6.283185307179586, 4.71238898038469, -2.0, 1e6, 1e22, 1e300,
                                -1e300, 0x1p-1074};
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  for (int i = 0; i < 300; ++i) angles.push_back(angle(rng));
  // The doubles nearest to multiples of pi/2, where sin or cos is tiny.
  for (int k = 1; k < 40; ++k) angles.push_back(k * 1.5707963267948966);
  for (const double a : angles) {
    const BoundedSinCos t = sincos_of(a);
    EXPECT_TRUE(Encloses(t.sin, boost::multiprecision::sin(Real(a)))) << a;
    EXPECT_TRUE(Encloses(t.cos, boost::multiprecision::cos(Real(a)))) << a;
  }
}

/// exactly_equal_products must never claim equal products that differ; inside its range it must
/// also recognise every equal pair (256-bit MPFR holds a product of two doubles exactly).
::testing::AssertionResult DecidesProductEqualityCorrectly(double a, double b, double c, double d) {
  const bool claimed = exactly_equal_products(a, b, c, d);
  const bool equal = Real(a) * Real(b) == Real(c) * Real(d);
  const bool decidable = in_two_product_range(a) && in_two_product_range(b) &&
                         in_two_product_range(c) && in_two_product_range(d);
  if (claimed && !equal) {
    return ::testing::AssertionFailure() << "claimed equal: " << std::hexfloat << a << " * " << b
                                         << " and " << c << " * " << d;
  }
  if (!claimed && equal && decidable) {
    return ::testing::AssertionFailure() << "missed equal products in range: " << std::hexfloat
                                         << a << " * " << b << " and " << c << " * " << d;
  }
  return ::testing::AssertionSuccess();
}

TEST(ExactlyEqualProducts, RecognisesEqualProductsAndRejectsProductsDifferingBelowRounding) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int i = 0; i < 2000; ++i) {
    const double a = std::ldexp(mantissa(rng), exponent(rng));
    const double b = std::ldexp(mantissa(rng), exponent(rng));
    // Equal: a power of two moved between the factors.
    ASSERT_TRUE(DecidesProductEqualityCorrectly(a, b, 2 * a, 0.5 * b));
    ASSERT_TRUE(exactly_equal_products(a, b, 2 * a, 0.5 * b));
    // Different by one ulp of a factor: the rounded products are often equal, the real ones
    // never are (the low parts of the two-products differ).
    const double a_next = std::nextafter(a, 2 * a);
    ASSERT_TRUE(DecidesProductEqualityCorrectly(a, b, a_next, b));
    ASSERT_FALSE(exactly_equal_products(a, b, a_next, b));
    ASSERT_TRUE(DecidesProductEqualityCorrectly(a, b, -a, -b));
    ASSERT_TRUE(DecidesProductEqualityCorrectly(a, -b, -a, b));
  }
}

TEST(ExactlyEqualProducts, ProductsWithAZeroFactorAreEqualAtAnyMagnitude) {
  // The cross products of exactly parallel axis-aligned normals: every component is 0 * x - 0 * y.
  for (const double x : {1.0, -0.0, 0x1p-1074, 1e-300, 1e300, 0x1p1000, -3.5}) {
    EXPECT_TRUE(exactly_equal_products(0.0, x, -0.0, 1.0)) << x;
    EXPECT_TRUE(exactly_equal_products(x, 0.0, 0.0, x)) << x;
    EXPECT_TRUE(DecidesProductEqualityCorrectly(x, 0.0, 0.0, x)) << x;
  }
  // A product that underflows to zero is not zero: not proved equal to one with a zero factor.
  EXPECT_FALSE(exactly_equal_products(1e-200, 1e-200, 0.0, 1.0));
  EXPECT_TRUE(DecidesProductEqualityCorrectly(1e-200, 1e-200, 0.0, 1.0));
}

TEST(ExactlyEqualProducts, OutOfRangeOrNonFiniteFactorsAreNeverClaimedEqual) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(exactly_equal_products(nan, 1.0, nan, 1.0));
  EXPECT_FALSE(exactly_equal_products(inf, 1.0, inf, 1.0));
  // Both products overflow to the same infinity; their real values differ.
  EXPECT_FALSE(exactly_equal_products(1e300, 1e300, 1e300, 2e300));
  EXPECT_TRUE(DecidesProductEqualityCorrectly(1e300, 1e300, 1e300, 2e300));
  // Equal real products outside the split's range: "not proved equal" is the allowed answer.
  EXPECT_TRUE(DecidesProductEqualityCorrectly(0x1p-460, 0x1p10, 0x1p-450, 1.0));
}

}  // namespace
}  // namespace clearjoint::geometry::detail
