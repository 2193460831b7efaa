// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The other revolute joint: a pin (shaft, bolt) longer than the hole it passes through, the
/// hole in a link or bushing (body i, the paper's bearing), the pin in body j (the paper's
/// journal). Axial play is limited by the pin's stops: the inner faces of its heads, collars or
/// washers against the link's two faces. docs/contact-detection.md, "The pin-in-hole joint".

#include <array>
#include <limits>
#include <string_view>

namespace clearjoint::geometry {

/// One axial stop: the inner face of a head, collar or washer on the pin, a plane perpendicular
/// to the pin's axis, bounded by a circle of radius `outer_radius` about the axis.
///
/// `position` is measured along the pin's unit axis from the pin's point P (PartPose::p_WP), the
/// pin point that sits at the hole's centre when the pin is centred. The stop's head lies on the
/// far side of its face from P: a stop at a positive position is a head on the side the pin's
/// axis points to, its face looking back (along -a_j) at the link's face on that side.
struct AxialStop {
  double position = 0.0;
  double outer_radius = 0.0;
};

/// At most one stop on each side of the hole.
inline constexpr int kMaxAxialStops = 2;

/// Hole radius Rh and the hole's length L between the link's two faces (body i), pin radius Rp
/// (body j), and 0, 1 or 2 axial stops. Any one unit of length.
/// Preconditions (checked by validate()): Rh > Rp > 0, L > 0, each in [kSmallestAcceptedLength,
/// kLargestAcceptedLength] (joint_geometry.hpp); each stop outside the hole (|position| > L/2) and
/// larger than it (outer_radius > Rh, also in range); two stops on opposite sides of P.
/// The pin is taken as long as it needs to be: its ends are not modelled (a free sliding pin that
/// leaves the hole is not detected as such).
struct PinInHoleDimensions {
  double hole_radius = 0.0;  ///< Rh
  double hole_length = 0.0;  ///< L, between the link's faces
  double pin_radius = 0.0;   ///< Rp
  std::array<AxialStop, kMaxAxialStops> stops{};
  int stop_count = 0;  ///< 0 (a free sliding pin), 1 or 2

  /// cr = Rh - Rp, the radial play (eq. 1 with the hole for the bearing). Exact in double when
  /// Rh <= 2 Rp (Sterbenz).
  double radial_clearance() const noexcept { return hole_radius - pin_radius; }
  /// ca = ((s_max - s_min) - L)/2 with two stops, the axial play on each side when centred (eq. 2
  /// with the gap between the stops for the bearing's length); infinity with fewer stops.
  double axial_clearance() const noexcept {
    if (stop_count < 2) return std::numeric_limits<double>::infinity();
    const double gap = stops[0].position < stops[1].position ? stops[1].position - stops[0].position
                                                              : stops[0].position - stops[1].position;
    return 0.5 * (gap - hole_length);
  }
};

/// The names validate() gives the fields in its messages, after the caller's path: the members
/// by default ("stops[1].outer_radius"); kPinInHolePartNames for a description grouped by part
/// ("hole.radius", "pin.stops[1].outer_radius").
struct PinInHoleDimensionNames {
  std::string_view hole_radius = "hole_radius";
  std::string_view hole_length = "hole_length";
  std::string_view pin_radius = "pin_radius";
  std::string_view stops = "stops";  ///< each stop's fields are named "<stops>[k].position", ...
  std::string_view stop_count = "stop_count";
};
inline constexpr PinInHoleDimensionNames kPinInHolePartNames{"hole.radius", "hole.length", "pin.radius", "pin.stops",
                                                             "pin.stop_count"};

/// The one check of a pin-in-hole joint's dimensions, for every front-end: throw InvalidInput
/// naming the field and its value ("dimensions.pin_radius = 10: must be smaller than hole_radius =
/// 10 (the radial clearance Rh - Rp must be positive)") for non-finite values, non-positive sizes,
/// sizes outside the accepted range, a pin not thinner than its hole, a stop count outside [0, 2],
/// a stop inside the hole (|position| <= L/2) or not larger than it (outer_radius <= Rh), and two
/// stops on the same side. `name` is the caller's path to the dimensions ("forces[0]"); empty,
/// the field names stand alone.
void validate(const PinInHoleDimensions& dimensions, std::string_view name = "dimensions",
              const PinInHoleDimensionNames& names = {});

}  // namespace clearjoint::geometry
