// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/film_conditions.hpp"

#include <cmath>
#include <string>

#include "clearjoint/geometry/model/primitives.hpp"
#include "refuse.hpp"

namespace clearjoint::lubrication {

namespace {

[[noreturn]] void refuse(const char* name, const char* field, double value, const char* rule) {
  detail::refuse(std::string(name) + "." + field, value, rule);
}

}  // namespace

void validate(const Lubricant& lubricant, const char* name) {
  if (!(std::isfinite(lubricant.viscosity) && lubricant.viscosity > 0.0)) {
    // The words of every other positive quantity's check (the kernel's, the dynamics').
    refuse(name, "viscosity", lubricant.viscosity,
           std::isfinite(lubricant.viscosity) ? "must be positive" : "must be finite");
  }
}

void validate(const OilSupply& supply, const char* name) {
  if (!(std::isfinite(supply.supply_pressure) && supply.supply_pressure >= 0.0)) {
    refuse(name, "supply_pressure", supply.supply_pressure,
           "must be a finite gauge pressure >= 0 (a groove below ambient would draw air)");
  }
  if (supply.kind == OilSupply::Kind::axial_groove) {
    const double length = supply.groove_direction_W.norm();
    if (!(std::isfinite(length) && length > 0.0)) {
      refuse(name, "groove_direction_W (norm)", length, "must be finite and non-zero");
    }
  }
}

std::string_view to_string(CavitationModel model) noexcept { return geometry::key_of(model); }

}  // namespace clearjoint::lubrication
