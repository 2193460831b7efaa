// SPDX-License-Identifier: BSD-3-Clause
#include "pin_in_hole_bench.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

namespace clearjoint::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// Rounds of the interleaved measurement: the median of 31 ratios discards the rounds that an
/// interruption lengthened on one side only.
constexpr int kRounds = 31;

/// A paper joint's input read as a pin through a hole: the bearing is the hole (radius Ri, length
/// Li), the journal the pin (radius Rj), with a head beyond each face, as far beyond as the
/// journal's bases are inside the bearing (ca), of outer radius 1.5 Ri. The poses are the same.
struct PinInHoleCase {
  geometry::PinInHoleDimensions dimensions;
  geometry::PartPose hole, pin;
};
PinInHoleCase pin_in_hole_input(const DetectionInput& input) {
  PinInHoleCase out;
  const geometry::JointDimensions& d = input.dimensions;
  out.dimensions.hole_radius = d.bearing_radius;
  out.dimensions.hole_length = d.bearing_length;
  out.dimensions.pin_radius = d.journal_radius;
  const double stop = 0.5 * d.bearing_length + d.axial_clearance();
  out.dimensions.stops[0] = {-stop, 1.5 * d.bearing_radius};
  out.dimensions.stops[1] = {stop, 1.5 * d.bearing_radius};
  out.dimensions.stop_count = 2;
  out.hole = input.bearing;
  out.pin = input.journal;
  return out;
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

void register_pin_in_hole_benchmark(const char* name, const std::vector<DetectionInput>& inputs) {
  auto cases = std::make_shared<std::vector<PinInHoleCase>>();
  for (const DetectionInput& input : inputs) cases->push_back(pin_in_hole_input(input));
  std::vector<double> ratios;
  double paper_total = 0.0, pin_total = 0.0;
  for (int round = 0; round < kRounds; ++round) {
    double paper = 0.0, pin = 0.0;
    for (int side = 0; side < 2; ++side) {
      const bool paper_side = (side == 0) == (round % 2 == 0);
      const auto start = Clock::now();
      if (paper_side) {
        for (const DetectionInput& input : inputs) {
          auto answer = geometry::detect_contacts(input.dimensions, input.bearing, input.journal);
          benchmark::DoNotOptimize(answer);
        }
        paper = seconds_since(start);
      } else {
        for (const PinInHoleCase& c : *cases) {
          auto answer = geometry::detect_pin_in_hole_contacts(c.dimensions, c.hole, c.pin);
          benchmark::DoNotOptimize(answer);
        }
        pin = seconds_since(start);
      }
    }
    ratios.push_back(pin / paper);
    paper_total += paper;
    pin_total += pin;
  }
  std::nth_element(ratios.begin(), ratios.begin() + kRounds / 2, ratios.end());
  const double ratio = ratios[kRounds / 2];
  const double n = static_cast<double>(inputs.size()) * kRounds;
  std::size_t in_contact = 0;
  for (const PinInHoleCase& c : *cases) {
    in_contact += geometry::detect_pin_in_hole_contacts(c.dimensions, c.hole, c.pin).contact_count > 0 ? 1 : 0;
  }
  const double contact_share = static_cast<double>(in_contact) / static_cast<double>(cases->size());
  const std::string title = std::string("pin_in_hole/") + name + "/certified";
  benchmark::RegisterBenchmark(title.c_str(), [cases, ratio, paper_total, pin_total, n, contact_share](benchmark::State& state) {
    std::size_t next = 0;
    for (auto _ : state) {
      const PinInHoleCase& c = (*cases)[next];
      auto answer = geometry::detect_pin_in_hole_contacts(c.dimensions, c.hole, c.pin);
      benchmark::DoNotOptimize(answer);
      if (++next == cases->size()) next = 0;
    }
    state.counters["inputs"] = static_cast<double>(cases->size());
    state.counters["contact_share"] = contact_share;
    state.counters["ratio_to_paper_joint"] = ratio;
    state.counters["interleaved_paper_joint_ns"] = 1e9 * paper_total / n;
    state.counters["interleaved_pin_in_hole_ns"] = 1e9 * pin_total / n;
  })->Iterations(static_cast<benchmark::IterationCount>(cases->size()) * 20);
}

}  // namespace clearjoint::bench
