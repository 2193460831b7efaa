// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The finite-width film for any journal pose (offset, tilt): the Reynolds equation on the
/// bearing's unwrapped surface, solved by finite volumes.
///
/// In theta and zeta = z / R (R the journal's radius), with H = h / c and P = p c^2 / (eta R^2),
///   d/dtheta(H^3 dP/dtheta) + d/dzeta(H^3 dP/dzeta) = 6 omega d(f H)/dtheta + 12 f dH/dt / c,
/// omega the journal's spin relative to the bearing, f the film fraction (1 in the full film).
/// Grid: N_theta cells around (periodic, or cut at an axial supply groove, which is then the
/// column theta = 0 at the supply pressure), N_z intervals across with ambient pressure at both
/// ends. H^3 is evaluated exactly at each cell face (film_thickness), so the scheme is second
/// order in the full film. Cavitation (film_conditions.hpp):
/// - half_sommerfeld: one sparse solve with f = 1, then negative pressures set to ambient;
/// - mass_conserving (Elrod-Adams): each node is either full (P >= 0, f = 1) or cavitated
///   (P = 0, 0 <= f < 1); the Couette flux f H is upwinded, and the piecewise-linear system is
///   solved by the active-set (semi-smooth Newton) iteration of Brugnano & Casulli (SIAM J. Sci.
///   Comput. 30, 2008): each step one sparse LU solve, stopping when the set of full nodes no
///   longer changes. The rupture boundary this gives satisfies the Reynolds condition; the scheme
///   is first order next to the cavity (upwinding), second order elsewhere.
/// Each linear solve factorises the system as a band matrix (unknowns column by column; around
/// a periodic film the columns are folded so that the band stays narrow), with no set-up of
/// its own to redo at every call: a 48 x 12 grid costs tens of microseconds. The band holds
/// about 3 N_theta N_z^2 doubles with a groove and 6 N_theta N_z^2 without (2.4 MB at 96 x 24,
/// periodic); its elimination costs of order N_theta N_z^3, so refine around before across.
/// Why not a Gauss-Seidel/SOR Elrod iteration: its sweeps grow with the grid and its stopping
/// rule is a tolerance, while the active-set iteration ends exactly after a few solves, and
/// fewer still when warm-started: the previous call's solution (same grid) is the first guess.

#include <memory>
#include <vector>
#include <string_view>

#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/film_load.hpp"
#include "clearjoint/lubrication/relative_motion.hpp"

namespace clearjoint::lubrication {

/// How each linear system is solved. Both give the same pressures to rounding; the second is
/// the general sparse factorisation that the first is checked and timed against.
enum class ReynoldsLinearSolver {
  band_lu,    ///< Gaussian elimination with partial pivoting in band storage (the default)
  sparse_lu,  ///< Eigen's SparseLU with a COLAMD ordering, set up again at every factorisation
};

}  // namespace clearjoint::lubrication

/// Keys "band_lu", "sparse_lu".
template <>
struct clearjoint::geometry::EnumTable<clearjoint::lubrication::ReynoldsLinearSolver> {
  using S = clearjoint::lubrication::ReynoldsLinearSolver;
  static constexpr std::string_view type_name = "ReynoldsLinearSolver";
  static constexpr auto entries = std::to_array({
      named_entry(S::band_lu, "band_lu", "band LU with partial pivoting"),
      named_entry(S::sparse_lu, "sparse_lu", "Eigen SparseLU, COLAMD ordering"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::lubrication::ReynoldsLinearSolver>());

namespace clearjoint::lubrication {

/// The key of the solver's entry in its table.
std::string_view to_string(ReynoldsLinearSolver solver) noexcept;

/// The grid and the cavitation model.
struct ReynoldsGridOptions {
  int circumferential_cells = 96;  ///< N_theta >= 8
  int axial_cells = 24;            ///< N_z >= 2 (intervals; N_z - 1 unknown rows)
  CavitationModel cavitation = CavitationModel::mass_conserving;
  int max_iterations = 100;  ///< active-set steps before giving up (converged = false)
  ReynoldsLinearSolver linear_solver = ReynoldsLinearSolver::band_lu;
  /// Solve a grid whose estimated cost (estimate_cost) is above kMaxGridBandBytes or
  /// kMaxGridOperations. Off, such a grid is refused before anything is allocated.
  bool allow_large_grid = false;
};

/// What one linear solve of a grid costs, estimated from its size alone before anything is
/// allocated, for the periodic film (the wider band: half-width 2 (N_z - 1) rows against N_z - 1
/// with a groove). The active-set iteration repeats the solve a few times (5 cold at 96 x 24).
struct ReynoldsGridCost {
  double unknowns = 0.0;    ///< N_theta (N_z - 1)
  double band_bytes = 0.0;  ///< the band's storage: unknowns x (3 half-width + 1) doubles
  double operations = 0.0;  ///< the elimination's multiplications and additions: 4 unknowns half-width^2
};
ReynoldsGridCost estimate_cost(const ReynoldsGridOptions& options) noexcept;

/// The largest band a grid may need without allow_large_grid: 64 MiB. The default 96 x 24 grid
/// needs 2.4 MB and 192 x 48, twice as fine both ways, 20 MB; 96 x 400 needed 734 MB (378 MB
/// with a groove, as measured) and 22.6 s.
inline constexpr double kMaxGridBandBytes = 64.0 * 1024 * 1024;
/// The most elimination operations a solve may need without allow_large_grid: 1e9, about half a
/// second on one core at the measured rate (96 x 400 with a groove, about 2.4e10 operations a
/// solve by estimate_cost's count for its narrower band, took 22.6 s for 5 solves); 96 x 24
/// needs 1.9e7, 192 x 48 3.2e8.
inline constexpr double kMaxGridOperations = 1e9;
/// The band is indexed with int: a grid whose band has more entries than an int counts is
/// refused even with allow_large_grid (it could not be stored).
inline constexpr double kMaxGridBandEntries = 2147483647.0;

/// Throw geometry::InvalidInput naming the field for a grid below the minimum (a 1 x 1 grid has no
/// unknown), a non-positive iteration limit, or a grid whose estimated cost is above the limits
/// (the message gives the estimate; allow_large_grid lifts kMaxGridBandBytes and
/// kMaxGridOperations, not kMaxGridBandEntries).
void validate(const ReynoldsGridOptions& options);

/// The widest film the grid solves, as width / diameter: 1e4. The axial term of the Reynolds
/// equation is scaled by (D / B)^2 against the circumferential one, so the band solve's rounding
/// grows as (B / D)^2 times the unit roundoff; measured on the default 96 x 24 grid against the
/// Sommerfeld number's limit as B / D grows (eps 0.1 to 0.97): within 1.2e-5 up to 1e5, 1.4e-3
/// off at 1e6, 19 % off at 1e7. At 1e4 the rounding stays far below the grid's discretisation
/// error; a wider bearing is the long-bearing limit (method long).
inline constexpr double kLargestGridWidthRatio = 1e4;
/// Refuses a film wider than kLargestGridWidthRatio diameters, naming `field`.
void validate_grid_width_ratio(double width_ratio, std::string_view field);

/// A solver that keeps its grid, factorisation pattern and last solution between calls. Not
/// thread-safe: one per joint (or per thread). Copyable state is deliberately not offered.
class ReynoldsGridSolver {
 public:
  explicit ReynoldsGridSolver(const ReynoldsGridOptions& options = {});
  ~ReynoldsGridSolver();
  ReynoldsGridSolver(ReynoldsGridSolver&&) noexcept;
  ReynoldsGridSolver& operator=(ReynoldsGridSolver&&) noexcept;

  /// The film load for the journal at `journal` in the bearing at `bearing`. theta = 0 lies at the
  /// groove for a grooved supply, else on the line of centres at the film's middle. Throws
  /// geometry::InvalidInput for bad input and when the film is not open everywhere (h_min <= 0:
  /// the journal touches the wall and contact, not the film, carries it).
  FilmLoad solve(const geometry::JointDimensions& dimensions, const geometry::PartPose& bearing,
                 const geometry::PartPose& journal, const RelativeMotion& motion,
                 const Lubricant& lubricant, const OilSupply& supply = {});

  /// The same on a film already resolved (theta = 0 as film.theta_zero_W; with a groove, that
  /// must be the groove's direction).
  FilmLoad solve(const FilmGeometry& film, const RelativeMotion& motion, const Lubricant& lubricant,
                 const OilSupply& supply = {});

  /// The last solve's pressure at the grid's unknown nodes, Pa, before a half-Sommerfeld solve
  /// sets its negative values to ambient: node (i, j), at theta = 2 pi i / N_theta from
  /// theta_zero_W and z = z_low + j B / N_z, j = 1 ... N_z - 1, at index i (N_z - 1) + j - 1, for
  /// a periodic film (no groove). Empty before the first solve. For half-Sommerfeld the system is
  /// linear in the motion (its matrix depends on the film's shape only), which is what lets
  /// FilmTable superpose these fields.
  std::vector<double> unclipped_pressures() const;

  /// Start the next call from a full film instead of the previous solution.
  void forget_previous_solution();

  const ReynoldsGridOptions& options() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace clearjoint::lubrication
