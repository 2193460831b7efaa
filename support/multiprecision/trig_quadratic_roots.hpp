// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The real roots of a trigonometric quadratic
///   f(theta) = p + q cos + s sin + cc cos^2 + ss sin^2 + cs cos sin
/// in multiprecision, for the two MPFR references (the rim queries' in support/testing,
/// the whole joint's in bench/detection): the excess of a rim over a cylinder wall is such a
/// function (paper eqs. 16-17), and so is its derivative. Written once over the number type Real
/// (a Boost.Multiprecision MPFR number; each reference chooses its precision).
///
/// Method: shift the angle by phi, a multiple of pi/4 with |f(phi + pi)| largest, so that the
/// half-angle substitution t = tan((theta - phi)/2) has no root at its pole; f (1 + t^2)^2 is then
/// a quartic in t. A Sturm sequence counts its distinct real roots in an interval, bisection on
/// the counts isolates them from Cauchy's bound, and safeguarded Newton refines each
/// sign-changing bracket; a root without a sign change (even multiplicity) is narrowed on the
/// counts. Test-only and bench-only code: never part of the installed library.
///
/// Why not CGAL's algebraic kernel (Algebraic_kernel_d_1, or its RS flavour): it isolates the
/// roots of polynomials with exact integer or rational coefficients. These coefficients are not
/// exact: they hold unit vectors (the rim frame's u and v, a/|a| in the joint reference) and are
/// rounded at the working precision, so an exact isolation of the rounded quartic proves nothing
/// more than the Sturm counts do on it. Taking each coefficient exactly (a dyadic rational,
/// denominators cleared) and isolating and refining the roots with Algebraic_kernel_d_1<Gmpz>
/// took about ten times as long per quartic as this routine, on random rim quartics at 150
/// digits with the same roots found. The decisions that need exactness (a tangency against two
/// crossings) are made by the callers from the root separation and the discriminant.

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace clearjoint::multiprecision {

template <class Real>
int sign_of(const Real& x) {
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

/// f(theta) = p + q cos + s sin + cc cos^2 + ss sin^2 + cs cos sin.
template <class Real>
struct TrigQuadratic {
  Real p, q, s, cc, ss, cs;

  Real at(const Real& c, const Real& sn) const { return p + q * c + s * sn + cc * c * c + ss * sn * sn + cs * c * sn; }
  Real at(const Real& angle) const { return at(cos(angle), sin(angle)); }
  TrigQuadratic derivative() const {
    // d cos = -sin, d sin = cos, d cos^2 = -2 cos sin, d sin^2 = 2 cos sin,
    // d (cos sin) = cos^2 - sin^2.
    return {Real(0), s, -q, cs, -cs, 2 * (ss - cc)};
  }
  /// g(psi) = f(phi + psi) with cos(phi) = cp, sin(phi) = sp.
  TrigQuadratic shifted(const Real& cp, const Real& sp) const {
    // cos(phi + psi) = cp C - sp S, sin(phi + psi) = sp C + cp S (C = cos psi, S = sin psi).
    TrigQuadratic g;
    g.p = p;
    g.q = q * cp + s * sp;
    g.s = -q * sp + s * cp;
    g.cc = cc * cp * cp + ss * sp * sp + cs * cp * sp;
    g.ss = cc * sp * sp + ss * cp * cp - cs * cp * sp;
    g.cs = -2 * cc * cp * sp + 2 * ss * sp * cp + cs * (cp * cp - sp * sp);
    return g;
  }
  /// Largest coefficient in the Fourier basis (1, cos, sin, cos 2, sin 2): f == 0 iff all vanish.
  Real fourier_size() const {
    Real m = abs(p + (cc + ss) / 2);
    for (const Real& x : {Real(abs(q)), Real(abs(s)), Real(abs((cc - ss) / 2)), Real(abs(cs / 2))}) m = std::max(m, x);
    return m;
  }
};

template <class Real>
using Poly = std::vector<Real>;  ///< ascending powers

template <class Real>
Real horner(const Poly<Real>& p, const Real& x) {
  Real r = 0;
  for (auto it = p.rbegin(); it != p.rend(); ++it) r = r * x + *it;
  return r;
}

/// Scales to max |coefficient| 1 (a positive factor: signs are kept) and drops leading
/// coefficients at most `negligible`; false when the polynomial is negligible as a whole.
template <class Real>
bool normalise(Poly<Real>& p, const Real& negligible) {
  Real m = 0;
  for (const Real& c : p) m = std::max(m, Real(abs(c)));
  if (m == 0) return false;
  for (Real& c : p) c /= m;
  while (!p.empty() && abs(p.back()) <= negligible) p.pop_back();
  return !p.empty();
}

template <class Real>
Poly<Real> derivative(const Poly<Real>& p) {
  Poly<Real> d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<int>(i));
  return d;
}

/// -(a mod b), the next member of a Sturm sequence.
template <class Real>
Poly<Real> negated_remainder(Poly<Real> a, const Poly<Real>& b) {
  while (a.size() >= b.size()) {
    const Real factor = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= factor * b[i];
    a.pop_back();
  }
  for (Real& c : a) c = -c;
  return a;
}

/// Sturm sequence: the number of distinct real roots in (a, b] is count(a) - count(b).
template <class Real>
class Sturm {
 public:
  Sturm(const Poly<Real>& p, const Real& negligible) {
    chain_.push_back(p);
    Poly<Real> d = derivative(p);
    if (!normalise(d, negligible)) return;
    chain_.push_back(d);
    while (chain_.back().size() > 1) {
      Poly<Real> r = negated_remainder(chain_[chain_.size() - 2], chain_.back());
      if (!normalise(r, negligible)) break;
      chain_.push_back(std::move(r));
    }
  }
  int count(const Real& x) const {
    int changes = 0, last = 0;
    for (const Poly<Real>& q : chain_) {
      const int s = sign_of(horner(q, x));
      if (s == 0) continue;
      if (last != 0 && s != last) ++changes;
      last = s;
    }
    return changes;
  }

 private:
  std::vector<Poly<Real>> chain_;
};

/// How far real_roots goes; each reference sets them from its working precision.
template <class Real>
struct IsolationLimits {
  Real negligible;    ///< coefficients at most this (after normalise) are rounding noise
  Real root_width;    ///< each root refined to this width (in t)
  Real cluster_width; ///< several roots in an interval this narrow are reported as one cluster
  int max_bisections; ///< safety cap on bisection steps
};

template <class Real>
struct IsolatedRoot {
  Real t;
  /// 1 for a simple root (a sign change); 2 for a root without a sign change (even multiplicity,
  /// a tangency to working precision); n > 1 for a cluster of n distinct roots narrower than
  /// cluster_width. Callers treat anything but 1 as undecided.
  int multiplicity_hint = 1;
};

/// Cauchy's bound on the roots' magnitudes.
template <class Real>
Real cauchy_bound(const Poly<Real>& e) {
  Real bound = 0;
  for (std::size_t i = 0; i + 1 < e.size(); ++i) bound = std::max(bound, Real(abs(e[i] / e.back())));
  return bound + 1;
}

/// The distinct real roots of `e` (normalised, degree >= 1), sorted.
template <class Real>
std::vector<IsolatedRoot<Real>> real_roots(const Poly<Real>& e, const IsolationLimits<Real>& limits) {
  const Real bound = cauchy_bound(e);
  const Sturm<Real> sturm(e, limits.negligible);
  const Poly<Real> de = derivative(e);
  struct Interval {
    Real lo, hi;
    int v_lo, v_hi;
    int depth;
  };
  std::vector<Interval> todo{{-bound, bound, sturm.count(-bound), sturm.count(bound), 0}};
  std::vector<IsolatedRoot<Real>> roots;
  while (!todo.empty()) {
    const Interval iv = todo.back();
    todo.pop_back();
    const int n = iv.v_lo - iv.v_hi;
    if (n <= 0) continue;
    if (n > 1) {
      if (iv.depth >= limits.max_bisections || iv.hi - iv.lo < limits.cluster_width) {
        roots.push_back({(iv.lo + iv.hi) / 2, n});
        continue;
      }
      Real mid = (iv.lo + iv.hi) / 2;
      if (horner(e, mid) == 0) mid = (iv.lo + 3 * mid) / 4;  // keep roots off the cut
      const int v_mid = sturm.count(mid);
      todo.push_back({iv.lo, mid, iv.v_lo, v_mid, iv.depth + 1});
      todo.push_back({mid, iv.hi, v_mid, iv.v_hi, iv.depth + 1});
      continue;
    }
    Real lo = iv.lo, hi = iv.hi;
    const int s_lo = sign_of(horner(e, lo));
    const int s_hi = sign_of(horner(e, hi));
    if (s_hi == 0) {
      roots.push_back({hi, 1});
      continue;
    }
    if (s_lo == s_hi) {
      // One distinct root without a sign change: even multiplicity. Bisect on Sturm counts.
      int v_lo = iv.v_lo;
      for (int i = 0; i < limits.max_bisections && hi - lo > limits.root_width; ++i) {
        const Real mid = (lo + hi) / 2;
        const int v_mid = sturm.count(mid);
        if (v_lo - v_mid >= 1) {
          hi = mid;
        } else {
          lo = mid;
          v_lo = v_mid;
        }
      }
      roots.push_back({(lo + hi) / 2, 2});
      continue;
    }
    // Safeguarded Newton on a sign-changing bracket: the bracket shrinks at every step, Newton
    // steps that leave it (or any after the 100th) are replaced by bisection.
    constexpr int kNewtonSteps = 100;
    Real x = (lo + hi) / 2;
    for (int i = 0; i < limits.max_bisections; ++i) {
      const Real fx = horner(e, x);
      const int sx = sign_of(fx);
      if (sx == 0) break;
      (sx == s_lo ? lo : hi) = x;
      Real next = x - fx / horner(de, x);
      if (!(next > lo && next < hi) || i > kNewtonSteps) next = (lo + hi) / 2;
      const Real moved = abs(next - x);
      x = next;
      if (hi - lo < limits.root_width || moved < limits.root_width * limits.root_width) break;
    }
    roots.push_back({x, 1});
  }
  std::sort(roots.begin(), roots.end(), [](const IsolatedRoot<Real>& a, const IsolatedRoot<Real>& b) { return a.t < b.t; });
  return roots;
}

/// f (1 + t^2)^2 as a quartic in t = tan((theta - phi)/2), phi = k pi/4 (cos phi, sin phi given).
template <class Real>
struct HalfAngleQuartic {
  int k = 0;          ///< phi = k pi / 4
  Real cphi, sphi;    ///< cos(phi), sin(phi)
  Poly<Real> e;       ///< ascending, not normalised
};

/// The shift phi with |f(phi + pi)| largest (the quartic's leading coefficient is f(phi + pi):
/// far from 0, no root hides at t = infinity), and the quartic of f shifted by it.
template <class Real>
HalfAngleQuartic<Real> half_angle_quartic(const TrigQuadratic<Real>& f) {
  static const Real half_sqrt2 = sqrt(Real(2)) / 2;
  static const std::array<std::pair<Real, Real>, 8> shifts = {{{Real(1), Real(0)},
                                                              {half_sqrt2, half_sqrt2},
                                                              {Real(0), Real(1)},
                                                              {-half_sqrt2, half_sqrt2},
                                                              {Real(-1), Real(0)},
                                                              {-half_sqrt2, -half_sqrt2},
                                                              {Real(0), Real(-1)},
                                                              {half_sqrt2, -half_sqrt2}}};
  int best = 0;
  Real best_value = -1;
  for (int k = 0; k < 8; ++k) {
    const Real value = abs(f.at(-shifts[k].first, -shifts[k].second));  // f(phi + pi)
    if (value > best_value) {
      best_value = value;
      best = k;
    }
  }
  const TrigQuadratic<Real> g = f.shifted(shifts[best].first, shifts[best].second);
  // g (1 + t^2)^2 with cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2).
  return {best, shifts[best].first, shifts[best].second,
          {g.p + g.q + g.cc, 2 * g.s + 2 * g.cs, 2 * g.p - 2 * g.cc + 4 * g.ss, 2 * g.s - 2 * g.cs,
           g.p - g.q + g.cc}};
}

}  // namespace clearjoint::multiprecision
