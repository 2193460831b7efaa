// SPDX-License-Identifier: BSD-3-Clause
// The result structs of clearjoint.h keep the layout of CJ_ABI_VERSION 1 (the ABI rules in the
// header: no member moves, structs never grow). Their members are written from the result field
// lists (scripts/projections/c_structs.py), whose order is the outputs' and not the ABI's; these
// offsets are what a program built against an older header reads.

#include <cstddef>

#include <gtest/gtest.h>

#include "clearjoint/clearjoint.h"

namespace {

static_assert(CJ_ABI_VERSION == 1, "a new ABI: write its layout below");

// The offsets below are those of the LP64 data model (Linux, macOS; pointers of 8 bytes).
constexpr bool kLp64 = sizeof(void*) == 8 && alignof(double) == 8;

TEST(CLayout, TheCertificateAndTheCrossingKeepTheirOffsets) {
  if (!kLp64) GTEST_SKIP() << "offsets written for LP64";
  EXPECT_EQ(offsetof(cj_certificate, level), 0u);
  EXPECT_EQ(offsetof(cj_certificate, reason), 4u);
  EXPECT_EQ(offsetof(cj_certificate, reason_text), 8u);
  EXPECT_EQ(sizeof(cj_certificate), 16u);
  EXPECT_EQ(offsetof(cj_crossing, angle), 0u);
  EXPECT_EQ(offsetof(cj_crossing, angle_error_bound), 8u);
  EXPECT_EQ(offsetof(cj_crossing, point), 16u);
  EXPECT_EQ(offsetof(cj_crossing, point_error_bound), 40u);
  EXPECT_EQ(offsetof(cj_crossing, multiplicity), 48u);
  EXPECT_EQ(sizeof(cj_crossing), 56u);
}

TEST(CLayout, TheContactKeepsItsOffsetsAndSize) {
  if (!kLp64) GTEST_SKIP() << "offsets written for LP64";
  EXPECT_EQ(offsetof(cj_contact, type), 0u);
  EXPECT_EQ(offsetof(cj_contact, base), 4u);
  EXPECT_EQ(offsetof(cj_contact, p_WCj), 8u);
  EXPECT_EQ(offsetof(cj_contact, p_WCi), 32u);
  EXPECT_EQ(offsetof(cj_contact, normal_W), 56u);
  EXPECT_EQ(offsetof(cj_contact, depth), 80u);
  EXPECT_EQ(offsetof(cj_contact, depth_error_bound), 88u);
  EXPECT_EQ(offsetof(cj_contact, p_WCj_error_bound), 96u);
  EXPECT_EQ(offsetof(cj_contact, p_WCi_error_bound), 104u);
  EXPECT_EQ(offsetof(cj_contact, crossings), 112u);
  EXPECT_EQ(offsetof(cj_contact, crossing_count), 224u);
  EXPECT_EQ(offsetof(cj_contact, certificate), 232u);
  EXPECT_EQ(sizeof(cj_contact), 280u);
}

TEST(CLayout, TheResultKeepsItsOffsetsAndSize) {
  if (!kLp64) GTEST_SKIP() << "offsets written for LP64";
  EXPECT_EQ(offsetof(cj_result, scenario), 0u);
  EXPECT_EQ(offsetof(cj_result, aligned), 4u);
  EXPECT_EQ(offsetof(cj_result, contact_count), 8u);
  EXPECT_EQ(offsetof(cj_result, certificate), 16u);
  EXPECT_EQ(offsetof(cj_result, contacts), 32u);
  EXPECT_EQ(sizeof(cj_result), 1776u);
}

TEST(CLayout, ThePinInHoleStructsKeepTheirOffsetsAndSizes) {
  if (!kLp64) GTEST_SKIP() << "offsets written for LP64";
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, hole_radius), 0u);
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, hole_length), 8u);
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, pin_radius), 16u);
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, stop_count), 24u);
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, stops), 32u);
  EXPECT_EQ(offsetof(cj_pin_in_hole_dimensions, reserved), 64u);
  EXPECT_EQ(sizeof(cj_pin_in_hole_dimensions), 96u);
  // The same layout as cj_result, so that code reading one reads the other.
  EXPECT_EQ(offsetof(cj_pin_in_hole_result, scenario), offsetof(cj_result, scenario));
  EXPECT_EQ(offsetof(cj_pin_in_hole_result, aligned), offsetof(cj_result, aligned));
  EXPECT_EQ(offsetof(cj_pin_in_hole_result, contact_count), offsetof(cj_result, contact_count));
  EXPECT_EQ(offsetof(cj_pin_in_hole_result, certificate), offsetof(cj_result, certificate));
  EXPECT_EQ(offsetof(cj_pin_in_hole_result, contacts), offsetof(cj_result, contacts));
  EXPECT_EQ(sizeof(cj_pin_in_hole_result), 1776u);
}

}  // namespace
