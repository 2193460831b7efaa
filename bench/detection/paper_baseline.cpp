// SPDX-License-Identifier: BSD-3-Clause
#include "paper_baseline.hpp"

#include <cmath>
#include <utility>

#include <Eigen/Dense>

namespace clearjoint::bench {
namespace {

using geometry::Certainty;
using geometry::Certificate;
using geometry::CertificateReason;
using geometry::Contact;
using geometry::ContactBase;
using geometry::ContactPresence;
using geometry::ContactType;
using geometry::JointContacts;
using geometry::Vector3;

// The paper's method proves nothing: what the library answers with its certificate switched off.
constexpr Certificate kBaselineCertificate{Certainty::uncertain, CertificateReason::certificate_switched_off};

struct Setup {
  double ri, rj, li, lj;
  Vector3 p_i, p_j;
  Vector3 a_i, a_j;            // unit axes
  Vector3 base_i[2];           // bearing base centres A, B (eqs. 3-4)
  Vector3 base_j[2];           // journal base centres facing A, B
};

int index_of(ContactBase base) { return base == ContactBase::a ? 0 : 1; }
double outward_sign(ContactBase base) { return base == ContactBase::a ? 1.0 : -1.0; }

void add_contact(JointContacts& out, const Contact& contact) {
  if (out.contact_count < geometry::kMaxContacts) out.contacts[out.contact_count++] = contact;
}

Contact make_contact(ContactType type, ContactBase base) {
  Contact contact;
  contact.type = type;
  contact.base = base;
  contact.certificate = kBaselineCertificate;
  return contact;
}

void add_crossing(Contact& contact, const Vector3& point) {
  geometry::RimCrossing crossing;
  crossing.point = point;  // angle and error bounds unknown (kNoErrorBound)
  contact.crossings[contact.crossing_count++] = crossing;
}

/// Parallel axes: eqs. (6)-(10).
void detect_aligned(const Setup& s, JointContacts& out, ContactPresence& presence) {
  const Vector3 offset = s.p_j - s.p_i;
  const Vector3 radial = offset - offset.dot(s.a_i) * s.a_i;
  const double eccentricity = radial.norm();
  if (eccentricity > s.ri - s.rj) {
    Contact contact = make_contact(ContactType::radial, ContactBase::mid);
    contact.normal_W = radial / eccentricity;                                            // eq. (6)
    contact.p_WCi = s.p_i + offset.dot(s.a_i) * s.a_i + s.ri * contact.normal_W;         // eq. (7)
    contact.p_WCj = s.p_j + s.rj * contact.normal_W;                                     // eq. (8)
    contact.depth = (contact.p_WCj - contact.p_WCi).norm();                              // eq. (23)
    presence.line = true;
    add_contact(out, contact);
  }
  for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
    const Vector3 normal = outward_sign(base) * s.a_i;
    const Vector3& p_WBj = s.base_j[index_of(base)];
    const Vector3& p_WBi = s.base_i[index_of(base)];
    if ((p_WBj - p_WBi).dot(normal) <= 0.0) continue;
    Contact contact = make_contact(ContactType::axial, base);
    contact.normal_W = normal;
    contact.p_WCj = p_WBj;                                                               // eq. (10)
    contact.p_WCi = p_WBj + (p_WBi - p_WBj).dot(s.a_i) * s.a_i;                          // eq. (9)
    contact.depth = (contact.p_WCj - contact.p_WCi).norm();                              // eq. (23)
    (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
    add_contact(out, contact);
  }
}

/// Axial contact of rim X with base plane X: eqs. (11)-(15).
void detect_axial(const Setup& s, ContactBase base, JointContacts& out, ContactPresence& presence) {
  const Vector3& c = s.base_j[index_of(base)];
  const Vector3& p_WBi = s.base_i[index_of(base)];
  // Points of the rim plane (a_j . x = a_j . c) on the base plane (a_i . x = a_i . B_i) form a
  // line of direction a_j x a_i; its point nearest to c is c + h (a_i - k a_j) / (1 - k^2),
  // k = a_i . a_j, h = a_i . (B_i - c), with 1 - k^2 = |a_i x a_j|^2.
  const Vector3 line_direction = s.a_j.cross(s.a_i);
  const double sin_squared = line_direction.squaredNorm();
  const double k = s.a_i.dot(s.a_j);
  const double h = s.a_i.dot(p_WBi - c);
  const Vector3 nearest = c + (h / sin_squared) * (s.a_i - k * s.a_j);
  const double half_chord_squared = s.rj * s.rj - (nearest - c).squaredNorm();
  if (!(half_chord_squared > 0.0)) return;  // zero or one point: no penetration
  const Vector3 along = std::sqrt(half_chord_squared / sin_squared) * line_direction;
  const Vector3 i1 = nearest + along, i2 = nearest - along;
  const Vector3 n_d = (0.5 * (i1 + i2) - c).normalized();                                // eq. (13)
  // eq. (14): of c +- Rj n_d, the point outside the bearing (beyond the base plane).
  const Vector3 normal = outward_sign(base) * s.a_i;
  const Vector3 plus = c + s.rj * n_d, minus = c - s.rj * n_d;
  Contact contact = make_contact(ContactType::axial, base);
  contact.p_WCj = (plus - p_WBi).dot(normal) >= (minus - p_WBi).dot(normal) ? plus : minus;
  contact.p_WCi = contact.p_WCj + (p_WBi - contact.p_WCj).dot(s.a_i) * s.a_i;            // eq. (15)
  contact.depth = (contact.p_WCj - contact.p_WCi).norm();                                // eq. (23)
  contact.normal_W = (contact.p_WCj - contact.p_WCi) / contact.depth;                   // eq. (22)
  add_crossing(contact, i1);
  add_crossing(contact, i2);
  (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
  add_contact(out, contact);
}

/// |a~_i (x - P_i)|^2 - Ri^2 (eq. 17): positive beyond the wall.
double wall_excess(const Setup& s, const Vector3& x) {
  const Vector3 y = x - s.p_i;
  return (y - y.dot(s.a_i) * s.a_i).squaredNorm() - s.ri * s.ri;
}

/// Plain Newton-Raphson on eqs. (16)-(17) for x in R^3:
///   F(x) = (|x - c|^2 - Rj^2, a_j . (x - c), |a~_i (x - P_i)|^2 - Ri^2) = 0.
/// Returns false when it does not converge within kNewtonMaxIterations steps.
bool newton_crossing(const Setup& s, const Vector3& c, Vector3& x) {
  for (int iteration = 0; iteration < kNewtonMaxIterations; ++iteration) {
    const Vector3 from_center = x - c;
    const Vector3 y = x - s.p_i;
    const Vector3 radial = y - y.dot(s.a_i) * s.a_i;
    const Vector3 f(from_center.squaredNorm() - s.rj * s.rj, s.a_j.dot(from_center),
                    radial.squaredNorm() - s.ri * s.ri);
    Eigen::Matrix3d jacobian;
    jacobian.row(0) = 2.0 * from_center.transpose();
    jacobian.row(1) = s.a_j.transpose();
    jacobian.row(2) = 2.0 * radial.transpose();  // gradient of |a~_i y|^2 for unit a_i
    // Eigen's closed-form 3x3 inverse (cofactors): the cheapest solve for one right-hand side.
    const Vector3 step = jacobian.inverse() * (-f);
    if (!step.allFinite()) return false;
    x += step;
    if (step.norm() <= kNewtonStepTolerance * s.rj) return true;
  }
  return false;
}

/// Radial contact of rim X with the wall: eqs. (16)-(21).
void detect_radial(const Setup& s, ContactBase base, JointContacts& out, ContactPresence& presence) {
  const Vector3& c = s.base_j[index_of(base)];
  // The rim point in the radial direction of its centre: u is that direction projected into the
  // rim plane (any in-plane direction for a centred rim).
  const Vector3 w = c - s.p_i;
  const Vector3 radial_of_center = w - w.dot(s.a_i) * s.a_i;
  Vector3 u = radial_of_center - radial_of_center.dot(s.a_j) * s.a_j;
  u = u.squaredNorm() > 0.0 ? u.normalized() : s.a_j.unitOrthogonal();
  const Vector3 v = s.a_j.cross(u);
  if (wall_excess(s, c + s.rj * u) <= 0.0) return;  // no penetration (small-tilt assumption)
  Vector3 i1 = c + s.rj * v, i2 = c - s.rj * v;     // the fixed starting guesses
  if (!newton_crossing(s, c, i1) || !newton_crossing(s, c, i2)) return;
  const Vector3 n_d = (0.5 * (i1 + i2) - c).normalized();                                // eq. (18)
  // eq. (19): of c +- Rj n_d, the point outside the bearing (farther from its axis).
  const Vector3 plus = c + s.rj * n_d, minus = c - s.rj * n_d;
  Contact contact = make_contact(ContactType::radial, base);
  contact.p_WCj = wall_excess(s, plus) >= wall_excess(s, minus) ? plus : minus;
  const Vector3 offset = contact.p_WCj - s.p_i;
  const Vector3 radial = offset - offset.dot(s.a_i) * s.a_i;
  contact.normal_W = radial.normalized();                                                // eq. (20)
  contact.p_WCi = s.p_i + offset.dot(s.a_i) * s.a_i + s.ri * contact.normal_W;          // eq. (21)
  contact.depth = (contact.p_WCj - contact.p_WCi).norm();                                // eq. (23)
  add_crossing(contact, i1);
  add_crossing(contact, i2);
  (base == ContactBase::a ? presence.radial_at_a : presence.radial_at_b) = true;
  add_contact(out, contact);
}

}  // namespace

JointContacts detect_contacts_paper_baseline(const geometry::JointDimensions& d,
                                             const geometry::PartPose& bearing,
                                             const geometry::PartPose& journal) {
  Setup s;
  s.ri = d.bearing_radius;
  s.rj = d.journal_radius;
  s.li = d.bearing_length;
  s.lj = d.journal_length;
  s.p_i = bearing.p_WP;
  s.p_j = journal.p_WP;
  s.a_i = bearing.axis_W.normalized();
  s.a_j = journal.axis_W.normalized();
  s.base_i[0] = s.p_i + 0.5 * s.li * s.a_i;  // eq. (3)
  s.base_i[1] = s.p_i - 0.5 * s.li * s.a_i;  // eq. (4)
  s.base_j[0] = s.p_j + 0.5 * s.lj * s.a_j;
  s.base_j[1] = s.p_j - 0.5 * s.lj * s.a_j;
  // Labels follow the bearing: the journal base on the side of bearing base A is rim A.
  if (s.a_i.dot(s.a_j) < 0.0) std::swap(s.base_j[0], s.base_j[1]);

  JointContacts out;
  out.certificate = kBaselineCertificate;
  ContactPresence presence;
  const Vector3 skew = s.a_i.cross(s.a_j);  // eq. (5)
  out.aligned = presence.aligned = skew.x() == 0.0 && skew.y() == 0.0 && skew.z() == 0.0;
  if (out.aligned) {
    detect_aligned(s, out, presence);
  } else {
    // Radial before axial, base A before B, as the library lists them.
    detect_radial(s, ContactBase::a, out, presence);
    detect_radial(s, ContactBase::b, out, presence);
    detect_axial(s, ContactBase::a, out, presence);
    detect_axial(s, ContactBase::b, out, presence);
  }
  out.scenario = geometry::classify_scenario(presence);
  return out;
}

}  // namespace clearjoint::bench
