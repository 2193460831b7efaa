// SPDX-License-Identifier: BSD-3-Clause
// The parts of an in-contact detection, each timed alone on the poses of
// bench_detect_contacts' detect/in_contact rows (detection_poses.hpp): the whole detection for
// reference, the circle-cylinder query of each rim that crosses the bearing wall, its two inner
// steps (the rim distance polynomial and the certified roots, through the kernel's detail
// headers), and the circle-plane query of each rim that crosses a base plane. `per_pose`: how
// many of each a detection makes on average.
//
// Each loop repeats one part over many inputs, so consecutive calls can overlap in the out-of-order
// core: these are throughput figures, and a change can speed a part up here and not the detection
// (docs/reports/benchmarks-kernel.md, "Third session of 2026-11-24": the proof by the slope took
// the roots from 141 to 122 ns here while the detection got slower, until a compiler flag was
// found). Use the rows to see where a change acts, and bench_detect_contacts to judge it.

#include <benchmark/benchmark.h>

#include <cstddef>
#include <string>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "detection_poses.hpp"
#include "filters/certified_rim_roots.hpp"
#include "predicates/rim_distance_polynomial.hpp"

namespace {

namespace geo = clearjoint::geometry;
using clearjoint::bench::kBearing;
using clearjoint::bench::kTable2;

/// The kernel inputs that the detections of `poses` pass on: every rim whose circle-cylinder
/// query finds crossings, and every rim and base plane whose circle-plane query does.
struct Parts {
  std::vector<geo::PartPose> poses;
  std::vector<geo::Circle3> wall_crossing_rims;
  std::vector<geo::detail::RimDistancePolynomial> polynomials;  // of those rims
  std::vector<geo::Circle3> plane_crossing_rims;
  std::vector<geo::Plane3> planes;  // the base plane each of those crosses
};

const geo::Cylinder3 kWall{geo::Vector3::Zero(), geo::Vector3::UnitZ(), kTable2.bearing_radius};

Parts parts_of(std::vector<geo::PartPose> poses) {
  Parts parts;
  parts.poses = std::move(poses);
  for (const geo::PartPose& journal : parts.poses) {
    for (const double side : {1.0, -1.0}) {
      const geo::Circle3 rim{journal.p_WP + side * 0.5 * kTable2.journal_length * journal.axis_W, journal.axis_W,
                             kTable2.journal_radius};
      if (geo::intersect_circle_cylinder(rim, kWall).crossing_count > 0) {
        parts.wall_crossing_rims.push_back(rim);
        parts.polynomials.push_back(geo::detail::rim_distance_polynomial(rim, kWall));
      }
      const geo::Plane3 plane{geo::Vector3(0, 0, side * 0.5 * kTable2.bearing_length), geo::Vector3(0, 0, side)};
      if (geo::intersect_circle_plane(rim, plane).topology == geo::CirclePlaneTopology::two_crossings) {
        parts.plane_crossing_rims.push_back(rim);
        parts.planes.push_back(plane);
      }
    }
  }
  return parts;
}

/// Registers `name`, timing `part(i)` for i cycling through [0, count).
template <class Part>
void register_part(const std::string& name, std::size_t count, std::size_t poses, Part part) {
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) mutable {
    std::size_t next = 0;
    for (auto _ : state) {
      part(next);
      if (++next == count) next = 0;
    }
    state.counters["per_pose"] = static_cast<double>(count) / static_cast<double>(poses);
  });
}

void register_all() {
  static const Parts parts =
      parts_of(clearjoint::bench::journals(1, clearjoint::bench::kMaxTilt, clearjoint::bench::Outcome::in_contact));
  const std::size_t poses = parts.poses.size();
  static geo::JointContacts reused;
  register_part("parts/in_contact/detect_reused_result", poses, poses, [](std::size_t i) {
    geo::detect_contacts(kTable2, kBearing, parts.poses[i], reused);
    benchmark::DoNotOptimize(reused);
  });
  register_part("parts/in_contact/wall_crossing_query", parts.wall_crossing_rims.size(), poses, [](std::size_t i) {
    geo::CircleCylinderIntersection hit = geo::intersect_circle_cylinder(parts.wall_crossing_rims[i], kWall);
    benchmark::DoNotOptimize(hit);
  });
  register_part("parts/in_contact/rim_distance_polynomial", parts.wall_crossing_rims.size(), poses,
                [](std::size_t i) {
                  geo::detail::RimDistancePolynomial g =
                      geo::detail::rim_distance_polynomial(parts.wall_crossing_rims[i], kWall);
                  benchmark::DoNotOptimize(g);
                });
  register_part("parts/in_contact/certified_rim_roots", parts.polynomials.size(), poses, [](std::size_t i) {
    geo::detail::RimRoots roots = geo::detail::certified_rim_roots(parts.polynomials[i]);
    benchmark::DoNotOptimize(roots);
  });
  register_part("parts/in_contact/plane_crossing_query", parts.plane_crossing_rims.size(), poses, [](std::size_t i) {
    geo::CirclePlaneIntersection hit = geo::intersect_circle_plane(parts.plane_crossing_rims[i], parts.planes[i]);
    benchmark::DoNotOptimize(hit);
  });
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(clearjoint::bench::kSeed + 1));
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
