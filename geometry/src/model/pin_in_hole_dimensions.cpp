// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"

#include <string>
#include <string_view>
#include <utility>

#include "model/input_checks.hpp"

namespace clearjoint::geometry {
namespace {

using detail::format;
using detail::reject;
using detail::require_positive;

void require_positive_in_range(double value, std::string_view name, std::string_view field) {
  require_positive(value, name, field);
  if (!detail::length_in_range(value)) detail::reject_out_of_range(format(value), name, field);
}

}  // namespace

void validate(const PinInHoleDimensions& dimensions, std::string_view name, const PinInHoleDimensionNames& names) {
  // In this order, so that the first bad field is the one named.
  const std::pair<double, std::string_view> sizes[] = {{dimensions.hole_radius, names.hole_radius},
                                                       {dimensions.hole_length, names.hole_length},
                                                       {dimensions.pin_radius, names.pin_radius}};
  for (const auto& [value, field] : sizes) require_positive_in_range(value, name, field);
  // The radial clearance Rh - Rp (eq. 1 with the hole for the bearing) must be positive.
  if (!(dimensions.pin_radius < dimensions.hole_radius)) {
    reject(name, names.pin_radius, format(dimensions.pin_radius),
           "must be smaller than " + std::string(names.hole_radius) + " = " + format(dimensions.hole_radius) +
               " (the radial clearance Rh - Rp must be positive: the pin must be thinner than its hole)");
  }
  if (dimensions.stop_count < 0 || dimensions.stop_count > kMaxAxialStops) {
    reject(name, names.stop_count, std::to_string(dimensions.stop_count),
           "must be 0, 1 or 2 (at most one stop on each side of the hole)");
  }
  const double half_length = 0.5 * dimensions.hole_length;
  for (int k = 0; k < dimensions.stop_count; ++k) {
    const AxialStop& stop = dimensions.stops[static_cast<std::size_t>(k)];
    // The inline tests first: a field's name is only put together for its message.
    const bool position_ok = detail::length_in_range(stop.position) &&
                             (stop.position > half_length || stop.position < -half_length);
    const bool radius_ok = stop.outer_radius > dimensions.hole_radius && detail::length_in_range(stop.outer_radius);
    if (position_ok && radius_ok) [[likely]] continue;
    const std::string prefix = std::string(names.stops) + "[" + std::to_string(k) + "].";
    const std::string position = prefix + "position";
    const std::string outer_radius = prefix + "outer_radius";
    if (!detail::every_value_finite(stop.position)) reject(name, position, format(stop.position), "must be finite");
    if (!detail::length_in_range(stop.position)) detail::reject_out_of_range(format(stop.position), name, position);
    // |s| > L/2: measured from the pin point at the hole's centre, a stop nearer than half the
    // hole's length would sit inside the hole. Exact: halving a double in range is exact.
    if (!position_ok) {
      reject(name, position, format(stop.position),
             "the stop lies inside the hole: its distance from the pin's point P must exceed " +
                 std::string(names.hole_length) + " / 2 = " + format(half_length));
    }
    require_positive_in_range(stop.outer_radius, name, outer_radius);
    reject(name, outer_radius, format(stop.outer_radius),
           "must be larger than " + std::string(names.hole_radius) + " = " + format(dimensions.hole_radius) +
               " (a stop smaller than the hole passes through it)");
  }
  if (dimensions.stop_count == 2 && (dimensions.stops[0].position > 0.0) == (dimensions.stops[1].position > 0.0)) {
    reject(name, std::string(names.stops) + "[1].position", format(dimensions.stops[1].position),
           "must lie on the other side of the pin's point P from " + std::string(names.stops) +
               "[0].position = " + format(dimensions.stops[0].position) + " (one stop on each side of the hole)");
  }
}

}  // namespace clearjoint::geometry
