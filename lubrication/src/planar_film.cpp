// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/lubrication/planar_film.hpp"

#include <cmath>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/lubrication/film_conditions.hpp"
#include "refuse.hpp"

namespace clearjoint::lubrication {

using detail::require;

void validate(const PlanarBearing& bearing, const PlanarFilmState& state, double viscosity) {
  require(std::isfinite(bearing.radius) && bearing.radius > 0.0, "bearing.radius", bearing.radius,
          "must be positive and finite");
  require(std::isfinite(bearing.width) && bearing.width > 0.0, "bearing.width", bearing.width,
          "must be positive and finite");
  require(std::isfinite(bearing.radial_clearance) && bearing.radial_clearance > 0.0 &&
              bearing.radial_clearance < bearing.radius,
          "bearing.radial_clearance", bearing.radial_clearance,
          "must be positive, finite and smaller than the radius");
  require(state.eccentricity_ratio >= 0.0 && state.eccentricity_ratio < 1.0,
          "state.eccentricity_ratio", state.eccentricity_ratio,
          "must be in [0, 1) (at 1 the journal touches the wall and the film has no thickness)");
  require(std::isfinite(state.eccentricity_ratio_rate), "state.eccentricity_ratio_rate",
          state.eccentricity_ratio_rate, "must be finite");
  require(std::isfinite(state.line_of_centres_rate), "state.line_of_centres_rate",
          state.line_of_centres_rate, "must be finite");
  require(std::isfinite(state.journal_spin), "state.journal_spin", state.journal_spin,
          "must be finite");
  validate(Lubricant{viscosity});
}

}  // namespace clearjoint::lubrication
