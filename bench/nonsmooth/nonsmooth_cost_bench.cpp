// SPDX-License-Identifier: BSD-3-Clause
// CPU time per simulated second of the paper's clearance slider-cranks, non-smooth (Moreau-Jean,
// fc3d NSGS, docs/nonsmooth.md) at h = 1e-5 s and 1e-4 s beside the compliant integrator
// (Dormand-Prince 5(4)) at the model file's tolerance (Table 2: 1e-7), side by side in one run.
// bench/nonsmooth/run_bench.sh runs it with interleaved repetitions and writes the cost table of
// docs/nonsmooth.md from its JSON (bench/nonsmooth/make_table.py).
//
//   nonsmooth_cost_bench --benchmark_out=nonsmooth.json --benchmark_out_format=json
//
// Both sides time the scheme alone: each iteration builds the model (not timed) and integrates
// its 1 s with nothing written; the compliant run reports only its end time, so neither side pays
// for report rows. The models are deterministic: every iteration of a row is the same run, no seed.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/nonsmooth/moreau_jean.hpp"

namespace {

using namespace clearjoint;

constexpr const char* kPlanar = "slider_crank_planar_clearance_aligned.json";
constexpr const char* kSpatial = "slider_crank_spatial_clearance.json";

dynamics::ModelDescription read(const char* file) {
  return dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
}

void compliant(benchmark::State& state, const char* file) {
  dynamics::ModelDescription model = read(file);
  // One report, at the end: the cost of the steps, not of interpolating 1e5 report rows.
  model.solver.report_step = model.solver.end_time - model.solver.start_time;
  dynamics::IntegrationStatistics stats;
  long impacts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    dynamics::BuiltModel built = dynamics::build_model(model);
    std::vector<double> y = built.initial_state;
    state.ResumeTiming();
    stats = dynamics::integrate(*built.system, y, model.solver,
                                [](double, std::span<const double> s) { benchmark::DoNotOptimize(s.data()); });
    benchmark::DoNotOptimize(y.data());
    state.PauseTiming();
    impacts = 0;
    for (const auto& element : built.system->force_elements()) {
      if (const auto* joint = dynamic_cast<const dynamics::ClearanceRevoluteJoint*>(element.get())) {
        impacts += joint->statistics().impacts;
      }
    }
    state.ResumeTiming();
  }
  state.counters["simulated_s"] = model.solver.end_time - model.solver.start_time;
  state.counters["tolerance"] = model.solver.relative_tolerance;
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["derivative_calls"] = static_cast<double>(stats.derivative_calls);
  state.counters["impacts"] = static_cast<double>(impacts);
}

void moreau_jean(benchmark::State& state, const char* file, double h) {
  dynamics::ModelDescription model = read(file);
  model.solver_method = dynamics::SolverMethod::moreau_jean;
  model.moreau_jean.step = h;
  const double end_time = model.solver.end_time;
  nonsmooth::MoreauJeanStatistics stats;
  for (auto _ : state) {
    state.PauseTiming();
    nonsmooth::MoreauJean scheme(model);
    state.ResumeTiming();
    // The run folder's rule (moreau_jean_run.hpp): the last step ends at or just after end_time.
    while (scheme.time() < end_time - 0.5 * h) scheme.step();
    benchmark::DoNotOptimize(scheme.state().data());
    stats = scheme.statistics();
  }
  state.counters["simulated_s"] = model.solver.end_time - model.solver.start_time;
  state.counters["h"] = h;
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["contact_problems"] = static_cast<double>(stats.contact_problems);
  state.counters["nsgs_sweeps"] = static_cast<double>(stats.solver_iterations);
  state.counters["unconverged_steps"] = static_cast<double>(stats.unconverged_steps);
}

void BM_CompliantPlanar(benchmark::State& s) { compliant(s, kPlanar); }
void BM_CompliantSpatial(benchmark::State& s) { compliant(s, kSpatial); }
void BM_MoreauJeanPlanarStep1e4(benchmark::State& s) { moreau_jean(s, kPlanar, 1e-4); }
void BM_MoreauJeanPlanarStep1e5(benchmark::State& s) { moreau_jean(s, kPlanar, 1e-5); }
void BM_MoreauJeanSpatialStep1e4(benchmark::State& s) { moreau_jean(s, kSpatial, 1e-4); }
void BM_MoreauJeanSpatialStep1e5(benchmark::State& s) { moreau_jean(s, kSpatial, 1e-5); }

// Each iteration is a whole simulated second; one per repetition is enough (the repetitions,
// interleaved, give the spread). CPU time is the process's, all threads: a BLAS library's worker
// threads, which Siconos Numerics may wake, are part of the cost.
BENCHMARK(BM_CompliantPlanar)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_MoreauJeanPlanarStep1e4)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_MoreauJeanPlanarStep1e5)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_CompliantSpatial)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_MoreauJeanSpatialStep1e4)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_MoreauJeanSpatialStep1e5)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
