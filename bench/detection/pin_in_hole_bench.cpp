// SPDX-License-Identifier: BSD-3-Clause
#include "pin_in_hole_bench.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

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

/// The median over kRounds rounds of (a pass over `cases`) / (a pass over `inputs`), the two
/// passes of a round back to back in alternating order; also the mean cost of each (ns a query)
/// and the median over rounds of each pass's cost a query (for the contact-share-matched mix).
struct Interleaved {
  double ratio = 0.0, paper_ns = 0.0, pin_ns = 0.0;
  double paper_median_ns = 0.0, pin_median_ns = 0.0;
};
double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}
Interleaved interleaved(const std::vector<DetectionInput>& inputs, const std::vector<PinInHoleCase>& cases) {
  Interleaved out;
  if (inputs.empty()) return out;
  std::vector<double> ratios, paper_passes, pin_passes;
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
        for (const PinInHoleCase& c : cases) {
          auto answer = geometry::detect_pin_in_hole_contacts(c.dimensions, c.hole, c.pin);
          benchmark::DoNotOptimize(answer);
        }
        pin = seconds_since(start);
      }
    }
    ratios.push_back(pin / paper);
    paper_passes.push_back(paper);
    pin_passes.push_back(pin);
    paper_total += paper;
    pin_total += pin;
  }
  const double size = static_cast<double>(inputs.size());
  const double n = size * kRounds;
  return {median(ratios), 1e9 * paper_total / n, 1e9 * pin_total / n, 1e9 * median(paper_passes) / size,
          1e9 * median(pin_passes) / size};
}

/// The pin-in-hole joint's cost relative to the paper's at the paper joint's contact share: each
/// joint's per-query costs on the poses where both are free and where both are in contact,
/// weighted alike by the share of the poses on which the paper's joint is in contact. The
/// same-pose ratio compares the joints on the same poses, but on those poses the pin touches far
/// more often (its edges lie at the link's faces, beyond the journal's rims, and its heads reach
/// Ro sin(tilt) beyond their centres), and a contact costs a query where a free pose costs only
/// prefilters: that ratio measures how often the geometries touch as much as what a detection
/// costs. The matched mix asks what the pin-in-hole detection costs in a simulation whose joint
/// is in contact as often as the paper's: the comparison of like with like.
double contact_share_matched_ratio(const Interleaved& free_flight, const Interleaved& contact, double share) {
  const double pin = share * contact.pin_median_ns + (1.0 - share) * free_flight.pin_median_ns;
  const double paper = share * contact.paper_median_ns + (1.0 - share) * free_flight.paper_median_ns;
  return paper > 0.0 ? pin / paper : 0.0;
}

}  // namespace

void register_pin_in_hole_benchmark(const char* name, const std::vector<DetectionInput>& inputs) {
  auto cases = std::make_shared<std::vector<PinInHoleCase>>();
  for (const DetectionInput& input : inputs) cases->push_back(pin_in_hole_input(input));
  // The same poses split by whether both joints are free or both in contact (the pin's edges lie
  // at the link's faces, beyond the journal's rims, so on the same poses it touches more often).
  std::vector<DetectionInput> free_inputs, contact_inputs;
  std::vector<PinInHoleCase> free_cases, contact_cases;
  std::size_t in_contact = 0, paper_in_contact = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const PinInHoleCase& c = (*cases)[i];
    const bool pin = geometry::detect_pin_in_hole_contacts(c.dimensions, c.hole, c.pin).contact_count > 0;
    const bool paper = geometry::detect_contacts(inputs[i].dimensions, inputs[i].bearing, inputs[i].journal).contact_count > 0;
    in_contact += pin ? 1 : 0;
    paper_in_contact += paper ? 1 : 0;
    if (!pin && !paper) {
      free_inputs.push_back(inputs[i]);
      free_cases.push_back(c);
    } else if (pin && paper) {
      contact_inputs.push_back(inputs[i]);
      contact_cases.push_back(c);
    }
  }
  const Interleaved all = interleaved(inputs, *cases);
  const Interleaved free_flight = interleaved(free_inputs, free_cases);
  const Interleaved contact = interleaved(contact_inputs, contact_cases);
  const double ratio = all.ratio;
  const double contact_share = static_cast<double>(in_contact) / static_cast<double>(cases->size());
  const double paper_contact_share = static_cast<double>(paper_in_contact) / static_cast<double>(cases->size());
  const double matched = contact_share_matched_ratio(free_flight, contact, paper_contact_share);
  const std::string title = std::string("pin_in_hole/") + name + "/certified";
  benchmark::RegisterBenchmark(title.c_str(), [cases, ratio, all, free_flight, contact, contact_share,
                                                paper_contact_share, matched,
                                                free_count = free_cases.size(),
                                                contact_count = contact_cases.size()](benchmark::State& state) {
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
    state.counters["interleaved_paper_joint_ns"] = all.paper_ns;
    state.counters["interleaved_pin_in_hole_ns"] = all.pin_ns;
    state.counters["both_free_inputs"] = static_cast<double>(free_count);
    state.counters["both_free_ratio"] = free_flight.ratio;
    state.counters["both_in_contact_inputs"] = static_cast<double>(contact_count);
    state.counters["both_in_contact_ratio"] = contact.ratio;
    state.counters["paper_contact_share"] = paper_contact_share;
    state.counters["contact_share_matched_ratio"] = matched;
  })->Iterations(static_cast<benchmark::IterationCount>(cases->size()) * 20);
}

}  // namespace clearjoint::bench
