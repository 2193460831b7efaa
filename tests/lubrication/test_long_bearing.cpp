// SPDX-License-Identifier: BSD-3-Clause
// The long-bearing closed form against its textbook formulas and against brute-force integration
// of the Reynolds equation in psi.
#include "clearjoint/lubrication/long_bearing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace clearjoint::lubrication {
namespace {

const double kPi = std::numbers::pi;
const PlanarBearing kBearing{0.01, 0.05, 1e-5};
const double kViscosity = 0.05;

TEST(LongBearing, GivesTheSommerfeldNumberAndAttitudeOfTheGuembelSolution) {
  for (const double eps : {0.1, 0.5, 0.9}) {
    const PlanarFilmLoad load = long_bearing_load(kBearing, {eps, 0.0, 0.0, 100.0}, kViscosity);
    const double psi = kBearing.radial_clearance / kBearing.radius;
    const double so = 3 * eps * std::sqrt(kPi * kPi * (1 - eps * eps) + 4 * eps * eps) /
                      ((2 + eps * eps) * (1 - eps * eps));
    EXPECT_NEAR(load.magnitude * psi * psi / (kBearing.width * 2 * kBearing.radius * kViscosity * 100.0),
                so, 1e-11 * so);
    EXPECT_NEAR(std::tan(load.attitude_angle), kPi * std::sqrt(1 - eps * eps) / (2 * eps), 1e-10);
  }
}

// Trapezoidal integration of p' from psi = pi, the periodic constant found numerically.
PlanarFilmLoad quadrature(const PlanarFilmState& s) {
  const int n = 400000;
  const double eps = s.eccentricity_ratio, omega = s.journal_spin - 2 * s.line_of_centres_rate;
  const double k = 6 * kViscosity * kBearing.radius * kBearing.radius /
                   (kBearing.radial_clearance * kBearing.radial_clearance);
  auto shape = [&](double psi, double constant) {
    const double d = 1 - eps * std::cos(psi);
    return (constant - eps * omega * std::cos(psi) - 2 * s.eccentricity_ratio_rate * std::sin(psi)) /
           (d * d * d);
  };
  // Periodicity: int (constant + rest) / d^3 = 0 fixes the constant.
  double i0 = 0, rest = 0;
  for (int j = 0; j < n; ++j) {
    const double psi = (j + 0.5) * 2 * kPi / n;
    i0 += shape(psi, 1.0) - shape(psi, 0.0);
    rest += shape(psi, 0.0);
  }
  const double constant = -rest / i0;
  std::vector<double> p(n + 1, 0.0);
  const double h = 2 * kPi / n;
  for (int j = 0; j < n; ++j) {
    const double psi = kPi + j * h;
    p[j + 1] = p[j] + 0.5 * h * (shape(psi, constant) + shape(psi + h, constant)) * k;
  }
  PlanarFilmLoad load;
  for (int j = 0; j < n; ++j) {
    const double psi = kPi + j * h;
    if (p[j] <= 0) continue;
    load.radial -= p[j] * std::cos(psi) * kBearing.radius * kBearing.width * h;
    load.tangential -= p[j] * std::sin(psi) * kBearing.radius * kBearing.width * h;
    load.max_pressure = std::max(load.max_pressure, p[j]);
  }
  return load;
}

TEST(LongBearing, AgreesWithIntegratingItsReynoldsEquationForRotationWhirlAndSqueeze) {
  // Rotation with whirl, rotation with squeeze, pure squeeze (approach and separation, the
  // second with its positive region on the other side), a centred journal pushed off, and a
  // separating journal whose spin still builds a film.
  const PlanarFilmState states[] = {{0.3, 0.0, 5.0, 80.0}, {0.6, 2.0, 0.0, 100.0},
                                    {0.7, 5.0, 0.0, 0.0},  {0.4, -4.0, 0.0, 0.0},
                                    {0.0, 4.0, 0.0, 0.0},  {0.5, -3.0, 10.0, 60.0},
                                    {0.9, 0.5, -2.0, 30.0}};
  for (const PlanarFilmState& state : states) {
    const PlanarFilmLoad closed = long_bearing_load(kBearing, state, kViscosity);
    const PlanarFilmLoad brute = quadrature(state);
    EXPECT_NEAR(closed.radial, brute.radial, 1e-5 * closed.magnitude);
    EXPECT_NEAR(closed.tangential, brute.tangential, 1e-5 * closed.magnitude);
    EXPECT_NEAR(closed.max_pressure, brute.max_pressure, 1e-5 * closed.max_pressure);
  }
}

TEST(LongBearing, CarriesNoLoadWhenCentredAndStill) {
  EXPECT_EQ(long_bearing_load(kBearing, {0.0, 0.0, 0.0, 100.0}, kViscosity).magnitude, 0.0);
}

TEST(LongBearing, MirrorsItsForceWhenTheSpinIsReversed) {
  const PlanarFilmLoad forward = long_bearing_load(kBearing, {0.6, 0.0, 0.0, 100.0}, kViscosity);
  const PlanarFilmLoad backward = long_bearing_load(kBearing, {0.6, 0.0, 0.0, -100.0}, kViscosity);
  EXPECT_NEAR(backward.radial, forward.radial, 1e-12 * forward.magnitude);
  EXPECT_NEAR(backward.tangential, -forward.tangential, 1e-12 * forward.magnitude);
}

}  // namespace
}  // namespace clearjoint::lubrication
