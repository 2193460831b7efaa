// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Points and arcs on a rim, in the angle of its CircleFrame.

#include <limits>
#include <tuple>

#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"

namespace clearjoint::geometry {

/// "No bound known" for the error fields below.
inline constexpr double kNoErrorBound = std::numeric_limits<double>::infinity();

/// A point where the rim meets a surface.
/// Invariant when the answer is certified or exact: the true crossing angle lies in
/// [angle - angle_error, angle + angle_error] and the true point within point_error (metres,
/// Euclidean) of `point`. Uncertain answers carry kNoErrorBound.
struct RimCrossing {
  double angle = 0.0;          ///< rim angle in [0, 2 pi)
  double angle_error = kNoErrorBound;
  Vector3 point = Vector3::Zero();
  double point_error = kNoErrorBound;
  /// 1: the rim crosses the surface; 2: it touches it (tangency, a double root); 3 or 4:
  /// higher-order contact. Never reported as two crossings or as none.
  int multiplicity = 1;
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<RimCrossing> {
  using X = RimCrossing;
  static constexpr std::string_view type_name = "RimCrossing";
  static constexpr std::tuple fields{
      fields::plain("angle", &X::angle, "rim angle in [0, 2 pi), radians"),
      fields::bound("angle_error", &X::angle_error),
      fields::plain("point", &X::point, "world frame, shape (3,)"),
      fields::bound("point_error", &X::point_error),
      fields::plain("multiplicity", &X::multiplicity, "1 crossing, 2 tangency, 3-4 higher-order contact")};
};
static_assert(detail::lists_every_member<RimCrossing>(), "a member of RimCrossing is missing from its field list");

/// The rim points with angle in the counter-clockwise sweep from `begin` to `end` (radians in
/// [0, 2 pi); end < begin when the arc passes through angle 0). `full` marks the whole rim
/// except, at most, one touching point: begin == end is that point's angle (a rim touching the
/// wall from outside), or begin = 0, end = 2 pi when nothing touches.
struct RimArc {
  double begin = 0.0;
  double end = 0.0;
  bool full = false;

  /// Angle of the arc's middle, in [0, 2 pi) (paper eqs. 13 and 18 take the contact point there);
  /// for a full arc, opposite its begin.
  double middle() const noexcept;
  /// Angular length in [0, 2 pi].
  double sweep() const noexcept;
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<RimArc> {
  static constexpr std::string_view type_name = "RimArc";
  static constexpr std::tuple fields{fields::plain("begin", &RimArc::begin), fields::plain("end", &RimArc::end),
                                     fields::plain("full", &RimArc::full)};
};
static_assert(detail::lists_every_member<RimArc>(), "a member of RimArc is missing from its field list");

}  // namespace clearjoint::geometry
