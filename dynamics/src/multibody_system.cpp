// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/multibody_system.hpp"

#include <algorithm>
#include <cmath>

#include "clearjoint/dynamics/errors.hpp"
#include "schur_block.hpp"
#include "small_cholesky.hpp"

namespace clearjoint::dynamics {

MultibodySystem::MultibodySystem(std::vector<BodyProperties> bodies,
                                 std::vector<JointEquations> joints,
                                 std::vector<std::unique_ptr<ForceElement>> force_elements,
                                 const BaumgarteParameters& baumgarte)
    : bodies_(std::move(bodies)),
      forces_(std::move(force_elements)),
      constraints_(std::move(joints), static_cast<int>(bodies_.size())),
      baumgarte_(baumgarte),
      kinematics_(static_cast<int>(bodies_.size())),
      applied_(kinematics_) {
  const int n = static_cast<int>(bodies_.size());
  for (int b = 0; b < n; ++b) validate(bodies_[b], "bodies[" + std::to_string(b) + "]");
  require_finite("baumgarte.alpha", baumgarte_.alpha);
  require_finite("baumgarte.beta", baumgarte_.beta);
  if (baumgarte_.alpha < 0.0 || baumgarte_.beta < 0.0) {
    throw ModelError("baumgarte = (" + format_number(baumgarte_.alpha) + ", " +
                     format_number(baumgarte_.beta) + "): alpha and beta must be >= 0");
  }
  layout_.body_count = n;
  for (size_t e = 0; e < forces_.size(); ++e) {
    extra_offsets_.push_back(layout_.extra_count);
    const int count = forces_[e]->extra_state_count();
    layout_.extra_count += count;
    const ForceEvents* events = events_of(*forces_[e]);
    if (events != nullptr && count > 0) events_.push_back({e, events});
  }
  inverse_mass_.resize(6 * n);
  for (int b = 0; b < n; ++b) {
    inverse_mass_.segment<3>(6 * b).setConstant(1.0 / bodies_[b].mass);
    inverse_mass_.segment<3>(6 * b + 3) = bodies_[b].principal_inertia.cwiseInverse();
  }
  const int m = constraints_.equation_count();
  g_ = Eigen::VectorXd::Zero(6 * n);
  accelerations_ = Eigen::VectorXd::Zero(6 * n);
  multipliers_ = Eigen::VectorXd::Zero(m);
  schur_rhs_ = Eigen::VectorXd::Zero(m);
  schur_ = Eigen::MatrixXd::Zero(m, m);
  // Pairs of joint sides on the same (moving) body: the non-zero blocks of the Schur matrix.
  const std::span<const JointEquations> equations = constraints_.joints();
  const int joint_count = static_cast<int>(equations.size());
  auto body_of = [&](int k, int side) {
    return side == 0 ? equations[k].body_i() : equations[k].body_j();
  };
  for (int later = 0; later < joint_count; ++later) {
    for (int earlier = 0; earlier <= later; ++earlier) {
      for (int later_side = 0; later_side < 2; ++later_side) {
        for (int earlier_side = 0; earlier_side < 2; ++earlier_side) {
          const BodyIndex b = body_of(later, later_side);
          if (b != kGround && b == body_of(earlier, earlier_side)) {
            shared_bodies_.push_back({later, later_side, earlier, earlier_side});
          }
        }
      }
    }
  }
  scaled_jacobians_.assign(equations.size(), {ConstraintRows::Block::Zero(), ConstraintRows::Block::Zero()});
  // L's non-zeros: the blocks of joints on a shared body, and their fill-in.
  std::vector<std::vector<bool>> coupled(equations.size(), std::vector<bool>(equations.size(), false));
  for (const SharedBody& pair : shared_bodies_) coupled[pair.later][pair.earlier] = true;
  std::vector<int> sizes;
  for (const JointEquations& joint : equations) sizes.push_back(joint.equation_count());
  detail::block_pattern(sizes, [&](int later, int earlier) { return bool(coupled[later][earlier]); },
                        schur_column_start_, schur_rows_below_);
}

BodyIndex MultibodySystem::body_index(std::string_view name, std::string_view field) const {
  if (name == kGroundName) return kGround;
  for (size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].name == name) return static_cast<BodyIndex>(b);
  }
  throw ModelError(std::string(field) + " = \"" + std::string(name) +
                   "\": no body of that name (use \"ground\" for the world frame)");
}

std::vector<double> MultibodySystem::pack(std::span<const BodyState> states) const {
  std::vector<double> y(static_cast<size_t>(layout_.size()), 0.0);
  for (BodyIndex b = 0; b < layout_.body_count; ++b) {
    const BodyState& s = states[b];
    double* q = y.data() + layout_.position_offset(b);
    double* v = y.data() + layout_.velocity_offset(b);
    Eigen::Map<Vector3>{q} = s.position_W;
    Eigen::Map<Vector4>{q + 3} = s.euler_parameters;
    Eigen::Map<Vector3>{v} = s.velocity_W;
    Eigen::Map<Vector3>{v + 3} = s.angular_velocity_B;
  }
  for (size_t e = 0; e < forces_.size(); ++e) {
    forces_[e]->initial_extra_state(std::span<double>(
        y.data() + layout_.extra_offset() + extra_offsets_[e],
        static_cast<size_t>(forces_[e]->extra_state_count())));
  }
  return y;
}

BodyState MultibodySystem::body_state(std::span<const double> y, BodyIndex b) const {
  const double* q = y.data() + layout_.position_offset(b);
  const double* v = y.data() + layout_.velocity_offset(b);
  BodyState s;
  s.position_W = Eigen::Map<const Vector3>(q);
  s.euler_parameters = Eigen::Map<const Vector4>(q + 3);
  s.velocity_W = Eigen::Map<const Vector3>(v);
  s.angular_velocity_B = Eigen::Map<const Vector3>(v + 3);
  return s;
}

void MultibodySystem::set_external_load(BodyIndex b, const Vector3& force_W, const Vector3& moment_W) {
  if (b < 0 || b >= layout_.body_count) {
    throw ModelError("external load: body index " + std::to_string(b) + " is not a moving body");
  }
  if (!force_W.allFinite() || !moment_W.allFinite()) {
    throw ModelError("external load on body " + std::to_string(b) + ": force and moment must be finite");
  }
  for (ExternalLoad& load : external_loads_) {
    if (load.body == b) {
      load.force_W = force_W;
      load.moment_W = moment_W;
      return;
    }
  }
  external_loads_.push_back({b, force_W, moment_W});
}

void MultibodySystem::derivative(double time, std::span<const double> y, std::span<double> dydt) {
  const int n = layout_.body_count;
  kinematics_.update(time, y);

  // Position coordinates: rdot and the Euler-parameter rates.
  for (BodyIndex b = 0; b < n; ++b) {
    const double* q = y.data() + layout_.position_offset(b);
    double* q_rate = dydt.data() + layout_.position_offset(b);
    const BodyKinematics& k = kinematics_.body(b);
    Eigen::Map<Vector3>{q_rate} = k.velocity_W;
    Eigen::Map<Vector4>{q_rate + 3} =
        euler_parameter_rate(Eigen::Map<const Vector4>(q + 3), k.angular_velocity_B);
  }

  // g of eq. (35): applied forces, then the moments in the body frame with the gyroscopic term.
  applied_.clear();
  std::fill(dydt.begin() + layout_.extra_offset(), dydt.end(), 0.0);
  for (size_t e = 0; e < forces_.size(); ++e) {
    const size_t offset = static_cast<size_t>(layout_.extra_offset() + extra_offsets_[e]);
    const size_t count = static_cast<size_t>(forces_[e]->extra_state_count());
    const ForceContext context{time, kinematics_, y.subspan(offset, count),
                               dydt.subspan(offset, count)};
    forces_[e]->add_forces(context, applied_);
  }
  for (const ExternalLoad& load : external_loads_) {
    applied_.add_force(load.body, load.force_W);
    applied_.add_moment(load.body, load.moment_W);
  }
  for (BodyIndex b = 0; b < n; ++b) {
    const BodyKinematics& k = kinematics_.body(b);
    const Vector3& w = k.angular_velocity_B;
    g_.segment<3>(6 * b) = applied_.force_W(b);
    g_.segment<3>(6 * b + 3) = k.rotation.transpose() * applied_.moment_W(b) -
                               w.cross(bodies_[b].principal_inertia.cwiseProduct(w));  // eq. (35)
  }

  if (constraints_.equation_count() == 0) {
    accelerations_ = inverse_mass_.cwiseProduct(g_);
  } else {
    solve_constrained_accelerations(time, y);
  }
  Eigen::Map<Eigen::VectorXd>(dydt.data() + layout_.velocity_offset(0), layout_.velocity_size()) =
      accelerations_;
}

void MultibodySystem::solve_constrained_accelerations(double time, std::span<const double> y) {
  using Block = ConstraintRows::Block;
  using Column = ConstraintRows::Column;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  constraints_.evaluate(time, kinematics_);
  const std::span<const JointEquations> joints = constraints_.joints();
  const int joint_count = static_cast<int>(joints.size());
  const double* v = y.data() + layout_.velocity_offset(0);
  auto body_of = [&](int k, int side) { return side == 0 ? joints[k].body_i() : joints[k].body_j(); };
  auto jacobian_of = [&](int k, int side) -> const Block& {
    const ConstraintRows& rows = constraints_.joint_rows(k);
    return side == 0 ? rows.jacobian_i : rows.jacobian_j;
  };

  // Per joint: Phi_q M^-1 on each body, and the Schur right-hand side
  // Phi_q M^-1 g - (gamma - 2 alpha dPhi/dt - beta^2 Phi), eq. (38), dPhi/dt = Phi_q v + Phi_t.
  for (int k = 0; k < joint_count; ++k) {
    const ConstraintRows& rows = constraints_.joint_rows(k);
    Column velocity_rows = rows.time_derivative;
    Column scaled_force_rows = Column::Zero();
    for (int side = 0; side < 2; ++side) {
      const BodyIndex b = body_of(k, side);
      if (b == kGround) continue;
      const Block& jacobian = jacobian_of(k, side);
      Block& scaled = scaled_jacobians_[k][side];
      scaled.noalias() = jacobian * inverse_mass_.segment<6>(6 * b).asDiagonal();
      velocity_rows.noalias() += jacobian * Eigen::Map<const Vector6>(v + 6 * b);
      scaled_force_rows.noalias() += scaled * g_.segment<6>(6 * b);
    }
    const Column stabilised_gamma = rows.gamma - (2.0 * baumgarte_.alpha) * velocity_rows -
                                    (baumgarte_.beta * baumgarte_.beta) * rows.value;
    schur_rhs_.segment(constraints_.first_row(k), rows.count) =
        (scaled_force_rows - stabilised_gamma).head(rows.count);
  }

  // Phi_q M^-1 Phi_q^T: one block per pair of joints on a shared body (lower triangle).
  schur_.setZero();
  for (const SharedBody& pair : shared_bodies_) {
    detail::add_product_block(scaled_jacobians_[pair.later][pair.later_side],
                              jacobian_of(pair.earlier, pair.earlier_side),
                              constraints_.joint_rows(pair.later).count,
                              constraints_.joint_rows(pair.earlier).count,
                              &schur_(constraints_.first_row(pair.later), constraints_.first_row(pair.earlier)),
                              schur_.outerStride());
  }
  const detail::CholeskyPattern pattern{schur_column_start_, schur_rows_below_};
  detail::CholeskyPivots pivots;
  const bool factored = detail::factor_cholesky_in_place(schur_, pattern, pivots);
  if (!factored || !(pivots.smallest > kRelativePivotTolerance * pivots.largest)) {
    throw SolverError("the constraint Jacobian lost rank at t = " + format_number(time) +
                      " (smallest/largest pivot of Phi_q M^-1 Phi_q^T = " +
                      format_number(pivots.largest > 0.0 ? pivots.smallest / pivots.largest : 0.0) +
                      "): redundant joints or a singular configuration of the mechanism");
  }
  multipliers_ = schur_rhs_;
  detail::solve_cholesky_in_place(schur_, pattern, multipliers_);

  // eq. (36): M dv/dt = g - Phi_q^T lambda, body by body.
  accelerations_ = g_;
  for (int k = 0; k < joint_count; ++k) {
    const int count = constraints_.joint_rows(k).count;
    Column lambda = Column::Zero();
    lambda.head(count) = multipliers_.segment(constraints_.first_row(k), count);
    for (int side = 0; side < 2; ++side) {
      const BodyIndex b = body_of(k, side);
      if (b == kGround) continue;
      accelerations_.segment<6>(6 * b).noalias() -= jacobian_of(k, side).transpose() * lambda;
    }
  }
  accelerations_.array() *= inverse_mass_.array();
}

bool MultibodySystem::update_extra_states(double time, std::span<double> y) {
  if (layout_.extra_count == 0) return false;
  kinematics_.update(time, y);
  bool changed = false;
  for (const ElementEvents& e : events_) {
    const size_t offset = static_cast<size_t>(layout_.extra_offset() + extra_offsets_[e.element]);
    const size_t count = static_cast<size_t>(forces_[e.element]->extra_state_count());
    changed = e.events->update_extra_state(time, kinematics_, y.subspan(offset, count)) || changed;
  }
  return changed;
}

bool MultibodySystem::begins_event(double time, std::span<const double> y) {
  if (layout_.extra_count == 0) return false;
  kinematics_.update(time, y);
  for (const ElementEvents& e : events_) {
    if (e.events->begins_event(kinematics_, extra_state(y, e.element))) return true;
  }
  return false;
}

std::span<const double> MultibodySystem::extra_state(std::span<const double> y, size_t e) const {
  return y.subspan(static_cast<size_t>(layout_.extra_offset() + extra_offsets_[e]),
                   static_cast<size_t>(forces_[e]->extra_state_count()));
}

double MultibodySystem::kinetic_energy(std::span<const double> y) const {
  double energy = 0.0;
  for (BodyIndex b = 0; b < layout_.body_count; ++b) {
    const double* v = y.data() + layout_.velocity_offset(b);
    const Eigen::Map<const Vector3> velocity(v);
    const Eigen::Map<const Vector3> omega(v + 3);
    energy += 0.5 * bodies_[b].mass * velocity.squaredNorm() +
              0.5 * omega.dot(bodies_[b].principal_inertia.cwiseProduct(omega));
  }
  return energy;
}

double MultibodySystem::potential_energy(double time, std::span<const double> y) {
  kinematics_.update(time, y);
  double energy = 0.0;
  for (const auto& element : forces_) energy += element->potential_energy(kinematics_);
  return energy;
}

ConstraintViolation MultibodySystem::constraint_violation(double time, std::span<const double> y) {
  kinematics_.update(time, y);
  if (constraints_.equation_count() == 0) return {};
  constraints_.evaluate(time, kinematics_);
  const Eigen::Map<const Eigen::VectorXd> v(y.data() + layout_.velocity_offset(0),
                                            layout_.velocity_size());
  ConstraintViolation violation;
  violation.position = constraints_.value().cwiseAbs().maxCoeff();
  violation.velocity =
      (constraints_.jacobian() * v + constraints_.time_derivative()).cwiseAbs().maxCoeff();
  return violation;
}

}  // namespace clearjoint::dynamics
