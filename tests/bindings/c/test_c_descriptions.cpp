// SPDX-License-Identifier: BSD-3-Clause
// The C API and the Fortran module against the library's descriptions of its enums and results
// (clearjoint/geometry/model/enum_table.hpp, result_fields.hpp). Both list codes and copy fields by
// hand, as C and Fortran must; these tests fail when a value or a field the library has is
// missing from them:
//  - every enum value has its constant, CJ_<ENUM>_<NAME> = code, in clearjoint.h (and in the
//    Fortran module for the enums it declares), and its key from the cj_*_string functions;
//  - copying a result into its C struct carries every field: changing any one field of the C++
//    result changes the bytes of the C struct.

#include <cctype>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "clearjoint/geometry/model/option_fields.hpp"
#include "conversions.hpp"
#include "pin_in_hole_conversions.hpp"
#include "option_changes.hpp"
#include "result_field_changes.hpp"

namespace {

namespace geo = clearjoint::geometry;

std::string read_file(const char* path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

/// Whether `source` declares `constant` = `code` (C: `NAME = 3`, Fortran: `NAME = 3`).
bool declares(const std::string& source, const std::string& constant, int code) {
  const std::regex pattern("\\b" + constant + "\\s*=\\s*" + std::to_string(code) + "\\b");
  return std::regex_search(source, pattern);
}

/// Every value of E has its C constant, and the Fortran one when `in_fortran`.
template <geo::TabledEnum E>
void expect_constants(const char* prefix, bool in_fortran, const char* (*to_text)(int)) {
  const std::string header = read_file(CLEARJOINT_C_HEADER);
  const std::string fortran = read_file(CLEARJOINT_FORTRAN_MODULE);
  ASSERT_FALSE(header.empty()) << CLEARJOINT_C_HEADER;
  for (const geo::EnumEntry<E>& entry : geo::EnumTable<E>::entries) {
    const int code = static_cast<int>(entry.value);
    const std::string constant = std::string(prefix) + upper(entry.name);
    EXPECT_TRUE(declares(header, constant, code))
        << "clearjoint.h lacks " << constant << " = " << code << " (" << geo::EnumTable<E>::type_name << "::"
        << entry.name << ")";
    if (in_fortran) {
      EXPECT_TRUE(declares(fortran, constant, code)) << "clearjoint.f90 lacks " << constant << " = " << code;
    }
    const bool is_reason = std::is_same_v<E, geo::CertificateReason>;
    EXPECT_EQ(std::string(to_text(code)), std::string(is_reason ? entry.label : entry.key)) << constant;
  }
  EXPECT_STREQ(to_text(geo::enum_count<E>()), "unknown");
  EXPECT_STREQ(to_text(-1), "unknown");
}

TEST(CDescriptions, EveryEnumValueHasItsConstantAndItsKey) {
  expect_constants<geo::ContactScenario>("CJ_SCENARIO_", true, cj_scenario_string);
  expect_constants<geo::Certainty>("CJ_CERTAINTY_", true, cj_certainty_string);
  expect_constants<geo::CertificateReason>("CJ_REASON_", true, cj_reason_string);
  expect_constants<geo::ContactType>("CJ_CONTACT_", true, cj_contact_type_string);
  expect_constants<geo::ContactBase>("CJ_BASE_", true, cj_base_string);
  // The Fortran module has no kernel queries.
  expect_constants<geo::CirclePlaneTopology>("CJ_CIRCLE_PLANE_", false, cj_circle_plane_topology_string);
  expect_constants<geo::CircleCylinderTopology>("CJ_CIRCLE_CYLINDER_", false,
                                                cj_circle_cylinder_topology_string);
  expect_constants<geo::PinInHoleScenario>("CJ_PIN_IN_HOLE_", true, cj_pin_in_hole_scenario_string);
}

TEST(CDescriptions, TheOptionsCarryEveryDetectionOptionByItsKey) {
  // One option at a time, changed from its default, through cj_options and back: a member added
  // to DetectionOptions (and so to its option list, which the compiler requires) that the C API
  // cannot pass fails here, as does a cj_options member spelt otherwise than the list's key.
  const std::string header = read_file(CLEARJOINT_C_HEADER);
  const auto options_struct = header.substr(header.find("typedef struct cj_options {"));
  const std::string declaration = options_struct.substr(0, options_struct.find("} cj_options;"));
  for (int k = 0; k < geo::kDetectionOptionCount; ++k) {
    const geo::OptionChange change = geo::change_one_option(k);
    const cj_options c = clearjoint::c_api::options_of(change.options);
    const geo::DetectionOptions back = clearjoint::c_api::detection_options_of(&c);
    EXPECT_EQ(geo::option_values(back), geo::option_values(change.options)) << change.key;
    EXPECT_TRUE(std::regex_search(declaration, std::regex("\\b" + std::string(change.key) + ";")))
        << "cj_options has no member " << change.key;
  }
  const cj_options defaults = cj_default_options();
  EXPECT_EQ(geo::option_values(clearjoint::c_api::detection_options_of(&defaults)),
            geo::option_values(geo::DetectionOptions{}));
}

TEST(CDescriptions, TheFortranAndMexOptionsNameEveryDetectionOption) {
  // The Fortran module mirrors cj_options; the MEX gateways read a struct's fields by name.
  const std::string fortran = read_file(CLEARJOINT_FORTRAN_MODULE);
  const auto type_start = fortran.find("type, bind(c), public :: cj_options");
  ASSERT_NE(type_start, std::string::npos);
  const std::string fortran_type = fortran.substr(type_start, fortran.find("end type", type_start) - type_start);
  const std::string mex = read_file(CLEARJOINT_MEX_INPUTS);
  const geo::DetectionOptions defaults;
  geo::visit_options(defaults, [&](std::string_view key, const auto&) {
    const std::string name(key);
    EXPECT_TRUE(std::regex_search(fortran_type, std::regex("\\b" + name + "\\b"))) << "Fortran cj_options lacks " << name;
    EXPECT_NE(mex.find("strcmp(field, \"" + name + "\")"), std::string::npos) << "the MEX options lack " << name;
  });
}

template <class CStruct>
bool same_bytes(const CStruct& a, const CStruct& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(CDescriptions, CopyingADetectionCarriesEveryField) {
  const auto base = geo::result_with_every_field_set<geo::JointContacts>();
  cj_result base_copy{};
  clearjoint::c_api::copy_result(base, base_copy);
  int changes = 0;
  geo::for_each_field_change(base, [&](std::string_view field, const geo::JointContacts& changed) {
    cj_result copy{};
    clearjoint::c_api::copy_result(changed, copy);
    EXPECT_FALSE(same_bytes(copy, base_copy)) << "cj_result does not carry " << field;
    ++changes;
  });
  // One contact with one crossing: 30 leaves when this test was written. A floor, not the count,
  // so that a field added to the lists needs no edit here: it is one more leaf, checked above.
  EXPECT_GE(changes, 30);
}

TEST(CDescriptions, CopyingAPinInHoleDetectionCarriesEveryField) {
  const auto base = geo::result_with_every_field_set<geo::PinInHoleContacts>();
  cj_pin_in_hole_result base_copy{};
  clearjoint::c_api::copy_pin_in_hole_result(base, base_copy);
  int changes = 0;
  geo::for_each_field_change(base, [&](std::string_view field, const geo::PinInHoleContacts& changed) {
    cj_pin_in_hole_result copy{};
    clearjoint::c_api::copy_pin_in_hole_result(changed, copy);
    EXPECT_FALSE(same_bytes(copy, base_copy)) << "cj_pin_in_hole_result does not carry " << field;
    ++changes;
  });
  // As for cj_result: a floor (one contact with one crossing), not the count.
  EXPECT_GE(changes, 30);
}

TEST(CDescriptions, ThePinInHoleDimensionsCarryEveryMember) {
  // Every member of PinInHoleDimensions, changed alone, through cj_pin_in_hole_dimensions.
  geo::PinInHoleDimensions base;
  base.hole_radius = 1.0;
  base.hole_length = 2.0;
  base.pin_radius = 0.5;
  base.stops[0] = {-1.5, 3.0};
  base.stops[1] = {1.5, 3.0};
  base.stop_count = 2;
  const auto through_c = [](const geo::PinInHoleDimensions& d) {
    cj_pin_in_hole_dimensions c{};
    c.hole_radius = d.hole_radius;
    c.hole_length = d.hole_length;
    c.pin_radius = d.pin_radius;
    c.stop_count = d.stop_count;
    for (int k = 0; k < CJ_MAX_AXIAL_STOPS; ++k) c.stops[k] = {d.stops[k].position, d.stops[k].outer_radius};
    return clearjoint::c_api::pin_in_hole_dimensions_of(c);
  };
  const auto same = [](const geo::PinInHoleDimensions& a, const geo::PinInHoleDimensions& b) {
    bool stops = true;
    for (int k = 0; k < geo::kMaxAxialStops; ++k) {
      stops = stops && a.stops[k].position == b.stops[k].position && a.stops[k].outer_radius == b.stops[k].outer_radius;
    }
    return stops && a.hole_radius == b.hole_radius && a.hole_length == b.hole_length &&
           a.pin_radius == b.pin_radius && a.stop_count == b.stop_count;
  };
  // Six doubles and an int: a member added to the struct changes its size and fails here.
  static_assert(sizeof(geo::PinInHoleDimensions) == 3 * sizeof(double) + 4 * sizeof(double) + sizeof(double));
  EXPECT_TRUE(same(through_c(base), base));
  for (int member = 0; member < 8; ++member) {
    geo::PinInHoleDimensions changed = base;
    switch (member) {
      case 0: changed.hole_radius = 1.25; break;
      case 1: changed.hole_length = 2.25; break;
      case 2: changed.pin_radius = 0.75; break;
      case 3: changed.stops[0].position = -1.75; break;
      case 4: changed.stops[0].outer_radius = 3.25; break;
      case 5: changed.stops[1].position = 1.75; break;
      case 6: changed.stops[1].outer_radius = 3.5; break;
      default: changed.stop_count = 1; break;
    }
    EXPECT_TRUE(same(through_c(changed), changed)) << "member " << member;
  }
}

TEST(CDescriptions, CopyingACrossingCarriesEveryField) {
  const auto base = geo::result_with_every_field_set<geo::RimCrossing>();
  cj_crossing base_copy{};
  clearjoint::c_api::copy_crossing(base, base_copy);
  geo::for_each_field_change(base, [&](std::string_view field, const geo::RimCrossing& changed) {
    cj_crossing copy{};
    clearjoint::c_api::copy_crossing(changed, copy);
    EXPECT_FALSE(same_bytes(copy, base_copy)) << "cj_crossing does not carry " << field;
  });
}

TEST(CDescriptions, CopyingAnArcCarriesEveryField) {
  const auto base = geo::result_with_every_field_set<geo::RimArc>();
  const cj_arc base_copy = clearjoint::c_api::arc_of(base);
  geo::for_each_field_change(base, [&](std::string_view field, const geo::RimArc& changed) {
    const cj_arc copy = clearjoint::c_api::arc_of(changed);
    EXPECT_FALSE(same_bytes(copy, base_copy)) << "cj_arc does not carry " << field;
  });
}

TEST(CDescriptions, CopyingTheKernelAnswersCarriesEveryField) {
  const auto plane = geo::result_with_every_field_set<geo::CirclePlaneIntersection>();
  const cj_circle_plane_result plane_copy = clearjoint::c_api::circle_plane_result_of(plane);
  geo::for_each_field_change(plane, [&](std::string_view field, const geo::CirclePlaneIntersection& changed) {
    EXPECT_FALSE(same_bytes(clearjoint::c_api::circle_plane_result_of(changed), plane_copy))
        << "cj_circle_plane_result does not carry " << field;
  });

  const auto cylinder = geo::result_with_every_field_set<geo::CircleCylinderIntersection>();
  const cj_circle_cylinder_result cylinder_copy = clearjoint::c_api::circle_cylinder_result_of(cylinder);
  geo::for_each_field_change(cylinder, [&](std::string_view field, const geo::CircleCylinderIntersection& changed) {
    EXPECT_FALSE(same_bytes(clearjoint::c_api::circle_cylinder_result_of(changed), cylinder_copy))
        << "cj_circle_cylinder_result does not carry " << field;
  });
}

}  // namespace
