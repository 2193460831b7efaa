// SPDX-License-Identifier: BSD-3-Clause
// Timings of full-joint contact detection (issue 5): the paper's Newton baseline, clearjoint's
// uncertified pipeline and its certified pipeline, side by side in one run, on the input families
// of input_families.hpp (the same inputs the accuracy evaluation scores).
//
// Two measures per method and input set, both in the Google Benchmark JSON:
// * the benchmark time: the timed loop cycles through the set, one full-joint query per
//   iteration, so it is the mean cost per query over the set (with repetitions, their median);
// * counters input_p50_ns, input_p99_ns, input_max_ns: the distribution over the inputs of the
//   cost of one query, measured before the benchmarks run, input by input, the three methods in
//   turn (so that a change of machine load falls on all of them), each input timed as a batch of
//   kBatch calls (alone when slower than kSlowQueryNs), kPasses times, keeping the median pass;
//   the clock's own cost is subtracted.
// Each timed loop covers its whole set (a multiple of the set size of iterations).
// Counters also give the set size and the share of inputs with contact (by the certified answer).
//
//   bench_detection [--suite=quick|full] [Google Benchmark flags]
//
// bench/run_detection_suite.sh runs it with repetitions and random interleaving.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "detection_methods.hpp"
#include "input_families.hpp"
#include "pin_in_hole_bench.hpp"

namespace {

namespace bench = clearjoint::bench;
using Clock = std::chrono::steady_clock;

/// Calls per timed batch in the per-input pass: enough to make the clock's cost (~20-40 ns a
/// reading pair, subtracted) small against a query of ~50 ns or more.
constexpr int kBatch = 8;
/// A query slower than this (the exact fallback near a tangency can take milliseconds) is timed
/// by itself instead of in a batch: the clock's cost is then negligible, and batches would make
/// the pass last minutes.
constexpr double kSlowQueryNs = 20000.0;
/// Passes over every input; the median pass is kept, which discards one-off interruptions.
constexpr int kPasses = 3;
/// Each timed loop runs whole passes over its set, as many as fill about this time (at least
/// one), so that its mean covers every input of the set once or more.
constexpr double kTargetLoopSeconds = 0.1;

double clock_overhead_ns() {
  std::vector<double> samples;
  for (int i = 0; i < 1001; ++i) {
    const auto start = Clock::now();
    const auto stop = Clock::now();
    samples.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
  }
  std::nth_element(samples.begin(), samples.begin() + 500, samples.end());
  return samples[500];
}

/// Per-input cost (ns per query) of each method, methods in turn for each input.
std::array<std::vector<double>, bench::kMethods.size()> per_input_costs(
    const std::vector<bench::DetectionInput>& inputs, double overhead_ns) {
  std::array<std::vector<double>, bench::kMethods.size()> costs;
  for (auto& c : costs) c.assign(inputs.size(), 0.0);
  std::vector<std::array<std::array<double, kPasses>, bench::kMethods.size()>> passes(inputs.size());
  for (int pass = 0; pass < kPasses; ++pass) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      for (std::size_t k = 0; k < bench::kMethods.size(); ++k) {
        // Rotate the order of the methods from input to input.
        const std::size_t m = (k + i + static_cast<std::size_t>(pass)) % bench::kMethods.size();
        const auto first_start = Clock::now();
        {
          auto answer = bench::run_method(bench::kMethods[m], inputs[i]);
          benchmark::DoNotOptimize(answer);
        }
        double ns = std::chrono::duration<double, std::nano>(Clock::now() - first_start).count();
        if (ns < kSlowQueryNs) {
          const auto start = Clock::now();
          for (int call = 0; call < kBatch; ++call) {
            auto answer = bench::run_method(bench::kMethods[m], inputs[i]);
            benchmark::DoNotOptimize(answer);
          }
          const auto stop = Clock::now();
          ns = (std::chrono::duration<double, std::nano>(stop - start).count() - overhead_ns) / kBatch;
        }
        passes[i][m][static_cast<std::size_t>(pass)] = std::max(0.0, ns);
      }
    }
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    for (std::size_t m = 0; m < bench::kMethods.size(); ++m) {
      auto p = passes[i][m];
      std::sort(p.begin(), p.end());
      costs[m][i] = p[kPasses / 2];
    }
  }
  return costs;
}

/// Nearest-rank percentile of a sample.
double percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

struct InputSet {
  std::string name;  // "realistic" or "near_tangent/k=7"
  std::vector<bench::DetectionInput> inputs;
  std::array<std::vector<double>, bench::kMethods.size()> costs;  // per input
  double contact_share = 0.0;
};

/// Registers the timed loops of one set. `repetitions` 0: the command line's.
void register_set(const InputSet& set, int repetitions) {
  for (std::size_t m = 0; m < bench::kMethods.size(); ++m) {
    const bench::Method method = bench::kMethods[m];
    const std::string name = set.name + "/" + std::string(bench::to_string(method));
    const std::map<std::string, double> counters{
        {"inputs", static_cast<double>(set.inputs.size())},
        {"contact_share", set.contact_share},
        {"input_p50_ns", percentile(set.costs[m], 0.5)},
        {"input_p99_ns", percentile(set.costs[m], 0.99)},
        {"input_max_ns", percentile(set.costs[m], 1.0)}};
    double pass_seconds = 0.0;
    for (const double ns : set.costs[m]) pass_seconds += 1e-9 * ns;
    const auto passes = static_cast<benchmark::IterationCount>(
        std::max(1.0, std::ceil(kTargetLoopSeconds / std::max(pass_seconds, 1e-9))));
    auto* registered = benchmark::RegisterBenchmark(name.c_str(), [&set, method, counters](benchmark::State& state) {
      std::size_t next = 0;
      for (auto _ : state) {
        auto answer = bench::run_method(method, set.inputs[next]);
        benchmark::DoNotOptimize(answer);
        if (++next == set.inputs.size()) next = 0;
      }
      state.counters["queries_per_s"] =
          benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
      for (const auto& [key, value] : counters) state.counters[key] = value;
    });
    registered->Iterations(passes * static_cast<benchmark::IterationCount>(set.inputs.size()));
    if (repetitions > 0) registered->Repetitions(repetitions);
  }
}

/// Removes --suite=... from argv (Google Benchmark rejects flags it does not know).
bench::SuiteSize take_suite_flag(int& argc, char** argv) {
  bench::SuiteSize size = bench::SuiteSize::full;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--suite=quick") == 0) {
      size = bench::SuiteSize::quick;
    } else if (std::strcmp(argv[i], "--suite=full") == 0) {
      size = bench::SuiteSize::full;
    } else if (std::strncmp(argv[i], "--suite=", 8) == 0) {
      std::fprintf(stderr, "bench_detection: %s: expected --suite=quick or --suite=full\n", argv[i]);
      std::exit(2);
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  return size;
}

}  // namespace

int main(int argc, char** argv) {
  const bench::SuiteSize size = take_suite_flag(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  // Sets: each family whole, and each group of the two margin families (for the plots against
  // the margin). std::vector<InputSet> never reallocates after this (reserve), so the
  // registered lambdas can hold references.
  std::vector<InputSet> sets;
  sets.reserve(64);
  std::string seeds;
  const double overhead_ns = clock_overhead_ns();
  for (const bench::FamilySpec& spec : bench::family_specs()) {
    seeds += std::string(seeds.empty() ? "" : ", ") + spec.name + " " + std::to_string(spec.seed);
    std::fprintf(stderr, "bench_detection: generating and pre-timing %s\n", spec.name);
    InputSet whole{spec.name, bench::generate_family(spec.name, size), {}, 0.0};
    whole.costs = per_input_costs(whole.inputs, overhead_ns);
    std::size_t in_contact = 0;
    for (const bench::DetectionInput& input : whole.inputs) {
      in_contact += bench::run_method(bench::Method::certified, input).contact_count > 0 ? 1 : 0;
    }
    whole.contact_share = static_cast<double>(in_contact) / static_cast<double>(whole.inputs.size());
    const std::string family = spec.name;
    if (family == "near_tangent" || family == "near_parallel") {
      std::vector<std::string> groups;
      for (const bench::DetectionInput& input : whole.inputs) {
        if (std::find(groups.begin(), groups.end(), input.group) == groups.end()) groups.push_back(input.group);
      }
      for (const std::string& group : groups) {
        InputSet part{family + "/" + group, {}, {}, 0.0};
        std::size_t contact = 0;
        for (std::size_t i = 0; i < whole.inputs.size(); ++i) {
          if (whole.inputs[i].group != group) continue;
          part.inputs.push_back(whole.inputs[i]);
          for (std::size_t m = 0; m < bench::kMethods.size(); ++m) part.costs[m].push_back(whole.costs[m][i]);
          contact += bench::run_method(bench::Method::certified, whole.inputs[i]).contact_count > 0 ? 1 : 0;
        }
        part.contact_share = static_cast<double>(contact) / static_cast<double>(part.inputs.size());
        sets.push_back(std::move(part));
      }
    }
    sets.push_back(std::move(whole));
  }
  // The groups of the margin families time one repetition each (they feed the plots against the
  // margin); whole families take the command line's repetitions.
  for (const InputSet& set : sets) register_set(set, set.name.find('/') != std::string::npos ? 1 : 0);
  // The pin-in-hole joint on the realistic poses, against the paper's joint measured interleaved.
  for (const InputSet& set : sets) {
    if (set.name == "realistic") bench::register_pin_in_hole_benchmark("realistic", set.inputs);
  }

  double load[3] = {0.0, 0.0, 0.0};
  if (getloadavg(load, 3) < 0) load[0] = load[1] = load[2] = -1.0;
  char load_text[64];
  std::snprintf(load_text, sizeof load_text, "%.2f %.2f %.2f", load[0], load[1], load[2]);
  benchmark::AddCustomContext("load_average_at_start", load_text);
  benchmark::AddCustomContext("suite_size", size == bench::SuiteSize::full ? "full" : "quick");
  benchmark::AddCustomContext("seeds", seeds);
  benchmark::AddCustomContext("clock_overhead_ns", std::to_string(overhead_ns));
  benchmark::AddCustomContext("per_input_timing",
                              "batches of " + std::to_string(kBatch) + " calls (single calls above " +
                                  std::to_string(kSlowQueryNs) + " ns), median of " +
                                  std::to_string(kPasses) + " passes, methods in turn");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
