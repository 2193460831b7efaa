// SPDX-License-Identifier: BSD-3-Clause
// Exits 0 only if the installed library answers a known query: a rim touching the wall from
// inside at one point (exact tangency, multiplicity 2).
#include <clearjoint/geometry/queries/intersect_circle_cylinder.hpp>

#include <cstdio>

int main() {
  using namespace clearjoint::geometry;
  const Circle3 rim{{1, 0, 0}, {0, 0, 1}, 1};
  const Cylinder3 wall{{0, 0, 0}, {0, 0, 1}, 2};
  const CircleCylinderIntersection hit = intersect_circle_cylinder(rim, wall);
  const bool ok = hit.crossing_count == 1 && hit.crossings[0].multiplicity == 2 &&
                  hit.certificate.level == Certainty::exact;
  std::printf("consumer: %d crossing(s), multiplicity %d, %s\n", hit.crossing_count,
              hit.crossings[0].multiplicity, ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
