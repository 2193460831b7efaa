// SPDX-License-Identifier: BSD-3-Clause
// Contact::p_WCj_error, p_WCi_error and depth_error against the MPFR reference of the joint as
// given (joint_reference.hpp): on every input family, every certified or exact contact's points
// and depth lie within their bounds of the reference's.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "input_families.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {
namespace {

using geometry::Certainty;
using geometry::Contact;
using geometry::JointContacts;

struct Tally {
  int contacts_checked = 0;
  int bounded_points = 0;
};

void check_family(const std::string& family, Tally& tally) {
  for (const DetectionInput& input : generate_family(family, SuiteSize::quick)) {
    const JointContacts found = geometry::detect_contacts(input.dimensions, input.bearing, input.journal);
    const ReferenceAnswer truth = reference_detect(joint_as_given(input.dimensions, input.bearing, input.journal));
    if (!truth.decided || static_cast<int>(truth.contacts.size()) != found.contact_count) continue;
    for (int i = 0; i < found.contact_count; ++i) {
      const Contact& contact = found.contacts[i];
      const ReferenceContact& reference = truth.contacts[static_cast<std::size_t>(i)];
      if (contact.certificate.level == Certainty::uncertain) {
        EXPECT_EQ(contact.depth_error, geometry::kNoErrorBound) << input.id;
        continue;
      }
      if (contact.type != reference.type || contact.base != reference.base || !reference.points_defined) continue;
      SCOPED_TRACE(input.id + ", contact " + std::to_string(i));
      ++tally.contacts_checked;
      const double journal_miss = static_cast<double>(distance(contact.p_WCj, reference.p_WCj));
      const double bearing_miss = static_cast<double>(distance(contact.p_WCi, reference.p_WCi));
      const double depth_miss = static_cast<double>(abs(Real(contact.depth) - reference.depth));
      EXPECT_LE(journal_miss, contact.p_WCj_error);
      EXPECT_LE(bearing_miss, contact.p_WCi_error);
      EXPECT_LE(depth_miss, contact.depth_error);
      // A bound no tighter than the joint's size would pass trivially: count the informative ones.
      if (contact.p_WCj_error < 1e-6 * input.dimensions.bearing_radius) ++tally.bounded_points;
    }
  }
}

TEST(ContactErrorBounds, EnclosePointsAndDepthOfTheReferenceOnEveryFamily) {
  Tally tally;
  for (const FamilySpec& spec : family_specs()) {
    SCOPED_TRACE(spec.name);
    check_family(spec.name, tally);
  }
  // The quick families hold a few thousand contacts; nearly all of their points are known to far
  // better than a micro-radius. These floors keep the test from passing on an empty run.
  EXPECT_GT(tally.contacts_checked, 500);
  EXPECT_GT(tally.bounded_points, tally.contacts_checked * 9 / 10);
}

}  // namespace
}  // namespace clearjoint::bench
