// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/long_bearing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "sommerfeld_integrals.hpp"

namespace clearjoint::lubrication {

namespace {

constexpr int kRootIterations = 100;

/// p'(psi) = k (a0 + a1 cos psi + a2 sin psi) / (1 - eps cos psi)^3, p(pi) = 0, written in the
/// Sommerfeld angle gamma (sommerfeld_integrals.hpp), in which p / k is a linear term plus a
/// trigonometric polynomial of degree 2: each evaluation costs one sine and one cosine.
struct LongBearingPressure {
  double eps, a0, a1, a2;
  detail::KernelIntegrals at_pi;

  /// p / k at gamma.
  double operator()(double gamma) const {
    const detail::KernelIntegrals f = detail::kernel_primitives(eps, gamma);
    return a0 * (f.one - at_pi.one) + a1 * (f.c - at_pi.c) + a2 * (f.s - at_pi.s);
  }
  /// d(p / k) / d gamma = p'(psi) dpsi/dgamma, with 1 - eps cos psi = s^2 / (1 + eps cos gamma),
  /// dpsi / dgamma = s / (1 + eps cos gamma), s = sqrt(1 - eps^2):
  ///   [a0 (1 + eps cos g) + a1 (cos g + eps) + a2 s sin g] (1 + eps cos g) / s^5.
  double slope(double gamma) const {
    const double s2 = (1.0 - eps) * (1.0 + eps);
    const double s = std::sqrt(s2);
    const double cos_g = std::cos(gamma), sin_g = std::sin(gamma);
    const double d = 1.0 + eps * cos_g;
    return (a0 * d + a1 * (cos_g + eps) + a2 * s * sin_g) * d / (s2 * s2 * s);
  }
};

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
  // Periodicity fixes the constant: a0 = 3 eps^2 Omega / (2 + eps^2).
  const LongBearingPressure p{eps, 3.0 * eps * eps * omega / (2.0 + eps * eps), -eps * omega,
                              -2.0 * state.eccentricity_ratio_rate,
                              detail::kernel_primitives(eps, pi)};
  PlanarFilmLoad load;
  // The pressure's extrema, where p' = 0: a1 cos psi + a2 sin psi = -a0, i.e.
  // cos(psi - alpha) = -a0 / M. A periodic p with p' not identically zero has two per period,
  // and is monotone between them: from p(pi) = 0 it runs to p(e1), then to p(e2), then back
  // to p(3 pi) = 0, so the region where p > 0 is [pi, r] or [r, 3 pi] with its other end r
  // between the extrema. No sampling and no quadrature: the ends and the integrals are closed
  // forms in gamma but for r itself, a root of a linear-plus-trigonometric function of gamma.
  const double m = std::hypot(p.a1, p.a2);
  if (!(m > 0.0) || std::abs(p.a0) > m) return load;  // p' = 0 (eps = 0 and no squeeze)
  const double alpha = std::atan2(p.a2, p.a1);
  const double spread = std::acos(std::clamp(-p.a0 / m, -1.0, 1.0));
  double e1 = into_period(alpha - spread), e2 = into_period(alpha + spread);
  if (e2 < e1) std::swap(e1, e2);
  const double g1 = detail::sommerfeld_angle(eps, e1), g2 = detail::sommerfeld_angle(eps, e2);
  const double p1 = p(g1), p2 = p(g2);
  double low = pi, high = 3.0 * pi;  // gamma = psi at multiples of pi
  if (p1 > 0.0) {
    // p rises to p1, falls through r to p2 <= 0 (p2 = 0 to rounding when e2 = 3 pi).
    high = p.a2 == 0.0 ? 2.0 * pi : (p2 < 0.0 ? pressure_root(p, g1, g2, p1, p2) : g2);
  } else if (p2 > 0.0) {
    low = p.a2 == 0.0 ? 2.0 * pi : (p1 < 0.0 ? pressure_root(p, g1, g2, p1, p2) : g1);
  } else {
    return load;  // p <= 0 over the period: no film force
  }
  // With a2 = 0 (no squeeze) p is odd about pi: its other root is psi = gamma = 2 pi exactly.

  const detail::KernelIntegrals a = detail::kernel_primitives(eps, low);
  const detail::KernelIntegrals b = detail::kernel_primitives(eps, high);
  const detail::KernelIntegrals j{b.one - a.one, b.c - a.c, b.s - a.s,
                                  b.cc - a.cc, b.sc - a.sc, b.ss - a.ss};
  const double c = bearing.radial_clearance;
  const double k = 6.0 * viscosity * bearing.radius * bearing.radius / (c * c);
  // Integration by parts with p = 0 at both ends of the region:
  //   F . e_hat = -R B int p cos = R B int p' sin,  F . t_hat = -R B int p sin = -R B int p' cos.
  const double rb_k = bearing.radius * bearing.width * k;
  load.radial = rb_k * (p.a0 * j.s + p.a1 * j.sc + p.a2 * j.ss);
  load.tangential = -rb_k * (p.a0 * j.c + p.a1 * j.cc + p.a2 * j.sc);
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = std::atan2(load.tangential, -load.radial);
  load.max_pressure = k * std::max(p1, p2);
  return load;
}

}  // namespace clearjoint::lubrication
