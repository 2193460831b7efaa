// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The portable Pair of pair_lanes.hpp (CLEARJOINT_LANES=PORTABLE, or a compiler without GCC's
// vector extensions): two doubles in a struct, every operator applied lane by lane with the
// scalar operation, so each lane holds exactly the bits the scalar code computes. It offers the
// subset of the vector extensions' syntax the kernel uses: braces, lane indexing, + - * / and
// their compound forms with a Pair or a broadcast double, comparisons giving a PairMask of -1/0
// lanes, and & | ~ on masks.

#include <bit>
#include <cmath>
#include <cstdint>

namespace clearjoint::geometry::detail {

struct PairMask {
  std::int64_t lane[2];
  constexpr std::int64_t& operator[](int i) { return lane[i]; }
  constexpr std::int64_t operator[](int i) const { return lane[i]; }
};

constexpr PairMask operator&(PairMask a, PairMask b) { return {a[0] & b[0], a[1] & b[1]}; }
constexpr PairMask operator|(PairMask a, PairMask b) { return {a[0] | b[0], a[1] | b[1]}; }
constexpr PairMask operator^(PairMask a, PairMask b) { return {a[0] ^ b[0], a[1] ^ b[1]}; }
constexpr PairMask operator~(PairMask a) { return {~a[0], ~a[1]}; }
constexpr PairMask& operator&=(PairMask& a, PairMask b) { return a = a & b; }
constexpr PairMask& operator|=(PairMask& a, PairMask b) { return a = a | b; }

struct Pair {
  double lane[2];
  constexpr double& operator[](int i) { return lane[i]; }
  constexpr double operator[](int i) const { return lane[i]; }
};

namespace pair_lanes {
constexpr Pair broadcast(double x) { return {x, x}; }
constexpr std::int64_t truth(bool b) { return b ? -1 : 0; }
}  // namespace pair_lanes

#define CLEARJOINT_PAIR_ARITHMETIC(op)                                                             \
  constexpr Pair operator op(Pair a, Pair b) { return {a[0] op b[0], a[1] op b[1]}; }             \
  constexpr Pair operator op(Pair a, double b) { return a op pair_lanes::broadcast(b); }          \
  constexpr Pair operator op(double a, Pair b) { return pair_lanes::broadcast(a) op b; }          \
  constexpr Pair& operator op##=(Pair & a, Pair b) { return a = a op b; }                          \
  constexpr Pair& operator op##=(Pair & a, double b) { return a = a op b; }
CLEARJOINT_PAIR_ARITHMETIC(+)
CLEARJOINT_PAIR_ARITHMETIC(-)
CLEARJOINT_PAIR_ARITHMETIC(*)
CLEARJOINT_PAIR_ARITHMETIC(/)
#undef CLEARJOINT_PAIR_ARITHMETIC

constexpr Pair operator-(Pair a) { return {-a[0], -a[1]}; }

#define CLEARJOINT_PAIR_COMPARISON(op)                                                             \
  constexpr PairMask operator op(Pair a, Pair b) {                                                 \
    return {pair_lanes::truth(a[0] op b[0]), pair_lanes::truth(a[1] op b[1])};                     \
  }                                                                                                \
  constexpr PairMask operator op(Pair a, double b) { return a op pair_lanes::broadcast(b); }      \
  constexpr PairMask operator op(double a, Pair b) { return pair_lanes::broadcast(a) op b; }
CLEARJOINT_PAIR_COMPARISON(<)
CLEARJOINT_PAIR_COMPARISON(<=)
CLEARJOINT_PAIR_COMPARISON(>)
CLEARJOINT_PAIR_COMPARISON(>=)
CLEARJOINT_PAIR_COMPARISON(==)
CLEARJOINT_PAIR_COMPARISON(!=)
#undef CLEARJOINT_PAIR_COMPARISON

inline bool all_lanes(PairMask m) { return (m[0] & m[1]) != 0; }
inline bool any_lane(PairMask m) { return (m[0] | m[1]) != 0; }

inline PairMask bits_of(Pair x) { return {std::bit_cast<std::int64_t>(x[0]), std::bit_cast<std::int64_t>(x[1])}; }
inline Pair pair_of_bits(PairMask bits) { return {std::bit_cast<double>(bits[0]), std::bit_cast<double>(bits[1])}; }

inline Pair select(PairMask mask, Pair a, Pair b) { return pair_of_bits((mask & bits_of(a)) | (~mask & bits_of(b))); }

inline Pair square_root(Pair x) { return {std::sqrt(x[0]), std::sqrt(x[1])}; }

}  // namespace clearjoint::geometry::detail
