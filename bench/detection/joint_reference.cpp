// SPDX-License-Identifier: BSD-3-Clause
#include "joint_reference.hpp"

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <utility>

#include "reference_circle.hpp"
#include "trig_quadratic_roots.hpp"

namespace clearjoint::bench {

using geometry::ContactBase;
using geometry::ContactPresence;
using geometry::ContactType;

// ---- conversions and vector algebra -------------------------------------------------------------

RealVector to_real(const geometry::Vector3& v) { return {Real(v.x()), Real(v.y()), Real(v.z())}; }
geometry::Vector3 to_double(const RealVector& v) {
  // MPFR's conversion to double rounds to nearest.
  return {v[0].convert_to<double>(), v[1].convert_to<double>(), v[2].convert_to<double>()};
}
Real dot(const RealVector& a, const RealVector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
RealVector cross(const RealVector& a, const RealVector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
RealVector add(const RealVector& a, const RealVector& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
RealVector sub(const RealVector& a, const RealVector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
RealVector scale(const Real& s, const RealVector& a) { return {s * a[0], s * a[1], s * a[2]}; }
Real norm(const RealVector& a) { return sqrt(dot(a, a)); }
RealVector normalized(const RealVector& a) { return scale(1 / norm(a), a); }
Real distance(const geometry::Vector3& p, const RealVector& q) { return norm(sub(to_real(p), q)); }
const Real& pi_constant() {
  static const Real pi = atan(Real(1)) * 4;
  return pi;
}

namespace {

int sign_of(const Real& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

Real two_pi() { return 2 * pi_constant(); }

Real wrap_angle(Real a) {
  a = fmod(a, two_pi());
  if (a < 0) a += two_pi();
  return a;
}

/// Sign of `value`, or 0 with `tie` set when it lies within kTieWidth * scale of zero without
/// being zero (an exact zero is a decided tie).
int decided_sign(const Real& value, const Real& scale, bool& tie) {
  if (value != 0 && abs(value) <= Real(kTieWidth) * scale) tie = true;
  return sign_of(value);
}

// ---- the rim --------------------------------------------------------------------------------

using Rim = ReferenceCircle;

// ---- trigonometric quadratics and their roots (support/multiprecision) ---------------------------

using TrigQuadratic = multiprecision::TrigQuadratic<Real>;

/// Coefficients below this fraction of the largest are rounding noise: the working precision is
/// 1e-120 and every coefficient is a short sum of products, while the Sturm remainders of roots
/// kAmbiguousSeparation apart stay far above it.
const Real& negligible() {
  static const Real value("1e-105");
  return value;
}

/// Safety cap on bisection steps: 2^-600 times any root bound is far below kRootWidth.
constexpr int kMaxBisections = 600;

struct PolyRoots {
  bool ambiguous = false;
  std::string why;
  std::vector<Real> roots;  // sorted
};

/// The distinct real roots of `e` (normalised, degree >= 1); ambiguous when two lie closer than
/// kAmbiguousSeparation or one has even multiplicity.
PolyRoots real_roots(const multiprecision::Poly<Real>& e) {
  static const multiprecision::IsolationLimits<Real> limits{negligible(), Real(kRootWidth), Real(kAmbiguousSeparation),
                                                            kMaxBisections};
  PolyRoots out;
  for (const multiprecision::IsolatedRoot<Real>& root : multiprecision::real_roots(e, limits)) {
    out.roots.push_back(root.t);
    if (root.multiplicity_hint == 2) {
      out.ambiguous = true;
      out.why = "a root of even multiplicity (a tangency to working precision)";
    } else if (root.multiplicity_hint > 2) {
      out.ambiguous = true;
      out.why = "a cluster of roots narrower than kAmbiguousSeparation";
    }
  }
  for (std::size_t i = 1; i < out.roots.size(); ++i) {
    if (out.roots[i] - out.roots[i - 1] < Real(kAmbiguousSeparation)) {
      out.ambiguous = true;
      out.why = "two roots closer than kAmbiguousSeparation";
    }
  }
  return out;
}

struct AngleRoots {
  bool ambiguous = false;
  std::string why;
  bool vanishes = false;     ///< f == 0 identically (to working precision)
  std::vector<Real> angles;  ///< distinct roots in [0, 2 pi), sorted
};

/// The real roots of f on the circle. `size` is the scale of the terms f sums (for the test of f
/// vanishing identically).
AngleRoots angle_roots(const TrigQuadratic& f, const Real& size) {
  AngleRoots out;
  if (f.fourier_size() <= negligible() * size) {
    out.vanishes = true;
    return out;
  }
  // The half-angle quartic after the shift that keeps its leading coefficient far from 0.
  const multiprecision::HalfAngleQuartic<Real> quartic = multiprecision::half_angle_quartic(f);
  const Real phi = pi_constant() * quartic.k / 4;
  multiprecision::Poly<Real> e = quartic.e;
  if (!multiprecision::normalise(e, negligible())) {
    out.vanishes = true;
    return out;
  }
  if (e.size() < 5) {
    out.ambiguous = true;
    out.why = "the quartic lost its leading term after the shift";
    return out;
  }
  const PolyRoots t_roots = real_roots(e);
  out.ambiguous = t_roots.ambiguous;
  out.why = t_roots.why;
  for (const Real& t : t_roots.roots) out.angles.push_back(wrap_angle(phi + 2 * atan(t)));
  std::sort(out.angles.begin(), out.angles.end());
  return out;
}

// ---- the joint's candidate contacts ------------------------------------------------------------

/// G(theta) = |(x(theta) - P_i) x e_i|^2 - Ri^2: positive where the rim is beyond the wall.
/// With w = c - P_i: (x - P_i) x e = A + B cos + C sin, A = w x e, B = r u x e, C = r v x e.
TrigQuadratic wall_excess(const ReferenceJoint& joint, const Rim& rim) {
  const RealVector& e = joint.bearing_axis_hat;
  const RealVector a = cross(sub(rim.center, joint.p_WPi), e);
  const RealVector b = scale(rim.radius, cross(rim.u, e));
  const RealVector c = scale(rim.radius, cross(rim.v, e));
  const Real ri = joint.bearing_radius;
  return {dot(a, a) - ri * ri, 2 * dot(a, b), 2 * dot(a, c), dot(b, b), dot(c, c), 2 * dot(b, c)};
}

/// Scale of G's terms (m^2), for the vanishing and tie tests.
Real wall_scale(const ReferenceJoint& joint, const Rim& rim) {
  const Real reach = norm(sub(rim.center, joint.p_WPi)) + rim.radius + joint.bearing_radius;
  return reach * reach;
}

/// Unit radial direction of point x from the bearing axis, and its distance from the axis.
std::pair<RealVector, Real> radial_of(const ReferenceJoint& joint, const RealVector& x) {
  const RealVector offset = sub(x, joint.p_WPi);
  const RealVector radial =
      sub(offset, scale(dot(offset, joint.bearing_axis_hat), joint.bearing_axis_hat));
  const Real length = norm(radial);
  return {scale(1 / length, radial), length};
}

/// eqs. (20)-(21), (23) for a journal point p_WCj beyond the wall.
ReferenceContact radial_contact_at(const ReferenceJoint& joint, ContactBase base,
                                   const RealVector& p_WCj) {
  ReferenceContact contact;
  contact.type = ContactType::radial;
  contact.base = base;
  contact.p_WCj = p_WCj;
  const auto [direction, distance_to_axis] = radial_of(joint, p_WCj);
  contact.normal_W = direction;                                                     // eq. (20)
  const RealVector offset = sub(p_WCj, joint.p_WPi);
  contact.p_WCi = add(add(joint.p_WPi, scale(dot(offset, joint.bearing_axis_hat), joint.bearing_axis_hat)),
                      scale(joint.bearing_radius, direction));                      // eq. (21)
  contact.depth = distance_to_axis - joint.bearing_radius;                          // eq. (23)
  return contact;
}

int index_of(ContactBase base) { return base == ContactBase::a ? 0 : 1; }
/// Outward normal of base X is s e_i with s = +1 at A, -1 at B.
int outward_sign(ContactBase base) { return base == ContactBase::a ? 1 : -1; }

Rim journal_rim(const ReferenceJoint& joint, ContactBase base) {
  return make_reference_circle(joint.journal_rim[index_of(base)], joint.journal_axis_hat, joint.journal_radius);
}

struct CandidateResult {
  bool decided = true;
  std::string why;
  std::vector<ReferenceContact> contacts;
  bool beyond_model = false;
};

/// Radial contacts of rim `base` (misaligned axes), eqs. (16)-(21).
CandidateResult radial_candidates(const ReferenceJoint& joint, ContactBase base) {
  CandidateResult out;
  const Rim rim = journal_rim(joint, base);
  const TrigQuadratic g = wall_excess(joint, rim);
  const Real size = wall_scale(joint, rim);
  const AngleRoots roots = angle_roots(g, size);
  if (roots.ambiguous || roots.vanishes) {
    out.decided = false;
    out.why = roots.vanishes ? "rim on the wall to working precision" : roots.why;
    return out;
  }
  bool tie = false;
  if (roots.angles.empty()) {
    if (decided_sign(g.at(Real(0)), size, tie) > 0) {
      // Beyond the wall all round: beyond the model, no arc middle.
      ReferenceContact contact = radial_contact_at(joint, base, rim.at(Real(0)));
      contact.points_defined = false;
      out.contacts.push_back(contact);
      out.beyond_model = true;
    }
  } else {
    const std::size_t n = roots.angles.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Real& begin = roots.angles[i];
      const Real& end = roots.angles[(i + 1) % n];
      Real sweep = end - begin;
      if (sweep <= 0) sweep += two_pi();  // wraps through 0 (or the whole circle for one root)
      const Real middle = begin + sweep / 2;
      if (decided_sign(g.at(middle), size, tie) <= 0) continue;
      ReferenceContact contact = radial_contact_at(joint, base, rim.at(middle));  // eqs. (18)-(19)
      contact.crossings = {rim.at(begin), rim.at(end)};
      if (n == 1) contact.crossings.pop_back();
      if (contact.depth > joint.radial_clearance) out.beyond_model = true;
      out.contacts.push_back(std::move(contact));
    }
    if (out.contacts.size() > 1) out.beyond_model = true;  // two penetration arcs on one rim
  }
  if (tie) {
    out.decided = false;
    out.why = "the wall excess at an arc middle is within kTieWidth of zero";
  }
  return out;
}

/// Signed distance beyond base X of the rim point at angle theta: alpha + rho cos(theta - theta0),
/// written as alpha + Rj (w . (u cos + v sin)) with w the base's outward unit normal projected into
/// the rim plane.
struct BaseDistance {
  Real alpha;
  RealVector w;  // projection of the outward normal into the rim plane (length sin of the tilt)
  Real rho;      // Rj |w|
};

BaseDistance base_distance(const ReferenceJoint& joint, const Rim& rim, ContactBase base) {
  const RealVector normal = scale(Real(outward_sign(base)), joint.bearing_axis_hat);
  BaseDistance d;
  d.alpha = dot(sub(rim.center, joint.bearing_base[index_of(base)]), normal);
  d.w = sub(normal, scale(dot(normal, rim.normal), rim.normal));
  d.rho = rim.radius * norm(d.w);
  return d;
}

/// Axial contact of rim `base` against base plane `base` (misaligned axes), eqs. (11)-(15).
CandidateResult axial_candidate(const ReferenceJoint& joint, ContactBase base) {
  CandidateResult out;
  const Rim rim = journal_rim(joint, base);
  const BaseDistance d = base_distance(joint, rim, base);
  const Real size = abs(d.alpha) + d.rho + joint.axial_clearance;
  bool tie = false;
  if (decided_sign(d.alpha + d.rho, size, tie) > 0) {
    ReferenceContact contact;
    contact.type = ContactType::axial;
    contact.base = base;
    const RealVector normal = scale(Real(outward_sign(base)), joint.bearing_axis_hat);
    const RealVector w_hat = normalized(d.w);
    contact.p_WCj = add(rim.center, scale(rim.radius, w_hat));  // deepest = arc middle, eqs. (13)-(14)
    contact.depth = d.alpha + d.rho;                             // eq. (23)
    contact.p_WCi = sub(contact.p_WCj, scale(contact.depth, normal));  // eq. (15)
    contact.normal_W = normal;
    if (decided_sign(d.alpha - d.rho, size, tie) < 0) {
      // Crossings at theta0 +- beta, cos(beta) = -alpha/rho: eqs. (11)-(12) solved in closed form.
      const Real cos_beta = -d.alpha / d.rho;
      const Real sin_beta = sqrt(1 - cos_beta * cos_beta);
      const RealVector side = cross(rim.normal, w_hat);
      for (const int sign : {1, -1}) {
        contact.crossings.push_back(add(
            rim.center, scale(rim.radius, add(scale(cos_beta, w_hat), scale(sign * sin_beta, side)))));
      }
    } else {
      out.beyond_model = true;  // the whole rim is beyond the base plane
      contact.all_round = true;
    }
    if (contact.depth > joint.axial_clearance) out.beyond_model = true;
    out.contacts.push_back(std::move(contact));
  }
  if (tie) {
    out.decided = false;
    out.why = "a rim's deepest or shallowest point lies within kTieWidth of a base plane";
  }
  return out;
}

/// Parallel axes, eqs. (6)-(10).
void detect_aligned(const ReferenceJoint& joint, ReferenceAnswer& answer, ContactPresence& presence) {
  const RealVector& e = joint.bearing_axis_hat;
  const RealVector offset = sub(joint.p_WPj, joint.p_WPi);
  const RealVector radial = sub(offset, scale(dot(offset, e), e));
  const Real eccentricity = norm(radial);
  bool tie = false;
  const Real size = eccentricity + joint.radial_clearance;
  if (decided_sign(eccentricity - joint.radial_clearance, size, tie) > 0) {
    ReferenceContact contact;
    contact.type = ContactType::radial;
    contact.base = ContactBase::mid;
    contact.normal_W = scale(1 / eccentricity, radial);                                    // eq. (6)
    contact.p_WCi = add(add(joint.p_WPi, scale(dot(offset, e), e)),
                        scale(joint.bearing_radius, contact.normal_W));                   // eq. (7)
    contact.p_WCj = add(joint.p_WPj, scale(joint.journal_radius, contact.normal_W));      // eq. (8)
    contact.depth = eccentricity - joint.radial_clearance;                                // eq. (23)
    if (contact.depth > joint.radial_clearance) presence.beyond_model = true;
    presence.line = true;
    answer.contacts.push_back(std::move(contact));
  }
  for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
    const RealVector normal = scale(Real(outward_sign(base)), e);
    const RealVector& p_WBj = joint.journal_rim[index_of(base)];
    const Real beyond = dot(sub(p_WBj, joint.bearing_base[index_of(base)]), normal);
    const Real face_size = abs(beyond) + joint.axial_clearance;
    if (decided_sign(beyond, face_size, tie) <= 0) continue;
    ReferenceContact contact;
    contact.type = ContactType::axial;
    contact.base = base;
    contact.normal_W = normal;
    contact.p_WCj = p_WBj;                                  // eq. (10)
    contact.p_WCi = sub(p_WBj, scale(beyond, normal));      // eq. (9)
    contact.depth = beyond;                                 // eq. (23)
    if (contact.depth > joint.axial_clearance) presence.beyond_model = true;
    (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
    answer.contacts.push_back(std::move(contact));
  }
  if (tie) {
    answer.decided = false;
    answer.why = "an aligned eccentricity or face distance within kTieWidth of its limit";
  }
}

/// How the base and rim centres P +- (L/2) a_hat take their unit axis a_hat (normals and the wall
/// always use the exact direction of the axis as given).
enum class CentreAxes {
  library_unit_axis,  ///< a_hat = geometry::unit_axis(pose), a double (the library's definition)
  exact_unit_axis,    ///< a_hat = a / |a| in MPFR
};

/// The unit axis that offsets the centres: see CentreAxes. The library's a_hat is a function of
/// the double axis; generator poses (RealPose) carry double axes, which is checked.
RealVector centre_axis(const RealVector& axis, CentreAxes axes) {
  if (axes == CentreAxes::exact_unit_axis) return normalized(axis);
  const geometry::Vector3 axis_double = to_double(axis);
  const RealVector back = to_real(axis_double);
  if (back[0] != axis[0] || back[1] != axis[1] || back[2] != axis[2]) {
    throw std::invalid_argument("joint reference: an axis that is not a double has no library unit axis");
  }
  return to_real(geometry::unit_axis(geometry::PartPose{geometry::Vector3::Zero(), axis_double}));
}

ReferenceJoint build_joint(const geometry::JointDimensions& d, const RealPose& bearing,
                           const RealPose& journal, CentreAxes axes) {
  ReferenceJoint joint;
  joint.bearing_radius = Real(d.bearing_radius);
  joint.journal_radius = Real(d.journal_radius);
  joint.radial_clearance = Real(d.bearing_radius) - Real(d.journal_radius);
  joint.axial_clearance = (Real(d.bearing_length) - Real(d.journal_length)) / 2;
  joint.p_WPi = bearing.p_WP;
  joint.p_WPj = journal.p_WP;
  joint.bearing_axis_hat = normalized(bearing.axis_W);
  joint.journal_axis_hat = normalized(journal.axis_W);
  const RealVector c = cross(bearing.axis_W, journal.axis_W);
  joint.exactly_parallel = c[0] == 0 && c[1] == 0 && c[2] == 0;
  const RealVector half_i = scale(Real(d.bearing_length) / 2, centre_axis(bearing.axis_W, axes));
  const RealVector half_j = scale(Real(d.journal_length) / 2, centre_axis(journal.axis_W, axes));
  joint.bearing_base = {add(bearing.p_WP, half_i), sub(bearing.p_WP, half_i)};  // eqs. (3)-(4)
  // Labels follow the bearing: the journal's base on the side of bearing base A is rim A.
  const bool same_direction = dot(bearing.axis_W, journal.axis_W) >= 0;
  const RealVector toward_a = same_direction ? half_j : scale(Real(-1), half_j);
  joint.journal_rim = {add(journal.p_WP, toward_a), sub(journal.p_WP, toward_a)};
  return joint;
}

}  // namespace

ReferenceJoint joint_as_given(const geometry::JointDimensions& dimensions, const RealPose& bearing,
                              const RealPose& journal) {
  return build_joint(dimensions, bearing, journal, CentreAxes::library_unit_axis);
}

ReferenceJoint joint_as_given(const geometry::JointDimensions& dimensions,
                              const geometry::PartPose& bearing, const geometry::PartPose& journal) {
  return build_joint(dimensions, {to_real(bearing.p_WP), to_real(bearing.axis_W)},
                     {to_real(journal.p_WP), to_real(journal.axis_W)}, CentreAxes::library_unit_axis);
}

ReferenceJoint joint_with_exact_unit_axes(const geometry::JointDimensions& dimensions,
                                          const geometry::PartPose& bearing,
                                          const geometry::PartPose& journal) {
  return build_joint(dimensions, {to_real(bearing.p_WP), to_real(bearing.axis_W)},
                     {to_real(journal.p_WP), to_real(journal.axis_W)}, CentreAxes::exact_unit_axis);
}

ReferenceAnswer reference_detect(const ReferenceJoint& joint) {
  ReferenceAnswer answer;
  ContactPresence presence;
  answer.aligned = presence.aligned = joint.exactly_parallel;
  if (joint.exactly_parallel) {
    detect_aligned(joint, answer, presence);
  } else {
    std::vector<CandidateResult> candidates;
    for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
      candidates.push_back(radial_candidates(joint, base));
      if (!candidates.back().contacts.empty()) {
        (base == ContactBase::a ? presence.radial_at_a : presence.radial_at_b) = true;
      }
    }
    for (const ContactBase base : {ContactBase::a, ContactBase::b}) {
      candidates.push_back(axial_candidate(joint, base));
      if (!candidates.back().contacts.empty()) {
        (base == ContactBase::a ? presence.axial_at_a : presence.axial_at_b) = true;
      }
    }
    for (CandidateResult& c : candidates) {
      if (!c.decided) {
        answer.decided = false;
        answer.why = c.why;
      }
      presence.beyond_model = presence.beyond_model || c.beyond_model;
      for (ReferenceContact& contact : c.contacts) answer.contacts.push_back(std::move(contact));
    }
  }
  answer.scenario = geometry::classify_scenario(presence);
  return answer;
}

RadialMargin radial_margin(const ReferenceJoint& joint, ContactBase base) {
  RadialMargin out;
  const Rim rim = journal_rim(joint, base);
  const TrigQuadratic g = wall_excess(joint, rim);
  const Real size = wall_scale(joint, rim);
  // G = dist^2 - Ri^2 is largest where dist is; the candidates are the roots of G'.
  const AngleRoots critical = angle_roots(g.derivative(), size);
  std::vector<Real> candidates = critical.angles;
  if (critical.vanishes) candidates = {Real(0)};  // G constant: every point is farthest
  if (critical.ambiguous && candidates.empty()) out.decided = false;
  Real best_angle = 0, best_value = g.at(Real(0));
  for (const Real& angle : candidates) {
    const Real value = g.at(angle);
    if (value > best_value) {
      best_value = value;
      best_angle = angle;
    }
  }
  const auto [direction, distance_to_axis] = radial_of(joint, rim.at(best_angle));
  out.margin = distance_to_axis - joint.bearing_radius;
  out.direction = direction;
  return out;
}

Real line_margin(const ReferenceJoint& joint) {
  const RealVector& e = joint.bearing_axis_hat;
  const RealVector offset = sub(joint.p_WPj, joint.p_WPi);
  return norm(sub(offset, scale(dot(offset, e), e))) - joint.radial_clearance;
}

Real axial_margin(const ReferenceJoint& joint, ContactBase base) {
  const Rim rim = journal_rim(joint, base);
  const BaseDistance d = base_distance(joint, rim, base);
  return d.alpha + d.rho;
}

}  // namespace clearjoint::bench
