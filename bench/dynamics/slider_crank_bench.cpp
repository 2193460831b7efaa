// SPDX-License-Identifier: BSD-3-Clause
// Wall time per simulated second for the paper's slider-cranks at the paper's settings (Table 2:
// tolerance 1e-7, reported step 1e-5 s): with ideal joints, and with their revolute clearance
// joints (the figure, the steps, the contact detections and impacts behind it), side by side in
// one run. bench/dynamics/run_bench.sh writes docs/reports/benchmarks-dynamics.md from its JSON.
//
//   dynamics_slider_crank_bench --benchmark_out=dynamics.json --benchmark_out_format=json
//
// No random numbers are involved (the models are deterministic), so there is no seed to log.
// BM_Integrate*: integration over 1 s with dense output at every 1e-5 s report time (observer does
// nothing: the cost of the solver alone). BM_Derivative*: one right-hand-side evaluation, the
// baseline that the integration cost divides into (steps x 7 evaluations).

#include <benchmark/benchmark.h>

#include <optional>
#include <string>
#include <variant>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"

namespace {

using namespace clearjoint::dynamics;

BuiltModel load(const char* file) {
  return build_model(read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file));
}

/// `film`: the lubricated joints' film method in place of the file's (none: the file's).
void integrate_one_second(benchmark::State& state, const char* file,
                          std::optional<FilmMethod> film = std::nullopt) {
  ModelDescription model = read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
  for (ForceDescription& force : model.forces) {
    auto* description = std::get_if<ClearanceRevoluteDescription>(&force);
    if (film && description && description->parameters.lubrication) description->parameters.lubrication->method = *film;
  }
  BuiltModel built = build_model(model);
  // A film table is built on the first film evaluation, once per process (BM_TableBuild in
  // bench/lubrication): here, before the timing, so that every repetition times the same run.
  std::vector<double> first_rate(built.initial_state.size());
  built.system->derivative(model.solver.start_time, built.initial_state, first_rate);
  const ClearanceRevoluteJoint* joint = nullptr;
  for (const auto& element : built.system->force_elements()) {
    if (const auto* j = dynamic_cast<const ClearanceRevoluteJoint*>(element.get())) joint = j;
  }
  const ClearanceJointStatistics before = joint ? joint->statistics() : ClearanceJointStatistics{};
  IntegrationStatistics stats;
  for (auto _ : state) {
    std::vector<double> y = built.initial_state;
    stats = integrate(*built.system, y, model.solver, [](double, std::span<const double> s) {
      benchmark::DoNotOptimize(s.data());
    });
    benchmark::DoNotOptimize(y.data());
  }
  // The models simulate exactly 1 s, so "Time" (wall, UseRealTime) is the time per simulated second.
  state.counters["simulated_s"] = model.solver.end_time - model.solver.start_time;
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["derivative_calls"] = static_cast<double>(stats.derivative_calls);
  state.counters["tolerance"] = model.solver.relative_tolerance;
  state.counters["restarts"] = static_cast<double>(stats.restarts);
  // A clearance joint's contact detections and recorded impacts per simulated second (its
  // counters run on over the iterations, which are identical runs).
  if (joint != nullptr) {
    const double iterations = static_cast<double>(state.iterations());
    state.counters["detection_calls"] =
        static_cast<double>(joint->statistics().detection_calls - before.detection_calls) / iterations;
    state.counters["impacts"] = static_cast<double>(joint->statistics().impacts - before.impacts) / iterations;
  }
}

void BM_IntegrateLubricatedPlanarSliderCrankShortBearing(benchmark::State& s) {
  integrate_one_second(s, "slider_crank_planar_clearance_lubricated.json", FilmMethod::short_bearing);
}
void BM_IntegrateLubricatedPlanarSliderCrankTable(benchmark::State& s) {
  integrate_one_second(s, "slider_crank_planar_clearance_lubricated.json", FilmMethod::table);
}

void derivative(benchmark::State& state, const char* file) {
  BuiltModel built = load(file);
  std::vector<double> rate(built.initial_state.size());
  for (auto _ : state) {
    built.system->derivative(0.0, built.initial_state, rate);
    benchmark::DoNotOptimize(rate.data());
  }
}

void BM_IntegratePlanarSliderCrank(benchmark::State& s) { integrate_one_second(s, "slider_crank_planar_ideal.json"); }
void BM_IntegrateSpatialSliderCrank(benchmark::State& s) { integrate_one_second(s, "slider_crank_spatial_ideal.json"); }
void BM_IntegrateSpatialSliderCrankWithClearance(benchmark::State& s) {
  integrate_one_second(s, "slider_crank_spatial_clearance.json");
}
void BM_IntegratePlanarSliderCrankWithClearance(benchmark::State& s) {
  integrate_one_second(s, "slider_crank_planar_clearance_aligned.json");
}
void BM_DerivativeSpatialSliderCrankWithClearance(benchmark::State& s) {
  derivative(s, "slider_crank_spatial_clearance.json");
}
void BM_DerivativePlanarSliderCrank(benchmark::State& s) { derivative(s, "slider_crank_planar_ideal.json"); }
void BM_DerivativeSpatialSliderCrank(benchmark::State& s) { derivative(s, "slider_crank_spatial_ideal.json"); }

BENCHMARK(BM_IntegratePlanarSliderCrank)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IntegrateSpatialSliderCrank)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IntegrateSpatialSliderCrankWithClearance)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IntegratePlanarSliderCrankWithClearance)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IntegrateLubricatedPlanarSliderCrankShortBearing)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IntegrateLubricatedPlanarSliderCrankTable)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DerivativePlanarSliderCrank)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_DerivativeSpatialSliderCrank)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_DerivativeSpatialSliderCrankWithClearance)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
