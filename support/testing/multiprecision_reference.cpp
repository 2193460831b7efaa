// SPDX-License-Identifier: BSD-3-Clause
#include "multiprecision_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <boost/multiprecision/gmp.hpp>

#include "trig_quadratic_roots.hpp"

namespace clearjoint::test::reference {
namespace {

using geometry::Circle3;
using geometry::CircleCylinderTopology;
using geometry::CirclePlaneTopology;
using geometry::Cylinder3;
using geometry::Plane3;
using geometry::Vector3;
using Rational = boost::multiprecision::mpq_rational;

/// Polynomial coefficients below this (after scaling the polynomial to max |coefficient| = 1) are
/// zero: the working precision is 1e-150 and every quantity is a short sum of products, so rounding
/// leaves far less than this, while any true coefficient of a non-ambiguous problem is far larger
/// (the Sturm remainders of roots kAmbiguousSeparation apart are ~1e-100).
const Real kNegligible("1e-125");
/// Safety cap on bisection steps (each halves the interval; 2^-700 is far below kRootWidth even
/// for the largest root bound).
constexpr int kMaxBisections = 700;

// ---- small vector algebra in MPFR -------------------------------------------------------------

RealVector to_real(const Vector3& v) { return {Real(v.x()), Real(v.y()), Real(v.z())}; }
Real dot(const RealVector& a, const RealVector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
RealVector cross(const RealVector& a, const RealVector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
RealVector sub(const RealVector& a, const RealVector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
RealVector add(const RealVector& a, const RealVector& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
RealVector scale(const Real& s, const RealVector& a) { return {s * a[0], s * a[1], s * a[2]}; }
Real norm(const RealVector& a) { return sqrt(dot(a, a)); }

const Real& pi_constant() {
  static const Real pi = atan(Real(1)) * 4;
  return pi;
}

Real wrap_angle(Real a) {
  const Real period = two_pi();
  a = fmod(a, period);
  if (a < 0) a += period;
  if (a >= period) a -= period;
  return a;
}

// ---- the rim frame, frame_of's definition evaluated in MPFR ------------------------------------

struct RimFrame {
  RealVector center;
  RealVector u;
  RealVector v;
  Real radius;
};

RimFrame rim_frame(const Circle3& circle) {
  // k = index of the smallest |normal_k|, first on ties (comparisons of doubles are exact).
  int k = 0;
  double smallest = std::abs(circle.normal.x());
  if (std::abs(circle.normal.y()) < smallest) {
    k = 1;
    smallest = std::abs(circle.normal.y());
  }
  if (std::abs(circle.normal.z()) < smallest) k = 2;
  const RealVector n = to_real(circle.normal);
  RealVector e{Real(0), Real(0), Real(0)};
  e[k] = 1;
  const RealVector u_raw = cross(n, e);
  RimFrame frame;
  frame.center = to_real(circle.center);
  frame.u = scale(1 / norm(u_raw), u_raw);
  frame.v = cross(scale(1 / norm(n), n), frame.u);
  frame.radius = Real(circle.radius);
  return frame;
}

RealVector frame_point(const RimFrame& f, const Real& cos_a, const Real& sin_a) {
  return add(f.center, scale(f.radius, add(scale(cos_a, f.u), scale(sin_a, f.v))));
}

// ---- trigonometric quadratics and their roots (support/multiprecision) -------------------------

using TrigQuadratic = multiprecision::TrigQuadratic<Real>;
using Poly = multiprecision::Poly<Real>;
using multiprecision::derivative;
using multiprecision::horner;
using multiprecision::sign_of;
using RealRoot = multiprecision::IsolatedRoot<Real>;

bool normalise(Poly& p) { return multiprecision::normalise(p, kNegligible); }
std::vector<RealRoot> real_roots(const Poly& e) {
  // Clusters narrower than kRootWidth are reported as such (multiplicity_hint > 1: ambiguous).
  static const multiprecision::IsolationLimits<Real> limits{kNegligible, Real(kRootWidth), Real(kRootWidth),
                                                            kMaxBisections};
  return multiprecision::real_roots(e, limits);
}

/// Discriminant of e4 t^4 + e3 t^3 + e2 t^2 + e1 t + e0 through the invariants
/// I = 12 a e - 3 b d + c^2 and J = 72 a c e + 9 b c d - 27 a d^2 - 27 e b^2 - 2 c^3:
/// disc = (4 I^3 - J^2) / 27.
Real quartic_discriminant(const Poly& p) {
  const Real &a = p[4], &b = p[3], &c = p[2], &d = p[1], &e = p[0];
  const Real i = 12 * a * e - 3 * b * d + c * c;
  const Real j = 72 * a * c * e + 9 * b * c * d - 27 * a * d * d - 27 * e * b * b - 2 * c * c * c;
  return (4 * i * i * i - j * j) / 27;
}

struct SolvedRoot {
  Real t;      // tan((theta - phi) / 2)
  Real cos_a;  // cos(theta), sin(theta): rational in t, no trigonometric function needed
  Real sin_a;
  Real angle;  // theta in [0, 2 pi)
  int multiplicity_hint = 1;
};

struct TrigSolution {
  bool ambiguous = false;
  std::string why;
  bool vanishes = false;  ///< f == 0 to working precision
  int sign_without_roots = 0;  ///< the sign of f when it has no real root
  std::vector<SolvedRoot> roots;  ///< sorted by angle
  /// For each gap between consecutive roots (gap i follows roots[i], cyclically), f's sign there.
  std::vector<int> gap_signs;
};

/// All real roots of f on [0, 2 pi). `size` is the scale of the terms whose sum f is (so f == 0
/// means cancellation down to the working precision).
TrigSolution solve(const TrigQuadratic& f, const Real& size) {
  TrigSolution out;
  if (f.fourier_size() <= kNegligible * size) {
    out.vanishes = true;
    out.ambiguous = true;
    out.why = "excess function vanishes to working precision";
    return out;
  }
  const multiprecision::HalfAngleQuartic<Real> quartic = multiprecision::half_angle_quartic(f);
  const Real& cphi = quartic.cphi;
  const Real& sphi = quartic.sphi;
  const Real phi = pi_constant() * quartic.k / 4;
  Poly e = quartic.e;
  if (!normalise(e) || e.size() != 5) {
    out.ambiguous = true;
    out.why = "quartic degenerate after the shift";
    return out;
  }
  const std::vector<RealRoot> t_roots = real_roots(e);
  for (std::size_t i = 0; i < t_roots.size(); ++i) {
    if (t_roots[i].multiplicity_hint > 1) {
      out.ambiguous = true;
      out.why = "multiple root or cluster of roots";
    }
    if (i > 0 && t_roots[i].t - t_roots[i - 1].t < kAmbiguousSeparation) {
      out.ambiguous = true;
      out.why = "two real roots closer than 1e-50";
    }
  }
  // A near-double root that is not real (a complex pair t0 +- i eps) shows as a real critical
  // point t0 with |e(t0)| ~ e''(t0) eps^2 / 2. Roots 2 eps < kAmbiguousSeparation apart are
  // ambiguous. The discriminant screens first: |disc| = a^6 prod (t_i - t_j)^2 <= a^6 d_min^2
  // (2 bound)^10, so a larger one proves every pair of complex roots is kAmbiguousSeparation apart.
  if (!out.ambiguous) {
    const Real disc = abs(quartic_discriminant(e));
    const Real sep = Real(kAmbiguousSeparation);
    const Real threshold = pow(e[4], 6) * sep * sep * pow(2 * multiprecision::cauchy_bound(e), 10);
    if (disc <= threshold) {
      Poly de = derivative(e);
      normalise(de);
      const Poly dde = derivative(derivative(e));
      for (const RealRoot& c : real_roots(de)) {
        const Real value = abs(horner(e, c.t));
        if (value <= std::max(Real(abs(horner(dde, c.t)) * sep * sep / 8), kNegligible)) {
          out.ambiguous = true;
          out.why = "a near-double root (real or complex) closer than 1e-50";
        }
      }
    }
  }

  // Signs between consecutive roots in t order; the last gap wraps through t = infinity, where
  // the sign is that of the leading coefficient.
  std::vector<int> t_gap_signs;
  for (std::size_t i = 0; i < t_roots.size(); ++i) {
    if (i + 1 < t_roots.size()) {
      t_gap_signs.push_back(sign_of(horner(e, (t_roots[i].t + t_roots[i + 1].t) / 2)));
    } else {
      t_gap_signs.push_back(sign_of(e[4]));
    }
  }
  if (t_roots.empty()) {
    Real best_abs = 0;
    for (const Real& t : {Real(-1), Real(0), Real(1)}) {
      const Real value = horner(e, t);
      if (abs(value) > best_abs) {
        best_abs = abs(value);
        out.sign_without_roots = sign_of(value);
      }
    }
  }

  // Back to theta. theta = phi + 2 atan(t) increases with t over (phi - pi, phi + pi), so the angle
  // order is a rotation of the t order.
  std::vector<SolvedRoot> roots;
  for (const RealRoot& root : t_roots) {
    const Real& t = root.t;
    SolvedRoot r;
    r.t = t;
    const Real denom = 1 + t * t;
    const Real cpsi = (1 - t * t) / denom;
    const Real spsi = 2 * t / denom;
    r.cos_a = cphi * cpsi - sphi * spsi;
    r.sin_a = sphi * cpsi + cphi * spsi;
    r.angle = wrap_angle(phi + 2 * atan(t));
    r.multiplicity_hint = root.multiplicity_hint;
    roots.push_back(std::move(r));
  }
  std::size_t first = 0;
  for (std::size_t i = 1; i < roots.size(); ++i) {
    if (roots[i].angle < roots[first].angle) first = i;
  }
  for (std::size_t i = 0; i < roots.size(); ++i) {
    out.roots.push_back(roots[(first + i) % roots.size()]);
    out.gap_signs.push_back(t_gap_signs[(first + i) % roots.size()]);
  }
  return out;
}

struct CylinderSetup {
  RimFrame frame;
  RealVector axis_point, axis;
  Real cylinder_radius;
  TrigQuadratic excess;  // G(theta) = |(x - p) x a|^2 - R^2 |a|^2
  Real size;
};

CylinderSetup cylinder_setup(const Circle3& circle, const Cylinder3& cylinder) {
  CylinderSetup s;
  s.frame = rim_frame(circle);
  s.axis_point = to_real(cylinder.axis_point);
  s.axis = to_real(cylinder.axis);
  s.cylinder_radius = Real(cylinder.radius);
  const RealVector A = cross(sub(s.frame.center, s.axis_point), s.axis);
  const RealVector B = scale(s.frame.radius, cross(s.frame.u, s.axis));
  const RealVector C = scale(s.frame.radius, cross(s.frame.v, s.axis));
  const Real r2a2 = s.cylinder_radius * s.cylinder_radius * dot(s.axis, s.axis);
  const Real AA = dot(A, A), BB = dot(B, B), CC = dot(C, C);
  s.excess = {AA - r2a2, 2 * dot(A, B), 2 * dot(A, C), BB, CC, 2 * dot(B, C)};
  s.size = AA + r2a2 + BB + CC;
  return s;
}

Real distance_to_axis_squared(const CylinderSetup& s, const RealVector& x) {
  const RealVector c = cross(sub(x, s.axis_point), s.axis);
  return dot(c, c) / dot(s.axis, s.axis);
}

}  // namespace

Real two_pi() {
  static const Real value = 2 * pi_constant();
  return value;
}

Real circular_distance(const Real& a, const Real& b) {
  const Real d = wrap_angle(a - b);
  return std::min(d, Real(two_pi() - d));
}

Real distance(const Vector3& p, const RealVector& q) { return norm(sub(to_real(p), q)); }

RealVector rim_point(const Circle3& circle, const Real& angle) {
  return frame_point(rim_frame(circle), cos(angle), sin(angle));
}

int CylinderReference::root_count() const {
  int n = 0;
  for (const auto& r : roots) n += r.multiplicity_hint;
  return n;
}

CylinderReference reference_circle_cylinder(const Circle3& circle, const Cylinder3& cylinder) {
  const CylinderSetup s = cylinder_setup(circle, cylinder);
  const TrigSolution sol = solve(s.excess, s.size);
  CylinderReference out;
  out.ambiguous = sol.ambiguous;
  out.why = sol.why;
  if (sol.vanishes) {
    out.topology = CircleCylinderTopology::on_surface;
    return out;
  }
  for (const SolvedRoot& r : sol.roots) {
    out.roots.push_back({r.angle, frame_point(s.frame, r.cos_a, r.sin_a), r.multiplicity_hint});
  }
  if (out.roots.empty()) {
    out.topology = sol.sign_without_roots > 0 ? CircleCylinderTopology::outside
                                              : CircleCylinderTopology::inside;
    if (sol.sign_without_roots > 0) out.outside_arcs.push_back({Real(0), two_pi()});
    return out;
  }
  out.topology = CircleCylinderTopology::crossing;
  const std::size_t n = sol.roots.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (sol.gap_signs[i] > 0) out.outside_arcs.push_back({sol.roots[i].angle, sol.roots[(i + 1) % n].angle});
  }
  return out;
}

Real cylinder_excess(const Circle3& circle, const Cylinder3& cylinder, const Real& angle) {
  const CylinderSetup s = cylinder_setup(circle, cylinder);
  return s.excess.at(cos(angle), sin(angle)) / dot(s.axis, s.axis);
}

FarthestReach farthest_reach(const Circle3& circle, const Cylinder3& cylinder) {
  const CylinderSetup s = cylinder_setup(circle, cylinder);
  const TrigSolution critical = solve(s.excess.derivative(), s.size);
  FarthestReach out;
  out.ambiguous = critical.ambiguous;
  if (critical.roots.empty()) {
    out.ambiguous = true;
    return out;
  }
  Real best = -1;
  for (const SolvedRoot& r : critical.roots) {
    const RealVector x = frame_point(s.frame, r.cos_a, r.sin_a);
    const Real d2 = distance_to_axis_squared(s, x);
    if (d2 > best) {
      best = d2;
      out.angle = r.angle;
      out.point = x;
    }
  }
  const RealVector w = sub(out.point, s.axis_point);
  const RealVector along = scale(dot(w, s.axis) / dot(s.axis, s.axis), s.axis);
  const RealVector radial = sub(w, along);
  out.distance = norm(radial);
  out.radial = scale(1 / out.distance, radial);
  return out;
}

Real plane_signed_distance(const Circle3& circle, const Plane3& plane, const Real& angle) {
  const RealVector x = rim_point(circle, angle);
  const RealVector n = to_real(plane.normal);
  return dot(n, sub(x, to_real(plane.point))) / norm(n);
}

PlaneReference reference_circle_plane(const Circle3& circle, const Plane3& plane) {
  PlaneReference out;
  // Exact classification with rationals: alpha = n_p . (c - p); the rim's signed offsets from the
  // centre's level span [-rho, rho] with rho^2 |n_c|^2 = r^2 |n_p x n_c|^2.
  auto q = [](double x) { return Rational(x); };
  const Rational npx = q(plane.normal.x()), npy = q(plane.normal.y()), npz = q(plane.normal.z());
  const Rational ncx = q(circle.normal.x()), ncy = q(circle.normal.y()), ncz = q(circle.normal.z());
  const Rational alpha = npx * (q(circle.center.x()) - q(plane.point.x())) +
                         npy * (q(circle.center.y()) - q(plane.point.y())) +
                         npz * (q(circle.center.z()) - q(plane.point.z()));
  const Rational cx = npy * ncz - npz * ncy, cy = npz * ncx - npx * ncz, cz = npx * ncy - npy * ncx;
  const Rational cross2 = cx * cx + cy * cy + cz * cz;
  const Rational nc2 = ncx * ncx + ncy * ncy + ncz * ncz;
  const Rational r2 = q(circle.radius) * q(circle.radius);
  const int alpha_sign = alpha > 0 ? 1 : (alpha < 0 ? -1 : 0);
  const Rational lhs = alpha * alpha * nc2, rhs = r2 * cross2;
  if (cross2 == 0 && alpha_sign == 0) {
    out.topology = CirclePlaneTopology::circle_in_plane;
    out.side = 0;
  } else if (lhs > rhs) {
    out.topology = CirclePlaneTopology::disjoint;
    out.side = alpha_sign;
  } else if (lhs == rhs) {
    out.topology = CirclePlaneTopology::tangent;
    out.side = alpha_sign;
  } else {
    out.topology = CirclePlaneTopology::two_crossings;
    out.side = 0;
  }

  // Closed form in MPFR: signed distance * |n_p| = alpha + beta cos + gamma sin.
  const RimFrame f = rim_frame(circle);
  const RealVector np = to_real(plane.normal);
  const Real np_norm = norm(np);
  const Real a = dot(np, sub(f.center, to_real(plane.point)));
  const Real beta = f.radius * dot(np, f.u);
  const Real gamma = f.radius * dot(np, f.v);
  const Real rho = sqrt(beta * beta + gamma * gamma);
  const Real theta0 = (rho == 0) ? Real(0) : wrap_angle(atan2(gamma, beta));
  out.deepest_angle = theta0;
  out.max_signed_distance = (a + rho) / np_norm;
  out.has_positive_points = out.max_signed_distance > 0 &&
                            out.topology != CirclePlaneTopology::circle_in_plane;
  auto add_root = [&](const Real& angle, int multiplicity) {
    out.roots.push_back({angle, frame_point(f, cos(angle), sin(angle)), multiplicity});
  };
  if (out.topology == CirclePlaneTopology::tangent) {
    // alpha > 0: touches at the minimum theta0 + pi; alpha < 0: at the maximum theta0.
    add_root(wrap_angle(alpha_sign > 0 ? theta0 + pi_constant() : theta0), 2);
  } else if (out.topology == CirclePlaneTopology::two_crossings) {
    const Real half_width = acos(-a / rho);
    add_root(wrap_angle(theta0 - half_width), 1);
    add_root(wrap_angle(theta0 + half_width), 1);
    if (out.roots[1].angle < out.roots[0].angle) std::swap(out.roots[0], out.roots[1]);
  }
  return out;
}

}  // namespace clearjoint::test::reference
