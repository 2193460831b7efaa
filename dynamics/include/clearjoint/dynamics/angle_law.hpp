// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A prescribed relative angle and its law in time: what an angle driver reads from a model
/// (joint_description.hpp) and what its constraint row evaluates (constraint_primitives.hpp).

namespace clearjoint::dynamics {

/// A prescribed angle theta(t) with its first two time derivatives.
struct AngleValue {
  double angle = 0.0;
  double rate = 0.0;
  double acceleration = 0.0;
};

/// theta(t) = rate t + acceleration t^2 / 2, measured from the relative orientation at t = 0.
struct AngleLaw {
  double rate = 0.0;
  double acceleration = 0.0;
  AngleValue at(double time) const {
    return {rate * time + 0.5 * acceleration * time * time, rate + acceleration * time,
            acceleration};
  }
};

}  // namespace clearjoint::dynamics
