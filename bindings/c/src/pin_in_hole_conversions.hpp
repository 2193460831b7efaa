// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Conversions between the C API's pin-in-hole structs (clearjoint.h, "The pin-in-hole joint")
/// and the C++ types they mirror; the contacts are converted as cj_detect's are
/// (conversions.hpp).

#include <string>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "conversions.hpp"

namespace clearjoint::c_api {

static_assert(CJ_MAX_AXIAL_STOPS == geo::kMaxAxialStops, "clearjoint.h and pin_in_hole_dimensions.hpp disagree");
static_assert(CJ_MAX_CONTACTS == geo::kMaxPinInHoleContacts,
              "cj_pin_in_hole_result's contacts array must hold every pin-in-hole contact");

/// Throw ValidationError naming the first nonzero reserved field of `d` (a field of a later
/// version of the API, clearjoint.h's ABI rules).
[[noreturn, gnu::cold, gnu::noinline]] inline void reject_reserved(const cj_pin_in_hole_dimensions& d) {
  const auto reject = [](const std::string& name, double value) {
    std::ostringstream message;
    message.precision(17);
    message << " = " << value << ": must be 0 (start from a zero-initialised struct)";
    throw ValidationError(name, message.str());
  };
  if (d.reserved0 != 0) reject("dimensions.reserved0", d.reserved0);
  for (int k = 0; k < 4; ++k) {
    if (d.reserved[k] != 0.0) reject("dimensions.reserved[" + std::to_string(k) + "]", d.reserved[k]);
  }
  throw ValidationError("dimensions.reserved", ": must be 0");
}

/// The kernel's dimensions; both stops are copied whatever stop_count says (the kernel reads
/// stops[0, stop_count) and validates stop_count itself).
inline geo::PinInHoleDimensions pin_in_hole_dimensions_of(const cj_pin_in_hole_dimensions& d) {
  if ((d.reserved0 != 0) | (d.reserved[0] != 0.0) | (d.reserved[1] != 0.0) | (d.reserved[2] != 0.0) |
      (d.reserved[3] != 0.0)) {
    reject_reserved(d);
  }
  geo::PinInHoleDimensions out;
  out.hole_radius = d.hole_radius;
  out.hole_length = d.hole_length;
  out.pin_radius = d.pin_radius;
  for (int k = 0; k < geo::kMaxAxialStops; ++k) out.stops[k] = {d.stops[k].position, d.stops[k].outer_radius};
  out.stop_count = d.stop_count;
  return out;
}

/// Scenario, aligned, certificate, count and contacts[0, contact_count); the contacts after them
/// and the reserved members are left alone, as copy_result leaves them.
inline void copy_pin_in_hole_result(const geo::PinInHoleContacts& from, cj_pin_in_hole_result& to) {
  to.scenario = code_of(from.scenario);
  to.aligned = from.aligned ? 1 : 0;
  to.contact_count = from.contact_count;
  to.certificate = certificate_of(from.certificate);
  for (int k = 0; k < from.contact_count; ++k) copy_contact(from.contacts[k], to.contacts[k]);
}

}  // namespace clearjoint::c_api
