// SPDX-License-Identifier: BSD-3-Clause
// Cost of one film load (issue 36): the closed forms, and the Reynolds grid cold and warm-started,
// at the grid that meets the published-table accuracy (96 x 24, bearing_characteristics_test) and
// at half that. The warm rows alternate between two nearby states (eps 0.6 and 0.601, the step of
// a dynamics run), so each call starts from the other's solution; the cold rows forget it first,
// the baseline that the warm start is measured against in the same run.
//
//   lubrication_film_bench --benchmark_out=lubrication.json --benchmark_out_format=json
//
// No random numbers are involved (the states are fixed), so there is no seed to log.

#include <benchmark/benchmark.h>

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

void grid_row(benchmark::State& state, CavitationModel model, bool warm) {
  ReynoldsGridOptions options;
  options.circumferential_cells = static_cast<int>(state.range(0));
  options.axial_cells = static_cast<int>(state.range(1));
  options.cavitation = model;
  ReynoldsGridSolver solver(options);
  const double radius = 0.01, clearance = 1e-5, width = 0.02;  // B/D = 1
  const JointDimensions joint{radius + clearance, width * 1.001, radius, width};
  RelativeMotion motion;
  motion.omega_BJ_W = Eigen::Vector3d(0, 0, 200.0);
  const OilSupply supply{OilSupply::Kind::axial_groove, -Eigen::Vector3d::UnitX(), 0.0};
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
BENCHMARK(BM_GridMassConservingWarm)->Args({96, 24})->Args({48, 12})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GridMassConservingCold)->Args({96, 24})->Args({48, 12})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GridHalfSommerfeld)->Args({96, 24})->Args({48, 12})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
