// SPDX-License-Identifier: BSD-3-Clause
#include "answer_text.hpp"

#include <cstdio>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

// The field lists (result_fields.hpp), where the revision has them: a field of Contact's list this
// file does not print by name is printed through them (append_later_fields). compare-answers.sh
// also builds this file against revisions from before the lists.
#if __has_include("clearjoint/geometry/model/field_lists.hpp")
#include "clearjoint/geometry/model/field_lists.hpp"
#define CLEARJOINT_ANSWER_TEXT_FIELD_LISTS 1
#endif

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;

// "%a" of a double needs at most 24 characters ("-0x1.fffffffffffffp+1023").
void append_number(std::string& line, double value) {
  char text[32];
  const int length = std::snprintf(text, sizeof text, " %a", value);
  line.append(text, static_cast<std::size_t>(length));
}

void append_vector(std::string& line, const geo::Vector3& v) {
  append_number(line, v.x());
  append_number(line, v.y());
  append_number(line, v.z());
}

// An integer or enum with its tag: " n2".
void append_tagged(std::string& line, const char* tag, int value) {
  line += ' ';
  line += tag;
  line += std::to_string(value);
}

// The reason's text. Certificates held it as a C string before the reason became an enum
// (CertificateReason); both print the same text, so revisions from either side compare.
template <class CertificateType>
std::string_view reason_text(const CertificateType& certificate) {
  if constexpr (std::is_convertible_v<decltype(certificate.reason), const char*>) {
    return certificate.reason != nullptr ? std::string_view(certificate.reason) : std::string_view("(null)");
  } else {
    return to_string(certificate.reason);
  }
}

void append_certificate(std::string& line, const geo::Certificate& certificate) {
  append_tagged(line, "c", static_cast<int>(certificate.level));
  line += " \"";
  // The reason is printed as text: two builds whose reasons are equal strings at different
  // addresses print the same line.
  line += reason_text(certificate);
  line += '"';
}

void append_crossing(std::string& line, const geo::RimCrossing& crossing) {
  line += " x";
  append_number(line, crossing.angle);
  append_number(line, crossing.angle_error);
  append_vector(line, crossing.point);
  append_number(line, crossing.point_error);
  append_tagged(line, "m", crossing.multiplicity);
}

void append_arc(std::string& line, const geo::RimArc& arc) {
  line += " arc";
  append_number(line, arc.begin);
  append_number(line, arc.end);
  append_tagged(line, "f", arc.full ? 1 : 0);
}

// " e <p_WCj_error> <p_WCi_error> <depth_error>", for revisions whose Contact has the bounds;
// nothing for the revisions before them, which then still build and print the other fields.
template <class ContactType>
void append_contact_errors(std::string& line, const ContactType& contact) {
  if constexpr (requires { contact.depth_error; }) {
    line += " e";
    append_number(line, contact.p_WCj_error);
    append_number(line, contact.p_WCi_error);
    append_number(line, contact.depth_error);
  }
}

#ifdef CLEARJOINT_ANSWER_TEXT_FIELD_LISTS
// The keys of the fields append_contact prints by name.
constexpr std::string_view kContactKeysByName[] = {
    "type", "base", "point_journal", "point_bearing", "normal", "depth", "point_journal_error",
    "point_bearing_error", "depth_error", "crossings", "certificate"};

constexpr bool printed_by_name(std::string_view key) {
  for (std::string_view k : kContactKeysByName) {
    if (k == key) return true;
  }
  return false;
}

void append_value(std::string& line, double value) { append_number(line, value); }
void append_value(std::string& line, geo::ErrorBound<const double> bound) { append_number(line, bound.value); }
void append_value(std::string& line, const geo::Vector3& value) { append_vector(line, value); }
void append_value(std::string& line, int value) { line += ' ' + std::to_string(value); }
void append_value(std::string& line, bool value) { line += value ? " 1" : " 0"; }
template <class E>
  requires std::is_enum_v<E>
void append_value(std::string& line, E value) {
  line += ' ' + std::to_string(static_cast<int>(value));
}

template <class ContactType, std::size_t I>
void append_if_later(std::string& line, const ContactType& contact) {
  constexpr const auto& field = std::get<I>(geo::ResultFields<ContactType>::fields);
  if constexpr (!printed_by_name(field.key)) {
    line += ' ';
    line += field.key;
    append_value(line, field.view(contact));
  }
}
#endif

// " <key> <value>" for each field of Contact's list beyond those printed by name: a field added
// to the list shows with no edit here. Nothing for revisions without the lists.
template <class ContactType>
void append_later_fields([[maybe_unused]] std::string& line, [[maybe_unused]] const ContactType& contact) {
#ifdef CLEARJOINT_ANSWER_TEXT_FIELD_LISTS
  if constexpr (requires { geo::ResultFields<ContactType>::fields; }) {
    constexpr std::size_t count = std::tuple_size_v<std::remove_cvref_t<decltype(geo::ResultFields<ContactType>::fields)>>;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (append_if_later<ContactType, I>(line, contact), ...);
    }(std::make_index_sequence<count>{});
  }
#endif
}

void append_contact(std::string& line, const geo::Contact& contact) {
  line += " |";
  append_tagged(line, "t", static_cast<int>(contact.type));
  append_tagged(line, "b", static_cast<int>(contact.base));
  append_vector(line, contact.p_WCj);
  append_vector(line, contact.p_WCi);
  append_vector(line, contact.normal_W);
  append_number(line, contact.depth);
  append_contact_errors(line, contact);
  append_tagged(line, "nc", contact.crossing_count);
  for (int k = 0; k < contact.crossing_count; ++k) append_crossing(line, contact.crossings[k]);
  append_certificate(line, contact.certificate);
  append_later_fields(line, contact);
}

}  // namespace

void append_answer(std::string& line, const geo::JointContacts& answer) {
  append_tagged(line, "s", static_cast<int>(answer.scenario));
  append_tagged(line, "al", answer.aligned ? 1 : 0);
  append_tagged(line, "n", answer.contact_count);
  append_certificate(line, answer.certificate);
  for (int i = 0; i < answer.contact_count; ++i) append_contact(line, answer.contacts[i]);
}

void append_answer(std::string& line, const geo::CircleCylinderIntersection& answer) {
  append_tagged(line, "t", static_cast<int>(answer.topology));
  append_tagged(line, "n", answer.crossing_count);
  append_tagged(line, "a", answer.arc_count);
  append_certificate(line, answer.certificate);
  for (int k = 0; k < answer.crossing_count; ++k) append_crossing(line, answer.crossings[k]);
  for (int k = 0; k < answer.arc_count; ++k) append_arc(line, answer.penetration_arcs[k]);
}

void append_answer(std::string& line, const geo::CirclePlaneIntersection& answer) {
  append_tagged(line, "t", static_cast<int>(answer.topology));
  append_tagged(line, "s", static_cast<int>(answer.side));  // PlaneSide: -1, 0, +1
  append_tagged(line, "n", answer.crossing_count);
  append_certificate(line, answer.certificate);
  // The arc is printed whatever has_penetration says: a build that leaves another arc there when
  // there is no penetration has still changed a public field.
  append_tagged(line, "pen", answer.has_penetration ? 1 : 0);
  append_arc(line, answer.penetration);
  line += " msd";
  append_number(line, answer.max_signed_distance);
  append_number(line, answer.max_signed_distance_error);
  for (int k = 0; k < answer.crossing_count; ++k) append_crossing(line, answer.crossings[k]);
}

void append_exception(std::string& line, const std::exception& error) {
  line += " threw ";
  line += error.what();
}

}  // namespace clearjoint::bench
