// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The order of a predicate's tiers, written once. The idea is CGAL's Filtered_predicate: evaluate
// the predicate with a fast approximate number type that can say "I cannot tell", and only then
// with an exact one. Here the approximate evaluation has two forms of one expression
// (plane_terms.hpp, rim_reach_terms.hpp, rim_distance_polynomial.hpp):
//  1. the a priori filter: plain double plus one absolute-value twin per value
//     (a_priori_bounds.hpp), valid only inside a magnitude guard;
//  2. the running-error filter (error_bounded.hpp), for every other finite input;
// one of the two runs, chosen by the guard (the running error is the filter of the inputs the a
// priori bounds do not cover, not a second attempt), and
//  3. the exact tier (exact/, CGAL rationals) runs when the filter leaves the answer open.
// "Open" is std::nullopt (CGAL throws Uncertain_conversion_exception: no exceptions on the hot
// path here). The tiers are callables, inlined: the dispatch costs nothing at run time.

#include <optional>
#include <utility>

namespace clearjoint::geometry::detail {

/// Tier 1 where the guard holds, tier 2 elsewhere: both return the same quantities (or decision)
/// with rigorous error bounds, so nothing after them depends on which ran.
template <class APriori, class RunningError>
[[gnu::always_inline]] inline auto floating_point_filter(bool a_priori_bounds_apply, APriori&& a_priori,
                                                         RunningError&& running_error) {
  return a_priori_bounds_apply ? std::forward<APriori>(a_priori)() : std::forward<RunningError>(running_error)();
}

/// The filter's decision (a std::optional), or the exact tier's when the filter has none.
template <class Filtered, class Exact>
[[gnu::always_inline]] inline auto filtered_or_exact(Filtered&& filtered, Exact&& exact) {
  if (auto decided = std::forward<Filtered>(filtered)()) return *std::move(decided);
  return std::forward<Exact>(exact)();
}

/// The three tiers in order: decide(the filter's quantities) -> std::optional<Result>, and
/// exact() -> Result when that is empty.
template <class APriori, class RunningError, class Decide, class Exact>
[[gnu::always_inline]] inline auto filtered_predicate(bool a_priori_bounds_apply, APriori&& a_priori,
                                                      RunningError&& running_error, Decide&& decide, Exact&& exact) {
  return filtered_or_exact(
      [&] { return decide(floating_point_filter(a_priori_bounds_apply, a_priori, running_error)); }, exact);
}

/// What a tier of a query that fills its answer in place returns: decided (the answer filled),
/// left open and why, or declined. The reason travels on: the exact tier's certificate names why
/// the filter could not decide, and the fallback's why the last tier that ran could not.
/// Declined stops the cascade without an answer and without the fallback: the caller asked the
/// tier not to run (the detection's first pass of the circle-plane query declines the exact tier,
/// whose recipes it builds only then, and asks again).
template <class Reason>
struct TierVerdict {
  enum class Outcome : unsigned char { decided, open, declined };
  Outcome outcome = Outcome::open;
  Reason why_open{};  ///< when open

  static TierVerdict done() { return {Outcome::decided, Reason{}}; }
  static TierVerdict open(Reason why) { return {Outcome::open, why}; }
  static TierVerdict declined() { return {Outcome::declined, Reason{}}; }
};

/// The tiers in order, for a query whose exact tier can give up (CGAL's exact number types always
/// decide; the circle-cylinder exact tier works on the doubles' integer mantissas and gives up
/// where an intermediate leaves the double range or root isolation exceeds its budget), and which
/// must still answer:
///  1. filter() -> TierVerdict: the floating-point filters;
///  2. exact(filter's reason) -> TierVerdict, where `exact_tier_on` and the filter left it open;
///  3. fallback(reason of the last tier that ran): an approximate answer, marked uncertain.
/// Each tier fills the answer itself: copying an answer out of a std::optional cost measurably on
/// the hot paths (intersect_circle_plane.cpp). Returns whether the answer was filled: false only
/// where a tier declined.
template <class Reason, class Filter, class Exact, class Fallback>
[[gnu::always_inline]] inline bool filtered_exact_or_fallback(bool exact_tier_on, Filter&& filter, Exact&& exact,
                                                              Fallback&& fallback) {
  using Outcome = typename TierVerdict<Reason>::Outcome;
  TierVerdict<Reason> verdict = std::forward<Filter>(filter)();
  if (verdict.outcome != Outcome::open) return verdict.outcome == Outcome::decided;
  if (exact_tier_on) {
    verdict = std::forward<Exact>(exact)(verdict.why_open);
    if (verdict.outcome != Outcome::open) return verdict.outcome == Outcome::decided;
  }
  std::forward<Fallback>(fallback)(verdict.why_open);
  return true;
}

}  // namespace clearjoint::geometry::detail
