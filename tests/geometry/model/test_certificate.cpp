// SPDX-License-Identifier: BSD-3-Clause
// Certificate: trust levels, their names, and how the parts of one answer combine.

#include "clearjoint/geometry/model/certificate.hpp"

#include <array>
#include <set>
#include <string_view>
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

TEST(Certificate, DefaultsToUncertainBecauseNothingDecidedIt) {
  const Certificate c;
  EXPECT_EQ(c.level, Certainty::uncertain);
  EXPECT_EQ(c.reason, CertificateReason::not_decided);
  EXPECT_NE(c.reason_text(), "");
}

TEST(Certificate, GivesEveryReasonButNoneADistinctNonEmptyText) {
  EXPECT_EQ(to_string(CertificateReason::none), "");
  std::set<std::string_view> texts;
  const int last = static_cast<int>(CertificateReason::edge_sides_undecided);
  for (int i = 1; i <= last; ++i) {
    const std::string_view text = to_string(static_cast<CertificateReason>(i));
    EXPECT_NE(text, "") << i;
    EXPECT_NE(text, "unknown") << i;
    EXPECT_TRUE(texts.insert(text).second) << "repeated: " << text;
  }
}

TEST(Certificate, WeakestOfExactAndCertifiedIsCertified) {
  const Certificate exact{Certainty::exact, CertificateReason::plane_filter_undecided};
  const Certificate certified{Certainty::certified, CertificateReason::none};
  EXPECT_EQ(weakest(exact, certified).level, Certainty::certified);
  EXPECT_EQ(weakest(certified, exact).level, Certainty::certified);
}

TEST(Certificate, WeakestKeepsTheReasonOfTheUncertainPart) {
  const Certificate exact{Certainty::exact, CertificateReason::plane_filter_undecided};
  const Certificate uncertain{Certainty::uncertain, CertificateReason::certificate_switched_off};
  const Certificate certified{Certainty::certified, CertificateReason::none};
  for (const Certificate& other : {exact, certified}) {
    const Certificate ab = weakest(other, uncertain);
    const Certificate ba = weakest(uncertain, other);
    EXPECT_EQ(ab.level, Certainty::uncertain);
    EXPECT_EQ(ba.level, Certainty::uncertain);
    EXPECT_EQ(ab.reason, CertificateReason::certificate_switched_off);
    EXPECT_EQ(ba.reason, CertificateReason::certificate_switched_off);
  }
}

TEST(Certificate, WeakestOfTwoEqualLevelsIsThatLevelWithOneOfTheirReasons) {
  for (Certainty level : kLevelsStrongestFirst) {
    const Certificate a{level, CertificateReason::subdivision_budget_exhausted};
    const Certificate b{level, CertificateReason::coefficient_overflow};
    const Certificate w = weakest(a, b);
    EXPECT_EQ(w.level, level);
    EXPECT_TRUE(w.reason == a.reason || w.reason == b.reason) << w.reason_text();
  }
}

TEST(Certificate, WeakestIsSymmetricInLevelForEveryPair) {
  // The level of weakest(a, b) is the later of the two in strongest-first order.
  for (std::size_t i = 0; i < kLevelsStrongestFirst.size(); ++i) {
    for (std::size_t j = 0; j < kLevelsStrongestFirst.size(); ++j) {
      const Certificate a{kLevelsStrongestFirst[i], CertificateReason::none};
      const Certificate b{kLevelsStrongestFirst[j], CertificateReason::certificate_switched_off};
      const Certainty expected = kLevelsStrongestFirst[std::max(i, j)];
      EXPECT_EQ(weakest(a, b).level, expected) << i << " " << j;
      EXPECT_EQ(weakest(b, a).level, expected) << i << " " << j;
    }
  }
}

}  // namespace
}  // namespace clearjoint::geometry
