// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Ball arithmetic in MPFR (a midpoint and a radius) for the Sturm chain's last members
// (sturm_chain.cpp), where they are small next to their terms beyond a double's precision.

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <cstddef>
#include <limits>

#include "arithmetic/error_bounded.hpp"

namespace clearjoint::geometry::detail {

/// Working precision of the chain's multiprecision filters (below), in bits: near a pair of close
/// roots the last members are small next to their terms by about the roots' squared distance
/// (2^-80 and less for the rims' tangencies), far beyond a double's precision.
constexpr mpfr_prec_t kChainFilterBits = 256;
/// Precision of the balls' radii: upper bounds only, rounded upwards.
constexpr mpfr_prec_t kRadiusBits = 64;

/// Limbs of an MPFR significand of this precision (mpfr_custom_get_size, in limbs).
constexpr std::size_t limbs(mpfr_prec_t bits) { return static_cast<std::size_t>((bits + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS); }

/// A real number enclosed as mid +- rad (ball arithmetic, as in Arb or MPFI's midpoint form):
/// mid rounded to nearest at kChainFilterBits bits, rad an upper bound on the distance to the true
/// value, every operation on it rounded upwards. A rounding to nearest at p bits moves a result by
/// at most 2^-p of its rounded magnitude, which each operation adds to rad. Where MPFR's exponent
/// range is exceeded, rad or mid become infinite or NaN and no sign is decided.
class Ball {
 public:
  Ball() {
    // MPFR's custom interface: the significands live in the ball (no allocation per number).
    mpfr_custom_init(mid_limbs_, kChainFilterBits);
    mpfr_custom_init_set(mid_, MPFR_ZERO_KIND, 0, kChainFilterBits, mid_limbs_);
    mpfr_custom_init(rad_limbs_, kRadiusBits);
    mpfr_custom_init_set(rad_, MPFR_ZERO_KIND, 0, kRadiusBits, rad_limbs_);
    mpfr_custom_init(scratch_limbs_, kRadiusBits);
    mpfr_custom_init_set(scratch_, MPFR_ZERO_KIND, 0, kRadiusBits, scratch_limbs_);
  }
  explicit Ball(const mpz_class& x) : Ball() {
    mpfr_set_z(mid_, x.get_mpz_t(), MPFR_RNDN);
    add_rounding();
  }
  Ball(const Ball&) = delete;  // the numbers point into the ball's own storage
  Ball& operator=(const Ball&) = delete;
  /// A copy of x (exact: the same precisions).
  void assign(const Ball& x) {
    mpfr_set(mid_, x.mid_, MPFR_RNDN);
    mpfr_set(rad_, x.rad_, MPFR_RNDU);
  }
  /// x + sign y (sign +-1).
  static void add(Ball& out, const Ball& x, const Ball& y, int sign) {
    (sign > 0 ? mpfr_add : mpfr_sub)(out.mid_, x.mid_, y.mid_, MPFR_RNDN);
    mpfr_add(out.rad_, x.rad_, y.rad_, MPFR_RNDU);
    out.add_rounding();
  }
  /// x y: |x y - X Y| <= |x| rad(Y) + |y| rad(X) + rad(X) rad(Y) before the product's rounding.
  static void multiply(Ball& out, const Ball& x, const Ball& y) {
    mpfr_ptr part = out.scratch_;
    mpfr_mul(out.rad_, x.rad_, y.rad_, MPFR_RNDU);
    mpfr_abs(part, x.mid_, MPFR_RNDU);
    mpfr_mul(part, part, y.rad_, MPFR_RNDU);
    mpfr_add(out.rad_, out.rad_, part, MPFR_RNDU);
    mpfr_abs(part, y.mid_, MPFR_RNDU);
    mpfr_mul(part, part, x.rad_, MPFR_RNDU);
    mpfr_add(out.rad_, out.rad_, part, MPFR_RNDU);
    mpfr_mul(out.mid_, x.mid_, y.mid_, MPFR_RNDN);
    out.add_rounding();
  }
  /// The true value's sign where the ball excludes 0, else 0.
  int sign() const { return mpfr_number_p(rad_) && mpfr_cmpabs(mid_, rad_) > 0 ? mpfr_sgn(mid_) : 0; }
  /// The true value times 2^-shift, negated when `negate`, as a Bounded (error_bounded.hpp).
  Bounded scaled_bounded(long shift, bool negate) const {
    mpfr_t scaled;
    mpfr_init2(scaled, kChainFilterBits);
    mpfr_mul_2si(scaled, mid_, -shift, MPFR_RNDN);  // exact: a power of two
    const double value = mpfr_get_d(scaled, MPFR_RNDN);
    mpfr_set_prec(scaled, kRadiusBits);
    mpfr_mul_2si(scaled, rad_, -shift, MPFR_RNDU);
    const double radius = mpfr_get_d(scaled, MPFR_RNDU);
    mpfr_clear(scaled);
    // Rounding mid to a double: 2^-53 of its magnitude, or an underflow.
    return {negate ? -value : value, (std::fabs(value) * 0x1p-52 + radius) * kErrorInflation + kUnderflowError};
  }
  long exponent() const { return mpfr_regular_p(mid_) ? mpfr_get_exp(mid_) : std::numeric_limits<long>::min(); }

 private:
  void add_rounding() {
    mpfr_abs(scratch_, mid_, MPFR_RNDU);
    mpfr_mul_2si(scratch_, scratch_, -static_cast<long>(kChainFilterBits), MPFR_RNDU);
    mpfr_add(rad_, rad_, scratch_, MPFR_RNDU);
  }
  mp_limb_t mid_limbs_[limbs(kChainFilterBits)];
  mp_limb_t rad_limbs_[limbs(kRadiusBits)];
  mp_limb_t scratch_limbs_[limbs(kRadiusBits)];
  mpfr_t mid_, rad_;
  mpfr_t scratch_;  ///< a radius-precision temporary of the operations writing this ball
};

}  // namespace clearjoint::geometry::detail
