// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Three-vectors whose components are two-lane doubles (pair_lanes.hpp): two vectors computed side
// by side, each lane rounded as the scalar operation would round it. The candidate prefilters
// (candidate_prefilter_lanes.hpp) and the a priori rim distance polynomial use them.

#include <array>

#include "arithmetic/pair_lanes.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry::detail {

/// Lane 0 base A's value, lane 1 base B's (or, in rim_distance_polynomial.cpp, a value and its
/// twin). The Pair of pair_lanes.hpp, not Eigen's Array2d: GCC builds an Array2d from two
/// doubles by two 8-byte stores and one 16-byte load, which the store buffer cannot forward (a stall of ~10 cycles each time, on the
/// critical path of the prefilter and of the a priori polynomial); a Pair it builds in registers.
using Lanes = Pair;
using LaneFlags = PairMask;
struct LaneVector3 {
  Lanes x, y, z;
};

/// x in both lanes.
inline Lanes broadcast(double x) { return Lanes{x, x}; }
inline Lanes lanes(const std::array<double, 2>& v) { return Lanes{v[0], v[1]}; }
inline LaneVector3 lanes(const std::array<Vector3, 2>& v) {
  return {Lanes{v[0].x(), v[1].x()}, Lanes{v[0].y(), v[1].y()}, Lanes{v[0].z(), v[1].z()}};
}
/// The same vector in both lanes.
inline LaneVector3 both_lanes(const Vector3& v) { return {broadcast(v.x()), broadcast(v.y()), broadcast(v.z())}; }
inline LaneVector3 operator+(const LaneVector3& p, const LaneVector3& q) { return {p.x + q.x, p.y + q.y, p.z + q.z}; }
inline LaneVector3 operator-(const LaneVector3& p, const LaneVector3& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
/// v scaled per lane (by +-1 in the callers: exact).
inline LaneVector3 scaled(const Lanes& s, const Vector3& v) { return {s * v.x(), s * v.y(), s * v.z()}; }
/// |v|_1 per lane, as Eigen's v.cwiseAbs().sum().
inline Lanes one_norm(const LaneVector3& v) { return magnitude(v.x) + magnitude(v.y) + magnitude(v.z); }
inline Lanes dot(const Vector3& a, const LaneVector3& v) { return a.x() * v.x + a.y() * v.y + a.z() * v.z; }
inline Lanes squared_norm(const LaneVector3& v) { return v.x * v.x + v.y * v.y + v.z * v.z; }
/// c x a per lane.
inline LaneVector3 cross(const LaneVector3& c, const Vector3& a) {
  return {c.y * a.z() - c.z * a.y(), c.z * a.x() - c.x * a.z(), c.x * a.y() - c.y * a.x()};
}
/// abs_cross (a_priori_bounds.hpp) per lane, for |c| and |a|.
inline LaneVector3 abs_cross(const LaneVector3& c, const Vector3& a) {
  return {c.y * a.z() + c.z * a.y(), c.z * a.x() + c.x * a.z(), c.x * a.y() + c.y * a.x()};
}

}  // namespace clearjoint::geometry::detail
