// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/film_thickness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {

namespace {

/// Journal axes closer than this cosine to perpendicular to the bearing's are refused: a tilt
/// beyond 60 degrees is far outside any joint whose clearance is small against its radius, and
/// the thin-film (Reynolds) model has stopped describing it long before.
constexpr double kSmallestAxisCosine = 0.5;

/// A theta hint whose part perpendicular to the axis is below this fraction of its length is
/// treated as having none (it would fix theta = 0 to within rounding noise only).
constexpr double kSmallestUsableHintFraction = 1e-8;

/// Golden-section steps in thinnest_film: the bracket shrinks by 0.618^48 ~ 1e-10, well below
/// where h (quadratic near its minimum) changes in double.
constexpr int kGoldenSectionSteps = 48;

/// A journal tilted by gamma cuts the plane z in an ellipse between the circles of radii R_j and
/// R_j / cos(gamma) about its axis' point, so the film along e(z)'s direction exceeds the
/// thinnest by at most R_j (1 / cos(gamma) - 1). Below this fraction of R_j (the unit roundoff,
/// the size of film_thickness's own rounding, a few ulps of R_j) that direction is the minimum
/// to rounding and thinnest_film skips the search: gamma below 2e-8 rad, an aligned journal.
constexpr double kAlignedExcessFraction = std::numeric_limits<double>::epsilon();

Vector3 perpendicular_unit(const Vector3& axis, const Vector3& hint) {
  Vector3 perpendicular = hint - hint.dot(axis) * axis;
  const double hint_length = hint.norm();
  if (!(perpendicular.norm() > kSmallestUsableHintFraction * hint_length)) {
    // The coordinate direction least aligned with the axis, made perpendicular (always usable).
    Eigen::Index k = 0;
    axis.cwiseAbs().minCoeff(&k);
    perpendicular = Vector3::Unit(k) - axis(k) * axis;
  }
  return perpendicular.normalized();
}

double wrap_angle(double theta) {
  const double two_pi = 2.0 * std::numbers::pi;
  theta = std::fmod(theta, two_pi);
  return theta < 0.0 ? theta + two_pi : theta;
}

}  // namespace

FilmGeometry describe_film(const geometry::JointDimensions& dimensions,
                           const geometry::PartPose& bearing, const geometry::PartPose& journal,
                           const Vector3& theta_zero_hint_W) {
  geometry::validate(dimensions);
  geometry::validate(bearing, "bearing");
  geometry::validate(journal, "journal");
  FilmGeometry film;
  film.axis_W = geometry::unit_axis(bearing);
  film.journal_axis_W = geometry::unit_axis(journal);
  double axis_cosine = film.journal_axis_W.dot(film.axis_W);
  if (axis_cosine < 0.0) {  // an axis means only a line: orient the journal's like the bearing's
    film.journal_axis_W = -film.journal_axis_W;
    axis_cosine = -axis_cosine;
  }
  if (!(axis_cosine > kSmallestAxisCosine)) {
    std::ostringstream message;
    message << "journal axis makes acos(" << axis_cosine
            << ") with the bearing's: a lubricating film needs nearly parallel axes";
    throw geometry::InvalidInput(message.str());
  }
  film.p_WB = bearing.p_WP;
  film.p_WJ = journal.p_WP;
  film.theta_zero_W = perpendicular_unit(film.axis_W, theta_zero_hint_W);
  film.theta_quarter_W = film.axis_W.cross(film.theta_zero_W);
  film.bearing_radius = dimensions.bearing_radius;
  film.journal_radius = dimensions.journal_radius;
  film.radial_clearance = dimensions.radial_clearance();

  const double z_journal_centre = (film.p_WJ - film.p_WB).dot(film.axis_W);
  const double journal_half_extent = 0.5 * dimensions.journal_length * axis_cosine;
  const double bearing_half_length = 0.5 * dimensions.bearing_length;
  film.z_low = std::max(z_journal_centre - journal_half_extent, -bearing_half_length);
  film.z_high = std::min(z_journal_centre + journal_half_extent, bearing_half_length);
  if (!(film.z_high > film.z_low)) {
    std::ostringstream message;
    message << "journal does not overlap its bearing axially (film from z = " << film.z_low
            << " to " << film.z_high << "): there is no film";
    throw geometry::InvalidInput(message.str());
  }
  return film;
}

Vector3 wall_normal(const FilmGeometry& film, double theta) {
  return std::cos(theta) * film.theta_zero_W + std::sin(theta) * film.theta_quarter_W;
}

Vector3 journal_offset(const FilmGeometry& film, double z) {
  const double axis_cosine = film.journal_axis_W.dot(film.axis_W);
  const double z_journal_centre = (film.p_WJ - film.p_WB).dot(film.axis_W);
  const double s = (z - z_journal_centre) / axis_cosine;
  const Vector3 offset = (film.p_WJ + s * film.journal_axis_W) - (film.p_WB + z * film.axis_W);
  return offset - offset.dot(film.axis_W) * film.axis_W;  // remove the rounding along a_B
}

double film_thickness(const FilmGeometry& film, double theta, double z) {
  return film_thickness_along(film, wall_normal(film, theta), z);
}

double film_thickness_along(const FilmGeometry& film, const Vector3& n, double z) {
  // The ray x(s) = C + s n from the bearing axis' point C in the plane z meets the journal's
  // cylinder where |w_perp + s n_perp|^2 = R_j^2 (w = C - P_j; perp: off the journal's axis),
  //   A s^2 + 2 b s + (|w_perp|^2 - R_j^2) = 0,  A = |n_perp|^2 = 1 - (n . a_j)^2,  b = w_perp . n_perp.
  // h = R_i - s+. s+ = R_j + t with t of the size of the eccentricity, so we solve for t:
  //   A t^2 + 2 b' t + k = 0,  b' = A R_j + b,  k = |w_perp|^2 + 2 b R_j - (n . a_j)^2 R_j^2,
  // and take its small root in the form without cancellation, t = -k / (b' + sqrt(b'^2 - A k)).
  // h = c - t, with c = R_i - R_j exact (Sterbenz): no difference of two radii is ever formed.
  const Vector3& a_j = film.journal_axis_W;
  const Vector3 w = (film.p_WB + z * film.axis_W) - film.p_WJ;
  const Vector3 w_perp = w - w.dot(a_j) * a_j;
  const double n_along = n.dot(a_j);
  const Vector3 n_perp = n - n_along * a_j;
  const double along_squared = n_along * n_along;
  const double a = 1.0 - along_squared;
  const double b = w_perp.dot(n_perp);
  const double r = film.journal_radius;
  const double b_shifted = a * r + b;
  const double k = w_perp.squaredNorm() + 2.0 * b * r - along_squared * r * r;
  const double t = -k / (b_shifted + std::sqrt(std::max(b_shifted * b_shifted - a * k, 0.0)));
  return film.radial_clearance - t;
}

double film_thickness_rate(const FilmGeometry& film, const RelativeMotion& motion, double theta,
                           double z) {
  return film_thickness_rate_along(film, motion, wall_normal(film, theta), z);
}

double film_thickness_rate_along(const FilmGeometry& film, const RelativeMotion& motion,
                                 const Vector3& n, double z) {
  // The journal axis' point in the plane z: q = P_j + s a_j, s = (z - z_j) / (a_j . a_B), with
  // z_j = (P_j - P_B) . a_B. In the bearing's frame (P_B, a_B still) its velocity is
  //   q' = v + s' a_j + s a_j',  a_j' = omega x a_j,
  //   s' = -(v . a_B) / cos - (z - z_j) (a_j' . a_B) / cos^2,  cos = a_j . a_B.
  const Vector3& a_j = film.journal_axis_W;
  const Vector3& v = motion.v_BJ_W;
  const double axis_cosine = a_j.dot(film.axis_W);
  const double z_journal_centre = (film.p_WJ - film.p_WB).dot(film.axis_W);
  const double s = (z - z_journal_centre) / axis_cosine;
  const Vector3 axis_rate = motion.omega_BJ_W.cross(a_j);
  const double s_rate = -v.dot(film.axis_W) / axis_cosine -
                        (z - z_journal_centre) * axis_rate.dot(film.axis_W) /
                            (axis_cosine * axis_cosine);
  const Vector3 q_rate = v + s_rate * a_j + s * axis_rate;
  return -q_rate.dot(n);
}

double journal_spin(const FilmGeometry& film, const RelativeMotion& motion) {
  return motion.omega_BJ_W.dot(film.axis_W);
}

ThinnestFilm thinnest_film(const FilmGeometry& film) {
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  ThinnestFilm best;
  bool first = true;
  // 1 / cos(gamma) - 1 = sin^2 / (cos (1 + cos)), with sin from the cross product: exact for the
  // small tilts where 1 - cos would round away.
  const double axis_cosine = std::abs(film.journal_axis_W.dot(film.axis_W));
  const double axis_sine = film.journal_axis_W.cross(film.axis_W).norm();
  const bool aligned =
      axis_sine * axis_sine <= kAlignedExcessFraction * axis_cosine * (1.0 + axis_cosine);
  for (const double z : {film.z_low, film.z_high}) {
    const Vector3 offset = journal_offset(film, z);
    const double centre =
        std::atan2(offset.dot(film.theta_quarter_W), offset.dot(film.theta_zero_W));
    if (aligned) {
      const double h = film_thickness(film, centre, z);
      if (first || h < best.thickness) {
        best = ThinnestFilm{h, wrap_angle(centre), z};
        first = false;
      }
      continue;
    }
    double low = centre - kThinnestFilmAngularBracket;
    double high = centre + kThinnestFilmAngularBracket;
    double left = high - golden * (high - low);
    double right = low + golden * (high - low);
    double h_left = film_thickness(film, left, z);
    double h_right = film_thickness(film, right, z);
    for (int step = 0; step < kGoldenSectionSteps; ++step) {
      if (h_left < h_right) {
        high = right;
        right = left;
        h_right = h_left;
        left = high - golden * (high - low);
        h_left = film_thickness(film, left, z);
      } else {
        low = left;
        left = right;
        h_left = h_right;
        right = low + golden * (high - low);
        h_right = film_thickness(film, right, z);
      }
    }
    const double theta = 0.5 * (low + high);
    const double h = film_thickness(film, theta, z);
    if (first || h < best.thickness) {
      best = ThinnestFilm{h, wrap_angle(theta), z};
      first = false;
    }
  }
  return best;
}

}  // namespace clearjoint::lubrication
