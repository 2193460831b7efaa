// SPDX-License-Identifier: BSD-3-Clause
#include "exact/circle_plane_exact.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <boost/multiprecision/cpp_int.hpp>

#include "exact/exact_dyadic.hpp"
#include "exact/exact_rational_point.hpp"
#include "predicates/plane_terms.hpp"

namespace clearjoint::geometry::detail {
namespace {

// ---- Integers on the stack --------------------------------------------------------------------
// GMP's integers live on the heap: deciding one tangency with them took some 45 allocations, which
// cost more than the arithmetic (callgrind: 15,000 instructions a query, half of them in malloc and
// free). The terms' integers are small on the inputs the kernel meets (a joint's lengths, normals
// and radii within some tens of binades of one another), so they are first tried as fixed-size
// integers on the stack (Boost.Multiprecision's cpp_int, checked: an operation that would overflow
// throws instead of wrapping), and GMP decides only where the inputs' magnitudes lie too far apart.
// Both are exact, so both give the same signs.

/// Bits of a stack integer's magnitude.
constexpr unsigned kStackIntegerBits = 1024;
using StackInteger = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<kStackIntegerBits, kStackIntegerBits, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::checked, void>,
    boost::multiprecision::et_off>;
/// Largest bit count of an input integer (the offset's, the normals' and the radius's, at their
/// common exponent) for which no term overflows: with every input below 2^B, |s| < 3 2^(2B),
/// |n_c|^2 < 3 2^(2B), |w|^2 < 3 (2^(2B + 1))^2 and r^2 < 2^(2B), so that the discriminant
/// s^2 |n_c|^2 - r^2 |w|^2 stays below 27 2^(6B) + 12 2^(6B) < 2^(6B + 6).
constexpr long kStackInputBits = (static_cast<long>(kStackIntegerBits) - 6) / 6;

/// mantissa 2^exponent on the stack: the stack form of ExactDyadic.
struct StackDyadic {
  StackInteger mantissa;
  long exponent = 0;
};

// Boost's bit operations refuse negative operands (a checked cpp_int throws std::range_error):
// they act on the magnitude here, the sign put back.
/// Bits of |x| (0 for zero).
long bit_count(const StackInteger& x) {
  return x == 0 ? 0 : static_cast<long>(boost::multiprecision::msb(boost::multiprecision::abs(x))) + 1;
}
/// x 2^shift.
StackInteger shifted_left(const StackInteger& x, long shift) {
  const auto bits = static_cast<unsigned>(shift);
  return x < 0 ? StackInteger(-(boost::multiprecision::abs(x) << bits)) : StackInteger(x << bits);
}

/// A finite double, exactly: an odd integer (or zero) of at most 53 bits times a power of two,
/// as exact_dyadic (odd, so that the integers at the common exponent carry no needless twos).
StackDyadic stack_dyadic(double x) {
  int binary_exponent = 0;
  const double fraction = std::frexp(x, &binary_exponent);
  auto mantissa = static_cast<long long>(std::ldexp(fraction, 53));  // exact: 53 bits
  long exponent = binary_exponent - 53L;
  if (mantissa != 0) {
    const int zeros = std::countr_zero(static_cast<unsigned long long>(mantissa));  // two's complement: |m|'s
    mantissa /= 1LL << zeros;  // exact: those bits are zero
    exponent += zeros;
  }
  return {StackInteger(mantissa), exponent};
}

/// The sum of `terms`, exactly, at their smallest exponent; empty where a shifted term would not
/// leave room for the sum below kStackIntegerBits.
template <std::size_t N>
std::optional<StackDyadic> stack_sum(const std::array<StackDyadic, N>& terms) {
  StackDyadic out;
  bool any = false;
  for (const StackDyadic& term : terms) {
    if (term.mantissa == 0) continue;
    out.exponent = any ? std::min(out.exponent, term.exponent) : term.exponent;
    any = true;
  }
  for (const StackDyadic& term : terms) {
    if (term.mantissa == 0) continue;
    const long shift = term.exponent - out.exponent;
    if (bit_count(term.mantissa) + shift + 4 > static_cast<long>(kStackIntegerBits)) return std::nullopt;
    out.mantissa += shifted_left(term.mantissa, shift);
  }
  return out;
}

/// An input point, exactly: the stored double or the recipe's value (exact_dyadic_point's sum).
std::optional<std::array<StackDyadic, 3>> stack_point(const Vector3& stored, const RoundedPoint* recipe,
                                                      int scale_exponent) {
  std::array<StackDyadic, 3> out;
  for (int i = 0; i < 3; ++i) {
    if (recipe == nullptr) {
      out[i] = stack_dyadic(stored[i]);
      continue;
    }
    // minuend - subtrahend + sign (length / 2) direction, then the query's rescaling.
    const StackDyadic minuend = stack_dyadic(recipe->minuend[i]), subtrahend = stack_dyadic(-recipe->subtrahend[i]);
    StackDyadic half_step{0, 0};
    if (recipe->sign != 0) {
      const StackDyadic direction = stack_dyadic(recipe->direction[i]), length = stack_dyadic(recipe->length);
      half_step = {direction.mantissa * length.mantissa, direction.exponent + length.exponent - 1};
      if (recipe->sign < 0) half_step.mantissa = -half_step.mantissa;
    }
    const std::optional<StackDyadic> sum = stack_sum(std::array<StackDyadic, 3>{minuend, subtrahend, half_step});
    if (!sum) return std::nullopt;
    out[i] = {sum->mantissa, sum->exponent - scale_exponent};
  }
  return out;
}

std::array<ExactDyadic, 3> exact(const Vector3& v) { return {exact_dyadic(v.x()), exact_dyadic(v.y()), exact_dyadic(v.z())}; }
std::array<ExactDyadic, 3> exact(const Vector3& stored, const RoundedPoint* recipe, int scale_exponent) {
  return recipe == nullptr ? exact(stored) : exact_dyadic_point(*recipe, scale_exponent);
}

/// The topology from the terms' signs (docs/circle-plane.md), for either integer type.
template <class Integer>
CirclePlaneTopologyAndSide topology_of(const PlaneTerms<Integer>& t) {
  const int side = t.s > 0 ? 1 : t.s < 0 ? -1 : 0;
  if (t.w2 == 0) {
    return side == 0 ? CirclePlaneTopologyAndSide{CirclePlaneTopology::circle_in_plane, 0}
                     : CirclePlaneTopologyAndSide{CirclePlaneTopology::disjoint, side};
  }
  if (t.discriminant > 0) return {CirclePlaneTopology::disjoint, side};
  if (t.discriminant == 0) return {CirclePlaneTopology::tangent, side};
  return {CirclePlaneTopology::two_crossings, 0};
}

/// The decision in stack integers, or empty where the inputs' integers at their common exponent
/// exceed kStackInputBits (or, should that bound be wrong, an operation overflows).
std::optional<CirclePlaneTopologyAndSide> stack_topology(const Circle3& circle, const Plane3& plane,
                                                         const RoundedPoint* centre, const RoundedPoint* point,
                                                         int scale_exponent) {
  try {
    const auto c = stack_point(circle.center, centre, scale_exponent);
    const auto p = stack_point(plane.point, point, scale_exponent);
    if (!c || !p) return std::nullopt;
    std::array<StackDyadic, 10> inputs;
    for (int i = 0; i < 3; ++i) {
      StackDyadic minus_p = (*p)[i];
      minus_p.mantissa = -minus_p.mantissa;
      const std::optional<StackDyadic> offset = stack_sum(std::array<StackDyadic, 2>{(*c)[i], minus_p});
      if (!offset) return std::nullopt;
      inputs[i] = *offset;
      inputs[3 + i] = stack_dyadic(circle.normal[i]);
      inputs[6 + i] = stack_dyadic(plane.normal[i]);
    }
    inputs[9] = stack_dyadic(circle.radius);
    // The integers at one exponent (integers_at_common_exponent), each below 2^kStackInputBits.
    long exponent = 0;
    bool any = false;
    for (const StackDyadic& d : inputs) {
      if (d.mantissa == 0) continue;
      exponent = any ? std::min(exponent, d.exponent) : d.exponent;
      any = true;
    }
    std::array<StackInteger, 10> x;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (inputs[i].mantissa == 0) continue;
      const long shift = inputs[i].exponent - exponent;
      if (bit_count(inputs[i].mantissa) + shift > kStackInputBits) return std::nullopt;
      x[i] = shifted_left(inputs[i].mantissa, shift);
    }
    return topology_of(plane_terms<PlaneTermsFor::signs>(Vector3Of<StackInteger>{x[0], x[1], x[2]},
                                                         Vector3Of<StackInteger>{x[3], x[4], x[5]},
                                                         Vector3Of<StackInteger>{x[6], x[7], x[8]}, x[9]));
  } catch (const std::overflow_error&) {
    return std::nullopt;
  }
}

}  // namespace

CirclePlaneTopologyAndSide exact_circle_plane_topology(const Circle3& circle, const Plane3& plane,
                                                       const RoundedPoint* centre,
                                                       const RoundedPoint* point, int scale_exponent) {
  if (const auto decided = stack_topology(circle, plane, centre, point, scale_exponent)) return *decided;
  // GMP: inputs whose magnitudes lie hundreds of binades apart.
  const std::array<ExactDyadic, 3> c = exact(circle.center, centre, scale_exponent);
  const std::array<ExactDyadic, 3> p = exact(plane.point, point, scale_exponent);
  const std::array<ExactDyadic, 3> n_c = exact(circle.normal), n_p = exact(plane.normal);
  // The offset c - p, both normals and the radius as integers at one exponent: every term of
  // plane_terms is homogeneous in them (s of degree 2, |w|^2 of degree 4, the discriminant of
  // degree 6), so the integers give each term times a positive power of two, the same signs.
  std::array<ExactDyadic, 10> inputs;
  for (int i = 0; i < 3; ++i) {
    ExactDyadic minus_p = p[i];
    minus_p.mantissa = -minus_p.mantissa;
    inputs[i] = exact_sum(c[i], minus_p);
    inputs[3 + i] = n_c[i];
    inputs[6 + i] = n_p[i];
  }
  inputs[9] = exact_dyadic(circle.radius);
  const std::array<mpz_class, 10> x = integers_at_common_exponent(inputs).integers;
  // The same terms the floating-point filters bound (plane_terms.hpp), here exact.
  const PlaneTerms<mpz_class> t = plane_terms<PlaneTermsFor::signs>(
      Vector3Of<mpz_class>{x[0], x[1], x[2]}, Vector3Of<mpz_class>{x[3], x[4], x[5]},
      Vector3Of<mpz_class>{x[6], x[7], x[8]}, x[9]);
  return topology_of(t);
}

}  // namespace clearjoint::geometry::detail
