// SPDX-License-Identifier: BSD-3-Clause
// The C API's static strings: versions, status and enum names. The names the C++ API has are
// taken from it (one spelling for both); the others are written here.
#include <array>
#include <iterator>
#include <string_view>

#include "clearjoint/version.hpp"
#include "conversions.hpp"

namespace {

namespace geo = clearjoint::geometry;

/// The C++ to_string functions return views of static, NUL-terminated literals.
const char* c_string(std::string_view literal) { return literal.data(); }

/// kReasonTexts' storage: entry code_of(r) holds to_string(r), for every reason r.
std::array<const char*, std::size(clearjoint::c_api::kAllReasons)> reason_texts() {
  std::array<const char*, std::size(clearjoint::c_api::kAllReasons)> texts{};
  for (geo::CertificateReason r : clearjoint::c_api::kAllReasons) {
    texts.at(static_cast<std::size_t>(clearjoint::c_api::code_of(r))) = c_string(geo::to_string(r));
  }
  return texts;
}

const std::array<const char*, std::size(clearjoint::c_api::kAllReasons)> kReasonTextStorage = reason_texts();

}  // namespace

// The C codes run from 0 to the number of reasons - 1 (clearjoint.h), one per C++ reason.
const char* const* const clearjoint::c_api::kReasonTexts = kReasonTextStorage.data();

extern "C" {

const char* cj_version(void) { return clearjoint::version_string(); }

int cj_abi_version(void) { return CJ_ABI_VERSION; }

const char* cj_status_string(int status) {
  switch (status) {
    case CJ_OK: return "ok";
    case CJ_INVALID_INPUT: return "invalid input";
    case CJ_OUT_OF_MEMORY: return "out of memory";
    case CJ_INTERNAL_ERROR: return "internal error";
    default: return "unknown";
  }
}

const char* cj_scenario_string(int scenario) {
  // Through code_of, the one mapping between the C codes and the C++ enum.
  using S = geo::ContactScenario;
  for (S s : {S::none, S::single_radial, S::single_axial, S::radial_at_both_bases, S::axial_at_both_bases,
              S::radial_and_axial_same_base, S::radial_and_axial_opposite_bases, S::two_radial_one_axial,
              S::one_radial_two_axial, S::all_four, S::line, S::face, S::line_and_face, S::beyond_model}) {
    if (clearjoint::c_api::code_of(s) == scenario) return c_string(geo::to_string(s));
  }
  return "unknown";
}

const char* cj_certainty_string(int certainty) {
  switch (certainty) {
    case CJ_CERTAINTY_EXACT: return c_string(geo::to_string(geo::Certainty::exact));
    case CJ_CERTAINTY_CERTIFIED: return c_string(geo::to_string(geo::Certainty::certified));
    case CJ_CERTAINTY_UNCERTAIN: return c_string(geo::to_string(geo::Certainty::uncertain));
    default: return "unknown";
  }
}

const char* cj_reason_string(int reason) {
  if (reason < 0 || reason >= static_cast<int>(std::size(clearjoint::c_api::kAllReasons))) return "unknown";
  return clearjoint::c_api::kReasonTexts[reason];
}

const char* cj_contact_type_string(int type) {
  switch (type) {
    case CJ_CONTACT_RADIAL: return "radial";
    case CJ_CONTACT_AXIAL: return "axial";
    default: return "unknown";
  }
}

const char* cj_base_string(int base) {
  switch (base) {
    case CJ_BASE_A: return "A";
    case CJ_BASE_B: return "B";
    case CJ_BASE_MID: return "mid";
    default: return "unknown";
  }
}

const char* cj_circle_plane_topology_string(int topology) {
  switch (topology) {
    case CJ_CIRCLE_PLANE_DISJOINT: return "disjoint";
    case CJ_CIRCLE_PLANE_TANGENT: return "tangent";
    case CJ_CIRCLE_PLANE_TWO_CROSSINGS: return "two crossings";
    case CJ_CIRCLE_PLANE_CIRCLE_IN_PLANE: return "circle in plane";
    default: return "unknown";
  }
}

const char* cj_circle_cylinder_topology_string(int topology) {
  switch (topology) {
    case CJ_CIRCLE_CYLINDER_INSIDE: return "inside";
    case CJ_CIRCLE_CYLINDER_OUTSIDE: return "outside";
    case CJ_CIRCLE_CYLINDER_CROSSING: return "crossing";
    case CJ_CIRCLE_CYLINDER_ON_SURFACE: return "on surface";
    default: return "unknown";
  }
}

}  // extern "C"
