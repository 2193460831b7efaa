// SPDX-License-Identifier: BSD-3-Clause
// Tests of geometry/src/arithmetic/filtered_predicate.hpp: the order of a predicate's tiers, which
// tier runs for which verdict, and which reason reaches the exact tier and the fallback.

#include "arithmetic/filtered_predicate.hpp"

#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace clearjoint::geometry::detail {
namespace {

enum class Why { none, filter_open, exact_gave_up };
using Verdict = TierVerdict<Why>;

/// Runs filtered_exact_or_fallback with tiers that record themselves in `trace` and the reason
/// they were handed.
struct Cascade {
  std::string trace;
  Why exact_was_told = Why::none, fallback_was_told = Why::none;

  bool answered = false;

  void run(bool exact_tier_on, Verdict filter_verdict, Verdict exact_verdict) {
    answered = filtered_exact_or_fallback<Why>(
        exact_tier_on,
        [&] {
          trace += "filter ";
          return filter_verdict;
        },
        [&](Why why) {
          trace += "exact ";
          exact_was_told = why;
          return exact_verdict;
        },
        [&](Why why) {
          trace += "fallback ";
          fallback_was_told = why;
        });
  }
};

TEST(FilteredExactOrFallback, StopsAtTheFilterWhenItDecides) {
  Cascade c;
  c.run(true, Verdict::done(), Verdict::done());
  EXPECT_EQ(c.trace, "filter ");
}

TEST(FilteredExactOrFallback, HandsTheFiltersReasonToTheExactTierAndStopsWhenItDecides) {
  Cascade c;
  c.run(true, Verdict::open(Why::filter_open), Verdict::done());
  EXPECT_EQ(c.trace, "filter exact ");
  EXPECT_EQ(c.exact_was_told, Why::filter_open);
}

TEST(FilteredExactOrFallback, FallsBackWithTheExactTiersReasonWhenItGivesUp) {
  Cascade c;
  c.run(true, Verdict::open(Why::filter_open), Verdict::open(Why::exact_gave_up));
  EXPECT_EQ(c.trace, "filter exact fallback ");
  EXPECT_EQ(c.fallback_was_told, Why::exact_gave_up);
}

TEST(FilteredExactOrFallback, FallsBackWithTheFiltersReasonWhenTheExactTierIsOff) {
  Cascade c;
  c.run(false, Verdict::open(Why::filter_open), Verdict::done());
  EXPECT_EQ(c.trace, "filter fallback ");
  EXPECT_EQ(c.fallback_was_told, Why::filter_open);
}

TEST(FilteredExactOrFallback, NeverRunsTheExactTierOrTheFallbackAfterADecisionEvenWhenTheExactTierIsOff) {
  Cascade c;
  c.run(false, Verdict::done(), Verdict::open(Why::exact_gave_up));
  EXPECT_EQ(c.trace, "filter ");
}

TEST(FilteredExactOrFallback, SaysTheAnswerIsFilledWhenATierDecidesOrTheFallbackRuns) {
  for (const bool exact_tier_on : {true, false}) {
    Cascade decided, fell_back;
    decided.run(exact_tier_on, Verdict::open(Why::filter_open), Verdict::done());
    fell_back.run(exact_tier_on, Verdict::open(Why::filter_open), Verdict::open(Why::exact_gave_up));
    EXPECT_TRUE(decided.answered);
    EXPECT_TRUE(fell_back.answered);
  }
}

TEST(FilteredExactOrFallback, StopsWithoutAnAnswerOrTheFallbackWhenTheExactTierDeclines) {
  Cascade c;
  c.run(true, Verdict::open(Why::filter_open), Verdict::declined());
  EXPECT_EQ(c.trace, "filter exact ");
  EXPECT_FALSE(c.answered);
  EXPECT_EQ(c.fallback_was_told, Why::none);
}

TEST(FilteredExactOrFallback, StopsWithoutAnAnswerWhenTheFilterDeclines) {
  Cascade c;
  c.run(true, Verdict::declined(), Verdict::done());
  EXPECT_EQ(c.trace, "filter ");
  EXPECT_FALSE(c.answered);
}

TEST(FilteredExactOrFallback, FallsBackWhenTheExactTierIsOffEvenIfItWouldDecline) {
  Cascade c;
  c.run(false, Verdict::open(Why::filter_open), Verdict::declined());
  EXPECT_EQ(c.trace, "filter fallback ");
  EXPECT_TRUE(c.answered);
}

TEST(FilteredPredicate, RunsTheAPrioriFilterInsideTheGuardAndTheRunningErrorOneOutside) {
  for (const bool guard : {true, false}) {
    std::string trace;
    const int quantities = floating_point_filter(
        guard,
        [&] {
          trace += "a priori ";
          return 1;
        },
        [&] {
          trace += "running error ";
          return 2;
        });
    EXPECT_EQ(quantities, guard ? 1 : 2);
    EXPECT_EQ(trace, guard ? "a priori " : "running error ");
  }
}

TEST(FilteredPredicate, RunsTheExactTierOnlyWhenTheFiltersDecisionIsEmpty) {
  for (const bool decides : {true, false}) {
    bool exact_ran = false;
    const int answer = filtered_predicate(
        true, [] { return 5; }, [] { return 6; },
        [&](int quantities) { return decides ? std::optional<int>(quantities) : std::nullopt; },
        [&] {
          exact_ran = true;
          return 7;
        });
    EXPECT_EQ(answer, decides ? 5 : 7);
    EXPECT_EQ(exact_ran, !decides);
  }
}

}  // namespace
}  // namespace clearjoint::geometry::detail
