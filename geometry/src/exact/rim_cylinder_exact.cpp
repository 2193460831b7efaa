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

#include "exact/rim_cylinder_exact.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "arithmetic/angles.hpp"
#include "exact/exact_dyadic.hpp"
#include "exact/exact_rational_point.hpp"
#include "exact/real_root_isolation.hpp"
#include "model/primitives_detail.hpp"

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

/// An enclosure [low, high] of doubles as a Bounded.
Bounded to_bounded(const std::pair<double, double>& range) {
  const double middle = 0.5 * (range.first + range.second);
  return {middle, std::max(middle - range.first, range.second - middle) * kErrorInflation};
}
Bounded to_bounded(const Rational& x) { return to_bounded(interval_of(x)); }

/// The exact problem in (X, Y) coordinates.
struct RimConic {
  Rational a, b, r2;  // ellipse a X^2 + b Y^2 = r2
  Polynomial M;       // the cylinder modulo the ellipse: L(X) + Y M(X) = 0
  /// L in rationals, formed at its first use (make_l): where M has no root in common with it,
  /// the crossings need only its coefficients as Bounded, which the integers give without the
  /// fraction each rational coefficient reduces.
  const Polynomial& L() const {
    if (!l_) l_ = make_l();
    return *l_;
  }
  std::function<Polynomial()> make_l;
  mutable std::optional<Polynomial> l_;
  Rational bound;     // a power of two with a bound^2 > r2: every real crossing has |X| < bound
  // a, b and r2 as Bounded (to_bounded), formed once for every crossing.
  Bounded a_bounded, b_bounded, r2_bounded;
};

/// A crossing in (X, Y): X in an interval; Y either from -L/M or +-sqrt((r2 - a X^2) / b).
struct Crossing {
  Bounded x, y;
  int multiplicity;
};

/// A polynomial's coefficients as Bounded (to_bounded), constant first: formed once per
/// polynomial, read at every crossing.
SmallVector<Bounded> bounded_coefficients(const Polynomial& p) {
  SmallVector<Bounded> out;
  for (int i = 0; i <= p.degree(); ++i) out.push_back(to_bounded(p[i]));
  return out;
}

Bounded polynomial_value(const SmallVector<Bounded>& p, const Bounded& x) {
  Bounded value(0.0);
  for (std::size_t i = p.size(); i-- > 0;) value = value * x + p[i];
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
  const Bounded y2 = (conic.r2_bounded - conic.a_bounded * x * x) / conic.b_bounded;
  return sqrt(Bounded(std::fmax(y2.value, 0.0), y2.error + std::fmax(-y2.value, 0.0)));
}

/// The exact sign of g at the isolated root: 0 when they share it; otherwise `root`'s interval
/// is bisected on its factor's exact signs until g has no root in it, and g's sign there is the
/// answer. The root lies in (low, high] (isolate_real_roots), so that is where g must not vanish.
/// Terminates because g's roots in the interval are not this root.
int sign_at_root(const Polynomial& g, IsolatedRoot& root, EvaluationBudget& budget) {
  if (root.low == root.high) return static_cast<int>(g.sign_at(root.low));
  if (g.degree() < 1) return static_cast<int>(CGAL::sign(g[0]));
  const SquareFreeFactor& factor = *root.factor;
  if (factor.shares_root_in(g, root.low, root.high)) return 0;
  const int sign_high = factor.sign_at(root.high);
  if (sign_high == 0) {
    root.low = root.high;
    return static_cast<int>(g.sign_at(root.high));
  }
  const SturmSequence chain(g);
  while (chain.roots_in(root.low, root.high) > 0) {
    budget.spend();
    const Rational middle = (root.low + root.high) / 2;
    const int at_middle = factor.sign_at(middle);
    if (at_middle == 0) {
      root.low = root.high = middle;
      break;
    }
    (at_middle == sign_high ? root.high : root.low) = middle;
  }
  return static_cast<int>(g.sign_at(root.high));
}

/// Crossings on a vertical line X = root: both ellipse points, or the vertex (Y = 0, doubled
/// multiplicity) when a X^2 = r2 exactly.
void add_vertical_line_crossings(const RimConic& conic, const IsolatedRoot& root, int multiplicity,
                                 SmallVector<Crossing>& out, EvaluationBudget& budget) {
  const Polynomial vertex_test(-conic.r2, Rational(0), conic.a);  // a X^2 - r2
  const Bounded x = bounded_x(root);
  IsolatedRoot refined = root;
  const int vertex_sign = sign_at_root(vertex_test, refined, budget);
  if (vertex_sign == 0) {
    out.push_back({x, Bounded(0.0), 2 * multiplicity});
    return;
  }
  if (vertex_sign > 0) return;  // the line misses the ellipse
  const Bounded height = ellipse_height(conic, x);
  out.push_back({x, height, multiplicity});
  out.push_back({x, -height, multiplicity});
}

/// Crossings where Y = -N(X) / m with N linear or quadratic and m a nonzero constant or a linear
/// M without root at X (`numerator`, `denominator`; their coefficients as Bounded beside them).
/// The double enclosure of -N/M usually signs Y. Near a rim symmetric about the plane through
/// its centre and the cylinder's axis, where two crossings share X and N and M nearly vanish
/// there, it cannot: then the exact signs of N and M at the root decide which half of the
/// ellipse holds the crossing (an enclosure of Y symmetric about 0 would be rigorous but would put
/// both crossings at the same angle with an error of a large part of the rim).
/// `numerator()` gives N (formed only where the double enclosure cannot sign Y).
template <class NumeratorOf>
void add_graph_crossings(const RimConic& conic, const NumeratorOf& numerator, const SmallVector<Bounded>& numerator_bounded,
                         const Polynomial& denominator, const SmallVector<Bounded>& denominator_bounded,
                         const IsolatedRoot& root, SmallVector<Crossing>& out, EvaluationBudget& budget) {
  Bounded x = bounded_x(root);
  Bounded y = -(polynomial_value(numerator_bounded, x) / polynomial_value(denominator_bounded, x));
  Bounded height = ellipse_height(conic, x);
  if (y.finite() && y.sign() != 0) {
    // The ellipse often bounds |Y| tighter; the proved sign of -N/M picks the half.
    if (height.error < y.error) y = y.sign() > 0 ? height : -height;
  } else {
    IsolatedRoot refined = root;
    const int numerator_sign = sign_at_root(numerator(), refined, budget);
    const int denominator_sign = sign_at_root(denominator, refined, budget);
    x = bounded_x(refined);
    height = ellipse_height(conic, x);
    if (denominator_sign == 0) {
      // Cannot happen (M and P sharing a root means L shares it too: the shared-root branch);
      // the enclosure symmetric about 0 stays rigorous.
      y = Bounded(0.0, height.value + height.error);
    } else {
      const int y_sign = -numerator_sign * denominator_sign;
      y = y_sign == 0 ? Bounded(0.0) : y_sign > 0 ? height : -height;
    }
  }
  out.push_back({x, y, root.multiplicity});
}

}  // namespace

namespace {

// ---- The inputs as integers ------------------------------------------------------------------
// Every input is dyadic (a double, or the exact rim centre: doubles combined and scaled by a power
// of two), so all of them are integers times 2^E for one exponent E, and every quantity of the
// conic below is an integer times 2^(k E), k its degree in the inputs (each formula sums terms of
// one degree). Computed so, no operation reduces a fraction; the rationals the crossings need
// are formed from the integers at the end, the same values as with rational arithmetic throughout.

using Integer = mpz_class;

struct IntegerVector {
  Integer x, y, z;
};
IntegerVector operator-(const IntegerVector& a, const IntegerVector& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
// Products accumulated in place (mpz_addmul, mpz_submul): gmpxx's expressions form a temporary,
// an allocation, per product.
Integer dot(const IntegerVector& a, const IntegerVector& b) {
  Integer out;
  mpz_mul(out.get_mpz_t(), a.x.get_mpz_t(), b.x.get_mpz_t());
  mpz_addmul(out.get_mpz_t(), a.y.get_mpz_t(), b.y.get_mpz_t());
  mpz_addmul(out.get_mpz_t(), a.z.get_mpz_t(), b.z.get_mpz_t());
  return out;
}
/// p q - r s
Integer difference_of_products(const Integer& p, const Integer& q, const Integer& r, const Integer& s) {
  Integer out;
  mpz_mul(out.get_mpz_t(), p.get_mpz_t(), q.get_mpz_t());
  mpz_submul(out.get_mpz_t(), r.get_mpz_t(), s.get_mpz_t());
  return out;
}
IntegerVector cross(const IntegerVector& a, const IntegerVector& b) {
  return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
          difference_of_products(a.x, b.y, a.y, b.x)};
}

/// x 2^(degree E): a quantity of that degree in the inputs, as a rational.
Rational rational(const Integer& x, int degree, long exponent) {
  Rational out;
  mpq_set_z(out.mpq(), x.get_mpz_t());
  const long e = degree * exponent;
  if (e > 0) mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(e));
  if (e < 0) mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-e));
  return out;
}

/// The coefficient limit (kMaxCoefficientBits) on P = (b P) / b, from the integers of b P (degree
/// 16) and of b (degree 4): P's coefficient k is scaled_p[k] 2^(12 E) / b in lowest terms, whose
/// bits are at most those of the unreduced fraction; the gcd is taken only when that is too large.
/// The conic's integers (below) that the sign of g at a rim point needs: b L = l0 + l1 X + l2 X^2
/// and M = (m0 + m1 X) 2^(5 E) (their degrees in the inputs: 8 and 5), and the ellipse's a, b, r2.
struct ConicIntegers {
  const Integer &l0, &l1, &l2, &m0, &m1, &a, &b, &r2;
};

/// Exact sign of g at the rim point with X = x (a double, so dyadic) and Y of the given sign (Y^2
/// from E): that of l + Y m with l = L(X), m = M(X), Y = +-sqrt(y2), y2 = (r2 - a X^2) / b.
/// Written as X = n / 2^k (n an integer, k >= 0), each of them is a positive multiple of an
/// integer sum, b > 0 and E's powers of two being positive factors:
///   l ~ L' = l0 4^k + l1 n 2^k + l2 n^2,  m ~ M' = m0 2^k + m1 n,  y2 ~ Y' = r2 4^k - a n^2,
/// and l^2 - y2 m^2 = 2^(8 E) (b L)^2 / b^2 - 2^(8 E) (r2 - a X^2) (m0 + m1 X)^2 / b has the sign
/// of L'^2 - b Y' M'^2. So the sign needs no fraction (the rational form reduced one per
/// operation, on numbers of a thousand bits near a tangency of the joint's rims).
int exact_sign_at(const ConicIntegers& k, double x, int y_sign) {
  int binary_exponent = 0;
  const double fraction = std::frexp(x, &binary_exponent);
  Integer n;
  mpz_set_d(n.get_mpz_t(), std::ldexp(fraction, 53));  // exact: 53 bits
  long shift = 53 - static_cast<long>(binary_exponent);  // X = n / 2^shift
  if (shift < 0) {
    mpz_mul_2exp(n.get_mpz_t(), n.get_mpz_t(), static_cast<mp_bitcnt_t>(-shift));
    shift = 0;
  }
  const auto times_power = [](const Integer& value, long bits) {
    Integer out;
    mpz_mul_2exp(out.get_mpz_t(), value.get_mpz_t(), static_cast<mp_bitcnt_t>(bits));
    return out;
  };
  const Integer n2 = n * n;
  const Integer l = times_power(k.l0, 2 * shift) + times_power(k.l1 * n, shift) + k.l2 * n2;
  const Integer m = times_power(k.m0, shift) + k.m1 * n;
  const Integer y2 = times_power(k.r2, 2 * shift) - k.a * n2;
  const int sl = sgn(l), sm = sgn(m) * y_sign;
  if (sm == 0 || sgn(y2) == 0) return sl;
  if (sl == 0 || sl == sm) return sl == 0 ? sm : sl;
  // l + sqrt(y2) m with opposite signs: compare squares.
  return sl * sgn(l * l - k.b * y2 * m * m);
}

void check_coefficient_size(const SmallVector<Integer>& scaled_p, const Integer& b, long exponent) {
  const std::size_t power_bits = static_cast<std::size_t>(std::labs(12 * exponent)) + 2;
  const std::size_t b_bits = mpz_sizeinbase(b.get_mpz_t(), 2);
  for (const Integer& x : scaled_p) {
    if (mpz_sizeinbase(x.get_mpz_t(), 2) + b_bits + power_bits <= kMaxCoefficientBits) continue;
    if (bit_size(rational(x, 16, exponent) / rational(b, 4, exponent)) > kMaxCoefficientBits) {
      throw ExactTierGiveUp{CertificateReason::exact_coefficients_too_large};
    }
  }
}

RimRoots exact_rim_roots_within_budget(const Circle3& circle, const Cylinder3& cylinder,
                                      const RoundedPoint* centre, int scale_exponent,
                                      EvaluationBudget& budget) {
  // The inputs, each exactly, at one scale 2^E (degree 1).
  std::array<ExactDyadic, 17> inputs;
  const auto put_vector = [&](std::size_t first, const Vector3& v) {
    for (int i = 0; i < 3; ++i) inputs[first + static_cast<std::size_t>(i)] = exact_dyadic(v[i]);
  };
  if (centre == nullptr) {
    put_vector(0, circle.center);
  } else {
    const std::array<ExactDyadic, 3> exact_centre = exact_dyadic_point(*centre, scale_exponent);
    std::copy(exact_centre.begin(), exact_centre.end(), inputs.begin());
  }
  put_vector(3, circle.normal);
  put_vector(6, cylinder.axis_point);
  put_vector(9, cylinder.axis);
  put_vector(12, circle.normal.cross(Vector3::Unit(frame_axis_index(circle.normal))));  // u' = n x e_k, exact
  inputs[15] = exact_dyadic(circle.radius);
  inputs[16] = exact_dyadic(cylinder.radius);
  const IntegersAtCommonExponent<17> scaled = integers_at_common_exponent(inputs);
  const long E = scaled.exponent;
  const std::array<Integer, 17>& x = scaled.integers;
  const auto vector_at = [&](std::size_t first) { return IntegerVector{x[first], x[first + 1], x[first + 2]}; };
  const IntegerVector c = vector_at(0), n = vector_at(3), p = vector_at(6), d = vector_at(9), u = vector_at(12);
  const Integer& r = x[15];
  const Integer& R = x[16];

  const IntegerVector q = c - p;                                       // degree 1
  const IntegerVector v = cross(n, u);                                 // 2
  const IntegerVector A = cross(q, d), B = cross(u, d), C = cross(v, d);  // 2, 2, 3
  const Integer a = dot(u, u), b = dot(v, v), r2 = r * r;              // 2, 4, 2
  const Integer q00 = dot(A, A) - R * R * dot(d, d);                   // 4
  const Integer q10 = 2 * dot(A, B), q01 = 2 * dot(A, C);              // 4, 5
  const Integer q20 = dot(B, B), q11 = 2 * dot(B, C), q02 = dot(C, C);  // 4, 5, 6
  // b L = (b q00 + q02 r^2) + b q10 X + (b q20 - q02 a) X^2 (degree 8): L's own coefficients
  // carry b's odd part in their denominators.
  const Integer scaled_l0 = b * q00 + q02 * r2, scaled_l1 = b * q10, scaled_l2 = b * q20 - q02 * a;

  RimConic conic;
  conic.a = rational(a, 2, E);
  conic.b = rational(b, 4, E);
  conic.r2 = rational(r2, 2, E);
  conic.make_l = [&] {
    return Polynomial(rational(scaled_l0, 8, E) / conic.b, rational(q10, 4, E), rational(scaled_l2, 8, E) / conic.b);
  };
  conic.M = Polynomial(rational(q01, 5, E), rational(q11, 5, E));
  conic.a_bounded = to_bounded(conic.a);
  conic.b_bounded = to_bounded(conic.b);
  conic.r2_bounded = to_bounded(conic.r2);
  // |X| <= r / sqrt(a) on the ellipse; use a power of two above it. The first guess comes from
  // the binary exponents (r / sqrt(a) itself can overflow a double, and a Gmpq made from an
  // infinity aborts the process), clamped to the double range; the loop makes it a bound.
  const int bound_exponent = std::clamp(
      std::ilogb(circle.radius) - std::ilogb(CGAL::to_double(conic.a)) / 2 + 2, -1000, 1000);
  conic.bound = Rational(std::ldexp(1.0, bound_exponent));
  while (conic.bound * conic.bound * conic.a <= conic.r2) conic.bound = conic.bound * 2;

  RimRoots result;
  result.proved = true;
  const bool l_is_zero = sgn(scaled_l0) == 0 && sgn(scaled_l1) == 0 && sgn(scaled_l2) == 0;  // b > 0
  if (l_is_zero && conic.M.is_zero()) {
    result.side_without_roots = RimSideWithoutRoots::on_surface;  // g vanishes on the whole rim
    return result;
  }

  SmallVector<Crossing> crossings;
  IsolatedRoots roots;
  if (conic.M.is_zero()) {
    // The cylinder meets E along vertical lines L(X) = 0.
    isolate_real_roots(conic.L(), conic.bound * 2, roots, budget);
    for (const IsolatedRoot& root : roots)
      add_vertical_line_crossings(conic, root, root.multiplicity, crossings, budget);
  } else {
    // L(-M0 / M1) = 0, times b M1^2 (nonzero): b L's homogeneous form at (-M0, M1).
    const bool shared_root =
        sgn(q11) != 0 && sgn(scaled_l0 * q11 * q11 - scaled_l1 * q01 * q11 + scaled_l2 * q01 * q01) == 0;
    if (!shared_root) {
      // b P = b (a X^2 - r^2) M^2 + (b L)^2 (degree 16 in the inputs): P's roots.
      const Integer m0 = q01 * q01, m1 = 2 * q01 * q11, m2 = q11 * q11;  // M^2
      SmallVector<Integer> scaled_p = {
          b * (-r2 * m0) + scaled_l0 * scaled_l0,
          b * (-r2 * m1) + 2 * scaled_l0 * scaled_l1,
          b * (a * m0 - r2 * m2) + scaled_l1 * scaled_l1 + 2 * scaled_l0 * scaled_l2,
          b * (a * m1) + 2 * scaled_l1 * scaled_l2,
          b * (a * m2) + scaled_l2 * scaled_l2};
      check_coefficient_size(scaled_p, b, E);
      isolate_real_roots(std::move(scaled_p), conic.bound, roots, budget);
      // L's coefficients (b L) 2^(4 E) / b, as to_bounded gives them, the zero ones on top left
      // out as CGAL's polynomial drops them.
      SmallVector<Bounded> l = {to_bounded(interval_of_quotient(scaled_l0, 4 * E, b)),
                                to_bounded(interval_of_quotient(scaled_l1, 4 * E, b)),
                                to_bounded(interval_of_quotient(scaled_l2, 4 * E, b))};
      while (l.size() > 1 && l.back().value == 0.0 && l.back().error == 0.0) l.pop_back();
      const SmallVector<Bounded> m = bounded_coefficients(conic.M);
      const auto numerator = [&]() -> const Polynomial& { return conic.L(); };
      for (const IsolatedRoot& root : roots) add_graph_crossings(conic, numerator, l, conic.M, m, root, crossings, budget);
    } else {
      // L = (X - X0) L1, M = q11 (X - X0): the line X = X0 and the line L1 + q11 Y = 0.
      const Rational x0 = -conic.M[0] / conic.M[1];
      Polynomial l1, remainder;
      Polynomial::euclidean_division(conic.L(), Polynomial(-x0, Rational(1)), l1, remainder);
      const Polynomial m1(conic.M[1]);
      SmallVector<Crossing> on_lines;
      add_vertical_line_crossings(conic, {x0, x0, 1, nullptr}, 1, on_lines, budget);
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
        add_graph_crossings(
            conic, [&]() -> const Polynomial& { return l1; }, bounded_coefficients(l1), m1, bounded_coefficients(m1),
            root, on_lines, budget);
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
  // An X on the rim with the sample's half: shrink by a part in 2^40 to stay on E.
  const double x_sample = finite_or_give_up(circle.radius * std::cos(sample) / u_norm * (1 - 0x1p-40));
  int sign = exact_sign_at({scaled_l0, scaled_l1, scaled_l2, q01, q11, a, b, r2}, x_sample,
                           std::sin(sample) >= 0 ? 1 : -1);
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
