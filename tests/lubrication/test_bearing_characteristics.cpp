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
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

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
  for (const BearingMotion motion : kBearingMotions) {
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
  EXPECT_EQ(error_of(names), "method = 'finite': unknown (known: grid, short, long)");
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

}  // namespace
}  // namespace clearjoint::lubrication
