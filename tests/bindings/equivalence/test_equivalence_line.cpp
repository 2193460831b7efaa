// SPDX-License-Identifier: BSD-3-Clause
// The equivalence test's C++ line writes every field of a detection: changing any one field of
// the result (a field the library's list has, result_fields.hpp) changes the line. The other
// languages' lines must equal it byte for byte, so they carry every field too.

#include <string>

#include <gtest/gtest.h>

#include "equivalence_line.hpp"
#include "result_field_changes.hpp"

namespace {

namespace geo = clearjoint::geometry;
using clearjoint::equivalence::line_of;

TEST(EquivalenceLine, WritesEveryFieldOfADetection) {
  const auto base = geo::result_with_every_field_set<geo::JointContacts>();
  for (const char tag : {'S', 'B'}) {
    const std::string base_line = line_of(tag, 0, base);
    geo::for_each_field_change(base, [&](std::string_view field, const geo::JointContacts& changed) {
      EXPECT_NE(line_of(tag, 0, changed), base_line) << "the " << tag << " line leaves out " << field;
    });
  }
}

}  // namespace
