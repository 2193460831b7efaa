// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A clearance joint's contacts as unilateral constraints (docs/nonsmooth.md, "Contacts"): the
/// certified detection (geometry::detect_contacts) run on a journal inflated by an activation
/// margin, so that contacts about to close within the step are found while the gap is still
/// open; each found contact gets its gap, its points on the journal and the bearing, a frame
/// (normal, two tangents) and its three rows of the contact Jacobian H.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "clearjoint/dynamics/clearance_joint_parameters.hpp"
#include "clearjoint/dynamics/system_kinematics.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"

namespace clearjoint::nonsmooth {

using dynamics::Matrix3;
using dynamics::Vector3;
using dynamics::Vector4;

/// Fraction of the smaller of the radial and axial clearances taken as the activation margin:
/// the inflated journal must still fit its bearing (below 1), and the margin must exceed the
/// half step's travel, h |u_N| / 2, of the activation test (at h = 1e-5 s and 1 m/s: 5e-6 m, a
/// twentieth of the paper's 0.1 mm clearances); a quarter satisfies both for approach speeds up
/// to 2 m / h (5 m/s at h = 1e-5 s). A faster approach is not detected (docs/nonsmooth.md).
inline constexpr double kActivationMarginFraction = 0.25;

/// One clearance joint, resolved to body indices.
struct ClearanceSite {
  std::string name;
  dynamics::BodyIndex bearing_body = dynamics::kGround;
  dynamics::BodyIndex journal_body = dynamics::kGround;
  Vector3 bearing_point_B = Vector3::Zero();
  Vector3 bearing_axis_B = Vector3::UnitZ();
  Vector3 journal_point_B = Vector3::Zero();
  Vector3 journal_axis_B = Vector3::UnitZ();
  dynamics::ClearanceJointParameters parameters;
  double margin = 0.0;  ///< activation margin [m]
};

/// One contact of one joint, at the step's start.
struct UnilateralContact {
  int site = 0;                     ///< index of its ClearanceSite
  geometry::Contact contact;        ///< as detected on the inflated journal (scenario, base, type)
  double gap = 0.0;                 ///< signed distance [m], > 0 open, < 0 penetrating
  Vector3 journal_point_W = Vector3::Zero();  ///< on the journal's true surface
  Vector3 bearing_point_W = Vector3::Zero();
  /// Columns: n (the journal's separating direction, -Contact::normal_W), t1, t2 (world).
  Matrix3 frame = Matrix3::Identity();
};

/// The site's activation margin for its dimensions (kActivationMarginFraction).
double activation_margin(const geometry::JointDimensions& dimensions);

/// Append the contacts of `site` whose gap is below its margin at these kinematics; returns the
/// scenario of the inflated detection. Throws dynamics::SolverError naming the joint and the
/// time if the detection rejects the poses.
geometry::ContactScenario find_contacts(const ClearanceSite& site, int site_index, double time,
                                        const dynamics::SystemKinematics& kinematics,
                                        std::vector<UnilateralContact>& out);

/// The contact's three rows of H (u = H v: u_N, u_T1, u_T2 of the journal relative to the
/// bearing at the contact points, in the contact frame), over the 6n velocity columns
/// [rdot_b; omega'_b]; the ground's columns do not exist.
void contact_jacobian(const UnilateralContact& contact, const ClearanceSite& site,
                      const dynamics::SystemKinematics& kinematics, Eigen::Ref<Eigen::MatrixXd> rows);

}  // namespace clearjoint::nonsmooth
