// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/normal_contact_force.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

/// delta^n, with the paper's n = 1.5 as delta sqrt(delta): same value to an ulp, and several
/// times cheaper than pow in the right-hand side, which evaluates it millions of times.
double power_of_depth(double depth, double exponent) noexcept {
  return exponent == 1.5 ? depth * std::sqrt(depth) : std::pow(depth, exponent);
}

}  // namespace

std::string_view to_string(NormalForceModel model) noexcept { return geometry::key_of(model); }

NormalForceModel normal_force_model_from_string(std::string_view name, std::string_view field) {
  if (const auto model = geometry::from_string<NormalForceModel>(name)) return *model;
  throw ModelError(std::string(field) + " = \"" + std::string(name) + "\": unknown normal force model (known: " +
                   geometry::known_keys<NormalForceModel>() + ")");
}

void validate(const NormalForceParameters& p, std::string_view field) {
  const std::string f(field);
  require_positive(f + ".stiffness", p.stiffness);
  require_positive(f + ".exponent", p.exponent);
  require_finite(f + ".restitution", p.restitution);
  const bool divides_by_restitution = p.model == NormalForceModel::flores;
  if (p.restitution > 1.0 || p.restitution < 0.0 ||
      (divides_by_restitution && p.restitution == 0.0)) {
    throw ModelError(f + ".restitution = " + format_number(p.restitution) +
                     (divides_by_restitution ? ": must lie in (0, 1] for the flores model"
                                             : ": must lie in [0, 1]"));
  }
  require_positive(f + ".minimum_impact_speed", p.minimum_impact_speed);
}

double hysteresis_factor(const NormalForceParameters& p) noexcept {
  const double ce = p.restitution;
  switch (p.model) {
    case NormalForceModel::hertz: return 0.0;
    case NormalForceModel::lankarani_nikravesh: return 0.75 * (1.0 - ce * ce);  // eq. (28)
    case NormalForceModel::hunt_crossley: return 1.5 * (1.0 - ce);
    case NormalForceModel::flores: return 1.6 * (1.0 - ce) / ce;
  }
  return 0.0;
}

double normal_contact_force(const NormalForceParameters& p, double depth, double approach_speed,
                            double impact_speed) noexcept {
  if (!(depth > 0.0)) return 0.0;
  const double elastic = p.stiffness * power_of_depth(depth, p.exponent);
  // The floor once more here (callers apply it too): an impact speed of 0 would otherwise make
  // 0 / 0 for Hertz's zero factor and a NaN force, which the clamp below turns into a silent 0.
  const double reference_speed =
      impact_speed > p.minimum_impact_speed ? impact_speed : p.minimum_impact_speed;
  const double damping = 1.0 + hysteresis_factor(p) * approach_speed / reference_speed;  // eq. (29)
  return std::max(0.0, elastic * damping);
}

double contact_elastic_energy(const NormalForceParameters& p, double depth) noexcept {
  if (!(depth > 0.0)) return 0.0;
  return p.stiffness * power_of_depth(depth, p.exponent) * depth / (p.exponent + 1.0);
}

}  // namespace clearjoint::dynamics
