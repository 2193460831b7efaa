// SPDX-License-Identifier: BSD-3-Clause
// validate(DetectionOptions): the one check of the detection's options, named by the caller.

#include "clearjoint/geometry/model/detection_options.hpp"

#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry {
namespace {

/// "field_path | what()" of the refusal, or "no error".
std::string refusal(double tolerance, std::string_view path) {
  DetectionOptions options;
  options.parallel_angle_tolerance = tolerance;
  try {
    validate(options, path);
  } catch (const InvalidInput& e) {
    return std::string(e.field_path()) + " | " + e.what();
  }
  return "no error";
}

TEST(DetectionOptions, ToleranceInZeroToHalfPiIsAccepted) {
  EXPECT_EQ(refusal(0.0, "options"), "no error");
  EXPECT_EQ(refusal(1.5, "options"), "no error");
}

TEST(DetectionOptions, ToleranceOutsideZeroToHalfPiIsNamedInTheCallersTerms) {
  EXPECT_EQ(refusal(2.0, "forces[0].detection"),
            "forces[0].detection.parallel_angle_tolerance | "
            "forces[0].detection.parallel_angle_tolerance = 2: must lie in [0, pi/2) radians");
  EXPECT_EQ(refusal(-0.1, "options"),
            "options.parallel_angle_tolerance | options.parallel_angle_tolerance = -0.1: must lie in [0, pi/2) radians");
  EXPECT_EQ(refusal(std::numeric_limits<double>::quiet_NaN(), "options"),
            "options.parallel_angle_tolerance | options.parallel_angle_tolerance = nan: must lie in [0, pi/2) radians");
}

}  // namespace
}  // namespace clearjoint::geometry
