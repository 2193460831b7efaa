// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The finite-width film at closed-form cost: the ReynoldsGridSolver's half-Sommerfeld film on an
/// aligned journal, tabulated once per bearing over the eccentricity ratio and interpolated.
///
/// For half-Sommerfeld the grid solves one linear system whose matrix depends on the film's shape
/// (eps) only and whose right-hand side is linear in the motion, then sets negative pressures to
/// ambient. The motion of an aligned journal enters through three rates: its spin omega, and the
/// velocity of its centre along the line of centres (c eps') and across it (c eps phi', the
/// whirl). The table stores, at each of kTableEccentricityNodes values of eps, the grid's
/// unclipped nodal pressures for each unit rate; a call interpolates the three fields to its eps
/// (cubic convolution, Keys, IEEE Trans. ASSP 29, 1981: third order, C1, four nodes), superposes
/// them with its rates, clips and integrates exactly as the grid does. So the squeeze-to-rotation
/// ratio and the whirl are exact (the table has no axis for them), and the only approximation is
/// the interpolation in eps of smooth full-film fields. The fields are interpolated on nodes
/// uniform in log(1 - eps), each scaled by (1 - eps)^2.5, the growth of the squeeze film's
/// pressure towards the wall, so that they vary slowly. Boost.Math's interpolators are 1-D over
/// one function: here one set of weights serves the 3 x N_theta x (N_z - 1) nodal values, which
/// a per-value spline object would refit or store apart.
///
/// The table's error against the grid is measured when it is built, between every pair of eps
/// nodes (where an interpolant strays furthest) over kTableErrorDirections motions, and reported
/// as FilmTable::error_bound. Outside its domain (eps above kTableLargestEccentricityRatio, a
/// tilted journal, an oil groove, the mass-conserving model) the caller solves the grid.
///
/// FilmTable::shared keeps each table for the life of the process and, across processes, in a
/// file cache (film_table_cache_folder(); docs/lubrication.md, "The table's file cache"): one file
/// per key, named by a hash of the key and holding the whole key, checked on every read.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/planar_film.hpp"

namespace clearjoint::lubrication {

namespace detail {
class GridSampler;  // film_table.cpp: the grid the table samples
}

/// What a table is built for: the film's sizes and the grid it reproduces. Two keys equal in
/// every field give the same table (FilmTable::shared returns the one it built).
struct FilmTableKey {
  double journal_radius = 0.0;    ///< R, m
  double radial_clearance = 0.0;  ///< c, m
  double width = 0.0;             ///< B, m
  int circumferential_cells = 48;
  int axial_cells = 12;
  CavitationModel cavitation = CavitationModel::half_sommerfeld;
  bool operator==(const FilmTableKey&) const = default;
};

/// The table's reach in eps: [0, 0.98], a film down to 0.02 c (2 um in the paper's joint, whose
/// lubricated model hands over to dry contact there). Beyond, the grid is solved.
inline constexpr double kTableLargestEccentricityRatio = 0.98;
/// Nodes uniform in log(1 - eps) over [0, kTableLargestEccentricityRatio]: 3 grid solves each to
/// build; 49 keep the measured error (FilmTable::error_bound) far below kTableErrorTarget on the
/// 48 x 12 grid (docs/lubrication.md).
inline constexpr int kTableEccentricityNodes = 129;
/// The motions the error is measured for between each pair of nodes: spin and squeeze mixed at
/// this many angles around the circle (pure spin, pure squeeze, approach and separation), plus
/// the same with whirl.
inline constexpr int kTableErrorDirections = 16;
/// The largest relative error of the force (|F_table - F_grid| / |F_grid|) a table is built to
/// keep, from issue 49: a film force within 0.5 % of the grid's along a run. The table's own
/// measured bound is FilmTable::error_bound.
inline constexpr double kTableErrorTarget = 5e-3;

/// The folder of the tables' file cache: $CLEARJOINT_CACHE_DIR when set (set and empty: no file
/// cache), else $XDG_CACHE_HOME/clearjoint when that is an absolute path (the XDG Base Directory
/// rule), else $HOME/.cache/clearjoint when HOME is set, else none. Read on every call.
std::optional<std::filesystem::path> film_table_cache_folder();

class FilmTable {
 public:
  /// Builds the table: 3 kTableEccentricityNodes grid solves, then 2 kTableErrorDirections
  /// between each pair of nodes to measure error_bound. Throws geometry::InvalidInput naming the field
  /// for bad sizes (validate(PlanarBearing...)), a grid the solver refuses, or the mass-conserving
  /// model (its load depends on the groove's position and on the spin and whirl apart).
  explicit FilmTable(const FilmTableKey& key);

  /// The table for `key`, kept for the life of the process (thread-safe): on first use read from
  /// the file cache in film_table_cache_folder(), else built and written there (cached).
  static std::shared_ptr<const FilmTable> shared(const FilmTableKey& key);

  /// The table for `key` read from its file in `folder`, else built and written there. A missing,
  /// short, foreign or damaged file (read) is rebuilt and replaced; a folder that cannot be
  /// created or written leaves the built table unwritten, silently. No folder: built, no file.
  /// Throws as the constructor does for a bad key.
  static std::shared_ptr<const FilmTable> cached(const FilmTableKey& key,
                                                 const std::optional<std::filesystem::path>& folder);
  /// The table stored in `file` if it is a whole, undamaged table for `key` (magic, format, the
  /// full key text, sizes, CRC-32, finite values, and the fields at three nodes against the grid
  /// solved afresh), else nullptr; never throws for what the file holds. The file's size is
  /// checked against the key's before anything is allocated.
  static std::shared_ptr<const FilmTable> read(const std::filesystem::path& file, const FilmTableKey& key);
  /// Writes the table into `folder` (created if missing) as cache_file_name(key()), atomically:
  /// a temporary file in the same folder, flushed to disk (fsync), then renamed over the name.
  /// False, leaving nothing behind, when any step fails.
  bool write(const std::filesystem::path& folder) const;
  /// Everything the table's values depend on, as text: the key's fields (doubles in hexadecimal
  /// floating point, exact), the table's constants, the cache format and the library version.
  static std::string cache_key(const FilmTableKey& key);
  /// "film-table-<16 hex digits>.bin": the 64-bit FNV-1a hash of cache_key(key).
  static std::filesystem::path cache_file_name(const FilmTableKey& key);
  /// The tables built (the grid sampled) in this process; one read from the cache is not counted.
  static std::uint64_t build_count() noexcept;
  /// The cache file's format (film_table_cache.cpp), in its header and in cache_key: raised
  /// whenever the file's layout or the meaning of what it stores changes, and whenever the
  /// table's construction changes within one library version (the read checks the fields at
  /// three nodes against the grid, not the error measurement).
  static constexpr std::uint32_t kCacheFormat = 1;

  /// The load for the aligned journal's state, or nullopt outside the table's eps range (the
  /// caller then solves the grid). state must be finite (validate(PlanarBearing...)); radial
  /// and tangential are along the line of centres e_hat and t_hat = a_B x e_hat (planar_film.hpp).
  std::optional<PlanarFilmLoad> load(const PlanarFilmState& state, double viscosity) const;

  /// The largest relative force error |F_table - F_grid| / |F_grid| measured against the grid
  /// midway (in log(1 - eps)) between every pair of nodes.
  double error_bound() const noexcept { return error_bound_; }
  /// The same per interval between neighbouring nodes: [e] for the interval from node e to
  /// e + 1, whose midpoint is at eps = interval_eccentricity(e).
  const std::vector<double>& interval_errors() const noexcept { return interval_errors_; }
  static double interval_eccentricity(int interval);
  const FilmTableKey& key() const noexcept { return key_; }

 private:
  struct Unsampled {};
  /// The table's sizes and its geometry (areas, side flow weights), its fields and errors zero.
  FilmTable(const FilmTableKey& key, Unsampled);
  /// The three fields at eps node e, scaled, into out[0 ... 3 node_count_).
  void sample_node(detail::GridSampler& sampler, int e, double* out) const;
  void sample_fields(detail::GridSampler& sampler);
  void measure_error(detail::GridSampler& sampler);
  /// Whether the stored fields match the grid at the first, middle and last node (a table read
  /// back from a file: catches one written by a build whose grid differs under the same version).
  bool agrees_with_grid_at_spot_nodes() const;
  double growth_at(int node) const;

  FilmTableKey key_;
  int half_rows_ = 0;   ///< the rows kept of each column: the half nearer z_low, the middle one included
  int node_count_ = 0;  ///< N_theta half_rows_ pressure nodes
  /// At each eps node, three fields of node_count_ pressures (Pa for unit viscosity and a unit
  /// rate: omega = 1 rad/s, eps' = 1 1/s, eps phi' = 1 1/s), scaled by (1 - eps)^2.5:
  /// fields_[(e * 3 + field) * node_count_ + k].
  std::vector<double> fields_;
  /// Per pressure node: -area n . e_hat, -area n . t_hat (m^2), times 2 for a row standing for
  /// its mirror too.
  std::vector<double> radial_area_, tangential_area_;
  /// Per eps node and column: the side flow through both end faces per unit pressure of the row
  /// next to them, times the viscosity (m^3 / (Pa s)): [e * N_theta + i].
  std::vector<double> side_flow_weight_;
  double error_bound_ = 0.0;
  std::vector<double> interval_errors_;
};

}  // namespace clearjoint::lubrication
