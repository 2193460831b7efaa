// SPDX-License-Identifier: BSD-3-Clause
// The film's thickness, its rate and its thinnest point, against the first-order film
// h = c - e(z) . n(theta) and against brute-force sampling.
#include "clearjoint/lubrication/film_thickness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {
namespace {

using geometry::JointDimensions;
using geometry::PartPose;

// A joint with c / R = 1e-3, the size of the paper's Section 6 joints.
const JointDimensions kJoint{0.010, 0.040, 0.00999, 0.038};

PartPose at(const Vector3& p, const Vector3& axis = Vector3::UnitZ()) { return PartPose{p, axis}; }

TEST(FilmThickness, IsTheClearanceEverywhereForACentredJournal) {
  const FilmGeometry film = describe_film(kJoint, at(Vector3::Zero()), at(Vector3::Zero()),
                                          Vector3::UnitX());
  for (double theta = 0.0; theta < 6.3; theta += 0.7) {
    for (const double z : {-0.019, 0.0, 0.019}) {
      EXPECT_NEAR(film_thickness(film, theta, z), kJoint.radial_clearance(), 1e-18);
    }
  }
  EXPECT_DOUBLE_EQ(film.z_low, -0.019);
  EXPECT_DOUBLE_EQ(film.z_high, 0.019);
}

TEST(FilmThickness, MatchesTheFirstOrderFilmForAnOffsetJournalToOrderCSquaredOverR) {
  const double c = kJoint.radial_clearance();
  const Vector3 offset(0.6 * c, 0.3 * c, 0.0);
  const FilmGeometry film =
      describe_film(kJoint, at(Vector3::Zero()), at(offset), Vector3::UnitX());
  for (double theta = 0.0; theta < 6.3; theta += 0.3) {
    const double first_order = c - offset.dot(wall_normal(film, theta));
    EXPECT_NEAR(film_thickness(film, theta, 0.01), first_order, c * c / kJoint.journal_radius);
  }
}

TEST(FilmThickness, OfATiltedJournalVariesAlongTheAxisAndIsThinnestAtAnEnd) {
  const double c = kJoint.radial_clearance();
  const double tilt = 0.8 * c / (0.5 * kJoint.journal_length);  // ends at +-0.8 c
  const FilmGeometry film = describe_film(kJoint, at(Vector3::Zero()),
                                          at(Vector3::Zero(), Vector3(tilt, 0.0, 1.0)),
                                          Vector3::UnitX());
  const ThinnestFilm thinnest = thinnest_film(film);
  // Brute force over the unwrapped surface.
  double brute = 1.0;
  for (int i = 0; i < 720; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const double z = film.z_low + j * film.width() / 40;
      brute = std::min(brute, film_thickness(film, i * std::numbers::pi / 360, z));
    }
  }
  EXPECT_LE(thinnest.thickness, brute);
  EXPECT_NEAR(thinnest.thickness, 0.2 * c, 1e-3 * c);
  EXPECT_TRUE(thinnest.z == film.z_low || thinnest.z == film.z_high);
  // The +z end leans towards +x: thinner there, thicker at the -z end.
  EXPECT_LT(film_thickness(film, 0.0, film.z_high) - film_thickness(film, 0.0, film.z_low), -1.5 * c);
}

TEST(FilmThickness, OfAnAlignedJournalIsThinnestExactlyOnTheLineOfCentres) {
  // The journal's section is a circle about its axis' point: h is least in that direction, where
  // the first-order film gives c - |e|, at both ends alike (ties go to z_low).
  const double c = kJoint.radial_clearance();
  const Vector3 offset(0.6 * c, -0.3 * c, 0.0);
  const FilmGeometry film = describe_film(kJoint, at(Vector3::Zero()), at(offset), Vector3::UnitX());
  const ThinnestFilm thinnest = thinnest_film(film);
  const double direction = std::atan2(-0.3, 0.6) + 2.0 * std::numbers::pi;
  EXPECT_EQ(thinnest.theta, direction);
  EXPECT_EQ(thinnest.z, film.z_low);
  EXPECT_EQ(thinnest.thickness, film_thickness(film, direction, film.z_low));
  EXPECT_NEAR(thinnest.thickness, c - offset.norm(), c * c / kJoint.journal_radius);
  for (int i = -50; i <= 50; ++i) {
    EXPECT_LE(thinnest.thickness, film_thickness(film, direction + i * 1e-3, 0.0));
  }
}

TEST(FilmThickness, IsTheSameInMillimetresAsInMetresScaled) {
  const double c = kJoint.radial_clearance();
  const JointDimensions mm{10.0, 40.0, 9.99, 38.0};
  const FilmGeometry metres = describe_film(kJoint, at(Vector3::Zero()),
                                            at(Vector3(0.5 * c, 0.0, 0.001), Vector3(1e-3, 0, 1)),
                                            Vector3::UnitX());
  const FilmGeometry millimetres = describe_film(
      mm, at(Vector3::Zero()), at(Vector3(500.0 * c, 0.0, 1.0), Vector3(1e-3, 0, 1)),
      Vector3::UnitX());
  for (double theta = 0.0; theta < 6.3; theta += 0.5) {
    EXPECT_NEAR(1000.0 * film_thickness(metres, theta, 0.005), film_thickness(millimetres, theta, 5.0),
                1e-9 * 1000.0 * c);
  }
}

TEST(FilmThicknessRate, IsMinusTheApproachSpeedAlongTheNormal) {
  const double c = kJoint.radial_clearance();
  const FilmGeometry film =
      describe_film(kJoint, at(Vector3::Zero()), at(Vector3(0.5 * c, 0, 0)), Vector3::UnitX());
  RelativeMotion motion;
  motion.v_BJ_W = Vector3(0.2, 0.0, 0.0);
  EXPECT_NEAR(film_thickness_rate(film, motion, 0.0, 0.0), -0.2, 1e-15);
  EXPECT_NEAR(film_thickness_rate(film, motion, std::numbers::pi, 0.0), 0.2, 1e-15);
  // A spin about the common axis does not change the film.
  RelativeMotion spin;
  spin.omega_BJ_W = Vector3(0.0, 0.0, 100.0);
  EXPECT_NEAR(film_thickness_rate(film, spin, 1.0, 0.01), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(journal_spin(film, spin), 100.0);
}

TEST(FilmThicknessRate, AgreesWithAFiniteDifferenceOfATiltingJournal) {
  const double c = kJoint.radial_clearance();
  RelativeMotion motion;
  motion.v_BJ_W = Vector3(0.01, -0.02, 0.003);
  motion.omega_BJ_W = Vector3(0.3, 0.5, 40.0);
  const Vector3 p(0.3 * c, 0.1 * c, 0.0005);
  const Vector3 axis = Vector3(2e-2 * c / 0.019, 0.0, 1.0).normalized();
  const double dt = 1e-7;
  const Vector3 p_next = p + dt * motion.v_BJ_W;
  const Vector3 axis_next = axis + dt * motion.omega_BJ_W.cross(axis);
  const FilmGeometry now = describe_film(kJoint, at(Vector3::Zero()), at(p, axis), Vector3::UnitX());
  const FilmGeometry next =
      describe_film(kJoint, at(Vector3::Zero()), at(p_next, axis_next), Vector3::UnitX());
  for (const double theta : {0.3, 2.0, 4.0}) {
    const double difference = (film_thickness(next, theta, 0.01) - film_thickness(now, theta, 0.01)) / dt;
    EXPECT_NEAR(film_thickness_rate(now, motion, theta, 0.01), difference, 2e-3 * 0.05);
  }
}

TEST(DescribeFilm, RefusesAJournalOutsideItsBearing) {
  EXPECT_THROW(describe_film(kJoint, at(Vector3::Zero()), at(Vector3(0, 0, 1.0)), Vector3::UnitX()),
               geometry::InvalidInput);
  EXPECT_THROW(describe_film(kJoint, at(Vector3::Zero()), at(Vector3::Zero(), Vector3::UnitX()),
                             Vector3::UnitX()),
               geometry::InvalidInput);
}

}  // namespace
}  // namespace clearjoint::lubrication
