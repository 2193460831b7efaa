// SPDX-License-Identifier: BSD-3-Clause
// ValidationError: the field's path and the detail, also once the error is named with the file
// it was found in.

#include "clearjoint/validation_error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace clearjoint {
namespace {

TEST(ValidationError, SplitsItsMessageIntoTheFieldPathAndTheDetail) {
  const ValidationError e("bodies[1].mass", " = -0.3: must be positive");
  EXPECT_STREQ(e.what(), "bodies[1].mass = -0.3: must be positive");
  EXPECT_EQ(e.field_path(), "bodies[1].mass");
  EXPECT_EQ(e.detail(), " = -0.3: must be positive");
}

TEST(ValidationError, KeepsTheFieldPathAndDetailWhenNamedWithItsFile) {
  const ValidationError inner("bodies[1].mass", " = -0.3: must be positive");
  const ValidationError e(inner, "models/crank.json");
  EXPECT_STREQ(e.what(), "models/crank.json: bodies[1].mass = -0.3: must be positive");
  EXPECT_EQ(e.field_path(), "bodies[1].mass");
  EXPECT_EQ(e.detail(), " = -0.3: must be positive");
}

TEST(ValidationError, KeepsAnEmptyPathAndTheWholeMessageAsDetailForAnErrorAboutNoOneField) {
  const ValidationError e(ValidationError("malformed JSON: unexpected end"), "crank.json");
  EXPECT_STREQ(e.what(), "crank.json: malformed JSON: unexpected end");
  EXPECT_EQ(e.field_path(), "");
  EXPECT_EQ(e.detail(), "malformed JSON: unexpected end");
}

TEST(ValidationError, KeepsTheFieldPathThroughTwoSources) {
  const ValidationError e(ValidationError(ValidationError("solver.end_time", " = -1: must be positive"), "a.json"),
                          "study.json");
  EXPECT_STREQ(e.what(), "study.json: a.json: solver.end_time = -1: must be positive");
  EXPECT_EQ(e.field_path(), "solver.end_time");
}

}  // namespace
}  // namespace clearjoint
