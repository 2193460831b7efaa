// SPDX-License-Identifier: BSD-3-Clause
// The C API's static strings: versions, status and enum names. The enum names are the keys of
// the library's tables (clearjoint/geometry/model/enum_table.hpp), a reason's text its sentence.

#include "clearjoint/version.hpp"
#include "conversions.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

namespace {

namespace geo = clearjoint::geometry;

/// The key of a code of E (the table's string literals are NUL-terminated), or "unknown".
template <class E>
const char* key_of_code(int code) {
  const geo::EnumEntry<E>* entry = geo::entry_of_code<E>(code);
  return entry != nullptr ? entry->key.data() : "unknown";
}

}  // namespace

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

const char* cj_scenario_string(int scenario) { return key_of_code<geo::ContactScenario>(scenario); }

const char* cj_certainty_string(int certainty) { return key_of_code<geo::Certainty>(certainty); }

const char* cj_reason_string(int reason) {
  const geo::EnumEntry<geo::CertificateReason>* entry = geo::entry_of_code<geo::CertificateReason>(reason);
  return entry != nullptr ? entry->label.data() : "unknown";
}

const char* cj_contact_type_string(int type) { return key_of_code<geo::ContactType>(type); }

const char* cj_base_string(int base) { return key_of_code<geo::ContactBase>(base); }

const char* cj_circle_plane_topology_string(int topology) {
  return key_of_code<geo::CirclePlaneTopology>(topology);
}

const char* cj_circle_cylinder_topology_string(int topology) {
  return key_of_code<geo::CircleCylinderTopology>(topology);
}

const char* cj_pin_in_hole_scenario_string(int scenario) { return key_of_code<geo::PinInHoleScenario>(scenario); }

}  // extern "C"
