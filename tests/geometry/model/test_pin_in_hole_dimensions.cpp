// SPDX-License-Identifier: BSD-3-Clause
// Tests of pin_in_hole_dimensions: the clearances and the one check of a pin-in-hole joint's
// dimensions, each bad field named with its value.

#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

namespace clearjoint::geometry {
namespace {

// A hole of radius 10 and length 20 (mm), a pin of radius 9.5, heads 0.5 beyond each face.
PinInHoleDimensions two_stops() {
  PinInHoleDimensions d;
  d.hole_radius = 10.0;
  d.hole_length = 20.0;
  d.pin_radius = 9.5;
  d.stops[0] = {-10.5, 16.0};
  d.stops[1] = {10.5, 16.0};
  d.stop_count = 2;
  return d;
}

std::string message_of(const PinInHoleDimensions& dimensions, const PinInHoleDimensionNames& names = {}) {
  try {
    validate(dimensions, "dimensions", names);
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(PinInHoleDimensions, ClearancesAreTheHoleMinusThePinAndHalfTheGapBeyondTheHole) {
  const PinInHoleDimensions d = two_stops();
  EXPECT_EQ(d.radial_clearance(), 0.5);
  EXPECT_EQ(d.axial_clearance(), 0.5);  // (10.5 - (-10.5) - 20) / 2
  PinInHoleDimensions one = d;
  one.stop_count = 1;
  EXPECT_EQ(one.axial_clearance(), std::numeric_limits<double>::infinity());
}

TEST(PinInHoleDimensions, ValidDimensionsWithZeroOneOrTwoStopsPass) {
  PinInHoleDimensions d = two_stops();
  EXPECT_EQ(message_of(d), "");
  d.stop_count = 1;
  EXPECT_EQ(message_of(d), "");
  d.stop_count = 0;
  EXPECT_EQ(message_of(d), "");
}

TEST(PinInHoleDimensions, APinThickerThanItsHoleIsNamed) {
  PinInHoleDimensions d = two_stops();
  d.pin_radius = 10.0;
  EXPECT_EQ(message_of(d),
            "dimensions.pin_radius = 10: must be smaller than hole_radius = 10 (the radial clearance Rh - Rp must "
            "be positive: the pin must be thinner than its hole)");
}

TEST(PinInHoleDimensions, AStopInsideTheHoleIsNamedWithHalfTheHoleLength) {
  PinInHoleDimensions d = two_stops();
  d.stops[1].position = 10.0;  // exactly at the face: no room for the link
  EXPECT_EQ(message_of(d),
            "dimensions.stops[1].position = 10: the stop lies inside the hole: its distance from the pin's point "
            "P must exceed hole_length / 2 = 10");
  d.stops[1].position = -3.0;
  EXPECT_EQ(message_of(d).rfind("dimensions.stops[1].position = -3: the stop lies inside the hole", 0), 0u);
}

TEST(PinInHoleDimensions, AStopNoLargerThanTheHoleOrOnTheSameSideIsNamed) {
  PinInHoleDimensions d = two_stops();
  d.stops[0].outer_radius = 10.0;
  EXPECT_EQ(message_of(d),
            "dimensions.stops[0].outer_radius = 10: must be larger than hole_radius = 10 (a stop smaller than the "
            "hole passes through it)");
  d = two_stops();
  d.stops[0].position = 12.0;
  EXPECT_EQ(message_of(d),
            "dimensions.stops[1].position = 10.5: must lie on the other side of the pin's point P from "
            "stops[0].position = 12 (one stop on each side of the hole)");
  d = two_stops();
  d.stop_count = 3;
  EXPECT_EQ(message_of(d), "dimensions.stop_count = 3: must be 0, 1 or 2 (at most one stop on each side of the hole)");
}

TEST(PinInHoleDimensions, NonFiniteNegativeAndOutOfRangeSizesAreNamed) {
  PinInHoleDimensions d = two_stops();
  d.hole_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(d), "dimensions.hole_radius = nan: must be finite");
  d = two_stops();
  d.hole_length = -1.0;
  EXPECT_EQ(message_of(d), "dimensions.hole_length = -1: must be positive");
  d = two_stops();
  d.pin_radius = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(d), "dimensions.pin_radius = inf: must be finite");
  d = two_stops();
  d.stops[0].position = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(d), "dimensions.stops[0].position = -inf: must be finite");
  d = two_stops();
  d.pin_radius = 1e-160;
  EXPECT_EQ(message_of(d).rfind("dimensions.pin_radius = 1e-160: a magnitude outside [1e-150, 1e150]", 0), 0u);
  d = two_stops();
  d.stops[1].outer_radius = 1e151;
  EXPECT_EQ(message_of(d).rfind("dimensions.stops[1].outer_radius = 1e+151: a magnitude outside", 0), 0u);
}

TEST(PinInHoleDimensions, TheCallersPathAndPartNamesPrefixTheField) {
  PinInHoleDimensions d = two_stops();
  d.stops[0].outer_radius = -2.0;
  try {
    validate(d, "forces[0]", kPinInHolePartNames);
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(std::string(error.what()), "forces[0].pin.stops[0].outer_radius = -2: must be positive");
    EXPECT_EQ(error.field_path(), "forces[0].pin.stops[0].outer_radius");
  }
}

TEST(PinInHoleScenario, EveryKeyReadsBackToItsValue) {
  for (const auto& entry : EnumTable<PinInHoleScenario>::entries) {
    EXPECT_EQ(from_string<PinInHoleScenario>(to_string(entry.value)), entry.value);
  }
  EXPECT_EQ(to_string(PinInHoleScenario::both_edges_opposite), "both_edges_opposite");
  EXPECT_EQ(enum_count<PinInHoleScenario>(), 11);
}

}  // namespace
}  // namespace clearjoint::geometry
