// SPDX-License-Identifier: BSD-3-Clause
// The lubricated joint's parameters and the rule that passes from the film to dry contact
// (joint_lubrication.hpp). The film itself, through the joint, is in test_joint_film.cpp.

#include "clearjoint/dynamics/joint_lubrication.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

constexpr double kLimit = 2e-6;  // m, h_l
constexpr double kWidth = 1e-6;  // m, w
constexpr double kClearance = 1e-4;  // m, c: the paper's Table 2 joint

JointLubrication oil() {
  JointLubrication l;
  l.viscosity = 0.04;
  l.film_thickness_limit = kLimit;
  l.transition_width = kWidth;
  return l;
}

std::string error_of(const JointLubrication& l) {
  try {
    validate(l, "joint.lubrication", kClearance);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FilmWeight, IsZeroBelowTheLimitOneAboveTheBandAndSmoothstepBetween) {
  const JointLubrication l = oil();
  EXPECT_EQ(film_weight(l, -1e-6), 0.0);
  EXPECT_EQ(film_weight(l, kLimit), 0.0);
  EXPECT_EQ(film_weight(l, kLimit + kWidth), 1.0);
  EXPECT_EQ(film_weight(l, 1e-4), 1.0);
  // (h - h_l) / w is rounded once or twice (a few ulps of h_l / w = 2).
  EXPECT_NEAR(film_weight(l, kLimit + 0.5 * kWidth), 0.5, 1e-14);
  EXPECT_NEAR(film_weight(l, kLimit + 0.25 * kWidth), 0.25 * 0.25 * 2.5, 1e-14);
}

// Continuous with a continuous slope: the jump between neighbours shrinks as the step squared at
// the band's ends (zero slope there) and linearly inside; the weight never decreases.
TEST(FilmWeight, IsContinuousWithZeroSlopeAtBothEndsOfTheBand) {
  const JointLubrication l = oil();
  for (double h : {kLimit, kLimit + kWidth}) {
    for (double step : {1e-9, 1e-10}) {
      EXPECT_LT(std::abs(film_weight(l, h + step) - film_weight(l, h - step)),
                4.0 * (step / kWidth) * (step / kWidth))
          << h << " " << step;
    }
  }
  double previous = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    const double w = film_weight(l, kLimit - 0.5 * kWidth + 2e-3 * k * kWidth);
    EXPECT_GE(w, previous);
    EXPECT_LE(w - previous, 1.5 * 2e-3 + 1e-15);  // slope at most 3/2 per band width
    previous = w;
  }
}

TEST(FilmRegime, NamesDryFilmAndBlendByTheWeight) {
  EXPECT_EQ(film_regime(0.0), FilmRegime::dry);
  EXPECT_EQ(film_regime(1.0), FilmRegime::film);
  EXPECT_EQ(film_regime(0.3), FilmRegime::blend);
  EXPECT_EQ(static_cast<int>(FilmRegime::dry), 0);
  EXPECT_EQ(static_cast<int>(FilmRegime::film), 1);
  EXPECT_EQ(static_cast<int>(FilmRegime::blend), 2);
}

TEST(JointLubrication, NamesTheFieldOfANegativeViscosityABadLimitAndATinyGrid) {
  JointLubrication l = oil();
  EXPECT_EQ(error_of(l), "no error");
  l.viscosity = -0.04;
  EXPECT_EQ(error_of(l), "joint.lubrication.viscosity = -0.040000000000000001: must be positive");
  l = oil();
  l.film_thickness_limit = 0.0;
  EXPECT_EQ(error_of(l), "joint.lubrication.film_thickness_limit = 0: must be positive");
  l = oil();
  l.method = FilmMethod::grid;
  l.circumferential_cells = l.axial_cells = 1;
  EXPECT_EQ(error_of(l), "joint.lubrication.grid = [1, 1]: options.circumferential_cells = 1: must be at least 8");
}

TEST(JointLubrication, NamesTheFieldAndTheRangeOfAViscositySupplyPressureLimitOrWidthOutOfRange) {
  JointLubrication l = oil();
  l.viscosity = 1e300;
  EXPECT_EQ(error_of(l), "joint.lubrication.viscosity = 1e+300: must be in [1e-06, 1e+06] Pa s "
                         "(gases to the stiffest greases)");
  l.viscosity = 1e-7;
  EXPECT_NE(error_of(l).find("joint.lubrication.viscosity = 1e-07: must be in [1e-06"), std::string::npos);
  l = oil();
  l.supply_pressure = 1e300;
  EXPECT_EQ(error_of(l), "joint.lubrication.supply_pressure = 1e+300: must be in [0, 1e+09] Pa "
                         "(a gauge pressure; 1 GPa is above any oil feed)");
  l.supply_pressure = 1e9;  // the largest accepted
  EXPECT_EQ(error_of(l), "no error");
  l = oil();
  l.film_thickness_limit = 1e300;
  EXPECT_NE(error_of(l).find("joint.lubrication.film_thickness_limit = 1e+300: must be in ["),
            std::string::npos);
  l.film_thickness_limit = kClearance;  // the film is never thicker: it would never act
  EXPECT_NE(error_of(l).find("joint.lubrication.film_thickness_limit = 1e-04: must be in"), std::string::npos);
  l.film_thickness_limit = 1e-11;
  EXPECT_NE(error_of(l).find("joint.lubrication.film_thickness_limit = 1e-11"), std::string::npos);
  l = oil();
  l.transition_width = 1e300;
  EXPECT_NE(error_of(l).find("joint.lubrication.transition_width = 1e+300: must be in ["),
            std::string::npos);
  l.transition_width = kClearance;  // the largest accepted
  EXPECT_EQ(error_of(l), "no error");
}

/// The film library's refusal of `description` under `name`: what() and field_path().
template <class Description>
std::pair<std::string, std::string> library_error_of(const Description& description, const char* name) {
  try {
    lubrication::validate(description, name);
  } catch (const ValidationError& e) {
    return {e.what(), std::string(e.field_path())};
  }
  return {"no error", ""};
}

TEST(JointLubrication, RefusesABadViscosityOrSupplyPressureWithTheFilmLibrarysOwnCheck) {
  // One check of a lubricant and of an oil supply (lubrication::validate), whichever front-end
  // is given the value: a model's clearance joint, or the film library called directly.
  for (const double viscosity : {-0.04, 0.0, std::nan("")}) {
    JointLubrication l = oil();
    l.viscosity = viscosity;
    const auto [message, path] = library_error_of(lubrication::Lubricant{viscosity}, "joint.lubrication");
    EXPECT_EQ(error_of(l), message);
    EXPECT_EQ(path, "joint.lubrication.viscosity");
  }
  JointLubrication l = oil();
  l.supply_pressure = -1.0;
  lubrication::OilSupply supply;
  supply.supply_pressure = -1.0;
  const auto [message, path] = library_error_of(supply, "joint.lubrication");
  EXPECT_EQ(error_of(l), message);
  EXPECT_EQ(path, "joint.lubrication.supply_pressure");
}

TEST(JointLubrication, RefusesAMassConservingClosedFormAndAMassConservingFilmWithoutAGroove) {
  JointLubrication l = oil();
  l.cavitation = lubrication::CavitationModel::mass_conserving;
  EXPECT_NE(error_of(l).find("joint.lubrication.cavitation = \"mass_conserving\""), std::string::npos);
  l.method = FilmMethod::grid;
  EXPECT_NE(error_of(l).find("joint.lubrication.groove_direction is missing"), std::string::npos);
  l.groove_direction_B = Vector3::Zero();
  EXPECT_NE(error_of(l).find("joint.lubrication.groove_direction"), std::string::npos);
  l.groove_direction_B = Vector3::UnitX();
  EXPECT_EQ(error_of(l), "no error");
  l.supply_pressure = -1.0;
  EXPECT_NE(error_of(l).find("joint.lubrication.supply_pressure = -1"), std::string::npos);
}

TEST(FilmMethod, ReadsBackItsOwnNamesAndNamesTheFieldOfAnUnknownOne) {
  for (FilmMethod m : {FilmMethod::short_bearing, FilmMethod::long_bearing, FilmMethod::grid}) {
    EXPECT_EQ(film_method_from_string(lubrication::to_string(m), "method"), m);
  }
  for (auto m : {lubrication::CavitationModel::half_sommerfeld,
                 lubrication::CavitationModel::mass_conserving}) {
    EXPECT_EQ(cavitation_model_from_string(lubrication::to_string(m), "cavitation"), m);
  }
  try {
    film_method_from_string("finite", "forces[0].lubrication.method");
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()),
              "forces[0].lubrication.method = \"finite\": unknown film method (known: grid, short, long, table)");
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
