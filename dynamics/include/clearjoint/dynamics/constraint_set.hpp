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

  /// Evaluate every joint's rows (joint_rows()) at this instant. No allocation. The stacked
  /// value(), time_derivative(), jacobian() and gamma() are assembled from them when first asked
  /// for after it: a right-hand side reads the joints' blocks only (MultibodySystem::derivative).
  /// The accessors fill that cache, so a ConstraintSet is not shared between threads.
  void evaluate(double time, const SystemKinematics& kinematics);

  const Eigen::VectorXd& value() const {
    assemble_dense();
    return value_;
  }
  const Eigen::VectorXd& time_derivative() const {
    assemble_dense();
    return time_derivative_;
  }
  const Eigen::MatrixXd& jacobian() const {
    assemble_dense();
    return jacobian_;
  }
  const Eigen::VectorXd& gamma() const {
    assemble_dense();
    return gamma_;
  }
  /// How many times the stacked arrays above were assembled (once per evaluate() asked for).
  long dense_assemblies() const { return dense_assemblies_; }
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
  /// Copy joint_rows_ into the stacked arrays unless they hold the last evaluate() already.
  void assemble_dense() const;
  // The stacked arrays: a cache of joint_rows_, filled on demand by the const accessors.
  mutable Eigen::VectorXd value_;
  mutable Eigen::VectorXd time_derivative_;
  mutable Eigen::MatrixXd jacobian_;
  mutable Eigen::VectorXd gamma_;
  mutable bool dense_current_ = true;  ///< all zero, as joint_rows_ before the first evaluate()
  mutable long dense_assemblies_ = 0;
};

}  // namespace clearjoint::dynamics
