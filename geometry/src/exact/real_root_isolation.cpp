// SPDX-License-Identifier: BSD-3-Clause
#include "real_root_isolation.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "error_bounded.hpp"
#include "exact_dyadic.hpp"

namespace clearjoint::geometry::detail {

/// Integer coefficients, constant term first, the last one nonzero (none: the zero polynomial),
/// and the same coefficients as doubles scaled by one power of two, with rounding bounds, for
/// the double filter of sign evaluations.
struct PendingRemainder;

class IntegerPolynomial {
 public:
  std::vector<mpz_class> c;
  std::vector<Bounded> scaled;
  /// Set on a Sturm chain member whose filter (`scaled`) was formed from multiprecision
  /// enclosures (sturm_chain): `c` then holds only the right number of placeholders, and
  /// exact_form() computes the exact coefficients at the first exact sign that needs them.
  std::shared_ptr<PendingRemainder> pending;
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
    std::vector<std::pair<double, long>> parts(c.size());
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

namespace {

using Integer = mpz_class;

IntegerPolynomial derivative(const IntegerPolynomial& p) {
  IntegerPolynomial d;
  for (int i = 1; i <= p.degree(); ++i) d.c.push_back(p.c[static_cast<std::size_t>(i)] * i);
  d.trim();
  return d;
}

/// Divides by the (positive) gcd of the coefficients and makes the leading coefficient positive
/// when `positive_leading`; a constant becomes +-1 (only its sign is ever read).
void make_primitive(IntegerPolynomial& p, bool positive_leading) {
  if (p.is_zero()) return;
  if (p.degree() == 0) {
    p.c[0] = sgn(p.c[0]);
    return;
  }
  Integer content = abs(p.c[0]);
  for (std::size_t i = 1; i < p.c.size() && content != 1; ++i) mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), p.c[i].get_mpz_t());
  if (positive_leading && sgn(p.leading()) < 0) content = -content;
  if (content != 1) {
    for (Integer& x : p.c) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), content.get_mpz_t());
  }
}

/// lc(b)^(deg a - deg b + 1) a = q b + r with deg r < deg b: returns r and the sign of the
/// factor lc(b)^(...). deg a >= deg b >= 0.
std::pair<IntegerPolynomial, int> pseudo_remainder(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial r = a;
  const int m = a.degree(), n = b.degree();
  const Integer& lead = b.leading();
  Integer top;
  for (int k = m - n; k >= 0; --k) {
    // r = lead r - top x^k b, whose x^(n + k) term cancels: it is set, not computed.
    std::swap(top, r.c[static_cast<std::size_t>(n + k)]);
    r.c[static_cast<std::size_t>(n + k)] = 0;
    for (int i = 0; i < n + k; ++i) r.c[static_cast<std::size_t>(i)] *= lead;
    for (int j = 0; j < n; ++j) {
      mpz_submul(r.c[static_cast<std::size_t>(j + k)].get_mpz_t(), top.get_mpz_t(), b.c[static_cast<std::size_t>(j)].get_mpz_t());
    }
  }
  r.c.resize(static_cast<std::size_t>(n));
  r.trim();
  const int steps = m - n + 1;
  return {std::move(r), sgn(lead) < 0 && steps % 2 == 1 ? -1 : 1};
}

/// a / b when b divides a in Q[x] and b is primitive: the quotient then has integer
/// coefficients (Gauss's lemma), and long division stays in the integers.
IntegerPolynomial exact_quotient(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial r = a, q;
  const int m = a.degree(), n = b.degree();
  q.c.assign(static_cast<std::size_t>(m - n + 1), Integer(0));
  for (int k = m - n; k >= 0; --k) {
    Integer& top = q.c[static_cast<std::size_t>(k)];
    mpz_divexact(top.get_mpz_t(), r.c[static_cast<std::size_t>(n + k)].get_mpz_t(), b.leading().get_mpz_t());
    for (int j = 0; j <= n; ++j) r.c[static_cast<std::size_t>(j + k)] -= top * b.c[static_cast<std::size_t>(j)];
  }
  q.trim();
  return q;
}

/// gcd in Z[x], primitive with a positive leading coefficient (primitive remainder sequence).
IntegerPolynomial polynomial_gcd(IntegerPolynomial a, IntegerPolynomial b) {
  if (a.degree() < b.degree()) std::swap(a, b);
  make_primitive(a, true);
  make_primitive(b, true);
  while (!b.is_zero()) {
    IntegerPolynomial r = pseudo_remainder(a, b).first;
    make_primitive(r, true);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

IntegerPolynomial difference(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial d;
  d.c.assign(std::max(a.c.size(), b.c.size()), Integer(0));
  for (std::size_t i = 0; i < a.c.size(); ++i) d.c[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) d.c[i] -= b.c[i];
  d.trim();
  return d;
}

/// A nonzero multiple of f with integer coefficients, primitive, its leading coefficient positive.
IntegerPolynomial integer_multiple(const RationalPolynomial& f) {
  IntegerPolynomial p;
  if (f.is_zero()) return p;
  Integer common = 1;
  for (int i = 0; i <= f.degree(); ++i) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), mpq_denref(f[i].mpq()));
  p.c.resize(static_cast<std::size_t>(f.degree() + 1));
  Integer factor;
  for (int i = 0; i <= f.degree(); ++i) {
    mpz_divexact(factor.get_mpz_t(), common.get_mpz_t(), mpq_denref(f[i].mpq()));
    mpz_mul(p.c[static_cast<std::size_t>(i)].get_mpz_t(), factor.get_mpz_t(), mpq_numref(f[i].mpq()));
  }
  p.trim();
  make_primitive(p, true);
  return p;
}

// ---- Dyadic points ------------------------------------------------------------------------

/// mantissa 2^exponent, the mantissa odd (or zero, with exponent 0): every point the isolation
/// visits is one (the bound, midpoints, doubles), and sums and halvings of them need no gcd.
struct Dyadic {
  Integer mantissa;
  long exponent = 0;

  void normalise() {
    if (sgn(mantissa) == 0) {
      exponent = 0;
      return;
    }
    const mp_bitcnt_t zeros = mpz_scan1(mantissa.get_mpz_t(), 0);
    if (zeros > 0) {
      mpz_tdiv_q_2exp(mantissa.get_mpz_t(), mantissa.get_mpz_t(), zeros);
      exponent += static_cast<long>(zeros);
    }
  }
  static Dyadic of_double(double x) {
    // Exact: a finite double is an integer of at most 53 bits times a power of two.
    int binary_exponent = 0;
    const double fraction = std::frexp(x, &binary_exponent);
    Dyadic d;
    mpz_set_d(d.mantissa.get_mpz_t(), std::ldexp(fraction, 53));
    d.exponent = binary_exponent - 53;
    d.normalise();
    return d;
  }
  static Dyadic of_rational(const Rational& x) {
    const mpz_srcptr denominator = mpq_denref(x.mpq());
    const mp_bitcnt_t power = mpz_scan1(denominator, 0);
    if (mpz_sizeinbase(denominator, 2) != power + 1) throw std::invalid_argument("isolate_real_roots: bound must be dyadic (a power of two)");
    Dyadic d;
    d.mantissa = Integer(mpq_numref(x.mpq()));
    d.exponent = -static_cast<long>(power);
    d.normalise();
    return d;
  }
  Rational to_rational() const {
    Rational r;
    mpq_set_z(r.mpq(), mantissa.get_mpz_t());
    if (exponent > 0) mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(exponent));
    if (exponent < 0) mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-exponent));
    return r;
  }
  /// CGAL::to_double of the same rational (mpq_get_d: truncation).
  double to_double() const { return CGAL::to_double(to_rational()); }
};

/// a and b with their mantissas brought to the smaller exponent.
std::pair<Integer, Integer> aligned(const Dyadic& a, const Dyadic& b, long& exponent) {
  exponent = std::min(a.exponent, b.exponent);
  Integer x, y;
  mpz_mul_2exp(x.get_mpz_t(), a.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(a.exponent - exponent));
  mpz_mul_2exp(y.get_mpz_t(), b.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(b.exponent - exponent));
  return {std::move(x), std::move(y)};
}
int compare(const Dyadic& a, const Dyadic& b) {
  // Different signs, or magnitudes in different binades, decide without aligning.
  const int sa = sgn(a.mantissa), sb = sgn(b.mantissa);
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  const long la = static_cast<long>(mpz_sizeinbase(a.mantissa.get_mpz_t(), 2)) + a.exponent;
  const long lb = static_cast<long>(mpz_sizeinbase(b.mantissa.get_mpz_t(), 2)) + b.exponent;
  if (la != lb) return (la < lb) == (sa > 0) ? -1 : 1;
  long exponent = 0;
  const auto [x, y] = aligned(a, b, exponent);
  return cmp(x, y);
}
bool operator<=(const Dyadic& a, const Dyadic& b) { return compare(a, b) <= 0; }
bool operator>(const Dyadic& a, const Dyadic& b) { return compare(a, b) > 0; }
Dyadic midpoint(const Dyadic& a, const Dyadic& b) {
  Dyadic m;
  const auto [x, y] = aligned(a, b, m.exponent);
  m.mantissa = x + y;
  m.exponent -= 1;
  m.normalise();
  return m;
}
Dyadic operator-(const Dyadic& a, const Dyadic& b) {
  Dyadic d;
  const auto [x, y] = aligned(a, b, d.exponent);
  d.mantissa = x - y;
  d.normalise();
  return d;
}
Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  Dyadic d;
  const auto [x, y] = aligned(a, b, d.exponent);
  d.mantissa = x + y;
  d.normalise();
  return d;
}
Dyadic operator-(Dyadic a) {
  a.mantissa = -a.mantissa;
  return a;
}

// ---- Signs ----------------------------------------------------------------------------------

/// The double filter's sign of p at x (0: not decided), from Horner in Bounded arithmetic. A
/// point or a power of it out of the double range gives a non-finite bound, which decides
/// nothing.
int filtered_sign(const IntegerPolynomial& p, const Bounded& x) {
  Bounded value = p.scaled.back();
  for (int i = p.degree() - 1; i >= 0; --i) value = value * x + p.scaled[static_cast<std::size_t>(i)];
  return value.sign();
}

/// x as a Bounded, or {NaN, NaN} (which decides no sign) beyond the range where the conversion
/// is plainly safe.
Bounded bounded(const Dyadic& x) {
  if (sgn(x.mantissa) == 0) return Bounded(0.0);
  long binary_exponent = 0;
  const double mantissa = mpz_get_d_2exp(&binary_exponent, x.mantissa.get_mpz_t());
  const long total = binary_exponent + x.exponent;
  constexpr long kSafeExponent = 1000;
  if (total > kSafeExponent || total < -kSafeExponent) {
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  }
  const double value = std::ldexp(mantissa, static_cast<int>(total));
  // mpz_get_d_2exp truncates to 53 bits: a relative error below 2^-52.
  return {value, mpz_sizeinbase(x.mantissa.get_mpz_t(), 2) > 53 ? std::fabs(value) * 0x1p-52 : 0.0};
}

/// Exact sign of p at x = m 2^e: that of sum c_i m^i 2^(e i), or with k = -e > 0 of the integer
/// sum c_i m^i 2^(k (d - i)) (the former times 2^(k d)).
int exact_sign(const IntegerPolynomial& p, const Dyadic& x) {
  const int d = p.degree();
  Integer value = p.leading(), term;
  if (x.exponent >= 0) {
    Integer point;
    mpz_mul_2exp(point.get_mpz_t(), x.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(x.exponent));
    for (int i = d - 1; i >= 0; --i) {
      value *= point;
      value += p.c[static_cast<std::size_t>(i)];
    }
  } else {
    const auto k = static_cast<mp_bitcnt_t>(-x.exponent);
    for (int i = d - 1; i >= 0; --i) {
      value *= x.mantissa;
      mpz_mul_2exp(term.get_mpz_t(), p.c[static_cast<std::size_t>(i)].get_mpz_t(), k * static_cast<mp_bitcnt_t>(d - i));
      value += term;
    }
  }
  return sgn(value);
}

/// Exact sign of p at the rational x = n / q (q > 0): that of sum c_i n^i q^(d - i).
int exact_sign(const IntegerPolynomial& p, const Rational& x) {
  const int d = p.degree();
  const mpz_srcptr n = mpq_numref(x.mpq()), q = mpq_denref(x.mpq());
  Integer value = p.leading(), power_of_q = 1, term;
  for (int i = d - 1; i >= 0; --i) {
    mpz_mul(value.get_mpz_t(), value.get_mpz_t(), n);
    mpz_mul(power_of_q.get_mpz_t(), power_of_q.get_mpz_t(), q);
    mpz_mul(term.get_mpz_t(), p.c[static_cast<std::size_t>(i)].get_mpz_t(), power_of_q.get_mpz_t());
    value += term;
  }
  return sgn(value);
}

template <class Point>
int sign_at(const IntegerPolynomial& p, const Point& x, const Bounded& approximate) {
  if (p.is_zero()) return 0;
  if (p.degree() == 0) return sgn(p.c[0]);
  const int filtered = filtered_sign(p, approximate);
  return filtered != 0 ? filtered : exact_sign(p.exact_form(), x);
}

Bounded bounded(const Rational& x) {
  const std::pair<double, double> range = interval_of(x);
  const double middle = 0.5 * (range.first + range.second);
  return {middle, std::max(middle - range.first, range.second - middle) * kErrorInflation};
}

// ---- Sturm sequences ---------------------------------------------------------------------------

/// Working precision of the chain's multiprecision filters (below), in bits: near a pair of close
/// roots the last members are small next to their terms by about the roots' squared distance
/// (2^-80 and less for the rims' tangencies), far beyond a double's precision.
constexpr mpfr_prec_t kChainFilterBits = 256;
/// Precision of the balls' radii: upper bounds only, rounded upwards.
constexpr mpfr_prec_t kRadiusBits = 64;

/// A real number enclosed as mid +- rad (ball arithmetic, as in Arb or MPFI's midpoint form):
/// mid rounded to nearest at kChainFilterBits bits, rad an upper bound on the distance to the true
/// value, every operation on it rounded upwards. A rounding to nearest at p bits moves a result by
/// at most 2^-p of its rounded magnitude, which each operation adds to rad. Where MPFR's exponent
/// range is exceeded, rad or mid become infinite or NaN and no sign is decided.
/// Limbs of an MPFR significand of this precision (mpfr_custom_get_size, in limbs).
constexpr std::size_t limbs(mpfr_prec_t bits) { return static_cast<std::size_t>((bits + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS); }

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

/// One step of the subresultant remainder sequence (sturm_chain): -prem(a, b) / (g h^delta), or
/// its sign alone (+-1) when it is a constant, or the zero polynomial.
IntegerPolynomial subresultant_remainder(const IntegerPolynomial& a, const IntegerPolynomial& b, const Integer& divisor) {
  auto [remainder, factor_sign] = pseudo_remainder(a, b);
  if (remainder.is_zero()) return remainder;
  if (remainder.degree() == 0) {
    // The last member: only its sign is read, which the positive divisor leaves as it is.
    remainder.c[0] = factor_sign > 0 ? -sgn(remainder.c[0]) : sgn(remainder.c[0]);
    return remainder;
  }
  if (divisor != 1) {
    for (Integer& x : remainder.c) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), divisor.get_mpz_t());
  }
  if (factor_sign > 0) {
    for (Integer& x : remainder.c) x = -x;
  }
  return remainder;
}

}  // namespace

/// A chain member known by its filter only: what its exact coefficients are made from.
struct PendingRemainder {
  IntegerPolynomial a, b;
  Integer divisor;
  std::optional<IntegerPolynomial> exact;
};

const IntegerPolynomial& IntegerPolynomial::exact_form() const {
  if (!pending) return *this;
  if (!pending->exact) pending->exact = subresultant_remainder(pending->a, pending->b, pending->divisor);
  return *pending->exact;
}

namespace {

/// The chain's last two members from a cubic a (p') and a quadratic b (the member after it), by
/// ball arithmetic (Ball), or false where it cannot decide them. With pseudo-division by b
/// (b2 x^2 + b1 x + b0) written out, prem(a, b) = r1 x + r0,
///   t = a2 b2 - a3 b1,   r1 = (a1 b2 - a3 b0) b2 - t b1,   r0 = a0 b2^2 - t b0,
/// and the next member, -r / (g h), is a positive multiple of -r: the filter of its signs is
/// formed from the balls of -r, and its exact coefficients wait until an exact sign needs them
/// (IntegerPolynomial::pending). The last member is the sign of -prem(b, -r / (g h)) =
/// -(b0 r1^2 - b1 r0 r1 + b2 r0^2) / (g h)^2. Both need r1 != 0 and that sum's sign proved.
/// The exact remainders multiply numbers of thousands of bits near a tangency of the rims;
/// the balls decide there (the members are small next to their terms by about the squared
/// distance of the close roots, within the filter's precision).
bool filtered_last_members(const IntegerPolynomial& a, const IntegerPolynomial& b, const Integer& divisor,
                           std::vector<IntegerPolynomial>& chain) {
  const Ball a0(a.c[0]), a1(a.c[1]), a2(a.c[2]), a3(a.c[3]);
  const Ball b0(b.c[0]), b1(b.c[1]), b2(b.c[2]);
  Ball x, y, t, r0, r1;
  Ball::multiply(x, a2, b2);
  Ball::multiply(y, a3, b1);
  Ball::add(t, x, y, -1);
  Ball::multiply(x, a1, b2);
  Ball::multiply(y, a3, b0);
  Ball::add(r1, x, y, -1);  // a1 b2 - a3 b0
  Ball::multiply(x, r1, b2);
  Ball::multiply(y, t, b1);
  Ball::add(r1, x, y, -1);
  Ball::multiply(x, b2, b2);
  Ball::multiply(y, a0, x);
  Ball::multiply(x, t, b0);
  Ball::add(r0, y, x, -1);
  if (r1.sign() == 0) return false;
  // b0 r1^2 - b1 r0 r1 + b2 r0^2
  Ball sum, term;
  Ball::multiply(x, r1, r1);
  Ball::multiply(sum, b0, x);
  Ball::multiply(x, r0, r1);
  Ball::multiply(term, b1, x);
  Ball::add(y, sum, term, -1);
  Ball::multiply(x, r0, r0);
  Ball::multiply(term, b2, x);
  Ball::add(sum, y, term, +1);
  const int last_sign = sum.sign();
  if (last_sign == 0) return false;

  IntegerPolynomial member;
  member.c.resize(2);  // placeholders: the exact coefficients are pending
  const long shift = std::max(r0.exponent(), r1.exponent());
  member.scaled = {r0.scaled_bounded(shift, true), r1.scaled_bounded(shift, true)};
  auto pending = std::make_shared<PendingRemainder>();
  pending->a.c = a.c;
  pending->b.c = b.c;
  pending->divisor = divisor;
  member.pending = std::move(pending);
  chain.push_back(std::move(member));
  IntegerPolynomial last;
  last.c.assign(1, Integer(-last_sign));
  chain.push_back(std::move(last));
  return true;
}

/// The sign of prem(a, b) for b = b1 x + b0: lc(b)^(deg a) a(-b0 / b1) = sum a_i (-b0)^i b1^(m - i)
/// (m = deg a), by ball arithmetic (Ball), or 0 where that cannot decide it: the chain's last
/// member where filtered_last_members did not form it.
int filtered_linear_remainder_sign(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  const int m = a.degree();
  const Ball minus_b0(-b.c[0]), b1(b.c[1]);
  Ball sum(a.c[static_cast<std::size_t>(m)]), power, term, next;
  power.assign(b1);
  // Horner in the homogeneous form: sum <- sum (-b0) + a_i b1^(m - i), the power built up.
  for (int i = m - 1; i >= 0; --i) {
    const Ball coefficient(a.c[static_cast<std::size_t>(i)]);
    Ball::multiply(term, coefficient, power);
    Ball::multiply(next, sum, minus_b0);
    Ball::add(sum, next, term, +1);
    if (i > 0) {
      Ball::multiply(next, power, b1);
      power.assign(next);
    }
  }
  return sum.sign();
}

/// p, p', then -rem of the last two (times positive factors, which leave every sign as it is),
/// until a constant or a zero remainder (the last member is then a multiple of gcd(p, p')).
/// The positive factors are those of the subresultant remainder sequence (Cohen, "A Course in
/// Computational Algebraic Number Theory", algorithm 3.3.1): each pseudo-remainder is divided
/// exactly by |g h^delta|, which keeps the coefficients' growth linear in the degree without the
/// gcds a primitive sequence takes (a member's sign pattern only matters, and the subresultant
/// members differ from the Euclidean remainders by nonzero constants; their magnitudes do not
/// depend on the signs the Sturm sequence gives the members). Where the members have more bits
/// than the filters' precision, the last members come from ball arithmetic when it decides them
/// (filtered_last_members, filtered_linear_remainder_sign); with fewer the exact remainders cost
/// less than the balls.
std::vector<IntegerPolynomial> sturm_chain(const IntegerPolynomial& p) {
  std::vector<IntegerPolynomial> chain{p, derivative(p)};
  Integer g = 1, h = 1, divisor, power;
  while (!chain.back().is_zero() && chain.back().degree() > 0) {
    const IntegerPolynomial& a = chain[chain.size() - 2];
    const IntegerPolynomial& b = chain.back();
    const auto delta = static_cast<unsigned long>(a.degree() - b.degree());
    mpz_pow_ui(power.get_mpz_t(), h.get_mpz_t(), delta);
    divisor = g * power;
    const bool large = mpz_sizeinbase(b.leading().get_mpz_t(), 2) > kChainFilterBits;
    if (large && a.degree() == 3 && b.degree() == 2 && filtered_last_members(a, b, divisor, chain)) break;
    if (large && b.degree() == 1) {
      if (const int sign = filtered_linear_remainder_sign(a, b); sign != 0) {
        // -prem(a, b) times a positive factor: lc(b)^(deg a) is negative only for an odd deg a.
        const bool factor_positive = !(sgn(b.leading()) < 0 && (a.degree() % 2 == 1));
        IntegerPolynomial last;
        last.c.assign(1, Integer(factor_positive ? -sign : sign));
        chain.push_back(std::move(last));
        break;
      }
    }
    IntegerPolynomial remainder = subresultant_remainder(a, b, divisor);
    if (remainder.is_zero()) break;
    if (remainder.degree() == 0) {
      chain.push_back(std::move(remainder));
      break;
    }
    // g = |lc(b)|, h = h^(1 - delta) g^delta: both magnitudes of the sequence's own.
    g = abs(b.leading());
    if (delta == 1) {
      h = g;
    } else {
      mpz_pow_ui(power.get_mpz_t(), g.get_mpz_t(), delta);
      Integer h_power;
      mpz_pow_ui(h_power.get_mpz_t(), h.get_mpz_t(), delta - 1);
      mpz_divexact(h.get_mpz_t(), power.get_mpz_t(), h_power.get_mpz_t());
    }
    chain.push_back(std::move(remainder));
  }
  for (IntegerPolynomial& member : chain) {
    if (!member.pending) member.prepare_filter();  // a pending member's filter is formed already
  }
  return chain;
}

/// Sign changes along the chain at x (zeros skipped), and the sign of its first member there.
struct ChainSigns {
  int variations = 0;
  int first = 0;
};
template <class Point>
ChainSigns chain_signs(const std::vector<IntegerPolynomial>& chain, const Point& x) {
  const Bounded approximate = bounded(x);
  ChainSigns out;
  int last = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const int s = sign_at(chain[i], x, approximate);
    if (i == 0) out.first = s;
    if (s == 0) continue;
    if (last != 0 && s != last) ++out.variations;
    last = s;
  }
  return out;
}

// ---- Isolation ---------------------------------------------------------------------------------

/// A point of the isolation with the chain's signs there.
struct Endpoint {
  Dyadic x;
  ChainSigns signs;
};

/// f about a dyadic centre c = m 2^-k (k >= 0): the integer polynomial G(s) = 2^(k d) f((m + s) / 2^k),
/// whose sign at s = (x - c) 2^k is f's at x. Its coefficients are those of f's Taylor expansion at
/// c (times powers of two), so the double filter's rounding is relative to |f(c)| and its first
/// derivatives there, not to the sum of |f_i x^i|: near a root, where bisection evaluates, Horner
/// at the point itself cancels to nothing, while the expansion decides down to |x - root| of about
/// 2^-52 |c - root|. Decisions are exact either way (the exact sum decides where the filter cannot);
/// the expansion only spares that sum.
/// Resolution of LocalExpansion::approximate_root_pair's guesses, in bits of the searched width.
constexpr int kPairGuessBits = 60;

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

/// Shrinks an isolating interval (low, high] of the square-free factor f to a few ulps around a
/// double Newton approximation, proved by two exact sign evaluations at double (hence dyadic)
/// points. Exact bisection to the same width costs ~64 evaluations; this costs two.
/// `monic` holds f's coefficients divided by its leading one, as doubles (CGAL::to_double).
bool tighten_with_double_newton(const IntegerPolynomial& f, const std::vector<double>& monic, Dyadic& low,
                                Dyadic& high, int sign_high) {
  const int degree = f.degree();
  double coefficient[5] = {0, 0, 0, 0, 0};
  double scale = 0.0;
  for (int i = 0; i <= degree && i < 5; ++i) scale = std::max(scale, std::fabs(monic[static_cast<std::size_t>(i)]));
  if (!(scale > 0.0) || !std::isfinite(scale) || degree > 4) return false;
  for (int i = 0; i <= degree; ++i) coefficient[i] = monic[static_cast<std::size_t>(i)] / scale;
  const double lo = low.to_double(), hi = high.to_double();
  if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
  double x = 0.5 * (lo + hi);
  for (int step = 0; step < 60; ++step) {
    double value = 0.0, slope = 0.0;
    for (int i = degree; i >= 0; --i) {
      slope = slope * x + value;
      value = value * x + coefficient[i];
    }
    if (slope == 0.0) break;
    const double next = std::clamp(x - value / slope, lo, hi);
    if (next == x) break;
    x = next;
  }
  // The signs near x from f expanded about x (LocalExpansion), taken at the first need.
  std::optional<LocalExpansion> expansion;
  const auto sign_near_x = [&](const Dyadic& point) {
    if (!expansion) expansion.emplace(f, Dyadic::of_double(x));
    const int filtered = expansion->filtered_sign_at(point);
    return filtered != 0 ? filtered : exact_sign(f, point);
  };
  for (double spread = 4; spread < 0x1p20; spread *= 16) {
    const double delta = spread * std::numeric_limits<double>::epsilon() * std::max(std::fabs(x), 1e-300);
    if (!std::isfinite(x - delta) || !std::isfinite(x + delta)) return false;
    const Dyadic a = Dyadic::of_double(x - delta), b = Dyadic::of_double(x + delta);
    if (a <= low || b > high) return false;
    const int sign_a = sign_near_x(a), sign_b = sign_near_x(b);
    if (sign_a == 0 || sign_b == 0) {
      low = high = sign_a == 0 ? a : b;
      return true;
    }
    if (sign_a != sign_b && sign_b == sign_high) {
      // A sign change inside (low, high], which holds exactly one root: that root.
      low = a;
      high = b;
      return true;
    }
  }
  return false;
}

/// Levels beyond which jump_to_last_level leaves the bisection to itself: its index must be an
/// exact double.
constexpr long kMostJumpLevels = 50;
/// Tries of jump_to_last_level's index (its guess, then a neighbour per try).
constexpr int kJumpTries = 4;

/// The interval bisect would end with, found without its levels: the levels L it would take
/// (the first with w 2^-L <= width_goal, w = b - a), the index j of the level-L interval
/// (a + j w 2^-L, a + (j + 1) w 2^-L] guessed from where G's rounded coefficients change sign,
/// and the guess proved by f's exact signs at both ends (the expansion's filter first): opposite
/// to sign_b at the lower end (not needed at a itself), sign_b at the upper end (known at b).
/// Then the root lies strictly between two level-L points, so none of bisect's midpoints (all
/// level-L points) is the root, each of them sends the bisection towards the root, and it ends
/// on this interval having spent L. Near a pair of close roots the double Newton of
/// tighten_with_double_newton does not settle and bisect runs some 40 levels, each with its
/// dyadic arithmetic; this proves the same end with two signs. False (nothing spent, a and b
/// untouched) when the guess is not proved within kJumpTries, or the levels are too many.
template <class Point>
bool jump_to_last_level(const IntegerPolynomial& f, const LocalExpansion& expansion, const Bounded& origin_offset,
                        const Point& point, Dyadic& a, Dyadic& b, int sign_b, const Dyadic& width_goal,
                        EvaluationBudget& budget) {
  long levels = 0;
  for (Dyadic current = b - a; current > width_goal && levels <= kMostJumpLevels; current.exponent -= 1) ++levels;
  if (levels > kMostJumpLevels) return false;
  const double low = origin_offset.value, high = expansion.offset(b).value;
  if (!(std::isfinite(low) && std::isfinite(high) && low < high)) return false;
  const double guess = expansion.approximate_sign_change(low, high, sign_b);
  const double count = std::ldexp(1.0, static_cast<int>(levels));  // level-L intervals
  double index = std::floor((guess - low) / (high - low) * count);
  if (!std::isfinite(index)) return false;
  const auto sign_at = [&](const Dyadic& x) {
    const int filtered = expansion.filtered_sign_at(x);
    return filtered != 0 ? filtered : exact_sign(f, x);
  };
  for (int attempt = 0; attempt < kJumpTries; ++attempt) {
    index = std::clamp(index, 0.0, count - 1);
    const Integer j(index);  // exact: a whole number below 2^kMostJumpLevels
    const Dyadic lower = point(j, levels), upper = point(j + 1, levels);
    const int at_upper = index + 1 == count ? sign_b : sign_at(upper);
    if (at_upper != sign_b) {  // the root lies above upper (or at it: then bisect hits it)
      if (at_upper == 0 || index + 1 == count) return false;
      index += 1;
      continue;
    }
    const int at_lower = index == 0 ? -sign_b : sign_at(lower);
    if (at_lower != -sign_b) {  // the root lies at or below lower
      if (at_lower == 0 || index == 0) return false;
      index -= 1;
      continue;
    }
    budget.spend(static_cast<int>(levels));
    a = lower;
    b = upper;
    return true;
  }
  return false;
}

/// Bisection of (a, b], which holds exactly one root of f (simple: f is square-free), until it is
/// at most `width_goal` wide or a midpoint is the root. Only the sign at the upper end is compared,
/// and it stays sign_b: b only ever moves to a point of that sign. The points are a + j w 2^-i
/// (w = b - a), kept as the integer j and the level i; their signs come from a local expansion of
/// f about the interval's middle, whose argument for such a point is (a - c) 2^k + j w 2^(k - i),
/// a Bounded sum, taken again about the current middle once the interval has shrunk by 2^20 and
/// the expansion's filter no longer decides; the exact sum decides the rest.
void bisect(const IntegerPolynomial& f, Dyadic& a, Dyadic& b, int sign_b, const Dyadic& width_goal,
            EvaluationBudget& budget) {
  const Dyadic width = b - a;
  if (!(width > width_goal)) return;
  const Dyadic origin = a;
  const auto point = [&](const Integer& j, long level) {  // origin + j width 2^-level
    Dyadic step;
    step.mantissa = j * width.mantissa;
    step.exponent = width.exponent - level;
    step.normalise();
    return origin + step;
  };
  std::optional<LocalExpansion> expansion(std::in_place, f, midpoint(a, b));
  Bounded origin_offset = expansion->offset(origin);
  if (jump_to_last_level(f, *expansion, origin_offset, point, a, b, sign_b, width_goal, budget)) return;
  long expansion_level = 0;
  constexpr long kRecentreShrink = 20;
  Bounded width_length = expansion->length(width);  // w 2^k
  Integer j = 0, middle_index;
  long level = 0;
  for (Dyadic current = width; current > width_goal; current.exponent -= 1, ++level) {
    budget.spend();
    mpz_mul_2exp(middle_index.get_mpz_t(), j.get_mpz_t(), 1);  // the middle, 2 j + 1 at level + 1
    mpz_add_ui(middle_index.get_mpz_t(), middle_index.get_mpz_t(), 1);
    const auto filtered = [&] {
      const double index = mpz_get_d(middle_index.get_mpz_t());  // truncated: within an ulp
      const Bounded bounded_index(index, mpz_sizeinbase(middle_index.get_mpz_t(), 2) > 53 ? std::fabs(index) * 0x1p-52 : 0.0);
      // w 2^(k - level - 1): a power-of-two scaling, exact but for underflow.
      const int down = static_cast<int>(std::min(level + 1, 2000L));
      const Bounded step_length(std::ldexp(width_length.value, -down),
                                std::ldexp(width_length.error, -down) + kUnderflowError);
      return expansion->filtered_sign_at_offset(origin_offset + bounded_index * step_length);
    };
    int at_middle = filtered();
    if (at_middle == 0 && level >= expansion_level + kRecentreShrink) {
      expansion.emplace(f, point(middle_index, level + 1));
      origin_offset = expansion->offset(origin);
      width_length = expansion->length(width);
      expansion_level = level;
      at_middle = filtered();
    }
    if (at_middle == 0) {
      const Dyadic middle = point(middle_index, level + 1);
      at_middle = exact_sign(f, middle);
      if (at_middle == 0) {
        a = b = middle;
        return;
      }
    }
    // b to the middle (j stays the lower end's index, doubled) or a to it.
    if (at_middle == sign_b) {
      mpz_mul_2exp(j.get_mpz_t(), j.get_mpz_t(), 1);
    } else {
      std::swap(j, middle_index);
    }
  }
  a = point(j, level);
  b = point(j + 1, level);
}

/// f's coefficients over its leading one, each as CGAL::to_double gives that rational (mpq_get_d
/// truncates the exact quotient, whatever the fraction's form, so no gcd is needed).
std::vector<double> monic_doubles(const IntegerPolynomial& f) {
  std::vector<double> out(f.c.size());
  mpq_t quotient;
  mpq_init(quotient);
  for (std::size_t i = 0; i < f.c.size(); ++i) {
    mpz_set(mpq_numref(quotient), f.c[i].get_mpz_t());
    mpz_set(mpq_denref(quotient), f.leading().get_mpz_t());  // positive (square_free_factors)
    out[i] = mpq_get_d(quotient);
  }
  mpq_clear(quotient);
  return out;
}

/// Levels of the isolation's walk the node descend_to_pair proves is left above the two roots'
/// guessed separation: room for the guess's error.
constexpr long kPairDescentMargin = 2;
/// Fewest levels descend_to_pair skips: one proof costs two chain evaluations, as one level does.
constexpr long kFewestPairDescentLevels = 2;

/// The node the isolation's walk (isolate_factor) would reach from (low, high], which holds
/// exactly two distinct roots of f, without its levels in between: where two roots lie close
/// together, the walk halves the node some 30 times, each time evaluating the chain at the
/// midpoint, before a midpoint separates them. The two roots are guessed from f expanded about
/// the node's middle (LocalExpansion::approximate_root_pair), the deepest node of the walk's grid
/// (a + j w 2^-K, a + (j + 1) w 2^-K] holding both guesses found from their binary digits, and
/// that node, K - kPairDescentMargin levels down, proved to hold two roots by the chain's exact
/// signs at its ends. Every node between (low, high] and it then holds both roots too, and each
/// one's other half none: the walk would have split each of them and found their other halves
/// empty, 2 K - 1 evaluations the budget is charged for (the node itself is charged when the walk
/// takes it). The walk goes on from that node and isolates the same roots in the same intervals.
/// Empty (nothing spent) where the guess is not proved or skips too few levels.
std::optional<std::pair<Endpoint, Endpoint>> descend_to_pair(const IntegerPolynomial& f,
                                                             const std::vector<IntegerPolynomial>& chain,
                                                             const Endpoint& low, const Endpoint& high,
                                                             EvaluationBudget& budget) {
  const LocalExpansion expansion(f, midpoint(low.x, high.x));
  const double from = expansion.offset(low.x).value, to = expansion.offset(high.x).value;
  if (!(std::isfinite(from) && std::isfinite(to) && from < to)) return std::nullopt;
  double first = 0.0, second = 0.0;
  if (!expansion.approximate_root_pair(from, to, first, second)) return std::nullopt;
  const double t1 = std::clamp((first - from) / (to - from), 0.0, 1.0);
  const double t2 = std::clamp((second - from) / (to - from), 0.0, 1.0);
  long common = 0;  // levels down which both guesses stay in one node
  while (common < kMostJumpLevels &&
         std::floor(std::ldexp(t1, static_cast<int>(common + 1))) == std::floor(std::ldexp(t2, static_cast<int>(common + 1)))) {
    ++common;
  }
  const long levels = common - kPairDescentMargin;
  if (levels < kFewestPairDescentLevels) return std::nullopt;
  const double count = std::ldexp(1.0, static_cast<int>(levels));
  const double index = std::min(std::floor(std::ldexp(t1, static_cast<int>(levels))), count - 1);
  Dyadic step = high.x - low.x;
  step.exponent -= levels;
  const auto point = [&](double j) {  // low + j step, j a whole number below 2^kMostJumpLevels
    Dyadic offset = step;
    offset.mantissa *= Integer(j);
    offset.normalise();
    return low.x + offset;
  };
  Endpoint node_low{point(index), {}}, node_high{point(index + 1), {}};
  node_low.signs = index == 0 ? low.signs : chain_signs(chain, node_low.x);
  node_high.signs = index + 1 == count ? high.signs : chain_signs(chain, node_high.x);
  if (node_low.signs.variations - node_high.signs.variations != 2) return std::nullopt;
  budget.spend(static_cast<int>(2 * levels - 1));
  return std::make_pair(std::move(node_low), std::move(node_high));
}

void isolate_factor(const std::shared_ptr<const SquareFreeFactor>& factor, const IntegerPolynomial& f,
                    const std::vector<IntegerPolynomial>& chain, const Dyadic& bound, std::vector<IsolatedRoot>& out,
                    EvaluationBudget& budget) {
  Dyadic width_goal = bound;
  width_goal.exponent -= kRefinementBits;
  const Dyadic lowest = -bound;
  // Nodes still to visit; a node below one where descend_to_pair was tried (and took the walk as
  // far down as its guess allows, or failed) does not try again: the guess there would be the
  // same pair, a few levels from its separation.
  struct Node {
    Endpoint low, high;
    bool may_descend;
  };
  std::vector<Node> pending;
  pending.push_back({{lowest, chain_signs(chain, lowest)}, {bound, chain_signs(chain, bound)}, true});
  std::vector<double> monic;
  while (!pending.empty()) {
    auto [low, high, may_descend] = std::move(pending.back());
    pending.pop_back();
    budget.spend();
    const int n = low.signs.variations - high.signs.variations;
    if (n == 0) continue;
    if (n == 2 && may_descend) {
      may_descend = false;
      if (auto node = descend_to_pair(f, chain, low, high, budget)) {
        pending.push_back({std::move(node->first), std::move(node->second), false});
        continue;
      }
    }
    if (n >= 2) {
      Dyadic middle = midpoint(low.x, high.x);
      const ChainSigns at_middle = chain_signs(chain, middle);
      pending.push_back({std::move(low), {middle, at_middle}, may_descend});
      pending.push_back({{std::move(middle), at_middle}, std::move(high), may_descend});
      continue;
    }
    // One root in (low, high]: bisect on the sign of the square-free factor.
    if (high.signs.first == 0) {
      out.push_back({high.x.to_rational(), high.x.to_rational(), factor->multiplicity(), factor});
      continue;
    }
    if (monic.empty()) monic = monic_doubles(f);
    Dyadic a = low.x, b = high.x;
    if (!tighten_with_double_newton(f, monic, a, b, high.signs.first)) {
      bisect(f, a, b, high.signs.first, width_goal, budget);
    }
    out.push_back({a.to_rational(), b.to_rational(), factor->multiplicity(), factor});
  }
}

/// Yun's square-free factorisation of p (primitive, positive leading coefficient, deg >= 1) into primitive factors with
/// positive leading coefficients, multiplicity 1 first, as CGAL's for the same polynomial up to
/// constant factors; factors of degree 0 left out. `chain` is p's Sturm chain, whose last member
/// is gcd(p, p').
std::vector<std::pair<IntegerPolynomial, int>> square_free_factors(const IntegerPolynomial& p,
                                                                   const std::vector<IntegerPolynomial>& chain) {
  std::vector<std::pair<IntegerPolynomial, int>> factors;
  IntegerPolynomial a = p;
  if (chain.back().degree() == 0) {
    factors.emplace_back(std::move(a), 1);
    return factors;
  }
  IntegerPolynomial c = chain.back();
  make_primitive(c, true);
  IntegerPolynomial w = exact_quotient(a, c), y = exact_quotient(derivative(a), c);
  IntegerPolynomial z = difference(y, derivative(w));
  int i = 1;
  while (!z.is_zero()) {
    IntegerPolynomial g = polynomial_gcd(w, z);
    if (g.degree() > 0) factors.emplace_back(g, i);
    ++i;
    w = exact_quotient(w, g);
    y = exact_quotient(z, g);
    z = difference(y, derivative(w));
  }
  make_primitive(w, true);
  if (w.degree() > 0) factors.emplace_back(std::move(w), i);
  return factors;
}

}  // namespace

SquareFreeFactor::SquareFreeFactor(std::shared_ptr<const IntegerPolynomial> polynomial, int multiplicity)
    : polynomial_(std::move(polynomial)), multiplicity_(multiplicity) {}

RationalPolynomial SquareFreeFactor::monic() const {
  std::vector<Rational> coefficients;
  const CGAL::Gmpz leading(polynomial_->leading().get_mpz_t());
  for (const Integer& x : polynomial_->c) coefficients.emplace_back(CGAL::Gmpz(x.get_mpz_t()), leading);
  return RationalPolynomial(coefficients.begin(), coefficients.end());
}

namespace {

void isolate(IntegerPolynomial p, const Rational& bound, std::vector<IsolatedRoot>& out, EvaluationBudget& budget) {
  if (p.degree() < 1) return;
  const Dyadic dyadic_bound = Dyadic::of_rational(bound);
  std::vector<IntegerPolynomial> chain = sturm_chain(p);
  auto factors = square_free_factors(p, chain);
  for (auto& [polynomial, multiplicity] : factors) {
    polynomial.prepare_filter();
    const bool whole = polynomial.degree() == p.degree();  // p was square-free: its chain serves
    std::vector<IntegerPolynomial> own_chain;
    if (!whole) own_chain = sturm_chain(polynomial);
    const auto shared = std::make_shared<const IntegerPolynomial>(std::move(polynomial));
    const auto factor = std::make_shared<const SquareFreeFactor>(shared, multiplicity);
    isolate_factor(factor, *shared, whole ? chain : own_chain, dyadic_bound, out, budget);
  }
}

}  // namespace

std::size_t bit_size(const Rational& x) {
  return mpz_sizeinbase(mpq_numref(x.mpq()), 2) + mpz_sizeinbase(mpq_denref(x.mpq()), 2);
}

int SquareFreeFactor::sign_at(const Rational& x) const {
  // The factor's leading coefficient is positive: its sign is the monic form's.
  return detail::sign_at(*polynomial_, x, bounded(x));
}

bool SquareFreeFactor::shares_root_in(const RationalPolynomial& g, const Rational& low, const Rational& high) const {
  const IntegerPolynomial common = polynomial_gcd(*polynomial_, integer_multiple(g));
  if (common.degree() < 1) return false;
  const std::vector<IntegerPolynomial> chain = sturm_chain(common);
  return chain_signs(chain, low).variations - chain_signs(chain, high).variations > 0;
}

void isolate_real_roots(const RationalPolynomial& f, const Rational& bound, std::vector<IsolatedRoot>& out,
                        EvaluationBudget& budget) {
  if (f.is_zero() || f.degree() < 1) return;
  for (int i = 0; i <= f.degree(); ++i) {
    if (bit_size(f[i]) > kMaxCoefficientBits) throw ExactTierGiveUp{CertificateReason::exact_coefficients_too_large};
  }
  isolate(integer_multiple(f), bound, out, budget);
}

void isolate_real_roots(std::vector<mpz_class> coefficients, const Rational& bound, std::vector<IsolatedRoot>& out,
                        EvaluationBudget& budget) {
  IntegerPolynomial p;
  p.c = std::move(coefficients);
  p.trim();
  if (p.degree() < 1) return;
  // Only the roots matter: the common power of two goes (it costs no gcd) and the leading
  // coefficient is made positive, as integer_multiple leaves it.
  mp_bitcnt_t twos = std::numeric_limits<mp_bitcnt_t>::max();
  for (const Integer& x : p.c) {
    if (sgn(x) != 0) twos = std::min(twos, mpz_scan1(x.get_mpz_t(), 0));
  }
  const bool negate = sgn(p.leading()) < 0;
  for (Integer& x : p.c) {
    if (twos > 0) mpz_tdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), twos);
    if (negate) x = -x;
  }
  isolate(std::move(p), bound, out, budget);
}

SturmSequence::SturmSequence(const RationalPolynomial& f) {
  const IntegerPolynomial p = integer_multiple(f);
  if (!p.is_zero()) chain_ = sturm_chain(p);
}
SturmSequence::~SturmSequence() = default;
SturmSequence::SturmSequence(SturmSequence&&) noexcept = default;

int SturmSequence::roots_in(const Rational& low, const Rational& high) const {
  if (chain_.empty()) return 0;
  return chain_signs(chain_, low).variations - chain_signs(chain_, high).variations;
}

}  // namespace clearjoint::geometry::detail
