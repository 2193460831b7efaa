// SPDX-License-Identifier: BSD-3-Clause
// The C API's cost against the C++ call it wraps, on the same poses in one process: the detection
// benchmark's random journals of the paper's joint (bench/geometry/detection_poses.hpp), in
// contact and in free flight.
//
// Rows, per set:
//   cpp_detect        C++ detect_contacts into one reused JointContacts (the in-place overload,
//                     the fastest C++ call; cj_detect uses it inside)
//   cj_detect         cj_detect into one reused cj_result
//   cpp_loop          one iteration: a C++ loop detecting every pose of the set into its own
//                     JointContacts (a simulation step of many joints)
//   cj_detect_many    one iteration: cj_detect_many over the same poses into a cj_result array
// Targets (issue 20): cj_detect <= 1.05 cpp_detect; cj_detect_many <= cpp_loop. Compare the rows
// by their ratio in one run with interleaved repetitions (bench/bindings/run_bindings_bench.sh).

#include <benchmark/benchmark.h>

#include <cstddef>
#include <string>
#include <vector>

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "detection_poses.hpp"

namespace {

namespace geo = clearjoint::geometry;
using clearjoint::bench::kBearing;
using clearjoint::bench::kTable2;

cj_pose c_pose(const geo::PartPose& p) {
  return {{p.p_WP.x(), p.p_WP.y(), p.p_WP.z()}, {p.axis_W.x(), p.axis_W.y(), p.axis_W.z()}};
}

const cj_dimensions kCTable2{kTable2.bearing_radius, kTable2.bearing_length, kTable2.journal_radius,
                             kTable2.journal_length};

void register_set(const std::string& set, const std::vector<geo::PartPose>& poses) {
  std::vector<cj_pose> c_poses;
  for (const geo::PartPose& p : poses) c_poses.push_back(c_pose(p));
  const double n = static_cast<double>(poses.size());

  benchmark::RegisterBenchmark(("c_api/" + set + "/cpp_detect").c_str(), [poses](benchmark::State& state) {
    geo::JointContacts found;
    std::size_t next = 0;
    for (auto _ : state) {
      geo::detect_contacts(kTable2, kBearing, poses[next], found);
      benchmark::DoNotOptimize(found);
      benchmark::ClobberMemory();
      if (++next == poses.size()) next = 0;
    }
  });

  benchmark::RegisterBenchmark(("c_api/" + set + "/cj_detect").c_str(), [c_poses](benchmark::State& state) {
    const cj_pose bearing = c_pose(kBearing);
    cj_result found;
    std::size_t next = 0;
    for (auto _ : state) {
      const cj_status status = cj_detect(&kCTable2, &bearing, &c_poses[next], nullptr, &found, nullptr, 0);
      benchmark::DoNotOptimize(status);
      benchmark::DoNotOptimize(found);
      benchmark::ClobberMemory();
      if (++next == c_poses.size()) next = 0;
    }
  });

  benchmark::RegisterBenchmark(("c_api/" + set + "/cpp_loop").c_str(), [poses, n](benchmark::State& state) {
    std::vector<geo::JointContacts> found(poses.size());
    for (auto _ : state) {
      for (std::size_t k = 0; k < poses.size(); ++k) geo::detect_contacts(kTable2, kBearing, poses[k], found[k]);
      benchmark::DoNotOptimize(found.data());
      benchmark::ClobberMemory();
    }
    state.counters["poses"] = n;
  });

  benchmark::RegisterBenchmark(("c_api/" + set + "/cj_detect_many").c_str(), [c_poses, n](benchmark::State& state) {
    const cj_pose bearing = c_pose(kBearing);
    const cj_pose_array bearings = cj_pose_array_repeat(&bearing);
    const cj_pose_array journals = cj_pose_array_rows(c_poses.front().p_WP);
    std::vector<cj_result> found(c_poses.size());
    for (auto _ : state) {
      const cj_status status = cj_detect_many(&kCTable2, &bearings, &journals, c_poses.size(), nullptr,
                                              found.data(), nullptr, nullptr, 0);
      benchmark::DoNotOptimize(status);
      benchmark::DoNotOptimize(found.data());
      benchmark::ClobberMemory();
    }
    state.counters["poses"] = n;
  });
}

}  // namespace

int main(int argc, char** argv) {
  using clearjoint::bench::journals;
  using clearjoint::bench::Outcome;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(clearjoint::bench::kSeed));
  benchmark::AddCustomContext("inputs_per_set", std::to_string(clearjoint::bench::kInputCount));
  register_set("in_contact", journals(1, clearjoint::bench::kMaxTilt, Outcome::in_contact));
  register_set("free_flight", journals(2, clearjoint::bench::kMaxTilt, Outcome::free_flight));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
