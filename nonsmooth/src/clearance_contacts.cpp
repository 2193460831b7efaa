// SPDX-License-Identifier: BSD-3-Clause
#include "clearance_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/kernel_pose.hpp"
#include "clearjoint/validation_error.hpp"

namespace clearjoint::nonsmooth {

namespace {

/// Two unit tangents completing n to a right-handed frame: t1 from the world axis least aligned
/// with n (first on ties), t2 = n x t1. A fixed rule, so a contact's tangents do not turn from
/// step to step while its normal stays.
Matrix3 contact_frame(const Vector3& n) {
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(n[k]) < std::abs(n[least])) least = k;
  }
  Vector3 t1 = Vector3::Unit(least) - n[least] * n;
  t1.normalize();
  Matrix3 frame;
  frame.col(0) = n;
  frame.col(1) = t1;
  frame.col(2) = n.cross(t1);
  return frame;
}

}  // namespace

double activation_margin(const geometry::JointDimensions& d) {
  return kActivationMarginFraction * std::min(d.radial_clearance(), 0.5 * (d.bearing_length - d.journal_length));
}

geometry::ContactScenario find_contacts(const ClearanceSite& site, int site_index, double time,
                                        const dynamics::SystemKinematics& kinematics,
                                        std::vector<UnilateralContact>& out) {
  if (site.parameters.pin_in_hole) {
    throw dynamics::ModelError("clearance joint '" + site.name + "': \"geometry\": \"pin_in_hole\" is not supported by "
                               "solver.method = \"moreau_jean\" (its contacts are the paper's joint's)");
  }
  const dynamics::BodyKinematics& bi = kinematics.body(site.bearing_body);
  const dynamics::BodyKinematics& bj = kinematics.body(site.journal_body);
  const geometry::PartPose bearing = dynamics::kernel_pose(bi, site.bearing_point_B, site.bearing_axis_B);
  const geometry::PartPose journal = dynamics::kernel_pose(bj, site.journal_point_B, site.journal_axis_B);
  // The journal inflated by the margin, radially and at both ends: a contact of the inflated
  // journal at depth d is a contact of the true one at gap margin - d, its journal point margin
  // nearer the bearing along the normal (exact for the line and face contacts of aligned axes,
  // to first order in the tilt for a rim's point contacts).
  geometry::JointDimensions inflated = site.parameters.dimensions;
  inflated.journal_radius += site.margin;
  inflated.journal_length += 2.0 * site.margin;
  geometry::JointContacts contacts;
  try {
    geometry::detect_contacts(inflated, bearing, journal, contacts, site.parameters.detection);
  } catch (const ValidationError& e) {
    throw dynamics::SolverError("clearance joint '" + site.name + "' at t = " +
                                dynamics::format_number(time) + " s: detection refused the poses: " + e.what());
  }
  for (int k = 0; k < contacts.contact_count; ++k) {
    const geometry::Contact& c = contacts.contacts[k];
    UnilateralContact u;
    u.site = site_index;
    u.contact = c;
    u.gap = site.margin - c.depth;
    u.bearing_point_W = c.p_WCi;
    u.journal_point_W = c.p_WCj - site.margin * c.normal_W;
    u.contact.p_WCj = u.journal_point_W;
    u.contact.depth = std::max(0.0, -u.gap);
    u.frame = contact_frame(-c.normal_W);
    out.push_back(u);
  }
  return contacts.scenario;
}

void contact_jacobian(const UnilateralContact& contact, const ClearanceSite& site,
                      const dynamics::SystemKinematics& kinematics, Eigen::Ref<Eigen::MatrixXd> rows) {
  rows.setZero();
  // Journal: +1, bearing: -1 (u is the journal's velocity relative to the bearing). The
  // velocity of a body point is rdot + A (omega' x s'), so d . v = d . rdot + (s' x A^T d) . omega'.
  const auto add_body = [&](dynamics::BodyIndex b, const Vector3& point_W, double sign) {
    if (b == dynamics::kGround) return;
    const dynamics::BodyKinematics& k = kinematics.body(b);
    const Vector3 s_B = k.rotation.transpose() * (point_W - k.position_W);
    for (int d = 0; d < 3; ++d) {
      const Vector3 direction = contact.frame.col(d);
      rows.block<1, 3>(d, 6 * b) += sign * direction.transpose();
      rows.block<1, 3>(d, 6 * b + 3) += sign * s_B.cross(k.rotation.transpose() * direction).transpose();
    }
  };
  add_body(site.journal_body, contact.journal_point_W, 1.0);
  add_body(site.bearing_body, contact.bearing_point_W, -1.0);
}

}  // namespace clearjoint::nonsmooth
