// SPDX-License-Identifier: BSD-3-Clause
// The handbook query against published finite-width bearing data: Raimondi & Boyd, "A solution
// for the finite journal bearing and its application to analysis and design, parts I-III", ASLE
// Transactions 1 (1958) 159-209, full (360 degree) bearing table as reproduced in Budynas &
// Nisbett, Shigley's Mechanical Engineering Design, chapter 12 (the table behind its Figs.
// 12-16 to 12-24). Columns used: h0/c (= 1 - eps), S = (r/c)^2 mu N / P and phi (degrees).
// R & B feed the film at ambient pressure at the thickest film and rupture it with the Reynolds
// condition, which the mass-conserving grid reproduces (bearing_characteristics.hpp).
// The table has no B/D = 1/8 and no pure-squeeze data, and no published table of either was found
// (docs/lubrication.md, Published data): for those, a labelled check against the short-bearing
// limit stands in, which is not a published comparison.
#include "clearjoint/lubrication/bearing_characteristics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {
namespace {

struct PublishedRow {
  double width_ratio, eccentricity_ratio, raimondi_boyd_s, attitude_degrees;
};

// Raimondi & Boyd (1958), via Shigley ch. 12: l/d = 1, 1/2, 1/4; h0/c = 0.9, 0.8, 0.6, 0.4, 0.2, 0.1.
constexpr PublishedRow kRaimondiBoyd[] = {
    {1.0, 0.1, 1.33, 79.5},    {1.0, 0.2, 0.631, 74.02},  {1.0, 0.4, 0.264, 63.10},
    {1.0, 0.6, 0.121, 50.58},  {1.0, 0.8, 0.0446, 36.24}, {1.0, 0.9, 0.0188, 26.45},
    {0.5, 0.1, 4.31, 81.62},   {0.5, 0.2, 2.03, 74.94},   {0.5, 0.4, 0.779, 61.45},
    {0.5, 0.6, 0.319, 48.14},  {0.5, 0.8, 0.0923, 33.31}, {0.5, 0.9, 0.0313, 23.66},
    {0.25, 0.1, 16.2, 82.31},  {0.25, 0.2, 7.57, 75.18},  {0.25, 0.4, 2.83, 60.86},
    {0.25, 0.6, 1.07, 46.72},  {0.25, 0.8, 0.261, 31.04}, {0.25, 0.9, 0.0736, 21.85},
};

// Issue 36's acceptance: So within 3 % on average and 5 % at worst, beta within 2 % and 4 %.
constexpr double kMeanSommerfeldTolerance = 0.03, kWorstSommerfeldTolerance = 0.05;
constexpr double kMeanAttitudeTolerance = 0.02, kWorstAttitudeTolerance = 0.04;

// The grid the comparison runs on, and the one whose cost bench/lubrication/film_bench.cpp
// measures. Against the rows below, 32 x 8 is the coarsest that still passes (So within 1.8 %
// on average, 3.1 % at worst); 48 x 12 keeps the worst So error near 2 %, under half of the
// tolerance, and 96 x 24 brings it only to 1.2 % (the tables' own rounding is of that order).
constexpr int kComparisonCircumferentialCells = 48, kComparisonAxialCells = 12;

BearingCharacteristicsQuery on_comparison_grid(double eccentricity_ratio, double width_ratio) {
  BearingCharacteristicsQuery query;
  query.eccentricity_ratio = eccentricity_ratio;
  query.width_ratio = width_ratio;
  query.grid.circumferential_cells = kComparisonCircumferentialCells;
  query.grid.axial_cells = kComparisonAxialCells;
  return query;
}

TEST(BearingCharacteristics, AgreeWithRaimondiAndBoydForPureRotationWithMassConservation) {
  double so_sum = 0, so_worst = 0, beta_sum = 0, beta_worst = 0;
  for (const PublishedRow& row : kRaimondiBoyd) {
    const BearingCharacteristics result =
        bearing_characteristics(on_comparison_grid(row.eccentricity_ratio, row.width_ratio));
    ASSERT_TRUE(result.converged);
    const double published_so = 1.0 / (2.0 * std::numbers::pi * row.raimondi_boyd_s);
    const double published_beta = row.attitude_degrees * std::numbers::pi / 180.0;
    const double so_error = std::abs(result.sommerfeld_number - published_so) / published_so;
    const double beta_error = std::abs(result.attitude_angle - published_beta) / published_beta;
    so_sum += so_error;
    beta_sum += beta_error;
    so_worst = std::max(so_worst, so_error);
    beta_worst = std::max(beta_worst, beta_error);
    RecordProperty("so_error_bd" + std::to_string(row.width_ratio) + "_eps" +
                       std::to_string(row.eccentricity_ratio),
                   std::to_string(so_error));
  }
  const double rows = std::size(kRaimondiBoyd);
  EXPECT_LT(so_sum / rows, kMeanSommerfeldTolerance);
  EXPECT_LT(so_worst, kWorstSommerfeldTolerance);
  EXPECT_LT(beta_sum / rows, kMeanAttitudeTolerance);
  EXPECT_LT(beta_worst, kWorstAttitudeTolerance);
}

// Not published data: the short-bearing (Ocvirk) limit. It neglects the circumferential pressure
// flow, so it overestimates So by a gap of order (B/D)^2 that grows with eps (28 % at B/D = 1/4,
// eps = 0.9, where the grid meets Raimondi & Boyd within 1 %). Halving B/D from 1/4 to 1/8 must
// therefore shrink the gap by a factor near 4: measured 2.9 to 3.5 on the 96 x 24 grid (the
// next term of the expansion still counts at eps = 0.9), so the bounds are 2.5 and 4.5. The
// attitude angle's own gap is 1.2 % at worst at B/D = 1/8 (rotation); pure squeeze loads along
// the line of centres.
constexpr double kSmallestGapRatio = 2.5, kLargestGapRatio = 4.5;
constexpr double kShortBearingAttitudeGap = 0.02;
constexpr double kSqueezeAttitude = 1e-6;  // rad: zero but for rounding in the force's sum

TEST(BearingCharacteristics, TendToTheShortBearingAtOneEighthWidthForRotationAndSqueeze) {
  for (const BearingMotion motion : {BearingMotion::rotation, BearingMotion::squeeze}) {
    for (const double eps : {0.1, 0.2, 0.4, 0.6, 0.8, 0.9}) {
      double gap[2] = {0.0, 0.0};
      for (int k = 0; k < 2; ++k) {
        BearingCharacteristicsQuery query;  // the default grid, 96 x 24, mass-conserving
        query.eccentricity_ratio = eps;
        query.width_ratio = k == 0 ? 0.25 : 0.125;
        query.motion = motion;
        const BearingCharacteristics grid = bearing_characteristics(query);
        ASSERT_TRUE(grid.converged);
        query.method = BearingMethod::short_bearing;
        query.cavitation = CavitationModel::half_sommerfeld;
        const BearingCharacteristics ocvirk = bearing_characteristics(query);
        gap[k] = (ocvirk.sommerfeld_number - grid.sommerfeld_number) / ocvirk.sommerfeld_number;
        EXPECT_GT(gap[k], 0.0) << to_string(motion) << " eps " << eps;
        if (k == 1 && motion == BearingMotion::rotation) {
          EXPECT_NEAR(grid.attitude_angle, ocvirk.attitude_angle,
                      kShortBearingAttitudeGap * ocvirk.attitude_angle) << "eps " << eps;
        }
        if (motion == BearingMotion::squeeze) {
          EXPECT_NEAR(grid.attitude_angle, 0.0, kSqueezeAttitude) << "eps " << eps;
        }
      }
      const double ratio = gap[0] / gap[1];
      EXPECT_GT(ratio, kSmallestGapRatio) << to_string(motion) << " eps " << eps;
      EXPECT_LT(ratio, kLargestGapRatio) << to_string(motion) << " eps " << eps;
      RecordProperty(std::string(to_string(motion)) + "_gap_bd0.125_eps" + std::to_string(eps),
                     std::to_string(gap[1]));
    }
  }
}

TEST(BearingCharacteristics, OfTheClosedFormsBracketTheFiniteHalfSommerfeldGrid) {
  for (const double bd : {0.25, 1.0, 2.0}) {
    BearingCharacteristicsQuery query;
    query.eccentricity_ratio = 0.5;
    query.width_ratio = bd;
    query.cavitation = CavitationModel::half_sommerfeld;
    const double grid = bearing_characteristics(query).sommerfeld_number;
    query.method = BearingMethod::short_bearing;
    const double short_so = bearing_characteristics(query).sommerfeld_number;
    query.method = BearingMethod::long_bearing;
    const double long_so = bearing_characteristics(query).sommerfeld_number;
    // Per unit B/D^2 (short) the finite film carries less; per unit width (long) too.
    EXPECT_LT(grid, short_so);
    EXPECT_LT(grid, long_so);
  }
}

TEST(BearingCharacteristics, OfPureSqueezeMatchTheShortBearingForANarrowBearing) {
  BearingCharacteristicsQuery query;
  query.eccentricity_ratio = 0.5;
  query.width_ratio = 0.125;
  query.motion = BearingMotion::squeeze;
  query.cavitation = CavitationModel::half_sommerfeld;
  query.grid.circumferential_cells = 128;
  query.grid.axial_cells = 16;
  const BearingCharacteristics grid = bearing_characteristics(query);
  query.method = BearingMethod::short_bearing;
  const BearingCharacteristics closed = bearing_characteristics(query);
  EXPECT_NEAR(grid.sommerfeld_number, closed.sommerfeld_number, 0.05 * closed.sommerfeld_number);
  EXPECT_NEAR(grid.attitude_angle, 0.0, 1e-6);  // pure squeeze: load along the line of centres
}

TEST(BearingCharacteristics, RefuseBadInputNamingIt) {
  BearingCharacteristicsQuery query;
  query.eccentricity_ratio = 1.0;
  try {
    bearing_characteristics(query);
    FAIL();
  } catch (const geometry::InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("eccentricity_ratio"), std::string::npos);
  }
  query.eccentricity_ratio = 0.5;
  query.grid.circumferential_cells = 1;
  query.grid.axial_cells = 1;
  EXPECT_THROW(bearing_characteristics(query), geometry::InvalidInput);
  query.grid = {};
  query.method = BearingMethod::short_bearing;  // closed forms know no mass conservation
  EXPECT_THROW(bearing_characteristics(query), geometry::InvalidInput);
}

// The closed forms' outputs against the textbook formulas evaluated with 50 digits
// (Boost.Multiprecision's cpp_bin_float_50), at eps = 1 - 2^-k for every k to the last double
// below 1 and at a few others, for pure rotation and pure squeeze. The input eps is the double
// given; 1 - eps^2 is formed from it exactly in 50 digits.
using Real = boost::multiprecision::cpp_bin_float_50;

struct Expected {
  Real sommerfeld, attitude, side_flow, pressure_ratio;
};

/// Sommerfeld (long bearing, half-Sommerfeld), Pinkus & Sternlicht ch. 3 / Hamrock,
/// Fundamentals of Fluid Film Lubrication ch. 10: rotation So = 3 eps sqrt(pi^2 (1 - eps^2) +
/// 4 eps^2) / ((2 + eps^2)(1 - eps^2)), tan beta = pi sqrt(1 - eps^2) / (2 eps), and the pressure
/// 6 eta omega R^2 / c^2 eps sin t (2 + eps cos t) / ((2 + eps^2)(1 + eps cos t)^2) peaking at
/// cos t = -3 eps / (2 + eps^2); squeeze W = 12 pi eta R^3 B eps' / (c^2 (1 - eps^2)^3/2), so
/// So = 6 pi / (1 - eps^2)^3/2, beta = 0, and the peak 4 k eps' / (1 - eps^2)^2 at the thinnest
/// film (the pressure's integral from psi = pi to 0 of -2 k eps' sin psi / (1 - eps cos psi)^3).
Expected long_bearing(double eps_in, bool rotation) {
  const Real pi = boost::math::constants::pi<Real>();
  const Real eps = eps_in, s2 = (1 - eps) * (1 + eps), s = sqrt(s2);
  if (!rotation) return {6 * pi / (s2 * s), 0, 0, 4 / (pi * s)};
  const Real so = 3 * eps * sqrt(pi * pi * s2 + 4 * eps * eps) / ((2 + eps * eps) * s2);
  const Real cos_t = -3 * eps / (2 + eps * eps), sin_t = sqrt((1 - cos_t) * (1 + cos_t));
  const Real peak = eps * sin_t * (2 + eps * cos_t) / ((2 + eps * eps) * pow(1 + eps * cos_t, 2));
  // F / (B D) = So eta omega / psi^2 and p = k omega (...) with k psi^2 / eta = 6: p / (F / (B D))
  // = 6 peak / So.
  return {so, atan2(pi * s, 2 * eps), 0, 6 * peak / so};
}

/// Ocvirk (short bearing, half-Sommerfeld), same references: rotation So = (B/D)^2 eps
/// sqrt(pi^2 (1 - eps^2) + 16 eps^2) / (2 (1 - eps^2)^2), tan beta = pi sqrt(1 - eps^2) / (4 eps),
/// side flow 2 pi Q_s / (R c omega B) = 2 pi eps, mid-plane pressure 3 eta omega B^2 eps sin t /
/// (4 c^2 (1 + eps cos t)^3) peaking at cos t = (1 - sqrt(1 + 24 eps^2)) / (4 eps); squeeze: the
/// load 2 (B/D)^2 J with J the integral of cos^2 / (1 - eps cos)^3 over (-pi/2, pi/2), beta = 0,
/// side flow 4 pi, peak 3 eta B^2 eps' / (2 c^2 (1 - eps)^3) at psi = 0. J by t = tan(psi / 2)
/// (not the library's Sommerfeld substitution): with a = 1 - eps, b = 1 + eps, w = a + b t^2,
/// 1 - eps cos psi = w / (1 + t^2) and (1 - t^2)^2 = (2 - w)^2 / b^2 (a + b = 2), so
/// J = (2 / b^2) (4 K3 - 4 K2 + K1), Kn the integral of w^-n over t in (-1, 1):
/// K1 = 2 atan(sqrt(b / a)) / sqrt(a b), K(n+1) = [t / (2 n a w^n)] + (2n - 1) / (2 n a) Kn,
/// i.e. K2 = 1 / (2 a) + K1 / (2 a), K3 = 1 / (8 a) + 3 K2 / (4 a).
Expected short_bearing(double eps_in, double bd, bool rotation) {
  const Real pi = boost::math::constants::pi<Real>();
  const Real eps = eps_in, s2 = (1 - eps) * (1 + eps), s = sqrt(s2), b = bd;
  if (rotation) {
    const Real so = b * b * eps * sqrt(pi * pi * s2 + 16 * eps * eps) / (2 * s2 * s2);
    const Real cos_t = (1 - sqrt(1 + 24 * eps * eps)) / (4 * eps);
    const Real sin_t = sqrt((1 - cos_t) * (1 + cos_t));
    // p / (F / (B D)) = p psi^2 / (So eta omega) = 3 (B/D)^2 eps sin t / ((1 + eps cos t)^3 So).
    return {so, atan2(pi * s, 4 * eps), 2 * pi * eps, 3 * b * b * eps * sin_t / (pow(1 + eps * cos_t, 3) * so)};
  }
  const Real a = 1 - eps, bb = 1 + eps;
  const Real k1 = 2 * atan(sqrt(bb / a)) / sqrt(a * bb);
  const Real k2 = 1 / (2 * a) + k1 / (2 * a);
  const Real k3 = 1 / (8 * a) + 3 * k2 / (4 * a);
  const Real j = 2 / (bb * bb) * (4 * k3 - 4 * k2 + k1);
  const Real so = 2 * b * b * j;
  return {so, 0, 4 * pi, 6 * b * b / (pow(1 - eps, 3) * so)};
}

double relative_error(double value, const Real& expected) {
  if (expected == 0) return std::abs(value);
  return static_cast<double>(abs((Real(value) - expected) / expected));
}

TEST(BearingCharacteristics, OfTheClosedFormsAreExactToTheirStatedErrorUpToTheLastDoubleBelowOne) {
  std::vector<double> eccentricities = {1e-100, 1e-8, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99};
  for (int k = 1; k <= 53; ++k) eccentricities.push_back(1.0 - std::ldexp(1.0, -k));
  double worst = 0.0;
  int checked = 0;
  for (const double eps : eccentricities) {
    for (const BearingMethod method : {BearingMethod::short_bearing, BearingMethod::long_bearing}) {
      for (const BearingMotion motion : {BearingMotion::rotation, BearingMotion::squeeze}) {
        for (const double bd : {1.0, 0.25}) {
          BearingCharacteristicsQuery query;
          query.eccentricity_ratio = eps;
          query.width_ratio = bd;
          query.method = method;
          query.motion = motion;
          query.cavitation = CavitationModel::half_sommerfeld;
          const BearingCharacteristics r = bearing_characteristics(query);
          const bool rotation = motion == BearingMotion::rotation;
          const Expected e = method == BearingMethod::long_bearing ? long_bearing(eps, rotation)
                                                                   : short_bearing(eps, bd, rotation);
          const double errors[] = {relative_error(r.sommerfeld_number, e.sommerfeld),
                                   relative_error(r.attitude_angle, e.attitude),
                                   relative_error(r.side_flow_variable, e.side_flow),
                                   relative_error(r.max_pressure_ratio, e.pressure_ratio)};
          const char* names[] = {"sommerfeld_number", "attitude_angle", "side_flow_variable",
                                 "max_pressure_ratio"};
          for (int q = 0; q < 4; ++q) {
            EXPECT_LE(errors[q], kClosedFormRelativeError)
                << names[q] << " at eps = 1 - " << 1.0 - eps << ", " << to_string(method) << ", "
                << to_string(motion) << ", B/D " << bd;
            worst = std::max(worst, errors[q]);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 61 * 2 * 2 * 2 * 4);
  std::ostringstream text;
  text << worst;
  RecordProperty("worst_relative_error", text.str());
}

TEST(BearingCharacteristics, RefuseAWidthRatioOrEccentricityWhoseOutputsWouldOverOrUnderflow) {
  const auto error = [](double eps, double bd) {
    BearingCharacteristicsQuery query;
    query.eccentricity_ratio = eps;
    query.width_ratio = bd;
    query.method = BearingMethod::short_bearing;
    query.cavitation = CavitationModel::half_sommerfeld;
    try {
      bearing_characteristics(query);
    } catch (const geometry::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(0.5, 1e149), "width_ratio = 1e+149: must be in [1e-50, 1e50] "
                               "(beyond, the outputs over- or underflow)");
  EXPECT_EQ(error(0.5, 1e-150).rfind("width_ratio = ", 0), 0u);
  EXPECT_EQ(error(0.5, 1e300).rfind("width_ratio = ", 0), 0u);
  EXPECT_EQ(error(1e-200, 1.0).rfind("eccentricity_ratio = ", 0), 0u);
  EXPECT_EQ(error(0.5, kLargestWidthRatio), "no error");
  EXPECT_EQ(error(kSmallestEccentricityRatio, kSmallestWidthRatio), "no error");
  EXPECT_EQ(error(0.0, 1.0), "no error");
}

std::string error_of(const BearingCharacteristicsNames& names) {
  try {
    query_from_names(0.5, 1.0, names);
  } catch (const geometry::InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(BearingCharacteristicsQueryFromNames, TakesTheLibrarysNamesAndDefaults) {
  BearingCharacteristicsNames names;
  const BearingCharacteristicsQuery defaults = query_from_names(0.5, 0.25, names);
  EXPECT_EQ(defaults.eccentricity_ratio, 0.5);
  EXPECT_EQ(defaults.width_ratio, 0.25);
  EXPECT_EQ(defaults.motion, BearingMotion::rotation);
  EXPECT_EQ(defaults.method, BearingMethod::grid);
  EXPECT_EQ(defaults.cavitation, CavitationModel::mass_conserving);
  EXPECT_EQ(defaults.grid.circumferential_cells, ReynoldsGridOptions{}.circumferential_cells);
  names.motion = "squeeze";
  names.method = "short";
  names.grid = std::pair{40, 10};
  const BearingCharacteristicsQuery named = query_from_names(0.5, 0.25, names);
  EXPECT_EQ(named.motion, BearingMotion::squeeze);
  EXPECT_EQ(named.method, BearingMethod::short_bearing);
  EXPECT_EQ(named.cavitation, CavitationModel::half_sommerfeld);  // the closed forms' default
  EXPECT_EQ(named.grid.circumferential_cells, 40);
  EXPECT_EQ(named.grid.axial_cells, 10);
  names.cavitation = "mass_conserving";
  EXPECT_EQ(query_from_names(0.5, 0.25, names).cavitation, CavitationModel::mass_conserving);
}

TEST(BearingCharacteristicsQueryFromNames, NamesTheFieldAndTheValueItRefuses) {
  BearingCharacteristicsNames names;
  names.motion = "spin";
  EXPECT_EQ(error_of(names), "motion = 'spin': unknown (known: rotation, squeeze)");
  names = {};
  names.method = "finite";
  EXPECT_EQ(error_of(names), "method = 'finite': unknown (known: grid, short, long, table)");
  names = {};
  names.cavitation = "jfo";
  EXPECT_EQ(error_of(names),
            "cavitation = 'jfo': unknown (known: half_sommerfeld, mass_conserving)");
  names = {};
  names.grid = std::pair{1, 1};
  EXPECT_EQ(error_of(names), "grid = 1x1: options.circumferential_cells = 1: must be at least 8");
  names.grid = std::pair{8, 1};
  EXPECT_EQ(error_of(names).rfind("grid = 8x1: options.axial_cells = 1: ", 0), 0u);
}

// The table reproduces the half-Sommerfeld grid it tabulates: So, beta, side flow and peak
// pressure within 0.5 % (the force's error bound, FilmTable::error_bound, is below it), for both
// motions; beyond its reach it names eps.
constexpr double kTableTolerance = 5e-3;

TEST(BearingCharacteristics, FromTheTableMatchTheHalfSommerfeldGrid) {
  for (const BearingMotion motion : {BearingMotion::rotation, BearingMotion::squeeze}) {
    for (const double eps : {0.2, 0.6, 0.9}) {
      BearingCharacteristicsQuery query;
      query.eccentricity_ratio = eps;
      query.width_ratio = 0.5;
      query.motion = motion;
      query.cavitation = CavitationModel::half_sommerfeld;
      query.grid.circumferential_cells = 48;
      query.grid.axial_cells = 12;
      const BearingCharacteristics grid = bearing_characteristics(query);
      query.method = BearingMethod::table;
      const BearingCharacteristics table = bearing_characteristics(query);
      EXPECT_NEAR(table.sommerfeld_number, grid.sommerfeld_number, kTableTolerance * grid.sommerfeld_number)
          << to_string(motion) << " eps " << eps;
      EXPECT_NEAR(table.side_flow_variable, grid.side_flow_variable, kTableTolerance * grid.side_flow_variable)
          << to_string(motion) << " eps " << eps;
      EXPECT_NEAR(table.max_pressure_ratio, grid.max_pressure_ratio, kTableTolerance * grid.max_pressure_ratio)
          << to_string(motion) << " eps " << eps;
      EXPECT_NEAR(table.attitude_angle, grid.attitude_angle, kTableTolerance) << to_string(motion) << " eps " << eps;
    }
  }
  BearingCharacteristicsQuery beyond;
  beyond.eccentricity_ratio = 0.99;
  beyond.method = BearingMethod::table;
  beyond.cavitation = CavitationModel::half_sommerfeld;
  beyond.grid.circumferential_cells = 48;
  beyond.grid.axial_cells = 12;
  try {
    bearing_characteristics(beyond);
    ADD_FAILURE() << "no error";
  } catch (const geometry::InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()),
              "eccentricity_ratio = 0.98999999999999999: beyond the table's reach (0.98, "
              "kTableLargestEccentricityRatio); use method = grid");
  }
  beyond.eccentricity_ratio = 0.5;
  beyond.cavitation = CavitationModel::mass_conserving;
  EXPECT_THROW(bearing_characteristics(beyond), geometry::InvalidInput);
}

TEST(BearingCharacteristics, OfTheGridAndTheTableRefuseAFilmWiderThanTheGridSolvesNamingTheWidthRatio) {
  // Measured before the limit: at B/D = 1e7 the grid's Sommerfeld number was 19 % off its limit
  // and the table's, built from that grid, 3e106 at 1e40.
  for (const BearingMethod method : {BearingMethod::grid, BearingMethod::table}) {
    BearingCharacteristicsQuery query;
    query.eccentricity_ratio = 0.5;
    query.method = method;
    query.cavitation = CavitationModel::half_sommerfeld;
    query.width_ratio = 1e7;
    try {
      bearing_characteristics(query);
      ADD_FAILURE() << to_string(method) << " accepted width_ratio = 1e7";
    } catch (const geometry::InvalidInput& e) {
      EXPECT_EQ(std::string(e.what()).rfind("width_ratio = 1e+07: the grid solves films at most 1e4", 0), 0u)
          << e.what();
    }
    query.width_ratio = kLargestGridWidthRatio;
    EXPECT_NO_THROW(bearing_characteristics(query)) << to_string(method);
  }
  // The closed forms have no such limit.
  BearingCharacteristicsQuery long_bearing;
  long_bearing.eccentricity_ratio = 0.5;
  long_bearing.method = BearingMethod::long_bearing;
  long_bearing.cavitation = CavitationModel::half_sommerfeld;
  long_bearing.width_ratio = 1e7;
  EXPECT_NO_THROW(bearing_characteristics(long_bearing));
}

}  // namespace
}  // namespace clearjoint::lubrication
