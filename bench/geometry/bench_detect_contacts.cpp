// SPDX-License-Identifier: BSD-3-Clause
// Timings of full-joint detection, detect_contacts (issue 4's targets), on the paper's joint
// (Marques et al. 2017, Table 2): random poses split by outcome into "in contact" (at least one
// contact) and "free flight" (none), and the aligned journal of the planar mechanism (Section 6.1).
//
// Every set is drawn once, before any timing, from a fixed seed written into the JSON context, and
// filtered by the outcome of one certified call per pose; the timed loop cycles through the set.
// Counters give the work behind a time: contacts per query and the share of each certificate
// level. The certified and the plain double pipelines run on the same inputs in the same process:
// compare them by their ratio. docs/reports/benchmarks-kernel.md has the command and the table.
//
// Frames: the bearing is fixed (centre at the origin, axis +z); the journal centre P_j and axis a_j
// are drawn at random.

#include <benchmark/benchmark.h>

#include "detection_poses.hpp"
#include "paper_baseline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"

namespace {

namespace geo = clearjoint::geometry;

using clearjoint::bench::journals;
using clearjoint::bench::kBearing;
using clearjoint::bench::kInputCount;
using clearjoint::bench::kMaxTilt;
using clearjoint::bench::kSeed;
using clearjoint::bench::kTable2;
using clearjoint::bench::Outcome;

const geo::DetectionOptions kCertified{};
const geo::DetectionOptions kUncertified{.intersection = {.certify = false}};

/// The paper's own method on the same poses (bench/detection/paper_baseline.hpp: plain double,
/// Newton from the paper's guesses, no proof), as the measuring stick of what the contract costs
/// without a certificate.
void register_paper_baseline(const std::string& name, const std::vector<geo::PartPose>& inputs) {
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    std::size_t next = 0;
    for (auto _ : state) {
      geo::JointContacts found = clearjoint::bench::detect_contacts_paper_baseline(kTable2, kBearing, inputs[next]);
      benchmark::DoNotOptimize(found);
      if (++next == inputs.size()) next = 0;
    }
    state.counters["inputs"] = static_cast<double>(inputs.size());
  });
}

/// `reuse_result`: time the in-place overload, writing every answer into one JointContacts (a
/// simulation loop's use), instead of returning a fresh 1.4 KB result per call.
void register_set(const std::string& name, const std::vector<geo::PartPose>& inputs,
                  const geo::DetectionOptions& options, bool reuse_result = false) {
  double contacts = 0, exact = 0, certified = 0, uncertain = 0, beyond = 0;
  for (const geo::PartPose& journal : inputs) {
    const geo::JointContacts found = geo::detect_contacts(kTable2, kBearing, journal, options);
    contacts += found.contact_count;
    exact += found.certificate.level == geo::Certainty::exact;
    certified += found.certificate.level == geo::Certainty::certified;
    uncertain += found.certificate.level == geo::Certainty::uncertain;
    beyond += found.scenario == geo::ContactScenario::beyond_model;
  }
  const double n = static_cast<double>(inputs.size());
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    std::size_t next = 0;
    geo::JointContacts reused;
    for (auto _ : state) {
      if (reuse_result) {
        geo::detect_contacts(kTable2, kBearing, inputs[next], reused, options);
        benchmark::DoNotOptimize(reused);
        benchmark::ClobberMemory();
      } else {
        geo::JointContacts found = geo::detect_contacts(kTable2, kBearing, inputs[next], options);
        benchmark::DoNotOptimize(found);
      }
      if (++next == inputs.size()) next = 0;
    }
    state.counters["queries_per_s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["inputs"] = n;
    state.counters["contacts_per_query"] = contacts / n;
    state.counters["beyond_model"] = beyond / n;
    state.counters["cert_exact"] = exact / n;
    state.counters["cert_certified"] = certified / n;
    state.counters["cert_uncertain"] = uncertain / n;
  });
}

/// Passes over the set in a per-pose run; each pose's cost is its median over the passes.
constexpr int kPerPosePasses = 15;

/// q-quantile (0 <= q <= 1) of `values` by the nearest rank (the values are reordered).
double quantile(std::vector<double>& values, double q) {
  const std::size_t rank = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank), values.end());
  return values[rank];
}

/// The cost of each pose on its own, not the mean over the set that the other rows give:
/// every pass times each call alone with steady_clock, in the set's order (so branch predictors
/// see the same mix of poses as in the other rows, not one pose repeated), less the clock's own
/// cost (the median of empty timings taken in the same pass). A pose's cost is its median over
/// kPerPosePasses passes; the counters give quantiles of those costs over the set, in ns, and
/// their mean (which the batch rows' time should be close to, plus the clock's interruption).
/// `detect` is the call timed (certified detection or the paper's method).
template <class Detect>
void register_per_pose(const std::string& name, const std::vector<geo::PartPose>& inputs, Detect detect) {
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    using Clock = std::chrono::steady_clock;
    Detect call = detect;  // a copy of its own: the call may keep state (a reused result)
    std::vector<std::vector<double>> samples(inputs.size());
    std::vector<double> empty(inputs.size());
    for (auto _ : state) {
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Clock::time_point before = Clock::now();
        const Clock::time_point after = Clock::now();
        empty[i] = std::chrono::duration<double, std::nano>(after - before).count();
      }
      const double clock_cost = quantile(empty, 0.5);
      const Clock::time_point pass_start = Clock::now();
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Clock::time_point before = Clock::now();
        call(inputs[i]);
        const Clock::time_point after = Clock::now();
        samples[i].push_back(std::chrono::duration<double, std::nano>(after - before).count() - clock_cost);
      }
      state.SetIterationTime(std::chrono::duration<double>(Clock::now() - pass_start).count() /
                             static_cast<double>(inputs.size()));
    }
    std::vector<double> per_pose(inputs.size());
    double total = 0.0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      per_pose[i] = quantile(samples[i], 0.5);
      total += per_pose[i];
    }
    state.counters["pose_mean_ns"] = total / static_cast<double>(inputs.size());
    for (const auto& [label, q] : {std::pair{"pose_p10_ns", 0.1}, std::pair{"pose_median_ns", 0.5},
                                   std::pair{"pose_p90_ns", 0.9}, std::pair{"pose_p99_ns", 0.99}}) {
      state.counters[label] = quantile(per_pose, q);
    }
    state.counters["inputs"] = static_cast<double>(inputs.size());
  })->Iterations(kPerPosePasses)->UseManualTime();
}

void register_all() {
  const auto in_contact = journals(1, kMaxTilt, Outcome::in_contact);
  const auto free_flight = journals(2, kMaxTilt, Outcome::free_flight);
  const auto aligned_contact = journals(3, 0.0, Outcome::in_contact);
  const auto aligned_free = journals(4, 0.0, Outcome::free_flight);
  register_set("detect/in_contact/certified", in_contact, kCertified);
  register_set("detect/in_contact/uncertified", in_contact, kUncertified);
  register_set("detect/free_flight/certified", free_flight, kCertified);
  register_set("detect/free_flight/uncertified", free_flight, kUncertified);
  register_set("detect/aligned_in_contact/certified", aligned_contact, kCertified);
  register_set("detect/aligned_free_flight/certified", aligned_free, kCertified);
  register_set("detect/in_contact/certified_reused_result", in_contact, kCertified, true);
  register_set("detect/free_flight/certified_reused_result", free_flight, kCertified, true);
  register_paper_baseline("detect/in_contact/paper_baseline", in_contact);
  register_paper_baseline("detect/free_flight/paper_baseline", free_flight);
  geo::JointContacts reused;  // one result for every call, as the reused-result row
  register_per_pose("detect/in_contact/certified_per_pose", in_contact, [reused](const geo::PartPose& journal) mutable {
    geo::detect_contacts(kTable2, kBearing, journal, reused, kCertified);
    benchmark::DoNotOptimize(reused);
    benchmark::ClobberMemory();
  });
  register_per_pose("detect/in_contact/paper_baseline_per_pose", in_contact, [](const geo::PartPose& journal) {
    geo::JointContacts found = clearjoint::bench::detect_contacts_paper_baseline(kTable2, kBearing, journal);
    benchmark::DoNotOptimize(found);
  });
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(kSeed));
  benchmark::AddCustomContext("inputs_per_benchmark", std::to_string(kInputCount));
  benchmark::AddCustomContext("joint",
                              "Marques et al. 2017 Table 2: Ri = 10 mm, Rj = 9.9 mm, Li = 20 mm, "
                              "Lj = 19.8 mm, cr = ca = 0.1 mm; journal offset <= 1.5 cr radially, "
                              "<= 1.5 ca axially, tilt <= 2 cr / Lj");
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
