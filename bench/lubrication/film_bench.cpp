// SPDX-License-Identifier: BSD-3-Clause
// Cost of one film load (issue 36): the closed forms, the table (issue 49) beside the grid it
// tabulates, and the Reynolds grid cold and warm-started,
// at 48 x 12 (the grid at which test_bearing_characteristics meets the published-table accuracy),
// at twice and at two thirds of it, each with the band LU and with the general sparse LU it
// replaced (the baseline, third argument 1). The warm rows alternate between two nearby states
// (eps 0.6 and 0.601, the step of a dynamics run), so each call starts from the other's
// solution; the cold rows forget it first. Fed by an axial groove but for the periodic rows.
// Compare in one run with interleaved repetitions:
//
//   lubrication_film_bench --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
//     --benchmark_out=lubrication.json --benchmark_out_format=json
//
// No random numbers are involved (the states are fixed), so there is no seed to log.

#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "clearjoint/lubrication/film_table.hpp"
#include "clearjoint/lubrication/long_bearing.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"
#include "clearjoint/lubrication/short_bearing.hpp"

namespace {

using namespace clearjoint::lubrication;
using clearjoint::geometry::JointDimensions;
using clearjoint::geometry::PartPose;

const PlanarBearing kPlanar{0.01, 0.02, 1e-5};
constexpr double kViscosity = 0.04;

void BM_ShortBearingRotation(benchmark::State& state) {
  PlanarFilmState film{0.6, 0.0, 0.0, 200.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(short_bearing_load(kPlanar, film, kViscosity));
  }
}
BENCHMARK(BM_ShortBearingRotation);

void BM_ShortBearingRotationWhirlSqueeze(benchmark::State& state) {
  PlanarFilmState film{0.6, 3.0, 20.0, 200.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(short_bearing_load(kPlanar, film, kViscosity));
  }
}
BENCHMARK(BM_ShortBearingRotationWhirlSqueeze);

// The same film's force alone, as a right-hand side asks for it: no peak-pressure search.
void BM_ShortBearingForceRotationWhirlSqueeze(benchmark::State& state) {
  PlanarFilmState film{0.6, 3.0, 20.0, 200.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(short_bearing_force(kPlanar, film, kViscosity));
  }
}
BENCHMARK(BM_ShortBearingForceRotationWhirlSqueeze);

void BM_LongBearingRotation(benchmark::State& state) {
  PlanarFilmState film{0.6, 0.0, 0.0, 200.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(long_bearing_load(kPlanar, film, kViscosity));
  }
}
BENCHMARK(BM_LongBearingRotation);

void BM_LongBearingRotationSqueeze(benchmark::State& state) {
  PlanarFilmState film{0.6, 3.0, 0.0, 200.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(long_bearing_load(kPlanar, film, kViscosity));
  }
}
BENCHMARK(BM_LongBearingRotationSqueeze);

void grid_row(benchmark::State& state, CavitationModel model, bool warm,
              OilSupply::Kind supply_kind = OilSupply::Kind::axial_groove) {
  ReynoldsGridOptions options;
  options.circumferential_cells = static_cast<int>(state.range(0));
  options.axial_cells = static_cast<int>(state.range(1));
  options.cavitation = model;
  options.linear_solver = static_cast<ReynoldsLinearSolver>(state.range(2));
  state.SetLabel(std::string(to_string(options.linear_solver)));
  ReynoldsGridSolver solver(options);
  const double radius = 0.01, clearance = 1e-5, width = 0.02;  // B/D = 1
  const JointDimensions joint{radius + clearance, width * 1.001, radius, width};
  RelativeMotion motion;
  motion.omega_BJ_W = Eigen::Vector3d(0, 0, 200.0);
  const OilSupply supply{supply_kind, -Eigen::Vector3d::UnitX(), 0.0};
  const PartPose poses[2] = {PartPose{Eigen::Vector3d(0.6 * clearance, 0, 0), Eigen::Vector3d::UnitZ()},
                             PartPose{Eigen::Vector3d(0.601 * clearance, 0, 0), Eigen::Vector3d::UnitZ()}};
  solver.solve(joint, PartPose{}, poses[1], motion, Lubricant{kViscosity}, supply);
  long iterations = 0, calls = 0;
  for (auto _ : state) {
    if (!warm) solver.forget_previous_solution();
    const FilmLoad load =
        solver.solve(joint, PartPose{}, poses[calls % 2], motion, Lubricant{kViscosity}, supply);
    iterations += load.iterations;
    ++calls;
    benchmark::DoNotOptimize(load);
  }
  state.counters["linear_solves_per_call"] = static_cast<double>(iterations) / calls;
}

void BM_GridMassConservingWarm(benchmark::State& state) {
  grid_row(state, CavitationModel::mass_conserving, true);
}
void BM_GridMassConservingCold(benchmark::State& state) {
  grid_row(state, CavitationModel::mass_conserving, false);
}
void BM_GridHalfSommerfeld(benchmark::State& state) {
  grid_row(state, CavitationModel::half_sommerfeld, true);
}
// No groove: the periodic film of a joint in the dynamics with the half-Sommerfeld model, whose
// folded band is twice as wide as the grooved one's.
void BM_GridHalfSommerfeldPeriodic(benchmark::State& state) {
  grid_row(state, CavitationModel::half_sommerfeld, true, OilSupply::Kind::none);
}
// Arguments: N_theta, N_z, ReynoldsLinearSolver (0 band_lu, 1 sparse_lu, the baseline).
void grid_sizes(benchmark::internal::Benchmark* b) {
  for (const int solver : {0, 1}) {
    for (const auto& [n_theta, n_z] : {std::pair{96, 24}, std::pair{48, 12}, std::pair{32, 8}}) {
      b->Args({n_theta, n_z, solver});
    }
  }
  b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_GridMassConservingWarm)->Apply(grid_sizes);
BENCHMARK(BM_GridMassConservingCold)->Apply(grid_sizes);
BENCHMARK(BM_GridHalfSommerfeld)->Apply(grid_sizes);
BENCHMARK(BM_GridHalfSommerfeldPeriodic)->Apply(grid_sizes);

// The table against the grid it tabulates, side by side (issue 49): the same periodic
// half-Sommerfeld film of the Section 6.1 joint (R 9.9 mm, c 0.1 mm, B 19.8 mm) on the 48 x 12
// grid, at the same two alternating states (eps 0.6 and 0.601, spin, squeeze and whirl). The
// table is built before the timing (FilmTable::shared; its build is BM_TableBuild).
const FilmTableKey kTableKey{9.9e-3, 1e-4, 19.8e-3, 48, 12, CavitationModel::half_sommerfeld};
const PlanarFilmState kTableStates[2] = {{0.6, 3.0, 20.0, 200.0}, {0.601, 3.0, 20.0, 200.0}};

void BM_TableSection61(benchmark::State& state) {
  const auto table = FilmTable::shared(kTableKey);
  long calls = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table->load(kTableStates[calls++ % 2], kViscosity));
  }
  state.counters["error_bound"] = table->error_bound();
}
BENCHMARK(BM_TableSection61)->Unit(benchmark::kMicrosecond);

void BM_GridSection61(benchmark::State& state) {
  ReynoldsGridOptions options;
  options.circumferential_cells = kTableKey.circumferential_cells;
  options.axial_cells = kTableKey.axial_cells;
  options.cavitation = CavitationModel::half_sommerfeld;
  ReynoldsGridSolver solver(options);
  const JointDimensions joint{kTableKey.journal_radius + kTableKey.radial_clearance, kTableKey.width * 1.001,
                              kTableKey.journal_radius, kTableKey.width};
  long calls = 0;
  for (auto _ : state) {
    const PlanarFilmState& s = kTableStates[calls++ % 2];
    const double e = s.eccentricity_ratio * kTableKey.radial_clearance;
    RelativeMotion motion;
    motion.omega_BJ_W = Eigen::Vector3d(0, 0, s.journal_spin);
    motion.v_BJ_W = Eigen::Vector3d(s.eccentricity_ratio_rate * kTableKey.radial_clearance, s.line_of_centres_rate * e, 0);
    benchmark::DoNotOptimize(solver.solve(joint, PartPose{}, PartPose{Eigen::Vector3d(e, 0, 0), Eigen::Vector3d::UnitZ()},
                                          motion, Lubricant{kViscosity}));
  }
}
BENCHMARK(BM_GridSection61)->Unit(benchmark::kMicrosecond);

void BM_TableBuild(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(FilmTable(kTableKey));
}
BENCHMARK(BM_TableBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
