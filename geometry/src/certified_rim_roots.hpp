#pragma once
// All roots of the rim distance polynomial g on the circle, each proved, plus a proof that no
// other root exists (docs/circle-cylinder.md, sections 2-3). Two floating-point tiers:
//   1. the first-harmonic proof: one step, covers rims whose tilt term is small next to their
//      offset term (nearly every realistic pose);
//   2. subdivision with Taylor bounds: any configuration whose roots are all simple and not too
//      close together.
// Where both fail (tangency, double roots) the caller goes to the exact tier (rim_cylinder_exact).

#include <array>
#include <limits>

#include "rim_distance_polynomial.hpp"

namespace clearjoint::geometry::detail {

/// A root of g: the true root lies in [angle - radius, angle + radius].
struct RootEnclosure {
  double angle = 0.0;   ///< in [0, 2 pi)
  double radius = 0.0;  ///< radians
  int multiplicity = 1;
  /// Sign of g just after the root (counter-clockwise): +1 the rim leaves the cylinder there.
  int sign_after = 0;
  /// cos and sin of the root's angle when the tier already has them (tier 1, by angle addition,
  /// within kAngleAdditionTrigError of the true values; the angle's own rounding is inside
  /// `radius`); NaN otherwise. They save the crossing point its libm sine and cosine.
  double cos = kNoTrig, sin = kNoTrig;
  static constexpr double kNoTrig = std::numeric_limits<double>::quiet_NaN();
  bool has_trig() const { return cos == cos; }
};

struct RimRoots {
  bool proved = false;            ///< false: the tier could not decide; `failure` says why
  const char* failure = "";
  int count = 0;                  ///< distinct roots
  std::array<RootEnclosure, 4> roots{};  ///< sorted by angle
  /// When count == 0: +1 every rim point is beyond the wall, -1 every point inside,
  /// 0 g vanishes identically (rim on the surface; only the exact tier reports this).
  int sign_without_roots = 0;
};

/// Sorts the first `count` roots by angle (insertion sort: at most four elements, and
/// std::sort on a 4-element array trips gcc 12's -Warray-bounds).
void sort_by_angle(RimRoots& roots);

/// Tier 1 then tier 2. Never returns a wrong `proved` answer (under the arithmetic model of
/// error_bounded.hpp).
RimRoots certified_rim_roots(const RimDistancePolynomial& g);

/// The same search without proofs: used when the caller switched certificates off, and as the
/// best guess when a proof fails and the exact fallback is disabled. `proved` stays false.
RimRoots approximate_rim_roots(const RimDistancePolynomial& g);

}  // namespace clearjoint::geometry::detail
