// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The film between a journal and its bearing, over the bearing's unwrapped surface.
///
/// Coordinates: z along the bearing's unit axis a_B, measured from the bearing's centre P_B;
/// theta around that axis, from the unit direction theta_zero_W (perpendicular to a_B), positive
/// by the right-hand rule about a_B. The wall normal n(theta) = cos(theta) theta_zero_W +
/// sin(theta) (a_B x theta_zero_W) points from the bearing's axis to its wall.
///
/// The film thickness h(theta, z) is the gap measured along n(theta) from the journal's
/// cylinder to the bearing's wall: exact for any pose (offset, tilt), from the same
/// geometry::JointDimensions and geometry::PartPose as the dry contact detection, so that a
/// lubricated and a dry joint agree on where the surfaces are. h < 0 where the journal's cylinder
/// reaches through the wall.

#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/lubrication/relative_motion.hpp"

namespace clearjoint::lubrication {

/// One journal pose in one bearing, resolved once (describe_film) for every film query.
struct FilmGeometry {
  Vector3 p_WB = Vector3::Zero();             ///< bearing centre P_B (origin of z)
  Vector3 axis_W = Vector3::UnitZ();          ///< bearing unit axis a_B
  Vector3 theta_zero_W = Vector3::UnitX();    ///< n(0), unit, perpendicular to a_B
  Vector3 theta_quarter_W = Vector3::UnitY(); ///< n(pi/2) = a_B x n(0)
  Vector3 p_WJ = Vector3::Zero();             ///< journal centre P_j
  Vector3 journal_axis_W = Vector3::UnitZ();  ///< journal unit axis a_j, a_j . a_B > 0
  double bearing_radius = 0.0;                ///< R_i
  double journal_radius = 0.0;                ///< R_j
  double radial_clearance = 0.0;              ///< c = R_i - R_j, eq. (1)
  /// The film's axial extent [z_low, z_high]: where the journal's axis segment, projected on
  /// the bearing's axis, overlaps the bearing. A tilt gamma moves a rim's real end by up to
  /// R_j sin(gamma) around the circumference; this extent ignores that, a relative error of
  /// order R_j gamma / B in the width B, below c / B for any tilt the clearance allows.
  double z_low = 0.0;
  double z_high = 0.0;

  double width() const noexcept { return z_high - z_low; }
};

/// Resolve a pose. theta_zero_hint_W fixes theta = 0 (its part perpendicular to the bearing's
/// axis; when it has none, a fixed perpendicular is chosen). Throws geometry::InvalidInput for bad
/// dimensions or poses (geometry::validate), a journal axis perpendicular to the bearing's, or a
/// journal that does not overlap its bearing axially.
FilmGeometry describe_film(const geometry::JointDimensions& dimensions,
                           const geometry::PartPose& bearing, const geometry::PartPose& journal,
                           const Vector3& theta_zero_hint_W);

/// n(theta), the unit wall normal.
Vector3 wall_normal(const FilmGeometry& film, double theta);

/// The journal axis' offset from the bearing's axis at the station z: the point of the journal's
/// axis line in the plane z, minus the bearing axis' point there (perpendicular to a_B). Its
/// length is the local eccentricity e(z); the film is thinnest towards it.
Vector3 journal_offset(const FilmGeometry& film, double z);

/// h(theta, z) in metres (see the file comment); computed in the stable form of the ray-cylinder
/// root (film_thickness.cpp), so that its rounding error is a few ulps of R_j, not of R_j / c.
double film_thickness(const FilmGeometry& film, double theta, double z);

/// dh/dt at (theta, z) for the relative motion: -(velocity of the journal axis' point in the
/// plane z) . n(theta), the squeeze of the film. First order in c / R (the classical Reynolds
/// film); the journal's spin does not change h.
double film_thickness_rate(const FilmGeometry& film, const RelativeMotion& motion, double theta,
                           double z);

/// film_thickness and film_thickness_rate along a wall normal n = wall_normal(film, theta) that
/// the caller has already formed: for sampling many stations z at one theta (the Reynolds grid)
/// without a sine and a cosine at each.
double film_thickness_along(const FilmGeometry& film, const Vector3& n_W, double z);
double film_thickness_rate_along(const FilmGeometry& film, const RelativeMotion& motion,
                                 const Vector3& n_W, double z);

/// The journal's spin about the bearing's axis relative to the bearing, omega_BJ . a_B (rad/s):
/// what drives the wedge term.
double journal_spin(const FilmGeometry& film, const RelativeMotion& motion);

/// The thinnest film and where it is.
struct ThinnestFilm {
  double thickness = 0.0;  ///< h_min, m (negative: the journal reaches through the wall)
  double theta = 0.0;      ///< rad, in [0, 2 pi)
  double z = 0.0;          ///< m, z_low or z_high (ties: z_low)
};

/// h_min over the film. To first order in c / R, h(theta, z) = c - e(z) . n(theta) with e(z)
/// affine in z, so min over theta is c - |e(z)|, concave in z: the minimum lies at an end of the
/// film, in the direction of e there. Each end is refined by golden-section search in theta
/// around that direction (kThinnestFilmAngularBracket), to the exact h. An aligned journal's
/// film is exactly thinnest in that direction (its section is a circle about e(z)'s point): for a
/// tilt whose effect on h is below rounding (film_thickness.cpp) the search is skipped.
ThinnestFilm thinnest_film(const FilmGeometry& film);

/// Half-width of the theta bracket searched around e(z)'s direction (rad). The exact minimum
/// lies within O((c / R) gamma^2) of that direction for a tilt gamma; 0.05 rad is generous.
inline constexpr double kThinnestFilmAngularBracket = 0.05;

}  // namespace clearjoint::lubrication
