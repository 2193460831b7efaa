// SPDX-License-Identifier: BSD-3-Clause
// Tests of bench/geometry/answer_families.hpp: dump_answers' text must be a function of the
// library build alone (the same lines every time), every line must hold exactly the fields its
// counts announce (answer_text.hpp's grammar), and the families must reach what they are there
// for: the certified and uncertified pipelines and the exact tier.

#include "answer_families.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace clearjoint::bench {
namespace {

// Inputs per family in these tests: every family, both lines of each input, ~0.1 s in all.
constexpr int kInputsPerFamily = 300;

std::vector<std::string> lines_of(const AnswerFamily& family, int input_limit = kInputsPerFamily) {
  std::vector<std::string> lines;
  print_family(family, [&](std::string_view line) { lines.emplace_back(line); }, input_limit);
  return lines;
}

// Splits a line at single spaces, except inside double quotes (a certificate's reason).
std::vector<std::string> fields_of(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (begin <= line.size()) {
    std::size_t end = line.find(' ', begin);
    if (begin < line.size() && line[begin] == '"') end = line.find(' ', line.find('"', begin + 1));
    if (end == std::string_view::npos) end = line.size();
    fields.emplace_back(line.substr(begin, end - begin));
    begin = end + 1;
  }
  return fields;
}

// Walks a line's fields by answer_text.hpp's grammar and says what is wrong, if anything: a field
// that is not what the grammar expects there, a number not in the %a form that reads back to
// itself, a line shorter or longer than its counts say.
class LineGrammar {
 public:
  explicit LineGrammar(std::string_view line) : fields_(fields_of(line)) {}

  std::string error() {
    if (fields_.size() < 3) return "fewer than 3 fields";
    next_ = 3;
    const std::string& query = fields_[2];
    if (fields_.size() > 3 && fields_[3] == "threw") return "";
    if (query == "detect" || query == "detect_uncertified") {
      joint_contacts();
    } else if (query == "circle_cylinder") {
      circle_cylinder();
    } else if (query == "circle_plane") {
      circle_plane();
    } else {
      return "unknown query " + query;
    }
    if (error_.empty() && next_ != fields_.size()) {
      error_ = std::to_string(fields_.size() - next_) + " fields past the answer";
    }
    return error_;
  }

 private:
  void joint_contacts() {
    tagged("s");
    tagged("al");
    const int contacts = tagged("n");
    certificate();
    for (int i = 0; i < contacts && error_.empty(); ++i) {
      word("|");
      tagged("t");
      tagged("b");
      numbers(10);  // p_WCj, p_WCi, normal_W, depth
      word("e");
      numbers(3);  // p_WCj_error, p_WCi_error, depth_error
      const int crossings = tagged("nc");
      for (int k = 0; k < crossings; ++k) crossing();
      certificate();
    }
  }
  void circle_cylinder() {
    tagged("t");
    const int crossings = tagged("n");
    const int arcs = tagged("a");
    certificate();
    for (int k = 0; k < crossings; ++k) crossing();
    for (int k = 0; k < arcs; ++k) arc();
  }
  void circle_plane() {
    tagged("t");
    tagged("s");
    const int crossings = tagged("n");
    certificate();
    tagged("pen");
    arc();
    word("msd");
    numbers(2);
    for (int k = 0; k < crossings; ++k) crossing();
  }
  void certificate() {
    tagged("c");
    const std::string& reason = take();
    if (reason.size() < 2 || reason.front() != '"' || reason.back() != '"') fail("a quoted reason");
  }
  void crossing() {
    word("x");
    numbers(6);
    tagged("m");
  }
  void arc() {
    word("arc");
    numbers(2);
    tagged("f");
  }

  const std::string& take() {
    static const std::string kPastTheEnd = "(past the end)";
    if (next_ >= fields_.size()) {
      fail("a field");
      return kPastTheEnd;
    }
    return fields_[next_++];
  }
  void word(std::string_view expected) {
    if (take() != expected) fail(std::string(expected));
  }
  // "n2": the tag, then a whole number (negative only for a plane's side).
  int tagged(std::string_view tag) {
    const std::string& field = take();
    char* end = nullptr;
    const long value = field.starts_with(tag) ? std::strtol(field.c_str() + tag.size(), &end, 10) : 0;
    if (end == nullptr || end == field.c_str() + tag.size() || *end != '\0') {
      fail(std::string(tag) + "<integer>");
      return 0;
    }
    return static_cast<int>(value);
  }
  void numbers(int count) {
    for (int i = 0; i < count; ++i) {
      const std::string& field = take();
      char printed[32];
      std::snprintf(printed, sizeof printed, "%a", std::strtod(field.c_str(), nullptr));
      if (field != printed) fail("a number in %a");
    }
  }
  void fail(const std::string& expected) {
    if (!error_.empty()) return;
    const std::size_t at = next_ == 0 ? 0 : next_ - 1;
    error_ = "field " + std::to_string(at) + ": expected " + expected + ", found '" +
             (at < fields_.size() ? fields_[at] : std::string()) + "'";
  }

  std::vector<std::string> fields_;
  std::size_t next_ = 0;
  std::string error_;
};

TEST(AnswerFamilies, AFamilyPrintsTheSameTextWhateverRanBeforeIt) {
  // The text must depend on the build alone, not on what the process did before: each family is
  // printed first, then again after every family has run (in reverse order, so that the reused
  // detection result, the kernel's caches and any stray random state hold another family's
  // leftovers). A family that read state left over from an earlier call, or a seed drawn at run
  // time, would print other lines the second time.
  const std::span<const AnswerFamily> families = answer_families();
  std::vector<std::vector<std::string>> first;
  for (const AnswerFamily& family : families) first.push_back(lines_of(family));
  for (std::size_t k = families.size(); k-- > 0;) {
    EXPECT_EQ(lines_of(families[k]), first[k]) << families[k].name;
  }
}

TEST(AnswerFamilies, TheFirstInputsPrintTheSameLinesWhateverTheLimit) {
  for (const AnswerFamily& family : answer_families()) {
    const std::vector<std::string> few = lines_of(family, 20);
    const std::vector<std::string> more = lines_of(family, 40);
    ASSERT_EQ(few.size(), 20u * kLinesPerInput) << family.name;
    EXPECT_TRUE(std::equal(few.begin(), few.end(), more.begin())) << family.name;
  }
}

TEST(AnswerFamilies, EveryLineHoldsExactlyTheFieldsItsCountsAnnounce) {
  for (const AnswerFamily& family : answer_families()) {
    const std::vector<std::string> lines = lines_of(family);
    ASSERT_EQ(lines.size(), static_cast<std::size_t>(kInputsPerFamily * kLinesPerInput));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      ASSERT_EQ(LineGrammar(lines[i]).error(), "") << lines[i];
      const std::vector<std::string> fields = fields_of(lines[i]);
      EXPECT_EQ(fields[0], family.name);
      EXPECT_EQ(fields[1], std::to_string(i / kLinesPerInput));
      EXPECT_NE(fields[3], "threw") << lines[i];  // every generated input is valid
    }
  }
}

TEST(AnswerFamilies, TheGrammarCheckRejectsAFieldTooFewOrTooManyOrADecimalNumber) {
  // The check above must be able to fail.
  const std::string line = lines_of(answer_families().front(), 1).front();
  ASSERT_EQ(LineGrammar(line).error(), "");
  EXPECT_NE(LineGrammar(line.substr(0, line.rfind(' '))).error(), "");
  EXPECT_NE(LineGrammar(line + " 0x1p+0").error(), "");
  // The first number, the same value in decimal.
  const std::size_t begin = line.find(" 0x") + 1, end = line.find(' ', begin);
  char decimal[32];
  std::snprintf(decimal, sizeof decimal, "%.17g", std::strtod(line.c_str() + begin, nullptr));
  const std::string in_decimal = line.substr(0, begin) + decimal + line.substr(end);
  EXPECT_NE(LineGrammar(in_decimal).error().find("%a"), std::string::npos) << in_decimal;
}

TEST(AnswerFamilies, DetectionsAreCertifiedExceptTheUncertifiedOnes) {
  for (const AnswerFamily& family : answer_families()) {
    for (const std::string& line : lines_of(family)) {
      const std::vector<std::string> fields = fields_of(line);
      if (fields[2] == "detect_uncertified") {
        EXPECT_EQ(fields[6] + " " + fields[7], "c2 \"certificate switched off\"") << line;
      } else if (fields[2] == "detect") {
        EXPECT_NE(fields[6], "c2") << line;
      }
    }
  }
}

TEST(AnswerFamilies, TheNearTangentFamilyReachesTheExactTier) {
  const AnswerFamily* family = find_answer_family("near_tangent");
  ASSERT_NE(family, nullptr);
  std::set<std::string> queries_with_exact_answers;
  for (const std::string& line : lines_of(*family)) {
    if (line.find(" c0 \"") != std::string::npos) queries_with_exact_answers.insert(fields_of(line)[2]);
  }
  EXPECT_EQ(queries_with_exact_answers, (std::set<std::string>{"circle_cylinder", "detect"}));
}

TEST(AnswerFamilies, TheFamiliesHold192000LinesUnderUniqueNames) {
  int lines = 0;
  std::set<std::string_view> names;
  for (const AnswerFamily& family : answer_families()) {
    lines += family.input_count * kLinesPerInput;
    EXPECT_TRUE(names.insert(family.name).second) << family.name;
    EXPECT_EQ(find_answer_family(family.name), &family);
    EXPECT_EQ(family.name.find(' '), std::string_view::npos) << family.name;
  }
  EXPECT_EQ(lines, 192000);  // the figure docs/verifying-refactors.md gives
  EXPECT_EQ(find_answer_family("no_such_family"), nullptr);
}

}  // namespace
}  // namespace clearjoint::bench
