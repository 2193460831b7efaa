// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/short_bearing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sommerfeld_integrals.hpp"

namespace clearjoint::lubrication {

namespace {

/// Samples of the mid-plane pressure over its positive half period before Newton refines the
/// largest: the pressure has one maximum there, which 16 samples bracket for any eps < 1.
constexpr int kMaxPressureSamples = 16;
constexpr int kMaxPressureNewtonSteps = 8;

/// -sin(psi + delta) / (1 - eps cos psi)^3: the mid-plane pressure over 3 eta B^2 M / (4 c^2).
double pressure_shape(double eps, double delta, double psi) {
  const double d = 1.0 - eps * std::cos(psi);
  return -std::sin(psi + delta) / (d * d * d);
}

/// Where pressure_shape peaks in (low, low + pi): the best sample, then Newton on the zero of the
/// derivative's numerator g = cos(psi + delta) d - 3 eps sin(psi + delta) sin psi, kept inside the
/// bracket of its neighbouring samples.
double peak_shape(double eps, double delta, double low) {
  const double step = std::numbers::pi / kMaxPressureSamples;
  int best = 0;
  double best_value = -1.0;
  for (int k = 0; k < kMaxPressureSamples; ++k) {
    const double value = pressure_shape(eps, delta, low + (k + 0.5) * step);
    if (value > best_value) {
      best_value = value;
      best = k;
    }
  }
  const double left = low + best * step, right = left + step;
  double psi = left + 0.5 * step;
  for (int iteration = 0; iteration < kMaxPressureNewtonSteps; ++iteration) {
    const double sp = std::sin(psi + delta), cp = std::cos(psi + delta);
    const double d = 1.0 - eps * std::cos(psi);
    const double g = cp * d - 3.0 * eps * sp * std::sin(psi);
    const double dg = -sp * d + cp * eps * std::sin(psi) -
                      3.0 * eps * (cp * std::sin(psi) + sp * std::cos(psi));
    if (dg == 0.0) break;
    psi = std::clamp(psi - g / dg, left, right);
  }
  return std::max(best_value, pressure_shape(eps, delta, psi));
}

}  // namespace

PlanarFilmLoad short_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                  double viscosity) {
  validate(bearing, state, viscosity);
  const double eps = state.eccentricity_ratio;
  // G = (6 eta / c^2) (a sin psi + b cos psi) / (1 - eps cos psi)^3 = (6 eta / c^2) M sin(psi + delta) / ...
  const double a = eps * (state.journal_spin - 2.0 * state.line_of_centres_rate);
  const double b = -2.0 * state.eccentricity_ratio_rate;
  const double m = std::hypot(a, b);
  PlanarFilmLoad load;
  if (m == 0.0) return load;  // no wedge, no squeeze: no pressure
  const double delta = std::atan2(b, a);
  // p > 0 where G < 0: psi + delta in (pi, 2 pi).
  const double low = std::numbers::pi - delta;
  const detail::KernelIntegrals j = detail::kernel_integrals(eps, low, low + std::numbers::pi);
  // F . e_hat = (R B^3 / 12) integral of G cos psi; F . t_hat likewise with sin psi.
  const double c = bearing.radial_clearance;
  const double scale = viscosity * bearing.radius * std::pow(bearing.width, 3) / (2.0 * c * c);
  load.radial = scale * (a * j.sc + b * j.cc);
  load.tangential = scale * (a * j.ss + b * j.sc);
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = std::atan2(load.tangential, -load.radial);
  load.max_pressure = 3.0 * viscosity * bearing.width * bearing.width * m / (4.0 * c * c) *
                      peak_shape(eps, delta, low);
  // Flow out of both ends, -(h^3 / 12 eta) dp/dz at z = +-B/2, over the positive half period:
  // R B c M exactly (the h^3 cancels).
  load.side_flow = bearing.radius * bearing.width * c * m;
  return load;
}

}  // namespace clearjoint::lubrication
