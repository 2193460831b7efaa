// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The line of one C++ answer in the equivalence test's format (README.md), shared by the writer
// (answers_cpp.cpp) and the test that it writes every field of a result
// (test_equivalence_line.cpp). Codes are the library's enum codes, which clearjoint.h's constants
// repeat (tests/bindings/c/test_c_descriptions.cpp checks them).

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "clearjoint/geometry/joint/detect_contacts.hpp"

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

inline std::string line_of(char tag, std::size_t index, const geo::JointContacts& r) {
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
  }
  return line;
}

}  // namespace clearjoint::equivalence
