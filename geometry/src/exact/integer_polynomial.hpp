// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Polynomials with integer coefficients for the real-root isolation (real_root_isolation.hpp):
// the arithmetic of the square-free factorisation and of Sturm chains (pseudo-remainders, exact
// quotients, gcds) in Z[x], and signs at dyadic and rational points, each tried first by a double
// filter with a running error bound (error_bounded.hpp) and computed exactly only when that
// cannot decide.

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "arithmetic/error_bounded.hpp"
#include "exact/dyadic_number.hpp"
#include "exact/exact_numbers.hpp"

namespace clearjoint::geometry::detail {

/// What a Sturm chain member known by its filter only is made from (sturm_chain.cpp).
struct PendingRemainder;

/// Integer coefficients, constant term first, the last one nonzero (none: the zero polynomial),
/// and the same coefficients as doubles scaled by one power of two, with rounding bounds, for
/// the double filter of sign evaluations.
class IntegerPolynomial {
 public:
  SmallVector<mpz_class> c;
  SmallVector<Bounded> scaled;
  /// Set on a Sturm chain member whose filter (`scaled`) was formed from multiprecision
  /// enclosures (sturm_chain): `c` then holds only the right number of placeholders, and
  /// exact_form() computes the exact coefficients at the first exact sign that needs them.
  std::shared_ptr<PendingRemainder> pending;
  /// (Defined with the Sturm chain, sturm_chain.cpp.)
  const IntegerPolynomial& exact_form() const;

  int degree() const { return static_cast<int>(c.size()) - 1; }
  bool is_zero() const { return c.empty(); }
  const mpz_class& leading() const { return c.back(); }
  void trim() {
    while (!c.empty() && sgn(c.back()) == 0) c.pop_back();
  }
  /// Fills `scaled`: c[i] 2^-shift, shift the largest binary exponent of a coefficient (the
  /// common positive scale leaves every sign as it is). mpz_get_d_2exp truncates to 53 bits (a
  /// relative error below 2^-52); a coefficient far below the largest may round into the
  /// subnormals or to zero (an absolute error below 2^-1074).
  void prepare_filter() {
    scaled.assign(c.size(), Bounded(0.0));
    long largest = std::numeric_limits<long>::min();
    SmallVector<std::pair<double, long>> parts(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (sgn(c[i]) == 0) continue;
      long exponent = 0;
      const double mantissa = mpz_get_d_2exp(&exponent, c[i].get_mpz_t());
      parts[i] = {mantissa, exponent};
      largest = std::max(largest, exponent);
    }
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (sgn(c[i]) == 0) continue;
      const long shift = std::max(parts[i].second - largest, -2000L);
      const double value = std::ldexp(parts[i].first, static_cast<int>(shift));
      // Truncation (2^-52 relative) and the rounding into the subnormals (2^-1075), with room.
      scaled[i] = Bounded(value, std::fabs(value) * 0x1p-51 + kUnderflowError);
    }
  }
};

/// p'.
IntegerPolynomial derivative(const IntegerPolynomial& p);

/// Divides by the (positive) gcd of the coefficients and makes the leading coefficient positive
/// when `positive_leading`; a constant becomes +-1 (only its sign is ever read).
void make_primitive(IntegerPolynomial& p, bool positive_leading);

/// lc(b)^(deg a - deg b + 1) a = q b + r with deg r < deg b: returns r and the sign of the
/// factor lc(b)^(...). deg a >= deg b >= 0.
std::pair<IntegerPolynomial, int> pseudo_remainder(const IntegerPolynomial& a, const IntegerPolynomial& b);

/// a / b when b divides a in Q[x] and b is primitive: the quotient then has integer
/// coefficients (Gauss's lemma), and long division stays in the integers.
IntegerPolynomial exact_quotient(const IntegerPolynomial& a, const IntegerPolynomial& b);

/// gcd in Z[x], primitive with a positive leading coefficient (primitive remainder sequence).
IntegerPolynomial polynomial_gcd(IntegerPolynomial a, IntegerPolynomial b);

/// a - b.
IntegerPolynomial difference(const IntegerPolynomial& a, const IntegerPolynomial& b);

/// A nonzero multiple of f with integer coefficients, primitive, its leading coefficient positive.
IntegerPolynomial integer_multiple(const RationalPolynomial& f);

/// The double filter's sign of p at x (0: not decided), from Horner in Bounded arithmetic. A
/// point or a power of it out of the double range gives a non-finite bound, which decides
/// nothing.
inline int filtered_sign(const IntegerPolynomial& p, const Bounded& x) {
  Bounded value = p.scaled.back();
  for (int i = p.degree() - 1; i >= 0; --i) value = value * x + p.scaled[static_cast<std::size_t>(i)];
  return value.sign();
}

/// Exact sign of p at x = m 2^e: that of sum c_i m^i 2^(e i), or with k = -e > 0 of the integer
/// sum c_i m^i 2^(k (d - i)) (the former times 2^(k d)).
int exact_sign(const IntegerPolynomial& p, const Dyadic& x);

/// Exact sign of p at the rational x = n / q (q > 0): that of sum c_i n^i q^(d - i).
int exact_sign(const IntegerPolynomial& p, const Rational& x);

/// The sign of p at x (a Dyadic or a Rational): the double filter's at `approximate` (x as a
/// Bounded), else the exact one.
template <class Point>
int sign_at(const IntegerPolynomial& p, const Point& x, const Bounded& approximate) {
  if (p.is_zero()) return 0;
  if (p.degree() == 0) return sgn(p.c[0]);
  const int filtered = filtered_sign(p, approximate);
  return filtered != 0 ? filtered : exact_sign(p.exact_form(), x);
}

/// x as a Bounded: the middle of CGAL's interval of x, its half-width as the error.
Bounded bounded(const Rational& x);

}  // namespace clearjoint::geometry::detail
