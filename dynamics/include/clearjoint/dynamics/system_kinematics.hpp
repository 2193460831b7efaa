// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The state vector layout used by the integrator, and the per-body kinematics derived from it
/// once per right-hand-side evaluation (what joints and force elements read).

#include <span>
#include <vector>

#include "clearjoint/dynamics/body.hpp"

namespace clearjoint::dynamics {

/// y = [ r_0 p_0 ... r_{n-1} p_{n-1} | rdot_0 omega'_0 ... | extra states of force elements ].
/// Positions use 7 coordinates per body (eq. 33's q), velocities 6 (v = [rdot; omega'], the
/// body-frame angular velocity), so the Jacobians below are 6 columns per body.
struct StateLayout {
  int body_count = 0;
  int extra_count = 0;

  int position_offset(BodyIndex b) const { return 7 * b; }
  int velocity_offset(BodyIndex b) const { return 7 * body_count + 6 * b; }
  int extra_offset() const { return 13 * body_count; }
  int velocity_size() const { return 6 * body_count; }
  int size() const { return 13 * body_count + extra_count; }
};

/// What joints and force elements need of one body, all derived from the state.
struct BodyKinematics {
  Vector3 position_W = Vector3::Zero();          ///< r, the mass centre
  Matrix3 rotation = Matrix3::Identity();        ///< A(p/|p|): body to world
  Vector3 velocity_W = Vector3::Zero();          ///< rdot
  Vector3 angular_velocity_B = Vector3::Zero();  ///< omega'
  Vector3 angular_velocity_W = Vector3::Zero();  ///< A omega'

  /// World position of a point given in the body frame: r + A s'.
  Vector3 point_W(const Vector3& s_B) const { return position_W + rotation * s_B; }
  /// World velocity of that point: rdot + omega x (A s').
  Vector3 point_velocity_W(const Vector3& s_B) const {
    return velocity_W + angular_velocity_W.cross(rotation * s_B);
  }
};

/// Kinematics of every body at one instant. The ground (kGround) is the world frame at rest.
class SystemKinematics {
 public:
  explicit SystemKinematics(int body_count);

  /// Read r, p, rdot, omega' of every body from y (layout above). The rotation uses p/|p|, so the
  /// physics does not see the drift of |p|; euler_norm_drift() reports it. No allocation.
  void update(double time, std::span<const double> y);
  /// Set one body directly (used when building models and in tests).
  void set(BodyIndex b, const BodyState& state);
  /// Set one body's kinematics as another engine computed them (engines/: Simbody, MuJoCo give
  /// rotation matrices, not Euler parameters). Precondition: rotation orthonormal and
  /// angular_velocity_W == rotation * angular_velocity_B.
  void set_kinematics(BodyIndex b, const BodyKinematics& kinematics) { bodies_[b] = kinematics; }

  const BodyKinematics& body(BodyIndex b) const { return b == kGround ? ground_ : bodies_[b]; }
  int body_count() const { return static_cast<int>(bodies_.size()); }
  double time() const { return time_; }
  /// max over bodies of | |p| - 1 | at the last update().
  double euler_norm_drift() const { return euler_norm_drift_; }

 private:
  std::vector<BodyKinematics> bodies_;
  BodyKinematics ground_;
  double time_ = 0.0;
  double euler_norm_drift_ = 0.0;
};

}  // namespace clearjoint::dynamics
