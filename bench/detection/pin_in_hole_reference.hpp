// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A multiprecision reference for the pin-in-hole joint's contact detection
/// (geometry::detect_pin_in_hole_contacts), the yardstick of its accuracy run. Bench-only code,
/// never linked into the library.
///
/// The joint is taken as the library defines it from its input doubles: the hole's edge centres
/// P_i +- (L/2) a_i_hat and the stops' centres P_j + s a_j_hat, a_hat = geometry::unit_axis(pose)
/// (the one rounding in the definition), every circle and plane normal and the pin's axis the
/// axes as given (a/|a|, taken here exactly in MPFR); everything evaluated in MPFR with
/// kReferenceDigits10 digits (joint_reference.hpp). The formulation is this file's own:
///
/// * Edge X against the pin: the excess G(theta) = |(x(theta) - P_j) x e_j|^2 - Rp^2 of the edge
///   circle x(theta) over the pin's cylinder, a trigonometric quadratic whose real roots the
///   half-angle quartic and Sturm sequences isolate (support/multiprecision). The contact arcs are
///   the gaps between consecutive roots where G < 0; the contact is at an arc's angular middle,
///   with depth Rp minus the middle's distance from the pin's axis and the radial normal there.
/// * A stop against its face: the signed distance of its outer circle beyond the face plane
///   (into the link) is alpha + rho cos(theta - theta0) in closed form; the contact is the
///   deepest point m, the circle crossing the face or lying beyond it all round, when m lies
///   farther than Rh from the hole's axis. Otherwise the edge circle against the stop's plane in
///   the same closed form: its deepest point q bounds the contact when q lies within Ro of the
///   pin's axis; otherwise the contact is at a corner where the two circles meet, beyond the
///   model (the edge's contact reported, or the outer circle's when the edge is not in the head).
/// * Parallel axes (eq. 5 exactly on the stored axes): the hole's mid circle against the pin (a
///   line contact) and each stop's centre beyond its face (a face contact).
/// * The pin's axis through the hole: its crossing with the hole's mid-plane within Rh of the axis.
///
/// `decided` is false when roots lie closer than kAmbiguousSeparation, a root has even
/// multiplicity, or a sign is within kTieWidth of zero (joint_reference.hpp's limits).

#include <string>
#include <vector>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {

/// What bounds a stop's contact against its face: the outer circle's deepest point (over the
/// link's face), the hole's edge's deepest point (within the head's rim), or a corner where the
/// two meet (beyond the model).
enum class StopBound { none, outer_circle, hole_edge, corner };

struct PinInHoleReferenceContact {
  geometry::ContactType type = geometry::ContactType::radial;
  geometry::ContactBase base = geometry::ContactBase::a;
  RealVector p_WCj, p_WCi, normal_W;
  Real depth;
  /// False where the library documents only a loose point (beyond the model: an edge inside the
  /// pin all round, a stop's outer circle over the hole).
  bool points_defined = true;
  StopBound stop_bound = StopBound::none;  ///< misaligned stops only
};

struct PinInHoleReferenceAnswer {
  bool decided = true;
  std::string why;
  geometry::PinInHoleScenario scenario = geometry::PinInHoleScenario::none;
  bool aligned = false;
  /// Radial (edge A, edge B, or the line) before axial (face A, face B), as the library lists.
  std::vector<PinInHoleReferenceContact> contacts;
};

PinInHoleReferenceAnswer reference_detect_pin_in_hole(const geometry::PinInHoleDimensions& dimensions,
                                                       const geometry::PartPose& hole,
                                                       const geometry::PartPose& pin);

}  // namespace clearjoint::bench
