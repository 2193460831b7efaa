// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Coulomb friction with the hyperbolic-tangent regularisation of the paper's eq. (32):
/// f_F = mu_k F_N tanh(k |v_T|) v_T / |v_T|  (eqs. 30-32), continuous through v_T = 0.

#include "clearjoint/dynamics/euler_parameters.hpp"

namespace clearjoint::dynamics {

/// Paper Table 2 values as defaults. mu_k = 0 switches friction off.
struct FrictionParameters {
  double coefficient = 0.1;            ///< mu_k (eq. 31); Table 2: 0.1
  double velocity_coefficient = 1000;  ///< k [s/m] (eq. 32), slope at v_T = 0; Table 2: 1000 s/m
};

/// Throw ModelError naming "<field>.coefficient" unless mu_k >= 0 and k > 0, both finite.
void validate(const FrictionParameters& parameters, std::string_view field);

/// The friction force vector of eq. (32), pointing along the relative tangential velocity v_T
/// (eq. 26); the body whose velocity relative to the other is v_T receives -f_F, the other +f_F.
/// Its magnitude mu_k F_N tanh(k |v_T|) never exceeds mu_k F_N. Returns zero for F_N <= 0 or
/// v_T = 0. No allocation; noexcept.
Vector3 regularised_friction_force(const FrictionParameters& parameters, double normal_force,
                                   const Vector3& tangential_velocity_W) noexcept;

}  // namespace clearjoint::dynamics
