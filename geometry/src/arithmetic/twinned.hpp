// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A value beside its absolute-value twin (a_priori_bounds.hpp): the number type of the a priori
// instances of the predicates written once over the number type (plane_terms.hpp,
// rim_reach_terms.hpp). Two layouts: Twinned packs the value in lane 0 of a Pair and the twin in
// lane 1 (pair_lanes.hpp), one register for both; ValueAndTwin keeps them apart (below).
//
// The twin is the expression on |inputs| with subtractions turned into additions. So + and *
// act on both lanes alike, and a - b subtracts b's value from a's and adds b's twin to a's
// twin: it subtracts b with its lane 1 negated, since x - (-y) rounds exactly as x + y (negation
// is exact). One chain of packed operations then forms both, each lane rounded exactly as the
// scalar operation, so the bits of the value and of the twin are those of the two computed one
// after the other (test: test_rim_plane_quantities.cpp).

#include <cmath>

#include "arithmetic/pair_lanes.hpp"

namespace clearjoint::geometry::detail {

struct Twinned {
  Pair lanes;  ///< {value, twin}

  /// An exact input x: {x, |x|}.
  static Twinned of(double x) {
    const PairMask kAllButLane1Sign = ~bits_of(Pair{0.0, -0.0});
    return {pair_of_bits(bits_of(Pair{x, x}) & kAllButLane1Sign)};
  }
  double value() const { return lanes[0]; }
  double twin() const { return lanes[1]; }
};

/// x with the sign of lane 1 flipped.
inline Pair twin_negated(Pair x) {
  const PairMask kLane1Sign = bits_of(Pair{0.0, -0.0});
  return pair_of_bits(bits_of(x) ^ kLane1Sign);
}

inline Twinned operator+(Twinned a, Twinned b) { return {a.lanes + b.lanes}; }
inline Twinned operator-(Twinned a, Twinned b) { return {a.lanes - twin_negated(b.lanes)}; }
inline Twinned operator*(Twinned a, Twinned b) { return {a.lanes * b.lanes}; }

/// A value and its absolute-value twin side by side instead of packed: the same rules as Twinned
/// (+ and * act on both, a - b adds b's twin), for V = double where the value and the twin come
/// apart (rim_reach's a priori form takes |q x d|^2 and its twin from AxisOffset,
/// rim_distance_polynomial.cpp), and V = Pair for two expressions at once, one per lane (bases A
/// and B in candidate_prefilter_lanes.hpp). Operands of different V mix as double and Pair do (a
/// double is broadcast to both lanes): a term both lanes share is formed once, in scalars.
template <class V>
struct ValueAndTwin {
  V value, twin;

  /// An exact input x: {x, |x|}.
  static ValueAndTwin of(V x) { return {x, magnitude(x)}; }
  /// An exact input that is never negative where it is used (a radius, an error bound): its own
  /// twin, without the sign mask.
  static ValueAndTwin nonnegative(V x) { return {x, x}; }
};

template <class A, class B>
auto operator+(const ValueAndTwin<A>& a, const ValueAndTwin<B>& b) {
  return ValueAndTwin<decltype(a.value + b.value)>{a.value + b.value, a.twin + b.twin};
}
template <class A, class B>
auto operator-(const ValueAndTwin<A>& a, const ValueAndTwin<B>& b) {
  return ValueAndTwin<decltype(a.value - b.value)>{a.value - b.value, a.twin + b.twin};
}
template <class A, class B>
auto operator*(const ValueAndTwin<A>& a, const ValueAndTwin<B>& b) {
  return ValueAndTwin<decltype(a.value * b.value)>{a.value * b.value, a.twin * b.twin};
}

}  // namespace clearjoint::geometry::detail
