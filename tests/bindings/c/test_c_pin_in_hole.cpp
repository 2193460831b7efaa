// SPDX-License-Identifier: BSD-3-Clause
// Tests of the C API's pin-in-hole joint (cj_detect_pin_in_hole, cj_detect_pin_in_hole_many)
// against the C++ API it wraps: the same answers bit for bit for every shipped scenario, statuses
// and messages naming the field, reserved fields, the scenario names. The equivalence test
// (tests/bindings/equivalence) adds random poses and the other languages.

#include "clearjoint/clearjoint.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

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

/// The shipped examples that share the first one's joint (all but one, whose heads differ): the
/// poses of a batch over one joint, every scenario but one among them.
std::vector<clearjoint::testing::PinInHoleExample> examples_of_one_joint() {
  auto examples = clearjoint::testing::read_pin_in_hole_examples(CLEARJOINT_PIN_IN_HOLE_EXAMPLES);
  const geo::PinInHoleDimensions first = examples.front().dimensions;
  std::erase_if(examples, [&](const auto& e) {
    const geo::PinInHoleDimensions& d = e.dimensions;
    return d.hole_radius != first.hole_radius || d.hole_length != first.hole_length ||
           d.pin_radius != first.pin_radius || d.stop_count != first.stop_count ||
           d.stops[0].position != first.stops[0].position || d.stops[1].position != first.stops[1].position ||
           d.stops[0].outer_radius != first.stops[0].outer_radius ||
           d.stops[1].outer_radius != first.stops[1].outer_radius;
  });
  return examples;
}

/// Every byte a pin-in-hole answer sets (the contacts past contact_count are left as they were).
void expect_same_bytes(const cj_pin_in_hole_result& a, const cj_pin_in_hole_result& b) {
  EXPECT_EQ(a.scenario, b.scenario);
  EXPECT_EQ(a.aligned, b.aligned);
  ASSERT_EQ(a.contact_count, b.contact_count);
  EXPECT_EQ(std::memcmp(&a.certificate, &b.certificate, sizeof(cj_certificate)), 0);
  EXPECT_EQ(std::memcmp(a.contacts, b.contacts, sizeof(cj_contact) * a.contact_count), 0);
}

TEST(CPinInHole, DetectManyReadsEveryLayoutInPlaceAndAnswersAsSingleCalls) {
  const auto examples = examples_of_one_joint();
  // 10 of the 11 shipped examples share the joint; the floor keeps the batch meaningful.
  ASSERT_GE(examples.size(), 9u);
  const std::size_t n = examples.size();
  const cj_pin_in_hole_dimensions dims = c_dimensions(examples.front().dimensions);
  std::vector<cj_pose> holes, pins;
  std::vector<cj_pin_in_hole_result> expected(n);
  for (std::size_t k = 0; k < n; ++k) {
    holes.push_back(c_pose(examples[k].hole));
    pins.push_back(c_pose(examples[k].pin));
    ASSERT_EQ(cj_detect_pin_in_hole(&dims, &holes[k], &pins[k], nullptr, &expected[k], nullptr, 0), CJ_OK);
    // Against the C++ call too, so that the batch is compared with the kernel's answer.
    expect_same_answer(expected[k], geo::detect_pin_in_hole_contacts(examples[k].dimensions, examples[k].hole,
                                                                     examples[k].pin));
  }
  const auto expect_all = [&](const std::vector<cj_pin_in_hole_result>& got, const char* layout) {
    SCOPED_TRACE(layout);
    for (std::size_t k = 0; k < n; ++k) {
      SCOPED_TRACE(k);
      expect_same_bytes(got[k], expected[k]);
    }
  };

  // Row-major n x 6 (arrays of cj_pose), the processed count on success.
  const cj_pose_array hole_rows = cj_pose_array_rows(holes.front().p_WP);
  const cj_pose_array pin_rows = cj_pose_array_rows(pins.front().p_WP);
  std::vector<cj_pin_in_hole_result> rows(n);
  std::size_t processed = 0;
  char message[256] = "stale";
  ASSERT_EQ(cj_detect_pin_in_hole_many(&dims, &hole_rows, &pin_rows, n, nullptr, rows.data(), &processed, message,
                                       sizeof message),
            CJ_OK)
      << message;
  EXPECT_EQ(processed, n);
  EXPECT_STREQ(message, "");
  expect_all(rows, "rows");

  // Column-major pins (MATLAB, Fortran) against one hole repeated (stride 0).
  std::vector<double> columns(6 * n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int c = 0; c < 6; ++c) columns[k + c * n] = c < 3 ? pins[k].p_WP[c] : pins[k].axis_W[c - 3];
  }
  const cj_pose_array one_hole = cj_pose_array_repeat(&holes.front());
  const cj_pose_array pin_columns = cj_pose_array_columns(columns.data(), n);
  std::vector<cj_pin_in_hole_result> by_columns(n);
  ASSERT_EQ(cj_detect_pin_in_hole_many(&dims, &one_hole, &pin_columns, n, nullptr, by_columns.data(), nullptr,
                                       nullptr, 0),
            CJ_OK);
  expect_all(by_columns, "columns");

  // Options reach the kernel: certificates off, every answer the single call's with them off.
  cj_options off = cj_default_options();
  off.certify = 0;
  std::vector<cj_pin_in_hole_result> uncertain(n);
  ASSERT_EQ(cj_detect_pin_in_hole_many(&dims, &hole_rows, &pin_rows, n, &off, uncertain.data(), nullptr, nullptr, 0),
            CJ_OK);
  for (std::size_t k = 0; k < n; ++k) {
    cj_pin_in_hole_result single{};  // zeroed as the batch's results are: unused slots compare equal
    ASSERT_EQ(cj_detect_pin_in_hole(&dims, &holes[k], &pins[k], &off, &single, nullptr, 0), CJ_OK);
    EXPECT_EQ(uncertain[k].certificate.level, CJ_CERTAINTY_UNCERTAIN);
    expect_same_bytes(uncertain[k], single);
  }
}

TEST(CPinInHole, DetectManyStopsAtTheFirstBadPoseAndNamesIt) {
  const cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  std::vector<cj_pose> pins(5, cj_pose{{0, 0, 0}, {0, 0.0125, 1}});
  pins[3].axis_W[0] = pins[3].axis_W[1] = pins[3].axis_W[2] = 0.0;
  const cj_pose_array holes = cj_pose_array_repeat(&kHole);
  const cj_pose_array rows = cj_pose_array_rows(pins.front().p_WP);
  std::vector<cj_pin_in_hole_result> results(pins.size());
  std::memset(results.data(), 0x5A, sizeof(cj_pin_in_hole_result) * results.size());
  std::size_t processed = 99;
  char message[256];
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &rows, pins.size(), nullptr, results.data(), &processed,
                                       message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(processed, 3u);
  EXPECT_STREQ(message, "poses[3]: pin.axis_W = [0, 0, 0]: must not be the zero vector");
  EXPECT_EQ(results[3].scenario, 0x5A5A5A5A);  // untouched from the failing pose on
  EXPECT_EQ(results[2].scenario, CJ_PIN_IN_HOLE_BOTH_EDGES_OPPOSITE);

  // A NaN in a pose is named with its pose and field.
  pins[3] = pins[0];
  pins[1].p_WP[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &rows, pins.size(), nullptr, results.data(), &processed,
                                       message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(processed, 1u);
  EXPECT_EQ(std::string(message).rfind("poses[1]: pin.p_WP = [0, 0, nan]", 0), 0u) << message;

  // Bad dimensions and options are not a pose's fault.
  cj_pin_in_hole_dimensions thick = dims;
  thick.pin_radius = 10.0;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&thick, &holes, &rows, 2, nullptr, results.data(), &processed, message,
                                       sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("dimensions.pin_radius = 10", 0), 0u) << message;
  EXPECT_EQ(processed, 0u);
  cj_options options = cj_default_options();
  options.parallel_angle_tolerance = -1.0;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &rows, 1, &options, results.data(), &processed, message,
                                       sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("options.parallel_angle_tolerance = -1", 0), 0u) << message;

  // NULL arrays and components are named.
  cj_pose_array broken = rows;
  broken.component[4] = nullptr;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &broken, 2, nullptr, results.data(), nullptr, message,
                                       sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_STREQ(message, "pins.component[4] = NULL: must point to the first pose's value");
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, nullptr, &rows, 2, nullptr, results.data(), nullptr, message,
                                       sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("holes = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &rows, 2, nullptr, nullptr, nullptr, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("results = NULL", 0), 0u) << message;
}

TEST(CPinInHole, DetectManyRefusesACountNoArrayCanHoldWithoutReadingAPose) {
  const cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  const cj_pose_array holes = cj_pose_array_repeat(&kHole);
  cj_pin_in_hole_result one;
  std::size_t processed = 99;
  char message[256];
  // (size_t)-1: a negative count converted, the usual way such a count arises.
  const std::size_t hostile = SIZE_MAX;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, &holes, &holes, hostile, nullptr, &one, &processed, message,
                                       sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("count = 18446744073709551615: more poses than an array of "
                                       "cj_pin_in_hole_result can hold", 0),
            0u)
      << message;
  EXPECT_EQ(processed, 0u);
}

TEST(CPinInHole, DetectManyOfNoPosesSucceedsWithoutReadingAnything) {
  const cj_pin_in_hole_dimensions dims = c_dimensions(joint());
  std::size_t processed = 7;
  EXPECT_EQ(cj_detect_pin_in_hole_many(&dims, nullptr, nullptr, 0, nullptr, nullptr, &processed, nullptr, 0), CJ_OK);
  EXPECT_EQ(processed, 0u);
}

}  // namespace
