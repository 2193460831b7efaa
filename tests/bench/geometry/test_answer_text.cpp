// SPDX-License-Identifier: BSD-3-Clause
// Tests of bench/geometry/answer_text.hpp: the text of an answer must change whenever one of its
// fields changes by the least amount a double can (one ulp, or the sign of a zero), and only in
// that field's place, or two builds could print the same text for different answers.

#include "answer_text.hpp"

#include "result_field_changes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Paper Table 2, in metres, with the journal centred and tilted by 0.012 rad about y: beyond the
// 2 cr / Lj ~ 0.0101 rad a centred journal can tilt, so each rim crosses the wall and its base
// (scenario (i), ca = cr and Lj / 2 = Rj make the two alike), each in two points, by ~2e-5 m
// (less than a clearance: within the model).
geo::JointContacts four_contacts() {
  const geo::JointDimensions table2{10e-3, 20e-3, 9.9e-3, 19.8e-3};
  const double tilt = 0.012;
  return geo::detect_contacts(table2, {Vector3::Zero(), Vector3::UnitZ()},
                              {Vector3::Zero(), Vector3(std::sin(tilt), 0.0, std::cos(tilt))});
}

// A rim of radius 0.9 centred 0.2 off the axis of the unit wall: crosses it twice.
geo::CircleCylinderIntersection rim_across_a_wall() {
  return geo::intersect_circle_cylinder({Vector3(0.2, 0.0, 0.5), Vector3(0.1, 0.0, 1.0), 0.9},
                                        {Vector3::Zero(), Vector3::UnitZ(), 1.0});
}

// A rim tilted through the plane z = 0.
geo::CirclePlaneIntersection rim_across_a_plane() {
  return geo::intersect_circle_plane({Vector3(0.0, 0.0, 0.1), Vector3(0.3, 0.0, 1.0), 0.5},
                                     {Vector3::Zero(), Vector3(0.0, 0.0, 2.0)});
}

template <class Answer>
std::string text_of(const Answer& answer) {
  std::string line;
  append_answer(line, answer);
  return line;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> fields;
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

void visit_vector(Vector3& v, const std::function<void(double&)>& visit) {
  visit(v.x());
  visit(v.y());
  visit(v.z());
}

void visit_crossing(geo::RimCrossing& crossing, const std::function<void(double&)>& visit) {
  visit(crossing.angle);
  visit(crossing.angle_error);
  visit_vector(crossing.point, visit);
  visit(crossing.point_error);
}

// Every double of the answer that the text must show: the counted entries only.
void visit_doubles(geo::JointContacts& answer, const std::function<void(double&)>& visit) {
  for (int i = 0; i < answer.contact_count; ++i) {
    geo::Contact& contact = answer.contacts[i];
    visit_vector(contact.p_WCj, visit);
    visit_vector(contact.p_WCi, visit);
    visit_vector(contact.normal_W, visit);
    visit(contact.depth);
    visit(contact.p_WCj_error);
    visit(contact.p_WCi_error);
    visit(contact.depth_error);
    for (int k = 0; k < contact.crossing_count; ++k) visit_crossing(contact.crossings[k], visit);
  }
}

void visit_doubles(geo::CircleCylinderIntersection& answer, const std::function<void(double&)>& visit) {
  for (int k = 0; k < answer.crossing_count; ++k) visit_crossing(answer.crossings[k], visit);
  for (int k = 0; k < answer.arc_count; ++k) {
    visit(answer.penetration_arcs[k].begin);
    visit(answer.penetration_arcs[k].end);
  }
}

void visit_doubles(geo::CirclePlaneIntersection& answer, const std::function<void(double&)>& visit) {
  for (int k = 0; k < answer.crossing_count; ++k) visit_crossing(answer.crossings[k], visit);
  visit(answer.penetration.begin);
  visit(answer.penetration.end);
  visit(answer.max_signed_distance);
  visit(answer.max_signed_distance_error);
}

// Moves each printed double of `answer` in turn to `changed(value)` and expects the text to
// differ in exactly one field, which reads back as the new value bit for bit. Returns how many
// doubles were checked.
template <class Answer>
int expect_each_double_shows(const Answer& answer, double (*changed)(double)) {
  const std::vector<std::string> before = fields_of(text_of(answer));
  int count = 0;
  Answer counting = answer;
  visit_doubles(counting, [&](double&) { ++count; });
  for (int target = 0; target < count; ++target) {
    Answer moved = answer;
    double new_value = 0.0;
    int index = 0;
    visit_doubles(moved, [&](double& value) {
      if (index++ == target) value = new_value = changed(value);
    });
    const std::vector<std::string> after = fields_of(text_of(moved));
    EXPECT_EQ(after.size(), before.size()) << "double " << target;
    if (after.size() != before.size()) continue;
    int differing = 0;
    for (std::size_t f = 0; f < after.size(); ++f) {
      if (after[f] == before[f]) continue;
      ++differing;
      const double read = std::strtod(after[f].c_str(), nullptr);
      EXPECT_EQ(std::memcmp(&read, &new_value, sizeof read), 0)
          << "double " << target << " printed as " << after[f];
    }
    EXPECT_EQ(differing, 1) << "double " << target;
  }
  return count;
}

double one_ulp_up(double value) { return std::nextafter(value, kInfinity); }
double one_ulp_down(double value) { return std::nextafter(value, -kInfinity); }
double with_sign_flipped(double value) { return -value; }

TEST(AnswerText, EveryDoubleOfADetectionShowsAOneUlpChangeInItsOwnField) {
  const geo::JointContacts answer = four_contacts();
  ASSERT_EQ(answer.scenario, geo::ContactScenario::all_four);
  ASSERT_EQ(answer.contact_count, 4);
  for (int i = 0; i < 4; ++i) ASSERT_EQ(answer.contacts[i].crossing_count, 2);
  // Four contacts of 13 doubles (points, normal, depth and their 3 bounds) and two crossings of 6 each.
  EXPECT_EQ(expect_each_double_shows(answer, one_ulp_up), 4 * (13 + 2 * 6));
  expect_each_double_shows(answer, one_ulp_down);
}

TEST(AnswerText, TheSignOfAZeroShows) {
  // Radial contacts' normals have a zero z component (the wall's normal is perpendicular to z);
  // every value of the answer with its sign flipped, zeros included, must show.
  const geo::JointContacts answer = four_contacts();
  ASSERT_EQ(answer.contacts[0].normal_W.z(), 0.0);
  expect_each_double_shows(answer, with_sign_flipped);
}

TEST(AnswerText, EveryDoubleOfACircleCylinderAnswerShowsAOneUlpChange) {
  const geo::CircleCylinderIntersection answer = rim_across_a_wall();
  ASSERT_EQ(answer.crossing_count, 2);
  ASSERT_EQ(answer.arc_count, 1);
  EXPECT_EQ(expect_each_double_shows(answer, one_ulp_up), 2 * 6 + 2);
}

TEST(AnswerText, EveryDoubleOfACirclePlaneAnswerShowsAOneUlpChange) {
  const geo::CirclePlaneIntersection answer = rim_across_a_plane();
  ASSERT_EQ(answer.topology, geo::CirclePlaneTopology::two_crossings);
  EXPECT_EQ(expect_each_double_shows(answer, one_ulp_up), 2 * 6 + 4);
}

TEST(AnswerText, EveryIntegerEnumAndCertificateOfADetectionShows) {
  const geo::JointContacts answer = four_contacts();
  const std::string before = text_of(answer);
  const std::vector<std::function<void(geo::JointContacts&)>> changes = {
      [](auto& a) { a.scenario = geo::ContactScenario::beyond_model; },
      [](auto& a) { a.aligned = !a.aligned; },
      [](auto& a) { a.certificate.level = geo::Certainty::exact; },
      [](auto& a) { a.certificate.reason = geo::CertificateReason::axes_parallel_within_tolerance; },
      [](auto& a) { a.contacts[1].type = geo::ContactType::axial; },
      [](auto& a) { a.contacts[1].base = geo::ContactBase::mid; },
      [](auto& a) { a.contacts[1].crossings[1].multiplicity = 2; },
      [](auto& a) { a.contacts[1].certificate.level = geo::Certainty::uncertain; },
      [](auto& a) { a.contacts[1].certificate.reason = geo::CertificateReason::axes_parallel_within_tolerance; },
      [](auto& a) { a.contacts[1].crossing_count = 1; },
      [](auto& a) { a.contact_count = 3; },
  };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    geo::JointContacts changed = answer;
    changes[i](changed);
    EXPECT_NE(text_of(changed), before) << "change " << i;
  }
}

TEST(AnswerText, EntriesPastTheCountsDoNotShow) {
  // The API leaves them unspecified: a reused result keeps old contacts there.
  const geo::JointContacts answer = four_contacts();
  geo::JointContacts stale = answer;
  stale.contacts[4].depth = 1.0;
  stale.contacts[5].certificate.level = geo::Certainty::uncertain;
  EXPECT_EQ(text_of(stale), text_of(answer));

  geo::CircleCylinderIntersection crossing = rim_across_a_wall();
  const std::string before = text_of(crossing);
  crossing.crossings[3].angle = 1.0;
  crossing.penetration_arcs[1].full = true;
  EXPECT_EQ(text_of(crossing), before);
}

// Against the library's field lists (result_fields.hpp): a field added to a result that the
// text leaves out fails here, named. (answer_text.cpp prints the fields it had before the lists
// by name, as compare-answers.sh builds it against revisions that have no lists; a field Contact's
// list gains later is printed through the list, after the contact's certificate.)
template <class Answer>
void expect_every_listed_field_shows() {
  const auto base = geo::result_with_every_field_set<Answer>();
  const std::string base_text = text_of(base);
  geo::for_each_field_change(base, [&](std::string_view field, const Answer& changed) {
    EXPECT_NE(text_of(changed), base_text) << "the answer text leaves out " << field;
  });
}

TEST(AnswerText, EveryListedFieldOfEveryAnswerShows) {
  expect_every_listed_field_shows<geo::JointContacts>();
  expect_every_listed_field_shows<geo::CircleCylinderIntersection>();
  expect_every_listed_field_shows<geo::CirclePlaneIntersection>();
}

TEST(AnswerText, AReasonIsPrintedAsItsText) {
  geo::JointContacts answer = four_contacts();
  answer.certificate.reason = geo::CertificateReason::certificate_switched_off;
  const std::string text = text_of(answer);
  EXPECT_NE(text.find("\"certificate switched off\""), std::string::npos) << text;
}

TEST(AnswerText, AnExceptionIsPrintedWithItsMessage) {
  std::string line = "family 0 detect";
  append_exception(line, geo::InvalidInput("journal.axis_W must not be zero"));
  EXPECT_EQ(line, "family 0 detect threw journal.axis_W must not be zero");
}

}  // namespace
}  // namespace clearjoint::bench
