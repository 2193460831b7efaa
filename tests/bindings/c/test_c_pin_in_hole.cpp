// SPDX-License-Identifier: BSD-3-Clause
// Tests of the C API's pin-in-hole joint (cj_detect_pin_in_hole) against the C++ API it wraps:
// the same answers bit for bit for every shipped scenario, statuses and messages naming the
// field, reserved fields, the scenario names. The equivalence test
// (tests/bindings/equivalence) adds random poses and the other languages.

#include "clearjoint/clearjoint.h"

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "pin_in_hole_examples.hpp"

namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

cj_pose c_pose(const geo::PartPose& p) {
  return {{p.p_WP.x(), p.p_WP.y(), p.p_WP.z()}, {p.axis_W.x(), p.axis_W.y(), p.axis_W.z()}};
}

cj_pin_in_hole_dimensions c_dimensions(const geo::PinInHoleDimensions& d) {
  cj_pin_in_hole_dimensions out{};
  out.hole_radius = d.hole_radius;
  out.hole_length = d.hole_length;
  out.pin_radius = d.pin_radius;
  out.stop_count = d.stop_count;
  for (int k = 0; k < d.stop_count; ++k) out.stops[k] = {d.stops[k].position, d.stops[k].outer_radius};
  return out;
}

/// Hole radius 10, length 20, pin radius 9.9, heads at -10.5 and +10.5 of outer radius 16.
geo::PinInHoleDimensions joint() {
  geo::PinInHoleDimensions d;
  d.hole_radius = 10.0;
  d.hole_length = 20.0;
  d.pin_radius = 9.9;
  d.stops[0] = {-10.5, 16.0};
  d.stops[1] = {10.5, 16.0};
  d.stop_count = 2;
  return d;
}

const cj_pose kHole{{0, 0, 0}, {0, 0, 1}};

void expect_same_vector(const double (&c)[3], const Vector3& cpp) {
  EXPECT_EQ(c[0], cpp.x());
  EXPECT_EQ(c[1], cpp.y());
  EXPECT_EQ(c[2], cpp.z());
}

/// The C result says what the C++ one says, every double compared exactly.
void expect_same_answer(const cj_pin_in_hole_result& c, const geo::PinInHoleContacts& cpp) {
  EXPECT_STREQ(cj_pin_in_hole_scenario_string(c.scenario), geo::to_string(cpp.scenario).data());
  EXPECT_EQ(c.aligned != 0, cpp.aligned);
  EXPECT_STREQ(cj_certainty_string(c.certificate.level), geo::to_string(cpp.certificate.level).data());
  EXPECT_STREQ(c.certificate.reason_text, cpp.certificate.reason_text().data());
  ASSERT_EQ(c.contact_count, cpp.contact_count);
  for (int k = 0; k < c.contact_count; ++k) {
    const cj_contact& x = c.contacts[k];
    const geo::Contact& y = cpp.contacts[k];
    EXPECT_STREQ(cj_contact_type_string(x.type), geo::to_string(y.type).data());
    EXPECT_STREQ(cj_base_string(x.base), geo::to_string(y.base).data());
    EXPECT_EQ(x.depth, y.depth);
    EXPECT_EQ(x.depth_error_bound, y.depth_error);
    EXPECT_EQ(x.p_WCj_error_bound, y.p_WCj_error);
    EXPECT_EQ(x.p_WCi_error_bound, y.p_WCi_error);
    expect_same_vector(x.p_WCj, y.p_WCj);
    expect_same_vector(x.p_WCi, y.p_WCi);
    expect_same_vector(x.normal_W, y.normal_W);
    ASSERT_EQ(x.crossing_count, y.crossing_count);
    for (int m = 0; m < x.crossing_count; ++m) {
      EXPECT_EQ(x.crossings[m].angle, y.crossings[m].angle);
      EXPECT_EQ(x.crossings[m].angle_error_bound, y.crossings[m].angle_error);
      expect_same_vector(x.crossings[m].point, y.crossings[m].point);
      EXPECT_EQ(x.crossings[m].point_error_bound, y.crossings[m].point_error);
      EXPECT_EQ(x.crossings[m].multiplicity, y.crossings[m].multiplicity);
    }
    EXPECT_STREQ(x.certificate.reason_text, y.certificate.reason_text().data());
  }
}

TEST(CPinInHole, GivesTheCppAnswerForEveryShippedScenario) {
  const auto examples = clearjoint::testing::read_pin_in_hole_examples(CLEARJOINT_PIN_IN_HOLE_EXAMPLES);
  ASSERT_EQ(examples.size(), static_cast<std::size_t>(geo::enum_count<geo::PinInHoleScenario>()));
  for (const auto& example : examples) {
    const cj_pin_in_hole_dimensions dims = c_dimensions(example.dimensions);
    const cj_pose hole = c_pose(example.hole), pin = c_pose(example.pin);
    cj_pin_in_hole_result result;
    char message[256] = "stale";
    ASSERT_EQ(cj_detect_pin_in_hole(&dims, &hole, &pin, nullptr, &result, message, sizeof message), CJ_OK)
        << example.id << ": " << message;
    EXPECT_STREQ(message, "");
    const geo::PinInHoleContacts cpp = geo::detect_pin_in_hole_contacts(example.dimensions, example.hole, example.pin);
    expect_same_answer(result, cpp);
    EXPECT_EQ("pin-" + std::string(cj_pin_in_hole_scenario_string(result.scenario)), example.id);
  }
}

TEST(CPinInHole, PassesItsOptionsToTheKernel) {
  // A pin tilted about the hole's centre, certificates off: both edges, uncertain.
  const cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  const cj_pose pin{{0, 0, 0}, {0, 0.0125, 1}};
  cj_options options = cj_default_options();
  options.certify = 0;
  cj_pin_in_hole_result result;
  ASSERT_EQ(cj_detect_pin_in_hole(&dims, &kHole, &pin, &options, &result, nullptr, 0), CJ_OK);
  EXPECT_EQ(result.scenario, CJ_PIN_IN_HOLE_BOTH_EDGES_OPPOSITE);
  EXPECT_EQ(result.certificate.level, CJ_CERTAINTY_UNCERTAIN);
  EXPECT_EQ(result.certificate.reason, CJ_REASON_CERTIFICATE_SWITCHED_OFF);
  geo::DetectionOptions cpp_options;
  cpp_options.intersection.certify = false;
  expect_same_answer(result, geo::detect_pin_in_hole_contacts(joint(), {Vector3::Zero(), Vector3::UnitZ()},
                                                              {Vector3::Zero(), Vector3(0, 0.0125, 1)}, cpp_options));
}

TEST(CPinInHole, RejectsABadFieldNamingItAndLeavesTheResultUntouched) {
  cj_pin_in_hole_result result;
  std::memset(&result, 0x5A, sizeof result);
  cj_pin_in_hole_result before;
  std::memcpy(&before, &result, sizeof result);
  char message[256];
  const auto rejects = [&](const cj_pin_in_hole_dimensions& dims, const cj_pose& pin, const char* expected) {
    EXPECT_EQ(cj_detect_pin_in_hole(&dims, &kHole, &pin, nullptr, &result, message, sizeof message),
              CJ_INVALID_INPUT);
    EXPECT_NE(std::string(message).find(expected), std::string::npos) << message;
    EXPECT_EQ(std::memcmp(&result, &before, sizeof result), 0) << expected;
  };
  const cj_pose centred{{0, 0, 0}, {0, 0, 1}};
  cj_pin_in_hole_dimensions thick = c_dimensions(joint());
  thick.pin_radius = 10.0;
  rejects(thick, centred, "dimensions.pin_radius = 10");
  cj_pin_in_hole_dimensions inside = c_dimensions(joint());
  inside.stops[1].position = 5.0;
  rejects(inside, centred, "dimensions.stops[1].position = 5");
  cj_pin_in_hole_dimensions count = c_dimensions(joint());
  count.stop_count = 3;
  rejects(count, centred, "dimensions.stop_count = 3");
  rejects(c_dimensions(joint()), cj_pose{{0, 0, 0}, {0, 0, 0}}, "pin.axis_W = [0, 0, 0]");
  cj_pin_in_hole_dimensions later = c_dimensions(joint());
  later.reserved[2] = 1.0;
  rejects(later, centred, "dimensions.reserved[2] = 1: must be 0");
  later = c_dimensions(joint());
  later.reserved0 = 7;
  rejects(later, centred, "dimensions.reserved0 = 7: must be 0");
}

TEST(CPinInHole, RejectsNullPointersByName) {
  const cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  cj_pin_in_hole_result result;
  char message[256];
  EXPECT_EQ(cj_detect_pin_in_hole(nullptr, &kHole, &kHole, nullptr, &result, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("dimensions = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect_pin_in_hole(&dims, nullptr, &kHole, nullptr, &result, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("hole = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect_pin_in_hole(&dims, &kHole, nullptr, nullptr, &result, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("pin = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect_pin_in_hole(&dims, &kHole, &kHole, nullptr, nullptr, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("result = NULL", 0), 0u) << message;
}

TEST(CPinInHole, AFreeSlidingPinNeedsNoStops) {
  cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  dims.stop_count = 0;
  const cj_pose pushed{{0, 0, 50.0}, {0, 0, 1}};
  cj_pin_in_hole_result result;
  ASSERT_EQ(cj_detect_pin_in_hole(&dims, &kHole, &pushed, nullptr, &result, nullptr, 0), CJ_OK);
  EXPECT_EQ(result.scenario, CJ_PIN_IN_HOLE_NONE);
  EXPECT_EQ(result.contact_count, 0);
}

}  // namespace
