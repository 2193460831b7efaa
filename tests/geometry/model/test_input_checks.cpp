// SPDX-License-Identifier: BSD-3-Clause
#include "model/input_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace clearjoint::geometry::detail {
namespace {

TEST(Format, WritesDoublesThatReadBackToTheSameValue) {
  for (double x : {0.1, 1.0 / 3, 9.9e-3, -1e-300, 4.9e-324, 1.7976931348623157e308}) {
    // strtod, not std::stod: stod throws on subnormal results (ERANGE).
    EXPECT_EQ(std::strtod(format(x).c_str(), nullptr), x) << format(x);
  }
}

TEST(Reject, NamesTheObjectTheFieldAndTheValue) {
  try {
    reject("rim A", "radius", format(-1.0), "must be positive");
    FAIL() << "reject returned";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "rim A.radius = -1: must be positive");
  }
}

TEST(RequirePositive, RejectsZeroNegativeNanAndInfinity) {
  EXPECT_NO_THROW(require_positive(1e-300, "x", "r"));
  for (double bad : {0.0, -0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(require_positive(bad, "x", "r"), InvalidInput) << bad;
  }
}

TEST(RequireNonzero, RejectsOnlyTheZeroVector) {
  EXPECT_NO_THROW(require_nonzero(Vector3(0, 0, 4.9e-324), "x", "axis"));
  EXPECT_THROW(require_nonzero(Vector3(0, -0.0, 0), "x", "axis"), InvalidInput);
}

TEST(RequireFinite, RejectsAnyNonFiniteComponent) {
  EXPECT_THROW(require_finite(Vector3(0, std::nan(""), 0), "x", "p"), InvalidInput);
  EXPECT_THROW(require_finite(Vector3(-HUGE_VAL, 0, 0), "x", "p"), InvalidInput);
  EXPECT_NO_THROW(require_finite(Vector3(1e308, -1e308, 0), "x", "p"));
}

}  // namespace
}  // namespace clearjoint::geometry::detail
