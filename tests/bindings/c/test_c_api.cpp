// SPDX-License-Identifier: BSD-3-Clause
// Tests of the C API (clearjoint.h) against the C++ API it wraps: the same answers bit for bit,
// statuses and messages naming the field, the batch call's layouts, enum names, the kernel
// queries. The equivalence test (tests/bindings/equivalence) adds 10,000 random poses and the
// other languages.

#include "clearjoint/clearjoint.h"

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/version.hpp"
#include "tilted_journal_scenarios.hpp"

namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

cj_dimensions c_dimensions(const geo::JointDimensions& d) {
  return {d.bearing_radius, d.bearing_length, d.journal_radius, d.journal_length};
}

cj_pose c_pose(const geo::PartPose& p) {
  return {{p.p_WP.x(), p.p_WP.y(), p.p_WP.z()}, {p.axis_W.x(), p.axis_W.y(), p.axis_W.z()}};
}

struct Case {
  geo::JointDimensions dims;
  geo::PartPose journal;
};

/// Every scenario of Fig. 2 plus none and beyond the model (the detection tests' cases).
std::vector<Case> scenario_cases() {
  using namespace geo::testing;
  std::vector<Case> cases;
  for (const ScenarioCase& c : kMisalignedCases) cases.push_back({c.dimensions, c.journal.pose()});
  for (const Vector3& centre : {Vector3(0.01, 0.02, 0.03), Vector3(0.0, 0.15, 0.02), Vector3(0.03, 0.04, 0.13),
                                Vector3(0.0, 0.25, 0.0)}) {
    cases.push_back({kTable2, {centre, Vector3::UnitZ()}});
  }
  cases.push_back({kTable2, {Vector3(0.0, 0.15, -0.13), -Vector3::UnitZ()}});
  cases.push_back({kTable2, TiltedJournal{0.0, 0.5, 0.005}.pose()});
  return cases;
}

void expect_same_vector(const double (&c)[3], const Vector3& cpp) {
  EXPECT_EQ(c[0], cpp.x());
  EXPECT_EQ(c[1], cpp.y());
  EXPECT_EQ(c[2], cpp.z());
}

void expect_same_crossing(const cj_crossing& c, const geo::RimCrossing& cpp) {
  EXPECT_EQ(c.angle, cpp.angle);
  EXPECT_EQ(c.angle_error_bound, cpp.angle_error);
  expect_same_vector(c.point, cpp.point);
  EXPECT_EQ(c.point_error_bound, cpp.point_error);
  EXPECT_EQ(c.multiplicity, cpp.multiplicity);
}

/// The C result says what the C++ one says, every double compared exactly.
void expect_same_answer(const cj_result& c, const geo::JointContacts& cpp) {
  EXPECT_STREQ(cj_scenario_string(c.scenario), geo::to_string(cpp.scenario).data());
  EXPECT_EQ(c.aligned != 0, cpp.aligned);
  EXPECT_STREQ(cj_certainty_string(c.certificate.level), geo::to_string(cpp.certificate.level).data());
  EXPECT_STREQ(c.certificate.reason_text, cpp.certificate.reason_text().data());
  EXPECT_STREQ(cj_reason_string(c.certificate.reason), cpp.certificate.reason_text().data());
  ASSERT_EQ(c.contact_count, cpp.contact_count);
  for (int k = 0; k < c.contact_count; ++k) {
    const cj_contact& x = c.contacts[k];
    const geo::Contact& y = cpp.contacts[k];
    EXPECT_EQ(x.type, y.type == geo::ContactType::radial ? CJ_CONTACT_RADIAL : CJ_CONTACT_AXIAL);
    EXPECT_EQ(x.base, y.base == geo::ContactBase::a ? CJ_BASE_A : y.base == geo::ContactBase::b ? CJ_BASE_B : CJ_BASE_MID);
    EXPECT_EQ(x.depth, y.depth);
    EXPECT_EQ(x.depth_error_bound, y.depth_error);
    EXPECT_EQ(x.p_WCj_error_bound, y.p_WCj_error);
    EXPECT_EQ(x.p_WCi_error_bound, y.p_WCi_error);
    expect_same_vector(x.p_WCj, y.p_WCj);
    expect_same_vector(x.p_WCi, y.p_WCi);
    expect_same_vector(x.normal_W, y.normal_W);
    ASSERT_EQ(x.crossing_count, y.crossing_count);
    for (int m = 0; m < x.crossing_count; ++m) expect_same_crossing(x.crossings[m], y.crossings[m]);
    EXPECT_STREQ(cj_certainty_string(x.certificate.level), geo::to_string(y.certificate.level).data());
  }
}

const cj_pose kBearing{{0, 0, 0}, {0, 0, 1}};

TEST(CApi, ReportsTheVersionOfTheLinkedLibraryAndItsAbi) {
  EXPECT_STREQ(cj_version(), CLEARJOINT_VERSION_STRING);
  EXPECT_EQ(cj_abi_version(), CJ_ABI_VERSION);
}

TEST(CApi, GivesTheCppAnswerForEveryScenario) {
  char message[256] = "stale";
  for (const Case& c : scenario_cases()) {
    const cj_dimensions dims = c_dimensions(c.dims);
    const cj_pose journal = c_pose(c.journal);
    cj_result result;
    ASSERT_EQ(cj_detect(&dims, &kBearing, &journal, nullptr, &result, message, sizeof message), CJ_OK);
    EXPECT_STREQ(message, "");  // cleared on success
    expect_same_answer(result, geo::detect_contacts(c.dims, {Vector3::Zero(), Vector3::UnitZ()}, c.journal));
  }
}

TEST(CApi, PassesItsOptionsToTheKernel) {
  // Nearly parallel axes: (c) exactly, a line contact marked uncertain under a 1e-5 rad tolerance;
  // certificates off: the same contacts, uncertain.
  const geo::PartPose nearly = geo::testing::TiltedJournal{0.15, 0.0, 1e-6}.pose();
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose journal = c_pose(nearly);
  cj_options options = cj_default_options();
  options.parallel_angle_tolerance = 1e-5;
  cj_result relaxed, uncertified;
  ASSERT_EQ(cj_detect(&dims, &kBearing, &journal, &options, &relaxed, nullptr, 0), CJ_OK);
  EXPECT_EQ(relaxed.scenario, CJ_SCENARIO_LINE);
  EXPECT_EQ(relaxed.certificate.level, CJ_CERTAINTY_UNCERTAIN);
  EXPECT_EQ(relaxed.certificate.reason, CJ_REASON_AXES_PARALLEL_WITHIN_TOLERANCE);
  EXPECT_STRNE(relaxed.certificate.reason_text, "");
  options = cj_default_options();
  options.certify = 0;
  ASSERT_EQ(cj_detect(&dims, &kBearing, &journal, &options, &uncertified, nullptr, 0), CJ_OK);
  EXPECT_EQ(uncertified.scenario, CJ_SCENARIO_RADIAL_AT_BOTH_BASES);
  EXPECT_EQ(uncertified.certificate.level, CJ_CERTAINTY_UNCERTAIN);
  EXPECT_EQ(uncertified.certificate.reason, CJ_REASON_CERTIFICATE_SWITCHED_OFF);
  EXPECT_STREQ(uncertified.certificate.reason_text, "certificate switched off");
  geo::DetectionOptions cpp_options;
  cpp_options.intersection.certify = false;
  expect_same_answer(uncertified, geo::detect_contacts(geo::testing::kTable2, {Vector3::Zero(), Vector3::UnitZ()},
                                                      nearly, cpp_options));
}

TEST(CApi, RejectsABadFieldNamingItAndLeavesTheResultUntouched) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose journal{{0, 0, 0}, {0, 0, 0}};
  cj_result result;
  std::memset(&result, 0x5A, sizeof result);
  cj_result before;
  std::memcpy(&before, &result, sizeof result);
  char message[256];
  EXPECT_EQ(cj_detect(&dims, &kBearing, &journal, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_STREQ(message, "journal.axis_W = [0, 0, 0]: must not be the zero vector");
  EXPECT_EQ(std::memcmp(&result, &before, sizeof result), 0);
  const cj_dimensions swapped{9.9, 20.0, 10.0, 19.8};
  const cj_pose centred{{0, 0, 0}, {0, 0, 1}};
  EXPECT_EQ(cj_detect(&swapped, &kBearing, &centred, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_NE(std::string(message).find("dimensions.journal_radius = 10"), std::string::npos) << message;
  cj_options options = cj_default_options();
  options.parallel_angle_tolerance = -1.0;
  EXPECT_EQ(cj_detect(&dims, &kBearing, &centred, &options, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_NE(std::string(message).find("options.parallel_angle_tolerance = -1"), std::string::npos) << message;
}

TEST(CApi, RejectsNullPointersByName) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  cj_result result;
  char message[256];
  EXPECT_EQ(cj_detect(nullptr, &kBearing, &kBearing, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("dimensions = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect(&dims, &kBearing, nullptr, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("journal = NULL", 0), 0u) << message;
  EXPECT_EQ(cj_detect(&dims, &kBearing, &kBearing, nullptr, nullptr, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("result = NULL", 0), 0u) << message;
}

TEST(CApi, TruncatesTheMessageToTheCallersBufferAndAcceptsNone) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose journal{{0, 0, 0}, {0, 0, 0}};
  cj_result result;
  char message[11];
  std::memset(message, 'x', sizeof message);
  EXPECT_EQ(cj_detect(&dims, &kBearing, &journal, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_STREQ(message, "journal.ax");
  EXPECT_EQ(cj_detect(&dims, &kBearing, &journal, nullptr, &result, nullptr, 0), CJ_INVALID_INPUT);
}

TEST(CApi, RejectsANonzeroReservedOptionFieldAsAFieldOfALaterVersion) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  cj_options options = cj_default_options();
  options.reserved[2] = 1.0;
  cj_result result;
  char message[256];
  EXPECT_EQ(cj_detect(&dims, &kBearing, &kBearing, &options, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("options.reserved[2] = 1: must be 0", 0), 0u) << message;
}

TEST(CApi, DefaultOptionsAreTheCppDefaults) {
  const cj_options options = cj_default_options();
  const geo::DetectionOptions cpp;
  EXPECT_EQ(options.certify != 0, cpp.intersection.certify);
  EXPECT_EQ(options.exact_fallback != 0, cpp.intersection.exact_fallback);
  EXPECT_EQ(options.parallel_angle_tolerance, cpp.parallel_angle_tolerance);
  for (double r : options.reserved) EXPECT_EQ(r, 0.0);
}

/// The scenario cases' journals as poses, with the Table 2 joint (the batch shares dimensions).
std::vector<cj_pose> table2_journals() {
  std::vector<cj_pose> out;
  for (const Case& c : scenario_cases()) {
    if (c.dims.journal_length == geo::testing::kTable2.journal_length &&
        c.dims.journal_radius == geo::testing::kTable2.journal_radius) {
      out.push_back(c_pose(c.journal));
    }
  }
  return out;
}

std::vector<cj_result> one_by_one(const std::vector<cj_pose>& journals) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  std::vector<cj_result> out(journals.size());
  for (std::size_t k = 0; k < journals.size(); ++k) {
    EXPECT_EQ(cj_detect(&dims, &kBearing, &journals[k], nullptr, &out[k], nullptr, 0), CJ_OK);
  }
  return out;
}

void expect_same_results(const std::vector<cj_result>& a, const std::vector<cj_result>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(a[k].scenario, b[k].scenario);
    ASSERT_EQ(a[k].contact_count, b[k].contact_count);
    EXPECT_EQ(std::memcmp(&a[k].certificate, &b[k].certificate, sizeof(cj_certificate)), 0);
    EXPECT_EQ(std::memcmp(a[k].contacts, b[k].contacts, sizeof(cj_contact) * a[k].contact_count), 0);
  }
}

TEST(CApi, DetectManyReadsEveryLayoutInPlaceAndAnswersAsSingleCalls) {
  const std::vector<cj_pose> journals = table2_journals();
  const std::size_t n = journals.size();
  const std::vector<cj_result> expected = one_by_one(journals);
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose_array bearings = cj_pose_array_repeat(&kBearing);

  // Row-major n x 6 (an array of cj_pose).
  std::vector<cj_result> rows(n);
  const cj_pose_array row_major = cj_pose_array_rows(journals.front().p_WP);
  ASSERT_EQ(cj_detect_many(&dims, &bearings, &row_major, n, nullptr, rows.data(), nullptr, nullptr, 0), CJ_OK);
  expect_same_results(rows, expected);

  // Column-major n x 6 (MATLAB), and six separate arrays (structure of arrays).
  std::vector<double> columns(6 * n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int c = 0; c < 6; ++c) columns[k + c * n] = c < 3 ? journals[k].p_WP[c] : journals[k].axis_W[c - 3];
  }
  std::vector<cj_result> by_columns(n);
  const cj_pose_array column_major = cj_pose_array_columns(columns.data(), n);
  ASSERT_EQ(cj_detect_many(&dims, &bearings, &column_major, n, nullptr, by_columns.data(), nullptr, nullptr, 0), CJ_OK);
  expect_same_results(by_columns, expected);
  std::vector<std::vector<double>> separate(6, std::vector<double>(n));
  cj_pose_array soa{};
  for (int c = 0; c < 6; ++c) {
    for (std::size_t k = 0; k < n; ++k) separate[c][k] = columns[k + c * n];
    soa.component[c] = separate[c].data();
  }
  soa.stride = sizeof(double);
  std::vector<cj_result> by_arrays(n);
  ASSERT_EQ(cj_detect_many(&dims, &bearings, &soa, n, nullptr, by_arrays.data(), nullptr, nullptr, 0), CJ_OK);
  expect_same_results(by_arrays, expected);

  // The caller's own records (an id and six doubles, packed: the doubles are misaligned).
#pragma pack(push, 1)
  struct Body {
    char id;
    double pose[6];
  };
#pragma pack(pop)
  std::vector<Body> bodies(n);
  for (std::size_t k = 0; k < n; ++k) {
    bodies[k].id = static_cast<char>(k);
    for (int c = 0; c < 6; ++c) bodies[k].pose[c] = columns[k + c * n];
  }
  cj_pose_array records{};
  for (int c = 0; c < 6; ++c) {
    records.component[c] = reinterpret_cast<const double*>(reinterpret_cast<const char*>(&bodies[0]) +
                                                           offsetof(Body, pose) + c * sizeof(double));
  }
  records.stride = sizeof(Body);
  std::vector<cj_result> by_records(n);
  ASSERT_EQ(cj_detect_many(&dims, &bearings, &records, n, nullptr, by_records.data(), nullptr, nullptr, 0), CJ_OK);
  expect_same_results(by_records, expected);
}

TEST(CApi, DetectManyStopsAtTheFirstBadPoseAndNamesIt) {
  std::vector<cj_pose> journals = table2_journals();
  journals[3].axis_W[0] = journals[3].axis_W[1] = journals[3].axis_W[2] = 0.0;
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose_array bearings = cj_pose_array_repeat(&kBearing);
  const cj_pose_array rows = cj_pose_array_rows(journals.front().p_WP);
  std::vector<cj_result> results(journals.size());
  std::memset(results.data(), 0x5A, sizeof(cj_result) * results.size());
  std::size_t processed = 99;
  char message[256];
  EXPECT_EQ(cj_detect_many(&dims, &bearings, &rows, journals.size(), nullptr, results.data(), &processed, message,
                           sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(processed, 3u);
  EXPECT_STREQ(message, "poses[3]: journal.axis_W = [0, 0, 0]: must not be the zero vector");
  EXPECT_EQ(results[3].scenario, 0x5A5A5A5A);  // untouched from the failing pose on
  EXPECT_NE(results[2].scenario, 0x5A5A5A5A);
  // Bad dimensions are not a pose's fault.
  const cj_dimensions bad{10.0, -20.0, 9.9, 19.8};
  EXPECT_EQ(cj_detect_many(&bad, &bearings, &rows, 2, nullptr, results.data(), &processed, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("dimensions.bearing_length = -20", 0), 0u) << message;
  EXPECT_EQ(processed, 0u);
  // Nor are bad options.
  cj_options options = cj_default_options();
  options.parallel_angle_tolerance = -1.0;
  EXPECT_EQ(cj_detect_many(&dims, &bearings, &rows, 2, &options, results.data(), &processed, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("options.parallel_angle_tolerance = -1", 0), 0u) << message;
  // A NULL component pointer is named.
  cj_pose_array broken = rows;
  broken.component[4] = nullptr;
  EXPECT_EQ(cj_detect_many(&dims, &bearings, &broken, 2, nullptr, results.data(), nullptr, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_STREQ(message, "journals.component[4] = NULL: must point to the first pose's value");
}

TEST(CApi, DetectManyRefusesACountNoArrayCanHoldWithoutReadingAPose) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  const cj_pose_array bearings = cj_pose_array_repeat(&kBearing);
  cj_result one;
  std::size_t processed = 99;
  char message[256];
  // (size_t)-1: a negative count converted, the usual way such a count arises.
  EXPECT_EQ(cj_detect_many(&dims, &bearings, &bearings, SIZE_MAX, nullptr, &one, &processed, message, sizeof message),
            CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("count = 18446744073709551615: more poses than an array of cj_result can hold",
                                       0),
            0u)
      << message;
  EXPECT_EQ(processed, 0u);
}

TEST(CApi, DetectManyOfNoPosesSucceedsWithoutReadingAnything) {
  const cj_dimensions dims = c_dimensions(geo::testing::kTable2);
  std::size_t processed = 7;
  EXPECT_EQ(cj_detect_many(&dims, nullptr, nullptr, 0, nullptr, nullptr, &processed, nullptr, 0), CJ_OK);
  EXPECT_EQ(processed, 0u);
}

TEST(CApi, ThreadsDetectingAtOnceGetTheirOwnAnswers) {
  // cj_detect keeps one scratch answer per thread; two threads detecting different poses must
  // each get the single-threaded answers.
  const std::vector<cj_pose> journals = table2_journals();
  const std::vector<cj_result> expected = one_by_one(journals);
  std::vector<cj_result> a, b;
  std::thread first([&] {
    for (int round = 0; round < 200; ++round) a = one_by_one(journals);
  });
  std::vector<cj_pose> reversed(journals.rbegin(), journals.rend());
  std::thread second([&] {
    for (int round = 0; round < 200; ++round) b = one_by_one(reversed);
  });
  first.join();
  second.join();
  expect_same_results(a, expected);
  std::vector<cj_result> b_forward(b.rbegin(), b.rend());
  expect_same_results(b_forward, expected);
}

TEST(CApi, NamesEveryEnumValueAndSaysUnknownForOthers) {
  for (int s = CJ_SCENARIO_NONE; s <= CJ_SCENARIO_BEYOND_MODEL; ++s) EXPECT_STRNE(cj_scenario_string(s), "unknown");
  EXPECT_STREQ(cj_scenario_string(CJ_SCENARIO_LINE), "j");
  EXPECT_STREQ(cj_scenario_string(CJ_SCENARIO_BEYOND_MODEL + 1), "unknown");
  EXPECT_STREQ(cj_scenario_string(-1), "unknown");
  EXPECT_STREQ(cj_certainty_string(CJ_CERTAINTY_CERTIFIED), "certified");
  EXPECT_STREQ(cj_certainty_string(7), "unknown");
  // Every reason C++ has, with its sentence; none has the empty one.
  for (int r = CJ_REASON_NONE; r <= CJ_REASON_EDGE_SIDES_UNDECIDED; ++r) {
    EXPECT_STREQ(cj_reason_string(r), geo::to_string(static_cast<geo::CertificateReason>(r)).data()) << r;
  }
  EXPECT_STREQ(cj_reason_string(CJ_REASON_NONE), "");
  EXPECT_STREQ(cj_reason_string(CJ_REASON_CERTIFICATE_SWITCHED_OFF), "certificate switched off");
  EXPECT_STREQ(cj_reason_string(CJ_REASON_EDGE_SIDES_UNDECIDED + 1), "unknown");
  EXPECT_STREQ(cj_contact_type_string(CJ_CONTACT_AXIAL), "axial");
  EXPECT_STREQ(cj_base_string(CJ_BASE_MID), "mid");
  EXPECT_STREQ(cj_base_string(3), "unknown");
  EXPECT_STREQ(cj_circle_plane_topology_string(CJ_CIRCLE_PLANE_TANGENT), "tangent");
  EXPECT_STREQ(cj_circle_cylinder_topology_string(CJ_CIRCLE_CYLINDER_ON_SURFACE), "on_surface");
  EXPECT_STREQ(cj_circle_plane_topology_string(CJ_CIRCLE_PLANE_TWO_CROSSINGS), "two_crossings");
  EXPECT_STREQ(cj_base_string(CJ_BASE_A), "a");
  EXPECT_STREQ(cj_status_string(CJ_INVALID_INPUT), "invalid input");
  EXPECT_STREQ(cj_status_string(42), "unknown");
}

TEST(CApi, CirclePlaneQueryGivesTheCppAnswer) {
  // A unit rim tilted 45 degrees about x, centred 0.5 above the plane z = 0: two crossings.
  const geo::Circle3 circle{{0, 0, 0.5}, {0, 1, 1}, 1.0};
  const geo::Plane3 plane{{0, 0, 0}, {0, 0, 1}};
  const cj_circle c_circle{{0, 0, 0.5}, {0, 1, 1}, 1.0};
  const cj_plane c_plane{{0, 0, 0}, {0, 0, 1}};
  cj_circle_plane_result result;
  ASSERT_EQ(cj_intersect_circle_plane(&c_circle, &c_plane, nullptr, &result, nullptr, 0), CJ_OK);
  const geo::CirclePlaneIntersection cpp = geo::intersect_circle_plane(circle, plane);
  EXPECT_EQ(result.topology, CJ_CIRCLE_PLANE_TWO_CROSSINGS);
  ASSERT_EQ(result.crossing_count, cpp.crossing_count);
  for (int k = 0; k < cpp.crossing_count; ++k) expect_same_crossing(result.crossings[k], cpp.crossings[k]);
  EXPECT_EQ(result.has_penetration != 0, cpp.has_penetration);
  EXPECT_EQ(result.penetration.begin, cpp.penetration.begin);
  EXPECT_EQ(result.penetration.end, cpp.penetration.end);
  EXPECT_EQ(result.max_signed_distance, cpp.max_signed_distance);
  EXPECT_EQ(result.max_signed_distance_error_bound, cpp.max_signed_distance_error);
  EXPECT_STREQ(cj_certainty_string(result.certificate.level), geo::to_string(cpp.certificate.level).data());
  // A zero normal is named.
  const cj_circle flat{{0, 0, 0.5}, {0, 0, 0}, 1.0};
  char message[256];
  EXPECT_EQ(cj_intersect_circle_plane(&flat, &c_plane, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("circle.normal = [0, 0, 0]", 0), 0u) << message;
}

TEST(CApi, CircleCylinderQueryGivesTheCppAnswerForAnExactTangency) {
  // A unit rim touching a radius-2 wall from inside at one point (multiplicity 2, exact).
  const cj_circle rim{{1, 0, 0}, {0, 0, 1}, 1.0};
  const cj_cylinder wall{{0, 0, 0}, {0, 0, 1}, 2.0};
  cj_circle_cylinder_result result;
  ASSERT_EQ(cj_intersect_circle_cylinder(&rim, &wall, nullptr, &result, nullptr, 0), CJ_OK);
  const geo::CircleCylinderIntersection cpp =
      geo::intersect_circle_cylinder({{1, 0, 0}, {0, 0, 1}, 1.0}, {{0, 0, 0}, {0, 0, 1}, 2.0});
  EXPECT_EQ(result.topology, CJ_CIRCLE_CYLINDER_CROSSING);
  ASSERT_EQ(result.crossing_count, 1);
  EXPECT_EQ(result.crossings[0].multiplicity, 2);
  expect_same_crossing(result.crossings[0], cpp.crossings[0]);
  EXPECT_EQ(result.arc_count, cpp.arc_count);
  EXPECT_EQ(result.certificate.level, CJ_CERTAINTY_EXACT);
  char message[256];
  const cj_cylinder thin{{0, 0, 0}, {0, 0, 1}, -2.0};
  EXPECT_EQ(cj_intersect_circle_cylinder(&rim, &thin, nullptr, &result, message, sizeof message), CJ_INVALID_INPUT);
  EXPECT_EQ(std::string(message).rfind("cylinder.radius = -2", 0), 0u) << message;
}

}  // namespace
