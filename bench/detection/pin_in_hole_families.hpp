// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Input families of the pin-in-hole joint's accuracy run (pin_in_hole_accuracy.cpp), each from a
/// fixed seed. Metres; every pose is generated in the hole's frame (a random direction for its
/// axis, its centre within 0.2 m of the origin, the axes given at random lengths) and turned into
/// the world frame.
///
///   random         random joints (Rh 5-50 mm, cr/Rh 1e-3 to 1e-1, L 0.5-3 Rh, 0-2 stops of
///                  outer radius 1.2-2.5 Rh with 0.5-3 cr of axial play) and pins offset up to 1.3 cr
///                  radially and 1.5 ca axially, tilted up to 2.5 cr / L: every scenario occurs.
///   near_tangent   the same joints and directions, the pin's displacement from the centred pose
///                  scaled to the first touch (bisected on the library's answer to the last bit,
///                  then either side of it): every candidate within a few ulps of touching.
///   near_parallel  tilts of 10^-k rad, k = 8..16, and exactly parallel axes (a tenth), offsets
///                  within 1e-6 of the line contact's threshold.
///   near_flush     a pin held against a head (one added where the joint has none), tilted by
///                  10^-k rad (k = 4..14), the stop's centre 0.5-100 Ro sin(tilt) beyond its face:
///                  mostly an outer circle beyond the face all round.
///   small_heads    heads of outer radius Rh + 0.02-3 cr on pins tilted by 0.2-2.5 cr / L, pressed
///                  against one head, its centre placed so that the stop's contact is bounded by
///                  its outer circle, by the hole's edge, or at a corner of the two (a third each).

#include <cstdint>
#include <string>
#include <vector>

#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"

namespace clearjoint::bench {

struct PinInHoleInput {
  std::string id;  ///< "random/17"
  geometry::PinInHoleDimensions dimensions;
  geometry::PartPose hole;
  geometry::PartPose pin;
};

/// The family's inputs: "random", "near_tangent", "near_parallel", "near_flush" or "small_heads";
/// `count` of them.
std::vector<PinInHoleInput> generate_pin_in_hole_family(const std::string& family, int count, std::uint64_t seed);

}  // namespace clearjoint::bench
