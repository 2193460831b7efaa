// SPDX-License-Identifier: BSD-3-Clause
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
#include <utility>

#include "clearjoint/geometry/model/certificate.hpp"
#include "predicates/rim_distance_polynomial.hpp"

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

/// Where a rim without crossings lies: the sign of g on the whole rim.
enum class RimSideWithoutRoots : signed char {
  inside = -1,     ///< every rim point strictly inside the wall (g < 0)
  on_surface = 0,  ///< g vanishes identically (only the exact tier reports this)
  beyond = 1,      ///< every rim point strictly beyond the wall (g > 0)
};
/// The side whose sign is `sign` (-1, 0 or +1).
constexpr RimSideWithoutRoots side_of_sign(int sign) { return static_cast<RimSideWithoutRoots>(sign); }

struct RimRoots {
  bool proved = false;  ///< false: the tier could not decide; `failure` says why
  /// Why the tier could not decide (when !proved); `none` otherwise.
  CertificateReason failure = CertificateReason::none;
  int count = 0;                  ///< distinct roots
  std::array<RootEnclosure, 4> roots{};  ///< sorted by angle
  /// When count == 0: where the rim lies.
  RimSideWithoutRoots side_without_roots = RimSideWithoutRoots::on_surface;
};

/// Tier 1's Halley runs stop after a step this small (relative to 1 + |angle|): convergence is
/// cubic, so the iterate is then off by about K |step|^3 (K a ratio of g's derivatives, of order
/// one away from tangencies), below 2^-60 relative, an ulp or less. 2^-18 (one step fewer in more
/// runs) left some crossings a few ulps worse on the accuracy suite; 2^-20 gives its figures.
inline constexpr double kHalleyLastStep = 0x1p-20;

/// Halley's iteration near grid angles whose sine and cosine come from a table (angle_grid.hpp);
/// every iterate is reached by angle addition (approximate_near). Halley, not Newton: from the
/// first-harmonic guesses (about 1e-3 rad off) it settles in two steps where Newton took three,
/// and each step is one division either way (the step is 2 g g' / (2 g'^2 - g g''), whose
/// g'' costs a few multiplications beside g and g'): a shorter dependency chain by a third.
/// Tier 1's two runs
/// (first_harmonic_proof in certified_rim_roots.cpp; declared here for its test) side by side,
/// run i in lane i (pair_lanes.hpp): each run is a chain of dependent divisions and polynomial
/// evaluations, and one chain of packed operations does the work of both. Each lane's arithmetic
/// is exactly what its run would do alone: a run that has stopped keeps its state (the masks in
/// `step`) while the other still iterates, and a move to another grid angle is a table look-up
/// for that lane alone.
struct HalleyRuns {
  std::array<Pair, 5> k;  ///< g's coefficient values, each in both lanes
  AngleBaseOf<Pair> base;
  Pair offset;
  Pair slope = {0.0, 0.0};      ///< |g'| at each run's last iterate evaluated
  PairMask running = {-1, -1};  ///< -1 while the run iterates, 0 once it has stopped

  /// Halley on g; run i starts at guesses[i] exactly: the grid angle nearest to it plus the
  /// (exact) offset.
  /// The constructor and step are always inlined: tier 1 calls them from two places (the
  /// first-harmonic proof and its cap), and GCC then kept them out of line, the runs' state in
  /// memory (certified_rim_roots.cpp, enclose_after_iteration).
  [[gnu::always_inline]] HalleyRuns(const RimDistancePolynomial& g, const std::array<double, 2>& guesses) {
    for (int i = 0; i < 5; ++i) k[i] = Pair{g.k[i].value, g.k[i].value};
    start_at({grid_angle(guesses[0]), grid_angle(guesses[1])});
  }

  /// Run i from at[i]. Each Pair is built whole rather than lane by lane: GCC wrote a lane as
  /// an 8-byte store, which the next step's 16-byte load of the Pair must wait for (no store
  /// forwarding), and kept the runs' state in memory for it.
  void start_at(const std::array<GridAngle, 2>& at) {
    base = {Pair{at[0].base.angle, at[1].base.angle}, Pair{at[0].base.cos, at[1].base.cos},
            Pair{at[0].base.sin, at[1].base.sin}};
    offset = Pair{at[0].offset, at[1].offset};
  }
  GridAngle current(int i) const { return {base_of(i), offset[i]}; }
  AngleBase base_of(int i) const { return {base.angle[i], base.cos[i], base.sin[i]}; }

  /// One iteration of each run that has not stopped.
  [[gnu::always_inline]] void step() {
    const ValueAndSlopeOf<Pair> at = approximate_at(k, cos_sin_near(base, offset));
    const Pair change = 2 * at.value * at.slope / (2 * at.slope * at.slope - at.value * at.curvature);
    const Pair next = offset - change;
    const PairMask finite = change - change == 0.0;  // std::isfinite(change)
    // The next iterate lies beyond the angle addition's range from the grid angle (a poor
    // first-harmonic guess): move to the grid angle nearest to it, a table look-up.
    const PairMask moves = running & finite & (magnitude(next) > kMaxAngleOffset);
    const PairMask advances = running & finite & ~moves;
    // Cubic convergence: after a step below kHalleyLastStep the iterate is off by an ulp or less
    // unless g' is small (near a tangency), where the proof's enclosure grows until its sign
    // checks pass. Either way the proof decides.
    const PairMask settles =
        advances & (magnitude(change) < kHalleyLastStep * (1.0 + magnitude(base.angle)));
    slope = select(running, magnitude(at.slope), slope);
    offset = select(advances, next, offset);
    running &= finite & ~settles;  // a non-finite step stops the run where it is
    if (!any_lane(moves)) return;
    std::array<GridAngle, 2> starts;
    for (int i = 0; i < 2; ++i) starts[i] = moves[i] ? grid_angle(base.angle[i] + next[i]) : current(i);
    start_at(starts);
  }
};

/// x in both lanes (PairBounded and its arithmetic: error_bounded.hpp).
inline PairBounded both_lanes(const Bounded& x) { return {Pair{x.value, x.value}, Pair{x.error, x.error}}; }
/// Bounded::sign() per lane, as masks: `positive` where it is +1, `negative` where it is -1.
struct PairSigns {
  PairMask positive, negative;
};
inline PairSigns signs(const PairBounded& x) {
  const Pair margin = sign_margin(x.error);
  return {x.value > margin, x.value < -margin};
}

/// The first-harmonic proof's end-arc signs (certified_rim_roots.cpp, tier 1): {at 0, at pi},
/// the sign g keeps over the end arc |psi| <= alpha, resp. |psi - pi| <= alpha, or 0 where none
/// is proved. g there lies in k0 + A [near, far] + [-Hg, Hg] (A > 0, linear in the cosine c):
/// it has a sign if both ends, widened by Hg, have it. Both arcs' near ends (c = cos alpha,
/// -cos alpha) are evaluated in one pair of lanes and both far ends (c = 1, -1) in another.
/// x - hg and x + hg are the same enclosure (hg's value is 0: the sums differ at most in the
/// sign of a zero, which sign() ignores), so one sign per end decides + and - alike.
inline std::array<int, 2> end_arc_signs(const Bounded& k0, const Bounded& amplitude, const Bounded& cos_alpha,
                                        double bound_h) {
  const PairBounded k0s = both_lanes(k0), amplitudes = both_lanes(amplitude);
  const PairBounded hg = both_lanes(Bounded(0.0, bound_h));
  const PairBounded near_cos = {Pair{cos_alpha.value, -cos_alpha.value}, Pair{cos_alpha.error, cos_alpha.error}};
  const PairBounded far_cos = {Pair{1.0, -1.0}, Pair{0.0, 0.0}};
  const PairSigns near = signs(k0s + amplitudes * near_cos - hg);
  const PairSigns far = signs(k0s + amplitudes * far_cos - hg);
  const PairMask positive = near.positive & far.positive, negative = near.negative & far.negative;
  return {positive[0] ? 1 : negative[0] ? -1 : 0, positive[1] ? 1 : negative[1] ? -1 : 0};
}

/// Sorts the first `count` roots by angle (insertion sort: at most four elements, and
/// std::sort on a 4-element array trips gcc 12's -Warray-bounds). Inline: see sort_and_wrap
/// (certified_rim_roots.cpp).
inline void sort_by_angle(RimRoots& roots) {
  for (int i = 1; i < roots.count && i < 4; ++i) {
    for (int j = i; j > 0 && roots.roots[j].angle < roots.roots[j - 1].angle; --j)
      std::swap(roots.roots[j], roots.roots[j - 1]);
  }
}

/// The roots of the rim that g encloses, decided by a tier beyond floating point (the exact tier,
/// rim_cylinder_exact.hpp, which this layer does not see), computed at most once and only when
/// tier 2 asks. Tier 2 asks where its search has narrowed to a minimum of |g| inside the
/// evaluation's noise, the mark of a tangency: a root of multiplicity >= 2 there is one the
/// subdivision can never prove (docs/circle-cylinder.md, section 3.1), and the search stops
/// instead of halving its way to kMaxDepth. The caller hands the same roots on as its answer.
class ExactRootsOnRequest {
 public:
  /// The roots (RimRoots::proved), or nullptr when the tier could not decide them.
  virtual const RimRoots* roots() = 0;

 protected:
  ~ExactRootsOnRequest() = default;
};

/// Tier 1 then tier 2. Never returns a wrong `proved` answer (under the arithmetic model of
/// error_bounded.hpp). With `exact`, tier 2 may ask it for the roots near a suspected tangency
/// and stop early where they prove one (the failure reason is the one the full search gives:
/// interval_proof_failed_near_multiple_root).
RimRoots certified_rim_roots(const RimDistancePolynomial& g, ExactRootsOnRequest* exact = nullptr);

/// The same search without proofs: used when the caller switched certificates off, and as the
/// best guess when a proof fails and the exact fallback is disabled. `proved` stays false.
RimRoots approximate_rim_roots(const RimDistancePolynomial& g);

}  // namespace clearjoint::geometry::detail
