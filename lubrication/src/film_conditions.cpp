// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/film_conditions.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::lubrication {

namespace {

[[noreturn]] void refuse(const char* name, const char* field, double value, const char* rule) {
  std::ostringstream message;
  message.precision(17);
  message << name << "." << field << " = " << value << ": " << rule;
  throw geometry::InvalidInput(message.str());
}

}  // namespace

void validate(const Lubricant& lubricant, const char* name) {
  if (!(std::isfinite(lubricant.viscosity) && lubricant.viscosity > 0.0)) {
    refuse(name, "viscosity", lubricant.viscosity, "must be positive and finite");
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
