// SPDX-License-Identifier: BSD-3-Clause
// The short-bearing closed form against its textbook formulas and against brute-force quadrature
// of its own pressure (which checks the Sommerfeld-substitution integrals for any motion).
#include "clearjoint/lubrication/short_bearing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {
namespace {

const double kPi = std::numbers::pi;
const PlanarBearing kBearing{0.01, 0.005, 1e-5};
const double kViscosity = 0.05;

TEST(ShortBearing, GivesTheOcvirkSommerfeldNumberAndAttitudeForPureRotation) {
  for (const double eps : {0.1, 0.5, 0.9}) {
    PlanarFilmState state;
    state.eccentricity_ratio = eps;
    state.journal_spin = 100.0;
    const PlanarFilmLoad load = short_bearing_load(kBearing, state, kViscosity);
    const double bd = kBearing.width / (2.0 * kBearing.radius);
    const double psi = kBearing.radial_clearance / kBearing.radius;
    const double so = bd * bd * eps * std::sqrt(kPi * kPi * (1 - eps * eps) + 16 * eps * eps) /
                      (2 * std::pow(1 - eps * eps, 2));
    EXPECT_NEAR(load.magnitude * psi * psi / (kBearing.width * 2 * kBearing.radius * kViscosity * 100.0),
                so, 1e-12 * so);
    EXPECT_NEAR(std::tan(load.attitude_angle), kPi * std::sqrt(1 - eps * eps) / (4 * eps), 1e-11);
    EXPECT_LT(load.radial, 0.0);  // pushes the journal back to the centre
    EXPECT_NEAR(load.side_flow, eps * kBearing.radius * 100.0 * kBearing.radial_clearance * kBearing.width,
                1e-15);
  }
}

// p(psi, z) = G(psi) (z^2 - B^2/4) / 2 integrated by brute force where it is positive.
PlanarFilmLoad quadrature(const PlanarFilmState& s) {
  const int n = 200000;
  const double c = kBearing.radial_clearance, b = kBearing.width, r = kBearing.radius;
  double fr = 0, ft = 0, pmax = 0;
  for (int k = 0; k < n; ++k) {
    const double psi = (k + 0.5) * 2 * kPi / n;
    const double d = 1 - s.eccentricity_ratio * std::cos(psi);
    const double g = 6 * kViscosity / (c * c) *
                     (s.eccentricity_ratio * (s.journal_spin - 2 * s.line_of_centres_rate) * std::sin(psi) -
                      2 * s.eccentricity_ratio_rate * std::cos(psi)) / (d * d * d);
    if (g >= 0) continue;
    const double integral_over_z = -g * b * b * b / 12;  // int of p dz
    fr -= integral_over_z * std::cos(psi) * r * 2 * kPi / n;
    ft -= integral_over_z * std::sin(psi) * r * 2 * kPi / n;
    pmax = std::max(pmax, -g * b * b / 8);
  }
  PlanarFilmLoad load;
  load.radial = fr;
  load.tangential = ft;
  load.max_pressure = pmax;
  return load;
}

TEST(ShortBearing, AgreesWithQuadratureOfItsPressureForRotationWhirlAndSqueeze) {
  const PlanarFilmState states[] = {{0.3, 2.0, 5.0, 80.0}, {0.7, -5.0, 0.0, 0.0},
                                    {0.85, 1.0, 60.0, -20.0}, {0.5, 3.0, 0.0, 0.0}};
  for (const PlanarFilmState& state : states) {
    const PlanarFilmLoad closed = short_bearing_load(kBearing, state, kViscosity);
    const PlanarFilmLoad brute = quadrature(state);
    EXPECT_NEAR(closed.radial, brute.radial, 1e-6 * std::abs(closed.magnitude));
    EXPECT_NEAR(closed.tangential, brute.tangential, 1e-6 * std::abs(closed.magnitude));
    EXPECT_NEAR(closed.max_pressure, brute.max_pressure, 1e-6 * closed.max_pressure);
  }
}

TEST(ShortBearing, CarriesNoLoadWhenCentredAndStill) {
  PlanarFilmState state;
  state.journal_spin = 100.0;
  EXPECT_EQ(short_bearing_load(kBearing, state, kViscosity).magnitude, 0.0);
}

TEST(ShortBearing, MirrorsItsForceWhenTheSpinIsReversed) {
  PlanarFilmState state{0.6, 0.0, 0.0, 100.0};
  const PlanarFilmLoad forward = short_bearing_load(kBearing, state, kViscosity);
  state.journal_spin = -100.0;
  const PlanarFilmLoad backward = short_bearing_load(kBearing, state, kViscosity);
  EXPECT_NEAR(backward.radial, forward.radial, 1e-12 * forward.magnitude);
  EXPECT_NEAR(backward.tangential, -forward.tangential, 1e-12 * forward.magnitude);
  EXPECT_NEAR(backward.attitude_angle, -forward.attitude_angle, 1e-12);
}

TEST(ShortBearing, RefusesBadInputNamingIt) {
  PlanarFilmState state{1.0, 0.0, 0.0, 1.0};
  EXPECT_THROW(short_bearing_load(kBearing, state, kViscosity), geometry::InvalidInput);
  state.eccentricity_ratio = 0.5;
  try {
    short_bearing_load(kBearing, state, -1.0);
    FAIL();
  } catch (const geometry::InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("viscosity"), std::string::npos);
  }
}

}  // namespace
}  // namespace clearjoint::lubrication
