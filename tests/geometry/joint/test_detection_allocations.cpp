// SPDX-License-Identifier: BSD-3-Clause
// Heap allocations of a detection (issue: "no heap allocation in a detection that does not reach
// the exact tier"). A simulation detects at every evaluation of its right-hand side, so an
// allocation there is paid hundreds of thousands of times per simulated second. Every heap
// allocation of this program is counted (support/testing/heap_allocation_counter.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "heap_allocation_counter.hpp"
#include "tilted_journal_scenarios.hpp"

namespace clearjoint::geometry {
namespace {

using testing::bearing_on_z;
using testing::kMisalignedCases;
using testing::kTable2;
using testing::TiltedJournal;

/// Table 2 journals (mm) around the bearing: centre offsets from well inside the clearance to
/// beyond it, in 16 directions, each axis tilted a little towards its offset and shifted along
/// the axis, so that free flight, radial, axial and mixed contacts all occur.
std::vector<PartPose> journals_around_the_bearing() {
  std::vector<PartPose> journals;
  const double cr = kTable2.radial_clearance();
  for (int direction = 0; direction < 16; ++direction) {
    const double angle = 0.39 * direction;
    for (const double eccentricity : {0.3, 0.9, 1.2, 1.6}) {
      for (const double axial : {0.0, 0.06, -0.12}) {
        const Vector3 offset(eccentricity * cr * std::cos(angle), eccentricity * cr * std::sin(angle), axial);
        const Vector3 axis = Vector3(0.004 * std::cos(angle + 0.3), 0.004 * std::sin(angle + 0.3), 1.0).normalized();
        journals.push_back({offset, axis});
      }
    }
  }
  for (const auto& scenario : kMisalignedCases) journals.push_back(scenario.journal.pose());
  return journals;
}

struct Counted {
  long allocations = 0;
  int detections = 0;   ///< those decided in floating point, which were counted
  int in_contact = 0;   ///< of those, with at least one contact
};

/// Heap allocations of both detect_contacts overloads on each pose whose answer is not exact
/// (the floating-point tiers decided it); the first call of each is made before counting.
Counted count_floating_point_detections(const std::vector<PartPose>& journals) {
  const PartPose bearing = bearing_on_z();
  JointContacts reused = detect_contacts(kTable2, bearing, journals.front());
  Counted counted;
  for (const PartPose& journal : journals) {
    const long before = clearjoint::testing::heap_allocations();
    const JointContacts fresh = detect_contacts(kTable2, bearing, journal);
    detect_contacts(kTable2, bearing, journal, reused);
    const long allocated = clearjoint::testing::heap_allocations() - before;
    if (fresh.certificate.level == Certainty::exact) continue;
    counted.allocations += allocated;
    ++counted.detections;
    counted.in_contact += fresh.contact_count > 0;
  }
  return counted;
}

TEST(DetectionAllocations, ADetectionDecidedInFloatingPointAllocatesNothing) {
  ASSERT_TRUE(clearjoint::testing::heap_allocations_are_counted()) << "this program's allocations are not counted";
  const std::vector<PartPose> journals = journals_around_the_bearing();
  const Counted counted = count_floating_point_detections(journals);
  // Nearly every pose is decided in floating point, and both free flight and contact occur.
  EXPECT_GT(counted.detections, static_cast<int>(journals.size()) * 9 / 10);
  EXPECT_GT(counted.in_contact, 50);
  EXPECT_LT(counted.in_contact, counted.detections);
  EXPECT_EQ(counted.allocations, 0);
}

TEST(DetectionAllocations, AnExactTangencyOfARimWithAPlaneAllocatesNothing) {
  // Rims that touch their plane exactly, which only the exact tier decides: the vertical unit
  // rim on the ground, and the paper's Table 2 in micrometres (a base tilted by
  // atan(199 / 19800), the journal rim 0.5 um off nominal: 19800 (9900.5 - 10000) + 199 9900 = 0).
  const Plane3 ground{{0, 0, 0}, {0, 0, 1}};
  const Circle3 unit_rim{{0, 0, 1}, {1, 0, 0}, 1};
  const Plane3 tilted_base{{0, 0, 10000}, {0, 199, 19800}};
  const Circle3 table2_rim{{0, 0, 9900.5}, {0, 0, 1}, 9900};
  (void)intersect_circle_plane(unit_rim, ground);
  for (const auto& [rim, plane] : {std::pair{unit_rim, ground}, std::pair{table2_rim, tilted_base}}) {
    const long before = clearjoint::testing::heap_allocations();
    const CirclePlaneIntersection answer = intersect_circle_plane(rim, plane);
    const long allocated = clearjoint::testing::heap_allocations() - before;
    EXPECT_EQ(answer.topology, CirclePlaneTopology::tangent);
    EXPECT_EQ(answer.certificate.level, Certainty::exact);
    EXPECT_EQ(allocated, 0);
  }
}

TEST(DetectionAllocations, CountsAllocationsWhenThereAreSome) {
  EXPECT_TRUE(clearjoint::testing::heap_allocations_are_counted());
}

}  // namespace
}  // namespace clearjoint::geometry
