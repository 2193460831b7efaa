// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Local expansions of an integer polynomial about a dyadic point (a Taylor shift, exact) for the
// real-root isolation (real_root_isolation.cpp): their double filter decides signs near a root
// that the polynomial's own coefficients cannot.

#include <gmpxx.h>

#include <cmath>
#include <vector>

#include "arithmetic/error_bounded.hpp"
#include "exact/dyadic_number.hpp"
#include "exact/integer_polynomial.hpp"

namespace clearjoint::geometry::detail {

/// Resolution of LocalExpansion::approximate_root_pair's guesses, in bits of the searched width.
constexpr int kPairGuessBits = 60;

/// f about a dyadic centre c = m 2^-k (k >= 0): the integer polynomial G(s) = 2^(k d) f((m + s) / 2^k),
/// whose sign at s = (x - c) 2^k is f's at x. Its coefficients are those of f's Taylor expansion at
/// c (times powers of two), so the double filter's rounding is relative to |f(c)| and its first
/// derivatives there, not to the sum of |f_i x^i|: near a root, where bisection evaluates, Horner
/// at the point itself cancels to nothing, while the expansion decides down to |x - root| of about
/// 2^-52 |c - root|. Decisions are exact either way (the exact sum decides where the filter cannot);
/// the expansion only spares that sum.
class LocalExpansion {
 public:
  LocalExpansion(const IntegerPolynomial& f, const Dyadic& centre) {
    // c = m 2^-k with an integer m.
    shift_ = centre.exponent < 0 ? static_cast<mp_bitcnt_t>(-centre.exponent) : 0;
    mpz_mul_2exp(m_.mantissa.get_mpz_t(), centre.mantissa.get_mpz_t(),
                 centre.exponent > 0 ? static_cast<mp_bitcnt_t>(centre.exponent) : 0);
    m_.exponent = 0;
    const int d = f.degree();
    g_.c.resize(f.c.size());
    for (int i = 0; i <= d; ++i) {
      mpz_mul_2exp(g_.c[static_cast<std::size_t>(i)].get_mpz_t(), f.c[static_cast<std::size_t>(i)].get_mpz_t(),
                   shift_ * static_cast<mp_bitcnt_t>(d - i));
    }
    // Taylor shift by m: H(s) -> H(s + m), Horner's scheme repeated (d (d + 1) / 2 steps).
    for (int i = 0; i < d; ++i) {
      for (int j = d - 1; j >= i; --j) {
        mpz_addmul(g_.c[static_cast<std::size_t>(j)].get_mpz_t(), m_.mantissa.get_mpz_t(),
                   g_.c[static_cast<std::size_t>(j + 1)].get_mpz_t());
      }
    }
    g_.prepare_filter();
  }
  /// (x - c) 2^k: the argument of G for the point x, as a Bounded.
  Bounded offset(const Dyadic& x) const {
    Dyadic scaled = x;
    scaled.exponent += static_cast<long>(shift_);
    return bounded(scaled - m_);
  }
  /// A length times 2^k, in G's units.
  Bounded length(Dyadic x) const {
    x.exponent += static_cast<long>(shift_);
    return bounded(x);
  }
  /// f's sign at the point whose offset is s, or 0 where the double filter cannot decide it.
  int filtered_sign_at_offset(const Bounded& s) const { return filtered_sign(g_, s); }
  int filtered_sign_at(const Dyadic& x) const { return filtered_sign(g_, offset(x)); }
  /// Where G's rounded coefficients, evaluated in plain doubles, change sign between the offsets
  /// low and high (G of sign `sign_high` towards high): bisection to adjacent doubles. A guess,
  /// which the caller proves or discards.
  double approximate_sign_change(double low, double high, int sign_high) const {
    for (int step = 0; step < 2200; ++step) {
      const double middle = 0.5 * (low + high);
      if (!(middle > low && middle < high)) break;
      double value = g_.scaled.back().value;
      for (int i = g_.degree() - 1; i >= 0; --i) value = value * middle + g_.scaled[static_cast<std::size_t>(i)].value;
      if (value == 0.0) return middle;
      ((value > 0.0 ? 1 : -1) == sign_high ? high : low) = middle;
    }
    return high;
  }
  /// Where G's rounded coefficients, in plain doubles, put two roots between the offsets low and
  /// high: G' changes sign between them, then G on each side of that extremum (bisections). A
  /// guess, which the caller proves or discards; false where the doubles show no such pair.
  bool approximate_root_pair(double low, double high, double& first, double& second) const {
    const auto value_at = [&](double s) {
      double value = g_.scaled.back().value;
      for (int i = g_.degree() - 1; i >= 0; --i) value = value * s + g_.scaled[static_cast<std::size_t>(i)].value;
      return value;
    };
    const auto slope_at = [&](double s) {
      double slope = g_.degree() * g_.scaled.back().value;
      for (int i = g_.degree() - 1; i >= 1; --i) slope = slope * s + i * g_.scaled[static_cast<std::size_t>(i)].value;
      return slope;
    };
    // Bisection of (a, b] on the sign of h towards b, down to 2^-kPairGuessBits of the whole
    // width: the guesses' positions only matter to that resolution.
    const double resolution = std::ldexp(high - low, -kPairGuessBits);
    const auto sign_change = [&](const auto& h, double a, double b) {
      const bool positive_at_b = h(b) > 0.0;
      while (b - a > resolution) {
        const double middle = 0.5 * (a + b);
        if (!(middle > a && middle < b)) break;
        ((h(middle) > 0.0) == positive_at_b ? b : a) = middle;
      }
      return b;
    };
    if (!(slope_at(low) * slope_at(high) < 0.0)) return false;
    const double extremum = sign_change(slope_at, low, high), at_extremum = value_at(extremum);
    if (!(at_extremum != 0.0 && std::isfinite(at_extremum))) return false;
    if (!(value_at(low) * at_extremum < 0.0 && value_at(high) * at_extremum < 0.0)) return false;
    first = sign_change(value_at, low, extremum);
    second = sign_change(value_at, extremum, high);
    return true;
  }

 private:
  Dyadic m_;
  mp_bitcnt_t shift_ = 0;
  IntegerPolynomial g_;
};

}  // namespace clearjoint::geometry::detail
