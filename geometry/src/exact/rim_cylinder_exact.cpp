// SPDX-License-Identifier: BSD-3-Clause
// The exact problem (docs/circle-cylinder.md, section 4). Write rim points as
//   x = c + X u' + Y v',   u' = n x e_k (exact), v' = n x u',  a = |u'|^2, b = |v'|^2,
// so the rim is the ellipse E: a X^2 + b Y^2 = r^2 in the (X, Y) plane, with rational
// coefficients, and the cylinder is the conic Q: |A + X B + Y C|^2 - R^2 D = 0 with A = q x d,
// B = u' x d, C = v' x d, D = |d|^2. Modulo E, Q = L(X) + Y M(X) with
//   L = q00 + q10 X + q20 X^2 + q02 (r^2 - a X^2) / b,   M = q01 + q11 X,
// which has the same intersection points and multiplicities with E. Eliminating Y gives
//   P(X) = (a X^2 - r^2) M^2 + b L^2   (degree <= 4),
// whose real roots are the crossings, one each, unless L and M share a root X0 (then the
// crossings are E meeting the line X = X0 and the line L/(X - X0) + q11 Y = 0).

#include "rim_cylinder_exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "angles.hpp"
#include "exact_rational_point.hpp"
#include "primitives_detail.hpp"
#include "real_root_isolation.hpp"

namespace clearjoint::geometry::detail {
namespace {

using Polynomial = RationalPolynomial;

constexpr CertificateReason kBeyondDoubleRange = CertificateReason::exact_intermediate_beyond_double_range;

/// A double computed from rationals, about to become a rational or an angle: a Gmpq made from
/// an infinity or a NaN aborts the process (GMP raises SIGFPE), so refuse it first.
double finite_or_give_up(double x) {
  if (!std::isfinite(x)) throw ExactTierGiveUp{kBeyondDoubleRange};
  return x;
}

struct RationalVector {
  Rational x, y, z;
};
RationalVector exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }
RationalVector operator-(const RationalVector& a, const RationalVector& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Rational dot(const RationalVector& a, const RationalVector& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
RationalVector cross(const RationalVector& a, const RationalVector& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Bounded to_bounded(const Rational& x) {
  const std::pair<double, double> range = CGAL::to_interval(x);
  const double middle = 0.5 * (range.first + range.second);
  return {middle, std::max(middle - range.first, range.second - middle) * kErrorInflation};
}

/// The exact problem in (X, Y) coordinates.
struct RimConic {
  Rational a, b, r2;  // ellipse a X^2 + b Y^2 = r2
  Polynomial L, M;    // the cylinder modulo the ellipse: L(X) + Y M(X) = 0
  Rational bound;     // a power of two with a bound^2 > r2: every real crossing has |X| < bound
};

/// A crossing in (X, Y): X in an interval; Y either from -L/M or +-sqrt((r2 - a X^2) / b).
struct Crossing {
  Bounded x, y;
  int multiplicity;
};

Bounded polynomial_value(const Polynomial& p, const Bounded& x) {
  Bounded value(0.0);
  for (int i = p.degree(); i >= 0; --i) value = value * x + to_bounded(p[i]);
  return value;
}

Bounded bounded_x(const IsolatedRoot& root) {
  const Bounded low = to_bounded(root.low), high = to_bounded(root.high);
  const double middle = 0.5 * (low.value + high.value);
  const double radius = std::max(high.value + high.error - middle, middle - low.value + low.error);
  return {middle, radius * kErrorInflation};
}

/// |Y| from the ellipse equation, for X in the given enclosure.
Bounded ellipse_height(const RimConic& conic, const Bounded& x) {
  const Bounded y2 = (to_bounded(conic.r2) - to_bounded(conic.a) * x * x) / to_bounded(conic.b);
  return sqrt(Bounded(std::fmax(y2.value, 0.0), y2.error + std::fmax(-y2.value, 0.0)));
}

/// Crossings on a vertical line X = root: both ellipse points, or the vertex (Y = 0, doubled
/// multiplicity) when a X^2 = r2 exactly.
void add_vertical_line_crossings(const RimConic& conic, const IsolatedRoot& root, int multiplicity,
                                 std::vector<Crossing>& out) {
  const Polynomial vertex_test(-conic.r2, Rational(0), conic.a);  // a X^2 - r2
  const Bounded x = bounded_x(root);
  if (root.low == root.high) {
    const CGAL::Sign s = vertex_test.sign_at(root.low);
    if (s == CGAL::ZERO) {
      out.push_back({x, Bounded(0.0), 2 * multiplicity});
      return;
    }
    if (s == CGAL::POSITIVE) return;  // the line misses the ellipse
  } else {
    // Irrational root: it is a vertex exactly when the factor shares it with a X^2 - r2.
    const Polynomial factor = root.factor->monic();
    const Polynomial common = CGAL::gcd(factor, vertex_test);
    if (common.degree() >= 1 && SturmSequence(common).roots_in(root.low, root.high) > 0 &&
        !(root.low == root.high)) {
      out.push_back({x, Bounded(0.0), 2 * multiplicity});
      return;
    }
    // Not a vertex: refine until a X^2 - r2 has no root on the interval, then read its sign.
    Rational low = root.low, high = root.high;
    const SturmSequence vertices(vertex_test);
    while (vertices.roots_in(low, high) > 0 || vertex_test.sign_at(high) == CGAL::ZERO) {
      const Rational middle = (low + high) / 2;
      const CGAL::Sign at_middle = factor.sign_at(middle);
      if (at_middle == CGAL::ZERO) {
        low = high = middle;
        break;
      }
      if (at_middle == factor.sign_at(high)) high = middle; else low = middle;
    }
    if (vertex_test.sign_at(high) == CGAL::POSITIVE) return;
  }
  const Bounded height = ellipse_height(conic, x);
  out.push_back({x, height, multiplicity});
  out.push_back({x, -height, multiplicity});
}

/// Crossings where Y = -N(X) / m with N linear or quadratic and m a nonzero constant or a linear
/// M without root on the isolating interval.
void add_graph_crossings(const RimConic& conic, const Polynomial& numerator,
                         const Polynomial& denominator, const IsolatedRoot& root,
                         std::vector<Crossing>& out) {
  const Bounded x = bounded_x(root);
  Bounded y = -(polynomial_value(numerator, x) / polynomial_value(denominator, x));
  const Bounded height = ellipse_height(conic, x);
  if (y.finite() && y.sign() != 0) {
    // The ellipse often bounds |Y| tighter; the proved sign of -N/M picks the half.
    if (height.error < y.error) y = y.sign() > 0 ? height : -height;
  } else {
    // Y too close to 0 to sign: an enclosure symmetric about 0 is still rigorous.
    y = Bounded(0.0, height.value + height.error);
  }
  out.push_back({x, y, root.multiplicity});
}

/// Exact sign of g at the rim point with rational X and Y of the given sign (Y^2 from E).
int exact_sign_at(const RimConic& conic, const Rational& x, int y_sign) {
  const Rational y2 = (conic.r2 - conic.a * x * x) / conic.b;
  const Rational l = conic.L.evaluate(x);
  const Rational m = conic.M.evaluate(x) * y_sign;
  const int sl = CGAL::sign(l), sm = CGAL::sign(m);
  if (sm == 0 || CGAL::sign(y2) == 0) return sl;
  if (sl == 0 || sl == sm) return sl == 0 ? sm : sl;
  // l + sqrt(y2) m with opposite signs: compare squares.
  return sl * static_cast<int>(CGAL::sign(l * l - y2 * m * m));
}

}  // namespace

namespace {

RationalVector exact_centre(const Circle3& circle, const RoundedPoint* centre, int scale_exponent) {
  if (centre == nullptr) return exact(circle.center);
  const std::array<Rational, 3> c = exact_rational_point(*centre, scale_exponent);
  return {c[0], c[1], c[2]};
}

RimRoots exact_rim_roots_within_budget(const Circle3& circle, const Cylinder3& cylinder,
                                      const RoundedPoint* centre, int scale_exponent,
                                      EvaluationBudget& budget) {
  const RationalVector c = exact_centre(circle, centre, scale_exponent), n = exact(circle.normal);
  const RationalVector q = c - exact(cylinder.axis_point), d = exact(cylinder.axis);
  const Vector3 u_double = circle.normal.cross(Vector3::Unit(frame_axis_index(circle.normal)));
  const RationalVector u = exact(u_double);
  const RationalVector v = cross(n, u);
  const RationalVector A = cross(q, d), B = cross(u, d), C = cross(v, d);
  const Rational r = circle.radius, R = cylinder.radius;

  RimConic conic;
  conic.a = dot(u, u);
  conic.b = dot(v, v);
  conic.r2 = r * r;
  const Rational q00 = dot(A, A) - R * R * dot(d, d);
  const Rational q10 = 2 * dot(A, B), q01 = 2 * dot(A, C);
  const Rational q20 = dot(B, B), q11 = 2 * dot(B, C), q02 = dot(C, C);
  // b L, whose coefficients are dyadic like every quantity above (sums of products of doubles):
  // L's own carry b's odd part in their denominators, and every product of them a gcd.
  const Polynomial scaled_L(conic.b * q00 + q02 * conic.r2, conic.b * q10, conic.b * q20 - q02 * conic.a);
  conic.L = Polynomial(scaled_L[0] / conic.b, q10, scaled_L.degree() == 2 ? scaled_L[2] / conic.b : Rational(0));
  conic.M = Polynomial(q01, q11);
  // |X| <= r / sqrt(a) on the ellipse; use a power of two above it. The first guess comes from
  // the binary exponents (r / sqrt(a) itself can overflow a double, and a Gmpq made from an
  // infinity aborts the process), clamped to the double range; the loop makes it a bound.
  const int bound_exponent = std::clamp(
      std::ilogb(circle.radius) - std::ilogb(CGAL::to_double(conic.a)) / 2 + 2, -1000, 1000);
  conic.bound = Rational(std::ldexp(1.0, bound_exponent));
  while (conic.bound * conic.bound * conic.a <= conic.r2) conic.bound = conic.bound * 2;

  RimRoots result;
  result.proved = true;
  if (conic.L.is_zero() && conic.M.is_zero()) {
    result.side_without_roots = RimSideWithoutRoots::on_surface;  // g vanishes on the whole rim
    return result;
  }

  std::vector<Crossing> crossings;
  std::vector<IsolatedRoot> roots;
  if (conic.M.is_zero()) {
    // The cylinder meets E along vertical lines L(X) = 0.
    isolate_real_roots(conic.L, conic.bound * 2, roots, budget);
    for (const IsolatedRoot& root : roots)
      add_vertical_line_crossings(conic, root, root.multiplicity, crossings);
  } else {
    // L(-M0 / M1) = 0, times b M1^2 (nonzero): b L's homogeneous form at (-M0, M1), dyadic.
    const auto scaled_L_at = [&](int i) { return i <= scaled_L.degree() ? scaled_L[i] : Rational(0); };
    const bool shared_root =
        conic.M.degree() == 1 && scaled_L_at(0) * conic.M[1] * conic.M[1] - scaled_L_at(1) * conic.M[0] * conic.M[1] +
                                         scaled_L_at(2) * conic.M[0] * conic.M[0] ==
                                     Rational(0);
    if (!shared_root) {
      // b P = b (a X^2 - r^2) M^2 + (b L)^2: P's roots, from dyadic coefficients; the
      // coefficient limit applies to P's own.
      const Polynomial ellipse(-conic.r2, Rational(0), conic.a);
      const Polynomial scaled_eliminated = conic.b * ellipse * conic.M * conic.M + scaled_L * scaled_L;
      isolate_real_roots(scaled_eliminated, conic.bound, roots, budget, conic.b);
      for (const IsolatedRoot& root : roots)
        add_graph_crossings(conic, conic.L, conic.M, root, crossings);
    } else {
      // L = (X - X0) L1, M = q11 (X - X0): the line X = X0 and the line L1 + q11 Y = 0.
      const Rational x0 = -conic.M[0] / conic.M[1];
      Polynomial l1, remainder;
      Polynomial::euclidean_division(conic.L, Polynomial(-x0, Rational(1)), l1, remainder);
      const Polynomial m1(conic.M[1]);
      std::vector<Crossing> on_lines;
      add_vertical_line_crossings(conic, {x0, x0, 1, nullptr}, 1, on_lines);
      const Polynomial ellipse(-conic.r2, Rational(0), conic.a);
      const Polynomial second_line = ellipse * m1 * m1 + conic.b * l1 * l1;
      isolate_real_roots(second_line, conic.bound, roots, budget);
      for (const IsolatedRoot& root : roots) {
        if (root.low <= x0 && x0 <= root.high && second_line.evaluate(x0) == Rational(0)) {
          // The two lines meet on E: that vertical-line point gains this multiplicity.
          const int y_sign = -static_cast<int>(l1.sign_at(x0)) * static_cast<int>(CGAL::sign(conic.M[1]));
          for (Crossing& point : on_lines) {
            if (y_sign == 0 || (point.y.value > 0) == (y_sign > 0))
              point.multiplicity += root.multiplicity;
          }
          continue;
        }
        add_graph_crossings(conic, l1, m1, root, on_lines);
      }
      crossings = std::move(on_lines);
    }
  }

  // Rational (X, Y) enclosures to rim angles: theta = atan2(Y |v'|, X |u'|); the vector
  // (X |u'|, Y |v'|) has length r, so a displacement delta moves the angle by at most
  // (pi / 2) |delta| / r.
  const double u_norm = finite_or_give_up(std::sqrt(CGAL::to_double(conic.a)));
  const double v_norm = finite_or_give_up(std::sqrt(CGAL::to_double(conic.b)));
  if (!(u_norm > 0.0 && v_norm > 0.0)) throw ExactTierGiveUp{kBeyondDoubleRange};
  for (const Crossing& crossing : crossings) {
    if (result.count == 4) break;  // cannot happen for a proper rim (degree 4)
    RootEnclosure& root = result.roots[result.count++];
    root.angle = wrap_angle(std::atan2(crossing.y.value * v_norm, crossing.x.value * u_norm));
    const double displacement =
        finite_or_give_up(std::hypot(crossing.x.error * u_norm, crossing.y.error * v_norm));
    root.radius = (0.5 * std::numbers::pi * displacement / circle.radius +
                   8 * kUnitRoundoff * (1.0 + root.angle)) * kErrorInflation;
    root.multiplicity = crossing.multiplicity;
  }
  sort_by_angle(result);

  // One exact sign of g at a rim point in the widest gap between roots, then parity: a root of
  // odd multiplicity flips the sign, an even one keeps it.
  double gap_start = 0.0, widest = -1.0;
  int after_index = -1;
  for (int i = 0; i < result.count; ++i) {
    const double from = result.roots[i].angle;
    const double to = i + 1 < result.count ? result.roots[i + 1].angle
                                           : result.roots[0].angle + kTwoPi;
    if (to - from > widest) {
      widest = to - from;
      gap_start = from;
      after_index = i;
    }
  }
  const double sample = result.count == 0 ? 1.0 : gap_start + 0.5 * widest;
  // A rational X on the rim with the sample's half: shrink by a part in 2^40 to stay on E.
  const Rational x_sample =
      Rational(finite_or_give_up(circle.radius * std::cos(sample) / u_norm * (1 - 0x1p-40)));
  int sign = exact_sign_at(conic, x_sample, std::sin(sample) >= 0 ? 1 : -1);
  if (result.count == 0) {
    result.side_without_roots = side_of_sign(sign);
    return result;
  }
  for (int step = 0; step < result.count; ++step) {
    const int i = (after_index + step) % result.count;
    result.roots[i].sign_after = sign;
    const int next = (i + 1) % result.count;
    if (result.roots[next].multiplicity % 2 == 1) sign = -sign;
  }
  return result;
}

}  // namespace

RimRoots exact_rim_roots(const Circle3& circle, const Cylinder3& cylinder,
                         const RoundedPoint* centre, int scale_exponent) {
  EvaluationBudget budget;
  try {
    return exact_rim_roots_within_budget(circle, cylinder, centre, scale_exponent, budget);
  } catch (const ExactTierGiveUp& gave_up) {
    RimRoots result;
    result.proved = false;
    result.failure = gave_up.why;
    return result;
  }
}

}  // namespace clearjoint::geometry::detail
