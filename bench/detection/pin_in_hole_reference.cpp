// SPDX-License-Identifier: BSD-3-Clause
#include "pin_in_hole_reference.hpp"

#include <algorithm>
#include <utility>

#include "reference_circle.hpp"
#include "trig_quadratic_roots.hpp"

namespace clearjoint::bench {
namespace {

using geometry::ContactBase;
using geometry::ContactType;
using geometry::PinInHoleScenario;
using TrigQuadratic = multiprecision::TrigQuadratic<Real>;

int sign_of(const Real& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }
Real two_pi() { return 2 * pi_constant(); }
Real wrap_angle(Real a) {
  a = fmod(a, two_pi());
  if (a < 0) a += two_pi();
  return a;
}

/// Coefficients below this fraction of the largest are rounding noise (as joint_reference.cpp:
/// the working precision is 1e-120).
const Real& negligible() {
  static const Real value("1e-105");
  return value;
}
constexpr int kMaxBisections = 600;

/// The sign of `value`, flagging `tie` within kTieWidth of its scale (an exact zero is decided).
int decided_sign(const Real& value, const Real& scale, bool& tie) {
  if (value != 0 && abs(value) <= Real(kTieWidth) * scale) tie = true;
  return sign_of(value);
}

using Circle = ReferenceCircle;

/// Excess of the circle over the cylinder through `p` along unit `e` with radius R:
/// |(x - p) x e|^2 - R^2 = |A + B cos + C sin|^2 - R^2.
TrigQuadratic cylinder_excess(const Circle& circle, const RealVector& p, const RealVector& e, const Real& radius) {
  const RealVector a = cross(sub(circle.center, p), e);
  const RealVector b = scale(circle.radius, cross(circle.u, e));
  const RealVector c = scale(circle.radius, cross(circle.v, e));
  return {dot(a, a) - radius * radius, 2 * dot(a, b), 2 * dot(a, c), dot(b, b), dot(c, c), 2 * dot(b, c)};
}

struct Roots {
  bool ambiguous = false;
  bool vanishes = false;
  std::string why;
  std::vector<Real> angles;  // sorted in [0, 2 pi)
};

Roots roots_of(const TrigQuadratic& f, const Real& size) {
  Roots out;
  if (f.fourier_size() <= negligible() * size) {
    out.vanishes = true;
    return out;
  }
  const multiprecision::HalfAngleQuartic<Real> quartic = multiprecision::half_angle_quartic(f);
  const Real phi = pi_constant() * quartic.k / 4;
  multiprecision::Poly<Real> e = quartic.e;
  if (!multiprecision::normalise(e, negligible()) || e.size() < 5) {
    out.ambiguous = true;
    out.why = "the quartic lost its leading term";
    return out;
  }
  static const multiprecision::IsolationLimits<Real> limits{negligible(), Real(kRootWidth),
                                                            Real(kAmbiguousSeparation), kMaxBisections};
  std::vector<Real> ts;
  for (const auto& root : multiprecision::real_roots(e, limits)) {
    if (root.multiplicity_hint != 1) {
      out.ambiguous = true;
      out.why = "a root of even multiplicity or a cluster (a tangency to working precision)";
    }
    ts.push_back(root.t);
  }
  for (std::size_t i = 1; i < ts.size(); ++i) {
    if (ts[i] - ts[i - 1] < Real(kAmbiguousSeparation)) {
      out.ambiguous = true;
      out.why = "two roots closer than kAmbiguousSeparation";
    }
  }
  for (const Real& t : ts) out.angles.push_back(wrap_angle(phi + 2 * atan(t)));
  std::sort(out.angles.begin(), out.angles.end());
  return out;
}

struct Joint {
  Real hole_radius, pin_radius, half_length, radial_clearance, axial_limit;
  RealVector p_i, p_j;
  RealVector hole_dir, pin_dir;          // a/|a| exactly: normals and the pin's axis
  RealVector hole_offset, pin_offset;    // unit_axis(pose) exactly: the centres' offsets
  bool exactly_parallel = false;
  int toward_a = 1;
};

RealVector edge_centre(const Joint& j, int sign) { return add(j.p_i, scale(sign * j.half_length, j.hole_offset)); }

struct Collector {
  PinInHoleReferenceAnswer& answer;
  bool beyond = false;
  bool tie = false;
  int radial = 0, axial = 0, faces = 0;
  bool line = false;
  void undecided(const std::string& why) {
    if (answer.decided) answer.why = why;
    answer.decided = false;
  }
};

/// The hole circle at `sign` against the pin: contacts on the arcs strictly inside the pin.
void hole_circle_against_pin(const Joint& j, int sign, ContactBase base, Collector& out) {
  const Circle circle = make_reference_circle(edge_centre(j, sign), j.hole_dir, j.hole_radius);
  const TrigQuadratic g = cylinder_excess(circle, j.p_j, j.pin_dir, j.pin_radius);
  const Real reach = norm(sub(circle.center, j.p_j)) + j.hole_radius + j.pin_radius;
  const Real size = reach * reach;
  const Roots roots = roots_of(g, size);
  if (roots.ambiguous || roots.vanishes) {
    out.undecided(roots.vanishes ? "an edge on the pin's surface" : roots.why);
    return;
  }
  const auto contact_at = [&](const Real& angle, bool defined) {
    PinInHoleReferenceContact contact;
    contact.type = ContactType::radial;
    contact.base = base;
    contact.p_WCi = circle.at(angle);
    const RealVector offset = sub(contact.p_WCi, j.p_j);
    const RealVector radial = sub(offset, scale(dot(offset, j.pin_dir), j.pin_dir));
    const Real distance = norm(radial);
    contact.normal_W = scale(1 / distance, radial);
    contact.depth = j.pin_radius - distance;
    contact.p_WCj = add(contact.p_WCi, scale(contact.depth, contact.normal_W));
    contact.points_defined = defined;
    if (contact.depth > j.radial_clearance) out.beyond = true;
    out.answer.contacts.push_back(contact);
    ++out.radial;
    if (base == ContactBase::mid) out.line = true;
  };
  if (roots.angles.empty()) {
    if (decided_sign(g.at(Real(0)), size, out.tie) < 0) {
      out.beyond = true;  // the whole circle inside the pin
      contact_at(Real(0), false);
    }
    return;
  }
  const std::size_t n = roots.angles.size();
  int arcs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Real& begin = roots.angles[i];
    const Real& end = roots.angles[(i + 1) % n];
    Real sweep = end - begin;
    if (sweep <= 0) sweep += two_pi();
    const Real middle = begin + sweep / 2;
    if (decided_sign(g.at(middle), size, out.tie) >= 0) continue;
    contact_at(middle, true);
    ++arcs;
  }
  if (arcs > 1) out.beyond = true;
}

/// Signed distance of circle points beyond a plane (unit normal n through q): alpha + Rc (w . dir).
struct PlaneReach {
  Real alpha, rho;
  RealVector w;  // n projected into the circle's plane
};
PlaneReach plane_reach(const Circle& circle, const RealVector& q, const RealVector& n) {
  PlaneReach r;
  r.alpha = dot(sub(circle.center, q), n);
  r.w = sub(n, scale(dot(n, circle.normal), circle.normal));
  r.rho = circle.radius * norm(r.w);
  return r;
}

int face_of(const Joint& j, const geometry::AxialStop& stop) {
  return (stop.position > 0.0) == (j.toward_a > 0) ? 0 : 1;
}

void stop_against_face(const Joint& j, const geometry::AxialStop& stop, bool aligned, Collector& out) {
  const int face = face_of(j, stop);
  const ContactBase base = face == 0 ? ContactBase::a : ContactBase::b;
  const RealVector into_link = scale(Real(face == 0 ? -1 : 1), j.hole_dir);
  const RealVector face_point = edge_centre(j, face == 0 ? 1 : -1);
  const RealVector stop_centre = add(j.p_j, scale(Real(stop.position), j.pin_offset));
  const Circle outer = make_reference_circle(stop_centre, j.pin_dir, Real(stop.outer_radius));
  const PlaneReach reach = plane_reach(outer, face_point, into_link);
  const Real size = abs(reach.alpha) + reach.rho + j.half_length + Real(stop.outer_radius);
  if (decided_sign(reach.alpha + reach.rho, size, out.tie) <= 0) return;
  PinInHoleReferenceContact contact;
  contact.type = ContactType::axial;
  contact.base = base;
  contact.normal_W = into_link;
  ++out.axial;
  if (aligned) {
    // A face contact: the stop's centre and its projection on the face.
    contact.depth = reach.alpha + reach.rho;
    contact.p_WCj = stop_centre;
    contact.p_WCi = sub(stop_centre, scale(contact.depth, into_link));
    ++out.faces;
  } else {
    // The stop's face disk less the hole is the contact region, the depth into the link linear
    // over it: its deepest point is the outer circle's deepest point m when m lies outside the
    // bore; otherwise the hole's edge's deepest point q into the head when q lies within Ro of the
    // pin's axis; otherwise a corner where the two circles meet (beyond the model).
    const RealVector m = add(outer.center, scale(outer.radius, normalized(reach.w)));
    const Real m_from_axis = norm(cross(sub(m, j.p_i), j.hole_dir));
    const Real m_scale = norm(sub(m, j.p_i)) + j.hole_radius;
    contact.depth = reach.alpha + reach.rho;
    contact.p_WCj = m;
    contact.p_WCi = sub(m, scale(contact.depth, into_link));
    contact.stop_bound = StopBound::outer_circle;
    if (decided_sign(m_from_axis - j.hole_radius, m_scale, out.tie) <= 0) {
      const Real head_side = stop.position > 0.0 ? 1 : -1;
      const RealVector into_head = scale(head_side, j.pin_dir);
      const Circle edge = make_reference_circle(face_point, j.hole_dir, j.hole_radius);
      const PlaneReach edge_reach = plane_reach(edge, stop_centre, into_head);
      const Real edge_size = abs(edge_reach.alpha) + edge_reach.rho + j.hole_radius;
      contact.stop_bound = StopBound::corner;
      if (decided_sign(edge_reach.alpha + edge_reach.rho, edge_size, out.tie) > 0) {
        contact.depth = edge_reach.alpha + edge_reach.rho;
        contact.p_WCi = add(edge.center, scale(edge.radius, normalized(edge_reach.w)));
        contact.normal_W = scale(Real(-1), into_head);
        contact.p_WCj = add(contact.p_WCi, scale(contact.depth, contact.normal_W));
        // q's distance from the pin's axis (through P_j along a_j) against the head's rim.
        const RealVector q_off = sub(contact.p_WCi, j.p_j);
        const Real q_from_axis = norm(cross(q_off, j.pin_dir));
        if (decided_sign(q_from_axis - Real(stop.outer_radius), norm(q_off) + Real(stop.outer_radius), out.tie) <= 0) {
          contact.stop_bound = StopBound::hole_edge;
        }
      }
      if (contact.stop_bound == StopBound::corner) {
        out.beyond = true;
        contact.points_defined = false;  // beyond the model
      }
    }
  }
  if (contact.depth > j.axial_limit) out.beyond = true;
  out.answer.contacts.push_back(contact);
}

}  // namespace

PinInHoleReferenceAnswer reference_detect_pin_in_hole(const geometry::PinInHoleDimensions& d,
                                                       const geometry::PartPose& hole,
                                                       const geometry::PartPose& pin) {
  Joint j;
  j.hole_radius = Real(d.hole_radius);
  j.pin_radius = Real(d.pin_radius);
  j.half_length = Real(d.hole_length) / 2;
  j.radial_clearance = j.hole_radius - j.pin_radius;
  if (d.stop_count == 2) {
    j.axial_limit = (abs(Real(d.stops[1].position) - Real(d.stops[0].position)) - Real(d.hole_length)) / 2;
  } else {
    j.axial_limit = j.half_length;
  }
  j.p_i = to_real(hole.p_WP);
  j.p_j = to_real(pin.p_WP);
  j.hole_dir = normalized(to_real(hole.axis_W));
  j.pin_dir = normalized(to_real(pin.axis_W));
  j.hole_offset = to_real(geometry::unit_axis(hole));
  j.pin_offset = to_real(geometry::unit_axis(pin));
  const RealVector c = cross(to_real(hole.axis_W), to_real(pin.axis_W));  // exact at this precision
  j.exactly_parallel = c[0] == 0 && c[1] == 0 && c[2] == 0;
  // The library's unit axes decide which face a stop looks at; their sign agrees with a_i . a_j's
  // wherever that is not within a rounding of 0 (the families keep it near +-1).
  j.toward_a = dot(to_real(hole.axis_W), to_real(pin.axis_W)) >= 0 ? 1 : -1;

  PinInHoleReferenceAnswer answer;
  answer.aligned = j.exactly_parallel;
  Collector out{answer};

  // The pin's axis through the hole's mid-plane, within Rh of the hole's axis.
  const Real along = dot(j.pin_dir, j.hole_dir);
  if (along == 0) {
    out.beyond = true;
  } else {
    const RealVector d_ji = sub(j.p_j, j.p_i);
    const Real t = -dot(d_ji, j.hole_dir) / along;
    const RealVector x = add(d_ji, scale(t, j.pin_dir));
    const Real rho = norm(cross(x, j.hole_dir));
    if (decided_sign(rho - j.hole_radius, j.hole_radius + norm(d_ji), out.tie) >= 0) out.beyond = true;
  }

  if (j.exactly_parallel) {
    hole_circle_against_pin(j, 0, ContactBase::mid, out);
    for (const int face : {0, 1}) {
      for (int k = 0; k < d.stop_count; ++k) {
        if (face_of(j, d.stops[k]) == face) stop_against_face(j, d.stops[k], true, out);
      }
    }
  } else {
    hole_circle_against_pin(j, 1, ContactBase::a, out);
    hole_circle_against_pin(j, -1, ContactBase::b, out);
    for (const int face : {0, 1}) {
      for (int k = 0; k < d.stop_count; ++k) {
        if (face_of(j, d.stops[k]) == face) stop_against_face(j, d.stops[k], false, out);
      }
    }
  }
  if (out.tie) out.undecided("a sign within kTieWidth of zero");

  if (out.beyond) {
    answer.scenario = PinInHoleScenario::beyond_model;
  } else if (answer.aligned) {
    if (out.faces > 1) {
      answer.scenario = PinInHoleScenario::beyond_model;
    } else if (out.line) {
      answer.scenario = out.faces == 1 ? PinInHoleScenario::line_and_face : PinInHoleScenario::line;
    } else {
      answer.scenario = out.faces == 1 ? PinInHoleScenario::face : PinInHoleScenario::none;
    }
  } else if (out.radial > 0 && out.axial > 0) {
    answer.scenario = PinInHoleScenario::edges_and_stops;
  } else if (out.axial > 0) {
    answer.scenario = out.axial == 1 ? PinInHoleScenario::one_stop : PinInHoleScenario::both_stops;
  } else if (out.radial == 1) {
    answer.scenario = PinInHoleScenario::one_edge;
  } else if (out.radial == 2) {
    const Real facing = dot(answer.contacts[0].normal_W, answer.contacts[1].normal_W);
    if (decided_sign(facing, Real(1), out.tie) == 0) out.undecided("the two edge normals are perpendicular");
    answer.scenario = facing < 0 ? PinInHoleScenario::both_edges_opposite : PinInHoleScenario::both_edges_same_side;
  }
  return answer;
}

}  // namespace clearjoint::bench
