// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The constants of a linear spring-damper (spring_damper.hpp), plain data.

namespace clearjoint::dynamics {

struct SpringDamperParameters {
  double stiffness = 0.0;    ///< k [N/m], >= 0
  double damping = 0.0;      ///< c [N s/m], >= 0
  double free_length = 0.0;  ///< l0 [m], >= 0
};

}  // namespace clearjoint::dynamics
