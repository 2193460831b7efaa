// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/constraint_set.hpp"

#include <Eigen/SVD>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

int rank_of(const Eigen::MatrixXd& rows) {
  if (rows.rows() == 0) return 0;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rows);
  const auto& sigma = svd.singularValues();
  if (sigma.size() == 0 || sigma[0] == 0.0) return 0;
  int rank = 0;
  for (Eigen::Index k = 0; k < sigma.size(); ++k) rank += sigma[k] > kRelativeRankTolerance * sigma[0];
  return rank;
}

}  // namespace

ConstraintSet::ConstraintSet(std::vector<JointEquations> joints, int body_count)
    : joints_(std::move(joints)), body_count_(body_count), joint_rows_(joints_.size()) {
  for (const JointEquations& joint : joints_) {
    first_rows_.push_back(equation_count_);
    equation_count_ += joint.equation_count();
  }
  value_ = Eigen::VectorXd::Zero(equation_count_);
  time_derivative_ = Eigen::VectorXd::Zero(equation_count_);
  gamma_ = Eigen::VectorXd::Zero(equation_count_);
  jacobian_ = Eigen::MatrixXd::Zero(equation_count_, 6 * body_count_);
}

void ConstraintSet::evaluate(double time, const SystemKinematics& kinematics) {
  for (size_t k = 0; k < joints_.size(); ++k) joints_[k].evaluate(time, kinematics, joint_rows_[k]);
  dense_current_ = false;
}

void ConstraintSet::assemble_dense() const {
  if (dense_current_) return;
  for (size_t k = 0; k < joints_.size(); ++k) {
    const JointEquations& joint = joints_[k];
    const ConstraintRows& rows = joint_rows_[k];
    const int row = first_rows_[k];
    const int n = rows.count;
    value_.segment(row, n) = rows.value.head(n);
    time_derivative_.segment(row, n) = rows.time_derivative.head(n);
    gamma_.segment(row, n) = rows.gamma.head(n);
    // Only the columns of bodies i and j are ever non-zero in these rows; they were zeroed at
    // construction and no other joint writes to them.
    if (joint.body_i() != kGround) {
      jacobian_.block(row, 6 * joint.body_i(), n, 6) = rows.jacobian_i.topRows(n);
    }
    if (joint.body_j() != kGround) {
      jacobian_.block(row, 6 * joint.body_j(), n, 6) = rows.jacobian_j.topRows(n);
    }
  }
  ++dense_assemblies_;
  dense_current_ = true;
}

void ConstraintSet::require_independent_rows() const {
  int previous_rank = 0;
  for (size_t k = 0; k < joints_.size(); ++k) {
    const int end = first_rows_[k] + joints_[k].equation_count();
    const int rank = rank_of(jacobian().topRows(end));
    if (rank < end) {
      const int lost = end - rank;
      throw SolverError("constraint Jacobian is rank deficient: joint '" + joints_[k].name() +
                        "' (" + std::string(to_string(joints_[k].type())) + ") adds only " +
                        std::to_string(rank - previous_rank) + " independent equation(s) of " +
                        std::to_string(joints_[k].equation_count()) + " (" +
                        std::to_string(lost) +
                        " redundant with the joints listed before it, or the mechanism is in a "
                        "singular configuration)");
    }
    previous_rank = rank;
  }
}

std::string ConstraintSet::describe_row(int row) const {
  for (size_t k = joints_.size(); k-- > 0;) {
    if (row >= first_rows_[k]) {
      return "joint '" + joints_[k].name() + "' (" + std::string(to_string(joints_[k].type())) +
             "), equation " + std::to_string(row - first_rows_[k]);
    }
  }
  return "row " + std::to_string(row);
}

}  // namespace clearjoint::dynamics
