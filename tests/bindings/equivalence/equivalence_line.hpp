// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The line of one C++ answer in the equivalence test's format (README.md), shared by the writers
// (answers_cpp.cpp, pin_in_hole_answers_cpp.cpp) and the test that it writes every field of a result
// (test_equivalence_line.cpp). Codes are the library's enum codes, which clearjoint.h's constants
// repeat (tests/bindings/c/test_c_descriptions.cpp checks them).

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

namespace clearjoint::equivalence {

namespace geo = clearjoint::geometry;

inline std::string hex(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  char text[24];
  std::snprintf(text, sizeof text, " %016llX", static_cast<unsigned long long>(bits));
  return text;
}

inline std::string hex(const geo::Vector3& v) { return hex(v.x()) + hex(v.y()) + hex(v.z()); }

template <geo::TabledEnum E>
int code(E value) {
  return static_cast<int>(value);
}

/// The fields of a contact the line writes in the README's order; every other field of Contact's
/// list (one added to it later) follows the contact's certificate, in the list's order, written
/// by its kind (appended_field).
inline constexpr std::string_view kContactKeysInOrder[] = {
    "type", "base", "depth", "point_journal", "point_bearing", "normal", "depth_error", "point_journal_error",
    "point_bearing_error", "crossings", "certificate"};

constexpr bool written_in_order(std::string_view key) {
  for (std::string_view k : kContactKeysInOrder) {
    if (k == key) return true;
  }
  return false;
}

inline std::string appended_field(double value) { return hex(value); }
inline std::string appended_field(geo::ErrorBound<const double> bound) { return hex(bound.value); }
inline std::string appended_field(const geo::Vector3& value) { return hex(value); }
inline std::string appended_field(int value) { return ' ' + std::to_string(value); }
inline std::string appended_field(bool value) { return value ? " 1" : " 0"; }
template <geo::TabledEnum E>
std::string appended_field(E value) {
  return ' ' + std::to_string(code(value));
}

template <std::size_t I>
void append_if_later(std::string& text, const geo::Contact& c) {
  constexpr const auto& field = std::get<I>(geo::ResultFields<geo::Contact>::fields);
  if constexpr (!written_in_order(field.key)) text += appended_field(field.view(c));
}

/// The fields of `c` its list has beyond kContactKeysInOrder.
inline std::string later_fields(const geo::Contact& c) {
  std::string text;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (append_if_later<I>(text, c), ...);
  }(std::make_index_sequence<std::tuple_size_v<std::remove_cvref_t<decltype(geo::ResultFields<geo::Contact>::fields)>>>{});
  return text;
}

/// `Answer`: JointContacts or PinInHoleContacts (the same members, the scenario's enum aside).
template <class Answer>
std::string line_of(char tag, std::size_t index, const Answer& r) {
  const bool text = tag == 'S';
  std::string line = std::string(1, tag) + ' ' + std::to_string(index) + " ok " + std::to_string(code(r.scenario)) +
                     ' ' + std::to_string(r.aligned ? 1 : 0) + ' ' + std::to_string(code(r.certificate.level)) +
                     ' ' + std::to_string(code(r.certificate.reason));
  if (text) line += " \"" + std::string(r.certificate.reason_text()) + '"';
  line += ' ' + std::to_string(r.contact_count);
  for (int k = 0; k < r.contact_count; ++k) {
    const geo::Contact& c = r.contacts[k];
    line += " | " + std::to_string(code(c.type)) + ' ' + std::to_string(code(c.base)) + hex(c.depth) + hex(c.p_WCj) +
            hex(c.p_WCi) + hex(c.normal_W) + hex(c.depth_error) + hex(c.p_WCj_error) + hex(c.p_WCi_error) + ' ' +
            std::to_string(c.crossing_count);
    for (int m = 0; m < c.crossing_count; ++m) {
      const geo::RimCrossing& x = c.crossings[m];
      line += hex(x.angle) + hex(x.angle_error) + hex(x.point) + hex(x.point_error) + ' ' +
              std::to_string(x.multiplicity);
    }
    line += ' ' + std::to_string(code(c.certificate.level)) + ' ' + std::to_string(code(c.certificate.reason));
    if (text) line += " \"" + std::string(c.certificate.reason_text()) + '"';
    line += later_fields(c);
  }
  return line;
}

}  // namespace clearjoint::equivalence
