// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/initial_conditions.hpp"

#include <Eigen/QR>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

/// Columns of Phi_q for [rdot; omega_W] instead of [rdot; omega']: omega' = A^T omega_W.
Eigen::MatrixXd world_frame_jacobian(const ConstraintSet& constraints,
                                     const SystemKinematics& kinematics) {
  Eigen::MatrixXd J = constraints.jacobian();
  for (BodyIndex b = 0; b < kinematics.body_count(); ++b) {
    J.middleCols<3>(6 * b + 3) = J.middleCols<3>(6 * b + 3) * kinematics.body(b).rotation.transpose();
  }
  return J;
}

std::vector<int> free_columns(int column_count, std::span<const int> held) {
  std::vector<bool> is_held(static_cast<size_t>(column_count), false);
  for (int c : held) is_held[c] = true;
  std::vector<int> columns;
  for (int c = 0; c < column_count; ++c) {
    if (!is_held[c]) columns.push_back(c);
  }
  return columns;
}

/// Minimum-norm solution x of J(:, columns) x = rhs, scattered back into a full-length vector.
Eigen::VectorXd minimum_norm_step(const Eigen::MatrixXd& J, const std::vector<int>& columns,
                                  const Eigen::VectorXd& rhs) {
  // Every coordinate held: nothing may move. Eigen's decompositions assert on a matrix without
  // columns, so the step is zero here and the caller's residual check reports the contradiction.
  if (columns.empty()) return Eigen::VectorXd::Zero(J.cols());
  Eigen::MatrixXd reduced(J.rows(), static_cast<Eigen::Index>(columns.size()));
  for (size_t k = 0; k < columns.size(); ++k) reduced.col(k) = J.col(columns[k]);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(reduced);
  cod.setThreshold(kRelativeRankTolerance);
  const Eigen::VectorXd x = cod.solve(rhs);
  Eigen::VectorXd full = Eigen::VectorXd::Zero(J.cols());
  for (size_t k = 0; k < columns.size(); ++k) full[columns[k]] = x[k];
  return full;
}

void set_kinematics(SystemKinematics& kinematics, const std::vector<BodyState>& states) {
  for (BodyIndex b = 0; b < kinematics.body_count(); ++b) kinematics.set(b, states[b]);
}

void check_held(int body_count, BodyIndex body, int component, const char* what) {
  if (body < 0 || body >= body_count || component < 0 || component > 5) {
    throw ModelError(std::string(what) + " (body " + std::to_string(body) + ", component " +
                     std::to_string(component) + "): no such body coordinate");
  }
}

}  // namespace

InitialConditionReport make_consistent(MultibodySystem& system, double time,
                                       std::vector<BodyState>& states,
                                       std::span<const HeldCoordinate> held_positions,
                                       std::span<const HeldVelocity> held_velocities,
                                       const InitialConditionOptions& options) {
  const int n = system.layout().body_count;
  for (BodyIndex b = 0; b < n; ++b) validate(states[b], system.bodies()[b].name);
  InitialConditionReport report;
  ConstraintSet& constraints = system.constraints();
  if (constraints.equation_count() == 0) return report;
  SystemKinematics kinematics(n);

  std::vector<int> held_position_columns;
  for (const HeldCoordinate& h : held_positions) {
    check_held(n, h.body, h.component, "held position");
    held_position_columns.push_back(6 * h.body + h.component);
  }
  const std::vector<int> position_columns = free_columns(6 * n, held_position_columns);

  for (BodyState& s : states) s.euler_parameters.normalize();
  set_kinematics(kinematics, states);
  constraints.evaluate(time, kinematics);
  constraints.require_independent_rows();

  // Newton-Raphson on Phi(q) = 0 over the free world-frame coordinates.
  for (;; ++report.iterations) {
    Eigen::Index worst = 0;
    report.position_residual = constraints.value().cwiseAbs().maxCoeff(&worst);
    if (report.position_residual <= options.position_tolerance) break;
    if (report.iterations == options.max_iterations || !std::isfinite(report.position_residual)) {
      throw SolverError("initial positions: constraints cannot be satisfied with the held "
                        "coordinates (after " + std::to_string(report.iterations) +
                        " Newton iterations |Phi| = " + format_number(report.position_residual) +
                        " at " + constraints.describe_row(static_cast<int>(worst)) +
                        "); the joints contradict each other or too many coordinates are held");
    }
    const Eigen::VectorXd step = minimum_norm_step(world_frame_jacobian(constraints, kinematics),
                                                   position_columns, -constraints.value());
    for (BodyIndex b = 0; b < n; ++b) {
      states[b].position_W += step.segment<3>(6 * b);
      states[b].euler_parameters = rotate_in_world(states[b].euler_parameters, step.segment<3>(6 * b + 3));
    }
    set_kinematics(kinematics, states);
    constraints.evaluate(time, kinematics);
  }

  // Velocities: held components set, the others changed as little as possible.
  Eigen::VectorXd v_W(6 * n);
  for (BodyIndex b = 0; b < n; ++b) {
    v_W.segment<3>(6 * b) = states[b].velocity_W;
    v_W.segment<3>(6 * b + 3) = kinematics.body(b).rotation * states[b].angular_velocity_B;
  }
  std::vector<int> held_velocity_columns;
  for (const HeldVelocity& h : held_velocities) {
    check_held(n, h.body, h.component, "held velocity");
    require_finite("held velocity value", h.value);
    held_velocity_columns.push_back(6 * h.body + h.component);
    v_W[6 * h.body + h.component] = h.value;
  }
  const Eigen::MatrixXd J_W = world_frame_jacobian(constraints, kinematics);
  const Eigen::VectorXd residual = J_W * v_W + constraints.time_derivative();
  v_W += minimum_norm_step(J_W, free_columns(6 * n, held_velocity_columns), -residual);
  Eigen::Index worst = 0;
  report.velocity_residual =
      (J_W * v_W + constraints.time_derivative()).cwiseAbs().maxCoeff(&worst);
  if (!(report.velocity_residual <= options.velocity_tolerance * (1.0 + v_W.cwiseAbs().maxCoeff()))) {
    throw SolverError("initial velocities: the held velocities contradict the constraints "
                      "(|Phi_q v + Phi_t| = " + format_number(report.velocity_residual) + " at " +
                      constraints.describe_row(static_cast<int>(worst)) + ")");
  }
  for (BodyIndex b = 0; b < n; ++b) {
    states[b].velocity_W = v_W.segment<3>(6 * b);
    states[b].angular_velocity_B = kinematics.body(b).rotation.transpose() * v_W.segment<3>(6 * b + 3);
  }
  return report;
}

}  // namespace clearjoint::dynamics
