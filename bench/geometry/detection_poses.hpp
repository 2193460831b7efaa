// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The detection benchmarks' joint and random journal poses (bench_detect_contacts,
// bench_detection_parts): the paper's joint (Marques et al. 2017, Table 2) with the bearing fixed
// (centre at the origin, axis +z), journals drawn from a fixed seed and kept by the outcome of
// one certified detection each. One definition, so that both benchmarks time the very same poses.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"

namespace clearjoint::bench {

/// Paper Table 2, in metres.
inline const geometry::JointDimensions kTable2{.bearing_radius = 10.0e-3,
                                              .bearing_length = 20.0e-3,
                                              .journal_radius = 9.9e-3,
                                              .journal_length = 19.8e-3};
/// Largest tilt of a centred journal spanning the radial clearance: 2 cr / Lj ~ 0.0101 rad.
inline const double kMaxTilt = 2.0 * kTable2.radial_clearance() / kTable2.journal_length;
inline const geometry::PartPose kBearing{geometry::Vector3::Zero(), geometry::Vector3::UnitZ()};

inline constexpr std::uint64_t kSeed = 20170824;
inline constexpr std::size_t kInputCount = 4096;

enum class Outcome { in_contact, free_flight };

/// kInputCount journal poses from stream `stream` (seed kSeed + stream) with the wanted outcome:
/// centre off the bearing axis by up to 1.5 cr and along it by up to 1.5 ca either way, axis
/// tilted by up to `max_tilt`, azimuths uniform. Fewer if 50 draws per pose do not find them.
std::vector<geometry::PartPose> journals(std::uint64_t stream, double max_tilt, Outcome wanted);

}  // namespace clearjoint::bench
