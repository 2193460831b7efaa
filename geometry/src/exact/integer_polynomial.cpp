// SPDX-License-Identifier: BSD-3-Clause
#include "exact/integer_polynomial.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <utility>

#include "exact/exact_dyadic.hpp"

namespace clearjoint::geometry::detail {

IntegerPolynomial derivative(const IntegerPolynomial& p) {
  IntegerPolynomial d;
  for (int i = 1; i <= p.degree(); ++i) d.c.push_back(p.c[static_cast<std::size_t>(i)] * i);
  d.trim();
  return d;
}

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

Bounded bounded(const Rational& x) {
  const std::pair<double, double> range = interval_of(x);
  const double middle = 0.5 * (range.first + range.second);
  return {middle, std::max(middle - range.first, range.second - middle) * kErrorInflation};
}

}  // namespace clearjoint::geometry::detail
