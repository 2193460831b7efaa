// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/long_bearing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sommerfeld_integrals.hpp"

namespace clearjoint::lubrication {

namespace {

/// Samples over the period (pi, 3 pi) that locate the pressure's second root with squeeze; the
/// pressure has at most two extrema per period (p' has at most two zeros), so 32 samples find its
/// sign change unless the root is within 2 pi / 32 of pi, where the bracket search below still
/// catches it through the first sample's sign.
constexpr int kRootSamples = 32;
constexpr int kRootIterations = 100;

/// p'(psi) = k (a0 + a1 cos psi + a2 sin psi) / (1 - eps cos psi)^3, p(pi) = 0.
struct LongBearingPressure {
  double eps, a0, a1, a2;
  detail::KernelIntegrals at_pi;

  /// p / k at psi.
  double operator()(double psi) const {
    const detail::KernelIntegrals f =
        detail::kernel_primitives(eps, detail::sommerfeld_angle(eps, psi));
    return a0 * (f.one - at_pi.one) + a1 * (f.c - at_pi.c) + a2 * (f.s - at_pi.s);
  }
  /// p' / k at psi.
  double slope(double psi) const {
    const double d = 1.0 - eps * std::cos(psi);
    return (a0 + a1 * std::cos(psi) + a2 * std::sin(psi)) / (d * d * d);
  }
};

/// The root of p in (low, high) where p changes sign: bisection safeguarding Newton.
double pressure_root(const LongBearingPressure& p, double low, double high) {
  double p_low = p(low);
  double psi = 0.5 * (low + high);
  for (int iteration = 0; iteration < kRootIterations && high - low > kLongBearingRootTolerance;
       ++iteration) {
    const double value = p(psi);
    if ((value > 0.0) == (p_low > 0.0)) {
      low = psi;
      p_low = value;
    } else {
      high = psi;
    }
    const double slope = p.slope(psi);
    const double newton = slope != 0.0 ? psi - value / slope : low - 1.0;
    psi = (newton > low && newton < high) ? newton : 0.5 * (low + high);
  }
  return psi;
}

}  // namespace

PlanarFilmLoad long_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                 double viscosity) {
  validate(bearing, state, viscosity);
  const double eps = state.eccentricity_ratio;
  const double pi = std::numbers::pi;
  const double omega = state.journal_spin - 2.0 * state.line_of_centres_rate;
  // Periodicity fixes the constant: a0 = 3 eps^2 Omega / (2 + eps^2).
  LongBearingPressure p{eps, 3.0 * eps * eps * omega / (2.0 + eps * eps), -eps * omega,
                        -2.0 * state.eccentricity_ratio_rate,
                        detail::kernel_primitives(eps, pi)};
  PlanarFilmLoad load;
  if (p.a0 == 0.0 && p.a1 == 0.0 && p.a2 == 0.0) return load;

  // The positive region [low, high] within the period (pi, 3 pi).
  double low = pi, high = 3.0 * pi;
  if (p.a2 == 0.0) {
    // p is odd about pi: its other root is 2 pi.
    if (p(1.5 * pi) > 0.0) {
      high = 2.0 * pi;
    } else {
      low = 2.0 * pi;
    }
  } else {
    const double step = 2.0 * pi / kRootSamples;
    double previous_psi = pi, previous = 0.0;
    bool found = false;
    for (int k = 1; k < kRootSamples && !found; ++k) {
      const double psi = pi + k * step;
      const double value = p(psi);
      if (k > 1 && ((value > 0.0) != (previous > 0.0))) {
        const double root = pressure_root(p, previous_psi, psi);
        if (previous > 0.0) {
          high = root;
        } else {
          low = root;
        }
        found = true;
      }
      previous_psi = psi;
      previous = value;
    }
    if (!found && p(2.0 * pi) <= 0.0) return load;  // p <= 0 over the period: no film force
  }

  const detail::KernelIntegrals j = detail::kernel_integrals(eps, low, high);
  const double c = bearing.radial_clearance;
  const double k = 6.0 * viscosity * bearing.radius * bearing.radius / (c * c);
  // Integration by parts with p = 0 at both ends of the region:
  //   F . e_hat = -R B int p cos = R B int p' sin,  F . t_hat = -R B int p sin = -R B int p' cos.
  const double rb_k = bearing.radius * bearing.width * k;
  load.radial = rb_k * (p.a0 * j.s + p.a1 * j.sc + p.a2 * j.ss);
  load.tangential = -rb_k * (p.a0 * j.c + p.a1 * j.cc + p.a2 * j.sc);
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = std::atan2(load.tangential, -load.radial);
  // The pressure's extrema: a1 cos psi + a2 sin psi = -a0, i.e. cos(psi - alpha) = -a0 / M.
  const double m = std::hypot(p.a1, p.a2);
  if (m > 0.0 && std::abs(p.a0) <= m) {
    const double alpha = std::atan2(p.a2, p.a1);
    const double spread = std::acos(-p.a0 / m);
    for (const double psi : {alpha + spread, alpha - spread}) {
      load.max_pressure = std::max(load.max_pressure, k * p(psi));
    }
  }
  return load;
}

}  // namespace clearjoint::lubrication
