// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/short_bearing.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "sommerfeld_integrals.hpp"

namespace clearjoint::lubrication {

namespace {

/// Samples of the mid-plane pressure over its positive half period, evenly spaced in the
/// Sommerfeld angle gamma (sommerfeld_integrals.hpp), before Brent's method refines the largest
/// between its two neighbours. Even in gamma, the samples crowd where the film is thin: near
/// eps -> 1 the peak is O(sqrt(1 - eps)) wide in psi but O(1) in gamma, so 32 samples bracket it
/// for any eps < 1 (the tests compare with a dense multiprecision maximisation).
constexpr int kMaxPressureSamples = 32;
/// Brent's method to half the mantissa's bits (Boost's advice): the argument to 2^-25 of the
/// bracket, hence the peak value, at a maximum, to about (2^-25)^2 = 1e-15 relatively.
constexpr int kMaxPressureBits = std::numeric_limits<double>::digits / 2;
constexpr std::uintmax_t kMaxPressureIterations = 200;

/// 1 - eps cos psi = (1 - eps) + 2 eps sin^2(psi / 2): both terms positive, no cancellation
/// near psi = 0 where the film is thinnest and the pressure peaks.
double film_factor(double eps, double psi) {
  const double half = std::sin(0.5 * psi);
  return (1.0 - eps) + 2.0 * eps * half * half;
}

/// -sin(psi + delta) / (1 - eps cos psi)^3: the mid-plane pressure over 3 eta B^2 M / (4 c^2).
double pressure_shape(double eps, double delta, double psi) {
  const double d = film_factor(eps, psi);
  return -std::sin(psi + delta) / (d * d * d);
}

/// psi(gamma), the inverse of the Sommerfeld substitution, continuous in gamma:
/// cos psi = (cos g + eps) / (1 + eps cos g), sin psi = s sin g / (1 + eps cos g).
double psi_of_gamma(double eps, double s, double gamma) {
  const double principal = std::atan2(s * std::sin(gamma), std::cos(gamma) + eps);
  return gamma + std::remainder(principal - gamma, 2.0 * std::numbers::pi);
}

/// The largest pressure_shape on the positive half period psi in (low, low + pi). The period is
/// first shifted so that the multiple of 2 pi nearest its middle is 0: the peak, O(sqrt(1 - eps))
/// wide near psi = 0 as eps -> 1, is then located with the relative precision of psi near 0.
double peak_shape(double eps, double delta, double low) {
  const double pi = std::numbers::pi;
  const double start = low - 2.0 * pi * std::round((low + 0.5 * pi) / (2.0 * pi));
  const double end = start + pi;
  const double s = std::sqrt((1.0 - eps) * (1.0 + eps));
  const double g_start = detail::sommerfeld_angle(eps, start);
  const double g_step = (detail::sommerfeld_angle(eps, end) - g_start) / kMaxPressureSamples;
  std::array<double, kMaxPressureSamples + 2> psi{};  // the samples between the two ends
  psi.front() = start;
  psi.back() = end;
  int best = 1;
  double best_value = -1.0;
  for (int k = 1; k <= kMaxPressureSamples; ++k) {
    psi[k] = std::clamp(psi_of_gamma(eps, s, g_start + (k - 0.5) * g_step), start, end);
    const double value = pressure_shape(eps, delta, psi[k]);
    if (value > best_value) {
      best_value = value;
      best = k;
    }
  }
  // The peak lies between the best sample's neighbours (or an end, where the pressure is 0).
  // Brent's method runs in u = (psi - centre) / half-width in [-1, 1]: its tolerance, 2^-25 |u|
  // + 2^-27, is then relative to the bracket, which is about as wide as the peak (in psi itself
  // the absolute 2^-27 = 7.5e-9 rad exceeds a peak 1e-8 wide at eps = 1 - 2^-53).
  const double centre = 0.5 * (psi[best - 1] + psi[best + 1]);
  const double half_width = 0.5 * (psi[best + 1] - psi[best - 1]);
  std::uintmax_t iterations = kMaxPressureIterations;
  const auto refined = boost::math::tools::brent_find_minima(
      [&](double u) { return -pressure_shape(eps, delta, centre + u * half_width); }, -1.0, 1.0,
      kMaxPressureBits, iterations);
  return std::max(best_value, -refined.second);
}

/// The film's coefficients for a state: G's amplitude M and phase delta (G = (6 eta / c^2) M
/// sin(psi + delta) / (1 - eps cos psi)^3), and low, where the positive half period begins.
struct Coefficients {
  double a = 0.0, b = 0.0, m = 0.0, delta = 0.0, low = 0.0;
};

Coefficients coefficients_of(const PlanarFilmState& state) {
  Coefficients k;
  // G = (6 eta / c^2) (a sin psi + b cos psi) / (1 - eps cos psi)^3 = (6 eta / c^2) M sin(psi + delta) / ...
  k.a = state.eccentricity_ratio * (state.journal_spin - 2.0 * state.line_of_centres_rate);
  k.b = -2.0 * state.eccentricity_ratio_rate;
  k.m = std::hypot(k.a, k.b);
  if (k.m == 0.0) return k;
  k.delta = std::atan2(k.b, k.a);
  // p > 0 where G < 0: psi + delta in (pi, 2 pi).
  k.low = std::numbers::pi - k.delta;
  return k;
}

}  // namespace

PlanarFilmLoad short_bearing_force(const PlanarBearing& bearing, const PlanarFilmState& state,
                                   double viscosity) {
  validate(bearing, state, viscosity);
  const double eps = state.eccentricity_ratio;
  const Coefficients k = coefficients_of(state);
  PlanarFilmLoad load;
  if (k.m == 0.0) return load;  // no wedge, no squeeze: no pressure
  const detail::KernelIntegrals j = detail::kernel_integrals(eps, k.low, k.low + std::numbers::pi);
  // F . e_hat = (R B^3 / 12) integral of G cos psi; F . t_hat likewise with sin psi.
  const double c = bearing.radial_clearance;
  const double scale = viscosity * bearing.radius * std::pow(bearing.width, 3) / (2.0 * c * c);
  load.radial = scale * (k.a * j.sc + k.b * j.cc);
  load.tangential = scale * (k.a * j.ss + k.b * j.sc);
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = std::atan2(load.tangential, -load.radial);
  load.max_pressure = std::numeric_limits<double>::quiet_NaN();
  // Flow out of both ends, -(h^3 / 12 eta) dp/dz at z = +-B/2, over the positive half period:
  // R B c M exactly (the h^3 cancels).
  load.side_flow = bearing.radius * bearing.width * c * k.m;
  return load;
}

PlanarFilmLoad short_bearing_load(const PlanarBearing& bearing, const PlanarFilmState& state,
                                  double viscosity) {
  PlanarFilmLoad load = short_bearing_force(bearing, state, viscosity);
  const Coefficients k = coefficients_of(state);
  if (k.m == 0.0) return load;
  const double c = bearing.radial_clearance;
  load.max_pressure = 3.0 * viscosity * bearing.width * bearing.width * k.m / (4.0 * c * c) *
                      peak_shape(state.eccentricity_ratio, k.delta, k.low);
  return load;
}

}  // namespace clearjoint::lubrication
