// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A double together with a rigorous bound on its distance to the real number it stands for
// (running error analysis, Higham, "Accuracy and Stability of Numerical Algorithms", sec. 3.3).
//
// Why not Boost.Interval or CGAL::Interval_nt: both need the FPU rounding mode switched (CGAL
// once per protected block, Boost per operation with its default policy), which costs more than
// the whole certified circle-cylinder query is allowed to (docs/circle-cylinder.md). This type
// stays in round-to-nearest and pays a few extra multiply-adds per operation instead.
//
// Model (IEEE binary64, round to nearest, no -ffast-math): for every basic operation
//   |fl(x op y) - (x op y)| <= u |fl(x op y)| + eta,   u = 2^-53, eta = 2^-1074,
// where eta covers gradual underflow. The error fields are themselves rounded; each update is
// multiplied by kErrorInflation, which exceeds the worst relative shortfall of the <= 8 rounded
// operations that compute it ((1 - u)^-8 < 1 + 9u < 1 + 2^-48), and every operation adds
// absolute underflow terms (magnified by the divisor in a division). Overflow shows up as a
// non-finite value or error, and callers treat that as "not certified".

#include <cmath>

#include "arithmetic/pair_lanes.hpp"
#include "arithmetic/vector3_of.hpp"

namespace clearjoint::geometry::detail {

/// Unit roundoff of binary64, round to nearest.
inline constexpr double kUnitRoundoff = 0x1p-53;
/// Smallest subnormal: bound on the absolute error of an underflowing operation.
inline constexpr double kUnderflowError = 0x1p-1074;
/// See the file comment: covers the rounding of the error computations themselves.
inline constexpr double kErrorInflation = 1.0 + 0x1p-48;

// The arithmetic below is written once for a value type T: double (Bounded) or Pair (PairBounded,
// two Boundeds side by side in SSE2 lanes, pair_lanes.hpp). A packed operation rounds each lane
// as the scalar operation would, so lane i of a PairBounded result is, bit for bit, the Bounded
// result on the operands' lane i.

/// The margin sign() demands: value - error is itself rounded; one relative rounding more.
template <class T>
T sign_margin(T error) {
  return error * kErrorInflation + kUnderflowError;
}

struct Bounded {
  double value = 0.0;
  double error = 0.0;  ///< |true - value| <= error

  constexpr Bounded() = default;
  constexpr Bounded(double exact) : value(exact), error(0.0) {}  // NOLINT: doubles are exact
  constexpr Bounded(double v, double e) : value(v), error(e) {}

  double lower() const { return value - error; }  // callers compare with margin; see sign()
  double upper() const { return value + error; }
  bool finite() const { return std::isfinite(value) && std::isfinite(error); }
  /// +1 or -1 when the sign of the true value is proved, 0 when it is not.
  int sign() const {
    const double margin = sign_margin(error);
    if (value > margin) return 1;
    if (value < -margin) return -1;
    return 0;
  }
};

/// max(x, 0), with NaN giving 0 as std::fmax does. Written out because std::fmax is an
/// out-of-line libm call under strict IEEE semantics (no -ffinite-math-only): it was two calls per
/// certified sqrt, a few percent of a circle-plane query.
inline double nonnegative_part(double x) { return x > 0.0 ? x : 0.0; }

/// Bounded for two values at once (see above); lane(i) is the i-th Bounded.
struct PairBounded {
  Pair value, error;
  Bounded lane(int i) const { return {value[i], error[i]}; }
  /// Bounded::sign() > 0 and sign() < 0, lane by lane: -1 where proved, 0 where not.
  PairMask positive() const { return value > sign_margin(error); }
  PairMask negative() const { return value < -sign_margin(error); }
};

template <class T>
T rounding_error(T computed) {
  return kUnitRoundoff * magnitude(computed) + kUnderflowError;
}

/// +, - and * of Bounded and of PairBounded (B), on their values of type T.
template <class B, class T = decltype(B::value)>
B bounded_sum(const B& a, const B& b) {
  const T v = a.value + b.value;
  return {v, (a.error + b.error + rounding_error(v)) * kErrorInflation};
}
template <class B, class T = decltype(B::value)>
B bounded_difference(const B& a, const B& b) {
  const T v = a.value - b.value;
  return {v, (a.error + b.error + rounding_error(v)) * kErrorInflation};
}
template <class B, class T = decltype(B::value)>
B bounded_product(const B& a, const B& b) {
  const T v = a.value * b.value;
  const T e = magnitude(a.value) * b.error + magnitude(b.value) * a.error + a.error * b.error;
  return {v, (e + rounding_error(v) + 2 * kUnderflowError) * kErrorInflation};
}

// Bounded's operators take their operands by value (not as templates): a double converts to an
// exact Bounded, as in Bounded(1.0) - x * x.
inline Bounded operator+(Bounded a, Bounded b) { return bounded_sum(a, b); }
inline Bounded operator-(Bounded a, Bounded b) { return bounded_difference(a, b); }
inline Bounded operator-(Bounded a) { return {-a.value, a.error}; }
inline Bounded operator*(Bounded a, Bounded b) { return bounded_product(a, b); }
inline PairBounded operator+(const PairBounded& a, const PairBounded& b) { return bounded_sum(a, b); }
inline PairBounded operator-(const PairBounded& a, const PairBounded& b) { return bounded_difference(a, b); }
inline PairBounded operator*(const PairBounded& a, const PairBounded& b) { return bounded_product(a, b); }
inline Bounded operator/(Bounded a, Bounded b) {
  const double v = a.value / b.value;
  const double denominator = std::fabs(b.value) - b.error * kErrorInflation;
  if (!(denominator > 0.0)) return {v, HUGE_VAL};  // divisor may be zero: no bound
  // The numerator's own roundings may be absolute (underflow, kUnderflowError each) and the
  // division magnifies them: add them before dividing.
  const double e = (a.error + std::fabs(v) * b.error + 4 * kUnderflowError) / denominator;
  return {v, (e * kErrorInflation + rounding_error(v) + kUnderflowError) * kErrorInflation};
}
inline Bounded& operator+=(Bounded& a, Bounded b) { return a = a + b; }

/// sqrt of a value whose true value is >= 0 (callers guarantee it, e.g. a sum of squares).
inline Bounded sqrt(Bounded a) {
  const double v = std::sqrt(nonnegative_part(a.value));
  const double low = a.value - a.error * kErrorInflation;
  double e;
  // Between these, v * v and low stay far from under- and overflow (v^2 >= low > 2^-900, and
  // v^2 ~ a.value < 2^1000); the product with a tiny error can still underflow, hence the
  // kUnderflowError. The one-division form below replaces sqrt(low) by low / v, which is up to
  // twice looser when low is far below a.value: it is taken only for errors below 2^-10 of the
  // value (the usual case), where the two differ by less than 0.05 %.
  constexpr double kNoUnderflowLow = 0x1p-900, kNoOverflowValue = 0x1p1000, kSmallRelativeError = 0x1p-10;
  if (low > kNoUnderflowLow && a.value < kNoOverflowValue && a.error <= kSmallRelativeError * a.value) {
    // |sqrt(x) - sqrt(x0)| = |x - x0| / (sqrt(x) + sqrt(x0)), x the true value, x0 = a.value.
    // With x >= low, low <= x0 and v = sqrt(x0)(1 + delta), |delta| <= u:
    //   sqrt(x) >= sqrt(low) >= low / sqrt(x0) >= low / (v (1 + 2u)),  sqrt(x0) >= v (1 - u),
    // so the sum is at least (low + v^2 (1 - u)(1 + 2u)) / (v (1 + 2u)). The factors 1 + 8u and
    // 1 - 4u cover those and the roundings of this line (six); the error multiplies the ratio
    // last, so that a huge error cannot overflow where the bound itself does not. One
    // division instead of a second square root (sqrt(low)), for a bound as tight to first order.
    e = a.error * (v * (1.0 + 8 * kUnitRoundoff) / (low + v * v * (1.0 - 4 * kUnitRoundoff))) +
        kUnderflowError;
  } else if (low > 0.0) {
    e = a.error / ((std::sqrt(low) + v) * (1.0 - 4 * kUnitRoundoff));
  } else {
    e = std::sqrt(nonnegative_part(a.value) + a.error) * (1.0 + 4 * kUnitRoundoff);
  }
  return {v, (e + rounding_error(v)) * kErrorInflation};
}

inline Bounded abs(Bounded a) { return {std::fabs(a.value), a.error}; }
inline Bounded square(Bounded a) { return a * a; }

/// sin and cos of an exactly known double angle. glibc documents at most 1 ulp for sin and cos
/// on x86-64 (its libm-test-ulps tables); we allow 2 ulps, i.e. 4u relative.
struct BoundedSinCos {
  Bounded sin;
  Bounded cos;
};
inline BoundedSinCos sincos_of(double angle) {
  const double s = std::sin(angle);
  const double c = std::cos(angle);
  constexpr double kLibmUlps = 4 * kUnitRoundoff;
  return {{s, kLibmUlps * std::fabs(s) + kUnderflowError},
          {c, kLibmUlps * std::fabs(c) + kUnderflowError}};
}

/// Three Bounded components, with the vector algebra the kernel needs.
using BoundedVector3 = Vector3Of<Bounded>;
inline BoundedVector3 operator-(const BoundedVector3& a, const BoundedVector3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Bounded dot(const BoundedVector3& a, const BoundedVector3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline BoundedVector3 cross(const BoundedVector3& a, const BoundedVector3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Bounded squared_norm(const BoundedVector3& a) { return dot(a, a); }

}  // namespace clearjoint::geometry::detail

namespace clearjoint::geometry::detail {

/// The factors for which exactly_equal_products is a decision: zero or of magnitude in
/// (2^-450, 2^450), so that no product under- or overflows and the split cannot overflow.
inline bool in_two_product_range(double x) {
  constexpr double kSafeMagnitude = 0x1p450, kTinyMagnitude = 0x1p-450;
  const double m = std::fabs(x);
  return m == 0.0 || (m > kTinyMagnitude && m < kSafeMagnitude);
}

/// a*b == c*d in real arithmetic, decided exactly (Dekker's TwoProduct with Veltkamp's split:
/// a*b = p + e exactly with |e| <= ulp(p)/2, and that representation is unique, so the real
/// products are equal iff both parts are). Valid while no product underflows or overflows and
/// no factor exceeds 2^996 (the split's own overflow); returns false, "not proved equal", out of
/// that range. Two cheaper exits come first, valid for any factors: rounding is monotone, so
/// real products that are equal round to the same double (p1 != p2 proves them different); and a
/// real product is zero exactly when a factor is, which decides the components of a cross
/// product of axis-aligned vectors (the aligned joints of the paper's planar examples) without
/// the split.
inline bool exactly_equal_products(double a, double b, double c, double d) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double p1 = a * b, p2 = c * d;
  if (p1 != p2) return false;
  if ((a == 0.0 || b == 0.0) && (c == 0.0 || d == 0.0)) return true;
  if (!(in_two_product_range(a) && in_two_product_range(b) && in_two_product_range(c) &&
        in_two_product_range(d))) {
    return false;
  }
  auto two_product_error = [](double x, double y, double p) {
    const double xs = kSplitter * x, xh = xs - (xs - x), xl = x - xh;
    const double ys = kSplitter * y, yh = ys - (ys - y), yl = y - yh;
    return ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
  };
  return two_product_error(a, b, p1) == two_product_error(c, d, p2);
}

}  // namespace clearjoint::geometry::detail
