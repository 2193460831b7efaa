// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The constraint stabilisation gains of the equations of motion (multibody_system.hpp), plain
/// data.

namespace clearjoint::dynamics {

/// Feedback gains of eq. (38): gamma - 2 alpha dPhi/dt - beta^2 Phi. Paper Table 2: 5 and 5.
struct BaumgarteParameters {
  double alpha = 5.0;  ///< [1/s], velocity feedback
  double beta = 5.0;   ///< [1/s], position feedback
};

}  // namespace clearjoint::dynamics
