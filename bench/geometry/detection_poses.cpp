// SPDX-License-Identifier: BSD-3-Clause
#include "detection_poses.hpp"

#include <cmath>
#include <numbers>

#include "uniform_source.hpp"

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;

// Draws allowed per kept pose before giving up (the in-contact share is ~0.7, free flight ~0.3).
constexpr std::size_t kMaxDrawsPerInput = 50;

geo::PartPose random_journal(UniformSource& uniform, double max_tilt) {
  const double radial_clearance = kTable2.radial_clearance(), axial_clearance = kTable2.axial_clearance();
  const double offset = uniform(0.0, 1.5 * radial_clearance);
  const double offset_azimuth = uniform(0.0, 2.0 * std::numbers::pi);
  const double shift = uniform(-1.5 * axial_clearance, 1.5 * axial_clearance);
  const double tilt = uniform(0.0, max_tilt);
  const double tilt_azimuth = uniform(0.0, 2.0 * std::numbers::pi);
  return {{offset * std::cos(offset_azimuth), offset * std::sin(offset_azimuth), shift},
          {std::sin(tilt) * std::cos(tilt_azimuth), std::sin(tilt) * std::sin(tilt_azimuth),
           std::cos(tilt)}};
}

}  // namespace

std::vector<geo::PartPose> journals(std::uint64_t stream, double max_tilt, Outcome wanted) {
  UniformSource uniform(kSeed + stream);
  std::vector<geo::PartPose> kept;
  for (std::size_t draws = 0; kept.size() < kInputCount && draws < kMaxDrawsPerInput * kInputCount;
       ++draws) {
    const geo::PartPose journal = random_journal(uniform, max_tilt);
    const bool contact = geo::detect_contacts(kTable2, kBearing, journal).contact_count > 0;
    if (contact == (wanted == Outcome::in_contact)) kept.push_back(journal);
  }
  return kept;
}

}  // namespace clearjoint::bench
