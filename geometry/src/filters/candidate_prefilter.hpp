// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The reach prefilters of a misaligned joint's four candidate point contacts (radial and axial at
// bases A and B; paper eqs. 11-21), proved together. They are the tests rim_reach and
// rim_side_of_plane make (the same formulas and a priori bounds, a_priori_bounds.hpp), with the
// terms the four share (the wall axis, the rim normal, n_p x n_c, the magnitude guard) computed
// once, and bases A and B side by side in SSE2 lanes (candidate_prefilter_lanes.hpp). In free
// flight they are the whole detection.

#include <array>

#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// The joint in the bearing-centred frame of detect_contacts (the wall's axis passes through the
/// origin). Index 0: base A, 1: base B. The radial tests take the circles centred at
/// radial_centres (the rims when the axes are misaligned; the journal's mid-length section twice
/// for the aligned line contact), the axial tests the rims.
struct CandidatePrefilterInput {
  std::array<Vector3, 2> radial_centres;  ///< rounded
  std::array<double, 2> radial_errors;    ///< bounds on their distance to the exact centres
  std::array<Vector3, 2> rim_centres;     ///< journal rim centres, rounded
  std::array<double, 2> rim_errors;
  std::array<Vector3, 2> base_points;  ///< bearing base centres, rounded
  std::array<double, 2> base_errors;
  Vector3 bearing_axis;  ///< a_i as given: the wall's axis; base plane normals +a_i (A), -a_i (B)
  Vector3 journal_axis;  ///< a_j as given: the rim normals
  double bearing_radius = 0.0;
  double journal_radius = 0.0;
};

/// true where that candidate is proved absent for every centre and base point within the errors:
/// radial at X when the circle at radial_centres[X] stays strictly inside the wall, axial at X
/// when rim X stays strictly on the inner side of base plane X.
struct CandidatesClear {
  std::array<bool, 2> radial{false, false};
  std::array<bool, 2> axial{false, false};
};
CandidatesClear prove_candidates_clear(const CandidatePrefilterInput& in);

}  // namespace clearjoint::geometry::detail
