// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Moreau-Jean time-stepping (theta-method) of a clearjoint model (docs/nonsmooth.md): ideal
/// joints as bilateral constraints at velocity level with a mass-weighted position projection,
/// each clearance joint's contacts as unilateral constraints with Coulomb friction and Newton's
/// impact law, the per-step frictional contact problem solved by Siconos Numerics (fc3d NSGS).

#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "clearjoint/dynamics/model_description.hpp"
#include "clearjoint/dynamics/multibody_system.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/nonsmooth/fclib_export.hpp"

namespace clearjoint::nonsmooth {

using dynamics::Matrix3;
using dynamics::Vector3;
using dynamics::Vector4;

/// One contact of the last step's problem (active: in the index set, gap + h u_N / 2 <= 0).
struct ContactPercussion {
  int joint = 0;  ///< index among the model's clearance joints (MoreauJean::clearance_joint_names)
  geometry::ContactType type = geometry::ContactType::radial;
  geometry::ContactBase base = geometry::ContactBase::mid;
  double gap = 0.0;                          ///< at the step's start [m], < 0 penetrating
  Vector3 normal_W = Vector3::UnitX();       ///< the journal's separating direction
  Vector3 journal_point_W = Vector3::Zero();
  Vector3 percussion_on_journal_W = Vector3::Zero();  ///< impulse of the step [N s]
  /// Its moment about the journal's axis centre P_j [N m s], as the compliant joint's mx..mz.
  Vector3 moment_on_journal_W = Vector3::Zero();
  double normal_percussion = 0.0;            ///< its normal part, >= 0 [N s]
  double normal_velocity_before = 0.0;       ///< u_N at the step's start [m/s], > 0 separating
  double normal_velocity_after = 0.0;        ///< u_N at its end [m/s]
};

struct MoreauJeanStatistics {
  long steps = 0;
  long contact_problems = 0;   ///< steps with at least one active contact
  long solver_iterations = 0;  ///< fc3d NSGS sweeps, summed
  long unconverged_steps = 0;  ///< steps whose contact problem missed the tolerance, fallback included
  long fallback_solves = 0;      ///< problems NSGS missed, handed to fc3d PROX
  long fallback_iterations = 0;  ///< PROX's iterations, summed
  double first_unconverged_time = std::numeric_limits<double>::quiet_NaN();  ///< [s]
  double largest_solver_error = 0.0;       ///< largest fc3d residual of any step
  double largest_projection_residual = 0.0;  ///< max |Phi| left after a projection
  long fclib_problems_written = 0;  ///< FCLIB files written (MoreauJean::write_fclib)
};

class MoreauJean {
 public:
  /// Builds the model (dynamics::build_model: consistent initial conditions) and reads the
  /// scheme's settings from model.moreau_jean, whatever model.solver_method says. Throws
  /// dynamics::ModelError naming the field for what the scheme does not support (a lubricated
  /// clearance joint).
  explicit MoreauJean(const dynamics::ModelDescription& model);
  ~MoreauJean();
  MoreauJean(const MoreauJean&) = delete;
  MoreauJean& operator=(const MoreauJean&) = delete;

  /// One step of length h. Throws dynamics::SolverError when the contact problem did not
  /// converge and the settings say stop, or when the detection refuses the poses.
  void step();
  double time() const;
  double step_size() const;
  /// The packed state y (dynamics::StateLayout) at time().
  std::span<const double> state() const;
  dynamics::MultibodySystem& system();
  /// The contacts of the last step, with their percussions.
  std::span<const ContactPercussion> contacts() const;
  std::span<const std::string> clearance_joint_names() const;
  /// The ideal joints' impulses of the last step, one per constraint row of
  /// system().constraints() [N s or N m s]: v(k+1) = v_free + M^-1 Phi_q^T mu + (contacts);
  /// mu / h is the mean of -lambda (eq. 37) over the step.
  std::span<const double> bilateral_percussions() const;
  /// Kinetic energy and the potential energy of every force element but the clearance joints
  /// (whose rigid contacts store none) at time().
  double kinetic_energy() const;
  double potential_energy();
  const MoreauJeanStatistics& statistics() const;
  /// From the next step on, write the contact problems fclib_export.hpp selects. Checks the
  /// folder first (prepare_fclib_folder, the error naming --write-fclib).
  void write_fclib(const FclibExport& fclib);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clearjoint::nonsmooth
