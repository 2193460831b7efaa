// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Normal contact force laws for the clearance joint (paper Section 4): Hertz with hysteresis
/// damping, F_N = K delta^n + chi delta^n delta_dot (eq. 27), chi from the initial impact velocity
/// delta_dot(-). The paper's choice is Lankarani-Nikravesh (eqs. 28-29); Hertz, Hunt-Crossley and
/// Flores et al. (2011) are the alternatives a model may choose.
///
/// Sign conventions: depth delta >= 0 is the penetration, approach speed delta_dot > 0 while the
/// penetration grows (compression), < 0 while it shrinks (restitution), as in
/// geometry::ContactKinematics. The force is the magnitude pushing the bodies apart.

#include <array>
#include <string_view>

#include "clearjoint/geometry/model/enum_table.hpp"

namespace clearjoint::dynamics {

enum class NormalForceModel {
  hertz,                ///< F = K delta^n: elastic, no energy loss
  lankarani_nikravesh,  ///< eq. (29): chi = 3 K (1 - ce^2) / (4 delta_dot(-)), eq. (28)
  hunt_crossley,        ///< chi = 3 K (1 - ce) / (2 delta_dot(-)) (Hunt and Crossley 1975)
  flores,               ///< chi = 8 K (1 - ce) / (5 ce delta_dot(-)) (Flores et al. 2011)
};

}  // namespace clearjoint::dynamics

/// The model-file spellings: "hertz", "lankarani_nikravesh", "hunt_crossley", "flores".
template <>
struct clearjoint::geometry::EnumTable<clearjoint::dynamics::NormalForceModel> {
  using M = clearjoint::dynamics::NormalForceModel;
  static constexpr std::string_view type_name = "NormalForceModel";
  static constexpr auto entries = std::to_array({
      named_entry(M::hertz, "hertz", "Hertz: elastic, no energy loss"),
      named_entry(M::lankarani_nikravesh, "lankarani_nikravesh", "Lankarani-Nikravesh, eqs. (28)-(29)"),
      named_entry(M::hunt_crossley, "hunt_crossley", "Hunt-Crossley (1975)"),
      named_entry(M::flores, "flores", "Flores et al. (2011)"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::dynamics::NormalForceModel>());

namespace clearjoint::dynamics {

/// The key of the model's entry in its table (the model-file spelling).
std::string_view to_string(NormalForceModel model) noexcept;
/// The inverse of to_string; throws ModelError `<field> = "<name>": unknown ...` listing the names.
NormalForceModel normal_force_model_from_string(std::string_view name, std::string_view field);

/// Paper Table 2 values as defaults.
struct NormalForceParameters {
  NormalForceModel model = NormalForceModel::lankarani_nikravesh;
  double stiffness = 1e11;   ///< K [N/m^n]; Table 2: 1e11 N/m^(3/2)
  double exponent = 1.5;     ///< n; 1.5 for metallic (Hertzian) contacts, Sec. 4
  double restitution = 0.9;  ///< ce; Table 2: 0.9
  /// Floor on the initial impact velocity delta_dot(-) [m/s] used in chi. chi grows as
  /// 1/delta_dot(-): a contact that starts by grazing (delta_dot(-) -> 0) would otherwise get an
  /// unbounded damping coefficient and stall the explicit integrator. Impacts slower than the
  /// floor are damped as if they had hit at the floor speed, i.e. less than the law asks: the
  /// energy they lose is below K delta_max^(n+1) (1 - ce^2)/(n+1) anyway, which vanishes with the
  /// impact speed. 1e-3 m/s is a few percent of the impact speeds of the paper's mechanisms
  /// (journal falling through 0.1 mm under gravity: sqrt(2 g cr) = 0.044 m/s).
  double minimum_impact_speed = 1e-3;
};

/// Throw ModelError naming "<field>.stiffness" etc. unless K > 0, n > 0, ce in [0, 1] (in (0, 1]
/// for flores, whose chi divides by ce) and the impact-speed floor > 0, all finite.
void validate(const NormalForceParameters& parameters, std::string_view field);

/// chi delta_dot(-) / K: 0 (hertz), 3 (1 - ce^2) / 4 (eq. 28), 3 (1 - ce) / 2, 8 (1 - ce) / (5 ce).
double hysteresis_factor(const NormalForceParameters& parameters) noexcept;

/// F_N = max(0, K delta^n (1 + hysteresis_factor delta_dot / delta_dot(-))), eq. (29) and its
/// alternatives. The clamp at 0 removes the pull that a strongly damped law gives at the end of
/// restitution (bodies in contact do not stick); it only ever removes force while the bodies
/// separate, so it never adds energy. depth <= 0 gives 0; an impact_speed below
/// minimum_impact_speed (or 0, or NaN) is raised to it, as the clearance joint does before the
/// call. No allocation; noexcept.
double normal_contact_force(const NormalForceParameters& parameters, double depth,
                            double approach_speed, double impact_speed) noexcept;

/// K delta^(n+1) / (n + 1): the energy stored by the elastic part K delta^n of every law. With
/// hertz (or ce = 1) the contact is conservative and this is its potential energy.
double contact_elastic_energy(const NormalForceParameters& parameters, double depth) noexcept;

}  // namespace clearjoint::dynamics
