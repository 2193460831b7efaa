// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// All joints of a system stacked into eq. (33) Phi(q, t) = 0 and eq. (34) Phi_q dv/dt = gamma,
/// with the Jacobian Phi_q as a dense m x 6n matrix (columns [rdot_b; omega'_b] per body b), and
/// joint by joint as its non-zero blocks (each joint's rows touch the columns of two bodies only),
/// which the right-hand side uses.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "clearjoint/dynamics/joint_equations.hpp"

namespace clearjoint::dynamics {

/// Rank decisions on Phi_q: a singular value below this fraction of the largest counts as zero.
/// Jacobian entries are O(1) for translations and O(body size) for rotations, so 1e-9 separates
/// genuine dependence (rounding level, ~1e-16) from any mechanism we model by many orders.
inline constexpr double kRelativeRankTolerance = 1e-9;

class ConstraintSet {
 public:
  ConstraintSet(std::vector<JointEquations> joints, int body_count);

  int equation_count() const { return equation_count_; }
  int body_count() const { return body_count_; }
  std::span<const JointEquations> joints() const { return joints_; }
  /// Row of the first equation of joint k in Phi.
  int first_row(int k) const { return first_rows_[k]; }

  /// Fill value(), time_derivative(), jacobian(), gamma() at this instant. No allocation.
  void evaluate(double time, const SystemKinematics& kinematics);

  const Eigen::VectorXd& value() const { return value_; }
  const Eigen::VectorXd& time_derivative() const { return time_derivative_; }
  const Eigen::MatrixXd& jacobian() const { return jacobian_; }
  const Eigen::VectorXd& gamma() const { return gamma_; }
  /// Joint k's rows at the last evaluate(): Phi_q's blocks for the columns of bodies i and j
  /// (rows beyond the joint's equation count are zero).
  const ConstraintRows& joint_rows(int k) const { return joint_rows_[k]; }

  /// Throw SolverError if the evaluated Phi_q has dependent rows, naming the first joint whose
  /// equations add nothing to those before it (a redundant joint, or a singular configuration).
  void require_independent_rows() const;

  /// "joint 'crank pin' (spherical), equation 2" for row `row` of Phi.
  std::string describe_row(int row) const;

 private:
  std::vector<JointEquations> joints_;
  std::vector<int> first_rows_;
  int body_count_ = 0;
  int equation_count_ = 0;
  std::vector<ConstraintRows> joint_rows_;
  Eigen::VectorXd value_;
  Eigen::VectorXd time_derivative_;
  Eigen::MatrixXd jacobian_;
  Eigen::VectorXd gamma_;
};

}  // namespace clearjoint::dynamics
