// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/reynolds_grid.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "band_lu.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {

namespace {

constexpr int kSmallestCircumferentialCells = 8;  // fewer cannot resolve one pressure lobe
constexpr int kSmallestAxialCells = 2;            // at least one unknown row between the ends

constexpr double kMebibyte = 1024.0 * 1024.0;  // for messages

enum Neighbour { kSelf = 0, kEast, kWest, kNorth, kSouth, kNeighbours };

void require_grid(bool holds, const char* field, int value, const char* rule) {
  if (holds) return;
  std::ostringstream message;
  message << "options." << field << " = " << value << ": " << rule;
  throw geometry::InvalidInput(message.str());
}

}  // namespace

void validate(const ReynoldsGridOptions& options) {
  require_grid(options.circumferential_cells >= kSmallestCircumferentialCells,
               "circumferential_cells", options.circumferential_cells, "must be at least 8");
  require_grid(options.axial_cells >= kSmallestAxialCells, "axial_cells", options.axial_cells,
               "must be at least 2 (the ends are at ambient pressure; no unknown lies between "
               "them otherwise)");
  require_grid(options.max_iterations >= 1, "max_iterations", options.max_iterations,
               "must be at least 1");
  const ReynoldsGridCost cost = estimate_cost(options);
  const double entries = cost.band_bytes / sizeof(double);
  const bool too_large = cost.band_bytes > kMaxGridBandBytes || cost.operations > kMaxGridOperations;
  if (entries > kMaxGridBandEntries || (too_large && !options.allow_large_grid)) {
    std::ostringstream message;
    message.precision(2);
    message << "options.circumferential_cells x axial_cells = " << options.circumferential_cells << "x"
            << options.axial_cells << ": estimated " << cost.band_bytes / kMebibyte << " MiB of band and "
            << cost.operations << " operations a linear solve, ";
    if (entries > kMaxGridBandEntries) {
      message << "more band entries than an int counts (" << kMaxGridBandEntries << "): too large to store";
    } else {
      message << "above the limits (" << kMaxGridBandBytes / kMebibyte << " MiB, " << kMaxGridOperations
              << " operations, about half a second a solve); allow_large_grid "
                 "solves it anyway";
    }
    throw geometry::InvalidInput(message.str());
  }
}

ReynoldsGridCost estimate_cost(const ReynoldsGridOptions& options) noexcept {
  ReynoldsGridCost cost;
  // In double: the counts of a grid near the int limit overflow an int.
  const double rows = std::max(0.0, static_cast<double>(options.axial_cells) - 1.0);
  const double columns = std::max(0.0, static_cast<double>(options.circumferential_cells));
  const double half_band = 2.0 * rows;  // periodic: neighbours folded two columns apart
  cost.unknowns = columns * rows;
  cost.band_bytes = cost.unknowns * (3.0 * half_band + 1.0) * sizeof(double);
  // Each of the unknowns' eliminations updates half_band rows over 2 half_band columns (the
  // pivots' fill included), a multiplication and an addition each.
  cost.operations = 4.0 * cost.unknowns * half_band * half_band;
  return cost;
}

std::string_view to_string(ReynoldsLinearSolver solver) noexcept { return geometry::key_of(solver); }

struct ReynoldsGridSolver::State {
  ReynoldsGridOptions options;
  // The pattern, built for one grid and one supply kind (periodic, or cut at a groove).
  bool pattern_built = false;
  bool pattern_grooved = false;
  int first_column = 0;  // 1 with a groove: column 0 is the groove
  int columns = 0;       // unknown columns
  int rows = 0;          // unknown rows (axial_cells - 1)
  // Where each grid column's unknowns sit in the system: see build_pattern.
  std::vector<int> column_position;
  // The system, in one of two stores (options.linear_solver); `values` points into it.
  detail::BandLu band;
  Eigen::SparseMatrix<double> matrix;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  double* values = nullptr;
  std::vector<std::array<int, kNeighbours>> positions;  // value index of each stencil entry
  // The last solution (u: P where full, f - 1 where cavitated) and which nodes were full.
  bool has_previous = false;
  Eigen::VectorXd u;
  double pressure_scale = 0.0;  // of the last solve: p = pressure_scale P
  std::vector<char> full;
  // Per-call work arrays.
  std::vector<double> h_east, h3_east, h3_north, h_rate;
  Eigen::VectorXd rhs;

  int index(int column, int row) const { return column_position[column] * rows + (row - 1); }
  void build_pattern(bool grooved);
  void clear_values();
  void factorize_and_solve();
};

void ReynoldsGridSolver::State::build_pattern(bool grooved) {
  const int n_theta = options.circumferential_cells;
  rows = options.axial_cells - 1;
  first_column = grooved ? 1 : 0;
  columns = n_theta - first_column;
  const int unknowns = columns * rows;
  // Unknowns column by column, axially within a column. Cut at a groove, the columns keep their
  // order and the system is a band of half-width `rows`. Periodic, they are folded (0, 1, N-1,
  // 2, N-2, ...) so that neighbours around the circle, the pair (N-1, 0) included, lie at most
  // two columns apart: a band of half-width 2 rows instead of one with far corners.
  column_position.assign(n_theta, -1);
  if (grooved) {
    for (int i = 1; i < n_theta; ++i) column_position[i] = i - 1;
  } else {
    for (int i = 0; i < n_theta; ++i) {
      column_position[i] = i == 0 ? 0 : (2 * i <= n_theta ? 2 * i - 1 : 2 * (n_theta - i));
    }
  }
  const int half_band = grooved ? rows : 2 * rows;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(unknowns) * kNeighbours);
  std::vector<std::array<int, kNeighbours>> neighbour(unknowns);
  for (int i = first_column; i < n_theta; ++i) {
    for (int j = 1; j <= rows; ++j) {
      const int k = index(i, j);
      const int east = (i + 1) % n_theta, west = (i + n_theta - 1) % n_theta;
      neighbour[k] = {k, (grooved && east == 0) ? -1 : index(east, j),
                      (grooved && west == 0) ? -1 : index(west, j), j < rows ? index(i, j + 1) : -1,
                      j > 1 ? index(i, j - 1) : -1};
      for (const int m : neighbour[k]) {
        if (m >= 0) entries.emplace_back(k, m, 1.0);
      }
    }
  }
  positions.assign(unknowns, {-1, -1, -1, -1, -1});
  if (options.linear_solver == ReynoldsLinearSolver::band_lu) {
    band.resize(unknowns, half_band, half_band);
    values = band.values();
    for (int k = 0; k < unknowns; ++k) {
      for (int e = 0; e < kNeighbours; ++e) {
        if (neighbour[k][e] >= 0) positions[k][e] = band.slot(k, neighbour[k][e]);
      }
    }
  } else {
    matrix.resize(unknowns, unknowns);
    matrix.setFromTriplets(entries.begin(), entries.end());
    matrix.makeCompressed();
    values = matrix.valuePtr();
    for (int k = 0; k < unknowns; ++k) {
      for (int e = 0; e < kNeighbours; ++e) {
        const int m = neighbour[k][e];
        if (m < 0) continue;
        // Entry (k, m) lives in column m (column-major storage): find its slot once.
        const int* begin = matrix.innerIndexPtr() + matrix.outerIndexPtr()[m];
        const int* end = matrix.innerIndexPtr() + matrix.outerIndexPtr()[m + 1];
        positions[k][e] =
            static_cast<int>(std::lower_bound(begin, end, k) - matrix.innerIndexPtr());
      }
    }
    lu.analyzePattern(matrix);
  }
  pattern_built = true;
  pattern_grooved = grooved;
  has_previous = false;
}

void ReynoldsGridSolver::State::clear_values() {
  if (options.linear_solver == ReynoldsLinearSolver::band_lu) {
    band.clear();
  } else {
    std::fill(values, values + matrix.nonZeros(), 0.0);
  }
}

void ReynoldsGridSolver::State::factorize_and_solve() {
  if (options.linear_solver == ReynoldsLinearSolver::band_lu) {
    if (!band.factorize()) {
      throw std::runtime_error("lubrication: the Reynolds system is singular (zero pivot)");
    }
    u = rhs;
    band.solve(u.data());
    return;
  }
  lu.factorize(matrix);
  if (lu.info() != Eigen::Success) {
    throw std::runtime_error("lubrication: the Reynolds system is singular (" +
                             lu.lastErrorMessage() + ")");
  }
  u = lu.solve(rhs);
}

ReynoldsGridSolver::ReynoldsGridSolver(const ReynoldsGridOptions& options)
    : state_(std::make_unique<State>()) {
  validate(options);
  state_->options = options;
}
ReynoldsGridSolver::~ReynoldsGridSolver() = default;
ReynoldsGridSolver::ReynoldsGridSolver(ReynoldsGridSolver&&) noexcept = default;
ReynoldsGridSolver& ReynoldsGridSolver::operator=(ReynoldsGridSolver&&) noexcept = default;

const ReynoldsGridOptions& ReynoldsGridSolver::options() const { return state_->options; }

void ReynoldsGridSolver::forget_previous_solution() { state_->has_previous = false; }

std::vector<double> ReynoldsGridSolver::unclipped_pressures() const {
  const State& s = *state_;
  if (!s.has_previous || s.pattern_grooved) return {};
  std::vector<double> pressures(static_cast<std::size_t>(s.columns) * s.rows);
  for (int i = 0; i < s.columns; ++i) {
    for (int j = 1; j <= s.rows; ++j) {
      pressures[static_cast<std::size_t>(i) * s.rows + (j - 1)] = s.pressure_scale * s.u[s.index(i, j)];
    }
  }
  return pressures;
}

FilmLoad ReynoldsGridSolver::solve(const geometry::JointDimensions& dimensions,
                                   const geometry::PartPose& bearing,
                                   const geometry::PartPose& journal, const RelativeMotion& motion,
                                   const Lubricant& lubricant, const OilSupply& supply) {
  validate(supply);
  Vector3 hint = supply.groove_direction_W;
  if (supply.kind == OilSupply::Kind::none) {
    // theta = 0 on the line of centres at the film's middle: the grid follows the journal, so
    // the previous solution stays a good first guess as the journal orbits.
    const FilmGeometry provisional = describe_film(dimensions, bearing, journal, Vector3::UnitX());
    hint = journal_offset(provisional, 0.5 * (provisional.z_low + provisional.z_high));
  }
  return solve(describe_film(dimensions, bearing, journal, hint), motion, lubricant, supply);
}

void validate_grid_width_ratio(double width_ratio, std::string_view field) {
  if (width_ratio <= kLargestGridWidthRatio) return;
  std::ostringstream message;
  message << field << " = " << width_ratio
          << ": the grid solves films at most 1e4 diameters wide (beyond, its rounding grows as the "
             "square of the width; use method = long, the infinitely long bearing)";
  throw geometry::InvalidInput(message.str());
}

FilmLoad ReynoldsGridSolver::solve(const FilmGeometry& film, const RelativeMotion& motion,
                                   const Lubricant& lubricant, const OilSupply& supply) {
  validate(lubricant);
  validate(supply);
  validate_grid_width_ratio(film.width() / (2.0 * film.journal_radius), "film width / diameter");
  State& s = *state_;
  const bool grooved = supply.kind == OilSupply::Kind::axial_groove;
  if (!s.pattern_built || s.pattern_grooved != grooved) s.build_pattern(grooved);

  FilmLoad load;
  load.thinnest = thinnest_film(film);
  if (!(load.thinnest.thickness > 0.0)) {
    std::ostringstream message;
    message << "thinnest film = " << load.thinnest.thickness
            << " m: the journal touches its bearing; contact, not the film, carries the load";
    throw geometry::InvalidInput(message.str());
  }

  const int n_theta = s.options.circumferential_cells;
  const int n_z = s.options.axial_cells;
  const double pi = std::numbers::pi;
  const double d_theta = 2.0 * pi / n_theta;
  const double radius = film.journal_radius;
  const double c = film.radial_clearance;
  const double d_z = film.width() / n_z;
  const double d_zeta = d_z / radius;
  const double omega = journal_spin(film, motion);
  auto z_at = [&](double row) { return film.z_low + row * d_z; };

  // Film samples: H and H^3 on the east faces (i + 1/2, j), H^3 on the north faces (i, j + 1/2),
  // dH/dt at the nodes; index column * (n_z + 1) + row.
  const std::size_t samples = static_cast<std::size_t>(n_theta) * (n_z + 1);
  s.h_east.assign(samples, 0.0);
  s.h3_east.assign(samples, 0.0);
  s.h3_north.assign(samples, 0.0);
  s.h_rate.assign(samples, 0.0);
  for (int i = 0; i < n_theta; ++i) {
    const double theta = i * d_theta;
    const Vector3 n_node = wall_normal(film, theta);  // one sine and cosine per column and face
    const Vector3 n_east = wall_normal(film, theta + 0.5 * d_theta);
    for (int j = 0; j <= n_z; ++j) {
      const std::size_t at = static_cast<std::size_t>(i) * (n_z + 1) + j;
      const double h_e = film_thickness_along(film, n_east, z_at(j)) / c;
      s.h_east[at] = h_e;
      s.h3_east[at] = h_e * h_e * h_e;
      if (j < n_z) {
        const double h_n = film_thickness_along(film, n_node, z_at(j + 0.5)) / c;
        s.h3_north[at] = h_n * h_n * h_n;
      }
      s.h_rate[at] = film_thickness_rate_along(film, motion, n_node, z_at(j)) / c;
    }
  }
  auto at = [&](int i, int j) { return static_cast<std::size_t>(i) * (n_z + 1) + j; };

  // P = p c^2 / (eta R^2); the groove's supply pressure in those units.
  const double pressure_scale = lubricant.viscosity * (radius / c) * (radius / c);
  const double supply_p = grooved ? supply.supply_pressure / pressure_scale : 0.0;
  const bool mass_conserving = s.options.cavitation == CavitationModel::mass_conserving;
  const int unknowns = s.columns * s.rows;

  if (!s.has_previous || s.u.size() != unknowns) {
    s.u = Eigen::VectorXd::Constant(unknowns, 0.0);
    s.full.assign(unknowns, 1);
  }
  if (!mass_conserving) s.full.assign(unknowns, 1);
  s.rhs.resize(unknowns);

  const double r_theta = d_zeta / d_theta, r_zeta = d_theta / d_zeta;
  const double couette = 6.0 * omega * d_zeta;
  const double squeeze = 12.0 * d_theta * d_zeta;
  double* values = s.values;

  // Node classes: an unknown node k >= 0 (full or cavitated), or a boundary at pressure P_b, f = 1.
  auto unknown_at = [&](int i, int j) -> int {
    if (j <= 0 || j >= n_z) return -1;
    i = (i % n_theta + n_theta) % n_theta;
    if (grooved && i == 0) return -1;
    return s.index(i, j);
  };
  auto boundary_pressure = [&](int j) {
    return (j <= 0 || j >= n_z) ? 0.0 : supply_p;  // ends ambient; otherwise the groove
  };

  int iteration = 0;
  bool converged = false;
  for (; iteration < s.options.max_iterations && !converged;) {
    s.clear_values();
    s.rhs.setZero();
    for (int i = s.first_column; i < n_theta; ++i) {
      const int east_i = (i + 1) % n_theta, west_i = (i + n_theta - 1) % n_theta;
      for (int j = 1; j < n_z; ++j) {
        const int k = s.index(i, j);
        const auto& pos = s.positions[k];
        double& rhs = s.rhs[k];
        // Pressure (Poiseuille) terms: coefficient times P of a neighbour, minus the same on P_k.
        const std::array<std::pair<double, std::pair<int, int>>, 4> diffusion = {{
            {r_theta * s.h3_east[at(i, j)], {east_i, j}},
            {r_theta * s.h3_east[at(west_i, j)], {west_i, j}},
            {r_zeta * s.h3_north[at(i, j)], {i, j + 1}},
            {r_zeta * s.h3_north[at(i, j - 1)], {i, j - 1}},
        }};
        const int slot[4] = {kEast, kWest, kNorth, kSouth};
        for (int e = 0; e < 4; ++e) {
          const double coefficient = diffusion[e].first;
          const int m = unknown_at(diffusion[e].second.first, diffusion[e].second.second);
          if (m < 0) {
            rhs -= coefficient * boundary_pressure(diffusion[e].second.second);
          } else if (s.full[m]) {
            values[pos[slot[e]]] += coefficient;
          }
          if (s.full[k]) values[pos[kSelf]] -= coefficient;
        }
        // Couette and squeeze terms: coefficient times the film fraction f of a node, with
        // f = 1 + u for a cavitated unknown, else 1.
        auto add_fraction = [&](double coefficient, int node, int slot_of_node) {
          if (node >= 0 && !s.full[node]) values[pos[slot_of_node]] += coefficient;
          rhs -= coefficient;
        };
        const double east_flux = couette * s.h_east[at(i, j)];
        const double west_flux = couette * s.h_east[at(west_i, j)];
        if (omega >= 0.0) {  // upwind: the face takes the fraction of the node it comes from
          add_fraction(-east_flux, k, kSelf);
          add_fraction(west_flux, unknown_at(west_i, j), kWest);
        } else {
          add_fraction(-east_flux, unknown_at(east_i, j), kEast);
          add_fraction(west_flux, k, kSelf);
        }
        add_fraction(-squeeze * s.h_rate[at(i, j)], k, kSelf);
        // A cavitated node's own unknown is its fraction; when nothing else involves it (no
        // Couette or squeeze through it) keep the row regular: its pressure is 0 by definition.
        if (!s.full[k] && values[pos[kSelf]] == 0.0) {
          values[pos[kSelf]] = 1.0;
          rhs = 0.0;
        }
      }
    }
    s.factorize_and_solve();
    ++iteration;
    if (!mass_conserving) {
      converged = true;
      break;
    }
    converged = true;
    for (int k = 0; k < unknowns; ++k) {
      const char now_full = s.u[k] >= 0.0 ? 1 : 0;
      if (now_full != s.full[k]) {
        s.full[k] = now_full;
        converged = false;
      }
    }
  }
  s.has_previous = true;
  s.pressure_scale = pressure_scale;
  load.iterations = iteration;
  load.converged = converged;

  // Pressures at every node of the grid (rows 0 and n_z at ambient, the groove at supply).
  auto pressure = [&](int i, int j) {
    const int k = unknown_at(i, j);
    if (k < 0) return boundary_pressure(j);
    return s.full[k] ? std::max(s.u[k], 0.0) : 0.0;
  };

  // Force and moment: the periodic trapezoidal rule in theta (exact for trigonometric
  // polynomials), the trapezoidal rule in z (the end rows carry p = 0).
  const double area = radius * d_theta * d_z;
  int cavitated = 0;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = i * d_theta;
    const Vector3 n = wall_normal(film, theta);
    for (int j = 1; j < n_z; ++j) {
      const double p = pressure_scale * pressure(i, j);
      if (unknown_at(i, j) >= 0 && p <= 0.0) ++cavitated;
      if (p <= 0.0) continue;
      const double z = z_at(j);
      const Vector3 dF = -p * area * n;
      load.force_W += dF;
      // The pressure acts along the journal's own normal, through its axis: its lever arm is
      // the axis' point in the plane z (film_thickness_rate's q) minus P_j. (Along n instead
      // it would add a spurious torque e x F about the axis, which in a real film the shear
      // stress carries; the Reynolds pressure alone does not give the friction torque.)
      load.moment_W += (film.p_WB + z * film.axis_W + journal_offset(film, z) - film.p_WJ).cross(dF);
      if (p > load.max_pressure) {
        load.max_pressure = p;
        load.max_pressure_theta = theta;
        load.max_pressure_z = z;
      }
    }
  }
  load.cavitated_fraction = unknowns > 0 ? static_cast<double>(cavitated) / unknowns : 0.0;
  // Side flow: the Poiseuille flux through the first and last faces, c R^2 / 12 H^3 dP/dzeta.
  double outflow = 0.0;
  for (int i = 0; i < n_theta; ++i) {
    outflow += s.h3_north[at(i, 0)] * (pressure(i, 1) - pressure(i, 0));
    outflow += s.h3_north[at(i, n_z - 1)] * (pressure(i, n_z - 1) - pressure(i, n_z));
  }
  load.side_flow = c * radius * radius / 12.0 * outflow / d_zeta * d_theta;
  return load;
}

}  // namespace clearjoint::lubrication
