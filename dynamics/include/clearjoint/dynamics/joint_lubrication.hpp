// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A lubricated clearance revolute joint (issue 36): what the model says about the oil film, the
/// rule that passes from the film to dry contact, and what the film gives at one instant.
///
/// The film (clearjoint::lubrication) acts between the journal and the bearing as a force at the
/// journal's centre P_j and a moment about it; the bearing receives the opposite. It is computed
/// from the same JointDimensions and poses as the dry detection, so the two agree on where the
/// surfaces are, and from the journal's motion relative to the bearing body:
///   v_BJ = v_j - v_i - omega_i x (P_j - P_i),   omega_BJ = omega_j - omega_i   (world frame).
///
/// Passing to dry contact (the combined approach of the lubricated-joint literature, e.g. Flores,
/// Ambrosio, Claro, Lankarani & Koshy, Nonlinear Dyn. 56 (2009) 277-295: film force while the film
/// is thick, the dry contact law once it has broken down). With h the film's minimum thickness
/// (lubrication::thinnest_film), h_l the film_thickness_limit and w the transition_width:
///   F = lambda(h) F_film + F_dry,   lambda = 0 for h <= h_l, 1 for h >= h_l + w,
///   lambda = s^2 (3 - 2 s), s = (h - h_l) / w, in between (C1: value and slope continuous).
/// F_dry is the paper's contact law (Sections 3-4), zero until the surfaces interpenetrate
/// (h < 0), and h_l > 0, so the two never act at once: the sum is the weighted blend
/// (1 - lambda) F_dry + lambda F_film. The film force grows without bound as h -> 0
/// ((1 - eps^2)^-2 for rotation, (1 - eps^2)^-5/2 for squeeze), so it is faded out where it is
/// still finite, over a band of thicknesses rather than at one; h_l stands for the thickness at
/// which the asperities of the two surfaces meet (of the order of their combined roughness).

#include <optional>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/euler_parameters.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"

namespace clearjoint::dynamics {

/// How the film's pressure is solved: lubrication::BearingMethod, named "short", "long", "grid"
/// (its EnumTable's keys). short and long are the Ocvirk and Sommerfeld closed forms at the
/// film's mid-plane (an aligned journal, half-Sommerfeld); grid is the ReynoldsGridSolver (any
/// pose, tilt included, either cavitation model); table is the grid's half-Sommerfeld film
/// tabulated once per bearing (lubrication::FilmTable), the grid itself where the table does not
/// reach (a tilted journal, a groove, eps above lubrication::kTableLargestEccentricityRatio).
using FilmMethod = lubrication::BearingMethod;
/// The method whose key is `name`; throws ModelError `<field> = "<name>": unknown ...`
/// listing the names.
FilmMethod film_method_from_string(std::string_view name, std::string_view field);
/// The cavitation model whose key is `name`, throwing ModelError like the above.
lubrication::CavitationModel cavitation_model_from_string(std::string_view name,
                                                          std::string_view field);

/// Which force carried the joint at one instant (the force table's film.regime column).
enum class FilmRegime {
  dry = 0,    ///< lambda = 0: the film has broken down; the dry contact law alone
  film = 1,   ///< lambda = 1: the film alone
  blend = 2,  ///< 0 < lambda < 1: the film, faded (see the file comment)
};

/// A model file's "lubrication" object of a clearance_revolute force.
struct JointLubrication {
  double viscosity = 0.0;  ///< eta, Pa s, > 0
  lubrication::CavitationModel cavitation = lubrication::CavitationModel::half_sommerfeld;
  FilmMethod method = FilmMethod::short_bearing;
  /// The grid (methods grid and table): N_theta around, N_z across; 48 x 12 keeps So within about 1 % of
  /// Raimondi & Boyd at B/D = 1 (docs/lubrication.md) at about 0.3 ms a solve.
  int circumferential_cells = 48;
  int axial_cells = 12;
  /// Solve a grid above the solver's cost limits (lubrication::kMaxGridBandBytes,
  /// kMaxGridOperations); off, such a grid is refused when the model is read.
  bool allow_large_grid = false;
  /// An axial oil groove fixed in the bearing (needed by the mass-conserving model, which
  /// otherwise drains): its direction from the bearing's axis in the bearing body's frame, and
  /// its gauge supply pressure. Absent: an enclosed film fed at its ends at ambient pressure.
  std::optional<Vector3> groove_direction_B;
  double supply_pressure = 0.0;  ///< Pa, >= 0
  double film_thickness_limit = 0.0;  ///< h_l, m, > 0: below it the film carries nothing
  /// w, m, > 0: the film is faded in over [h_l, h_l + w]. The joint reads this struct's 0 as
  /// "= h_l" (a model file's default too).
  double transition_width = 0.0;
};

/// The viscosities accepted, Pa s: every fluid a journal bearing runs on lies inside, from gases
/// (hydrogen 8.9e-6, air 1.8e-5) to bitumen-like greases (about 1e5); beyond, the film force of
/// any joint the geometry accepts leaves the range the integrator's step control can follow.
inline constexpr double kSmallestViscosity = 1e-6;
inline constexpr double kLargestViscosity = 1e6;
/// The largest gauge supply pressure, Pa: 1 GPa is above any oil feed (hydrostatic bearings run
/// at tens of MPa) and of the order of the peak pressures of elastohydrodynamic contacts.
inline constexpr double kLargestSupplyPressure = 1e9;
/// h_l and w relative to the radial clearance c: at least 1e-6 c (with c >= 10 um that is below
/// 1e-11 m, under an atomic diameter, so any physical asperity height lies above; the film force
/// at h_l, which grows as (c / h_l)^2, then stays within 1e12 of its centred value), and h_l
/// below c, w at most c: the film is never thicker than c (eps = 0), so a larger limit or band
/// would leave the film never (or never fully) applied.
inline constexpr double kSmallestFilmLengthOfClearance = 1e-6;

/// Throw ModelError naming "<name>.<field>" and the accepted range for a viscosity outside
/// [kSmallestViscosity, kLargestViscosity], a supply pressure outside [0, kLargestSupplyPressure],
/// a film_thickness_limit outside [1e-6 c, c) or a transition_width outside [1e-6 c, c] (c the
/// joint's radial clearance, kSmallestFilmLengthOfClearance), a grid below 8 x 2 cells or above
/// the solver's cost limit without allow_large_grid, a closed form with the mass-conserving model,
/// a mass-conserving film without a groove, or a zero groove direction.
void validate(const JointLubrication& lubrication, const std::string& name, double radial_clearance);

/// lambda(h) of the file comment: the share of the film force applied at minimum thickness h.
double film_weight(const JointLubrication& lubrication, double min_thickness) noexcept;
/// The regime of a weight.
FilmRegime film_regime(double weight) noexcept;

/// The film at one instant. Quantities the film solution gives (pressure, attitude angle) are
/// NaN when it was not solved (regime dry: its weight is zero).
struct JointFilmState {
  FilmRegime regime = FilmRegime::dry;
  double weight = 0.0;               ///< lambda
  double min_thickness = 0.0;        ///< h_min, m (negative where the surfaces interpenetrate)
  double eccentricity_ratio = 0.0;   ///< eps = |e| / c at the film's mid-plane
  double attitude_angle = 0.0;       ///< beta, rad: from the load carried (-F) to the line of centres
  double max_pressure = 0.0;         ///< largest gauge pressure, Pa
  Vector3 force_on_journal_W = Vector3::Zero();   ///< lambda F_film, N
  Vector3 moment_on_journal_W = Vector3::Zero();  ///< lambda M_film about P_j, N m
  /// The film's power on the system, F . v_BJ + M . omega_BJ, W (the rate of film.work).
  double power = 0.0;
};

}  // namespace clearjoint::dynamics
