// SPDX-License-Identifier: BSD-3-Clause
#include "filters/certified_rim_roots.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "arithmetic/angles.hpp"

namespace clearjoint::geometry::detail {
namespace {

/// Newton steps (tier 2) or Halley steps (tier 1) from a good start: from the first harmonic's
/// roots (or an arc midpoint) they reach double precision in 3-4, resp. 2-3 steps; more only
/// burns time before the proof.
constexpr int kMaxIterationSteps = 6;
/// Growth of the trial enclosure when a sign check is inconclusive, and how often to try.
constexpr double kEnclosureGrowth = 8.0;
constexpr int kMaxEnclosureTrials = 8;
/// Tier 2: initial arcs, deepest bisection (arc width 2 pi / 16 / 2^34 ~ 2e-11 rad) and total
/// arc budget. Roots closer than about the deepest width are left to the exact tier.
constexpr int kInitialArcs = 16;
constexpr int kMaxDepth = 34;
constexpr int kMaxArcs = 1500;
/// Tier 2 starts its arcs here rather than at 0: exactly representable test poses put roots at
/// multiples of pi/2, and an arc boundary on a root can never be decided by a sign test.
constexpr double kSubdivisionStart = 0.3183098861837907;  // 1/pi, no special angle
/// Relative slack on comparisons of rounded bounds (covers a handful of roundings).
constexpr double kSlack = 1.0 + 0x1p-44;

double high(const Bounded& x) { return std::fabs(x.value) + x.error; }

double newton(const RimDistancePolynomial& g, double theta, double low, double high_end) {
  for (int i = 0; i < kMaxIterationSteps; ++i) {
    const double step = g.approximate_newton_step(theta);
    if (!std::isfinite(step)) break;
    const double next = std::clamp(theta - step, low, high_end);
    if (next == theta) break;
    theta = next;
    // Quadratic convergence: once a step is below ~1e-8 rad the next error is below an ulp.
    if (std::fabs(step) < 4 * kUnitRoundoff * (1.0 + std::fabs(theta))) break;
  }
  return theta;
}

/// Proves a simple root near `theta` where g changes sign as `direction` (+1: - to +) by a sign
/// change of the rigorous g over [theta - eps, theta + eps], inside [low, high_end].
bool enclose_simple_root(const RimDistancePolynomial& g, double theta, int direction, double low,
                         double high_end, RootEnclosure& out) {
  // First trial: a few ulps of theta; the sign checks themselves say if that was too tight.
  double eps = 16 * kUnitRoundoff * (1.0 + std::fabs(theta));
  for (int trial = 0; trial < kMaxEnclosureTrials; ++trial, eps *= kEnclosureGrowth) {
    const double lo = std::max(theta - eps, low);
    const double hi = std::min(theta + eps, high_end);
    if (g.value(lo).sign() == -direction && g.value(hi).sign() == direction) {
      out.angle = theta;
      out.radius = std::max(theta - lo, hi - theta) * kSlack;
      out.multiplicity = 1;
      out.sign_after = direction;
      return true;
    }
    if (lo == low && hi == high_end) break;
  }
  return false;
}

/// The enclosure of each root of tier 1 from g and g' at the iterate x itself (lane i: root i,
/// g changing sign as directions[i] there): one evaluation for both roots where the sign change
/// took two per root. `at` is approximate_at there, x = base + offset the real sum. With
/// |g(x)| <= V, directions[i] g'(x) >= S > 0 and |g''| <= M2 everywhere, a half-width rho with
///   V <= S rho / 2   and   M2 rho <= S / 2
/// encloses a root: on [x - rho, x + rho] directions[i] g' >= S / 2 > 0, so g is strictly
/// monotone there and moves by at least S rho / 2 >= V from g(x) towards each end: g(x - rho)
/// and g(x + rho) bracket 0 as directions[i] says. The interval holds a simple root of that
/// direction, and tier 1's count proof leaves only one such root on the circle.
/// The roundings: V and S are rounded outwards by kSlack (a few relative roundings each), and
/// S must exceed kSmallestProofSlope, so that no product below underflows by more than the
/// kUnderflowError terms added.
struct SlopeBounds {
  Pair value, slope;  ///< V and S
  double curvature;   ///< M2
};
/// Far above underflow, far below any slope a proof could use (coefficients of rescaled inputs,
/// scale_normalisation.hpp, are within a few hundred binades of 1).
constexpr double kSmallestProofSlope = 0x1p-900;
SlopeBounds slope_bounds(const RimDistancePolynomial& g, const RimDistancePolynomial::NearErrorBounds& errors,
                         const ValueAndSlopeOf<Pair>& at, const Pair& directions) {
  return {(magnitude(at.value) + errors.value) * kSlack,           // V
          (at.slope * directions - errors.slope) / kSlack,         // S (times +-1: exact)
          g.curvature_bound()};
}
/// Lanes where `half_width` passes both conditions: 2 V <= S rho and 2 M2 rho <= S, each side
/// rounded the safe way (the doublings exact).
PairMask encloses(const SlopeBounds& b, const Pair& half_width) {
  return (b.slope > kSmallestProofSlope) & ((2 * b.value + kUnderflowError) * kSlack <= b.slope * half_width) &
         ((2 * b.curvature * half_width + 4 * kUnderflowError) * kSlack <= b.slope);
}
/// The planned half-width: kPlannedWidth times value's error bound over the last Halley
/// iterate's |g'| (HalleyRuns::slope), known before g at the final iterate is, so that the bound
/// the crossings carry does not wait for that evaluation (only the branch on the proof does, and
/// it is predicted). The half-width 2 V / S from g at the final iterate put that evaluation on
/// the critical path, and the in-contact detection measured slower. The factor 2.2 leaves
/// room for |g(x)| (about an ulp of the angle times |g'|, far below the error bound) and for the
/// change of slope over the last step: the accuracy suite's near-tangent families fall back to
/// the sign change on 39 rims at 2.2, 37 at 2.5 and 149 at 2.1, the benchmark's poses on none;
/// the enclosures are about 2.2 / 2 times the smallest this proof allows.
constexpr double kPlannedWidth = 2.2;

/// Widens eps (by kEnclosureGrowth, at most kMaxEnclosureTrials times) until the signs of g at
/// base + (offset -+ eps), by angle addition (value_near, both ends in the two lanes), prove a
/// sign change `direction` (+1: - to +) between them; false if none does within the angle
/// addition's range. The last fallback of enclose_after_iteration's proof by slope.
bool prove_sign_change(const RimDistancePolynomial& g, const AngleBase& base, double offset,
                       int direction, double& eps) {
  for (int trial = 0; trial < kMaxEnclosureTrials; ++trial, eps *= kEnclosureGrowth) {
    if (std::fabs(offset) + eps > kMaxAngleOffset) return false;
    const PairBounded ends = g.value_near(base, Pair{offset - eps, offset + eps});
    if (ends.lane(0).sign() == -direction && ends.lane(1).sign() == direction) return true;
  }
  return false;
}

/// The sign-change enclosures (prove_sign_change) of the roots in the lanes `proved` leaves 0;
/// the others keep `half_width`. False if one fails.
bool enclose_by_sign_change(const RimDistancePolynomial& g, const HalleyRuns& runs, const Pair& angle,
                            const int (&directions)[2], PairMask proved, Pair& half_width) {
  // First trial: twice the root's uncertainty, |g error| / |g'|, with g's error budget being the
  // coefficient errors plus a few ulps of the terms, if wider than a few ulps of the angle; later
  // trials grow by kEnclosureGrowth. The slope is the last Halley iterate's: a heuristic for the
  // first trial only.
  const double term_size = std::fabs(g.k[0].value) + std::fabs(g.k[1].value) +
                           std::fabs(g.k[2].value) + std::fabs(g.k[3].value) + std::fabs(g.k[4].value);
  const double budget = g.coefficient_error() + 16 * kUnitRoundoff * term_size;
  Pair eps = 16 * kUnitRoundoff * (1.0 + magnitude(angle));
  const Pair from_slope = 2 * budget / runs.slope;
  eps = select((runs.slope > 0.0) & (eps < from_slope), from_slope, eps);
  double widths[2] = {half_width[0], half_width[1]};
  for (int i = 0; i < 2; ++i) {
    if (proved[i]) continue;
    double width = eps[i];
    if (!prove_sign_change(g, runs.base_of(i), runs.offset[i], directions[i], width)) return false;
    // The proof's points offset -+ eps are rounded sums: (1 + 4u) covers it.
    widths[i] = width * (1 + 4 * kUnitRoundoff);
  }
  half_width = Pair{widths[0], widths[1]};  // rebuilt whole: see HalleyRuns::start_at
  return true;
}

/// The proofs of tier 1's two simple roots where the Halley runs stopped, root i in lane i (g
/// changes sign as directions[i] there), into result.roots[0, 1], wrapped and sorted by angle.
/// Always inlined: with the cap proof as its second caller GCC kept it out of line, and tier 1's
/// common path measured slower.
[[gnu::always_inline]] inline bool enclose_after_iteration(const RimDistancePolynomial& g, const HalleyRuns& runs,
                                                           RimRoots& result) {
  const int directions[2] = {+1, -1};
  const Pair offset = runs.offset;
  const Pair angle = runs.base.angle + offset;
  // The reported angle is the rounded sum, within u |angle| of base + offset (and the
  // sign-change fallback's points within u |offset| of theirs).
  const Pair rounding = 2 * kUnitRoundoff * (magnitude(angle) + magnitude(offset)) + kUnderflowError;
  // g, g' at each real base + offset: the same cosine and sine (bit for bit) as the Halley steps
  // form, handed on to the crossing points. Angle addition holds for |offset| <= kMaxAngleOffset,
  // which every iterate keeps (HalleyRuns::step); checked, as the fallback does.
  const ValueAndSlopeOf<Pair> at = approximate_at(runs.k, cos_sin_near(runs.base, offset));
  const RimDistancePolynomial::NearErrorBounds errors = g.near_error_bounds();
  const SlopeBounds bounds = slope_bounds(g, errors, at, Pair{1.0, -1.0});
  const PairMask in_range = magnitude(offset) <= kMaxAngleOffset;
  Pair half_width = (kPlannedWidth * errors.value / runs.slope + kUnderflowError) * kSlack;
  PairMask proved = encloses(bounds, half_width) & in_range;
  // Near a tangency (|g'| small next to |g''|) the slope's conditions fail: the sign change,
  // which the iteration's remaining error does not hamper, decides those lanes. (The half-width
  // 2 V / S from g at x itself, tried in between, never rescued a lane there: 0 of the 63 in
  // the tests that reach this.)
  if (!all_lanes(proved) && !enclose_by_sign_change(g, runs, angle, directions, proved, half_width)) return false;
  const Pair radius = (half_width + rounding) * kSlack;
  // Wrapped into [0, 2 pi) and written straight into angle order, as sort_and_wrap would leave
  // them: sorting after writing swapped the two 56-byte enclosures with 16-byte loads of fields
  // just stored as doubles, which the store buffer cannot forward (a stall per crossing rim).
  double wrapped[2], radii[2];
  for (int i = 0; i < 2; ++i) {
    wrapped[i] = wrap_angle(angle[i]);
    // Wrapping subtracts a rounded 2 pi: widen by its rounding (one ulp of 2 pi is 8.9e-16).
    radii[i] = wrapped[i] != angle[i] ? radius[i] + 2 * kUnitRoundoff * kTwoPi : radius[i];
  }
  const int lane_0_slot = wrapped[1] < wrapped[0] ? 1 : 0;  // sort_by_angle's order, ties kept
  for (int i = 0; i < 2; ++i) {
    RootEnclosure& root = result.roots[i == 0 ? lane_0_slot : 1 - lane_0_slot];
    root.angle = wrapped[i];
    root.radius = radii[i];
    root.multiplicity = 1;
    root.sign_after = directions[i];
    root.cos = at.cos[i];
    root.sin = at.sin[i];
  }
  return true;
}

/// Tier 2's roots (collect_distinct) into [0, 2 pi) and angle order; tier 1 writes its two in
/// order directly (enclose_after_iteration).
void sort_and_wrap(RimRoots& result) {
  for (int i = 0; i < result.count; ++i) {
    RootEnclosure& root = result.roots[i];
    const double wrapped = wrap_angle(root.angle);
    // Wrapping subtracts a rounded 2 pi: widen by its rounding (one ulp of 2 pi is 8.9e-16).
    if (wrapped != root.angle) root.radius += 2 * kUnitRoundoff * kTwoPi;
    root.angle = wrapped;
  }
  sort_by_angle(result);
}

/// Tier 1's end once the count proof leaves exactly two simple roots, g rising through the one
/// run 0 seeks and falling through run 1's: the Halley runs to their stop, then the proofs of
/// both roots (enclose_after_iteration) into `result`. False if a proof fails.
[[gnu::always_inline]] inline bool iterate_and_enclose_two_roots(const RimDistancePolynomial& g, HalleyRuns& runs,
                                                                 RimRoots& result) {
  for (int i = 0; i < kMaxIterationSteps && any_lane(runs.running); ++i) runs.step();
  if (!enclose_after_iteration(g, runs, result)) return false;
  result.count = 2;
  result.proved = true;
  return true;
}

// ---- Tier 1, the cap: a rim barely beyond the wall, or barely inside it -----------------
// (docs/circle-cylinder.md, section 2.1.) When the rim's deepest reach lies within the second
// harmonic's size of the wall (a contact just beginning or just missed: the prefilters pass it,
// and 15 of the benchmark's 4,096 in-contact poses have such a rim), first_harmonic_proof cannot
// sign the end arc around psi = 0, and tier 2's subdivision costs some 25 times tier 1 for it.
// With |h''| <= Hdd, g'' = -A cos(psi) + h'' < 0 on the cap |psi| <= gamma, A cos(gamma) = 2 Hdd:
// g is strictly concave there, so it has at most two roots there, and if it is negative at the
// cap's ends, it is negative everywhere else: for gamma >= alpha the ends lie on the monotone
// arcs, on which g falls from psi = gamma and rises to psi = -gamma, and the end arc around pi
// is proved negative. Then
//   - two proved roots whose slopes have opposite signs are all of g's roots (two disjoint
//     enclosures, each holding a root, and no room for a third);
//   - a concave g proved negative at its peak (by the tangent there) has none.

/// What first_harmonic_proof hands to cap_proof.
struct CapInputs {
  Bounded k0, amplitude;  ///< k0 and A, enclosed
  double amplitude_low;   ///< a lower bound on A
  double cos_alpha_low;   ///< a lower bound on cos(alpha)
  double bound_h;         ///< Hg >= |h|
  double bound_ddh;       ///< Hdd >= |h''|
  double phi;             ///< the first harmonic's peak, within kApproximateAngleError
};
/// cap_proof takes caps with gamma >= pi / 3 only (cos(gamma) <= 1/2): the peak estimate, at
/// most kLargestPeakShift from phi, then lies inside the cap, as the tangent bound needs.
constexpr double kLargestCapCosine = 0.5;
constexpr double kLargestPeakShift = 1.0;

/// The cap proof; false where it cannot decide (tier 2 then). Out of line and cold: the
/// first-harmonic proof's common path should not carry it.
[[gnu::noinline, gnu::cold]] bool cap_proof(const RimDistancePolynomial& g, const CapInputs& in,
                                            RimRoots& result) {
  // cos(gamma) rounded up, so that A cos(gamma) >= 2 Hdd > Hdd for every A >= amplitude_low.
  const double cos_gamma = (2 * in.bound_ddh / in.amplitude_low + kUnderflowError) * kSlack;
  if (!(cos_gamma <= kLargestCapCosine && cos_gamma * kSlack <= in.cos_alpha_low)) return false;
  // g at the cap's ends lies in k0 + A cos(gamma) +- Hg.
  if ((in.k0 + in.amplitude * Bounded(cos_gamma) + Bounded(0.0, in.bound_h)).sign() >= 0) return false;

  // The peak from the quadratic model at psi = 0 (cos phi = k1 / A, sin phi = k2 / A, rounded:
  // a guess), and the roots, if any, where that model vanishes.
  const double inverse_amplitude = 1.0 / in.amplitude.value;
  const ValueAndSlope at = g.approximate_at(CosSin{g.k[1].value * inverse_amplitude, g.k[2].value * inverse_amplitude});
  if (!(at.curvature < 0.0)) return false;
  const double peak_shift = -at.slope / at.curvature;
  const double peak = in.phi + peak_shift;
  const double peak_value = at.value + 0.5 * at.slope * peak_shift;  // g - g'^2 / (2 g'')
  if (peak_value > 0.0) {
    const double half_gap = std::sqrt(-2 * peak_value / at.curvature);
    HalleyRuns runs(g, {peak - half_gap, peak + half_gap});
    return iterate_and_enclose_two_roots(g, runs, result);
  }
  // No root: for t and x on the cap, g(t) <= g(x) + g'(x) (t - x) (concavity), and
  // |t - x| <= gamma + |x - phi| <= pi / 2 + |peak_shift| + phi's error.
  if (!(std::fabs(peak_shift) <= kLargestPeakShift)) return false;
  const Bounded value = g.value(peak);
  const double reach = (0.5 * std::numbers::pi + std::fabs(peak_shift) + kApproximateAngleError) * kSlack;
  const double tangent_rise = high(g.derivative(peak)) * reach * kSlack;
  if ((value + Bounded(0.0, tangent_rise)).sign() >= 0) return false;
  result.proved = true;
  result.count = 0;
  result.side_without_roots = RimSideWithoutRoots::inside;
  return true;
}

// ---- Tier 1: the first-harmonic proof (docs/circle-cylinder.md, section 2) ----------------
// Write g = k0 + A cos(psi) + h(theta), psi = theta - phi, with A = hypot(k1, k2) of the stored
// centre values and h the second harmonic plus the first harmonic's coefficient errors:
// |h| <= Hg, |h'| <= Hd. Pick alpha with A sin(alpha) > Hd. Then g is strictly monotone where
// |sin psi| >= sin(alpha) (two arcs), and if k0 + A c + [-Hg, Hg] keeps one sign for c in
// [cos alpha, 1] and in [-1, -cos alpha], the two remaining arcs hold no root. So g has 0 roots
// (both end signs equal) or exactly 2 simple roots, one per monotone arc (signs differ).
bool first_harmonic_proof(const RimDistancePolynomial& g, RimRoots& result) {
  const Bounded& k0 = g.k[0];
  const double second = high(g.k[3]) + high(g.k[4]);
  const double first_error = g.k[1].error + g.k[2].error;
  const double bound_h = (second + first_error) * kSlack;
  const double bound_dh = (2 * second + first_error) * kSlack;
  // A^2 = k1^2 + k2^2 of the stored values (exact operands), both squares in one pair of lanes.
  const PairBounded first_harmonic = {Pair{g.k[1].value, g.k[2].value}, Pair{0.0, 0.0}};
  const PairBounded squares = first_harmonic * first_harmonic;
  const Bounded amplitude = sqrt(squares.lane(0) + squares.lane(1));
  const double amplitude_low = amplitude.lower() / kSlack;

  // If there are two roots, they lie at psi = +-acos(-k0 / A) to first order; g decreases through
  // the + one. These are the Halley runs' starting guesses, which the second harmonic moves the roots
  // away from by far more than the approximations' 4e-7 rad (angles.hpp): libm's atan2 and acos
  // would buy nothing. Formed (with their grid angles, angle_grid.hpp) before the proof that
  // there are two roots, which nearly every rim that gets here has: the chain of square roots
  // and divisions then overlaps with the proof's arithmetic instead of following it.
  const Pair phi_beta = approximate_atan2_and_acos(g.k[2].value, g.k[1].value, -k0.value / amplitude.value);
  const double phi = phi_beta[0], beta = phi_beta[1];
  HalleyRuns runs(g, {phi - beta, phi + beta});

  // sin(alpha) = 2 Hd / A: the factor 2 leaves room for rounding; beyond 1/2 the monotone
  // arcs get too short to be useful and tier 2 is the better tool.
  if (!(amplitude_low > 4 * bound_dh)) return false;
  const double sin_alpha = 2 * bound_dh / amplitude_low * kSlack;
  const Bounded cos_alpha = sqrt(Bounded(1.0) - Bounded(sin_alpha) * sin_alpha);
  const auto [sign_at_zero, sign_at_pi] = end_arc_signs(k0, amplitude, cos_alpha, bound_h);
  if (sign_at_zero == 0 && sign_at_pi < 0) {
    const double bound_ddh = (4 * second + first_error) * kSlack;  // |h''|: 4 per second-harmonic term
    return cap_proof(g, {k0, amplitude, amplitude_low, cos_alpha.lower() / kSlack, bound_h, bound_ddh, phi}, result);
  }
  if (sign_at_zero == 0 || sign_at_pi == 0) return false;
  if (sign_at_zero == sign_at_pi) {
    result.proved = true;
    result.count = 0;
    result.side_without_roots = side_of_sign(sign_at_zero);
    return true;
  }
  if (sign_at_zero < 0) return false;  // impossible with A > 0; keep the proof honest
  return iterate_and_enclose_two_roots(g, runs, result);
}

// ---- Tier 2: subdivision with Taylor bounds (docs/circle-cylinder.md, section 3) ---------
/// The signs of g (Bounded::sign) at an arc's ends, when known: an end that is its parent's
/// middle keeps the sign g had there, the same evaluation the monotone case would repeat.
constexpr int kSignNotYetKnown = 2;
struct Arc {
  double low, high;
  int depth;
  int sign_low = kSignNotYetKnown, sign_high = kSignNotYetKnown;
};

/// Keeps the distinct roots among `found` (a root next to the seam of the circle can be found
/// from both sides, with overlapping enclosures) and sorts them.
void collect_distinct(const RootEnclosure* found, int count, int seen_sign, RimRoots& result) {
  result.count = 0;
  for (int i = 0; i < count; ++i) {
    bool duplicate = false;
    for (int j = 0; j < result.count; ++j) {
      const double gap = std::fabs(wrap_angle(found[i].angle - result.roots[j].angle + 1.0) - 1.0);
      if (gap <= found[i].radius + result.roots[j].radius) duplicate = true;
    }
    if (!duplicate && result.count < 4) result.roots[result.count++] = found[i];
  }
  result.side_without_roots = side_of_sign(result.count == 0 ? seen_sign : 0);
  sort_and_wrap(result);
}

// ---- Tier 2's stop at a proved multiple root (docs/circle-cylinder.md, section 3.1) -------
// Let an arc [low, high] hold a root t0 of multiplicity >= 2 of the function g encloses. At t0 both
// g and g' vanish, and |g''| <= M2 (second_derivative_bound) everywhere, so at the middle m of any
// arc holding t0, with rho >= |m - t0|: |g(m)| <= M2 rho^2 / 2 and |g'(m)| <= M2 rho. The
// enclosures of g(m) and g'(m) contain those values, so neither the no-root test nor the
// monotone test below can pass on such an arc: the search halves it to kMaxDepth and fails there
// with interval_proof_failed_near_multiple_root, about 2 (kMaxDepth - depth) evaluations later.
// (No more than four roots can turn up first: a double root leaves at most two others.) So where
// the exact tier, asked once, proves a multiple root inside the arc, the search stops at once
// with that reason: the answer and its certificate are the ones the full search leads to, and
// the tangencies that took tier 2 some 65 evaluations take about 30.

/// Arcs at least this deep (width 2 pi / 16 / 2^8, about 1.5e-3 rad) where both tests fail are
/// checked for a tangency (looks_like_tangency). Shallower arcs fail both tests around any
/// pair of roots (their Newton start is too far for the check to mean much); deeper checks save
/// less of the descent (about 1.6 arcs per level at the benchmark's tangencies: the exact-tangency
/// benchmark measured 8.7 us per rim checking from depth 8, 9.5 us from depth 12).
constexpr int kTangencyCheckDepth = 8;
/// Newton steps on g' from the arc's middle towards the critical point: from within 1.5e-3 rad of
/// it, the second step leaves an error near 1e-11 rad (quadratic convergence), which moves the
/// critical value by some 1e-22 of g'', far below any error bound of g.
constexpr int kCriticalPointSteps = 2;
/// A critical value of |g| at most this many times its own error bound looks like a tangency: at
/// a double root the computed value is its rounding alone, inside the bound. At 16 the check
/// also caught near-tangent pairs that tier 2 goes on to separate, and asked the exact tier for
/// nothing (the detection suite's near_tangent k=11 set took 2.3 times as long).
constexpr double kTangencyNoiseFactor = 2;
/// Critical points checked per query, each three evaluations of g: the first check looks up to
/// kCriticalPointReach arc widths around its arc, and once the exact roots are known every later
/// arc is tested against them without a check. A second check cost the near-tangent pairs that
/// tier 2 separates 5 % and caught no tangency the first one missed.
constexpr int kMaxTangencyChecks = 1;
/// The argument above multiplies M2 by the squared radius of a kMaxDepth arc (~2^-74): above this
/// bound on M2 the products stay normal numbers, whose roundings kSlack covers.
constexpr double kSmallestCurvatureForStop = 0x1p-900;

/// How far beyond an arc the critical point may lie, in arc widths: the search meets the arcs
/// beside a tangency's (which fail both tests too) before the arc that holds it.
constexpr double kCriticalPointReach = 2.0;

/// Whether the minimum of |g| near `middle` (within kCriticalPointReach arc widths of [low, high])
/// lies within kTangencyNoiseFactor times its error bound: the sign of a tangency that tier 2
/// would halve its way into.
bool looks_like_tangency(const RimDistancePolynomial& g, double middle, double low, double high_end) {
  const double reach = kCriticalPointReach * (high_end - low);
  double theta = middle;
  for (int i = 0; i < kCriticalPointSteps; ++i) {
    const ValueAndSlope at = g.approximate_at(CosSin{std::cos(theta), std::sin(theta)});
    if (!(at.curvature != 0.0)) return false;
    const double next = std::clamp(theta - at.slope / at.curvature, low - reach, high_end + reach);
    if (!std::isfinite(next)) return false;
    theta = next;
  }
  const Bounded at = g.value(theta);
  return std::fabs(at.value) <= kTangencyNoiseFactor * at.error;
}

/// Whether one of `exact`'s roots of multiplicity >= 2 lies, with its whole enclosure, inside
/// [low, high] (tier 2's arcs start at kSubdivisionStart, the roots' angles lie in [0, 2 pi)).
bool holds_multiple_root(const RimRoots& exact, double low, double high_end) {
  for (int i = 0; i < exact.count; ++i) {
    const RootEnclosure& root = exact.roots[static_cast<std::size_t>(i)];
    if (root.multiplicity < 2) continue;
    for (const double turn : {0.0, kTwoPi}) {
      const double angle = root.angle + turn;
      // The rounded 2 pi and the sums here: a few ulps of the angle.
      const double margin = root.radius * kSlack + 4 * kUnitRoundoff * angle;
      if (angle - margin >= low && angle + margin <= high_end) return true;
    }
  }
  return false;
}

bool subdivision_proof(const RimDistancePolynomial& g, RimRoots& result, ExactRootsOnRequest* exact) {
  const double curvature = g.second_derivative_bound();
  Arc stack[kMaxDepth * 2 + kInitialArcs + 2];
  int top = 0;
  const double step = kTwoPi / kInitialArcs;
  for (int i = kInitialArcs - 1; i >= 0; --i) {
    const double low = kSubdivisionStart + i * step;
    // The last arc ends one ulp past start + 2 pi, so rounding never leaves a gap on the circle.
    const double high_end = (i == kInitialArcs - 1)
                                ? std::nextafter(kSubdivisionStart + kTwoPi, HUGE_VAL)
                                : kSubdivisionStart + (i + 1) * step;
    stack[top++] = {low, high_end, 0};
  }
  int seen_sign = 0, arcs_done = 0, found = 0;
  RootEnclosure roots[5];
  // The tangency check's state: checks made, whether the exact tier may still be asked (once, and
  // only where section 3.1's argument holds), its roots once asked (nullptr if undecided).
  int tangency_checks = 0;
  bool may_ask = exact != nullptr && curvature >= kSmallestCurvatureForStop;
  const RimRoots* exact_roots = nullptr;
  while (top > 0) {
    const Arc arc = stack[--top];
    if (++arcs_done > kMaxArcs) {
      result.failure = CertificateReason::subdivision_budget_exhausted;
      collect_distinct(roots, found, seen_sign, result);
      return false;
    }
    const double middle = 0.5 * (arc.low + arc.high);
    const double radius = std::max(middle - arc.low, arc.high - middle) * kSlack;
    const auto [at, slope] = g.value_and_derivative(middle);
    // Taylor: |g(t) - g(m)| <= |g'(m)| rho + M2 rho^2 / 2 on the arc.
    const double variation = (high(slope) * radius + 0.5 * curvature * radius * radius) * kSlack;
    if (std::fabs(at.value) - at.error * kSlack > variation) {
      seen_sign = at.value > 0 ? 1 : -1;
      continue;  // no root on this arc
    }
    const bool monotone = std::fabs(slope.value) - slope.error * kSlack > curvature * radius * kSlack;
    if (monotone) {
      // g' keeps its sign on the arc: at most one root; the end signs say whether there is one.
      const int direction = slope.value > 0 ? 1 : -1;
      const int sign_low = arc.sign_low != kSignNotYetKnown ? arc.sign_low : g.value(arc.low).sign();
      const int sign_high = arc.sign_high != kSignNotYetKnown ? arc.sign_high : g.value(arc.high).sign();
      if (sign_low != 0 && sign_low == sign_high) {
        seen_sign = sign_low;
        continue;
      }
      if (sign_low == -direction && sign_high == direction) {
        if (found == 4) {
          result.failure = CertificateReason::more_than_four_roots;
          collect_distinct(roots, found, seen_sign, result);
          return false;
        }
        const double theta = newton(g, middle, arc.low, arc.high);
        RootEnclosure root;
        if (enclose_simple_root(g, theta, direction, arc.low, arc.high, root)) {
          roots[found++] = root;
          continue;
        }
        if (arc.depth >= kMaxDepth) {
          roots[found++] = {middle, radius, 1, direction};  // the whole (tiny) arc encloses it
          continue;
        }
        // Newton did not settle from this arc's middle: a shorter arc gives it a better start,
        // rather than reporting the whole arc as a uselessly wide enclosure. Falls through.
      }
    }
    if (!monotone && arc.depth >= kTangencyCheckDepth) {
      if (may_ask && tangency_checks < kMaxTangencyChecks) {
        ++tangency_checks;
        if (looks_like_tangency(g, middle, arc.low, arc.high)) {
          may_ask = false;
          exact_roots = exact->roots();
        }
      }
    }
    // The stop of section 3.1, where the arc budget leaves room for two arcs per level of the
    // descent (the full search took about 1.6 at the benchmark's tangencies): only a search that
    // spent the rest of its kMaxArcs beside the tangency would have run out of arcs first.
    const bool proved_doomed = exact_roots != nullptr && !monotone &&
                               arcs_done + 2 * (kMaxDepth - arc.depth) + 2 <= kMaxArcs &&
                               holds_multiple_root(*exact_roots, arc.low, arc.high);
    if (arc.depth >= kMaxDepth || proved_doomed) {
      result.failure = CertificateReason::interval_proof_failed_near_multiple_root;
      // Best guess for the uncertain path: g vanishes to double precision here.
      seen_sign = at.value > 0 ? 1 : -1;
      collect_distinct(roots, found, seen_sign, result);
      return false;
    }
    const int sign_middle = at.sign();
    stack[top++] = {middle, arc.high, arc.depth + 1, sign_middle, arc.sign_high};
    stack[top++] = {arc.low, middle, arc.depth + 1, arc.sign_low, sign_middle};
  }
  collect_distinct(roots, found, seen_sign, result);
  result.proved = true;
  return true;
}

}  // namespace

RimRoots certified_rim_roots(const RimDistancePolynomial& g, ExactRootsOnRequest* exact) {
  RimRoots result;
  result.side_without_roots = g.k[0].value > 0 ? RimSideWithoutRoots::beyond : RimSideWithoutRoots::inside;  // only a guess until proved
  // Bounded::finite() of every coefficient, each value and error in the two lanes: x - x is +0
  // for a finite x and NaN otherwise, and the sum of those is +0 exactly when every term is.
  Pair differences = {0.0, 0.0};
  for (const Bounded& coefficient : g.k) {
    const Pair x = {coefficient.value, coefficient.error};
    differences += x - x;
  }
  if (!all_lanes(differences == 0.0)) {
    result.failure = CertificateReason::coefficient_overflow;
    return result;
  }
  if (first_harmonic_proof(g, result)) return result;
  result = RimRoots{};
  subdivision_proof(g, result, exact);
  return result;
}

RimRoots approximate_rim_roots(const RimDistancePolynomial& g) {
  // Without certificates: drop the coefficient errors and run the same search; a failed
  // search keeps whatever roots it had found.
  RimDistancePolynomial plain = g;
  for (Bounded& coefficient : plain.k) coefficient.error = 0.0;
  RimRoots result = certified_rim_roots(plain);
  result.proved = false;
  if (result.failure == CertificateReason::none) result.failure = CertificateReason::certificate_switched_off;
  return result;
}

}  // namespace clearjoint::geometry::detail
