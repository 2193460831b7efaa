// SPDX-License-Identifier: BSD-3-Clause
// Cost of one film load (issue 36): the closed forms, and the Reynolds grid cold and warm-started,
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

}  // namespace

BENCHMARK_MAIN();
