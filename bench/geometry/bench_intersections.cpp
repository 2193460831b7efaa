// SPDX-License-Identifier: BSD-3-Clause
// Timings of the kernel's rim queries on the paper's joint (Marques et al. 2017, Table 2).
//
// Every input set is built once, before any timing, from a fixed seed that is written into the
// JSON context; each timed loop cycles through its set. Each benchmark also reports, as counters,
// the share of its inputs per topology and per certificate level, computed outside the timed loop,
// so that a time can be read together with the work it stands for. The certified and the plain
// double pipelines run on the same inputs in the same process: compare them by their ratio, which
// is steadier than either absolute time. docs/reports/benchmarks-kernel.md has the command and the
// table.
//
// Frames: the bearing frame is the world frame W. The bearing axis a_i is +z through the origin
// P_i, its base B is the plane z = +Li/2 with its normal pointing out of the bearing. The journal
// axis a_j and the journal centre P_j (the middle of its axis) are drawn at random; the journal rim
// at base B is the circle of centre P_j + (Lj/2) a_j, normal a_j, radius Rj (paper Fig. 5).

#include <benchmark/benchmark.h>

#include "plain_circle_plane.hpp"
#include "uniform_source.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/geometry/model/intersection_options.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

// Paper Table 2, in metres.
constexpr double kBearingRadius = 10.0e-3;   // Ri
constexpr double kJournalRadius = 9.9e-3;    // Rj
constexpr double kBearingLength = 20.0e-3;   // Li
constexpr double kJournalLength = 19.8e-3;   // Lj
constexpr double kAxialClearance = 0.1e-3;   // ca
// cr = Ri - Rj. The subtraction of the two stored doubles is exact (Sterbenz: Ri/2 <= Rj <= Ri),
// so near-tangent inputs built from it have exactly the margin they are given.
constexpr double kRadialClearance = kBearingRadius - kJournalRadius;

// Largest journal tilt of a realistic pose: the tilt at which a centred journal of length Lj
// spans the radial clearance on both sides, 2 cr / Lj ~ 0.0101 rad.
constexpr double kMaxTilt = 2.0 * kRadialClearance / kJournalLength;

constexpr std::uint64_t kSeed = 20170823;
// Inputs per random set; a power of two keeps the loop's index update cheap.
constexpr std::size_t kInputCount = 4096;
// Margin of the near-tangent inputs, relative to cr: far below what the floating-point proof can
// resolve on Table 2 coordinates (one ulp of 0.01 m is ~1.7e-14 cr), so the exact fallback decides.
constexpr double kNearTangencyMargin = 1e-15;

const geo::IntersectionOptions kCertified{};
const geo::IntersectionOptions kUncertified{.certify = false};
const geo::IntersectionOptions kNoExactFallback{.certify = true, .exact_fallback = false};

struct RimCylinderQuery {
  geo::Circle3 rim;
  geo::Cylinder3 wall;
};

struct RimPlaneQuery {
  geo::Circle3 rim;
  geo::Plane3 base;
};

using clearjoint::bench::UniformSource;

/// A direction tilted from +z by an angle in [0, max_tilt], azimuth uniform.
Vector3 tilted_axis(UniformSource& uniform, double max_tilt) {
  const double tilt = uniform(0.0, max_tilt);
  const double azimuth = uniform(0.0, 2.0 * std::numbers::pi);
  return {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt)};
}

/// A point at distance in [0, max_offset] from the z axis, azimuth uniform, height `z`.
Vector3 offset_point(UniformSource& uniform, double max_offset, double z) {
  const double offset = uniform(0.0, max_offset);
  const double azimuth = uniform(0.0, 2.0 * std::numbers::pi);
  return {offset * std::cos(azimuth), offset * std::sin(azimuth), z};
}

/// The journal rim at base B (paper Fig. 5): centre P_j + (Lj/2) a_j, normal a_j, radius Rj.
geo::Circle3 rim_at_base_b(const Vector3& p_WJ, const Vector3& axis_W) {
  return geo::Circle3{p_WJ + 0.5 * kJournalLength * axis_W, axis_W, kJournalRadius};
}

const geo::Cylinder3 kBearingWall{Vector3::Zero(), Vector3::UnitZ(), kBearingRadius};
const geo::Plane3 kBearingBaseB{Vector3(0.0, 0.0, 0.5 * kBearingLength), Vector3::UnitZ()};

/// Rims against the wall, journal offset up to `max_offset` off the bearing axis and tilted up to
/// `max_tilt`.
std::vector<RimCylinderQuery> random_wall_queries(std::uint64_t stream, double max_offset,
                                                  double max_tilt) {
  UniformSource uniform(kSeed + stream);
  std::vector<RimCylinderQuery> queries;
  queries.reserve(kInputCount);
  for (std::size_t k = 0; k < kInputCount; ++k) {
    const Vector3 p_WJ = offset_point(uniform, max_offset, 0.0);
    const Vector3 axis_W = tilted_axis(uniform, max_tilt);
    queries.push_back({rim_at_base_b(p_WJ, axis_W), kBearingWall});
  }
  return queries;
}

/// Rims against base B. The journal centre moves axially by [0, 2 ca], so the rim centre ends
/// between ca inside and ca beyond the base, and moves radially by up to 1.5 cr; with the tilt the
/// rim reaches up to Rj sin(max_tilt) ~ ca either side of its centre: crossing and disjoint rims
/// on both sides all occur. max_tilt = 0 gives the aligned journal of a planar mechanism (paper
/// Section 6.1): every rim parallel to the base, beyond it or inside by up to ca.
std::vector<RimPlaneQuery> random_base_queries(std::uint64_t stream, double max_tilt) {
  UniformSource uniform(kSeed + stream);
  std::vector<RimPlaneQuery> queries;
  queries.reserve(kInputCount);
  for (std::size_t k = 0; k < kInputCount; ++k) {
    const double axial_shift = uniform(0.0, 2.0 * kAxialClearance);
    const Vector3 p_WJ = offset_point(uniform, 1.5 * kRadialClearance, axial_shift);
    const Vector3 axis_W = tilted_axis(uniform, max_tilt);
    queries.push_back({rim_at_base_b(p_WJ, axis_W), kBearingBaseB});
  }
  return queries;
}

/// Exact tangencies with small integer coordinates: every input is representable, so the answer
/// is a true tangency (a double root) that no floating-point filter can separate from a crossing.
std::vector<RimCylinderQuery> exact_tangent_wall_queries() {
  const Vector3 z = Vector3::UnitZ();
  return {
      // Rim inside the wall, touching it at (2, 0, 0): |x|^2 - 4 = 2 cos(theta) - 2.
      {{{1, 0, 0}, z, 1}, {{0, 0, 0}, z, 2}},
      {{{-1, 0, 0}, z, 1}, {{0, 0, 0}, z, 2}},
      {{{0, 1, 0}, z, 1}, {{0, 0, 0}, z, 2}},
      {{{0, -1, 0}, z, 1}, {{0, 0, 0}, z, 2}},
      {{{1, 0, 5}, z, 1}, {{0, 0, -7}, z, 2}},                 // shifted along the axis
      {{{1, 0, 0}, {0, 0, -2}, 1}, {{0, 0, 0}, {0, 0, 3}, 2}},  // normal and axis not unit
      {{{2, 0, 0}, z, 2}, {{0, 0, 0}, z, 4}},                  // scaled by 2
      {{{3, 1, 0}, z, 1}, {{2, 1, 0}, z, 2}},                  // axis off the origin
      {{{0, 1, 0}, {1, 0, 0}, 1}, {{0, 0, 0}, {1, 0, 0}, 2}},  // axes along x
      // Rim outside the wall, touching it at (1, 0, 0): |x|^2 - 1 = 4 + 4 cos(theta).
      {{{2, 0, 0}, z, 1}, {{0, 0, 0}, z, 1}},
      // Rim across the axis in the plane x = 0: two tangencies, at (0, +-1, 0).
      {{{0, 0, 0}, {1, 0, 0}, 1}, {{0, 0, 0}, z, 1}},
  };
}

/// Table 2 rims perpendicular to the wall's axis whose farthest point is 1e-15 cr inside or
/// beyond the wall: centre offset e = cr -+ 1e-15 cr along +-x or +-y, so max |x| = Rj + e.
std::vector<RimCylinderQuery> near_tangent_wall_queries() {
  std::vector<RimCylinderQuery> queries;
  const double margin = kNearTangencyMargin * kRadialClearance;
  for (const double sign : {1.0, -1.0}) {
    // Rounding the centre offset moves the margin by at most half an ulp of cr (~7e-21 m), under a
    // tenth of the margin: the sign of each case is what it says.
    const double offset = kRadialClearance - sign * margin;
    for (const Vector3& direction :
         {Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(-1, 0, 0), Vector3(0, -1, 0)}) {
      const Vector3 center = offset * direction + Vector3(0.0, 0.0, 0.5 * kJournalLength);
      queries.push_back({{center, Vector3::UnitZ(), kJournalRadius}, kBearingWall});
    }
  }
  return queries;
}

/// Exact tangencies of a rim with a plane, integer or dyadic coordinates.
std::vector<RimPlaneQuery> exact_tangent_base_queries() {
  const Vector3 z = Vector3::UnitZ();
  return {
      {{{0, 0, 1}, {1, 0, 0}, 1}, {{0, 0, 0}, z}},          // rim above the plane, touching at 0
      {{{0, 0, -1}, {0, 1, 0}, 1}, {{0, 0, 0}, z}},         // below
      {{{0, 0, 4}, {1, 0, 0}, 3}, {{5, 7, 1}, {0, 0, 5}}},  // normal not unit, plane off origin
      // Rim tilted by a 3-4-5 triangle: highest point z_c + 5 * 3/5 = 0.
      {{{0, 0, -3}, {0, 3, 4}, 5}, {{0, 0, 0}, z}},
      // Table 2 in micrometres (exact integers): bearing base tilted by atan(199/19800) ~ 0.01 rad,
      // journal rim 0.5 um off nominal: 19800 (9900.5 - 10000) + 199 * 9900 = 0.
      {{{0, 0, 9900.5}, z, 9900}, {{0, 0, 10000}, {0, 199, 19800}}},
  };
}

/// The micrometre Table 2 tangency above, with the rim centre moved by one ulp either way: the
/// smallest representable margins, 19800 ulp(9900.5) / 19801 ~ 1.8e-12 um ~ 1.8e-14 ca.
std::vector<RimPlaneQuery> near_tangent_base_queries() {
  std::vector<RimPlaneQuery> queries;
  for (const double toward : {0.0, 1.0e5}) {
    const double z_center = std::nextafter(9900.5, toward);
    queries.push_back({{{0, 0, z_center}, Vector3::UnitZ(), 9900}, {{0, 0, 10000}, {0, 199, 19800}}});
  }
  return queries;
}

using Shares = std::map<std::string, double>;

void add_certificate_share(Shares& shares, const geo::Certificate& certificate, double weight) {
  shares[std::string("cert_") + std::string(geo::to_string(certificate.level))] += weight;
}

/// Share of the inputs per outcome, from one untimed call per input.
Shares outcome_shares(const std::vector<RimCylinderQuery>& queries,
                      const geo::IntersectionOptions& options) {
  // crossing: topology crossing; of those, roots4: four roots counted with multiplicity (two
  // penetration arcs, or tangencies); tangent: some crossing of multiplicity >= 2.
  Shares shares{{"inside", 0.0}, {"outside", 0.0}, {"crossing", 0.0}, {"roots4", 0.0},
                {"tangent", 0.0}, {"on_surface", 0.0}};
  const double weight = 1.0 / static_cast<double>(queries.size());
  for (const RimCylinderQuery& q : queries) {
    const geo::CircleCylinderIntersection hit = geo::intersect_circle_cylinder(q.rim, q.wall, options);
    switch (hit.topology) {
      case geo::CircleCylinderTopology::inside: shares["inside"] += weight; break;
      case geo::CircleCylinderTopology::outside: shares["outside"] += weight; break;
      case geo::CircleCylinderTopology::on_surface: shares["on_surface"] += weight; break;
      case geo::CircleCylinderTopology::crossing:
        shares["crossing"] += weight;
        if (hit.root_count() == 4) shares["roots4"] += weight;
        break;
    }
    for (int k = 0; k < hit.crossing_count; ++k) {
      if (hit.crossings[static_cast<std::size_t>(k)].multiplicity > 1) {
        shares["tangent"] += weight;
        break;
      }
    }
    add_certificate_share(shares, hit.certificate, weight);
  }
  return shares;
}

Shares outcome_shares(const std::vector<RimPlaneQuery>& queries,
                      const geo::IntersectionOptions& options) {
  Shares shares{{"disjoint", 0.0}, {"tangent", 0.0}, {"crossing", 0.0}, {"in_plane", 0.0}};
  const double weight = 1.0 / static_cast<double>(queries.size());
  for (const RimPlaneQuery& q : queries) {
    const geo::CirclePlaneIntersection hit = geo::intersect_circle_plane(q.rim, q.base, options);
    switch (hit.topology) {
      case geo::CirclePlaneTopology::disjoint: shares["disjoint"] += weight; break;
      case geo::CirclePlaneTopology::tangent: shares["tangent"] += weight; break;
      case geo::CirclePlaneTopology::two_crossings: shares["crossing"] += weight; break;
      case geo::CirclePlaneTopology::circle_in_plane: shares["in_plane"] += weight; break;
    }
    add_certificate_share(shares, hit.certificate, weight);
  }
  return shares;
}

/// Times `query` over `inputs`, one call per iteration, cycling; `shares` become counters.
template <class Input, class Query>
void time_queries(benchmark::State& state, const std::vector<Input>& inputs, const Shares& shares,
                  Query query) {
  std::size_t next = 0;
  for (auto _ : state) {
    auto result = query(inputs[next]);
    benchmark::DoNotOptimize(result);
    if (++next == inputs.size()) next = 0;
  }
  state.counters["rims_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  for (const auto& [name, share] : shares) state.counters[name] = share;
}

void register_wall(const std::string& name, std::vector<RimCylinderQuery> inputs,
                   const geo::IntersectionOptions& options) {
  Shares shares = outcome_shares(inputs, options);
  benchmark::RegisterBenchmark(
      name.c_str(),
      [inputs = std::move(inputs), shares = std::move(shares), options](benchmark::State& state) {
        time_queries(state, inputs, shares, [&options](const RimCylinderQuery& q) {
          return geo::intersect_circle_cylinder(q.rim, q.wall, options);
        });
      });
}

void register_base(const std::string& name, std::vector<RimPlaneQuery> inputs,
                   const geo::IntersectionOptions& options) {
  Shares shares = outcome_shares(inputs, options);
  benchmark::RegisterBenchmark(
      name.c_str(),
      [inputs = std::move(inputs), shares = std::move(shares), options](benchmark::State& state) {
        time_queries(state, inputs, shares, [&options](const RimPlaneQuery& q) {
          return geo::intersect_circle_plane(q.rim, q.base, options);
        });
      });
}

/// The plain-double measuring stick of plain_circle_plane.hpp on the same inputs (no counters:
/// its answers are not certified and are not counted).
template <class Plain>
void register_plain_base(const std::string& name, std::vector<RimPlaneQuery> inputs, Plain plain) {
  benchmark::RegisterBenchmark(name.c_str(), [inputs = std::move(inputs), plain](benchmark::State& state) {
    time_queries(state, inputs, {}, [&plain](const RimPlaneQuery& q) { return plain(q.rim, q.base); });
  });
}

/// The inputs whose certified answer has `topology` (to split a family's cost by outcome).
std::vector<RimPlaneQuery> with_topology(const std::vector<RimPlaneQuery>& queries,
                                         geo::CirclePlaneTopology topology) {
  std::vector<RimPlaneQuery> kept;
  for (const RimPlaneQuery& q : queries) {
    if (geo::intersect_circle_plane(q.rim, q.base, kCertified).topology == topology) kept.push_back(q);
  }
  return kept;
}

void register_all() {
  // Journal offset up to 1.5 cr and tilted up to 2 cr / Lj: the rim centre can sit up to ~2.5 cr
  // off the bearing axis, so a good share of the rims cross the wall.
  const auto wall_random = random_wall_queries(1, 1.5 * kRadialClearance, kMaxTilt);
  // Offset and tilt at a quarter of those: the rim stays within Rj + 0.5 cr of the axis, half a
  // clearance inside the wall.
  const auto wall_inside = random_wall_queries(2, 0.25 * kRadialClearance, 0.25 * kMaxTilt);
  const auto base_random = random_base_queries(3, kMaxTilt);
  // Aligned journals (tilt 0, the planar mechanism of paper Section 6.1): rims parallel to the
  // base, and perpendicular to the wall's axis.
  const auto base_aligned = random_base_queries(4, 0.0);
  const auto wall_aligned = random_wall_queries(5, 1.5 * kRadialClearance, 0.0);

  register_wall("circle_cylinder/random_pose/certified", wall_random, kCertified);
  register_wall("circle_cylinder/random_pose/uncertified", wall_random, kUncertified);
  register_wall("circle_cylinder/well_inside/certified", wall_inside, kCertified);
  register_wall("circle_cylinder/well_inside/uncertified", wall_inside, kUncertified);
  register_base("circle_plane/random_pose/certified", base_random, kCertified);
  register_base("circle_plane/random_pose/uncertified", base_random, kUncertified);
  // The same rims split by outcome: a disjoint rim needs the depth of its deepest point only; a
  // crossing one also two crossing angles (acos and asin) and points.
  register_base("circle_plane/random_pose_disjoint/certified",
                with_topology(base_random, geo::CirclePlaneTopology::disjoint), kCertified);
  register_base("circle_plane/random_pose_crossing/certified",
                with_topology(base_random, geo::CirclePlaneTopology::two_crossings), kCertified);
  // The arithmetic the contract needs, without proof (plain_circle_plane.hpp): the whole answer,
  // and the topology with the depth alone.
  register_plain_base("circle_plane/random_pose/plain_double_floor", base_random, clearjoint::bench::plain_circle_plane);
  register_plain_base("circle_plane/random_pose/plain_double_topology_and_depth", base_random,
                      clearjoint::bench::plain_circle_plane_depth);
  register_plain_base("circle_plane/random_pose_disjoint/plain_double_floor",
                      with_topology(base_random, geo::CirclePlaneTopology::disjoint), clearjoint::bench::plain_circle_plane);
  register_plain_base("circle_plane/random_pose_crossing/plain_double_floor",
                      with_topology(base_random, geo::CirclePlaneTopology::two_crossings),
                      clearjoint::bench::plain_circle_plane);
  register_plain_base("circle_plane/aligned_journal/plain_double_floor", base_aligned, clearjoint::bench::plain_circle_plane);
  register_wall("circle_cylinder/aligned_journal/certified", wall_aligned, kCertified);
  register_wall("circle_cylinder/aligned_journal/uncertified", wall_aligned, kUncertified);
  register_base("circle_plane/aligned_journal/certified", base_aligned, kCertified);
  register_base("circle_plane/aligned_journal/uncertified", base_aligned, kUncertified);

  // The exact fallback: the same inputs with it on (exact answers) and off (the cost of the
  // floating-point attempt alone, answers uncertain).
  register_wall("circle_cylinder/exact_tangency/certified", exact_tangent_wall_queries(), kCertified);
  register_wall("circle_cylinder/exact_tangency/no_exact_fallback", exact_tangent_wall_queries(),
                kNoExactFallback);
  register_wall("circle_cylinder/near_tangency_1e-15cr/certified", near_tangent_wall_queries(),
                kCertified);
  register_wall("circle_cylinder/near_tangency_1e-15cr/no_exact_fallback",
                near_tangent_wall_queries(), kNoExactFallback);
  register_base("circle_plane/exact_tangency/certified", exact_tangent_base_queries(), kCertified);
  register_base("circle_plane/exact_tangency/no_exact_fallback", exact_tangent_base_queries(),
                kNoExactFallback);
  register_base("circle_plane/near_tangency_1ulp/certified", near_tangent_base_queries(),
                kCertified);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(kSeed));
  benchmark::AddCustomContext("random_inputs_per_benchmark", std::to_string(kInputCount));
  benchmark::AddCustomContext("joint",
                              "Marques et al. 2017 Table 2: Ri = 10 mm, Rj = 9.9 mm, Li = 20 mm, "
                              "Lj = 19.8 mm, cr = ca = 0.1 mm");
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
