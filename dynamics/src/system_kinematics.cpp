// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/system_kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace clearjoint::dynamics {

namespace {

void fill(BodyKinematics& k, const Vector3& r, const Vector4& p, const Vector3& rdot,
          const Vector3& omega_B) {
  k.position_W = r;
  k.rotation = rotation_from_euler_parameters(p / p.norm());
  k.velocity_W = rdot;
  k.angular_velocity_B = omega_B;
  k.angular_velocity_W = k.rotation * omega_B;
}

}  // namespace

SystemKinematics::SystemKinematics(int body_count) : bodies_(static_cast<size_t>(body_count)) {}

void SystemKinematics::update(double time, std::span<const double> y) {
  const StateLayout layout{body_count(), 0};
  time_ = time;
  euler_norm_drift_ = 0.0;
  for (BodyIndex b = 0; b < body_count(); ++b) {
    const double* q = y.data() + layout.position_offset(b);
    const double* v = y.data() + layout.velocity_offset(b);
    const Vector4 p(q[3], q[4], q[5], q[6]);
    fill(bodies_[b], Vector3(q[0], q[1], q[2]), p, Vector3(v[0], v[1], v[2]),
         Vector3(v[3], v[4], v[5]));
    euler_norm_drift_ = std::max(euler_norm_drift_, std::abs(p.norm() - 1.0));
  }
}

void SystemKinematics::set(BodyIndex b, const BodyState& state) {
  fill(bodies_[b], state.position_W, state.euler_parameters, state.velocity_W,
       state.angular_velocity_B);
}

}  // namespace clearjoint::dynamics
