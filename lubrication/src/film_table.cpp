// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/film_table.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <mutex>
#include <numbers>
#include <span>
#include <string>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/lubrication/film_thickness.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"
#include "clearjoint/version.hpp"

namespace clearjoint::lubrication {

namespace {

constexpr int kFields = 3;  // spin, squeeze (eps'), whirl (eps phi')
/// The pressure's growth towards the wall, divided out of the stored fields so that they vary
/// slowly: the squeeze film's pressure grows as (1 - eps^2)^-5/2 (the short bearing's,
/// short_bearing.cpp), the fastest of the three.
constexpr double kGrowthExponent = 2.5;
/// The bearing's length exceeds the film's by this fraction, as in bearing_characteristics.cpp:
/// any amount works (the film is the journal's length); JointDimensions needs Li > Lj.
constexpr double kBearingLengthMargin = 1e-3;

/// u in [0, 1] -> eps: uniform in log(1 - eps), eps(0) = 0, eps(1) = kTableLargestEccentricityRatio.
double eccentricity_of(double u) { return -std::expm1(u * std::log1p(-kTableLargestEccentricityRatio)); }
double position_of(double eps) { return std::log1p(-eps) / std::log1p(-kTableLargestEccentricityRatio); }
double growth(double eps) { return std::pow(1.0 - eps, kGrowthExponent); }

/// A table read from the cache must match the grid solved afresh at a few nodes to this fraction
/// of each field's largest value: well above the rounding by which two builds of one version can
/// differ (another summation order or FMA: a few ulps per operation of the band solve), far below
/// any change of the solver that would matter (kTableErrorTarget = 5e-3).
constexpr double kSpotCheckTolerance = 1e-9;
std::atomic<std::uint64_t> build_counter{0};

/// Keys' cubic convolution (a = -1/2) at x in node units over nodes 0 ... last: four rows and
/// their weights, the ghost rows beyond either end folded in by Keys' boundary rule
/// f(-1) = 3 f(0) - 3 f(1) + f(2), which keeps the interpolant third order there.
struct RowWeights {
  std::array<int, 4> rows{};
  std::array<double, 4> weights{};
};
RowWeights keys_rows(double x, int last) {
  const int i = std::clamp(static_cast<int>(x), 0, last - 1);
  const double t = x - i, t2 = t * t, t3 = t2 * t;
  const std::array<double, 4> w = {0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
                                   0.5 * (-3.0 * t3 + 4.0 * t2 + t), 0.5 * (t3 - t2)};
  // Rows i-1 ... i+2 mapped onto i-1 ... i+2 clamped into [0, last] (as a window of 4 real rows).
  const int first = std::clamp(i - 1, 0, last - 3);
  RowWeights r;
  for (int a = 0; a < 4; ++a) r.rows[a] = first + a;
  const auto add = [&](int row, double weight) { r.weights[row - first] += weight; };
  for (int a = 0; a < 4; ++a) {
    const int row = i - 1 + a;
    if (row < 0) {
      add(0, 3.0 * w[a]), add(1, -3.0 * w[a]), add(2, w[a]);
    } else if (row > last) {
      add(last, 3.0 * w[a]), add(last - 1, -3.0 * w[a]), add(last - 2, w[a]);
    } else {
      add(row, w[a]);
    }
  }
  return r;
}

}  // namespace

namespace detail {

/// The grid at the table's bearing: an aligned journal with its line of centres along +x, theta = 0
/// on it, for unit viscosity.
class GridSampler {
 public:
  explicit GridSampler(const FilmTableKey& key)
      : key_(key),
        dimensions_{key.journal_radius + key.radial_clearance, key.width * (1.0 + kBearingLengthMargin),
                    key.journal_radius, key.width},
        solver_(options(key)) {}

  static ReynoldsGridOptions options(const FilmTableKey& key) {
    ReynoldsGridOptions o;
    o.circumferential_cells = key.circumferential_cells;
    o.axial_cells = key.axial_cells;
    o.cavitation = key.cavitation;
    return o;
  }

  FilmGeometry film(double eps) const {
    geometry::PartPose bearing, journal;  // bearing at the origin, axis z
    journal.p_WP = Vector3(eps * key_.radial_clearance, 0.0, 0.0);
    FilmGeometry film = describe_film(dimensions_, bearing, journal, Vector3::UnitX());
    film.theta_zero_W = Vector3::UnitX();  // also at eps = 0, where the hint alone decides
    film.theta_quarter_W = Vector3::UnitY();
    return film;
  }

  /// Spin omega, squeeze eps', whirl eps phi' (all 1/s).
  FilmLoad solve(double eps, double spin, double squeeze, double whirl) {
    RelativeMotion motion;
    motion.omega_BJ_W = Vector3(0.0, 0.0, spin);
    motion.v_BJ_W = key_.radial_clearance * Vector3(squeeze, whirl, 0.0);
    return solver_.solve(film(eps), motion, Lubricant{1.0});
  }
  std::vector<double> unclipped_pressures() const { return solver_.unclipped_pressures(); }

 private:
  FilmTableKey key_;
  geometry::JointDimensions dimensions_;
  ReynoldsGridSolver solver_;
};

}  // namespace detail

using detail::GridSampler;

double FilmTable::growth_at(int node) const {
  return growth(eccentricity_of(static_cast<double>(node) / (kTableEccentricityNodes - 1)));
}

FilmTable::FilmTable(const FilmTableKey& key) : FilmTable(key, Unsampled{}) {
  GridSampler sampler(key);
  sample_fields(sampler);
  measure_error(sampler);
  ++build_counter;
}

FilmTable::FilmTable(const FilmTableKey& key, Unsampled) : key_(key) {
  validate(PlanarBearing{key.journal_radius, key.width, key.radial_clearance}, PlanarFilmState{}, 1.0);
  if (key.cavitation != CavitationModel::half_sommerfeld) {
    throw geometry::InvalidInput(
        "cavitation = mass_conserving: the table is half-Sommerfeld only (a mass-conserving film "
        "is not linear in its motion, and needs a groove); use method grid");
  }
  validate(GridSampler::options(key));
  const GridSampler sampler(key);
  // The aligned film is symmetric about its mid-plane (the same H at every z, ambient at both
  // ends): the table keeps the half of each column nearer z_low, rows j = 0 ... half - 1 of the
  // grid's rows = N_z - 1 unknown rows, each standing for itself and its mirror row - 1 - j.
  const int n_theta = key.circumferential_cells, rows = key.axial_cells - 1;
  half_rows_ = (rows + 1) / 2;
  node_count_ = n_theta * half_rows_;
  fields_.assign(static_cast<std::size_t>(kTableEccentricityNodes) * kFields * node_count_, 0.0);
  interval_errors_.assign(kTableEccentricityNodes - 1, 0.0);
  side_flow_weight_.assign(static_cast<std::size_t>(kTableEccentricityNodes) * n_theta, 0.0);
  radial_area_.resize(node_count_);
  tangential_area_.resize(node_count_);

  // The grid's quadrature (reynolds_grid.cpp): dF = -p R d_theta d_z n at each node; side flow
  // c R^2 / 12 H^3 dP/dzeta through the end faces, P = p c^2 / (eta R^2), the ends at p = 0.
  const FilmGeometry centred = sampler.film(0.0);
  const double d_theta = 2.0 * std::numbers::pi / n_theta, d_z = key.width / key.axial_cells;
  const double radius = centred.journal_radius, c = centred.radial_clearance;
  const double area = radius * d_theta * d_z;
  for (int i = 0; i < n_theta; ++i) {
    const Vector3 n = wall_normal(centred, i * d_theta);
    for (int j = 0; j < half_rows_; ++j) {
      const double mirrors = (rows % 2 == 1 && j == half_rows_ - 1) ? 1.0 : 2.0;  // the middle row is its own
      radial_area_[i * half_rows_ + j] = -mirrors * area * n.x();
      tangential_area_[i * half_rows_ + j] = -mirrors * area * n.y();
    }
  }
  const double flow_scale = c * c * c / 12.0 * d_theta / (d_z / radius);  // times H^3 p / eta
  for (int e = 0; e < kTableEccentricityNodes; ++e) {
    const FilmGeometry film = sampler.film(eccentricity_of(static_cast<double>(e) / (kTableEccentricityNodes - 1)));
    for (int i = 0; i < n_theta; ++i) {
      const Vector3 n = wall_normal(film, i * d_theta);
      const double h_low = film_thickness_along(film, n, film.z_low + 0.5 * d_z) / c;
      const double h_high = film_thickness_along(film, n, film.z_high - 0.5 * d_z) / c;
      // Both end faces, each next to a row the table keeps as row 0.
      side_flow_weight_[static_cast<std::size_t>(e) * n_theta + i] =
          flow_scale * (h_low * h_low * h_low + h_high * h_high * h_high);
    }
  }
}

void FilmTable::sample_node(GridSampler& sampler, int e, double* out) const {
  const int n_theta = key_.circumferential_cells, rows = key_.axial_cells - 1;
  const double eps = eccentricity_of(static_cast<double>(e) / (kTableEccentricityNodes - 1));
  const double g = growth(eps);
  const std::array<std::array<double, 3>, kFields> unit = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int f = 0; f < kFields; ++f) {
    sampler.solve(eps, unit[f][0], unit[f][1], unit[f][2]);
    const std::vector<double> p = sampler.unclipped_pressures();
    double* const field = out + static_cast<std::size_t>(f) * node_count_;
    for (int i = 0; i < n_theta; ++i) {
      for (int j = 0; j < half_rows_; ++j) {  // the mean of a row and its mirror: symmetric to rounding
        field[i * half_rows_ + j] = g * 0.5 * (p[i * rows + j] + p[i * rows + rows - 1 - j]);
      }
    }
  }
}

void FilmTable::sample_fields(GridSampler& sampler) {
  for (int e = 0; e < kTableEccentricityNodes; ++e) {
    sample_node(sampler, e, &fields_[static_cast<std::size_t>(e) * kFields * node_count_]);
  }
}

void FilmTable::measure_error(GridSampler& sampler) {
  // The error midway between nodes, where an interpolant strays furthest from them, for spin and
  // squeeze mixed at kTableErrorDirections angles, without and with whirl.
  for (int e = 0; e + 1 < kTableEccentricityNodes; ++e) {
    const double eps = interval_eccentricity(e);
    for (int d = 0; d < 2 * kTableErrorDirections; ++d) {
      const double angle = 2.0 * std::numbers::pi * (d % kTableErrorDirections) / kTableErrorDirections;
      // Squeeze weighted by 1 / sqrt(1 - eps^2) against spin so that neither swamps the other
      // near the wall (the short bearing's ratio of the two loads).
      const double spin = std::cos(angle), squeeze = std::sin(angle) * std::sqrt((1.0 - eps) * (1.0 + eps));
      const double whirl = d < kTableErrorDirections ? 0.0 : 0.5 * spin;
      const FilmLoad grid = sampler.solve(eps, spin, squeeze, whirl);
      PlanarFilmState state;
      state.eccentricity_ratio = eps;
      state.journal_spin = spin;
      state.eccentricity_ratio_rate = squeeze;
      state.line_of_centres_rate = eps > 0.0 ? whirl / eps : 0.0;
      const PlanarFilmLoad table = *load(state, 1.0);
      const double size = std::hypot(grid.force_W.x(), grid.force_W.y());
      const double difference = std::hypot(table.radial - grid.force_W.x(), table.tangential - grid.force_W.y());
      if (size > 0.0) interval_errors_[e] = std::max(interval_errors_[e], difference / size);
    }
  }
  error_bound_ = *std::max_element(interval_errors_.begin(), interval_errors_.end());
}

bool FilmTable::agrees_with_grid_at_spot_nodes() const {
  GridSampler sampler(key_);
  std::vector<double> fresh(static_cast<std::size_t>(kFields) * node_count_);
  for (const int e : {0, (kTableEccentricityNodes - 1) / 2, kTableEccentricityNodes - 1}) {
    sample_node(sampler, e, fresh.data());
    const double* stored = &fields_[static_cast<std::size_t>(e) * kFields * node_count_];
    for (int f = 0; f < kFields; ++f) {
      const auto field = std::span(fresh).subspan(static_cast<std::size_t>(f) * node_count_, node_count_);
      double size = 0.0;
      for (const double p : field) size = std::max(size, std::abs(p));
      for (int k = 0; k < node_count_; ++k) {
        // Written as !(<=) so that a NaN fails too.
        if (!(std::abs(stored[f * node_count_ + k] - field[k]) <= kSpotCheckTolerance * size)) return false;
      }
    }
  }
  return true;
}

std::string FilmTable::cache_key(const FilmTableKey& key) {
  // Doubles in hexadecimal floating point (std::to_chars: exact, whatever the locale).
  const auto exact = [](double value) {
    std::array<char, 32> text{};
    const auto end = std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::hex).ptr;
    return std::string(text.data(), end);
  };
  std::string out = "clearjoint film table\n";
  out += "format " + std::to_string(kCacheFormat) + "\n";
  out += "library " + std::string(version_string()) + "\n";
  out += "journal_radius " + exact(key.journal_radius) + "\n";
  out += "radial_clearance " + exact(key.radial_clearance) + "\n";
  out += "width " + exact(key.width) + "\n";
  out += "circumferential_cells " + std::to_string(key.circumferential_cells) + "\n";
  out += "axial_cells " + std::to_string(key.axial_cells) + "\n";
  out += "cavitation " + std::to_string(static_cast<int>(key.cavitation)) + "\n";
  out += "eccentricity_nodes " + std::to_string(kTableEccentricityNodes) + "\n";
  out += "error_directions " + std::to_string(kTableErrorDirections) + "\n";
  out += "largest_eccentricity_ratio " + exact(kTableLargestEccentricityRatio) + "\n";
  out += "growth_exponent " + exact(kGrowthExponent) + "\n";
  out += "fields " + std::to_string(kFields) + "\n";
  return out;
}

std::uint64_t FilmTable::build_count() noexcept { return build_counter.load(); }

double FilmTable::interval_eccentricity(int interval) {
  return eccentricity_of((interval + 0.5) / (kTableEccentricityNodes - 1));
}

std::shared_ptr<const FilmTable> FilmTable::shared(const FilmTableKey& key) {
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const FilmTable>> tables;
  const std::lock_guard lock(mutex);
  for (const auto& table : tables) {
    if (table->key() == key) return table;
  }
  tables.push_back(cached(key, film_table_cache_folder()));
  return tables.back();
}

std::optional<PlanarFilmLoad> FilmTable::load(const PlanarFilmState& state, double viscosity) const {
  const double eps = state.eccentricity_ratio;
  if (!(eps >= 0.0 && eps <= kTableLargestEccentricityRatio)) return std::nullopt;
  const RowWeights r = keys_rows(position_of(eps) * (kTableEccentricityNodes - 1), kTableEccentricityNodes - 1);
  // p_k = eta / growth(eps) sum over rows and fields of weight x rate x stored value.
  const std::array<double, kFields> rates = {state.journal_spin, state.eccentricity_ratio_rate,
                                             eps * state.line_of_centres_rate};
  const double scale = viscosity / growth(eps);
  // The interpolated, superposed field: twelve passes of p += coefficient x stored field, each a
  // loop the compiler vectorises.
  thread_local std::vector<double> pressure;
  pressure.assign(node_count_, 0.0);
  double* const p = pressure.data();
  for (int a = 0; a < 4; ++a) {
    for (int f = 0; f < kFields; ++f) {
      const double coefficient = scale * r.weights[a] * rates[f];
      if (coefficient == 0.0) continue;
      const double* field = &fields_[(static_cast<std::size_t>(r.rows[a]) * kFields + f) * node_count_];
      for (int k = 0; k < node_count_; ++k) p[k] += coefficient * field[k];
    }
  }
  PlanarFilmLoad load;
  double max_pressure = 0.0;
  for (int k = 0; k < node_count_; ++k) {
    const double clipped = std::max(p[k], 0.0);  // half-Sommerfeld: ambient where the full film would pull
    load.radial += clipped * radial_area_[k];
    load.tangential += clipped * tangential_area_[k];
    max_pressure = std::max(max_pressure, clipped);
  }
  load.max_pressure = max_pressure;
  const int n_theta = key_.circumferential_cells;
  double side_flow = 0.0;
  for (int i = 0; i < n_theta; ++i) {
    const double clipped = std::max(p[i * half_rows_], 0.0);  // the row next to the ends
    if (clipped == 0.0) continue;
    double weight = 0.0;
    for (int a = 0; a < 4; ++a) {
      weight += r.weights[a] * side_flow_weight_[static_cast<std::size_t>(r.rows[a]) * n_theta + i];
    }
    side_flow += weight * clipped;
  }
  load.side_flow = side_flow / viscosity;
  load.magnitude = std::hypot(load.radial, load.tangential);
  load.attitude_angle = load.magnitude > 0.0 ? std::atan2(load.tangential, -load.radial) : 0.0;
  return load;
}

}  // namespace clearjoint::lubrication
