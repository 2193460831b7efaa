// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/long_bearing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>


namespace clearjoint::lubrication {

namespace {

constexpr int kRootIterations = 100;

/// The pressure over k = 6 eta R^2 / c^2 in the Sommerfeld angle gamma (sommerfeld_integrals.hpp),
/// where p'(psi) = k (a0 + a1 cos psi + a2 sin psi) / (1 - eps cos psi)^3 with the periodic
/// a0 = 3 eps^2 Omega / (2 + eps^2), a1 = -eps Omega, a2 = -2 eps' becomes, with
/// D = 1 + eps cos g (1 - eps cos psi = s^2 / D, dpsi / dgamma = s / D, s^2 = 1 - eps^2),
///   dp/dgamma = (b0 + b1 cos g + b2 sin g) D,
///   b0 = rot eps^2, b1 = -2 eps rot, b2 = sq,  rot = Omega / (s^3 (2 + eps^2)),  sq = a2 / s^4.
/// The factor s^2 that a0 D + a1 (cos g + eps) = Omega s^2 (eps^2 - 2 eps cos g) / (2 + eps^2)
/// holds is taken out by hand: formed from a0 and a1, it is a difference of terms 1 / s^2 times
/// larger than itself, which lost every digit near eps -> 1. With it, no sum below cancels but
/// at the ends of the positive region (p = 0 there), and every output is exact to a few ulps
/// for any eps < 1 (kClosedFormRelativeError, bearing_characteristics.hpp). Integrated from
/// p(pi) = 0 the linear terms cancel (periodicity):
///   p = -rot eps sin g (1 + s^2 + eps cos g) + sq ((eps / 2) sin^2 g - (1 + cos g)).
struct LongBearingPressure {
  double eps, s2, s, rot, sq;

  double b0() const { return rot * eps * eps; }
  double b1() const { return -2.0 * eps * rot; }
  double b2() const { return sq; }

  /// p / k at gamma.
  double operator()(double gamma) const {
    const double sin_g = std::sin(gamma), cos_g = std::cos(gamma);
    return -rot * eps * sin_g * (1.0 + s2 + eps * cos_g) +
           sq * (0.5 * eps * sin_g * sin_g - (1.0 + cos_g));
  }
  /// d(p / k) / d gamma.
  double slope(double gamma) const {
    const double sin_g = std::sin(gamma), cos_g = std::cos(gamma);
    return (b0() + b1() * cos_g + b2() * sin_g) * (1.0 + eps * cos_g);
  }
};

/// The force primitives at gamma, over R B k: with p' dpsi = dp and sin psi = s sin g / D,
/// cos psi = (cos g + eps) / D (D cancels),
///   F . e_hat = s [ -rot (eps^2 cos g + eps sin^2 g) + sq (g - sin g cos g) / 2 ],
///   F . t_hat = rot eps (s^2 g + (eps + cos g) sin g) - sq (sin^2 g / 2 - eps cos g).
/// sin_g and cos_g are passed in so that the ends at multiples of pi use 0 and -+1 exactly:
/// std::sin(2 pi) = -2.4e-16 is as large as s^2 g itself at eps = 1 - 2^-53.
struct ForcePrimitives {
  double radial, tangential;
};
ForcePrimitives force_primitives(const LongBearingPressure& p, double gamma, double sin_g,
                                 double cos_g) {
  const double eps = p.eps;
  return {p.s * (-p.rot * (eps * eps * cos_g + eps * sin_g * sin_g) +
                 p.sq * 0.5 * (gamma - sin_g * cos_g)),
          p.rot * eps * (p.s2 * gamma + (eps + cos_g) * sin_g) -
              p.sq * (0.5 * sin_g * sin_g - eps * cos_g)};
}

/// force_primitives at gamma = n pi exactly (sin 0, cos (-1)^n), or at any other gamma.
ForcePrimitives force_primitives_at(const LongBearingPressure& p, double gamma, int multiple_of_pi) {
  if (multiple_of_pi != 0) {
    return force_primitives(p, multiple_of_pi * std::numbers::pi, 0.0, multiple_of_pi % 2 == 0 ? 1.0 : -1.0);
  }
  return force_primitives(p, gamma, std::sin(gamma), std::cos(gamma));
}

/// The root of p in [low, high] (gamma), where p(low) and p(high) have opposite signs and p is
/// monotone (the bracket joins two extrema): Newton safeguarded by bisection, from the secant.
double pressure_root(const LongBearingPressure& p, double low, double high, double p_low,
                     double p_high) {
  double gamma = low - p_low * (high - low) / (p_high - p_low);
  if (!(gamma > low && gamma < high)) gamma = 0.5 * (low + high);
  for (int iteration = 0; iteration < kRootIterations; ++iteration) {
    const double value = p(gamma);
    if ((value > 0.0) == (p_low > 0.0)) {
      low = gamma;
    } else {
      high = gamma;
    }
    const double slope = p.slope(gamma);
    const double newton = slope != 0.0 ? gamma - value / slope : low - 1.0;
    const double next = (newton > low && newton < high) ? newton : 0.5 * (low + high);
    const bool done = std::abs(next - gamma) <= kLongBearingRootTolerance ||
                      high - low <= kLongBearingRootTolerance;
    gamma = next;
    if (done) break;
  }
  return gamma;
}

/// psi + 2 pi k in (pi, 3 pi].
double into_period(double psi) {
  const double pi = std::numbers::pi;
  double offset = std::fmod(psi - pi, 2.0 * pi);
  if (offset <= 0.0) offset += 2.0 * pi;
  return pi + offset;
}

}  // namespace

PlanarFilmLoad long_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                 double viscosity) {
  validate(bearing, state, viscosity);
  const double eps = state.eccentricity_ratio;
  const double pi = std::numbers::pi;
  const double omega = state.journal_spin - 2.0 * state.line_of_centres_rate;
  const double s2 = (1.0 - eps) * (1.0 + eps);  // 1 - eps^2 without cancellation
  const double s = std::sqrt(s2);
  const LongBearingPressure p{eps, s2, s, omega / (s2 * s * (2.0 + eps * eps)),
                              -2.0 * state.eccentricity_ratio_rate / (s2 * s2)};
  PlanarFilmLoad load;
  // The pressure's extrema, where dp/dgamma = 0 (D > 0): b1 cos g + b2 sin g = -b0, i.e.
  // cos(g - alpha) = -b0 / M. A periodic p with p' not identically zero has two per period,
  // and is monotone between them: from p(pi) = 0 it runs to p(e1), then to p(e2), then back
  // to p(3 pi) = 0, so the region where p > 0 is [pi, r] or [r, 3 pi] with its other end r
  // between the extrema. No sampling and no quadrature: the ends and the integrals are closed
  // forms in gamma but for r itself, a root of a trigonometric polynomial in gamma.
  const double b0 = p.b0(), b1 = p.b1(), b2 = p.b2();
  const double m = std::hypot(b1, b2);
  if (!(m > 0.0) || std::abs(b0) > m) return load;  // p' = 0 (eps = 0 and no squeeze)
  const double alpha = std::atan2(b2, b1);
  const double spread = std::acos(std::clamp(-b0 / m, -1.0, 1.0));
  double g1 = into_period(alpha - spread), g2 = into_period(alpha + spread);
  if (g2 < g1) std::swap(g1, g2);
  const double p1 = p(g1), p2 = p(g2);
  // The region in gamma, [low, high]; an end at a multiple of pi is kept as that multiple.
  double low = pi, high = 3.0 * pi;
  int low_multiple = 1, high_multiple = 3;
  if (b0 == 0.0 && b1 == 0.0) {
    // Pure squeeze: p = sq ((eps / 2) sin^2 g - (1 + cos g)) has the sign of -sq over the whole
    // period ((eps / 2) sin^2 g <= eps (1 + cos g)), and touches 0 only at pi and 3 pi.
    if (!(b2 < 0.0)) return load;
  } else if (p1 > 0.0) {
    // p rises to p1, falls through r to p2 <= 0 (p2 = 0 to rounding when g2 = 3 pi).
    if (b2 == 0.0) {
      high_multiple = 2;  // no squeeze: p is odd about pi, its other root is gamma = 2 pi
    } else if (p2 < 0.0) {
      high = pressure_root(p, g1, g2, p1, p2);
      high_multiple = 0;
    } else {
      high = g2;
      high_multiple = 0;
    }
  } else if (p2 > 0.0) {
    if (b2 == 0.0) {
      low_multiple = 2;
    } else if (p1 < 0.0) {
      low = pressure_root(p, g1, g2, p1, p2);
      low_multiple = 0;
    } else {
      low = g1;
      low_multiple = 0;
    }
  } else {
    return load;  // p <= 0 over the period: no film force
  }
  const ForcePrimitives a = force_primitives_at(p, low, low_multiple);
  const ForcePrimitives b = force_primitives_at(p, high, high_multiple);
  const double c = bearing.radial_clearance;
  const double k = 6.0 * viscosity * bearing.radius * bearing.radius / (c * c);
  // Integration by parts with p = 0 at both ends of the region:
  //   F . e_hat = -R B int p cos = R B int p' sin,  F . t_hat = -R B int p sin = -R B int p' cos.
  const double rb_k = bearing.radius * bearing.width * k;
  load.radial = rb_k * (b.radial - a.radial);
  load.tangential = rb_k * (b.tangential - a.tangential);
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = std::atan2(load.tangential, -load.radial);
  load.max_pressure = k * std::max(p1, p2);
  return load;
}

}  // namespace clearjoint::lubrication
