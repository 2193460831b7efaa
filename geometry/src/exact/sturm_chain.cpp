// SPDX-License-Identifier: BSD-3-Clause
#include "exact/sturm_chain.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "exact/ball_arithmetic.hpp"

namespace clearjoint::geometry::detail {
namespace {

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
                           SturmChain& chain) {
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

}  // namespace

SturmChain sturm_chain(const IntegerPolynomial& p) {
  SturmChain chain;  // (an initializer list would copy both members)
  chain.push_back(p);
  chain.push_back(derivative(p));
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

}  // namespace clearjoint::geometry::detail
