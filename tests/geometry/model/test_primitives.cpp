// SPDX-License-Identifier: BSD-3-Clause
// Primitives: validation of every field, and the documented rim parametrisation (frame_of,
// point_at).

#include "clearjoint/geometry/model/primitives.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry_test_support.hpp"

namespace clearjoint::geometry {
namespace {

using testing::documented_frame;
using testing::LongFrame;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
/// frame_of rounds u and v to double after a normalisation: a few ulps per component.
constexpr double kFrameTolerance = 4 * kEps;
/// point_at is documented as accurate to "a few ulps of |center| + radius"; 8 ulps.
constexpr double kPointUlps = 8 * kEps;

const Circle3 kGoodCircle{Vector3(1, 2, 3), Vector3(0, 0, 2), 0.5};
const Plane3 kGoodPlane{Vector3(1, 2, 3), Vector3(0, -3, 0)};
const Cylinder3 kGoodCylinder{Vector3(1, 2, 3), Vector3(0, 0, 7), 0.25};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

/// The text a message must contain to name a bad value: "nan", "inf" (with its sign), or the
/// shortest decimal form of the number.
std::string value_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0) return "0";
  std::string s = std::to_string(value);  // e.g. "-1.000000"
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

template <class Primitive>
void expect_rejected(const Primitive& p, const std::string& field, double value,
                     const std::string& name = "") {
  try {
    if (name.empty()) {
      validate(p);
    } else {
      validate(p, name);
    }
    ADD_FAILURE() << "validate accepted a bad " << field << " = " << value;
  } catch (const InvalidInput& e) {
    const std::string what = lower(e.what());
    EXPECT_NE(what.find(lower(field)), std::string::npos) << "message: " << e.what();
    EXPECT_NE(what.find(value_text(value)), std::string::npos)
        << "message: " << e.what() << " should name the value " << value_text(value);
  }
}

const std::vector<double> kNonFinite = {kNaN, kInf, -kInf};

// ---- validate: accepted inputs -----------------------------------------------------------------

TEST(Validate, AcceptsWellFormedPrimitivesWithNonUnitDirections) {
  EXPECT_NO_THROW(validate(kGoodCircle));
  EXPECT_NO_THROW(validate(kGoodPlane));
  EXPECT_NO_THROW(validate(kGoodCylinder));
}

TEST(Validate, AcceptsTinyButPositiveRadiiAndTinyNonZeroDirections) {
  // The preconditions are radius > 0 and direction != 0, nothing stricter.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_NO_THROW(validate(Circle3{Vector3::Zero(), Vector3(0, 0, 1e-300), tiny}));
  EXPECT_NO_THROW(validate(Plane3{Vector3::Zero(), Vector3(tiny, 0, 0)}));
  EXPECT_NO_THROW(validate(Cylinder3{Vector3::Zero(), Vector3(0, 1e-300, 0), tiny}));
}

TEST(Validate, AcceptsHugeFiniteValues) {
  const double huge = std::numeric_limits<double>::max();
  EXPECT_NO_THROW(validate(Circle3{Vector3(huge, -huge, 0), Vector3(huge, 0, 0), huge}));
  EXPECT_NO_THROW(validate(Cylinder3{Vector3(0, 0, -huge), Vector3(0, huge, 0), huge}));
}

// ---- validate: every bad field, one by one -----------------------------------------------------

TEST(Validate, RejectsANonFiniteCircleCenterInEachComponent) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Circle3 c = kGoodCircle;
      c.center[i] = bad;
      expect_rejected(c, "circle.center", bad);
    }
  }
}

TEST(Validate, RejectsANonFiniteCircleNormalInEachComponent) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Circle3 c = kGoodCircle;
      c.normal[i] = bad;
      expect_rejected(c, "circle.normal", bad);
    }
  }
}

TEST(Validate, RejectsAZeroCircleNormal) {
  Circle3 c = kGoodCircle;
  c.normal = Vector3::Zero();
  expect_rejected(c, "circle.normal", 0.0);
  c.normal = Vector3(-0.0, 0.0, -0.0);
  expect_rejected(c, "circle.normal", 0.0);
}

TEST(Validate, RejectsACircleRadiusThatIsNotPositiveOrNotFinite) {
  for (double bad : {0.0, -0.0, -1.0, -0.125, kNaN, kInf, -kInf}) {
    Circle3 c = kGoodCircle;
    c.radius = bad;
    expect_rejected(c, "circle.radius", bad);
  }
}

TEST(Validate, RejectsANonFinitePlanePointInEachComponent) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Plane3 p = kGoodPlane;
      p.point[i] = bad;
      expect_rejected(p, "plane.point", bad);
    }
  }
}

TEST(Validate, RejectsANonFiniteOrZeroPlaneNormal) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Plane3 p = kGoodPlane;
      p.normal[i] = bad;
      expect_rejected(p, "plane.normal", bad);
    }
  }
  Plane3 p = kGoodPlane;
  p.normal = Vector3::Zero();
  expect_rejected(p, "plane.normal", 0.0);
}

TEST(Validate, RejectsANonFiniteCylinderAxisPointInEachComponent) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Cylinder3 c = kGoodCylinder;
      c.axis_point[i] = bad;
      expect_rejected(c, "cylinder.axis_point", bad);
    }
  }
}

TEST(Validate, RejectsANonFiniteOrZeroCylinderAxis) {
  for (int i = 0; i < 3; ++i) {
    for (double bad : kNonFinite) {
      Cylinder3 c = kGoodCylinder;
      c.axis[i] = bad;
      expect_rejected(c, "cylinder.axis", bad);
    }
  }
  Cylinder3 c = kGoodCylinder;
  c.axis = Vector3::Zero();
  expect_rejected(c, "cylinder.axis", 0.0);
}

TEST(Validate, RejectsACylinderRadiusThatIsNotPositiveOrNotFinite) {
  for (double bad : {0.0, -0.0, -1.0, -2.5, kNaN, kInf, -kInf}) {
    Cylinder3 c = kGoodCylinder;
    c.radius = bad;
    expect_rejected(c, "cylinder.radius", bad);
  }
}

TEST(Validate, PrefixesTheFieldWithTheGivenName) {
  Circle3 c = kGoodCircle;
  c.radius = -1;
  expect_rejected(c, "rim A.radius", -1.0, "rim A");
  Cylinder3 w = kGoodCylinder;
  w.axis = Vector3::Zero();
  expect_rejected(w, "bearing wall.axis", 0.0, "bearing wall");
  Plane3 p = kGoodPlane;
  p.point.y() = kNaN;
  expect_rejected(p, "base B.point", kNaN, "base B");
}

TEST(Validate, ThrowsAnInvalidArgument) {
  Circle3 c = kGoodCircle;
  c.radius = 0;
  EXPECT_THROW(validate(c), std::invalid_argument);
}

// ---- frame_of ----------------------------------------------------------------------------------

void expect_frame(const Vector3& normal, const Vector3& u, const Vector3& v) {
  const CircleFrame f = frame_of(Circle3{Vector3(4, -5, 6), normal, 2.0});
  EXPECT_NEAR((f.u - u).lpNorm<Eigen::Infinity>(), 0.0, kFrameTolerance)
      << "normal " << normal.transpose() << ": u = " << f.u.transpose();
  EXPECT_NEAR((f.v - v).lpNorm<Eigen::Infinity>(), 0.0, kFrameTolerance)
      << "normal " << normal.transpose() << ": v = " << f.v.transpose();
}

TEST(FrameOf, UsesTheXAxisForANormalAlongZ) {
  // k = 0 (first of the tied zeros): u = z x x = y, v = z x y = -x.
  expect_frame(Vector3(0, 0, 1), Vector3(0, 1, 0), Vector3(-1, 0, 0));
  expect_frame(Vector3(0, 0, 5), Vector3(0, 1, 0), Vector3(-1, 0, 0));
}

TEST(FrameOf, FlipsBothUAndVWhenTheNormalIsNegated) {
  expect_frame(Vector3(0, 0, -1), Vector3(0, -1, 0), Vector3(-1, 0, 0));
}

TEST(FrameOf, UsesTheYAxisForANormalAlongX) {
  // |n| = (1, 0, 0): smallest is index 1 (first of the tied zeros). u = x x y = z, v = x x z = -y.
  expect_frame(Vector3(3, 0, 0), Vector3(0, 0, 1), Vector3(0, -1, 0));
}

TEST(FrameOf, MatchesTheDocumentedFrameOfTheTiltedRim) {
  // n = (0,3,4): k = 0, u = (0,4,-3)/5, v = (-1,0,0).
  expect_frame(Vector3(0, 3, 4), Vector3(0, 0.8, -0.6), Vector3(-1, 0, 0));
}

TEST(FrameOf, BreaksTiesOnTheSmallestComponentTowardTheFirstIndex) {
  // |n| = (2, 1, 1): k = 1. u = (2,-1,1) x y = (-1, 0, 2)/sqrt5.
  const double s5 = std::sqrt(5.0);
  const Vector3 n(2, -1, 1);
  const Vector3 u = Vector3(-1, 0, 2) / s5;
  expect_frame(n, u, n.normalized().cross(u));
  // All equal: k = 0.
  const Vector3 m(1, -1, 1);
  const Vector3 um = m.cross(Vector3::UnitX()).normalized();
  expect_frame(m, um, m.normalized().cross(um));
  // -0 and +0 tie: k = 0.
  expect_frame(Vector3(-0.0, 0.0, 1.0), Vector3(0, 1, 0), Vector3(-1, 0, 0));
}

TEST(FrameOf, IsRightHandedOrthonormalAndMatchesTheDocumentedFormulaForRandomNormals) {
  constexpr unsigned kSeed = 4242;
  RecordProperty("seed", static_cast<int>(kSeed));
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const Vector3 n(coord(rng), coord(rng), coord(rng));
    const CircleFrame f = frame_of(Circle3{Vector3::Zero(), n, 1.0});
    const LongFrame ref = documented_frame(n);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(f.u[i], static_cast<double>(ref.u[i]), kFrameTolerance) << trial;
      EXPECT_NEAR(f.v[i], static_cast<double>(ref.v[i]), kFrameTolerance) << trial;
    }
    EXPECT_NEAR(f.u.norm(), 1.0, kFrameTolerance);
    EXPECT_NEAR(f.v.norm(), 1.0, kFrameTolerance);
    EXPECT_NEAR(f.u.dot(f.v), 0.0, kFrameTolerance);
    EXPECT_NEAR(f.u.dot(n.normalized()), 0.0, kFrameTolerance);
    EXPECT_GT(f.u.cross(f.v).dot(n), 0.0);
  }
}

TEST(FrameOf, DoesNotDependOnTheNormalsLength) {
  const Vector3 n(0.3, -1.7, 2.9);
  for (double factor : {1e-200, 1e-3, 0.5, 4.0, 1e3, 1e200}) {
    const CircleFrame a = frame_of(Circle3{Vector3::Zero(), n, 1.0});
    const CircleFrame b = frame_of(Circle3{Vector3::Zero(), n * factor, 1.0});
    EXPECT_NEAR((a.u - b.u).norm(), 0.0, kFrameTolerance) << factor;
    EXPECT_NEAR((a.v - b.v).norm(), 0.0, kFrameTolerance) << factor;
  }
}

// ---- point_at ----------------------------------------------------------------------------------

TEST(PointAt, StartsAtUAndReachesVAQuarterTurnLater) {
  const Circle3 c{Vector3(1, 2, 3), Vector3(0, 0, 1), 2.0};
  const CircleFrame f = frame_of(c);
  const double tol = kPointUlps * (c.center.norm() + c.radius);
  EXPECT_NEAR((point_at(c, f, 0.0) - Vector3(1, 4, 3)).norm(), 0.0, tol);
  EXPECT_NEAR((point_at(c, f, std::numbers::pi / 2) - Vector3(-1, 2, 3)).norm(), 0.0, tol);
  EXPECT_NEAR((point_at(c, f, std::numbers::pi) - Vector3(1, 0, 3)).norm(), 0.0, tol);
  EXPECT_NEAR((point_at(c, f, 1.5 * std::numbers::pi) - Vector3(3, 2, 3)).norm(), 0.0, tol);
}

TEST(PointAt, StaysOnTheRimAndAgreesWithTheDocumentedParametrisation) {
  constexpr unsigned kSeed = 777;
  RecordProperty("seed", static_cast<int>(kSeed));
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> coord(-5.0, 5.0), angle(0.0, testing::kTwoPi);
  for (int trial = 0; trial < 500; ++trial) {
    const Circle3 c{Vector3(coord(rng), coord(rng), coord(rng)),
                    Vector3(coord(rng), coord(rng), coord(rng)), 0.1 + std::abs(coord(rng))};
    const CircleFrame f = frame_of(c);
    const double a = angle(rng);
    const Vector3 p = point_at(c, f, a);
    const double tol = kPointUlps * (c.center.norm() + c.radius);
    EXPECT_NEAR((p - testing::documented_point(c, a)).norm(), 0.0, tol) << trial;
    EXPECT_NEAR((p - c.center).norm(), c.radius, tol);
    EXPECT_NEAR((p - c.center).dot(c.normal.normalized()), 0.0, tol);
  }
}

// ---- the error carries the field's path ---------------------------------------------------------

TEST(InvalidInput, IsAValidationErrorWhosePathNamesTheField) {
  try {
    validate(Circle3{Vector3::Zero(), Vector3::UnitZ(), -1.0}, "rim A");
    ADD_FAILURE() << "validate accepted a negative radius";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.field_path(), "rim A.radius");
    EXPECT_EQ(e.detail(), " = -1: must be positive");
    EXPECT_STREQ(e.what(), "rim A.radius = -1: must be positive");
  }
}

}  // namespace
}  // namespace clearjoint::geometry
