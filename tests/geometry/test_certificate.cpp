// SPDX-License-Identifier: BSD-3-Clause
// Certificate: trust levels, their names, and how the parts of one answer combine.

#include "clearjoint/geometry/certificate.hpp"

#include <array>
#include <string>

#include <gtest/gtest.h>

namespace clearjoint::geometry {
namespace {

constexpr std::array<Certainty, 3> kLevelsStrongestFirst = {Certainty::exact, Certainty::certified,
                                                            Certainty::uncertain};

TEST(Certificate, NamesEachLevelAfterItsEnumerator) {
  EXPECT_EQ(to_string(Certainty::exact), "exact");
  EXPECT_EQ(to_string(Certainty::certified), "certified");
  EXPECT_EQ(to_string(Certainty::uncertain), "uncertain");
}

TEST(Certificate, DefaultsToCertifiedWithAnEmptyReason) {
  const Certificate c;
  EXPECT_EQ(c.level, Certainty::certified);
  ASSERT_NE(c.reason, nullptr);
  EXPECT_EQ(std::string(c.reason), "");
}

TEST(Certificate, WeakestOfExactAndCertifiedIsCertified) {
  const Certificate exact{Certainty::exact, "rationals"};
  const Certificate certified{Certainty::certified, ""};
  EXPECT_EQ(weakest(exact, certified).level, Certainty::certified);
  EXPECT_EQ(weakest(certified, exact).level, Certainty::certified);
}

TEST(Certificate, WeakestKeepsTheReasonOfTheUncertainPart) {
  const Certificate exact{Certainty::exact, "rationals"};
  const Certificate uncertain{Certainty::uncertain, "certificate switched off"};
  for (const Certificate& other : {exact, Certificate{}}) {
    const Certificate ab = weakest(other, uncertain);
    const Certificate ba = weakest(uncertain, other);
    EXPECT_EQ(ab.level, Certainty::uncertain);
    EXPECT_EQ(ba.level, Certainty::uncertain);
    EXPECT_EQ(std::string(ab.reason), "certificate switched off");
    EXPECT_EQ(std::string(ba.reason), "certificate switched off");
  }
}

TEST(Certificate, WeakestOfTwoEqualLevelsIsThatLevelWithOneOfTheirReasons) {
  for (Certainty level : kLevelsStrongestFirst) {
    const Certificate a{level, "first reason"};
    const Certificate b{level, "second reason"};
    const Certificate w = weakest(a, b);
    EXPECT_EQ(w.level, level);
    const std::string reason = w.reason;
    EXPECT_TRUE(reason == "first reason" || reason == "second reason") << reason;
  }
}

TEST(Certificate, WeakestIsSymmetricInLevelForEveryPair) {
  // The level of weakest(a, b) is the later of the two in strongest-first order.
  for (std::size_t i = 0; i < kLevelsStrongestFirst.size(); ++i) {
    for (std::size_t j = 0; j < kLevelsStrongestFirst.size(); ++j) {
      const Certificate a{kLevelsStrongestFirst[i], "a"};
      const Certificate b{kLevelsStrongestFirst[j], "b"};
      const Certainty expected = kLevelsStrongestFirst[std::max(i, j)];
      EXPECT_EQ(weakest(a, b).level, expected) << i << " " << j;
      EXPECT_EQ(weakest(b, a).level, expected) << i << " " << j;
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry
