// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Bodies, ideal joints and force elements, and the right-hand side of the equations of motion:
/// Newton-Euler (eq. 35) with Lagrange multipliers (eq. 36) and Baumgarte stabilisation (eq. 38).

#include <Eigen/Core>
#include <array>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "clearjoint/dynamics/baumgarte_parameters.hpp"
#include "clearjoint/dynamics/constraint_set.hpp"
#include "clearjoint/dynamics/force_element.hpp"
#include "clearjoint/dynamics/force_events.hpp"

namespace clearjoint::dynamics {

/// Cholesky pivots (squared diagonal of L) of Phi_q M^-1 Phi_q^T below this fraction of the
/// largest mean the constraint Jacobian lost rank. Each pivot lies between the smallest and the
/// largest eigenvalue, so their ratio is at least 1 / cond(Phi_q M^-1 Phi_q^T). Legitimate pivot ratios are bounded by cond(Phi_q)^2 cond(M); for the
/// models here that is below 1e8, rounding-level dependence shows up near 1e-16: 1e-12 is between.
inline constexpr double kRelativePivotTolerance = 1e-12;

/// Largest constraint residuals: max |Phi| (eq. 33) and max |Phi_q v + dPhi/dt| (its derivative).
struct ConstraintViolation {
  double position = 0.0;
  double velocity = 0.0;
};

/// The whole multibody model. Not copyable (force accumulators point at its own kinematics) and
/// not thread-safe: derivative() reuses preallocated work space.
class MultibodySystem {
 public:
  MultibodySystem(std::vector<BodyProperties> bodies, std::vector<JointEquations> joints,
                  std::vector<std::unique_ptr<ForceElement>> force_elements,
                  const BaumgarteParameters& baumgarte);
  MultibodySystem(const MultibodySystem&) = delete;
  MultibodySystem& operator=(const MultibodySystem&) = delete;

  const StateLayout& layout() const { return layout_; }
  std::span<const BodyProperties> bodies() const { return bodies_; }
  std::span<const std::unique_ptr<ForceElement>> force_elements() const { return forces_; }
  ConstraintSet& constraints() { return constraints_; }
  const ConstraintSet& constraints() const { return constraints_; }
  const BaumgarteParameters& baumgarte() const { return baumgarte_; }
  /// Index of the body called `name` ("ground" gives kGround); throws ModelError naming `field`.
  BodyIndex body_index(std::string_view name, std::string_view field) const;

  /// State vector from body states; force elements' extra state at their initial values.
  std::vector<double> pack(std::span<const BodyState> states) const;
  /// One body's state read back from y.
  BodyState body_state(std::span<const double> y, BodyIndex b) const;

  /// dy/dt at (t, y): r' = rdot, p' = L(p)^T omega' / 2, and dv/dt, lambda from eq. (38) solved
  /// by the Schur complement (Phi_q M^-1 Phi_q^T) lambda = Phi_q M^-1 g - gamma_stabilised,
  /// dv/dt = M^-1 (g - Phi_q^T lambda). M is diagonal in these coordinates (principal axes).
  /// The products use Phi_q's block structure (a joint's rows touch two bodies' columns), the
  /// Schur matrix is assembled from joint-pair blocks that share a body and factored once
  /// (Cholesky, in place). Throws SolverError if Phi_q loses rank. No heap allocation.
  void derivative(double time, std::span<const double> y, std::span<double> dydt);

  /// Let the force elements with events and extra state change it discretely at (t, y), an
  /// accepted state (ForceEvents::update_extra_state). Returns true if any element changed y.
  bool update_extra_states(double time, std::span<double> y);
  /// True if any force element with events would record one that begins at (t, y)
  /// (ForceEvents::begins_event). Updates kinematics(). No allocation.
  bool begins_event(double time, std::span<const double> y);
  /// Force element e's extra variables within y.
  std::span<const double> extra_state(std::span<const double> y, size_t e) const;

  /// A load the caller applies to body b from now on (a control, a co-simulation's coupling):
  /// a force at the mass centre and a moment, world frame, added to g after the force elements
  /// (replacing b's earlier load). Constant until set again or cleared. Without loads nothing is
  /// added, so a model's answers do not change.
  void set_external_load(BodyIndex b, const Vector3& force_W, const Vector3& moment_W);
  void clear_external_loads() { external_loads_.clear(); }

  /// Results of the last derivative() call.
  const SystemKinematics& kinematics() const { return kinematics_; }
  const Eigen::VectorXd& accelerations() const { return accelerations_; }  ///< dv/dt
  const Eigen::VectorXd& multipliers() const { return multipliers_; }      ///< lambda
  const Eigen::VectorXd& generalised_forces() const { return g_; }         ///< g, eq. (35)

  double kinetic_energy(std::span<const double> y) const;
  /// Sum of the force elements' potential energies (updates kinematics()).
  double potential_energy(double time, std::span<const double> y);
  /// Constraint residuals at (t, y) (updates kinematics() and constraints()).
  ConstraintViolation constraint_violation(double time, std::span<const double> y);

 private:
  /// dv/dt and lambda of eq. (38) from kinematics_ and g_ (derivative()'s constrained part).
  void solve_constrained_accelerations(double time, std::span<const double> y);

  struct ExternalLoad {
    BodyIndex body;
    Vector3 force_W;
    Vector3 moment_W;
  };

  std::vector<BodyProperties> bodies_;
  std::vector<std::unique_ptr<ForceElement>> forces_;
  std::vector<ExternalLoad> external_loads_;
  std::vector<int> extra_offsets_;
  /// The elements with events and extra state (events_of, found once): what the integrator's
  /// discrete updates and onset probes ask.
  struct ElementEvents {
    size_t element = 0;
    const ForceEvents* events = nullptr;
  };
  std::vector<ElementEvents> events_;
  StateLayout layout_;
  ConstraintSet constraints_;
  BaumgarteParameters baumgarte_;
  SystemKinematics kinematics_;
  GeneralisedForces applied_;
  Eigen::VectorXd inverse_mass_;  ///< diagonal of M^-1: 1/m (x3), 1/J'_k (x3) per body
  Eigen::VectorXd g_;
  Eigen::VectorXd accelerations_;
  Eigen::VectorXd multipliers_;
  /// Two joints' Jacobian blocks on one shared body: their product is a block of the Schur
  /// matrix (rows of `later`, columns of `earlier`, on or below the diagonal).
  struct SharedBody {
    int later = 0;
    int later_side = 0;  ///< 0: the joint's body i, 1: its body j
    int earlier = 0;
    int earlier_side = 0;
  };
  std::vector<SharedBody> shared_bodies_;
  /// Phi_q M^-1 per joint and side (0: body i, 1: body j), zero for the ground.
  std::vector<std::array<ConstraintRows::Block, 2>> scaled_jacobians_;
  Eigen::VectorXd schur_rhs_;
  Eigen::MatrixXd schur_;  ///< lower triangle assembled, then factored in place (L)
  /// Rows below the diagonal that can be non-zero in L, column by column (small_cholesky.hpp,
  /// detail::CholeskyPattern): the blocks of shared_bodies_ and their fill-in.
  std::vector<int> schur_column_start_;
  std::vector<int> schur_rows_below_;
};

}  // namespace clearjoint::dynamics
