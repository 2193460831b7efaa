// SPDX-License-Identifier: BSD-3-Clause
// The kernel underneath detect_contacts: one journal rim (a circle) against the bearing wall (a
// cylinder). Every crossing is found and proved, with an enclosure of its angle and point, and the
// answer says how far it can be trusted.
#include <clearjoint/geometry/queries/intersect_circle_cylinder.hpp>

#include <cstdio>
#include <string>

namespace geo = clearjoint::geometry;

int main() {
  // Rim of radius 9.9 mm at height 9.9 mm, its centre 0.15 mm off the axis and its plane tilted
  // (the normal need not be unit length), against a wall of radius 10 mm about the z axis.
  const geo::Circle3 rim{{0, 0.15e-3, 0.0099}, {0, 0.01, 1}, 0.0099};
  const geo::Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 0.010};
  const geo::CircleCylinderIntersection hit = geo::intersect_circle_cylinder(rim, wall);

  std::printf("topology %s, %d crossing(s), %d penetration arc(s), certificate %s\n",
              hit.topology == geo::CircleCylinderTopology::crossing ? "crossing" : "no crossing",
              hit.crossing_count, hit.arc_count,
              std::string(geo::to_string(hit.certificate.level)).c_str());
  for (int k = 0; k < hit.crossing_count; ++k) {
    const geo::RimCrossing& x = hit.crossings[static_cast<std::size_t>(k)];
    std::printf("  angle %.15f rad (+- %.1e), point (%.9f, %.9f, %.9f) (+- %.1e m), multiplicity %d\n",
                x.angle, x.angle_error, x.point.x(), x.point.y(), x.point.z(), x.point_error,
                x.multiplicity);
  }
  for (int k = 0; k < hit.arc_count; ++k) {
    const geo::RimArc& arc = hit.penetration_arcs[static_cast<std::size_t>(k)];
    std::printf("  beyond the wall from %.6f to %.6f rad, deepest at %.6f\n", arc.begin, arc.end,
                arc.middle());
  }
  // The tilted rim leaves the wall on one side only: two simple crossings, one arc, proved.
  const bool ok = hit.topology == geo::CircleCylinderTopology::crossing && hit.crossing_count == 2 &&
                  hit.arc_count == 1 && hit.crossings[0].multiplicity == 1 &&
                  hit.certificate.level != geo::Certainty::uncertain;
  std::printf("%s\n", ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
