// SPDX-License-Identifier: BSD-3-Clause
// detect_contacts under every power-of-two change of units: a joint whose lengths are all
// multiplied by 2^k is the same joint (the axes keep their direction, the base centres
// P +- (L/2) a_hat scale exactly), so its true contacts are the reference's times 2^k. At every
// exponent of double, the answer is either refused (a length outside the accepted range,
// InvalidInput naming it) or every certified bound encloses those true contacts. Before the range
// was checked, a scenario (a) pose scaled by 2^522 came back certified with depth 0 +- 1.25e141
// (true depth 4.03e152), and 25 of 1,120 scalings broke their bounds.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "tilted_journal_scenarios.hpp"

namespace clearjoint::geometry {
namespace {

using testing::bearing_on_z;
using testing::kMisalignedCases;
using testing::kTable2;

struct Joint {
  std::string name;
  JointDimensions dimensions;
  PartPose bearing, journal;
};

/// The twelve misaligned scenarios, the aligned line and face contacts, a rim beyond the model,
/// and the scenario (a) pose in metres with the bearing off the origin.
std::vector<Joint> joints() {
  std::vector<Joint> out;
  for (const auto& c : kMisalignedCases) out.push_back({c.name, c.dimensions, bearing_on_z(), c.journal.pose()});
  out.push_back({"aligned line", kTable2, bearing_on_z(), {{0.0, 0.15, 0.0}, {0.0, 0.0, 1.0}}});
  out.push_back({"aligned face", kTable2, bearing_on_z(), {{0.0, 0.0, 0.15}, {0.0, 0.0, 1.0}}});
  out.push_back({"beyond model", kTable2, bearing_on_z(), {{0.0, 0.5, 0.0}, {0.0, 0.005, 1.0}}});
  out.push_back({"metres, off the origin", {0.01, 0.02, 0.0099, 0.0198}, {{0.25, -0.5, 0.125}, {0.0, 0.0, 1.0}},
                 {{0.25, -0.5 + 8e-5, 0.125}, {0.0, 0.005, 1.0}}});
  return out;
}

double scaled(double x, int k) { return std::ldexp(x, k); }
Vector3 scaled(const Vector3& v, int k) { return {scaled(v.x(), k), scaled(v.y(), k), scaled(v.z(), k)}; }

Joint scaled(const Joint& joint, int k) {
  const JointDimensions& d = joint.dimensions;
  return {joint.name,
          {scaled(d.bearing_radius, k), scaled(d.bearing_length, k), scaled(d.journal_radius, k),
           scaled(d.journal_length, k)},
          {scaled(joint.bearing.p_WP, k), joint.bearing.axis_W},
          {scaled(joint.journal.p_WP, k), joint.journal.axis_W}};
}

/// Whether every length of the scaled joint is what the accepted range allows and is the exact
/// scaling of the original (no rounding into subnormals, no overflow).
bool accepted_exactly(const Joint& original, const Joint& joint, int k) {
  auto ok = [k](double before, double after, bool may_be_zero) {
    if (after == 0.0) return may_be_zero && before == 0.0;
    const double magnitude = std::fabs(after);
    return magnitude >= kSmallestAcceptedLength && magnitude <= kLargestAcceptedLength &&
           std::ldexp(after, -k) == before;
  };
  const JointDimensions &a = original.dimensions, &b = joint.dimensions;
  bool all = ok(a.bearing_radius, b.bearing_radius, false) && ok(a.bearing_length, b.bearing_length, false) &&
             ok(a.journal_radius, b.journal_radius, false) && ok(a.journal_length, b.journal_length, false);
  for (int i = 0; i < 3; ++i) {
    all = all && ok(original.bearing.p_WP[i], joint.bearing.p_WP[i], true) &&
          ok(original.journal.p_WP[i], joint.journal.p_WP[i], true);
  }
  return all;
}

/// Whether a length in range is rejected: a finite, non-zero scaled value outside the range, or an
/// overflow, or a value that rounded to 0 (then possibly rejected as a non-positive size).
bool has_length_outside_range(const Joint& joint) {
  auto outside = [](double x, bool may_be_zero) {
    if (x == 0.0) return !may_be_zero;
    const double magnitude = std::fabs(x);
    return !(magnitude >= kSmallestAcceptedLength && magnitude <= kLargestAcceptedLength);
  };
  const JointDimensions& d = joint.dimensions;
  bool any = outside(d.bearing_radius, false) || outside(d.bearing_length, false) ||
             outside(d.journal_radius, false) || outside(d.journal_length, false);
  for (int i = 0; i < 3; ++i) any = any || outside(joint.bearing.p_WP[i], true) || outside(joint.journal.p_WP[i], true);
  return any;
}

/// The rounding of the check itself: |a - b| and a + b are each rounded once (relative u), and the
/// Euclidean norm a few times more. 16 u covers both with room.
constexpr double kCheckRounding = 16 * std::numeric_limits<double>::epsilon();

/// Two enclosures of one true value (reference times 2^k, and the scaled answer) must overlap.
bool overlap(double value, double error, double reference, double reference_error, int k) {
  const double gap = std::fabs(value - scaled(reference, k));
  return gap <= (error + scaled(reference_error, k)) * (1 + kCheckRounding);
}
bool overlap(const Vector3& value, double error, const Vector3& reference, double reference_error, int k) {
  const double gap = (value - scaled(reference, k)).norm();
  return gap <= (error + scaled(reference_error, k)) * (1 + kCheckRounding);
}

bool proved(const Certificate& c) { return c.level != Certainty::uncertain; }

TEST(DetectContactsScaling, EveryPowerOfTwoOfEveryJointIsRefusedOrHoldsItsCertificates) {
  int refused = 0, answered = 0, compared_contacts = 0;
  for (const Joint& joint : joints()) {
    SCOPED_TRACE(joint.name);
    const JointContacts reference = detect_contacts(joint.dimensions, joint.bearing, joint.journal);
    ASSERT_TRUE(proved(reference.certificate)) << "the unscaled reference must be certified";
    for (int k = std::numeric_limits<double>::min_exponent - std::numeric_limits<double>::digits;
         k <= std::numeric_limits<double>::max_exponent; ++k) {
      SCOPED_TRACE("2^" + std::to_string(k));
      const Joint s = scaled(joint, k);
      if (has_length_outside_range(s)) {
        EXPECT_THROW(detect_contacts(s.dimensions, s.bearing, s.journal), InvalidInput);
        ++refused;
        continue;
      }
      ASSERT_TRUE(accepted_exactly(joint, s, k)) << "in range yet not an exact scaling";
      const JointContacts answer = detect_contacts(s.dimensions, s.bearing, s.journal);
      ++answered;
      if (!proved(answer.certificate)) continue;
      EXPECT_EQ(answer.scenario, reference.scenario);
      ASSERT_EQ(answer.contact_count, reference.contact_count);
      for (int i = 0; i < answer.contact_count; ++i) {
        const Contact& c = answer.contacts[i];
        const Contact& r = reference.contacts[i];
        if (!proved(c.certificate)) continue;
        ASSERT_TRUE(proved(r.certificate));
        EXPECT_EQ(c.type, r.type) << i;
        EXPECT_EQ(c.base, r.base) << i;
        EXPECT_TRUE(overlap(c.depth, c.depth_error, r.depth, r.depth_error, k))
            << i << ": depth " << c.depth << " +- " << c.depth_error << ", reference " << r.depth << " +- "
            << r.depth_error;
        EXPECT_TRUE(overlap(c.p_WCj, c.p_WCj_error, r.p_WCj, r.p_WCj_error, k)) << i;
        EXPECT_TRUE(overlap(c.p_WCi, c.p_WCi_error, r.p_WCi, r.p_WCi_error, k)) << i;
        EXPECT_LE((c.normal_W - r.normal_W).norm(), 1e-12) << i;
        ++compared_contacts;
      }
    }
  }
  // Each joint has about 1000 accepted exponents and 1100 refused ones; a sweep that answered
  // nothing, or compared no contact, would prove nothing.
  EXPECT_GT(refused, 10000);
  EXPECT_GT(answered, 10000);
  EXPECT_GT(compared_contacts, 10000);
}

TEST(DetectContactsScaling, AnswersAreCertifiedAtEveryAcceptedExponent) {
  // Inside the accepted range the floating-point tiers see the same numbers up to a power of two:
  // no answer may lose its certificate to a change of units.
  for (const Joint& joint : joints()) {
    SCOPED_TRACE(joint.name);
    for (int k = -1074; k <= 1023; ++k) {
      const Joint s = scaled(joint, k);
      if (has_length_outside_range(s)) continue;
      const JointContacts answer = detect_contacts(s.dimensions, s.bearing, s.journal);
      EXPECT_TRUE(proved(answer.certificate)) << "2^" << k << ": " << answer.certificate.reason_text();
    }
  }
}

TEST(DetectContactsScaling, NamesTheFieldAndTheRangeOfALengthOutsideIt) {
  const double f = std::ldexp(1.0, 522);
  const JointDimensions d{0.01 * f, 0.02 * f, 0.0099 * f, 0.0198 * f};
  try {
    detect_contacts(d, PartPose{}, PartPose{{0.0, 8e-5 * f, 0.0}, {0.0, 0.005, 1.0}});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("dimensions.bearing_radius = 1.372959532026122e+155: ", 0), 0u) << message;
    EXPECT_NE(message.find("a magnitude outside [1e-150, 1e150], the range of lengths accepted"), std::string::npos)
        << message;
  }
  try {
    detect_contacts(kTable2, PartPose{}, PartPose{{0.0, 1e-160, 0.0}, {0.0, 0.0, 1.0}});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(std::string(error.what()).rfind("journal.p_WP = [0, 1e-160, 0]: a magnitude outside", 0),
              0u)
        << error.what();
  }
  // Zero coordinates and the range's own ends are accepted.
  EXPECT_NO_THROW(detect_contacts({1e150, 1e150, 0.5e150, 0.5e150}, PartPose{{0.0, 0.0, 1e-150}, {0, 0, 1}},
                                  PartPose{{1e-150, 0.0, 0.0}, {0, 0, 1}}));
}

}  // namespace
}  // namespace clearjoint::geometry
