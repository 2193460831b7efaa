// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The oil film of one lubricated clearance joint at one instant: from the parts' poses and
/// relative motion to the weighted film force (joint_lubrication.hpp) and what the force table
/// records. Private to the dynamics module: ClearanceRevoluteJoint owns one.

#include <memory>
#include <optional>

#include "clearjoint/dynamics/joint_lubrication.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/lubrication/relative_motion.hpp"
#include "clearjoint/lubrication/film_table.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"

namespace clearjoint::dynamics {

/// Counters for the run summary.
struct JointFilmStatistics {
  long solves = 0;          ///< film solutions (instants with a non-zero film weight)
  long not_converged = 0;   ///< grid solves whose active set did not settle (FilmLoad::converged)
  long linear_solves = 0;   ///< sparse LU solves of the grid
  long table_fallbacks = 0; ///< method table: solutions the grid gave (outside the table's domain)
};

/// What JointFilm::evaluate computes beyond the force, moment, power and regime.
enum class FilmDetail {
  /// Also the largest pressure, as the force table records it.
  outputs,
  /// The force alone, for a right-hand side: max_pressure may be NaN. The short bearing's peak
  /// pressure is a search that costs more than its force; the other methods find it for free.
  force,
};

class JointFilm {
 public:
  /// `lubrication` must have passed validate().
  JointFilm(const JointLubrication& lubrication, const geometry::JointDimensions& dimensions);

  /// The film for the bearing and journal at these poses (world frame) and the journal's motion
  /// relative to the bearing body. groove_W: the groove's direction in W (the bearing turns it),
  /// when the model has one. Throws geometry::InvalidInput for poses the film cannot describe and
  /// std::runtime_error for a singular grid system; the joint turns both into a SolverError.
  ///
  /// The grid solver keeps its last active set (which nodes carry pressure) as the first guess of
  /// the next solve: that changes how many linear solves a call costs, not its answer, which is the
  /// solution of the linear system of the final active set, the same from any first guess once
  /// the iteration has converged (Brugnano & Casulli 2008: the discrete problem has one solution).
  /// So add_forces stays a function of (t, y) at trial stages and rejected steps alike; a solve
  /// that does not converge is counted (statistics().not_converged) and keeps its last iterate.
  JointFilmState evaluate(const geometry::PartPose& bearing, const geometry::PartPose& journal,
                          const std::optional<Vector3>& groove_W,
                          const lubrication::RelativeMotion& motion,
                          FilmDetail detail = FilmDetail::outputs);

  const JointFilmStatistics& statistics() const { return statistics_; }

 private:
  JointLubrication lubrication_;
  geometry::JointDimensions dimensions_;
  std::optional<lubrication::ReynoldsGridSolver> grid_;  ///< methods grid and table (its fallback)
  /// Method table: the table of the film's current width, from FilmTable::shared on first use.
  std::shared_ptr<const lubrication::FilmTable> table_;
  JointFilmStatistics statistics_;
};

}  // namespace clearjoint::dynamics
